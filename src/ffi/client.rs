//! Reading and writing client memory at the C boundary: pointer arguments read into owned
//! values, results written through out pointers, and the client images that a display
//! list copies when it compiles a command.

use super::{compiling_list, with_ctx, with_ctx_list, with_ctx_raw};
use crate::context::client_image::image_span;
use crate::context::state::PixelStore;
use crate::context::{Context, GlResult};
use crate::gl::types::*;
use libc::c_void;

/// The `n` values at `p` (empty when `p` is null).
///
/// # Safety
/// `p`, when not null, must be readable for `n` values.
#[inline]
pub(crate) unsafe fn read_vec<T: Copy>(p: *const T, n: usize) -> Vec<T> {
    if p.is_null() {
        return Vec::new();
    }
    // SAFETY: the caller promises `n` readable values at the non-null `p`.
    unsafe { std::slice::from_raw_parts(p, n) }.to_vec()
}

/// The `n` values at `p` converted to `f64` (the float and integer vector forms of a
/// parameter call), `None` when `p` is null.
///
/// # Safety
/// `p`, when not null, must be readable for `n` values.
#[inline]
pub(crate) unsafe fn read_f64<T: Copy + Into<f64>>(p: *const T, n: usize) -> Option<Vec<f64>> {
    // SAFETY: forwarded caller contract.
    (!p.is_null()).then(|| {
        unsafe { read_vec(p, n) }
            .into_iter()
            .map(Into::into)
            .collect()
    })
}

/// Writes `vals`, each converted by `f`, to `dst` (nothing when `dst` is null).
///
/// # Safety
/// `dst`, when not null, must be writable for `vals.len()` values.
#[inline]
pub(crate) unsafe fn write_all<S: Copy, T>(dst: *mut T, vals: &[S], f: impl Fn(S) -> T) {
    if dst.is_null() {
        return;
    }
    for (i, &v) in vals.iter().enumerate() {
        // SAFETY: the caller promises room for every value.
        unsafe { dst.add(i).write_unaligned(f(v)) };
    }
}

/// Writes `v` to `dst` (nothing when `dst` is null).
///
/// # Safety
/// `dst`, when not null, must be writable.
#[inline]
pub(crate) unsafe fn write_one<T>(dst: *mut T, v: T) {
    if !dst.is_null() {
        // SAFETY: checked non-null; the caller promises it is writable.
        unsafe { dst.write_unaligned(v) };
    }
}

/// Runs a texture image command on `pixels`. While a display list is compiled the image
/// the unpack state describes is copied now, and the list records `f` on the copy with
/// that unpack state (run too under GL_COMPILE_AND_EXECUTE); otherwise `f` runs at once on
/// `pixels` with the current unpack state. `dims` and `size` (`w, h, d`) say how much
/// client memory the image spans ([`image_span`]).
///
/// # Safety
/// `pixels`, when not null, must hold the image the arguments and unpack state describe.
pub(crate) unsafe fn image_command<F>(
    dims: u8,
    format_type: (GLenum, GLenum),
    size: (GLsizei, GLsizei, GLsizei),
    pixels: *const c_void,
    f: F,
) where
    F: Fn(&mut Context, *const c_void, PixelStore) -> GlResult<()> + Send + Sync + 'static,
{
    if !compiling_list() {
        return with_ctx(|c| {
            let unpack = c.state.unpack;
            f(c, pixels, unpack)
        });
    }
    let unpack = with_ctx_raw(|c| Ok(c.state.unpack));
    let span = (!pixels.is_null())
        .then(|| image_span(dims, format_type, &unpack, size))
        .flatten();
    // SAFETY: the caller promises the described image, `span` bytes, is readable.
    let bytes = span.map(|n| unsafe { read_vec(pixels as *const u8, n) });
    with_ctx_list(move |c| {
        let p = bytes
            .as_ref()
            .map_or(std::ptr::null(), |b| b.as_ptr() as *const c_void);
        f(c, p, unpack)
    })
}

/// The `(a[i], b[i])` pairs of a multi-draw call's two arrays: GL_INVALID_VALUE for a
/// negative `n`, no pairs when either array is null.
///
/// # Safety
/// `a` and `b`, when not null, must be readable for `n` values each.
pub(crate) unsafe fn read_pairs<A: Copy, B: Copy>(
    a: *const A,
    b: *const B,
    n: GLsizei,
) -> GlResult<Vec<(A, B)>> {
    let n = super::non_negative(n)?;
    if a.is_null() || b.is_null() {
        return Ok(Vec::new());
    }
    // SAFETY: forwarded caller contract.
    let (a, b) = unsafe { (read_vec(a, n), read_vec(b, n)) };
    Ok(a.into_iter().zip(b).collect())
}
