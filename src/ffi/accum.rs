//! The accumulation buffer (gl.h): glAccum and glClearAccum.
#![allow(non_snake_case)]

use super::enums::*;
use super::types::*;
use super::with_ctx_list;
use crate::context::accum::AccumOp;
use crate::context::error::GlError;

/// glAccum (GL_INVALID_OPERATION without an accumulation buffer).
#[no_mangle]
pub extern "C" fn glAccum(op: GLenum, value: GLfloat) {
    with_ctx_list(move |c| {
        let op = match op {
            GL_ACCUM => AccumOp::Accum,
            GL_LOAD => AccumOp::Load,
            GL_RETURN => AccumOp::Return,
            GL_MULT => AccumOp::Mult,
            GL_ADD => AccumOp::Add,
            _ => return Err(GlError::InvalidEnum),
        };
        c.accum(op, value)
    })
}

/// glClearAccum (values clamped to [-1, 1]).
#[no_mangle]
pub extern "C" fn glClearAccum(red: GLfloat, green: GLfloat, blue: GLfloat, alpha: GLfloat) {
    with_ctx_list(move |c| c.clear_accum([red, green, blue, alpha]))
}
