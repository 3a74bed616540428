//! Binding framebuffer objects: the working copy a bound object is drawn through, how it is
//! assembled from the attachments and written back, and the reads through the read binding.
//!
//! See [`super::fbo`] for the model. The working copy's rows are GL's (row 0 at the
//! bottom, [`Framebuffer::y_flip`] false), as llvmpipe draws into objects: its viewport is
//! not flipped, so window coordinates round as they do there and loading or writing back is
//! a plain row copy (the window's buffer is y-down and flipped). Its size is the
//! smallest of the attached images (GL 3.0 lets them differ); writing back touches only that
//! region of each image, and happens only when something was drawn. A single-sample
//! object keeps its written-back working copy between binds: reused as it is when no
//! attached image changed since, reloaded in place when the layout still fits.

use super::fbo::{Attachment, FboState, ImageKind, Status, SAMPLES};
use super::{Context, GlError, GlResult};
use crate::framebuffer::{ColorFormat, DepthFormat, Framebuffer};
use crate::texture::{BaseFormat, TextureState};

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
}

/// Mutable access to one attached image's values, rows bottom-up with `width` per row.
enum ImageMut<'a> {
    /// RGBA8 colour (texture texels or renderbuffer colour), and the base format.
    Color(&'a mut [[u8; 4]], BaseFormat),
    /// Depth texels: the value as a little-endian u32 in each RGBA8 slot.
    DepthTexels(&'a mut [[u8; 4]]),
    /// Renderbuffer depth and (possibly empty) stencil.
    DepthStencil(&'a mut [u32], &'a mut [u8]),
    /// Renderbuffer stencil.
    Stencil(&'a mut [u8]),
    /// Wide renderbuffer colour ([`super::fbo::RbFormat::Wide`]).
    Wide(&'a mut [[f32; 4]]),
}

/// Sample plane `plane` of a renderbuffer's values (`v` itself when it has no planes).
fn plane_of<T>(v: &mut [T], n: usize, samples: u32, plane: usize) -> &mut [T] {
    if samples == 0 || v.is_empty() {
        v
    } else {
        &mut v[plane * n..(plane + 1) * n]
    }
}

/// The image `a` names (sample plane `plane` of a multisample renderbuffer), with its row
/// width, for reading and writing.
fn image_mut<'a>(
    fbo: &'a mut FboState,
    textures: &'a mut TextureState,
    a: Attachment,
    plane: usize,
) -> Option<(ImageMut<'a>, usize)> {
    match a {
        Attachment::None => None,
        Attachment::Renderbuffer(name) => {
            let rb = fbo.renderbuffers.get_mut(&name)?.as_mut()?;
            let (w, n, ns) = (rb.width, rb.width * rb.height, rb.samples);
            let img = if !rb.color.is_empty() {
                let base = match rb.format {
                    Some(super::fbo::RbFormat::Rgb8) => BaseFormat::Rgb,
                    Some(super::fbo::RbFormat::Legacy(b)) => b,
                    _ => BaseFormat::Rgba,
                };
                ImageMut::Color(plane_of(&mut rb.color, n, ns, plane), base)
            } else if !rb.wide.is_empty() {
                ImageMut::Wide(plane_of(&mut rb.wide, n, ns, plane))
            } else if !rb.depth.is_empty() {
                ImageMut::DepthStencil(
                    plane_of(&mut rb.depth, n, ns, plane),
                    plane_of(&mut rb.stencil, n, ns, plane),
                )
            } else {
                ImageMut::Stencil(plane_of(&mut rb.stencil, n, ns, plane))
            };
            Some((img, w))
        }
        Attachment::Texture(t) => {
            let img = t.find_mut(textures)?;
            let (w, h) = (img.width, img.height);
            let start = t.layer * w * h;
            let texels = img.texels.get_mut(start..start + w * h)?;
            let v = match img.base {
                BaseFormat::Depth => ImageMut::DepthTexels(texels),
                b => ImageMut::Color(texels, b),
            };
            Some((v, w))
        }
    }
}

impl Context {
    /// The images the working copy of object `name` is made of, and its size; `None`
    /// when the object is incomplete.
    fn parts(&self, name: u32) -> Option<(Parts, usize, usize)> {
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
        Some((parts, w, h))
    }

    /// Assembles a working copy of object `name` from its attachments (`None` when it is
    /// incomplete), for reading: sample plane 0 of a multisample object, never the cache.
    fn assemble(&mut self, name: u32) -> Option<Framebuffer> {
        self.assemble_plane(name, 0, false)
    }

    /// Assembles the working copy of draw object `name`: plane 0 (from the object's cache
    /// when it has one), and for a multisample object its planes 1..4 into
    /// [`FboState::ms_planes`].
    fn assemble_draw(&mut self, name: u32) -> Option<Framebuffer> {
        self.fbo.ms_planes.clear();
        self.fbo.drawn = false;
        let fb = self.assemble_plane(name, 0, true)?;
        if self.fbo.samples(name, &self.textures) > 0 {
            let planes: Option<Vec<_>> = (1..SAMPLES)
                .map(|s| self.assemble_plane(name, s, false))
                .collect();
            self.fbo.ms_planes = planes?;
        }
        Some(fb)
    }

    /// Assembles sample plane `plane` of object `name` (0 for single-sample images). With
    /// `cached`, a single-sample object's cached copy is reused: as it is when every image
    /// is at the version it holds, else with the images loaded into it when the layout
    /// still fits.
    fn assemble_plane(&mut self, name: u32, plane: usize, cached: bool) -> Option<Framebuffer> {
        let cached = if cached && self.fbo.samples(name, &self.textures) == 0 {
            self.fbo.object_mut(name).and_then(|f| f.cache.take())
        } else {
            None
        };
        let (parts, w, h) = self.parts(name)?;
        let info = |a: Option<Attachment>| a.and_then(|a| self.fbo.image_info(a, &self.textures));
        let format = match info(parts.color).map(|i| i.kind) {
            Some(ImageKind::Color(BaseFormat::Rgb)) => ColorFormat::Rgb,
            _ => ColorFormat::Rgba,
        };
        let depth = match info(parts.depth).map(|i| i.kind) {
            Some(ImageKind::Depth(d, _)) => d,
            _ => DepthFormat::None,
        };
        let stencil = parts.stencil.is_some();
        let wide = self.fbo.wide_kind(parts.color);
        let seen: Vec<(Attachment, u64)> = parts
            .roles()
            .map(|(a, _)| (a, self.fbo.version(a)))
            .collect();
        let fits = |f: &Framebuffer| {
            (
                f.width,
                f.height,
                f.format,
                f.depth_format,
                f.stencil.is_empty(),
                f.wide,
            ) == (w, h, format, depth, !stencil, wide)
        };
        let mut fb = match cached {
            Some(c) if fits(&c.fb) && c.seen == seen => return Some(c.fb),
            Some(c) if fits(&c.fb) => {
                let mut fb = c.fb;
                fb.resolve();
                fb.uniform_color = None;
                fb
            }
            _ => {
                let mut fb = Framebuffer::new(w, h, format, depth, stencil);
                // llvmpipe draws objects unflipped: memory row = GL row, as in the images.
                fb.y_flip = false;
                fb.set_wide(wide);
                fb
            }
        };
        let (fbo, textures) = (&mut self.fbo, &mut self.textures);
        for (a, stencil) in parts.roles() {
            if let Some((img, iw)) = image_mut(fbo, textures, a, plane) {
                load(&mut fb, img, iw, stencil);
            }
        }
        Some(fb)
    }

    /// Writes the working copy of the bound draw object back into its attachments (when
    /// anything was drawn since it was assembled); returns the versions it now holds.
    fn write_back(&mut self) -> Vec<(Attachment, u64)> {
        let Some((parts, _, _)) = self.parts(self.fbo.draw).filter(|_| self.fbo.draw != 0) else {
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
                for (a, _) in parts.roles() {
                    if !done.contains(&a) {
                        self.fbo.bump(a);
                        done.push(a);
                    }
                }
            }
        }
        parts
            .roles()
            .map(|(a, _)| (a, self.fbo.version(a)))
            .collect()
    }

    /// Writes the working copy back and keeps it in the draw object's cache.
    fn park(&mut self) {
        let seen = self.write_back();
        self.park_as(seen);
    }

    /// Keeps the (written back) working copy in the draw object's cache as holding the
    /// image versions `seen` (single-sample objects only; planes are dropped).
    fn park_as(&mut self, seen: Vec<(Attachment, u64)>) {
        let name = self.fbo.draw;
        self.fbo.ms_planes.clear();
        let single = self.fbo.samples(name, &self.textures) == 0;
        if let (Some(fb), Some(f), true) = (self.fb.take(), self.fbo.object_mut(name), single) {
            f.cache = Some(Box::new(super::fbo::Cached { fb, seen }));
        }
    }

    /// The versions of the images the draw object's working copy holds.
    fn held_versions(&self) -> Vec<(Attachment, u64)> {
        match self.parts(self.fbo.draw).filter(|_| self.fbo.draw != 0) {
            Some((parts, _, _)) => parts
                .roles()
                .map(|(a, _)| (a, self.fbo.version(a)))
                .collect(),
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
    /// bound for drawing,
    /// writes the working copy back now, and marks it to be assembled anew when the GL
    /// call ends ([`Context::fbo_refresh`]), so that the change is seen either way.
    pub fn fbo_touch(&mut self, texture: u32) {
        let attached = self.fbo.draw_object().is_some_and(|f| {
            f.color
                .iter()
                .chain([&f.depth, &f.stencil])
                .any(|a| matches!(*a, Attachment::Texture(t) if t.name == texture && t.name != 0))
        });
        if attached && !self.fbo.stale {
            self.fbo_sync();
            self.fbo.stale_seen = self.held_versions();
            self.fbo.stale = true;
        }
    }

    /// Assembles the working copy anew after [`Context::fbo_touch`] (the C boundary calls
    /// it when a GL call ends).
    #[inline]
    pub fn fbo_refresh(&mut self) {
        if self.fbo.stale {
            self.fbo.stale = false;
            self.settle_draws();
            let seen = std::mem::take(&mut self.fbo.stale_seen);
            self.park_as(seen);
            self.fb = self.assemble_draw(self.fbo.draw);
        }
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
        if self.fbo.ms_planes.is_empty() {
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
            if let Some(p) = self.assemble_plane(name, s, false) {
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
        match self.fb.as_ref() {
            Some(fb) => (
                // A wide attachment's channels have its width (16 or 32 bits).
                fb.format
                    .channel_bits()
                    .map(|b| fb.wide.filter(|_| b > 0).map_or(b, |k| k.bits())),
                fb.depth_format.bits(),
                fb.stencil_bits(),
            ),
            None => ([0; 4], 0, 0),
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
        if self.fbo.read == self.fbo.draw {
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
        if self.fbo.read == self.fbo.draw {
            return None;
        }
        self.fbo_sync();
        if self.fbo.read == 0 {
            return self.fbo.window.clone();
        }
        let name = self.fbo.read;
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

/// Copies image `img` (rows bottom-up, `iw` wide) into the working copy `fb`. `stencil`
/// says the attachment is the stencil attachment (a depth-stencil image fills both).
fn load(fb: &mut Framebuffer, img: ImageMut<'_>, iw: usize, stencil: bool) {
    let (w, h) = (fb.width, fb.height);
    for y in 0..h {
        let (src, dst) = (y * iw, fb.row(y) * w);
        match &img {
            ImageMut::Color(px, _) => {
                let st = fb.format;
                for x in 0..w {
                    let c = px[src + x];
                    fb.color[dst + x] = if st == ColorFormat::Rgb {
                        [c[0], c[1], c[2], 255]
                    } else {
                        c
                    };
                }
            }
            ImageMut::DepthTexels(px) if !stencil => {
                for x in 0..w {
                    fb.depth[dst + x] = u32::from_le_bytes(px[src + x]);
                }
            }
            ImageMut::Wide(px) => {
                if let Some(k) = fb.wide {
                    for x in 0..w {
                        let v = px[src + x];
                        fb.wide_color[dst + x] = v;
                        fb.color[dst + x] = k.mirror(v);
                    }
                }
            }
            ImageMut::DepthStencil(d, s) => {
                if !stencil && !fb.depth.is_empty() {
                    fb.depth[dst..dst + w].copy_from_slice(&d[src..src + w]);
                }
                if stencil && !s.is_empty() && !fb.stencil.is_empty() {
                    fb.stencil[dst..dst + w].copy_from_slice(&s[src..src + w]);
                }
            }
            ImageMut::Stencil(s) if stencil && !fb.stencil.is_empty() => {
                fb.stencil[dst..dst + w].copy_from_slice(&s[src..src + w]);
            }
            _ => {}
        }
    }
}

/// Writes the working copy `fb` back into image `img` (the inverse of [`load`]); colour
/// is stored as the image's base format keeps it.
fn store(fb: &Framebuffer, img: ImageMut<'_>, iw: usize, stencil: bool) {
    let (w, h) = (fb.width, fb.height);
    let mut img = img;
    for y in 0..h {
        let (dst, src) = (y * iw, fb.row(y) * w);
        match &mut img {
            ImageMut::Color(px, base) => {
                for x in 0..w {
                    px[dst + x] = base.swizzle(fb.color[src + x], 0, 255);
                }
            }
            ImageMut::DepthTexels(px) if !stencil && !fb.depth.is_empty() => {
                for x in 0..w {
                    px[dst + x] = fb.depth[src + x].to_le_bytes();
                }
            }
            ImageMut::Wide(px) if fb.wide.is_some() => {
                for x in 0..w {
                    px[dst + x] = fb.wide_at(src + x);
                }
            }
            ImageMut::DepthStencil(d, s) => {
                if !stencil && !fb.depth.is_empty() {
                    d[dst..dst + w].copy_from_slice(&fb.depth[src..src + w]);
                }
                if stencil && !s.is_empty() && !fb.stencil.is_empty() {
                    s[dst..dst + w].copy_from_slice(&fb.stencil[src..src + w]);
                }
            }
            ImageMut::Stencil(s) if stencil && !fb.stencil.is_empty() => {
                s[dst..dst + w].copy_from_slice(&fb.stencil[src..src + w]);
            }
            _ => {}
        }
    }
}
