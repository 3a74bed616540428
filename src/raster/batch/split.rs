//! The geometry split: a large draw of independent triangles is cut into sections that the
//! draw's thread and one pool thread set up at the same time, each section into a batch of
//! its own, while the batches are drawn in section order, band by band, by whichever of the
//! two threads is free.
//!
//! Small triangles cost more to set up than to draw, so with the ordinary pipeline (the
//! draw's thread sets up, the pool draws) the pool thread waits much of the time; here
//! both threads do both. The order each pixel sees is still the primitive order: a batch
//! is drawn only after every band of the batch before it is done, each band of a batch is
//! drawn by one thread, and a section's triangles are binned in their own order. The
//! images are therefore byte-identical to single-threaded rendering. The counters are the
//! same too, except `vertices` (each thread has its own post-transform cache, so vertices
//! shared by sections set up on different threads are transformed twice) and `tris_paired` (a rectangle's halves in two sections are drawn as two triangles).
//!
//! The scheduler is a loop both threads run ([`Shared::work`]): draw the next band of the
//! batch at the cursor when that batch is set up, else set up the next section when its
//! ring slot is free (at most [`RING`] sections ahead of the cursor), else spin.

use super::{
    box_area, box_rows, draw_bin, BandCell, Batch, Job, Padded, Pairing, Rasterizer, SideFn, Task,
    TriangleSink,
};
use crate::fragment::FragPlan;
use crate::geometry::setup::SetupTriangle;
use crate::raster::Draw;
use crate::stats::Stats;
use crate::texture::UnitPlan;
use std::cell::UnsafeCell;
use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::Duration;

/// Sections set up ahead of the batch being drawn, at most (the ring of batches).
const RING: usize = 4;

/// Triangles per section of a split draw: `SOFTGL_GEOM_SECTION` (0 turns the split off),
/// else 4096 ([`crate::tuning::Tuning::geom_section`]). A draw is split when it has at
/// least two sections.
pub fn geom_section() -> usize {
    crate::tuning::tuning().geom_section
}

/// One section's set-up triangles, binned into bands the way the [`Rasterizer`] bins a
/// batch (and paired into rectangles the same way).
pub struct Binner {
    batch: Batch,
    pairing: Pairing,
    region: [i64; 4],
    nvary: usize,
    band_rows: usize,
    pair: bool,
}

/// Appends `t` (whose box holds `area` pixels of `region`) to `batch`, binned by its rows.
#[inline]
pub(super) fn bin(
    batch: &mut Batch,
    t: &SetupTriangle,
    area: i64,
    nvary: usize,
    region: [i64; 4],
    rows: usize,
) {
    let (y0, y1) = box_rows(t, region);
    // Bands are 32 rows unless a measurement says otherwise: a shift, not two divisions
    // per triangle.
    let band = |y: usize| {
        if rows.is_power_of_two() {
            y >> rows.trailing_zeros()
        } else {
            y / rows
        }
    };
    batch.push(t, nvary, region, band(y0), band(y1));
    batch.work += area;
}

impl TriangleSink for Binner {
    #[inline]
    fn triangle(&mut self, t: &SetupTriangle, stats: &mut Stats) {
        let area = box_area(t, self.region);
        if area == 0 {
            stats.tris_offscreen += 1;
            return;
        }
        stats.tris_rasterized += 1;
        let Binner {
            batch,
            pairing,
            region,
            nvary,
            band_rows,
            pair,
        } = self;
        let (region, nvary, rows) = (*region, *nvary, *band_rows);
        pairing.offer(t, area, *pair, nvary, region, stats, |t, a, _| {
            bin(batch, t, a, nvary, region, rows)
        });
    }
}

impl Binner {
    /// A binner that fills `batch` (cleared, with a bin per band of `band_rows` rows)
    /// with triangles of `region` carrying `nvary` varyings, pairing halves of rectangles
    /// when `pair`.
    pub(super) fn new(
        batch: Batch,
        region: [i64; 4],
        nvary: usize,
        band_rows: usize,
        pair: bool,
    ) -> Self {
        Binner {
            batch,
            pairing: Pairing::default(),
            region,
            nvary,
            band_rows,
            pair,
        }
    }

    /// The filled batch.
    pub(super) fn into_batch(self) -> Batch {
        self.batch
    }

    /// Bins the triangle still held back for pairing, at the end of a section.
    pub(super) fn finish(&mut self, stats: &mut Stats) {
        let (region, nvary, rows) = (self.region, self.nvary, self.band_rows);
        let batch = &mut self.batch;
        self.pairing.release(region, stats, |t, a, _| {
            bin(batch, t, a, nvary, region, rows)
        });
    }
}

/// A ring slot: the batch of one section, and which section it holds once set up.
struct Slot {
    /// Section + 1 of the set-up batch in `binner` (0: none yet). Polled by the drawing
    /// thread while the other fills `binner`, so not on `binner`'s lines.
    ready: Padded<AtomicUsize>,
    binner: UnsafeCell<Binner>,
}

/// What both threads of a split draw share.
struct Shared<'a, 'f> {
    /// Sections of the draw.
    sections: usize,
    /// The next section to set up.
    next: Padded<AtomicUsize>,
    /// The batch being drawn (high 32 bits) and its next unclaimed band (low 32 bits).
    /// Polled by an idle thread: alone on its line, as are the other atomics, so that
    /// the draw thread's stores to its stack next to `Shared` do not stall on it.
    cursor: Padded<AtomicU64>,
    /// Bands of the batch at the cursor drawn so far.
    bands_done: Padded<AtomicUsize>,
    /// Set when a thread panicked: both stop.
    abort: Padded<AtomicBool>,
    slots: Vec<Slot>,
    bands: Vec<BandCell<'f>>,
    plan: &'a FragPlan,
    units: &'a [UnitPlan<'a>],
    region: [i64; 4],
    nvary: usize,
    /// The pool thread's counters.
    stats: Mutex<Stats>,
}

// SAFETY: the cells are reached under the scheduler's claims. A slot's binner is written
// only by the thread that claimed its section from `next` (`compare_exchange` hands every
// section out once), and only when the section it held before (RING earlier) has been
// drawn completely (the cursor is past it); it is read by drawing threads only after its
// `ready` store (release) names the section at the cursor. Band `b` of the batch at the
// cursor is reached only by the thread whose `compare_exchange` on `cursor` claimed it,
// and the cursor moves to the next batch only after every band of this one is done
// (`bands_done`, acquire-release), so the next batch's draw of a band happens after the
// last one's. `UnitPlan` is `Sync`; the framebuffer behind the bands stays borrowed by
// the `Rasterizer` until both threads are done (`split_geometry` waits for the job).
unsafe impl Sync for Shared<'_, '_> {}

/// Sets `abort` when dropped during a panic, so that the other thread stops waiting.
struct StopOnUnwind<'s>(&'s AtomicBool);

impl Drop for StopOnUnwind<'_> {
    fn drop(&mut self) {
        if std::thread::panicking() {
            self.0.store(true, Ordering::Relaxed);
        }
    }
}

/// Waits, when dropped (also during a panic), until the job handed to the pool is done.
struct WaitJob<'j>(&'j Job, Duration);

impl Drop for WaitJob<'_> {
    fn drop(&mut self) {
        self.0.wait_done(self.1);
    }
}

/// What one step of [`Shared::work`] found.
#[derive(PartialEq)]
enum Step {
    /// It drew a band or set up a section.
    Worked,
    /// Nothing to do right now.
    Idle,
    /// Every batch is drawn (or a thread panicked).
    Done,
}

impl Shared<'_, '_> {
    /// One thread's share of the draw: draws bands and sets up sections (with `geom` and
    /// this thread's `state`) until every batch is drawn, counting into `stats`. The draw's
    /// thread sets up first and draws when the ring is full; the pool thread draws first and
    /// sets up when no band is ready (the ordinary pipeline's roles, with the idle time of
    /// either one given to the other's work).
    fn work<T>(
        &self,
        state: &mut T,
        geom: &(impl Fn(&mut T, usize, &mut Binner, &mut Stats) + Sync),
        draw_first: bool,
        stats: &mut Stats,
    ) {
        let _stop = StopOnUnwind(&self.abort);
        loop {
            let mut step = if draw_first {
                self.draw_band(stats)
            } else {
                self.set_up(state, geom, stats)
            };
            if step == Step::Idle {
                step = if draw_first {
                    self.set_up(state, geom, stats)
                } else {
                    self.draw_band(stats)
                };
            }
            match step {
                Step::Done => return,
                Step::Worked => {}
                Step::Idle => std::hint::spin_loop(),
            }
        }
    }

    /// The batch at the cursor and the band to claim next, or `None` when all are drawn.
    #[inline]
    fn cursor(&self) -> Option<(u64, usize, usize)> {
        let cur = self.cursor.load(Ordering::Acquire);
        let (d, b) = ((cur >> 32) as usize, cur as u32 as usize);
        (d < self.sections && !self.abort.load(Ordering::Relaxed)).then_some((cur, d, b))
    }

    /// Draws the next band of the batch at the cursor, if that batch is set up.
    fn draw_band(&self, stats: &mut Stats) -> Step {
        let Some((cur, d, b)) = self.cursor() else {
            return Step::Done;
        };
        let nb = self.bands.len();
        let slot = &self.slots[d % RING];
        if b >= nb || slot.ready.load(Ordering::Acquire) != d + 1 {
            return Step::Idle;
        }
        if self
            .cursor
            .compare_exchange_weak(cur, cur + 1, Ordering::AcqRel, Ordering::Relaxed)
            .is_err()
        {
            return Step::Worked;
        }
        // SAFETY: section `d` is set up and stays unwritten until the cursor has passed it
        // (see `Shared`'s `Sync`).
        let batch = unsafe { &(*slot.binner.get()).batch };
        let bin = &batch.bins[b];
        if !bin.is_empty() {
            // SAFETY: band `b` of batch `d` was claimed by this thread alone.
            let band = unsafe { &mut *self.bands[b].0.get() };
            let d = &mut Draw::new(self.region, self.plan, self.units, band, stats);
            draw_bin(batch, bin, self.nvary, d);
        }
        if self.bands_done.fetch_add(1, Ordering::AcqRel) + 1 == nb {
            self.bands_done.store(0, Ordering::Relaxed);
            self.cursor.store(((d + 1) as u64) << 32, Ordering::Release);
        }
        Step::Worked
    }

    /// Sets up the next section, if its ring slot is free.
    fn set_up<T>(
        &self,
        state: &mut T,
        geom: &(impl Fn(&mut T, usize, &mut Binner, &mut Stats) + Sync),
        stats: &mut Stats,
    ) -> Step {
        let Some((_, d, _)) = self.cursor() else {
            return Step::Done;
        };
        let s = self.next.load(Ordering::Acquire);
        if s >= self.sections || s >= d + RING {
            return Step::Idle;
        }
        if self
            .next
            .compare_exchange_weak(s, s + 1, Ordering::AcqRel, Ordering::Relaxed)
            .is_err()
        {
            return Step::Worked;
        }
        let slot = &self.slots[s % RING];
        // SAFETY: section `s` was claimed by this thread alone, and the batch its slot held
        // (section s − RING < d) is drawn: nobody reads the slot now.
        let binner = unsafe { &mut *slot.binner.get() };
        binner.batch.clear();
        geom(state, s, binner, stats);
        binner.finish(stats);
        slot.ready.store(s + 1, Ordering::Release);
        Step::Worked
    }
}

impl Rasterizer<'_, '_> {
    /// Whether [`Self::split_geometry`] can run (threads are on for this draw).
    pub fn can_split(&self) -> bool {
        self.threads
    }

    /// Sets up and draws `sections` sections of a draw on this thread and one pool
    /// thread (see the module doc). `geom(state, s, binner, stats)` sets up the triangles
    /// of section `s` (at most `section_len`) into `binner` in primitive order, with a
    /// `state` that `init` makes once on each thread. Everything pending is drawn first.
    pub fn split_geometry<T, I, G>(
        &mut self,
        sections: usize,
        section_len: usize,
        stats: &mut Stats,
        init: I,
        geom: G,
    ) where
        I: Fn() -> T + Sync,
        G: Fn(&mut T, usize, &mut Binner, &mut Stats) + Sync,
    {
        self.flush(stats);
        let (region, nvary, rows, pair) =
            (self.region, self.nvary, self.tune.band_rows, self.tune.pair);
        let bands: Vec<BandCell<'_>> = self
            .fb
            .bands(rows)
            .into_iter()
            .map(|b| BandCell(UnsafeCell::new(b)))
            .collect();
        let nb = bands.len();
        let mut ring = std::mem::take(&mut self.ring);
        ring.resize_with(RING, Batch::default);
        let slots = ring
            .into_iter()
            .map(|mut batch| {
                batch.clear();
                batch.bins.resize_with(nb, Vec::new);
                batch.reserve(
                    section_len,
                    nvary,
                    crate::raster::prims::flat_varyings(self.plan) != 0,
                );
                Slot {
                    ready: Padded(AtomicUsize::new(0)),
                    binner: UnsafeCell::new(Binner::new(batch, region, nvary, rows, pair)),
                }
            })
            .collect();
        let shared = Shared {
            sections,
            next: Padded(AtomicUsize::new(0)),
            cursor: Padded(AtomicU64::new(0)),
            bands_done: Padded(AtomicUsize::new(0)),
            abort: Padded(AtomicBool::new(false)),
            slots,
            bands,
            plan: self.plan,
            units: self.units,
            region,
            nvary,
            stats: Mutex::new(Stats::default()),
        };
        let side = || {
            let mut state = init();
            let mut s = Stats::default();
            shared.work(&mut state, &geom, true, &mut s);
            shared
                .stats
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .add(&s);
        };
        {
            let f: &(dyn Fn() + Sync) = &side;
            // SAFETY: only the lifetime is erased. `_wait` (dropped first, also during a
            // panic) waits until the pool task has called `f` and returned, before `side`
            // and what it borrows go out of scope.
            let f: *const (dyn Fn() + Sync + 'static) = unsafe { std::mem::transmute(f) };
            let _wait = WaitJob(&self.job, self.tune.pool_spin);
            self.job
                .hand_over(Task::Side(SideFn(f)), 1, self.tune.pool_stay);
            let mut state = init();
            shared.work(&mut state, &geom, false, stats);
        }
        let aborted = shared.abort.load(Ordering::Relaxed);
        stats.add(&shared.stats.into_inner().unwrap_or_else(|e| e.into_inner()));
        self.ring = shared
            .slots
            .into_iter()
            .map(|s| s.binner.into_inner().batch)
            .collect();
        assert!(!aborted, "geometry split: the pool thread panicked");
    }
}
