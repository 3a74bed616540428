//! The tea set — teapot, teacup, teaspoon — as freeglut 3.4 tessellates it: each
//! bicubic Bézier patch of [`data`] evaluated in single precision on an 8 x 8 grid
//! (solid) or a 10 x 10 grid (wire), with the same Bernstein weights, sums in the same
//! order, the same normals and the same triangles and line strips, so it rasterises
//! to freeglut's pixels.
//!
//! Placement: the data's z axis (up) becomes y, the object is lowered by its centre
//! height and scaled by half the size argument, all folded into the control points.
//! Quirk kept from freeglut: normals are computed once, at the first size drawn; a
//! later size only moves the vertices.

#![allow(non_snake_case)]

pub mod data;

use crate::gl::GL_LINE_STRIP;
use crate::shapes::draw::{self, Mesh};
use std::sync::Mutex;

/// Grid points per patch side, filled and wire.
const SOLID_GRID: usize = 8;
const WIRE_GRID: usize = 10;

/// One tea-set object: its patches and points, its vertical offset, and which patches
/// are turned or mirrored.
struct Object {
    patches: &'static [[u8; 16]],
    points: &'static [[f32; 3]],
    /// Height of the data's origin above the object's centre.
    z_offset: f32,
    /// Teapot and teacup: the first six patches are turned to all four quadrants and
    /// the rest mirrored; the teaspoon's are used as they are.
    symmetric: bool,
    /// Teapot only: the lid's knob (patch 3) and the bottom's centre (patch 5) meet
    /// in a point where the derivatives vanish; their first grid row gets the normal
    /// straight up or down instead.
    pole_normals: bool,
}

const TEAPOT: Object = Object {
    patches: &data::TEAPOT_PATCHES,
    points: &data::TEAPOT_POINTS,
    z_offset: 1.575,
    symmetric: true,
    pole_normals: true,
};
const TEACUP: Object = Object {
    patches: &data::TEACUP_PATCHES,
    points: &data::TEACUP_POINTS,
    z_offset: 1.5121,
    symmetric: true,
    pole_normals: false,
};
const TEASPOON: Object = Object {
    patches: &data::TEASPOON_PATCHES,
    points: &data::TEASPOON_POINTS,
    z_offset: -0.0315,
    symmetric: false,
    pole_normals: false,
};

/// The cubic Bernstein weights and their derivatives at `grid` equal steps of [0, 1].
fn bernstein(grid: usize) -> Vec<([f32; 4], [f32; 4])> {
    (0..grid)
        .map(|s| {
            let x = s as f32 / (grid as f32 - 1.0);
            let y = 1.0 - x;
            let (yy, xx) = (y * y, x * x);
            (
                [y * yy, 3.0 * x * yy, 3.0 * xx * y, x * xx],
                [
                    -3.0 * yy,
                    3.0 * yy - 6.0 * x * y,
                    6.0 * x * y - 3.0 * xx,
                    3.0 * xx,
                ],
            )
        })
        .collect()
}

type Cp = [[[f32; 3]; 4]; 4];

/// Patch `p`'s control points in GL's axes, lowered and scaled.
fn control_points(obj: &Object, p: usize, scale: f32) -> Cp {
    let mut cp = [[[0.0; 3]; 4]; 4];
    for (i, &k) in obj.patches[p].iter().enumerate() {
        let c = obj.points[usize::from(k)];
        cp[i / 4][i % 4] = [
            c[0] * scale / 2.0,
            (c[2] - obj.z_offset) * scale / 2.0,
            -c[1] * scale / 2.0,
        ];
    }
    cp
}

fn add_scaled(acc: &mut [f32; 3], w: f32, v: [f32; 3]) {
    for k in 0..3 {
        acc[k] += w * v[k];
    }
}

/// Evaluates one patch on the grid, row by row: positions, and unit normals from the
/// cross product of the two partial derivatives.
fn eval_patch(cp: &Cp, bern: &[([f32; 4], [f32; 4])], out: &mut Mesh) {
    for (b0u, b1u) in bern {
        for (b0v, b1v) in bern {
            let (mut pos, mut du, mut dv) = ([0.0f32; 3], [0.0f32; 3], [0.0f32; 3]);
            for i in 0..4 {
                let (mut row, mut row_d) = ([0.0f32; 3], [0.0f32; 3]);
                for j in 0..4 {
                    add_scaled(&mut row, b0v[j], cp[i][j]);
                    add_scaled(&mut row_d, b1v[j], cp[i][j]);
                }
                add_scaled(&mut pos, b0u[i], row);
                add_scaled(&mut du, b0u[i], row_d);
                add_scaled(&mut dv, b1u[i], row);
            }
            let n = [
                du[1] * dv[2] - du[2] * dv[1],
                du[2] * dv[0] - du[0] * dv[2],
                du[0] * dv[1] - du[1] * dv[0],
            ];
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            out.push(pos, [n[0] / len, n[1] / len, n[2] / len]);
        }
    }
}

/// Appends the copies of the patch just evaluated (the last `grid`² entries of `v`,
/// three floats each): three quarter turns about y, or one mirror image in z = 0 with
/// the rows reversed to keep the winding.
fn replicate(v: &mut Vec<f32>, grid: usize, turn: bool) {
    let start = v.len() - 3 * grid * grid;
    let base: Vec<[f32; 3]> = v[start..]
        .chunks_exact(3)
        .map(|c| [c[0], c[1], c[2]])
        .collect();
    if turn {
        for f in [
            |p: [f32; 3]| [p[2], p[1], -p[0]],
            |p: [f32; 3]| [-p[0], p[1], -p[2]],
            |p: [f32; 3]| [-p[2], p[1], p[0]],
        ] {
            v.extend(base.iter().flat_map(|&p| f(p)));
        }
    } else {
        for row in base.chunks_exact(grid).rev() {
            v.extend(row.iter().flat_map(|p| [p[0], p[1], -p[2]]));
        }
    }
}

/// Every patch's grid points (copies included), in drawing order.
fn evaluate(obj: &Object, grid: usize, scale: f32) -> Mesh {
    let bern = bernstein(grid);
    let mut m = Mesh::with_capacity(0);
    for p in 0..obj.patches.len() {
        eval_patch(&control_points(obj, p, scale), &bern, &mut m);
        if obj.pole_normals && (p == 3 || p == 5) {
            let first_row = m.norms.len() - 3 * grid * grid;
            let y = if p == 3 { 1.0 } else { -1.0 };
            for n in m.norms[first_row..first_row + 3 * grid].chunks_exact_mut(3) {
                n.copy_from_slice(&[0.0, y, 0.0]);
            }
        }
        if obj.symmetric {
            replicate(&mut m.verts, grid, p < 6);
            replicate(&mut m.norms, grid, p < 6);
        }
    }
    m
}

/// Triangle indices: each grid square (a, b one row down) as (a, b, b+1), (a, b+1, a+1).
fn triangles(patches: usize, grid: usize) -> Vec<u16> {
    let mut idx = Vec::with_capacity(patches * (grid - 1) * (grid - 1) * 6);
    for p in 0..patches {
        for r in 0..grid - 1 {
            for c in 0..grid - 1 {
                let a = (p * grid * grid + r * grid + c) as u16;
                let b = a + grid as u16;
                idx.extend([a, b, b + 1, a, b + 1, a + 1]);
            }
        }
    }
    idx
}

/// Line-strip indices: every patch's columns, then every patch's rows.
fn strips(patches: usize, grid: usize) -> Vec<u16> {
    let at = |p: usize, r: usize, c: usize| (p * grid * grid + r * grid + c) as u16;
    let mut idx = Vec::with_capacity(patches * grid * grid * 2);
    for p in 0..patches {
        idx.extend((0..grid).flat_map(|c| (0..grid).map(move |r| at(p, r, c))));
    }
    for p in 0..patches {
        idx.extend((0..grid).flat_map(|r| (0..grid).map(move |c| at(p, r, c))));
    }
    idx
}

/// One object's cached tessellation in one mode.
struct Built {
    scale: f32,
    mesh: Mesh,
    texcs: Vec<f32>,
    idx: Vec<u16>,
}

/// Builds (or moves to a new size) and draws one object.
fn draw(obj: &Object, cache: &Mutex<Option<Built>>, size: f32, solid: bool) {
    let grid = if solid { SOLID_GRID } else { WIRE_GRID };
    let mut cache = cache.lock().unwrap_or_else(|e| e.into_inner());
    match cache.as_mut() {
        Some(b) if b.scale == size => {}
        Some(b) => {
            b.mesh.verts = evaluate(obj, grid, size).verts;
            b.scale = size;
        }
        None => {
            let mesh = evaluate(obj, grid, size);
            let patches = mesh.len() / (grid * grid);
            let texcs = if solid {
                let step = |k: usize| k as f32 / (grid as f32 - 1.0);
                let one: Vec<f32> = (0..grid * grid)
                    .flat_map(|k| [step(k / grid), step(k % grid)])
                    .collect();
                one.repeat(patches)
            } else {
                Vec::new()
            };
            let idx = if solid {
                triangles(patches, grid)
            } else {
                strips(patches, grid)
            };
            *cache = Some(Built {
                scale: size,
                mesh,
                texcs,
                idx,
            });
        }
    }
    let b = cache.as_ref().expect("built above");
    if solid {
        draw::solid(&b.mesh, Some(&b.texcs), Some(&b.idx), 1);
    } else {
        draw::wire(&b.mesh, Some(&b.idx), grid, GL_LINE_STRIP, &[], 0);
    }
}

macro_rules! tea_set {
    ($($(#[$doc:meta])* $name:ident, $obj:expr, $solid:expr, $div:expr;)*) => {$(
        $(#[$doc])*
        #[no_mangle]
        pub extern "C" fn $name(size: f64) {
            static CACHE: Mutex<Option<Built>> = Mutex::new(None);
            draw(&$obj, &CACHE, size as f32 / $div, $solid);
        }
    )*};
}

tea_set! {
    /// `glutSolidTeapot`: the Utah teapot, `size` about half its height.
    glutSolidTeapot, TEAPOT, true, 1.0;
    /// `glutWireTeapot`.
    glutWireTeapot, TEAPOT, false, 1.0;
    /// `glutSolidTeacup` (freeglut): a teacup to go with a teapot of the same size.
    glutSolidTeacup, TEACUP, true, 2.5;
    /// `glutWireTeacup` (freeglut).
    glutWireTeacup, TEACUP, false, 2.5;
    /// `glutSolidTeaspoon` (freeglut): a teaspoon to go with a teapot of the same size.
    glutSolidTeaspoon, TEASPOON, true, 2.5;
    /// `glutWireTeaspoon` (freeglut).
    glutWireTeaspoon, TEASPOON, false, 2.5;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_and_outward_body_normals() {
        let m = evaluate(&TEAPOT, SOLID_GRID, 1.0);
        // 6 patches turned to four quadrants, 4 mirrored once.
        assert_eq!(m.len(), (6 * 4 + 4 * 2) * SOLID_GRID * SOLID_GRID);
        // The body patches (1 and 2, all quadrants): normals point away from the y axis.
        let per = SOLID_GRID * SOLID_GRID;
        for copy in 0..4 {
            let start = (4 + copy) * per;
            for k in start..start + per {
                let (v, n) = (&m.verts[3 * k..3 * k + 3], &m.norms[3 * k..3 * k + 3]);
                assert!(v[0] * n[0] + v[2] * n[2] > 0.0, "{v:?} {n:?}");
            }
        }
        assert_eq!(triangles(32, SOLID_GRID).len(), 32 * 49 * 6);
        assert_eq!(strips(32, WIRE_GRID).len(), 32 * 100 * 2);
    }

    #[test]
    fn teacup_and_teaspoon_are_finite_and_sized() {
        for (obj, patches) in [(&TEACUP, 6 * 4 + 2), (&TEASPOON, 16)] {
            let m = evaluate(obj, WIRE_GRID, 1.0);
            assert_eq!(m.len(), patches * WIRE_GRID * WIRE_GRID);
            assert!(m.verts.iter().all(|c| c.is_finite() && c.abs() < 2.0));
        }
    }
}
