//! The GL and OSMesa functions this library calls, declared without naming a library.
//!
//! `libsoftglut.so` is linked with these symbols undefined; the loader binds them to
//! whichever GL the program is linked with (`-lsoftgl` or Mesa's `-lOSMesa`), so the
//! same GLUT/GLU code runs on both. Functions a GL may lack (glBitmap) are looked up
//! at run time with `OSMesaGetProcAddress` instead, so linking never fails on them.

#![allow(non_snake_case, missing_docs)]

use std::ffi::{c_char, c_void};

pub type GLenum = u32;
pub type GLint = i32;
pub type GLsizei = i32;
pub type GLfloat = f32;
pub type GLdouble = f64;
pub type GLboolean = u8;
pub type GLubyte = u8;

pub const GL_POINTS: GLenum = 0x0000;
pub const GL_LINES: GLenum = 0x0001;
pub const GL_LINE_LOOP: GLenum = 0x0002;
pub const GL_LINE_STRIP: GLenum = 0x0003;
pub const GL_TRIANGLES: GLenum = 0x0004;
pub const GL_TRIANGLE_STRIP: GLenum = 0x0005;
pub const GL_TRIANGLE_FAN: GLenum = 0x0006;
pub const GL_QUADS: GLenum = 0x0007;
pub const GL_QUAD_STRIP: GLenum = 0x0008;
pub const GL_POLYGON: GLenum = 0x0009;
pub const GL_BYTE: GLenum = 0x1400;
pub const GL_UNSIGNED_BYTE: GLenum = 0x1401;
pub const GL_SHORT: GLenum = 0x1402;
pub const GL_UNSIGNED_SHORT: GLenum = 0x1403;
pub const GL_INT: GLenum = 0x1404;
pub const GL_UNSIGNED_INT: GLenum = 0x1405;
pub const GL_FLOAT: GLenum = 0x1406;
pub const GL_RGBA: GLenum = 0x1908;
pub const GL_TEXTURE_1D: GLenum = 0x0DE0;
pub const GL_TEXTURE_2D: GLenum = 0x0DE1;
pub const GL_MAX_TEXTURE_SIZE: GLenum = 0x0D33;
pub const GL_UNPACK_ROW_LENGTH: GLenum = 0x0CF2;
pub const GL_UNPACK_SKIP_ROWS: GLenum = 0x0CF3;
pub const GL_UNPACK_SKIP_PIXELS: GLenum = 0x0CF4;
pub const GL_UNPACK_ALIGNMENT: GLenum = 0x0CF5;
pub const GL_PACK_ROW_LENGTH: GLenum = 0x0D02;
pub const GL_PACK_SKIP_ROWS: GLenum = 0x0D03;
pub const GL_PACK_SKIP_PIXELS: GLenum = 0x0D04;
pub const GL_PACK_ALIGNMENT: GLenum = 0x0D05;
pub const GL_MODELVIEW_MATRIX: GLenum = 0x0BA6;
pub const GL_PROJECTION_MATRIX: GLenum = 0x0BA7;
pub const GL_VIEWPORT: GLenum = 0x0BA2;
pub const GL_EXTENSIONS: GLenum = 0x1F03;

pub const OSMESA_RGBA: GLenum = GL_RGBA;

/// `OSMesaContext`.
pub type OsMesaContext = *mut c_void;
/// `OSMESAproc`.
pub type OsMesaProc = Option<unsafe extern "C" fn()>;

extern "C" {
    pub fn OSMesaCreateContextExt(
        format: GLenum,
        depth_bits: GLint,
        stencil_bits: GLint,
        accum_bits: GLint,
        sharelist: OsMesaContext,
    ) -> OsMesaContext;
    pub fn OSMesaMakeCurrent(
        ctx: OsMesaContext,
        buffer: *mut c_void,
        ty: GLenum,
        width: GLsizei,
        height: GLsizei,
    ) -> GLboolean;
    pub fn OSMesaDestroyContext(ctx: OsMesaContext);
    pub fn OSMesaGetCurrentContext() -> OsMesaContext;
    pub fn OSMesaGetProcAddress(name: *const c_char) -> OsMesaProc;

    pub fn glBegin(mode: GLenum);
    pub fn glEnd();
    pub fn glVertex2f(x: GLfloat, y: GLfloat);
    pub fn glVertex3f(x: GLfloat, y: GLfloat, z: GLfloat);
    pub fn glNormal3f(x: GLfloat, y: GLfloat, z: GLfloat);
    pub fn glTexCoord2f(s: GLfloat, t: GLfloat);
    pub fn glPushMatrix();
    pub fn glPopMatrix();
    pub fn glTranslatef(x: GLfloat, y: GLfloat, z: GLfloat);
    pub fn glScalef(x: GLfloat, y: GLfloat, z: GLfloat);
    pub fn glMultMatrixd(m: *const GLdouble);
    pub fn glMultMatrixf(m: *const GLfloat);
    pub fn glOrtho(l: GLdouble, r: GLdouble, b: GLdouble, t: GLdouble, n: GLdouble, f: GLdouble);
    pub fn glViewport(x: GLint, y: GLint, w: GLsizei, h: GLsizei);
    pub fn glFinish();
    pub fn glEnable(cap: GLenum);
    pub fn glIsEnabled(cap: GLenum) -> GLboolean;
    pub fn glPushAttrib(mask: u32);
    pub fn glPopAttrib();
    pub fn glGetFloatv(pname: GLenum, params: *mut GLfloat);
    pub fn glMap1f(
        target: GLenum,
        u1: GLfloat,
        u2: GLfloat,
        stride: GLint,
        order: GLint,
        p: *const GLfloat,
    );
    pub fn glMap2f(
        target: GLenum,
        u1: GLfloat,
        u2: GLfloat,
        ustride: GLint,
        uorder: GLint,
        v1: GLfloat,
        v2: GLfloat,
        vstride: GLint,
        vorder: GLint,
        p: *const GLfloat,
    );
    pub fn glMapGrid1f(n: GLint, u1: GLfloat, u2: GLfloat);
    pub fn glMapGrid2f(nu: GLint, u1: GLfloat, u2: GLfloat, nv: GLint, v1: GLfloat, v2: GLfloat);
    pub fn glEvalMesh1(mode: GLenum, i1: GLint, i2: GLint);
    pub fn glEvalMesh2(mode: GLenum, i1: GLint, i2: GLint, j1: GLint, j2: GLint);
    pub fn glEvalCoord2f(u: GLfloat, v: GLfloat);
    pub fn glEvalCoord1f(u: GLfloat);
    pub fn glPolygonMode(face: GLenum, mode: GLenum);
    pub fn glGetString(name: GLenum) -> *const GLubyte;
    pub fn glGetIntegerv(pname: GLenum, params: *mut GLint);
    pub fn glPixelStorei(pname: GLenum, param: GLint);
    pub fn glTexImage1D(
        target: GLenum,
        level: GLint,
        internal: GLint,
        width: GLsizei,
        border: GLint,
        format: GLenum,
        ty: GLenum,
        pixels: *const c_void,
    );
    pub fn glTexImage2D(
        target: GLenum,
        level: GLint,
        internal: GLint,
        width: GLsizei,
        height: GLsizei,
        border: GLint,
        format: GLenum,
        ty: GLenum,
        pixels: *const c_void,
    );
}

/// `glBitmap`'s signature.
pub type BitmapFn = unsafe extern "C" fn(
    width: GLsizei,
    height: GLsizei,
    xorig: GLfloat,
    yorig: GLfloat,
    xmove: GLfloat,
    ymove: GLfloat,
    bitmap: *const GLubyte,
);

/// `glBitmap` of the current GL, or `None` when it does not provide one.
pub fn bitmap_fn() -> Option<BitmapFn> {
    // SAFETY: the name is a NUL-terminated literal; OSMesaGetProcAddress only reads it.
    let p = unsafe { OSMesaGetProcAddress(c"glBitmap".as_ptr()) };
    // SAFETY: a non-null result for "glBitmap" is that GL's glBitmap, whose C signature
    // is BitmapFn; function pointers of both types have the same representation.
    p.map(|f| unsafe { std::mem::transmute::<unsafe extern "C" fn(), BitmapFn>(f) })
}

/// One `glGetIntegerv` value.
pub fn get_int(pname: GLenum) -> GLint {
    let mut v = [0 as GLint; 4];
    // SAFETY: four ints is enough for every single-valued pname used here.
    unsafe { glGetIntegerv(pname, v.as_mut_ptr()) };
    v[0]
}

/// The unpack (or pack) parameters in effect: alignment, row length, skip rows/pixels.
#[derive(Clone, Copy, Debug)]
pub struct PixelStore {
    /// Row alignment in bytes.
    pub alignment: GLint,
    /// Row length in pixels (0 = the image width).
    pub row_length: GLint,
    /// Rows skipped.
    pub skip_rows: GLint,
    /// Pixels skipped at the start of each row.
    pub skip_pixels: GLint,
}

impl PixelStore {
    /// The current unpack parameters.
    pub fn unpack() -> Self {
        PixelStore {
            alignment: get_int(GL_UNPACK_ALIGNMENT),
            row_length: get_int(GL_UNPACK_ROW_LENGTH),
            skip_rows: get_int(GL_UNPACK_SKIP_ROWS),
            skip_pixels: get_int(GL_UNPACK_SKIP_PIXELS),
        }
    }

    /// The current pack parameters.
    pub fn pack() -> Self {
        PixelStore {
            alignment: get_int(GL_PACK_ALIGNMENT),
            row_length: get_int(GL_PACK_ROW_LENGTH),
            skip_rows: get_int(GL_PACK_SKIP_ROWS),
            skip_pixels: get_int(GL_PACK_SKIP_PIXELS),
        }
    }

    /// Sets the unpack parameters.
    pub fn set_unpack(self) {
        // SAFETY: plain GL state calls with integer arguments.
        unsafe {
            glPixelStorei(GL_UNPACK_ALIGNMENT, self.alignment);
            glPixelStorei(GL_UNPACK_ROW_LENGTH, self.row_length);
            glPixelStorei(GL_UNPACK_SKIP_ROWS, self.skip_rows);
            glPixelStorei(GL_UNPACK_SKIP_PIXELS, self.skip_pixels);
        }
    }

    /// Tightly packed rows (alignment 1, no skips).
    pub const TIGHT: PixelStore = PixelStore {
        alignment: 1,
        row_length: 0,
        skip_rows: 0,
        skip_pixels: 0,
    };
}

/// Immediate-mode helpers (thin safe wrappers; the GL calls have no pointer arguments).
pub mod im {
    use super::*;

    /// `glBegin`.
    pub fn begin(mode: GLenum) {
        // SAFETY: no pointer arguments.
        unsafe { glBegin(mode) }
    }
    /// `glEnd`.
    pub fn end() {
        // SAFETY: no arguments.
        unsafe { glEnd() }
    }
    /// `glVertex3f`.
    pub fn v3(p: [f32; 3]) {
        // SAFETY: no pointer arguments.
        unsafe { glVertex3f(p[0], p[1], p[2]) }
    }
    /// `glVertex2f`.
    pub fn v2(x: f32, y: f32) {
        // SAFETY: no pointer arguments.
        unsafe { glVertex2f(x, y) }
    }
    /// `glNormal3f`.
    pub fn n3(n: [f32; 3]) {
        // SAFETY: no pointer arguments.
        unsafe { glNormal3f(n[0], n[1], n[2]) }
    }
    /// `glTexCoord2f`.
    pub fn t2(s: f32, t: f32) {
        // SAFETY: no pointer arguments.
        unsafe { glTexCoord2f(s, t) }
    }
    /// `glPushMatrix`.
    pub fn push() {
        // SAFETY: no arguments.
        unsafe { glPushMatrix() }
    }
    /// `glPopMatrix`.
    pub fn pop() {
        // SAFETY: no arguments.
        unsafe { glPopMatrix() }
    }
    /// `glTranslatef`.
    pub fn translate(x: f32, y: f32, z: f32) {
        // SAFETY: no pointer arguments.
        unsafe { glTranslatef(x, y, z) }
    }
    /// `glScalef`.
    pub fn scale(x: f32, y: f32, z: f32) {
        // SAFETY: no pointer arguments.
        unsafe { glScalef(x, y, z) }
    }
    /// `glMultMatrixf` of a column-major matrix.
    pub fn mult_f32(m: &[f32; 16]) {
        // SAFETY: m points to 16 floats.
        unsafe { glMultMatrixf(m.as_ptr()) }
    }
    /// `glMultMatrixd` of a column-major matrix.
    pub fn mult(m: &[f64; 16]) {
        // SAFETY: m points to 16 doubles.
        unsafe { glMultMatrixd(m.as_ptr()) }
    }
}
