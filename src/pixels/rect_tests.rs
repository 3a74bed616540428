//! Tests of [`super::rasterize`]'s texel selection.

use super::*;
use crate::test_rng::xorshift32;

/// The texel every pixel's own plane evaluation selects (the selection before columns
/// were cached), for the span of `tri` at row `py` from `x` on.
fn per_pixel<M: Madd>(tri: &SetupTriangle, q: &Quad, py: usize, x: usize, n: usize) -> Vec<u32> {
    let (ps, pt) = (&tri.vary[VARY_TEX], &tri.vary[VARY_TEX + 1]);
    (x..x + n)
        .map(|px| {
            let (fx, fy) = (px as f32, py as f32);
            texel_at(eval::<M>(pt, fx, fy), q.h as f32, q.h) * q.w as u32
                + texel_at(eval::<M>(ps, fx, fy), q.w as f32, q.w)
        })
        .collect()
}

#[test]
fn cached_columns_select_the_texels_of_per_pixel_evaluation() {
    let mut r = xorshift32(0x5eed_0042);
    let (mut spans, mut cached) = (0usize, 0usize);
    for case in 0..400 {
        let fma = case % 2 == 0;
        let (fb_w, fb_h) = (64 + (r() % 200) as usize, 64 + (r() % 200) as usize);
        let zoom = |r: &mut dyn FnMut() -> u32| match r() % 4 {
            0 => 1.0,
            1 => -1.0 - (r() % 8) as f32 * 0.25,
            _ => 0.25 + (r() % 16) as f32 * 0.25,
        };
        let q = Quad {
            x: (r() % (fb_w as u32 + 80)) as i32 - 40,
            y: (r() % (fb_h as u32 + 80)) as i32 - 40,
            w: 1 + (r() % 100) as usize,
            h: 1 + (r() % 100) as usize,
            zoom: [zoom(&mut r), zoom(&mut r)],
            z: (r() % 1000) as f32 / 1000.0,
            flip_t: r() & 1 == 0,
        };
        let x0 = (r() % 20) as i64;
        let y0 = (r() % 20) as i64;
        let d = Dest {
            fb_w,
            fb_h,
            region: [x0, y0, fb_w as i64 - x0, fb_h as i64 - y0],
            fma,
            y_flip: r() & 1 == 0,
        };
        rasterize(&q, &d, |tri, py, x, texels| {
            let (ps, pt) = (&tri.vary[VARY_TEX], &tri.vary[VARY_TEX + 1]);
            spans += 1;
            cached += usize::from(ps.dady == 0.0 && pt.dadx == 0.0);
            // Fused is one rounding whether an instruction or `fmaf` computes it.
            let want = if fma {
                per_pixel::<Fused>(tri, &q, py, x, texels.len())
            } else {
                per_pixel::<Unfused>(tri, &q, py, x, texels.len())
            };
            assert_eq!(
                texels,
                &want[..],
                "case {case} row {py} from {x}: {q:?} {d:?}"
            );
        });
    }
    // Both selections ran, the cached one on most spans.
    assert!(cached > spans / 2 && cached < spans, "{cached} of {spans}");
}
