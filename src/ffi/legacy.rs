//! GL 1.0–1.5 entry points of the little-used state: colour-index state (glIndex*,
//! glIndexMask, glClearIndex), which an RGBA context keeps without drawing with it;
//! glSampleCoverage (used by 4x multisample framebuffer objects); glDrawBuffer/glReadBuffer
//! (of the window, or of the bound framebuffer object); and the ARB_imaging subset, which
//! Mesa does not implement (each call is GL_INVALID_OPERATION there, and here).
#![allow(non_snake_case)]

use super::families::c_fns;
use super::types::*;
use super::{with_ctx, with_ctx_list, with_ctx_vertex};
use crate::context::dlist::VertexOp;
use crate::context::error::GlError;

/// Sets the current colour index (allowed between glBegin and glEnd).
fn index(i: f32) {
    with_ctx_vertex(VertexOp::Index(i))
}

/// Reads one value from a `glIndex*v` pointer (nothing for null).
///
/// # Safety
/// `p` must be null or point to one readable value.
unsafe fn read1<T: Copy>(p: *const T) -> Option<T> {
    // SAFETY: the caller promises one readable value behind a non-null pointer.
    (!p.is_null()).then(|| unsafe { p.read_unaligned() })
}

c_fns! {
    safe fn glIndexd(c: GLdouble) => index(c as f32);
    safe fn glIndexf(c: GLfloat) => index(c);
    safe fn glIndexi(c: GLint) => index(c as f32);
    safe fn glIndexs(c: GLshort) => index(c as f32);
    safe fn glIndexub(c: GLubyte) => index(c as f32);
    unsafe fn glIndexdv(c: *const GLdouble) => if let Some(v) = read1(c) { index(v as f32) };
    unsafe fn glIndexfv(c: *const GLfloat) => if let Some(v) = read1(c) { index(v) };
    unsafe fn glIndexiv(c: *const GLint) => if let Some(v) = read1(c) { index(v as f32) };
    unsafe fn glIndexsv(c: *const GLshort) => if let Some(v) = read1(c) { index(v as f32) };
    unsafe fn glIndexubv(c: *const GLubyte) => if let Some(v) = read1(c) { index(v as f32) };
}

/// glIndexMask (GL_INDEX_WRITEMASK; an RGBA context writes no indices).
#[no_mangle]
pub extern "C" fn glIndexMask(mask: GLuint) {
    with_ctx_list(move |c| {
        c.state.legacy.index_mask = mask;
        Ok(())
    })
}

/// glClearIndex (GL_INDEX_CLEAR_VALUE; an RGBA context clears no indices).
#[no_mangle]
pub extern "C" fn glClearIndex(c: GLfloat) {
    with_ctx_list(move |ctx| {
        ctx.state.legacy.set_clear_index(c);
        Ok(())
    })
}

/// glSampleCoverage: stored, and applied when drawing into a 4x multisample object.
#[no_mangle]
pub extern "C" fn glSampleCoverage(value: GLfloat, invert: GLboolean) {
    with_ctx_list(move |c| {
        c.state.legacy.set_sample_coverage(value, invert != 0);
        Ok(())
    })
}

/// glDrawBuffer: GL_NONE turns colour writes off; every name of the single front-left
/// buffer (front, back, left, front-and-back) draws into it, as Mesa's OSMesa does.
#[no_mangle]
pub extern "C" fn glDrawBuffer(mode: GLenum) {
    with_ctx_list(move |c| c.draw_buffer(mode))
}

/// glReadBuffer: GL_NONE makes colour reads GL_INVALID_OPERATION.
#[no_mangle]
pub extern "C" fn glReadBuffer(mode: GLenum) {
    with_ctx_list(move |c| c.read_buffer(mode))
}

/// An ARB_imaging call: Mesa has no imaging subset, so its dispatch reports
/// GL_INVALID_OPERATION and does nothing (not even compiling into a display list).
fn imaging_unsupported() {
    with_ctx(|_| Err::<(), _>(GlError::InvalidOperation))
}

// The ARB_imaging entry points: unsupported (GL_INVALID_OPERATION, as in Mesa).
c_fns! {
    safe fn glColorTable(_target: GLenum, _internalformat: GLenum, _width: GLsizei, _format: GLenum, _type_: GLenum, _table: *const GLvoid) => imaging_unsupported();
    safe fn glColorSubTable(_target: GLenum, _start: GLsizei, _count: GLsizei, _format: GLenum, _type_: GLenum, _data: *const GLvoid) => imaging_unsupported();
    safe fn glColorTableParameterfv(_target: GLenum, _pname: GLenum, _params: *const GLfloat) => imaging_unsupported();
    safe fn glColorTableParameteriv(_target: GLenum, _pname: GLenum, _params: *const GLint) => imaging_unsupported();
    safe fn glCopyColorTable(_target: GLenum, _internalformat: GLenum, _x: GLint, _y: GLint, _width: GLsizei) => imaging_unsupported();
    safe fn glCopyColorSubTable(_target: GLenum, _start: GLsizei, _x: GLint, _y: GLint, _width: GLsizei) => imaging_unsupported();
    safe fn glGetColorTable(_target: GLenum, _format: GLenum, _type_: GLenum, _table: *mut GLvoid) => imaging_unsupported();
    safe fn glGetColorTableParameterfv(_target: GLenum, _pname: GLenum, _params: *mut GLfloat) => imaging_unsupported();
    safe fn glGetColorTableParameteriv(_target: GLenum, _pname: GLenum, _params: *mut GLint) => imaging_unsupported();
    safe fn glConvolutionFilter1D(_target: GLenum, _internalformat: GLenum, _width: GLsizei, _format: GLenum, _type_: GLenum, _image: *const GLvoid) => imaging_unsupported();
    safe fn glConvolutionFilter2D(_target: GLenum, _internalformat: GLenum, _width: GLsizei, _height: GLsizei, _format: GLenum, _type_: GLenum, _image: *const GLvoid) => imaging_unsupported();
    safe fn glConvolutionParameterf(_target: GLenum, _pname: GLenum, _params: GLfloat) => imaging_unsupported();
    safe fn glConvolutionParameterfv(_target: GLenum, _pname: GLenum, _params: *const GLfloat) => imaging_unsupported();
    safe fn glConvolutionParameteri(_target: GLenum, _pname: GLenum, _params: GLint) => imaging_unsupported();
    safe fn glConvolutionParameteriv(_target: GLenum, _pname: GLenum, _params: *const GLint) => imaging_unsupported();
    safe fn glCopyConvolutionFilter1D(_target: GLenum, _internalformat: GLenum, _x: GLint, _y: GLint, _width: GLsizei) => imaging_unsupported();
    safe fn glCopyConvolutionFilter2D(_target: GLenum, _internalformat: GLenum, _x: GLint, _y: GLint, _width: GLsizei, _height: GLsizei) => imaging_unsupported();
    safe fn glGetConvolutionFilter(_target: GLenum, _format: GLenum, _type_: GLenum, _image: *mut GLvoid) => imaging_unsupported();
    safe fn glGetConvolutionParameterfv(_target: GLenum, _pname: GLenum, _params: *mut GLfloat) => imaging_unsupported();
    safe fn glGetConvolutionParameteriv(_target: GLenum, _pname: GLenum, _params: *mut GLint) => imaging_unsupported();
    safe fn glSeparableFilter2D(_target: GLenum, _internalformat: GLenum, _width: GLsizei, _height: GLsizei, _format: GLenum, _type_: GLenum, _row: *const GLvoid, _column: *const GLvoid) => imaging_unsupported();
    safe fn glGetSeparableFilter(_target: GLenum, _format: GLenum, _type_: GLenum, _row: *mut GLvoid, _column: *mut GLvoid, _span: *mut GLvoid) => imaging_unsupported();
    safe fn glHistogram(_target: GLenum, _width: GLsizei, _internalformat: GLenum, _sink: GLboolean) => imaging_unsupported();
    safe fn glGetHistogram(_target: GLenum, _reset: GLboolean, _format: GLenum, _type_: GLenum, _values: *mut GLvoid) => imaging_unsupported();
    safe fn glGetHistogramParameterfv(_target: GLenum, _pname: GLenum, _params: *mut GLfloat) => imaging_unsupported();
    safe fn glGetHistogramParameteriv(_target: GLenum, _pname: GLenum, _params: *mut GLint) => imaging_unsupported();
    safe fn glResetHistogram(_target: GLenum) => imaging_unsupported();
    safe fn glMinmax(_target: GLenum, _internalformat: GLenum, _sink: GLboolean) => imaging_unsupported();
    safe fn glGetMinmax(_target: GLenum, _reset: GLboolean, _format: GLenum, _types: GLenum, _values: *mut GLvoid) => imaging_unsupported();
    safe fn glGetMinmaxParameterfv(_target: GLenum, _pname: GLenum, _params: *mut GLfloat) => imaging_unsupported();
    safe fn glGetMinmaxParameteriv(_target: GLenum, _pname: GLenum, _params: *mut GLint) => imaging_unsupported();
    safe fn glResetMinmax(_target: GLenum) => imaging_unsupported();
}
