//! The C boundary: `#[no_mangle] extern "C"` functions with the exact names and types of
//! Mesa's `GL/gl.h`, `GL/glext.h` and `GL/osmesa.h`, and nothing else.
//!
//! Every GL function finds the thread's current context, converts its raw arguments into
//! Rust values (`CompareFunc::from_gl(e)?`), calls a safe context method and records a GL
//! error when that fails. No panic crosses this line: [`with_ctx`] catches unwinding and
//! reports GL_OUT_OF_MEMORY instead. A GL call without a current context does nothing.
//!
//! The headers in `include/GL` are generated from these files by cbindgen
//! (`cargo run --example gen_headers`); a test fails when they are stale.

pub mod aliases_ext;
pub mod aliases_gl;
pub mod arrays;
pub mod buffers;
pub mod draw;
pub mod enums;
pub mod fragment;
pub mod fragment_ext;
pub mod glext_enums;
pub mod immediate;
pub mod lighting;
pub mod lighting_ext;
pub mod matrix;
pub mod multidraw;
pub mod osmesa;
pub mod proc_table;
pub mod query;
pub mod state;
pub mod textures;
pub mod textures_ext;
pub mod types;

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
/// without a context or on error.
#[inline]
pub(crate) fn with_ctx<R: Default>(f: impl FnOnce(&mut Context) -> GlResult<R>) -> R {
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
    match catch_unwind(AssertUnwindSafe(|| f(ctx))) {
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
    Some(with_ctx(|c| Ok(c.stats)))
}
