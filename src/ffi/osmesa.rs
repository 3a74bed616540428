//! The OSMesa API (`GL/osmesa.h`): contexts, binding a user buffer, and reading it back.
//!
//! A context handle is a heap object registered in a process-wide list, so a stale or
//! foreign handle is rejected instead of dereferenced. A context is claimed by the thread
//! that makes it current; another thread cannot make it current until it is released.

#![allow(non_camel_case_types, non_snake_case)]

use super::client::write_one;
use super::enums::*;
use super::families::c_fns;
use super::types::*;
use crate::context::share::ShareGroup;
use crate::context::{Context, GlError, GlResult, Visual};
use crate::framebuffer::{ColorFormat, DepthFormat};
use libc::{c_char, c_int, c_void};
use std::cell::{Cell, UnsafeCell};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;

/// OSMESA_COLOR_INDEX
pub const OSMESA_COLOR_INDEX: GLenum = GL_COLOR_INDEX;
/// OSMESA_RGBA
pub const OSMESA_RGBA: GLenum = GL_RGBA;
/// OSMESA_BGRA
pub const OSMESA_BGRA: GLenum = 0x1;
/// OSMESA_ARGB
pub const OSMESA_ARGB: GLenum = 0x2;
/// OSMESA_RGB
pub const OSMESA_RGB: GLenum = GL_RGB;
/// OSMESA_BGR
pub const OSMESA_BGR: GLenum = 0x4;
/// OSMESA_RGB_565
pub const OSMESA_RGB_565: GLenum = 0x5;
/// OSMESA_ROW_LENGTH
pub const OSMESA_ROW_LENGTH: c_int = 0x10;
/// OSMESA_Y_UP
pub const OSMESA_Y_UP: c_int = 0x11;
/// OSMESA_WIDTH
pub const OSMESA_WIDTH: c_int = 0x20;
/// OSMESA_HEIGHT
pub const OSMESA_HEIGHT: c_int = 0x21;
/// OSMESA_FORMAT
pub const OSMESA_FORMAT: c_int = 0x22;
/// OSMESA_TYPE
pub const OSMESA_TYPE: c_int = 0x23;
/// OSMESA_MAX_WIDTH
pub const OSMESA_MAX_WIDTH: c_int = 0x24;
/// OSMESA_MAX_HEIGHT
pub const OSMESA_MAX_HEIGHT: c_int = 0x25;
/// OSMESA_DEPTH_BITS
pub const OSMESA_DEPTH_BITS: c_int = 0x30;
/// OSMESA_STENCIL_BITS
pub const OSMESA_STENCIL_BITS: c_int = 0x31;
/// OSMESA_ACCUM_BITS
pub const OSMESA_ACCUM_BITS: c_int = 0x32;
/// OSMESA_PROFILE
pub const OSMESA_PROFILE: c_int = 0x33;
/// OSMESA_CORE_PROFILE
pub const OSMESA_CORE_PROFILE: c_int = 0x34;
/// OSMESA_COMPAT_PROFILE
pub const OSMESA_COMPAT_PROFILE: c_int = 0x35;
/// OSMESA_CONTEXT_MAJOR_VERSION
pub const OSMESA_CONTEXT_MAJOR_VERSION: c_int = 0x36;
/// OSMESA_CONTEXT_MINOR_VERSION
pub const OSMESA_CONTEXT_MINOR_VERSION: c_int = 0x37;
/// OSMESA_MAJOR_VERSION (the OSMesa API version we mirror)
pub const OSMESA_MAJOR_VERSION: c_int = 11;
/// OSMESA_MINOR_VERSION
pub const OSMESA_MINOR_VERSION: c_int = 2;
/// OSMESA_PATCH_VERSION
pub const OSMESA_PATCH_VERSION: c_int = 0;

/// The largest buffer side OSMesa accepts (llvmpipe's 16384).
const MAX_SIZE: GLsizei = 16384;

/// Set in `owner` by OSMesaDestroyContext: the thread that has the context current frees
/// it when it lets go (or the destroyer does, when no thread had it).
const ORPHAN: u64 = 1 << 63;

/// An OSMesa context (opaque to C).
pub struct osmesa_context {
    /// The thread id (see [`thread_id`]) that has it current, or 0; plus [`ORPHAN`].
    owner: AtomicU64,
    /// The GL context.
    ctx: UnsafeCell<Context>,
    /// The colour format requested at creation (OSMESA_RGBA …).
    format: GLenum,
    /// The share group (texture and buffer objects), shared with the `sharelist` context.
    group: ShareGroup,
}

/// The handle type of `GL/osmesa.h`.
pub type OSMesaContext = *mut osmesa_context;

/// The function-pointer type OSMesaGetProcAddress returns.
pub type OSMESAproc = Option<unsafe extern "C" fn()>;

/// Live context handles, so that stale handles are rejected.
static LIVE: Mutex<Vec<usize>> = Mutex::new(Vec::new());

thread_local! {
    static CURRENT_HANDLE: Cell<OSMesaContext> = const { Cell::new(std::ptr::null_mut()) };
    static THREAD_ID: u64 = {
        static NEXT: AtomicU64 = AtomicU64::new(1);
        NEXT.fetch_add(1, Ordering::Relaxed)
    };
}

/// A small non-zero id of the calling thread.
fn thread_id() -> u64 {
    THREAD_ID.with(|t| *t)
}

fn is_live(c: OSMesaContext) -> bool {
    !c.is_null()
        && LIVE
            .lock()
            .map(|l| l.contains(&(c as usize)))
            .unwrap_or(false)
}

/// The colour layout Mesa picks for a format/type pair at OSMesaMakeCurrent
/// (`osmesa_choose_format`), `None` for pairs it rejects. 16-bit and float buffers are
/// R16G16B16A16 / R32G32B32A32 (or their RGB forms) whatever the channel order asked for.
fn color_format(format: GLenum, ty: GLenum) -> Option<ColorFormat> {
    let wide = matches!(ty, GL_UNSIGNED_SHORT | GL_FLOAT);
    match (format, ty) {
        (OSMESA_RGBA, GL_UNSIGNED_BYTE) => Some(ColorFormat::Rgba),
        (OSMESA_BGRA, GL_UNSIGNED_BYTE) => Some(ColorFormat::Bgra),
        (OSMESA_ARGB, GL_UNSIGNED_BYTE) => Some(ColorFormat::Argb),
        (OSMESA_RGBA | OSMESA_BGRA | OSMESA_ARGB, _) if wide => Some(ColorFormat::Rgba),
        (OSMESA_RGB, GL_UNSIGNED_BYTE) => Some(ColorFormat::Rgb),
        (OSMESA_RGB, _) if wide => Some(ColorFormat::Rgb),
        (OSMESA_RGB_565, GL_UNSIGNED_SHORT_5_6_5) => Some(ColorFormat::Rgb565),
        _ => None,
    }
}

/// The 8-bit type of a format (its layout before the first OSMesaMakeCurrent).
fn default_type(format: GLenum) -> GLenum {
    if format == OSMESA_RGB_565 {
        GL_UNSIGNED_SHORT_5_6_5
    } else {
        GL_UNSIGNED_BYTE
    }
}

/// `f()`, or `fallback` when it panics (no panic crosses the C boundary).
fn no_panic<R>(fallback: R, f: impl FnOnce() -> R) -> R {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)).unwrap_or(fallback)
}

/// Creates a context from parsed attributes (Mesa's `OSMesaCreateContextAttribs` rules).
fn create(
    format: GLenum,
    depth: c_int,
    stencil: c_int,
    accum: c_int,
    sharelist: OSMesaContext,
) -> OSMesaContext {
    if depth < 0 || stencil < 0 || accum < 0 {
        return std::ptr::null_mut();
    }
    if !matches!(
        format,
        OSMESA_RGBA
            | OSMESA_BGRA
            | OSMESA_ARGB
            | OSMESA_RGB
            | OSMESA_RGB_565
            | OSMESA_BGR
            | OSMESA_COLOR_INDEX
    ) {
        return std::ptr::null_mut();
    }
    let depth_format = if depth > 0 && stencil > 0 || depth >= 24 {
        DepthFormat::Z24
    } else if depth >= 16 {
        DepthFormat::Z16
    } else {
        DepthFormat::None
    };
    let visual = Visual {
        format: color_format(format, default_type(format)).unwrap_or(ColorFormat::Rgba),
        depth: depth_format,
        stencil: stencil > 0,
        accum_bits: accum,
    };
    let Ok(mut live) = LIVE.lock() else {
        return std::ptr::null_mut();
    };
    let group = if live.contains(&(sharelist as usize)) {
        // SAFETY: registered in LIVE, which we hold locked, so it is not freed meanwhile.
        unsafe { &*sharelist }.group.clone()
    } else {
        ShareGroup::default()
    };
    let c = Box::into_raw(Box::new(osmesa_context {
        owner: AtomicU64::new(0),
        ctx: UnsafeCell::new(Context::new(visual)),
        format,
        group,
    }));
    live.push(c as usize);
    c
}

/// OSMesaCreateContext: `Ext(format, 24, 8, 0, sharelist)`.
#[no_mangle]
pub extern "C" fn OSMesaCreateContext(format: GLenum, sharelist: OSMesaContext) -> OSMesaContext {
    OSMesaCreateContextExt(format, 24, 8, 0, sharelist)
}

/// OSMesaCreateContextExt: a context with the given depth, stencil and accumulation bits.
#[no_mangle]
pub extern "C" fn OSMesaCreateContextExt(
    format: GLenum,
    depthBits: GLint,
    stencilBits: GLint,
    accumBits: GLint,
    sharelist: OSMesaContext,
) -> OSMesaContext {
    let make = || create(format, depthBits, stencilBits, accumBits, sharelist);
    no_panic(std::ptr::null_mut(), make)
}

/// The format, depth, stencil and accumulation bits of an OSMesaCreateContextAttribs
/// list; `None` for an unknown key, a core profile or a version above 2.1 (softgl
/// implements the GL 2.1 compatibility profile).
///
/// # Safety
/// `list` must be NULL or point to a zero-terminated list of int pairs.
unsafe fn parse_attribs(list: *const c_int) -> Option<(GLenum, c_int, c_int, c_int)> {
    let (mut format, mut depth, mut stencil, mut accum) = (OSMESA_RGBA, 0, 0, 0);
    let (mut major, mut minor) = (1, 0);
    if list.is_null() {
        return Some((format, depth, stencil, accum));
    }
    let mut i = 0usize;
    loop {
        // SAFETY: the list is zero-terminated (caller contract); we stop at the key 0.
        let key = unsafe { *list.add(i) };
        if key == 0 {
            break;
        }
        // SAFETY: every non-zero key is followed by its value.
        let val = unsafe { *list.add(i + 1) };
        match key {
            OSMESA_FORMAT => format = val as GLenum,
            OSMESA_DEPTH_BITS => depth = val,
            OSMESA_STENCIL_BITS => stencil = val,
            OSMESA_ACCUM_BITS => accum = val,
            OSMESA_PROFILE if val == OSMESA_COMPAT_PROFILE => {}
            OSMESA_CONTEXT_MAJOR_VERSION => major = val,
            OSMESA_CONTEXT_MINOR_VERSION => minor = val,
            _ => return None,
        }
        i += 2;
    }
    ((major, minor) <= (2, 1)).then_some((format, depth, stencil, accum))
}

/// OSMesaCreateContextAttribs: a zero-terminated key/value list. softgl implements the GL
/// 2.1 compatibility profile, so a core profile or a version above 2.1 gives NULL.
///
/// # Safety
/// `attribList` must be NULL or point to a zero-terminated list of int pairs.
#[no_mangle]
pub unsafe extern "C" fn OSMesaCreateContextAttribs(
    attribList: *const c_int,
    sharelist: OSMesaContext,
) -> OSMesaContext {
    // SAFETY: forwarded caller contract.
    match unsafe { parse_attribs(attribList) } {
        Some((format, depth, stencil, accum)) => {
            OSMesaCreateContextExt(format, depth, stencil, accum, sharelist)
        }
        None => std::ptr::null_mut(),
    }
}

/// Unregisters `ctx` and frees it, unless another thread has it current (that thread
/// frees it when it lets go).
fn destroy(ctx: OSMesaContext) {
    let Ok(mut live) = LIVE.lock() else { return };
    let Some(pos) = live.iter().position(|&p| p == ctx as usize) else {
        return;
    };
    live.swap_remove(pos);
    drop(live);
    // SAFETY: `ctx` was registered in LIVE, so it is a valid, not yet freed context (only
    // this call, which removed it, or its owner after ORPHAN is set, frees it).
    let c = unsafe { &*ctx };
    if CURRENT_HANDLE.with(|h| h.get()) == ctx {
        flush_current();
        // SAFETY: current on this thread, so this thread has the only reference.
        c.group.check_in(unsafe { &mut *c.ctx.get() });
        CURRENT_HANDLE.with(|h| h.set(std::ptr::null_mut()));
        super::set_current(std::ptr::null_mut());
        c.owner.store(0, Ordering::Release);
    }
    // Claims (made under the LIVE lock) are over; if another thread has it current,
    // that thread frees it when it lets go. Do not touch `c` after this otherwise.
    if c.owner.fetch_or(ORPHAN, Ordering::AcqRel) == 0 {
        if crate::tuning::tuning().stats {
            // The knobs in effect, once per process, before the first counters.
            static TUNING_SHOWN: std::sync::Once = std::sync::Once::new();
            TUNING_SHOWN.call_once(|| {
                eprintln!(
                    "softgl tuning (instruction set in effect: {}):\n{}",
                    crate::cpu::level().name(),
                    crate::tuning::tuning().report().trim_end()
                );
            });
            // SAFETY: no thread has this context current (checked above).
            eprintln!("softgl stats:\n{}", unsafe { &*c.ctx.get() }.stats.report());
            eprintln!("{}", crate::engine::cache::report());
        }
        // SAFETY: unregistered above and current on no thread: nobody else can reach it.
        drop(unsafe { Box::from_raw(ctx) });
    }
}

/// OSMesaDestroyContext. A context current on another thread is not freed (that would
/// leave the other thread a dangling context); it is only unregistered.
#[no_mangle]
pub extern "C" fn OSMesaDestroyContext(ctx: OSMesaContext) {
    no_panic((), || destroy(ctx))
}

/// OSMesaMakeCurrent: binds `ctx` to this thread and `buffer` as its colour buffer.
/// `(NULL, NULL, …)` unbinds. Returns GL_FALSE for bad arguments, an unsupported
/// format/type pair, or a context current on another thread.
///
/// # Safety
/// `buffer` must hold `width * height` pixels of the context's format and `type`
/// (or OSMESA_ROW_LENGTH rows), and stay valid while the context draws into it.
#[no_mangle]
pub unsafe extern "C" fn OSMesaMakeCurrent(
    ctx: OSMesaContext,
    buffer: *mut c_void,
    type_: GLenum,
    width: GLsizei,
    height: GLsizei,
) -> GLboolean {
    no_panic(GL_FALSE as GLboolean, || {
        make_current(ctx, buffer, type_, width, height)
    })
}

/// Draws the deferred immediate-mode batch of the context current on this thread.
fn flush_current() {
    let p = super::current();
    if !p.is_null() {
        let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            // SAFETY: the current context is live and owned by this thread.
            unsafe { &mut *p }.flush_pending()
        }));
    }
}

/// Gives up this thread's claim on `h` (current here), freeing it when
/// OSMesaDestroyContext was called for it meanwhile from another thread.
fn let_go(h: OSMesaContext) {
    // SAFETY: a handle current on this thread is not freed by anyone else (destroy on
    // another thread only sets ORPHAN), and only this thread uses its context.
    let c = unsafe { &*h };
    // SAFETY: as above: this thread holds the only reference to the GL context.
    c.group.check_in(unsafe { &mut *c.ctx.get() });
    let prev = c.owner.swap(0, Ordering::AcqRel);
    if prev & ORPHAN != 0 {
        // SAFETY: unregistered (ORPHAN is set after removal from LIVE) and no longer
        // current anywhere: this thread holds the last reference.
        drop(unsafe { Box::from_raw(h) });
    }
}

fn release_current() {
    flush_current();
    let old = CURRENT_HANDLE.with(|h| h.get());
    if !old.is_null() {
        let_go(old);
    }
    CURRENT_HANDLE.with(|h| h.set(std::ptr::null_mut()));
    super::set_current(std::ptr::null_mut());
}

fn make_current(
    ctx: OSMesaContext,
    buffer: *mut c_void,
    type_: GLenum,
    width: GLsizei,
    height: GLsizei,
) -> GLboolean {
    const FALSE: GLboolean = GL_FALSE as GLboolean;
    if ctx.is_null() && buffer.is_null() {
        release_current();
        return GL_TRUE as GLboolean;
    }
    if buffer.is_null() || width < 1 || height < 1 || width > MAX_SIZE || height > MAX_SIZE {
        return FALSE;
    }
    let me = thread_id();
    let prev = CURRENT_HANDLE.with(|h| h.get());
    // Check the handle and claim it under the LIVE lock, so that a concurrent
    // OSMesaDestroyContext either sees our claim or makes us see a stale handle.
    let Ok(live) = LIVE.lock() else {
        return FALSE;
    };
    if !live.contains(&(ctx as usize)) {
        return FALSE;
    }
    // SAFETY: `ctx` is registered in LIVE (and cannot be freed while we hold the lock).
    let c = unsafe { &*ctx };
    let Some(format) = color_format(c.format, type_) else {
        return FALSE;
    };
    if prev != ctx
        && c.owner
            .compare_exchange(0, me, Ordering::AcqRel, Ordering::Acquire)
            .is_err()
    {
        return FALSE;
    }
    drop(live);
    flush_current();
    if prev != ctx && !prev.is_null() {
        let_go(prev);
    }
    CURRENT_HANDLE.with(|h| h.set(ctx));
    let gl = c.ctx.get();
    super::set_current(gl);
    // SAFETY: this thread now owns the context (claimed above), so no other reference exists.
    let gl = unsafe { &mut *gl };
    if prev != ctx {
        c.group.check_out(gl);
    }
    gl.attach_user_buffer(
        format,
        buffer as usize,
        type_,
        (width as usize, height as usize),
    );
    GL_TRUE as GLboolean
}

/// OSMesaGetCurrentContext.
#[no_mangle]
pub extern "C" fn OSMesaGetCurrentContext() -> OSMesaContext {
    CURRENT_HANDLE.with(|h| h.get())
}

/// OSMesaPixelStore on the context current on this thread.
fn pixel_store(c: &mut Context, pname: GLint, value: GLint) -> GlResult<()> {
    match pname {
        OSMESA_ROW_LENGTH => c.set_user_row_length(value),
        OSMESA_Y_UP => {
            c.set_user_y_up(value != 0);
            Ok(())
        }
        _ => Err(GlError::InvalidEnum),
    }
}

/// OSMesaPixelStore: OSMESA_ROW_LENGTH (pixels, 0 = width) and OSMESA_Y_UP for the current
/// context.
#[no_mangle]
pub extern "C" fn OSMesaPixelStore(pname: GLint, value: GLint) {
    super::with_ctx_anywhere(|c| pixel_store(c, pname, value))
}

/// An OSMesaGetIntegerv value of the context current on this thread.
fn buffer_parameter(c: &Context, pname: GLint) -> GlResult<GLint> {
    let handle = OSMesaGetCurrentContext();
    Ok(match pname {
        OSMESA_WIDTH => c.target.width as GLint,
        OSMESA_HEIGHT => c.target.height as GLint,
        // SAFETY: the current handle is live while its context is current.
        OSMESA_FORMAT => unsafe { &*handle }.format as GLint,
        OSMESA_TYPE => c.target.ty as GLint,
        OSMESA_ROW_LENGTH => c.target.row_length,
        OSMESA_Y_UP => c.target.y_up as GLint,
        OSMESA_MAX_WIDTH | OSMESA_MAX_HEIGHT => MAX_SIZE,
        _ => return Err(GlError::InvalidEnum),
    })
}

/// OSMesaGetIntegerv: the current context's buffer parameters.
///
/// # Safety
/// `value` must be NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn OSMesaGetIntegerv(pname: GLint, value: *mut GLint) {
    if value.is_null() {
        return;
    }
    if let Some(v) = super::with_ctx_anywhere(|c| buffer_parameter(c, pname).map(Some)) {
        // SAFETY: checked non-null; the caller promises it is writable.
        unsafe { write_one(value, v) };
    }
}

/// Whether there is a buffer, and its width, height, format or bytes per value, and
/// address (zeros and NULL for no context).
type BufferInfo = (bool, [GLint; 3], *mut c_void);

/// No buffer: zeros and NULL.
const NO_BUFFER: BufferInfo = (false, [0; 3], std::ptr::null_mut());

/// The depth buffer copy of a live handle (see [`OSMesaGetDepthBuffer`]).
fn depth_buffer(c: OSMesaContext) -> BufferInfo {
    if !is_live(c) {
        return NO_BUFFER;
    }
    // SAFETY: live handle. Reading the context from another thread while it draws would
    // race; Mesa has the same contract (call it from the rendering thread).
    match unsafe { &mut *(*c).ctx.get() }.depth_buffer_view() {
        Some((w, h, bytes, p)) => (true, [w, h, bytes], p),
        None => NO_BUFFER,
    }
}

/// The user buffer a live handle was bound to by OSMesaMakeCurrent (its numbers are
/// reported even before it has one, when the call answers GL_FALSE).
fn color_buffer(c: OSMesaContext) -> BufferInfo {
    if !is_live(c) {
        return NO_BUFFER;
    }
    // SAFETY: live handle; only plain fields are read.
    let h = unsafe { &*c };
    // SAFETY: as above.
    let t = unsafe { &*h.ctx.get() }.target;
    let nums = [t.width as GLint, t.height as GLint, h.format as GLint];
    (t.ptr != 0, nums, t.ptr as *mut c_void)
}

/// Writes a buffer's three numbers and address through the out pointers that are not
/// NULL; GL_TRUE when there is a buffer.
///
/// # Safety
/// The out pointers must be NULL or writable.
unsafe fn write_buffer_info(
    (ok, nums, p): BufferInfo,
    out: [*mut GLint; 3],
    buffer: *mut *mut c_void,
) -> GLboolean {
    // SAFETY: the caller promises each out pointer is NULL or writable.
    unsafe {
        out.iter().zip(nums).for_each(|(&o, v)| write_one(o, v));
        write_one(buffer, p);
    }
    ok as GLboolean
}

c_fns! {
    /// OSMesaGetDepthBuffer: a copy of the depth buffer (bottom-up rows; 4 bytes per value
    /// for 24-bit depth with stencil in the high byte, 2 for 16-bit), refreshed at each
    /// flush.
    unsafe fn OSMesaGetDepthBuffer(c: OSMesaContext, width: *mut GLint, height: *mut GLint, bytesPerValue: *mut GLint, buffer: *mut *mut c_void) -> GLboolean => write_buffer_info(depth_buffer(c), [width, height, bytesPerValue], buffer);
    /// OSMesaGetColorBuffer: the user buffer bound by OSMesaMakeCurrent.
    unsafe fn OSMesaGetColorBuffer(c: OSMesaContext, width: *mut GLint, height: *mut GLint, format: *mut GLint, buffer: *mut *mut c_void) -> GLboolean => write_buffer_info(color_buffer(c), [width, height, format], buffer);
}

/// OSMesaColorClamp: accepted. Mesa sets GL_CLAMP_FRAGMENT_COLOR (TRUE or FIXED_ONLY);
/// fixed-function colours are already in [0,1] (vertex colours are clamped, textures are
/// unorm), and softgl renders every buffer through its 8-bit path, so both settings give
/// the same pixels.
#[no_mangle]
pub extern "C" fn OSMesaColorClamp(_enable: GLboolean) {}

/// OSMesaPostprocess: accepted like Mesa's (a filter name and level, before the first
/// OSMesaMakeCurrent); the gallium post-processing filters themselves are not implemented.
///
/// # Safety
/// `filter` is not read.
#[no_mangle]
pub unsafe extern "C" fn OSMesaPostprocess(
    _osmesa: OSMesaContext,
    _filter: *const c_char,
    _enable_value: libc::c_uint,
) {
}

/// OSMesaGetProcAddress: the address of an exported OSMesa or GL function, NULL otherwise.
///
/// # Safety
/// `funcName` must be NULL or a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn OSMesaGetProcAddress(funcName: *const c_char) -> OSMESAproc {
    if funcName.is_null() {
        return None;
    }
    // SAFETY: caller contract: a NUL-terminated string.
    let name = unsafe { std::ffi::CStr::from_ptr(funcName) }.to_bytes();
    super::proc_table::lookup(name)
}
