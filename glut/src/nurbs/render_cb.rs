//! GLU_NURBS_TESSELLATOR mode: the same pieces and grids as the renderer, evaluated
//! here (de Casteljau in f64) and handed to the client's BEGIN/VERTEX/NORMAL/COLOR/
//! TEXTURE_COORD/END callbacks instead of GL. Curves come as one GL_LINE_STRIP per
//! piece, surfaces as GL_TRIANGLES per patch; without a normal map the normal is the
//! cross product of the surface's partial derivatives (central differences). Curve
//! pieces get U_STEP steps (per unit parameter under GLU_DOMAIN_DISTANCE), surfaces the
//! renderer's grid; libGLU's tessellator mode emits other primitives (its own strips
//! and fans), so only the geometry, not the call sequence, corresponds.

use super::bezier::curve_piece;
use super::render::Patch;
use super::trim::{de_casteljau, polylines, triangles};
use super::{is_vertex, CurveDef, Nurbs, SurfDef, TrimPiece};
use crate::gl::{GLenum, GL_LINE_STRIP, GL_TRIANGLES};

/// Which callback a map's values go to: 1 vertex, 2 normal, 3 colour, 4 texture.
fn slot(target: GLenum) -> usize {
    match target & 0x0F {
        7 | 8 => 1,
        2 => 2,
        0 | 1 => 3,
        _ => 4,
    }
}

impl Nurbs {
    fn cb_begin(&self, mode: GLenum) {
        // SAFETY: BEGIN callbacks take (GLenum) or (GLenum, void *).
        unsafe {
            if let Some(f) = self.callbacks[6] {
                std::mem::transmute::<
                    unsafe extern "C" fn(),
                    extern "C" fn(GLenum, *mut std::ffi::c_void),
                >(f)(mode, self.user_data)
            } else if let Some(f) = self.callbacks[0] {
                std::mem::transmute::<unsafe extern "C" fn(), extern "C" fn(GLenum)>(f)(mode)
            }
        }
    }

    fn cb_end(&self) {
        // SAFETY: END callbacks take () or (void *).
        unsafe {
            if let Some(f) = self.callbacks[11] {
                std::mem::transmute::<unsafe extern "C" fn(), extern "C" fn(*mut std::ffi::c_void)>(
                    f,
                )(self.user_data)
            } else if let Some(f) = self.callbacks[5] {
                std::mem::transmute::<unsafe extern "C" fn(), extern "C" fn()>(f)()
            }
        }
    }

    /// Calls the callback in `slot` (1…4) with a float array.
    fn cb_values(&self, slot: usize, v: &[f32]) {
        // SAFETY: these callbacks take (GLfloat *) or (GLfloat *, void *); the array
        // outlives the call and has at least four entries.
        unsafe {
            if let Some(f) = self.callbacks[slot + 6] {
                std::mem::transmute::<
                    unsafe extern "C" fn(),
                    extern "C" fn(*const f32, *mut std::ffi::c_void),
                >(f)(v.as_ptr(), self.user_data)
            } else if let Some(f) = self.callbacks[slot] {
                std::mem::transmute::<unsafe extern "C" fn(), extern "C" fn(*const f32)>(f)(
                    v.as_ptr(),
                )
            }
        }
    }
}

/// Homogeneous vertex values divided by w; others as they are (padded to four).
fn finish(target: GLenum, v: &[f64]) -> [f32; 4] {
    let mut out = [0f32, 0., 0., 1.];
    if target & 0x0F == 8 && v.len() == 4 && v[3] != 0.0 {
        for c in 0..3 {
            out[c] = (v[c] / v[3]) as f32;
        }
    } else {
        for (o, x) in out.iter_mut().zip(v) {
            *o = *x as f32;
        }
    }
    out
}

/// Emits a curve's pieces as line strips.
pub fn curve(n: &Nurbs, maps: &[CurveDef], bp: &[f32]) {
    let Some(geo) = maps.iter().find(|m| is_vertex(m.target)) else {
        return;
    };
    for w in bp.windows(2) {
        let (a, b) = (w[0], w[1]);
        let pieces: Vec<(GLenum, usize, Vec<f32>)> = maps
            .iter()
            .filter(|m| m.basis.range().0 <= a && m.basis.range().1 >= b)
            .map(|m| (m.target, m.dim, curve_piece(&m.basis, &m.pts, m.dim, a, b)))
            .collect();
        let steps = match n.method {
            super::DOMAIN_DISTANCE => (n.u_step * (b - a)).max(1.0),
            _ => n.u_step.max(1.0),
        }
        .min(4096.0) as usize;
        let _ = geo;
        n.cb_begin(GL_LINE_STRIP);
        for i in 0..=steps {
            let u = i as f64 / steps as f64;
            // Vertex last, as glVertex ends a vertex.
            for (target, dim, p) in pieces.iter().rev() {
                let v = finish(*target, &de_casteljau(p, *dim, u));
                n.cb_values(slot(*target), &v);
            }
        }
        n.cb_end();
    }
}

/// A tensor-product Bézier patch's value at local (u, v) in [0, 1]².
fn eval_patch(p: &[f32], dim: usize, ks: usize, kt: usize, u: f64, v: f64) -> Vec<f64> {
    let mut col = Vec::with_capacity(ks * dim);
    for i in 0..ks {
        let row = &p[i * kt * dim..(i + 1) * kt * dim];
        col.extend(de_casteljau(row, dim, v).into_iter().map(|x| x as f32));
    }
    de_casteljau(&col, dim, u)
}

/// Emits a surface's patches as triangles.
pub fn surface(n: &Nurbs, patches: &[Patch], geo: &SurfDef, loops: &[Vec<TrimPiece>]) {
    let lines = polylines(geo, loops);
    for p in patches {
        let tris = triangles(p, &lines);
        if tris.is_empty() {
            continue;
        }
        let (ds, dt) = (f64::from(p.s.1 - p.s.0), f64::from(p.t.1 - p.t.0));
        let has_normal = p.maps.iter().any(|m| slot(m.0) == 2);
        n.cb_begin(GL_TRIANGLES);
        for tri in &tris {
            for q in tri {
                let (u, v) = (
                    (q[0] - f64::from(p.s.0)) / ds,
                    (q[1] - f64::from(p.t.0)) / dt,
                );
                for (target, dim, ks, kt, pts) in p.maps.iter().rev() {
                    let val = finish(*target, &eval_patch(pts, *dim, *ks, *kt, u, v));
                    if slot(*target) == 1 && !has_normal {
                        let at = |u: f64, v: f64| {
                            finish(
                                *target,
                                &eval_patch(
                                    pts,
                                    *dim,
                                    *ks,
                                    *kt,
                                    u.clamp(0.0, 1.0),
                                    v.clamp(0.0, 1.0),
                                ),
                            )
                        };
                        let h = 1e-4;
                        let (a, b) = (at(u + h, v), at(u - h, v));
                        let (c, d) = (at(u, v + h), at(u, v - h));
                        let su = [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
                        let tv = [c[0] - d[0], c[1] - d[1], c[2] - d[2]];
                        let mut nrm = [
                            su[1] * tv[2] - su[2] * tv[1],
                            su[2] * tv[0] - su[0] * tv[2],
                            su[0] * tv[1] - su[1] * tv[0],
                            0.0,
                        ];
                        let len = (nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]).sqrt();
                        if len > 0.0 {
                            nrm.iter_mut().take(3).for_each(|x| *x /= len);
                        }
                        n.cb_values(2, &nrm);
                    }
                    n.cb_values(slot(*target), &val);
                }
            }
        }
        n.cb_end();
    }
}
