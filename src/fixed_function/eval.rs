//! Bezier evaluation for glEvalCoord (GL evaluators) with Mesa's f32 arithmetic
//! (`math/m_eval.c`): curves and surface points by the Horner scheme, with binomial
//! coefficients built as `(order-1)·∏(order-i)·(1/i)`; surface points with partial
//! derivatives (for GL_AUTO_NORMAL) by de Casteljau steps.
//!
//! Control points are `f32`, `dim` per point; a surface net is stored u-major
//! (`[u][v][k]`), as Mesa copies it.

/// Mesa's table of `1/i` (f32).
#[inline(always)]
fn inv(i: usize) -> f32 {
    1.0f32 / i as f32
}

/// A point on the Bezier curve of `order` control points `cp` (stride `stride` floats
/// between points) at `t`, `dim` components into `out`.
pub fn horner_curve(cp: &[f32], stride: usize, out: &mut [f32], t: f32, dim: usize, order: usize) {
    if order < 2 {
        out[..dim].copy_from_slice(&cp[..dim]);
        return;
    }
    let mut bincoeff = (order - 1) as f32;
    let s = 1.0f32 - t;
    for k in 0..dim {
        out[k] = s * cp[k] + bincoeff * t * cp[stride + k];
    }
    let mut powert = t * t;
    for i in 2..order {
        bincoeff *= (order - i) as f32;
        bincoeff *= inv(i);
        let p = &cp[i * stride..];
        for k in 0..dim {
            out[k] = s * out[k] + bincoeff * powert * p[k];
        }
        powert *= t;
    }
}

/// A point on the tensor-product Bezier surface `cn` (`uorder` x `vorder` points) at
/// `(u, v)`.
pub fn horner_surf(
    cn: &[f32],
    out: &mut [f32],
    u: f32,
    v: f32,
    dim: usize,
    uorder: usize,
    vorder: usize,
) {
    let uinc = vorder * dim;
    let mut cp = [0f32; 4 * MAX_ORDER];
    if vorder > uorder {
        if uorder >= 2 {
            // The control polygon in v of the curve at u: Horner along u per column.
            for j in 0..vorder {
                horner_curve(&cn[j * dim..], uinc, &mut cp[j * dim..], u, dim, uorder);
            }
            horner_curve(&cp, dim, out, v, dim, vorder);
        } else {
            horner_curve(cn, dim, out, v, dim, vorder);
        }
    } else if vorder > 1 {
        for i in 0..uorder {
            horner_curve(&cn[i * uinc..], dim, &mut cp[i * dim..], v, dim, vorder);
        }
        horner_curve(&cp, dim, out, u, dim, uorder);
    } else {
        horner_curve(cn, uinc, out, u, dim, uorder);
    }
}

/// The largest evaluator order (GL_MAX_EVAL_ORDER, Mesa's 30).
pub const MAX_ORDER: usize = 30;

/// A point on the surface and its (unscaled) partial derivative directions in u and v.
#[allow(clippy::too_many_arguments)]
pub fn de_casteljau_surf(
    cn: &[f32],
    out: &mut [f32; 4],
    du: &mut [f32; 4],
    dv: &mut [f32; 4],
    u: f32,
    v: f32,
    dim: usize,
    uorder: usize,
    vorder: usize,
) {
    let (us, vs) = (1.0f32 - u, 1.0f32 - v);
    let uinc = vorder * dim;
    let c = |i: usize, j: usize, k: usize| cn[i * uinc + j * dim + k];
    for k in 0..dim {
        // Working net for this component, [i][j] with stride vorder.
        let mut d = [0f32; MAX_ORDER * MAX_ORDER];
        let at = |i: usize, j: usize| i * vorder + j;
        for i in 0..uorder {
            for j in 0..vorder {
                d[at(i, j)] = c(i, j, k);
            }
        }
        let (mut nu, mut nv) = (uorder, vorder);
        // Bilinear steps while both directions have more than two points.
        while nu > 2 && nv > 2 {
            for i in 0..nu - 1 {
                d[at(i, 0)] = us * d[at(i, 0)] + u * d[at(i + 1, 0)];
                for j in 0..nv - 1 {
                    d[at(i, j + 1)] = us * d[at(i, j + 1)] + u * d[at(i + 1, j + 1)];
                    d[at(i, j)] = vs * d[at(i, j)] + v * d[at(i, j + 1)];
                }
            }
            nu -= 1;
            nv -= 1;
        }
        if nu == 2 && nv > 2 {
            // Finish u: a row of u-differences and a row of points, then linear steps in v.
            let (mut a, mut p) = ([0f32; MAX_ORDER], [0f32; MAX_ORDER]);
            for j in 0..nv {
                a[j] = d[at(1, j)] - d[at(0, j)];
                p[j] = us * d[at(0, j)] + u * d[at(1, j)];
            }
            (dv[k], du[k], out[k]) = finish_line(a, p, nv, v, vs);
        } else if nv == 2 && nu > 2 {
            // Finish v: a column of v-differences and a column of points, then steps in u.
            let (mut a, mut p) = ([0f32; MAX_ORDER], [0f32; MAX_ORDER]);
            for i in 0..nu {
                a[i] = d[at(i, 1)] - d[at(i, 0)];
                p[i] = vs * d[at(i, 0)] + v * d[at(i, 1)];
            }
            (du[k], dv[k], out[k]) = finish_line(a, p, nu, u, us);
        } else if nu == 2 && nv == 2 {
            let (p00, p01, p10, p11) = (d[at(0, 0)], d[at(0, 1)], d[at(1, 0)], d[at(1, 1)]);
            du[k] = vs * (p10 - p00) + v * (p11 - p01);
            dv[k] = us * (p01 - p00) + u * (p11 - p10);
            out[k] = us * (vs * p00 + v * p01) + u * (vs * p10 + v * p11);
        } else {
            // An order-1 direction: no tangent plane (Mesa reads past the net here).
            let mut pt = [0f32; 4];
            horner_surf(cn, &mut pt, u, v, dim, uorder, vorder);
            du[k] = 0.0;
            dv[k] = 0.0;
            out[k] = pt[k];
        }
    }
}

/// Finishes a patch reduced to two rows in one direction: linear de Casteljau steps at
/// `t` (`ts` = 1 − t) along the other, over the `n` differences `a` across the rows and
/// points `p` between them. Returns the derivative along, the derivative across and the
/// point.
#[inline]
fn finish_line(
    mut a: [f32; MAX_ORDER],
    mut p: [f32; MAX_ORDER],
    mut n: usize,
    t: f32,
    ts: f32,
) -> (f32, f32, f32) {
    while n > 2 {
        for j in 0..n - 1 {
            a[j] = ts * a[j] + t * a[j + 1];
            p[j] = ts * p[j] + t * p[j + 1];
        }
        n -= 1;
    }
    (p[1] - p[0], ts * a[0] + t * a[1], ts * p[0] + t * p[1])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cubic_curve_midpoint() {
        let cp = [0.0f32, 1.0, 2.0, 3.0];
        let mut out = [0f32; 1];
        horner_curve(&cp, 1, &mut out, 0.5, 1, 4);
        assert!((out[0] - 1.5).abs() < 1e-6);
    }

    #[test]
    fn surface_point_and_derivatives_agree_with_horner() {
        let mut cn = [0f32; 3 * 4 * 4];
        for i in 0..4 {
            for j in 0..4 {
                let p = &mut cn[(i * 4 + j) * 3..];
                p[0] = i as f32;
                p[1] = j as f32;
                p[2] = ((i * 3 + j * 5) % 7) as f32 * 0.1;
            }
        }
        let (mut a, mut du, mut dv) = ([0f32; 4], [0f32; 4], [0f32; 4]);
        de_casteljau_surf(&cn, &mut a, &mut du, &mut dv, 0.3, 0.6, 3, 4, 4);
        let mut b = [0f32; 4];
        horner_surf(&cn, &mut b, 0.3, 0.6, 3, 4, 4);
        for k in 0..3 {
            assert!((a[k] - b[k]).abs() < 1e-5, "{a:?} {b:?}");
        }
        assert!(du[0] > 0.0 && dv[1] > 0.0);
    }
}
