//! A deterministic fuzzer: random sequences of GL calls through the exported functions,
//! half of them structured (geometry with huge/NaN/Inf values, random state, matrices,
//! viewports, depth ranges, buffers, reads, context re-binds) and half hostile calls of
//! any exported function from the table in `robust_common`. After every call: no panic
//! (caught panics would be reported as GL_OUT_OF_MEMORY), and GL_OUT_OF_MEMORY only for a
//! buffer too large to allocate.
//!
//! `cargo test --release --test robust_fuzz` runs 50 000 calls; `scripts/fuzz.sh N` runs
//! N calls per process (`SOFTGL_FUZZ_CALLS`, `SOFTGL_FUZZ_SEED`) through the ignored test.
#![cfg(all(target_arch = "x86_64", unix))]

mod robust_common;

use robust_common::*;
use softgl::ffi::arrays::*;
use softgl::ffi::buffers::*;
use softgl::ffi::draw::*;
use softgl::ffi::enums::*;
use softgl::ffi::fragment::*;
use softgl::ffi::glext_enums::*;
use softgl::ffi::immediate::*;
use softgl::ffi::matrix::*;
use softgl::ffi::osmesa::*;
use softgl::ffi::query::*;
use softgl::ffi::state::*;

/// Client memory the fuzzer's arrays point into: enough for 128 vertices at any stride
/// the fuzzer uses (<= 64 bytes) plus the largest element.
const VMEM: usize = 1 << 16;

/// A context with its own colour buffer (sizes and formats vary).
struct Target {
    ctx: OSMesaContext,
    buf: Vec<u8>,
    w: i32,
    h: i32,
}

impl Target {
    fn new(rng: &mut Rng) -> Target {
        let (format, bpp, ty) = rng.pick(&[
            (OSMESA_RGBA, 4, GL_UNSIGNED_BYTE),
            (OSMESA_BGRA, 4, GL_UNSIGNED_BYTE),
            (OSMESA_RGB, 3, GL_UNSIGNED_BYTE),
            (OSMESA_RGB_565, 2, GL_UNSIGNED_SHORT_5_6_5),
        ]);
        let depth = rng.pick(&[0, 16, 24, 32]);
        let stencil = rng.pick(&[0, 8]);
        let ctx = OSMesaCreateContextExt(format, depth, stencil, 0, std::ptr::null_mut());
        assert!(!ctx.is_null());
        let w = 1 + rng.below(48) as i32;
        let h = 1 + rng.below(48) as i32;
        let mut buf = vec![0u8; (w * h * bpp) as usize];
        // SAFETY: the buffer holds w*h pixels of the format; the context is destroyed
        // (Drop) before the buffer is freed.
        let ok = unsafe { OSMesaMakeCurrent(ctx, buf.as_mut_ptr().cast(), ty, w, h) };
        assert_eq!(ok, 1);
        Target { ctx, buf, w, h }
    }
}

impl Drop for Target {
    fn drop(&mut self) {
        OSMesaDestroyContext(self.ctx);
        let _ = self.buf.len();
    }
}

/// A float for geometry: mostly sensible, sometimes huge, tiny, NaN or infinite.
fn coord(rng: &mut Rng) -> f32 {
    match rng.below(20) {
        0 => rng.pick(&[f32::NAN, f32::INFINITY, f32::NEG_INFINITY]),
        1 => rng.pick(&[1e7, -1e7, 1e30, -1e30, f32::MAX, f32::MIN, 1e-30, -0.0]),
        2 | 3 => rng.range(-1e6, 1e6) as f32,
        4 => rng.range(-1e3, 1e3) as f32,
        _ => rng.range(-2.0, 2.0) as f32,
    }
}

/// A matrix entry: like [`coord`] but mostly near the identity's range.
fn mat(rng: &mut Rng) -> [f32; 16] {
    let mut m = [0f32; 16];
    for (i, v) in m.iter_mut().enumerate() {
        *v = if rng.chance(0.6) {
            if i % 5 == 0 {
                1.0
            } else {
                0.0
            }
        } else {
            coord(rng)
        };
    }
    m
}

const CAPS: &[u32] = &[
    GL_DEPTH_TEST,
    GL_BLEND,
    GL_CULL_FACE,
    GL_STENCIL_TEST,
    GL_SCISSOR_TEST,
    GL_ALPHA_TEST,
    GL_COLOR_LOGIC_OP,
    GL_DITHER,
    GL_POLYGON_OFFSET_FILL,
    GL_LIGHTING,
    GL_TEXTURE_2D,
    GL_FOG,
    GL_NORMALIZE,
    GL_COLOR_MATERIAL,
    GL_LINE_SMOOTH,
    GL_POINT_SMOOTH,
];

const PRIMS: &[u32] = &[
    GL_POINTS,
    GL_LINES,
    GL_LINE_STRIP,
    GL_LINE_LOOP,
    GL_TRIANGLES,
    GL_TRIANGLE_STRIP,
    GL_TRIANGLE_FAN,
    GL_QUADS,
    GL_QUAD_STRIP,
    GL_POLYGON,
];

const BLEND: &[u32] = &[
    GL_ZERO,
    GL_ONE,
    GL_SRC_COLOR,
    GL_ONE_MINUS_SRC_COLOR,
    GL_DST_COLOR,
    GL_SRC_ALPHA,
    GL_ONE_MINUS_DST_ALPHA,
    GL_SRC_ALPHA_SATURATE,
    GL_CONSTANT_COLOR,
    GL_ONE_MINUS_CONSTANT_ALPHA,
];

const FUNCS: &[u32] = &[
    GL_NEVER,
    GL_LESS,
    GL_EQUAL,
    GL_LEQUAL,
    GL_GREATER,
    GL_NOTEQUAL,
    GL_GEQUAL,
    GL_ALWAYS,
];

const TYPES: &[u32] = &[
    GL_BYTE,
    GL_UNSIGNED_BYTE,
    GL_SHORT,
    GL_UNSIGNED_SHORT,
    GL_INT,
    GL_UNSIGNED_INT,
    GL_FLOAT,
    GL_DOUBLE,
];

/// Functions whose hostile table calls must stay small (they read client memory through
/// sizes, or set state that sizes later reads and writes of client memory). ARB/EXT
/// aliases count as their core function: `glArrayElementEXT(65536)` reads past `vmem`
/// just as `glArrayElement(65536)` would (the harness's fault, not the library's: that
/// was the crash the long runs found).
fn must_stay_small(name: &str) -> bool {
    let name = name
        .strip_suffix("ARB")
        .or_else(|| name.strip_suffix("EXT"))
        .unwrap_or(name);
    name.starts_with("glDraw")
        || name.starts_with("glMultiDraw")
        || name == "glArrayElement"
        || name.starts_with("glPixelStore")
        || name == "OSMesaPixelStore"
}

struct Fuzzer {
    rng: Rng,
    fns: Vec<Func>,
    target: Option<Target>,
    vmem: Vec<f32>,
    scratch: Vec<u64>,
    calls: u64,
    buffers: Vec<u32>,
    /// Fragments and rasterized triangles of finished contexts (shows the fuzz draws).
    drawn: (u64, u64),
}

impl Fuzzer {
    fn new(seed: u64) -> Fuzzer {
        let mut rng = Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1);
        let vmem = (0..VMEM / 4)
            .map(|_| {
                if rng.chance(0.05) {
                    coord(&mut rng)
                } else {
                    rng.range(-1.5, 1.5) as f32
                }
            })
            .collect();
        Fuzzer {
            rng,
            fns: functions(),
            target: None,
            vmem,
            scratch: vec![0; 8192],
            calls: 0,
            buffers: vec![],
            drawn: (0, 0),
        }
    }

    /// Makes sure a context is current (a hostile call may have destroyed or unbound it).
    fn ensure_context(&mut self) {
        if OSMesaGetCurrentContext().is_null() || self.target.is_none() {
            self.retire();
            self.target = Some(Target::new(&mut self.rng));
            self.buffers.clear();
        }
    }

    /// Drops the current target, adding its work counters to `drawn`.
    fn retire(&mut self) {
        if let Some(s) = softgl::ffi::current_stats() {
            self.drawn.0 += s.fragments;
            self.drawn.1 += s.tris_rasterized;
        }
        self.target = None;
    }

    /// Undoes state that would make the *harness* break the API contract: pack and
    /// OSMesa row parameters larger than the buffers the fuzzer passes.
    fn keep_harness_honest(&mut self) {
        glEnd();
        let mut v = 0;
        for p in [
            GL_PACK_ROW_LENGTH,
            GL_PACK_SKIP_ROWS,
            GL_PACK_SKIP_PIXELS,
            GL_PACK_ALIGNMENT,
        ] {
            // SAFETY: one component.
            unsafe { glGetIntegerv(p, &mut v) };
            if !(0..=8).contains(&v) {
                glPixelStorei(p, if p == GL_PACK_ALIGNMENT { 4 } else { 0 });
            }
        }
        let w = self.target.as_ref().map_or(0, |t| t.w);
        // SAFETY: one component.
        unsafe { OSMesaGetIntegerv(OSMESA_ROW_LENGTH, &mut v) };
        if v > w {
            OSMesaPixelStore(OSMESA_ROW_LENGTH, 0);
        }
        while glGetError() != GL_NO_ERROR {}
    }

    fn check(&mut self, what: &str, p0: usize, oom_ok: bool) {
        self.calls += 1;
        let e = glGetError();
        assert_eq!(panics(), p0, "call {} ({what}) panicked", self.calls);
        assert!(
            e != GL_OUT_OF_MEMORY || oom_ok,
            "call {} ({what}) reported GL_OUT_OF_MEMORY",
            self.calls
        );
    }

    /// One hostile call of a random exported function.
    fn table_call(&mut self) {
        let i = self.rng.below(self.fns.len() as u64) as usize;
        let f = self.fns[i].clone();
        if f.name == "OSMesaMakeCurrent" && self.rng.chance(0.9) {
            return;
        }
        let small = must_stay_small(&f.name) || self.rng.chance(0.5);
        self.scratch.fill(0);
        let ptr = if small {
            self.scratch.as_mut_ptr() as u64
        } else {
            0
        };
        let handle = self.target.as_ref().map_or(0, |t| t.ctx as u64);
        let rng = &mut self.rng;
        let args: Vec<Arg> = f
            .params
            .iter()
            .map(|&k| hostile(rng, k, small, ptr, handle))
            .collect();
        if std::env::var_os("SOFTGL_FUZZ_TRACE").is_some() {
            eprintln!("{} {} {:?}", self.calls, f.name, args);
        }
        let p0 = panics();
        // SAFETY: pointers are null or the zeroed 64 KiB scratch buffer with sizes below 8;
        // calls that read client arrays by index stay small (see `must_stay_small`), and
        // client arrays point into `vmem` or `scratch`, both big enough for that.
        let ret = unsafe { call(&f, &args) };
        if f.name.starts_with("OSMesaCreateContext") {
            OSMesaDestroyContext(ret as OSMesaContext);
        }
        let huge_alloc = f.name == "glBufferData";
        self.check(&f.name, p0, huge_alloc);
        if f.name == "OSMesaMakeCurrent" || f.name == "OSMesaDestroyContext" {
            // The context may now draw into `scratch` or be gone: start a fresh one.
            // SAFETY: unbinding.
            unsafe { OSMesaMakeCurrent(std::ptr::null_mut(), std::ptr::null_mut(), 0, 0, 0) };
            self.retire();
        }
    }

    fn vertex(&mut self) {
        let p0 = panics();
        let r = &mut self.rng;
        match r.below(6) {
            0 => glVertex2f(coord(r), coord(r)),
            1 => glVertex3f(coord(r), coord(r), coord(r)),
            2 => glVertex4f(coord(r), coord(r), coord(r), coord(r)),
            3 => glColor4f(coord(r), coord(r), coord(r), coord(r)),
            4 => glColor3ub(r.below(256) as u8, r.below(256) as u8, r.below(256) as u8),
            _ => glVertex3d(coord(r) as f64, coord(r) as f64, r.range(-1e12, 1e12)),
        }
        self.check("vertex", p0, false);
    }

    fn structured(&mut self) {
        let p0 = panics();
        let r = &mut self.rng;
        let what: &str = match r.below(31) {
            0..=4 => {
                glBegin(r.pick(PRIMS));
                let n = r.below(12);
                for _ in 0..n {
                    self.vertex();
                }
                let p0 = panics();
                glEnd();
                self.check("glEnd", p0, false);
                return;
            }
            5 => {
                let cap = self.rng.pick(CAPS);
                if self.rng.chance(0.6) {
                    glEnable(cap)
                } else {
                    glDisable(cap)
                }
                "glEnable"
            }
            6 => {
                let m = mat(r);
                glMatrixMode(r.pick(&[GL_MODELVIEW, GL_PROJECTION]));
                // SAFETY: 16 floats.
                unsafe {
                    if r.chance(0.5) {
                        glLoadMatrixf(m.as_ptr())
                    } else {
                        glMultMatrixf(m.as_ptr())
                    }
                }
                "matrix"
            }
            7 => {
                let v = |r: &mut Rng| r.range(-3.0, 3.0);
                glMatrixMode(GL_PROJECTION);
                glLoadIdentity();
                let n = r.pick(&[0.001, 0.1, 1.0, 1e-7, -1.0, f64::NAN]);
                let f = r.pick(&[1.0, 10.0, 1e6, 1e12, f64::INFINITY]);
                if r.chance(0.5) {
                    glFrustum(v(r), v(r), v(r), v(r), n, f);
                } else {
                    glOrtho(v(r), v(r), v(r), v(r), n, f);
                }
                glMatrixMode(GL_MODELVIEW);
                "projection"
            }
            8 => {
                glRotatef(coord(r) * 90.0, coord(r), coord(r), coord(r));
                glTranslatef(coord(r), coord(r), coord(r));
                glScalef(coord(r), coord(r), coord(r));
                "transform"
            }
            9 => {
                let big = |r: &mut Rng| r.pick(&[0, 1, -5, 17, 64, 1 << 20, -(1 << 30), i32::MAX]);
                glViewport(big(r), big(r), big(r), big(r));
                "glViewport"
            }
            10 => {
                glDepthRange(coord(r) as f64, coord(r) as f64);
                "glDepthRange"
            }
            11 => {
                let b = |r: &mut Rng| r.below(70) as i32 - 3;
                glScissor(b(r), b(r), b(r), b(r));
                "glScissor"
            }
            12 => {
                glBlendFunc(r.pick(BLEND), r.pick(BLEND));
                glBlendColor(coord(r), coord(r), coord(r), coord(r));
                "glBlendFunc"
            }
            13 => {
                glDepthFunc(r.pick(FUNCS));
                glAlphaFunc(r.pick(FUNCS), coord(r));
                glStencilFunc(r.pick(FUNCS), r.below(512) as i32 - 100, r.next() as u32);
                glStencilOp(
                    r.pick(&[GL_KEEP, GL_ZERO, GL_INCR, GL_DECR, GL_INVERT, GL_REPLACE]),
                    r.pick(&[GL_KEEP, GL_INCR_WRAP, GL_DECR_WRAP]),
                    r.pick(&[GL_KEEP, GL_ZERO, GL_INCR, GL_REPLACE]),
                );
                "test funcs"
            }
            14 => {
                glClearColor(coord(r), coord(r), coord(r), coord(r));
                glClearDepth(coord(r) as f64);
                glClear(r.pick(&[
                    GL_COLOR_BUFFER_BIT,
                    GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT,
                    0x4500,
                ]));
                "glClear"
            }
            15 => {
                glCullFace(r.pick(&[GL_FRONT, GL_BACK, GL_FRONT_AND_BACK]));
                glFrontFace(r.pick(&[GL_CW, GL_CCW]));
                glShadeModel(r.pick(&[GL_FLAT, GL_SMOOTH]));
                glColorMask(r.below(2) as u8, r.below(2) as u8, 1, r.below(2) as u8);
                glDepthMask(r.below(2) as u8);
                "raster state"
            }
            16..=19 => return self.draw_arrays(),
            20 => {
                // A buffer object with random contents, bound to a random target.
                let t = r.pick(&[GL_ARRAY_BUFFER, GL_ELEMENT_ARRAY_BUFFER]);
                let mut b = 0;
                let n = r.below(4096) as usize;
                let off = r.below((VMEM / 4 - 1024) as u64) as usize;
                // SAFETY: one name; `n` bytes of `vmem` from `off` (n <= 4096 bytes).
                unsafe {
                    glGenBuffers(1, &mut b);
                    glBindBuffer(t, b);
                    glBufferData(
                        t,
                        n as isize,
                        self.vmem[off..].as_ptr().cast(),
                        GL_STREAM_DRAW,
                    );
                }
                self.buffers.push(b);
                "buffer"
            }
            21 => {
                let b = if self.buffers.is_empty() || r.chance(0.2) {
                    r.below(5) as u32
                } else {
                    r.pick(&self.buffers)
                };
                if r.chance(0.2) {
                    // SAFETY: one name.
                    unsafe { glDeleteBuffers(1, &b) };
                } else {
                    glBindBuffer(r.pick(&[GL_ARRAY_BUFFER, GL_ELEMENT_ARRAY_BUFFER]), b);
                }
                "bind/delete"
            }
            22 => {
                let t = self.target.as_ref().unwrap();
                let (w, h) = (t.w, t.h);
                let mut out = vec![0f32; (w * h * 4 + 64) as usize];
                let fmt = r.pick(&[GL_RGBA, GL_DEPTH_COMPONENT, GL_STENCIL_INDEX, GL_RGB]);
                let ty = r.pick(&[GL_UNSIGNED_BYTE, GL_FLOAT, GL_UNSIGNED_INT, GL_SHORT]);
                let (x, y) = (r.below(8) as i32 - 4, r.below(8) as i32 - 4);
                // SAFETY: pack parameters stay <= 8 (keep_harness_honest), so w x h pixels
                // of at most 16 bytes plus padding fit in `out`.
                unsafe { glReadPixels(x, y, w.min(8), h.min(8), fmt, ty, out.as_mut_ptr().cast()) };
                "glReadPixels"
            }
            23 => {
                if r.chance(0.5) {
                    glPushMatrix()
                } else {
                    glPopMatrix()
                }
                "push/pop"
            }
            24 => {
                glFinish();
                "glFinish"
            }
            25 => {
                glRectf(coord(r), coord(r), coord(r), coord(r));
                "glRectf"
            }
            26 => {
                // A new context of another size and format.
                self.retire();
                self.ensure_context();
                "new context"
            }
            27 | 28 => {
                // Back to sane transforms, so that later geometry lands on screen.
                glMatrixMode(GL_PROJECTION);
                glLoadIdentity();
                glMatrixMode(GL_MODELVIEW);
                glLoadIdentity();
                let t = self.target.as_ref().unwrap();
                glViewport(0, 0, t.w, t.h);
                glDepthRange(0.0, 1.0);
                "reset transforms"
            }
            _ => {
                let ta = self.rng.pick(&[
                    GL_VERTEX_ARRAY,
                    GL_COLOR_ARRAY,
                    GL_NORMAL_ARRAY,
                    GL_TEXTURE_COORD_ARRAY,
                ]);
                if self.rng.chance(0.7) {
                    glEnableClientState(ta)
                } else {
                    glDisableClientState(ta)
                }
                "client state"
            }
        };
        self.check(what, p0, false);
    }

    /// Points the client arrays into `vmem` (or offsets into a bound buffer) and draws.
    fn draw_arrays(&mut self) {
        let p0 = panics();
        let r = &mut self.rng;
        let base = self.vmem.as_ptr() as usize;
        let mut bound = 0;
        // SAFETY: one component.
        unsafe { glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &mut bound) };
        let ptr = |r: &mut Rng| -> *const std::ffi::c_void {
            if bound != 0 {
                (r.below(256)) as *const _
            } else {
                (base + r.below(64) as usize * 4) as *const _
            }
        };
        let stride = r.pick(&[0, 4, 12, 16, 32, 64]);
        // Client pointers stay in `vmem`, which covers 128 vertices at stride
        // <= 64 (or the default stride of at most 4 doubles) from any offset used here.
        glVertexPointer(r.pick(&[2, 3, 4]), r.pick(TYPES), stride, ptr(r));
        if r.chance(0.5) {
            glColorPointer(r.pick(&[3, 4]), r.pick(TYPES), stride, ptr(r));
        }
        if r.chance(0.2) {
            glNormalPointer(r.pick(&[GL_FLOAT, GL_BYTE]), stride, ptr(r));
        }

        if r.chance(0.8) {
            glEnableClientState(GL_VERTEX_ARRAY);
        }
        let mode = r.pick(PRIMS);
        let first = r.below(64) as i32;
        let count = r.below(64) as i32;
        let mut eb = 0;
        // SAFETY: one component.
        unsafe { glGetIntegerv(GL_ELEMENT_ARRAY_BUFFER_BINDING, &mut eb) };
        if eb != 0 && client_memory_array_enabled() {
            // Indices from a buffer are arbitrary; a client-memory array cannot be
            // bounds-checked (GL makes such a draw the program's fault), so unbind.
            glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
            eb = 0;
        }
        self.assert_arrays_honest();
        let r = &mut self.rng;
        let idx: Vec<u32> = (0..count).map(|_| r.below(128) as u32).collect();
        let idx16: Vec<u16> = idx.iter().map(|&i| i as u16).collect();
        // Client indices are < 128 (vertices inside `vmem`); element-buffer offsets
        // are bounds-checked by the library.
        match r.below(4) {
            0 | 1 => glDrawArrays(mode, first, count),
            2 if eb != 0 => glDrawElements(
                mode,
                count,
                r.pick(&[GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_UNSIGNED_INT]),
                r.below(64) as *const _,
            ),
            2 => glDrawElements(mode, count, GL_UNSIGNED_INT, idx.as_ptr().cast()),
            _ if eb == 0 => glDrawRangeElements(
                mode,
                0,
                127,
                count,
                GL_UNSIGNED_SHORT,
                idx16.as_ptr().cast(),
            ),
            _ => glDrawArrays(mode, first, count),
        }

        self.check("draw arrays", p0, false);
    }

    /// Checks the harness's side of the contract: every enabled client-memory array
    /// covers 128 vertices inside `vmem` or `scratch`.
    fn assert_arrays_honest(&self) {
        let ranges = [
            (self.vmem.as_ptr() as usize, self.vmem.len() * 4),
            (self.scratch.as_ptr() as usize, self.scratch.len() * 8),
        ];
        for (a, b, pp, sz, ty, st) in [
            (
                GL_VERTEX_ARRAY,
                GL_VERTEX_ARRAY_BUFFER_BINDING,
                GL_VERTEX_ARRAY_POINTER,
                GL_VERTEX_ARRAY_SIZE,
                GL_VERTEX_ARRAY_TYPE,
                GL_VERTEX_ARRAY_STRIDE,
            ),
            (
                GL_COLOR_ARRAY,
                GL_COLOR_ARRAY_BUFFER_BINDING,
                GL_COLOR_ARRAY_POINTER,
                GL_COLOR_ARRAY_SIZE,
                GL_COLOR_ARRAY_TYPE,
                GL_COLOR_ARRAY_STRIDE,
            ),
            (
                GL_TEXTURE_COORD_ARRAY,
                GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING,
                GL_TEXTURE_COORD_ARRAY_POINTER,
                GL_TEXTURE_COORD_ARRAY_SIZE,
                GL_TEXTURE_COORD_ARRAY_TYPE,
                GL_TEXTURE_COORD_ARRAY_STRIDE,
            ),
        ] {
            let q = |p| {
                let mut v = 0;
                // SAFETY: one component.
                unsafe { glGetIntegerv(p, &mut v) };
                v
            };
            if glIsEnabled(a) == 0 || q(b) != 0 {
                continue;
            }
            let mut ptr = std::ptr::null_mut();
            // SAFETY: one pointer.
            unsafe { glGetPointerv(pp, &mut ptr) };
            let ptr = ptr as usize;
            // Null plus an offset reads nothing (the library's null-page rule).
            if ptr < 4096 {
                continue;
            }
            let tsize = match q(ty) as u32 {
                GL_BYTE | GL_UNSIGNED_BYTE => 1,
                GL_SHORT | GL_UNSIGNED_SHORT => 2,
                GL_DOUBLE => 8,
                _ => 4,
            };
            let esize = (q(sz) * tsize) as usize;
            let stride = if q(st) == 0 { esize } else { q(st) as usize };
            let end = ptr + 128 * stride + esize;
            assert!(
                ranges.iter().any(|&(lo, n)| ptr >= lo && end <= lo + n),
                "harness: array {a:#x} at {ptr:#x} stride {stride} esize {esize} is outside its memory"
            );
        }
        while glGetError() != GL_NO_ERROR {}
    }

    fn step(&mut self) {
        self.ensure_context();
        if self.rng.chance(0.35) {
            self.table_call();
        } else {
            self.structured();
        }
        self.keep_harness_honest();
    }
}

/// Whether an enabled array reads client memory (no buffer object behind it).
fn client_memory_array_enabled() -> bool {
    [
        (GL_VERTEX_ARRAY, GL_VERTEX_ARRAY_BUFFER_BINDING),
        (GL_COLOR_ARRAY, GL_COLOR_ARRAY_BUFFER_BINDING),
        (GL_NORMAL_ARRAY, GL_NORMAL_ARRAY_BUFFER_BINDING),
        (
            GL_TEXTURE_COORD_ARRAY,
            GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING,
        ),
    ]
    .iter()
    .any(|&(a, b)| {
        let mut v = 0;
        // SAFETY: one component.
        unsafe { glGetIntegerv(b, &mut v) };
        glIsEnabled(a) != 0 && v == 0
    })
}

/// Runs `calls` fuzz calls from `seed`; returns the number of GL calls made and the
/// fragments and triangles drawn.
fn fuzz(seed: u64, calls: u64) -> (u64, (u64, u64)) {
    install_panic_counter();
    let mut f = Fuzzer::new(seed);
    while f.calls < calls {
        f.step();
    }
    f.retire();
    (f.calls, f.drawn)
}

#[test]
fn fuzz_50k_calls() {
    let (n, (frags, tris)) = fuzz(1, 50_000);
    assert!(n >= 50_000);
    assert!(
        frags > 10_000 && tris > 500,
        "the fuzzer hardly draws: {frags} {tris}"
    );
}

/// `SOFTGL_FUZZ_CALLS=N SOFTGL_FUZZ_SEED=S cargo test --release --test robust_fuzz -- --ignored`
/// (`SOFTGL_FUZZ_TRACE=1` prints every table call, to find the last one before a crash).
#[test]
#[ignore]
fn fuzz_long() {
    let calls = std::env::var("SOFTGL_FUZZ_CALLS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1_000_000);
    let seed = std::env::var("SOFTGL_FUZZ_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(2);
    let t = std::time::Instant::now();
    let (n, (frags, tris)) = fuzz(seed, calls);
    eprintln!(
        "fuzz seed {seed}: {n} calls in {:.1} s ({tris} triangles, {frags} fragments), no crash",
        t.elapsed().as_secs_f64()
    );
}

/// Regression: the long runs crashed in `glArrayElementEXT(65536)`, a hostile index the
/// harness must not pass (client arrays cover 128 vertices); aliases now stay small.
#[test]
fn aliases_of_client_memory_readers_stay_small() {
    for name in [
        "glArrayElementEXT",
        "glDrawArraysEXT",
        "glDrawRangeElementsEXT",
        "glMultiDrawArraysEXT",
        "glArrayElement",
    ] {
        assert!(must_stay_small(name), "{name}");
    }
    assert!(!must_stay_small("glBindBufferARB"));
}
