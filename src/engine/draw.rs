//! The engine in the draw path: [`Walk`] takes the rows of a triangle's chunks with the
//! units' sampled texels (the rasterizer's general textured walk samples them), gathers
//! up to [`MAX_BATCH`] rows, and runs the state's cached program over them; it counts
//! what the hand-written shaders count ([`Stats`]).
//!
//! The rows of one triangle never overlap, so deferring them to the end of a batch keeps
//! the order of every pixel's writes; [`Walk::finish`] runs the last batch before the
//! next triangle.

use super::cache;
use super::exec::{ChunkIn, Io, Program, Scratch, MAX_BATCH};
use super::ff::FfState;
use super::lower::planes_of;
use crate::fragment::span::{TexLanes, LANES};
use crate::fragment::FragPlan;
use crate::framebuffer::{ColorFormat, Target};
use crate::geometry::setup::SetupTriangle;
use crate::geometry::MAX_VARY;
use crate::pipe::MAX_TEXTURE_UNITS;
use crate::stats::Stats;
use crate::texture::UnitPlan;
use std::rc::Rc;

/// Input streams at most: four channels per unit.
const STREAMS: usize = 4 * MAX_TEXTURE_UNITS;

/// The uniform words a program's walk passes at most ([`Walk::with_program`]).
pub const MAX_UNIFORMS: usize = 64;

/// A walk's buffers, kept per thread between triangles.
struct State {
    scratch: Scratch,
    chunks: [ChunkIn; MAX_BATCH],
    /// Lanes inside the row of each chunk (colour reads are counted per row).
    ns: [u8; MAX_BATCH],
    live_out: [u8; MAX_BATCH],
    /// Stream s of chunk k at `s * MAX_BATCH + k`.
    streams: Vec<[u32; 8]>,
    planes: [[f32; 3]; 2 + MAX_VARY],
    /// A program walk's uniforms ([`Walk::with_program`]).
    uniforms: [f32; MAX_UNIFORMS],
    len: usize,
}

impl State {
    fn new() -> Box<State> {
        let chunk = ChunkIn {
            idx: 0,
            fx: 0.0,
            fy: 0.0,
            live: 0,
        };
        Box::new(State {
            scratch: Scratch::default(),
            chunks: [chunk; MAX_BATCH],
            ns: [0; MAX_BATCH],
            live_out: [0; MAX_BATCH],
            streams: vec![[0; 8]; STREAMS * MAX_BATCH],
            planes: [[0.0; 3]; 2 + MAX_VARY],
            uniforms: [0.0; MAX_UNIFORMS],
            len: 0,
        })
    }
}

thread_local! {
    /// The buffers of this thread's last walk.
    static STATE: std::cell::Cell<Option<Box<State>>> = const { std::cell::Cell::new(None) };
}

/// One triangle's walk through the engine (see the module doc).
pub struct Walk {
    st: Box<State>,
    prog: Rc<Program>,
    units: usize,
    blend: bool,
    writes: bool,
    count_samples: bool,
    /// The uniforms are the walk's own (else the triangle's flat varyings).
    own_uniforms: bool,
}

/// Which triangles the engine shades (`SOFTGL_ENGINE`).
#[inline]
pub fn mode() -> crate::tuning::Engine {
    crate::tuning::tuning().engine
}

/// Whether the engine writes `fb`: an RGBA8 layout, not a wide buffer.
fn target_ok(fb: &Target<'_>) -> bool {
    fb.wide.is_none()
        && matches!(
            fb.format,
            ColorFormat::Rgba | ColorFormat::Bgra | ColorFormat::Argb
        )
}

impl Walk {
    /// The walk of a triangle drawn with `plan` and `units` into `fb` (`persp`: the
    /// varyings take the perspective divide), when the state lowers (the caller checks
    /// [`enabled`]).
    pub fn new(
        plan: &FragPlan,
        units: &[UnitPlan<'_>],
        persp: bool,
        fb: &Target<'_>,
    ) -> Option<Walk> {
        if !target_ok(fb)
            || units.is_empty()
            || units.len() > MAX_TEXTURE_UNITS
            || !super::ff::covers(plan)
        {
            return None;
        }
        let mut envs = [None; MAX_TEXTURE_UNITS];
        for (e, u) in envs.iter_mut().zip(units) {
            *e = Some(u.env);
        }
        let prog = cache::program(&FfState {
            plan: *plan,
            envs,
            units: units.len() as u8,
            persp,
        })?;
        let st = STATE.with(|s| s.take()).unwrap_or_else(State::new);
        Some(Walk {
            st,
            prog,
            units: units.len(),
            blend: plan.blend.is_some(),
            writes: plan.color_mask != [false; 4],
            count_samples: plan.count_samples,
            own_uniforms: false,
        })
    }

    /// The walk of a triangle drawn with the compiled program `prog` into `fb` under
    /// `plan`, whose uniform `k` is the bits `uniforms[k]` and which reads the texels of
    /// `units` lookups ([`Walk::row`]); `None` when the target or the plan is not one the
    /// engine draws.
    pub fn with_program(
        prog: Rc<Program>,
        plan: &FragPlan,
        uniforms: &[u32; MAX_UNIFORMS],
        units: usize,
        fb: &Target<'_>,
    ) -> Option<Walk> {
        if !target_ok(fb) || !super::ff::covers(plan) || units > MAX_TEXTURE_UNITS {
            return None;
        }
        let mut st = STATE.with(|s| s.take()).unwrap_or_else(State::new);
        for (d, &u) in st.uniforms.iter_mut().zip(uniforms) {
            *d = f32::from_bits(u);
        }
        Some(Walk {
            st,
            prog,
            units,
            blend: plan.blend.is_some(),
            writes: plan.color_mask != [false; 4],
            count_samples: plan.count_samples,
            own_uniforms: true,
        })
    }

    /// Starts triangle `t` (its planes become the program's).
    #[inline]
    pub fn begin(&mut self, t: &SetupTriangle) {
        self.st.planes = planes_of(t);
    }

    /// Adds the row of 8 pixels from `x` in row `py` with its `live` lanes and the units'
    /// texels `tex`; runs the batch when it is full.
    #[inline]
    #[allow(clippy::too_many_arguments)]
    pub fn row(
        &mut self,
        t: &SetupTriangle,
        fb: &mut Target<'_>,
        py: usize,
        x: usize,
        live: &[bool; LANES],
        tex: &TexLanes,
        stats: &mut Stats,
    ) {
        let mut bits = 0u8;
        for (i, &l) in live.iter().enumerate() {
            bits |= u8::from(l) << i;
        }
        if bits == 0 {
            return;
        }
        stats.fragments += u64::from(bits.count_ones());
        let st = &mut *self.st;
        let k = st.len;
        st.chunks[k] = ChunkIn {
            idx: (py - fb.y0) * fb.width + x,
            fx: x as f32,
            fy: py as f32,
            live: bits,
        };
        st.ns[k] = LANES.min(fb.width - x) as u8;
        for (u, lanes) in tex.iter().enumerate().take(self.units) {
            for ch in 0..4 {
                let dst = &mut st.streams[(4 * u + ch) * MAX_BATCH + k];
                for (d, l) in dst.iter_mut().zip(lanes) {
                    *d = l[ch].to_bits();
                }
            }
        }
        st.len += 1;
        if st.len == MAX_BATCH {
            self.flush(t, fb, stats);
        }
    }

    /// Runs the gathered rows and counts their work.
    fn flush(&mut self, t: &SetupTriangle, fb: &mut Target<'_>, stats: &mut Stats) {
        let st = &mut *self.st;
        let n = st.len;
        if n == 0 {
            return;
        }
        st.len = 0;
        let mut inputs: [&[[u32; 8]]; STREAMS] = [&[]; STREAMS];
        for (s, i) in inputs.iter_mut().enumerate().take(4 * self.units) {
            *i = &st.streams[s * MAX_BATCH..s * MAX_BATCH + n];
        }
        let mut io = Io {
            planes: &st.planes,
            inputs: &inputs[..4 * self.units],
            color: &mut *fb.color,
            depth: &mut *fb.depth,
            uniforms: if self.own_uniforms {
                &st.uniforms
            } else {
                &t.flat
            },
            live_out: &mut st.live_out[..n],
        };
        let c = self.prog.run(&mut st.scratch, &mut io, &st.chunks[..n], n);
        stats.alpha_failed += c.killed;
        stats.depth_reads += c.depth_reads;
        stats.depth_failed += c.depth_failed;
        for (&out, &w) in st.live_out[..n].iter().zip(&st.ns[..n]) {
            let passed = u64::from(out.count_ones());
            if self.count_samples {
                stats.samples_passed += passed;
            }
            if self.writes && passed != 0 {
                if self.blend {
                    stats.color_reads += u64::from(w);
                }
                stats.color_writes += passed;
            }
        }
    }

    /// Runs the last rows of triangle `t` and gives the buffers back to the thread.
    #[inline]
    pub fn end(mut self, t: &SetupTriangle, fb: &mut Target<'_>, stats: &mut Stats) {
        self.flush(t, fb, stats);
        STATE.with(|s| s.set(Some(self.st)));
    }
}
