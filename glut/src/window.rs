//! Windows (OSMesa contexts), callbacks, the deterministic clock and `glutMainLoop`.

#![allow(non_snake_case)]

use crate::config::{Config, Key};
use crate::gl::{self, OsMesaContext};
use std::cell::RefCell;
use std::ffi::{c_char, c_int, c_uint, c_void, CStr};

/// `void (*)(void)`.
pub type VoidCb = Option<extern "C" fn()>;
/// `void (*)(int, int)`.
pub type IntIntCb = Option<extern "C" fn(c_int, c_int)>;
/// `void (*)(int)`.
pub type IntCb = Option<extern "C" fn(c_int)>;
/// `void (*)(unsigned char, int, int)`.
pub type KeyCb = Option<extern "C" fn(u8, c_int, c_int)>;
/// `void (*)(int, int, int)`.
pub type SpecialCb = Option<extern "C" fn(c_int, c_int, c_int)>;
/// `void (*)(int, int, int, int)`.
pub type MouseCb = Option<extern "C" fn(c_int, c_int, c_int, c_int)>;

const GLUT_DOUBLE: c_uint = 0x0002;
const GLUT_ACCUM: c_uint = 0x0004;
/// `GLUT_MULTISAMPLE`: a display-mode bit, and glutSetOption's sample count.
const GLUT_MULTISAMPLE: c_uint = 0x0080;
/// Accumulation bits per channel of a GLUT_ACCUM window.
const ACCUM_BITS: i32 = 16;
const GLUT_VISIBLE: c_int = 1;

/// The callbacks of one window.
#[derive(Clone, Copy, Default)]
struct Callbacks {
    display: VoidCb,
    reshape: IntIntCb,
    keyboard: KeyCb,
    keyboard_up: KeyCb,
    special: SpecialCb,
    special_up: SpecialCb,
    mouse: MouseCb,
    motion: IntIntCb,
    passive_motion: IntIntCb,
    visibility: IntCb,
    entry: IntCb,
    close: VoidCb,
}

/// One window: an OSMesa context and the memory it draws into.
struct Window {
    ctx: OsMesaContext,
    /// RGBA, bottom row first (OSMesa's layout).
    buf: Vec<u8>,
    width: i32,
    height: i32,
    x: i32,
    y: i32,
    double: bool,
    /// The last swapped frame (double-buffered windows).
    front: Option<Vec<u8>>,
    cb: Callbacks,
    title: String,
    /// A reshape is due (created or resized since the last one).
    needs_reshape: bool,
}

/// A pending `glutTimerFunc`.
struct Timer {
    due: i32,
    seq: u64,
    cb: extern "C" fn(c_int),
    value: c_int,
}

/// The whole GLUT state (one per thread, as GLUT is single-threaded).
struct State {
    config: Option<Config>,
    init_size: (i32, i32),
    init_pos: (i32, i32),
    init_mode: c_uint,
    windows: Vec<Option<Window>>,
    current: usize,
    idle: VoidCb,
    timers: Vec<Timer>,
    timer_seq: u64,
    now_ms: i32,
    leave: bool,
    action_on_close: c_int,
    /// glutInitContextVersion's (major, minor), glutInitContextFlags,
    /// glutInitContextProfile: recorded for glutGet; OSMesa makes a legacy context.
    context: (c_int, c_int, c_int, c_int),
    /// glutSetOption(GLUT_MULTISAMPLE): recorded; OSMesa windows are single-sampled.
    samples: c_int,
}

impl State {
    const fn new() -> Self {
        State {
            config: None,
            init_size: (300, 300),
            init_pos: (-1, -1),
            init_mode: 0,
            windows: Vec::new(),
            current: 0,
            idle: None,
            timers: Vec::new(),
            timer_seq: 0,
            now_ms: 0,
            leave: false,
            action_on_close: 0,
            context: (1, 0, 0, 0),
            samples: 4,
        }
    }

    fn config(&mut self) -> &Config {
        self.config.get_or_insert_with(Config::from_env)
    }

    fn win(&mut self) -> Option<&mut Window> {
        let i = self.current.checked_sub(1)?;
        self.windows.get_mut(i)?.as_mut()
    }
}

thread_local! {
    static STATE: RefCell<State> = const { RefCell::new(State::new()) };
}

/// Runs `f` on the state. Never call a user callback inside `f`.
fn with<R>(f: impl FnOnce(&mut State) -> R) -> R {
    STATE.with(|s| f(&mut s.borrow_mut()))
}

/// Runs `f` on the current window, if there is one.
fn with_win<R: Default>(f: impl FnOnce(&mut Window) -> R) -> R {
    with(|s| s.win().map(f).unwrap_or_default())
}

fn make_current(w: &mut Window) {
    // SAFETY: buf holds width*height RGBA bytes and stays allocated (and unmoved) until
    // the window is resized or destroyed, when it is re-bound or the context destroyed.
    unsafe {
        gl::OSMesaMakeCurrent(
            w.ctx,
            w.buf.as_mut_ptr().cast::<c_void>(),
            gl::GL_UNSIGNED_BYTE,
            w.width,
            w.height,
        );
    }
}

/// Selects window `id` (1-based) and makes its context current; false if it is gone.
fn select(id: usize) -> bool {
    with(|s| {
        let Some(Some(w)) = s.windows.get_mut(id.wrapping_sub(1)) else {
            return false;
        };
        make_current(w);
        s.current = id;
        true
    })
}

/// `glutInit`: reads the configuration; command-line arguments are left alone.
#[no_mangle]
pub extern "C" fn glutInit(_argcp: *mut c_int, _argv: *mut *mut c_char) {
    with(|s| {
        s.config = Some(Config::from_env());
        s.now_ms = 0;
    });
}

/// `glutInitDisplayMode`: GLUT_DOUBLE decides when a frame is captured.
#[no_mangle]
pub extern "C" fn glutInitDisplayMode(mode: c_uint) {
    with(|s| s.init_mode = mode);
}

/// `glutInitWindowSize`.
#[no_mangle]
pub extern "C" fn glutInitWindowSize(width: c_int, height: c_int) {
    if width > 0 && height > 0 {
        with(|s| s.init_size = (width, height));
    }
}

/// `glutInitWindowPosition` (remembered for glutGet only).
#[no_mangle]
pub extern "C" fn glutInitWindowPosition(x: c_int, y: c_int) {
    with(|s| s.init_pos = (x, y));
}

/// `glutCreateWindow`: a new OSMesa context with depth and stencil (and a 16-bit
/// accumulation buffer with GLUT_ACCUM; GLUT_MULTISAMPLE is accepted, the window
/// stays single-sampled); returns its id.
#[no_mangle]
pub extern "C" fn glutCreateWindow(title: *const c_char) -> c_int {
    let title = if title.is_null() {
        String::new()
    } else {
        // SAFETY: a non-null title is a NUL-terminated C string (GLUT's contract).
        unsafe { CStr::from_ptr(title) }
            .to_string_lossy()
            .into_owned()
    };
    let accum = with(|s| s.init_mode & GLUT_ACCUM != 0);
    let accum = if accum { ACCUM_BITS } else { 0 };
    // SAFETY: plain constructor call; a NULL share context is allowed.
    let ctx =
        unsafe { gl::OSMesaCreateContextExt(gl::OSMESA_RGBA, 24, 8, accum, std::ptr::null_mut()) };
    if ctx.is_null() {
        eprintln!("softglut: OSMesaCreateContextExt failed");
        std::process::exit(1);
    }
    let id = with(|s| {
        let (width, height) = s.config().size.unwrap_or(s.init_size);
        let w = Window {
            ctx,
            buf: vec![0; width as usize * height as usize * 4],
            width,
            height,
            x: s.init_pos.0.max(0),
            y: s.init_pos.1.max(0),
            double: s.init_mode & GLUT_DOUBLE != 0,
            front: None,
            cb: Callbacks::default(),
            title,
            needs_reshape: true,
        };
        s.windows.push(Some(w));
        s.windows.len()
    });
    select(id);
    id as c_int
}

/// `glutDestroyWindow`; destroying the last window ends `glutMainLoop`.
#[no_mangle]
pub extern "C" fn glutDestroyWindow(id: c_int) {
    let w = with(|s| {
        let w = s.windows.get_mut((id as usize).wrapping_sub(1))?.take();
        if s.current == id as usize {
            s.current = 0;
        }
        if s.windows.iter().all(Option::is_none) {
            s.leave = true;
        }
        w
    });
    if let Some(w) = w {
        crate::menu::window_destroyed(id);
        // Release the context before destroying it, as freeglut's EGL back end does
        // (eglMakeCurrent with no context, then eglDestroyContext): Mesa 22.3's
        // OSMesaDestroyContext crashes when handed the current context.
        // SAFETY: querying the current context has no preconditions; unbinding with all
        // arguments NULL/0 is OSMesa's documented way to release the current context;
        // the context was created by glutCreateWindow and is destroyed once.
        unsafe {
            if gl::OSMesaGetCurrentContext() == w.ctx {
                gl::OSMesaMakeCurrent(std::ptr::null_mut(), std::ptr::null_mut(), 0, 0, 0);
            }
            gl::OSMesaDestroyContext(w.ctx);
        }
    }
}

/// `glutGetWindow`: the current window's id, 0 if none.
#[no_mangle]
pub extern "C" fn glutGetWindow() -> c_int {
    with(|s| s.current as c_int)
}

/// `glutSetWindow`.
#[no_mangle]
pub extern "C" fn glutSetWindow(id: c_int) {
    select(id as usize);
}

/// `glutSetWindowTitle` (kept for nothing but completeness: there is no title bar).
#[no_mangle]
pub extern "C" fn glutSetWindowTitle(title: *const c_char) {
    if title.is_null() {
        return;
    }
    // SAFETY: a non-null title is a NUL-terminated C string.
    let t = unsafe { CStr::from_ptr(title) }
        .to_string_lossy()
        .into_owned();
    with_win(|w| w.title = t);
}

/// `glutSetIconTitle`: no icon; accepted.
#[no_mangle]
pub extern "C" fn glutSetIconTitle(_title: *const c_char) {}

/// `glutReshapeWindow`: resizes the buffer; reshape is called before the next frame.
#[no_mangle]
pub extern "C" fn glutReshapeWindow(width: c_int, height: c_int) {
    if width <= 0 || height <= 0 {
        return;
    }
    with_win(|w| {
        if (w.width, w.height) != (width, height) {
            w.width = width;
            w.height = height;
            w.buf = vec![0; width as usize * height as usize * 4];
            w.front = None;
            w.needs_reshape = true;
            make_current(w);
        }
    });
}

/// `glutPositionWindow` (remembered for glutGet only).
#[no_mangle]
pub extern "C" fn glutPositionWindow(x: c_int, y: c_int) {
    with_win(|w| {
        w.x = x;
        w.y = y;
    });
}

/// `glutFullScreen`: no screen, so the window keeps its size.
#[no_mangle]
pub extern "C" fn glutFullScreen() {}

/// `glutShowWindow`, `glutHideWindow`, `glutIconifyWindow`, `glutPopWindow`,
/// `glutPushWindow`, `glutSetCursor`, `glutWarpPointer`, `glutIgnoreKeyRepeat`:
/// accepted, nothing to do headless.
#[no_mangle]
pub extern "C" fn glutShowWindow() {}
/// See [`glutShowWindow`].
#[no_mangle]
pub extern "C" fn glutHideWindow() {}
/// See [`glutShowWindow`].
#[no_mangle]
pub extern "C" fn glutIconifyWindow() {}
/// See [`glutShowWindow`].
#[no_mangle]
pub extern "C" fn glutPopWindow() {}
/// See [`glutShowWindow`].
#[no_mangle]
pub extern "C" fn glutPushWindow() {}
/// See [`glutShowWindow`].
#[no_mangle]
pub extern "C" fn glutSetCursor(_cursor: c_int) {}
/// See [`glutShowWindow`].
#[no_mangle]
pub extern "C" fn glutWarpPointer(_x: c_int, _y: c_int) {}
/// See [`glutShowWindow`].
#[no_mangle]
pub extern "C" fn glutIgnoreKeyRepeat(_ignore: c_int) {}

macro_rules! window_callback {
    ($(#[$doc:meta] $name:ident => $field:ident : $ty:ty;)*) => {$(
        #[$doc]
        #[no_mangle]
        pub extern "C" fn $name(f: $ty) {
            with_win(|w| w.cb.$field = f);
        }
    )*};
}

window_callback! {
    /// `glutDisplayFunc`.
    glutDisplayFunc => display: VoidCb;
    /// `glutReshapeFunc` (default: glViewport over the window).
    glutReshapeFunc => reshape: IntIntCb;
    /// `glutKeyboardFunc`: receives `SOFTGLUT_KEYS`' ASCII keys.
    glutKeyboardFunc => keyboard: KeyCb;
    /// `glutKeyboardUpFunc`: called after each fed ASCII key.
    glutKeyboardUpFunc => keyboard_up: KeyCb;
    /// `glutSpecialFunc`: receives `SOFTGLUT_KEYS`' special keys.
    glutSpecialFunc => special: SpecialCb;
    /// `glutSpecialUpFunc`: called after each fed special key.
    glutSpecialUpFunc => special_up: SpecialCb;
    /// `glutMouseFunc` (there is no mouse: never called).
    glutMouseFunc => mouse: MouseCb;
    /// `glutMotionFunc` (never called).
    glutMotionFunc => motion: IntIntCb;
    /// `glutPassiveMotionFunc` (never called).
    glutPassiveMotionFunc => passive_motion: IntIntCb;
    /// `glutVisibilityFunc`: called once with GLUT_VISIBLE when the main loop starts.
    glutVisibilityFunc => visibility: IntCb;
    /// `glutEntryFunc` (never called).
    glutEntryFunc => entry: IntCb;
    /// `glutCloseFunc` (freeglut): called when glutMainLoop returns.
    glutCloseFunc => close: VoidCb;
}

/// `glutWMCloseFunc` (freeglut's old name for glutCloseFunc).
#[no_mangle]
pub extern "C" fn glutWMCloseFunc(f: VoidCb) {
    glutCloseFunc(f);
}

/// `glutIdleFunc`: called once per frame, after display.
#[no_mangle]
pub extern "C" fn glutIdleFunc(f: VoidCb) {
    with(|s| s.idle = f);
}

/// `glutTimerFunc`: fires at the first frame whose clock is at least now + msecs.
#[no_mangle]
pub extern "C" fn glutTimerFunc(msecs: c_uint, f: Option<extern "C" fn(c_int)>, value: c_int) {
    let Some(cb) = f else { return };
    with(|s| {
        let due = s.now_ms.saturating_add(msecs.min(i32::MAX as u32) as i32);
        s.timer_seq += 1;
        let seq = s.timer_seq;
        s.timers.push(Timer {
            due,
            seq,
            cb,
            value,
        });
    });
}

/// `glutPostRedisplay`: every frame is displayed anyway.
#[no_mangle]
pub extern "C" fn glutPostRedisplay() {}

/// `glutPostWindowRedisplay`: see [`glutPostRedisplay`].
#[no_mangle]
pub extern "C" fn glutPostWindowRedisplay(_id: c_int) {}

/// `glutSwapBuffers`: finishes drawing and keeps the image as this frame's picture.
#[no_mangle]
pub extern "C" fn glutSwapBuffers() {
    // SAFETY: no arguments; a context is current while a window exists.
    unsafe { gl::glFinish() };
    with_win(|w| w.front = Some(w.buf.clone()));
}

/// `glutLeaveMainLoop`: glutMainLoop returns after the current frame is written.
#[no_mangle]
pub extern "C" fn glutLeaveMainLoop() {
    with(|s| s.leave = true);
}

/// `glutSetOption`: GLUT_ACTION_ON_WINDOW_CLOSE and GLUT_MULTISAMPLE are remembered;
/// glutMainLoop always returns (headless runs end by frame count).
#[no_mangle]
pub extern "C" fn glutSetOption(what: c_uint, value: c_int) {
    match what {
        0x01F9 => with(|s| s.action_on_close = value),
        GLUT_MULTISAMPLE => with(|s| s.samples = value),
        _ => {}
    }
}

/// `glutInitContextVersion` (freeglut): recorded (glutGet GLUT_INIT_MAJOR_VERSION,
/// GLUT_INIT_MINOR_VERSION); OSMesa windows get its compatibility context.
#[no_mangle]
pub extern "C" fn glutInitContextVersion(major: c_int, minor: c_int) {
    with(|s| (s.context.0, s.context.1) = (major, minor));
}

/// `glutInitContextFlags` (freeglut): recorded (glutGet GLUT_INIT_FLAGS).
#[no_mangle]
pub extern "C" fn glutInitContextFlags(flags: c_int) {
    with(|s| s.context.2 = flags);
}

/// `glutInitContextProfile` (freeglut): recorded (glutGet GLUT_INIT_PROFILE).
#[no_mangle]
pub extern "C" fn glutInitContextProfile(profile: c_int) {
    with(|s| s.context.3 = profile);
}

/// `glutGetModifiers`: fed keys carry no modifiers.
#[no_mangle]
pub extern "C" fn glutGetModifiers() -> c_int {
    0
}

/// `glutDeviceGet`: a keyboard and a three-button mouse exist, nothing else.
#[no_mangle]
pub extern "C" fn glutDeviceGet(what: c_uint) -> c_int {
    match what {
        0x0258 | 0x0259 => 1,
        0x025D => 3,
        _ => 0,
    }
}

/// `glutExtensionSupported`: whether `name` is a word of the GL extension string.
#[no_mangle]
pub extern "C" fn glutExtensionSupported(name: *const c_char) -> c_int {
    if name.is_null() {
        return 0;
    }
    // SAFETY: a non-null name is a NUL-terminated C string (GLUT's contract).
    let name = unsafe { CStr::from_ptr(name) }.to_bytes();
    // SAFETY: plain GL query; the result is NULL or a static NUL-terminated string.
    let ext = unsafe { gl::glGetString(gl::GL_EXTENSIONS) };
    if ext.is_null() || name.is_empty() || name.contains(&b' ') {
        return 0;
    }
    // SAFETY: checked non-null above; GL extension strings are NUL-terminated.
    let ext = unsafe { CStr::from_ptr(ext.cast::<c_char>()) }.to_bytes();
    c_int::from(ext.split(|&b| b == b' ').any(|w| w == name))
}

/// `glutGet`.
#[no_mangle]
pub extern "C" fn glutGet(what: c_uint) -> c_int {
    with(|s| {
        let (iw, ih) = s.init_size;
        let (ix, iy) = s.init_pos;
        let mode = s.init_mode as c_int;
        let now = s.now_ms;
        let action = s.action_on_close;
        let (context, samples) = (s.context, s.samples);
        let win = s.win().map(|w| (w.x, w.y, w.width, w.height, w.double));
        match (what, win) {
            (0x02BC, _) => now,
            (0x0064, Some(w)) => w.0,
            (0x0065, Some(w)) => w.1,
            (0x0066, Some(w)) => w.2,
            (0x0067, Some(w)) => w.3,
            (0x0073, Some(w)) => w.4 as c_int,
            (0x0068, Some(_)) => 32,
            (0x0069, Some(_)) => 8,
            (0x006A, Some(_)) => 24,
            (0x006B..=0x006E, Some(_)) => 8,
            // Accumulation sizes: what the window's GL says.
            (0x006F..=0x0072, Some(_)) => gl::get_int(0x0D58 + what - 0x006F),
            (0x0200, _) => context.0,
            (0x0201, _) => context.1,
            (0x0202, _) => context.2,
            (0x0203, _) => context.3,
            (GLUT_MULTISAMPLE, _) => samples,
            (0x012C, _) => crate::menu::num_items(),
            (0x0074, Some(_)) => 1,
            (0x007C, _) => 1,
            (0x0064..=0x007D, _) => 0,
            (0x00C8, _) => 1920,
            (0x00C9, _) => 1080,
            (0x00CA, _) => 508,
            (0x00CB, _) => 286,
            (0x0190, _) => 1,
            (0x01F4, _) => ix,
            (0x01F5, _) => iy,
            (0x01F6, _) => iw,
            (0x01F7, _) => ih,
            (0x01F8, _) => mode,
            (0x01F9, _) => action,
            (0x01FC, _) => 30200,
            (0x01FF, _) => 0,
            _ => 0,
        }
    })
}

/// Ids of the open windows.
fn open_windows() -> Vec<usize> {
    with(|s| {
        s.windows
            .iter()
            .enumerate()
            .filter(|(_, w)| w.is_some())
            .map(|(i, _)| i + 1)
            .collect()
    })
}

/// Calls reshape on window `id` if it is due (default: a viewport over the window).
fn reshape_if_due(id: usize) {
    let due = with(|s| {
        let w = s.windows.get_mut(id - 1)?.as_mut()?;
        let due = std::mem::take(&mut w.needs_reshape);
        due.then_some((w.cb.reshape, w.width, w.height))
    });
    if let Some((cb, width, height)) = due {
        match cb {
            Some(f) => f(width, height),
            // SAFETY: plain GL call with integer arguments.
            None => unsafe { gl::glViewport(0, 0, width, height) },
        }
    }
}

/// Feeds the keys scheduled for `frame` to the current window.
fn feed_keys(frame: u32) {
    let keys: Vec<Key> = with(|s| {
        s.config()
            .keys
            .iter()
            .filter(|(f, _)| *f == frame)
            .map(|&(_, k)| k)
            .collect()
    });
    for key in keys {
        let Some((cb, w, h)) = with(|s| s.win().map(|w| (w.cb, w.width, w.height))) else {
            return;
        };
        let (x, y) = (w / 2, h / 2);
        match key {
            Key::Ascii(c) => {
                if let Some(f) = cb.keyboard {
                    f(c, x, y);
                }
                if let Some(f) = cb.keyboard_up {
                    f(c, x, y);
                }
            }
            Key::Special(k) => {
                if let Some(f) = cb.special {
                    f(k, x, y);
                }
                if let Some(f) = cb.special_up {
                    f(k, x, y);
                }
            }
        }
    }
}

/// Fires the timers due now, earliest first; timers they add wait for a later frame.
fn fire_timers() {
    let mut due: Vec<Timer> = with(|s| {
        let now = s.now_ms;
        let (d, keep) = std::mem::take(&mut s.timers)
            .into_iter()
            .partition(|t| t.due <= now);
        s.timers = keep;
        d
    });
    due.sort_by_key(|t| (t.due, t.seq));
    for t in due {
        (t.cb)(t.value);
    }
}

/// Displays window `id` and writes its frame.
fn display_and_write(id: usize, frame: u32) {
    if !select(id) {
        return;
    }
    reshape_if_due(id);
    let cb = with(|s| s.win().and_then(|w| w.cb.display));
    if let Some(f) = cb {
        f();
    }
    // SAFETY: no arguments; window id's context is current.
    unsafe { gl::glFinish() };
    let out = with(|s| {
        let dir = s.config().output.clone();
        let w = s.win()?;
        let pixels = match (&w.front, w.double) {
            (Some(front), true) => front.clone(),
            _ => w.buf.clone(),
        };
        let name = if id == 1 {
            format!("frame_{frame:04}.png")
        } else {
            format!("window{id}_frame_{frame:04}.png")
        };
        Some((dir.join(name), pixels, w.width, w.height))
    });
    if let Some((path, pixels, width, height)) = out {
        if let Err(e) = write_png(&path, &pixels, width as u32, height as u32) {
            eprintln!("softglut: cannot write {}: {e}", path.display());
            std::process::exit(1);
        }
    }
}

/// Writes an RGBA, bottom-row-first buffer as an RGB PNG (top row first; alpha, which
/// a window does not show, is dropped).
pub fn write_png(path: &std::path::Path, rgba: &[u8], w: u32, h: u32) -> image::ImageResult<()> {
    let row = w as usize * 4;
    let mut rgb = Vec::with_capacity(w as usize * h as usize * 3);
    for y in (0..h as usize).rev() {
        for px in rgba[y * row..(y + 1) * row].chunks_exact(4) {
            rgb.extend_from_slice(&px[..3]);
        }
    }
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir)?;
    }
    image::save_buffer(path, &rgb, w, h, image::ExtendedColorType::Rgb8)
}

/// `glutMainLoop`: reshape once, then `SOFTGLUT_FRAMES` frames of keys, timers,
/// display (one PNG per window) and idle, the clock advancing `SOFTGLUT_STEP_MS` per
/// frame. Returns after the last frame, glutLeaveMainLoop or the last window's
/// destruction.
#[no_mangle]
pub extern "C" fn glutMainLoop() {
    let (frames, step) = with(|s| {
        s.leave = false;
        let c = s.config();
        (c.frames, c.step_ms)
    });
    let start = glutGetWindow() as usize;
    for id in open_windows() {
        let vis = with(|s| s.windows[id - 1].as_ref().and_then(|w| w.cb.visibility));
        select(id);
        reshape_if_due(id);
        if let Some(f) = vis {
            f(GLUT_VISIBLE);
        }
    }
    select(start);
    for frame in 0..frames {
        feed_keys(frame);
        fire_timers();
        for id in open_windows() {
            display_and_write(id, frame);
        }
        select(start);
        if with(|s| s.leave) {
            break;
        }
        if let Some(f) = with(|s| s.idle) {
            f();
        }
        if with(|s| s.leave) {
            break;
        }
        with(|s| s.now_ms = s.now_ms.saturating_add(step));
    }
    for id in open_windows() {
        let close = with(|s| s.windows[id - 1].as_ref().and_then(|w| w.cb.close));
        if let Some(f) = close {
            select(id);
            f();
        }
    }
}

/// `glutMainLoopEvent` (freeglut): fires the due timers (there are no other events).
#[no_mangle]
pub extern "C" fn glutMainLoopEvent() {
    fire_timers();
}
