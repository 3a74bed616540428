//! [`light_vertex`](super::light_vertex) for eight vertices at once, one vertex per lane
//! of AVX2 registers: every operation of the scalar function, in the same order, lane by
//! lane (gallivm's `pow` included), so each lane's result is the scalar result bit for bit
//! (the tests below compare them). It serves the plans the vertex block path lights
//! ([`crate::fixed_function::transform::VertexStage::block_ok`]): everything except
//! per-vertex materials (glMaterial between glBegin and glEnd).
//!
//! Every function here is `#[inline(always)]` and `unsafe`: it runs inside the block
//! kernels compiled for AVX2 (and FMA when `FMA`), whose callers vouch for the CPU.

use super::{LightPlan, Tracked};
use crate::fixed_function::gallivm_lanes::{pow, s, sel, si};
use crate::simd::F32x8;

/// Eight f32 lanes.
type V = F32x8;

/// What one block of vertices gives: front, back, front secondary and back secondary
/// colours (the back ones equal the front ones without two-sided lighting), unclamped.
pub type Lit8 = [[V; 4]; 4];

/// `|v|`. Safety: AVX2.
#[inline(always)]
unsafe fn abs(v: V) -> V {
    // SAFETY: forwarded.
    v.bits().and(unsafe { si(0x7fff_ffff) }).as_f32()
}

/// `-v`. Safety: AVX2.
#[inline(always)]
unsafe fn neg(v: V) -> V {
    // SAFETY: forwarded.
    v.bits().xor(unsafe { si(i32::MIN) }).as_f32()
}

/// [`super::dp3`].
#[inline(always)]
fn dp3(a: [V; 3], b: [V; 3]) -> V {
    a[2].mul(b[2]).add(a[1].mul(b[1])).add(a[0].mul(b[0]))
}

/// `scale3`.
#[inline(always)]
fn scale3(v: [V; 3], k: V) -> [V; 3] {
    [v[0].mul(k), v[1].mul(k), v[2].mul(k)]
}

/// [`crate::fixed_function::gallivm_math::rsq`]. Safety: AVX2.
#[inline(always)]
unsafe fn rsq(x: V) -> V {
    // SAFETY: forwarded.
    unsafe { s(1.0).div(abs(x).sqrt()) }
}

/// `normalize_shader`. Safety: AVX2.
#[inline(always)]
unsafe fn normalize(v: [V; 3]) -> [V; 3] {
    // SAFETY: forwarded.
    scale3(v, unsafe { rsq(dp3(v, v)) })
}

/// Every lane `v` (a constant vector). Safety: AVX2.
///
/// No closures here and below: a closure is compiled without the kernel's target
/// features, so an intrinsic inside one would be an out-of-line call.
#[inline(always)]
unsafe fn s3(v: [f32; 3]) -> [V; 3] {
    // SAFETY: forwarded.
    unsafe { [s(v[0]), s(v[1]), s(v[2])] }
}

/// Every lane `v` (a constant vector). Safety: AVX2.
#[inline(always)]
unsafe fn s4(v: [f32; 4]) -> [V; 4] {
    // SAFETY: forwarded.
    unsafe { [s(v[0]), s(v[1]), s(v[2]), s(v[3])] }
}

/// `mul4` of a constant and a vector. Safety: AVX2.
#[inline(always)]
unsafe fn mul4(a: [f32; 4], b: [V; 4]) -> [V; 4] {
    // SAFETY: forwarded.
    unsafe {
        [
            s(a[0]).mul(b[0]),
            s(a[1]).mul(b[1]),
            s(a[2]).mul(b[2]),
            s(a[3]).mul(b[3]),
        ]
    }
}

/// `lit`: LIT's y and z. Safety: AVX2, and FMA when `FMA`.
#[inline(always)]
unsafe fn lit<const FMA: bool>(x: V, y: V, w: V) -> (V, V) {
    // SAFETY: forwarded.
    unsafe {
        let zero = F32x8::zero();
        let ly = x.max(zero);
        let wc = w.min(s(128.0)).max(s(-128.0));
        let p = pow::<FMA>(y.max(zero), wc);
        (ly, sel(zero.cmp_ge(x), zero, p))
    }
}

/// A face's material terms (ambient, diffuse, specular, emission) with the tracked
/// ones replaced by the vertex colours. Safety: AVX2.
#[inline(always)]
unsafe fn material(m: &crate::pipe::Material, t: Tracked, color: [V; 4]) -> [[V; 4]; 4] {
    // SAFETY: forwarded.
    unsafe {
        [
            if t.ambient { color } else { s4(m.ambient) },
            if t.diffuse { color } else { s4(m.diffuse) },
            if t.specular { color } else { s4(m.specular) },
            if t.emission { color } else { s4(m.emission) },
        ]
    }
}

/// [`super::eye_normal`] of eight normals (x, y, z lanes).
///
/// # Safety
/// The CPU has AVX2.
#[inline(always)]
pub unsafe fn eye_normal(plan: &LightPlan, normal: [V; 3]) -> [V; 3] {
    if !plan.need_eye_coords && !plan.normalize && plan.normal_scale.is_none() {
        return normal;
    }
    let mut n = normal;
    if plan.need_eye_coords {
        let r = &plan.invtrans;
        // SAFETY: forwarded.
        n = unsafe {
            [
                dp3(normal, s3(r[0])),
                dp3(normal, s3(r[1])),
                dp3(normal, s3(r[2])),
            ]
        };
    }
    if plan.normalize {
        // SAFETY: forwarded.
        n = unsafe { normalize(n) };
    } else if let Some(k) = plan.normal_scale {
        // SAFETY: forwarded.
        n = scale3(n, unsafe { s(k) });
    }
    n
}

/// [`super::light_vertex`] of eight vertices: `eye` their eye positions (read only when
/// [`LightPlan::needs_eye_position`]), `normal` [`eye_normal`]'s result and `color` their
/// primary colours, as lanes. The plan has no per-vertex materials.
///
/// # Safety
/// The CPU has AVX2, and FMA when `FMA`.
#[inline(always)]
pub unsafe fn light_vertex<const FMA: bool>(
    plan: &LightPlan,
    eye: [V; 3],
    normal: [V; 3],
    color: [V; 4],
) -> Lit8 {
    // SAFETY: (whole body) forwarded from the caller.
    unsafe {
        let zero = F32x8::zero();
        let one = s(1.0);
        let faces = if plan.model.two_side { 2 } else { 1 };
        let lm = plan.model.ambient;
        // Per face: the material terms and the scene colour, per vertex when tracked.
        let mut mat = [[[zero; 4]; 4]; 2];
        let mut scene = [[zero; 4]; 2];
        for f in 0..faces {
            let t = plan.tracked[f];
            if t.any() {
                let m = material(&plan.material[f], t, color);
                // `scene_color`: lm·ambient + emission, the diffuse alpha.
                scene[f] = [
                    s(lm[0]).mul(m[0][0]).add(m[3][0]),
                    s(lm[1]).mul(m[0][1]).add(m[3][1]),
                    s(lm[2]).mul(m[0][2]).add(m[3][2]),
                    m[1][3],
                ];
                mat[f] = m;
            } else {
                scene[f] = s4(plan.scene[f]);
            }
        }
        let mut col0 = scene;
        let mut col1 = [[zero, zero, zero, one]; 2];
        let shin_zero = plan.shininess_is_zero;
        let eye_hat = if plan.model.local_viewer && !shin_zero {
            normalize(eye)
        } else {
            [zero; 3]
        };
        for l in &plan.lights {
            let (vp, dist) = if l.positional {
                let d = [
                    s(l.pos[0]).sub(eye[0]),
                    s(l.pos[1]).sub(eye[1]),
                    s(l.pos[2]).sub(eye[2]),
                ];
                let q = dp3(d, d);
                let r = rsq(q);
                (scale3(d, r), Some((r, q)))
            } else {
                (s3(l.pos), None)
            };
            let mut att: Option<V> = None;
            if let Some((dir, cos_cutoff, exponent)) = l.spot {
                let sd = dp3([neg(vp[0]), neg(vp[1]), neg(vp[2])], s3(dir));
                let slt = sel(s(cos_cutoff).cmp_lt(sd), one, zero);
                att = Some(slt.mul(pow::<FMA>(abs(sd), s(exponent))));
            }
            if let (Some(k), Some((r, q))) = (l.atten, dist) {
                let qa = abs(q);
                let d = qa.sqrt();
                let dv = [r.mul(d), d, qa];
                let q = one.div(dp3(s3(k), dv));
                att = Some(match att {
                    Some(a) => q.mul(a),
                    None => q,
                });
            }
            let half = if shin_zero {
                [zero; 3]
            } else if plan.model.local_viewer {
                normalize([
                    vp[0].sub(eye_hat[0]),
                    vp[1].sub(eye_hat[1]),
                    vp[2].sub(eye_hat[2]),
                ])
            } else if !l.positional {
                s3(l.half)
            } else {
                normalize([vp[0].add(zero), vp[1].add(zero), vp[2].add(one)])
            };
            let nl = dp3(normal, vp);
            let dots = if shin_zero {
                [nl; 4]
            } else {
                [
                    nl,
                    dp3(normal, half),
                    s(-plan.material[1].shininess),
                    s(plan.material[0].shininess),
                ]
            };
            for f in 0..faces {
                let (x, y, w) = if f == 0 {
                    (dots[0], dots[1], dots[3])
                } else {
                    (neg(dots[0]), neg(dots[1]), neg(dots[2]))
                };
                let [amb, diff, spec] = if plan.tracked[f].any() {
                    let m = &mat[f];
                    [
                        mul4(l.colors[0], m[0]),
                        mul4(l.colors[1], m[1]),
                        mul4(l.colors[2], m[2]),
                    ]
                } else {
                    let p = &l.prod[f];
                    [s4(p[0]), s4(p[1]), s4(p[2])]
                };
                let (ly, lz);
                if let Some(a) = att {
                    let (y0, z0) = lit::<FMA>(x, y, w);
                    ly = y0.mul(a);
                    lz = z0.mul(a);
                    for i in 0..3 {
                        col0[f][i] = a.mul(amb[i]).add(col0[f][i]);
                    }
                } else {
                    if shin_zero {
                        ly = x.max(zero);
                        lz = sel(zero.cmp_lt(x), one, zero);
                    } else {
                        (ly, lz) = lit::<FMA>(x, y, w);
                    }
                    for i in 0..3 {
                        col0[f][i] = amb[i].add(col0[f][i]);
                    }
                }
                for i in 0..3 {
                    col0[f][i] = ly.mul(diff[i]).add(col0[f][i]);
                }
                let acc = if plan.model.separate_specular {
                    &mut col1[f]
                } else {
                    &mut col0[f]
                };
                for i in 0..3 {
                    acc[i] = lz.mul(spec[i]).add(acc[i]);
                }
            }
        }
        let front = [col0[0][0], col0[0][1], col0[0][2], scene[0][3]];
        let front_spec = [col1[0][0], col1[0][1], col1[0][2], one];
        let (back, back_spec) = if plan.model.two_side {
            (
                [col0[1][0], col0[1][1], col0[1][2], scene[1][3]],
                [col1[1][0], col1[1][1], col1[1][2], one],
            )
        } else {
            (front, front_spec)
        };
        [front, back, front_spec, back_spec]
    }
}
