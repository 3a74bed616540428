//! Binding framebuffer objects: the working copy a bound object is drawn through, how it is
//! assembled from the attachments and written back, and the reads through the read binding.
//!
//! See [`super::fbo`] for the model. The working copy's rows are GL's (row 0 at the
//! bottom, [`Framebuffer::y_flip`] false), as llvmpipe draws into objects: its viewport is
//! not flipped, so window coordinates round as they do there, and the images' rows are the
//! working copy's rows. Its size is the smallest of the attached images (GL 3.0 lets them
//! differ).
//!
//! What binding and unbinding cost:
//! - Renderbuffer buffers laid out as the working copy's (RGBA8 and RGBA sRGB colour,
//!   every depth and stencil format, of the working copy's size) are lent to it, every
//!   sample plane of a multisample one too: moved in on assembly and back when the object
//!   is parked, never copied ([`super::fbo_lend`]). So is a depth texture level of the
//!   working copy's size (a shadow map), while the texture is not sampled.
//! - The other images (colour texture images, RGB, legacy and wide colour) are copied in
//!   ([`super::fbo_image::load`]) and written back ([`super::fbo_image::store`]): only the
//!   region the working copy covers, and only when something was drawn.
//! - An object's working copy, with its sample planes, is kept between binds
//!   ([`super::fbo::Cached`]): reused as it is (its loans made anew) when no attached image
//!   changed since, refilled in place when the layout still fits, so a bind allocates
//!   nothing.
//! - A resolving glBlitFramebuffer reads the multisample source's planes with their
//!   buffers lent ([`Context::with_read_planes`]); other reads through another binding
//!   assemble a copy.

use super::fbo::{Attachment, Cached, ImageKind, Layout, Status, SAMPLES};
use super::fbo_image::{image_mut, load, store};
use super::fbo_lend::Loan;
use super::{Context, GlError, GlResult};
use crate::framebuffer::{ColorFormat, DepthFormat, Framebuffer};
use crate::memory::HugeBuf;
use crate::texture::BaseFormat;

/// The colour, depth and stencil images of an object that a working copy is made of.
#[derive(Clone, Copy, Debug, Default)]
struct Parts {
    color: Option<Attachment>,
    depth: Option<Attachment>,
    stencil: Option<Attachment>,
}

impl Parts {
    /// Each attached part, with whether it is the stencil attachment (a depth-stencil
    /// image attached to both points is visited twice, once for each role).
    fn roles(self) -> impl Iterator<Item = (Attachment, bool)> {
        [
            (self.color, false),
            (self.depth, false),
            (self.stencil, true),
        ]
        .into_iter()
        .filter_map(|(a, s)| Some((a?, s)))
    }

    /// [`Parts::roles`] with the index of each role (colour 0, depth 1, stencil 2).
    fn roles_indexed(self) -> impl Iterator<Item = (usize, (Attachment, bool))> {
        [
            (self.color, false),
            (self.depth, false),
            (self.stencil, true),
        ]
        .into_iter()
        .enumerate()
        .filter_map(|(k, (a, s))| Some((k, (a?, s))))
    }
}

/// A working copy laid out as `l` (rows as GL's: llvmpipe draws objects unflipped)
/// without its buffers yet: [`Context::fill`] lends or allocates them.
fn hollow(l: &Layout) -> Framebuffer {
    let mut fb = Framebuffer::new(0, 0, l.format, l.depth, l.stencil);
    fb.width = l.size.0;
    fb.height = l.size.1;
    fb.pending_rows = vec![false; l.size.1];
    fb.y_flip = false;
    fb.wide = l.wide;
    fb.wide_single = l.single;
    fb.srgb = l.srgb;
    fb
}

impl Context {
    /// The images the working copy of object `name` is made of, and its layout; `None`
    /// when the object is incomplete.
    fn parts(&self, name: u32) -> Option<(Parts, Layout)> {
        if self.fbo.status(name, &self.textures) != Status::Complete {
            return None;
        }
        let f = self.fbo.object(name)?;
        let color = f
            .draw_buffer
            .map(|i| f.color[i])
            .filter(|&a| a != Attachment::None);
        let depth = Some(f.depth).filter(|&a| a != Attachment::None);
        let stencil = Some(f.stencil).filter(|&a| a != Attachment::None);
        let (mut w, mut h) = (usize::MAX, usize::MAX);
        let every = f.color.iter().chain([&f.depth, &f.stencil]);
        for &a in every.filter(|&&a| a != Attachment::None) {
            let i = self.fbo.image_info(a, &self.textures)?;
            w = w.min(i.width);
            h = h.min(i.height);
        }
        let parts = Parts {
            color,
            depth,
            stencil,
        };
        let info = |a: Option<Attachment>| a.and_then(|a| self.fbo.image_info(a, &self.textures));
        let wide = self.fbo.wide_kind(parts.color, &self.textures);
        let wide_tex = wide.is_some() && matches!(parts.color, Some(Attachment::Texture(_)));
        let color_kind = info(parts.color).map(|i| i.kind);
        let format =
            match color_kind {
                Some(ImageKind::Color(BaseFormat::Rgb)) => ColorFormat::Rgb,
                // a float or 16-bit red, RG or luminance image has no alpha to blend with
                // (llvmpipe's destination alpha is 1)
                Some(ImageKind::Color(
                    BaseFormat::Red | BaseFormat::Rg | BaseFormat::Luminance,
                )) if wide_tex => ColorFormat::Rgb,
                _ => ColorFormat::Rgba,
            };
        let depth = match info(parts.depth).map(|i| i.kind) {
            Some(ImageKind::Depth(d, _)) => d,
            _ => DepthFormat::None,
        };
        // a float or 16-bit image of one channel (llvmpipe's nr_channels == 1)
        let single = wide_tex
            && matches!(
                color_kind,
                Some(ImageKind::Color(
                    BaseFormat::Red
                        | BaseFormat::Alpha
                        | BaseFormat::Luminance
                        | BaseFormat::Intensity
                ))
            );
        let layout = Layout {
            size: (w, h),
            format,
            depth,
            stencil: parts.stencil.is_some(),
            wide,
            single,
            srgb: parts
                .color
                .is_some_and(|a| self.fbo.is_srgb(a, &self.textures)),
        };
        Some((parts, layout))
    }

    /// Assembles a working copy of object `name` from its attachments (`None` when it is
    /// incomplete), for reading: sample plane 0 of a multisample object.
    fn assemble(&mut self, name: u32) -> Option<Framebuffer> {
        self.assemble_plane(name, 0)
    }

    /// Assembles the working copy of draw object `name`: plane 0, and for a multisample
    /// object its planes 1..4 into [`FboState::ms_planes`]. The object's kept copy is
    /// reused when its layout still fits (as it is when every image is at the version it
    /// holds), and renderbuffer buffers are lent to it rather than copied
    /// ([`super::fbo_lend`]).
    fn assemble_draw(&mut self, name: u32) -> Option<Framebuffer> {
        // Nothing is on loan here, but for a working copy of share-group tables that
        // were replaced: its loans find no storage of theirs and end.
        self.return_loans();
        self.fbo.ms_planes.clear();
        self.fbo.drawn = false;
        let cache = self.fbo.object_mut(name).and_then(|f| f.cache.take());
        let (parts, layout) = self.parts(name)?;
        let planes = if self.fbo.samples(name, &self.textures) > 0 {
            SAMPLES
        } else {
            1
        };
        let seen = self.versions_of(parts);
        let (fbs, current) = match cache {
            Some(c) if c.layout == layout && c.planes.len() + 1 == planes => {
                let current = c.seen == seen;
                (std::iter::once(c.fb).chain(c.planes).collect(), current)
            }
            _ => (
                (0..planes).map(|_| hollow(&layout)).collect::<Vec<_>>(),
                false,
            ),
        };
        let mut fbs = fbs;
        for (plane, fb) in fbs.iter_mut().enumerate() {
            if !current {
                fb.uniform_color = None;
            }
            let loans = self.fill(fb, parts, &layout, plane, current, true);
            self.fbo.loans.extend(loans);
        }
        let mut first = fbs.remove(0);
        self.fbo.ms_planes = fbs;
        self.load_more_colors(name, &mut first, planes > 1);
        Some(first)
    }

    /// [`Self::assemble`] for the other modules of the context.
    pub(super) fn assemble_copy(&mut self, name: u32) -> Option<Framebuffer> {
        self.assemble(name)
    }

    /// Assembles sample plane `plane` of object `name` (0 for single-sample images) into
    /// a new working copy, for reading.
    fn assemble_plane(&mut self, name: u32, plane: usize) -> Option<Framebuffer> {
        let (parts, layout) = self.parts(name)?;
        let mut fb = hollow(&layout);
        self.fill(&mut fb, parts, &layout, plane, false, false);
        Some(fb)
    }

    /// Every sample plane of object `name` assembled for reading, with its renderbuffer
    /// buffers lent to them where they can be (the loans, which the caller returns).
    pub(super) fn lend_planes(&mut self, name: u32) -> Option<(Vec<Framebuffer>, Vec<Loan>)> {
        let (parts, layout) = self.parts(name)?;
        let n = if self.fbo.samples(name, &self.textures) > 0 {
            SAMPLES
        } else {
            1
        };
        let (mut planes, mut loans) = (Vec::new(), Vec::new());
        for p in 0..n {
            let mut fb = hollow(&layout);
            loans.extend(self.fill(&mut fb, parts, &layout, p, false, true));
            planes.push(fb);
        }
        Some((planes, loans))
    }

    /// Fills working copy `fb` (sample plane `plane`, laid out as `layout`) from the
    /// images `parts`: with `lend`, the renderbuffer buffers that can be lent move in (the
    /// loans made); the other images are copied in unless `current` says `fb` holds them
    /// already.
    fn fill(
        &mut self,
        fb: &mut Framebuffer,
        parts: Parts,
        layout: &Layout,
        plane: usize,
        current: bool,
        lend: bool,
    ) -> Vec<Loan> {
        let mut lent = [false; 3];
        let mut loans = Vec::new();
        if lend {
            for (k, (a, stencil)) in parts.roles_indexed() {
                let (fbo, textures) = (&mut self.fbo, &mut self.textures);
                if let Some(l) = super::fbo_lend::lend(fbo, textures, fb, a, plane, stencil) {
                    loans.push(l);
                    lent[k] = true;
                }
            }
        }
        // A kept copy lacks the buffers it had on loan, a hollow one all of them: new
        // zeroed ones, loaded below.
        let n = fb.width * fb.height;
        let mut refill = !current;
        if fb.color.len() != n {
            let a = if layout.format.has_alpha() { 0 } else { 255 };
            fb.color = HugeBuf::filled(n, [0, 0, 0, a]);
            refill = true;
        }
        if layout.wide.is_some() && fb.wide_color.len() != n {
            fb.set_wide(layout.wide);
            refill = true;
        }
        if layout.depth != DepthFormat::None && fb.depth.len() != n {
            fb.depth = HugeBuf::filled(n, 0);
            refill = true;
        }
        if layout.stencil && fb.stencil.len() != n {
            fb.stencil = HugeBuf::filled(n, 0);
            refill = true;
        }
        if refill {
            let (fbo, textures) = (&mut self.fbo, &mut self.textures);
            for (k, (a, stencil)) in parts.roles_indexed() {
                if lent[k] {
                    continue;
                }
                if let Some((img, iw)) = image_mut(fbo, textures, a, plane) {
                    load(fb, img, iw, stencil);
                }
            }
        }
        loans
    }

    /// The versions of the images `parts`.
    fn versions_of(&self, parts: Parts) -> Vec<(Attachment, u64)> {
        parts
            .roles()
            .map(|(a, _)| (a, self.fbo.version(a)))
            .collect()
    }

    /// Writes the working copy of the bound draw object back into its attachments (when
    /// anything was drawn since it was assembled); returns the versions it now holds.
    /// Lent buffers need no copy: the images are the working copy's own buffers.
    fn write_back(&mut self) -> Vec<(Attachment, u64)> {
        let Some((parts, _)) = self.parts(self.fbo.draw).filter(|_| self.fbo.draw != 0) else {
            return Vec::new();
        };
        if std::mem::take(&mut self.fbo.drawn) {
            if let Some(fb) = self.fb.as_mut() {
                fb.resolve();
                let (fbo, textures) = (&mut self.fbo, &mut self.textures);
                for (a, stencil) in parts.roles() {
                    if let Some((img, iw)) = image_mut(fbo, textures, a, 0) {
                        store(fb, img, iw, stencil);
                    }
                }
                let mut planes = std::mem::take(&mut self.fbo.ms_planes);
                for (k, p) in planes.iter_mut().enumerate() {
                    p.resolve();
                    for (a, stencil) in parts.roles() {
                        let (fbo, textures) = (&mut self.fbo, &mut self.textures);
                        if let Some((img, iw)) = image_mut(fbo, textures, a, k + 1) {
                            store(p, img, iw, stencil);
                        }
                    }
                }
                self.fbo.ms_planes = planes;
                // A depth-stencil image is one image in both roles: one new version.
                let mut done: Vec<Attachment> = Vec::new();
                for a in self.store_more_colors() {
                    self.fbo.bump(a);
                    done.push(a);
                }
                for (a, _) in parts.roles() {
                    if !done.contains(&a) {
                        self.fbo.bump(a);
                        done.push(a);
                    }
                }
            }
        }
        self.versions_of(parts)
    }

    /// Writes the working copy back and keeps it in the draw object's cache.
    fn park(&mut self) {
        let seen = self.write_back();
        self.park_as(seen);
    }

    /// Returns the working copy's loans and keeps it (with its sample planes) in the
    /// draw object's cache as holding the image versions `seen`.
    fn park_as(&mut self, seen: Vec<(Attachment, u64)>) {
        let name = self.fbo.draw;
        let layout = self.fb.as_ref().map(Layout::of);
        self.return_loans();
        let planes = std::mem::take(&mut self.fbo.ms_planes);
        if let (Some(mut fb), Some(layout)) = (self.fb.take(), layout) {
            fb.resolve();
            // draw buffers 1.. are copies, loaded anew by the next assembly
            fb.more_colors = Vec::new();
            if let Some(f) = self.fbo.object_mut(name) {
                f.cache = Some(Box::new(Cached {
                    fb,
                    planes,
                    layout,
                    seen,
                }));
            }
        }
    }

    /// The versions of the images the draw object's working copy holds.
    fn held_versions(&self) -> Vec<(Attachment, u64)> {
        match self.parts(self.fbo.draw).filter(|_| self.fbo.draw != 0) {
            Some((parts, _)) => self.versions_of(parts),
            None => Vec::new(),
        }
    }

    /// Writes pending draws into the bound draw object's images, so that they can be read
    /// or changed directly (texture calls, glGenerateMipmap, reads through another binding).
    pub fn fbo_sync(&mut self) {
        if self.fbo.draw != 0 {
            self.settle_draws();
            crate::context::pixel_ops::bitmap_cache::flush(self);
            self.write_back();
        }
    }

    /// Called before texture `texture`'s images change: when it is attached to the object
    /// bound for drawing, writes the working copy back now, takes back its images the
    /// working copy holds on loan, and marks it to be assembled anew when the GL call ends
    /// ([`Context::fbo_refresh`]), so that the change is seen either way.
    pub fn fbo_touch(&mut self, texture: u32) {
        if !self.draws_into(texture) {
            return;
        }
        if !self.fbo.stale {
            self.fbo_sync();
            self.fbo.stale_seen = self.held_versions();
            self.fbo.stale = true;
        }
        self.unlend_texture(texture);
    }

    /// Whether texture `texture` is attached to the object bound for drawing.
    fn draws_into(&self, texture: u32) -> bool {
        self.fbo.draw_object().is_some_and(|f| {
            f.color
                .iter()
                .chain([&f.depth, &f.stencil])
                .any(|a| matches!(*a, Attachment::Texture(t) if t.name == texture && t.name != 0))
        })
    }

    /// Called before texture `texture`'s images are read directly (glGetTexImage): when
    /// it is attached to the object bound for drawing, writes the drawing into it (and
    /// takes back the images lent to the working copy).
    pub fn fbo_sync_texture(&mut self, texture: u32) {
        if self.draws_into(texture) {
            self.fbo_sync();
            self.unlend_texture(texture);
        }
    }

    /// Assembles the working copy anew after [`Context::fbo_touch`] (the C boundary calls
    /// it when a GL call ends). The test is inlined into every entry point; the work is
    /// not (left to the compiler, the whole function was a call per GL call: 2–4% of a
    /// frame of immediate-mode vertices, sweep state 181).
    #[inline(always)]
    pub fn fbo_refresh(&mut self) {
        if self.fbo.stale {
            self.fbo_reassemble();
        }
    }

    /// [`Self::fbo_refresh`]'s work when the working copy is stale.
    #[cold]
    #[inline(never)]
    fn fbo_reassemble(&mut self) {
        self.fbo.stale = false;
        self.settle_draws();
        let seen = std::mem::take(&mut self.fbo.stale_seen);
        self.park_as(seen);
        self.fb = self.assemble_draw(self.fbo.draw);
    }

    /// Detaches the images `which` picks from the bound draw and read objects (deleting
    /// an attached texture or renderbuffer detaches it from the bound framebuffers only,
    /// as GL 3.0 says). The caller has called [`Context::fbo_touch`].
    pub fn detach_bound(&mut self, which: impl Fn(Attachment) -> bool) {
        for name in [self.fbo.draw, self.fbo.read] {
            if let Some(f) = self.fbo.object_mut(name) {
                for a in f.color.iter_mut().chain([&mut f.depth, &mut f.stencil]) {
                    if which(*a) {
                        *a = Attachment::None;
                    }
                }
            }
        }
    }

    /// Runs `f`, which may change attachments or attached images, between writing the
    /// working copy back and assembling it anew.
    pub fn fbo_edit<R>(&mut self, f: impl FnOnce(&mut Self) -> GlResult<R>) -> GlResult<R> {
        if self.fbo.draw == 0 {
            return f(self);
        }
        self.fbo_sync();
        let seen = self.held_versions();
        let r = f(self);
        self.park_as(seen);
        self.fb = self.assemble_draw(self.fbo.draw);
        r
    }

    /// Before the share group's tables leave this context: writes pending draws into the
    /// bound draw object's images and drops its working copy (another context of the
    /// group may change the images meanwhile).
    pub fn fbo_check_in(&mut self) {
        if self.fbo.draw != 0 {
            self.fbo_sync();
            self.return_loans();
            self.fbo.ms_planes.clear();
            self.fbo.stale = false;
            self.fb = None;
        }
    }

    /// After the share group's tables came back: assembles the bound draw object's
    /// working copy anew from its images.
    pub fn fbo_check_out(&mut self) {
        if self.fbo.draw != 0 {
            self.fb = self.assemble_draw(self.fbo.draw);
        }
    }

    /// Makes object `name` (0: the window) the draw binding, moving the working copy.
    pub fn set_draw_framebuffer(&mut self, name: u32) {
        self.settle_draws();
        crate::context::pixel_ops::bitmap_cache::flush(self);
        if name == self.fbo.draw {
            return;
        }
        if self.fbo.draw == 0 {
            self.fbo.window = self.fb.take();
        } else {
            self.park();
        }
        self.fbo.draw = name;
        self.fbo.ms_planes.clear();
        self.fb = if name == 0 {
            self.fbo.window.take()
        } else {
            self.assemble_draw(name)
        };
    }

    /// GL_SAMPLES of the draw framebuffer: 4 for a multisample object, else 0.
    pub fn draw_samples(&self) -> u32 {
        if self.fbo.ms_planes.is_empty() && !self.fbo.ms_held {
            0
        } else {
            SAMPLES as u32
        }
    }

    /// The sample count of the read framebuffer (0 for the window).
    pub fn read_samples(&self) -> u32 {
        self.fbo.samples(self.fbo.read, &self.textures)
    }

    /// Runs `f` once for each sample plane of the draw framebuffer, with that plane in
    /// `fb` and its index as the argument (once, with 0, for a single-sample one). Pending
    /// draws are settled first; `f` must not rebind or reassemble the draw framebuffer.
    pub fn for_each_sample(&mut self, mut f: impl FnMut(&mut Self, usize)) {
        if self.fbo.ms_planes.is_empty() {
            return f(self, 0);
        }
        self.settle_draws();
        crate::context::pixel_ops::bitmap_cache::flush(self);
        f(self, 0);
        for s in 1..SAMPLES {
            self.settle_draws();
            crate::context::pixel_ops::bitmap_cache::flush(self);
            let Some(fb) = self.fb.as_mut() else { return };
            std::mem::swap(fb, &mut self.fbo.ms_planes[s - 1]);
            f(self, s);
            self.settle_draws();
            crate::context::pixel_ops::bitmap_cache::flush(self);
            if let Some(fb) = self.fb.as_mut() {
                std::mem::swap(fb, &mut self.fbo.ms_planes[s - 1]);
            }
        }
    }

    /// All the sample planes of the read framebuffer (one for a single-sample one), for a
    /// blit; `None` when there is nothing to read.
    pub fn read_planes(&mut self) -> Option<Vec<Framebuffer>> {
        let samples = self.read_samples();
        if self.reads_other_buffer() && samples == 0 {
            return Some(vec![self.read_other_buffer()?]);
        }
        if self.fbo.read == self.fbo.draw {
            self.fbo_sync();
            let mut v = vec![self.fb.clone()?];
            v.extend(self.fbo.ms_planes.iter().cloned());
            return Some(v);
        }
        let first = self.read_framebuffer_copy()?;
        if samples == 0 {
            return Some(vec![first]);
        }
        let name = self.fbo.read;
        let mut v = vec![first];
        let f = self.fbo.object_mut(name)?;
        let saved = f.draw_buffer;
        f.draw_buffer = f.read_buffer;
        for s in 1..SAMPLES {
            if let Some(p) = self.assemble_plane(name, s) {
                v.push(p);
            }
        }
        if let Some(f) = self.fbo.object_mut(name) {
            f.draw_buffer = saved;
        }
        Some(v)
    }

    /// Runs `f` with the window's framebuffer in `fb` (OSMesa calls that look at the
    /// window while an object is bound for drawing).
    pub fn with_window<R>(&mut self, f: impl FnOnce(&mut Self) -> R) -> R {
        if self.fbo.draw == 0 {
            return f(self);
        }
        self.settle_draws();
        crate::context::pixel_ops::bitmap_cache::flush(self);
        std::mem::swap(&mut self.fb, &mut self.fbo.window);
        let planes = std::mem::take(&mut self.fbo.ms_planes);
        let r = f(self);
        self.fbo.ms_planes = planes;
        std::mem::swap(&mut self.fb, &mut self.fbo.window);
        r
    }

    /// Colour (r, g, b, a), depth and stencil bits of the draw framebuffer (glGet's
    /// GL_RED_BITS … GL_STENCIL_BITS).
    pub fn draw_bits(&self) -> ([i32; 4], i32, i32) {
        if self.fbo.draw == 0 {
            let stencil = if self.visual.stencil { 8 } else { 0 };
            return (self.color_bits(), self.visual.depth.bits(), stencil);
        }
        let color = self
            .fbo
            .draw_object()
            .and_then(|f| f.draw_buffer.map(|i| f.color[i]));
        let wide = color.and_then(|a| self.fbo.wide_sizes(a, &self.textures));
        match self.fb.as_ref() {
            Some(fb) => (
                wide.map_or(fb.format.channel_bits(), |w| w.0),
                fb.depth_format.bits(),
                fb.stencil_bits(),
            ),
            None => ([0; 4], 0, 0),
        }
    }

    /// GL_COLOR_CLEAR_VALUE: the clear colour as given while the draw framebuffer is an
    /// object drawing into a float colour image, else clamped to [0, 1] (Mesa's
    /// `_mesa_get_clamp_fragment_color` under GL_CLAMP_FRAGMENT_COLOR = FIXED_ONLY; the
    /// OSMesa window never has a float visual).
    pub fn clear_color_query(&self) -> [f32; 4] {
        let c = self.state.clear_color;
        let float = self.fbo.draw != 0
            && self
                .fb
                .as_ref()
                .and_then(|fb| fb.wide)
                .is_some_and(|k| k.is_float());
        if float {
            c
        } else {
            c.map(|v| super::clamp01(v as f64) as f32)
        }
    }

    /// GL_INVALID_FRAMEBUFFER_OPERATION when the draw framebuffer is an incomplete object.
    pub fn check_draw_framebuffer(&self) -> GlResult<()> {
        if self.fbo.draw != 0 && self.fb.is_none() && self.inflight.is_none() {
            return Err(GlError::InvalidFramebufferOperation);
        }
        Ok(())
    }

    /// GL_INVALID_FRAMEBUFFER_OPERATION when the read framebuffer is an incomplete object.
    pub fn check_read_framebuffer(&self) -> GlResult<()> {
        if self.fbo.read != 0 && self.fbo.status(self.fbo.read, &self.textures) != Status::Complete
        {
            return Err(GlError::InvalidFramebufferOperation);
        }
        Ok(())
    }

    /// Readies the read framebuffer for [`Context::read_fb`] (glReadPixels,
    /// glCopyTex(Sub)Image): GL_INVALID_FRAMEBUFFER_OPERATION when it is incomplete.
    pub fn prepare_read(&mut self) -> GlResult<()> {
        self.check_read_framebuffer()?;
        // Mesa: reading a multisample buffer is GL_INVALID_OPERATION (resolve it first).
        if self.read_samples() > 0 {
            return Err(GlError::InvalidOperation);
        }
        self.fbo.read_copy = self.read_framebuffer_copy();
        Ok(())
    }

    /// The framebuffer reads come from: the draw framebuffer itself, or the copy
    /// [`Context::prepare_read`] made of another one.
    pub fn read_fb(&self) -> Option<&Framebuffer> {
        if self.fbo.read == self.fbo.draw && !self.reads_other_buffer() {
            self.fb.as_ref()
        } else {
            self.fbo.read_copy.as_ref()
        }
    }

    /// The base format of the colour image reads come from: the read buffer's attachment
    /// of the read framebuffer object (GL_RGBA for the window and for no image).
    pub fn read_color_base(&self) -> BaseFormat {
        let Some(f) = self.fbo.object(self.fbo.read) else {
            return BaseFormat::Rgba;
        };
        let info = f
            .read_buffer
            .and_then(|i| self.fbo.image_info(f.color[i], &self.textures));
        match info.map(|i| i.kind) {
            Some(ImageKind::Color(b)) => b,
            _ => BaseFormat::Rgba,
        }
    }

    /// Whether colour can be read: the read buffer is not GL_NONE (and, for an object,
    /// names an attached image).
    pub fn reads_color(&self) -> bool {
        match self.fbo.object(self.fbo.read) {
            None => self.state.legacy.reads_color(),
            Some(f) => f
                .read_buffer
                .is_some_and(|i| f.color[i] != Attachment::None),
        }
    }

    /// A copy of the read framebuffer, with its colour taken from the read buffer, when it
    /// is not the draw framebuffer (then the caller reads `fb` itself: `None`).
    pub fn read_framebuffer_copy(&mut self) -> Option<Framebuffer> {
        if self.reads_other_buffer() {
            return self.read_other_buffer();
        }
        if self.fbo.read == self.fbo.draw {
            return None;
        }
        self.fbo_sync();
        if self.fbo.read == 0 {
            return self.fbo.window.clone();
        }
        let name = self.fbo.read;
        self.unlend_for(name);
        let f = self.fbo.object_mut(name)?;
        // Assemble with the read buffer in the draw buffer's place.
        let saved = f.draw_buffer;
        f.draw_buffer = f.read_buffer;
        let fb = self.assemble(name);
        if let Some(f) = self.fbo.object_mut(name) {
            f.draw_buffer = saved;
        }
        fb
    }
}
