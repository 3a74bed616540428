//! Memory-bound loops (clears, the copy into the user buffer) split over the thread pool
//! in contiguous chunks. Each element is written by exactly one thread with the same value
//! as single-threaded, so results do not depend on the thread count.

use rayon::prelude::*;

/// Bytes below which a loop stays on the calling thread. Measured on the 2-core bench
/// machine (15:30 UTC run): with a 256 KiB threshold a 1024² glClear(COLOR|DEPTH) took
/// 0.686 ms on two threads against 0.576 ms on one (memset 0.30 ms), and 0.30 against
/// 0.12 ms at 512²: these loops are memory-bound and the hand-off only adds cost, so
/// they stay single-threaded for any frame up to 4096².
const MIN_PARALLEL_BYTES: usize = 128 * 1024 * 1024;

/// How many chunks a loop over `bytes` bytes is split into (1: run it here).
fn chunks(bytes: usize) -> usize {
    let t = crate::cpu::threads();
    if t <= 1 || bytes < MIN_PARALLEL_BYTES {
        1
    } else {
        t
    }
}

/// `s.fill(v)`, over threads when `s` is large.
pub fn fill<T: Copy + Send + Sync>(s: &mut [T], v: T) {
    for_each_chunk(s, |c| c.fill(v));
}

/// Calls `f` on contiguous chunks covering `s`, over threads when `s` is large.
pub fn for_each_chunk<T: Send, F: Fn(&mut [T]) + Sync + Send>(s: &mut [T], f: F) {
    let n = chunks(std::mem::size_of_val(s));
    if n == 1 {
        f(s);
    } else {
        // Chunks of whole 4 KiB pages so two threads never share a cache line.
        let per = (s.len().div_ceil(n) * std::mem::size_of::<T>()).next_multiple_of(4096)
            / std::mem::size_of::<T>().max(1);
        s.par_chunks_mut(per.max(1)).for_each(f);
    }
}

/// Calls `f(lo, hi)` on contiguous row ranges covering `0..rows` (rows of `row_bytes`
/// bytes each), over threads when the rows are large together.
pub fn row_ranges<F: Fn(usize, usize) + Sync>(rows: usize, row_bytes: usize, f: F) {
    let n = chunks(rows * row_bytes).min(rows.max(1));
    if n == 1 {
        f(0, rows);
    } else {
        let per = rows.div_ceil(n);
        (0..n).into_par_iter().for_each(|k| {
            let lo = k * per;
            let hi = (lo + per).min(rows);
            if lo < hi {
                f(lo, hi);
            }
        });
    }
}
