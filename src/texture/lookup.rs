//! The shader lookups that the fixed-function units never make: a level-of-detail
//! argument (`texture2D(s, c, bias)`, `texture2DLod`, `textureLod`), `texelFetch` and
//! `textureSize`, each on a 2x2 quad of the program's values (Mesa 22.3's gallivm rules,
//! `lp_build_lod_selector`, `lp_build_fetch_texel`, `lp_build_size_query_soa`).
//!
//! # Level of detail
//! With a bias or a level-of-detail argument llvmpipe keeps one LOD per pixel, not per
//! quad:
//! - a bias is added to the quad's LOD as the general path computes it
//!   (`0.5 · fast_log2(rho²)` from the quad's differences, never the exponent-only fast
//!   path; a cube map's rho is each pixel's own), pixel by pixel;
//! - a level of detail replaces it (no log2 at all);
//! - then, as for every lookup, the sampler's quantised bias, `max_lod` and `min_lod`
//!   apply where llvmpipe applies them ([`lod::LodParams`]); GL_TEXTURE_MIN_LOD equal to
//!   MAX_LOD still forces `min_lod` and ignores the argument, and a texture that needs no
//!   LOD (one filter, no mipmaps) ignores it too;
//! - the LOD's integer part is x86's conversion (`cvtps2dq`): NaN and values of
//!   magnitude 2^31 or more are `i32::MIN`, so a LOD of +∞ minifies at the base level.
//!
//! Per-pixel LODs take llvmpipe's 8-bit path only where the minification and
//! magnification filters are the same; elsewhere the float path. Each pixel is sampled
//! with its own LOD forced into a copy of the plan ([`lod::LodParams::min_max_equal`]), one
//! quad sampling per distinct LOD of the quad.
//!
//! # texelFetch and textureSize
//! `texelFetch` reads texel (s, t) of level `first + l` with no filter, on the float
//! path's conversion; a level outside the texture's levels or a texel outside the level
//! gives zero in every channel the format has and 1 in alpha where it has none.
//! `textureSize` is `max(size >> l, 1)` of the base level per dimension, and zero when
//! `first + l` is not one of the texture's levels; llvmpipe takes `l` from the first
//! lane of its vector, softgl from each quad's first pixel.

use super::lod;
use super::{sample, BaseFormat, ExtKind, UnitPlan};

/// What a shader lookup's level-of-detail argument is (its `l` operand), or which of the
/// non-sampling lookups it is.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum LookupKind {
    /// No argument: the quad's LOD from its coordinates, as the fixed-function units.
    #[default]
    Implicit,
    /// A bias added to the quad's LOD, per pixel.
    Bias,
    /// The level of detail itself, per pixel.
    Lod,
    /// `texelFetch`: integer texel coordinates in s and t, the level in `l` (each an
    /// integer as f32).
    Fetch,
    /// `textureSize`: the size of level `l` in R, G (and B).
    Size,
}

/// The value which [`Lod::from_value`] turns into the levels llvmpipe takes for `v`:
/// `v` itself, except where x86's conversion gives `i32::MIN` for a positive LOD (2^31
/// or more: minification at the base level, which the smallest positive normal gives
/// with a zero fraction in the 8-bit path and a vanishing one in the float path).
fn as_forced(v: f32) -> f32 {
    if v >= 2_147_483_648.0 {
        f32::MIN_POSITIVE
    } else {
        v
    }
}

/// Each pixel's LOD before any bias, as the general path computes it: `0.5 ·
/// fast_log2(rho²)`, rho from the quad's differences at the base level (a cube map's
/// per pixel, from its own direction: `lp_build_cube_lookup`).
fn base_log2(u: &UnitPlan<'_>, s: [f32; 4], t: [f32; 4], r: [f32; 4]) -> [f32; 4] {
    let b = u.image(u.first);
    let log2 = |r2: f32| {
        let r2 = if r2.is_finite() { r2 } else { 0.0 };
        lod::fast_log2(r2) * 0.5
    };
    match &u.ext.kind {
        ExtKind::Cube(_) | ExtKind::CubeSeamless(_) => {
            std::array::from_fn(|i| log2(super::cube::pixel_rho(b.width as f32, i, s, t, r)))
        }
        ExtKind::Volume(v) => [log2(super::volume::quad_rho(u, v, s, t, r)); 4],
        ExtKind::Flat => {
            let q = lod::rho(u.dims, b.width as f32, b.height as f32, s, t);
            [log2(if u.dims > 1 { q } else { q * q }); 4]
        }
    }
}

/// Samples a quad (TL, TR, BL, BR) of a lookup with a per-pixel LOD argument `l`
/// (`kind`: [`LookupKind::Bias`] or [`LookupKind::Lod`]), with `r` for 3D, cube-map and
/// depth targets; pixels that are not `live` may receive any value.
pub fn sample_quad_lods(
    u: &UnitPlan<'_>,
    kind: LookupKind,
    (s, t, r): ([f32; 4], [f32; 4], Option<[f32; 4]>),
    l: [f32; 4],
    live: [bool; 4],
) -> [[f32; 4]; 4] {
    let quad = |p: &UnitPlan<'_>| match r {
        Some(r) => p.sample_quad_str(s, t, r),
        None => p.sample_quad(s, t),
    };
    let mut p = u.clone();
    p.aos = u.aos && u.min_filter == u.mag_filter;
    if !u.needs_lod || u.lod.min_max_equal {
        // The argument is ignored (`lp_build_sample_common`, the min = max LOD case).
        return quad(&p);
    }
    let base = match kind {
        LookupKind::Bias => {
            let q = base_log2(u, s, t, r.unwrap_or([0.0; 4]));
            std::array::from_fn(|i| q[i] + l[i])
        }
        _ => l,
    };
    let lods = base.map(|v| as_forced(u.lod.adjust(v)));
    p.lod.min_max_equal = true;
    let mut out = [[0.0; 4]; 4];
    let mut done = [false; 4];
    for i in 0..4 {
        if done[i] || !live[i] {
            continue;
        }
        p.lod.min_lod = lods[i];
        let v = quad(&p);
        for j in i..4 {
            if live[j] && lods[j].to_bits() == lods[i].to_bits() {
                out[j] = v[j];
                done[j] = true;
            }
        }
    }
    out
}

/// The value of a texel outside the texture: zero in every channel the base format has,
/// 1 in alpha where it has none (the format swizzle of zero).
fn outside(base: BaseFormat) -> [f32; 4] {
    match base {
        BaseFormat::Alpha
        | BaseFormat::Intensity
        | BaseFormat::LuminanceAlpha
        | BaseFormat::Rgba => [0.0; 4],
        _ => [0.0, 0.0, 0.0, 1.0],
    }
}

/// x86's float to integer conversion of an integral value (`i32::MIN` out of range).
fn int(v: f32) -> i64 {
    if v.abs() < 2_147_483_648.0 {
        v as i64
    } else {
        i64::from(i32::MIN)
    }
}

/// The level `first + l` of `u`, when it is one of its levels.
fn level(u: &UnitPlan<'_>, l: f32) -> Option<usize> {
    let lv = int(l) + u.first as i64;
    (u.first as i64..=u.last as i64)
        .contains(&lv)
        .then_some(lv as usize)
}

/// Whether `texelFetch` and `textureSize` can read unit `u`: a flat (1D or 2D) target;
/// `texelFetch` also needs a colour texture (depth texels are stored packed).
pub fn reads(u: &UnitPlan<'_>, kind: LookupKind) -> bool {
    let flat = matches!(u.ext.kind, ExtKind::Flat);
    match kind {
        LookupKind::Fetch => flat && u.ext.depth.is_none(),
        LookupKind::Size => flat,
        _ => true,
    }
}

/// `texelFetch` of one pixel: texel (`s`, `t`) of level `first + l` (integers as f32).
pub fn fetch(u: &UnitPlan<'_>, s: f32, t: f32, l: f32) -> [f32; 4] {
    let Some(lv) = level(u, l) else {
        return outside(u.base_format);
    };
    let img = u.image(lv);
    let (x, y) = (int(s), int(t));
    let y = if u.dims == 1 { 0 } else { y };
    if !(0..img.width as i64).contains(&x) || !(0..img.height as i64).contains(&y) {
        return outside(u.base_format);
    }
    let (x, y) = (x as usize, y as usize);
    if u.ext.floats {
        img.ftexel(y * img.width + x)
    } else {
        sample::texel_float(u, img.texel(x, y))
    }
}

/// `textureSize` at level `l` (an integer as f32): the width, the height (2D) as f32.
pub fn size(u: &UnitPlan<'_>, l: f32) -> [f32; 4] {
    if level(u, l).is_none() {
        return [0.0; 4];
    }
    let b = u.image(u.first);
    let n = int(l) as u32;
    let dim = |v: usize| ((v >> n.min(63)).max(1)) as f32;
    match u.dims {
        1 => [dim(b.width), 0.0, 0.0, 0.0],
        _ => [dim(b.width), dim(b.height), 0.0, 0.0],
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture::lod::LodParams;
    use crate::texture::Lod;

    #[test]
    fn adjust_adds_the_sampler_bias_then_clamps_max_then_min() {
        let p = LodParams {
            bias: 0.5,
            min_lod: 1.0,
            max_lod: 3.0,
            apply_min: true,
            apply_max: true,
            min_max_equal: false,
        };
        assert_eq!(p.adjust(0.25), 1.0);
        assert_eq!(p.adjust(2.0), 2.5);
        assert_eq!(p.adjust(9.0), 3.0);
        // NaN gives way to each clamp, as `minps(lod, max)` and `maxps(lod, min)` do
        assert_eq!(p.adjust(f32::NAN), 3.0);
        let q = LodParams {
            apply_max: false,
            ..p
        };
        assert_eq!(q.adjust(f32::NAN), 1.0);
    }

    #[test]
    fn huge_lods_minify_at_the_base_level() {
        for v in [2_147_483_648.0, f32::INFINITY, 1e30] {
            let l = Lod::from_value(as_forced(v), super::super::MipFilter::Linear);
            assert!(l.positive && l.ipart == 0, "{v}: {l:?}");
            assert_eq!((l.fpart * 256.0) as i32, 0);
        }
        for v in [-2_147_483_648.0, f32::NEG_INFINITY, f32::NAN] {
            let l = Lod::from_value(as_forced(v), super::super::MipFilter::Nearest);
            assert!(!l.positive, "{v}");
        }
        assert_eq!(as_forced(2.5), 2.5);
        assert_eq!(int(f32::INFINITY), i64::from(i32::MIN));
        assert_eq!(int(-7.0), -7);
    }
}
