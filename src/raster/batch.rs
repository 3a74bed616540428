//! Batches large triangles of a draw and rasterizes them in parallel over bands of rows.
//!
//! Each band of [`BAND_ROWS`] rows is owned by one thread at a time and receives every
//! triangle of the batch in order, so each pixel sees the same fragments in the same order
//! as single-threaded rendering: the images are byte-identical with threads on and off.
//! Small triangles are not worth a thread hand-off: they flush the batch and are drawn
//! directly.

use super::raster_triangle;
use crate::fragment::FragPlan;
use crate::framebuffer::Framebuffer;
use crate::geometry::setup::SetupTriangle;
use crate::stats::Stats;
use crate::texture::UnitPlan;
use rayon::prelude::*;

/// Rows per band (even, so 2x2 quads stay inside one band).
pub const BAND_ROWS: usize = 32;
/// A triangle whose box covers fewer pixels is drawn without batching.
const BIG_TRIANGLE: i64 = 2048;
/// Pixels of triangle boxes that make a batch worth splitting over threads.
const PARALLEL_WORK: i64 = 64 * 1024;
/// Triangles a batch holds at most.
const MAX_BATCH: usize = 256;

/// The rasterization side of a draw: the target, the plan and the pending batch.
pub struct Rasterizer<'a, 'f> {
    fb: &'f mut Framebuffer,
    plan: &'a FragPlan,
    units: &'a [UnitPlan<'a>],
    region: [i64; 4],
    threads: bool,
    batch: Vec<SetupTriangle>,
    work: i64,
}

/// The pixel count of `t`'s box inside `region`.
fn box_area(t: &SetupTriangle, region: [i64; 4]) -> i64 {
    let w = t.bbox[2].min(region[2] - 1) - t.bbox[0].max(region[0]) + 1;
    let h = t.bbox[3].min(region[3] - 1) - t.bbox[1].max(region[1]) + 1;
    w.max(0) * h.max(0)
}

impl<'a, 'f> Rasterizer<'a, 'f> {
    /// A rasterizer for one draw into `fb` clipped to `region`.
    pub fn new(
        fb: &'f mut Framebuffer,
        plan: &'a FragPlan,
        units: &'a [UnitPlan<'a>],
        region: [i64; 4],
    ) -> Self {
        Rasterizer {
            fb,
            plan,
            units,
            region,
            threads: crate::cpu::threads() > 1,
            batch: Vec::new(),
            work: 0,
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
        if self.threads && area >= BIG_TRIANGLE {
            self.batch.push(t.clone());
            self.work += area;
            if self.batch.len() >= MAX_BATCH {
                self.flush(stats);
            }
            return;
        }
        self.flush(stats);
        raster_triangle(
            t,
            self.region,
            self.plan,
            self.units,
            &mut self.fb.target(),
            stats,
        );
    }

    /// Draws the pending batch, over threads when it is large enough.
    pub fn flush(&mut self, stats: &mut Stats) {
        if self.batch.is_empty() {
            return;
        }
        let (plan, units, region) = (self.plan, self.units, self.region);
        if self.work < PARALLEL_WORK {
            let mut target = self.fb.target();
            for t in &self.batch {
                raster_triangle(t, region, plan, units, &mut target, stats);
            }
        } else {
            let batch = &self.batch;
            let mut bands = self.fb.bands(BAND_ROWS);
            let band_stats: Vec<Stats> = bands
                .par_iter_mut()
                .map(|band| {
                    let mut s = Stats::default();
                    for t in batch {
                        raster_triangle(t, region, plan, units, band, &mut s);
                    }
                    s
                })
                .collect();
            for s in &band_stats {
                stats.add_pixels(s);
            }
        }
        self.batch.clear();
        self.work = 0;
    }
}
