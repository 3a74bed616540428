//! Counters of the work the pipeline did and skipped, readable by tests and printed at
//! context destruction when `SOFTGL_STATS=1` (after the knobs in effect, printed once:
//! [`crate::tuning::Tuning::report`]).

/// Work counters of one context (cumulative since creation or the last reset).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Draw calls that reached the pipeline.
    pub draws: u64,
    /// Vertices through the vertex stage.
    pub vertices: u64,
    /// Triangles assembled.
    pub triangles: u64,
    /// Triangles rejected whole because all vertices are outside one clip plane.
    pub tris_clip_rejected: u64,
    /// Triangles cut by the clipper.
    pub tris_clipped: u64,
    /// Triangles removed by face culling.
    pub tris_culled: u64,
    /// Triangles with zero area after snapping (or non-finite).
    pub tris_degenerate: u64,
    /// Triangles that reached the rasterizer.
    pub tris_rasterized: u64,
    /// Triangles whose bounding box missed the drawable region, and tiny ones (at most
    /// 2x2 pixel centres in their box) that setup found to cover no pixel centre.
    pub tris_offscreen: u64,
    /// Pairs of rasterized triangles drawn as one axis-aligned rectangle (both count in
    /// `tris_rasterized`; see `raster::batch`).
    pub tris_paired: u64,
    /// Fragments (covered pixels) generated.
    pub fragments: u64,
    /// Fragments that failed the depth test.
    pub depth_failed: u64,
    /// Fragments killed by the alpha test.
    pub alpha_failed: u64,
    /// Fragments killed by the stencil test.
    pub stencil_failed: u64,
    /// Stencil buffer reads.
    pub stencil_reads: u64,
    /// Depth buffer reads.
    pub depth_reads: u64,
    /// Colour buffer reads (blending, logic op).
    pub color_reads: u64,
    /// Colour buffer writes.
    pub color_writes: u64,
    /// Samples that passed every fragment test, counted only while an occlusion query is
    /// active (the draw's [`crate::fragment::FragPlan::count_samples`]).
    pub samples_passed: u64,
    /// Draws whose last batch was left drawing on the pool when the draw returned (chunks
    /// of a long glBegin/glEnd batch: see `Rasterizer::flush_detached`).
    pub draws_detached: u64,
}

impl Stats {
    /// Adds the per-pixel counters of a band rendered on another thread.
    pub fn add_pixels(&mut self, o: &Stats) {
        self.fragments += o.fragments;
        self.depth_failed += o.depth_failed;
        self.alpha_failed += o.alpha_failed;
        self.stencil_failed += o.stencil_failed;
        self.stencil_reads += o.stencil_reads;
        self.depth_reads += o.depth_reads;
        self.color_reads += o.color_reads;
        self.color_writes += o.color_writes;
        self.samples_passed += o.samples_passed;
    }

    /// Adds every counter of `o` (the work of a draw's other thread).
    pub fn add(&mut self, o: &Stats) {
        self.draws += o.draws;
        self.vertices += o.vertices;
        self.triangles += o.triangles;
        self.tris_clip_rejected += o.tris_clip_rejected;
        self.tris_clipped += o.tris_clipped;
        self.tris_culled += o.tris_culled;
        self.tris_degenerate += o.tris_degenerate;
        self.tris_rasterized += o.tris_rasterized;
        self.tris_offscreen += o.tris_offscreen;
        self.tris_paired += o.tris_paired;
        self.draws_detached += o.draws_detached;
        self.add_pixels(o);
    }

    /// A multi-line human-readable report.
    pub fn report(&self) -> String {
        format!("{self:#?}")
    }
}
