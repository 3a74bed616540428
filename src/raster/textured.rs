//! The row walk of the texture fast path (see [`crate::texture::fast`]): one 2D unit on
//! the 8-bit path with REPLACE, MODULATE or DECAL, no separate specular colour, no fog.
//! Pairs of rows as in `rows_textured`, one `1 / w` per pixel shared by the texture
//! coordinates and the colour, 8-bit texels straight into the specialised environment,
//! then the general per-fragment operations of [`shade_chunk`].
// Lane loops index several arrays in step.
#![allow(clippy::needless_range_loop)]

use super::row_span;
use crate::fragment::span::{
    frag_colors, one_over_w, shade_chunk, tex_coords_oow, ChunkColors, Madd, LANES,
};
use crate::fragment::FragPlan;
use crate::framebuffer::Target;
use crate::geometry::setup::SetupTriangle;
use crate::geometry::VARY_TEX;
use crate::stats::Stats;
use crate::texture::fast::{self, FastEnv};
use crate::texture::UnitPlan;

/// The fast path's environment when this draw qualifies: one unit with a fast form, and no
/// colour sum or fog after the environment.
#[inline(always)]
pub(super) fn fast_env(plan: &FragPlan, units: &[UnitPlan<'_>]) -> Option<FastEnv> {
    match units {
        [u] if !plan.separate_specular && plan.fog.is_none() => u.fast,
        _ => None,
    }
}

/// Walks the 8-pixel chunks of the pairs of rows (aligned to even pixel coordinates, as
/// llvmpipe's 2x2 quads are) that `t` covers in `b`: `f(qy, x, fx, fy, live)` gets the
/// top row, the chunk's first column, the lanes' pixel x and the two rows' pixel y as f32,
/// and each row's covered lanes (a chunk is visited when either row covers part of it).
#[inline(always)]
pub(super) fn for_each_chunk(
    t: &SetupTriangle,
    b: [i64; 4],
    mut f: impl FnMut(i64, i64, &[f32; LANES], [f32; 2], [[bool; LANES]; 2]),
) {
    let mut qy = b[1] & !1;
    while qy <= b[3] {
        let spans = [row_span(t, b, qy), row_span(t, b, qy + 1)];
        let lo = spans.iter().flatten().map(|s| s.0).min();
        let hi = spans.iter().flatten().map(|s| s.1).max();
        let (Some(lo), Some(hi)) = (lo, hi) else {
            qy += 2;
            continue;
        };
        let fy = [qy as f32, (qy + 1) as f32];
        let mut x = lo & !1;
        while x <= hi {
            let mut live = [[false; LANES]; 2];
            for (r, span) in spans.iter().enumerate() {
                if let Some((a, z)) = span {
                    for (i, l) in live[r].iter_mut().enumerate() {
                        let px = x + i as i64;
                        *l = px >= *a && px <= *z;
                    }
                }
            }
            let mut fx = [0f32; LANES];
            for (i, v) in fx.iter_mut().enumerate() {
                *v = (x + i as i64) as f32;
            }
            f(qy, x, &fx, fy, live);
            x += LANES as i64;
        }
        qy += 2;
    }
}

/// Shades the rows `b` of `t` through the fast path.
#[inline(always)]
pub(super) fn rows_tex_fast<M: Madd, const DEPTH: bool, const FLAT: bool, const PERSP: bool>(
    t: &SetupTriangle,
    b: [i64; 4],
    plan: &FragPlan,
    u: &UnitPlan<'_>,
    env: FastEnv,
    fb: &mut Target<'_>,
    stats: &mut Stats,
) {
    // Texels of the current chunk; lanes of skipped quads keep stale values, never used.
    let mut tex = [[[0u8; 4]; LANES]; 2];
    let reads_frag = env.reads_frag();
    for_each_chunk(t, b, |qy, x, fx, fy, live| {
        let oow = [
            one_over_w::<M, PERSP>(t, fx, fy[0]),
            one_over_w::<M, PERSP>(t, fx, fy[1]),
        ];
        let (s0, t0) = tex_coords_oow::<M, PERSP>(t, VARY_TEX, fx, fy[0], &oow[0]);
        let (s1, t1) = tex_coords_oow::<M, PERSP>(t, VARY_TEX, fx, fy[1], &oow[1]);
        for j in 0..LANES / 2 {
            let (l, r) = (2 * j, 2 * j + 1);
            if !(live[0][l] || live[0][r] || live[1][l] || live[1][r]) {
                continue;
            }
            let v = fast::quad_u8(
                u,
                [s0[l], s0[r], s1[l], s1[r]],
                [t0[l], t0[r], t1[l], t1[r]],
            );
            tex[0][l] = v[0];
            tex[0][r] = v[1];
            tex[1][l] = v[2];
            tex[1][r] = v[3];
        }
        for r in 0..2 {
            if !live[r].iter().any(|&l| l) {
                continue;
            }
            let frag = if reads_frag {
                frag_colors::<M, FLAT, PERSP>(t, fx, fy[r], &oow[r])
            } else {
                [[0f32; LANES]; 4]
            };
            let c = fast::env_lanes(env, &tex[r], &frag);
            shade_chunk::<M, DEPTH, FLAT, PERSP, true>(
                t,
                plan,
                &[],
                ChunkColors::Ready(&c),
                fb,
                (qy + r as i64) as usize,
                x as usize,
                live[r],
                stats,
            );
        }
    });
}
