//! The C boundary: `#[no_mangle] extern "C"` functions with the exact names and types of
//! Mesa's `GL/gl.h`, `GL/glext.h` and `GL/osmesa.h`, and nothing else.
//!
//! Every GL function finds the thread's current context, converts its raw arguments into
//! Rust values (`CompareFunc::from_gl(e)?`), calls a safe context method and records a GL
//! error when that fails. No panic crosses this line: [`with_ctx`] catches unwinding and
//! reports GL_OUT_OF_MEMORY instead. A GL call without a current context does nothing.
//!
//! Which wrapper a GL function uses decides how it behaves inside glNewList/glEndList:
//! - [`with_ctx_list`] for every command GL 1.5 §5.4 lets a display list record (state
//!   changes, matrix calls, glClear, glCallList, glPushAttrib …). Its closure must be
//!   `Fn + Send + Sync + 'static` and capture only owned, already-read argument values:
//!   read every pointer argument (vectors, matrices, images) into an owned value *before*
//!   the closure. While a list is compiled the boxed closure is stored in the list (and also
//!   run for GL_COMPILE_AND_EXECUTE); otherwise it runs at once. Validation belongs inside
//!   the closure, so errors are generated when the list executes, as GL and Mesa do.
//! - [`with_ctx_vertex`] for the per-vertex commands (glBegin/glEnd, glVertex, glColor,
//!   glNormal, glTexCoord …), given as a [`VertexOp`]: lists store them inline as vertex
//!   nodes, replayed as Mesa replays its vertex nodes.
//! - [`with_ctx`] for commands that always execute immediately, even while compiling
//!   (glGen*/glDelete*/glIs*, glGet*, glReadPixels, glPixelStore, client array state,
//!   glFlush/glFinish, buffer objects, glFeedbackBuffer/glSelectBuffer/glRenderMode);
//!   [`with_ctx_raw`] only where the deferred immediate-mode batch must not be drawn first.
//!
//! The wrappers also enforce the glBegin/glEnd rule (GL 1.5 §2.6.3), so no entry point
//! checks it itself: between glBegin and glEnd only the per-vertex commands, glMaterial,
//! glEvalCoord/glEvalPoint, glArrayElement and glCallList(s) may run. Every other command is
//! GL_INVALID_OPERATION, changes nothing and returns 0, before any argument is looked at,
//! as Mesa's dispatch table for the inside of glBegin/glEnd does (glGetError and glIsEnabled
//! included). [`with_ctx`] and [`with_ctx_list`] refuse there; the allowed listable
//! commands use [`with_ctx_list_anywhere`], OSMesa's own functions [`with_ctx_anywhere`].
//! A command compiled into a display list keeps the rule: it fails when the list runs
//! inside glBegin/glEnd, and compiled between a glBegin and glEnd of the list itself it is
//! compiled as the error (Mesa's `_mesa_compile_error`).
//!
//! The headers in `include/GL` are generated from these files by cbindgen
//! (`cargo run --example gen_headers`); a test fails when they are stale.

pub mod accum;
pub mod aliases_ext;
pub mod aliases_gl;
pub mod arrays;
pub mod arrays_ext;
pub mod arrays_gl14;
pub mod buffers;
pub mod draw;
pub use crate::gl::enums;
pub mod eval;
mod families;
pub mod feedback;
pub mod fragment;
pub mod fragment_ext;
pub mod framebuffers;
pub use crate::gl::glext_enums;
pub mod immediate;
pub mod legacy;
pub mod lighting;
pub mod lighting_ext;
pub mod lists;
pub mod matrix;
pub mod multidraw;
pub mod osmesa;
pub mod pixels;
pub mod pixels_draw;
pub mod pixels_ext;
pub mod points;
pub mod proc_table;
pub mod queries;
pub mod query;
pub mod rasterization;
pub mod shaders;
pub mod shaders_arb;
pub mod shaders_uniform;
pub mod state;
pub mod texgen;
pub mod textures;
pub mod textures_3d;
pub mod textures_compressed;
pub mod textures_ext;
pub mod transform_ext;
pub mod vertex_attrib;
pub mod vertex_attrib_int;
pub mod vertex_input;
pub use crate::gl::types;

use crate::context::dlist::VertexOp;
use crate::context::{Context, GlError, GlResult};
use std::cell::Cell;
use std::panic::{catch_unwind, AssertUnwindSafe};

thread_local! {
    /// The context current on this thread (null when none).
    static CURRENT: Cell<*mut Context> = const { Cell::new(std::ptr::null_mut()) };
}

/// Sets the thread's current context pointer.
pub(crate) fn set_current(ctx: *mut Context) {
    CURRENT.with(|c| c.set(ctx));
}

/// The thread's current context pointer (null when none).
pub(crate) fn current() -> *mut Context {
    CURRENT.with(|c| c.get())
}

/// Runs `f` on the current context after drawing any deferred glBegin/glEnd batch;
/// records its error, and turns a panic into GL_OUT_OF_MEMORY. Returns `R::default()`
/// without a context or on error, and between glBegin and glEnd (GL_INVALID_OPERATION).
#[inline]
pub(crate) fn with_ctx<R: Default>(f: impl FnOnce(&mut Context) -> GlResult<R>) -> R {
    with_ctx_raw(|c| {
        c.outside_begin_end()?;
        c.flush_pending();
        f(c)
    })
}

/// As [`with_ctx`] for the client-state calls that only change bindings or array
/// pointers (glBindBuffer, gl*Pointer, glEnableClientState …): a draw's batch left drawing
/// on the pool stays there ([`Context::flush_pending_keep`]), since it holds every vertex
/// it draws and reads no buffer object or client array.
#[inline]
pub(crate) fn with_ctx_keep<R: Default>(f: impl FnOnce(&mut Context) -> GlResult<R>) -> R {
    with_ctx_raw(|c| {
        c.outside_begin_end()?;
        c.flush_pending_keep();
        f(c)
    })
}

/// As [`with_ctx`] but allowed between glBegin and glEnd: for OSMesa's own functions,
/// which are not GL commands.
#[inline]
pub(crate) fn with_ctx_anywhere<R: Default>(f: impl FnOnce(&mut Context) -> GlResult<R>) -> R {
    with_ctx_raw(|c| {
        c.flush_pending();
        f(c)
    })
}

/// As [`with_ctx`] but without flushing the deferred batch: for glBegin and the vertex
/// attribute calls, which Mesa records into the same vertex buffer.
#[inline]
pub(crate) fn with_ctx_raw<R: Default>(f: impl FnOnce(&mut Context) -> GlResult<R>) -> R {
    let p = current();
    if p.is_null() {
        return R::default();
    }
    // SAFETY: CURRENT only holds a pointer set by OSMesaMakeCurrent on this thread; that
    // context is claimed by this thread (no other thread can make it current) and is not
    // freed while current here (OSMesaDestroyContext unbinds it first). GL calls never
    // re-enter the library, so this is the only live reference.
    let ctx = unsafe { &mut *p };
    let r = catch_unwind(AssertUnwindSafe(|| f(ctx)));
    ctx.fbo_refresh();
    match r {
        Ok(Ok(r)) => r,
        Ok(Err(e)) => {
            ctx.record_error(e);
            R::default()
        }
        Err(_) => {
            ctx.record_error(GlError::OutOfMemory);
            R::default()
        }
    }
}

/// Runs a listable command: records `f` into the display list being compiled (running it
/// too under GL_COMPILE_AND_EXECUTE), or runs it now as [`with_ctx`] does. See the module
/// documentation for what `f` may capture, and for the glBegin/glEnd rule it applies.
#[inline]
pub(crate) fn with_ctx_list<F>(f: F)
where
    F: Fn(&mut Context) -> GlResult<()> + Send + Sync + 'static,
{
    listable(f, false, false)
}

/// As [`with_ctx_list`] for the state calls that touch neither a framebuffer nor a
/// texture image, a buffer object or a display list, and read nothing a draw on the pool
/// writes: the matrices, texgen and clip planes, glEnable/glDisable, lights, materials and
/// fog, the fragment tests, blending and masks, the rasterization modes, viewport and
/// scissor, texture bindings and environments, glCallList. A draw's batch left drawing on
/// the pool stays there ([`Context::flush_pending_keep`]), so the next draw goes on
/// overlapping it: the batch owns copies of everything it draws with (its fragment plan,
/// its unit plans), and the texture images those borrow are only changed by calls that
/// wait for it. Inside a display list such a call keeps the same rule.
#[inline]
pub(crate) fn with_ctx_list_keep<F>(f: F)
where
    F: Fn(&mut Context) -> GlResult<()> + Send + Sync + 'static,
{
    listable(f, false, true)
}

/// [`with_ctx_list_keep`] for the keeping calls allowed between glBegin and glEnd
/// (glMaterial, glCallList(s)).
#[inline]
pub(crate) fn with_ctx_list_anywhere_keep<F>(f: F)
where
    F: Fn(&mut Context) -> GlResult<()> + Send + Sync + 'static,
{
    listable(f, true, true)
}

/// Whether the current context is compiling a display list (for the commands Mesa
/// compiles differently from how it runs them).
pub(crate) fn compiling_list() -> bool {
    with_ctx_raw(|c| Ok(c.lists.compile_mode().is_some()))
}

/// As [`with_ctx_list`] for the listable commands allowed between glBegin and glEnd
/// (glMaterial, glEvalCoord, glEvalPoint, glCallList(s)).
#[inline]
pub(crate) fn with_ctx_list_anywhere<F>(f: F)
where
    F: Fn(&mut Context) -> GlResult<()> + Send + Sync + 'static,
{
    listable(f, true, false)
}

/// The body of [`with_ctx_list`] (`anywhere` false), [`with_ctx_list_anywhere`],
/// [`with_ctx_list_keep`] and [`with_ctx_list_anywhere_keep`] (`keep`: the draws on the
/// pool are not waited for).
#[inline]
fn listable<F>(f: F, anywhere: bool, keep: bool)
where
    F: Fn(&mut Context) -> GlResult<()> + Send + Sync + 'static,
{
    with_ctx_raw(|c| match c.lists.compile_mode() {
        None => {
            if !anywhere {
                c.outside_begin_end()?;
            }
            if keep {
                c.flush_pending_keep();
            } else {
                c.flush_pending();
            }
            f(c)
        }
        Some(execute) => {
            if !anywhere && c.lists.compiling_inside_begin() {
                // Compiled as its error, raised now too under GL_COMPILE_AND_EXECUTE.
                c.lists
                    .push_call(Box::new(|_| Err(GlError::InvalidOperation)));
                return if execute {
                    Err(GlError::InvalidOperation)
                } else {
                    Ok(())
                };
            }
            let r = if execute {
                c.flush_pending();
                f(c)
            } else {
                Ok(())
            };
            if anywhere {
                c.lists.push_call_as(Box::new(f), keep);
            } else {
                c.lists.push_call_as(
                    Box::new(move |c: &mut Context| {
                        c.outside_begin_end()?;
                        f(c)
                    }),
                    keep,
                );
            }
            r
        }
    })
}

/// Runs a per-vertex command: records it into the vertex node of the display list being
/// compiled (running it too under GL_COMPILE_AND_EXECUTE), or runs it now without drawing
/// the deferred batch first.
#[inline]
pub(crate) fn with_ctx_vertex(op: VertexOp) {
    with_ctx_raw(|c| c.vertex_command(op))
}

/// Converts a C GLboolean.
#[inline]
pub(crate) fn gl_bool(b: types::GLboolean) -> bool {
    b != 0
}

/// Fails with GL_INVALID_VALUE on a negative count or size.
#[inline]
pub(crate) fn non_negative(n: i32) -> GlResult<usize> {
    usize::try_from(n).map_err(|_| GlError::InvalidValue)
}

/// The work counters of the thread's current context, after drawing any deferred
/// immediate-mode batch (a Rust-side API for tests and tools; not exported to C).
pub fn current_stats() -> Option<crate::stats::Stats> {
    let p = current();
    if p.is_null() {
        return None;
    }
    Some(with_ctx_anywhere(|c| Ok(c.stats)))
}

/// Reading and writing client memory at the C boundary: pointer arguments read into owned
/// values, results written through out pointers, and the client images that a display
/// list copies when it compiles a command.
pub(crate) mod client {
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
        if p.is_null() {
            return None;
        }
        // SAFETY: forwarded caller contract.
        let v = unsafe { read_vec(p, n) };
        Some(v.into_iter().map(Into::into).collect())
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
                if unpack.buffer == 0 {
                    return f(c, pixels, unpack);
                }
                // An unpack buffer: the image is a copy of its bytes at offset `pixels`;
                // arguments that describe no image fail in the command, on a null pointer.
                let Some(n) = image_span(dims, format_type, &unpack, size) else {
                    return f(c, std::ptr::null(), unpack);
                };
                let bytes = c.unpack_source(pixels, Some(format_type.1), n)?;
                let p = bytes
                    .as_ref()
                    .map_or(pixels, |b| b.as_ptr() as *const c_void);
                f(c, p, unpack)
            });
        }
        let unpack = with_ctx_raw(|c| Ok(c.state.unpack));
        let span = (unpack.buffer != 0 || !pixels.is_null())
            .then(|| image_span(dims, format_type, &unpack, size))
            .flatten();
        let bytes = match span {
            // An unpack buffer is read when the list is compiled, as client memory is.
            Some(n) if unpack.buffer != 0 => {
                match with_ctx_raw(|c| c.unpack_source(pixels, Some(format_type.1), n).map(Some)) {
                    Some(b) => b,
                    None => return,
                }
            }
            // SAFETY: the caller promises the described image, `span` bytes, is readable.
            Some(n) => Some(unsafe { read_vec(pixels as *const u8, n) }),
            None => None,
        };
        with_ctx_list(move |c| {
            let p = bytes
                .as_ref()
                .map_or(std::ptr::null(), |b| b.as_ptr() as *const c_void);
            f(c, p, unpack)
        })
    }

    /// The bytes an unpacking command decoded at the C boundary reads from the unpack
    /// buffer ([`Context::unpack_source`]): `Some(None)` when none is bound (read the client
    /// pointer), `Some(Some(copy))` when one is, `None` when its checks failed (the error is
    /// recorded; the command must do nothing) or there is no context.
    pub(crate) fn unpack_buffer_bytes(
        pixels: *const c_void,
        ty: Option<GLenum>,
        span: usize,
    ) -> Option<Option<Vec<u8>>> {
        with_ctx_raw(|c| c.unpack_source(pixels, ty, span).map(Some))
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
}
