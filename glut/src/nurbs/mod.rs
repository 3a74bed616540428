//! GLU's NURBS interface (`gluNewNurbsRenderer` … `gluEndSurface`), written from the
//! GLU 1.3 specification, with the sampling rules of SGI's libGLU.
//!
//! Curves and surfaces are collected between their begin and end calls, validated
//! (errors go to the `GLU_NURBS_ERROR` callback as `GLU_NURBS_ERROR1 + n - 1`), cut
//! into Bézier pieces ([`bezier`]) and drawn through GL's evaluators ([`render`]):
//! one `glMap1f`/`glMapGrid1f`/`glEvalMesh1` per curve segment, one `glMap2f` …
//! `glEvalMesh2` per untrimmed patch, and `glEvalCoord2f` over a triangulation of the
//! trimmed domain for trimmed surfaces ([`trim`]).

pub mod bezier;
pub mod calls;
pub mod render;
pub mod render_cb;
pub mod trim;

use crate::gl::{GLenum, GLfloat, GLint};
use bezier::Basis;
use std::ffi::c_void;

/// `GLU_INVALID_ENUM`.
const GLU_INVALID_ENUM: GLenum = 100900;
/// `GLU_INVALID_VALUE`.
const GLU_INVALID_VALUE: GLenum = 100901;
/// `GLU_NURBS_ERROR`.
const GLU_NURBS_ERROR: GLenum = 100103;
/// `GLU_NURBS_ERROR1`; error n is reported as this + n - 1.
pub const GLU_NURBS_ERROR1: GLenum = 100251;

const AUTO_LOAD_MATRIX: GLenum = 100200;
const CULLING: GLenum = 100201;
const PARAMETRIC_TOLERANCE: GLenum = 100202;
const SAMPLING_TOLERANCE: GLenum = 100203;
const DISPLAY_MODE: GLenum = 100204;
const SAMPLING_METHOD: GLenum = 100205;
const U_STEP: GLenum = 100206;
const V_STEP: GLenum = 100207;
const NURBS_MODE: GLenum = 100160;
const NURBS_TESSELLATOR: GLenum = 100161;
const NURBS_RENDERER: GLenum = 100162;
/// `GLU_FILL`.
pub const FILL: GLenum = 100012;
/// `GLU_OUTLINE_POLYGON`.
pub const OUTLINE_POLYGON: GLenum = 100240;
/// `GLU_OUTLINE_PATCH`.
pub const OUTLINE_PATCH: GLenum = 100241;
/// `GLU_PATH_LENGTH`.
pub const PATH_LENGTH: GLenum = 100215;
/// `GLU_PARAMETRIC_ERROR`.
pub const PARAMETRIC_ERROR: GLenum = 100216;
/// `GLU_DOMAIN_DISTANCE`.
pub const DOMAIN_DISTANCE: GLenum = 100217;
/// `GLU_OBJECT_PARAMETRIC_ERROR`.
pub const OBJECT_PARAMETRIC_ERROR: GLenum = 100208;
/// `GLU_OBJECT_PATH_LENGTH`.
pub const OBJECT_PATH_LENGTH: GLenum = 100209;
pub(crate) const MAP1_TRIM_2: GLenum = 100210;
pub(crate) const MAP1_TRIM_3: GLenum = 100211;
/// `GLU_NURBS_BEGIN`: the first of the twelve tessellation callbacks.
const NURBS_BEGIN: GLenum = 100164;

/// More knots or points than this in one call are refused (as too few knots) rather
/// than read: no drawable definition comes near it.
pub(crate) const MAX_KNOTS: i64 = 1 << 16;

/// A client callback as registered.
type AnyFn = Option<unsafe extern "C" fn()>;

/// The number of coordinates of a GL evaluator map, for GL_MAP1_* or GL_MAP2_* targets.
pub fn map_dim(target: GLenum) -> Option<usize> {
    let base = match target {
        0x0D90..=0x0D98 => target - 0x0D90,
        0x0DB0..=0x0DB8 => target - 0x0DB0,
        _ => return None,
    };
    Some([4, 1, 3, 1, 2, 3, 4, 3, 4][base as usize])
}

/// Whether a map target is a vertex map (GL_MAP1/2_VERTEX_3/4).
pub fn is_vertex(target: GLenum) -> bool {
    matches!(target, 0x0D97 | 0x0D98 | 0x0DB7 | 0x0DB8)
}

/// One `gluNurbsCurve` of a curve (or a trim loop).
#[derive(Clone, Debug)]
pub struct CurveDef {
    /// The GL map target (or GLU_MAP1_TRIM_2/3).
    pub target: GLenum,
    /// Coordinates per control point.
    pub dim: usize,
    /// Order and knots.
    pub basis: Basis,
    /// The control points, packed.
    pub pts: Vec<f32>,
}

/// One `gluNurbsSurface` of a surface.
#[derive(Clone, Debug)]
pub struct SurfDef {
    /// The GL_MAP2_* target.
    pub target: GLenum,
    /// Coordinates per control point.
    pub dim: usize,
    /// The s direction.
    pub s: Basis,
    /// The t direction.
    pub t: Basis,
    /// The control points, packed, s outer.
    pub pts: Vec<f32>,
}

/// A piece of a trim loop: a polyline or a NURBS curve in the (s, t) domain.
#[derive(Clone, Debug)]
pub enum TrimPiece {
    /// `gluPwlCurve` points, as (s, t).
    Pwl(Vec<[f32; 2]>),
    /// `gluNurbsCurve` with GLU_MAP1_TRIM_2 or _3.
    Curve(CurveDef),
}

/// Where a NURBS object is in the begin/end sequence.
#[derive(Debug)]
pub(crate) enum Stage {
    Idle,
    Curve(Vec<CurveDef>),
    Surface {
        maps: Vec<SurfDef>,
        loops: Vec<Vec<TrimPiece>>,
        in_trim: bool,
    },
}

/// A `GLUnurbs`.
pub struct Nurbs {
    /// GLU_SAMPLING_METHOD.
    pub method: GLenum,
    /// GLU_SAMPLING_TOLERANCE (pixels).
    pub tolerance: f32,
    /// GLU_PARAMETRIC_TOLERANCE.
    pub param_tolerance: f32,
    /// GLU_U_STEP.
    pub u_step: f32,
    /// GLU_V_STEP.
    pub v_step: f32,
    /// GLU_DISPLAY_MODE.
    pub display: GLenum,
    /// GLU_CULLING.
    pub culling: bool,
    /// GLU_AUTO_LOAD_MATRIX.
    pub auto_load: bool,
    /// GLU_NURBS_MODE is GLU_NURBS_TESSELLATOR.
    pub tessellator: bool,
    /// The sampling matrix (row-vector convention, as SGI keeps it).
    pub smat: [[f32; 4]; 4],
    /// The culling matrix (modelview × projection).
    pub cmat: [[f32; 4]; 4],
    /// GLU_NURBS_ERROR.
    error_cb: AnyFn,
    /// BEGIN … END, then BEGIN_DATA … END_DATA.
    pub callbacks: [AnyFn; 12],
    /// gluNurbsCallbackData's pointer.
    pub user_data: *mut c_void,
    pub(crate) stage: Stage,
    /// An error made the current object undrawable.
    pub(crate) bad: bool,
}

const IDENTITY: [[f32; 4]; 4] = [
    [1., 0., 0., 0.],
    [0., 1., 0., 0.],
    [0., 0., 1., 0.],
    [0., 0., 0., 1.],
];

impl Nurbs {
    fn new() -> Self {
        Nurbs {
            method: PATH_LENGTH,
            tolerance: 50.0,
            param_tolerance: 0.5,
            u_step: 100.0,
            v_step: 100.0,
            display: FILL,
            culling: false,
            auto_load: true,
            tessellator: false,
            smat: IDENTITY,
            cmat: IDENTITY,
            error_cb: None,
            callbacks: [None; 12],
            user_data: std::ptr::null_mut(),
            stage: Stage::Idle,
            bad: false,
        }
    }

    /// Reports GLU error `code` to the error callback.
    fn post(&self, code: GLenum) {
        if let Some(f) = self.error_cb {
            // SAFETY: GLU_NURBS_ERROR callbacks take (GLenum).
            unsafe { std::mem::transmute::<unsafe extern "C" fn(), extern "C" fn(GLenum)>(f)(code) }
        }
    }

    /// Reports NURBS error `n` (1…37).
    pub(crate) fn nurbs_error(&mut self, n: u32) {
        self.post(GLU_NURBS_ERROR1 + n - 1);
    }

    /// Loads the sampling and culling matrices from modelview, projection, viewport.
    pub fn load_matrices(&mut self, model: &[f32; 16], proj: &[f32; 16], view: [i32; 4]) {
        let mut v = [[0f32; 4]; 4];
        for (i, row) in v.iter_mut().enumerate() {
            for (j, x) in row.iter_mut().enumerate() {
                *x = model[i * 4] * proj[j]
                    + model[i * 4 + 1] * proj[4 + j]
                    + model[i * 4 + 2] * proj[8 + j]
                    + model[i * 4 + 3] * proj[12 + j];
            }
        }
        self.cmat = v;
        let xs = 0.5 * view[2] as f32;
        let ys = 0.5 * view[3] as f32;
        for (row, r) in self.smat.iter_mut().zip(&v) {
            *row = [r[0] * xs, r[1] * ys, 0.0, r[3]];
        }
    }
}

/// The object behind a handle, or None for NULL.
pub(crate) fn obj<'a>(p: *mut Nurbs) -> Option<&'a mut Nurbs> {
    // SAFETY: non-NULL handles come from gluNewNurbsRenderer and live until deleted.
    unsafe { p.as_mut() }
}

/// `gluNewNurbsRenderer`.
#[no_mangle]
pub extern "C" fn gluNewNurbsRenderer() -> *mut Nurbs {
    Box::into_raw(Box::new(Nurbs::new()))
}

/// `gluDeleteNurbsRenderer`: frees a renderer from gluNewNurbsRenderer (NULL ignored).
#[no_mangle]
pub extern "C" fn gluDeleteNurbsRenderer(nobj: *mut Nurbs) {
    if !nobj.is_null() {
        // SAFETY: the pointer came from Box::into_raw in gluNewNurbsRenderer.
        drop(unsafe { Box::from_raw(nobj) });
    }
}

/// `gluNurbsProperty`.
#[no_mangle]
pub extern "C" fn gluNurbsProperty(nobj: *mut Nurbs, property: GLenum, value: GLfloat) {
    let Some(n) = obj(nobj) else { return };
    let is = |e: GLenum| value == e as f32;
    match property {
        AUTO_LOAD_MATRIX => n.auto_load = value != 0.0,
        CULLING => n.culling = value != 0.0,
        SAMPLING_METHOD => {
            if is(PATH_LENGTH) || is(PARAMETRIC_ERROR) || is(DOMAIN_DISTANCE) {
                n.method = value as GLenum;
            } else if is(OBJECT_PATH_LENGTH) || is(OBJECT_PARAMETRIC_ERROR) {
                n.method = value as GLenum;
                n.auto_load = false;
                n.smat = IDENTITY;
            } else {
                n.post(GLU_INVALID_VALUE);
            }
        }
        SAMPLING_TOLERANCE => n.tolerance = value,
        PARAMETRIC_TOLERANCE => n.param_tolerance = value,
        DISPLAY_MODE => {
            if is(FILL) || is(OUTLINE_POLYGON) || is(OUTLINE_PATCH) {
                n.display = value as GLenum;
            } else {
                n.post(GLU_INVALID_VALUE);
            }
        }
        U_STEP => n.u_step = value.max(0.0),
        V_STEP => n.v_step = value.max(0.0),
        NURBS_MODE => {
            if is(NURBS_RENDERER) || is(NURBS_TESSELLATOR) {
                n.tessellator = is(NURBS_TESSELLATOR);
            } else {
                n.post(GLU_INVALID_ENUM);
            }
        }
        _ => n.post(GLU_INVALID_ENUM),
    }
}

/// `gluGetNurbsProperty`: writes the property's value to `value` (non-NULL).
#[no_mangle]
pub extern "C" fn gluGetNurbsProperty(nobj: *mut Nurbs, property: GLenum, value: *mut GLfloat) {
    let Some(n) = obj(nobj) else { return };
    let v = match property {
        AUTO_LOAD_MATRIX => f32::from(u8::from(n.auto_load)),
        CULLING => f32::from(u8::from(n.culling)),
        SAMPLING_METHOD => n.method as f32,
        SAMPLING_TOLERANCE => n.tolerance,
        PARAMETRIC_TOLERANCE => n.param_tolerance,
        U_STEP => n.u_step,
        V_STEP => n.v_step,
        DISPLAY_MODE => n.display as f32,
        NURBS_MODE => {
            (if n.tessellator {
                NURBS_TESSELLATOR
            } else {
                NURBS_RENDERER
            }) as f32
        }
        _ => {
            n.post(GLU_INVALID_ENUM);
            return;
        }
    };
    // SAFETY: the caller passes room for one float (NULL is skipped).
    if let Some(out) = unsafe { value.as_mut() } {
        *out = v;
    }
}

/// Reads `n` floats from a client array (None for NULL).
pub(crate) fn read_f32(p: *const GLfloat, n: usize) -> Option<Vec<f32>> {
    if p.is_null() {
        return None;
    }
    // SAFETY: the caller's array holds `n` floats per the GLU call's contract.
    Some(unsafe { std::slice::from_raw_parts(p, n) }.to_vec())
}

/// Reads 16 floats, or None for NULL.
fn read16(p: *const GLfloat) -> Option<[f32; 16]> {
    read_f32(p, 16).map(|v| {
        let mut m = [0f32; 16];
        m.copy_from_slice(&v);
        m
    })
}

/// `gluLoadSamplingMatrices`.
#[no_mangle]
pub extern "C" fn gluLoadSamplingMatrices(
    nobj: *mut Nurbs,
    model: *const GLfloat,
    proj: *const GLfloat,
    view: *const GLint,
) {
    let Some(n) = obj(nobj) else { return };
    let (Some(m), Some(p)) = (read16(model), read16(proj)) else {
        return;
    };
    if view.is_null() {
        return;
    }
    // SAFETY: the viewport is four GLints per GLU.
    let v = unsafe { std::slice::from_raw_parts(view, 4) };
    n.load_matrices(&m, &p, [v[0], v[1], v[2], v[3]]);
}

/// `gluNurbsCallback`.
#[no_mangle]
pub extern "C" fn gluNurbsCallback(nobj: *mut Nurbs, which: GLenum, f: AnyFn) {
    let Some(n) = obj(nobj) else { return };
    match which {
        GLU_NURBS_ERROR => n.error_cb = f,
        w if (NURBS_BEGIN..NURBS_BEGIN + 12).contains(&w) => {
            n.callbacks[(w - NURBS_BEGIN) as usize] = f
        }
        _ => n.post(GLU_INVALID_ENUM),
    }
}

/// `gluNurbsCallbackData`: the pointer passed to the `_DATA` callbacks.
#[no_mangle]
pub extern "C" fn gluNurbsCallbackData(nobj: *mut Nurbs, data: *mut c_void) {
    if let Some(n) = obj(nobj) {
        n.user_data = data;
    }
}

/// `gluNurbsCallbackDataEXT`: the same as gluNurbsCallbackData.
#[no_mangle]
pub extern "C" fn gluNurbsCallbackDataEXT(nobj: *mut Nurbs, data: *mut c_void) {
    gluNurbsCallbackData(nobj, data)
}

/// GLU's NURBS error strings, `GLU_NURBS_ERROR1` … `GLU_NURBS_ERROR37`, worded as SGI's
/// GLU words them (spelling included) since programs print them.
pub const ERROR_STRINGS: [&str; 37] = [
    "spline order un-supported\0",
    "too few knots\0",
    "valid knot range is empty\0",
    "decreasing knot sequence knot\0",
    "knot multiplicity greater than order of spline\0",
    "gluEndCurve() must follow gluBeginCurve()\0",
    "gluBeginCurve() must precede gluEndCurve()\0",
    "missing or extra geometric data\0",
    "can't draw piecewise linear trimming curves\0",
    "missing or extra domain data\0",
    "missing or extra domain data\0",
    "gluEndTrim() must precede gluEndSurface()\0",
    "gluBeginSurface() must precede gluEndSurface()\0",
    "curve of improper type passed as trim curve\0",
    "gluBeginSurface() must precede gluBeginTrim()\0",
    "gluEndTrim() must follow gluBeginTrim()\0",
    "gluBeginTrim() must precede gluEndTrim()\0",
    "invalid or missing trim curve\0",
    "gluBeginTrim() must precede gluPwlCurve()\0",
    "piecewise linear trimming curve referenced twice\0",
    "piecewise linear trimming curve and nurbs curve mixed\0",
    "improper usage of trim data type\0",
    "nurbs curve referenced twice\0",
    "nurbs curve and piecewise linear trimming curve mixed\0",
    "nurbs surface referenced twice\0",
    "invalid property\0",
    "gluEndSurface() must follow gluBeginSurface()\0",
    "intersecting or misoriented trim curves\0",
    "intersecting trim curves\0",
    "UNUSED\0",
    "unconnected trim curves\0",
    "unknown knot error\0",
    "negative vertex count encountered\0",
    "negative byte-stride encounteed\0",
    "unknown type descriptor\0",
    "null control point reference\0",
    "duplicate point on piecewise linear trimming curve\0",
];
