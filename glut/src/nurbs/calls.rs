//! The begin/end sequence and the definition calls, with SGI's recovery from misuse:
//! a begin inside an open object reports an error and ends that object first (drawing
//! it), a definition outside any begin is wrapped in an implicit begin/end, and a
//! curve whose every definition was refused reports error 9 at its end.

use super::bezier::{self, Basis};
use super::{
    is_vertex, map_dim, obj, read_f32, render, CurveDef, Nurbs, Stage, SurfDef, TrimPiece,
};
use super::{MAP1_TRIM_2, MAP1_TRIM_3, MAX_KNOTS};
use crate::gl::{GLenum, GLfloat, GLint};

impl Nurbs {
    fn begin_curve(&mut self) {
        if matches!(self.stage, Stage::Curve(_)) {
            self.nurbs_error(6);
            self.end_curve();
        }
        if !matches!(self.stage, Stage::Surface { in_trim: true, .. }) {
            self.stage = Stage::Curve(Vec::new());
            self.bad = false;
        }
    }

    fn end_curve(&mut self) {
        if matches!(self.stage, Stage::Surface { in_trim: true, .. }) {
            return;
        }
        let Stage::Curve(maps) = std::mem::replace(&mut self.stage, Stage::Idle) else {
            self.nurbs_error(7);
            return;
        };
        if self.bad {
            return;
        }
        if maps.is_empty() {
            self.nurbs_error(9);
            return;
        }
        if maps.iter().filter(|m| is_vertex(m.target)).count() != 1 {
            self.nurbs_error(8);
            return;
        }
        render::curve(self, &maps);
    }

    fn begin_surface(&mut self) {
        if matches!(self.stage, Stage::Surface { .. }) {
            self.nurbs_error(27);
            self.end_surface();
        }
        self.stage = Stage::Surface {
            maps: Vec::new(),
            loops: Vec::new(),
            in_trim: false,
        };
        self.bad = false;
    }

    fn end_trim(&mut self) {
        let Stage::Surface { loops, in_trim, .. } = &mut self.stage else {
            self.nurbs_error(17);
            return;
        };
        if !*in_trim {
            self.nurbs_error(17);
            return;
        }
        *in_trim = false;
        if loops.last().is_none_or(|l| l.is_empty()) {
            self.nurbs_error(18);
            self.bad = true;
        }
    }

    fn end_surface(&mut self) {
        if matches!(self.stage, Stage::Surface { in_trim: true, .. }) {
            self.nurbs_error(12);
            self.end_trim();
        }
        let Stage::Surface { maps, loops, .. } = std::mem::replace(&mut self.stage, Stage::Idle)
        else {
            self.nurbs_error(13);
            return;
        };
        if self.bad || maps.is_empty() {
            return;
        }
        if maps.iter().filter(|m| is_vertex(m.target)).count() != 1 {
            self.nurbs_error(8);
            return;
        }
        render::surface(self, &maps, &loops);
    }
}

/// `gluBeginCurve`.
#[no_mangle]
pub extern "C" fn gluBeginCurve(nobj: *mut Nurbs) {
    if let Some(n) = obj(nobj) {
        n.begin_curve();
    }
}

/// `gluEndCurve`: draws the curve.
#[no_mangle]
pub extern "C" fn gluEndCurve(nobj: *mut Nurbs) {
    if let Some(n) = obj(nobj) {
        n.end_curve();
    }
}

/// Why a definition was refused: reported already; `bad` when it spoils the object.
struct Refused {
    bad: bool,
}

/// Validates and packs one curve definition.
fn curve_def(
    n: &mut Nurbs,
    knot_count: GLint,
    knots: *const GLfloat,
    stride: GLint,
    ctl: *const GLfloat,
    order: GLint,
    target: GLenum,
) -> Result<CurveDef, Refused> {
    let fail = |n: &mut Nurbs, e: u32, bad: bool| {
        n.nurbs_error(e);
        Err(Refused { bad })
    };
    let dim = match target {
        MAP1_TRIM_2 => 2,
        MAP1_TRIM_3 => 3,
        t if (0x0D90..=0x0D98).contains(&t) => map_dim(t).unwrap_or(3),
        _ => return fail(n, 35, true),
    };
    if stride < 0 {
        return fail(n, 34, true);
    }
    if knot_count < 0 || i64::from(knot_count) > MAX_KNOTS {
        return fail(n, 2, false);
    }
    let kv = if knot_count == 0 {
        Vec::new()
    } else {
        match read_f32(knots, knot_count as usize) {
            Some(k) => k,
            None => return fail(n, 36, true),
        }
    };
    if let Err(e) = bezier::validate(&kv, i64::from(order)) {
        return fail(n, e as u32, false);
    }
    let basis = Basis {
        order: order as usize,
        knots: kv,
    };
    let count = basis.count();
    if ctl.is_null() {
        return fail(n, 36, true);
    }
    let stride = (stride as usize).max(dim);
    let mut pts = Vec::with_capacity(count * dim);
    for i in 0..count {
        // SAFETY: the caller's array holds `count` points `stride` floats apart.
        let p = unsafe { std::slice::from_raw_parts(ctl.add(i * stride), dim) };
        pts.extend_from_slice(p);
    }
    Ok(CurveDef {
        target,
        dim,
        basis,
        pts,
    })
}

/// `gluNurbsCurve`: a curve map, or a trim piece inside gluBeginTrim. Outside
/// gluBeginCurve it is drawn at once, as its own curve.
#[no_mangle]
pub extern "C" fn gluNurbsCurve(
    nobj: *mut Nurbs,
    knot_count: GLint,
    knots: *const GLfloat,
    stride: GLint,
    ctl: *const GLfloat,
    order: GLint,
    target: GLenum,
) {
    let Some(n) = obj(nobj) else { return };
    let in_trim = matches!(n.stage, Stage::Surface { in_trim: true, .. });
    let implicit = !in_trim && !matches!(n.stage, Stage::Curve(_));
    if implicit {
        if matches!(n.stage, Stage::Surface { .. }) {
            // A curve map inside a surface but outside a trim: not a trim piece.
            n.nurbs_error(14);
            n.bad = true;
            return;
        }
        n.begin_curve();
    }
    let trim_target = matches!(target, MAP1_TRIM_2 | MAP1_TRIM_3);
    if in_trim != trim_target {
        n.nurbs_error(if in_trim { 14 } else { 22 });
        n.bad = true;
    } else {
        match curve_def(n, knot_count, knots, stride, ctl, order, target) {
            Ok(def) => match &mut n.stage {
                Stage::Curve(maps) => maps.push(def),
                Stage::Surface { loops, .. } => {
                    if let Some(l) = loops.last_mut() {
                        l.push(TrimPiece::Curve(def));
                    }
                }
                Stage::Idle => {}
            },
            Err(r) => n.bad |= r.bad,
        }
    }
    if implicit {
        n.end_curve();
    }
}

/// `gluBeginSurface`.
#[no_mangle]
pub extern "C" fn gluBeginSurface(nobj: *mut Nurbs) {
    if let Some(n) = obj(nobj) {
        n.begin_surface();
    }
}

/// Reads one direction's knots, or reports why not.
fn knots_of(n: &mut Nurbs, count: GLint, knots: *const GLfloat, order: GLint) -> Option<Basis> {
    if count < 0 || i64::from(count) > MAX_KNOTS {
        n.nurbs_error(2);
        return None;
    }
    let kv = if count == 0 {
        Vec::new()
    } else if let Some(k) = read_f32(knots, count as usize) {
        k
    } else {
        n.nurbs_error(36);
        n.bad = true;
        return None;
    };
    if let Err(e) = bezier::validate(&kv, i64::from(order)) {
        n.nurbs_error(e as u32);
        return None;
    }
    Some(Basis {
        order: order as usize,
        knots: kv,
    })
}

/// `gluNurbsSurface`: one map of the surface. Outside gluBeginSurface it is drawn at
/// once, as its own surface.
#[no_mangle]
pub extern "C" fn gluNurbsSurface(
    nobj: *mut Nurbs,
    s_count: GLint,
    s_knots: *const GLfloat,
    t_count: GLint,
    t_knots: *const GLfloat,
    s_stride: GLint,
    t_stride: GLint,
    ctl: *const GLfloat,
    s_order: GLint,
    t_order: GLint,
    target: GLenum,
) {
    let Some(n) = obj(nobj) else { return };
    let Some(dim) = (0x0DB0..=0x0DB8)
        .contains(&target)
        .then(|| map_dim(target))
        .flatten()
    else {
        n.nurbs_error(35);
        n.bad = true;
        return;
    };
    if s_stride < 0 || t_stride < 0 {
        n.nurbs_error(34);
        n.bad = true;
        return;
    }
    let Some(s) = knots_of(n, s_count, s_knots, s_order) else {
        return;
    };
    let Some(t) = knots_of(n, t_count, t_knots, t_order) else {
        return;
    };
    let (ns, nt) = (s.count(), t.count());
    if ctl.is_null() || ns.saturating_mul(nt) > MAX_KNOTS as usize {
        n.nurbs_error(36);
        n.bad = true;
        return;
    }
    let mut pts = Vec::with_capacity(ns * nt * dim);
    for i in 0..ns {
        for j in 0..nt {
            let off = i * s_stride as usize + j * t_stride as usize;
            // SAFETY: the caller's array holds the ns × nt points at these strides.
            pts.extend_from_slice(unsafe { std::slice::from_raw_parts(ctl.add(off), dim) });
        }
    }
    let implicit = !matches!(n.stage, Stage::Surface { .. });
    if implicit {
        n.begin_surface();
    }
    if let Stage::Surface { maps, .. } = &mut n.stage {
        maps.push(SurfDef {
            target,
            dim,
            s,
            t,
            pts,
        });
    }
    if implicit {
        n.end_surface();
    }
}

/// `gluBeginTrim`.
#[no_mangle]
pub extern "C" fn gluBeginTrim(nobj: *mut Nurbs) {
    let Some(n) = obj(nobj) else { return };
    if !matches!(n.stage, Stage::Surface { .. }) {
        n.nurbs_error(15);
        n.begin_surface();
    }
    if matches!(n.stage, Stage::Surface { in_trim: true, .. }) {
        n.nurbs_error(16);
        n.end_trim();
    }
    if let Stage::Surface { loops, in_trim, .. } = &mut n.stage {
        *in_trim = true;
        loops.push(Vec::new());
    }
}

/// `gluPwlCurve`: a polyline trim piece of `count` points `stride` floats apart.
#[no_mangle]
pub extern "C" fn gluPwlCurve(
    nobj: *mut Nurbs,
    count: GLint,
    data: *const GLfloat,
    stride: GLint,
    target: GLenum,
) {
    let Some(n) = obj(nobj) else { return };
    let dim = match target {
        MAP1_TRIM_2 => 2,
        MAP1_TRIM_3 => 3,
        _ => {
            n.nurbs_error(35);
            n.bad = true;
            return;
        }
    };
    if count < 0 || stride < 0 || i64::from(count) > MAX_KNOTS || data.is_null() {
        n.nurbs_error(if count < 0 {
            33
        } else if stride < 0 {
            34
        } else {
            36
        });
        n.bad = true;
        return;
    }
    if !matches!(n.stage, Stage::Surface { in_trim: true, .. }) {
        n.nurbs_error(19);
        return;
    }
    let stride = (stride as usize).max(dim);
    let pts: Vec<[f32; 2]> = (0..count as usize)
        .map(|i| {
            // SAFETY: the caller's array holds `count` points `stride` floats apart.
            let p = unsafe { std::slice::from_raw_parts(data.add(i * stride), dim) };
            if dim == 3 {
                [p[0] / p[2], p[1] / p[2]]
            } else {
                [p[0], p[1]]
            }
        })
        .collect();
    if let Stage::Surface { loops, .. } = &mut n.stage {
        if let Some(l) = loops.last_mut() {
            l.push(TrimPiece::Pwl(pts));
        }
    }
}

/// `gluEndTrim`.
#[no_mangle]
pub extern "C" fn gluEndTrim(nobj: *mut Nurbs) {
    if let Some(n) = obj(nobj) {
        n.end_trim();
    }
}

/// `gluEndSurface`: draws the surface.
#[no_mangle]
pub extern "C" fn gluEndSurface(nobj: *mut Nurbs) {
    if let Some(n) = obj(nobj) {
        n.end_surface();
    }
}
