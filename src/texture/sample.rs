//! Texel filtering with llvmpipe's arithmetic (docs/llvmpipe-rules.md §9.2).
//!
//! - **AoS path** (8-bit formats with REPEAT/CLAMP_TO_EDGE, no anisotropy): texel indices
//!   and 8-bit weights from [`wrap::aos_linear`]; each lerp is
//!   `v0 + ((w·(v1 − v0) + 128) >> 8)` (pmulhrsw), x for both rows then y; the LINEAR mip
//!   blend uses `trunc(fpart·256)` with the same lerp; the result is `u as f32 · f32(1/255)`.
//! - **SoA path** (GL_CLAMP, CLAMP_TO_BORDER, MIRRORED_REPEAT, anisotropic): texels are
//!   converted to float first, weights are `u − floor(u)` of `u = s·size − 0.5`, and every
//!   lerp is `fmuladd(w, v1 − v0, v0)`, fused exactly when the CPU has FMA (as LLVM does).
//! - **Anisotropic**: not llvmpipe's EWA; see [`sample_quad_aniso`].

use super::lod::{self, Lod};
use super::wrap;
use super::{Filter, Level, MipFilter, UnitPlan};

/// f32(1/255), the unorm8 → float factor.
pub const INV_255: f32 = 1.0 / 255.0;

/// Whether the float lerps fuse, as llvmpipe's `llvm.fmuladd` does on an FMA CPU: the
/// level's choice ([`crate::cpu::level`]).
pub fn has_fma() -> bool {
    crate::cpu::isa().fused()
}

/// The 8.8 fixed-point lerp of the AoS path.
#[inline(always)]
pub fn lerp8(a: u8, b: u8, w: i32) -> u8 {
    (a as i32 + ((w * (b as i32 - a as i32) + 128) >> 8)) as u8
}

/// The float lerp of the SoA path: `fmuladd(w, b − a, a)`.
#[inline(always)]
pub fn lerpf(fma: bool, w: f32, a: f32, b: f32) -> f32 {
    if fma {
        w.mul_add(b - a, a)
    } else {
        w * (b - a) + a
    }
}

#[inline(always)]
pub(crate) fn lerp8x4(a: [u8; 4], b: [u8; 4], w: i32) -> [u8; 4] {
    each4!(|c| lerp8(a[c], b[c], w))
}

#[inline(always)]
pub(crate) fn lerpfx4(fma: bool, w: f32, a: [f32; 4], b: [f32; 4]) -> [f32; 4] {
    each4!(|c| lerpf(fma, w, a[c], b[c]))
}

#[inline(always)]
pub(crate) fn to_float(v: [u8; 4]) -> [f32; 4] {
    each4!(|c| v[c] as f32 * INV_255)
}

/// A texel as the float (SoA) path sees it: `u·f32(1/255)`, or through the plan's decode
/// tables (sRGB, signed, components of fewer than 8 bits; [`super::PlanExt::decode`]).
/// The one conversion of stored bytes to floats on that path: every float sampler uses it
/// or the same tables.
#[inline(always)]
pub(crate) fn texel_float(p: &UnitPlan<'_>, v: [u8; 4]) -> [f32; 4] {
    match p.ext.decode {
        Some(t) => each4!(|c| t[c][v[c] as usize]),
        None => to_float(v),
    }
}

/// Which filter and levels a LOD selects: `(filter, level0, level1, fraction)`.
#[inline(always)]
pub fn select_levels(p: &UnitPlan<'_>, lod: Lod) -> (Filter, usize, usize, f32) {
    if !lod.positive {
        return (p.mag_filter, p.first, p.first, 0.0);
    }
    let (first, last) = (p.first as i64, p.last as i64);
    match p.mip_filter {
        MipFilter::None => (p.min_filter, p.first, p.first, 0.0),
        MipFilter::Nearest => {
            let l = (lod.ipart as i64 + first).clamp(first, last) as usize;
            (p.min_filter, l, l, 0.0)
        }
        MipFilter::Linear => {
            let l0 = lod.ipart as i64 + first;
            if l0 < first {
                (p.min_filter, p.first, p.first, 0.0)
            } else if l0 >= last {
                (p.min_filter, p.last, p.last, 0.0)
            } else {
                (p.min_filter, l0 as usize, l0 as usize + 1, lod.fpart)
            }
        }
    }
}

/// One level, AoS (8-bit) filtering.
#[inline(always)]
fn aos_filter(p: &UnitPlan<'_>, img: &Level, filter: Filter, s: f32, t: f32) -> [u8; 4] {
    let (w, h) = (img.width, img.height);
    match filter {
        Filter::Nearest => {
            let x = wrap::aos_nearest(s, w, p.pot[0], p.wrap_s);
            let y = if p.dims == 2 {
                wrap::aos_nearest(t, h, p.pot[1], p.wrap_t)
            } else {
                0
            };
            img.texel(x, y)
        }
        Filter::Linear => {
            let (x0, x1, wx) = wrap::aos_linear(s, w, p.pot[0], p.wrap_s);
            if p.dims == 1 {
                return lerp8x4(img.texel(x0, 0), img.texel(x1, 0), wx);
            }
            let (y0, y1, wy) = wrap::aos_linear(t, h, p.pot[1], p.wrap_t);
            let r0 = lerp8x4(img.texel(x0, y0), img.texel(x1, y0), wx);
            let r1 = lerp8x4(img.texel(x0, y1), img.texel(x1, y1), wx);
            lerp8x4(r0, r1, wy)
        }
    }
}

/// One level, SoA (float) filtering with the border colour.
#[inline(always)]
fn soa_filter(p: &UnitPlan<'_>, img: &Level, filter: Filter, s: f32, t: f32) -> [f32; 4] {
    let (w, h) = (img.width, img.height);
    let fetch = |x: Option<usize>, y: Option<usize>| match (x, y) {
        (Some(x), Some(y)) if p.ext.floats => img.ftexel(y * w + x),
        (Some(x), Some(y)) => texel_float(p, img.texel(x, y)),
        _ => p.border,
    };
    let lerp = |w, a, b| lerpfx4(p.fma, w, a, b);
    soa_taps(p, filter, (w, h), (s, t), fetch, lerp)
}

/// SoA (float) filtering of a `w`×`h` level at (s, t) (1D when `p.dims` is 1): `get`
/// gives a texel's value (a coordinate outside the level is `None`: the border), `lerp`
/// blends two by a weight.
#[inline(always)]
pub(super) fn soa_taps<T>(
    p: &UnitPlan<'_>,
    filter: Filter,
    (w, h): (usize, usize),
    (s, t): (f32, f32),
    get: impl Fn(Option<usize>, Option<usize>) -> T,
    lerp: impl Fn(f32, T, T) -> T,
) -> T {
    let two_d = p.dims >= 2;
    match filter {
        Filter::Nearest => {
            let x = wrap::soa_nearest(s, w, p.pot[0], p.wrap_s);
            let y = if two_d {
                wrap::soa_nearest(t, h, p.pot[1], p.wrap_t)
            } else {
                Some(0)
            };
            get(x, y)
        }
        Filter::Linear => {
            let (x0, x1, wx) = wrap::soa_linear(s, w, p.pot[0], p.wrap_s);
            if !two_d {
                return lerp(wx, get(x0, Some(0)), get(x1, Some(0)));
            }
            let (y0, y1, wy) = wrap::soa_linear(t, h, p.pot[1], p.wrap_t);
            let r0 = lerp(wx, get(x0, y0), get(x1, y0));
            let r1 = lerp(wx, get(x0, y1), get(x1, y1));
            lerp(wy, r0, r1)
        }
    }
}

/// Samples one coordinate pair with a given LOD.
#[inline(always)]
pub fn sample(p: &UnitPlan<'_>, s: f32, t: f32, lod: Lod) -> [f32; 4] {
    sample_levels(p, select_levels(p, lod), s, t)
}

/// Samples one coordinate pair with the levels [`select_levels`] chose.
#[inline(always)]
fn sample_levels(p: &UnitPlan<'_>, sel: (Filter, usize, usize, f32), s: f32, t: f32) -> [f32; 4] {
    sample_levels_in(p, p.levels, sel, s, t)
}

/// [`sample_levels`] reading the images of `levels` (a cube map face) instead of the
/// plan's own.
#[inline(always)]
pub fn sample_levels_in(
    p: &UnitPlan<'_>,
    levels: &[Option<Level>],
    (filter, l0, l1, frac): (Filter, usize, usize, f32),
    s: f32,
    t: f32,
) -> [f32; 4] {
    let img = |l: usize| levels[l].as_ref().expect("complete texture");
    if p.aos {
        let a = aos_filter(p, img(l0), filter, s, t);
        if l1 == l0 {
            return to_float(a);
        }
        let b = aos_filter(p, img(l1), filter, s, t);
        to_float(lerp8x4(a, b, (frac * 256.0) as i32))
    } else {
        let a = soa_filter(p, img(l0), filter, s, t);
        if l1 == l0 {
            return a;
        }
        let b = soa_filter(p, img(l1), filter, s, t);
        lerpfx4(p.fma, frac, a, b)
    }
}

/// How many levels a capped anisotropic footprint is sharpened by at most (see
/// [`sample_quad_aniso`]).
const ANISO_SHARPEN: f32 = 0.5;

/// Anisotropic filtering (GL_TEXTURE_MAX_ANISOTROPY_EXT > 1) — our own algorithm, not
/// llvmpipe's EWA of nearest texels:
///
/// The quad's texel-space derivative vectors give the footprint's major and minor axis
/// lengths `Pmax ≥ Pmin`. `N = min(ceil(Pmax/Pmin), max_aniso)` probes are placed evenly
/// along the major axis, at `(k + 0.5)/N − 0.5` of its length around the pixel's coordinate;
/// each probe is a float (SoA) sample with the unit's filters at
/// `lod = log2(Pmax / N) − ½·min(1, log2(Pmax / (N·Pmin)))⁺` (a true log2, plus bias and
/// clamps), and the probes are averaged.
///
/// The sharpening term acts only when `max_aniso` caps N below the footprint's aspect
/// ratio: then a probe at `log2(Pmax/N)` blurs the minor axis by `Pmax/(N·Pmin)` more than
/// the pixel's own footprint, and a trilinear probe already blurs more than the box filter
/// a pixel integrates (its kernel's variance is about 3× a box of the same width, i.e.
/// ~0.8 of a level). Taking back up to half a level there, in proportion to the excess in
/// octaves, measured (tests/aniso_truth.rs, bench/filter_study.md) lower MAE and higher
/// PSNR than without at every level on the ground plane: at 2x it lifts PSNR by ~1.4 dB.
/// This is the classic footprint-assembly method: with N ≤ 16 trilinear probes it reads at
/// most 128 texels, about the cost of llvmpipe's EWA at 16x, and it filters with the mipmaps
/// instead of nearest texels, which is closer to a supersampled reference.
///
/// Inlined into the rasterizer's CPU-specific entry points (its floors and fused lerps
/// then compile to single instructions instead of library calls); the levels are chosen
/// once per quad.
#[inline(always)]
#[allow(clippy::needless_range_loop)]
pub fn sample_quad_aniso(p: &UnitPlan<'_>, s: [f32; 4], t: [f32; 4]) -> [[f32; 4]; 4] {
    let b = p.image(p.first);
    let (w, h) = (b.width as f32, b.height as f32);
    let (dsdx, dsdy) = (s[1] - s[0], s[2] - s[0]);
    let (dtdx, dtdy) = if p.dims == 2 {
        (t[1] - t[0], t[2] - t[0])
    } else {
        (0.0, 0.0)
    };
    let px2 = (dsdx * w).powi(2) + (dtdx * h).powi(2);
    let py2 = (dsdy * w).powi(2) + (dtdy * h).powi(2);
    let (major2, minor2, ax) = if px2 >= py2 {
        (px2, py2, (dsdx, dtdx))
    } else {
        (py2, px2, (dsdy, dtdy))
    };
    if !(major2.is_finite() && minor2.is_finite()) {
        let mut out = [[0.0f32; 4]; 4];
        for i in 0..4 {
            out[i] = sample(p, s[i], t[i], Lod::MAG);
        }
        return out;
    }
    let ratio = if minor2 > 0.0 {
        (major2 / minor2).sqrt()
    } else {
        f32::INFINITY
    };
    // `f32::clamp` written out (NaN stays NaN): the call was left out of line.
    let (c, hi) = (ratio.ceil(), p.max_anisotropy.max(1.0));
    let n = (if c < 1.0 {
        1.0
    } else if c > hi {
        hi
    } else {
        c
    }) as usize;
    // With the probe count capped below the aspect ratio, each probe's footprint
    // (Pmax / N) is wider than the pixel's minor axis: sharpen by up to half a level,
    // in proportion to the excess (in octaves, saturating at one).
    let excess = if ratio > n as f32 {
        (ratio / n as f32).log2().min(1.0)
    } else {
        0.0
    };
    let mut lodv =
        0.5 * major2.max(f32::MIN_POSITIVE).log2() - (n as f32).log2() - ANISO_SHARPEN * excess
            + p.lod.bias;
    if p.lod.min_max_equal {
        lodv = p.lod.min_lod;
    } else {
        if p.lod.apply_max {
            lodv = lodv.min(p.lod.max_lod);
        }
        if p.lod.apply_min {
            lodv = lodv.max(p.lod.min_lod);
        }
    }
    let levels = select_levels(p, Lod::from_value(lodv, p.mip_filter));
    let inv = 1.0 / n as f32;
    let mut out = [[0.0f32; 4]; 4];
    for i in 0..4 {
        let mut acc = [0.0f32; 4];
        for k in 0..n {
            let f = (k as f32 + 0.5) * inv - 0.5;
            let c = sample_levels(p, levels, s[i] + f * ax.0, t[i] + f * ax.1);
            for ch in 0..4 {
                acc[ch] += c[ch];
            }
        }
        for ch in 0..4 {
            out[i][ch] = acc[ch] * inv;
        }
    }
    out
}

/// The LOD helper re-exported for callers that evaluate per pixel.
pub use lod::compute as compute_lod;

#[cfg(test)]
mod tests {
    use super::super::env::Combine;
    use super::super::{BaseFormat, Level, LodParams, SamplerParams, UnitPlan, Wrap};
    use super::*;

    fn plan<'a>(levels: &'a [Option<Level>], aos: bool, wrap: Wrap, last: usize) -> UnitPlan<'a> {
        let sp = SamplerParams {
            min_filter: Filter::Linear,
            mag_filter: Filter::Linear,
            mip_filter: MipFilter::Linear,
            ..Default::default()
        };
        UnitPlan {
            levels,
            first: 0,
            last,
            dims: 2,
            min_filter: Filter::Linear,
            mag_filter: Filter::Linear,
            mip_filter: MipFilter::Linear,
            wrap_s: wrap,
            wrap_t: wrap,
            border: [0.0; 4],
            aos,
            pot: [true, true],
            max_anisotropy: 1.0,
            lod: LodParams::new(&sp, 0.0, false),
            needs_lod: true,
            base_format: BaseFormat::Rgba,
            env: Combine::derive(&Default::default(), BaseFormat::Rgba),
            fast: None,
            fma: false,
            ext: Default::default(),
        }
    }

    fn img(w: usize, h: usize, f: impl Fn(usize, usize) -> [u8; 4]) -> Option<Level> {
        let texels = (0..w * h).map(|i| f(i % w, i / w)).collect();
        Some(crate::texture::tests::rgba_level(w, h, texels))
    }

    /// A 2x2 texture, red = 0, 100 / 200, 255.
    fn red_2x2() -> Vec<Option<Level>> {
        vec![img(2, 2, |x, y| {
            [[[0u8, 100], [200, 255]][y][x], 0, 0, 255]
        })]
    }

    #[test]
    fn lerp8_matches_pmulhrsw_model() {
        assert_eq!(lerp8(0, 1, 128), 1);
        assert_eq!(lerp8(220, 31, 128), 126);
        assert_eq!(lerp8(89, 67, 128), 78);
        assert_eq!(lerp8(10, 10, 77), 10);
        assert_eq!(lerp8(0, 255, 255), 254);
    }

    #[test]
    fn aos_bilinear_hand_computed() {
        let lv = red_2x2();
        let p = plan(&lv, true, Wrap::ClampToEdge, 0);
        // s = 0.6: u·256 = 307.2 → 307 − 128 = 179 → x0 = 0, wx = 179
        // t = 0.4: u·256 = 204.8 → 205 − 128 = 77 → y0 = 0, wy = 77
        // row0: 0 + ((179·100 + 128) >> 8) = 70; row1: 200 + ((179·55 + 128) >> 8) = 238
        // y: 70 + ((77·168 + 128) >> 8) = 70 + 51 = 121
        let c = sample(&p, 0.6, 0.4, Lod::MAG);
        assert_eq!(c[0], 121.0 * INV_255);
        assert_eq!(c[3], 1.0);
    }

    #[test]
    fn soa_bilinear_float_weights() {
        let lv = red_2x2();
        let p = plan(&lv, false, Wrap::MirroredRepeat, 0);
        let c = sample(&p, 0.6, 0.4, Lod::MAG);
        let t = |v: u8| v as f32 * INV_255;
        let wx = 0.6f32 * 2.0 - 0.5;
        let wy = 0.4f32 * 2.0 - 0.5;
        let r0 = wx * (t(100) - t(0)) + t(0);
        let r1 = wx * (t(255) - t(200)) + t(200);
        assert_eq!(c[0], wy * (r1 - r0) + r0);
    }

    #[test]
    fn gl_clamp_blends_border() {
        let lv = vec![img(2, 2, |_, _| [255, 255, 255, 255])];
        let mut p = plan(&lv, false, Wrap::Clamp, 0);
        p.border = [0.0, 0.0, 0.0, 0.0];
        let c = sample(&p, 0.0, 0.5, Lod::MAG);
        assert_eq!(c, [0.5; 4]);
    }

    #[test]
    fn mip_linear_aos_weight_truncates() {
        let lv = vec![
            img(2, 2, |_, _| [0, 0, 0, 0]),
            img(1, 1, |_, _| [255, 255, 255, 255]),
        ];
        let p = plan(&lv, true, Wrap::Repeat, 1);
        let lod = Lod {
            positive: true,
            ipart: 0,
            fpart: 0.22,
        };
        // w = trunc(56.32) = 56 → 0 + ((56·255 + 128) >> 8) = 56
        assert_eq!(sample(&p, 0.5, 0.5, lod)[0], 56.0 * INV_255);
        // beyond the last level: last level, no blend
        let lod = Lod {
            positive: true,
            ipart: 3,
            fpart: 0.5,
        };
        assert_eq!(sample(&p, 0.5, 0.5, lod)[0], 1.0);
    }

    #[test]
    fn aniso_averages_along_major_axis() {
        let lv = vec![img(8, 8, |x, _| {
            let v = if x % 2 == 0 { 0 } else { 255 };
            [v, v, v, 255]
        })];
        let mut p = plan(&lv, false, Wrap::Repeat, 0);
        p.mip_filter = MipFilter::None;
        p.min_filter = Filter::Nearest;
        p.mag_filter = Filter::Nearest;
        p.max_anisotropy = 16.0;
        // 4 texels per pixel along x, 1 along y: 4 probes average the stripes to 0.5
        let s = [0.0, 0.5, 0.0, 0.5].map(|v: f32| v + 1.0 / 64.0);
        let t = [0.0, 0.0, 0.125, 0.125];
        let q = sample_quad_aniso(&p, s, t);
        assert!((q[0][0] - 0.5).abs() < 1e-6, "{:?}", q[0]);
    }
}
