//! The state sweep (`bench --sweep N`, issue 42 item 4): N seeded random GL 1.x states,
//! each timed on softgl and llvmpipe and compared with llvmpipe's image.
//!
//! `bench/scenes/sweep.c` builds state number `SWEEP_STATE` of seed `SWEEP_SEED` from its own
//! generator and draws a fixed set of patches with it (it prints the state in words as a
//! `state ...` line). For each state the four renderers of [`RENDERERS`] run in
//! alternation (softgl, llvmpipe-1, llvmpipe, softgl-1), `reps` times; a renderer's time is
//! the median over repetitions of each run's median frame time. softgl's last frame is
//! compared with llvmpipe-1's (identical pixels, max channel difference), and each
//! renderer's threaded frame with its single-thread frame. The report gives the
//! distribution of the time ratios (min, median, p90, max; the headline is the worst case,
//! with its state in words) and of the error, and lists every state that differs. Writes
//! `target/bench/sweep.md` and `sweep.csv` (one row per state) and copies the summary to
//! `bench/sweep.md`.

use super::{
    build, compare, fmt_ms, fmt_pct, machine_line, median, out_dir, read_frame, root, run_scene,
    save_png, Config, ErrorStats, Renderer, RENDERERS,
};
use std::fmt::Write as _;
use std::fs;
use std::path::PathBuf;
use std::time::Instant;

/// The sweep's scene in `bench/scenes/`; the main benchmark leaves it out.
pub const SCENE: &str = "sweep";

/// Frame size, repetitions and timed frames when `--sizes`, `--reps`, `--frames` are not
/// given: 200 states then take a few minutes.
const DEFAULT_SIZE: u32 = 256;
const DEFAULT_REPS: usize = 1;
const DEFAULT_FRAMES: usize = 3;

/// What was measured for one state.
struct StateResult {
    index: usize,
    state: String,
    ms: [Option<f64>; RENDERERS.len()],
    error: Result<ErrorStats, String>,
    /// softgl (threads) against softgl-1 and llvmpipe against llvmpipe-1, identical %.
    threads: [Option<f64>; 2],
    failures: Vec<String>,
}

impl StateResult {
    fn ratio(&self, a: usize, b: usize) -> Option<f64> {
        match (self.ms[a], self.ms[b]) {
            (Some(x), Some(y)) if y > 0.0 => Some(x / y),
            _ => None,
        }
    }
    /// softgl-1 / llvmpipe-1.
    fn ratio1(&self) -> Option<f64> {
        self.ratio(3, 1)
    }
    /// softgl / llvmpipe (default threads).
    fn ratio_n(&self) -> Option<f64> {
        self.ratio(0, 2)
    }
}

/// Nearest-rank percentile of sorted values.
fn percentile(sorted: &[f64], p: f64) -> Option<f64> {
    if sorted.is_empty() {
        return None;
    }
    let rank = ((p / 100.0) * sorted.len() as f64).ceil() as usize;
    Some(sorted[rank.clamp(1, sorted.len()) - 1])
}

/// "min / median / p90 / max" of `values` and the index (into `values`) of the maximum.
fn distribution(values: &[Option<f64>]) -> (String, Option<usize>) {
    let mut v: Vec<f64> = values.iter().flatten().copied().collect();
    v.sort_by(|a, b| a.total_cmp(b));
    let worst = values
        .iter()
        .enumerate()
        .filter_map(|(i, x)| x.map(|x| (i, x)))
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(i, _)| i);
    let f = |x: Option<f64>| x.map_or("—".into(), |x| format!("{x:.2}"));
    (
        format!(
            "| {} | {} | {} | {} | {} |",
            v.len(),
            f(v.first().copied()),
            f(median(&v)),
            f(percentile(&v, 90.0)),
            f(v.last().copied())
        ),
        worst,
    )
}

/// Runs the sweep and writes its tables.
pub fn run(cfg: &Config, states: usize) -> Result<(), String> {
    let started = Instant::now();
    let size = if cfg.sizes_given {
        cfg.sizes.first().copied().unwrap_or(DEFAULT_SIZE)
    } else {
        DEFAULT_SIZE
    };
    let reps = if cfg.reps_given {
        cfg.reps
    } else {
        DEFAULT_REPS
    };
    let frames = if cfg.frames_given {
        cfg.frames
    } else {
        DEFAULT_FRAMES
    };
    let seed = cfg.sweep_seed.to_string();
    eprintln!("sweep: compiling {SCENE} against softgl and OSMesa");
    let bins = [build(SCENE, true)?, build(SCENE, false)?];
    let out = out_dir();
    let img_dir = out.join("images");
    let _ = fs::create_dir_all(&img_dir);
    let mut results = Vec::with_capacity(states);
    for index in 0..states {
        if index % 20 == 0 {
            eprintln!(
                "sweep: state {index}/{states} ({:.0} s so far)",
                started.elapsed().as_secs_f64()
            );
        }
        let state_s = index.to_string();
        let env = [
            ("SWEEP_SEED", seed.as_str()),
            ("SWEEP_STATE", state_s.as_str()),
        ];
        let mut runs: [Vec<f64>; RENDERERS.len()] = Default::default();
        let mut outputs: [Option<PathBuf>; RENDERERS.len()] = Default::default();
        let mut failures = Vec::new();
        for _ in 0..reps {
            for (ri, &r) in RENDERERS.iter().enumerate() {
                if failures.iter().any(|f: &String| f.starts_with(r.label())) {
                    continue;
                }
                let ours = matches!(r, Renderer::Softgl | Renderer::Softgl1);
                let output = out.join("runs").join(format!("{SCENE}.{}.out", r.label()));
                match run_scene(
                    &bins[usize::from(!ours)],
                    r,
                    &output,
                    size,
                    frames,
                    cfg.timeout,
                    &env,
                ) {
                    Ok(o) => match median(&o.frame_ms) {
                        Some(m) => {
                            runs[ri].push(m);
                            outputs[ri] = Some(output);
                        }
                        None => failures.push(format!("{}: printed no frame times", r.label())),
                    },
                    Err(e) => failures.push(format!("{}: {e}", r.label())),
                }
            }
        }
        // The state in words, from softgl's (or else llvmpipe's) stdout.
        let state = outputs
            .iter()
            .flatten()
            .find_map(|o| {
                let name = o.file_name()?.to_string_lossy().into_owned();
                let log = fs::read_to_string(out.join("logs").join(format!("{name}.stdout")));
                log.ok()?
                    .lines()
                    .find_map(|l| l.strip_prefix("state ").map(str::to_owned))
            })
            .unwrap_or_default();
        let frames_read: [Option<super::Frame>; RENDERERS.len()] =
            std::array::from_fn(|i| outputs[i].as_deref().and_then(|p| read_frame(p).ok()));
        let error = match (&frames_read[0], &frames_read[1]) {
            (Some(a), Some(b)) => compare(a, b),
            _ => Err("no comparison".into()),
        };
        let threads = [(0, 3), (2, 1)].map(|(a, b)| match (&frames_read[a], &frames_read[b]) {
            (Some(x), Some(y)) => compare(x, y).ok().map(|e| e.identical_pct),
            _ => None,
        });
        if !matches!(&error, Ok(e) if e.pixels_off == 0) {
            for (i, r) in RENDERERS.iter().enumerate().take(2) {
                if let Some(f) = &frames_read[i] {
                    save_png(
                        f,
                        &img_dir.join(format!("{SCENE}-{index}.{}.png", r.label())),
                    );
                }
            }
        }
        let ms = std::array::from_fn(|i| median(&runs[i]));
        results.push(StateResult {
            index,
            state,
            ms,
            error,
            threads,
            failures,
        });
    }
    let md = report(
        cfg,
        &results,
        size,
        reps,
        frames,
        started.elapsed().as_secs_f64(),
    );
    let csv = csv(&results);
    let write = |path: PathBuf, text: &str| -> Result<(), String> {
        fs::write(&path, text).map_err(|e| format!("writing {}: {e}", path.display()))
    };
    write(out.join(format!("{SCENE}.md")), &md.full)?;
    write(out.join(format!("{SCENE}.csv")), &csv)?;
    write(
        root().join("bench").join(format!("{SCENE}.md")),
        &md.summary,
    )?;
    println!("{}", md.summary);
    eprintln!(
        "sweep: wrote target/bench/{SCENE}.md (every state), {SCENE}.csv and bench/{SCENE}.md \
         (the summary)"
    );
    Ok(())
}

/// The summary (committed as `bench/sweep.md`) and the full report (summary + every state).
struct Report {
    summary: String,
    full: String,
}

fn report(
    cfg: &Config,
    results: &[StateResult],
    size: u32,
    reps: usize,
    frames: usize,
    secs: f64,
) -> Report {
    let mut s = String::new();
    let _ = writeln!(s, "# State sweep: softgl against llvmpipe\n");
    let _ = writeln!(
        s,
        "Generated by `bash scripts/bench.sh --sweep {n} --sweep-seed {seed}` \
         (`bench/runner/sweep.rs`, states from `bench/scenes/sweep.c`). {machine}. {n} states \
         of seed {seed} at {size}×{size}, {reps} repetition(s) × {frames} timed frames per \
         renderer (after one warm-up frame), the renderers in alternation per state: softgl \
         (default threads), llvmpipe with 1 thread, llvmpipe (default threads), softgl-1 \
         (SOFTGL_THREADS=1). Times are the median frame time (draw + glFinish); ratios < 1 \
         mean softgl is faster. The error compares softgl's last frame with llvmpipe-1's over \
         all RGBA channels. Sweep time {secs:.0} s.\n",
        n = results.len(),
        seed = cfg.sweep_seed,
        machine = machine_line(),
    );
    let _ = writeln!(s, "## Time ratios\n");
    let _ = writeln!(s, "| ratio | states | min | median | p90 | max |");
    let _ = writeln!(s, "|---|---:|---:|---:|---:|---:|");
    let r1: Vec<Option<f64>> = results.iter().map(StateResult::ratio1).collect();
    let rn: Vec<Option<f64>> = results.iter().map(StateResult::ratio_n).collect();
    let (d1, w1) = distribution(&r1);
    let (dn, wn) = distribution(&rn);
    let _ = writeln!(s, "| softgl-1 / llvmpipe-1 {d1}");
    let _ = writeln!(s, "| softgl / llvmpipe {dn}\n");
    for (what, worst, ratios) in [
        ("softgl-1 / llvmpipe-1", w1, &r1),
        ("softgl / llvmpipe", wn, &rn),
    ] {
        if let Some(i) = worst {
            let r = &results[i];
            let _ = writeln!(
                s,
                "**Worst case, {what}: {:.2}×**, state {} ({} ms against {} ms): `{}`\n",
                ratios[i].unwrap_or(f64::NAN),
                r.index,
                fmt_ms(if what.contains("-1") {
                    r.ms[3]
                } else {
                    r.ms[0]
                }),
                fmt_ms(if what.contains("-1") {
                    r.ms[1]
                } else {
                    r.ms[2]
                }),
                r.state
            );
        }
    }
    // Error distribution.
    let errs: Vec<&ErrorStats> = results
        .iter()
        .filter_map(|r| r.error.as_ref().ok())
        .collect();
    let mut ident: Vec<f64> = errs.iter().map(|e| e.identical_pct).collect();
    ident.sort_by(|a, b| a.total_cmp(b));
    let exact = errs.iter().filter(|e| e.pixels_off == 0).count();
    let within = |d: u8| {
        errs.iter()
            .filter(|e| e.pixels_off > 0 && e.max_diff <= d)
            .count()
    };
    let beyond = errs.iter().filter(|e| e.max_diff > 2).count();
    let _ = writeln!(s, "## Error against llvmpipe\n");
    let _ = writeln!(
        s,
        "{} of {} states compared; **{exact} byte-identical**, {} differ by at most 1 in a \
         channel, {} by at most 2, {beyond} by more. Identical pixels per state: min {}, p10 \
         {}, median {}.\n",
        errs.len(),
        results.len(),
        within(1),
        within(2) - within(1),
        ident.first().map_or("—".into(), |v| format!("{v:.2}%")),
        percentile(&ident, 10.0).map_or("—".into(), |v| format!("{v:.2}%")),
        median(&ident).map_or("—".into(), |v| format!("{v:.2}%")),
    );
    let threads_off: Vec<String> = results
        .iter()
        .flat_map(|r| {
            let mut v = Vec::new();
            if r.threads[0].is_some_and(|p| p < 100.0) {
                v.push(format!("{} (softgl)", r.index));
            }
            if r.threads[1].is_some_and(|p| p < 100.0) {
                v.push(format!("{} (llvmpipe)", r.index));
            }
            v
        })
        .collect();
    let _ = writeln!(
        s,
        "Threads against one thread: {}.\n",
        if threads_off.is_empty() {
            "identical on every state, softgl and llvmpipe".to_owned()
        } else {
            format!("differ on {}", threads_off.join(", "))
        }
    );
    let failed: Vec<&StateResult> = results.iter().filter(|r| !r.failures.is_empty()).collect();
    if !failed.is_empty() {
        let _ = writeln!(s, "Failures:\n");
        for r in failed {
            let _ = writeln!(s, "- state {}: {}", r.index, r.failures.join("; "));
        }
        let _ = writeln!(s);
    }
    let header =
        "| state | softgl-1 ms | llvmpipe-1 ms | softgl-1/lp-1 | softgl ms | llvmpipe ms | \
                  softgl/lp | identical % | px off | max diff | state in words |\n\
                  |---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
    let row = |r: &StateResult| -> String {
        let (i, off, md) = match &r.error {
            Ok(e) => (
                fmt_pct(e.identical_pct, e.pixels_off),
                e.pixels_off.to_string(),
                e.max_diff.to_string(),
            ),
            Err(e) => (e.clone(), "—".into(), "—".into()),
        };
        let f = |x: Option<f64>| x.map_or("—".into(), |x| format!("{x:.2}"));
        format!(
            "| {} | {} | {} | {} | {} | {} | {} | {i} | {off} | {md} | `{}` |\n",
            r.index,
            fmt_ms(r.ms[3]),
            fmt_ms(r.ms[1]),
            f(r.ratio1()),
            fmt_ms(r.ms[0]),
            fmt_ms(r.ms[2]),
            f(r.ratio_n()),
            r.state.replace('|', "/")
        )
    };
    let _ = writeln!(s, "### States that differ from llvmpipe\n");
    s.push_str(header);
    for r in results
        .iter()
        .filter(|r| !matches!(&r.error, Ok(e) if e.pixels_off == 0))
    {
        s.push_str(&row(r));
    }
    let _ = writeln!(s, "\n### The ten slowest states (softgl-1 / llvmpipe-1)\n");
    s.push_str(header);
    let mut by_ratio: Vec<&StateResult> = results.iter().filter(|r| r.ratio1().is_some()).collect();
    by_ratio.sort_by(|a, b| {
        b.ratio1()
            .unwrap_or(0.0)
            .total_cmp(&a.ratio1().unwrap_or(0.0))
    });
    for r in by_ratio.into_iter().take(10) {
        s.push_str(&row(r));
    }
    let mut full = s.clone();
    let _ = writeln!(full, "\n## Every state\n");
    full.push_str(header);
    for r in results {
        full.push_str(&row(r));
    }
    let _ = writeln!(
        s,
        "\nEvery state's row is in `target/bench/sweep.md` and `sweep.csv`; the frames of the \
         states that differ are in `target/bench/images/sweep-N.*.png`."
    );
    Report { summary: s, full }
}

fn csv(results: &[StateResult]) -> String {
    let mut c = String::from(
        "state,softgl_ms,llvmpipe1_ms,llvmpipe_ms,softgl1_ms,ratio_softgl1_llvmpipe1,\
         ratio_softgl_llvmpipe,identical_pct,pixels_off,max_diff,softgl_threads_identical_pct,\
         llvmpipe_threads_identical_pct,failures,description\n",
    );
    let o = |v: Option<f64>| v.map_or(String::new(), |v| format!("{v:.4}"));
    for r in results {
        let (i, off, md) = match &r.error {
            Ok(e) => (
                format!("{:.4}", e.identical_pct),
                e.pixels_off.to_string(),
                e.max_diff.to_string(),
            ),
            Err(_) => Default::default(),
        };
        let _ = writeln!(
            c,
            "{},{},{},{},{},{},{},{i},{off},{md},{},{},\"{}\",\"{}\"",
            r.index,
            o(r.ms[0]),
            o(r.ms[1]),
            o(r.ms[2]),
            o(r.ms[3]),
            o(r.ratio1()),
            o(r.ratio_n()),
            o(r.threads[0]),
            o(r.threads[1]),
            r.failures.join("; ").replace('"', "'"),
            r.state.replace('"', "'")
        );
    }
    c
}
