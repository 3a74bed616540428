//! Texture coordinate wrapping, per axis, exactly as llvmpipe's samplers compute it
//! (`lp_bld_sample_aos.c` for the 8-bit AoS path, `lp_bld_sample_soa.c` for the float SoA
//! path; docs/llvmpipe-rules.md §9.2).
//!
//! Every function takes the normalised coordinate `s` (already divided by q), the level size
//! and whether the *resource's* level-0 size on this axis is a power of two (llvmpipe picks
//! the REPEAT code statically from it). Results are always valid texel indices; `None`
//! means "outside the image: use the border colour".

use super::Wrap;

/// `x - floor(x)` clamped below 1 (`lp_build_fract_safe`).
#[inline(always)]
pub fn fract_safe(x: f32) -> f32 {
    (x - x.floor()).min(f32::from_bits(0x3f7f_ffff))
}

/// `x - floor(x)` (`lp_build_fract`).
#[inline(always)]
pub fn fract(x: f32) -> f32 {
    x - x.floor()
}

/// f32 → i32 as cvttps2dq/cvtps2dq would for in-range values (NaN and overflow give 0 or
/// saturate; the callers wrap or clamp the result, so any value is safe).
#[inline(always)]
fn to_i32(x: f32) -> i32 {
    x as i32
}

/// AoS NEAREST (`lp_build_sample_wrap_nearest_int`): the texel index.
#[inline(always)]
pub fn aos_nearest(s: f32, size: usize, pot: bool, wrap: Wrap) -> usize {
    let len = size as i32;
    match wrap {
        Wrap::Repeat if pot => (to_i32((s * size as f32).floor()) & (len - 1)) as usize,
        Wrap::Repeat => (to_i32(fract_safe(s) * size as f32)).clamp(0, len - 1) as usize,
        _ => to_i32((s * size as f32).floor()).clamp(0, len - 1) as usize,
    }
}

/// AoS LINEAR (`lp_build_sample_wrap_linear_int`): `(i0, i1, w)` with an 8-bit weight:
/// `fx = round_half_even(s·size·256) − 128`, `i0 = fx >> 8`, `w = fx & 255`.
#[inline(always)]
pub fn aos_linear(s: f32, size: usize, pot: bool, wrap: Wrap) -> (usize, usize, i32) {
    let len = size as i32;
    match wrap {
        Wrap::Repeat if !pot => {
            // lp_build_coord_repeat_npot_linear_int
            let u = fract(s) * size as f32 * 256.0;
            let fx = to_i32(u.round_ties_even()).wrapping_sub(128);
            let w = fx & 255;
            let mut i0 = fx >> 8;
            if i0 < 0 {
                i0 = len - 1;
            }
            i0 = i0.min(len - 1);
            let i1 = if i0 != len - 1 { i0 + 1 } else { 0 };
            (i0 as usize, i1 as usize, w)
        }
        _ => {
            let u = s * (size as f32 * 256.0);
            let fx = to_i32(u.round_ties_even()).wrapping_sub(128);
            let w = fx & 255;
            let i0 = fx >> 8;
            let i1 = i0.wrapping_add(1);
            if wrap == Wrap::Repeat {
                ((i0 & (len - 1)) as usize, (i1 & (len - 1)) as usize, w)
            } else {
                (
                    i0.clamp(0, len - 1) as usize,
                    i1.clamp(0, len - 1) as usize,
                    w,
                )
            }
        }
    }
}

/// `2·(x/2 − round(x/2))`, then `abs`, NaN → 0 (`lp_build_coord_mirror` with posOnly).
#[inline(always)]
pub fn mirror(s: f32) -> f32 {
    let h = s * 0.5;
    let f = h - h.round_ties_even();
    let m = (f + f).abs();
    if m.is_nan() {
        0.0
    } else {
        m
    }
}

/// SoA NEAREST (`lp_build_sample_wrap_nearest`); `None` = border.
#[inline(always)]
pub fn soa_nearest(s: f32, size: usize, pot: bool, wrap: Wrap) -> Option<usize> {
    let len = size as i32;
    let sz = size as f32;
    Some(match wrap {
        Wrap::Repeat if pot => (to_i32((s * sz).floor()) & (len - 1)) as usize,
        Wrap::Repeat => to_i32(fract_safe(s) * sz).clamp(0, len - 1) as usize,
        Wrap::Clamp | Wrap::ClampToEdge => to_i32(s * sz).clamp(0, len - 1) as usize,
        Wrap::ClampToBorder => {
            let i = (s * sz).floor();
            if !(i >= 0.0 && i < sz) {
                return None;
            }
            i as usize
        }
        Wrap::MirroredRepeat => to_i32(mirror(s) * sz).clamp(0, len - 1) as usize,
    })
}

/// SoA LINEAR (`lp_build_sample_wrap_linear`): `(i0, i1, weight)` with float weight;
/// `None` indices read the border colour.
#[inline(always)]
pub fn soa_linear(
    s: f32,
    size: usize,
    pot: bool,
    wrap: Wrap,
) -> (Option<usize>, Option<usize>, f32) {
    let len = size as i32;
    let sz = size as f32;
    let floor_fract = |u: f32| {
        let f = u.floor();
        (to_i32(f), u - f)
    };
    let inside = |i: i32| (0..len).contains(&i).then_some(i as usize);
    match wrap {
        Wrap::Repeat if pot => {
            let (i0, w) = floor_fract(s * sz - 0.5);
            let i1 = i0.wrapping_add(1);
            (
                Some((i0 & (len - 1)) as usize),
                Some((i1 & (len - 1)) as usize),
                w,
            )
        }
        Wrap::Repeat => {
            let (mut i0, w) = floor_fract(fract(s) * sz - 0.5);
            if i0 < 0 {
                i0 = len - 1;
            }
            i0 = i0.min(len - 1);
            let i1 = if i0 != len - 1 { i0 + 1 } else { 0 };
            (Some(i0 as usize), Some(i1 as usize), w)
        }
        Wrap::Clamp => {
            let u = s * sz;
            // clamp to [0, size] (NaN → 0), then −0.5
            let u = if u > 0.0 { u.min(sz) } else { 0.0 };
            let (i0, w) = floor_fract(u - 0.5);
            (inside(i0), inside(i0 + 1), w)
        }
        Wrap::ClampToEdge => {
            let u = s * sz;
            let u = if u < sz { u } else { sz };
            let u = u - 0.5;
            let u = if u > 0.0 { u } else { 0.0 };
            let (i0, w) = floor_fract(u);
            let i0 = i0.clamp(0, len - 1);
            (Some(i0 as usize), Some((i0 + 1).min(len - 1) as usize), w)
        }
        Wrap::ClampToBorder => {
            // `f32::clamp`'s comparisons (NaN stays NaN), written out: the library call
            // was left out of line in the level copies of the quad sampler.
            let (u, hi) = (s * sz, sz + 0.5);
            let u = if u < -0.5 {
                -0.5
            } else if u > hi {
                hi
            } else {
                u
            };
            let u = if u.is_nan() { -0.5 } else { u };
            let (i0, w) = floor_fract(u - 0.5);
            (inside(i0), inside(i0 + 1), w)
        }
        Wrap::MirroredRepeat => {
            let (i0, w) = floor_fract(mirror(s) * sz - 0.5);
            let i1 = (i0 + 1).min(len - 1);
            let i0 = i0.clamp(0, len - 1);
            (Some(i0 as usize), Some(i1.max(0) as usize), w)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn aos_linear_formula() {
        // u = 0.3·4 = 1.2 → fx = round(307.2) − 128 = 179 → i0 = 0, w = 179
        assert_eq!(aos_linear(0.3, 4, true, Wrap::ClampToEdge), (0, 1, 179));
        // left edge: u = 0.125·4 = 0.5 → fx = 0 → (0, 1, 0)
        assert_eq!(aos_linear(0.125, 4, true, Wrap::Repeat), (0, 1, 0));
        // s = 0: fx = −128 → i0 = −1 (wraps to 3 with REPEAT), w = 128
        assert_eq!(aos_linear(0.0, 4, true, Wrap::Repeat), (3, 0, 128));
        assert_eq!(aos_linear(0.0, 4, true, Wrap::ClampToEdge), (0, 0, 128));
        // NPOT repeat: negative i0 becomes size−1, i1 wraps to 0
        assert_eq!(aos_linear(0.0, 3, false, Wrap::Repeat), (2, 0, 128));
        assert_eq!(aos_linear(1.25, 3, false, Wrap::Repeat), (0, 1, 64));
    }

    #[test]
    fn aos_linear_rounds_half_even() {
        // u·256 = 2.5 exactly → rounds to 2 → fx = −126
        let s = 2.5 / 256.0 / 4.0;
        assert_eq!(aos_linear(s, 4, true, Wrap::ClampToEdge), (0, 0, 130));
    }

    #[test]
    fn nearest_wraps() {
        assert_eq!(aos_nearest(-0.1, 4, true, Wrap::Repeat), 3);
        assert_eq!(aos_nearest(1.1, 4, true, Wrap::ClampToEdge), 3);
        assert_eq!(aos_nearest(-0.1, 3, false, Wrap::Repeat), 2);
        assert_eq!(soa_nearest(-0.1, 4, true, Wrap::ClampToBorder), None);
        assert_eq!(soa_nearest(1.2, 4, true, Wrap::MirroredRepeat), Some(3));
        assert_eq!(soa_nearest(-0.2, 4, true, Wrap::MirroredRepeat), Some(0));
        assert_eq!(soa_nearest(1.9, 4, true, Wrap::MirroredRepeat), Some(0));
        assert_eq!(soa_nearest(f32::NAN, 5, false, Wrap::Repeat), Some(4));
    }

    #[test]
    fn soa_linear_modes() {
        // GL_CLAMP at s = 0: u = 0 → −0.5 → i0 = −1 (border), i1 = 0, w = 0.5
        assert_eq!(soa_linear(0.0, 4, true, Wrap::Clamp), (None, Some(0), 0.5));
        // far outside: clamped to the edge, still half border
        assert_eq!(soa_linear(7.0, 4, true, Wrap::Clamp), (Some(3), None, 0.5));
        assert_eq!(
            soa_linear(0.0, 4, true, Wrap::ClampToEdge),
            (Some(0), Some(1), 0.0)
        );
        assert_eq!(
            soa_linear(-3.0, 4, true, Wrap::ClampToBorder),
            (None, Some(0), 0.0)
        );
        assert_eq!(
            soa_linear(0.3, 4, true, Wrap::Repeat),
            (Some(0), Some(1), 0.3 * 4.0 - 0.5)
        );
    }

    #[test]
    fn never_out_of_range() {
        for &s in &[
            f32::NAN,
            f32::INFINITY,
            -f32::INFINITY,
            1e30,
            -1e30,
            -1e-9,
            0.99999,
        ] {
            for &size in &[1usize, 3, 4, 7, 16] {
                let pot = size.is_power_of_two();
                for w in [
                    Wrap::Repeat,
                    Wrap::Clamp,
                    Wrap::ClampToEdge,
                    Wrap::ClampToBorder,
                    Wrap::MirroredRepeat,
                ] {
                    if w.is_simple() {
                        assert!(aos_nearest(s, size, pot, w) < size);
                        let (a, b, _) = aos_linear(s, size, pot, w);
                        assert!(a < size && b < size, "{s} {size} {w:?}");
                    }
                    if let Some(i) = soa_nearest(s, size, pot, w) {
                        assert!(i < size);
                    }
                    let (a, b, _) = soa_linear(s, size, pot, w);
                    assert!(a.is_none_or(|a| a < size) && b.is_none_or(|b| b < size));
                }
            }
        }
    }
}
