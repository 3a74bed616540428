//! Texturing through the exported C functions: objects, uploads and readback, parameters,
//! environment, texture units, GL errors, and the plan the rasterizer will use.

use softgl::ffi::enums::*;
use softgl::ffi::glext_enums::*;
use softgl::ffi::osmesa::*;
use softgl::ffi::query::*;
use softgl::ffi::state::*;
use softgl::ffi::textures::*;

struct Ctx {
    ctx: OSMesaContext,
    _buf: Vec<u8>,
}

impl Ctx {
    fn new() -> Ctx {
        let ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, std::ptr::null_mut());
        assert!(!ctx.is_null());
        let mut buf = vec![0u8; 16 * 16 * 4];
        // SAFETY: the buffer holds 16x16 RGBA pixels and outlives the binding.
        let ok =
            unsafe { OSMesaMakeCurrent(ctx, buf.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, 16, 16) };
        assert_eq!(ok, GL_TRUE as u8);
        Ctx { ctx, _buf: buf }
    }
}

impl Drop for Ctx {
    fn drop(&mut self) {
        OSMesaDestroyContext(self.ctx);
    }
}

fn get_i(pname: u32) -> i32 {
    let mut v = [0i32; 4];
    // SAFETY: at most 4 components.
    unsafe { glGetIntegerv(pname, v.as_mut_ptr()) };
    v[0]
}

fn level_i(level: i32, pname: u32) -> i32 {
    let mut v = 0;
    // SAFETY: one value.
    unsafe { glGetTexLevelParameteriv(GL_TEXTURE_2D, level, pname, &mut v) };
    v
}

fn new_texture() -> u32 {
    let mut t = 0;
    // SAFETY: room for one name.
    unsafe { glGenTextures(1, &mut t) };
    glBindTexture(GL_TEXTURE_2D, t);
    t
}

#[test]
fn objects_binding_and_errors() {
    let _c = Ctx::new();
    let mut names = [0u32; 2];
    // SAFETY: room for 2 names.
    unsafe { glGenTextures(2, names.as_mut_ptr()) };
    assert!(names[0] != 0 && names[0] != names[1]);
    assert_eq!(glIsTexture(names[0]), 0, "not a texture until bound");
    glBindTexture(GL_TEXTURE_2D, names[0]);
    assert_eq!(glIsTexture(names[0]), 1);
    assert_eq!(get_i(GL_TEXTURE_BINDING_2D), names[0] as i32);
    glBindTexture(GL_TEXTURE_1D, names[0]);
    assert_eq!(glGetError(), GL_INVALID_OPERATION);
    glBindTexture(GL_TEXTURE_3D, names[0]);
    assert_eq!(glGetError(), GL_INVALID_OPERATION);
    glBindTexture(0x1234, names[0]);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    // SAFETY: negative count is rejected before reading.
    unsafe { glGenTextures(-1, names.as_mut_ptr()) };
    assert_eq!(glGetError(), GL_INVALID_VALUE);
    // SAFETY: one readable name.
    unsafe { glDeleteTextures(1, names.as_ptr()) };
    assert_eq!(get_i(GL_TEXTURE_BINDING_2D), 0);
    assert_eq!(glGetError(), GL_NO_ERROR);
}

#[test]
fn units_and_enables() {
    let _c = Ctx::new();
    glActiveTexture(GL_TEXTURE0 + 2);
    assert_eq!(get_i(GL_ACTIVE_TEXTURE), (GL_TEXTURE0 + 2) as i32);
    glEnable(GL_TEXTURE_2D);
    assert_eq!(glIsEnabled(GL_TEXTURE_2D), 1);
    glActiveTexture(GL_TEXTURE0);
    assert_eq!(glIsEnabled(GL_TEXTURE_2D), 0, "enables are per unit");
    glActiveTexture(GL_TEXTURE0 + 2);
    assert_eq!(glIsEnabled(GL_TEXTURE_2D), 1);
    // GL 1.5 §2.7: GL_TEXTUREi with i >= GL_MAX_TEXTURE_UNITS is GL_INVALID_ENUM (softgl
    // has no shader image units, so 8 is also its combined limit; llvmpipe's is 192). This is
    // what piglit's `texunits` checks; it passes on Mesa against Mesa's own limits.
    assert_eq!(get_i(GL_MAX_TEXTURE_UNITS), 8);
    glActiveTexture(GL_TEXTURE0 + 8);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    assert_eq!(get_i(GL_ACTIVE_TEXTURE), (GL_TEXTURE0 + 2) as i32);
    glActiveTexture(GL_TEXTURE0 + 7);
    assert_eq!(glGetError(), GL_NO_ERROR);
    assert_eq!(get_i(GL_ACTIVE_TEXTURE), (GL_TEXTURE0 + 7) as i32);
    glActiveTexture(GL_TEXTURE0 + 2);
    assert_eq!(glIsEnabled(GL_TEXTURE_2D), 1);
    assert_eq!(glGetError(), GL_NO_ERROR);
    glMultiTexCoord2f(GL_TEXTURE0 + 3, 0.25, 0.5);
    glActiveTexture(GL_TEXTURE0 + 3);
    let mut tc = [0f32; 4];
    // SAFETY: 4 components.
    unsafe { glGetFloatv(GL_CURRENT_TEXTURE_COORDS, tc.as_mut_ptr()) };
    assert_eq!(tc, [0.25, 0.5, 0.0, 1.0]);
    assert_eq!(get_i(GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT), 16);
}

#[test]
fn upload_round_trip_odd_width_alignment_1() {
    let _c = Ctx::new();
    new_texture();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    let data: Vec<u8> = (0..5 * 3 * 3).map(|i| (i * 7) as u8).collect();
    // SAFETY: 5x3 RGB bytes with alignment 1.
    unsafe {
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_RGB as i32,
            5,
            3,
            0,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            data.as_ptr().cast(),
        )
    };
    assert_eq!(glGetError(), GL_NO_ERROR);
    assert_eq!(
        (level_i(0, GL_TEXTURE_WIDTH), level_i(0, GL_TEXTURE_HEIGHT)),
        (5, 3)
    );
    assert_eq!(level_i(0, GL_TEXTURE_INTERNAL_FORMAT), GL_RGB as i32);
    let mut back = vec![0u8; data.len()];
    // SAFETY: room for the 5x3 RGB image.
    unsafe {
        glGetTexImage(
            GL_TEXTURE_2D,
            0,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            back.as_mut_ptr().cast(),
        )
    };
    assert_eq!(back, data);
    // sub-image with row length and skip
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 4);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
    let sub: Vec<u8> = (100..100 + 4 * 3 * 3).map(|i| i as u8).collect();
    // SAFETY: 4-pixel rows, 3 rows of RGB bytes.
    unsafe {
        glTexSubImage2D(
            GL_TEXTURE_2D,
            0,
            3,
            1,
            2,
            2,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            sub.as_ptr().cast(),
        )
    };
    assert_eq!(glGetError(), GL_NO_ERROR);
    // SAFETY: room for the image.
    unsafe {
        glGetTexImage(
            GL_TEXTURE_2D,
            0,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            back.as_mut_ptr().cast(),
        )
    };
    let px = |x: usize, y: usize| &back[(y * 5 + x) * 3..(y * 5 + x) * 3 + 3];
    assert_eq!(px(3, 1), &sub[15..18]);
    assert_eq!(px(4, 2), &sub[30..33]);
    assert_eq!(px(0, 0), &data[0..3]);
    // out of range sub-image
    // SAFETY: rejected before reading.
    unsafe {
        glTexSubImage2D(
            GL_TEXTURE_2D,
            0,
            4,
            0,
            2,
            1,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            sub.as_ptr().cast(),
        )
    };
    assert_eq!(glGetError(), GL_INVALID_VALUE);
}

#[test]
fn tex_image_errors_and_proxy() {
    let _c = Ctx::new();
    new_texture();
    let p = std::ptr::null();
    // SAFETY: null data is allowed.
    unsafe {
        glTexImage2D(GL_TEXTURE_2D, 0, 7, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, p);
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_RGBA as i32,
            -1,
            4,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            p,
        );
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_RGBA as i32,
            16385,
            1,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            p,
        );
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_RGBA as i32,
            4,
            4,
            2,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            p,
        );
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_RGBA as i32,
            4,
            4,
            0,
            GL_INTENSITY,
            GL_UNSIGNED_BYTE,
            p,
        );
        assert_eq!(glGetError(), GL_INVALID_ENUM);
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_RGBA as i32,
            4,
            4,
            0,
            GL_RGBA,
            GL_UNSIGNED_SHORT_5_6_5,
            p,
        );
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
        glTexImage2D(
            GL_TEXTURE_2D,
            -1,
            GL_RGBA as i32,
            4,
            4,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            p,
        );
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        assert_eq!(
            level_i(0, GL_TEXTURE_WIDTH),
            0,
            "failed calls change nothing"
        );
        // border 1 is stripped
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_RGBA as i32,
            6,
            4,
            1,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            p,
        );
        assert_eq!(glGetError(), GL_NO_ERROR);
        assert_eq!(
            (level_i(0, GL_TEXTURE_WIDTH), level_i(0, GL_TEXTURE_HEIGHT)),
            (4, 2)
        );
        glTexImage2D(
            GL_PROXY_TEXTURE_2D,
            0,
            GL_LUMINANCE as i32,
            64,
            32,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            p,
        );
        let mut w = 0;
        glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &mut w);
        assert_eq!(w, 64);
        glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_LUMINANCE_SIZE, &mut w);
        assert_eq!(w, 8);
        glTexImage2D(
            GL_PROXY_TEXTURE_2D,
            0,
            GL_RGBA as i32,
            1 << 20,
            1,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            p,
        );
        glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &mut w);
        assert_eq!(w, 0, "a proxy that does not fit answers 0");
        assert_eq!(glGetError(), GL_NO_ERROR);
    }
}

#[test]
fn parameters_and_env() {
    let _c = Ctx::new();
    new_texture();
    let mut v = 0;
    // SAFETY: single values.
    unsafe {
        glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &mut v);
        assert_eq!(v as u32, GL_NEAREST_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_MIRRORED_REPEAT as i32);
        glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, &mut v);
        assert_eq!(v as u32, GL_MIRRORED_REPEAT);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_NEAREST as i32);
        assert_eq!(glGetError(), GL_INVALID_ENUM);
        glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 0.5);
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        let border = [0.5f32, 2.0, -1.0, 0.25];
        glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border.as_ptr());
        let mut b = [0f32; 4];
        glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, b.as_mut_ptr());
        assert_eq!(b, [0.5, 1.0, 0.0, 0.25]);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE as i32);
        glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DOT3_RGB as i32);
        glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_DOT3_RGB as i32);
        assert_eq!(glGetError(), GL_INVALID_ENUM, "DOT3 is RGB-only");
        glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, GL_SRC_COLOR as i32);
        assert_eq!(glGetError(), GL_INVALID_ENUM);
        glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 3.0);
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, (GL_TEXTURE0 + 1) as i32);
        glGetTexEnviv(GL_TEXTURE_ENV, GL_SOURCE1_RGB, &mut v);
        assert_eq!(v as u32, GL_TEXTURE0 + 1);
        glGetTexEnviv(GL_TEXTURE_ENV, GL_COMBINE_RGB, &mut v);
        assert_eq!(v as u32, GL_DOT3_RGB);
        glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 0.5);
        let mut f = 0.0;
        glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, &mut f);
        assert_eq!(f, 0.5);
        assert_eq!(glGetError(), GL_NO_ERROR);
    }
}

#[test]
fn generate_mipmap_and_completeness() {
    let _c = Ctx::new();
    new_texture();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, 1);
    let data = [
        0u8, 0, 0, 255, 255, 255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 255,
    ];
    // SAFETY: 2x2 RGBA bytes.
    unsafe {
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_RGBA8 as i32,
            2,
            2,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            data.as_ptr().cast(),
        )
    };
    assert_eq!(level_i(1, GL_TEXTURE_WIDTH), 1);
    let mut px = [0u8; 4];
    // SAFETY: room for 1 RGBA pixel.
    unsafe {
        glGetTexImage(
            GL_TEXTURE_2D,
            1,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            px.as_mut_ptr().cast(),
        )
    };
    // lerp(0,255,128) = 128 per row, then lerp(128,128) = 128
    assert_eq!(px, [128, 128, 128, 255]);
}
