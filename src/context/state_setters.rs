//! Listable commands that set two state values at once: glAlphaFunc, glLineStipple,
//! glPolygonOffset; and glEvalPoint1/2, which evaluate at a point of the map grid.

use super::state::CompareFunc;
use super::Context;

impl Context {
    /// glAlphaFunc.
    pub(crate) fn alpha_func(&mut self, f: CompareFunc, ref_: f32) {
        self.state.frag.alpha_func = f;
        self.state.frag.alpha_ref = ref_;
    }

    /// glLineStipple (the factor is clamped to [1, 256]).
    pub(crate) fn line_stipple(&mut self, factor: i32, pattern: u16) {
        self.raster.line.stipple_repeat = factor.clamp(1, 256) as u32;
        self.raster.line.stipple_pattern = pattern;
    }

    /// glPolygonOffset.
    pub(crate) fn polygon_offset(&mut self, factor: f32, units: f32) {
        self.raster.polygon.offset_factor = factor;
        self.raster.polygon.offset_units = units;
    }

    /// glEvalPoint1: `u = i * du + u1` with Mesa's `du = (u2 - u1) / n`.
    pub(crate) fn eval_point1(&mut self, i: i32) {
        let g = self.eval.grid1;
        self.eval_coord(i as f32 * g.step() + g.d[0], None);
    }

    /// glEvalPoint2.
    pub(crate) fn eval_point2(&mut self, i: i32, j: i32) {
        let [gu, gv] = self.eval.grid2;
        let u = i as f32 * gu.step() + gu.d[0];
        let v = j as f32 * gv.step() + gv.d[0];
        self.eval_coord(u, Some(v));
    }
}
