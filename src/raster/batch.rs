//! Batches the triangles of a draw and rasterizes them on the thread pool over bands of
//! rows, while the draw goes on setting up the next batch.
//!
//! With threads on, every set-up triangle is stored compactly (only the draw's varyings)
//! and its index is appended to the bin of each band of [`BAND_ROWS`] rows its box
//! touches. A full batch is handed to the pool and the draw fills the second batch
//! meanwhile (llvmpipe bins into tiles and rasterizes them on its threads the same way);
//! the pool draws it on all its threads but one, since the draw's own thread keeps a core
//! busy. Before handing over the next batch the draw takes the first back, drawing its
//! remaining bands itself rather than waiting idle. Each band is claimed by one thread,
//! which draws the band's triangles in primitive order, and batches are drawn one after
//! the other, so each pixel sees the same fragments in the same order as single-threaded
//! rendering: the images are byte-identical with threads on and off. The last batch of a
//! draw is drawn before the draw returns, on the calling thread alone when it is little
//! work; a draw of triangles (a glBegin/glEnd batch or a chunk of a long one, a display
//! list's vertex node, glDrawArrays/glDrawElements; multisampled in one pass too) returns
//! while the pool draws its last batch ([`Rasterizer::flush_detached`]), holding the
//! framebuffer, with a copy of the unit plans. The next such draw sets up its triangles
//! meanwhile and then takes the batch back ([`Rasterizer::adopt`]); any other GL call but
//! the per-vertex ones and the calls that touch no image (`ffi::with_ctx_list_keep` and
//! `ffi::with_ctx_keep`: matrices, enables, materials, blending, bindings, array
//! pointers, glUniform, glCallList, glGetError, most glGet …) settles it first, drawing
//! its remaining bands too. A draw whose batch is too small for the pool
//! leaves it unlaunched instead, and the next draw's triangles join it ([`segs`]: one
//! batch, several draws' plans). So a program's many small strips become batches over
//! many bands that keep both threads drawing, as llvmpipe's binning of a whole scene
//! does. A draw of independent triangles that finds the pool with nothing to draw hands
//! the set-up of half of its rest to the pool thread ([`side`]), whose triangles then
//! join the batch after the draw's own. The batches live in a per-thread
//! pool, so drawing allocates little once they have grown (a band list per batch).
//! Waking a sleeping pool thread costs a good part of a millisecond here, so a pool task
//! polls for the next batch for a while after drawing one and the draw's thread polls
//! briefly for the last band before it sleeps ([`Job`]).

mod job;
mod pairing;
mod segs;
mod side;
mod split;
use job::{Job, Padded, SideFn, Task};
use pairing::Pairing;
use segs::{DrawRec, Own, Seg, Start};

pub use side::{fork2, fork2_split};
pub use split::{geom_section, Binner};

use super::{raster_triangle, Draw};
use crate::fragment::FragPlan;
use crate::framebuffer::{Framebuffer, Target};
use crate::geometry::setup::{Edge, Plane, SetupTriangle};
use crate::stats::Stats;
use crate::texture::UnitPlan;
use std::cell::{RefCell, UnsafeCell};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Duration;

/// Pixels of triangle boxes that make a batch worth splitting over threads.
const PARALLEL_WORK: i64 = 32 * 1024;
/// Triangles of a draw's first threaded batch (later ones double up to the maximum): the
/// pool waits while it is set up. Measured (22:20, 2 threads, 5 interleaved runs): 4096 →
/// 512 changed sprites 512² 11.87 → 11.81 ms, immediate_100k 1024² 13.28 → 12.87 ms, small_tris
/// 1024² 17.06 → 16.85 ms (within the noise, never worse).
const FIRST_BATCH: usize = 512;
/// Single-threaded, pixels of triangle boxes after which a batch is drawn.
const MAX_WORK_LOCAL: i64 = 1 << 26;

/// A batched triangle without its varyings (those are in [`Batch::planes`], `nvary` per
/// triangle, and for flat shading in [`Batch::flats`]). Its box is kept clipped to the
/// batch's region, which is all the rasterizer reads of it, so it fits `i32`: 16 bytes of
/// the 120 a triangle's head takes.
#[derive(Clone, Copy)]
struct Head {
    edges: [Edge; 3],
    bbox: [i32; 4],
    front: bool,
    z: Plane,
    w: Plane,
    persp: bool,
    flat_u8: [u8; 4],
}

/// The pending triangles of a draw and their bins.
#[derive(Default)]
struct Batch {
    heads: Vec<Head>,
    planes: Vec<Plane>,
    /// The provoking vertex's varyings, `nflat` per triangle.
    flats: Vec<f32>,
    /// Flat values kept per triangle: the draw's `nvary` when it shades flat, else 0
    /// (smooth spans never read them; set by [`Batch::reserve`]).
    nflat: usize,
    /// Per band: the indices of the triangles whose box touches it, in order.
    bins: Vec<Vec<u32>>,
    /// Pixels of the triangles' boxes inside the region.
    work: i64,
    /// The earlier draws whose triangles the batch holds before its own draw's
    /// ([`segs`]); empty for a batch of one draw.
    segs: Vec<Seg>,
    /// Where the batch's own draw's triangles start (after the last segment).
    own: Start,
}

impl Batch {
    /// Forgets the triangles (keeps the buffers).
    fn clear(&mut self) {
        self.heads.clear();
        self.planes.clear();
        self.flats.clear();
        for b in &mut self.bins {
            b.clear();
        }
        self.work = 0;
        self.segs.clear();
        self.own = Start::default();
    }

    /// Makes room for a full batch at once, so that the first draws do not copy the
    /// growing buffers again and again (address space only: untouched pages cost nothing),
    /// and records whether the draw shades `flat` (whether triangles keep flat values).
    /// Called on an empty batch.
    fn reserve(&mut self, max_batch: usize, nvary: usize, flat: bool) {
        self.nflat = if flat { nvary } else { 0 };
        self.heads
            .reserve(max_batch.saturating_sub(self.heads.len()));
        let n = max_batch * nvary;
        self.planes.reserve(n.saturating_sub(self.planes.len()));
        let n = max_batch * self.nflat;
        self.flats.reserve(n.saturating_sub(self.flats.len()));
    }

    /// Appends `t` (its first `nvary` varyings, its box clipped to `region`) and bins it
    /// into bands `b0..=b1`. `t` covers a pixel of `region`, so the clipped box is not
    /// empty and inside the framebuffer.
    /// Inlined: called out of line, it read `region` back from the stack right after the
    /// caller had stored it in halves (a store-forwarding stall that took a quarter of the
    /// function's samples).
    #[inline(always)]
    fn push(&mut self, t: &SetupTriangle, nvary: usize, region: [i64; 4], b0: usize, b1: usize) {
        let SetupTriangle {
            edges,
            bbox,
            front,
            z,
            w,
            persp,
            vary,
            flat,
            flat_u8,
        } = t;
        let idx = self.heads.len() as u32;
        // The clip `raster_triangle` makes (it reads the box no other way); a region is
        // inside a framebuffer of at most `MAX_SIZE` pixels a side, so the values fit.
        let clipped = clip_box(*bbox, region);
        debug_assert!(clipped.iter().all(|&v| i32::try_from(v).is_ok()));
        self.heads.push(Head {
            edges: *edges,
            bbox: clipped.map(|v| v as i32),
            front: *front,
            z: *z,
            w: *w,
            persp: *persp,
            flat_u8: *flat_u8,
        });
        self.planes.extend_from_slice(&vary[..nvary]);
        self.flats.extend_from_slice(&flat[..self.nflat]);
        for bin in &mut self.bins[b0..=b1] {
            bin.push(idx);
        }
    }

    /// Copies triangle `i` of the batch's own draw into `t`, whose varyings past `nvary`
    /// (and flat values of a smooth draw) stay as setup leaves them: zero.
    #[inline]
    fn load(&self, i: usize, nvary: usize, t: &mut SetupTriangle) {
        self.load_in(i, self.own, nvary, self.nflat, t);
    }
}

/// A batch being drawn: its bands are claimed one at a time by the pool's threads and,
/// whenever the draw has to wait for it, by the draw's own thread ([`Work::help`]).
struct Work {
    /// The triangles and their bins (read-only while the batch is drawn).
    batch: Batch,
    /// The framebuffer's bands, one per bin; band `i` is claimed by whoever took `i` from
    /// `next`.
    bands: Vec<BandCell<'static>>,
    /// The next unclaimed band (claimed by every thread, so alone on its line).
    next: Padded<AtomicUsize>,
    plan: FragPlan,
    /// A copy of the draw's unit plans: the work may outlive the draw that made it
    /// ([`Rasterizer::flush_detached`]). The images they borrow stay untouched until the
    /// work is taken back (every GL call that could change them settles it first: all but
    /// the per-vertex calls, the state calls that keep it and the next draw), so the
    /// lifetime is the protocol's, not the type system's.
    units: Vec<UnitPlan<'static>>,
    region: [i64; 4],
    nvary: usize,
    /// The pixel counters of the drawn bands.
    stats: Mutex<Stats>,
}

/// One band of a [`Work`], written only by the thread that claimed it.
struct BandCell<'f>(UnsafeCell<Target<'f>>);

// SAFETY: a `Work` is shared between the draw's thread and one pool job. Each band is
// reached only by the thread that claimed its index from `next` (`fetch_add` hands every
// index out once); the batch is only read; the framebuffer behind the band targets and the
// texture images behind `units` stay borrowed by the `Rasterizer` that made the work, which
// takes it back (`wait`, called by every method that touches the framebuffer and by
// `Drop`) only after the job has finished, or, for a work left in flight, by the context
// that holds the framebuffer and settles it before any call that could touch either
// ([`InFlight`]). `UnitPlan` is `Sync` and `Framebuffer` `Send` (checked in
// `launch`).
unsafe impl Sync for Work {}
// SAFETY: as for `Sync` above: the raw parts are only used under that protocol.
unsafe impl Send for Work {}

impl Work {
    /// Draws unclaimed bands until none is left, then adds their counters to the work's.
    fn help(&self) {
        self.help_while(|| true);
    }

    /// Draws unclaimed bands, one at a time while `more()` holds, until none is left; adds
    /// their counters to the work's. Returns whether unclaimed bands are left.
    fn help_while(&self, more: impl Fn() -> bool) -> bool {
        let units = &self.units[..];
        let mut s = Stats::default();
        let mut left = true;
        while more() {
            let b = self.next.fetch_add(1, Ordering::Relaxed);
            let Some(cell) = self.bands.get(b) else {
                left = false;
                break;
            };
            // SAFETY: band `b` was claimed by this call alone (see `Work`'s `Sync`).
            let band = unsafe { &mut *cell.0.get() };
            let bin = &self.batch.bins[b];
            if self.batch.segs.is_empty() {
                let d = &mut Draw::new(self.region, &self.plan, units, band, &mut s);
                draw_bin(&self.batch, bin, self.nvary, d);
            } else if !bin.is_empty() {
                band.resolve();
                let own = Own {
                    plan: &self.plan,
                    units,
                    region: self.region,
                    nvary: self.nvary,
                    nflat: self.batch.nflat,
                };
                segs::draw_indices(&self.batch, bin, own, band, &mut s);
            }
        }
        self.stats
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .add_pixels(&s);
        left && self.next.load(Ordering::Relaxed) < self.bands.len()
    }
}

/// What a draw keeps between draws on one thread: both batches, the geometry split's
/// ring of batches and the job slot.
#[derive(Default)]
struct Pool {
    batches: [Batch; 2],
    ring: Vec<Batch>,
    job: Arc<Job>,
}

thread_local! {
    /// The batch buffers of the last draw on this thread, reused by the next one.
    static POOL: RefCell<Pool> = RefCell::new(Pool::default());
}

/// The rasterization side of a draw: the target, the plan and the pending batch.
pub struct Rasterizer<'a, 'f> {
    fb: &'f mut Framebuffer,
    plan: &'a FragPlan,
    units: &'a [UnitPlan<'a>],
    region: [i64; 4],
    nvary: usize,
    threads: bool,
    /// The batching knobs (bands, batch limits, pool timing: [`crate::tuning`]); the
    /// images are the same for any values, each pixel still sees its fragments in
    /// primitive order.
    tune: &'static crate::tuning::Tuning,
    /// The batch being filled.
    batch: Batch,
    /// The other batch, `None` while it is in flight.
    spare: Option<Batch>,
    /// The batch being drawn by the pool (and by this thread when it waits).
    inflight: Option<Arc<Work>>,
    /// The job slot (batches handed to the pool go through it).
    job: Arc<Job>,
    /// Triangles after which the current batch is handed to the pool: [`FIRST_BATCH`] for
    /// a draw's first batch, doubling up to `max_batch`.
    limit: usize,
    /// The triangle held back for [`pair`].
    pairing: Pairing,
    /// The geometry split's batches ([`Rasterizer::split_geometry`]), kept for the next draw.
    ring: Vec<Batch>,
    /// The sum of the pixel boxes (inside the region) of the triangles rasterized so far.
    box_sum: i64,
    /// Batches handed to the pool so far ([`Rasterizer::launch`]).
    launches: u64,
    /// While a pool thread sets up the second half of an offloaded draw
    /// ([`Rasterizer::offload`]): full batches are not handed over (the hand-over would
    /// wait for that half) but keep filling.
    hold: bool,
}

/// Where the draw's set-up triangles go: the [`Rasterizer`] itself, or a [`Binner`] that
/// fills one section's batch of a split draw.
pub trait TriangleSink {
    /// Rasterizes (or batches) one set-up triangle.
    fn triangle(&mut self, t: &SetupTriangle, stats: &mut Stats);
}

/// An inclusive box (x0, y0, x1, y1) clipped to `region` (exclusive high end); empty
/// when x0 > x1 or y0 > y1.
#[inline(always)]
fn clip_box(b: [i64; 4], region: [i64; 4]) -> [i64; 4] {
    [
        b[0].max(region[0]),
        b[1].max(region[1]),
        b[2].min(region[2] - 1),
        b[3].min(region[3] - 1),
    ]
}

/// The pixel count of `t`'s box inside `region`.
fn box_area(t: &SetupTriangle, region: [i64; 4]) -> i64 {
    let [x0, y0, x1, y1] = clip_box(t.bbox, region);
    (x1 - x0 + 1).max(0) * (y1 - y0 + 1).max(0)
}

impl<'a, 'f> Rasterizer<'a, 'f> {
    /// A rasterizer for one draw into `fb` clipped to `region`, whose triangles carry
    /// `nvary` varyings.
    ///
    /// # Safety
    /// The rasterizer must be dropped, not leaked (`mem::forget`): batches on the pool
    /// reach `fb`, `plan` and `units` through raw pointers, and only `flush` and `Drop`
    /// wait for them before the borrows end.
    pub unsafe fn new(
        fb: &'f mut Framebuffer,
        plan: &'a FragPlan,
        units: &'a [UnitPlan<'a>],
        region: [i64; 4],
        nvary: usize,
    ) -> Self {
        // A draw issued from a pool thread must not wait for the pool: no threads then.
        let threads = crate::cpu::threads() > 1 && rayon::current_thread_index().is_none();
        let pool = POOL.with(|p| std::mem::take(&mut *p.borrow_mut()));
        let [mut batch, mut spare] = pool.batches;
        let tune = crate::tuning::tuning();
        let nb = fb.height.div_ceil(tune.band_rows);
        for b in [&mut batch, &mut spare] {
            b.clear();
            b.bins.resize_with(nb, Vec::new);
        }
        Rasterizer {
            fb,
            plan,
            units,
            region,
            nvary: nvary.min(crate::geometry::MAX_VARY),
            threads,
            tune,
            batch,
            spare: Some(spare),
            inflight: None,
            job: pool.job,
            limit: FIRST_BATCH.min(tune.max_batch),
            pairing: Pairing::default(),
            ring: pool.ring,
            box_sum: 0,
            launches: 0,
            hold: false,
        }
    }

    /// Gets a pool thread running and waiting for this draw's first task, when threads are
    /// on and none is: a draw that will hand work to the pool after setting up its first
    /// triangles (the probe of a geometry split) calls this first, so that the pool thread
    /// starts (a thread is made, or a sleeping one wakes, a good part of a millisecond on
    /// this kind of machine) while it sets them up. `SOFTGL_POOL_START=0` turns this off.
    pub fn start_pool(&self) {
        if self.tune.pool_start
            && self.threads
            && self.inflight.is_none()
            && !self.job.busy.load(Ordering::Acquire)
        {
            self.job.hand_over(Task::Start, 1, self.tune.pool_stay);
        }
    }

    /// Takes back `a`, the last batch of the previous draw into this rasterizer's
    /// framebuffer, left drawing on the pool ([`InFlight::release`]): it is waited for,
    /// and its remaining bands drawn by this thread, before this draw's first batch is
    /// drawn or anything touches the framebuffer, so this draw sets up its triangles
    /// while the pool draws it. Settled at once when this rasterizer does not hand work
    /// to the same job (no threads here, or another thread's pool).
    pub fn adopt(&mut self, mut a: Adopted, stats: &mut Stats) {
        let fits = a
            .pending
            .as_ref()
            .is_none_or(|p| p.bins.len() == self.batch.bins.len());
        if self.threads
            && self.inflight.is_none()
            && self.batch.heads.is_empty()
            && fits
            && Arc::ptr_eq(&a.job, &self.job)
        {
            stats.draws_adopted += 1;
            self.inflight = a.work.take();
            // A pending batch goes on filling with this draw's triangles ([`segs`]).
            let fresh = a.pending.take().map(|mut p| {
                p.nflat = if super::prims::flat_varyings(self.plan) != 0 {
                    self.nvary
                } else {
                    0
                };
                std::mem::replace(&mut self.batch, p)
            });
            if self.inflight.is_some() {
                // The second batch is the one in flight: `wait` brings it back.
                self.spare = None;
            } else if self.spare.is_none() {
                self.spare = fresh;
            }
        } else {
            a.settle(stats, Some(&mut *self.fb));
        }
    }

    /// The framebuffer, after drawing the pending batch (for lines and points).
    pub fn target(&mut self, stats: &mut Stats) -> &mut Framebuffer {
        self.flush(stats);
        self.fb
    }

    /// The sum of the pixel boxes (inside the region) of the triangles rasterized so far,
    /// for choosing how to draw the rest.
    pub fn box_area_sum(&self) -> i64 {
        self.box_sum
    }

    /// The enabled texture units' plans.
    pub fn units(&self) -> &'a [UnitPlan<'a>] {
        self.units
    }

    /// The drawable region.
    pub fn region(&self) -> [i64; 4] {
        self.region
    }

    /// Rasterizes (or batches) one set-up triangle.
    pub fn triangle(&mut self, t: &SetupTriangle, stats: &mut Stats) {
        let area = box_area(t, self.region);
        if area == 0 {
            stats.tris_offscreen += 1;
            return;
        }
        stats.tris_rasterized += 1;
        self.box_sum += area;
        let mut p = std::mem::take(&mut self.pairing);
        let (on, nvary, region) = (self.tune.pair, self.nvary, self.region);
        p.offer(t, area, on, nvary, region, stats, |t, a, s| {
            self.emit(t, a, s)
        });
        self.pairing = p;
    }

    /// Draws the held triangle, if any.
    fn release(&mut self, stats: &mut Stats) {
        let mut p = std::mem::take(&mut self.pairing);
        p.release(self.region, stats, |t, a, s| self.emit(t, a, s));
        self.pairing = p;
    }

    /// Rasterizes (or batches) `t`, whose box holds `area` pixels of the region.
    fn emit(&mut self, t: &SetupTriangle, area: i64, stats: &mut Stats) {
        if !self.threads && area < self.tune.band_area && self.plan.shader.is_none() {
            // Drawn at once, after the batched triangles before it (primitive order).
            // (Without threads nothing is ever in flight: only a pending batch needs drawing.)
            // A shader's triangles are batched, small ones too: the engine runs the rows
            // of a band's consecutive triangles together (`shaded`).
            if !self.batch.heads.is_empty() {
                self.flush(stats);
            }
            // Only the triangle's rows leave a deferred glClear behind.
            let (y0, y1) = box_rows(t, self.region);
            let (region, plan, units) = (self.region, self.plan, self.units);
            let mut target = self.fb.target_rows(y0..y1 + 1);
            raster_triangle(t, &mut Draw::new(region, plan, units, &mut target, stats));
            return;
        }
        if self.batch.heads.is_empty() {
            self.batch.reserve(
                self.tune.max_batch,
                self.nvary,
                crate::raster::prims::flat_varyings(self.plan) != 0,
            );
        }
        split::bin(
            &mut self.batch,
            t,
            area,
            self.nvary,
            self.region,
            self.tune.band_rows,
        );
        self.after_bin(stats);
    }

    /// Draws the batch (no threads) or hands it to the pool once it is full, after a
    /// triangle was binned.
    #[inline]
    fn after_bin(&mut self, stats: &mut Stats) {
        if !self.threads {
            if self.batch.heads.len() >= self.tune.max_batch || self.batch.work >= MAX_WORK_LOCAL {
                self.flush(stats);
            }
            return;
        }
        if self.hold {
            return;
        }
        let joined = !self.batch.segs.is_empty() && self.batch.work >= self.tune.detach_work;
        if self.batch.heads.len() >= self.limit || self.batch.work >= self.tune.max_work || joined {
            // The pool is idle while the first batch is set up: start small, then grow.
            self.limit = (self.limit * 2).min(self.tune.max_batch);
            // Hand the full batch to the pool and keep setting up the next one meanwhile.
            self.wait(stats);
            self.launch();
        }
    }

    /// Draws every pending triangle (waits for the pool, then draws the last batch, over
    /// threads when it is large enough).
    pub fn flush(&mut self, stats: &mut Stats) {
        self.release(stats);
        self.wait(stats);
        if self.batch.heads.is_empty() {
            return;
        }
        let (plan, units, region, nvary) = (self.plan, self.units, self.region, self.nvary);
        if !self.threads && self.batch.heads.len() > 1 {
            // One band after the other, each with all of its triangles. (Only a threaded
            // draw takes another draw's batch over, so this one has no segments.)
            debug_assert!(self.batch.segs.is_empty());
            let mut bands = self.fb.bands(self.tune.band_rows);
            for (band, bin) in bands.iter_mut().zip(&self.batch.bins) {
                draw_bin(
                    &self.batch,
                    bin,
                    nvary,
                    &mut Draw::new(region, plan, units, band, stats),
                );
            }
        } else if !self.threads || self.batch.work < PARALLEL_WORK {
            // Only the bands the batch reaches leave a deferred glClear behind.
            let rows = reached_rows(&self.batch, self.tune.band_rows);
            let mut target = self.fb.target_rows(rows);
            if self.batch.segs.is_empty() {
                let d = &mut Draw::new(region, plan, units, &mut target, stats);
                let mut t = SetupTriangle::default();
                for i in 0..self.batch.heads.len() {
                    self.batch.load(i, nvary, &mut t);
                    raster_triangle(&t, d);
                }
            } else {
                let own = Own {
                    plan,
                    units,
                    region,
                    nvary,
                    nflat: self.batch.nflat,
                };
                segs::draw_all(&self.batch, own, &mut target, stats);
            }
        } else {
            // Over the pool's threads and this one.
            self.launch();
            self.wait(stats);
            return;
        }
        self.batch.clear();
    }

    /// As [`Rasterizer::flush`], except that a last batch of at least
    /// [`crate::tuning::Tuning::detach_work`] pixels is left drawing on the pool and
    /// returned: the draw's thread goes on while the pool finishes it (a glBegin/glEnd
    /// draw returns to take the next vertices). Nothing else is pending once this returns.
    ///
    /// # Safety
    /// Until the returned [`InFlight`] is settled or dropped, the pool writes the
    /// framebuffer's bands: once this rasterizer is dropped, the framebuffer must go into
    /// [`InFlight::hold`] before anything else touches it, and no other rasterizer may
    /// start on this thread meanwhile (it would hand the same job slot a second batch).
    pub unsafe fn flush_detached(&mut self, stats: &mut Stats) -> Option<InFlight> {
        self.release(stats);
        if !self.threads {
            self.flush(stats);
            return None;
        }
        let pending = if self.batch.work >= self.tune.detach_work {
            self.wait(stats);
            self.launch();
            None
        } else if self.batch.heads.is_empty() {
            None
        } else {
            // Too little for the pool yet: left for the next draw's triangles to join
            // ([`segs`]), behind the batch in flight.
            let rec = self.rec();
            let mut b = std::mem::take(&mut self.batch);
            b.close(rec);
            Some(b)
        };
        let work = self.inflight.take();
        if work.is_none() && pending.is_none() {
            return None;
        }
        stats.draws_detached += 1;
        Some(InFlight {
            work,
            pending,
            job: Arc::clone(&self.job),
            spin: self.tune.pool_spin,
            fb: None,
        })
    }

    /// This draw's record, for its triangles in a batch that outlives it.
    fn rec(&self) -> DrawRec {
        DrawRec {
            plan: *self.plan,
            units: static_units(self.units),
            region: self.region,
            nvary: self.nvary,
            nflat: self.batch.nflat,
        }
    }

    /// Takes the batch in flight back once it is drawn, helping to draw its remaining
    /// bands meanwhile, and adds its counters to `stats`.
    fn wait(&mut self, stats: &mut Stats) {
        let Some(work) = self.inflight.as_ref() else {
            return;
        };
        if self.tune.pool_help {
            work.help();
        }
        self.job.wait_done(self.tune.pool_spin);
        // Taken only now, so that a panic above still leaves `Drop` waiting for the job.
        // The job dropped its handle before it reported done.
        let mut b = reclaim(self.inflight.take(), stats);
        b.bins.resize_with(self.batch.bins.len(), Vec::new);
        self.spare = Some(b);
    }

    /// Hands the current batch to the pool (the previous one must be back) and starts
    /// filling the spare one. While this thread goes on setting up triangles, the job
    /// draws bands on all the pool's threads but one (the cores are shared with this
    /// thread); when this thread has to wait for the batch it draws bands too.
    fn launch(&mut self) {
        let work = self.take_work();
        post_work(&self.job, &work);
        self.inflight = Some(work);
    }

    /// The current batch as a [`Work`] in flight: this thread draws its bands while the
    /// pool's task is busy (setting up an offloaded half, [`side`]), and hands the rest
    /// to the pool as soon as the task is done. Returns whether it handed any over (then
    /// the task was done first); `wait` takes the work back either way.
    fn draw_while_busy(&mut self) -> bool {
        let work = self.take_work();
        let job = &self.job;
        let left = work.help_while(|| job.busy.load(Ordering::Acquire));
        if left {
            post_work(job, &work);
        }
        self.inflight = Some(work);
        left
    }

    /// The current batch as a [`Work`] over the framebuffer's bands (the spare batch
    /// becomes the current one).
    fn take_work(&mut self) -> Arc<Work> {
        fn shareable<T: Sync>() {}
        fn sendable<T: Send>() {}
        shareable::<UnitPlan<'static>>();
        sendable::<Framebuffer>();
        self.launches += 1;
        let spare = self.spare.take().unwrap_or_default();
        let batch = std::mem::replace(&mut self.batch, spare);
        let own = (
            *self.plan,
            static_units(self.units),
            self.region,
            self.nvary,
        );
        // SAFETY: this rasterizer keeps `self.fb` borrowed and does not touch it until
        // `wait` has taken the work back from the job.
        unsafe { make_work(batch, self.fb, own) }
    }
}

/// Hands `work` to `job`, drawn by all the pool's threads but one when this thread
/// helps ([`Tuning::pool_help`](crate::tuning::Tuning)).
fn post_work(job: &Arc<Job>, work: &Arc<Work>) {
    let tune = crate::tuning::tuning();
    let threads = crate::cpu::threads();
    let helpers = if tune.pool_help { threads - 1 } else { threads }.max(1);
    job.hand_over(Task::Bands(Arc::clone(work)), helpers, tune.pool_stay);
}

/// `batch` as a [`Work`] over `fb`'s bands, whose own triangles are drawn with `own`
/// (plan, units, region, varyings).
///
/// # Safety
/// `fb` must not be touched (nor dropped) until the work is drawn and taken back
/// (`finish` or `Rasterizer::wait`): the bands reach it through raw pointers.
unsafe fn make_work(
    batch: Batch,
    fb: &mut Framebuffer,
    own: (FragPlan, Vec<UnitPlan<'static>>, [i64; 4], usize),
) -> Arc<Work> {
    let tune = crate::tuning::tuning();
    let bands = fb.bands(tune.band_rows);
    // SAFETY: the caller keeps `fb` untouched until the work is taken back (see `Work`).
    let bands: Vec<Target<'static>> = unsafe { std::mem::transmute(bands) };
    let (plan, units, region, nvary) = own;
    let work = Arc::new(Work {
        batch,
        bands: bands
            .into_iter()
            .map(|b| BandCell(UnsafeCell::new(b)))
            .collect(),
        next: Padded(AtomicUsize::new(0)),
        plan,
        units,
        region,
        nvary,
        stats: Mutex::new(Stats::default()),
    });
    work
}

/// A copy of `units` for a batch that may outlive the draw ([`Work`]'s `units`).
fn static_units(units: &[UnitPlan<'_>]) -> Vec<UnitPlan<'static>> {
    // SAFETY: only the lifetime changes; the texture images the plans borrow stay
    // untouched until the batch is drawn (see `units` in `Work`).
    unsafe { std::mem::transmute::<Vec<UnitPlan<'_>>, Vec<UnitPlan<'static>>>(units.to_vec()) }
}

/// Takes back a batch whose job has reported done (the job dropped its handle before
/// that): adds its counters to `stats` and returns its buffers, cleared.
fn reclaim(work: Option<Arc<Work>>, stats: &mut Stats) -> Batch {
    let mut b = match work.and_then(Arc::into_inner) {
        Some(w) => {
            stats.add_pixels(&w.stats.into_inner().unwrap_or_else(|e| e.into_inner()));
            w.batch
        }
        None => Batch::default(),
    };
    b.clear();
    b
}

/// The last batch of a draw, still drawn by the pool after the draw returned
/// ([`Rasterizer::flush_detached`]), and the framebuffer it draws into
/// ([`InFlight::hold`]): nothing else can reach the framebuffer until
/// [`InFlight::settle`] hands it back. Dropping it waits for the pool too.
pub struct InFlight {
    /// The batch on the pool (taken by `settle`).
    work: Option<Arc<Work>>,
    /// A batch not handed to the pool yet, all of its triangles in closed segments
    /// ([`segs`]), drawn after `work`.
    pending: Option<Batch>,
    /// The job slot it was handed to.
    job: Arc<Job>,
    /// How long to poll before sleeping ([`Tuning::wait_spin`]).
    spin: Duration,
    /// The framebuffer the batch draws into, held until it is drawn. (Moving a
    /// `Framebuffer` leaves its buffers, which the pool writes, where they are.)
    fb: Option<Framebuffer>,
}

impl InFlight {
    /// Keeps `fb` until the batch is drawn; it must be the framebuffer the rasterizer
    /// that returned this drew into (see [`Rasterizer::flush_detached`]).
    pub fn hold(&mut self, fb: Option<Framebuffer>) {
        self.fb = fb;
    }

    /// Waits until the batch is drawn (drawing its remaining bands meanwhile), adds its
    /// counters to `stats`, gives its buffers back to this thread's pool for the next
    /// draw, and returns the framebuffer.
    pub fn settle(mut self, stats: &mut Stats) -> Option<Framebuffer> {
        finish(self.work.take(), &self.job, self.spin, stats);
        let mut fb = self.fb.take();
        if let (Some(b), Some(fb)) = (self.pending.take(), fb.as_mut()) {
            draw_pending(b, fb, &self.job, self.spin, stats);
        }
        fb
    }

    /// Gives the framebuffer back without waiting, and the batch to the next draw into it,
    /// which takes the batch back ([`Rasterizer::adopt`]) after setting up its own
    /// triangles. The framebuffer's contents must not be touched until then.
    pub fn release(mut self) -> (Adopted, Option<Framebuffer>) {
        let a = Adopted {
            work: self.work.take(),
            pending: self.pending.take(),
            job: Arc::clone(&self.job),
            spin: self.spin,
        };
        (a, self.fb.take())
    }
}

impl Drop for InFlight {
    fn drop(&mut self) {
        // Before `fb` is dropped.
        if self.work.is_some() {
            self.job.wait_done(self.spin);
        }
    }
}

/// A batch left in flight by the last draw ([`InFlight::release`]), for the next draw's
/// rasterizer to take back ([`Rasterizer::adopt`]) or to settle ([`Adopted::settle`]).
/// Dropping it waits for the pool.
pub struct Adopted {
    work: Option<Arc<Work>>,
    pending: Option<Batch>,
    job: Arc<Job>,
    spin: Duration,
}

impl Adopted {
    /// As [`InFlight::settle`], for batches whose framebuffer `fb` is back with its owner.
    pub fn settle(mut self, stats: &mut Stats, fb: Option<&mut Framebuffer>) {
        finish(self.work.take(), &self.job, self.spin, stats);
        if let (Some(b), Some(fb)) = (self.pending.take(), fb) {
            draw_pending(b, fb, &self.job, self.spin, stats);
        }
    }
}

impl Drop for Adopted {
    fn drop(&mut self) {
        if self.work.is_some() {
            self.job.wait_done(self.spin);
        }
    }
}

/// Draws the remaining bands of `work`, a batch handed to `job`, waits until the job is
/// done, adds the batch's counters to `stats` and gives its buffers back to this thread's
/// pool.
fn finish(work: Option<Arc<Work>>, job: &Job, spin: Duration, stats: &mut Stats) {
    if let Some(w) = &work {
        if crate::tuning::tuning().pool_help {
            w.help();
        }
    }
    job.wait_done(spin);
    give_back(reclaim(work, stats));
}

/// Draws `b`, a batch left pending by a draw ([`InFlight`]'s `pending`, all of it in
/// closed segments), into `fb`: over `job`'s pool thread and this one when it reaches
/// several bands (the job must be idle), else on this thread alone; then gives its
/// buffers back to this thread's pool.
fn draw_pending(
    mut b: Batch,
    fb: &mut Framebuffer,
    job: &Arc<Job>,
    spin: Duration,
    stats: &mut Stats,
) {
    let tune = crate::tuning::tuning();
    let reached = b.bins.iter().filter(|bin| !bin.is_empty()).count();
    // (A draw on a pool thread must not wait for the pool.)
    let threads = match rayon::current_thread_index() {
        None => crate::cpu::threads(),
        Some(_) => 1,
    };
    let last = b
        .segs
        .last()
        .map(|s| (s.rec.plan, s.rec.region, s.rec.nvary));
    if let (true, Some((plan, region, nvary))) = (threads > 1 && reached > 1, last) {
        // Every triangle is in a segment with its own draw's plan: the batch's own draw
        // has none (its plan and units are never used).
        // SAFETY: `fb` stays borrowed here until `finish` has waited for the job.
        let work = unsafe { make_work(b, fb, (plan, Vec::new(), region, nvary)) };
        post_work(job, &work);
        finish(Some(work), job, spin, stats);
        return;
    }
    let rows = reached_rows(&b, tune.band_rows);
    segs::draw_closed(&b, &mut fb.target_rows(rows), stats);
    b.clear();
    give_back(b);
}

/// Puts `b`'s buffers into this thread's pool for the next draw.
fn give_back(b: Batch) {
    // Only while no rasterizer has the pool out (it is back between draws): the batch
    // fills the slot the draw left empty.
    POOL.with(|p| {
        if let Ok(mut p) = p.try_borrow_mut() {
            if let Some(slot) = p.batches.iter_mut().find(|s| s.heads.capacity() == 0) {
                *slot = b;
            }
        }
    });
}

/// The rows of the bands `batch` reaches (from its first band with a triangle to its last).
fn reached_rows(batch: &Batch, band_rows: usize) -> std::ops::Range<usize> {
    let bins = &batch.bins;
    let first = bins.iter().position(|b| !b.is_empty()).unwrap_or(0);
    let end = bins
        .iter()
        .rposition(|b| !b.is_empty())
        .map_or(0, |l| l + 1);
    first * band_rows..end * band_rows
}

/// The first and last row (y-down, inclusive) of `t`'s box inside `region` (the box is
/// known to hold pixels of the region).
#[inline(always)]
fn box_rows(t: &SetupTriangle, region: [i64; 4]) -> (usize, usize) {
    let [_, y0, _, y1] = clip_box(t.bbox, region);
    (y0 as usize, y1 as usize)
}

/// Draws the triangles of one band's bin into the band `d` draws into.
fn draw_bin(batch: &Batch, bin: &[u32], nvary: usize, d: &mut Draw<'_, '_>) {
    if bin.is_empty() {
        // Nothing to draw here: the band keeps a deferred glClear pending.
        return;
    }
    // The band's share of a deferred glClear, written while the band is in the cache.
    d.fb.resolve();
    let mut t = SetupTriangle::default();
    for &i in bin {
        batch.load(i as usize, nvary, &mut t);
        raster_triangle(&t, d);
    }
}

impl TriangleSink for Rasterizer<'_, '_> {
    #[inline]
    fn triangle(&mut self, t: &SetupTriangle, stats: &mut Stats) {
        Rasterizer::triangle(self, t, stats)
    }
}

impl Drop for Rasterizer<'_, '_> {
    fn drop(&mut self) {
        // The job must be done before the borrows it uses end. (Draws end with `flush`, so
        // nothing is held or pending here unless a draw was cut short.)
        let mut s = Stats::default();
        self.release(&mut s);
        self.wait(&mut s);
        let pool = Pool {
            batches: [
                std::mem::take(&mut self.batch),
                self.spare.take().unwrap_or_default(),
            ],
            ring: std::mem::take(&mut self.ring),
            job: Arc::clone(&self.job),
        };
        POOL.with(|p| *p.borrow_mut() = pool);
    }
}
