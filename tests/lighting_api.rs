//! glLight/glLightModel/glMaterial/glColorMaterial/glFog through the exported C functions:
//! errors change nothing, glGet round-trips, Mesa's defaults and conversions.

use softgl::ffi::enums::*;
use softgl::ffi::glext_enums::*;
use softgl::ffi::immediate::*;
use softgl::ffi::lighting::*;
use softgl::ffi::lighting_ext::*;
use softgl::ffi::matrix::*;
use softgl::ffi::osmesa::*;
use softgl::ffi::query::*;
use softgl::ffi::state::*;

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

fn light4(l: u32, p: u32) -> [f32; 4] {
    let mut v = [0f32; 4];
    // SAFETY: 4 values are writable.
    unsafe { glGetLightfv(l, p, v.as_mut_ptr()) };
    v
}

fn mat4(f: u32, p: u32) -> [f32; 4] {
    let mut v = [0f32; 4];
    // SAFETY: 4 values are writable.
    unsafe { glGetMaterialfv(f, p, v.as_mut_ptr()) };
    v
}

fn getf(p: u32) -> [f32; 4] {
    let mut v = [0f32; 16];
    // SAFETY: 16 values are writable.
    unsafe { glGetFloatv(p, v.as_mut_ptr()) };
    [v[0], v[1], v[2], v[3]]
}

fn geti(p: u32) -> i32 {
    let mut v = [0i32; 16];
    // SAFETY: 16 values are writable.
    unsafe { glGetIntegerv(p, v.as_mut_ptr()) };
    v[0]
}

#[test]
fn defaults() {
    let _c = Ctx::new();
    assert_eq!(light4(GL_LIGHT0, GL_DIFFUSE), [1.0; 4]);
    assert_eq!(light4(GL_LIGHT1, GL_DIFFUSE), [0.0, 0.0, 0.0, 1.0]);
    assert_eq!(light4(GL_LIGHT3, GL_POSITION), [0.0, 0.0, 1.0, 0.0]);
    assert_eq!(light4(GL_LIGHT3, GL_SPOT_DIRECTION)[..3], [0.0, 0.0, -1.0]);
    assert_eq!(light4(GL_LIGHT3, GL_SPOT_CUTOFF)[0], 180.0);
    assert_eq!(mat4(GL_FRONT, GL_AMBIENT), [0.2, 0.2, 0.2, 1.0]);
    assert_eq!(mat4(GL_BACK, GL_DIFFUSE), [0.8, 0.8, 0.8, 1.0]);
    assert_eq!(getf(GL_LIGHT_MODEL_AMBIENT), [0.2, 0.2, 0.2, 1.0]);
    assert_eq!(geti(GL_LIGHT_MODEL_COLOR_CONTROL), GL_SINGLE_COLOR as i32);
    assert_eq!(geti(GL_COLOR_MATERIAL_FACE), GL_FRONT_AND_BACK as i32);
    assert_eq!(
        geti(GL_COLOR_MATERIAL_PARAMETER),
        GL_AMBIENT_AND_DIFFUSE as i32
    );
    assert_eq!(geti(GL_FOG_MODE), GL_EXP as i32);
    assert_eq!(getf(GL_FOG_DENSITY)[0], 1.0);
    assert_eq!(getf(GL_FOG_END)[0], 1.0);
    assert_eq!(geti(GL_FOG_COORD_SRC), GL_FRAGMENT_DEPTH as i32);
    assert_eq!(getf(GL_CURRENT_SECONDARY_COLOR), [0.0, 0.0, 0.0, 1.0]);
    assert_eq!(glGetError(), GL_NO_ERROR);
}

#[test]
fn errors_change_nothing() {
    let _c = Ctx::new();
    glLightf(GL_LIGHT0 + 8, GL_SPOT_CUTOFF, 10.0);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    glLightf(GL_LIGHT0, 0x1234, 10.0);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    for bad in [-1.0, 90.5, 179.0] {
        glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, bad);
        assert_eq!(glGetError(), GL_INVALID_VALUE);
    }
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 45.0);
    assert_eq!(light4(GL_LIGHT0, GL_SPOT_CUTOFF)[0], 45.0);
    glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 129.0);
    assert_eq!(glGetError(), GL_INVALID_VALUE);
    glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, -1.0);
    assert_eq!(glGetError(), GL_INVALID_VALUE);
    assert_eq!(light4(GL_LIGHT0, GL_SPOT_EXPONENT)[0], 0.0);
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, -0.5);
    assert_eq!(glGetError(), GL_INVALID_VALUE);
    glMaterialf(GL_FRONT, GL_SHININESS, 128.5);
    assert_eq!(glGetError(), GL_INVALID_VALUE);
    glMaterialf(0x1234, GL_SHININESS, 10.0);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    glMaterialf(GL_FRONT, GL_SPOT_CUTOFF, 10.0);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    assert_eq!(mat4(GL_FRONT, GL_SHININESS)[0], 0.0);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_FRONT as i32);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    glColorMaterial(GL_FRONT, GL_SHININESS);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    glColorMaterial(0x1234, GL_DIFFUSE);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    glFogf(GL_FOG_DENSITY, -1.0);
    assert_eq!(glGetError(), GL_INVALID_VALUE);
    glFogi(GL_FOG_MODE, GL_FRONT as i32);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    glFogi(GL_FOG_COORD_SRC, GL_FRONT as i32);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    assert_eq!(geti(GL_FOG_MODE), GL_EXP as i32);
    let mut v = [0f32; 4];
    // SAFETY: 4 values are writable.
    unsafe { glGetMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, v.as_mut_ptr()) };
    assert_eq!(glGetError(), GL_INVALID_ENUM, "queries need one face");
    // Between glBegin and glEnd: glLight is an error, glMaterial is allowed.
    glBegin(GL_TRIANGLES);
    glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 3.0);
    glMaterialf(GL_FRONT, GL_SHININESS, 7.0);
    glEnd();
    assert_eq!(glGetError(), GL_INVALID_OPERATION);
    assert_eq!(light4(GL_LIGHT0, GL_SPOT_EXPONENT)[0], 0.0);
    assert_eq!(mat4(GL_FRONT, GL_SHININESS)[0], 7.0);
}

#[test]
fn round_trips_and_eye_space() {
    let _c = Ctx::new();
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(1.0, 2.0, 3.0);
    let pos = [1.0f32, 1.0, 1.0, 1.0];
    // SAFETY: 4 readable values.
    unsafe { glLightfv(GL_LIGHT2, GL_POSITION, pos.as_ptr()) };
    assert_eq!(light4(GL_LIGHT2, GL_POSITION), [2.0, 3.0, 4.0, 1.0]);
    let dir = [0.0f32, 0.0, -1.0];
    // SAFETY: 3 readable values.
    unsafe { glLightfv(GL_LIGHT2, GL_SPOT_DIRECTION, dir.as_ptr()) };
    assert_eq!(light4(GL_LIGHT2, GL_SPOT_DIRECTION)[..3], [0.0, 0.0, -1.0]);
    let amb = [i32::MAX, 0, i32::MIN, i32::MAX];
    // SAFETY: 4 readable values.
    unsafe { glLightiv(GL_LIGHT2, GL_AMBIENT, amb.as_ptr()) };
    // Mesa's INT_TO_FLOAT maps 0 to 1/(2^32-2), not 0.
    assert_eq!(
        light4(GL_LIGHT2, GL_AMBIENT),
        [1.0, 1.0 / 4294967294.0, -1.0, 1.0]
    );
    let mut iv = [0i32; 4];
    // SAFETY: 4 writable values.
    unsafe { glGetLightiv(GL_LIGHT2, GL_AMBIENT, iv.as_mut_ptr()) };
    assert_eq!(iv, [i32::MAX, 0, -i32::MAX, i32::MAX]);

    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    glLightModeli(
        GL_LIGHT_MODEL_COLOR_CONTROL,
        GL_SEPARATE_SPECULAR_COLOR as i32,
    );
    assert_eq!(geti(GL_LIGHT_MODEL_TWO_SIDE), 1);
    assert_eq!(
        geti(GL_LIGHT_MODEL_COLOR_CONTROL),
        GL_SEPARATE_SPECULAR_COLOR as i32
    );

    glMaterialf(GL_BACK, GL_SHININESS, 12.0);
    assert_eq!(mat4(GL_BACK, GL_SHININESS)[0], 12.0);
    assert_eq!(mat4(GL_FRONT, GL_SHININESS)[0], 0.0);

    // Colour material: tracked terms follow the current colour and ignore glMaterial.
    glColorMaterial(GL_FRONT, GL_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glColor4f(0.25, 0.5, 0.75, 1.0);
    let red = [1.0f32, 0.0, 0.0, 1.0];
    // SAFETY: 4 readable values.
    unsafe { glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, red.as_ptr()) };
    assert_eq!(mat4(GL_FRONT, GL_DIFFUSE), [0.25, 0.5, 0.75, 1.0]);
    assert_eq!(mat4(GL_BACK, GL_DIFFUSE), red);

    glFogi(GL_FOG_MODE, GL_LINEAR as i32);
    glFogf(GL_FOG_START, 2.0);
    glFogf(GL_FOG_END, 9.0);
    let col = [2.0f32, 0.5, -1.0, 1.0];
    // SAFETY: 4 readable values.
    unsafe { glFogfv(GL_FOG_COLOR, col.as_ptr()) };
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD as i32);
    assert_eq!(geti(GL_FOG_MODE), GL_LINEAR as i32);
    assert_eq!(getf(GL_FOG_START)[0], 2.0);
    assert_eq!(getf(GL_FOG_END)[0], 9.0);
    assert_eq!(getf(GL_FOG_COLOR), [1.0, 0.5, 0.0, 1.0], "clamped");
    assert_eq!(geti(GL_FOG_COORD_SRC), GL_FOG_COORD as i32);

    glSecondaryColor3ub(255, 0, 51);
    assert_eq!(getf(GL_CURRENT_SECONDARY_COLOR), [1.0, 0.0, 0.2, 1.0]);
    glFogCoordf(-3.5);
    assert_eq!(getf(GL_CURRENT_FOG_COORD)[0], -3.5);
    assert_eq!(glGetError(), GL_NO_ERROR);
}
