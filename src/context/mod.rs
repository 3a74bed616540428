//! The GL state machine: one [`Context`] per OSMesa context, holding plain state data,
//! matrix stacks, named objects, the vertex-input state and the framebuffer. Its modules
//! own the state of each area (lighting, texgen, rasterization, fragment operations, pixel
//! transfer …), immediate mode and display lists, the attribute stacks, framebuffer
//! objects, occlusion queries, feedback and selection, evaluators, the accumulation buffer,
//! buffer-object storage and the objects shared between contexts.
//!
//! Every method validates its arguments first and returns a [`GlError`] without touching
//! state when they are wrong; the C boundary records the error for glGetError.

pub mod accum;
pub mod arrays;
pub mod attrib;
pub mod bitmap_read;
pub mod buffer_api;
pub mod buffer_select;
pub mod builtin_matrices;
pub mod builtin_uniforms;
pub mod client_arrays;
pub mod client_image;
pub mod dlist;
pub mod dlist_node;

pub mod draw;
pub mod draw_cmd;
pub use crate::gl::error;
pub mod eval;
pub mod fbo;
pub mod fbo_api;
pub mod fbo_bind;
pub mod fbo_draw_buffers;
pub mod fbo_image;
pub mod fbo_lend;
pub mod fbo_query;
pub mod feedback;
pub mod frag_outputs;
pub mod fragment_state;
pub mod generic_attrib;
pub mod get;
pub mod get_extra;
pub mod get_shader;
pub mod hint_clip;
pub mod immediate;
pub mod instanced;
pub mod legacy_state;
pub mod lighting_state;
pub mod list_calls;
pub mod multi_draw;
pub mod pack;
pub mod pixel_api;
pub mod pixel_buffer;
pub mod pixel_ops;
pub mod pixel_state;
pub mod pixel_transfer;
pub mod point_sprite;
pub mod polygon_cmds;
pub mod program_draw;
pub mod program_link;
pub mod queries;
pub mod raster_state;
pub mod shader_objects;
pub mod share;
pub mod state;
pub mod state_setters;
pub mod store;
pub mod texgen_state;
pub mod texture_3d;
pub mod texture_ci;
pub mod texture_compressed;
pub mod texture_copy;
pub mod texture_ds;
pub mod texture_get;
pub mod texture_gl;
pub mod texture_pack;
pub mod texture_params;
pub mod texture_spec;
pub mod uniforms;
pub mod user_buffer;
pub mod vertex_cmd;
pub mod vertex_material;

use crate::fixed_function::matrix::{Mat4, MatrixStack};
use crate::framebuffer::{ColorFormat, DepthFormat, Framebuffer};
use crate::stats::Stats;
pub use error::{GlError, GlResult};
use state::{Cap, MatrixMode, State, MAX_TEXTURE_UNITS};

/// GL_MAX_MODELVIEW_STACK_DEPTH (Mesa's value).
pub const MAX_MODELVIEW_STACK_DEPTH: usize = 32;
/// GL_MAX_PROJECTION_STACK_DEPTH (Mesa's value).
pub const MAX_PROJECTION_STACK_DEPTH: usize = 32;
/// GL_MAX_TEXTURE_STACK_DEPTH (Mesa's value).
pub const MAX_TEXTURE_STACK_DEPTH: usize = 10;
/// GL_MAX_COLOR_MATRIX_STACK_DEPTH (Mesa's value).
pub const MAX_COLOR_STACK_DEPTH: usize = 4;
/// GL_MAX_VIEWPORT_DIMS and the largest OSMesa buffer (llvmpipe's limit).
pub const MAX_VIEWPORT: i32 = 16384;

/// The buffers an OSMesa context was created with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Visual {
    /// Colour layout.
    pub format: ColorFormat,
    /// Depth layout.
    pub depth: DepthFormat,
    /// Whether there is an 8-bit stencil buffer.
    pub stencil: bool,
    /// Accumulation bits requested (any positive number gives Mesa's 16-bit buffer).
    pub accum_bits: i32,
}

/// All matrix stacks.
#[derive(Clone, Debug)]
pub struct Matrices {
    /// GL_MODELVIEW.
    pub modelview: MatrixStack,
    /// GL_PROJECTION.
    pub projection: MatrixStack,
    /// GL_TEXTURE, one per unit.
    pub texture: Vec<MatrixStack>,
    /// GL_COLOR.
    pub color: MatrixStack,
}

impl Default for Matrices {
    fn default() -> Self {
        Matrices {
            modelview: MatrixStack::new(MAX_MODELVIEW_STACK_DEPTH),
            projection: MatrixStack::new(MAX_PROJECTION_STACK_DEPTH),
            texture: (0..MAX_TEXTURE_UNITS)
                .map(|_| MatrixStack::new(MAX_TEXTURE_STACK_DEPTH))
                .collect(),
            color: MatrixStack::new(MAX_COLOR_STACK_DEPTH),
        }
    }
}

/// One GL context.
pub struct Context {
    /// Plain GL state.
    pub state: State,
    /// Matrix stacks.
    pub matrices: Matrices,
    /// Client arrays and buffer objects.
    pub arrays: arrays::ArrayState,
    /// glBegin/glEnd in progress.
    pub immediate: immediate::Immediate,
    /// The generic vertex attributes' current values (glVertexAttrib*).
    pub generic_current: [[f32; 4]; arrays::MAX_VERTEX_ATTRIBS],
    /// The instance a draw is drawing (a vertex shader's `gl_InstanceID`): 0 outside
    /// instanced draws ([`instanced`]). Not in [`arrays::ArrayState`], which a draw moves
    /// out of the context while it reads the arrays.
    pub draw_instance: u32,
    /// The first error not yet read by glGetError.
    pub error: Option<GlError>,
    /// The buffers this context was created with.
    pub visual: Visual,
    /// Colour/depth/stencil storage; `None` until the first OSMesaMakeCurrent.
    pub fb: Option<Framebuffer>,
    /// Whether something was drawn or cleared since the last copy to the user buffer.
    pub dirty: bool,
    /// Work counters.
    pub stats: Stats,
    /// Where glFlush/glFinish copy the colour buffer (the OSMesa user buffer).
    pub target: UserTarget,
    /// The copy OSMesaGetDepthBuffer hands out, refreshed at each flush once requested.
    pub depth_copy: Option<Vec<u8>>,
    /// Texture objects and texture units.
    pub textures: crate::texture::TextureState,
    /// Lights, materials, colour material and fog.
    pub light: crate::context::lighting_state::LightingState,
    /// Line, point and polygon rasterization state.
    pub raster: raster_state::RasterState,
    /// glTexGen state per texture unit.
    pub texgen: texgen_state::TexGenState,
    /// User clip planes.
    pub clip_planes: texgen_state::ClipPlanes,
    /// The current raster position.
    pub raster_pos: pixel_state::RasterPos,
    /// Pixel zoom (GL_PIXEL_MODE_BIT).
    pub pixel_modes: pixel_state::PixelModes,
    /// glPixelMap tables (in no attribute group).
    pub pixel_maps: pixel_transfer::PixelMaps,
    /// glBitmap calls not drawn yet (Mesa's bitmap cache).
    pub bitmap_cache: crate::context::pixel_ops::bitmap_cache::BitmapCache,
    /// Display lists.
    pub lists: dlist::ListState,
    /// glPushAttrib / glPushClientAttrib stacks.
    pub attrib: attrib::AttribStacks,
    /// Occlusion query objects.
    pub queries: queries::QueryState,
    /// The accumulation buffer and its clear value.
    pub accum: accum::AccumState,
    /// Evaluator maps and grids.
    pub eval: eval::EvalState,
    /// Render mode, feedback and selection buffers, name stack.
    pub feedback: feedback::FeedbackState,
    /// Framebuffer and renderbuffer objects and their bindings.
    pub fbo: fbo::FboState,
    /// GL 2.0 shader and program objects and the current program.
    pub shaders: shader_objects::ShaderState,
    /// The last batch of a glBegin/glEnd draw, still drawn by the pool
    /// ([`crate::raster::batch::Rasterizer::flush_detached`]), holding the framebuffer
    /// (`fb` is `None` meanwhile) until [`Context::settle_draws`] puts it back or the next
    /// such draw takes it over ([`Context::release_inflight`]).
    inflight: Option<crate::raster::batch::InFlight>,
    /// Buffers reused by glDrawPixels and glCopyPixels.
    pub pixel_scratch: crate::pixels::draw::Scratch,
}

/// The OSMesa user buffer and its layout parameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct UserTarget {
    /// The user's buffer (0 when none).
    pub ptr: usize,
    /// Its component type (GL_UNSIGNED_BYTE …).
    pub ty: u32,
    /// Width in pixels.
    pub width: usize,
    /// Height in pixels.
    pub height: usize,
    /// OSMESA_ROW_LENGTH in pixels (0 = width).
    pub row_length: i32,
    /// OSMESA_Y_UP: row 0 of the user buffer is the bottom row.
    pub y_up: bool,
}

impl Default for UserTarget {
    fn default() -> Self {
        UserTarget {
            ptr: 0,
            ty: 0,
            width: 0,
            height: 0,
            row_length: 0,
            y_up: true,
        }
    }
}

impl Drop for Context {
    fn drop(&mut self) {
        // The pool may still be drawing into `fb`.
        self.settle_draws();
    }
}

impl Context {
    /// A context with GL's initial state and no framebuffer yet.
    pub fn new(visual: Visual) -> Self {
        Context {
            state: State::default(),
            matrices: Matrices::default(),
            arrays: arrays::ArrayState::default(),
            immediate: immediate::Immediate::default(),
            generic_current: [generic_attrib::GENERIC_DEFAULT; arrays::MAX_VERTEX_ATTRIBS],
            draw_instance: 0,
            error: None,
            visual,
            fb: None,
            dirty: false,
            stats: Stats::default(),
            target: UserTarget::default(),
            depth_copy: None,
            textures: crate::texture::TextureState::default(),
            light: Default::default(),
            raster: Default::default(),
            texgen: Default::default(),
            clip_planes: Default::default(),
            raster_pos: Default::default(),
            pixel_modes: Default::default(),
            pixel_maps: Default::default(),
            bitmap_cache: Default::default(),
            lists: Default::default(),
            attrib: Default::default(),
            queries: Default::default(),
            accum: Default::default(),
            eval: Default::default(),
            feedback: Default::default(),
            fbo: Default::default(),
            shaders: Default::default(),
            inflight: None,
            pixel_scratch: Default::default(),
        }
    }

    /// Waits for the draw still running on the pool, if any, and puts its framebuffer
    /// back into `fb` (see `inflight`). Every GL call but the per-vertex ones and the
    /// state calls that touch no image (`ffi::with_ctx_list_keep`) does this first
    /// (through [`Context::flush_pending`]), as do draws, framebuffer (re)binding and
    /// dropping the context.
    #[inline]
    pub fn settle_draws(&mut self) {
        if let Some(f) = self.inflight.take() {
            self.fb = f.settle(&mut self.stats);
        }
        self.unhold_samples();
    }

    /// Puts the sample planes a multisample draw's batch held (`fbo.ms_held`) back into
    /// `fbo.ms_planes`, once nothing is left on the pool.
    pub(crate) fn unhold_samples(&mut self) {
        if self.fbo.ms_held && self.inflight.is_none() {
            if let Some(fb) = self.fb.as_mut() {
                self.fbo.ms_planes = fb.release_samples();
            }
            self.fbo.ms_held = false;
        }
    }

    /// The draw still running on the pool, if any, with its framebuffer put back into `fb`
    /// without waiting: for the next draw into `fb`, whose rasterizer takes it back
    /// ([`crate::raster::batch::Rasterizer::adopt`]) before anything touches `fb`.
    pub(crate) fn release_inflight(&mut self) -> Option<crate::raster::batch::Adopted> {
        let (a, fb) = self.inflight.take()?.release();
        self.fb = fb;
        Some(a)
    }

    /// Hands `fb` to `f`, the last batch of a draw still drawing into it on the pool,
    /// until [`Context::settle_draws`].
    ///
    /// # Safety
    /// `f` must come from [`crate::raster::batch::Rasterizer::flush_detached`] over this
    /// context's `fb`, with nothing touching `fb` since, and no other draw in flight (the
    /// draw settled first).
    pub(crate) unsafe fn keep_inflight(&mut self, mut f: crate::raster::batch::InFlight) {
        debug_assert!(self.inflight.is_none());
        f.hold(self.fb.take());
        self.inflight = Some(f);
    }

    /// Draws a deferred glBegin/glEnd batch, if any, and waits for the draws on the pool.
    /// Every GL call except the vertex attribute calls and glBegin does this first, as
    /// Mesa flushes its vertex buffer.
    #[inline]
    pub fn flush_pending(&mut self) {
        self.draw_pending(false);
        self.settle_draws();
    }

    /// Draws a deferred glBegin/glEnd batch, if any, leaving its last batch of triangles
    /// drawing on the pool (glBegin, and glEnd of a mode that is never merged, which go on
    /// to more vertices; the next draw takes it back, any other GL call waits for it).
    pub fn flush_pending_keep(&mut self) {
        self.draw_pending(true);
    }

    /// Draws a deferred glBegin/glEnd batch, if any; with `keep`, its last batch of
    /// triangles may stay drawing on the pool.
    fn draw_pending(&mut self, keep: bool) {
        if let Some(mode) = self.immediate.pending.take() {
            if self.draw_pending_node(mode, keep) {
                self.immediate.generic_inside = false;
                return;
            }
            let mats = self.take_vertex_materials();
            let verts = std::mem::take(&mut self.immediate.verts);
            if verts.has_generic() {
                // Each vertex carries its generic attributes: a vertex shader reads them.
                self.immediate.generic_inside = false;
            }
            // A batch from a display list is drawn indexed, as Mesa draws vertex nodes.
            let idx: Option<Vec<u32>> = self
                .immediate
                .indexed
                .then(|| (0..verts.len() as u32).collect());
            draw::draw_batch(self, mode, &verts, idx.as_deref(), mats.as_deref(), keep);
            let im = &mut self.immediate;
            let total = std::mem::take(&mut im.streamed) + verts.len();
            im.verts = verts;
            im.verts.clear();
            if total > im.verts.room() {
                // The batch was drawn in chunks: the next one like it is held whole and
                // drawn here (with room to spare, so that it is not drawn by its last
                // glVertex either).
                im.verts.reserve_total(total + total / 4);
            }
        }
        // The batch that set generic attributes inside glBegin/glEnd is drawn (or none is
        // left: a display list's glBegin/glEnd is drawn before its next call).
        self.immediate.generic_inside = false;
    }

    /// Records `e` unless an earlier error is still unread.
    pub fn record_error(&mut self, e: GlError) {
        if self.error.is_none() {
            self.error = Some(e);
        }
    }

    /// glGetError: returns and clears the recorded error.
    pub fn take_error(&mut self) -> Option<GlError> {
        self.error.take()
    }

    /// The glBegin/glEnd rule of the GL entry points (applied by the `src/ffi` wrappers):
    /// GL_INVALID_OPERATION between a glBegin and glEnd executed now. A glBegin compiled
    /// under GL_COMPILE_AND_EXECUTE does not count, as in Mesa, which draws that primitive
    /// only at its glEnd: commands that are not compiled run as usual there, and the
    /// compiled ones follow the list's rule ([`dlist::ListState::compiling_inside_begin`]).
    #[inline]
    pub fn outside_begin_end(&self) -> GlResult<()> {
        if self.immediate.active.is_some() && self.lists.compiling.is_none() {
            Err(GlError::InvalidOperation)
        } else {
            Ok(())
        }
    }

    /// Fails with GL_INVALID_OPERATION between glBegin and glEnd.
    #[inline]
    pub fn check_outside_begin(&self) -> GlResult<()> {
        if self.immediate.active.is_some() {
            Err(GlError::InvalidOperation)
        } else {
            Ok(())
        }
    }

    /// Binds (or resizes) the framebuffer for a user buffer of `w` x `h`. A new size or
    /// format gives a new, zeroed framebuffer, as Mesa does; the first binding sets the
    /// viewport and scissor to the buffer size. `retyped` (a new component type) also gives
    /// a new framebuffer, as Mesa picks another pipe format.
    pub fn bind_framebuffer(&mut self, w: usize, h: usize, retyped: bool) {
        self.with_window(|c| c.bind_window_buffer(w, h, retyped));
    }

    /// [`Context::bind_framebuffer`] with the window's framebuffer in `fb`.
    fn bind_window_buffer(&mut self, w: usize, h: usize, retyped: bool) {
        self.settle_draws();
        let first = self.fb.is_none();
        let same = !retyped
            && self.fb.as_ref().is_some_and(|fb| {
                fb.width == w && fb.height == h && fb.format == self.visual.format
            });
        if !same {
            self.fb = Some(Framebuffer::new(
                w,
                h,
                self.visual.format,
                self.visual.depth,
                self.visual.stencil,
            ));
            self.dirty = false;
        }
        if first {
            self.state.viewport = [0, 0, w as i32, h as i32];
            self.state.scissor = [0, 0, w as i32, h as i32];
        }
    }

    /// glFlush/glFinish: copies the colour buffer into the user buffer if anything was drawn
    /// or cleared since the last copy (Mesa's `rb->defined`), and refreshes the depth copy.
    pub fn flush(&mut self) {
        crate::context::pixel_ops::bitmap_cache::flush(self);
        let Some(fb) = self.window_fb() else { return };
        if !self.dirty || self.target.ptr == 0 {
            return;
        }
        let wide = wide_type(self.target.ty);
        let bpp = fb.format.bytes_per_pixel() * wide.map_or(1, |w| w.bytes());
        let row_px = if self.target.row_length > 0 {
            self.target.row_length as usize
        } else {
            fb.width
        };
        // SAFETY: OSMesaMakeCurrent's contract: the buffer holds at least
        // row_length * height pixels of the format (the program promised it to Mesa too).
        unsafe {
            match wide {
                None => fb.copy_to_user(self.target.ptr as *mut u8, row_px * bpp, self.target.y_up),
                Some(t) => fb.copy_to_user_wide(
                    self.target.ptr as *mut u8,
                    row_px * bpp,
                    self.target.y_up,
                    t,
                ),
            }
        };
        self.dirty = false;
        if self.depth_copy.is_some() {
            self.depth_copy = Some(self.depth_snapshot());
        }
    }

    /// The OSMesa window's framebuffer, wherever it is (parked while an object is bound
    /// for drawing).
    pub fn window_fb(&self) -> Option<&Framebuffer> {
        if self.fbo.draw == 0 {
            self.fb.as_ref()
        } else {
            self.fbo.window.as_ref()
        }
    }

    /// Bits per colour channel (r, g, b, a) of the bound buffer: 16 or 32 for
    /// GL_UNSIGNED_SHORT and GL_FLOAT user buffers.
    pub fn color_bits(&self) -> [i32; 4] {
        let bits = self.visual.format.channel_bits();
        match wide_type(self.target.ty) {
            Some(t) => bits.map(|b| if b > 0 { 8 * t.bytes() as i32 } else { 0 }),
            None => bits,
        }
    }

    /// The depth (and stencil) buffer as OSMesaGetDepthBuffer presents it: bottom-up rows,
    /// 4 bytes per value for Z24 (stencil in the high byte), 2 for Z16.
    pub fn depth_snapshot(&self) -> Vec<u8> {
        let Some(fb) = self.window_fb() else {
            return Vec::new();
        };
        let mut out = Vec::new();
        for row in (0..fb.height).rev() {
            for x in 0..fb.width {
                let i = row * fb.width + x;
                match fb.depth_format {
                    DepthFormat::Z16 => {
                        out.extend_from_slice(&(fb.depth_at(i) as u16).to_ne_bytes())
                    }
                    DepthFormat::Z24 => {
                        let s = fb.stencil.get(i).copied().unwrap_or(0) as u32;
                        out.extend_from_slice(&(fb.depth_at(i) | (s << 24)).to_ne_bytes());
                    }
                    // the window is never float
                    DepthFormat::None | DepthFormat::Z32 | DepthFormat::Z32F => {}
                }
            }
        }
        out
    }

    /// glEnable / glDisable.
    pub fn set_cap(&mut self, cap: Cap, on: bool) -> GlResult<()> {
        self.state.caps.set(cap, on);
        // GL_TEXTURE_1D/2D are per texture unit; `state.caps` mirrors the active unit.
        let unit = &mut self.textures.units[self.state.active_texture];
        match cap {
            Cap::Texture1D => unit.enabled_1d = on,
            Cap::Texture2D => unit.enabled_2d = on,
            Cap::Texture3D => unit.enabled_3d = on,
            Cap::TextureCubeMap => unit.enabled_cube = on,
            Cap::TexGenS | Cap::TexGenT | Cap::TexGenR | Cap::TexGenQ => {
                let bit = 1u8 << (cap as u8 - Cap::TexGenS as u8);
                let g = &mut self.texgen.units[self.state.active_texture].enabled;
                *g = if on { *g | bit } else { *g & !bit };
            }
            Cap::ClipPlane0
            | Cap::ClipPlane1
            | Cap::ClipPlane2
            | Cap::ClipPlane3
            | Cap::ClipPlane4
            | Cap::ClipPlane5
            | Cap::ClipPlane6
            | Cap::ClipPlane7 => {
                let bit = 1u8 << (cap as u8 - Cap::ClipPlane0 as u8);
                let g = &mut self.clip_planes.enabled;
                *g = if on { *g | bit } else { *g & !bit };
            }
            // Mesa copies the current colour into the tracked material when colour material
            // is switched (and whenever the colour changes while it is on).
            Cap::ColorMaterial => self.light.sync_color_material(self.state.current.color),
            _ => {}
        }
        Ok(())
    }

    /// Mirrors the active unit's GL_TEXTURE_GEN_S/T/R/Q enables into the cap bits.
    pub fn sync_texgen_caps(&mut self) {
        let g = self.texgen.units[self.state.active_texture].enabled;
        for (k, cap) in [Cap::TexGenS, Cap::TexGenT, Cap::TexGenR, Cap::TexGenQ]
            .into_iter()
            .enumerate()
        {
            self.state.caps.set(cap, g & (1 << k) != 0);
        }
    }

    /// The matrix stack glMatrixMode selects.
    pub fn current_stack(&mut self) -> &mut MatrixStack {
        match self.state.matrix_mode {
            MatrixMode::ModelView => &mut self.matrices.modelview,
            MatrixMode::Projection => &mut self.matrices.projection,
            MatrixMode::Texture => &mut self.matrices.texture[self.state.active_texture],
            MatrixMode::Color => &mut self.matrices.color,
        }
    }

    /// glPushMatrix: GL_STACK_OVERFLOW when the selected stack is full.
    pub fn push_matrix(&mut self) -> GlResult<()> {
        if self.current_stack().push() {
            Ok(())
        } else {
            Err(GlError::StackOverflow)
        }
    }

    /// glPopMatrix: GL_STACK_UNDERFLOW when the selected stack holds one matrix.
    pub fn pop_matrix(&mut self) -> GlResult<()> {
        if self.current_stack().pop() {
            Ok(())
        } else {
            Err(GlError::StackUnderflow)
        }
    }

    /// Applies `f` to the current matrix (outside glBegin/glEnd).
    pub fn with_matrix(&mut self, f: impl FnOnce(&mut Mat4)) -> GlResult<()> {
        self.with_matrix_flags(|m, _| f(m))
    }

    /// Applies `f` to the current matrix and its Mesa flags (outside glBegin/glEnd).
    pub fn with_matrix_flags(
        &mut self,
        f: impl FnOnce(&mut Mat4, &mut crate::fixed_function::mesa_matrix::MatFlags),
    ) -> GlResult<()> {
        let (m, fl) = self.current_stack().top_both_mut();
        f(m, fl);
        Ok(())
    }

    /// glViewport.
    pub fn viewport(&mut self, x: i32, y: i32, w: i32, h: i32) -> GlResult<()> {
        if w < 0 || h < 0 {
            return Err(GlError::InvalidValue);
        }
        self.state.viewport = [x, y, w.min(MAX_VIEWPORT), h.min(MAX_VIEWPORT)];
        Ok(())
    }

    /// glScissor.
    pub fn scissor(&mut self, x: i32, y: i32, w: i32, h: i32) -> GlResult<()> {
        crate::context::pixel_ops::bitmap_cache::flush(self);
        if w < 0 || h < 0 {
            return Err(GlError::InvalidValue);
        }
        self.state.scissor = [x, y, w, h];
        Ok(())
    }

    /// glDepthRange (clamped to [0,1]).
    pub fn depth_range(&mut self, n: f64, f: f64) -> GlResult<()> {
        // Mesa keeps the range as f32 (it is then widened again for the viewport transform).
        self.state.depth_range = [clamp01(n) as f32 as f64, clamp01(f) as f32 as f64];
        Ok(())
    }

    /// The drawable rectangle in y-down pixels: framebuffer ∩ scissor, as (x0, y0, x1, y1)
    /// exclusive at the high end; `None` when empty.
    pub fn draw_region(&self) -> Option<[i64; 4]> {
        let fb = self.fb.as_ref()?;
        let (w, h) = (fb.width as i64, fb.height as i64);
        let mut r = [0, 0, w, h];
        if self.state.caps.get(Cap::ScissorTest) {
            let [sx, sy, sw, sh] = self.state.scissor.map(|v| v as i64);
            // GL y-up rows [sy, sy+sh) are y-down rows [h-sy-sh, h-sy) (in the window).
            let (y0, y1) = if fb.y_flip {
                (h - sy - sh, h - sy)
            } else {
                (sy, sy + sh)
            };
            r = [r[0].max(sx), r[1].max(y0), r[2].min(sx + sw), r[3].min(y1)];
        }
        (r[0] < r[2] && r[1] < r[3]).then_some(r)
    }

    /// glClear.
    pub fn clear(&mut self, mask: u32) -> GlResult<()> {
        crate::context::pixel_ops::bitmap_cache::flush(self);
        use crate::gl::enums::*;
        let all =
            GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT;
        if mask & !all != 0 {
            return Err(GlError::InvalidValue);
        }
        self.check_draw_framebuffer()?;
        if mask & GL_ACCUM_BUFFER_BIT != 0 {
            self.clear_accum_buffer();
        }
        // Every sample plane of a multisample draw buffer gets the clear values.
        self.for_each_sample(|c, _| c.clear_plane(mask));
        Ok(())
    }

    /// glClear's writes into the draw framebuffer in `fb` (one sample plane of a
    /// multisample object).
    fn clear_plane(&mut self, mask: u32) {
        use crate::gl::enums::*;
        let Some(region) = self.draw_region() else {
            return;
        };
        let st = &self.state;
        let Some(fb) = self.fb.as_mut() else {
            return;
        };
        let [x0, y0, x1, y1] = region.map(|v| v as usize);
        let w = fb.width;
        // Mesa clears with pipe->clear only for full-buffer, full-mask clears; otherwise it
        // draws a quad, whose colour and depth go through the shader's conversions.
        let color_mask = st.color_write_mask();
        // an sRGB buffer with GL_FRAMEBUFFER_SRGB on encodes the clear colour
        let srgb = crate::plan::srgb_store(&st.caps, fb.srgb);
        let quad_path = region != [0, 0, fb.width as i64, fb.height as i64]
            || color_mask != [true; 4]
            || (st.frag.stencil_front.writemask & 0xFF) != 0xFF;
        if !quad_path {
            // The whole colour and depth buffers: recorded, written later by whatever
            // reads or draws them (`Framebuffer::defer_clear`).
            let color = (mask & GL_COLOR_BUFFER_BIT != 0).then(|| {
                if srgb {
                    crate::framebuffer::srgb::clear_value(st.clear_color)
                } else {
                    fb.clear_value(st.clear_color)
                }
            });
            let depth = (mask & GL_DEPTH_BUFFER_BIT != 0 && st.depth_mask)
                .then(|| fb.depth_format.quantize_clear(st.clear_depth));
            fb.defer_clear(color, depth);
        } else {
            fb.resolve();
        }
        if quad_path && mask & GL_COLOR_BUFFER_BIT != 0 && color_mask.iter().any(|&m| m) {
            let v = if srgb {
                let fma = crate::geometry::cpu_has_fma();
                fb.store_rgba8(crate::framebuffer::srgb::shader_value(st.clear_color, fma))
            } else if quad_path {
                fb.store_rgba8(st.clear_color.map(crate::framebuffer::float_to_ubyte))
            } else {
                fb.clear_value(st.clear_color)
            };
            let m = color_mask;
            if m == [true; 4] && x0 == 0 && x1 == w {
                fb.clear_rows(y0..y1, Some(v), None);
            }
            // Only a clear of the whole buffer leaves it uniform (glFlush then fills the
            // user buffer instead of copying it).
            fb.uniform_color = (!quad_path).then_some(v);
            for y in y0..y1 {
                let row = &mut fb.color[y * w + x0..y * w + x1];
                if m == [true; 4] {
                    if x0 != 0 || x1 != w {
                        row.fill(v);
                    }
                } else {
                    for p in row {
                        for c in 0..4 {
                            if m[c] {
                                p[c] = v[c];
                            }
                        }
                    }
                }
            }
        }
        if mask & GL_COLOR_BUFFER_BIT != 0 && !fb.more_colors.is_empty() {
            // Mesa clears every draw buffer with the same value (its clear quad's shader
            // writes all colour buffers).
            let v = match quad_path {
                true => fb.store_rgba8(st.clear_color.map(crate::framebuffer::float_to_ubyte)),
                false => fb.clear_value(st.clear_color),
            };
            fb.clear_more_colors([x0, y0, x1, y1], color_mask, v);
        }
        if let (Some(k), true) = (fb.wide, mask & GL_COLOR_BUFFER_BIT != 0) {
            // A wide buffer gets the clear colour at its own precision: packed as the fast
            // clear does, or converted as the quad's shader output.
            let v = st.clear_color.map(|c| {
                if quad_path {
                    k.from_shader(c)
                } else {
                    k.from_clear(c)
                }
            });
            fb.clear_wide([x0, y0, x1, y1], color_mask, v);
        }
        if quad_path && mask & GL_DEPTH_BUFFER_BIT != 0 && st.depth_mask && !fb.depth.is_empty() {
            let v = if quad_path {
                // the state tracker's quad: z = f32(2d − 1) through the viewport's ·0.5 + 0.5
                let z = (st.clear_depth * 2.0 - 1.0) as f32;
                fb.depth_format.quantize(z * 0.5 + 0.5)
            } else {
                fb.depth_format.quantize_clear(st.clear_depth)
            };
            if x0 == 0 && x1 == w {
                fb.clear_rows(y0..y1, None, Some(v));
            } else {
                for y in y0..y1 {
                    fb.depth[y * w + x0..y * w + x1].fill(v);
                }
            }
        }
        if mask & GL_STENCIL_BUFFER_BIT != 0 && !fb.stencil.is_empty() {
            let wm = (st.frag.stencil_front.writemask & 0xFF) as u8;
            let v = (st.clear_stencil & 0xFF) as u8;
            for y in y0..y1 {
                for s in &mut fb.stencil[y * w + x0..y * w + x1] {
                    *s = (*s & !wm) | (v & wm);
                }
            }
        }
        self.dirty = true;
        self.fbo.drawn = true;
    }
}

/// Clamps to [0,1] (NaN becomes 0).
pub fn clamp01(v: f64) -> f64 {
    if v > 0.0 {
        v.min(1.0)
    } else {
        0.0
    }
}

/// The wide channel type of an OSMesaMakeCurrent `type`, `None` for 8-bit types.
pub(crate) fn wide_type(ty: u32) -> Option<crate::framebuffer::WideType> {
    use crate::framebuffer::WideType;
    match ty {
        crate::gl::enums::GL_UNSIGNED_SHORT => Some(WideType::U16),
        crate::gl::enums::GL_FLOAT => Some(WideType::F32),
        _ => None,
    }
}
