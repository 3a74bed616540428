//! The filter study (`bench --filter-study`, benchmark issue item 3): frame time against
//! error for every minification filter and anisotropy level, softgl and llvmpipe.
//!
//! `bench/scenes/filter_study.c` draws the checkerboard ground plane of
//! `c_tests/tex_truth_plane.h` at 512×512 with the filter named by `FILTER_STUDY`. The runs
//! alternate as in the main benchmark (for each repetition, for each filter: every renderer
//! of [`RENDERERS`] — softgl, llvmpipe with one thread, llvmpipe with its default threads,
//! softgl with one thread), and the time of a filter and renderer is the median over
//! repetitions of each run's median frame time. The error
//! is that of each renderer's last frame against the analytic ground truth
//! (`ground_truth.rs`, 16×16 samples per pixel): mean absolute error and PSNR over the RGB
//! channels of the pixels the plane fully covers. Writes `target/bench/filter_study.md`,
//! `.csv` and `.png`, and copies the table to `bench/filter_study.md` and the chart to
//! `docs/filter_study.png`.

use super::ground_truth::{ground_truth, TruthError};
use super::{
    build, chart, compare, fmt_ms, fmt_pct, fmt_ratio, machine_line, median, out_dir, read_frame,
    root, run_scene, save_png, Config, Frame, Renderer, RENDERERS,
};
use std::fmt::Write as _;
use std::fs;
use std::path::PathBuf;
use std::time::Instant;

/// The study's scene in `bench/scenes/`; the main benchmark leaves it out.
pub const SCENE: &str = "filter_study";

/// Frame size (square).
const SIZE: u32 = 512;

/// Ground-truth samples per pixel along each axis.
const SAMPLES: usize = 16;

/// The filters: `FILTER_STUDY` value, short id for the chart, name for the table.
const MODES: &[(&str, &str, &str)] = &[
    ("nearest", "N", "NEAREST"),
    ("linear", "L", "LINEAR"),
    ("nearest_mipmap_nearest", "NMN", "NEAREST_MIPMAP_NEAREST"),
    ("linear_mipmap_nearest", "LMN", "LINEAR_MIPMAP_NEAREST"),
    ("nearest_mipmap_linear", "NML", "NEAREST_MIPMAP_LINEAR"),
    ("linear_mipmap_linear", "LML", "LINEAR_MIPMAP_LINEAR"),
    ("aniso2", "A2", "LINEAR_MIPMAP_LINEAR, anisotropy 2"),
    ("aniso4", "A4", "LINEAR_MIPMAP_LINEAR, anisotropy 4"),
    ("aniso8", "A8", "LINEAR_MIPMAP_LINEAR, anisotropy 8"),
    ("aniso16", "A16", "LINEAR_MIPMAP_LINEAR, anisotropy 16"),
];

/// Everything measured for one filter and renderer.
#[derive(Default)]
struct Slot {
    run_medians: Vec<f64>,
    failure: Option<String>,
    output: Option<PathBuf>,
}

/// Runs the study and writes its table and chart.
pub fn run(cfg: &Config) -> Result<(), String> {
    let started = Instant::now();
    eprintln!("filter study: compiling {SCENE} against softgl and OSMesa");
    let bins = [build(SCENE, true), build(SCENE, false)];
    // One slot per renderer, in the order of `RENDERERS` (softgl, llvmpipe-1, llvmpipe,
    // softgl-1).
    let mut slots: Vec<[Slot; RENDERERS.len()]> =
        MODES.iter().map(|_| Default::default()).collect();
    let out = out_dir();
    for rep in 0..cfg.reps {
        eprintln!(
            "filter study: repetition {}/{} ({:.0} s so far)",
            rep + 1,
            cfg.reps,
            started.elapsed().as_secs_f64()
        );
        for ((mode, _, _), slot) in MODES.iter().zip(&mut slots) {
            for (ri, &r) in RENDERERS.iter().enumerate() {
                let s = &mut slot[ri];
                let ours = matches!(r, Renderer::Softgl | Renderer::Softgl1);
                let bin = match &bins[usize::from(!ours)] {
                    Ok(b) => b,
                    Err(e) => {
                        s.failure.get_or_insert_with(|| e.clone());
                        continue;
                    }
                };
                if s.failure.is_some() {
                    continue;
                }
                let output = out
                    .join("runs")
                    .join(format!("{SCENE}-{mode}.{}.out", r.label()));
                let env = [("FILTER_STUDY", *mode)];
                match run_scene(bin, r, &output, SIZE, cfg.frames, cfg.timeout, &env) {
                    Ok(o) => match median(&o.frame_ms) {
                        Some(m) => {
                            s.run_medians.push(m);
                            s.output = Some(output);
                        }
                        None => s.failure = Some("printed no frame times".into()),
                    },
                    Err(e) => {
                        eprintln!("  {mode} {}: {e}", r.label());
                        s.failure = Some(e);
                    }
                }
            }
        }
    }

    eprintln!("filter study: ground truth {SIZE}x{SIZE}, {SAMPLES}x{SAMPLES} samples/pixel");
    let size = SIZE as usize;
    let truth = ground_truth(size, size, SAMPLES);
    let img_dir = out.join("images");
    let _ = fs::create_dir_all(&img_dir);
    let _ = image::RgbImage::from_raw(SIZE, SIZE, truth.to_rgb())
        .map(|t| t.save(img_dir.join(format!("{SCENE}-truth.png"))));

    let mut md = String::new();
    let _ = writeln!(md, "# Filter study: frame time against error\n");
    let _ = writeln!(
        md,
        "Generated by `bash scripts/bench.sh --filter-study` (`bench/runner/filter_study.rs`). \
         {}. The ground plane of `bench/scenes/filter_study.c` (a 512×512 black/white \
         checkerboard with its untinted mip chain, `c_tests/tex_truth_plane.h`) at \
         {SIZE}×{SIZE} with each filter. {} repetitions × {} timed frames per renderer, run in \
         alternation (softgl default threads, llvmpipe 1 thread, llvmpipe default threads, \
         softgl-1 = softgl with SOFTGL_THREADS=1); times are the median over repetitions of \
         each run's median frame time (draw + glFinish), in ms. Single-thread against \
         single-thread: softgl-1/lp-1; default against default: softgl/lp.\n",
        machine_line(),
        cfg.reps,
        cfg.frames
    );
    let judged = slots
        .iter()
        .find_map(|s| s[0].output.as_deref().map(read_frame))
        .and_then(Result::ok)
        .map_or(0, |f| truth.error(&f.rgba, size * 4, true).pixels);
    let _ = writeln!(
        md,
        "Error is against the analytic ground truth (`bench/runner/ground_truth.rs`): the exact \
         checkerboard averaged over each pixel's square with {0}×{0} jittered samples through \
         the inverse of the plane's projection, in f64. MAE is the mean absolute error in \
         8-bit levels and PSNR is 10·log10(255²/MSE), over the RGB channels of the {judged} \
         pixels the plane fully covers (the sky and the plane's silhouette are left out). \
         *identical %* compares softgl's frame with llvmpipe-1's byte for byte.\n",
        truth.samples
    );
    let _ = writeln!(
        md,
        "| id | filter | softgl-1 ms | llvmpipe-1 ms | softgl-1/lp-1 | softgl ms | llvmpipe ms | \
         softgl/lp | softgl MAE | llvmpipe MAE | softgl PSNR dB | llvmpipe PSNR dB | \
         identical % | note |"
    );
    let _ = writeln!(
        md,
        "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|"
    );
    let mut csv = String::from(
        "filter,id,size,softgl_ms,llvmpipe1_ms,llvmpipe_ms,softgl1_ms,softgl_mae,llvmpipe1_mae,\
         llvmpipe_mae,softgl_rmse,llvmpipe1_rmse,llvmpipe_rmse,softgl_psnr_db,\
         llvmpipe1_psnr_db,llvmpipe_psnr_db,identical_pct_softgl_vs_llvmpipe1,judged_pixels,note\n",
    );
    let mut points = Vec::new();
    for ((mode, id, name), slot) in MODES.iter().zip(&slots) {
        let ms: [Option<f64>; RENDERERS.len()] =
            std::array::from_fn(|i| median(&slot[i].run_medians));
        let frames: [Option<Frame>; RENDERERS.len()] = std::array::from_fn(|i| {
            slot[i]
                .output
                .as_deref()
                .and_then(|p| read_frame(p).ok())
                .filter(|f| (f.width, f.height) == (SIZE, SIZE))
        });
        let errs: [Option<TruthError>; RENDERERS.len()] = std::array::from_fn(|i| {
            frames[i]
                .as_ref()
                .map(|f| truth.error(&f.rgba, size * 4, true))
        });
        for (i, r) in RENDERERS.iter().enumerate().take(2) {
            if let Some(f) = &frames[i] {
                save_png(
                    f,
                    &img_dir.join(format!("{SCENE}-{mode}.{}.png", r.label())),
                );
            }
        }
        let mut notes: Vec<String> = Vec::new();
        for (i, r) in RENDERERS.iter().enumerate() {
            if let Some(f) = &slot[i].failure {
                notes.push(format!("{}: {f}", r.label()));
            }
        }
        let ident = match (&frames[0], &frames[1]) {
            (Some(a), Some(b)) => compare(a, b).ok(),
            _ => None,
        };
        for (a, b, what) in [(2, 1, "llvmpipe"), (3, 0, "softgl")] {
            if let (Some(fa), Some(fb)) = (&frames[a], &frames[b]) {
                if let Ok(e) = compare(fa, fb) {
                    if e.pixels_off > 0 {
                        notes.push(format!(
                            "{what} threads vs 1 thread: {:.2}% identical",
                            e.identical_pct
                        ));
                    }
                }
            }
        }
        let mae = |e: Option<TruthError>| e.map_or("—".into(), |e| format!("{:.2}", e.mae));
        let psnr = |e: Option<TruthError>| e.map_or("—".into(), |e| format!("{:.2}", e.psnr));
        let note = notes.join("; ").replace('|', "/");
        let _ = writeln!(
            md,
            "| {id} | {name} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {note} |",
            fmt_ms(ms[3]),
            fmt_ms(ms[1]),
            fmt_ratio(ms[3], ms[1]),
            fmt_ms(ms[0]),
            fmt_ms(ms[2]),
            fmt_ratio(ms[0], ms[2]),
            mae(errs[0]),
            mae(errs[1]),
            psnr(errs[0]),
            psnr(errs[1]),
            ident.map_or("—".into(), |e| fmt_pct(e.identical_pct, e.pixels_off)),
        );
        let opt = |v: Option<f64>| v.map_or(String::new(), |v| format!("{v:.4}"));
        let _ = writeln!(
            csv,
            "{mode},{id},{SIZE},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},\"{note}\"",
            opt(ms[0]),
            opt(ms[1]),
            opt(ms[2]),
            opt(ms[3]),
            opt(errs[0].map(|e| e.mae)),
            opt(errs[1].map(|e| e.mae)),
            opt(errs[2].map(|e| e.mae)),
            opt(errs[0].map(|e| e.rmse)),
            opt(errs[1].map(|e| e.rmse)),
            opt(errs[2].map(|e| e.rmse)),
            opt(errs[0].map(|e| e.psnr)),
            opt(errs[1].map(|e| e.psnr)),
            opt(errs[2].map(|e| e.psnr)),
            opt(ident.map(|e| e.identical_pct)),
            judged,
        );
        for i in 0..RENDERERS.len() {
            if let (Some(ms), Some(e)) = (ms[i], errs[i]) {
                points.push(chart::Point {
                    ms,
                    error_pct: e.mae,
                    series: i,
                    // softgl-1 shares softgl's circle: drawn hollow.
                    hollow: i == 3,
                    label: (*id).to_owned(),
                });
            }
        }
    }
    let _ = writeln!(
        md,
        "\nllvmpipe's MAE and PSNR are those of its 1-thread frame; the default-thread frame \
         is the same unless the note says otherwise (its figures are in the CSV). The chart \
         `docs/filter_study.png` plots every (filter, renderer) as median frame time (x, log) \
         against MAE (y, log). Study time {:.0} s; the last frames and the truth are in \
         `target/bench/images/{SCENE}-*.png`.",
        started.elapsed().as_secs_f64()
    );

    let series = [
        chart::Series {
            name: "softgl".into(),
            color: [215, 40, 40],
        },
        chart::Series {
            name: "llvmpipe, 1 thread".into(),
            color: [40, 80, 200],
        },
        chart::Series {
            name: "llvmpipe, default threads".into(),
            color: [30, 150, 60],
        },
        chart::Series {
            name: "softgl, 1 thread (hollow)".into(),
            color: [230, 130, 20],
        },
    ];
    let mut legend = vec!["filters".to_owned()];
    legend.extend(MODES.iter().map(|(_, id, name)| {
        let short = name.replace("LINEAR_MIPMAP_LINEAR, anisotropy", "LML, aniso");
        format!("{id:<4}{short}")
    }));
    let y = chart::YAxis {
        label: "error: mean absolute error against the ground truth, 8-bit levels (log scale)"
            .into(),
        min: 0.1,
        max: 100.0,
        zero_line: false,
    };
    let img = chart::draw_with(
        &format!("Filter study, {SIZE}x{SIZE}: frame time against error"),
        &series,
        &points,
        &legend,
        &y,
        false,
    );
    let write = |path: PathBuf, bytes: &[u8]| -> Result<(), String> {
        if let Some(dir) = path.parent() {
            fs::create_dir_all(dir).map_err(|e| format!("mkdir {}: {e}", dir.display()))?;
        }
        fs::write(&path, bytes).map_err(|e| format!("writing {}: {e}", path.display()))
    };
    let png = out.join(format!("{SCENE}.png"));
    img.save(&png)
        .map_err(|e| format!("writing {}: {e}", png.display()))?;
    write(out.join(format!("{SCENE}.md")), md.as_bytes())?;
    write(out.join(format!("{SCENE}.csv")), csv.as_bytes())?;
    write(
        root().join("bench").join(format!("{SCENE}.md")),
        md.as_bytes(),
    )?;
    let png_bytes = fs::read(&png).map_err(|e| format!("reading {}: {e}", png.display()))?;
    write(root().join("docs").join(format!("{SCENE}.png")), &png_bytes)?;
    println!("{md}");
    eprintln!(
        "filter study: wrote target/bench/{SCENE}.md, .csv, .png, bench/{SCENE}.md and \
         docs/{SCENE}.png"
    );
    Ok(())
}
