//! Hostile API input: every exported function called with invalid enums, negative and
//! huge sizes, NaN/Inf, null pointers and stale handles; with and without a current
//! context. Checks: nothing panics (a panic caught by `with_ctx` would surface as
//! GL_OUT_OF_MEMORY), GL_OUT_OF_MEMORY only where an allocation really is too large, a
//! call that records an error leaves all queryable state and the pixels unchanged, and a
//! garbage enum is never accepted silently. Plus hand-written cases for the rules the
//! table cannot know (the exact error the spec names).
#![cfg(all(target_arch = "x86_64", unix))]

mod robust_common;

use robust_common::*;
use softgl::ffi::buffers::*;
use softgl::ffi::draw::*;
use softgl::ffi::enums::*;
use softgl::ffi::glext_enums::*;
use softgl::ffi::immediate::*;
use softgl::ffi::multidraw::*;
use softgl::ffi::osmesa::*;
use softgl::ffi::query::*;
use softgl::ffi::state::*;
use std::sync::OnceLock;

/// The pnames glGetDoublev accepts and the caps glIsEnabled knows (found by asking the
/// library about every value below 0x10000, so that new state is covered automatically).
fn queryable() -> &'static (Vec<u32>, Vec<u32>) {
    static Q: OnceLock<(Vec<u32>, Vec<u32>)> = OnceLock::new();
    Q.get_or_init(|| {
        let _c = Ctx::new(16, 16);
        let mut pn = vec![];
        let mut caps = vec![];
        let mut buf = [0f64; 64];
        take_error();
        for p in 0..0x10000u32 {
            // SAFETY: 64 doubles is more than any GL 1.5 query returns.
            unsafe { glGetDoublev(p, buf.as_mut_ptr()) };
            if glGetError() == GL_NO_ERROR {
                pn.push(p);
            }
            glIsEnabled(p);
            if glGetError() == GL_NO_ERROR {
                caps.push(p);
            }
        }
        assert!(
            pn.len() > 100 && caps.len() > 10,
            "{} {}",
            pn.len(),
            caps.len()
        );
        (pn, caps)
    })
}

/// Everything a program can observe without drawing: every glGetDoublev value, every
/// glIsEnabled cap, both buffer bindings' sizes, the client-array pointers and the pixels.
fn snapshot() -> Vec<u64> {
    let (pn, caps) = queryable();
    let mut out = vec![];
    let mut buf = [0f64; 64];
    for &p in pn {
        buf.fill(-12345.0);
        // SAFETY: room for any query.
        unsafe { glGetDoublev(p, buf.as_mut_ptr()) };
        out.push(p as u64);
        out.extend(
            buf.iter()
                .take_while(|v| **v != -12345.0)
                .map(|v| v.to_bits()),
        );
    }
    for &c in caps {
        out.push(glIsEnabled(c) as u64);
    }
    for t in [GL_ARRAY_BUFFER, GL_ELEMENT_ARRAY_BUFFER] {
        for q in [
            GL_BUFFER_SIZE,
            GL_BUFFER_USAGE,
            GL_BUFFER_MAPPED,
            GL_BUFFER_ACCESS,
        ] {
            let mut v = -7;
            // SAFETY: one component.
            unsafe { glGetBufferParameteriv(t, q, &mut v) };
            out.push(v as u64);
        }
    }
    for p in [
        GL_VERTEX_ARRAY_POINTER,
        GL_COLOR_ARRAY_POINTER,
        GL_NORMAL_ARRAY_POINTER,
        GL_TEXTURE_COORD_ARRAY_POINTER,
    ] {
        let mut v = std::ptr::null_mut();
        // SAFETY: one pointer.
        unsafe { glGetPointerv(p, &mut v) };
        out.push(v as u64);
    }
    // The reads below use the default pack state (a hostile glPixelStore may have set
    // skips or a row length that would write past these buffers); it is put back after.
    const PACK: [u32; 8] = [
        GL_PACK_SWAP_BYTES,
        GL_PACK_LSB_FIRST,
        GL_PACK_ROW_LENGTH,
        GL_PACK_SKIP_ROWS,
        GL_PACK_SKIP_PIXELS,
        GL_PACK_ALIGNMENT,
        GL_PACK_IMAGE_HEIGHT,
        GL_PACK_SKIP_IMAGES,
    ];
    const PACK_DEFAULTS: [i32; 8] = [0, 0, 0, 0, 0, 4, 0, 0];
    let mut pack = [0i32; 8];
    for ((p, v), d) in PACK.iter().zip(&mut pack).zip(PACK_DEFAULTS) {
        // SAFETY: one component.
        unsafe { glGetIntegerv(*p, v) };
        glPixelStorei(*p, d);
    }
    let mut px = vec![0u8; 16 * 16 * 4];
    // SAFETY: room for 16x16 RGBA (the contexts here are 16x16).
    unsafe {
        glReadPixels(
            0,
            0,
            16,
            16,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            px.as_mut_ptr().cast(),
        )
    };
    let mut z = vec![0u32; 16 * 16];
    // SAFETY: room for 16x16 uints.
    unsafe {
        glReadPixels(
            0,
            0,
            16,
            16,
            GL_DEPTH_COMPONENT,
            GL_UNSIGNED_INT,
            z.as_mut_ptr().cast(),
        )
    };
    out.extend(
        px.chunks(8)
            .map(|c| u64::from_ne_bytes(c.try_into().unwrap())),
    );
    out.extend(z.iter().map(|&v| v as u64));
    for (p, v) in PACK.iter().zip(pack) {
        glPixelStorei(*p, v);
    }
    take_error();
    out
}

/// Functions that may report GL_OUT_OF_MEMORY for a request that cannot be allocated.
const ALLOCATING: &[&str] = &[
    "glBufferData",
    "glDrawArrays",
    "glDrawElements",
    "glDrawRangeElements",
    "glMultiDrawArrays",
    "glMultiDrawElements",
];

/// Puts the context back into a state where queries work: ends an open glBegin and
/// unmaps mapped buffers (a hostile round may have done either).
fn settle() {
    glEnd();
    glUnmapBuffer(GL_ARRAY_BUFFER);
    glUnmapBuffer(GL_ELEMENT_ARRAY_BUFFER);
    take_error();
}

/// Some state to make the snapshot meaningful: a buffer bound to each target, a drawn
/// triangle in the colour and depth buffers, client arrays from a buffer.
fn populate() -> [u32; 2] {
    let mut b = [0u32; 2];
    let verts: [f32; 9] = [-1.0, -1.0, 0.0, 1.0, -1.0, 0.5, 0.0, 1.0, 0.2];
    let idx: [u16; 3] = [0, 1, 2];
    // SAFETY: pointers valid for the sizes given.
    unsafe {
        glGenBuffers(2, b.as_mut_ptr());
        glBindBuffer(GL_ARRAY_BUFFER, b[0]);
        glBufferData(GL_ARRAY_BUFFER, 36, verts.as_ptr().cast(), GL_STATIC_DRAW);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[1]);
        glBufferData(
            GL_ELEMENT_ARRAY_BUFFER,
            6,
            idx.as_ptr().cast(),
            GL_STATIC_DRAW,
        );
        softgl::ffi::arrays::glVertexPointer(3, GL_FLOAT, 0, std::ptr::null());
    }
    softgl::ffi::arrays::glEnableClientState(GL_VERTEX_ARRAY);
    glEnable(GL_DEPTH_TEST);
    glClearColor(0.1, 0.2, 0.3, 0.4);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glColor4f(0.9, 0.5, 0.1, 1.0);
    // Indices come from the bound element buffer (offset 0).
    glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, std::ptr::null());
    assert_eq!(take_error(), GL_NO_ERROR);
    b
}

/// A summary of what the table run found, for the assertion message.
#[derive(Default)]
struct Findings {
    calls: usize,
    errors: usize,
    problems: Vec<String>,
}

fn run_function(f: &Func, rounds: usize, seed: u64, find: &mut Findings) {
    // Declared before the context: the context may be re-bound to it and must die first.
    let mut scratch = vec![0u64; 8192];
    let c = Ctx::new(16, 16);
    populate();
    let mut rng = Rng(seed ^ 0x9E37_79B9_7F4A_7C15);
    let handle = c.ctx as u64;
    for round in 0..rounds {
        scratch.fill(0);
        let small = round % 2 == 1;
        let ptr = if small {
            scratch.as_mut_ptr() as u64
        } else {
            0
        };
        let args: Vec<Arg> = f
            .params
            .iter()
            .map(|&k| hostile(&mut rng, k, small, ptr, handle))
            .collect();
        settle();
        let before = snapshot();
        let p0 = panics();
        // SAFETY: pointers are null or a zeroed 64 KiB buffer, and with a non-null pointer
        // every size argument is below 8, so the buffer covers what the call may touch.
        let ret = unsafe { call(f, &args) };
        find.calls += 1;
        if f.name.starts_with("OSMesaCreateContext") {
            OSMesaDestroyContext(ret as OSMesaContext);
        }
        if f.name.starts_with("OSMesa") {
            // OSMesa calls report through return values, not glGetError; they may have
            // re-bound or destroyed the context: the table only checks they do not panic.
            if panics() != p0 {
                find.problems.push(format!("{} {args:?}: panicked", f.name));
            }
            continue;
        }
        let err = take_error();
        if panics() != p0 {
            find.problems
                .push(format!("{} {args:?}: panicked (error {err:#x})", f.name));
            continue;
        }
        if err == GL_OUT_OF_MEMORY {
            let huge = args.iter().zip(&f.params).any(|(a, k)| match (a, k) {
                (Arg::I(v), Kind::IntPtr) => (*v as i64).unsigned_abs() >= 1 << 30,
                (Arg::I(v), Kind::Int) => (*v as i64).unsigned_abs() >= 1 << 16,
                _ => false,
            });
            // An ARB/EXT alias allocates as its core function does.
            let core = f.name.trim_end_matches("EXT").trim_end_matches("ARB");
            if !(ALLOCATING.contains(&core) && huge) {
                find.problems
                    .push(format!("{} {args:?}: GL_OUT_OF_MEMORY", f.name));
            }
        }
        let garbage_enum = args.iter().zip(&f.params).any(|(a, k)| {
            *k == Kind::Enum && matches!(a, Arg::I(v) if *v == 0xFFFF_FFFF || *v == 0xDEAD)
        });
        // A null pointer is itself undefined in GL; softgl then ignores the whole call
        // (Mesa would crash), so the enum rule applies with real pointers only.
        let null_ptr = !small && f.params.contains(&Kind::Ptr);
        // glMultiTexCoord* takes the target's low three bits as the unit with no error,
        // as Mesa does (`vbo_attrib_tmp.h`: `(target & 0x7) + VBO_ATTRIB_TEX0`).
        let masks_enum = f.name.starts_with("glMultiTexCoord");
        if garbage_enum && err == GL_NO_ERROR && !null_ptr && f.name != "glGetError" && !masks_enum
        {
            find.problems
                .push(format!("{} {args:?}: garbage enum accepted", f.name));
        }
        if err != GL_NO_ERROR {
            find.errors += 1;
            settle();
            if snapshot() != before {
                find.problems.push(format!(
                    "{} {args:?}: error {err:#x} but state changed",
                    f.name
                ));
            }
        }
    }
    drop(c);
    drop(scratch);
}

#[test]
fn every_function_survives_hostile_arguments() {
    install_panic_counter();
    let fns = functions();
    assert!(fns.len() > 200, "{} functions", fns.len());
    let mut find = Findings::default();
    for (i, f) in fns.iter().enumerate() {
        if std::env::var_os("SOFTGL_ROBUST_TRACE").is_some() {
            eprintln!("{}", f.name);
        }
        run_function(f, 128, i as u64 + 1, &mut find);
    }
    eprintln!(
        "{} functions, {} calls, {} recorded an error, {} pnames, {} caps",
        fns.len(),
        find.calls,
        find.errors,
        queryable().0.len(),
        queryable().1.len()
    );
    find.problems.sort();
    find.problems
        .dedup_by(|a, b| a.split(' ').next() == b.split(' ').next());
    assert!(
        find.problems.is_empty(),
        "{} calls, {} errors, problems (first per function):\n{}",
        find.calls,
        find.errors,
        find.problems.join("\n")
    );
}

#[test]
fn without_a_context_every_function_is_a_no_op() {
    install_panic_counter();
    // SAFETY: unbinding.
    let ok = unsafe { OSMesaMakeCurrent(std::ptr::null_mut(), std::ptr::null_mut(), 0, 0, 0) };
    assert_eq!(ok, 1);
    let mut scratch = vec![0xA5A5_A5A5_A5A5_A5A5u64; 8192];
    let mut rng = Rng(7);
    let p0 = panics();
    for f in functions() {
        if f.name.starts_with("OSMesa") {
            continue;
        }
        for round in 0..8 {
            let small = round % 2 == 1;
            let ptr = if small {
                scratch.as_mut_ptr() as u64
            } else {
                0
            };
            let args: Vec<Arg> = f
                .params
                .iter()
                .map(|&k| hostile(&mut rng, k, small, ptr, 0))
                .collect();
            // SAFETY: as in the table test.
            let ret = unsafe { call(&f, &args) };
            // Value-returning calls give 0 (FALSE, GL_NO_ERROR, NULL) without a context.
            let ret_ok = match f.name.as_str() {
                "glIsEnabled" | "glIsBuffer" | "glUnmapBuffer" => ret as u8 == 0,
                "glGetError" => ret as u32 == 0,
                "glGetString" | "glMapBuffer" => ret == 0,
                _ => true,
            };
            assert!(ret_ok, "{} returned {ret:#x} without a context", f.name);
            assert!(
                scratch.iter().all(|&v| v == 0xA5A5_A5A5_A5A5_A5A5),
                "{} {args:?} wrote through a pointer without a context",
                f.name
            );
        }
    }
    assert_eq!(panics(), p0, "a call without a context panicked");
    assert!(
        scratch.iter().all(|&v| v == 0xA5A5_A5A5_A5A5_A5A5),
        "a call without a context wrote through a pointer"
    );
    assert_eq!(glGetError(), GL_NO_ERROR);
    assert!(OSMesaGetCurrentContext().is_null());
}

#[test]
fn buffer_data_too_large_is_out_of_memory_and_keeps_the_store() {
    let _c = Ctx::new(16, 16);
    let mut b = 0;
    // SAFETY: one name; pointers valid for the sizes given.
    unsafe {
        glGenBuffers(1, &mut b);
        glBindBuffer(GL_ARRAY_BUFFER, b);
        glBufferData(GL_ARRAY_BUFFER, 8, [1u8; 8].as_ptr().cast(), GL_STATIC_DRAW);
    }
    for size in [isize::MAX, isize::MAX - 15, 1 << 50] {
        // SAFETY: the request fails before the null data pointer matters.
        unsafe { glBufferData(GL_ARRAY_BUFFER, size, std::ptr::null(), GL_STATIC_DRAW) };
        assert_eq!(take_error(), GL_OUT_OF_MEMORY, "size {size}");
    }
    // SAFETY: as above.
    unsafe {
        glBufferData(
            GL_ARRAY_BUFFER,
            isize::MIN,
            std::ptr::null(),
            GL_STATIC_DRAW,
        )
    };
    assert_eq!(take_error(), GL_INVALID_VALUE);
    let mut size = 0;
    let mut back = [0u8; 8];
    // SAFETY: one component; 8 bytes.
    unsafe {
        glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &mut size);
        glGetBufferSubData(GL_ARRAY_BUFFER, 0, 8, back.as_mut_ptr().cast());
        glGetBufferSubData(GL_ARRAY_BUFFER, 4, 8, back.as_mut_ptr().cast());
    }
    assert_eq!(take_error(), GL_INVALID_VALUE, "read past the end");
    assert_eq!((size, back), (8, [1u8; 8]));
    // SubData ranges that overflow when added.
    // SAFETY: rejected before the pointer is read.
    unsafe {
        glBufferSubData(
            GL_ARRAY_BUFFER,
            isize::MAX,
            isize::MAX,
            back.as_ptr().cast(),
        )
    };
    assert_eq!(take_error(), GL_INVALID_VALUE);
}

/// Three vertices in a buffer, and element buffers with out-of-range indices and offsets.
#[test]
fn draw_elements_out_of_range_stays_in_bounds() {
    install_panic_counter();
    let c = Ctx::new(16, 16);
    populate();
    let before = c.read();
    let p0 = panics();
    let idx: [u32; 6] = [0, 1, 2, 3, 1_000_000_000, u32::MAX];
    let mut eb = 0;
    // SAFETY: pointers valid for the sizes given; element offsets are bounds-checked.
    unsafe {
        glGenBuffers(1, &mut eb);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, eb);
        glBufferData(
            GL_ELEMENT_ARRAY_BUFFER,
            24,
            idx.as_ptr().cast(),
            GL_STATIC_DRAW,
        );
        for ty in [GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_UNSIGNED_INT] {
            for off in [0usize, 3, 12, 23, 24, 25, 1000, usize::MAX / 2, usize::MAX] {
                for count in [0, 1, 3, 6, 7, 1 << 20] {
                    glDrawElements(GL_TRIANGLES, count, ty, off as *const _);
                    let e = take_error();
                    assert!(
                        e == GL_NO_ERROR || e == GL_INVALID_OPERATION,
                        "type {ty:#x} offset {off} count {count}: {e:#x}"
                    );
                    glDrawRangeElements(GL_TRIANGLES, 0, 2, count, ty, off as *const _);
                    let e = take_error();
                    assert!(
                        e == GL_NO_ERROR || e == GL_INVALID_OPERATION,
                        "range: type {ty:#x} offset {off} count {count}: {e:#x}"
                    );
                }
            }
        }
        // Vertex array offset past the end of its buffer.
        softgl::ffi::arrays::glVertexPointer(3, GL_FLOAT, 0, 1_000_000 as *const _);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glDrawArrays(GL_TRIANGLES, i32::MAX - 1, 3);
        softgl::ffi::arrays::glVertexPointer(4, GL_DOUBLE, i32::MAX, usize::MAX as *const _);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glDrawArrays(GL_TRIANGLES, i32::MAX - 1, 3);
    }
    take_error();
    assert_eq!(panics(), p0, "out-of-range drawing panicked");
    glFinish();
    let _ = before;
}

#[test]
fn begin_end_nesting() {
    let _c = Ctx::new(16, 16);
    glBegin(GL_TRIANGLES);
    glBegin(GL_TRIANGLES);
    assert_eq!(
        {
            glEnd();
            take_error()
        },
        GL_INVALID_OPERATION,
        "nested glBegin"
    );
    glEnd();
    assert_eq!(take_error(), GL_INVALID_OPERATION, "glEnd without glBegin");
    glBegin(GL_TRIANGLES);
    let mut v = [0i32; 4];
    // SAFETY: 4 components.
    unsafe { glGetIntegerv(GL_VIEWPORT, v.as_mut_ptr()) };
    glEnd();
    assert_eq!(take_error(), GL_INVALID_OPERATION, "glGet inside glBegin");
    assert_eq!(v, [0; 4], "a failed glGet writes nothing");
    glBegin(GL_TRIANGLES);
    glVertex2f(0.0, 0.0);
    // Buffer calls are not allowed between glBegin and glEnd.
    let mut b = 0;
    // SAFETY: one name.
    unsafe { glGenBuffers(1, &mut b) };
    glEnd();
    assert_eq!(take_error(), GL_INVALID_OPERATION);
    assert_eq!(b, 0);
}

#[test]
fn deleted_and_unknown_names() {
    let _c = Ctx::new(16, 16);
    let mut b = [0u32; 3];
    // SAFETY: room for the names given.
    unsafe {
        glGenBuffers(3, b.as_mut_ptr());
        glBindBuffer(GL_ARRAY_BUFFER, b[0]);
        glBufferData(GL_ARRAY_BUFFER, 4, std::ptr::null(), GL_STATIC_DRAW);
        glDeleteBuffers(3, b.as_ptr());
    }
    assert_eq!(take_error(), GL_NO_ERROR);
    let mut bound = -1;
    // SAFETY: one component.
    unsafe { glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &mut bound) };
    assert_eq!(bound, 0, "deleting a bound buffer unbinds it");
    assert_eq!(glIsBuffer(b[0]), 0);
    assert_eq!(glIsBuffer(0xFFFF_FFFF), 0);
    // SAFETY: deleting unknown names and 0 is allowed and ignored.
    unsafe { glDeleteBuffers(2, [0u32, 0xFFFF_FFF0].as_ptr()) };
    assert_eq!(take_error(), GL_NO_ERROR);
    // No buffer bound: data calls are INVALID_OPERATION.
    // SAFETY: rejected before the pointers are used.
    unsafe {
        glBufferData(GL_ARRAY_BUFFER, 4, std::ptr::null(), GL_STATIC_DRAW);
        assert_eq!(take_error(), GL_INVALID_OPERATION);
        glBufferSubData(GL_ARRAY_BUFFER, 0, 4, [0u8; 4].as_ptr().cast());
        assert_eq!(take_error(), GL_INVALID_OPERATION);
        assert!(glMapBuffer(GL_ARRAY_BUFFER, GL_READ_WRITE).is_null());
        assert_eq!(take_error(), GL_INVALID_OPERATION);
        glGenBuffers(-1, b.as_mut_ptr());
        assert_eq!(take_error(), GL_INVALID_VALUE);
        glDeleteBuffers(-1, b.as_ptr());
        assert_eq!(take_error(), GL_INVALID_VALUE);
        // Null name arrays with a positive count: nothing written or read, no crash.
        glGenBuffers(4, std::ptr::null_mut());
        glDeleteBuffers(4, std::ptr::null());
        take_error();
    }
}

#[test]
fn null_pointers_where_the_api_takes_pointers() {
    install_panic_counter();
    let c = Ctx::new(16, 16);
    populate();
    let before = c.read();
    let p0 = panics();
    // SAFETY: every pointer is null: the library must not dereference it.
    unsafe {
        glVertex3fv(std::ptr::null());
        glColor4ubv(std::ptr::null());
        glGetIntegerv(GL_VIEWPORT, std::ptr::null_mut());
        glGetDoublev(GL_MODELVIEW_MATRIX, std::ptr::null_mut());
        glReadPixels(
            0,
            0,
            16,
            16,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            std::ptr::null_mut(),
        );
        glReadPixels(
            0,
            0,
            i32::MAX,
            i32::MAX,
            GL_RGBA,
            GL_FLOAT,
            std::ptr::null_mut(),
        );
        softgl::ffi::matrix::glLoadMatrixf(std::ptr::null());
        softgl::ffi::matrix::glMultMatrixd(std::ptr::null());
        glMultiDrawArrays(GL_TRIANGLES, std::ptr::null(), std::ptr::null(), 5);
        glMultiDrawElements(
            GL_TRIANGLES,
            std::ptr::null(),
            GL_UNSIGNED_SHORT,
            std::ptr::null(),
            5,
        );
        glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, std::ptr::null_mut());
        assert!(OSMesaGetProcAddress(std::ptr::null()).is_none());
        OSMesaGetIntegerv(OSMESA_WIDTH, std::ptr::null_mut());
        OSMesaGetColorBuffer(
            c.ctx,
            std::ptr::null_mut(),
            std::ptr::null_mut(),
            std::ptr::null_mut(),
            std::ptr::null_mut(),
        );
        OSMesaGetDepthBuffer(
            c.ctx,
            std::ptr::null_mut(),
            std::ptr::null_mut(),
            std::ptr::null_mut(),
            std::ptr::null_mut(),
        );
    }
    take_error();
    assert_eq!(panics(), p0);
    assert_eq!(c.read(), before, "null pointers drew something");
}

#[test]
fn contexts_destroyed_twice_and_across_threads() {
    let a = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, std::ptr::null_mut());
    assert!(!a.is_null());
    OSMesaDestroyContext(a);
    OSMesaDestroyContext(a);
    OSMesaDestroyContext(std::ptr::null_mut());
    OSMesaDestroyContext(0x1000 as OSMesaContext);
    // SAFETY: a destroyed handle is rejected before the buffer matters.
    let ok = unsafe { OSMesaMakeCurrent(a, [0u8; 64].as_mut_ptr().cast(), GL_UNSIGNED_BYTE, 4, 4) };
    assert_eq!(ok, 0, "a destroyed context cannot be made current");

    // One context, two threads: the second cannot claim it while the first has it.
    let ctx = OSMesaCreateContext(OSMESA_RGBA, std::ptr::null_mut());
    let h = ctx as usize;
    let (tx, rx) = std::sync::mpsc::channel::<()>();
    let (tx2, rx2) = std::sync::mpsc::channel::<()>();
    let t = std::thread::spawn(move || {
        let mut buf = vec![0u8; 8 * 8 * 4];
        // SAFETY: buffer of 8x8 RGBA, unbound below before it is freed.
        let ok = unsafe {
            OSMesaMakeCurrent(
                h as OSMesaContext,
                buf.as_mut_ptr().cast(),
                GL_UNSIGNED_BYTE,
                8,
                8,
            )
        };
        assert_eq!(ok, 1);
        tx.send(()).unwrap();
        rx2.recv().unwrap();
        // The other thread destroyed the handle meanwhile: this thread still has a
        // working context until it lets go.
        glClearColor(1.0, 0.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glFinish();
        assert_eq!(&buf[..4], &[255, 0, 0, 255]);
        // SAFETY: unbinding.
        unsafe { OSMesaMakeCurrent(std::ptr::null_mut(), std::ptr::null_mut(), 0, 0, 0) };
        drop(buf);
    });
    rx.recv().unwrap();
    let mut buf = vec![0u8; 8 * 8 * 4];
    // SAFETY: 8x8 RGBA buffer; the call must fail.
    let ok = unsafe { OSMesaMakeCurrent(ctx, buf.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, 8, 8) };
    assert_eq!(
        ok, 0,
        "a context current on another thread cannot be made current"
    );
    OSMesaDestroyContext(ctx);
    OSMesaDestroyContext(ctx);
    tx2.send(()).unwrap();
    t.join().unwrap();
    // SAFETY: the handle was unregistered: rejected.
    let ok = unsafe { OSMesaMakeCurrent(ctx, buf.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, 8, 8) };
    assert_eq!(ok, 0);
}

#[test]
fn osmesa_bad_arguments() {
    // SAFETY: a zero-terminated attribute list.
    let c = unsafe {
        OSMesaCreateContextAttribs([OSMESA_DEPTH_BITS, -5, 0].as_ptr(), std::ptr::null_mut())
    };
    assert!(c.is_null());
    assert!(OSMesaCreateContextExt(0xDEAD, 16, 0, 0, std::ptr::null_mut()).is_null());
    // Absurd bit counts: either a context with the largest supported buffers or NULL.
    OSMesaDestroyContext(OSMesaCreateContextExt(
        OSMESA_RGBA,
        i32::MAX,
        i32::MAX,
        i32::MAX,
        std::ptr::null_mut(),
    ));
    let c = Ctx::new(16, 16);
    let mut buf = vec![0u8; 16];
    // SAFETY: each call fails before the buffer matters, or binds 2x2 RGBA (16 bytes).
    unsafe {
        assert_eq!(
            OSMesaMakeCurrent(c.ctx, buf.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, -1, 2),
            0
        );
        assert_eq!(
            OSMesaMakeCurrent(c.ctx, buf.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, 1 << 20, 2),
            0
        );
        assert_eq!(
            OSMesaMakeCurrent(c.ctx, buf.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, 2, 2),
            1
        );
    }
    OSMesaPixelStore(OSMESA_ROW_LENGTH, -1);
    assert_eq!(take_error(), GL_INVALID_VALUE);
    OSMesaPixelStore(0x7777, 1);
    assert_eq!(take_error(), GL_INVALID_ENUM);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    // SAFETY: re-bind to the context's own buffer before `buf` goes away.
    unsafe { OSMesaMakeCurrent(c.ctx, c.buf.as_ptr() as *mut _, GL_UNSIGNED_BYTE, c.w, c.h) };
    drop(buf);
}
