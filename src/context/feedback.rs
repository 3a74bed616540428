//! The feedback and selection render modes (GL 1.5 §5.2–5.3): the render mode, the
//! program's feedback and selection buffers, the name stack and the hit record, with
//! Mesa's arithmetic (`main/feedback.c`).

use super::error::{GlError, GlResult};
use super::get::Value;
use crate::geometry::feedback::PrimSink;
use crate::geometry::ClipVertex;
use crate::gl::enums::*;

/// The deepest name stack (Mesa's `MAX_NAME_STACK_DEPTH`).
pub const MAX_NAME_STACK_DEPTH: usize = 64;

/// glRenderMode's three modes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum RenderMode {
    /// Primitives are rasterized.
    #[default]
    Render,
    /// Primitives that survive clipping and culling produce hit records.
    Select,
    /// Primitives are written to the feedback buffer as tokens and vertices.
    Feedback,
}

impl RenderMode {
    /// The mode named by a GL enum.
    pub fn from_gl(e: u32) -> GlResult<Self> {
        Ok(match e {
            GL_RENDER => RenderMode::Render,
            GL_SELECT => RenderMode::Select,
            GL_FEEDBACK => RenderMode::Feedback,
            _ => return Err(GlError::InvalidEnum),
        })
    }

    /// The GL enum of the mode.
    pub fn to_gl(self) -> u32 {
        match self {
            RenderMode::Render => GL_RENDER,
            RenderMode::Select => GL_SELECT,
            RenderMode::Feedback => GL_FEEDBACK,
        }
    }
}

/// What each feedback vertex holds (glFeedbackBuffer's type; GL_2D initially).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FeedbackLayout {
    /// The GL enum (GL_2D … GL_4D_COLOR_TEXTURE), for glGet.
    pub gl: u32,
    /// Window z follows x and y.
    pub z: bool,
    /// Clip w follows z.
    pub w: bool,
    /// Four colour components follow.
    pub color: bool,
    /// Four texture coordinates follow.
    pub texture: bool,
}

impl Default for FeedbackLayout {
    fn default() -> Self {
        FeedbackLayout {
            gl: GL_2D,
            z: false,
            w: false,
            color: false,
            texture: false,
        }
    }
}

impl FeedbackLayout {
    /// The layout of a feedback type enum.
    pub fn from_gl(e: u32) -> GlResult<Self> {
        let (z, w, color, texture) = match e {
            GL_2D => (false, false, false, false),
            GL_3D => (true, false, false, false),
            GL_3D_COLOR => (true, false, true, false),
            GL_3D_COLOR_TEXTURE => (true, false, true, true),
            GL_4D_COLOR_TEXTURE => (true, true, true, true),
            _ => return Err(GlError::InvalidEnum),
        };
        Ok(FeedbackLayout {
            gl: e,
            z,
            w,
            color,
            texture,
        })
    }
}

/// One vertex as feedback reports it: window x, y (GL's bottom-up), z, clip w, the
/// primary colour and texture unit 0's coordinates.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FeedbackVertex {
    /// Window position and clip w.
    pub win: [f32; 4],
    /// Primary colour.
    pub color: [f32; 4],
    /// Texture coordinates of unit 0.
    pub texcoord: [f32; 4],
}

/// Selection mode's pending hit: whether a primitive hit since the last hit record, and
/// the window-z range of the hits.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PendingHit {
    /// A primitive hit since the last record.
    pub hit: bool,
    /// Smallest window z of the hits.
    pub min_z: f32,
    /// Largest window z of the hits.
    pub max_z: f32,
}

impl PendingHit {
    /// No hit, the range starting from [1, `max_z`]: Mesa starts the largest z at 0
    /// initially and after glSelectBuffer and glInitNames, at −1 after a hit record.
    fn cleared(max_z: f32) -> Self {
        PendingHit {
            hit: false,
            min_z: 1.0,
            max_z,
        }
    }
}

impl Default for PendingHit {
    fn default() -> Self {
        PendingHit::cleared(0.0)
    }
}

/// Render mode, buffers and name stack of a context.
#[derive(Clone, Debug, Default)]
pub struct FeedbackState {
    /// The current render mode.
    pub mode: RenderMode,
    /// The feedback buffer (a program pointer, 0 when none).
    pub fb_buffer: usize,
    /// Its size in floats.
    pub fb_size: usize,
    /// What a vertex holds.
    pub fb_layout: FeedbackLayout,
    /// Values generated since feedback mode was entered (written while below `fb_size`).
    pub fb_count: usize,
    /// The selection buffer (a program pointer, 0 when none).
    pub sel_buffer: usize,
    /// Its size in unsigned integers.
    pub sel_size: usize,
    /// Values generated since selection mode was entered.
    pub sel_count: usize,
    /// Hit records written.
    pub hits: i32,
    /// The hit not yet recorded.
    pub pending: PendingHit,
    /// The name stack.
    pub names: Vec<u32>,
    /// The next feedback line is a GL_LINE_RESET_TOKEN (Mesa's feedback stage keeps this
    /// across draws until a line is written).
    pub line_reset: bool,
}

/// Mesa's conversion of a hit depth in [0,1] to an unsigned integer: the product with
/// `(float)0xFFFFFFFF` (which is 2^32) converted as x86 does an unsigned cast, through
/// a 64-bit integer, so z = 1.0 wraps to 0.
fn hit_depth(z: f32) -> u32 {
    let v = 4_294_967_295u32 as f32 * z;
    if v.is_nan() {
        0
    } else {
        v as i64 as u32
    }
}

impl FeedbackState {
    /// Appends one value to the feedback buffer (counted even when the buffer is full).
    pub fn token(&mut self, v: f32) {
        if self.fb_count < self.fb_size && self.fb_buffer != 0 {
            let p = (self.fb_buffer as *mut f32).wrapping_add(self.fb_count);
            // SAFETY: glFeedbackBuffer's contract: the program keeps `fb_size` floats
            // writable at `fb_buffer` while in feedback mode; `fb_count < fb_size`.
            unsafe { p.write_unaligned(v) };
        }
        self.fb_count += 1;
    }

    /// Appends a vertex in the current layout.
    pub fn vertex(&mut self, v: &FeedbackVertex) {
        let l = self.fb_layout;
        self.token(v.win[0]);
        self.token(v.win[1]);
        if l.z {
            self.token(v.win[2]);
        }
        if l.w {
            self.token(v.win[3]);
        }
        if l.color {
            v.color.iter().for_each(|&c| self.token(c));
        }
        if l.texture {
            v.texcoord.iter().for_each(|&c| self.token(c));
        }
    }

    fn record(&mut self, v: u32) {
        if self.sel_count < self.sel_size && self.sel_buffer != 0 {
            let p = (self.sel_buffer as *mut u32).wrapping_add(self.sel_count);
            // SAFETY: glSelectBuffer's contract: `sel_size` unsigned integers stay
            // writable at `sel_buffer` while in selection mode; `sel_count < sel_size`.
            unsafe { p.write_unaligned(v) };
        }
        self.sel_count += 1;
    }

    /// Notes a hit at window depth `z` (selection mode).
    pub fn update_hit(&mut self, z: f32) {
        let p = &mut self.pending;
        p.hit = true;
        if z < p.min_z {
            p.min_z = z;
        }
        if z > p.max_z {
            p.max_z = z;
        }
    }

    /// Writes the pending hit record, if any: the name-stack depth, the depth range and
    /// the names.
    fn write_hit_record(&mut self) {
        if !self.pending.hit {
            return;
        }
        let (lo, hi) = (hit_depth(self.pending.min_z), hit_depth(self.pending.max_z));
        self.record(self.names.len() as u32);
        self.record(lo);
        self.record(hi);
        for k in 0..self.names.len() {
            self.record(self.names[k]);
        }
        self.pending = PendingHit::cleared(-1.0);
        self.hits += 1;
    }

    fn reset_names(&mut self) {
        self.names.clear();
        self.pending = PendingHit::cleared(0.0);
    }

    /// glFeedbackBuffer.
    pub fn feedback_buffer(&mut self, size: i32, ty: u32, buffer: usize) -> GlResult<()> {
        if self.mode == RenderMode::Feedback {
            return Err(GlError::InvalidOperation);
        }
        let size = usize::try_from(size).map_err(|_| GlError::InvalidValue)?;
        if buffer == 0 && size > 0 {
            self.fb_size = 0;
            return Err(GlError::InvalidValue);
        }
        self.fb_layout = FeedbackLayout::from_gl(ty)?;
        self.fb_size = size;
        self.fb_buffer = buffer;
        self.fb_count = 0;
        Ok(())
    }

    /// glSelectBuffer.
    pub fn select_buffer(&mut self, size: i32, buffer: usize) -> GlResult<()> {
        let size = usize::try_from(size).map_err(|_| GlError::InvalidValue)?;
        if self.mode == RenderMode::Select {
            return Err(GlError::InvalidOperation);
        }
        self.sel_buffer = buffer;
        self.sel_size = size;
        self.sel_count = 0;
        self.pending = PendingHit::cleared(0.0);
        Ok(())
    }

    /// glRenderMode: leaves the current mode (returning its count, or -1 on overflow) and
    /// enters `mode`. Unlike Mesa, which leaves the old mode before it validates the new
    /// one, an invalid call changes nothing (GL 1.5 §2.5).
    pub fn render_mode(&mut self, mode: u32) -> GlResult<i32> {
        let mode = RenderMode::from_gl(mode)?;
        match mode {
            RenderMode::Select if self.sel_size == 0 => return Err(GlError::InvalidOperation),
            RenderMode::Feedback if self.fb_size == 0 => return Err(GlError::InvalidOperation),
            _ => {}
        }
        let result = match self.mode {
            RenderMode::Render => 0,
            RenderMode::Select => {
                self.write_hit_record();
                let r = if self.sel_count > self.sel_size {
                    -1
                } else {
                    self.hits
                };
                self.sel_count = 0;
                self.hits = 0;
                self.reset_names();
                r
            }
            RenderMode::Feedback => {
                let r = if self.fb_count > self.fb_size {
                    -1
                } else {
                    self.fb_count.min(i32::MAX as usize) as i32
                };
                self.fb_count = 0;
                r
            }
        };
        self.mode = mode;
        Ok(result)
    }

    /// glDrawPixels, glCopyPixels and glBitmap outside render mode: in feedback mode
    /// `token` and the raster position as a vertex; nothing in selection mode (GL 1.5
    /// Appendix B, corollary 6).
    pub fn raster_token(&mut self, token: u32, raster: &FeedbackVertex) {
        if self.mode == RenderMode::Feedback {
            self.token(token as f32);
            self.vertex(raster);
        }
    }

    /// glPassThrough.
    pub fn pass_through(&mut self, token: f32) {
        if self.mode == RenderMode::Feedback {
            self.token(GL_PASS_THROUGH_TOKEN as f32);
            self.token(token);
        }
    }

    /// glInitNames.
    pub fn init_names(&mut self) {
        if self.mode == RenderMode::Select {
            self.write_hit_record();
            self.reset_names();
        }
    }

    /// glLoadName.
    pub fn load_name(&mut self, name: u32) -> GlResult<()> {
        if self.mode != RenderMode::Select {
            return Ok(());
        }
        if self.names.is_empty() {
            return Err(GlError::InvalidOperation);
        }
        self.write_hit_record();
        if let Some(top) = self.names.last_mut() {
            *top = name;
        }
        Ok(())
    }

    /// glPushName.
    pub fn push_name(&mut self, name: u32) -> GlResult<()> {
        if self.mode != RenderMode::Select {
            return Ok(());
        }
        if self.names.len() >= MAX_NAME_STACK_DEPTH {
            return Err(GlError::StackOverflow);
        }
        self.write_hit_record();
        self.names.push(name);
        Ok(())
    }

    /// glPopName.
    pub fn pop_name(&mut self) -> GlResult<()> {
        if self.mode != RenderMode::Select {
            return Ok(());
        }
        if self.names.is_empty() {
            return Err(GlError::StackUnderflow);
        }
        self.write_hit_record();
        self.names.pop();
        Ok(())
    }

    /// The glGet values of this state, if `pname` is one of them.
    pub fn get(&self, pname: u32) -> Option<Value> {
        use super::get::Kind;
        let int = |v: f64| Value::from_f64(Kind::Int, &[v]);
        Some(match pname {
            GL_RENDER_MODE => int(self.mode.to_gl() as f64),
            GL_FEEDBACK_BUFFER_SIZE => int(self.fb_size as f64),
            GL_FEEDBACK_BUFFER_TYPE => int(self.fb_layout.gl as f64),
            GL_SELECTION_BUFFER_SIZE => int(self.sel_size as f64),
            GL_NAME_STACK_DEPTH => int(self.names.len() as f64),
            GL_MAX_NAME_STACK_DEPTH => int(MAX_NAME_STACK_DEPTH as f64),
            _ => return None,
        })
    }
}

/// Writes the primitives of a draw into the feedback buffer, or notes their hits.
pub struct FeedbackSink<'a> {
    /// The context's feedback state.
    pub state: &'a mut FeedbackState,
    /// Framebuffer height (window y is flipped back to GL's bottom-up rows).
    pub height: f32,
    /// Where texture unit 0's coordinates are among the varyings.
    pub tex0: usize,
}

impl FeedbackSink<'_> {
    fn vertex(&mut self, v: &ClipVertex) {
        if self.state.mode == RenderMode::Select {
            return self.state.update_hit(v.win[2]);
        }
        let t = self.tex0;
        let fv = FeedbackVertex {
            win: [v.win[0], self.height - v.win[1], v.win[2], 1.0 / v.win[3]],
            color: [v.vary[0], v.vary[1], v.vary[2], v.vary[3]],
            texcoord: [v.vary[t], v.vary[t + 1], v.vary[t + 2], v.vary[t + 3]],
        };
        self.state.vertex(&fv);
    }

    fn token(&mut self, t: u32) {
        if self.state.mode == RenderMode::Feedback {
            self.state.token(t as f32);
        }
    }
}

impl PrimSink for FeedbackSink<'_> {
    fn point(&mut self, v: &ClipVertex) {
        self.token(GL_POINT_TOKEN);
        self.vertex(v);
    }

    fn line(&mut self, a: &ClipVertex, b: &ClipVertex) {
        // GL_LINE_RESET_TOKEN only after the unfilled stage restarted the stipple: Mesa's
        // draw module sends no restart for line primitives themselves.
        if self.state.mode == RenderMode::Feedback && std::mem::take(&mut self.state.line_reset) {
            self.token(GL_LINE_RESET_TOKEN);
        } else {
            self.token(GL_LINE_TOKEN);
        }
        self.vertex(a);
        self.vertex(b);
    }

    fn triangle(&mut self, v: [&ClipVertex; 3]) {
        self.token(GL_POLYGON_TOKEN);
        self.token(3);
        v.iter().for_each(|p| self.vertex(p));
    }

    fn reset_stipple(&mut self) {
        if self.state.mode == RenderMode::Feedback {
            self.state.line_reset = true;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hit_depth_matches_mesas_unsigned_cast() {
        assert_eq!(hit_depth(0.0), 0);
        assert_eq!(hit_depth(0.5), 1 << 31);
        // (float)0xFFFFFFFF is 2^32; x86's conversion through 64 bits wraps it to 0.
        assert_eq!(hit_depth(1.0), 0);
        assert_eq!(hit_depth(0.25), 1 << 30);
    }

    #[test]
    fn overflowing_feedback_counts_past_the_buffer_and_reports_minus_one() {
        let mut buf = [0f32; 3];
        let mut s = FeedbackState::default();
        s.feedback_buffer(3, GL_2D, buf.as_mut_ptr() as usize)
            .unwrap();
        s.render_mode(GL_FEEDBACK).unwrap();
        for v in [1.0, 2.0, 3.0, 4.0] {
            s.token(v);
        }
        assert_eq!(s.render_mode(GL_RENDER), Ok(-1));
        assert_eq!(buf, [1.0, 2.0, 3.0]);
    }

    #[test]
    fn invalid_render_mode_changes_nothing() {
        let mut names = [0u32; 8];
        let mut s = FeedbackState::default();
        s.select_buffer(8, names.as_mut_ptr() as usize).unwrap();
        s.render_mode(GL_SELECT).unwrap();
        s.push_name(7).unwrap();
        s.update_hit(0.5);
        assert_eq!(s.render_mode(0x1234), Err(GlError::InvalidEnum));
        assert_eq!((s.mode, s.hits, s.names.len()), (RenderMode::Select, 0, 1));
        assert_eq!(s.render_mode(GL_RENDER), Ok(1));
        assert_eq!(&names[..4], &[1, 1 << 31, 1 << 31, 7]);
    }
}
