//! The AVX2 span shader for the most common plan: smooth or flat colour, optional
//! perspective, optional depth test, plain colour write (no alpha test, stencil, blending,
//! logic op or texture). Eight pixels per iteration in 256-bit registers: eight of a row's
//! span, or for a triangle less than four pixels wide, a 4x2 block of two rows
//! ([`shade_pair`]).
//!
//! It computes exactly what [`super::span::shade_chunk`] computes: the plane evaluation
//! `fmuladd(dady, py, fmuladd(dadx, px, a0))` (fused only in the FMA variant), the exact
//! reciprocal of the 1/w plane, and `cvtps2dq` (round half to even under the default
//! MXCSR) for the colour and Z24 conversions, which is the instruction llvmpipe uses.

#![cfg(target_arch = "x86_64")]

use super::simd_plane::{write8_in, Bits8};
use super::span::Span;
use super::{BlendPlan, DepthPlan, FragPlan};
use crate::framebuffer::{DepthFormat, Target};
use crate::geometry::setup::{Plane, SetupTriangle};
use crate::pipe::CompareFunc;
use crate::pipe::{BlendEquation, BlendFactor};
use crate::simd::{F32x8, I32x8, U16x16};
use crate::stats::Stats;

/// Evaluates `p` at lanes `fx`, row `fy`.
#[inline(always)]
pub(super) unsafe fn eval<const FMA: bool>(p: &Plane, fx: F32x8, fy: F32x8) -> F32x8 {
    // SAFETY: called only from functions compiled with AVX2 (and FMA when FMA is set).
    unsafe {
        let (a0, dx, dy) = (
            F32x8::splat(p.a0),
            F32x8::splat(p.dadx),
            F32x8::splat(p.dady),
        );
        if FMA {
            dy.mul_add(fy, dx.mul_add(fx, a0))
        } else {
            dy.mul(fy).add(dx.mul(fx).add(a0))
        }
    }
}

/// Clamps to [0,1] with NaN → 0 (`maxps` returns its second operand for NaN).
#[inline(always)]
pub(super) unsafe fn sat(v: F32x8) -> F32x8 {
    // SAFETY: AVX2 context (see `eval`).
    unsafe { v.max(F32x8::zero()).min(F32x8::splat(1.0)) }
}

/// `d FUNC q` as a lane mask, for unsigned values below 2^31.
#[inline(always)]
pub(crate) unsafe fn depth_pass(func: CompareFunc, q: I32x8, d: I32x8) -> I32x8 {
    // SAFETY: AVX2 context (see `eval`).
    unsafe {
        let ones = I32x8::splat(-1);
        let gt = q.cmpgt(d);
        let lt = d.cmpgt(q);
        let eq = q.cmpeq(d);
        match func {
            CompareFunc::Never => I32x8::zero(),
            CompareFunc::Less => lt,
            CompareFunc::Equal => eq,
            CompareFunc::LEqual => gt.xor(ones),
            CompareFunc::Greater => gt,
            CompareFunc::NotEqual => eq.xor(ones),
            CompareFunc::GEqual => lt.xor(ones),
            CompareFunc::Always => ones,
        }
    }
}

/// `d FUNC q` as a lane mask for the values of `format`: [`depth_pass`], with the sign bit
/// of both sides flipped first for Z32 (whose values reach 2^32 − 1), which turns the
/// signed compare into the unsigned one llvmpipe makes.
#[inline(always)]
pub(super) unsafe fn depth_pass_in(
    func: CompareFunc,
    format: DepthFormat,
    q: I32x8,
    d: I32x8,
) -> I32x8 {
    // SAFETY: AVX2 context (see `eval`).
    unsafe {
        if format == DepthFormat::Z32 {
            let sign = I32x8::splat(i32::MIN);
            depth_pass(func, q.xor(sign), d.xor(sign))
        } else {
            depth_pass(func, q, d)
        }
    }
}

/// The depth test of the `live` lanes of 8 pixels at `idx` of the depth rows `depth` (a
/// target's, or a sample plane's; lanes `fx`, row `fy`): Z from the plane, clamped and
/// quantised as [`super::span::shade_chunk`] does, compared with the stored values and,
/// where it passes and the plan writes depth, stored. Returns the passing lanes.
///
/// # Safety
/// AVX2 (+FMA when `FMA`) context; the live lanes lie inside `depth`.
#[inline(always)]
pub(super) unsafe fn depth_test8<const FMA: bool>(
    t: &SetupTriangle,
    d: &DepthPlan,
    depth: &mut [u32],
    idx: usize,
    fx: F32x8,
    fy: F32x8,
    live: I32x8,
) -> I32x8 {
    // SAFETY: forwarded from the caller; the masked store touches passing lanes only.
    unsafe {
        let (pass, q) = depth_probe8::<FMA>(t, d, depth, idx, fx, fy, live);
        if d.write {
            let dptr = depth.as_mut_ptr().add(idx) as *mut i32;
            store_masked(dptr, depth.len().saturating_sub(idx), pass, q);
        }
        pass
    }
}

/// [`depth_test8`] without the store (also for a test run again after it,
/// [`super::simd_gen::depth_pretest`]): the `live` lanes of the 8 at `idx` whose Z passes
/// against the stored values, and the Z of all 8. When all 8 values lie inside `depth`
/// they are read with one plain load (the masked load costs more, and the dead lanes are
/// masked after).
///
/// # Safety
/// AVX2 (+FMA when `FMA`) context; the live lanes lie inside `depth`.
#[inline(always)]
pub(super) unsafe fn depth_probe8<const FMA: bool>(
    t: &SetupTriangle,
    d: &DepthPlan,
    depth: &[u32],
    idx: usize,
    fx: F32x8,
    fy: F32x8,
    live: I32x8,
) -> (I32x8, I32x8) {
    // SAFETY: forwarded from the caller; the plain load reads 8 values inside `depth`,
    // the masked one live lanes only.
    unsafe {
        let q = depth_q::<FMA>(t, d.format, fx, fy);
        let dptr = depth.as_ptr().add(idx) as *const i32;
        let old = if depth.len().saturating_sub(idx) >= super::span::LANES {
            I32x8::load(dptr)
        } else {
            I32x8::maskload(dptr, live)
        };
        (live.and(depth_pass_in(d.func, d.format, q, old)), q)
    }
}

/// Stores the `pass` lanes of `v` at `ptr`, of which `avail` 32-bit values up to the end
/// of the buffer may be touched: a plain store when all 8 lanes pass and lie inside the
/// buffer, else `vpmaskmovd`. The masked store is microcoded on AMD (Zen 4 here: 8–9% of a
/// bilinear frame sat on it), so full chunks avoid it; a partial chunk keeps it, since a
/// load-blend-store there made immediate_100k 1024² (1 thread) slower, 28.0 → 38.6 ms
/// (25th percentile of 50 frames), probably by chaining each store to the next
/// triangle's load of the same pixels.
///
/// # Safety
/// AVX2 context; the passing lanes lie inside the buffer, and `avail` is the number of
/// values from `ptr` to its end.
#[inline(always)]
pub(crate) unsafe fn store_masked(ptr: *mut i32, avail: usize, pass: I32x8, v: I32x8) {
    // SAFETY: forwarded from the caller; the plain load and store touch 8 values only
    // when `avail` says they are inside the buffer.
    unsafe {
        let m = pass.movemask();
        if m == 0xff && avail >= 8 {
            v.store(ptr);
        } else {
            v.maskstore(ptr, pass);
        }
    }
}

/// Writes the packed RGBA8 colours `px` of the `pass` lanes of 8 pixels at `idx` of the
/// colour buffer, blended over the stored colours when `BLEND` (`n`: the lanes inside the
/// row, counted as colour reads as [`super::span::shade_chunk`] counts them). With `OVER`
/// the plan is one that [`blend_is_over`] accepts, blended by [`over8`]: the same
/// arithmetic as [`blend8`] for that plan, without the per-call factor dispatch.
///
/// # Safety
/// AVX2 context; the passing lanes lie inside the colour buffer.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(super) unsafe fn write8<const BLEND: bool, const OVER: bool>(
    plan: &FragPlan,
    fb: &mut Target<'_>,
    idx: usize,
    n: usize,
    pass: I32x8,
    px: I32x8,
    stats: &mut Stats,
) {
    // SAFETY: forwarded from the caller.
    unsafe { write8_in::<BLEND, OVER>(plan, fb.color, idx, n, pass, px, Bits8::PLAIN, stats) }
}

/// Whether `p` is the classic "over" blend: SRC_ALPHA, ONE_MINUS_SRC_ALPHA, ADD for RGB
/// and alpha alike, which [`over8`] computes without dispatching on the factors.
pub fn blend_is_over(p: &BlendPlan) -> bool {
    p.src_rgb == BlendFactor::SrcAlpha
        && p.dst_rgb == BlendFactor::OneMinusSrcAlpha
        && p.src_a == BlendFactor::SrcAlpha
        && p.dst_a == BlendFactor::OneMinusSrcAlpha
        && p.eq_rgb == BlendEquation::Add
        && p.eq_a == BlendEquation::Add
}

/// The "over" blend of eight packed RGBA8 source pixels over eight destination pixels:
/// [`blend8`] for a plan that [`blend_is_over`] accepts.
#[inline(always)]
pub(crate) unsafe fn over8(px: I32x8, dst: I32x8) -> I32x8 {
    // SAFETY: AVX2 context (see `eval`).
    unsafe {
        let z = I32x8::zero();
        // Not closures: they would be compiled without AVX2 and not inlined.
        let lo = over16(px.unpack_lo_u8(z), dst.unpack_lo_u8(z));
        let hi = over16(px.unpack_hi_u8(z), dst.unpack_hi_u8(z));
        lo.pack_u8(hi)
    }
}

/// The "over" blend of four pixels held as 16-bit channel words: `blend16` for a plan
/// that [`blend_is_over`] accepts.
#[inline(always)]
unsafe fn over16(s: U16x16, d: U16x16) -> U16x16 {
    // SAFETY: AVX2 context (see `eval`).
    unsafe {
        let c255 = U16x16::splat(255);
        let a = alpha_words(s);
        mul8x16(s, a).add(mul8x16(d, c255.sub(a))).min(c255)
    }
}

/// `DEPTH` of [`shade_span`]: no depth test.
pub const D_NONE: u8 = 0;
/// `DEPTH` of [`shade_span`]: GL_LESS on a Z24 buffer.
pub const D_LESS: u8 = 1;
/// `DEPTH` of [`shade_span`]: GL_LEQUAL on a Z24 buffer.
pub const D_LEQUAL: u8 = 2;
/// `DEPTH` of [`shade_span`]: any function and format, read from the plan per chunk.
pub const D_ANY: u8 = 3;
/// `BLEND` of [`shade_span`]: no blending.
pub const B_NONE: u8 = 0;
/// `BLEND` of [`shade_span`]: any blend plan ([`blend8`]).
pub const B_ANY: u8 = 1;
/// `BLEND` of [`shade_span`]: a plan that [`blend_is_over`] accepts ([`over8`]).
pub const B_OVER: u8 = 2;

/// The `DEPTH` code of [`shade_span`] for a plan.
pub fn depth_code(plan: &FragPlan) -> u8 {
    match plan.depth.map(|d| (d.func, d.format)) {
        None => D_NONE,
        Some((CompareFunc::Less, DepthFormat::Z24)) => D_LESS,
        Some((CompareFunc::LEqual, DepthFormat::Z24)) => D_LEQUAL,
        Some(_) => D_ANY,
    }
}

/// The `BLEND` code of [`shade_span`] for a plan.
pub fn blend_code(plan: &FragPlan) -> u8 {
    match &plan.blend {
        None => B_NONE,
        Some(b) if blend_is_over(b) => B_OVER,
        Some(_) => B_ANY,
    }
}

/// `q FUNC old` as a lane mask, with the function fixed at compile time when `D` names it.
#[inline(always)]
unsafe fn depth_pass_d<const D: u8>(
    func: CompareFunc,
    format: DepthFormat,
    q: I32x8,
    old: I32x8,
) -> I32x8 {
    // SAFETY: AVX2 context (see `eval`).
    unsafe {
        match D {
            D_LESS => old.cmpgt(q),
            D_LEQUAL => q.cmpgt(old).xor(I32x8::splat(-1)),
            _ => depth_pass_in(func, format, q, old),
        }
    }
}

/// Z of 8 pixels quantised to the depth buffer's format, as [`depth_test8`] computes it.
#[inline(always)]
unsafe fn depth_q<const FMA: bool>(
    t: &SetupTriangle,
    f: DepthFormat,
    fx: F32x8,
    fy: F32x8,
) -> I32x8 {
    // SAFETY: AVX2 context (see `eval`).
    unsafe {
        let z = sat(eval::<FMA>(&t.z, fx, fy));
        match f {
            DepthFormat::Z24 => z.mul(F32x8::splat(16_777_215.0)).to_i32(),
            // `sat` is llvmpipe's clamp (maxps then minps: NaN and −0 give +0), and the
            // float's bits are stored.
            DepthFormat::Z32F => z.bits(),
            // [`crate::framebuffer::z32_unorm`]: z·2³¹ is exact and at most 2³¹, which
            // `cvttps2dq` turns into 0x80000000 (its overflow value), the same bits.
            DepthFormat::Z32 => {
                let r = z.mul(F32x8::splat(2_147_483_648.0)).to_i32_trunc();
                r.shl::<1>().sub(r.shr::<31>())
            }
            _ => {
                // f32(f32(z * 65535/65536) + 128) keeps the rounded value in the low 16 bits.
                let v = z
                    .mul(F32x8::splat(65535.0 / 65536.0))
                    .add(F32x8::splat(128.0));
                v.bits().and(I32x8::splat(0xFFFF))
            }
        }
    }
}

/// The packed RGBA8 colours of 8 pixels (lanes `fx`, row `fy`), as
/// [`super::span::shade_chunk`] converts them.
#[inline(always)]
unsafe fn color8<const FMA: bool, const FLAT: bool, const PERSP: bool>(
    t: &SetupTriangle,
    flat: I32x8,
    fx: F32x8,
    fy: F32x8,
) -> I32x8 {
    // SAFETY: AVX2 context (see `eval`).
    unsafe {
        if FLAT {
            return flat;
        }
        let oow = if PERSP {
            F32x8::splat(1.0).div(eval::<FMA>(&t.w, fx, fy))
        } else {
            F32x8::splat(1.0)
        };
        let mut acc = I32x8::zero();
        for ch in 0..4 {
            let mut a = eval::<FMA>(&t.vary[ch], fx, fy);
            if PERSP {
                a = a.mul(oow);
            }
            let u = sat(a).mul(F32x8::splat(255.0)).to_i32();
            acc = acc.or(u.shl_var(I32x8::splat(8 * ch as i32)));
        }
        acc
    }
}

/// Per-span tallies of [`chunk8`], added to the stats once per span.
#[derive(Default)]
struct Tally {
    /// Fragments that passed the depth test.
    passed: u64,
    /// Colour buffer reads.
    reads: u64,
}

impl Tally {
    /// Adds a span's (or block's) `count` fragments and these tallies to `stats`.
    #[inline(always)]
    fn count<const DEPTH: u8>(&self, plan: &FragPlan, count: u64, stats: &mut Stats) {
        stats.fragments += count;
        let passed = if DEPTH != D_NONE {
            stats.depth_reads += count;
            stats.depth_failed += count - self.passed;
            self.passed
        } else {
            count
        };
        if plan.color_mask[0] {
            stats.color_writes += passed;
            stats.color_reads += self.reads;
        }
    }
}

/// One chunk of [`shade_span`]: the 8 pixels at `idx` (lanes `fx`, row `fy`), of which
/// the first `n` are live (`live` as a mask; all 8 when `FULL`, which uses plain loads
/// and stores: every lane lies in this span, so rewriting a lane with its own value is
/// invisible).
///
/// # Safety
/// AVX2 (+FMA when `FMA`) context; the live lanes lie inside the buffers.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
unsafe fn chunk8<
    const FMA: bool,
    const DEPTH: u8,
    const FLAT: bool,
    const PERSP: bool,
    const BLEND: u8,
    const FULL: bool,
    const PAIR: bool,
>(
    t: &SetupTriangle,
    plan: &FragPlan,
    fb: &mut Target<'_>,
    idx: usize,
    fx: F32x8,
    fy: F32x8,
    n: usize,
    live: I32x8,
    flat: I32x8,
    tally: &mut Tally,
) {
    // SAFETY: (whole body) forwarded from the caller; full loads and stores cover
    // `idx..idx + 8` only when `FULL`, masked ones only live (passing) lanes otherwise.
    unsafe {
        let mut pass = live;
        let mut all = true;
        if DEPTH != D_NONE {
            let Some(d) = plan.depth else { return };
            // The format is fixed at compile time for the named functions.
            let format = match DEPTH {
                D_LESS | D_LEQUAL => DepthFormat::Z24,
                _ => d.format,
            };
            let q = depth_q::<FMA>(t, format, fx, fy);
            let dptr = fb.depth.as_mut_ptr().add(idx) as *mut i32;
            let old = if FULL {
                I32x8::load(dptr)
            } else if PAIR {
                load_pair(dptr, fb.width, live)
            } else {
                I32x8::maskload(dptr as *const i32, live)
            };
            pass = depth_pass_d::<DEPTH>(d.func, format, q, old);
            if !FULL {
                pass = live.and(pass);
            }
            let m = pass.movemask();
            if m == 0 {
                return;
            }
            tally.passed += m.count_ones() as u64;
            all = FULL && m == 0xFF;
            if d.write {
                if FULL {
                    let v = old.blendv(q, pass);
                    v.store(dptr);
                } else if PAIR {
                    store_pair(dptr, fb.width, pass, q);
                } else {
                    store_masked(dptr, fb.depth.len().saturating_sub(idx), pass, q);
                }
            }
        }
        if !plan.color_mask[0] {
            return;
        }
        let px = color8::<FMA, FLAT, PERSP>(t, flat, fx, fy);
        let cptr = fb.color.as_mut_ptr().add(idx) as *mut i32;
        let px = if BLEND == B_NONE {
            px
        } else {
            let dst = if FULL {
                I32x8::load(cptr)
            } else if PAIR {
                load_pair(cptr, fb.width, pass)
            } else {
                I32x8::maskload(cptr as *const i32, pass)
            };
            tally.reads += if PAIR {
                // Counted as the two rows' spans count: a row's live lanes, when one of
                // them passed the depth test.
                let (l, m) = (live.movemask(), pass.movemask());
                let row = |r: u32| if m & r != 0 { (l & r).count_ones() } else { 0 };
                u64::from(row(0x0F) + row(0xF0))
            } else {
                n as u64
            };
            let out = match (BLEND, &plan.blend) {
                (B_OVER, _) => over8(px, dst),
                (_, Some(b)) => blend8(b, px, dst),
                (_, None) => px,
            };
            if FULL && !all {
                // Failing lanes keep their stored colour.
                dst.blendv(out, pass)
            } else {
                out
            }
        };
        if FULL && (all || BLEND != B_NONE) {
            px.store(cptr);
        } else if PAIR {
            store_pair(cptr, fb.width, pass, px);
        } else {
            store_masked(cptr, fb.color.len().saturating_sub(idx), pass, px);
        }
    }
}

/// Shades span `s`. The caller guarantees the plan has no alpha test,
/// stencil, logic op or texture, a colour format with 8-bit alpha layout that stores
/// values unchanged (RGBA, BGRA, ARGB), a full colour mask or none, and that `DEPTH`
/// ([`depth_code`]) and `BLEND` ([`blend_code`]) match the plan.
///
/// Whole chunks of 8 pixels use plain loads and stores; only the last, partial chunk is
/// masked. The stats are added once per span.
///
/// # Safety
/// Must be called from a function compiled with AVX2 (and FMA when `FMA`).
#[inline(always)]
pub unsafe fn shade_span<
    const FMA: bool,
    const DEPTH: u8,
    const FLAT: bool,
    const PERSP: bool,
    const BLEND: u8,
>(
    t: &SetupTriangle,
    plan: &FragPlan,
    fb: &mut Target<'_>,
    s: Span,
    stats: &mut Stats,
) {
    let Span { y: py, x0, x1 } = s;
    let count = (x1 + 1 - x0) as u64;
    let mut tally = Tally::default();
    // SAFETY: (whole body) AVX2 (+FMA) context guaranteed by the caller; every chunk
    // covers lanes `x..x + n` with `x + n <= x1 + 1 <= w`, inside row `py`.
    unsafe {
        let lane = F32x8::new([0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0]);
        let fy = F32x8::splat(py as f32);
        let flat = I32x8::splat(u32::from_le_bytes(t.flat_u8) as i32);
        let row = (py - fb.y0) * fb.width;
        let end = x1 + 1;
        let mut x = x0;
        // Pixel coordinates are integers below 2^24: stepping by 8 is exact.
        let mut fx = F32x8::splat(x as f32).add(lane);
        let all = I32x8::splat(-1);
        while x + 8 <= end {
            chunk8::<FMA, DEPTH, FLAT, PERSP, BLEND, true, false>(
                t,
                plan,
                fb,
                row + x,
                fx,
                fy,
                8,
                all,
                flat,
                &mut tally,
            );
            x += 8;
            fx = fx.add(F32x8::splat(8.0));
        }
        if x < end {
            let n = end - x;
            let lane_i = I32x8::new([0, 1, 2, 3, 4, 5, 6, 7]);
            let live = I32x8::splat(n as i32).cmpgt(lane_i);
            chunk8::<FMA, DEPTH, FLAT, PERSP, BLEND, false, false>(
                t,
                plan,
                fb,
                row + x,
                fx,
                fy,
                n,
                live,
                flat,
                &mut tally,
            );
        }
    }
    tally.count::<DEPTH>(plan, count, stats);
}

/// Shades the pixels of a 4x2 block set in `mask` in one chunk: bits 0–3 are pixels
/// `x0..x0 + 4` of row `py`, bits 4–7 the same columns of row `py + 1` (the row pairs of
/// a narrow triangle, [`crate::raster`]). Each pixel gets exactly what [`shade_span`]
/// gives it (every value is computed per lane from the pixel's own coordinates), and the
/// stats count the same as the rows' spans would.
///
/// # Safety
/// As [`shade_span`]; the pixels set in `mask` lie inside the target's rows and width.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub unsafe fn shade_pair<
    const FMA: bool,
    const DEPTH: u8,
    const FLAT: bool,
    const PERSP: bool,
    const BLEND: u8,
>(
    t: &SetupTriangle,
    plan: &FragPlan,
    fb: &mut Target<'_>,
    py: usize,
    x0: usize,
    mask: u32,
    stats: &mut Stats,
) {
    let count = mask.count_ones() as u64;
    let mut tally = Tally::default();
    // SAFETY: AVX2 (+FMA) context guaranteed by the caller; the live lanes are the pixels
    // of `mask`, inside the target.
    unsafe {
        // Pixel coordinates are integers below 2^24: the sums are exact, the same values
        // as a span's lanes.
        let fx = F32x8::splat(x0 as f32).add(F32x8::new([0.0, 1.0, 2.0, 3.0, 0.0, 1.0, 2.0, 3.0]));
        let fy = F32x8::splat(py as f32).add(F32x8::new([0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0]));
        let bits = I32x8::new([1, 2, 4, 8, 16, 32, 64, 128]);
        let live = I32x8::splat(mask as i32).and(bits).cmpeq(bits);
        let flat = I32x8::splat(u32::from_le_bytes(t.flat_u8) as i32);
        let idx = (py - fb.y0) * fb.width + x0;
        chunk8::<FMA, DEPTH, FLAT, PERSP, BLEND, false, true>(
            t,
            plan,
            fb,
            idx,
            fx,
            fy,
            count as usize,
            live,
            flat,
            &mut tally,
        );
    }
    tally.count::<DEPTH>(plan, count, stats);
}

/// Loads the `live` lanes of a 4x2 block: lanes 0–3 from `ptr`, lanes 4–7 from the row
/// `stride` values further (0 in the other lanes).
///
/// # Safety
/// AVX2 context; the live lanes lie inside the buffer.
#[inline(always)]
unsafe fn load_pair(ptr: *const i32, stride: usize, live: I32x8) -> I32x8 {
    // SAFETY: forwarded from the caller; masked loads touch live lanes only, and the second
    // row's address is formed with wrapping arithmetic (it may lie past the buffer when
    // none of its lanes is live).
    unsafe { I32x8::maskload_halves(ptr, ptr.wrapping_add(stride), live) }
}

/// Stores the `pass` lanes of a 4x2 block (see [`load_pair`]).
///
/// # Safety
/// AVX2 context; the passing lanes lie inside the buffer.
#[inline(always)]
unsafe fn store_pair(ptr: *mut i32, stride: usize, pass: I32x8, v: I32x8) {
    // SAFETY: as in `load_pair`.
    unsafe {
        v.maskstore_halves(ptr, ptr.wrapping_add(stride), pass);
    }
}

/// Broadcasts each pixel's alpha word to its four channel words (16-bit lanes).
#[inline(always)]
unsafe fn alpha_words(v: U16x16) -> U16x16 {
    // SAFETY: AVX2 context (see `eval`).
    v.shuffle4::<0xFF>()
}

/// A blend factor for four pixels in 16-bit lanes (`rgb` selects the RGB factor rules).
#[inline(always)]
unsafe fn factor16(f: BlendFactor, s: U16x16, d: U16x16, k: U16x16, rgb: bool) -> U16x16 {
    // SAFETY: AVX2 context (see `eval`).
    unsafe {
        let c255 = U16x16::splat(255);
        // A function, not a closure, so it is compiled with the caller's AVX2.
        #[inline(always)]
        unsafe fn inv(v: U16x16) -> U16x16 {
            // SAFETY: AVX2 context (see `eval`).
            unsafe { U16x16::splat(255).sub(v) }
        }
        match f {
            BlendFactor::Zero => U16x16::zero(),
            BlendFactor::One => c255,
            BlendFactor::SrcColor => s,
            BlendFactor::OneMinusSrcColor => inv(s),
            BlendFactor::DstColor => d,
            BlendFactor::OneMinusDstColor => inv(d),
            BlendFactor::SrcAlpha => alpha_words(s),
            BlendFactor::OneMinusSrcAlpha => inv(alpha_words(s)),
            BlendFactor::DstAlpha => alpha_words(d),
            BlendFactor::OneMinusDstAlpha => inv(alpha_words(d)),
            BlendFactor::ConstantColor => k,
            BlendFactor::OneMinusConstantColor => inv(k),
            BlendFactor::ConstantAlpha => alpha_words(k),
            BlendFactor::OneMinusConstantAlpha => inv(alpha_words(k)),
            BlendFactor::SrcAlphaSaturate => {
                if rgb {
                    alpha_words(s).min(inv(alpha_words(d)))
                } else {
                    c255
                }
            }
        }
    }
}

/// llvmpipe's unorm8 multiply on 16-bit lanes: `(t + (t >> 8) + 128) >> 8`, `t = a·b`.
#[inline(always)]
unsafe fn mul8x16(a: U16x16, b: U16x16) -> U16x16 {
    // SAFETY: AVX2 context (see `eval`).
    unsafe {
        let t = a.mullo(b);
        t.add(t.shr::<8>()).add(U16x16::splat(128)).shr::<8>()
    }
}

#[inline(always)]
unsafe fn equation16(eq: BlendEquation, s: U16x16, sf: U16x16, d: U16x16, df: U16x16) -> U16x16 {
    // SAFETY: AVX2 context (see `eval`).
    unsafe {
        match eq {
            BlendEquation::Add => mul8x16(s, sf).add(mul8x16(d, df)).min(U16x16::splat(255)),
            BlendEquation::Subtract => mul8x16(s, sf).sub_sat(mul8x16(d, df)),
            BlendEquation::ReverseSubtract => mul8x16(d, df).sub_sat(mul8x16(s, sf)),
            BlendEquation::Min => s.min(d),
            BlendEquation::Max => s.max(d),
        }
    }
}

/// Blends four pixels held as 16-bit channel words.
#[inline(always)]
unsafe fn blend16(p: &BlendPlan, s: U16x16, d: U16x16, k: U16x16) -> U16x16 {
    // SAFETY: AVX2 context (see `eval`).
    unsafe {
        let rgb = equation16(
            p.eq_rgb,
            s,
            factor16(p.src_rgb, s, d, k, true),
            d,
            factor16(p.dst_rgb, s, d, k, true),
        );
        let same_alpha = p.src_a == p.src_rgb
            && p.dst_a == p.dst_rgb
            && p.eq_a == p.eq_rgb
            && !matches!(p.src_rgb, BlendFactor::SrcAlphaSaturate)
            && !matches!(p.dst_rgb, BlendFactor::SrcAlphaSaturate);
        if same_alpha {
            return rgb;
        }
        let a = equation16(
            p.eq_a,
            s,
            factor16(p.src_a, s, d, k, false),
            d,
            factor16(p.dst_a, s, d, k, false),
        );
        rgb.blend::<0b1000_1000>(a)
    }
}

/// Blends eight packed RGBA8 source pixels over eight destination pixels exactly as
/// [`super::blend::blend`] does.
#[inline(always)]
pub(crate) unsafe fn blend8(p: &BlendPlan, src: I32x8, dst: I32x8) -> I32x8 {
    // SAFETY: AVX2 context (see `eval`).
    unsafe {
        let z = I32x8::zero();
        let kc = p.color;
        let k = U16x16::splat4(kc.map(u16::from));
        let lo = blend16(p, src.unpack_lo_u8(z), dst.unpack_lo_u8(z), k);
        let hi = blend16(p, src.unpack_hi_u8(z), dst.unpack_hi_u8(z), k);
        lo.pack_u8(hi)
    }
}
