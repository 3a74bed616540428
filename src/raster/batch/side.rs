//! The offload: a draw of independent triangles hands the set-up of its second half to an
//! idle pool thread.
//!
//! Many programs draw scenes of a few hundred to a few thousand triangles per draw: MuJoCo
//! replays a display list of GL_QUADS per body, six times a frame (reflection, scene, and
//! per light a shadow-map pass and a lit pass). Setting such a draw up (vertex stage, clip
//! test, triangle setup) costs more than rasterizing it, above all in the depth-only
//! shadow passes, so with the ordinary pipeline the pool thread polls for work while the
//! draw's thread sets up. The geometry split ([`super::split`]) shares the set-up of draws
//! of more than 8192 triangles, but it draws every pending batch first and its own before
//! it returns, which costs more than it saves on a draw of a few hundred.
//!
//! Here a streamed draw of at least `SOFTGL_OFFLOAD` triangles (GL_TRIANGLES or GL_QUADS:
//! the halves share no primitive), started while nothing is in flight and a pool task
//! polls for its next task ([`super::job::Job::try_post`]), posts the set-up of its second
//! half to that task, which bins it into a batch of its own ([`Binner`]). Meanwhile the
//! draw's thread sets up the first half into its rasterizer, keeping its full batches
//! (`Rasterizer::hold`): handing one to the pool would wait for the pool's half, and
//! MuJoCo's lit floor spent an eighth of its draw that way. If the pool is still setting
//! up when the draw's thread is done with its half, the draw's thread draws its batch's
//! bands meanwhile (they come first in primitive order) and hands the bands left to the
//! pool once the pool's half is done (`Rasterizer::draw_while_busy`); it idled through
//! an eighth of each lit floor draw waiting there (humanoid s0, 7 alternating runs:
//! 37.01 → 35.02 ms). Then it appends the
//! second half's triangles after its own ([`Rasterizer::append`]), so the rasterizer sees
//! every triangle in primitive order and the images are those of one thread. If the pool
//! task has not begun the half by then, the draw's thread sets it up itself (unless
//! `SOFTGL_OFFLOAD_WAIT`, for tests, has it start a pool task and wait), straight
//! into its rasterizer with its own cache, as if nothing had been offloaded. Until the
//! pool is free, a draw sets up `geometry::reject::CHUNK` (64) primitives at a time and
//! looks again, so a draw that starts while the pool draws the batch of the draw before
//! offloads half of what is left once that batch is drawn.
//!
//! The counters are those of one thread except `vertices` (a vertex of both halves is
//! transformed on both threads), `tris_paired` (the halves of a rectangle cut between
//! the two halves are drawn as two triangles) and `draws_offloaded`, which counts the
//! halves a pool thread set up.

use super::job::{SideFn, Task};
use super::split::Binner;
use super::{Batch, Head, Rasterizer};
use crate::stats::Stats;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Mutex;

/// Waits for the job when dropped during a panic: the side task borrows the stack.
struct WaitOnUnwind<'j>(&'j super::Job);

impl Drop for WaitOnUnwind<'_> {
    fn drop(&mut self) {
        if std::thread::panicking() {
            self.0.wait_done(crate::tuning::tuning().pool_spin);
        }
    }
}

/// Posts `f` as a side task to `job`'s pool task: to one that polls for work, or, with
/// `start`, to a new one when none polls. Returns whether it was posted.
///
/// # Safety
/// When it was posted, `f` must stay alive until `job` reports the task done
/// ([`super::Job::wait_done`], or a later `Job::hand_over`, which waits for it first).
unsafe fn post_side(job: &std::sync::Arc<super::Job>, f: &(dyn Fn() + Sync), start: bool) -> bool {
    // SAFETY: only the lifetime is erased; the caller keeps `f` alive as said above.
    let f: *const (dyn Fn() + Sync + 'static) = unsafe { std::mem::transmute(f) };
    let task = Task::Side(SideFn(f));
    if start {
        job.hand_over(task, 1, crate::tuning::tuning().pool_stay);
        true
    } else {
        job.try_post(task).is_ok()
    }
}

impl Rasterizer<'_, '_> {
    /// Whether a draw of `tris` triangles may offload part of its set-up at all: threads
    /// are on and it has at least `SOFTGL_OFFLOAD` triangles.
    pub fn may_offload(&self, tris: usize) -> bool {
        let min = self.tune.offload;
        min > 0 && tris >= min && self.threads
    }

    /// Whether a draw of `tris` triangles may offload its second half now: threads are
    /// on, it has at least `SOFTGL_OFFLOAD` triangles and the pool has nothing to draw (a
    /// batch the draw before left in flight and the pool has drawn is taken back).
    pub fn can_offload(&mut self, tris: usize, stats: &mut Stats) -> bool {
        if !self.may_offload(tris) || self.job.busy.load(Ordering::Acquire) {
            return false;
        }
        // A batch left in flight by the draw before and drawn by now is taken back.
        self.wait(stats);
        true
    }

    /// Runs `main(self, stats, false)` (the first half's set-up into this rasterizer) on
    /// this thread while a polling pool task runs `side` (the second half's set-up into a
    /// batch of its own), then appends the second half after the first. When no pool
    /// task polls, or it has not begun by the time the first half is set up, this thread
    /// sets the second half up itself, into this rasterizer: `main(self, stats, true)`.
    pub fn offload<G, M>(&mut self, stats: &mut Stats, side: G, mut main: M)
    where
        G: Fn(&mut Binner, &mut Stats) + Sync,
        M: FnMut(&mut Self, &mut Stats, bool),
    {
        let mut batch = self.ring.pop().unwrap_or_default();
        batch.clear();
        batch.bins.resize_with(self.batch.bins.len(), Vec::new);
        batch.reserve(
            0,
            self.nvary,
            crate::raster::prims::flat_varyings(self.plan) != 0,
        );
        let binner = Binner::new(
            batch,
            self.region,
            self.nvary,
            self.tune.band_rows,
            self.tune.pair,
        );
        let cell = Mutex::new((binner, Stats::default()));
        let claimed = AtomicBool::new(false);
        let on_pool = || {
            if claimed.swap(true, Ordering::AcqRel) {
                return;
            }
            let mut g = cell.lock().unwrap_or_else(|e| e.into_inner());
            let (b, s) = &mut *g;
            side(b, s);
            b.finish(s);
            s.draws_offloaded += 1;
        };
        let job = std::sync::Arc::clone(&self.job);
        let wait = self.tune.offload_wait;
        // SAFETY: this function returns (or unwinds, `WaitOnUnwind`) only after the job
        // is done: either the set-up here handed a batch to the job, which waits for the
        // side task to be done first (`Job::hand_over`), or `wait_done` below waits.
        let posted = unsafe { post_side(&job, &on_pool, wait) };
        let launches = self.launches;
        let mine = {
            let _unwind = WaitOnUnwind(&job);
            // Handing a full batch to the pool would wait for the half it sets up: this
            // thread keeps setting up its own half meanwhile (the batch grows).
            self.hold = posted;
            main(self, stats, false);
            self.hold = false;
            let mine = !wait && !claimed.swap(true, Ordering::AcqRel);
            if mine {
                main(self, stats, true);
            }
            if posted && !mine && self.tune.pool_help && !self.batch.heads.is_empty() {
                // The pool thread is still setting up its half: draw the bands of this
                // half's batch meanwhile (they come first in primitive order), handing
                // the rest to the pool once it is done (which waits for the side task).
                if !self.draw_while_busy() {
                    // Every band is drawn and the pool still sets up: wait for it.
                    job.wait_done(self.tune.pool_spin);
                }
            }
            if posted && self.launches == launches {
                // The pool task is done with the closure (and with the half it claimed).
                job.wait_done(self.tune.pool_spin);
            }
            mine
        };
        let (binner, s) = cell.into_inner().unwrap_or_else(|e| e.into_inner());
        let batch = binner.into_batch();
        if !mine {
            stats.add(&s);
            self.append(&batch, stats);
        }
        self.ring.push(batch);
    }

    /// Appends the triangles of `b` (binned for this rasterizer's region, bands and
    /// varyings) after those set up so far, into one batch handed to the pool when full
    /// as [`Rasterizer::triangle`] hands its batches. Copying them takes a few
    /// microseconds, so batches of the usual sizes would only add the tails where one
    /// thread draws a batch's last band while the other waits for it (humanoid s0, 9
    /// alternating runs: 26.30 → 26.04 ms; s4 51.03 → 50.29, showcase s0 30.56 → 30.02).
    fn append(&mut self, b: &Batch, stats: &mut Stats) {
        // The half of a rectangle held back goes first: primitive order.
        self.release(stats);
        let (nvary, nflat, rows) = (self.nvary, b.nflat, self.tune.band_rows);
        if self.batch.heads.is_empty() {
            self.batch.reserve(
                self.tune.max_batch,
                self.nvary,
                crate::raster::prims::flat_varyings(self.plan) != 0,
            );
        }
        for (i, h) in b.heads.iter().enumerate() {
            let planes = &b.planes[i * nvary..(i + 1) * nvary];
            let flats = &b.flats[i * nflat..(i + 1) * nflat];
            let area = self.batch.push_head(h, planes, flats, rows);
            self.box_sum += area;
        }
        if !b.heads.is_empty() {
            self.after_bin(stats);
        }
    }
}

/// Runs `f(0)` on this thread and `f(1)` on the draw pool's thread when its task polls
/// for work, or with `start` on a pool task started for it (else here too, after
/// `f(0)`; also when the pool thread has not begun it by then), and returns when both are
/// done: work too large for one thread that waits for nothing else (a depth texture's
/// write-back, `context::fbo_image`; a large draw of lines or points, `raster::banded`,
/// which starts the task: nothing else keeps the pool polling then). Without threads, or
/// on a pool thread, both run here.
pub fn fork2(start: bool, f: impl Fn(usize) + Sync) {
    if crate::cpu::threads() < 2 || rayon::current_thread_index().is_some() {
        f(0);
        f(1);
        return;
    }
    let job = super::POOL.with(|p| std::sync::Arc::clone(&p.borrow().job));
    let claimed = AtomicBool::new(false);
    let second = || {
        if !claimed.swap(true, Ordering::AcqRel) {
            f(1);
        }
    };
    // SAFETY: the job is waited for (also when `f(0)` panics, `WaitOnUnwind`) before
    // `second` goes out of scope.
    let posted = unsafe { post_side(&job, &second, start) };
    let _unwind = WaitOnUnwind(&job);
    f(0);
    second();
    if posted {
        job.wait_done(crate::tuning::tuning().pool_spin);
    }
}

/// [`fork2`] (not starting a pool task) over the two parts of `data` split at `at`:
/// `f(0, &mut data[..at])` and `f(1, &mut data[at..])`, one of them on the pool's thread
/// when its task polls for work.
pub fn fork2_split<T: Send>(data: &mut [T], at: usize, f: impl Fn(usize, &mut [T]) + Sync) {
    let (a, b) = data.split_at_mut(at.min(data.len()));
    let parts = [Mutex::new(a), Mutex::new(b)];
    fork2(false, |k| {
        let mut part = parts[k].lock().unwrap_or_else(|e| e.into_inner());
        f(k, &mut part);
    });
}

impl Batch {
    /// Appends a head binned elsewhere for the same region and bands, with its varyings
    /// and flat values, and bins it into `rows`-row bands; returns its box's pixels.
    fn push_head(&mut self, h: &Head, planes: &[super::Plane], flats: &[f32], rows: usize) -> i64 {
        let [x0, y0, x1, y1] = h.bbox;
        let area = i64::from(x1 - x0 + 1) * i64::from(y1 - y0 + 1);
        let idx = self.heads.len() as u32;
        self.heads.push(*h);
        self.planes.extend_from_slice(planes);
        self.flats.extend_from_slice(flats);
        for bin in &mut self.bins[y0 as usize / rows..=y1 as usize / rows] {
            bin.push(idx);
        }
        self.work += area;
        area
    }
}
