//! Rasterization: walks the rows of a set-up triangle, computes each row's exact covered
//! span from the integer edge functions (no per-pixel edge test), and hands spans to the
//! fragment stage's span shader chosen once per triangle.

use crate::cpu::Isa;
use crate::fragment::span::{shade_span, Fused, Madd, Unfused};
use crate::fragment::FragPlan;
use crate::framebuffer::Framebuffer;
use crate::geometry::setup::SetupTriangle;
use crate::stats::Stats;

pub mod lines;

/// Rasterizes `t` inside `region` (y-down pixels, exclusive high end).
pub fn raster_triangle(
    t: &SetupTriangle,
    region: [i64; 4],
    plan: &FragPlan,
    fb: &mut Framebuffer,
    stats: &mut Stats,
) {
    let x_lo = t.bbox[0].max(region[0]);
    let x_hi = t.bbox[2].min(region[2] - 1);
    let y_lo = t.bbox[1].max(region[1]);
    let y_hi = t.bbox[3].min(region[3] - 1);
    if x_lo > x_hi || y_lo > y_hi {
        stats.tris_offscreen += 1;
        return;
    }
    stats.tris_rasterized += 1;
    let b = [x_lo, y_lo, x_hi, y_hi];
    match crate::cpu::isa() {
        // SAFETY (all three): `cpu::isa` only reports a variant whose features the CPU has.
        #[cfg(target_arch = "x86_64")]
        Isa::Avx2Fma => unsafe { tri_avx2_fma(t, b, plan, fb, stats) },
        #[cfg(target_arch = "x86_64")]
        Isa::Avx2 => unsafe { tri_avx2(t, b, plan, fb, stats) },
        #[cfg(target_arch = "x86_64")]
        Isa::Fma => unsafe { tri_fma(t, b, plan, fb, stats) },
        _ => raster_rows::<Unfused>(t, b, plan, fb, stats),
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
unsafe fn tri_avx2_fma(
    t: &SetupTriangle,
    b: [i64; 4],
    plan: &FragPlan,
    fb: &mut Framebuffer,
    stats: &mut Stats,
) {
    raster_rows::<Fused>(t, b, plan, fb, stats)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn tri_avx2(
    t: &SetupTriangle,
    b: [i64; 4],
    plan: &FragPlan,
    fb: &mut Framebuffer,
    stats: &mut Stats,
) {
    raster_rows::<Unfused>(t, b, plan, fb, stats)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
unsafe fn tri_fma(
    t: &SetupTriangle,
    b: [i64; 4],
    plan: &FragPlan,
    fb: &mut Framebuffer,
    stats: &mut Stats,
) {
    raster_rows::<Fused>(t, b, plan, fb, stats)
}

#[inline(always)]
fn raster_rows<M: Madd>(
    t: &SetupTriangle,
    b: [i64; 4],
    plan: &FragPlan,
    fb: &mut Framebuffer,
    stats: &mut Stats,
) {
    if plan.needs_full_path() {
        rows_full::<M, true>(t, b, plan, fb, stats)
    } else {
        rows_full::<M, false>(t, b, plan, fb, stats)
    }
}

#[inline(always)]
fn rows_full<M: Madd, const FULL: bool>(
    t: &SetupTriangle,
    b: [i64; 4],
    plan: &FragPlan,
    fb: &mut Framebuffer,
    stats: &mut Stats,
) {
    match (plan.depth.is_some(), plan.flat, t.persp) {
        (false, false, false) => rows::<M, false, false, false, FULL>(t, b, plan, fb, stats),
        (false, false, true) => rows::<M, false, false, true, FULL>(t, b, plan, fb, stats),
        (false, true, _) => rows::<M, false, true, false, FULL>(t, b, plan, fb, stats),
        (true, false, false) => rows::<M, true, false, false, FULL>(t, b, plan, fb, stats),
        (true, false, true) => rows::<M, true, false, true, FULL>(t, b, plan, fb, stats),
        (true, true, _) => rows::<M, true, true, false, FULL>(t, b, plan, fb, stats),
    }
}

/// The row walk, specialised like the span shader it calls (everything inlines into the
/// FMA or non-FMA entry point).
#[inline(always)]
fn rows<M: Madd, const DEPTH: bool, const FLAT: bool, const PERSP: bool, const FULL: bool>(
    t: &SetupTriangle,
    b: [i64; 4],
    plan: &FragPlan,
    fb: &mut Framebuffer,
    stats: &mut Stats,
) {
    for py in b[1]..=b[3] {
        let mut lo = b[0];
        let mut hi = b[2];
        for e in &t.edges {
            match e.span(py) {
                Some((a, z)) => {
                    lo = lo.max(a);
                    hi = hi.min(z);
                }
                None => {
                    hi = lo - 1;
                    break;
                }
            }
        }
        if lo <= hi {
            shade_span::<M, DEPTH, FLAT, PERSP, FULL>(
                t,
                plan,
                fb,
                py as usize,
                lo as usize,
                hi as usize,
                stats,
            );
        }
    }
}

/// Shades single pixels `(x, y)` (y-down, inside the framebuffer) with the planes of `t`:
/// the entry for lines and points, which compute their own coverage.
pub fn shade_pixels(
    t: &SetupTriangle,
    pixels: &[(usize, usize)],
    plan: &FragPlan,
    fb: &mut Framebuffer,
    stats: &mut Stats,
) {
    match crate::cpu::isa() {
        // SAFETY: `cpu::isa` only reports a variant whose features the CPU has.
        #[cfg(target_arch = "x86_64")]
        Isa::Avx2Fma | Isa::Fma => unsafe { pixels_fma(t, pixels, plan, fb, stats) },
        _ => pixels_any::<Unfused>(t, pixels, plan, fb, stats),
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
unsafe fn pixels_fma(
    t: &SetupTriangle,
    pixels: &[(usize, usize)],
    plan: &FragPlan,
    fb: &mut Framebuffer,
    stats: &mut Stats,
) {
    pixels_any::<Fused>(t, pixels, plan, fb, stats)
}

#[inline(always)]
fn pixels_any<M: Madd>(
    t: &SetupTriangle,
    pixels: &[(usize, usize)],
    plan: &FragPlan,
    fb: &mut Framebuffer,
    stats: &mut Stats,
) {
    // Lines and points are few pixels: the general path serves every plan.
    for &(x, y) in pixels {
        match (plan.depth.is_some(), plan.flat) {
            (false, false) => {
                shade_span::<M, false, false, false, true>(t, plan, fb, y, x, x, stats)
            }
            (false, true) => shade_span::<M, false, true, false, true>(t, plan, fb, y, x, x, stats),
            (true, false) => shade_span::<M, true, false, false, true>(t, plan, fb, y, x, x, stats),
            (true, true) => shade_span::<M, true, true, false, true>(t, plan, fb, y, x, x, stats),
        }
    }
}
