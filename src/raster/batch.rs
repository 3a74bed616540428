//! Batches the triangles of a draw and rasterizes them on the thread pool over bands of
//! rows, while the draw goes on setting up the next batch.
//!
//! With threads on, every set-up triangle is stored compactly (only the draw's varyings)
//! and its index is appended to the bin of each band of [`BAND_ROWS`] rows its box
//! touches. A full batch is handed to the pool and the draw fills the second batch
//! meanwhile (llvmpipe bins into tiles and rasterizes them on its threads the same way);
//! before handing over the next one it waits for the first. On the pool, one thread owns a
//! band at a time and draws the band's triangles in primitive order, and batches are drawn
//! one after the other, so each pixel sees the same fragments in the same order as
//! single-threaded rendering: the images are byte-identical with threads on and off. The
//! last batch of a draw is drawn before the draw returns, on the calling thread when it is
//! little work. The batches live in a per-thread pool, so drawing allocates nothing once
//! they have grown.

use super::raster_triangle;
use crate::fragment::FragPlan;
use crate::framebuffer::{Framebuffer, Target};
use crate::geometry::setup::{Edge, Plane, SetupTriangle};
use crate::stats::Stats;
use crate::texture::UnitPlan;
use rayon::prelude::*;
use std::cell::RefCell;
use std::sync::{Arc, Condvar, Mutex};

/// Rows per band (even, so 2x2 quads stay inside one band) unless `SOFTGL_BAND_ROWS`
/// says otherwise ([`Tuning`]).
pub const BAND_ROWS: usize = 32;
/// Pixels of triangle boxes that make a batch worth splitting over threads.
const PARALLEL_WORK: i64 = 32 * 1024;
/// Triangles a batch holds at most.
const MAX_BATCH: usize = 4096;
/// Pixels of triangle boxes after which a batch is handed to the pool. Measured (17:57,
/// quiet machine, 2 threads, 1024²): 1M px → 32M px took blend_quads 29.5 → 20.6 ms,
/// depth_back_to_front 12.2 → 9.5, depth_front_to_back 5.0 → 3.5, sprites 32.9 → 29.5;
/// small-triangle draws are bounded by `MAX_BATCH` first and did not change.
const MAX_WORK: i64 = 1 << 25;
/// Single-threaded, triangles whose box covers at least this many pixels are batched and
/// drawn band by band, so that a band's colour and depth rows stay in the cache while
/// every triangle of the batch is drawn into them (at 1024x1024 the buffers are 4 MB each,
/// twice the L2 cache); smaller ones are drawn at once.
const BAND_AREA: i64 = 4096;
/// Single-threaded, pixels of triangle boxes after which a batch is drawn.
const MAX_WORK_LOCAL: i64 = 1 << 26;

/// The batching constants, read once; the environment variables `SOFTGL_BAND_ROWS`,
/// `SOFTGL_MAX_WORK` and `SOFTGL_BAND_AREA` override them for measurements (the images
/// are the same for any values: each pixel still sees its fragments in primitive order).
#[derive(Clone, Copy, Debug)]
struct Tuning {
    /// Rows per band (even).
    band_rows: usize,
    /// Threaded: pixels of boxes after which a batch goes to the pool.
    max_work: i64,
    /// Single-threaded: the box size from which triangles are batched into bands.
    band_area: i64,
}

/// The batching constants ([`Tuning`]).
fn tuning() -> Tuning {
    static T: std::sync::OnceLock<Tuning> = std::sync::OnceLock::new();
    *T.get_or_init(|| {
        let var = |k: &str| std::env::var(k).ok().and_then(|v| v.parse::<i64>().ok());
        Tuning {
            band_rows: var("SOFTGL_BAND_ROWS")
                .map_or(BAND_ROWS, |v| (v.clamp(2, 4096) as usize) & !1),
            max_work: var("SOFTGL_MAX_WORK").map_or(MAX_WORK, |v| v.max(1)),
            band_area: var("SOFTGL_BAND_AREA").map_or(BAND_AREA, |v| v.max(0)),
        }
    })
}

/// A batched triangle without its varyings (those are in [`Batch::planes`] and
/// [`Batch::flats`], `nvary` per triangle).
#[derive(Clone, Copy)]
struct Head {
    edges: [Edge; 3],
    bbox: [i64; 4],
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
    flats: Vec<f32>,
    /// Per band: the indices of the triangles whose box touches it, in order.
    bins: Vec<Vec<u32>>,
    /// Pixels of the triangles' boxes inside the region.
    work: i64,
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
    }

    /// Appends `t` (its first `nvary` varyings) and bins it into bands `b0..=b1`.
    fn push(&mut self, t: &SetupTriangle, nvary: usize, b0: usize, b1: usize) {
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
        self.heads.push(Head {
            edges: *edges,
            bbox: *bbox,
            front: *front,
            z: *z,
            w: *w,
            persp: *persp,
            flat_u8: *flat_u8,
        });
        self.planes.extend_from_slice(&vary[..nvary]);
        self.flats.extend_from_slice(&flat[..nvary]);
        for bin in &mut self.bins[b0..=b1] {
            bin.push(idx);
        }
    }

    /// Copies triangle `i` into `t`, whose varyings past `nvary` stay zero as setup leaves
    /// them.
    #[inline]
    fn load(&self, i: usize, nvary: usize, t: &mut SetupTriangle) {
        let h = &self.heads[i];
        t.edges = h.edges;
        t.bbox = h.bbox;
        t.front = h.front;
        t.z = h.z;
        t.w = h.w;
        t.persp = h.persp;
        t.flat_u8 = h.flat_u8;
        t.vary[..nvary].copy_from_slice(&self.planes[i * nvary..(i + 1) * nvary]);
        t.flat[..nvary].copy_from_slice(&self.flats[i * nvary..(i + 1) * nvary]);
    }
}

/// The completion state of a batch rasterized on the pool while the draw goes on.
#[derive(Default)]
struct JobState {
    /// The batch (handed to the job, handed back when it is drawn).
    batch: Option<Batch>,
    /// Whether the job has not finished yet.
    busy: bool,
    /// The pixel counters of the finished job.
    stats: Stats,
}

/// A job slot shared with the pool: the state and its signal.
#[derive(Default)]
struct Job {
    state: Mutex<JobState>,
    done: Condvar,
}

/// What a draw keeps between draws on one thread: both batches and the job slot.
#[derive(Default)]
struct Pool {
    batches: [Batch; 2],
    job: Arc<Job>,
}

thread_local! {
    /// The batch buffers of the last draw on this thread, reused by the next one.
    static POOL: RefCell<Pool> = RefCell::new(Pool::default());
}

/// The borrowed inputs of a job, as raw pointers so that it can run on the pool while the
/// draw goes on.
struct JobInputs {
    fb: *mut Framebuffer,
    plan: FragPlan,
    units: *const UnitPlan<'static>,
    n_units: usize,
    region: [i64; 4],
    nvary: usize,
    band_rows: usize,
}

// SAFETY: the pointers are only dereferenced by the job, while the `Rasterizer` that made
// them waits for it before touching the framebuffer again or ending its borrows (`wait`,
// called by every method that uses them and by `Drop`); `UnitPlan` and `Framebuffer` are
// `Sync`/`Send` (checked in `launch`).
unsafe impl Send for JobInputs {}

/// The rasterization side of a draw: the target, the plan and the pending batch.
pub struct Rasterizer<'a, 'f> {
    fb: &'f mut Framebuffer,
    plan: &'a FragPlan,
    units: &'a [UnitPlan<'a>],
    region: [i64; 4],
    nvary: usize,
    threads: bool,
    /// The batching constants.
    tune: Tuning,
    /// The batch being filled.
    batch: Batch,
    /// The other batch, `None` while a job draws it.
    spare: Option<Batch>,
    /// The job slot (batches handed to the pool go through it).
    job: Arc<Job>,
}

/// The pixel count of `t`'s box inside `region`.
fn box_area(t: &SetupTriangle, region: [i64; 4]) -> i64 {
    let w = t.bbox[2].min(region[2] - 1) - t.bbox[0].max(region[0]) + 1;
    let h = t.bbox[3].min(region[3] - 1) - t.bbox[1].max(region[1]) + 1;
    w.max(0) * h.max(0)
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
        let tune = tuning();
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
            job: pool.job,
        }
    }

    /// The framebuffer, after drawing the pending batch (for lines and points).
    pub fn target(&mut self, stats: &mut Stats) -> &mut Framebuffer {
        self.flush(stats);
        self.fb
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
        if !self.threads && area < self.tune.band_area {
            // Drawn at once, after the batched triangles before it (primitive order).
            self.flush(stats);
            raster_triangle(
                t,
                self.region,
                self.plan,
                self.units,
                &mut self.fb.target(),
                stats,
            );
            return;
        }
        let y0 = t.bbox[1].max(self.region[1]) as usize;
        let y1 = t.bbox[3].min(self.region[3] - 1) as usize;
        self.batch.push(
            t,
            self.nvary,
            y0 / self.tune.band_rows,
            y1 / self.tune.band_rows,
        );
        self.batch.work += area;
        if !self.threads {
            if self.batch.heads.len() >= MAX_BATCH || self.batch.work >= MAX_WORK_LOCAL {
                self.flush(stats);
            }
            return;
        }
        if self.batch.heads.len() >= MAX_BATCH || self.batch.work >= self.tune.max_work {
            // Hand the full batch to the pool and keep setting up the next one meanwhile.
            self.wait(stats);
            self.launch();
        }
    }

    /// Draws every pending triangle (waits for the pool, then draws the last batch, over
    /// threads when it is large enough).
    pub fn flush(&mut self, stats: &mut Stats) {
        self.wait(stats);
        if self.batch.heads.is_empty() {
            return;
        }
        let (plan, units, region, nvary) = (self.plan, self.units, self.region, self.nvary);
        if !self.threads && self.batch.heads.len() > 1 {
            // One band after the other, each with all of its triangles.
            let mut bands = self.fb.bands(self.tune.band_rows);
            for (band, bin) in bands.iter_mut().zip(&self.batch.bins) {
                draw_bin(&self.batch, bin, nvary, region, plan, units, band, stats);
            }
        } else if !self.threads || self.batch.work < PARALLEL_WORK {
            let mut target = self.fb.target();
            let mut t = SetupTriangle::default();
            for i in 0..self.batch.heads.len() {
                self.batch.load(i, nvary, &mut t);
                raster_triangle(&t, region, plan, units, &mut target, stats);
            }
        } else {
            let rows = self.tune.band_rows;
            let s = draw_bands(&self.batch, self.fb, nvary, region, plan, units, rows);
            stats.add_pixels(&s);
        }
        self.batch.clear();
    }

    /// Waits for the batch on the pool, if any, and takes it back with its counters.
    fn wait(&mut self, stats: &mut Stats) {
        if self.spare.is_some() {
            return;
        }
        let mut st = self.job.state.lock().unwrap_or_else(|e| e.into_inner());
        while st.busy {
            st = self.job.done.wait(st).unwrap_or_else(|e| e.into_inner());
        }
        stats.add_pixels(&st.stats);
        let mut b = st.batch.take().unwrap_or_default();
        drop(st);
        b.clear();
        self.spare = Some(b);
    }

    /// Hands the current batch to the pool (the previous one must be back) and starts
    /// filling the spare one.
    fn launch(&mut self) {
        fn shareable<T: Sync>() {}
        fn sendable<T: Send>() {}
        shareable::<UnitPlan<'static>>();
        sendable::<Framebuffer>();
        let spare = self.spare.take().unwrap_or_default();
        let batch = std::mem::replace(&mut self.batch, spare);
        {
            let mut st = self.job.state.lock().unwrap_or_else(|e| e.into_inner());
            st.batch = Some(batch);
            st.busy = true;
            st.stats = Stats::default();
        }
        let inputs = JobInputs {
            fb: &mut *self.fb,
            plan: *self.plan,
            units: self.units.as_ptr().cast(),
            n_units: self.units.len(),
            region: self.region,
            nvary: self.nvary,
            band_rows: self.tune.band_rows,
        };
        let job = Arc::clone(&self.job);
        rayon::spawn(move || {
            let inputs = inputs;
            let batch = job
                .state
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .batch
                .take();
            let mut s = Stats::default();
            if let Some(batch) = &batch {
                // SAFETY: see `JobInputs`: the rasterizer does not touch the framebuffer or
                // end the borrows of the units until this job reports done.
                let (fb, units) = unsafe {
                    (
                        &mut *inputs.fb,
                        std::slice::from_raw_parts(inputs.units, inputs.n_units),
                    )
                };
                s = draw_bands(
                    batch,
                    fb,
                    inputs.nvary,
                    inputs.region,
                    &inputs.plan,
                    units,
                    inputs.band_rows,
                );
            }
            let mut st = job.state.lock().unwrap_or_else(|e| e.into_inner());
            st.batch = batch;
            st.stats = s;
            st.busy = false;
            drop(st);
            job.done.notify_all();
        });
    }
}

/// Draws `batch` into `fb` with the pool, each band (of `band_rows` rows) drawing its own
/// bin.
fn draw_bands(
    batch: &Batch,
    fb: &mut Framebuffer,
    nvary: usize,
    region: [i64; 4],
    plan: &FragPlan,
    units: &[UnitPlan<'_>],
    band_rows: usize,
) -> Stats {
    let mut bands = fb.bands(band_rows);
    bands
        .par_iter_mut()
        .zip(batch.bins.par_iter())
        .map(|(band, bin)| {
            let mut s = Stats::default();
            draw_bin(batch, bin, nvary, region, plan, units, band, &mut s);
            s
        })
        .reduce(Stats::default, |mut a, b| {
            a.add_pixels(&b);
            a
        })
}

/// Draws the triangles of one band's bin into the band, counting into `s`.
#[allow(clippy::too_many_arguments)]
fn draw_bin(
    batch: &Batch,
    bin: &[u32],
    nvary: usize,
    region: [i64; 4],
    plan: &FragPlan,
    units: &[UnitPlan<'_>],
    band: &mut Target<'_>,
    s: &mut Stats,
) {
    // The band's share of a deferred glClear, written while the band is in the cache.
    band.resolve();
    if bin.is_empty() {
        return;
    }
    let mut t = SetupTriangle::default();
    for &i in bin {
        batch.load(i as usize, nvary, &mut t);
        raster_triangle(&t, region, plan, units, band, s);
    }
}

impl Drop for Rasterizer<'_, '_> {
    fn drop(&mut self) {
        // The job must be done before the borrows it uses end.
        let mut s = Stats::default();
        self.wait(&mut s);
        let pool = Pool {
            batches: [
                std::mem::take(&mut self.batch),
                self.spare.take().unwrap_or_default(),
            ],
            job: Arc::clone(&self.job),
        };
        POOL.with(|p| *p.borrow_mut() = pool);
    }
}
