//! Shared helpers of the robustness tests: a current context with its buffer, a panic
//! counter, a small deterministic RNG, and a table of every exported function with the
//! kinds of its parameters (parsed from `src/ffi/*.rs`, so new functions are covered
//! without editing the tests) plus a caller that can invoke any of them with chosen
//! argument values.
#![allow(dead_code)]

#[path = "../../tools/ffi_expand.rs"]
mod ffi_expand;

use softgl::ffi::enums::*;
use softgl::ffi::glext_enums::*;
use softgl::ffi::osmesa::*;
use softgl::ffi::query::*;
use softgl::ffi::state::*;
use std::cell::Cell;
use std::collections::HashMap;

/// A current RGBA context with 24-bit depth and 8-bit stencil drawing into `buf`.
pub struct Ctx {
    /// The handle.
    pub ctx: OSMesaContext,
    /// The user colour buffer (w*h RGBA).
    pub buf: Vec<u8>,
    /// Width and height.
    pub w: i32,
    /// Height.
    pub h: i32,
}

impl Ctx {
    /// A `w`×`h` context with `depth` depth bits and 8 stencil bits, current on this thread.
    pub fn with_depth(w: i32, h: i32, depth: i32) -> Ctx {
        let ctx = OSMesaCreateContextExt(OSMESA_RGBA, depth, 8, 0, std::ptr::null_mut());
        assert!(!ctx.is_null());
        let mut buf = vec![0u8; (w * h * 4) as usize];
        // SAFETY: the buffer holds w*h RGBA pixels and lives as long as the binding (Drop
        // destroys the context before the buffer is freed).
        let ok = unsafe { OSMesaMakeCurrent(ctx, buf.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, w, h) };
        assert_eq!(ok, GL_TRUE as u8);
        Ctx { ctx, buf, w, h }
    }

    /// A `w`×`h` context with 24-bit depth.
    pub fn new(w: i32, h: i32) -> Ctx {
        Ctx::with_depth(w, h, 24)
    }

    /// The framebuffer as RGBA rows, bottom row first (glReadPixels).
    pub fn read(&self) -> Vec<u8> {
        let mut out = vec![0u8; (self.w * self.h * 4) as usize];
        // SAFETY: room for w*h RGBA pixels with the default pack alignment of 4.
        unsafe {
            glReadPixels(
                0,
                0,
                self.w,
                self.h,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                out.as_mut_ptr().cast(),
            )
        };
        out
    }

    /// The depth buffer as floats, bottom row first.
    pub fn read_depth(&self) -> Vec<f32> {
        let mut out = vec![0f32; (self.w * self.h) as usize];
        // SAFETY: room for w*h floats.
        unsafe {
            glReadPixels(
                0,
                0,
                self.w,
                self.h,
                GL_DEPTH_COMPONENT,
                GL_FLOAT,
                out.as_mut_ptr().cast(),
            )
        };
        out
    }
}

impl Drop for Ctx {
    fn drop(&mut self) {
        OSMesaDestroyContext(self.ctx);
    }
}

/// Drains the error flag; returns the first error.
pub fn take_error() -> u32 {
    let e = glGetError();
    while glGetError() != GL_NO_ERROR {}
    e
}

thread_local! {
    static PANICS: Cell<usize> = const { Cell::new(0) };
}

/// Installs (once) a panic hook that counts panics per thread and keeps the message.
pub fn install_panic_counter() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        let prev = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            PANICS.with(|p| p.set(p.get() + 1));
            prev(info);
        }));
    });
}

/// Panics seen on this thread so far (including ones `with_ctx` caught).
pub fn panics() -> usize {
    PANICS.with(|p| p.get())
}

/// xorshift64*: a deterministic RNG for the fuzzer and the table test.
#[derive(Clone)]
pub struct Rng(pub u64);

impl Rng {
    /// The next 64 random bits.
    pub fn next(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        self.0 = x;
        x.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    /// Uniform in `0..n` (n > 0).
    pub fn below(&mut self, n: u64) -> u64 {
        self.next() % n.max(1)
    }
    /// One element of `s`.
    pub fn pick<T: Copy>(&mut self, s: &[T]) -> T {
        s[self.below(s.len() as u64) as usize]
    }
    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
    /// True with probability `p`.
    pub fn chance(&mut self, p: f64) -> bool {
        self.unit() < p
    }
}

/// What a parameter of an exported function is, as far as calling it goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Kind {
    /// GLenum.
    Enum,
    /// GLbitfield.
    Bits,
    /// GLuint / unsigned int.
    UInt,
    /// GLint / GLsizei / int.
    Int,
    /// GLboolean / GLubyte.
    UByte,
    /// GLbyte.
    Byte,
    /// GLshort.
    Short,
    /// GLushort.
    UShort,
    /// GLintptr / GLsizeiptr.
    IntPtr,
    /// GLfloat / GLclampf.
    Float,
    /// GLdouble / GLclampd.
    Double,
    /// Any data pointer.
    Ptr,
    /// OSMesaContext.
    Ctx,
}

impl Kind {
    fn parse(t: &str) -> Kind {
        let t = t.trim();
        if t.starts_with('*') {
            return Kind::Ptr;
        }
        match t.trim_start_matches("libc::") {
            "GLenum" => Kind::Enum,
            "GLbitfield" => Kind::Bits,
            "GLuint" | "c_uint" => Kind::UInt,
            "GLint" | "GLsizei" | "c_int" => Kind::Int,
            "GLboolean" | "GLubyte" => Kind::UByte,
            "GLbyte" => Kind::Byte,
            "GLshort" => Kind::Short,
            "GLushort" => Kind::UShort,
            "GLintptr" | "GLsizeiptr" => Kind::IntPtr,
            "GLfloat" | "GLclampf" => Kind::Float,
            "GLdouble" | "GLclampd" => Kind::Double,
            "OSMesaContext" => Kind::Ctx,
            other => {
                panic!("robust_common: unknown parameter type `{other}`: add it to Kind::parse")
            }
        }
    }

    /// Whether the value travels in an integer register / slot (else a vector register).
    fn is_int(self) -> bool {
        !matches!(self, Kind::Float | Kind::Double)
    }
}

/// One argument value, already in the form the C ABI passes it.
#[derive(Clone, Copy, Debug)]
pub enum Arg {
    /// An integer or pointer, extended to 64 bits as its type requires.
    I(u64),
    /// A float.
    F(f32),
    /// A double.
    D(f64),
}

/// An exported function: name, parameter kinds, address.
#[derive(Clone, Debug)]
pub struct Func {
    /// Its C name.
    pub name: String,
    /// Its parameters.
    pub params: Vec<Kind>,
    /// Its address (from OSMesaGetProcAddress).
    pub addr: unsafe extern "C" fn(),
}

/// Every exported function with its parameter kinds, parsed from `src/ffi/*.rs`; checks
/// that the parsed set is exactly `proc_table::names()`.
pub fn functions() -> Vec<Func> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src/ffi");
    let mut sigs: HashMap<String, Vec<Kind>> = HashMap::new();
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .collect();
    files.sort();
    for path in files {
        let text = ffi_expand::expand(&std::fs::read_to_string(&path).unwrap());
        let mut rest = text.as_str();
        while let Some(i) = rest.find("extern \"C\" fn ") {
            rest = &rest[i + "extern \"C\" fn ".len()..];
            let open = rest.find('(').unwrap();
            let name = rest[..open].trim().to_string();
            let close = rest.find(')').unwrap();
            // The `$name` of a macro definition (src/ffi/families.rs) declares nothing.
            if name.starts_with('$') {
                rest = &rest[close..];
                continue;
            }
            let params: Vec<Kind> = rest[open + 1..close]
                .split(',')
                .filter(|p| p.contains(':'))
                .map(|p| Kind::parse(p.split_once(':').unwrap().1))
                .collect();
            sigs.insert(name, params);
            rest = &rest[close..];
        }
    }
    let mut out = vec![];
    for name in softgl::ffi::proc_table::names() {
        let params = sigs
            .remove(name)
            .unwrap_or_else(|| panic!("no signature found for {name}"));
        let c = std::ffi::CString::new(name).unwrap();
        // SAFETY: NUL-terminated name.
        let addr = unsafe { OSMesaGetProcAddress(c.as_ptr()) }.expect(name);
        out.push(Func {
            name: name.to_string(),
            params,
            addr,
        });
    }
    out
}

/// The universal x86-64 System V call shape: six integer registers, eight vector registers,
/// then stack slots. Any `extern "C"` function whose arguments are integers, pointers,
/// floats and doubles takes its integer arguments from the integer registers in order, its
/// floating arguments from the vector registers in order, and the rest from consecutive
/// 8-byte stack slots in declaration order; extra arguments are ignored by the callee.
type Universal = unsafe extern "C" fn(
    u64,
    u64,
    u64,
    u64,
    u64,
    u64,
    f64,
    f64,
    f64,
    f64,
    f64,
    f64,
    f64,
    f64,
    u64,
    u64,
    u64,
    u64,
    u64,
    u64,
    u64,
    u64,
) -> u64;

/// Calls `f` with `args` (one per parameter, of the matching kind) and returns the raw
/// integer return register.
///
/// # Safety
/// Pointer arguments must satisfy the function's contract for the other arguments.
#[cfg(all(target_arch = "x86_64", unix))]
pub unsafe fn call(f: &Func, args: &[Arg]) -> u64 {
    assert_eq!(args.len(), f.params.len(), "{}", f.name);
    let (mut ints, mut flts, mut stack) = (Vec::new(), Vec::new(), Vec::new());
    for (k, a) in f.params.iter().zip(args) {
        let (bits, int) = match *a {
            Arg::I(v) => (v, true),
            Arg::F(v) => (v.to_bits() as u64, false),
            Arg::D(v) => (v.to_bits(), false),
        };
        assert_eq!(int, k.is_int(), "{}: argument kind", f.name);
        if int && ints.len() < 6 {
            ints.push(bits);
        } else if !int && flts.len() < 8 {
            flts.push(f64::from_bits(bits));
        } else {
            stack.push(bits);
        }
    }
    assert!(stack.len() <= 8, "{}: too many stack arguments", f.name);
    ints.resize(6, 0);
    flts.resize(8, 0.0);
    stack.resize(8, 0);
    // SAFETY: see `Universal`: on x86-64 System V this call passes exactly the arguments
    // the real function reads (integers are extended to 64 bits by `Arg`), and the caller
    // cleans up the stack, so the extra arguments are harmless.
    unsafe {
        let u: Universal = std::mem::transmute(f.addr);
        u(
            ints[0], ints[1], ints[2], ints[3], ints[4], ints[5], flts[0], flts[1], flts[2],
            flts[3], flts[4], flts[5], flts[6], flts[7], stack[0], stack[1], stack[2], stack[3],
            stack[4], stack[5], stack[6], stack[7],
        )
    }
}

/// Enum values worth trying: garbage and a spread of real ones.
pub const ENUMS: &[u32] = &[
    0,
    1,
    0xFFFF_FFFF,
    0xDEAD,
    GL_TRIANGLES,
    GL_POLYGON,
    GL_POLYGON + 1,
    GL_QUADS,
    GL_LINES,
    GL_POINTS,
    GL_FLOAT,
    GL_DOUBLE,
    GL_SHORT,
    GL_INT,
    GL_UNSIGNED_BYTE,
    GL_UNSIGNED_SHORT,
    GL_UNSIGNED_INT,
    GL_ARRAY_BUFFER,
    GL_ELEMENT_ARRAY_BUFFER,
    GL_RGBA,
    GL_RGB,
    GL_COMPRESSED_RGBA_S3TC_DXT5_EXT,
    GL_COMPRESSED_SIGNED_RG_RGTC2,
    GL_DEPTH_COMPONENT,
    GL_STENCIL_INDEX,
    GL_MODELVIEW,
    GL_PROJECTION,
    GL_TEXTURE,
    GL_BLEND,
    GL_DEPTH_TEST,
    GL_CULL_FACE,
    GL_STENCIL_TEST,
    GL_SCISSOR_TEST,
    GL_VERTEX_ARRAY,
    GL_COLOR_ARRAY,
    GL_V3F,
    GL_T4F_C4F_N3F_V4F,
    GL_READ_WRITE,
    GL_STATIC_DRAW,
    GL_BUFFER_SIZE,
    GL_VIEWPORT,
    GL_FRONT_AND_BACK,
    GL_FRONT,
    GL_ZERO,
    GL_ONE,
    GL_SRC_ALPHA,
    GL_FUNC_ADD,
    GL_LESS,
    GL_ALWAYS,
    GL_KEEP,
    GL_INCR,
    GL_XOR,
    GL_NICEST,
    GL_PACK_ALIGNMENT,
    GL_UNPACK_ALIGNMENT,
    GL_PACK_ROW_LENGTH,
    GL_VENDOR,
    GL_EXTENSIONS,
    GL_VERTEX_ARRAY_POINTER,
    GL_BUFFER_MAP_POINTER,
    GL_FLAT,
    GL_CCW,
];

/// Integer values worth trying (sizes, counts, offsets, coordinates).
pub const INTS: &[i64] = &[
    0,
    1,
    2,
    3,
    4,
    -1,
    -2,
    7,
    8,
    16,
    255,
    65535,
    65536,
    i32::MAX as i64,
    i32::MIN as i64,
    1 << 20,
    -(1 << 20),
];

/// Float values worth trying.
pub const FLOATS: &[f64] = &[
    0.0,
    1.0,
    -1.0,
    0.5,
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    1e38,
    -1e38,
    1e300,
    1e-45,
    1e7,
    -1e7,
    2.0,
];

/// A hostile value of kind `k`. With `small`, sizes stay within what a 64 KiB scratch
/// buffer can serve, so that a non-null pointer argument is honest.
pub fn hostile(rng: &mut Rng, k: Kind, small: bool, ptr: u64, ctx: u64) -> Arg {
    let int = |rng: &mut Rng| {
        if small {
            rng.pick(&[0i64, 1, 2, 3, 4, -1, -7, 7])
        } else {
            rng.pick(INTS)
        }
    };
    match k {
        Kind::Enum => Arg::I(rng.pick(ENUMS) as u64),
        Kind::Bits => {
            Arg::I(rng.pick(&[0u32, 0xFFFF_FFFF, 0x4100, 0x4000, 0x100, 0x400, 0x8]) as u64)
        }
        Kind::UInt => Arg::I(if small {
            rng.pick(&[0u32, 1, 2, 3, 0xFF, 0xFFFF_FFFF])
        } else {
            rng.pick(INTS) as u32
        } as u64),
        Kind::Int => Arg::I(int(rng) as i32 as i64 as u64),
        Kind::UByte => Arg::I(rng.pick(&[0u8, 1, 2, 255, 128]) as u64),
        Kind::Byte => Arg::I(rng.pick(&[0i8, 1, -1, 127, -128]) as i64 as u64),
        Kind::Short => Arg::I(rng.pick(&[0i16, 1, -1, i16::MAX, i16::MIN]) as i64 as u64),
        Kind::UShort => Arg::I(rng.pick(&[0u16, 1, 0xFFFF]) as u64),
        Kind::IntPtr => Arg::I(if small {
            int(rng)
        } else {
            rng.pick(&[
                0i64,
                -1,
                1,
                16,
                isize::MAX as i64,
                isize::MIN as i64,
                1 << 40,
            ])
        } as u64),
        Kind::Float => Arg::F(rng.pick(FLOATS) as f32),
        Kind::Double => Arg::D(rng.pick(FLOATS)),
        Kind::Ptr => Arg::I(ptr),
        Kind::Ctx => Arg::I(rng.pick(&[0u64, ctx, 0xDEAD_BEE0, ctx.wrapping_add(8)])),
    }
}
