//! Every `SOFTGL_*` environment variable the library reads, read once into one [`Tuning`]
//! that [`tuning`] returns. The knobs are switches for measurements and for running every
//! compiled path on any machine: none of them changes an image (except `SOFTGL_ISA` on a
//! machine where a level rounds differently, see `crate::cpu`).
//!
//! The table of every knob (name, default, effect, where it is used), and of the variables
//! only the tests and scripts read, is `docs/tuning.md`; a test below checks that the table
//! names exactly the knobs of [`Tuning`], and another that no other file of `src/` reads the
//! environment. `SOFTGL_STATS=1` prints the values in effect ([`Tuning::report`]) once,
//! before the first context's work counters.
//!
//! A leaf: it imports nothing from the crate. Values that need the rest of the library to
//! be understood are kept as given (`SOFTGL_ISA` is parsed by `crate::cpu::level`).

use std::ffi::OsString;
use std::sync::OnceLock;
use std::time::Duration;

/// [`Tuning::band_rows`]'s default: rows per band.
pub const BAND_ROWS: usize = 32;
/// [`Tuning::max_work`]'s default. Measured (17:57, quiet machine, 2 threads, 1024²): 1M px
/// → 32M px took blend_quads 29.5 → 20.6 ms, depth_back_to_front 12.2 → 9.5,
/// depth_front_to_back 5.0 → 3.5, sprites 32.9 → 29.5; small-triangle draws are bounded by
/// [`MAX_BATCH`] first and did not change.
pub const MAX_WORK: i64 = 1 << 25;
/// [`Tuning::detach_work`]'s default: a threaded batch's size (see its doc; measured in
/// docs/performance.md, stop 67).
pub const DETACH_WORK: i64 = 1 << 15;
/// [`Tuning::band_area`]'s default: at 1024x1024 the colour and depth buffers are 4 MB
/// each, twice the L2 cache, so a band's rows are kept in the cache while every big
/// triangle of a batch is drawn into them; smaller triangles are drawn at once.
pub const BAND_AREA: i64 = 4096;
/// [`Tuning::max_batch`]'s default: triangles a batch holds at most.
pub const MAX_BATCH: usize = 4096;
/// [`Tuning::pool_stay`]'s default, in microseconds.
pub const POOL_STAY_US: u64 = 2000;
/// [`Tuning::pool_spin`]'s default, in microseconds.
pub const POOL_SPIN_US: u64 = 500;
/// [`Tuning::pool_yield`]'s default, in microseconds.
pub const POOL_YIELD_US: u64 = 100;
/// [`Tuning::geom_section`]'s default: triangles per section.
pub const GEOM_SECTION: usize = 4096;
/// [`Tuning::split_probe`]'s default: triangles.
pub const SPLIT_PROBE: usize = 1024;
/// [`Tuning::prim_bands`]'s default: estimated fragments (measured in
/// docs/performance.md, stop 71).
pub const PRIM_BANDS: usize = 8192;

/// [`Tuning::offload`]'s default: triangles (measured in docs/performance.md, stop 70).
pub const OFFLOAD: usize = 256;
/// [`Tuning::ms_prefetch`]'s default: the rows below ([`MsPrefetch::Below`]).
pub const MS_PREFETCH: MsPrefetch = MsPrefetch::Below;
/// [`Tuning::engine`]'s default: the engine shades the general textured walk's triangles
/// where it was measured faster ([`Engine::Auto`]).
pub const ENGINE: Engine = Engine::Auto;
/// The smallest bounding box, in pixels, of a triangle [`Engine::Auto`] hands to the
/// engine: its stage executor pays each operation's call once per batch of up to 32 chunk
/// rows, which a triangle of a few rows does not fill (stop 55: the `fog` scene's 147k
/// small triangles took 1.3–1.5× longer through it).
pub const ENGINE_MIN_BOX: i64 = 1024;
/// Pixels per chunk of glBlitFramebuffer's multisample resolve on the thread pool
/// (`crate::pixels::resolve`): 64 Ki pixels read 1 MB of sample planes, enough to amortise
/// a task and small enough that 1080p splits into 32 chunks for two threads to share.
pub const RESOLVE_CHUNK: usize = 1 << 16;
/// The variable that caps the instruction set ([`Tuning::isa`]), for messages about it.
pub const ISA_VAR: &str = "SOFTGL_ISA";

/// Which texture path `SOFTGL_TEX_PATH` leaves on ([`Tuning::tex_path`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TexPath {
    /// The fast path with its register walk (unset, or any other value).
    Fast,
    /// `general`: the fast path off, every texture through the general path.
    General,
    /// `array`: the fast path without the register walk (`raster::textured::vec8`).
    Array,
}

impl TexPath {
    /// The value as `SOFTGL_TEX_PATH` spells it (`fast` for the default).
    pub fn name(self) -> &'static str {
        match self {
            TexPath::Fast => "fast",
            TexPath::General => "general",
            TexPath::Array => "array",
        }
    }
}

/// Which lines of the sample planes the one-pass multisample walk asks for ahead
/// (`SOFTGL_MS_PREFETCH`, [`Tuning::ms_prefetch`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MsPrefetch {
    /// `0`: none.
    Off,
    /// `1`: each chunk's columns two rows down (the next pair of rows).
    Below,
    /// `2`: the chunk 64 pixels further along the same rows.
    Ahead,
}

/// Which triangles of the general textured walk the engine shades (`SOFTGL_ENGINE`,
/// [`Tuning::engine`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Engine {
    /// `0`: none; the hand-written 8-lane walk shades them all.
    Off,
    /// `1`: every triangle whose state lowers.
    On,
    /// `2`: those where it is faster (`raster::textured::engine_takes`): no early depth or
    /// stencil test (the hand-written walk samples only the lanes that pass one), a
    /// combiner that walk interprets (two or more units, or one unit beyond a plain
    /// product), and a bounding box of at least [`ENGINE_MIN_BOX`] pixels.
    Auto,
}

/// Every knob the library reads, as read from the environment (once, by [`tuning`]).
/// A value that does not parse counts as unset unless its field says otherwise.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Tuning {
    /// `SOFTGL_ISA`: the highest instruction-set level to run (`scalar`, `fma`, `avx2`,
    /// `avx2fma`, `avx512`), as given; `None` (the default) when unset or empty: the CPU's
    /// best. Parsed, and an unknown name reported, by `crate::cpu::level`.
    pub isa: Option<String>,
    /// `SOFTGL_THREADS`: threads that rasterize large draws, at least 1 (1 turns threading
    /// off). Default: the machine's cores (`available_parallelism`); 0 counts as unset.
    pub threads: usize,
    /// `SOFTGL_REF_CPU_CAPS`: for the test harnesses only (`crate::cpu::reference_cpu_caps`),
    /// the `GALLIUM_OVERRIDE_CPU_CAPS` the reference llvmpipe runs with, as given (empty for
    /// none). Default `None`: unset, the harness picks from the level.
    pub ref_cpu_caps: Option<String>,
    /// `SOFTGL_BAND_ROWS`: rows per band of threaded and cache-banded drawing, even (2x2
    /// quads stay inside one band), clamped to 2..=4096 and rounded down to even.
    /// Default [`BAND_ROWS`] (32) rows.
    pub band_rows: usize,
    /// `SOFTGL_MAX_WORK`: threaded, pixels of triangle boxes after which a batch is handed
    /// to the pool, at least 1. Default [`MAX_WORK`] (2^25) pixels.
    pub max_work: i64,
    /// `SOFTGL_DETACH_WORK`: threaded, pixels of triangle boxes from which the batch a
    /// glBegin/glEnd draw ends with is handed to the pool when the draw returns (the next
    /// draw sets up its triangles meanwhile and takes it back); a smaller one is kept for
    /// the next draw's triangles to join, and handed over once the joined batch holds as
    /// many. At least 1. Default [`DETACH_WORK`] pixels.
    pub detach_work: i64,
    /// `SOFTGL_BAND_AREA`: single-threaded, the box size in pixels from which triangles are
    /// batched and drawn band by band, at least 0. Default [`BAND_AREA`] (4096) pixels.
    pub band_area: i64,
    /// `SOFTGL_MAX_BATCH`: triangles a batch holds at most, clamped to 1..=2^20.
    /// Default [`MAX_BATCH`] (4096) triangles.
    pub max_batch: usize,
    /// `SOFTGL_POOL_HELP`: whether the draw's thread draws bands of the batch in flight
    /// while it waits for it (and the pool leaves it a core). Default on; a value that
    /// parses as the integer 0 turns it off.
    pub pool_help: bool,
    /// `SOFTGL_PAIR`: whether two triangles that make an axis-aligned rectangle with
    /// bit-identical planes are drawn as one (`raster::batch::pair`). Default on; a value
    /// that parses as the integer 0 turns it off.
    pub pair: bool,
    /// `SOFTGL_POOL_STAY_US`: how long a pool task polls for the draw thread's next batch
    /// after drawing one, given in microseconds, clamped to 0..=1 s (0: return at once).
    /// Default [`POOL_STAY_US`] (2000 µs).
    pub pool_stay: Duration,
    /// `SOFTGL_POOL_SPIN_US`: how long the draw thread polls for the batch in flight
    /// before it sleeps, given in microseconds, clamped to 0..=1 s. Default
    /// [`POOL_SPIN_US`] (500 µs).
    pub pool_spin: Duration,
    /// `SOFTGL_POOL_YIELD_US`: after polling this long (a pool task for the next batch, the
    /// draw thread for the batch in flight), a thread gives its core away between checks
    /// (`sched_yield`), so that on a busy machine the polling costs others little CPU; on an
    /// idle one the call returns at once. Given in microseconds, clamped to 0..=1 s (0:
    /// from the start). Default [`POOL_YIELD_US`] (100 µs).
    pub pool_yield: Duration,
    /// `SOFTGL_POOL_START`: whether a draw that will hand work to the pool starts a pool
    /// thread before it sets up its first triangles. Default on; exactly `0` turns it off.
    pub pool_start: bool,
    /// `SOFTGL_NARROW`: whether the AVX2 row walk shades triangles less than 4 pixels wide
    /// as 4x2 blocks. Default on; exactly `0` turns it off.
    pub narrow: bool,
    /// `SOFTGL_MS_PREFETCH`: which sample-plane lines the one-pass multisample walk
    /// prefetches: `0` none, `1` two rows down, `2` 64 pixels ahead; other values count
    /// as unset. Default [`MS_PREFETCH`].
    pub ms_prefetch: MsPrefetch,
    /// `SOFTGL_GEOM_SECTION`: triangles per section of a draw whose set-up is split over
    /// two threads, at most 2^20 (0 turns the split off). Default [`GEOM_SECTION`] (4096)
    /// triangles.
    pub geom_section: usize,
    /// `SOFTGL_SPLIT_PROBE`: triangles a draw that may be split sets up the ordinary way
    /// first, to measure their boxes (used at most a section, at least 1). Default
    /// [`SPLIT_PROBE`] (1024) triangles.
    pub split_probe: usize,
    /// `SOFTGL_OFFLOAD`: the fewest triangles of a streamed GL_TRIANGLES or GL_QUADS draw
    /// whose second half an idle pool thread sets up while the draw's thread sets up the
    /// first (`raster::batch::side`); 0 turns the offload off. Default [`OFFLOAD`].
    pub offload: usize,
    /// `SOFTGL_PRIM_BANDS`: the estimated fragments from which a draw of lines or points
    /// is drawn on two bands of rows by two threads (`raster::banded`); 0 turns it off.
    /// Default [`PRIM_BANDS`].
    pub prim_bands: usize,
    /// `SOFTGL_OFFLOAD_WAIT`: whether an offloading draw always hands its half to a pool
    /// thread (starting one when none polls) and waits for it, rather than setting the
    /// half up itself when the pool thread has not begun it: the pool's path on any
    /// machine and load, for tests. Default off; any value but `0` turns it on.
    pub offload_wait: bool,
    /// `SOFTGL_SETUP8`: whether the colour-only triangles of a streamed draw are set up
    /// eight at a time in AVX2 lanes. Default on; exactly `0` turns it off.
    pub setup8: bool,
    /// `SOFTGL_TEX_PATH`: which texture paths are on (`general`, `array`). Default
    /// [`TexPath::Fast`]: all of them.
    pub tex_path: TexPath,
    /// `SOFTGL_ENGINE`: which triangles of the general textured walk shade through the
    /// engine (`crate::engine::draw`) when the draw's state lowers: `0` none, `1` all,
    /// `2` where it is faster. Default [`ENGINE`].
    pub engine: Engine,
    /// `SOFTGL_ALPHA_EARLY`: whether the general textured walk runs an alpha test that
    /// reads no texel before sampling (`fragment::simd_gen::alpha_early`), while it kills
    /// enough fragments. Default on; exactly `0` turns it off.
    pub alpha_early: bool,
    /// `SOFTGL_DEPTH_FIRST`: whether the general textured walk tests depth, read-only,
    /// before sampling when an alpha test that reads texels comes first
    /// (`fragment::simd_gen::depth_first`). Default on; exactly `0` turns it off.
    pub depth_first: bool,
    /// `SOFTGL_STATS`: whether a context prints its work counters when it is destroyed
    /// (the first one also prints [`Tuning::report`]). Default off; any value but `0`
    /// turns it on.
    pub stats: bool,
}

impl Tuning {
    /// The knobs from the process environment.
    pub fn from_env() -> Tuning {
        Tuning::from_lookup(|k| std::env::var_os(k))
    }

    /// The knobs from `get`, which returns a variable's value (`None` when unset).
    pub fn from_lookup(get: impl Fn(&str) -> Option<OsString>) -> Tuning {
        // A value that is not Unicode counts as unset, as `std::env::var` makes it.
        let text = |k: &str| get(k).and_then(|v| v.into_string().ok());
        let int = |k: &str| text(k).and_then(|v| v.parse::<i64>().ok());
        let size = |k: &str| text(k).and_then(|v| v.parse::<usize>().ok());
        let not_zero = |k: &str| text(k).as_deref() != Some("0");
        let micros = |k: &str, d: u64| {
            Duration::from_micros(int(k).map_or(d, |v| v.clamp(0, 1_000_000) as u64))
        };
        Tuning {
            isa: text(ISA_VAR).filter(|v| !v.is_empty()),
            threads: size("SOFTGL_THREADS")
                .filter(|&n| n >= 1)
                .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get())),
            ref_cpu_caps: text("SOFTGL_REF_CPU_CAPS"),
            band_rows: int("SOFTGL_BAND_ROWS")
                .map_or(BAND_ROWS, |v| (v.clamp(2, 4096) as usize) & !1),
            max_work: int("SOFTGL_MAX_WORK").map_or(MAX_WORK, |v| v.max(1)),
            detach_work: int("SOFTGL_DETACH_WORK").map_or(DETACH_WORK, |v| v.max(1)),
            band_area: int("SOFTGL_BAND_AREA").map_or(BAND_AREA, |v| v.max(0)),
            max_batch: int("SOFTGL_MAX_BATCH").map_or(MAX_BATCH, |v| v.clamp(1, 1 << 20) as usize),
            pool_help: int("SOFTGL_POOL_HELP") != Some(0),
            pair: int("SOFTGL_PAIR") != Some(0),
            pool_stay: micros("SOFTGL_POOL_STAY_US", POOL_STAY_US),
            pool_spin: micros("SOFTGL_POOL_SPIN_US", POOL_SPIN_US),
            pool_yield: micros("SOFTGL_POOL_YIELD_US", POOL_YIELD_US),
            pool_start: not_zero("SOFTGL_POOL_START"),
            narrow: not_zero("SOFTGL_NARROW"),
            ms_prefetch: match int("SOFTGL_MS_PREFETCH") {
                Some(0) => MsPrefetch::Off,
                Some(1) => MsPrefetch::Below,
                Some(2) => MsPrefetch::Ahead,
                _ => MS_PREFETCH,
            },
            geom_section: size("SOFTGL_GEOM_SECTION").map_or(GEOM_SECTION, |v| v.min(1 << 20)),
            split_probe: size("SOFTGL_SPLIT_PROBE").unwrap_or(SPLIT_PROBE),
            offload: size("SOFTGL_OFFLOAD").unwrap_or(OFFLOAD),
            prim_bands: size("SOFTGL_PRIM_BANDS").unwrap_or(PRIM_BANDS),
            offload_wait: get("SOFTGL_OFFLOAD_WAIT").is_some_and(|v| v != "0"),
            setup8: not_zero("SOFTGL_SETUP8"),
            tex_path: match text("SOFTGL_TEX_PATH").as_deref() {
                Some("general") => TexPath::General,
                Some("array") => TexPath::Array,
                _ => TexPath::Fast,
            },
            engine: match int("SOFTGL_ENGINE") {
                Some(0) => Engine::Off,
                Some(1) => Engine::On,
                Some(2) => Engine::Auto,
                _ => ENGINE,
            },
            alpha_early: not_zero("SOFTGL_ALPHA_EARLY"),
            depth_first: not_zero("SOFTGL_DEPTH_FIRST"),
            stats: get("SOFTGL_STATS").is_some_and(|v| v != "0"),
        }
    }

    /// Every knob's name and value in effect, in the order of the fields (the list the
    /// report prints and the documentation table is checked against).
    pub fn knobs(&self) -> Vec<(&'static str, String)> {
        // Destructured without `..`, so a new field does not compile until it is listed.
        let Tuning {
            isa,
            threads,
            ref_cpu_caps,
            band_rows,
            max_work,
            detach_work,
            band_area,
            max_batch,
            pool_help,
            pair,
            pool_stay,
            pool_spin,
            pool_yield,
            pool_start,
            narrow,
            ms_prefetch,
            geom_section,
            split_probe,
            offload,
            prim_bands,
            offload_wait,
            setup8,
            tex_path,
            engine,
            alpha_early,
            depth_first,
            stats,
        } = self;
        let given = |v: &Option<String>| {
            v.as_ref()
                .map_or("(unset)".to_string(), |s| format!("{s:?}"))
        };
        let on = |b: &bool| if *b { "1" } else { "0" }.to_string();
        vec![
            ("SOFTGL_ISA", given(isa)),
            ("SOFTGL_THREADS", threads.to_string()),
            ("SOFTGL_REF_CPU_CAPS", given(ref_cpu_caps)),
            ("SOFTGL_BAND_ROWS", band_rows.to_string()),
            ("SOFTGL_MAX_WORK", max_work.to_string()),
            ("SOFTGL_DETACH_WORK", detach_work.to_string()),
            ("SOFTGL_BAND_AREA", band_area.to_string()),
            ("SOFTGL_MAX_BATCH", max_batch.to_string()),
            ("SOFTGL_POOL_HELP", on(pool_help)),
            ("SOFTGL_PAIR", on(pair)),
            ("SOFTGL_POOL_STAY_US", pool_stay.as_micros().to_string()),
            ("SOFTGL_POOL_SPIN_US", pool_spin.as_micros().to_string()),
            ("SOFTGL_POOL_YIELD_US", pool_yield.as_micros().to_string()),
            ("SOFTGL_POOL_START", on(pool_start)),
            ("SOFTGL_NARROW", on(narrow)),
            ("SOFTGL_MS_PREFETCH", (*ms_prefetch as u8).to_string()),
            ("SOFTGL_GEOM_SECTION", geom_section.to_string()),
            ("SOFTGL_SPLIT_PROBE", split_probe.to_string()),
            ("SOFTGL_OFFLOAD", offload.to_string()),
            ("SOFTGL_PRIM_BANDS", prim_bands.to_string()),
            ("SOFTGL_OFFLOAD_WAIT", on(offload_wait)),
            ("SOFTGL_SETUP8", on(setup8)),
            ("SOFTGL_TEX_PATH", tex_path.name().to_string()),
            ("SOFTGL_ENGINE", (*engine as u8).to_string()),
            ("SOFTGL_ALPHA_EARLY", on(alpha_early)),
            ("SOFTGL_DEPTH_FIRST", on(depth_first)),
            ("SOFTGL_STATS", on(stats)),
        ]
    }

    /// The values in effect, one `NAME=value` line each (no `name: number` lines, which
    /// harnesses read as work counters from the same stderr).
    pub fn report(&self) -> String {
        self.knobs()
            .into_iter()
            .map(|(k, v)| format!("    {k}={v}\n"))
            .collect()
    }
}

/// The knobs in effect, read from the environment on the first call.
#[inline]
pub fn tuning() -> &'static Tuning {
    static T: OnceLock<Tuning> = OnceLock::new();
    T.get_or_init(Tuning::from_env)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeSet;
    use std::path::{Path, PathBuf};

    fn root() -> PathBuf {
        PathBuf::from(env!("CARGO_MANIFEST_DIR"))
    }

    /// The tuning made from `vars` alone.
    fn with(vars: &[(&str, &str)]) -> Tuning {
        Tuning::from_lookup(|k| vars.iter().find(|(n, _)| *n == k).map(|(_, v)| v.into()))
    }

    /// Every `SOFTGL_…` name in `text`.
    fn names_in(text: &str) -> BTreeSet<String> {
        let mut out = BTreeSet::new();
        let mut rest = text;
        while let Some(i) = rest.find("SOFTGL_") {
            let tail = &rest[i..];
            let end = tail
                .find(|c: char| !(c.is_ascii_uppercase() || c.is_ascii_digit() || c == '_'))
                .unwrap_or(tail.len());
            // (`SOFTGL_*`, the family, names no variable.)
            if end > "SOFTGL_".len() {
                out.insert(tail[..end].to_string());
            }
            rest = &tail[end..];
        }
        out
    }

    /// The knob names in the first column of the table under the `## ` heading `section`
    /// of `docs/tuning.md`.
    fn doc_table(section: &str) -> Vec<String> {
        let doc = std::fs::read_to_string(root().join("docs/tuning.md")).expect("docs/tuning.md");
        let mut inside = false;
        let mut names = Vec::new();
        for line in doc.lines() {
            if let Some(h) = line.strip_prefix("## ") {
                inside = h.trim() == section;
            } else if inside && line.starts_with('|') {
                let cell = line
                    .split('|')
                    .nth(1)
                    .unwrap_or("")
                    .trim()
                    .trim_matches('`');
                if cell.starts_with("SOFTGL_") {
                    names.push(cell.to_string());
                }
            }
        }
        assert!(
            !names.is_empty(),
            "no table under `## {section}` in docs/tuning.md"
        );
        names
    }

    /// The files under `dir` (recursively), skipping build output.
    fn files(dir: &Path, out: &mut Vec<PathBuf>) {
        let Ok(entries) = std::fs::read_dir(dir) else {
            return;
        };
        for e in entries.flatten() {
            let p = e.path();
            if p.is_dir() {
                if p.file_name().is_some_and(|n| n != "target" && n != ".git") {
                    files(&p, out);
                }
            } else {
                out.push(p);
            }
        }
    }

    #[test]
    fn defaults_when_nothing_is_set() {
        let t = with(&[]);
        assert_eq!(t.isa, None);
        assert!(t.threads >= 1);
        assert_eq!(t.ref_cpu_caps, None);
        assert_eq!(
            (t.band_rows, t.max_work, t.band_area, t.max_batch),
            (32, 1 << 25, 4096, 4096)
        );
        assert_eq!(
            (t.pool_stay.as_micros(), t.pool_spin.as_micros()),
            (2000, 500)
        );
        assert_eq!(t.pool_yield.as_micros(), 100);
        assert_eq!((t.geom_section, t.split_probe), (4096, 1024));
        assert_eq!((t.offload, t.offload_wait), (256, false));
        assert!(t.pool_help && t.pair && t.pool_start && t.narrow && t.setup8);
        assert_eq!(t.tex_path, TexPath::Fast);
        assert!(!t.stats);
    }

    #[test]
    fn values_are_parsed_and_clamped_as_before() {
        let t = with(&[
            ("SOFTGL_ISA", "avx2"),
            ("SOFTGL_THREADS", "3"),
            ("SOFTGL_REF_CPU_CAPS", ""),
            ("SOFTGL_BAND_ROWS", "7"),
            ("SOFTGL_MAX_WORK", "-5"),
            ("SOFTGL_BAND_AREA", "-1"),
            ("SOFTGL_MAX_BATCH", "99999999"),
            ("SOFTGL_POOL_HELP", "00"),
            ("SOFTGL_PAIR", "0"),
            ("SOFTGL_POOL_STAY_US", "5000000"),
            ("SOFTGL_POOL_SPIN_US", "-3"),
            ("SOFTGL_POOL_YIELD_US", "7"),
            ("SOFTGL_POOL_START", "00"),
            ("SOFTGL_NARROW", "0"),
            ("SOFTGL_GEOM_SECTION", "0"),
            ("SOFTGL_SPLIT_PROBE", "x"),
            ("SOFTGL_SETUP8", "1"),
            ("SOFTGL_TEX_PATH", "general"),
            ("SOFTGL_STATS", ""),
        ]);
        assert_eq!(t.isa.as_deref(), Some("avx2"));
        assert_eq!(t.threads, 3);
        assert_eq!(t.ref_cpu_caps.as_deref(), Some(""));
        assert_eq!(
            (t.band_rows, t.max_work, t.band_area, t.max_batch),
            (6, 1, 0, 1 << 20)
        );
        // POOL_HELP and PAIR compare the parsed integer, POOL_START, NARROW and SETUP8 the text.
        assert!(!t.pool_help && !t.pair && t.pool_start && !t.narrow && t.setup8);
        assert_eq!(
            (t.pool_stay.as_micros(), t.pool_spin.as_micros()),
            (1_000_000, 0)
        );
        assert_eq!(t.pool_yield.as_micros(), 7);
        assert_eq!((t.geom_section, t.split_probe), (0, 1024));
        assert_eq!(t.tex_path, TexPath::General);
        assert!(t.stats, "an empty SOFTGL_STATS counts as on");
        let t = with(&[
            ("SOFTGL_THREADS", "0"),
            ("SOFTGL_BAND_ROWS", "1"),
            ("SOFTGL_ISA", ""),
        ]);
        assert!(t.threads >= 1 && t.isa.is_none());
        assert_eq!(t.band_rows, 2);
        assert_eq!(
            with(&[("SOFTGL_TEX_PATH", "array")]).tex_path,
            TexPath::Array
        );
        assert_eq!(
            with(&[("SOFTGL_TEX_PATH", "other")]).tex_path,
            TexPath::Fast
        );
        assert!(!with(&[("SOFTGL_STATS", "0")]).stats);
    }

    #[test]
    fn report_has_one_line_per_knob_and_no_counter_lines() {
        let t = with(&[("SOFTGL_BAND_ROWS", "64")]);
        let r = t.report();
        assert_eq!(r.lines().count(), t.knobs().len());
        assert!(r.contains("SOFTGL_BAND_ROWS=64\n"));
        // Harnesses read `name: number` lines of the same stderr as work counters.
        assert!(r.lines().all(|l| !l.contains(": ")), "{r}");
    }

    #[test]
    fn docs_table_names_exactly_the_knobs() {
        let knobs: Vec<String> = with(&[])
            .knobs()
            .into_iter()
            .map(|(k, _)| k.to_string())
            .collect();
        let mut documented = doc_table("Library knobs");
        let mut sorted = knobs.clone();
        sorted.sort();
        documented.sort();
        assert_eq!(
            documented, sorted,
            "docs/tuning.md's library table against Tuning::knobs"
        );
        // The names the report prints are the names read.
        let asked = std::cell::RefCell::new(BTreeSet::new());
        Tuning::from_lookup(|k| {
            asked.borrow_mut().insert(k.to_string());
            None
        });
        assert_eq!(
            asked.into_inner(),
            knobs.into_iter().collect(),
            "the names from_lookup reads"
        );
    }

    #[test]
    fn every_other_softgl_variable_is_in_the_test_table() {
        let library: BTreeSet<String> = doc_table("Library knobs").into_iter().collect();
        let others: BTreeSet<String> = doc_table("Test and script variables").into_iter().collect();
        assert!(
            library.is_disjoint(&others),
            "{:?}",
            library.intersection(&others)
        );
        let mut paths = Vec::new();
        for d in ["tests", "scripts", "examples", "bench", "c_tests", "tools"] {
            files(&root().join(d), &mut paths);
        }
        paths.push(root().join("README.md"));
        let mut missing = BTreeSet::new();
        for p in paths {
            let Ok(text) = std::fs::read_to_string(&p) else {
                continue;
            };
            for n in names_in(&text) {
                if !library.contains(&n) && !others.contains(&n) {
                    missing.insert(format!("{n} ({})", p.display()));
                }
            }
        }
        assert!(missing.is_empty(), "not in docs/tuning.md: {missing:?}");
    }

    #[test]
    fn no_other_library_file_reads_the_environment() {
        let mut paths = Vec::new();
        files(&root().join("src"), &mut paths);
        let this = root().join("src/tuning.rs");
        let mut found = Vec::new();
        for p in paths
            .iter()
            .filter(|p| p.extension().is_some_and(|e| e == "rs") && **p != this)
        {
            let text = std::fs::read_to_string(p).expect("source");
            for (i, line) in text.lines().enumerate() {
                // Comments may name a knob; code may not read one (nor any variable).
                let code = line.split("//").next().unwrap_or("");
                if code.contains("SOFTGL_") || code.contains("env::var") {
                    found.push(format!("{}:{}: {}", p.display(), i + 1, line.trim()));
                }
            }
        }
        assert!(paths.len() > 20, "src/ not found");
        assert!(
            found.is_empty(),
            "read the knob through crate::tuning instead:\n{}",
            found.join("\n")
        );
    }
}
