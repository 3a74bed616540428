//! The variant cache: compiled programs keyed by the state the lowering reads
//! ([`FfState`]: the fragment plan and the units' combiners, never GL enums), one cache
//! per thread, most recently used first.
//!
//! A triangle of the same state as the previous one finds its program at the front (one
//! comparison); a miss lowers and compiles in microseconds (`docs/engine.md`), so there
//! is no asynchronous compile and no first-draw fallback. States that do not lower are
//! cached too (as `None`), so refusing costs a look-up, not a lowering. The counters
//! (compiles, hits, time spent compiling) are process-wide and printed with
//! `SOFTGL_STATS=1` by [`report`].

use super::exec::{compile, Program};
use super::ff::{lower, FfState};
use std::cell::RefCell;
use std::rc::Rc;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};

/// Entries a thread's cache keeps (the least recently used goes first).
const CAPACITY: usize = 256;

/// Lowerings and compiles done (misses), by every thread.
static COMPILES: AtomicU64 = AtomicU64::new(0);
/// Look-ups that found their state (hits).
static HITS: AtomicU64 = AtomicU64::new(0);
/// Misses whose state did not lower.
static REFUSED: AtomicU64 = AtomicU64::new(0);
/// Nanoseconds spent lowering and compiling.
static COMPILE_NS: AtomicU64 = AtomicU64::new(0);

/// What a cached program was made from: a fixed-function state, or a registered
/// fragment shader's variant (its id, the lowering options that vary per draw, and the
/// fragment plan of the operations after it; uniform values are run inputs, not keys).
// Both variants are large values compared in place (one comparison per triangle on a
// hit); boxing one would cost an allocation per look-up.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Key {
    /// A fixed-function state ([`lower`]).
    Ff(FfState),
    /// A fragment shader's variant.
    Shader {
        /// The shader's registration id (`crate::shader::draw`).
        id: u64,
        /// The target height when rows are flipped (`gl_FragCoord.y`).
        flip: Option<u32>,
        /// The fragment plan (its own `shader` field cleared).
        plan: crate::fragment::FragPlan,
        /// The walk stores the colours (`super::draw::host_store`).
        host: bool,
    },
}

/// One cached state: its program, or `None` when it does not lower.
type Entry = (Key, Option<Rc<Program>>);

thread_local! {
    /// This thread's entries, most recently used first.
    static CACHE: RefCell<Vec<Entry>> = const { RefCell::new(Vec::new()) };
}

/// The program of `s`, compiled on a miss; `None` when `s` does not lower.
pub fn program(s: &FfState) -> Option<Rc<Program>> {
    program_of(&Key::Ff(*s), || lower(s))
}

/// The program of `s`, lowered by `build` and compiled on a miss; `None` when `build`
/// refuses.
pub fn program_of(s: &Key, build: impl FnOnce() -> Option<super::ir::Ir>) -> Option<Rc<Program>> {
    CACHE.with(|c| {
        let mut c = c.borrow_mut();
        if let Some(i) = c.iter().position(|(k, _)| k == s) {
            HITS.fetch_add(1, Relaxed);
            if i != 0 {
                let e = c.remove(i);
                c.insert(0, e);
            }
            return c[0].1.clone();
        }
        let start = std::time::Instant::now();
        let prog = build().map(|ir| Rc::new(compile(&ir)));
        COMPILE_NS.fetch_add(start.elapsed().as_nanos() as u64, Relaxed);
        COMPILES.fetch_add(1, Relaxed);
        if prog.is_none() {
            REFUSED.fetch_add(1, Relaxed);
        }
        c.truncate(CAPACITY - 1);
        c.insert(0, (*s, prog.clone()));
        prog
    })
}

/// The counters as one line for the `SOFTGL_STATS` report (`key=value` pairs, not the
/// `name: number` lines of the work counters).
pub fn report() -> String {
    format!(
        "softgl engine: compiles={} refused={} hits={} compile_us={}",
        COMPILES.load(Relaxed),
        REFUSED.load(Relaxed),
        HITS.load(Relaxed),
        COMPILE_NS.load(Relaxed) / 1000
    )
}
