//! Feedback and selection (gl.h): glRenderMode, glFeedbackBuffer, glSelectBuffer,
//! glPassThrough and the name stack. glRenderMode and the two buffer calls execute at
//! once inside glNewList (GL 1.5 §5.4); the others are compiled.
#![allow(non_snake_case)]

use super::types::*;
use super::{with_ctx, with_ctx_list};

/// glRenderMode: returns the number of hit records (GL_SELECT) or feedback values
/// (GL_FEEDBACK) of the mode being left, -1 when they overflowed the buffer, 0 otherwise.
#[no_mangle]
pub extern "C" fn glRenderMode(mode: GLenum) -> GLint {
    with_ctx(|c| c.feedback.render_mode(mode))
}

/// glFeedbackBuffer: `size` floats at `buffer` receive feedback values.
#[no_mangle]
pub extern "C" fn glFeedbackBuffer(size: GLsizei, type_: GLenum, buffer: *mut GLfloat) {
    let buffer = buffer as usize;
    with_ctx(|c| c.feedback.feedback_buffer(size, type_, buffer))
}

/// glSelectBuffer: `size` unsigned integers at `buffer` receive hit records.
#[no_mangle]
pub extern "C" fn glSelectBuffer(size: GLsizei, buffer: *mut GLuint) {
    let buffer = buffer as usize;
    with_ctx(|c| c.feedback.select_buffer(size, buffer))
}

/// glPassThrough: a GL_PASS_THROUGH_TOKEN and `token` in feedback mode.
#[no_mangle]
pub extern "C" fn glPassThrough(token: GLfloat) {
    with_ctx_list(move |c| {
        c.feedback.pass_through(token);
        Ok(())
    })
}

/// glInitNames: empties the name stack (selection mode only).
#[no_mangle]
pub extern "C" fn glInitNames() {
    with_ctx_list(|c| {
        c.feedback.init_names();
        Ok(())
    })
}

/// glLoadName: replaces the top of the name stack (selection mode only).
#[no_mangle]
pub extern "C" fn glLoadName(name: GLuint) {
    with_ctx_list(move |c| c.feedback.load_name(name))
}

/// glPushName: pushes a name (selection mode only; GL_STACK_OVERFLOW past 64).
#[no_mangle]
pub extern "C" fn glPushName(name: GLuint) {
    with_ctx_list(move |c| c.feedback.push_name(name))
}

/// glPopName: pops a name (selection mode only; GL_STACK_UNDERFLOW when empty).
#[no_mangle]
pub extern "C" fn glPopName() {
    with_ctx_list(|c| c.feedback.pop_name())
}
