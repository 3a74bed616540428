//! The fixed-function vertex stage: object position to clip space with the combined
//! projection × modelview matrix, lighting (or the vertex colour), llvmpipe's colour clamp,
//! the fog coordinate, texture coordinates through the texture matrices, clip mask and
//! window position.

use super::fog::{eye_z_dp4, vertex_fog_coord};
use super::lighting::{eye_normal, eye_position, light_vertex, LightPlan};
use super::matrix::{Mat4, IDENTITY};
use super::mesa_matrix::MatFlags;
use super::point_size::PointAtten;
use super::texgen::{generate, NormalXform, TexGenPlan};
use crate::geometry::clip::UserPlanes;
use crate::geometry::fetch::VertexIn;
use crate::geometry::{
    clip_mask, user_clip_mask, ClipMask, ClipVertex, Viewport, VARY_FOG, VARY_SPEC, VARY_TEX,
};
use crate::pipe::FogState;
use crate::pipe::TexGenState;
use crate::pipe::MAX_TEXTURE_UNITS;

/// Per-draw constants of the vertex stage.
#[derive(Clone, Debug)]
pub struct VertexStage {
    /// Projection × modelview, multiplied as Mesa does.
    pub mvp: Mat4,
    /// The modelview (for eye coordinates).
    pub modelview: Mat4,
    /// The viewport transform.
    pub viewport: Viewport,
    /// Whether the host fuses multiply-adds (as llvmpipe then does).
    pub fma: bool,
    /// The enabled texture units, in order: (unit, texture matrix unless identity).
    pub tex_units: [(usize, Option<Mat4>); MAX_TEXTURE_UNITS],
    /// How many entries of `tex_units` are used.
    pub n_tex: usize,
    /// Texture coordinate generation of each entry of `tex_units`.
    pub texgen: [Option<TexGenPlan>; MAX_TEXTURE_UNITS],
    /// The eye-space normal transform, when some generation reads the normal.
    pub normal_xform: Option<NormalXform>,
    /// Lighting, when GL_LIGHTING is on.
    pub light: Option<LightPlan>,
    /// Fog, when GL_FOG is on.
    pub fog: Option<FogState>,
    /// User clip planes in clip space.
    pub ucp: UserPlanes,
    /// The enabled user clip planes (bits).
    pub ucp_enabled: u8,
    /// GL_COLOR_SUM without lighting: the secondary colour passes through.
    pub color_sum: bool,
    /// Point-size attenuation, when GL_POINT_DISTANCE_ATTENUATION is not (1, 0, 0).
    pub point_atten: Option<PointAtten>,
    /// Whether texture coordinate generation computes the eye position (which the
    /// attenuation then reuses).
    pub texgen_eye: bool,
    /// The least varying count [`Self::nvary`] gives (a fragment shader's varyings).
    pub min_vary: usize,
    /// With a vertex shader under GL_VERTEX_PROGRAM_TWO_SIDE, where its back colours
    /// start (after every other varying); the lighting's back colours otherwise.
    pub vs_back: Option<usize>,
}

/// llvmpipe's vertex colour clamp: `max(min(x, 1), 0)`, so NaN becomes 1, written as the
/// comparisons `minps`/`maxps` make (the second operand unless the first is less/greater),
/// so -0.0 becomes +0.0 at every optimisation level: `f32::max` leaves the sign of a zero
/// result unspecified (an unoptimised build kept -0.0 where the release build and the
/// vector block transform give +0.0).
#[inline]
pub fn clamp_color(v: f32) -> f32 {
    let m = if v < 1.0 { v } else { 1.0 };
    if m > 0.0 {
        m
    } else {
        0.0
    }
}

impl VertexStage {
    /// A stage without texturing, lighting or fog.
    pub fn new(mvp: Mat4, modelview: Mat4, viewport: Viewport, fma: bool) -> Self {
        VertexStage {
            mvp,
            modelview,
            viewport,
            fma,
            tex_units: [(0, None); MAX_TEXTURE_UNITS],
            n_tex: 0,
            texgen: [None; MAX_TEXTURE_UNITS],
            normal_xform: None,
            light: None,
            fog: None,
            ucp: UserPlanes::default(),
            ucp_enabled: 0,
            color_sum: false,
            point_atten: None,
            texgen_eye: false,
            min_vary: 0,
            vs_back: None,
        }
    }

    /// Adds texture unit `unit` with texture matrix `m` (skipped when it is the identity,
    /// as Mesa's fixed-function vertex program does).
    pub fn add_texture_unit(&mut self, unit: usize, m: &Mat4) {
        if self.n_tex < MAX_TEXTURE_UNITS {
            self.tex_units[self.n_tex] = (unit, (*m != IDENTITY).then_some(*m));
            self.n_tex += 1;
        }
    }

    /// Sets up texture coordinate generation for the units added so far. Returns whether
    /// any of it needs eye coordinates (which moves lighting into eye space).
    pub fn add_texgen(
        &mut self,
        st: &TexGenState,
        mv_flags: MatFlags,
        normalize: bool,
        rescale: bool,
    ) -> bool {
        let mut eye = false;
        let mut normal = false;
        for k in 0..self.n_tex {
            let p = TexGenPlan::new(&st.units[self.tex_units[k].0]);
            if let Some(p) = &p {
                eye |= p.needs_eye();
                normal |= p.needs_normal();
            }
            self.texgen[k] = p;
        }
        self.normal_xform =
            normal.then(|| NormalXform::new(&self.modelview, mv_flags, normalize, rescale));
        self.texgen_eye = eye;
        eye
    }

    /// Enables the user clip planes `enabled` of `eye_planes` (eye space), moving them to
    /// clip space with the inverse projection as Mesa's `_mesa_update_clip_plane` does.
    pub fn set_user_planes(
        &mut self,
        eye_planes: &[[f32; 4]; 8],
        enabled: u8,
        projection: &crate::fixed_function::matrix::MatrixStack,
    ) {
        self.ucp_enabled = enabled;
        for (i, (dst, p)) in self.ucp.planes.iter_mut().zip(eye_planes).enumerate() {
            if enabled & (1 << i) != 0 {
                *dst = crate::fixed_function::matrix::plane_times_inverse(projection, *p);
            }
        }
    }

    /// Whether back-face colours are computed (two-sided lighting, or a vertex shader's
    /// back colours).
    pub fn two_side(&self) -> bool {
        self.vs_back.is_some() || self.light.as_ref().is_some_and(|l| l.two_side())
    }

    /// Where the back colours start among the varyings (with [`Self::two_side`]).
    pub fn back_offset(&self) -> usize {
        self.vs_back.unwrap_or(VARY_TEX + 4 * self.n_tex)
    }

    /// The number of varying floats this stage writes.
    pub fn nvary(&self) -> usize {
        self.nvary_ff().max(self.min_vary)
    }

    /// [`Self::nvary`] from what this stage computes.
    fn nvary_ff(&self) -> usize {
        if self.two_side() {
            self.back_offset() + 8
        } else if self.n_tex > 0 {
            VARY_TEX + 4 * self.n_tex
        } else if self.fog.is_some() {
            VARY_FOG + 1
        } else if self.color_sum || self.light.as_ref().is_some_and(|l| l.separate_specular()) {
            VARY_SPEC + 4
        } else {
            4
        }
    }

    /// The clip-space position of object position `pos` and its clip mask: the first
    /// step of [`Self::run_into`], also used alone to find whether any vertex of a draw
    /// is outside the clip volume before its primitives are assembled.
    #[inline(always)]
    pub fn clip_position(&self, pos: [f32; 4]) -> ([f32; 4], ClipMask) {
        let clip = self.mvp.transform(pos);
        let mut mask = clip_mask(clip, self.viewport.halfz);
        if self.ucp_enabled != 0 {
            mask |= user_clip_mask(clip, &self.ucp.planes, self.ucp_enabled, self.fma);
        }
        (clip, mask)
    }

    /// Runs one vertex through the stage.
    #[inline]
    pub fn run(&self, v: &VertexIn) -> ClipVertex {
        let mut out = ClipVertex::default();
        self.run_into(v, &mut out);
        out
    }

    /// Runs one vertex through the stage into `out`, writing the position, the mask and
    /// the varyings this stage writes (the same fields for every vertex of a draw, so an
    /// entry reused within a draw needs nothing cleared).
    #[inline]
    pub fn run_into(&self, v: &VertexIn, out: &mut ClipVertex) {
        // On FMA levels the viewport transform and lighting's gallivm `pow` fuse their
        // multiply-adds, and `pow` floors: compiled without FMA (and SSE4.1) those are
        // calls into libm.
        #[cfg(target_arch = "x86_64")]
        if self.fma && crate::cpu::has_fma_instructions() {
            // SAFETY: the CPU has FMA.
            return unsafe { self.run_into_fma(v, out) };
        }
        self.run_into_any(v, out)
    }

    /// [`Self::run_into`] compiled with FMA (which implies SSE4.1's `roundss`).
    ///
    /// # Safety
    /// The CPU has FMA.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "fma")]
    #[inline(never)]
    unsafe fn run_into_fma(&self, v: &VertexIn, out: &mut ClipVertex) {
        self.run_into_any(v, out)
    }

    /// [`Self::run_into`]'s body, for whatever instruction set its caller is compiled for.
    #[inline(always)]
    pub(super) fn run_into_any(&self, v: &VertexIn, out: &mut ClipVertex) {
        let (clip, mask) = self.clip_position(v.pos);
        out.clip = clip;
        out.win = self.viewport.apply_shader(clip, self.fma);
        out.mask = mask;
        let mut eye = None;
        match &self.light {
            Some(lp) => {
                let e = lp
                    .needs_eye_position()
                    .then(|| eye_position(&self.modelview, v.pos));
                eye = e;
                let n = eye_normal(lp, v.normal);
                let lit = light_vertex(lp, e.unwrap_or([0.0, 0.0, 0.0, 1.0]), n, v.color);
                out.vary[..4].copy_from_slice(&lit.front.map(clamp_color));
                out.vary[VARY_SPEC..VARY_SPEC + 4]
                    .copy_from_slice(&lit.front_spec.map(clamp_color));
                if lp.two_side() {
                    let b = self.back_offset();
                    out.vary[b..b + 4].copy_from_slice(&lit.back.map(clamp_color));
                    out.vary[b + 4..b + 8].copy_from_slice(&lit.back_spec.map(clamp_color));
                }
            }
            None => {
                out.vary[..4].copy_from_slice(&v.color.map(clamp_color));
                if self.color_sum {
                    out.vary[VARY_SPEC..VARY_SPEC + 4]
                        .copy_from_slice(&v.secondary.map(clamp_color));
                }
            }
        }
        if let Some(f) = &self.fog {
            out.vary[VARY_FOG] = vertex_fog_coord(f, &self.modelview, v.pos, eye, v.fog_coord);
        }
        let lit_eye = eye;
        let n = self.normal_xform.map(|x| x.apply(v.normal));
        for (k, (unit, m)) in self.tex_units[..self.n_tex].iter().enumerate() {
            let mut tc = v.texcoord[*unit];
            if let Some(g) = &self.texgen[k] {
                let e = *eye.get_or_insert_with(|| eye_position(&self.modelview, v.pos));
                tc = generate(g, tc, v.pos, e, n.unwrap_or_default());
            }
            let tc = match m {
                Some(m) => m.transform(tc),
                None => tc,
            };
            out.vary[VARY_TEX + 4 * k..VARY_TEX + 4 * k + 4].copy_from_slice(&tc);
        }
        if let Some(pa) = &self.point_atten {
            // The program's eye position exists when lighting or eye-space texgen made it.
            let full = if self.texgen_eye { eye } else { lit_eye };
            let z = full.map_or_else(|| eye_z_dp4(&self.modelview, v.pos), |e| e[2]);
            out.psize = pa.size(z);
        }
    }
}
