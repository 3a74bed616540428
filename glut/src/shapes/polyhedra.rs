//! The Platonic solids, the rhombic dodecahedron and the Sierpinski sponge in
//! freeglut 3.4's placement: the same vertex positions (in single precision), face
//! normals, face vertex order and triangulation, so they rasterise to freeglut's
//! pixels.
//!
//! The coordinates are computed here from their closed forms; the tables only say
//! which vertex goes where. Faces with three corners are drawn as separate triangles;
//! four-cornered faces as triangles (0,1,2) and (0,2,3); pentagons as (0,1,2), (0,2,4)
//! and (4,2,3).

use super::draw::{self, Mesh};
use crate::gl::GL_LINE_LOOP;

/// The golden ratio φ.
fn phi() -> f64 {
    (1.0 + 5f64.sqrt()) / 2.0
}

/// Rounds to single precision; a coordinate within 1e-12 of zero (the rounding error
/// of a cosine or a cross product that is zero in exact arithmetic) becomes 0.
fn f32v(v: [f64; 3]) -> [f32; 3] {
    v.map(|c| if c.abs() < 1e-12 { 0.0 } else { c as f32 })
}

/// A polyhedron: vertex positions, one normal per face, and each face's vertex
/// indices counter-clockwise seen from outside (`corners` per face).
pub struct Solid {
    verts: Vec<[f32; 3]>,
    normals: Vec<[f32; 3]>,
    faces: &'static [u8],
    corners: usize,
}

impl Solid {
    /// Every face's corners in order, each with the face's normal; positions scaled
    /// by `scale` unless it is 1.
    fn mesh(&self, scale: f32) -> Mesh {
        let mut m = Mesh::with_capacity(self.faces.len());
        for (face, n) in self.faces.chunks_exact(self.corners).zip(&self.normals) {
            for &v in face {
                let p = self.verts[usize::from(v)];
                let p = if scale == 1.0 {
                    p
                } else {
                    [scale * p[0], scale * p[1], scale * p[2]]
                };
                m.push(p, *n);
            }
        }
        m
    }

    /// Draws the solid filled or as one line loop per face.
    pub fn draw(&self, scale: f32, solid: bool) {
        let m = self.mesh(scale);
        if !solid {
            draw::wire(&m, None, self.corners, GL_LINE_LOOP, &[], 0);
            return;
        }
        let split: &[u16] = match self.corners {
            4 => &[0, 1, 2, 0, 2, 3],
            5 => &[0, 1, 2, 0, 2, 4, 4, 2, 3],
            _ => return draw::solid(&m, None, None, 1),
        };
        let faces = self.faces.len() / self.corners;
        let idx: Vec<u16> = (0..faces)
            .flat_map(|f| split.iter().map(move |&k| (f * self.corners) as u16 + k))
            .collect();
        draw::solid(&m, None, Some(&idx), 1);
    }
}

/// Cube of edge 1: corners (±½, ±½, ±½); faces +z, +x, +y, -x, -y, -z.
pub fn cube() -> Solid {
    let c = |x: f32, y: f32, z: f32| [x * 0.5, y * 0.5, z * 0.5];
    Solid {
        verts: vec![
            c(1., 1., 1.),
            c(-1., 1., 1.),
            c(-1., -1., 1.),
            c(1., -1., 1.),
            c(1., -1., -1.),
            c(1., 1., -1.),
            c(-1., 1., -1.),
            c(-1., -1., -1.),
        ],
        normals: vec![
            [0., 0., 1.],
            [1., 0., 0.],
            [0., 1., 0.],
            [-1., 0., 0.],
            [0., -1., 0.],
            [0., 0., -1.],
        ],
        faces: &[
            0, 1, 2, 3, 0, 3, 4, 5, 0, 5, 6, 1, 1, 6, 7, 2, 7, 4, 3, 2, 4, 7, 6, 5,
        ],
        corners: 4,
    }
}

/// Dodecahedron of radius √3: the cube corners (±1, ±1, ±1) and the cyclic
/// permutations of (0, ±φ, ±1/φ); its face normals are the unit vectors along the
/// cyclic permutations of (0, ±1, ±φ).
pub fn dodecahedron() -> Solid {
    let (b, a) = (phi(), phi() - 1.0);
    let v = |x: f64, y: f64, z: f64| f32v([x, y, z]);
    let l = (1.0 + b * b).sqrt();
    let (s, t) = (1.0 / l, b / l);
    let n = |x: f64, y: f64, z: f64| f32v([x, y, z]);
    Solid {
        verts: vec![
            v(0., b, a),
            v(-1., 1., 1.),
            v(-a, 0., b),
            v(a, 0., b),
            v(1., 1., 1.),
            v(0., b, -a),
            v(1., 1., -1.),
            v(a, 0., -b),
            v(-a, 0., -b),
            v(-1., 1., -1.),
            v(0., -b, a),
            v(1., -1., 1.),
            v(-1., -1., 1.),
            v(0., -b, -a),
            v(-1., -1., -1.),
            v(1., -1., -1.),
            v(b, -a, 0.),
            v(b, a, 0.),
            v(-b, a, 0.),
            v(-b, -a, 0.),
        ],
        normals: vec![
            n(0., s, t),
            n(0., s, -t),
            n(0., -s, t),
            n(0., -s, -t),
            n(t, 0., s),
            n(-t, 0., s),
            n(t, 0., -s),
            n(-t, 0., -s),
            n(s, t, 0.),
            n(s, -t, 0.),
            n(-s, t, 0.),
            n(-s, -t, 0.),
        ],
        faces: &[
            0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 3, 2, 12, 13, 14, 8, 7, 15, 3, 11, 16, 17, 4, 2,
            1, 18, 19, 12, 7, 6, 17, 16, 15, 8, 14, 19, 18, 9, 17, 6, 5, 0, 4, 16, 11, 10, 13, 15,
            18, 1, 0, 5, 9, 19, 14, 13, 10, 12,
        ],
        corners: 5,
    }
}

/// Icosahedron of radius 1 with vertices on ±x: around +x, five vertices at
/// x = 1/√5 and angles 0°, 72°, … in the y-z plane; around -x, five at x = -1/√5
/// and angles 180°, 108°, 36°, -36°, -108°. The face normals are the (unnormalised)
/// cross products of each face's first two edges, as freeglut's are.
pub fn icosahedron() -> Solid {
    let (x, r) = (1.0 / 5f64.sqrt(), 2.0 / 5f64.sqrt());
    let ring = |x: f64, deg: f64| {
        let a = deg.to_radians();
        [x, r * a.cos(), r * a.sin()]
    };
    let mut exact = vec![[1.0, 0.0, 0.0]];
    exact.extend([0.0, 72.0, 144.0, 216.0, 288.0].map(|d| ring(x, d)));
    exact.extend([180.0, 108.0, 36.0, -36.0, -108.0].map(|d| ring(-x, d)));
    exact.push([-1.0, 0.0, 0.0]);
    let faces: &[u8] = &[
        0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5, 0, 5, 1, 1, 8, 2, 2, 7, 3, 3, 6, 4, 4, 10, 5, 5, 9, 1,
        1, 9, 8, 2, 8, 7, 3, 7, 6, 4, 6, 10, 5, 10, 9, 11, 9, 10, 11, 8, 9, 11, 7, 8, 11, 6, 7, 11,
        10, 6,
    ];
    let normals = faces
        .chunks_exact(3)
        .map(|f| {
            let [p, q, s] = [0, 1, 2].map(|k| exact[usize::from(f[k])]);
            let (u, w) = (sub(q, p), sub(s, p));
            f32v([
                u[1] * w[2] - u[2] * w[1],
                u[2] * w[0] - u[0] * w[2],
                u[0] * w[1] - u[1] * w[0],
            ])
        })
        .collect();
    Solid {
        verts: exact.into_iter().map(f32v).collect(),
        normals,
        faces,
        corners: 3,
    }
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// Octahedron of radius 1: the unit axis points; normals (±1, ±1, ±1)/√3.
pub fn octahedron() -> Solid {
    let k = 1.0 / 3f64.sqrt();
    let normals = (0..8)
        .map(|i| {
            let sign = |bit: i32| if i & bit == 0 { k } else { -k };
            f32v([sign(4), sign(2), sign(1)])
        })
        .collect();
    Solid {
        verts: vec![
            [1., 0., 0.],
            [0., 1., 0.],
            [0., 0., 1.],
            [-1., 0., 0.],
            [0., -1., 0.],
            [0., 0., -1.],
        ],
        normals,
        faces: &[
            0, 1, 2, 0, 5, 1, 0, 2, 4, 0, 4, 5, 3, 2, 1, 3, 1, 5, 3, 4, 2, 3, 5, 4,
        ],
        corners: 3,
    }
}

/// Rhombic dodecahedron of radius 1: the poles (0, 0, ±1), the eight points
/// (±√2/2, 0, ±½) and (0, ±√2/2, ±½), and the four (±√2/2, ±√2/2, 0). Its normals
/// are freeglut's: (±√2/4, ±√2/4, ±½) — of length √2/2, not 1 — and the side axes.
pub fn rhombic_dodecahedron() -> Solid {
    let r = 2f64.sqrt() / 2.0;
    let q = 2f64.sqrt() / 4.0;
    let v = |x: f64, y: f64, z: f64| f32v([x, y, z]);
    Solid {
        verts: vec![
            v(0., 0., 1.),
            v(r, 0., 0.5),
            v(0., r, 0.5),
            v(-r, 0., 0.5),
            v(0., -r, 0.5),
            v(r, r, 0.),
            v(-r, r, 0.),
            v(-r, -r, 0.),
            v(r, -r, 0.),
            v(r, 0., -0.5),
            v(0., r, -0.5),
            v(-r, 0., -0.5),
            v(0., -r, -0.5),
            v(0., 0., -1.),
        ],
        normals: vec![
            v(q, q, 0.5),
            v(-q, q, 0.5),
            v(-q, -q, 0.5),
            v(q, -q, 0.5),
            v(0., 1., 0.),
            v(-1., 0., 0.),
            v(0., -1., 0.),
            v(1., 0., 0.),
            v(q, q, -0.5),
            v(-q, q, -0.5),
            v(-q, -q, -0.5),
            v(q, -q, -0.5),
        ],
        faces: &[
            0, 1, 5, 2, 0, 2, 6, 3, 0, 3, 7, 4, 0, 4, 8, 1, 5, 10, 6, 2, 6, 11, 7, 3, 7, 12, 8, 4,
            8, 9, 5, 1, 5, 9, 13, 10, 6, 10, 13, 11, 7, 11, 13, 12, 8, 12, 13, 9,
        ],
        corners: 4,
    }
}

/// Tetrahedron of radius 1: (1, 0, 0), (-1/3, 2√2/3, 0) and (-1/3, -√2/3, ±√6/3);
/// each face's normal points away from the vertex opposite it.
pub fn tetrahedron() -> Solid {
    let verts = tetra_verts();
    Solid {
        normals: verts.iter().map(|&v| away(v)).collect(),
        verts,
        faces: TETRA_FACES,
        corners: 3,
    }
}

/// The direction opposite `v`, with zero coordinates +0 (not -0).
fn away(v: [f32; 3]) -> [f32; 3] {
    v.map(|c| 0.0 - c)
}

/// Face `i` of the tetrahedron is the one opposite vertex `i`.
const TETRA_FACES: &[u8] = &[1, 3, 2, 0, 2, 3, 0, 3, 1, 0, 1, 2];

fn tetra_verts() -> Vec<[f32; 3]> {
    let (s2, s6) = (2f64.sqrt(), 6f64.sqrt());
    vec![
        f32v([1.0, 0.0, 0.0]),
        f32v([-1.0 / 3.0, 2.0 * s2 / 3.0, 0.0]),
        f32v([-1.0 / 3.0, -s2 / 3.0, s6 / 3.0]),
        f32v([-1.0 / 3.0, -s2 / 3.0, -s6 / 3.0]),
    ]
}

/// Appends the faces of the level-`levels` sponge at `offset` with tetrahedra of
/// radius `scale`: level 0 is one tetrahedron, level n four level n-1 sponges of
/// half the radius, centred halfway towards each vertex.
fn sponge_faces(levels: u32, offset: [f64; 3], scale: f32, t: &[[f32; 3]], m: &mut Mesh) {
    if levels == 0 {
        for (face, n) in TETRA_FACES.chunks_exact(3).zip(t) {
            for &v in face {
                let p = t[usize::from(v)];
                let at = |k: usize| offset[k] as f32 + scale * p[k];
                m.push([at(0), at(1), at(2)], away(*n));
            }
        }
        return;
    }
    let half = (f64::from(scale) / 2.0) as f32;
    for v in t {
        let o = [0, 1, 2].map(|k| offset[k] + f64::from(half * v[k]));
        sponge_faces(levels - 1, o, half, t, m);
    }
}

/// Draws the Sierpinski sponge (nothing for a negative level; at most level 8).
pub fn sponge(levels: i32, offset: [f64; 3], scale: f32, solid: bool) {
    let Ok(levels @ 0..=8) = u32::try_from(levels) else {
        return;
    };
    let mut m = Mesh::with_capacity(12 * 4usize.pow(levels));
    sponge_faces(levels, offset, scale, &tetra_verts(), &mut m);
    if solid {
        draw::solid(&m, None, None, 1);
    } else {
        draw::wire(&m, None, 3, GL_LINE_LOOP, &[], 0);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn all() -> Vec<(&'static str, Solid, f32)> {
        vec![
            ("cube", cube(), 0.75f32.sqrt()),
            ("dodecahedron", dodecahedron(), 3f32.sqrt()),
            ("icosahedron", icosahedron(), 1.0),
            ("octahedron", octahedron(), 1.0),
            ("rhombic dodecahedron", rhombic_dodecahedron(), 1.0),
            ("tetrahedron", tetrahedron(), 1.0),
        ]
    }

    #[test]
    fn faces_are_flat_outward_and_counter_clockwise() {
        for (name, s, radius) in all() {
            for v in &s.verts {
                let r = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
                // The rhombic dodecahedron's side corners lie inside its radius.
                assert!(r <= radius + 1e-6, "{name}: {v:?}");
            }
            for (face, n) in s.faces.chunks_exact(s.corners).zip(&s.normals) {
                let p: Vec<[f64; 3]> = face
                    .iter()
                    .map(|&i| s.verts[usize::from(i)].map(f64::from))
                    .collect();
                let dot = |a: [f64; 3]| {
                    a[0] * f64::from(n[0]) + a[1] * f64::from(n[1]) + a[2] * f64::from(n[2])
                };
                for q in &p {
                    assert!((dot(*q) - dot(p[0])).abs() < 1e-5, "{name}: face not flat");
                }
                assert!(dot(p[0]) > 0.0, "{name}: normal points inwards");
                for k in 0..p.len() {
                    let (a, b, c) = (p[k], p[(k + 1) % p.len()], p[(k + 2) % p.len()]);
                    let (u, w) = (sub(b, a), sub(c, b));
                    let turn = [
                        u[1] * w[2] - u[2] * w[1],
                        u[2] * w[0] - u[0] * w[2],
                        u[0] * w[1] - u[1] * w[0],
                    ];
                    assert!(dot(turn) > 0.0, "{name}: face winds clockwise");
                }
            }
        }
    }

    #[test]
    fn every_vertex_is_used_and_sponge_levels_multiply() {
        for (name, s, _) in all() {
            for i in 0..s.verts.len() {
                assert!(s.faces.contains(&(i as u8)), "{name}: vertex {i} unused");
            }
        }
        let mut m = Mesh::with_capacity(0);
        sponge_faces(2, [0.0; 3], 1.0, &tetra_verts(), &mut m);
        assert_eq!(m.len(), 12 * 16);
    }
}
