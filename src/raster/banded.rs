//! Lines and points on both threads: a draw of them is not binned like triangles, so on
//! its own it ran on the draw's thread alone (sweep states of lines and points: no gain
//! from a second thread, where llvmpipe gains 1.2–1.3×). When a textured draw's
//! estimated fragments reach [`crate::tuning::Tuning::prim_bands`], the framebuffer is cut into
//! two bands of rows (an even number each, so that no 2x2 quad straddles them) and each
//! thread draws every primitive of the draw into its own band ([`super::batch::fork2`]);
//! [`super::Draw::clip`] keeps each to its rows. Each thread repeats the primitives'
//! set-up (a line's stipple dashes, its edges), which is cheap beside their fragments,
//! and draws its band in the draw's order, so the bytes and the per-pixel counters are
//! those of one thread.

use super::Draw;
use crate::fragment::FragPlan;
use crate::framebuffer::Framebuffer;
use crate::stats::Stats;
use crate::texture::UnitPlan;
use std::sync::Mutex;

/// Runs `draw` over `fb` inside `region`: once over the whole framebuffer, or, when the
/// draw is textured, `work` (its estimated fragments) reaches the threshold and a second
/// thread may help, once per band on two threads.
pub fn draw_banded(
    fb: &mut Framebuffer,
    region: [i64; 4],
    plan: &FragPlan,
    units: &[UnitPlan<'_>],
    stats: &mut Stats,
    work: impl FnOnce() -> f64,
    draw: impl Fn(&mut Draw<'_, '_>) + Sync,
) {
    let min = crate::tuning::tuning().prim_bands;
    // One-pass multisampling keeps its sample planes with the whole framebuffer.
    // Untextured fragments cost so little that repeating each primitive's set-up on the
    // second thread cost more than it saved (sweep state 29, two-pixel-wide untextured
    // lines: 1.04 -> 1.43 ms on two threads).
    let split = min > 0
        && !units.is_empty()
        && plan.ms.is_none()
        && crate::cpu::threads() >= 2
        && fb.height >= 4
        && work() >= min as f64;
    if !split {
        let mut target = fb.target();
        draw(&mut Draw::new(region, plan, units, &mut target, stats));
        return;
    }
    stats.draws_banded += 1;
    let band_rows = (fb.height.div_ceil(2) + 1) & !1;
    let slots: Vec<Mutex<_>> = fb
        .bands(band_rows)
        .into_iter()
        .map(|t| Mutex::new((t, Stats::default())))
        .collect();
    super::batch::fork2(true, |i| {
        if let Some(slot) = slots.get(i) {
            // Each slot is locked by its one thread only.
            let mut guard = slot.lock().unwrap_or_else(|e| e.into_inner());
            let (target, st) = &mut *guard;
            target.resolve();
            draw(&mut Draw::new(region, plan, units, target, st));
        }
    });
    for slot in slots {
        let (_, st) = slot.into_inner().unwrap_or_else(|e| e.into_inner());
        stats.add_pixels(&st);
    }
}
