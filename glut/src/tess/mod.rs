//! GLU 1.3's polygon tessellator (`gluNewTess` … `gluTessEndPolygon`, and the GLU 1.0
//! `gluBeginPolygon`/`gluNextContour`/`gluEndPolygon`), written from the GLU 1.3
//! specification.
//!
//! The contours are projected onto a plane (along the normal given with
//! `gluTessNormal`, or one computed so that the contours' total signed area is
//! positive), their planar arrangement is built ([`arrange`]: intersections become new
//! vertices through the COMBINE callback), each region gets its winding number and
//! the regions inside per the winding rule are cut into triangles or, in
//! boundary-only mode, outlined with closed loops ([`sweep`]). Output goes through the
//! client's callbacks: independent triangles (GL_TRIANGLES) counterclockwise about the
//! normal, with edge flags when an EDGE_FLAG callback is set (true on the boundary of
//! the inside), or GL_LINE_LOOPs with outer loops counterclockwise and holes clockwise.

#![allow(non_snake_case)]

pub mod arrange;
pub mod sweep;

use crate::gl::{GLdouble, GLenum};
use arrange::Vtx;
use std::ffi::c_void;

const GL_TRIANGLES: GLenum = 0x0004;
const GL_LINE_LOOP: GLenum = 0x0002;

const GLU_INVALID_ENUM: GLenum = 100900;
const GLU_INVALID_VALUE: GLenum = 100901;

/// `GLU_TESS_BEGIN`, the first callback enum; the twelve are consecutive.
const TESS_BEGIN: GLenum = 100100;
const TESS_VERTEX: usize = 1;
const TESS_END: usize = 2;
const TESS_ERROR: usize = 3;
const TESS_EDGE_FLAG: usize = 4;
const TESS_COMBINE: usize = 5;
/// Offset of each `_DATA` variant from its plain callback.
const DATA: usize = 6;

const TESS_WINDING_RULE: GLenum = 100140;
const TESS_BOUNDARY_ONLY: GLenum = 100141;
const TESS_TOLERANCE: GLenum = 100142;

/// `GLU_TESS_WINDING_ODD`.
pub const WINDING_ODD: GLenum = 100130;
/// `GLU_TESS_WINDING_NONZERO`.
pub const WINDING_NONZERO: GLenum = 100131;
/// `GLU_TESS_WINDING_POSITIVE`.
pub const WINDING_POSITIVE: GLenum = 100132;
/// `GLU_TESS_WINDING_NEGATIVE`.
pub const WINDING_NEGATIVE: GLenum = 100133;
/// `GLU_TESS_WINDING_ABS_GEQ_TWO`.
pub const WINDING_ABS_GEQ_TWO: GLenum = 100134;

const MISSING_BEGIN_POLYGON: GLenum = 100151;
const MISSING_BEGIN_CONTOUR: GLenum = 100152;
const MISSING_END_POLYGON: GLenum = 100153;
const MISSING_END_CONTOUR: GLenum = 100154;
const COORD_TOO_LARGE: GLenum = 100155;
const NEED_COMBINE_CALLBACK: GLenum = 100156;

/// `GLU_TESS_MAX_COORD`.
const MAX_COORD: f64 = 1.0e150;

/// A client callback as registered (cast to its real signature when called).
type AnyFn = Option<unsafe extern "C" fn()>;

/// Where a tessellator is in the begin/end sequence.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Debug)]
enum Stage {
    Dormant,
    InPolygon,
    InContour,
}

/// A `GLUtesselator`.
pub struct Tess {
    stage: Stage,
    normal: [f64; 3],
    rule: GLenum,
    boundary_only: bool,
    tolerance: f64,
    /// BEGIN … COMBINE, then BEGIN_DATA … COMBINE_DATA.
    callbacks: [AnyFn; 12],
    polygon_data: *mut c_void,
    verts: Vec<([f64; 3], *mut c_void)>,
    contours: Vec<Vec<usize>>,
}

impl Tess {
    fn new() -> Self {
        Tess {
            stage: Stage::Dormant,
            normal: [0.0; 3],
            rule: WINDING_ODD,
            boundary_only: false,
            tolerance: 0.0,
            callbacks: [None; 12],
            polygon_data: std::ptr::null_mut(),
            verts: Vec::new(),
            contours: Vec::new(),
        }
    }

    /// The `_DATA` callback if set (called with the polygon data), else the plain one.
    fn pick(&self, which: usize) -> (AnyFn, bool) {
        match self.callbacks[which + DATA] {
            Some(f) => (Some(f), true),
            None => (self.callbacks[which], false),
        }
    }

    fn error(&self, code: GLenum) {
        // SAFETY: the ERROR callbacks take (GLenum) or (GLenum, void *) per GLU.
        unsafe {
            match self.pick(TESS_ERROR) {
                (Some(f), true) => {
                    cast::<extern "C" fn(GLenum, *mut c_void)>(f)(code, self.polygon_data)
                }
                (Some(f), false) => cast::<extern "C" fn(GLenum)>(f)(code),
                (None, _) => {}
            }
        }
    }

    fn begin(&self, mode: GLenum) {
        // SAFETY: the BEGIN callbacks take (GLenum) or (GLenum, void *) per GLU.
        unsafe {
            match self.pick(0) {
                (Some(f), true) => {
                    cast::<extern "C" fn(GLenum, *mut c_void)>(f)(mode, self.polygon_data)
                }
                (Some(f), false) => cast::<extern "C" fn(GLenum)>(f)(mode),
                (None, _) => {}
            }
        }
    }

    fn vertex(&self, data: *mut c_void) {
        // SAFETY: the VERTEX callbacks take (void *) or (void *, void *) per GLU.
        unsafe {
            match self.pick(TESS_VERTEX) {
                (Some(f), true) => {
                    cast::<extern "C" fn(*mut c_void, *mut c_void)>(f)(data, self.polygon_data)
                }
                (Some(f), false) => cast::<extern "C" fn(*mut c_void)>(f)(data),
                (None, _) => {}
            }
        }
    }

    fn end(&self) {
        // SAFETY: the END callbacks take () or (void *) per GLU.
        unsafe {
            match self.pick(TESS_END) {
                (Some(f), true) => cast::<extern "C" fn(*mut c_void)>(f)(self.polygon_data),
                (Some(f), false) => cast::<extern "C" fn()>(f)(),
                (None, _) => {}
            }
        }
    }

    fn edge_flag(&self, flag: bool) {
        // SAFETY: the EDGE_FLAG callbacks take (GLboolean) or (GLboolean, void *).
        unsafe {
            match self.pick(TESS_EDGE_FLAG) {
                (Some(f), true) => {
                    cast::<extern "C" fn(u8, *mut c_void)>(f)(u8::from(flag), self.polygon_data)
                }
                (Some(f), false) => cast::<extern "C" fn(u8)>(f)(u8::from(flag)),
                (None, _) => {}
            }
        }
    }

    /// Calls COMBINE: the new vertex's client data, None without a callback or when
    /// the callback left it NULL.
    fn combine(&self, xyz: [f64; 3], data: [*mut c_void; 4], w: [f32; 4]) -> Option<*mut c_void> {
        let mut made: *mut c_void = std::ptr::null_mut();
        type Plain = extern "C" fn(*const f64, *const *mut c_void, *const f32, *mut *mut c_void);
        type WithData = extern "C" fn(
            *const f64,
            *const *mut c_void,
            *const f32,
            *mut *mut c_void,
            *mut c_void,
        );
        // SAFETY: the COMBINE callbacks take (GLdouble[3], void *[4], GLfloat[4], void **)
        // and the polygon data for the _DATA one; the arrays live across the call.
        unsafe {
            match self.pick(TESS_COMBINE) {
                (Some(f), true) => cast::<WithData>(f)(
                    xyz.as_ptr(),
                    data.as_ptr(),
                    w.as_ptr(),
                    &mut made,
                    self.polygon_data,
                ),
                (Some(f), false) => {
                    cast::<Plain>(f)(xyz.as_ptr(), data.as_ptr(), w.as_ptr(), &mut made)
                }
                (None, _) => return None,
            }
        }
        (!made.is_null()).then_some(made)
    }

    /// Moves to `want`, reporting (and making up for) the calls that were skipped,
    /// the way GLU recovers from a begin/end sequence error.
    fn go_to(&mut self, want: Stage) {
        while self.stage != want {
            if self.stage < want {
                match self.stage {
                    Stage::Dormant => {
                        self.error(MISSING_BEGIN_POLYGON);
                        self.begin_polygon(std::ptr::null_mut());
                    }
                    _ => {
                        self.error(MISSING_BEGIN_CONTOUR);
                        self.begin_contour();
                    }
                }
            } else {
                match self.stage {
                    Stage::InContour => {
                        self.error(MISSING_END_CONTOUR);
                        self.end_contour();
                    }
                    _ => {
                        self.error(MISSING_END_POLYGON);
                        self.reset();
                    }
                }
            }
        }
    }

    fn reset(&mut self) {
        self.stage = Stage::Dormant;
        // Errors after the polygon (bad properties) reach ERROR_DATA with NULL, as
        // SGI's GLU does.
        self.polygon_data = std::ptr::null_mut();
        self.verts.clear();
        self.contours.clear();
    }

    fn begin_polygon(&mut self, data: *mut c_void) {
        self.go_to(Stage::Dormant);
        self.stage = Stage::InPolygon;
        self.polygon_data = data;
        self.verts.clear();
        self.contours.clear();
    }

    fn begin_contour(&mut self) {
        self.go_to(Stage::InPolygon);
        self.stage = Stage::InContour;
        self.contours.push(Vec::new());
    }

    fn end_contour(&mut self) {
        self.go_to(Stage::InContour);
        self.stage = Stage::InPolygon;
    }

    fn add_vertex(&mut self, p: [f64; 3], data: *mut c_void) {
        self.go_to(Stage::InContour);
        let mut too_large = false;
        let p = p.map(|c| {
            if c.abs() > MAX_COORD {
                too_large = true;
                c.clamp(-MAX_COORD, MAX_COORD)
            } else {
                c
            }
        });
        if too_large {
            self.error(COORD_TOO_LARGE);
        }
        self.verts.push((p, data));
        let i = self.verts.len() - 1;
        if let Some(c) = self.contours.last_mut() {
            c.push(i);
        }
    }

    fn end_polygon(&mut self) {
        self.go_to(Stage::InPolygon);
        self.tessellate();
        self.reset();
    }

    /// The projection plane's axes: (s axis, t axis, t sign).
    fn projection(&self) -> (usize, usize, f64) {
        let n = if self.normal == [0.0; 3] {
            computed_normal(&self.verts, &self.contours)
        } else {
            self.normal
        };
        let i = (0..3)
            .max_by(|&a, &b| n[a].abs().total_cmp(&n[b].abs()))
            .unwrap_or(2);
        let sign = if n[i] < 0.0 { -1.0 } else { 1.0 };
        ((i + 1) % 3, (i + 2) % 3, sign)
    }

    fn tessellate(&self) {
        let (a, b, sign) = self.projection();
        let mut input: Vec<Vtx> = self
            .verts
            .iter()
            .map(|&(xyz, data)| Vtx {
                s: xyz[a],
                t: sign * xyz[b],
                xyz,
                data,
            })
            .collect();
        if self.normal == [0.0; 3] && signed_area(&input, &self.contours) < 0.0 {
            // A computed normal points so that the contours' total area is positive.
            input.iter_mut().for_each(|v| v.t = -v.t);
        }
        let mut combine = |xyz, data, w, _needed| self.combine(xyz, data, w);
        let arr = arrange::arrange(&input, &self.contours, &mut combine);
        if arr.missing_combine {
            self.error(NEED_COMBINE_CALLBACK);
            return;
        }
        let bounds = sweep::classify(&arr.verts, &arr.segs, self.rule);
        if self.boundary_only {
            for lp in sweep::boundaries(&arr.verts, &bounds) {
                self.begin(GL_LINE_LOOP);
                lp.iter().for_each(|&v| self.vertex(arr.verts[v].data));
                self.end();
            }
            return;
        }
        let tris = sweep::triangulate(&arr.verts, &bounds);
        if tris.is_empty() {
            return;
        }
        let flags = self.pick(TESS_EDGE_FLAG).0.is_some();
        let edges: std::collections::HashSet<(usize, usize)> = if flags {
            bounds
                .iter()
                .map(|(s, _)| (s.lo.min(s.hi), s.lo.max(s.hi)))
                .collect()
        } else {
            Default::default()
        };
        self.begin(GL_TRIANGLES);
        let mut last_flag = None;
        for t in &tris {
            for k in 0..3 {
                if flags {
                    let (p, q) = (t[k], t[(k + 1) % 3]);
                    let f = edges.contains(&(p.min(q), p.max(q)));
                    if last_flag != Some(f) {
                        self.edge_flag(f);
                        last_flag = Some(f);
                    }
                }
                self.vertex(arr.verts[t[k]].data);
            }
        }
        self.end();
    }
}

/// Casts a registered callback to its real signature.
///
/// # Safety
/// `F` must be the function's actual C signature.
unsafe fn cast<F: Copy>(f: unsafe extern "C" fn()) -> F {
    // SAFETY: function pointers all have one representation; the caller vouches for
    // the signature.
    unsafe { std::mem::transmute_copy(&f) }
}

/// A normal for contours given none: Newell's (area-weighted), else the largest
/// cross product of vertex differences (contours enclosing no net area).
fn computed_normal(verts: &[([f64; 3], *mut c_void)], contours: &[Vec<usize>]) -> [f64; 3] {
    let mut n = [0.0; 3];
    for c in contours {
        for k in 0..c.len() {
            let (p, q) = (verts[c[k]].0, verts[c[(k + 1) % c.len()]].0);
            n[0] += (p[1] - q[1]) * (p[2] + q[2]);
            n[1] += (p[2] - q[2]) * (p[0] + q[0]);
            n[2] += (p[0] - q[0]) * (p[1] + q[1]);
        }
    }
    if n.iter().any(|c| c.abs() > 0.0) {
        return n;
    }
    let Some(&(o, _)) = verts.first() else {
        return [0.0, 0.0, 1.0];
    };
    let d = |p: [f64; 3]| [p[0] - o[0], p[1] - o[1], p[2] - o[2]];
    let len = |v: [f64; 3]| v.iter().map(|c| c * c).sum::<f64>();
    let far = verts
        .iter()
        .map(|v| d(v.0))
        .max_by(|a, b| len(*a).total_cmp(&len(*b)))
        .unwrap_or([0.0; 3]);
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    verts
        .iter()
        .map(|v| cross(far, d(v.0)))
        .max_by(|a, b| len(*a).total_cmp(&len(*b)))
        .filter(|c| len(*c) > 0.0)
        .unwrap_or([0.0, 0.0, 1.0])
}

/// The contours' total signed area in the projection plane.
fn signed_area(verts: &[Vtx], contours: &[Vec<usize>]) -> f64 {
    contours
        .iter()
        .flat_map(|c| {
            (0..c.len()).map(move |k| {
                let (p, q) = (verts[c[k]], verts[c[(k + 1) % c.len()]]);
                p.s * q.t - q.s * p.t
            })
        })
        .sum()
}

/// Runs `f` on a tessellator pointer (nothing for NULL).
fn with<R>(t: *mut Tess, f: impl FnOnce(&mut Tess) -> R) -> Option<R> {
    // SAFETY: a non-null tessellator comes from gluNewTess and is not yet deleted.
    unsafe { t.as_mut() }.map(f)
}

/// `gluNewTess`.
#[no_mangle]
pub extern "C" fn gluNewTess() -> *mut Tess {
    Box::into_raw(Box::new(Tess::new()))
}

/// `gluDeleteTess`: an unfinished polygon is discarded (with its errors reported).
#[no_mangle]
pub extern "C" fn gluDeleteTess(t: *mut Tess) {
    if t.is_null() {
        return;
    }
    with(t, |t| t.go_to(Stage::Dormant));
    // SAFETY: t came from gluNewTess and is deleted once (GLU's contract).
    drop(unsafe { Box::from_raw(t) });
}

/// `gluTessCallback`: sets (or with NULL clears) one of the twelve callbacks.
#[no_mangle]
pub extern "C" fn gluTessCallback(t: *mut Tess, which: GLenum, f: AnyFn) {
    with(t, |t| match which.checked_sub(TESS_BEGIN) {
        Some(k) if k < 12 => t.callbacks[k as usize] = f,
        _ => t.error(GLU_INVALID_ENUM),
    });
}

/// `gluTessProperty`: the winding rule, boundary-only mode or the tolerance.
#[no_mangle]
pub extern "C" fn gluTessProperty(t: *mut Tess, which: GLenum, value: GLdouble) {
    with(t, |t| match which {
        TESS_WINDING_RULE => {
            let rule = value as GLenum;
            if f64::from(rule) != value {
                t.error(GLU_INVALID_VALUE);
            } else if (WINDING_ODD..=WINDING_ABS_GEQ_TWO).contains(&rule) {
                t.rule = rule;
            } else {
                // SGI's GLU (the reference) treats an unknown whole-number rule as a
                // GLU_TESS_BOUNDARY_ONLY value, without an error: programs see that.
                t.boundary_only = value != 0.0;
            }
        }
        TESS_BOUNDARY_ONLY => t.boundary_only = value != 0.0,
        TESS_TOLERANCE => {
            if (0.0..=1.0).contains(&value) {
                t.tolerance = value;
            } else {
                t.error(GLU_INVALID_VALUE);
            }
        }
        _ => t.error(GLU_INVALID_ENUM),
    });
}

/// `gluGetTessProperty`.
#[no_mangle]
pub extern "C" fn gluGetTessProperty(t: *mut Tess, which: GLenum, value: *mut GLdouble) {
    with(t, |t| {
        let v = match which {
            TESS_WINDING_RULE => f64::from(t.rule),
            TESS_BOUNDARY_ONLY => f64::from(u8::from(t.boundary_only)),
            TESS_TOLERANCE => t.tolerance,
            _ => {
                t.error(GLU_INVALID_ENUM);
                0.0
            }
        };
        if !value.is_null() {
            // SAFETY: GLU's contract: a non-null value points to a writable double.
            unsafe { value.write(v) };
        }
    });
}

/// `gluTessNormal`: the projection normal, (0, 0, 0) to compute one per polygon.
#[no_mangle]
pub extern "C" fn gluTessNormal(t: *mut Tess, x: GLdouble, y: GLdouble, z: GLdouble) {
    with(t, |t| t.normal = [x, y, z]);
}

/// `gluTessBeginPolygon`: `data` is passed to the `_DATA` callbacks.
#[no_mangle]
pub extern "C" fn gluTessBeginPolygon(t: *mut Tess, data: *mut c_void) {
    with(t, |t| t.begin_polygon(data));
}

/// `gluTessBeginContour`.
#[no_mangle]
pub extern "C" fn gluTessBeginContour(t: *mut Tess) {
    with(t, Tess::begin_contour);
}

/// `gluTessVertex`: the location is copied; `data` is what the VERTEX callback gets.
#[no_mangle]
pub extern "C" fn gluTessVertex(t: *mut Tess, location: *const GLdouble, data: *mut c_void) {
    if location.is_null() {
        return;
    }
    // SAFETY: GLU's contract: location points to three doubles.
    let p = unsafe { [*location, *location.add(1), *location.add(2)] };
    with(t, |t| t.add_vertex(p, data));
}

/// `gluTessEndContour`.
#[no_mangle]
pub extern "C" fn gluTessEndContour(t: *mut Tess) {
    with(t, Tess::end_contour);
}

/// `gluTessEndPolygon`: tessellates and calls back.
#[no_mangle]
pub extern "C" fn gluTessEndPolygon(t: *mut Tess) {
    with(t, Tess::end_polygon);
}

/// `gluBeginPolygon` (GLU 1.0): a polygon and its first contour.
#[no_mangle]
pub extern "C" fn gluBeginPolygon(t: *mut Tess) {
    with(t, |t| {
        t.begin_polygon(std::ptr::null_mut());
        t.begin_contour();
    });
}

/// `gluNextContour` (GLU 1.0): the contour type is not needed by GLU 1.3 rules.
#[no_mangle]
pub extern "C" fn gluNextContour(t: *mut Tess, _kind: GLenum) {
    with(t, |t| {
        t.end_contour();
        t.begin_contour();
    });
}

/// `gluEndPolygon` (GLU 1.0).
#[no_mangle]
pub extern "C" fn gluEndPolygon(t: *mut Tess) {
    with(t, |t| {
        t.end_contour();
        t.end_polygon();
    });
}

#[cfg(test)]
mod tests;
