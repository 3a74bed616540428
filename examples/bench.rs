//! The softgl benchmark runner: frame time and error against Mesa's llvmpipe in one run.
//!
//! Run by hand with `bash scripts/bench.sh` (never as a test). It compiles every C scene in
//! `bench/scenes/` twice (against `libsoftgl.so` and against `-lOSMesa`), then runs the
//! four renderers in alternation — softgl (default threads), llvmpipe with
//! `LP_NUM_THREADS=1`, llvmpipe with its default thread count, softgl with
//! `SOFTGL_THREADS=1` — for several repetitions at each size. Each scene times its own
//! frames; the runner takes the median frame time of each run and the median over the runs,
//! compares softgl's final frame with llvmpipe's, and measures whole-process wall time and
//! peak memory (`wait4` rusage) of one-frame runs. It writes `target/bench/results.md`,
//! `results.csv`, `process.csv`, `clear_memset.csv` and `time_vs_error.png`. See
//! `bench/README.md`.
//!
//! With `--filter-study` it runs the filter study instead (`bench/runner/filter_study.rs`):
//! the ground plane of `bench/scenes/filter_study.c` with every minification filter and
//! anisotropy level, timed the same way and judged against the analytic ground truth.
//!
//! With `--sweep N` it runs the state sweep instead (`bench/runner/sweep.rs`): N seeded
//! random GL 1.x states of `bench/scenes/sweep.c`, each timed on softgl and llvmpipe and
//! compared with llvmpipe's image.

#[path = "../bench/runner/chart.rs"]
mod chart;
#[path = "../bench/runner/filter_study.rs"]
mod filter_study;
#[path = "../bench/runner/ground_truth.rs"]
mod ground_truth;
#[path = "../bench/runner/sweep.rs"]
mod sweep;

use std::collections::BTreeSet;
use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::mpsc;
use std::time::{Duration, Instant};

/// Scenes in the order and with the short ids of the benchmark issue; other `.c` files in
/// `bench/scenes/` are appended after them.
const KNOWN_SCENES: &[(&str, &str)] = &[
    ("big_triangles", "a"),
    ("blend_quads", "b"),
    ("small_tris_200k", "c"),
    ("tex_bilinear", "d"),
    ("tex_trilinear_plane", "e"),
    ("depth_front_to_back", "f1"),
    ("depth_back_to_front", "f2"),
    ("sprites_10k", "g"),
    ("immediate_100k", "h"),
    ("clear_only", "i"),
    ("fbo_msaa_shadow", "j"),
    // One scene per feature group of issue 42's table.
    ("tex3d_cube_texgen", "k"),
    ("multitex_combine", "l"),
    ("shadow_texgen", "m"),
    ("wrap_env_formats", "n"),
    ("lights8", "o"),
    ("stencil_ops", "p"),
    ("pushattrib_pixels", "q"),
    ("buffer_ushort", "r1"),
    ("buffer_float", "r2"),
    ("fog", "s"),
    ("query_accum_feedback", "t"),
    ("polygon_modes_offset", "u"),
    ("alpha_lines_points", "v"),
];

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Renderer {
    Softgl,
    Lp1,
    LpN,
    /// softgl with `SOFTGL_THREADS=1` (the single-thread comparison with llvmpipe-1).
    Softgl1,
}

/// Indices 0..3 are fixed: softgl (default threads), llvmpipe-1, llvmpipe, softgl-1.
const RENDERERS: [Renderer; 4] = [
    Renderer::Softgl,
    Renderer::Lp1,
    Renderer::LpN,
    Renderer::Softgl1,
];

impl Renderer {
    fn label(self) -> &'static str {
        match self {
            Renderer::Softgl => "softgl",
            Renderer::Lp1 => "llvmpipe-1",
            Renderer::LpN => "llvmpipe",
            Renderer::Softgl1 => "softgl-1",
        }
    }
}

/// One-frame runs per scene and renderer unless `--wall-reps` says otherwise (or `--reps`
/// asks for more): a one-frame process's wall time spreads by a third from run to run on
/// this kind of machine, and medians of 9 runs moved the softgl/llvmpipe ratio of a scene
/// by 0.07 between two runs minutes apart (blend_quads 0.23 and 0.16).
const WALL_REPS: usize = 25;

struct Config {
    filter_study: bool,
    /// `--sweep N`: run the state sweep over N states instead of the scenes.
    sweep: Option<usize>,
    /// `--sweep-seed S` (default 1).
    sweep_seed: u32,
    /// Whether reps, frames and sizes were given (the sweep has its own defaults).
    reps_given: bool,
    frames_given: bool,
    sizes_given: bool,
    reps: usize,
    frames: usize,
    sizes: Vec<u32>,
    scenes: Option<Vec<String>>,
    timeout: Duration,
    wall_reps: usize,
    wall_size: u32,
}

impl Config {
    fn from_env_and_args() -> Result<Config, String> {
        let env = |k: &str| std::env::var(k).ok().filter(|v| !v.is_empty());
        let mut reps = env("BENCH_REPS").unwrap_or_else(|| "9".into());
        let mut frames = env("BENCH_FRAMES").unwrap_or_else(|| "10".into());
        let mut sizes = env("BENCH_SIZES").unwrap_or_else(|| "512,1024".into());
        let mut scenes = env("BENCH_SCENES");
        let mut timeout = env("BENCH_TIMEOUT").unwrap_or_else(|| "120".into());
        let mut wall_reps = env("BENCH_WALL_REPS");
        let mut wall_size = env("BENCH_WALL_SIZE").unwrap_or_else(|| "512".into());
        let mut filter_study = false;
        let mut sweep = None;
        let mut sweep_seed = env("BENCH_SWEEP_SEED").unwrap_or_else(|| "1".into());
        let given =
            |var: &str, flag: &str| env(var).is_some() || std::env::args().any(|a| a == flag);
        let (reps_given, frames_given, sizes_given) = (
            given("BENCH_REPS", "--reps"),
            given("BENCH_FRAMES", "--frames"),
            given("BENCH_SIZES", "--sizes"),
        );
        let mut args = std::env::args().skip(1);
        while let Some(a) = args.next() {
            let slot = match a.as_str() {
                "--filter-study" => {
                    filter_study = true;
                    continue;
                }
                "--sweep" => {
                    sweep = args.next();
                    if sweep.is_none() {
                        return Err("--sweep needs a number of states".into());
                    }
                    continue;
                }
                "--sweep-seed" => &mut sweep_seed,
                "--reps" => &mut reps,
                "--frames" => &mut frames,
                "--sizes" => &mut sizes,
                "--timeout" => &mut timeout,
                "--wall-size" => &mut wall_size,
                "--scenes" => {
                    scenes = args.next();
                    continue;
                }
                "--wall-reps" => {
                    wall_reps = args.next();
                    continue;
                }
                "-h" | "--help" => {
                    return Err("usage: bench [--reps N] [--frames N] [--sizes 512,1024] \
                         [--scenes a,b] [--timeout S] [--wall-reps N] [--wall-size N] \
                         [--filter-study] [--sweep N [--sweep-seed S]]\n\
                         (or the env vars BENCH_REPS, BENCH_FRAMES, BENCH_SIZES, \
                         BENCH_SCENES, BENCH_TIMEOUT, BENCH_WALL_REPS, BENCH_WALL_SIZE, \
                         BENCH_SWEEP_SEED)"
                        .into())
                }
                other => return Err(format!("unknown argument {other:?} (try --help)")),
            };
            *slot = args.next().ok_or_else(|| format!("{a} needs a value"))?;
        }
        let num = |name: &str, s: &str| -> Result<usize, String> {
            s.trim()
                .parse::<usize>()
                .map_err(|_| format!("{name}: not a number: {s:?}"))
        };
        let reps = num("reps", &reps)?.max(1);
        Ok(Config {
            filter_study,
            sweep: sweep.map(|s| num("sweep", &s)).transpose()?,
            sweep_seed: sweep_seed
                .trim()
                .parse()
                .map_err(|_| format!("sweep-seed: not a number: {sweep_seed:?}"))?,
            reps_given,
            frames_given,
            sizes_given,
            reps,
            frames: num("frames", &frames)?.max(1),
            sizes: sizes
                .split(',')
                .map(|s| num("sizes", s).map(|v| v as u32))
                .collect::<Result<_, _>>()?,
            scenes: scenes.map(|s| s.split(',').map(|x| x.trim().to_owned()).collect()),
            timeout: Duration::from_secs(num("timeout", &timeout)? as u64),
            wall_reps: match wall_reps {
                Some(s) => num("wall-reps", &s)?.max(1),
                None => reps.max(WALL_REPS),
            },
            wall_size: num("wall-size", &wall_size)? as u32,
        })
    }
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn out_dir() -> PathBuf {
    root().join("target").join("bench")
}

/// One benchmark scene found in `bench/scenes/`.
struct Scene {
    name: String,
    id: String,
    /// The "PENDING FEATURE: ..." note from the scene's header comment, if any.
    pending: Option<String>,
    /// One-line description: the first line of the header comment.
    about: String,
    softgl_bin: Result<PathBuf, String>,
    osmesa_bin: Result<PathBuf, String>,
}

fn find_scenes(filter: &Option<Vec<String>>) -> Result<Vec<Scene>, String> {
    let dir = root().join("bench").join("scenes");
    let mut names: Vec<String> = fs::read_dir(&dir)
        .map_err(|e| format!("{}: {e}", dir.display()))?
        .filter_map(|e| e.ok())
        .filter_map(|e| {
            let p = e.path();
            if p.extension()? != "c" {
                return None;
            }
            Some(p.file_stem()?.to_string_lossy().into_owned())
        })
        // The filter study's and the sweep's scenes are run only by --filter-study and
        // --sweep.
        .filter(|n| n != filter_study::SCENE && n != sweep::SCENE)
        .collect();
    names.sort_by_key(|n| {
        KNOWN_SCENES
            .iter()
            .position(|(k, _)| k == n)
            .unwrap_or(usize::MAX)
    });
    let mut extra = 0u8;
    let mut scenes = Vec::new();
    for name in names {
        let id = match KNOWN_SCENES.iter().find(|(k, _)| *k == name) {
            Some((_, id)) => (*id).to_owned(),
            None => {
                extra += 1;
                format!("x{extra}")
            }
        };
        if let Some(f) = filter {
            if !f.iter().any(|s| *s == name || *s == id) {
                continue;
            }
        }
        let src = fs::read_to_string(dir.join(format!("{name}.c"))).unwrap_or_default();
        let pending = src.lines().find_map(|l| {
            let rest = l.split("PENDING FEATURE:").nth(1)?;
            let feat = rest.split(['.', '(']).next().unwrap_or(rest).trim();
            Some(feat.to_owned())
        });
        let about = src
            .lines()
            .find_map(|l| l.split_once(&format!("{name}.c - ")).map(|x| x.1))
            .map(|s| {
                // Drop the "(a) " id prefix of the header line: the id has its own column.
                let s = s.trim().trim_end_matches('.');
                match s.split_once(") ") {
                    Some((id, rest)) if id.starts_with('(') && id.len() <= 4 => rest.to_owned(),
                    _ => s.to_owned(),
                }
            })
            .unwrap_or_default();
        scenes.push(Scene {
            name,
            id,
            pending,
            about,
            softgl_bin: Err("not built".into()),
            osmesa_bin: Err("not built".into()),
        });
    }
    Ok(scenes)
}

/// Compiles one scene for one side; on failure returns a short reason for the table.
fn build(scene: &str, softgl: bool) -> Result<PathBuf, String> {
    let side = if softgl { "softgl" } else { "osmesa" };
    let bin_dir = out_dir().join("bin").join(side);
    fs::create_dir_all(&bin_dir).map_err(|e| format!("mkdir: {e}"))?;
    let bin = bin_dir.join(scene);
    let _ = fs::remove_file(&bin);
    let src = root()
        .join("bench")
        .join("scenes")
        .join(format!("{scene}.c"));
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".into());
    let mut cmd = Command::new(&cc);
    cmd.current_dir(root()).args(["-O2", "-Wall"]);
    if softgl {
        let lib = root().join("target").join("release");
        if root().join("include/GL/gl.h").exists() {
            cmd.arg(format!("-I{}", root().join("include").display()));
        }
        cmd.arg(&src)
            .arg("-o")
            .arg(&bin)
            .arg(format!("-L{}", lib.display()))
            .arg("-lsoftgl")
            .arg(format!("-Wl,-rpath,{}", lib.display()))
            .arg("-lm");
    } else {
        cmd.arg("-DSGL_REFERENCE_OSMESA=1")
            .arg(&src)
            .arg("-o")
            .arg(&bin)
            .args(["-lOSMesa", "-lm"]);
    }
    let out = cmd.output().map_err(|e| format!("cannot run {cc}: {e}"))?;
    if out.status.success() {
        return Ok(bin);
    }
    let err = String::from_utf8_lossy(&out.stderr);
    fs::write(bin_dir.join(format!("{scene}.log")), err.as_bytes()).ok();
    Err(explain_build_failure(&err))
}

/// Turns compiler/linker output into "missing symbol glFoo, glBar" or the first error line.
fn explain_build_failure(stderr: &str) -> String {
    let between = |line: &str, open: char, close: char| -> Option<String> {
        let start = line.find(open)? + open.len_utf8();
        let len = line[start..].find(close)?;
        Some(line[start..start + len].to_owned())
    };
    let mut symbols = BTreeSet::new();
    let mut undeclared = BTreeSet::new();
    for line in stderr.lines() {
        if line.contains("undefined reference to") {
            let rest = line.split("undefined reference to").nth(1).unwrap_or("");
            let name = between(rest, '`', '\'').or_else(|| between(rest, '‘', '’'));
            symbols.extend(name);
        } else if line.contains("undeclared") {
            let name = between(line, '‘', '’').or_else(|| between(line, '\'', '\''));
            undeclared.extend(name);
        }
    }
    if !symbols.is_empty() {
        let list: Vec<_> = symbols.into_iter().collect();
        return format!("missing symbol {}", list.join(", "));
    }
    if !undeclared.is_empty() {
        let list: Vec<_> = undeclared.into_iter().collect();
        return format!("missing in header: {}", list.join(", "));
    }
    let first = stderr
        .lines()
        .find(|l| l.contains("error"))
        .unwrap_or("build failed");
    format!("build failed: {}", first.trim())
}

/// What one run of a scene program produced.
struct RunOutcome {
    frame_ms: Vec<f64>,
    memset_ms: Vec<f64>,
    wall: Duration,
    max_rss_kb: i64,
}

/// Runs a scene binary with extra environment variables `env`; `Err` carries a short
/// reason (crash, exit code, timeout).
fn run_scene(
    bin: &Path,
    renderer: Renderer,
    output: &Path,
    size: u32,
    frames: usize,
    timeout: Duration,
    env: &[(&str, &str)],
) -> Result<RunOutcome, String> {
    let log_dir = out_dir().join("logs");
    fs::create_dir_all(&log_dir).map_err(|e| format!("mkdir: {e}"))?;
    let stem = output
        .file_name()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let stdout_path = log_dir.join(format!("{stem}.stdout"));
    let stderr_path = log_dir.join(format!("{stem}.stderr"));
    let _ = fs::remove_file(output);
    let mut cmd = Command::new(bin);
    cmd.arg(output)
        .arg(size.to_string())
        .arg(size.to_string())
        .arg(frames.to_string())
        .stdin(Stdio::null())
        .stdout(fs::File::create(&stdout_path).map_err(|e| format!("log: {e}"))?)
        .stderr(fs::File::create(&stderr_path).map_err(|e| format!("log: {e}"))?)
        .env_remove("LP_NUM_THREADS")
        .envs(env.iter().copied());
    match renderer {
        Renderer::Softgl => {
            cmd.env_remove("SOFTGL_THREADS");
        }
        Renderer::Softgl1 => {
            cmd.env("SOFTGL_THREADS", "1");
        }
        Renderer::Lp1 => {
            cmd.env("GALLIUM_DRIVER", "llvmpipe")
                .env("LP_NUM_THREADS", "1");
        }
        Renderer::LpN => {
            cmd.env("GALLIUM_DRIVER", "llvmpipe");
        }
    }
    let start = Instant::now();
    let child = cmd
        .spawn()
        .map_err(|e| format!("cannot start {}: {e}", bin.display()))?;
    let pid = child.id() as libc::pid_t;
    // The child is reaped by wait4 below (for its rusage), not by `Child::wait`.
    drop(child);
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let mut status = 0;
        // SAFETY: an all-zero rusage is a valid value of this plain C struct.
        let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
        // SAFETY: pid is our own unreaped child; both pointers are valid for the call.
        let r = unsafe { libc::wait4(pid, &mut status, 0, &mut usage) };
        let _ = tx.send((r, status, usage, Instant::now()));
    });
    let (r, status, usage, end) = match rx.recv_timeout(timeout) {
        Ok(v) => v,
        Err(_) => {
            // SAFETY: pid is our child, not yet reaped (the waiter thread is still blocked).
            unsafe { libc::kill(pid, libc::SIGKILL) };
            let _ = rx.recv();
            return Err(format!("timeout after {} s", timeout.as_secs()));
        }
    };
    if r != pid {
        return Err(format!("wait4 failed: {}", std::io::Error::last_os_error()));
    }
    let stdout = fs::read_to_string(&stdout_path).unwrap_or_default();
    if libc::WIFSIGNALED(status) {
        let sig = libc::WTERMSIG(status);
        let name = match sig {
            libc::SIGSEGV => " SIGSEGV",
            libc::SIGABRT => " SIGABRT",
            libc::SIGBUS => " SIGBUS",
            libc::SIGILL => " SIGILL",
            libc::SIGFPE => " SIGFPE",
            _ => "",
        };
        return Err(format!("crashed (signal {sig}{name})"));
    }
    let code = libc::WEXITSTATUS(status);
    if code != 0 {
        let err = fs::read_to_string(&stderr_path).unwrap_or_default();
        let last = err
            .lines()
            .rev()
            .find(|l| !l.trim().is_empty())
            .unwrap_or("");
        return Err(format!("exit {code}: {}", last.trim()));
    }
    let values = |key: &str| -> Vec<f64> {
        stdout
            .lines()
            .filter_map(|l| l.strip_prefix(key)?.trim().parse().ok())
            .collect()
    };
    Ok(RunOutcome {
        frame_ms: values("frame_ms "),
        memset_ms: values("memset_ms "),
        wall: end - start,
        max_rss_kb: usage.ru_maxrss,
    })
}

/// An RGBA image read back from a scene's output file.
struct Frame {
    width: u32,
    height: u32,
    rgba: Vec<u8>,
}

fn read_frame(path: &Path) -> Result<Frame, String> {
    let data = fs::read(path).map_err(|e| format!("no output: {e}"))?;
    let nl = data
        .iter()
        .position(|&b| b == b'\n')
        .ok_or("output has no header")?;
    let header = String::from_utf8_lossy(&data[..nl]);
    let f: Vec<&str> = header.split_whitespace().collect();
    if f.len() < 8 || f[0] != "SGLIMG" || f[4] != "4" || f[5] != "RGBA" {
        return Err(format!("unexpected output header {header:?}"));
    }
    let width: u32 = f[2].parse().map_err(|_| "bad width")?;
    let height: u32 = f[3].parse().map_err(|_| "bad height")?;
    let n = width as usize * height as usize * 4;
    let body = data.get(nl + 1..nl + 1 + n).ok_or("output truncated")?;
    Ok(Frame {
        width,
        height,
        rgba: body.to_vec(),
    })
}

/// Error of `ours` against `reference`, over all four channels.
#[derive(Clone, Copy)]
struct ErrorStats {
    identical_pct: f64,
    pixels_off: usize,
    max_diff: u8,
    psnr_db: f64,
}

fn compare(ours: &Frame, reference: &Frame) -> Result<ErrorStats, String> {
    if (ours.width, ours.height) != (reference.width, reference.height) {
        return Err(format!(
            "output size {}x{}, expected {}x{}",
            ours.width, ours.height, reference.width, reference.height
        ));
    }
    let mut identical = 0usize;
    let mut max_diff = 0u8;
    let mut sq = 0f64;
    for (a, b) in ours
        .rgba
        .chunks_exact(4)
        .zip(reference.rgba.chunks_exact(4))
    {
        if a == b {
            identical += 1;
            continue;
        }
        for (x, y) in a.iter().zip(b) {
            let d = x.abs_diff(*y);
            max_diff = max_diff.max(d);
            sq += (d as f64) * (d as f64);
        }
    }
    let pixels = (ours.width as usize * ours.height as usize).max(1);
    let mse = sq / (pixels * 4) as f64;
    Ok(ErrorStats {
        identical_pct: 100.0 * identical as f64 / pixels as f64,
        pixels_off: pixels - identical,
        max_diff,
        psnr_db: if mse == 0.0 {
            f64::INFINITY
        } else {
            10.0 * (255.0f64 * 255.0 / mse).log10()
        },
    })
}

fn save_png(frame: &Frame, path: &Path) {
    let Some(img) = image::RgbaImage::from_raw(frame.width, frame.height, frame.rgba.clone())
    else {
        return;
    };
    // The buffer is bottom row first (OSMESA_Y_UP).
    let _ = image::imageops::flip_vertical(&img).save(path);
}

fn median(v: &[f64]) -> Option<f64> {
    let mut s: Vec<f64> = v.iter().copied().filter(|x| x.is_finite()).collect();
    if s.is_empty() {
        return None;
    }
    s.sort_by(|a, b| a.total_cmp(b));
    let n = s.len();
    Some(if n % 2 == 1 {
        s[n / 2]
    } else {
        (s[n / 2 - 1] + s[n / 2]) / 2.0
    })
}

/// Everything measured for one (scene, size).
struct Cell {
    scene: usize,
    size: u32,
    /// Per renderer: the median frame time of each successful run.
    run_medians: [Vec<f64>; 4],
    /// Per renderer: median memset time of each run (clear_only only).
    memset_medians: [Vec<f64>; 4],
    /// Per renderer: the first failure, if any run failed.
    failure: [Option<String>; 4],
    /// Per renderer: the output file of the last successful run.
    output: [Option<PathBuf>; 4],
}

/// One-frame process runs of one scene on one renderer.
#[derive(Default)]
struct ProcessStats {
    wall_ms: Vec<f64>,
    rss_mib: Vec<f64>,
    failure: Option<String>,
}

struct Summary {
    ms: [Option<f64>; 4],
    ours: Result<ErrorStats, String>,
    lpn: Option<ErrorStats>,
}

fn summarize(cell: &Cell, scenes: &[Scene]) -> Summary {
    let ms = [0, 1, 2, 3].map(|i| median(&cell.run_medians[i]));
    let frames = [0, 1, 2].map(|i| cell.output[i].as_deref().map(read_frame));
    let ours = match (&frames[0], &frames[1]) {
        (Some(Ok(a)), Some(Ok(b))) => compare(a, b),
        (Some(Err(e)), _) => Err(e.clone()),
        (None, _) => Err(cell.failure[0]
            .clone()
            .unwrap_or_else(|| "no output".into())),
        (_, Some(Err(e))) => Err(format!("reference: {e}")),
        (_, None) => Err("reference failed".into()),
    };
    let lpn = match (&frames[2], &frames[1]) {
        (Some(Ok(a)), Some(Ok(b))) => compare(a, b).ok(),
        _ => None,
    };
    let img_dir = out_dir().join("images");
    let _ = fs::create_dir_all(&img_dir);
    let name = &scenes[cell.scene].name;
    for (i, r) in RENDERERS.iter().enumerate().take(2) {
        if let Some(Ok(f)) = &frames[i] {
            save_png(
                f,
                &img_dir.join(format!("{name}-{}.{}.png", cell.size, r.label())),
            );
        }
    }
    Summary { ms, ours, lpn }
}

fn fmt_ms(v: Option<f64>) -> String {
    match v {
        Some(v) if v >= 100.0 => format!("{v:.0}"),
        Some(v) if v >= 10.0 => format!("{v:.1}"),
        Some(v) => format!("{v:.2}"),
        None => "—".into(),
    }
}

fn fmt_ratio(a: Option<f64>, b: Option<f64>) -> String {
    match (a, b) {
        (Some(a), Some(b)) if b > 0.0 => format!("{:.2}", a / b),
        _ => "—".into(),
    }
}

/// A percentage of identical pixels that never rounds up to "100.00" when pixels differ.
fn fmt_pct(pct: f64, off: usize) -> String {
    let s = format!("{pct:.2}");
    if off > 0 && s == "100.00" {
        "99.99+".into()
    } else {
        s
    }
}

fn fmt_psnr(p: f64) -> String {
    if p.is_infinite() {
        "inf".into()
    } else {
        format!("{p:.1}")
    }
}

fn ratio(a: Option<f64>, b: Option<f64>) -> Option<f64> {
    match (a, b) {
        (Some(a), Some(b)) if b > 0.0 => Some(a / b),
        _ => None,
    }
}

fn csv_opt(v: Option<f64>) -> String {
    v.map_or(String::new(), |v| format!("{v:.4}"))
}

fn main() {
    if let Err(e) = real_main() {
        eprintln!("bench: {e}");
        std::process::exit(1);
    }
}

fn real_main() -> Result<(), String> {
    let cfg = Config::from_env_and_args()?;
    let lib = root().join("target/release/libsoftgl.so");
    if !lib.exists() {
        return Err(format!(
            "{} is missing: run `cargo build --release` (scripts/bench.sh does)",
            lib.display()
        ));
    }
    let out = out_dir();
    fs::create_dir_all(out.join("runs")).map_err(|e| format!("mkdir: {e}"))?;
    if cfg.filter_study {
        return filter_study::run(&cfg);
    }
    if let Some(states) = cfg.sweep {
        return sweep::run(&cfg, states);
    }
    let mut scenes = find_scenes(&cfg.scenes)?;
    if scenes.is_empty() {
        return Err("no scenes selected".into());
    }

    eprintln!(
        "bench: compiling {} scenes against softgl and OSMesa",
        scenes.len()
    );
    for s in &mut scenes {
        s.softgl_bin = build(&s.name, true);
        s.osmesa_bin = build(&s.name, false);
        for (side, r) in [("softgl", &s.softgl_bin), ("osmesa", &s.osmesa_bin)] {
            if let Err(e) = r {
                eprintln!("  {} ({side}): {e}", s.name);
            }
        }
    }

    // Timing: reps outermost, so slow drifts of the machine hit all renderers alike;
    // within a (scene, size) the renderers run back to back: A B C A B C ...
    let mut cells: Vec<Cell> = Vec::new();
    for (si, _) in scenes.iter().enumerate() {
        for &size in &cfg.sizes {
            cells.push(Cell {
                scene: si,
                size,
                run_medians: Default::default(),
                memset_medians: Default::default(),
                failure: Default::default(),
                output: Default::default(),
            });
        }
    }
    let started = Instant::now();
    for rep in 0..cfg.reps {
        eprintln!(
            "bench: repetition {}/{} ({:.0} s so far)",
            rep + 1,
            cfg.reps,
            started.elapsed().as_secs_f64()
        );
        for cell in &mut cells {
            let scene = &scenes[cell.scene];
            for (ri, &r) in RENDERERS.iter().enumerate() {
                let bin = match r {
                    Renderer::Softgl | Renderer::Softgl1 => &scene.softgl_bin,
                    _ => &scene.osmesa_bin,
                };
                let bin = match bin {
                    Ok(b) => b,
                    Err(e) => {
                        cell.failure[ri].get_or_insert_with(|| e.clone());
                        continue;
                    }
                };
                // A renderer that crashed or timed out once is not run again.
                if cell.failure[ri].is_some() {
                    continue;
                }
                let output = out.join("runs").join(format!(
                    "{}-{}.{}.out",
                    scene.name,
                    cell.size,
                    r.label()
                ));
                match run_scene(bin, r, &output, cell.size, cfg.frames, cfg.timeout, &[]) {
                    Ok(o) => {
                        if let Some(m) = median(&o.frame_ms) {
                            cell.run_medians[ri].push(m);
                        } else {
                            cell.failure[ri].get_or_insert("printed no frame times".into());
                        }
                        if let Some(m) = median(&o.memset_ms) {
                            cell.memset_medians[ri].push(m);
                        }
                        cell.output[ri] = Some(output);
                    }
                    Err(e) => {
                        eprintln!("  {} {} {}: {e}", scene.name, cell.size, r.label());
                        cell.failure[ri].get_or_insert(e);
                        cell.output[ri] = None;
                    }
                }
            }
        }
    }

    // Whole-process cost of a one-frame run (frames = 0: only the warm-up frame),
    // softgl and llvmpipe (default threads) alternating.
    eprintln!("bench: one-frame process runs ({} each)", cfg.wall_reps);
    let mut process: Vec<[ProcessStats; 2]> = scenes.iter().map(|_| Default::default()).collect();
    for _ in 0..cfg.wall_reps {
        for (si, scene) in scenes.iter().enumerate() {
            for (k, (r, bin)) in [
                (Renderer::Softgl, &scene.softgl_bin),
                (Renderer::LpN, &scene.osmesa_bin),
            ]
            .into_iter()
            .enumerate()
            {
                let slot = &mut process[si][k];
                let bin = match bin {
                    Ok(b) => b,
                    Err(e) => {
                        slot.failure.get_or_insert_with(|| e.clone());
                        continue;
                    }
                };
                if slot.failure.is_some() {
                    continue;
                }
                let output =
                    out.join("runs")
                        .join(format!("{}-oneframe.{}.out", scene.name, r.label()));
                match run_scene(bin, r, &output, cfg.wall_size, 0, cfg.timeout, &[]) {
                    Ok(o) => {
                        slot.wall_ms.push(o.wall.as_secs_f64() * 1e3);
                        slot.rss_mib.push(o.max_rss_kb as f64 / 1024.0);
                    }
                    Err(e) => slot.failure = Some(e),
                }
            }
        }
    }

    // ---- Report -------------------------------------------------------------------
    let summaries: Vec<Summary> = cells.iter().map(|c| summarize(c, &scenes)).collect();
    let mut md = String::new();
    let machine = machine_line();
    let _ = writeln!(md, "# softgl benchmark\n");
    let _ = writeln!(
        md,
        "{machine}. {} repetitions × {} timed frames (after one warm-up frame) per renderer, \
         run in alternation (softgl default threads, llvmpipe 1 thread, llvmpipe default \
         threads, softgl-1 = softgl with SOFTGL_THREADS=1). Single-thread against single-thread: \
         softgl-1/lp-1; default against default: softgl/lp. Times are the median over repetitions of each run's median frame time \
         (draw + glFinish), in ms. Ratios < 1 mean softgl is faster. Error columns compare \
         softgl's last frame with llvmpipe (1 thread) over all RGBA channels.\n",
        cfg.reps, cfg.frames
    );
    let _ = writeln!(
        md,
        "| id | scene | size | softgl-1 ms | llvmpipe-1 ms | softgl-1/lp-1 | softgl ms | \
         llvmpipe ms | softgl/lp | identical % | px off | max diff | PSNR dB | note |"
    );
    let _ = writeln!(
        md,
        "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|"
    );
    let mut csv = String::from(
        "scene,id,width,height,softgl_ms,llvmpipe1_ms,llvmpipe_ms,ratio_softgl_llvmpipe1,\
         ratio_softgl_llvmpipe,identical_pct,pixels_off,max_diff,psnr_db,llvmpipe_vs_llvmpipe1_identical_pct,\
         softgl_runs,llvmpipe1_runs,llvmpipe_runs,status,pending_feature,softgl1_ms,\
         ratio_softgl1_llvmpipe1,softgl1_runs\n",
    );
    for (cell, sum) in cells.iter().zip(&summaries) {
        let scene = &scenes[cell.scene];
        let mut notes: Vec<String> = Vec::new();
        if let Some(p) = &scene.pending {
            notes.push(format!("pending feature: {p}"));
        }
        for (ri, r) in RENDERERS.iter().enumerate() {
            if let Some(f) = &cell.failure[ri] {
                let who = if ri == 0 {
                    String::new()
                } else {
                    format!("{}: ", r.label())
                };
                let n = format!("{who}{f}");
                if !notes.contains(&n) {
                    notes.push(n);
                }
            }
        }
        if let Err(e) = &sum.ours {
            let n = e.to_string();
            if !notes.iter().any(|x| x.ends_with(&n)) {
                notes.push(n);
            }
        }
        if let Some(l) = &sum.lpn {
            if l.identical_pct < 100.0 {
                notes.push(format!(
                    "llvmpipe threads vs 1 thread: {:.2}% identical",
                    l.identical_pct
                ));
            }
        }
        let (ident, off, maxd, psnr) = match &sum.ours {
            Ok(e) => (
                fmt_pct(e.identical_pct, e.pixels_off),
                e.pixels_off.to_string(),
                e.max_diff.to_string(),
                fmt_psnr(e.psnr_db),
            ),
            Err(_) => ("—".into(), "—".into(), "—".into(), "—".into()),
        };
        let _ = writeln!(
            md,
            "| {} | {} | {}² | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            scene.id,
            scene.name,
            cell.size,
            fmt_ms(sum.ms[3]),
            fmt_ms(sum.ms[1]),
            fmt_ratio(sum.ms[3], sum.ms[1]),
            fmt_ms(sum.ms[0]),
            fmt_ms(sum.ms[2]),
            fmt_ratio(sum.ms[0], sum.ms[2]),
            ident,
            off,
            maxd,
            psnr,
            notes.join("; ").replace('|', "/")
        );
        let status = if cell.failure[0].is_some() && sum.ms[0].is_none() {
            "softgl failed"
        } else if sum.ours.is_err() {
            "no comparison"
        } else {
            "ok"
        };
        let _ = writeln!(
            csv,
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},\"{}\",\"{}\",{},{},{}",
            scene.name,
            scene.id,
            cell.size,
            cell.size,
            csv_opt(sum.ms[0]),
            csv_opt(sum.ms[1]),
            csv_opt(sum.ms[2]),
            csv_opt(ratio(sum.ms[0], sum.ms[1])),
            csv_opt(ratio(sum.ms[0], sum.ms[2])),
            sum.ours
                .as_ref()
                .map_or(String::new(), |e| format!("{:.4}", e.identical_pct)),
            sum.ours
                .as_ref()
                .map_or(String::new(), |e| e.pixels_off.to_string()),
            sum.ours
                .as_ref()
                .map_or(String::new(), |e| e.max_diff.to_string()),
            sum.ours.as_ref().map_or(String::new(), |e| {
                if e.psnr_db.is_infinite() {
                    "inf".into()
                } else {
                    format!("{:.3}", e.psnr_db)
                }
            }),
            sum.lpn
                .as_ref()
                .map_or(String::new(), |e| format!("{:.4}", e.identical_pct)),
            cell.run_medians[0].len(),
            cell.run_medians[1].len(),
            cell.run_medians[2].len(),
            status,
            scene.pending.clone().unwrap_or_default(),
            csv_opt(sum.ms[3]),
            csv_opt(ratio(sum.ms[3], sum.ms[1])),
            cell.run_medians[3].len(),
        );
    }

    // glClear against memset in the same process.
    let mut clear_csv =
        String::from("width,height,renderer,glclear_ms,memset_ms,ratio_glclear_memset\n");
    let clear_cells: Vec<&Cell> = cells
        .iter()
        .filter(|c| scenes[c.scene].name == "clear_only")
        .collect();
    if !clear_cells.is_empty() {
        let _ = writeln!(
            md,
            "\n## glClear against memset\n\nclear_only: glClear(COLOR|DEPTH) + glFinish per \
             frame, against memset over w×h×8 bytes (RGBA + 32-bit depth) timed in the same \
             process; medians as above.\n"
        );
        let _ = writeln!(
            md,
            "| size | renderer | glClear ms | memset ms | glClear/memset |"
        );
        let _ = writeln!(md, "|---|---|---:|---:|---:|");
        for c in clear_cells {
            for (ri, r) in RENDERERS.iter().enumerate() {
                let g = median(&c.run_medians[ri]);
                let m = median(&c.memset_medians[ri]);
                let _ = writeln!(
                    md,
                    "| {}² | {} | {} | {} | {} |",
                    c.size,
                    r.label(),
                    fmt_ms3(g),
                    fmt_ms3(m),
                    fmt_ratio(g, m)
                );
                let _ = writeln!(
                    clear_csv,
                    "{},{},{},{},{},{}",
                    c.size,
                    c.size,
                    r.label(),
                    csv_opt(g),
                    csv_opt(m),
                    csv_opt(ratio(g, m))
                );
            }
        }
    }

    // Whole-process table.
    let _ = writeln!(
        md,
        "\n## One-frame process: wall time and peak memory\n\n\
         Each scene run once per repetition with 0 timed frames (context, setup, one frame, \
         output file, exit) at {0}x{0}, {1} times each, softgl and llvmpipe (default threads) \
         alternating; medians. Wall time is spawn to exit as seen by the runner; peak memory is \
         the child's max RSS from wait4. llvmpipe's times include LLVM shader compilation \
         (Mesa's on-disk shader cache is warm after the first run).\n",
        cfg.wall_size, cfg.wall_reps
    );
    let _ = writeln!(
        md,
        "| id | scene | softgl ms | llvmpipe ms | time ratio | softgl MiB | llvmpipe MiB | \
         memory ratio | note |"
    );
    let _ = writeln!(md, "|---|---|---:|---:|---:|---:|---:|---:|---|");
    let mut proc_csv = String::from(
        "scene,id,size,softgl_wall_ms,llvmpipe_wall_ms,ratio_wall,softgl_maxrss_mib,\
         llvmpipe_maxrss_mib,ratio_maxrss,note\n",
    );
    for (scene, p) in scenes.iter().zip(&process) {
        let (sw, lw) = (median(&p[0].wall_ms), median(&p[1].wall_ms));
        let (sm, lm) = (median(&p[0].rss_mib), median(&p[1].rss_mib));
        let mut note = Vec::new();
        if let Some(e) = &p[0].failure {
            note.push(e.clone());
        }
        if let Some(e) = &p[1].failure {
            note.push(format!("llvmpipe: {e}"));
        }
        let note = note.join("; ").replace('|', "/");
        let mib = |v: Option<f64>| v.map_or("—".into(), |v| format!("{v:.1}"));
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            scene.id,
            scene.name,
            fmt_ms(sw),
            fmt_ms(lw),
            fmt_ratio(sw, lw),
            mib(sm),
            mib(lm),
            fmt_ratio(sm, lm),
            note
        );
        let _ = writeln!(
            proc_csv,
            "{},{},{},{},{},{},{},{},{},\"{}\"",
            scene.name,
            scene.id,
            cfg.wall_size,
            csv_opt(sw),
            csv_opt(lw),
            csv_opt(ratio(sw, lw)),
            csv_opt(sm),
            csv_opt(lm),
            csv_opt(ratio(sm, lm)),
            note
        );
    }

    let _ = writeln!(md, "\n## Scenes\n");
    for s in &scenes {
        let pending = s
            .pending
            .as_ref()
            .map_or(String::new(), |p| format!(" — pending feature: {p}"));
        let _ = writeln!(md, "- **{}** `{}`: {}{}", s.id, s.name, s.about, pending);
    }
    let _ = writeln!(
        md,
        "\nTotal benchmark time {:.0} s. Images of the last frames: `target/bench/images/`.",
        started.elapsed().as_secs_f64()
    );

    // Chart.
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
    ];
    let max_size = cfg.sizes.iter().copied().max().unwrap_or(0);
    let mut points = Vec::new();
    for (cell, sum) in cells.iter().zip(&summaries) {
        let scene = &scenes[cell.scene];
        let errors = [
            sum.ours.as_ref().ok().map(|e| 100.0 - e.identical_pct),
            sum.ms[1].map(|_| 0.0),
            sum.lpn.map(|e| 100.0 - e.identical_pct),
        ];
        for (ri, err) in errors.into_iter().enumerate() {
            if let (Some(ms), Some(err)) = (sum.ms[ri], err) {
                points.push(chart::Point {
                    ms,
                    error_pct: err,
                    series: ri,
                    hollow: cfg.sizes.len() > 1 && cell.size == max_size,
                    label: format!("{}/{}", scene.id, cell.size),
                });
            }
        }
    }
    let legend: Vec<String> = scenes
        .iter()
        .map(|s| {
            let p = if s.pending.is_some() { " *" } else { "" };
            format!("{:<3} {}{p}", s.id, s.name)
        })
        .chain(
            scenes
                .iter()
                .any(|s| s.pending.is_some())
                .then(|| "* pending feature".to_owned()),
        )
        .collect();
    let img = chart::draw(
        "softgl vs llvmpipe: frame time against error",
        &series,
        &points,
        &legend,
    );
    let png = out.join("time_vs_error.png");
    img.save(&png)
        .map_err(|e| format!("writing {}: {e}", png.display()))?;

    let write = |name: &str, text: &str| -> Result<(), String> {
        let p = out.join(name);
        fs::write(&p, text).map_err(|e| format!("writing {}: {e}", p.display()))
    };
    write("results.md", &md)?;
    write("results.csv", &csv)?;
    write("process.csv", &proc_csv)?;
    write("clear_memset.csv", &clear_csv)?;
    println!("{md}");
    eprintln!(
        "bench: wrote target/bench/results.md, results.csv, process.csv, clear_memset.csv, \
         time_vs_error.png"
    );
    Ok(())
}

fn fmt_ms3(v: Option<f64>) -> String {
    v.map_or("—".into(), |v| format!("{v:.3}"))
}

/// "CPU model, N cores, Mesa version" for the report header.
fn machine_line() -> String {
    let cpu = fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|s| s.trim().to_owned())
        })
        .unwrap_or_else(|| "unknown CPU".into());
    let cores = std::thread::available_parallelism().map_or(0, |n| n.get());
    let mesa = Command::new("dpkg-query")
        .args(["-W", "-f=${Version}", "libosmesa6"])
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map(|o| String::from_utf8_lossy(&o.stdout).into_owned())
        .unwrap_or_else(|| "unknown".into());
    format!("{cpu}, {cores} cores, libosmesa6 {mesa}")
}
