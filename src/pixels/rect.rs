//! The textured rectangle behind glDrawPixels, glCopyPixels and glBitmap.
//!
//! Mesa's state tracker draws every pixel rectangle as a quad (`st_draw_quad`, a triangle
//! fan v0..v3) whose corners are the raster position `(x, y)` (already rounded to integers
//! by the caller) and `(x + w·zoomX, y + h·zoomY)`, converted to clip space as
//! `v / fb_size · 2 − 1` in f32 and back by the viewport transform of a viewport that
//! covers the framebuffer. The image is a texture sampled NEAREST with CLAMP_TO_EDGE at
//! normalised coordinates: s goes 0..1 left to right and t 0..1 bottom to top (top to
//! bottom with `flip_t`, for glCopyPixels, whose temporary texture is y-down).
//!
//! This module reproduces that draw: the same corner arithmetic, the draw module's clipping
//! of a quad that reaches past the framebuffer (whose new vertices change the planes'
//! rounding), llvmpipe's snapping, fill rule and attribute planes (through
//! [`setup_triangle`]), and `floor(s·w)` texel selection, so that fractional and negative
//! zooms pick the texels llvmpipe picks. Each covered span is handed to a callback with
//! its pixels' texels, and [`Fragments`] runs the per-fragment operations of
//! [`shade_chunk`] on them eight pixels at a time: in AVX2 registers where the 8-lane
//! fragment shader covers the plan and target
//! ([`crate::fragment::simd_gen::shade_ready_row`]), else lane by lane (compiled for AVX2
//! where the level has it).
//!
//! A triangle whose s plane does not vary along y and whose t plane does not vary along x
//! (every quad the clipper leaves whole, and most of its pieces) selects the same texel
//! column for a pixel column in every row: the columns are evaluated once per triangle,
//! the row once per span. The other triangles evaluate both planes per pixel.

use crate::fragment::span::{eval, shade_chunk, unorm8, ChunkColors, Fused, Madd, Unfused, LANES};
use crate::fragment::FragPlan;
use crate::framebuffer::Target;
use crate::geometry::clip::clip_triangle;
use crate::geometry::setup::{setup_triangle, CullMode, Plane, SetupResult, SetupTriangle};
use crate::geometry::{clip_mask, ClipVertex, Viewport, VARY_TEX};
use crate::stats::Stats;

/// A pixel rectangle to rasterize.
#[derive(Clone, Copy, Debug)]
pub struct Quad {
    /// Window x, y (GL, y-up) of the lower-left corner.
    pub x: i32,
    /// Window y.
    pub y: i32,
    /// Image width in texels.
    pub w: usize,
    /// Image height in texels.
    pub h: usize,
    /// glPixelZoom (1, 1 for bitmaps).
    pub zoom: [f32; 2],
    /// Window z in [0,1] (the raster position's).
    pub z: f32,
    /// Texture rows run top to bottom (glCopyPixels).
    pub flip_t: bool,
}

/// Framebuffer size and the draw region (y-down, exclusive high end).
#[derive(Clone, Copy, Debug)]
pub struct Dest {
    /// Framebuffer width.
    pub fb_w: usize,
    /// Framebuffer height.
    pub fb_h: usize,
    /// Scissor ∩ framebuffer, y-down `[x0, y0, x1, y1)`.
    pub region: [i64; 4],
    /// Whether the CPU fuses multiply-adds (llvmpipe does where it can).
    pub fma: bool,
    /// Whether the framebuffer's rows are y-down ([`crate::framebuffer::Framebuffer::y_flip`]).
    pub y_flip: bool,
}

/// Calls `f(tri, py, x, texels)` for every span of pixels `(x + i, py)` (y-down) the quad
/// covers inside the region, with the texel each pixel's NEAREST sampling selects (as an
/// index `row · w + col` into the image) in `texels[i]`.
pub fn rasterize<F: FnMut(&SetupTriangle, usize, usize, &[usize])>(q: &Quad, d: &Dest, mut f: F) {
    if q.w == 0 || q.h == 0 {
        return;
    }
    if d.fma {
        #[cfg(target_arch = "x86_64")]
        if std::is_x86_feature_detected!("fma") {
            // SAFETY: the CPU has FMA (checked).
            return unsafe { raster_fma(q, d, &mut f) };
        }
        raster_m::<Fused, F>(q, d, &mut f)
    } else {
        raster_m::<Unfused, F>(q, d, &mut f)
    }
}

/// [`raster_m`] fused, compiled with FMA: the per-pixel `fmuladd`s of the texel
/// coordinates are instructions, not calls to `fmaf`.
///
/// # Safety
/// The CPU has FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
unsafe fn raster_fma<F: FnMut(&SetupTriangle, usize, usize, &[usize])>(
    q: &Quad,
    d: &Dest,
    f: &mut F,
) {
    raster_m::<Fused, F>(q, d, f)
}

/// The texel index along one axis of size `n` at normalised coordinate `c`: `floor(c·n)`
/// clamped to `[0, n − 1]`. The saturating cast truncates, which is the floor for every
/// value the clamp keeps (negative values, −0 and NaN all give 0).
#[inline(always)]
fn texel_at(c: f32, nf: f32, n: usize) -> usize {
    ((c * nf) as usize).min(n - 1)
}

#[inline(always)]
fn raster_m<M: Madd, F: FnMut(&SetupTriangle, usize, usize, &[usize])>(
    q: &Quad,
    d: &Dest,
    f: &mut F,
) {
    let (fbw, fbh) = (d.fb_w as f32, d.fb_h as f32);
    let x0 = q.x as f32;
    let x1 = q.x as f32 + q.w as f32 * q.zoom[0];
    let y0 = q.y as f32;
    let y1 = q.y as f32 + q.h as f32 * q.zoom[1];
    let zc = q.z * 2.0 - 1.0;
    let vp = Viewport::oriented(
        [0, 0, d.fb_w as i32, d.fb_h as i32],
        [0.0, 1.0],
        d.fb_h,
        d.y_flip,
    );
    let (t_bot, t_top) = if q.flip_t { (0.0, 1.0) } else { (1.0, 0.0) };
    let corner = |x: f32, y: f32, s: f32, t: f32| {
        let clip = [x / fbw * 2.0 - 1.0, y / fbh * 2.0 - 1.0, zc, 1.0];
        let mut v = ClipVertex {
            clip,
            win: vp.apply_shader(clip, d.fma),
            ..Default::default()
        };
        v.vary[VARY_TEX] = s;
        v.vary[VARY_TEX + 1] = t;
        v
    };
    let v = [
        corner(x0, y1, 0.0, t_bot),
        corner(x1, y1, 1.0, t_bot),
        corner(x1, y0, 1.0, t_top),
        corner(x0, y0, 0.0, t_top),
    ];
    let (wf, hf) = (q.w as f32, q.h as f32);
    let mut texels = Vec::new();
    let mut cols = Columns::default();
    quad_spans_clipped(&v, &vp, d.region, |tri, py, lo, hi| {
        let fy = py as f32;
        let (ps, pt) = (&tri.vary[VARY_TEX], &tri.vary[VARY_TEX + 1]);
        texels.clear();
        if ps.dady == 0.0 && pt.dadx == 0.0 {
            // s varies along x only and t along y only (every unclipped quad): a
            // `madd(0, f, v)` is `v` up to the sign of a zero, which selects the same
            // texel, so each column's texel holds for every row and each row's for every
            // column.
            let (x0, x1) = (
                tri.bbox[0].max(d.region[0]),
                tri.bbox[2].min(d.region[2] - 1),
            );
            let cs = cols.of(ps, (x0, x1), |px| {
                texel_at(eval::<M>(ps, px as f32, fy), wf, q.w)
            });
            let base = texel_at(eval::<M>(pt, lo as f32, fy), hf, q.h) * q.w;
            let span = &cs[(lo - x0) as usize..=(hi - x0) as usize];
            texels.extend(span.iter().map(|&c| base + c));
        } else {
            texels.extend((lo..=hi).map(|px| {
                let fx = px as f32;
                let s = eval::<M>(ps, fx, fy);
                let t = eval::<M>(pt, fx, fy);
                texel_at(t, hf, q.h) * q.w + texel_at(s, wf, q.w)
            }));
        }
        f(tri, py as usize, lo as usize, &texels);
    });
}

/// The texel column of each pixel column `x0..=x1` of a triangle whose s plane does not
/// vary along y, kept while the plane and the range stay the same (the spans of one
/// triangle, and of the fan's second triangle when it shares the plane).
#[derive(Default)]
struct Columns {
    /// The plane's `a0`, `dadx` bits and the range the columns were computed for.
    key: Option<(u32, u32, i64, i64)>,
    /// `cols[x − x0]`.
    cols: Vec<usize>,
}

impl Columns {
    /// The columns of `range` under plane `p`, computed by `col(x)` when not cached.
    #[inline(always)]
    fn of(&mut self, p: &Plane, range: (i64, i64), col: impl Fn(i64) -> usize) -> &[usize] {
        let key = Some((p.a0.to_bits(), p.dadx.to_bits(), range.0, range.1));
        if self.key != key {
            self.key = key;
            self.cols.clear();
            self.cols.extend((range.0..=range.1).map(col));
        }
        &self.cols
    }
}

/// Calls `f` for each pixel (px, py) inside `region` (x0, y0, x1, y1, end exclusive) that
/// the quad `v` covers, drawn as the fan (v0, v1, v2), (v0, v2, v3) with llvmpipe's setup
/// and the rasterizer state of its blitter and `st_draw_quad` (no culling, bottom-left
/// fill rule), with the triangle that covers it.
pub(super) fn quad_pixels(
    v: &[ClipVertex; 4],
    region: [i64; 4],
    mut f: impl FnMut(&SetupTriangle, i64, i64),
) {
    let mut tri = SetupTriangle::default();
    for [a, b, c] in [[0, 1, 2], [0, 2, 3]] {
        tri_spans(
            [&v[a], &v[b], &v[c]],
            region,
            &mut tri,
            &mut |t, py, lo, hi| {
                for px in lo..=hi {
                    f(t, px, py);
                }
            },
        );
    }
}

/// Sets up triangle `v` under the rasterizer state of [`quad_pixels`] into `tri` and calls
/// `f(tri, py, lo, hi)` for each span of pixels `lo..=hi` of row `py` it covers inside
/// `region`.
fn tri_spans(
    v: [&ClipVertex; 3],
    region: [i64; 4],
    tri: &mut SetupTriangle,
    f: &mut impl FnMut(&SetupTriangle, i64, i64, i64),
) {
    let cull = CullMode {
        front: false,
        back: false,
        front_ccw: true,
        top_left: false,
    };
    if !matches!(
        setup_triangle(v, VARY_TEX + 2, cull, None, tri),
        SetupResult::Draw
    ) {
        return;
    }
    for py in tri.bbox[1].max(region[1])..=tri.bbox[3].min(region[3] - 1) {
        let (lo, hi) = tri.cut_span(
            py,
            tri.bbox[0].max(region[0]),
            tri.bbox[2].min(region[2] - 1),
        );
        if lo <= hi {
            f(tri, py, lo, hi);
        }
    }
}

/// [`quad_pixels`], span by span, for a quad whose corners may lie outside the clip volume (a raster
/// position near the edge, a large zoom): llvmpipe's draw module clips each fan triangle
/// ([`clip_triangle`], no guard band) and sets up the pieces, whose planes start from the
/// new vertices and so round differently from the unclipped triangle's (measured: a 96x96
/// image at x = 341 with zoom 2.5 on a 512-wide buffer picks the lower texel at 31 of the
/// pixel centres that fall exactly on a texel edge in each row).
fn quad_spans_clipped(
    v: &[ClipVertex; 4],
    vp: &Viewport,
    region: [i64; 4],
    mut f: impl FnMut(&SetupTriangle, i64, i64, i64),
) {
    let v: [ClipVertex; 4] = std::array::from_fn(|i| ClipVertex {
        mask: clip_mask(v[i].clip, false),
        ..v[i]
    });
    let ucp = crate::geometry::clip::UserPlanes::default();
    let mut tri = SetupTriangle::default();
    for [a, b, c] in [[0, 1, 2], [0, 2, 3]] {
        let (ma, mb, mc) = (v[a].mask, v[b].mask, v[c].mask);
        if ma & mb & mc != 0 {
            continue;
        }
        let or = ma | mb | mc;
        let vs = [&v[a], &v[b], &v[c]];
        if or == 0 {
            tri_spans(vs, region, &mut tri, &mut f);
            continue;
        }
        clip_triangle(vs, or, &ucp, vp, VARY_TEX + 2, 0, None, |p, q, r| {
            tri_spans([p, q, r], region, &mut tri, &mut f)
        });
    }
}

/// The per-fragment operations (alpha, stencil, depth tests, blending or logic op, masks)
/// for single fragments of a pixel rectangle.
pub struct Fragments<'a, 'b> {
    /// What the fragment stage does.
    pub plan: &'a FragPlan,
    /// The framebuffer.
    pub target: Target<'b>,
    /// Work counters.
    pub stats: &'a mut Stats,
    /// The 8-lane shader's per-triangle plan for the last face it drew
    /// ([`Self::ready_avx2fma`]): made once, not for every chunk of 8 pixels, where it
    /// was 7% of a frame of pixel rectangles (`pushattrib_pixels`).
    #[cfg(target_arch = "x86_64")]
    gen: Option<(bool, crate::fragment::simd_gen::GenPlan)>,
}

impl<'a, 'b> Fragments<'a, 'b> {
    /// The fragment stage of `plan` into `target`, counted in `stats`.
    pub fn new(plan: &'a FragPlan, target: Target<'b>, stats: &'a mut Stats) -> Self {
        Fragments {
            plan,
            target,
            stats,
            #[cfg(target_arch = "x86_64")]
            gen: None,
        }
    }
    /// The fragments of up to [`LANES`] consecutive pixels of row `py` from `x` on, each
    /// with the shader colour `color(lane)` or none (`None`: no fragment); their depth is
    /// the triangle's z plane. As [`Self::put`] for each one in turn: the pixels differ, so
    /// no fragment's tests or blending see another's result.
    pub fn put_chunk(
        &mut self,
        tri: &SetupTriangle,
        py: usize,
        x: usize,
        color: impl Fn(usize) -> Option<[f32; 4]>,
    ) {
        let mut c = [[0u8; LANES]; 4];
        let mut cf = [[0f32; LANES]; 4];
        let mut live = [false; LANES];
        for (l, live) in live.iter_mut().enumerate() {
            if let Some(rgba) = color(l) {
                *live = true;
                for k in 0..4 {
                    c[k][l] = unorm8(rgba[k]);
                    cf[k][l] = rgba[k];
                }
            }
        }
        if !live.contains(&true) {
            return;
        }
        self.shade(tri, py, x, live, &c, &cf);
    }

    /// [`Self::put_chunk`] with the colours already converted to unorm8, for a target that
    /// is not wide (whose conversion that is: [`unorm8`] of the shader colour).
    pub fn put_chunk8(
        &mut self,
        tri: &SetupTriangle,
        py: usize,
        x: usize,
        color: impl Fn(usize) -> Option<[u8; 4]>,
    ) {
        debug_assert!(self.target.wide.is_none());
        let mut c = [[0u8; LANES]; 4];
        let mut live = [false; LANES];
        for (l, live) in live.iter_mut().enumerate() {
            if let Some(rgba) = color(l) {
                *live = true;
                for k in 0..4 {
                    c[k][l] = rgba[k];
                }
            }
        }
        if !live.contains(&true) {
            return;
        }
        self.shade(tri, py, x, live, &c, &[[0f32; LANES]; 4]);
    }

    /// One fragment of shader colour `rgba` at `(px, py)`; its depth is the triangle's z
    /// plane (constant over a pixel rectangle) or `z` when given (depth images). An 8-bit
    /// target gets the colour converted to unorm8, a wide one converts it at its own
    /// precision.
    pub fn put(
        &mut self,
        tri: &SetupTriangle,
        px: usize,
        py: usize,
        rgba: [f32; 4],
        z: Option<f32>,
    ) {
        let mut c = [[0u8; LANES]; 4];
        let mut cf = [[0f32; LANES]; 4];
        for k in 0..4 {
            c[k][0] = unorm8(rgba[k]);
            cf[k][0] = rgba[k];
        }
        let mut live = [false; LANES];
        live[0] = true;
        let zt;
        let t = match z {
            Some(z) => {
                let mut t2 = tri.clone();
                t2.z.a0 = z;
                t2.z.dadx = 0.0;
                t2.z.dady = 0.0;
                zt = t2;
                &zt
            }
            None => tri,
        };
        self.shade(t, py, px, live, &c, &cf);
    }

    /// Runs the per-fragment operations on the `live` lanes of the chunk at `x` in row
    /// `py` with colours `c` (and `cf` for a wide target); compiled for AVX2 where the
    /// level has it (the same operations: no multiply-add is fused in either).
    fn shade(
        &mut self,
        t: &SetupTriangle,
        py: usize,
        px: usize,
        live: [bool; LANES],
        c: &[[u8; LANES]; 4],
        cf: &[[f32; LANES]; 4],
    ) {
        #[cfg(target_arch = "x86_64")]
        {
            let isa = crate::cpu::isa();
            if isa.avx2() && crate::fragment::simd_gen::plan_ok(self.plan, &self.target) {
                // SAFETY: the level is the AVX2 one (`Isa::avx2`: AVX2 with FMA), so the
                // CPU has these features; the plan and target are ones the 8-lane shader
                // takes.
                return unsafe { self.ready_avx2fma(t, py, px, live, c, cf) };
            }
            if isa.avx2() {
                // SAFETY: the level is an AVX2 one, so the CPU has these features.
                return unsafe { self.shade_avx2(t, py, px, live, c, cf) };
            }
        }
        self.shade_any(t, py, px, live, c, cf)
    }

    /// [`Self::shade`] on 8 lanes ([`crate::fragment::simd_gen::shade_ready_row`]: the
    /// same bytes and counts as [`Self::shade_any`]), compiled for AVX2 and FMA.
    /// Multiply-adds fuse as the plan says (`FragPlan::fma`: a float blend); the z plane
    /// of a pixel rectangle is constant, so its evaluation is the same fused or not.
    ///
    /// # Safety
    /// The CPU has AVX2, FMA, POPCNT, BMI1, BMI2 and LZCNT;
    /// [`crate::fragment::simd_gen::plan_ok`] accepts the plan and target.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma,popcnt,bmi1,bmi2,lzcnt")]
    unsafe fn ready_avx2fma(
        &mut self,
        t: &SetupTriangle,
        py: usize,
        px: usize,
        live: [bool; LANES],
        c: &[[u8; LANES]; 4],
        cf: &[[f32; LANES]; 4],
    ) {
        use crate::fragment::simd_gen::{shade_ready_row, GenPlan};
        let g = match self.gen {
            Some((front, g)) if front == t.front => g,
            _ => {
                let g = GenPlan::new(self.plan, t, &[]);
                self.gen = Some((t.front, g));
                g
            }
        };
        let (p, fb, st) = (self.plan, &mut self.target, &mut *self.stats);
        // SAFETY: forwarded from the caller; the chunk's live lanes lie inside row `py`.
        unsafe {
            if p.depth.is_some() {
                shade_ready_row::<true, true>(t, p, &g, fb, py, px, &live, c, cf, st)
            } else {
                shade_ready_row::<true, false>(t, p, &g, fb, py, px, &live, c, cf, st)
            }
        }
    }

    /// [`Self::shade_any`] compiled for AVX2.
    ///
    /// # Safety
    /// The CPU has AVX2, POPCNT, BMI1, BMI2 and LZCNT.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,popcnt,bmi1,bmi2,lzcnt")]
    unsafe fn shade_avx2(
        &mut self,
        t: &SetupTriangle,
        py: usize,
        px: usize,
        live: [bool; LANES],
        c: &[[u8; LANES]; 4],
        cf: &[[f32; LANES]; 4],
    ) {
        self.shade_any(t, py, px, live, c, cf)
    }

    /// [`Self::shade`]'s body.
    #[inline(always)]
    fn shade_any(
        &mut self,
        t: &SetupTriangle,
        py: usize,
        px: usize,
        live: [bool; LANES],
        c: &[[u8; LANES]; 4],
        cf: &[[f32; LANES]; 4],
    ) {
        let src = if self.target.wide.is_some() {
            ChunkColors::ReadyWide(c, cf)
        } else {
            ChunkColors::Ready(c)
        };
        let (p, fb, st) = (self.plan, &mut self.target, &mut *self.stats);
        // The z plane is constant, so fused and unfused evaluation agree.
        if p.depth.is_some() {
            shade_chunk::<Unfused, true, false, false, true>(t, p, &[], src, fb, py, px, live, st)
        } else {
            shade_chunk::<Unfused, false, false, false, true>(t, p, &[], src, fb, py, px, live, st)
        }
    }
}

#[cfg(test)]
#[path = "rect_tests.rs"]
mod tests;
