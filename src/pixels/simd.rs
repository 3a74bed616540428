//! Pixel-rectangle fragments eight at a time in AVX2 registers: the spans that
//! [`super::rect::rasterize`] hands over, with their texel indices, become 8-lane chunks
//! whose packed RGBA8 colours are gathered from the image's converted texels
//! (`vpgatherdd`), or for a bitmap whose live lanes are the gathered mask words, then run
//! through the per-fragment operations of the general 8-lane walk
//! ([`crate::fragment::simd_gen::ready_row`]: alpha test, stencil, depth, blending or
//! logic op, colour mask, store).
//!
//! It computes what [`super::rect::Fragments::put_chunk8`] computes lane by lane (the
//! same colours, the same z plane evaluated unfused, the same counters); the scalar path
//! stays for CPUs and levels without AVX2 (`SOFTGL_ISA=scalar`/`sse4.1`), for wide and
//! non-RGBA colour buffers, sRGB writes, multisample draws and depth and stencil images.
//!
//! Measured on scene q (`pushattrib_pixels`, 512², one thread): see docs/performance.md,
//! "Stop 59, pixels".

#![cfg(target_arch = "x86_64")]

use crate::fragment::simd_gen::{plan_ok, ready_row, GenPlan};
use crate::fragment::span::LANES;
use crate::fragment::FragPlan;
use crate::framebuffer::Target;
use crate::geometry::setup::SetupTriangle;
use crate::simd::I32x8;
use crate::stats::Stats;

/// What the texels of a rectangle give their fragments.
#[derive(Clone, Copy)]
pub enum Texels<'a> {
    /// A packed RGBA8 colour (bytes in memory order R, G, B, A) per texel.
    Color(&'a [[u8; 4]]),
    /// One packed RGBA8 colour; a texel makes a fragment where its mask word is −1 and
    /// none where it is 0 (glBitmap).
    Mask(&'a [i32], [u8; 4]),
}

/// Whether [`span`] runs the fragments of `plan` into `fb`: an AVX2 level, and an 8-bit
/// target and plan the 8-lane walk covers ([`plan_ok`]).
pub fn covers(plan: &FragPlan, fb: &Target<'_>) -> bool {
    #[cfg(test)]
    if SCALAR_ONLY.with(|s| s.get()) {
        return false;
    }
    crate::cpu::isa().avx2() && fb.wide.is_none() && plan_ok(plan, fb)
}

#[cfg(test)]
thread_local! {
    /// Set by a test on its own thread: pixel rectangles take the per-lane path.
    static SCALAR_ONLY: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Runs the fragments of the span of pixels `x..x + texels.len()` of row `py` (y-down)
/// of triangle `t`, pixel `i` taking texel `texels[i]` of `src`, in chunks of
/// [`LANES`] from `x` on.
///
/// # Safety
/// [`covers`] holds for `plan` and `fb`; the span lies inside `fb`'s rows; every index in
/// `texels` is in range of `src`, which is not empty.
#[allow(clippy::too_many_arguments)]
pub unsafe fn span(
    t: &SetupTriangle,
    plan: &FragPlan,
    fb: &mut Target<'_>,
    py: usize,
    x: usize,
    texels: &[u32],
    src: Texels<'_>,
    stats: &mut Stats,
) {
    // SAFETY: `covers` checked for AVX2 (whose levels have POPCNT, BMI1, BMI2 and
    // LZCNT too); the rest is forwarded from the caller.
    unsafe {
        if plan.depth.is_some() {
            span_avx2::<true>(t, plan, fb, py, x, texels, src, stats)
        } else {
            span_avx2::<false>(t, plan, fb, py, x, texels, src, stats)
        }
    }
}

/// [`span`]'s body, compiled for AVX2.
///
/// # Safety
/// As [`span`]; `DEPTH` says whether the plan has a depth test.
#[target_feature(enable = "avx2,popcnt,bmi1,bmi2,lzcnt")]
#[allow(clippy::too_many_arguments)]
unsafe fn span_avx2<const DEPTH: bool>(
    t: &SetupTriangle,
    plan: &FragPlan,
    fb: &mut Target<'_>,
    py: usize,
    x: usize,
    texels: &[u32],
    src: Texels<'_>,
    stats: &mut Stats,
) {
    let g = GenPlan::new(plan, t, &[]);
    // SAFETY: (whole body) AVX2 context; the gathers read texels `src` holds (the
    // caller's indices, and index 0 in the lanes past a short last chunk); the chunks
    // lie inside the row, as the caller's span does.
    unsafe {
        let lanes = I32x8::new([0, 1, 2, 3, 4, 5, 6, 7]);
        for (i, k) in texels.chunks(LANES).enumerate() {
            let (idx, mut live) = if k.len() == LANES {
                (I32x8::load(k.as_ptr()), I32x8::splat(-1))
            } else {
                let mut a = [0u32; LANES];
                a[..k.len()].copy_from_slice(k);
                (
                    I32x8::load(a.as_ptr()),
                    I32x8::splat(k.len() as i32).cmpgt(lanes),
                )
            };
            let px = match src {
                Texels::Color(c) => I32x8::gather(c.as_ptr().cast(), idx),
                Texels::Mask(m, c) => {
                    live = live.and(I32x8::gather(m.as_ptr(), idx));
                    if live.movemask() == 0 {
                        continue;
                    }
                    I32x8::splat(i32::from_ne_bytes(c))
                }
            };
            ready_row::<DEPTH>(t, plan, &g, fb, py, x + i * LANES, live, px, stats);
        }
    }
}

#[cfg(test)]
#[path = "simd_tests.rs"]
mod tests;
