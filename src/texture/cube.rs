//! GL_TEXTURE_CUBE_MAP: completeness, face selection and sampling as llvmpipe does them
//! (`lp_build_cube_lookup` in `lp_bld_sample.c`, docs/llvmpipe-rules.md §9.1).
//!
//! - Faces are numbered as gallium does: +X, −X, +Y, −Y, +Z, −Z (GL's order).
//! - The major axis is z when `|r| ≥ max(|s|, |t|)`, else x when `|s| > |t|`, else y; the
//!   face is the axis plus the sign bit of the major coordinate. The minor coordinates
//!   are mirrored per the spec's table by flipping sign bits.
//! - Without a LOD: `s' = sc·(0.5/|ma|) + 0.5` (0 when ma = 0). With a LOD
//!   (`need_derivs`): `s' = sc·|0.5·(1/ma)| + 0.5`, and the derivatives of the projected
//!   coordinates are `(d.sc − (d.ma·(1/ma))·sc)·(0.5·(1/ma))`, from the pixel's own
//!   direction and its row (ddx) and column (ddy) differences in the quad, with
//!   `rho² = max((W·dsdx)² + (W·dtdx)², …)` of the face size. A mipmapped cube map has
//!   one LOD per pixel; without a mip filter (min ≠ mag) the quad's top-left pixel
//!   decides.
//! - Without GL_TEXTURE_CUBE_MAP_SEAMLESS each face is sampled on its own with every wrap
//!   mode forced to CLAMP_TO_EDGE (llvmpipe does this for cube maps whatever the program
//!   set), on the 8-bit AoS path for 8-bit formats. With it, LINEAR filtering reads
//!   across the face edges ([`super::cube_seamless`]).

use super::lod::{self, Lod};
use super::sample::{sample_levels_in, select_levels};
use super::{Level, MipFilter, TextureObject, UnitPlan, MAX_LEVELS};

/// The six level arrays of a cube map, in face order.
pub type Faces<'a> = [&'a [Option<Level>]; 6];

/// `(base, last)` of a cube-complete texture, `None` otherwise: every face has a square
/// base image of the same size and format and (when mipmapping) a full chain.
pub fn complete_range(obj: &TextureObject) -> Option<(usize, usize)> {
    let p = &obj.params;
    if p.base_level < 0 || p.base_level > p.max_level || p.base_level as usize >= MAX_LEVELS {
        return None;
    }
    let base = p.base_level as usize;
    let b = obj.face_levels(0).get(base)?.as_ref()?;
    if b.width == 0 || b.width != b.height {
        return None;
    }
    let log2 = usize::BITS - 1 - b.width.leading_zeros();
    let last = (base + log2 as usize)
        .min(p.max_level as usize)
        .min(MAX_LEVELS - 1);
    let last = if p.mip_filter == MipFilter::None {
        base
    } else {
        last
    };
    for face in 0..6 {
        let levels = obj.face_levels(face);
        for l in base..=last {
            let img = levels.get(l)?.as_ref()?;
            let size = (b.width >> (l - base)).max(1);
            if img.width != size || img.height != size || img.base != b.base || !img.has_texels(1) {
                return None;
            }
        }
    }
    Some((base, last))
}

/// The sign bit of `x` as a mask.
#[inline(always)]
fn sign(x: f32) -> u32 {
    x.to_bits() & 0x8000_0000
}

/// `x` with its sign bit flipped by `mask`.
#[inline(always)]
fn flip(x: f32, mask: u32) -> f32 {
    f32::from_bits(x.to_bits() ^ mask)
}

/// Major-axis choice of one direction: 0 = x, 1 = y, 2 = z.
#[inline(always)]
fn major(s: f32, t: f32, r: f32) -> usize {
    let (a_s, a_t, a_r) = (s.abs(), t.abs(), r.abs());
    if a_r >= a_s.max(a_t) {
        2
    } else if a_s > a_t {
        0
    } else {
        1
    }
}

/// The face and the mirrored, unprojected minor coordinates `(sc, tc)` of a direction
/// (or of its derivative, mirrored with the direction's own signs), and `ma`.
#[inline(always)]
fn minor(axis: usize, ma_sign: u32, v: [f32; 3]) -> (f32, f32) {
    const NEG: u32 = 0x8000_0000;
    match axis {
        0 => (flip(v[2], ma_sign ^ NEG), flip(v[1], NEG)),
        1 => (v[0], flip(v[2], ma_sign)),
        _ => (flip(v[0], ma_sign), flip(v[1], NEG)),
    }
}

/// Face index and face coordinates of one pixel; `lod` selects the `need_derivs`
/// projection.
#[inline(always)]
pub(super) fn project(s: f32, t: f32, r: f32, lod: bool) -> (usize, f32, f32) {
    let axis = major(s, t, r);
    let ma = [s, t, r][axis];
    let ms = sign(ma);
    let (sc, tc) = minor(axis, ms, [s, t, r]);
    let k = if lod {
        (0.5 * (1.0 / ma)).abs()
    } else {
        let a = ma.abs();
        if a > 0.0 {
            0.5 / a
        } else {
            0.0
        }
    };
    let face = 2 * axis + (ms >> 31) as usize;
    (face, sc * k + 0.5, tc * k + 0.5)
}

/// The LOD of pixel `i` of a quad, as `lp_build_cube_lookup` derives it: from the
/// pixel's own direction and its quad's row (x) and column (y) differences.
#[inline(always)]
fn pixel_lod(p: &UnitPlan<'_>, size: f32, i: usize, s: [f32; 4], t: [f32; 4], r: [f32; 4]) -> Lod {
    lod::from_rho(&p.lod, p.mip_filter, true, pixel_rho(size, i, s, t, r))
}

/// [`pixel_lod`]'s rho² (texels squared) for a base level of `size` texels.
#[inline(always)]
pub(super) fn pixel_rho(size: f32, i: usize, s: [f32; 4], t: [f32; 4], r: [f32; 4]) -> f32 {
    let v = [s[i], t[i], r[i]];
    // ddx: right minus left of the pixel's row; ddy: bottom minus top of its column
    let (xl, xr) = if i < 2 { (0, 1) } else { (2, 3) };
    let (yt, yb) = if i & 1 == 0 { (0, 2) } else { (1, 3) };
    let ddx = [s[xr] - s[xl], t[xr] - t[xl], r[xr] - r[xl]];
    let ddy = [s[yb] - s[yt], t[yb] - t[yt], r[yb] - r[yt]];
    let axis = major(v[0], v[1], v[2]);
    let ma = v[axis];
    let ms = sign(ma);
    let ima = 1.0 / ma;
    let imahalf = 0.5 * ima;
    let (sc, tc) = minor(axis, ms, v);
    let deriv = Deriv {
        axis,
        ms,
        ima,
        imahalf,
        sc,
        tc,
        size,
    };
    deriv.sq(ddx).max(deriv.sq(ddy))
}

/// What [`pixel_lod`] needs to turn a direction difference into face derivatives (a
/// struct with inlined methods rather than closures, which the compiler may leave out of
/// line without the caller's target features).
struct Deriv {
    axis: usize,
    ms: u32,
    ima: f32,
    imahalf: f32,
    sc: f32,
    tc: f32,
    size: f32,
}

impl Deriv {
    /// The squared length, in texels, of the face derivative of direction difference `d`.
    #[inline(always)]
    fn sq(&self, d: [f32; 3]) -> f32 {
        let (dsc, dtc) = minor(self.axis, self.ms, d);
        let m = d[self.axis] * self.ima;
        let (a, b) = (
            (dsc - m * self.sc) * self.imahalf,
            (dtc - m * self.tc) * self.imahalf,
        );
        let (a, b) = (self.size * a, self.size * b);
        a * a + b * b
    }
}

/// The filter and levels of each pixel of a 2x2 quad of direction vectors, and whether
/// the faces are projected with `need_derivs`. llvmpipe computes a cube map's LOD per
/// pixel when it mipmaps, and per quad (from the top-left pixel) when only the
/// min/mag switch needs it.
#[inline(always)]
pub(super) fn quad_levels(
    p: &UnitPlan<'_>,
    s: [f32; 4],
    t: [f32; 4],
    r: [f32; 4],
) -> ([LevelSel; 4], bool) {
    let need_derivs = p.needs_lod && !p.lod.min_max_equal;
    if !need_derivs {
        let lod = if p.needs_lod {
            lod::from_rho(&p.lod, p.mip_filter, true, 0.0)
        } else {
            Lod::MAG
        };
        return ([select_levels(p, lod); 4], false);
    }
    let size = p.image(p.first).width as f32;
    if p.mip_filter == MipFilter::None {
        let sel = select_levels(p, pixel_lod(p, size, 0, s, t, r));
        return ([sel; 4], true);
    }
    let sels = each4!(|i| select_levels(p, pixel_lod(p, size, i, s, t, r)));
    (sels, true)
}

/// What [`select_levels`] returns: `(filter, level0, level1, fraction)`.
pub(super) type LevelSel = (super::Filter, usize, usize, f32);

/// Samples a 2x2 quad (TL, TR, BL, BR) of direction vectors, each face on its own.
#[inline(always)]
pub fn sample_quad(
    p: &UnitPlan<'_>,
    faces: &Faces<'_>,
    s: [f32; 4],
    t: [f32; 4],
    r: [f32; 4],
) -> [[f32; 4]; 4] {
    let (sels, need_derivs) = quad_levels(p, s, t, r);
    each4!(|i| {
        let (face, fs, ft) = project(s[i], t[i], r[i], need_derivs);
        sample_levels_in(p, faces[face], sels[i], fs, ft)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn faces_follow_the_spec_table() {
        // +X: sc = -rz, tc = -ry
        assert_eq!(project(1.0, 0.5, 0.25, false), (0, 0.375, 0.25));
        // -X: sc = +rz, tc = -ry
        assert_eq!(project(-1.0, 0.5, 0.25, false), (1, 0.625, 0.25));
        // +Y: sc = rx, tc = rz
        assert_eq!(project(0.5, 1.0, 0.25, false), (2, 0.75, 0.625));
        // -Y: sc = rx, tc = -rz
        assert_eq!(project(0.5, -1.0, 0.25, false), (3, 0.75, 0.375));
        // +Z: sc = rx, tc = -ry
        assert_eq!(project(0.5, 0.25, 1.0, false), (4, 0.75, 0.375));
        // -Z: sc = -rx, tc = -ry
        assert_eq!(project(0.5, 0.25, -1.0, false), (5, 0.25, 0.375));
    }

    #[test]
    fn ties_prefer_z_then_y() {
        assert_eq!(project(1.0, 1.0, 1.0, false).0, 4);
        assert_eq!(project(1.0, 1.0, 0.5, false).0, 2);
    }
}
