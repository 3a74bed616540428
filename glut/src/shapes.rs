//! GLUT's solid and wire shapes, built from their definitions: spheres, cones, tori
//! and cylinders from their parametric equations, the Platonic solids from their
//! vertex sets (each face is the set of vertices farthest along the face's normal,
//! which is a vertex direction of the dual solid).

#![allow(non_snake_case)]

use crate::gl::im;
use crate::gl::{
    GL_LINE_LOOP, GL_LINE_STRIP, GL_POLYGON, GL_QUADS, GL_QUAD_STRIP, GL_TRIANGLE_FAN,
};
use std::f64::consts::PI;

type V3 = [f64; 3];

fn f32v(v: V3) -> [f32; 3] {
    [v[0] as f32, v[1] as f32, v[2] as f32]
}
fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
fn normalize(a: V3) -> V3 {
    let l = dot(a, a).sqrt();
    if l == 0.0 {
        a
    } else {
        [a[0] / l, a[1] / l, a[2] / l]
    }
}
fn scale(a: V3, s: f64) -> V3 {
    [a[0] * s, a[1] * s, a[2] * s]
}

/// (cos, sin) of `n` equal steps around the circle, with the last equal to the first.
fn circle(n: i32) -> Vec<(f64, f64)> {
    (0..=n)
        .map(|i| {
            let a = 2.0 * PI * f64::from(i % n) / f64::from(n);
            (a.cos(), a.sin())
        })
        .collect()
}

/// The faces of a convex solid: for each normal direction, the vertices with the
/// largest projection on it, ordered counter-clockwise seen from outside.
pub fn faces(verts: &[V3], normals: &[V3]) -> Vec<(V3, Vec<V3>)> {
    normals
        .iter()
        .map(|&n| {
            let n = normalize(n);
            let best = verts.iter().map(|&v| dot(v, n)).fold(f64::MIN, f64::max);
            let mut face: Vec<V3> = verts
                .iter()
                .copied()
                .filter(|&v| dot(v, n) > best - 1e-6 * best.abs().max(1.0))
                .collect();
            let c = scale(
                face.iter()
                    .fold([0.0; 3], |a, &v| [a[0] + v[0], a[1] + v[1], a[2] + v[2]]),
                1.0 / face.len() as f64,
            );
            let u = normalize(sub(face[0], c));
            let w = cross(n, u);
            face.sort_by(|&a, &b| {
                let d = |p: V3| {
                    let r = sub(p, c);
                    dot(r, w).atan2(dot(r, u))
                };
                d(a).total_cmp(&d(b))
            });
            (n, face)
        })
        .collect()
}

/// Draws faces filled (GL_POLYGON per face, flat normals) or as line loops.
fn draw_faces(fs: &[(V3, Vec<V3>)], solid: bool) {
    for (n, face) in fs {
        im::begin(if solid { GL_POLYGON } else { GL_LINE_LOOP });
        im::n3(f32v(*n));
        for &v in face {
            im::v3(f32v(v));
        }
        im::end();
    }
}

/// All sign combinations of (±a, ±b, ±c) for the given magnitudes (zeros kept once).
fn signs(a: f64, b: f64, c: f64) -> Vec<V3> {
    let mut out = Vec::new();
    for sa in [1.0, -1.0] {
        for sb in [1.0, -1.0] {
            for sc in [1.0, -1.0] {
                let v = [a * sa, b * sb, c * sc];
                if !out.contains(&v) {
                    out.push(v);
                }
            }
        }
    }
    out
}

/// Cyclic permutations (x,y,z), (y,z,x), (z,x,y) of every point.
fn cyclic(points: Vec<V3>) -> Vec<V3> {
    let mut out = Vec::new();
    for p in points {
        for q in [p, [p[1], p[2], p[0]], [p[2], p[0], p[1]]] {
            if !out.contains(&q) {
                out.push(q);
            }
        }
    }
    out
}

/// The golden ratio.
fn phi() -> f64 {
    (1.0 + 5f64.sqrt()) / 2.0
}

fn cube_faces(size: f64) -> Vec<(V3, Vec<V3>)> {
    let h = size / 2.0;
    faces(&signs(h, h, h), &cyclic(signs(1.0, 0.0, 0.0)))
}

fn octa_verts() -> Vec<V3> {
    cyclic(signs(1.0, 0.0, 0.0))
}

/// Tetrahedron of radius 1: alternate corners of a cube.
fn tetra_verts() -> Vec<V3> {
    let r = 1.0 / 3f64.sqrt();
    signs(r, r, r)
        .into_iter()
        .filter(|v| v[0] * v[1] * v[2] > 0.0)
        .collect()
}

/// Icosahedron of radius 1: cyclic permutations of (0, ±1, ±φ), scaled.
fn icosa_verts() -> Vec<V3> {
    let s = 1.0 / (1.0 + phi() * phi()).sqrt();
    cyclic(signs(0.0, s, phi() * s))
}

/// Dodecahedron of radius √3 (GLUT's size): the cube corners and the cyclic
/// permutations of (0, ±1/φ, ±φ).
fn dodeca_verts() -> Vec<V3> {
    let mut v = signs(1.0, 1.0, 1.0);
    v.extend(cyclic(signs(0.0, 1.0 / phi(), phi())));
    v
}

/// Face normals of the icosahedron: the vertex directions of its dual dodecahedron,
/// the cube corners and the cyclic permutations of (0, ±φ, ±1/φ).
fn icosa_normals() -> Vec<V3> {
    let mut v = signs(1.0, 1.0, 1.0);
    v.extend(cyclic(signs(0.0, phi(), 1.0 / phi())));
    v
}

/// Face normals of the dodecahedron: its dual icosahedron's vertex directions,
/// the cyclic permutations of (0, ±φ, ±1).
fn dodeca_normals() -> Vec<V3> {
    cyclic(signs(0.0, phi(), 1.0))
}

macro_rules! solid_pair {
    ($(#[$doc:meta] $solid:ident, $wire:ident, $faces:expr;)*) => {$(
        #[$doc]
        #[no_mangle]
        pub extern "C" fn $solid() {
            draw_faces(&$faces, true);
        }
        #[$doc]
        #[no_mangle]
        pub extern "C" fn $wire() {
            draw_faces(&$faces, false);
        }
    )*};
}

solid_pair! {
    /// Tetrahedron of radius 1 centred at the origin.
    glutSolidTetrahedron, glutWireTetrahedron,
        faces(&tetra_verts(), &tetra_verts().iter().map(|v| scale(*v, -1.0)).collect::<Vec<_>>());
    /// Octahedron of radius 1.
    glutSolidOctahedron, glutWireOctahedron, faces(&octa_verts(), &signs(1.0, 1.0, 1.0));
    /// Icosahedron of radius 1.
    glutSolidIcosahedron, glutWireIcosahedron, faces(&icosa_verts(), &icosa_normals());
    /// Dodecahedron of radius √3.
    glutSolidDodecahedron, glutWireDodecahedron, faces(&dodeca_verts(), &dodeca_normals());
    /// Rhombic dodecahedron (freeglut), radius 1.
    glutSolidRhombicDodecahedron, glutWireRhombicDodecahedron,
        faces(&rhombic_verts(), &cyclic(signs(1.0, 1.0, 0.0)));
}

/// Rhombic dodecahedron: (±1,±1,±1)/2 and (±1,0,0) with permutations (radius 1).
fn rhombic_verts() -> Vec<V3> {
    let mut v = signs(0.5, 0.5, 0.5);
    v.extend(octa_verts());
    v
}

/// `glutSolidCube`: a cube of edge `size` centred at the origin.
#[no_mangle]
pub extern "C" fn glutSolidCube(size: f64) {
    let fs = cube_faces(size);
    im::begin(GL_QUADS);
    for (n, face) in &fs {
        im::n3(f32v(*n));
        for &v in face {
            im::v3(f32v(v));
        }
    }
    im::end();
}

/// `glutWireCube`.
#[no_mangle]
pub extern "C" fn glutWireCube(size: f64) {
    draw_faces(&cube_faces(size), false);
}

/// Sphere point and normal at longitude index `i`, latitude angle `theta` from +z.
fn sphere_point(radius: f64, c: (f64, f64), theta: f64) -> (V3, V3) {
    let n = [c.0 * theta.sin(), c.1 * theta.sin(), theta.cos()];
    (scale(n, radius), n)
}

/// `glutSolidSphere`: `slices` around the z axis, `stacks` from +z to -z.
#[no_mangle]
pub extern "C" fn glutSolidSphere(radius: f64, slices: i32, stacks: i32) {
    if slices < 2 || stacks < 1 {
        return;
    }
    let ring = circle(slices);
    for j in 0..stacks {
        let t0 = PI * f64::from(j) / f64::from(stacks);
        let t1 = PI * f64::from(j + 1) / f64::from(stacks);
        im::begin(GL_QUAD_STRIP);
        for &c in &ring {
            for t in [t0, t1] {
                let (p, n) = sphere_point(radius, c, t);
                im::n3(f32v(n));
                im::v3(f32v(p));
            }
        }
        im::end();
    }
}

/// `glutWireSphere`: the latitude circles and longitude half-circles.
#[no_mangle]
pub extern "C" fn glutWireSphere(radius: f64, slices: i32, stacks: i32) {
    if slices < 2 || stacks < 1 {
        return;
    }
    let ring = circle(slices);
    for j in 1..stacks {
        let t = PI * f64::from(j) / f64::from(stacks);
        im::begin(GL_LINE_LOOP);
        for &c in &ring[..slices as usize] {
            let (p, n) = sphere_point(radius, c, t);
            im::n3(f32v(n));
            im::v3(f32v(p));
        }
        im::end();
    }
    for &c in &ring[..slices as usize] {
        im::begin(GL_LINE_STRIP);
        for j in 0..=stacks {
            let (p, n) = sphere_point(radius, c, PI * f64::from(j) / f64::from(stacks));
            im::n3(f32v(n));
            im::v3(f32v(p));
        }
        im::end();
    }
}

/// `glutSolidCone`: base of radius `base` on z = 0, apex at z = `height`.
#[no_mangle]
pub extern "C" fn glutSolidCone(base: f64, height: f64, slices: i32, stacks: i32) {
    if slices < 2 || stacks < 1 {
        return;
    }
    let ring = circle(slices);
    let len = (base * base + height * height)
        .sqrt()
        .max(f64::MIN_POSITIVE);
    let (nz, nr) = (base / len, height / len);
    // The base, facing -z.
    im::begin(GL_TRIANGLE_FAN);
    im::n3([0.0, 0.0, -1.0]);
    im::v3([0.0, 0.0, 0.0]);
    for &(c, s) in ring.iter().rev() {
        im::v3(f32v([c * base, s * base, 0.0]));
    }
    im::end();
    for j in 0..stacks {
        let f0 = f64::from(j) / f64::from(stacks);
        let f1 = f64::from(j + 1) / f64::from(stacks);
        im::begin(GL_QUAD_STRIP);
        for &(c, s) in &ring {
            im::n3(f32v([c * nr, s * nr, nz]));
            for f in [f1, f0] {
                let r = base * (1.0 - f);
                im::v3(f32v([c * r, s * r, height * f]));
            }
        }
        im::end();
    }
}

/// `glutWireCone`: stack circles and lines from the base to the apex.
#[no_mangle]
pub extern "C" fn glutWireCone(base: f64, height: f64, slices: i32, stacks: i32) {
    if slices < 2 || stacks < 1 {
        return;
    }
    let ring = circle(slices);
    let len = (base * base + height * height)
        .sqrt()
        .max(f64::MIN_POSITIVE);
    let (nz, nr) = (base / len, height / len);
    for j in 0..stacks {
        let f = f64::from(j) / f64::from(stacks);
        let r = base * (1.0 - f);
        im::begin(GL_LINE_LOOP);
        for &(c, s) in &ring[..slices as usize] {
            im::n3(f32v([c * nr, s * nr, nz]));
            im::v3(f32v([c * r, s * r, height * f]));
        }
        im::end();
    }
    im::begin(crate::gl::GL_LINES);
    for &(c, s) in &ring[..slices as usize] {
        im::n3(f32v([c * nr, s * nr, nz]));
        im::v3(f32v([c * base, s * base, 0.0]));
        im::v3(f32v([0.0, 0.0, height]));
    }
    im::end();
}

/// `glutSolidCylinder` (freeglut): radius, z from 0 to `height`, with end caps.
#[no_mangle]
pub extern "C" fn glutSolidCylinder(radius: f64, height: f64, slices: i32, stacks: i32) {
    if slices < 2 || stacks < 1 {
        return;
    }
    let ring = circle(slices);
    for (z, nz, rev) in [(0.0, -1.0, true), (height, 1.0, false)] {
        im::begin(GL_TRIANGLE_FAN);
        im::n3([0.0, 0.0, nz]);
        im::v3(f32v([0.0, 0.0, z]));
        let pts: Vec<_> = if rev {
            ring.iter().rev().copied().collect()
        } else {
            ring.clone()
        };
        for (c, s) in pts {
            im::v3(f32v([c * radius, s * radius, z]));
        }
        im::end();
    }
    for j in 0..stacks {
        let z0 = height * f64::from(j) / f64::from(stacks);
        let z1 = height * f64::from(j + 1) / f64::from(stacks);
        im::begin(GL_QUAD_STRIP);
        for &(c, s) in &ring {
            im::n3(f32v([c, s, 0.0]));
            im::v3(f32v([c * radius, s * radius, z1]));
            im::v3(f32v([c * radius, s * radius, z0]));
        }
        im::end();
    }
}

/// `glutWireCylinder` (freeglut).
#[no_mangle]
pub extern "C" fn glutWireCylinder(radius: f64, height: f64, slices: i32, stacks: i32) {
    if slices < 2 || stacks < 1 {
        return;
    }
    let ring = circle(slices);
    for j in 0..=stacks {
        let z = height * f64::from(j) / f64::from(stacks);
        im::begin(GL_LINE_LOOP);
        for &(c, s) in &ring[..slices as usize] {
            im::n3(f32v([c, s, 0.0]));
            im::v3(f32v([c * radius, s * radius, z]));
        }
        im::end();
    }
    im::begin(crate::gl::GL_LINES);
    for &(c, s) in &ring[..slices as usize] {
        im::n3(f32v([c, s, 0.0]));
        im::v3(f32v([c * radius, s * radius, 0.0]));
        im::v3(f32v([c * radius, s * radius, height]));
    }
    im::end();
}

/// Torus point and normal: tube angle `p` (cos, sin), ring angle `r` (cos, sin).
fn torus_point(inner: f64, outer: f64, p: (f64, f64), r: (f64, f64)) -> (V3, V3) {
    let d = outer + inner * p.0;
    ([r.0 * d, r.1 * d, inner * p.1], [r.0 * p.0, r.1 * p.0, p.1])
}

/// `glutSolidTorus`: a tube of radius `inner` around a circle of radius `outer` in
/// the z = 0 plane.
#[no_mangle]
pub extern "C" fn glutSolidTorus(inner: f64, outer: f64, sides: i32, rings: i32) {
    if sides < 3 || rings < 3 {
        return;
    }
    let (tube, ring) = (circle(sides), circle(rings));
    for i in 0..rings as usize {
        im::begin(GL_QUAD_STRIP);
        for &p in &tube {
            for r in [ring[i], ring[i + 1]] {
                let (v, n) = torus_point(inner, outer, p, r);
                im::n3(f32v(n));
                im::v3(f32v(v));
            }
        }
        im::end();
    }
}

/// `glutWireTorus`: the tube circles and the ring circles.
#[no_mangle]
pub extern "C" fn glutWireTorus(inner: f64, outer: f64, sides: i32, rings: i32) {
    if sides < 3 || rings < 3 {
        return;
    }
    let (tube, ring) = (circle(sides), circle(rings));
    for &r in &ring[..rings as usize] {
        im::begin(GL_LINE_LOOP);
        for &p in &tube[..sides as usize] {
            let (v, n) = torus_point(inner, outer, p, r);
            im::n3(f32v(n));
            im::v3(f32v(v));
        }
        im::end();
    }
    for &p in &tube[..sides as usize] {
        im::begin(GL_LINE_LOOP);
        for &r in &ring[..rings as usize] {
            let (v, n) = torus_point(inner, outer, p, r);
            im::n3(f32v(n));
            im::v3(f32v(v));
        }
        im::end();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solids_have_their_face_counts() {
        let tn: Vec<V3> = tetra_verts().iter().map(|v| scale(*v, -1.0)).collect();
        let count = |fs: Vec<(V3, Vec<V3>)>| fs.iter().map(|f| f.1.len()).collect::<Vec<_>>();
        assert_eq!(count(faces(&tetra_verts(), &tn)), vec![3; 4]);
        assert_eq!(count(cube_faces(1.0)), vec![4; 6]);
        assert_eq!(
            count(faces(&octa_verts(), &signs(1.0, 1.0, 1.0))),
            vec![3; 8]
        );
        assert_eq!(count(faces(&icosa_verts(), &icosa_normals())), vec![3; 20]);
        assert_eq!(
            count(faces(&dodeca_verts(), &dodeca_normals())),
            vec![5; 12]
        );
        assert_eq!(
            count(faces(&rhombic_verts(), &cyclic(signs(1.0, 1.0, 0.0)))),
            vec![4; 12]
        );
    }

    #[test]
    fn faces_wind_counter_clockwise_from_outside() {
        for (n, f) in faces(&dodeca_verts(), &dodeca_normals())
            .into_iter()
            .chain(faces(&icosa_verts(), &icosa_normals()))
        {
            let area = cross(sub(f[1], f[0]), sub(f[2], f[0]));
            assert!(dot(area, n) > 0.0);
        }
    }
}
