//! GL_TEXTURE_3D: completeness, mipmap generation and sampling with llvmpipe's arithmetic.
//!
//! # Storage
//! A 3D level is a [`Level`] whose texels hold `depth` slices of `width x height` one
//! after the other (slice z, row y, column x at `(z·height + y)·width + x`); the depth of
//! each level is also kept in [`TextureObject::depths`] so proxies know it.
//!
//! # Sampling (docs/llvmpipe-rules.md §9, `lp_bld_sample_aos.c` / `lp_bld_sample_soa.c`)
//! - LOD: `rho² = max((W·dsdx)² + (H·dtdx)² + (D·drdx)², same for y)`, summed in that order
//!   (`lp_build_rho` with `no_rho_approx`), then the 2D rules ([`lod::from_rho`]).
//! - AoS (8-bit, REPEAT / CLAMP_TO_EDGE on s, t and r): 8.8 weights on every axis; LINEAR
//!   lerps x on the four rows, then y on both slices, then z (`lp_build_lerp_3d`).
//! - SoA (GL_CLAMP, CLAMP_TO_BORDER, MIRRORED_REPEAT): float weights, the same lerp order
//!   with `fmuladd`, border colour for texels outside.
//! - Mipmaps are generated as `util_gen_mipmap` blits them: each texel of level n+1 is the
//!   8-bit trilinear AoS sample of level n at its centre.

use super::lod::{self, Lod};
use super::mipmap::axis;
use super::sample::{lerp8, lerp8x4, lerpf, lerpfx4, select_levels, texel_float, to_float};
use super::wrap;
use super::{Filter, Level, TextureObject, UnitPlan, Wrap, MAX_LEVELS};

/// The 3D part of a unit's sampling plan.
#[derive(Clone, Copy, Debug)]
pub struct VolumePlan<'a> {
    /// Wrap mode of r (after llvmpipe's GL_CLAMP→CLAMP_TO_EDGE for nearest-only sampling).
    pub wrap_r: Wrap,
    /// Whether the level-0 depth is a power of two (selects the REPEAT code).
    pub pot_r: bool,
    /// Depth of each level.
    pub depths: &'a [usize; MAX_LEVELS],
}

/// `(base, last)` of a complete 3D texture (GL 1.5 §3.8.10), `None` when incomplete.
pub fn complete_range(obj: &TextureObject) -> Option<(usize, usize)> {
    obj.complete_chain(|l| obj.depths[l])
}

/// The texel at (x, y, z) of a 3D level.
#[inline(always)]
fn texel(img: &Level, x: usize, y: usize, z: usize) -> [u8; 4] {
    img.texels[(z * img.height + y) * img.width + x]
}

/// The next smaller 3D level of `src` (depth `d`), as `util_gen_mipmap` blits it.
pub fn downsample(src: &Level, d: usize) -> (Level, usize) {
    let (dw, dh, dd) = (
        (src.width / 2).max(1),
        (src.height / 2).max(1),
        (d / 2).max(1),
    );
    let xs: Vec<_> = (0..dw).map(|x| axis(dw, x, src.width)).collect();
    let ys: Vec<_> = (0..dh).map(|y| axis(dh, y, src.height)).collect();
    let mut texels = Vec::with_capacity(dw * dh * dd);
    for z in 0..dd {
        let (z0, z1, wz) = axis(dd, z, d);
        for &(y0, y1, wy) in &ys {
            for &(x0, x1, wx) in &xs {
                let slice = |z| {
                    let r0 = lerp8x4(texel(src, x0, y0, z), texel(src, x1, y0, z), wx);
                    let r1 = lerp8x4(texel(src, x0, y1, z), texel(src, x1, y1, z), wx);
                    lerp8x4(r0, r1, wy)
                };
                let (a, b) = (slice(z0), slice(z1));
                let v = std::array::from_fn(|c| lerp8(a[c], b[c], wz));
                texels.push(super::upload::render_quantise_rgba(v, &src.storage));
            }
        }
    }
    let img = Level::derived(src, dw, dh, texels);
    (img, dd)
}

/// Regenerates levels `base+1 ..= max_level` of a 3D texture from level `base`.
pub fn generate(obj: &mut TextureObject, base: usize, max_level: usize) {
    let mut l = base;
    while l < max_level.min(MAX_LEVELS - 1) {
        let Some(src) = obj.levels[l].as_ref() else {
            return;
        };
        let d = obj.depths[l];
        if src.width == 1 && src.height == 1 && d == 1 {
            return;
        }
        let (mut next, nd) = downsample(src, d);
        // float 3D levels keep the 8-bit filtered values (not llvmpipe's float blit)
        next.set_floats(None);
        obj.levels[l + 1] = Some(next);
        obj.depths[l + 1] = nd;
        l += 1;
    }
}

/// The LOD of a quad (TL, TR, BL, BR) of 3D coordinates.
#[inline(always)]
fn quad_lod(p: &UnitPlan<'_>, v: &VolumePlan<'_>, s: [f32; 4], t: [f32; 4], r: [f32; 4]) -> Lod {
    if !p.needs_lod {
        return Lod::MAG;
    }
    lod::from_rho(&p.lod, p.mip_filter, true, quad_rho(p, v, s, t, r))
}

/// [`quad_lod`]'s rho² (texels squared): the larger of the quad's x and y differences.
#[inline(always)]
pub(super) fn quad_rho(
    p: &UnitPlan<'_>,
    v: &VolumePlan<'_>,
    s: [f32; 4],
    t: [f32; 4],
    r: [f32; 4],
) -> f32 {
    let b = p.image(p.first);
    let (w, h, d) = (b.width as f32, b.height as f32, v.depths[p.first] as f32);
    let sq = |ds: f32, dt: f32, dr: f32| {
        let (a, b, c) = (ds * w, dt * h, dr * d);
        a * a + b * b + c * c
    };
    let rx = sq(s[1] - s[0], t[1] - t[0], r[1] - r[0]);
    let ry = sq(s[2] - s[0], t[2] - t[0], r[2] - r[0]);
    rx.max(ry)
}

/// Samples a 2x2 quad of a 3D texture with one LOD.
#[inline(always)]
pub fn sample_quad(
    p: &UnitPlan<'_>,
    v: &VolumePlan<'_>,
    s: [f32; 4],
    t: [f32; 4],
    r: [f32; 4],
) -> [[f32; 4]; 4] {
    let sel = select_levels(p, quad_lod(p, v, s, t, r));
    std::array::from_fn(|i| sample_levels(p, v, sel, s[i], t[i], r[i]))
}

/// One coordinate with the levels [`select_levels`] chose.
#[inline(always)]
fn sample_levels(
    p: &UnitPlan<'_>,
    v: &VolumePlan<'_>,
    (filter, l0, l1, frac): (Filter, usize, usize, f32),
    s: f32,
    t: f32,
    r: f32,
) -> [f32; 4] {
    if p.aos {
        let a = aos_filter(p, v, l0, filter, [s, t, r]);
        if l1 == l0 {
            return to_float(a);
        }
        let b = aos_filter(p, v, l1, filter, [s, t, r]);
        to_float(lerp8x4(a, b, (frac * 256.0) as i32))
    } else {
        let a = soa_filter(p, v, l0, filter, [s, t, r]);
        if l1 == l0 {
            return a;
        }
        let b = soa_filter(p, v, l1, filter, [s, t, r]);
        lerpfx4(p.fma, frac, a, b)
    }
}

/// Sizes, pot flags and wraps of the three axes of `level`.
#[inline(always)]
fn axes<'i>(
    p: &'i UnitPlan<'_>,
    v: &VolumePlan<'_>,
    level: usize,
) -> (&'i Level, [usize; 3], [bool; 3], [Wrap; 3]) {
    let img = p.image(level);
    (
        img,
        [img.width, img.height, v.depths[level]],
        [p.pot[0], p.pot[1], v.pot_r],
        [p.wrap_s, p.wrap_t, v.wrap_r],
    )
}

/// One level, AoS (8-bit) filtering.
#[inline(always)]
fn aos_filter(
    p: &UnitPlan<'_>,
    v: &VolumePlan<'_>,
    level: usize,
    filter: Filter,
    c: [f32; 3],
) -> [u8; 4] {
    let (img, size, pot, wraps) = axes(p, v, level);
    match filter {
        Filter::Nearest => {
            let i: [usize; 3] =
                std::array::from_fn(|k| wrap::aos_nearest(c[k], size[k], pot[k], wraps[k]));
            texel(img, i[0], i[1], i[2])
        }
        Filter::Linear => {
            let [(x0, x1, wx), (y0, y1, wy), (z0, z1, wz)] =
                std::array::from_fn(|k| wrap::aos_linear(c[k], size[k], pot[k], wraps[k]));
            let slice = |z| {
                let r0 = lerp8x4(texel(img, x0, y0, z), texel(img, x1, y0, z), wx);
                let r1 = lerp8x4(texel(img, x0, y1, z), texel(img, x1, y1, z), wx);
                lerp8x4(r0, r1, wy)
            };
            lerp8x4(slice(z0), slice(z1), wz)
        }
    }
}

/// One level, SoA (float) filtering with the border colour.
#[inline(always)]
fn soa_filter(
    p: &UnitPlan<'_>,
    v: &VolumePlan<'_>,
    level: usize,
    filter: Filter,
    c: [f32; 3],
) -> [f32; 4] {
    let (img, size, pot, wraps) = axes(p, v, level);
    let fetch = |x: Option<usize>, y: Option<usize>, z: Option<usize>| match (x, y, z) {
        (Some(x), Some(y), Some(z)) if p.ext.floats => {
            img.ftexel((z * img.height + y) * img.width + x)
        }
        (Some(x), Some(y), Some(z)) => texel_float(p, texel(img, x, y, z)),
        _ => p.border,
    };
    match filter {
        Filter::Nearest => {
            let i: [Option<usize>; 3] =
                std::array::from_fn(|k| wrap::soa_nearest(c[k], size[k], pot[k], wraps[k]));
            fetch(i[0], i[1], i[2])
        }
        Filter::Linear => {
            let [(x0, x1, wx), (y0, y1, wy), (z0, z1, wz)] =
                std::array::from_fn(|k| wrap::soa_linear(c[k], size[k], pot[k], wraps[k]));
            let slice = |z| {
                let r0 = lerpfx4(p.fma, wx, fetch(x0, y0, z), fetch(x1, y0, z));
                let r1 = lerpfx4(p.fma, wx, fetch(x0, y1, z), fetch(x1, y1, z));
                lerpfx4(p.fma, wy, r0, r1)
            };
            let (a, b) = (slice(z0), slice(z1));
            std::array::from_fn(|ch| lerpf(p.fma, wz, a[ch], b[ch]))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture::{MipFilter, Target};

    fn level(w: usize, h: usize, d: usize, v: u8) -> Level {
        crate::texture::tests::rgba_level(w, h, vec![[v; 4]; w * h * d])
    }

    #[test]
    fn completeness_checks_depth_halving() {
        let mut o = TextureObject::new(Some(Target::Tex3D));
        o.levels[0] = Some(level(4, 2, 8, 0));
        o.depths[0] = 8;
        o.params.mip_filter = MipFilter::None;
        assert_eq!(complete_range(&o), Some((0, 0)));
        o.params.mip_filter = MipFilter::Linear;
        assert_eq!(complete_range(&o), None);
        generate(&mut o, 0, 1000);
        assert_eq!(o.depths[..4], [8, 4, 2, 1]);
        assert_eq!(complete_range(&o), Some((0, 3)));
        o.depths[2] = 3;
        assert_eq!(complete_range(&o), None);
    }

    #[test]
    fn downsample_of_a_constant_volume_is_constant() {
        let (img, d) = downsample(&level(4, 4, 4, 77), 4);
        assert_eq!((img.width, img.height, d), (2, 2, 2));
        assert!(img.texels.iter().all(|t| *t == [77; 4]));
    }
}
