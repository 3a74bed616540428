//! GLUT's solid and wire shapes, built as freeglut 3.4 builds them so that a program
//! draws the same pixels with softglut as with freeglut: the same vertex positions
//! and normals (single precision, from the same closed forms and sine tables), the
//! same faces and strips in the same order, drawn with the same vertex-array calls.
//!
//! [`round`] has the sphere, cone, cylinder and torus, [`polyhedra`] the Platonic
//! solids, the rhombic dodecahedron and the Sierpinski sponge, [`draw`] the GL calls.

#![allow(non_snake_case)]

pub mod draw;
pub mod polyhedra;
pub mod round;

use polyhedra::Solid;

macro_rules! solid_pair {
    ($(#[$doc:meta] $solid:ident, $wire:ident, $shape:path;)*) => {$(
        #[$doc]
        #[no_mangle]
        pub extern "C" fn $solid() {
            $shape().draw(1.0, true);
        }
        #[$doc]
        #[no_mangle]
        pub extern "C" fn $wire() {
            $shape().draw(1.0, false);
        }
    )*};
}

solid_pair! {
    /// Tetrahedron of radius 1 centred at the origin, a vertex on +x.
    glutSolidTetrahedron, glutWireTetrahedron, polyhedra::tetrahedron;
    /// Octahedron of radius 1, vertices on the axes.
    glutSolidOctahedron, glutWireOctahedron, polyhedra::octahedron;
    /// Icosahedron of radius 1, vertices on ±x.
    glutSolidIcosahedron, glutWireIcosahedron, polyhedra::icosahedron;
    /// Dodecahedron of radius √3.
    glutSolidDodecahedron, glutWireDodecahedron, polyhedra::dodecahedron;
    /// Rhombic dodecahedron (freeglut), radius 1, vertices on ±z.
    glutSolidRhombicDodecahedron, glutWireRhombicDodecahedron, polyhedra::rhombic_dodecahedron;
}

/// The cube of edge `size` (converted to single precision first).
fn cube(size: f64, solid: bool) {
    Solid::draw(&polyhedra::cube(), size as f32, solid);
}

/// `glutSolidCube`: a cube of edge `size` centred at the origin.
#[no_mangle]
pub extern "C" fn glutSolidCube(size: f64) {
    cube(size, true);
}

/// `glutWireCube`.
#[no_mangle]
pub extern "C" fn glutWireCube(size: f64) {
    cube(size, false);
}

/// `glutSolidSphere`: `slices` around the z axis, `stacks` from +z to -z.
#[no_mangle]
pub extern "C" fn glutSolidSphere(radius: f64, slices: i32, stacks: i32) {
    round::sphere(radius as f32, slices, stacks, true);
}

/// `glutWireSphere`: the latitude circles and the meridians.
#[no_mangle]
pub extern "C" fn glutWireSphere(radius: f64, slices: i32, stacks: i32) {
    round::sphere(radius as f32, slices, stacks, false);
}

/// `glutSolidCone`: base of radius `base` on z = 0, apex at z = `height`.
#[no_mangle]
pub extern "C" fn glutSolidCone(base: f64, height: f64, slices: i32, stacks: i32) {
    round::cone(base as f32, height as f32, slices, stacks, true);
}

/// `glutWireCone`: the stack circles and lines from the base to the apex.
#[no_mangle]
pub extern "C" fn glutWireCone(base: f64, height: f64, slices: i32, stacks: i32) {
    round::cone(base as f32, height as f32, slices, stacks, false);
}

/// `glutSolidCylinder` (freeglut): radius, z from 0 to `height`, with end caps.
#[no_mangle]
pub extern "C" fn glutSolidCylinder(radius: f64, height: f64, slices: i32, stacks: i32) {
    round::cylinder(radius as f32, height as f32, slices, stacks, true);
}

/// `glutWireCylinder` (freeglut).
#[no_mangle]
pub extern "C" fn glutWireCylinder(radius: f64, height: f64, slices: i32, stacks: i32) {
    round::cylinder(radius as f32, height as f32, slices, stacks, false);
}

/// `glutSolidTorus`: a tube of radius `inner` around a circle of radius `outer` in
/// the z = 0 plane.
#[no_mangle]
pub extern "C" fn glutSolidTorus(inner: f64, outer: f64, sides: i32, rings: i32) {
    round::torus(inner as f32, outer as f32, sides, rings, true);
}

/// `glutWireTorus`: the tube circles and the ring circles.
#[no_mangle]
pub extern "C" fn glutWireTorus(inner: f64, outer: f64, sides: i32, rings: i32) {
    round::torus(inner as f32, outer as f32, sides, rings, false);
}

/// Reads the sponge's offset: three doubles, or the origin for NULL.
fn sponge_offset(offset: *const f64) -> [f64; 3] {
    if offset.is_null() {
        return [0.0; 3];
    }
    // SAFETY: the caller passes an array of three doubles (GLUT's contract); NULL was
    // handled above.
    unsafe { [*offset, *offset.add(1), *offset.add(2)] }
}

/// `glutSolidSierpinskiSponge` (freeglut): `levels` levels of tetrahedra of radius
/// `scale` around `offset` (three doubles).
#[no_mangle]
pub extern "C" fn glutSolidSierpinskiSponge(levels: i32, offset: *const f64, scale: f64) {
    polyhedra::sponge(levels, sponge_offset(offset), scale as f32, true);
}

/// `glutWireSierpinskiSponge` (freeglut).
#[no_mangle]
pub extern "C" fn glutWireSierpinskiSponge(levels: i32, offset: *const f64, scale: f64) {
    polyhedra::sponge(levels, sponge_offset(offset), scale as f32, false);
}
