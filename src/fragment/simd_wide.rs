//! The colour write of wide buffers (16-bit unorm, half and single float) on 8 lanes:
//! what [`super::wide::store`] computes pixel by pixel, in 256-bit registers, for the
//! 8-lane walks ([`super::simd_gen::shade_row`]).
//!
//! A wide plane holds each pixel as four f32 (RGBA), so the 8 pixels of a chunk are four
//! registers of two pixels each; they are transposed to one register per channel after
//! the load and back before the store (plain 32-byte accesses when all 8 pixels pass,
//! `vpmaskmovd` otherwise: AMD microcodes its stores). The stored value is read as
//! [`crate::framebuffer::samples::PlaneRows::wide_at`] reads it (the 8-bit mirror decides
//! whether the wide value is current), blended at the buffer's precision (unorm16 in
//! 32-bit integer lanes with llvmpipe's `mul`, floats in f32 with the folded factors of
//! [`super::wide`]), stored through the colour mask, and its 8-bit mirror written.
//!
//! Rust's `f32::min` and `max` (the MIN and MAX equations, SRC_ALPHA_SATURATE) are
//! reproduced with LLVM's x86 lowering of `minnum`: `a.min(b)` is `vminps(b, a)`, and `b`
//! where `a` is NaN. The one case [`covers`] leaves to the per-pixel store is a logic op
//! into a 16-bit buffer (and a fused float blend in a copy compiled without FMA).

#![cfg(target_arch = "x86_64")]
// Channel loops index several arrays in step.
#![allow(clippy::needless_range_loop)]

use super::simd::sat;
use super::wide::{blend_factor, complement, positive, WideDst};
use super::{BlendPlan, FragPlan};
use crate::framebuffer::wide::unorm16;
use crate::framebuffer::WideKind;
use crate::pipe::{BlendEquation, BlendFactor};
use crate::simd::{F32x8, I32x8};
use crate::texture::env::vec8::Vec4;

/// Whether [`store8`] covers a store of `plan` into `dst` in a copy compiled with FMA
/// (`fma_ctx`) or without.
#[inline(always)]
pub fn covers(dst: WideDst, plan: &FragPlan, fma_ctx: bool) -> bool {
    let logic16 = dst.kind == WideKind::Unorm16 && plan.blend.is_none() && plan.logic.is_some();
    let unfusable = plan.fma && !fma_ctx && plan.blend.is_some() && dst.kind.is_float();
    !logic16 && !unfusable
}

/// Writes the lanes of `pass` of the 8 pixels at `idx` of the colour rows `color` and
/// the wide rows `wide` with the shader colours `s` (one register per channel), as
/// [`super::wide::store`] does; returns the number of pixels written.
///
/// # Safety
/// AVX2 context (FMA when `FMA`); [`covers`] accepted the store; the lanes of `pass` lie
/// inside both slices from `idx`.
#[inline(always)]
pub unsafe fn store8<const FMA: bool>(
    dst: WideDst,
    plan: &FragPlan,
    color: &mut [[u8; 4]],
    wide: &mut [[f32; 4]],
    idx: usize,
    pass: I32x8,
    s: Vec4,
) -> u64 {
    let k = dst.kind;
    let mask = plan.color_mask;
    // SAFETY: (whole body) the caller's AVX2 (+FMA) context; the masked loads and stores
    // touch the lanes of `pass` only, which lie in the slices (the pointers are formed
    // with wrapping arithmetic and never dereferenced outside them).
    unsafe {
        let wptr = wide.as_mut_ptr().wrapping_add(idx) as *mut i32;
        let cptr = color.as_mut_ptr().wrapping_add(idx) as *mut i32;
        // All 8 pixels pass and lie in both slices: plain loads and stores (`vpmaskmovd`
        // stores are microcoded on AMD; see `super::simd::store_masked`).
        let full = pass.movemask() == 0xff && wide.len() >= idx + 8 && color.len() >= idx + 8;
        let reads = plan.blend.is_some() || mask != [true; 4];
        let d = if reads {
            let raw = load_aos(wptr, pass, full);
            let c8 = if full {
                I32x8::load(cptr)
            } else {
                I32x8::maskload(cptr, pass)
            };
            let current = mirror8(k, raw).cmpeq(c8).as_f32();
            let mut d = from_u8(k, c8);
            for ch in 0..4 {
                d[ch] = d[ch].blendv(raw[ch], current);
            }
            d
        } else {
            [F32x8::zero(); 4]
        };
        let mut v = match &plan.blend {
            Some(b) if k.is_float() => blend_float::<FMA>(k, plan, b, s, d, dst.single),
            Some(b) => blend16(b, plan.blend_color, s, d),
            // Float buffers ignore the logic op (`covers` leaves 16-bit ones out).
            None => {
                let mut v = s;
                for c in v.iter_mut() {
                    *c = from_shader(k, *c);
                }
                v
            }
        };
        if !dst.alpha {
            v[3] = F32x8::splat(k.one());
        }
        for ch in 0..4 {
            if !mask[ch] {
                v[ch] = d[ch];
            }
        }
        store_aos(wptr, pass, v, full);
        let m8 = mirror8(k, v);
        if full {
            m8.store(cptr);
        } else {
            m8.maskstore(cptr, pass);
        }
        u64::from(pass.movemask().count_ones())
    }
}

/// The per-pixel mask of the register holding pixels `2j` and `2j + 1` (four lanes each).
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn pixel_mask(pass: I32x8, j: i32) -> I32x8 {
    // SAFETY: the caller's AVX2 context.
    unsafe {
        let (a, b) = (2 * j, 2 * j + 1);
        pass.permute_var(I32x8::new([a, a, a, a, b, b, b, b]))
    }
}

/// The RGBA f32 pixels at `p` (the lanes of `pass`, others 0) as one register per channel;
/// plain loads when `full` (all 8 pixels pass).
///
/// # Safety
/// AVX2 context; the lanes of `pass` are readable, all 8 pixels when `full`.
#[inline(always)]
unsafe fn load_aos(p: *const i32, pass: I32x8, full: bool) -> Vec4 {
    // SAFETY: the caller's AVX2 context; masked loads read the lanes of `pass` only, plain
    // ones the 8 pixels the caller vouches for.
    unsafe {
        let mut q = [F32x8::zero(); 4];
        for (j, r) in q.iter_mut().enumerate() {
            let at = p.wrapping_add(8 * j);
            *r = if full {
                I32x8::load(at)
            } else {
                I32x8::maskload(at, pixel_mask(pass, j as i32))
            }
            .as_f32();
        }
        // Pixels (0 | 4), (1 | 5), (2 | 6), (3 | 7) per 128-bit half.
        let u0 = q[0].perm128::<0x20>(q[2]);
        let u1 = q[0].perm128::<0x31>(q[2]);
        let u2 = q[1].perm128::<0x20>(q[3]);
        let u3 = q[1].perm128::<0x31>(q[3]);
        // r r g g and b b a a of pixels (0, 1 | 4, 5) and (2, 3 | 6, 7).
        let t0 = u0.unpack_lo(u1);
        let t1 = u0.unpack_hi(u1);
        let t2 = u2.unpack_lo(u3);
        let t3 = u2.unpack_hi(u3);
        [
            t0.shuffle::<0x44>(t2),
            t0.shuffle::<0xEE>(t2),
            t1.shuffle::<0x44>(t3),
            t1.shuffle::<0xEE>(t3),
        ]
    }
}

/// Stores the channels `v` as RGBA f32 pixels at `p`, the lanes of `pass` only (all 8
/// with plain stores when `full`).
///
/// # Safety
/// AVX2 context; the lanes of `pass` are writable, all 8 pixels when `full`.
#[inline(always)]
unsafe fn store_aos(p: *mut i32, pass: I32x8, v: Vec4, full: bool) {
    // SAFETY: the caller's AVX2 context; masked stores write the lanes of `pass` only,
    // plain ones the 8 pixels the caller vouches for.
    unsafe {
        let q = crate::simd::pack::pixels_of(v);
        for (j, r) in q.iter().enumerate() {
            let at = p.wrapping_add(8 * j);
            if full {
                r.bits().store(at);
            } else {
                r.bits().maskstore(at, pixel_mask(pass, j as i32));
            }
        }
    }
}

/// The packed 8-bit mirror ([`WideKind::mirror8`] of each channel) of stored values `v`.
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn mirror8(k: WideKind, v: Vec4) -> I32x8 {
    // SAFETY: the caller's AVX2 context.
    unsafe {
        let mut acc = I32x8::zero();
        for (ch, c) in v.iter().enumerate() {
            let u = k.mirror8_lanes(*c);
            acc = acc.or(u.shl_var(I32x8::splat(8 * ch as i32)));
        }
        acc
    }
}

/// The stored values of packed 8-bit pixels `c8` ([`WideKind::from_u8`]).
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn from_u8(k: WideKind, c8: I32x8) -> Vec4 {
    // SAFETY: the caller's AVX2 context.
    unsafe {
        let mut v = [F32x8::zero(); 4];
        for (ch, c) in v.iter_mut().enumerate() {
            let b = c8
                .shr_var(I32x8::splat(8 * ch as i32))
                .and(I32x8::splat(0xFF));
            *c = k.from_u8_lanes(b);
        }
        v
    }
}

/// [`unorm16`] per lane, as integers.
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn unorm16_8(c: F32x8) -> I32x8 {
    // SAFETY: the caller's AVX2 context.
    unsafe {
        let v = sat(c)
            .mul(F32x8::splat(65535.0f32 / 65536.0f32))
            .add(F32x8::splat(128.0));
        v.bits().and(I32x8::splat(0xFFFF))
    }
}

/// [`crate::framebuffer::wide::f16_round`] per lane: toward zero to a half's precision
/// (the low 13 mantissa bits cleared; below 2^-14 steps of 2^-24), 65504 past it, and
/// infinities and NaN unchanged.
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn f16_8(x: F32x8) -> F32x8 {
    // SAFETY: the caller's AVX2 context.
    unsafe {
        let bits = x.bits();
        let sign = bits.and(I32x8::splat(i32::MIN));
        let abs = bits.and(I32x8::splat(i32::MAX));
        let normal = bits.and(I32x8::splat(!0x1FFF));
        let step = 2.0f32.powi(-24);
        let tiny = abs
            .as_f32()
            .mul(F32x8::splat(1.0 / step))
            .to_i32_trunc()
            .to_f32()
            .mul(F32x8::splat(step))
            .bits()
            .or(sign);
        let max = I32x8::splat(65504.0f32.to_bits() as i32).or(sign);
        let is_tiny = I32x8::splat(2.0f32.powi(-14).to_bits() as i32).cmpgt(abs);
        let is_big = abs.cmpgt(I32x8::splat(65504.0f32.to_bits() as i32 - 1));
        let finite = I32x8::splat(f32::INFINITY.to_bits() as i32).cmpgt(abs);
        let r = normal
            .blendv(tiny, is_tiny)
            .blendv(max, is_big)
            .blendv(bits, finite.xor(I32x8::splat(-1)));
        r.as_f32()
    }
}

/// A shader channel as the buffer stores it ([`WideKind::from_shader`]).
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn from_shader(k: WideKind, c: F32x8) -> F32x8 {
    // SAFETY: the caller's AVX2 context.
    unsafe {
        match k {
            WideKind::Unorm16 => unorm16_8(c).to_f32(),
            WideKind::Float16 => f16_8(c),
            WideKind::Float32 => c,
        }
    }
}

/// Rust's `a.min(b)` as LLVM lowers it on x86: `vminps(b, a)`, `b` where `a` is NaN.
#[inline(always)]
fn rmin(a: F32x8, b: F32x8) -> F32x8 {
    b.blendv(b.min(a), a.cmp_ord(a))
}

/// Rust's `a.max(b)`, as [`rmin`].
#[inline(always)]
fn rmax(a: F32x8, b: F32x8) -> F32x8 {
    b.blendv(b.max(a), a.cmp_ord(a))
}

/// The colour and alpha equation and factors of channel `ch`.
#[inline(always)]
fn channel_of(p: &BlendPlan, ch: usize) -> (BlendEquation, BlendFactor, BlendFactor) {
    if ch < 3 {
        (p.eq_rgb, p.src_rgb, p.dst_rgb)
    } else {
        (p.eq_a, p.src_a, p.dst_a)
    }
}

/// llvmpipe's unorm16 multiply ([`super::wide::mul16`]) per lane.
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn mul16(a: I32x8, b: I32x8) -> I32x8 {
    // SAFETY: the caller's AVX2 context.
    unsafe {
        let t = a.mullo(b);
        t.add(t.shr::<16>()).add(I32x8::splat(0x8000)).shr::<16>()
    }
}

/// A blend factor in 16-bit fixed point per lane (`super::wide`'s `factor16`): `s`, `d`
/// and the constant colour `k` as integers.
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn factor16(
    f: BlendFactor,
    s: &[I32x8; 4],
    d: &[I32x8; 4],
    k: &[I32x8; 4],
    ch: usize,
) -> I32x8 {
    // SAFETY: the caller's AVX2 context.
    let (zero, one) = unsafe { (I32x8::zero(), I32x8::splat(65535)) };
    blend_factor!(f, s, d, k, ch; zero, one, I32x8::sub, I32x8::min)
}

/// Blends in 16-bit fixed point as [`super::wide`]'s `blend` does for unorm16.
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn blend16(p: &BlendPlan, kf: [f32; 4], s: Vec4, d: Vec4) -> Vec4 {
    // SAFETY: the caller's AVX2 context.
    unsafe {
        let one = I32x8::splat(65535);
        let mut si = [I32x8::zero(); 4];
        let mut di = [I32x8::zero(); 4];
        let mut ki = [I32x8::zero(); 4];
        for ch in 0..4 {
            si[ch] = unorm16_8(s[ch]);
            di[ch] = d[ch].to_i32_trunc();
            ki[ch] = I32x8::splat(i32::from(unorm16(kf[ch])));
        }
        let mut out = [F32x8::zero(); 4];
        for ch in 0..4 {
            let (eq, sfe, dfe) = channel_of(p, ch);
            let sf = factor16(sfe, &si, &di, &ki, ch);
            let df = factor16(dfe, &si, &di, &ki, ch);
            let (sc, dc) = (si[ch], di[ch]);
            let v = match eq {
                BlendEquation::Add => mul16(sc, sf).add(mul16(dc, df)).min_u32(one),
                BlendEquation::Subtract => mul16(sc, sf).sub(mul16(dc, df)).max(I32x8::zero()),
                BlendEquation::ReverseSubtract => {
                    mul16(dc, df).sub(mul16(sc, sf)).max(I32x8::zero())
                }
                BlendEquation::Min => sc.min(dc),
                BlendEquation::Max => sc.max(dc),
            };
            out[ch] = v.to_f32();
        }
        out
    }
}

/// A blend factor in f32 per lane (`super::wide`'s `factor_f`).
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn factor_f(f: BlendFactor, s: &Vec4, d: &Vec4, k: &Vec4, ch: usize) -> F32x8 {
    // SAFETY: the caller's AVX2 context.
    let (zero, one) = unsafe { (F32x8::zero(), F32x8::splat(1.0)) };
    blend_factor!(f, s, d, k, ch; zero, one, F32x8::sub, rmin)
}

/// A blend equation in f32 per lane, each product rounded (`super::wide`'s `equation_f`).
#[inline(always)]
fn equation_f(eq: BlendEquation, s: F32x8, sf: F32x8, d: F32x8, df: F32x8) -> F32x8 {
    match eq {
        BlendEquation::Add => s.mul(sf).add(d.mul(df)),
        BlendEquation::Subtract => s.mul(sf).sub(d.mul(df)),
        BlendEquation::ReverseSubtract => d.mul(df).sub(s.mul(sf)),
        BlendEquation::Min => rmin(s, d),
        BlendEquation::Max => rmax(s, d),
    }
}

/// `w·(b − a) + a`, fused when `fused` (then the context has FMA).
///
/// # Safety
/// AVX2 context, FMA when `fused`.
#[inline(always)]
unsafe fn lerp<const FMA: bool>(fused: bool, w: F32x8, a: F32x8, b: F32x8) -> F32x8 {
    // SAFETY: the caller's AVX2 context; `mul_add` only in copies compiled with FMA.
    unsafe {
        if FMA && fused {
            w.mul_add(b.sub(a), a)
        } else {
            w.mul(b.sub(a)).add(a)
        }
    }
}

/// Blends float shader colours over stored float colours as [`super::wide`]'s
/// `blend_float` does (the folded factors when they pair up, `plan.fma` fusing the lerp),
/// then stores at precision `k`.
///
/// # Safety
/// AVX2 context (FMA when `FMA`; [`covers`] keeps `plan.fma` to copies with FMA).
#[inline(always)]
unsafe fn blend_float<const FMA: bool>(
    k: WideKind,
    plan: &FragPlan,
    p: &BlendPlan,
    s: Vec4,
    d: Vec4,
    single: bool,
) -> Vec4 {
    // SAFETY: the caller's AVX2 (+FMA) context.
    unsafe {
        let mut kf = [F32x8::zero(); 4];
        for ch in 0..4 {
            kf[ch] = F32x8::splat(plan.blend_color[ch]);
        }
        let fused = plan.fma;
        let same = single || (p.src_rgb == p.dst_rgb && p.src_a == p.dst_a);
        let mut out = [F32x8::zero(); 4];
        for ch in 0..4 {
            let (eq, sfe, dfe) = channel_of(p, ch);
            let (sc, dc) = (s[ch], d[ch]);
            let sf = factor_f(sfe, &s, &d, &kf, ch);
            let df = factor_f(dfe, &s, &d, &kf, ch);
            let folded = if same {
                match (complement(sfe) == Some(dfe), eq) {
                    (true, BlendEquation::Add) if positive(sfe) => {
                        Some(lerp::<FMA>(fused, sf, dc, sc))
                    }
                    (true, BlendEquation::Add) => Some(lerp::<FMA>(fused, df, sc, dc)),
                    (true, BlendEquation::Subtract) if positive(sfe) => {
                        Some(sc.add(dc).mul(sf).sub(dc))
                    }
                    (true, BlendEquation::Subtract) => Some(sc.sub(sc.add(dc).mul(df))),
                    (true, BlendEquation::ReverseSubtract) if positive(sfe) => {
                        Some(dc.sub(sc.add(dc).mul(sf)))
                    }
                    (true, BlendEquation::ReverseSubtract) => Some(sc.add(dc).mul(df).sub(sc)),
                    (false, BlendEquation::Add) if sfe == dfe => Some(sc.add(dc).mul(sf)),
                    (false, BlendEquation::Subtract) if sfe == dfe => Some(sc.sub(dc).mul(sf)),
                    (false, BlendEquation::ReverseSubtract) if sfe == dfe => {
                        Some(dc.sub(sc).mul(sf))
                    }
                    _ => None,
                }
            } else {
                None
            };
            let v = match folded {
                Some(v) => v,
                None => equation_f(eq, sc, sf, dc, df),
            };
            out[ch] = from_shader(k, v);
        }
        out
    }
}
