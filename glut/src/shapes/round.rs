//! The shapes with circular cross-sections — sphere, cone, cylinder and torus — laid
//! out as freeglut 3.4 lays them out: the same vertices (computed in single precision
//! from the same sine tables), the same normals, and the same triangle strips and line
//! loops in the same order, so they rasterise to the same pixels.
//!
//! Sphere, cone and cylinder run around the z axis clockwise seen from +z (freeglut
//! walks its circle table backwards), starting on +x; each is one strip per stack.

use super::draw::{self, Mesh};
use crate::gl::{GL_LINES, GL_LINE_LOOP, GL_LINE_STRIP};

/// Index lists are 16-bit like freeglut's (larger shapes wrap as they do there), but
/// shapes needing more than this many vertices are not drawn at all.
const MAX_VERTS: i64 = 1 << 22;

/// `n + 1` samples of (sin, cos) around a circle (half a circle when `half`), in
/// single precision; a negative `n` walks the circle the other way. The last sample
/// repeats the first (or is exactly (0, -1) for a half circle).
fn circle_table(n: i32, half: bool) -> (Vec<f32>, Vec<f32>) {
    let size = n.unsigned_abs() as usize;
    let turn = if half { 1.0f32 } else { 2.0 } * std::f32::consts::PI;
    let step = turn / (if n == 0 { 1 } else { n }) as f32;
    let mut sin = vec![0.0f32; size + 1];
    let mut cos = vec![1.0f32; size + 1];
    for i in 1..size {
        let a = f64::from(step * i as f32);
        sin[i] = a.sin() as f32;
        cos[i] = a.cos() as f32;
    }
    if half {
        sin[size] = 0.0;
        cos[size] = -1.0;
    } else {
        sin[size] = sin[0];
        cos[size] = cos[0];
    }
    (sin, cos)
}

/// True when a shape of `verts` vertices is small enough to build.
fn fits(verts: i64) -> bool {
    (1..=MAX_VERTS).contains(&verts)
}

/// Sphere vertices: the top pole, `stacks - 1` rings of `slices` from the top down,
/// the bottom pole.
fn sphere_mesh(radius: f32, slices: i32, stacks: i32) -> Mesh {
    let (s1, c1) = circle_table(-slices, false);
    let (s2, c2) = circle_table(stacks, true);
    let n = slices as usize;
    let mut m = Mesh::with_capacity(n * (stacks as usize - 1) + 2);
    m.push([0.0, 0.0, radius], [0.0, 0.0, 1.0]);
    for i in 1..stacks as usize {
        for j in 0..n {
            let d = [c1[j] * s2[i], s1[j] * s2[i], c2[i]];
            m.push([d[0] * radius, d[1] * radius, d[2] * radius], d);
        }
    }
    m.push([0.0, 0.0, -radius], [0.0, 0.0, -1.0]);
    m
}

/// Draws the sphere, filled or as its rings and meridians.
pub fn sphere(radius: f32, slices: i32, stacks: i32, solid: bool) {
    if slices < 1 || stacks < 2 || !fits(i64::from(slices) * i64::from(stacks - 1) + 2) {
        return;
    }
    let m = sphere_mesh(radius, slices, stacks);
    let (n, last) = (slices as usize, m.len() - 1);
    let ring = |i: usize, j: usize| (1 + i * n + j) as u16;
    if solid {
        let mut idx = Vec::with_capacity((n + 1) * 2 * stacks as usize);
        // Top cap: each ring-1 vertex paired with the pole.
        for j in (0..n).chain([0]) {
            idx.extend([ring(0, j), 0]);
        }
        for i in 0..stacks as usize - 2 {
            for j in (0..n).chain([0]) {
                idx.extend([ring(i + 1, j), ring(i, j)]);
            }
        }
        for j in (0..n).chain([0]) {
            idx.extend([last as u16, ring(stacks as usize - 2, j)]);
        }
        draw::solid(&m, None, Some(&idx), stacks as usize);
    } else {
        let mut meridians = Vec::with_capacity(n * (stacks as usize + 1));
        for j in 0..n {
            meridians.push(0);
            meridians.extend((0..stacks as usize - 1).map(|i| ring(i, j)));
            meridians.push(last as u16);
        }
        let rings: Vec<u16> = (0..n * (stacks as usize - 1))
            .map(|k| (1 + k) as u16)
            .collect();
        draw::wire(
            &m,
            Some(&meridians),
            stacks as usize + 1,
            GL_LINE_STRIP,
            &rings,
            n,
        );
    }
}

/// Vertices of a cone or cylinder side: `rings` rings of `slices` starting at z = 0,
/// stepping z and the radius by single-precision increments; `normal` gives each
/// ring vertex's normal from its (cos, sin).
fn push_rings(
    m: &mut Mesh,
    (sin, cos): (&[f32], &[f32]),
    rings: i32,
    (mut z, z_step): (f32, f32),
    (mut r, r_step): (f32, f32),
    normal: impl Fn(f32, f32) -> [f32; 3],
) -> f32 {
    for _ in 0..rings {
        for j in 0..sin.len() - 1 {
            m.push([cos[j] * r, sin[j] * r, z], normal(cos[j], sin[j]));
        }
        z += z_step;
        r -= r_step;
    }
    z
}

/// Index of vertex `j` of side ring `ring` (ring 0 is the bottom cap's rim) in a cone
/// or cylinder mesh of `n` slices.
fn at(n: usize, ring: usize, j: usize) -> u16 {
    (1 + ring * n + j) as u16
}

/// Draws a cone's or cylinder's mesh: filled, the bottom cap strip (centre 0 with
/// ring 0), a strip between each pair of side rings 1..=stacks+1, then `top_cap`'s
/// strip; as a wire, lines from side ring 1 to side ring stacks+1 and loops around
/// side rings 1..=`loops`.
fn side(
    m: &Mesh,
    n: usize,
    stacks: usize,
    top_cap: Option<(usize, u16)>,
    loops: usize,
    solid: bool,
) {
    let around = || (0..n).chain([0]);
    if solid {
        let mut idx = Vec::with_capacity(2 * (n + 1) * (stacks + 2));
        for j in around() {
            idx.extend([0, at(n, 0, j)]);
        }
        for i in 1..=stacks {
            for j in around() {
                idx.extend([at(n, i, j), at(n, i + 1, j)]);
            }
        }
        if let Some((ring, centre)) = top_cap {
            for j in around() {
                idx.extend([at(n, ring, j), centre]);
            }
        }
        draw::solid(m, None, Some(&idx), idx.len() / (2 * (n + 1)));
    } else {
        let lines: Vec<u16> = (0..n)
            .flat_map(|j| [at(n, 1, j), at(n, stacks + 1, j)])
            .collect();
        let rings: Vec<u16> = (1..=loops)
            .flat_map(|i| (0..n).map(move |j| at(n, i, j)))
            .collect();
        draw::wire(m, Some(&lines), 2 * n, GL_LINES, &rings, n);
    }
}

/// Draws the cone: base of radius `base` on z = 0, apex at z = `height`.
pub fn cone(base: f32, height: f32, slices: i32, stacks: i32, solid: bool) {
    if slices < 1 || stacks < 1 || !fits(i64::from(slices) * (i64::from(stacks) + 2) + 1) {
        return;
    }
    let z_step = height / stacks as f32;
    let r_step = base / stacks as f32;
    let hyp = f64::from(height * height + base * base).sqrt();
    let (cosn, sinn) = (
        (f64::from(height) / hyp) as f32,
        (f64::from(base) / hyp) as f32,
    );
    let (sin, cos) = circle_table(-slices, false);
    let (n, st) = (slices as usize, stacks as usize);
    let mut m = Mesh::with_capacity(n * (st + 2) + 1);
    // The base: its centre, and its rim with the base's normal.
    m.push([0.0, 0.0, 0.0], [0.0, 0.0, -1.0]);
    let down = |_, _| [0.0, 0.0, -1.0];
    push_rings(&mut m, (&sin, &cos), 1, (0.0, 0.0), (base, 0.0), down);
    let slant = |c: f32, s: f32| [c * cosn, s * cosn, sinn];
    push_rings(
        &mut m,
        (&sin, &cos),
        stacks + 1,
        (0.0, z_step),
        (base, r_step),
        slant,
    );
    side(&m, n, st, None, st, solid);
}

/// Draws the cylinder: radius `radius`, z from 0 to `height`, with both end caps.
pub fn cylinder(radius: f32, height: f32, slices: i32, stacks: i32, solid: bool) {
    if slices < 1 || stacks < 1 || !fits(i64::from(slices) * (i64::from(stacks) + 3) + 2) {
        return;
    }
    let z_step = height / stacks as f32;
    let (sin, cos) = circle_table(-slices, false);
    let (n, st) = (slices as usize, stacks as usize);
    let mut m = Mesh::with_capacity(n * (st + 3) + 2);
    m.push([0.0, 0.0, 0.0], [0.0, 0.0, -1.0]);
    let t = (&sin[..], &cos[..]);
    push_rings(&mut m, t, 1, (0.0, 0.0), (radius, 0.0), |_, _| {
        [0.0, 0.0, -1.0]
    });
    let z = push_rings(
        &mut m,
        t,
        stacks + 1,
        (0.0, z_step),
        (radius, 0.0),
        |c, s| [c, s, 0.0],
    );
    // The top cap's rim sits where the last side ring was put (one step back), its
    // centre at exactly `height`.
    push_rings(&mut m, t, 1, (z - z_step, 0.0), (radius, 0.0), |_, _| {
        [0.0, 0.0, 1.0]
    });
    m.push([0.0, 0.0, height], [0.0, 0.0, 1.0]);
    let centre = (m.len() - 1) as u16;
    side(&m, n, st, Some((st + 2, centre)), st + 1, solid);
}

/// Draws the torus: a tube of radius `inner` around a circle of radius `outer` in the
/// z = 0 plane; `sides` around the tube, `rings` around the z axis.
pub fn torus(inner: f32, outer: f32, sides: i32, rings: i32, solid: bool) {
    if sides < 2 || rings < 2 || !fits(i64::from(sides) * i64::from(rings)) {
        return;
    }
    let (spsi, cpsi) = circle_table(rings, false);
    let (sphi, cphi) = circle_table(-sides, false);
    let (ns, nr) = (sides as usize, rings as usize);
    let mut m = Mesh::with_capacity(ns * nr);
    for j in 0..nr {
        for i in 0..ns {
            let d = outer + cphi[i] * inner;
            m.push(
                [cpsi[j] * d, spsi[j] * d, sphi[i] * inner],
                [cpsi[j] * cphi[i], spsi[j] * cphi[i], sphi[i]],
            );
        }
    }
    let at = |j: usize, i: usize| (j * ns + i) as u16;
    if solid {
        // One strip per side band, walking the rings; the last band wraps to side 0.
        let mut idx = Vec::with_capacity((nr + 1) * 2 * ns);
        for i in 0..ns {
            let next = (i + 1) % ns;
            for j in (0..nr).chain([0]) {
                idx.extend([at(j, i), at(j, next)]);
            }
        }
        draw::solid(&m, None, Some(&idx), ns);
    } else {
        let ring_loops: Vec<u16> = (0..nr)
            .flat_map(|j| (0..ns).map(move |i| at(j, i)))
            .collect();
        let side_loops: Vec<u16> = (0..ns)
            .flat_map(|i| (0..nr).map(move |j| at(j, i)))
            .collect();
        draw::wire(&m, Some(&ring_loops), ns, GL_LINE_LOOP, &side_loops, nr);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn circle_tables_close_and_run_both_ways() {
        let (s, c) = circle_table(6, false);
        assert_eq!((s[6], c[6]), (s[0], c[0]));
        assert!(s[1] > 0.0 && (c[1] - 0.5).abs() < 1e-6);
        let (s, _) = circle_table(-6, false);
        assert!(s[1] < 0.0);
        let (s, c) = circle_table(4, true);
        assert_eq!((s[4], c[4]), (0.0, -1.0));
        assert!((s[2] - 1.0).abs() < 1e-6 && c[2].abs() < 1e-6);
    }

    #[test]
    fn sphere_normals_are_unit_and_radial() {
        let m = sphere_mesh(2.0, 7, 5);
        assert_eq!(m.len(), 7 * 4 + 2);
        for (v, n) in m.verts.chunks_exact(3).zip(m.norms.chunks_exact(3)) {
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            assert!((len - 1.0).abs() < 1e-6);
            for k in 0..3 {
                assert!((v[k] - 2.0 * n[k]).abs() < 1e-6);
            }
        }
    }
}
