//! GL 1.4 multi-draw (glMultiDrawArrays, glMultiDrawElements) and glDrawRangeElements as
//! sequences of the single draws of [`super::draw_cmd`]: every draw is validated before the
//! first runs, so an error leaves no partial draw, and compiling one into a display list
//! compiles each of its draws.

use super::dlist::Elements;
use super::draw_cmd::{array_range, draw_arrays, draw_elements_base, element_list};
use super::state::Primitive;
use super::{Context, GlError, GlResult};
use crate::gl::types::*;

/// The draws of one multi-draw call, read from the client's arrays: `Err` for a negative
/// draw count (the call's error), one `(first or count, …)` pair per draw.
pub(crate) type Draws<T> = GlResult<Vec<T>>;

impl Context {
    /// glMultiDrawArrays: the `(first, count)` draws, validated (a zero-count draw checks
    /// mode, glBegin and mapped buffers; then no first or count may be negative) before
    /// any runs.
    pub(crate) fn multi_draw_arrays(
        &mut self,
        mode: GLenum,
        draws: &Draws<(GLint, GLsizei)>,
    ) -> GlResult<()> {
        let draws = draws.as_ref().map_err(|e| *e)?;
        draw_arrays(self, mode, 0, 0)?;
        if draws.iter().any(|&(f, k)| k < 0 || f < 0) {
            return Err(GlError::InvalidValue);
        }
        for &(f, k) in draws {
            draw_arrays(self, mode, f, k)?;
        }
        Ok(())
    }

    /// glMultiDrawArrays compiled into the display list: one draw per pair.
    pub(crate) fn compile_multi_draw_arrays(
        &mut self,
        mode: GLenum,
        draws: &Draws<(GLint, GLsizei)>,
    ) {
        match draws {
            Err(e) => self.compile_draw(Err(*e), Ok(Elements::List(Vec::new()))),
            Ok(p) => {
                for &(f, k) in p {
                    self.compile_draw(Primitive::from_gl(mode), array_range(f, k));
                }
            }
        }
    }

    /// glMultiDrawElements: the `(count, indices)` draws, validated (mode and type by a
    /// zero-count draw, then the counts) before any runs.
    pub(crate) fn multi_draw_elements(
        &mut self,
        mode: GLenum,
        type_: GLenum,
        draws: &Draws<(GLsizei, *const GLvoid)>,
        bases: &[GLint],
    ) -> GlResult<()> {
        let draws = draws.as_ref().map_err(|e| *e)?;
        draw_elements_base(self, mode, 0, type_, std::ptr::null(), 0)?;
        if draws.iter().any(|&(k, _)| k < 0) {
            return Err(GlError::InvalidValue);
        }
        for (i, &(k, p)) in draws.iter().enumerate() {
            let base = bases.get(i).copied().unwrap_or(0);
            draw_elements_base(self, mode, k, type_, p, base)?;
        }
        Ok(())
    }

    /// glMultiDrawElements compiled into the display list: one draw per pair, its indices
    /// read now.
    pub(crate) fn compile_multi_draw_elements(
        &mut self,
        mode: GLenum,
        type_: GLenum,
        draws: &Draws<(GLsizei, *const GLvoid)>,
        bases: &[GLint],
    ) {
        let draws = match draws {
            Ok(d) => d,
            Err(e) => return self.compile_draw(Err(*e), Ok(Elements::List(Vec::new()))),
        };
        for (i, &(k, p)) in draws.iter().enumerate() {
            let base = bases.get(i).copied().unwrap_or(0);
            let idx = element_list(self, k, type_, p).map(|e| with_base(e, base));
            self.compile_draw(Primitive::from_gl(mode), idx);
        }
    }

    /// glDrawRangeElements (the range is a hint; indices outside it are still drawn, but
    /// `end < start` is GL_INVALID_VALUE before anything else).
    pub(crate) fn draw_range_elements(&mut self, mode: GLenum, d: &RangeDraw) -> GlResult<()> {
        check_range(d.start, d.end)?;
        draw_elements_base(self, mode, d.count, d.type_, d.indices, d.base)
    }

    /// glDrawRangeElements compiled into the display list.
    pub(crate) fn compile_draw_range_elements(&mut self, mode: GLenum, d: &RangeDraw) {
        let idx = check_range(d.start, d.end)
            .and_then(|_| element_list(self, d.count, d.type_, d.indices))
            .map(|e| with_base(e, d.base));
        self.compile_draw(Primitive::from_gl(mode), idx)
    }
}

/// The arguments of glDrawRangeElements after its mode.
pub(crate) struct RangeDraw {
    /// The smallest index the call promises.
    pub start: GLuint,
    /// The largest index the call promises.
    pub end: GLuint,
    /// How many indices.
    pub count: GLsizei,
    /// Their type.
    pub type_: GLenum,
    /// Where they are (client memory, or an offset into the element buffer).
    pub indices: *const GLvoid,
    /// The base vertex (glDrawRangeElementsBaseVertex; 0 for glDrawRangeElements).
    pub base: GLint,
}

/// A compiled element list with `base` added to every index (the base-vertex draws in a
/// display list).
pub(crate) fn with_base(e: Elements, base: GLint) -> Elements {
    match e {
        Elements::List(mut v) if base != 0 => {
            v.iter_mut().for_each(|i| *i = i.wrapping_add_signed(base));
            Elements::List(v)
        }
        e => e,
    }
}

/// GL_INVALID_VALUE when a glDrawRangeElements range ends before it starts.
fn check_range(start: GLuint, end: GLuint) -> GlResult<()> {
    if end < start {
        Err(GlError::InvalidValue)
    } else {
        Ok(())
    }
}
