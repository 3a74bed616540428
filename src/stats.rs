//! Counters of the work the pipeline did and skipped, readable by tests and printed at
//! context destruction when `SOFTGL_STATS=1` (after the knobs in effect, printed once:
//! [`crate::tuning::Tuning::report`]).

/// The counters struct: each field a `u64` counter declared as `name: draw` (counted by
/// the thread that runs the draw) or `name: pixel` (also counted by the threads rendering
/// bands), and the sums [`Stats::add_pixels`] and [`Stats::add`] over those groups.
macro_rules! counters {
    (
        $(#[$m:meta])*
        pub struct $t:ident { $($(#[$fm:meta])* $f:ident: $kind:ident,)+ }
    ) => {
        $(#[$m])*
        pub struct $t {
            $($(#[$fm])* pub $f: u64,)+
        }

        impl $t {
            /// Adds the per-pixel counters of a band rendered on another thread.
            pub fn add_pixels(&mut self, o: &$t) {
                $(counters!(@add_if_pixel $kind self o $f);)+
            }

            /// Adds every counter of `o` (the work of a draw's other thread).
            pub fn add(&mut self, o: &$t) {
                $(self.$f += o.$f;)+
            }
        }
    };
    (@add_if_pixel pixel $s:ident $o:ident $f:ident) => {
        $s.$f += $o.$f
    };
    (@add_if_pixel draw $s:ident $o:ident $f:ident) => {};
}

counters! {
    /// Work counters of one context (cumulative since creation or the last reset).
    #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
    pub struct Stats {
        /// Draw calls that reached the pipeline.
        draws: draw,
        /// Draws with a current program whose fragment shader ran through the engine.
        program_draws: draw,
        /// Draws with a current program that drew nothing: a vertex shader, a fragment
        /// shader the engine does not run, or primitives other than filled triangles
        /// (see `shader::draw`).
        program_draws_refused: draw,
        /// Triangles of a program draw not drawn: the fragment state or the target is not
        /// one the engine draws (stencil, logic op, wide or sRGB buffers …).
        program_tris_refused: pixel,
        /// Draws without a fragment shader into an object with several draw buffers:
        /// only draw buffer 0 is written where fixed function is not lowered into the
        /// engine (Mesa writes the colour to each; `context::fbo_draw_buffers`).
        ff_draws_one_buffer: draw,
        /// Vertices through the vertex stage.
        vertices: draw,
        /// Triangles assembled.
        triangles: draw,
        /// Triangles rejected whole because all vertices are outside one clip plane.
        tris_clip_rejected: draw,
        /// Triangles cut by the clipper.
        tris_clipped: draw,
        /// Triangles removed by face culling.
        tris_culled: draw,
        /// Triangles with zero area after snapping (or non-finite).
        tris_degenerate: draw,
        /// Triangles that reached the rasterizer.
        tris_rasterized: draw,
        /// Triangles whose bounding box missed the drawable region, and tiny ones (at most
        /// 2x2 pixel centres in their box) that setup found to cover no pixel centre.
        tris_offscreen: draw,
        /// Pairs of rasterized triangles drawn as one axis-aligned rectangle (both count in
        /// `tris_rasterized`; see `raster::batch`).
        tris_paired: draw,
        /// Fragments (covered pixels) generated.
        fragments: pixel,
        /// Fragments that failed the depth test.
        depth_failed: pixel,
        /// Fragments killed by the alpha test.
        alpha_failed: pixel,
        /// Fragments killed by the stencil test.
        stencil_failed: pixel,
        /// Stencil buffer reads.
        stencil_reads: pixel,
        /// Depth buffer reads.
        depth_reads: pixel,
        /// Colour buffer reads (blending, logic op).
        color_reads: pixel,
        /// Colour buffer writes.
        color_writes: pixel,
        /// Samples that passed every fragment test, counted only while an occlusion query is
        /// active (the draw's [`crate::fragment::FragPlan::count_samples`]).
        samples_passed: pixel,
        /// Draws whose last batch was left drawing on the pool when the draw returned
        /// (glBegin/glEnd draws: see `Rasterizer::flush_detached`).
        draws_detached: draw,
        /// Draws that took over the batch the draw before them left on the pool (see
        /// `Rasterizer::adopt`) instead of waiting for it.
        draws_adopted: draw,
        /// Draws whose second half a pool thread set up while the draw's thread set up
        /// the first (see `raster::batch::side`).
        draws_offloaded: draw,
        /// Draws of lines or points drawn by two threads, each into its own band of rows
        /// (see `raster::banded`).
        draws_banded: draw,
    }
}

impl Stats {
    /// A multi-line human-readable report.
    pub fn report(&self) -> String {
        format!("{self:#?}")
    }
}
