//! 8-lane operations on the rows of one plane, a target's or a sample plane's (laid out
//! alike, [`crate::framebuffer::samples::PlaneRows`]): the stencil test with its updates
//! and the colour write through the colour mask, next to [`super::simd::depth_test8`].
//! The single-sample AVX2 paths write their target's rows through them, and the one-pass
//! multisample shader ([`super::multisample`]) each sample plane's rows.
//!
//! They compute what [`super::span::stencil_depth`] and [`super::span::write_colors`]
//! compute lane by lane: the stencil compare `ref & mask FUNC stored & mask`, each lane's
//! one update (stencil fail, depth fail or depth pass) through the write mask, and the
//! blended colour stored through the colour mask.

#![cfg(target_arch = "x86_64")]

use super::simd::{blend8, depth_pass, depth_test8, over8, store_masked};
use super::span::LANES;
use super::{FragPlan, StencilFacePlan};
use crate::geometry::setup::SetupTriangle;
use crate::pipe::StencilOp;
use crate::simd::{F32x8, I32x8};
use crate::stats::Stats;

/// Which stored bits a colour write keeps and which it sets, per packed RGBA8 pixel: the
/// channels the colour mask leaves out are kept, and a format without alpha stores alpha
/// 255 ([`crate::framebuffer::ColorFormat::store_rgba8`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Bits8 {
    /// Bits of the stored colour kept.
    pub keep: u32,
    /// Bits set in the written colour (before the kept bits are merged back).
    pub set: u32,
}

impl Bits8 {
    /// A full colour mask into a format that stores RGBA8 unchanged.
    pub const PLAIN: Bits8 = Bits8 { keep: 0, set: 0 };

    /// The bits of `mask` and `format` (RGB565 is not an 8-bit packed layout: callers
    /// leave it to the scalar store).
    pub fn of(mask: [bool; 4], format: crate::framebuffer::ColorFormat) -> Self {
        let mut keep = 0;
        for (ch, &m) in mask.iter().enumerate() {
            if !m {
                keep |= 0xFF << (8 * ch);
            }
        }
        let set = if format.has_alpha() { 0 } else { 0xFF00_0000 };
        Bits8 { keep, set }
    }
}

/// [`write8`] into the colour rows `color` (a target's, or a sample plane's), with the
/// stored bits `bits` keeps merged back after blending and those it sets set, as
/// [`super::span::write_colors`] stores through the colour mask.
///
/// # Safety
/// AVX2 context; the passing lanes lie inside `color`.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(super) unsafe fn write8_in<const BLEND: bool, const OVER: bool>(
    plan: &FragPlan,
    color: &mut [[u8; 4]],
    idx: usize,
    n: usize,
    pass: I32x8,
    px: I32x8,
    bits: Bits8,
    stats: &mut Stats,
) {
    // SAFETY: forwarded from the caller; the masked load and store touch passing lanes.
    unsafe {
        let cptr = color.as_mut_ptr().add(idx) as *mut i32;
        let load = BLEND || OVER || bits.keep != 0;
        let dst = if load {
            I32x8::maskload(cptr as *const i32, pass)
        } else {
            px
        };
        let mut px = if BLEND || OVER {
            stats.color_reads += n as u64;
            if OVER {
                over8(px, dst)
            } else {
                let b = plan.blend.as_ref().expect("BLEND implies a blend plan");
                blend8(b, px, dst)
            }
        } else {
            px
        };
        if bits.set != 0 {
            px = px.or(I32x8::splat(bits.set as i32));
        }
        if bits.keep != 0 {
            let keep = I32x8::splat(bits.keep as i32);
            px = px.and(keep.xor(I32x8::splat(-1))).or(dst.and(keep));
        }
        store_masked(cptr, color.len().saturating_sub(idx), pass, px);
        stats.color_writes += pass.movemask().count_ones() as u64;
    }
}

/// The lanes set in `m` (all ones or zero per lane).
#[inline(always)]
pub(super) fn count(m: I32x8) -> u64 {
    u64::from(m.movemask().count_ones())
}

/// `a & !b` per lane.
#[inline(always)]
pub(super) fn and_not(a: I32x8, b: I32x8) -> I32x8 {
    // SAFETY: AVX2 as `a` proves.
    a.and(b.xor(unsafe { I32x8::splat(-1) }))
}

/// The stencil values of the lanes of a chunk (0..=255 per lane) and the lanes that
/// failed the stencil test: what [`stencil_test8`] read, for [`stencil_update8`].
#[derive(Clone, Copy)]
pub(super) struct Stencil8 {
    /// The stored values.
    pub old: I32x8,
    /// The live lanes that failed the test.
    pub fail: I32x8,
}

/// The stencil test of the `live` lanes of the `n` values at `idx` of `stencil` with face
/// `sp`: returns the stored values and failing lanes, and clears the failing lanes of
/// `live` (counted as [`super::span::stencil_depth`] counts them).
///
/// # Safety
/// AVX2 context.
#[inline(always)]
pub(super) unsafe fn stencil_test8(
    sp: &StencilFacePlan,
    stencil: &[u8],
    idx: usize,
    n: usize,
    live: &mut I32x8,
    stats: &mut Stats,
) -> Stencil8 {
    let mut b = [0u8; LANES];
    // A whole chunk is one 8-byte load; a variable length calls memcpy (3.8% of
    // stencil_ops on one thread).
    if n == LANES {
        b.copy_from_slice(&stencil[idx..idx + LANES]);
    } else {
        b[..n].copy_from_slice(&stencil[idx..idx + n]);
    }
    // SAFETY: forwarded from the caller.
    unsafe {
        let old = I32x8::from_u8(b);
        let masked = old.and(I32x8::splat(i32::from(sp.mask)));
        let test = depth_pass(sp.func, I32x8::splat(i32::from(sp.masked_ref)), masked);
        stats.stencil_reads += count(*live);
        let fail = and_not(*live, test);
        stats.stencil_failed += count(fail);
        *live = live.and(test);
        Stencil8 { old, fail }
    }
}

/// Stencil operation `op` on the values `s` with reference `r` (lanes of 0..=255), as
/// [`StencilOp::apply`].
#[inline(always)]
fn stencil_op8(op: StencilOp, s: I32x8, r: I32x8) -> I32x8 {
    // SAFETY: AVX2 as `s` proves.
    let (one, max) = unsafe { (I32x8::splat(1), I32x8::splat(255)) };
    match op {
        StencilOp::Keep => s,
        StencilOp::Zero => s.xor(s),
        StencilOp::Replace => r,
        StencilOp::Incr => s.add(one).min(max),
        StencilOp::Decr => s.sub(one).max(s.xor(s)),
        StencilOp::Invert => s.xor(max),
        StencilOp::IncrWrap => s.add(one).and(max),
        StencilOp::DecrWrap => s.sub(one).and(max),
    }
}

/// Writes the stencil updates of a chunk tested by [`stencil_test8`]: `st.fail` lanes
/// get the stencil-fail operation, `zfail` lanes the depth-fail one and `pass` lanes the
/// pass one, each through the write mask; the other lanes of the `n` at `idx` are
/// rewritten with their own values.
///
/// # Safety
/// AVX2 context.
#[inline(always)]
pub(super) unsafe fn stencil_update8(
    sp: &StencilFacePlan,
    stencil: &mut [u8],
    idx: usize,
    n: usize,
    st: Stencil8,
    zfail: I32x8,
    pass: I32x8,
) {
    if sp.fail == StencilOp::Keep && sp.zfail == StencilOp::Keep && sp.zpass == StencilOp::Keep
        || sp.write == 0
    {
        return;
    }
    // SAFETY: forwarded from the caller.
    let (r, w) = unsafe {
        (
            I32x8::splat(i32::from(sp.reference)),
            I32x8::splat(i32::from(sp.write)),
        )
    };
    let s = st.old;
    // Each lane's update: (s & !write) | (op(s) & write).
    let kept = and_not(s, w);
    let mut v = s;
    for (op, lanes) in [(sp.fail, st.fail), (sp.zfail, zfail), (sp.zpass, pass)] {
        if op != StencilOp::Keep {
            v = v.blendv(kept.or(stencil_op8(op, s, r).and(w)), lanes);
        }
    }
    let v = v.to_u8();
    if n == LANES {
        stencil[idx..idx + LANES].copy_from_slice(&v);
    } else {
        stencil[idx..idx + n].copy_from_slice(&v[..n]);
    }
}

/// The stencil test, the depth test at `fx`, `fy` ([`depth_test8`]) and the stencil
/// updates of the `live` lanes of the `n` values at `idx` of a plane's rows `stencil` and
/// `depth`, with face `sp` when the stencil test is on, counted as
/// [`super::span::stencil_depth`] counts them; returns the lanes that pass both.
///
/// # Safety
/// AVX2 context (FMA when `FMA`); the live lanes lie inside the rows.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(super) unsafe fn stencil_depth8<const FMA: bool, const DEPTH: bool>(
    t: &SetupTriangle,
    plan: &FragPlan,
    sp: Option<&StencilFacePlan>,
    stencil: &mut [u8],
    depth: &mut [u32],
    (idx, n): (usize, usize),
    (fx, fy): (F32x8, F32x8),
    mut live: I32x8,
    stats: &mut Stats,
) -> I32x8 {
    // SAFETY: forwarded from the caller; `depth_test8` touches live lanes only.
    unsafe {
        // Not `Option::map`: a closure left out of line loses the caller's target features.
        #[allow(clippy::manual_map)]
        let st = match sp {
            Some(sp) => Some(stencil_test8(sp, stencil, idx, n, &mut live, stats)),
            None => None,
        };
        let mut zfail = I32x8::zero();
        if DEPTH {
            let d = plan.depth.expect("DEPTH implies a depth plan");
            stats.depth_reads += count(live);
            if live.movemask() != 0 {
                let pass = depth_test8::<FMA>(t, &d, depth, idx, fx, fy, live);
                zfail = and_not(live, pass);
                stats.depth_failed += count(zfail);
                live = pass;
            }
        }
        if let (Some(sp), Some(st)) = (sp, st) {
            stencil_update8(sp, stencil, idx, n, st, zfail, live);
        }
        if plan.count_samples {
            stats.samples_passed += count(live);
        }
        live
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipe::CompareFunc;

    /// Every stencil operation, write mask and stored value: [`stencil_update8`] stores
    /// what [`StencilFacePlan::update`] gives, and the bytes round-trip through the lanes.
    #[test]
    fn stencil_lanes_match_scalar_rules() {
        if !crate::simd::cpu::isa().avx2() {
            return;
        }
        use StencilOp as O;
        let ops = [
            O::Keep,
            O::Zero,
            O::Replace,
            O::Incr,
            O::Decr,
            O::Invert,
            O::IncrWrap,
            O::DecrWrap,
        ];
        for op in ops {
            for write in [0xFFu8, 0x0F, 0xA5] {
                let sp = StencilFacePlan {
                    func: CompareFunc::Always,
                    masked_ref: 0x5C,
                    reference: 0x5C,
                    mask: 0xFF,
                    fail: O::Keep,
                    zfail: O::Keep,
                    zpass: op,
                    write,
                };
                for base in (0..256).step_by(LANES) {
                    let vals: [u8; LANES] = std::array::from_fn(|i| (base + i) as u8);
                    let mut buf = vals;
                    // SAFETY: AVX2 checked above.
                    unsafe {
                        assert_eq!(I32x8::from_u8(vals).to_u8(), vals);
                        let mut live = I32x8::splat(-1);
                        let mut stats = Stats::default();
                        let st = stencil_test8(&sp, &buf, 0, LANES, &mut live, &mut stats);
                        stencil_update8(&sp, &mut buf, 0, LANES, st, I32x8::zero(), live);
                    }
                    let want = vals.map(|v| sp.update(op, v));
                    assert_eq!(buf, want, "{op:?} write {write:#x}");
                }
            }
        }
    }
}
