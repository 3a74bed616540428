//! The glUniform families at the C boundary: glUniform{1,2,3,4}{f,i}[v],
//! glUniformMatrix{2,3,4}fv, GL 2.1's non-square glUniformMatrix{C}x{R}fv, and
//! glGetUniform{f,i}v. The checks and the storage are
//! [`crate::context::Context::set_uniform`]'s; the values of a vector form are read only
//! once the call is known to be valid, and no more than the uniform holds.
//!
//! glUniform runs at once even while a display list is compiled (GL 2.0 lists it; softgl
//! does not record it yet).
#![allow(non_snake_case)]

use super::client::{read_vec, write_all};
use super::families::c_fns;
use super::types::*;
use super::{with_ctx, with_ctx_keep};
use crate::context::uniforms::UniformShape;

/// A uniform's 32-bit word from a value of a glUniform call.
trait Word: Copy {
    /// The word (a float's bits, an integer's two's complement).
    fn word(self) -> u32;
}

impl Word for GLfloat {
    fn word(self) -> u32 {
        self.to_bits()
    }
}

impl Word for GLint {
    fn word(self) -> u32 {
        self as u32
    }
}

/// The scalar forms: one element of the given words. Like every glUniform, it leaves a
/// draw's batch drawing on the pool (`with_ctx_keep`): a batch holds its own copy of the
/// uniform values (`ShaderRef::uniforms`), and a vertex shader has run before its draw
/// returned.
fn scalars(location: GLint, shape: UniformShape, words: &[u32]) {
    with_ctx_keep(|c| {
        c.set_uniform(location, 1, shape, &|n| {
            words[..n.min(words.len())].to_vec()
        })
    })
}

/// The vector and matrix forms: `count` elements at `value`.
///
/// # Safety
/// `value` null or readable for `count` elements of the shape.
unsafe fn vectors<T: Word>(location: GLint, count: GLsizei, shape: UniformShape, value: *const T) {
    with_ctx_keep(|c| {
        c.set_uniform(location, count, shape, &|n| {
            // SAFETY: `n` never exceeds `count` elements, the values the caller promises.
            unsafe { read_vec(value, n) }
                .into_iter()
                .map(Word::word)
                .collect()
        })
    })
}

/// glGetUniform{f,i}v.
///
/// # Safety
/// `params` null or writable for the uniform element's components.
unsafe fn get<T>(program: GLuint, location: GLint, params: *mut T, int: bool, conv: fn(f64) -> T) {
    with_ctx(|c| {
        let v = c.get_uniform(program, location, int)?;
        // SAFETY: forwarded caller contract.
        unsafe { write_all(params, &v, conv) };
        Ok(())
    })
}

c_fns! {
    safe fn glUniform1f(location: GLint, v0: GLfloat) => scalars(location, UniformShape::Vector { n: 1, int: false }, &[v0.to_bits()]);
    unsafe fn glUniform1fv(location: GLint, count: GLsizei, value: *const GLfloat) => vectors(location, count, UniformShape::Vector { n: 1, int: false }, value);
    safe fn glUniform1i(location: GLint, v0: GLint) => scalars(location, UniformShape::Vector { n: 1, int: true }, &[v0 as u32]);
    unsafe fn glUniform1iv(location: GLint, count: GLsizei, value: *const GLint) => vectors(location, count, UniformShape::Vector { n: 1, int: true }, value);
    safe fn glUniform2f(location: GLint, v0: GLfloat, v1: GLfloat) => scalars(location, UniformShape::Vector { n: 2, int: false }, &[v0.to_bits(), v1.to_bits()]);
    unsafe fn glUniform2fv(location: GLint, count: GLsizei, value: *const GLfloat) => vectors(location, count, UniformShape::Vector { n: 2, int: false }, value);
    safe fn glUniform2i(location: GLint, v0: GLint, v1: GLint) => scalars(location, UniformShape::Vector { n: 2, int: true }, &[v0 as u32, v1 as u32]);
    unsafe fn glUniform2iv(location: GLint, count: GLsizei, value: *const GLint) => vectors(location, count, UniformShape::Vector { n: 2, int: true }, value);
    safe fn glUniform3f(location: GLint, v0: GLfloat, v1: GLfloat, v2: GLfloat) => scalars(location, UniformShape::Vector { n: 3, int: false }, &[v0.to_bits(), v1.to_bits(), v2.to_bits()]);
    unsafe fn glUniform3fv(location: GLint, count: GLsizei, value: *const GLfloat) => vectors(location, count, UniformShape::Vector { n: 3, int: false }, value);
    safe fn glUniform3i(location: GLint, v0: GLint, v1: GLint, v2: GLint) => scalars(location, UniformShape::Vector { n: 3, int: true }, &[v0 as u32, v1 as u32, v2 as u32]);
    unsafe fn glUniform3iv(location: GLint, count: GLsizei, value: *const GLint) => vectors(location, count, UniformShape::Vector { n: 3, int: true }, value);
    safe fn glUniform4f(location: GLint, v0: GLfloat, v1: GLfloat, v2: GLfloat, v3: GLfloat) => scalars(location, UniformShape::Vector { n: 4, int: false }, &[v0.to_bits(), v1.to_bits(), v2.to_bits(), v3.to_bits()]);
    unsafe fn glUniform4fv(location: GLint, count: GLsizei, value: *const GLfloat) => vectors(location, count, UniformShape::Vector { n: 4, int: false }, value);
    safe fn glUniform4i(location: GLint, v0: GLint, v1: GLint, v2: GLint, v3: GLint) => scalars(location, UniformShape::Vector { n: 4, int: true }, &[v0 as u32, v1 as u32, v2 as u32, v3 as u32]);
    unsafe fn glUniform4iv(location: GLint, count: GLsizei, value: *const GLint) => vectors(location, count, UniformShape::Vector { n: 4, int: true }, value);
    unsafe fn glUniformMatrix2fv(location: GLint, count: GLsizei, transpose: GLboolean, value: *const GLfloat) => vectors(location, count, UniformShape::Matrix { cols: 2, rows: 2, transpose: transpose != 0 }, value);
    unsafe fn glUniformMatrix2x3fv(location: GLint, count: GLsizei, transpose: GLboolean, value: *const GLfloat) => vectors(location, count, UniformShape::Matrix { cols: 2, rows: 3, transpose: transpose != 0 }, value);
    unsafe fn glUniformMatrix2x4fv(location: GLint, count: GLsizei, transpose: GLboolean, value: *const GLfloat) => vectors(location, count, UniformShape::Matrix { cols: 2, rows: 4, transpose: transpose != 0 }, value);
    unsafe fn glUniformMatrix3x2fv(location: GLint, count: GLsizei, transpose: GLboolean, value: *const GLfloat) => vectors(location, count, UniformShape::Matrix { cols: 3, rows: 2, transpose: transpose != 0 }, value);
    unsafe fn glUniformMatrix3fv(location: GLint, count: GLsizei, transpose: GLboolean, value: *const GLfloat) => vectors(location, count, UniformShape::Matrix { cols: 3, rows: 3, transpose: transpose != 0 }, value);
    unsafe fn glUniformMatrix3x4fv(location: GLint, count: GLsizei, transpose: GLboolean, value: *const GLfloat) => vectors(location, count, UniformShape::Matrix { cols: 3, rows: 4, transpose: transpose != 0 }, value);
    unsafe fn glUniformMatrix4x2fv(location: GLint, count: GLsizei, transpose: GLboolean, value: *const GLfloat) => vectors(location, count, UniformShape::Matrix { cols: 4, rows: 2, transpose: transpose != 0 }, value);
    unsafe fn glUniformMatrix4x3fv(location: GLint, count: GLsizei, transpose: GLboolean, value: *const GLfloat) => vectors(location, count, UniformShape::Matrix { cols: 4, rows: 3, transpose: transpose != 0 }, value);
    unsafe fn glUniformMatrix4fv(location: GLint, count: GLsizei, transpose: GLboolean, value: *const GLfloat) => vectors(location, count, UniformShape::Matrix { cols: 4, rows: 4, transpose: transpose != 0 }, value);
    unsafe fn glGetUniformfv(program: GLuint, location: GLint, params: *mut GLfloat) => get(program, location, params, false, |v| v as GLfloat);
    unsafe fn glGetUniformiv(program: GLuint, location: GLint, params: *mut GLint) => get(program, location, params, true, |v| v as GLint);
}
