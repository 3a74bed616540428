//! Framebuffer and renderbuffer objects (GL_ARB_framebuffer_object, with GL 3.0's rules):
//! the object tables, attachments, the completeness rules and the queries.
//!
//! # How a framebuffer object is drawn into
//! The attached images are the truth: a renderbuffer's own storage, or a texture level's
//! texels (rows bottom-up, as GL numbers them). While an object is bound for drawing, the
//! context draws into a *working copy*: an ordinary [`Framebuffer`] (colour, depth and
//! stencil in y-down rows, the OSMesa window's layout) assembled from the attachments by
//! [`super::fbo_bind`], and written back into them whenever something else may look at
//! them (rebinding, texture specification, glGenerateMipmap, reads through another
//! binding). Renderbuffer buffers of the working copy's layout are not copied but lent to
//! it while it is bound ([`super::fbo_lend`]): then the working copy holds the truth. The
//! window's own framebuffer is parked in [`FboState::window`] meanwhile.
//!
//! glDrawBuffer selects the colour attachment the working copy draws into; glDrawBuffers
//! adds attachments for draw buffers 1.. ([`super::fbo_draw_buffers`]).
//!
//! # Multisample renderbuffers (docs/fbo-rules.md §3)
//! llvmpipe has one multisample mode, 4x: GL_MAX_SAMPLES is 4, a request of 1 to 4
//! samples gets 4 (GL_RENDERBUFFER_SAMPLES), more is GL_INVALID_OPERATION. A 4x
//! renderbuffer keeps its 4 sample planes one after the other in its vectors (plane s at
//! `s·w·h`). The working copy of a 4x object is four [`Framebuffer`]s, one per sample:
//! plane 0 in the context's `fb`, planes 1–3 in [`FboState::ms_planes`]. Everything that
//! writes the draw buffer runs once per plane with that plane in `fb`
//! (`Context::for_each_sample`) — clears, pixel rectangles, points and lines — except
//! filled triangles with GL_MULTISAMPLE on, drawn once into the four planes (planes 1–3
//! lent to `fb` for the draw: `crate::fragment::MsPass`).
//! Attachments with different sample counts are GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE.

use super::{GlError, GlResult};
use crate::framebuffer::{DepthFormat, Framebuffer, WideKind};
use crate::memory::{HugeBuf, Plain};
use crate::texture::{BaseFormat, Level, TextureObject, TextureState};
use std::collections::HashMap;

/// GL_MAX_COLOR_ATTACHMENTS (Mesa's value).
pub const MAX_COLOR_ATTACHMENTS: usize = 8;
/// GL_MAX_RENDERBUFFER_SIZE (llvmpipe's 2D texture limit).
pub const MAX_RENDERBUFFER_SIZE: usize = 16384;
/// GL_MAX_SAMPLES: llvmpipe's only multisample count (`LP_MAX_SAMPLES`).
pub const MAX_SAMPLES: i32 = 4;
/// The sample planes of a multisample image.
pub const SAMPLES: usize = 4;

/// The storage layout of a renderbuffer (what `glRenderbufferStorage` chose).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RbFormat {
    /// 8-bit RGBA colour.
    Rgba8,
    /// 8-bit RGB colour (alpha reads as 1, as llvmpipe's R8G8B8X8).
    Rgb8,
    /// 8-bit alpha, luminance, luminance-alpha or intensity (renderable in the
    /// compatibility profile, as in Mesa).
    Legacy(BaseFormat),
    /// Depth only.
    Depth(DepthFormat),
    /// Depth of this format with 8-bit stencil in one image (GL_DEPTH24_STENCIL8: Z24,
    /// GL_DEPTH32F_STENCIL8: Z32F).
    DepthStencil(DepthFormat),
    /// 8-bit stencil only.
    Stencil8,
    /// Colour wider than 8 bits (GL_RGBA16, GL_RGBA16F, GL_RGBA32F; with `false` the RGB
    /// forms, whose alpha reads as 1), drawn through the wide colour plane.
    Wide(WideKind, bool),
    /// 8-bit sRGB colour (GL_SRGB8_ALPHA8; with `false` GL_SRGB8, whose alpha reads as 1):
    /// stored like RGBA8 / RGB8, encoded on write while GL_FRAMEBUFFER_SRGB is on.
    Srgb(bool),
}

/// GL_RGBA32F (ARB_texture_float; not in the generated enums).
const RGBA32F: u32 = 0x8814;
/// GL_RGB32F.
const RGB32F: u32 = 0x8815;
/// GL_RGBA16F.
const RGBA16F: u32 = 0x881A;
/// GL_RGB16F.
const RGB16F: u32 = 0x881B;

impl RbFormat {
    /// The layout for a glRenderbufferStorage internal format; `None` when the format is
    /// not colour-, depth- or stencil-renderable (GL_INVALID_ENUM).
    pub fn from_internal(internal: u32) -> Option<RbFormat> {
        use crate::gl::enums::*;
        use crate::gl::glext_enums::*;
        Some(match internal {
            GL_RGBA | GL_RGBA8 | GL_RGBA2 | GL_RGBA4 | GL_RGB5_A1 | GL_RGB10_A2 | GL_RGBA12 => {
                RbFormat::Rgba8
            }
            GL_RGB | GL_RGB8 | GL_R3_G3_B2 | GL_RGB4 | GL_RGB5 | GL_RGB10 | GL_RGB12 => {
                RbFormat::Rgb8
            }
            GL_RGBA16 => RbFormat::Wide(WideKind::Unorm16, true),
            GL_RGB16 => RbFormat::Wide(WideKind::Unorm16, false),
            RGBA16F => RbFormat::Wide(WideKind::Float16, true),
            RGB16F => RbFormat::Wide(WideKind::Float16, false),
            RGBA32F => RbFormat::Wide(WideKind::Float32, true),
            RGB32F => RbFormat::Wide(WideKind::Float32, false),
            // the sized sRGB formats only: GL_SRGB, GL_SRGB_ALPHA and the sluminance ones
            // are GL_INVALID_ENUM in Mesa (measured)
            GL_SRGB8_ALPHA8 => RbFormat::Srgb(true),
            GL_SRGB8 => RbFormat::Srgb(false),
            GL_ALPHA | GL_ALPHA4 | GL_ALPHA8 | GL_ALPHA12 | GL_ALPHA16 => {
                RbFormat::Legacy(BaseFormat::Alpha)
            }
            GL_LUMINANCE | GL_LUMINANCE4 | GL_LUMINANCE8 | GL_LUMINANCE12 | GL_LUMINANCE16 => {
                RbFormat::Legacy(BaseFormat::Luminance)
            }
            GL_LUMINANCE_ALPHA
            | GL_LUMINANCE4_ALPHA4
            | GL_LUMINANCE6_ALPHA2
            | GL_LUMINANCE8_ALPHA8
            | GL_LUMINANCE12_ALPHA4
            | GL_LUMINANCE12_ALPHA12
            | GL_LUMINANCE16_ALPHA16 => RbFormat::Legacy(BaseFormat::LuminanceAlpha),
            GL_INTENSITY | GL_INTENSITY4 | GL_INTENSITY8 | GL_INTENSITY12 | GL_INTENSITY16 => {
                RbFormat::Legacy(BaseFormat::Intensity)
            }
            GL_DEPTH_COMPONENT16 => RbFormat::Depth(DepthFormat::Z16),
            GL_DEPTH_COMPONENT | GL_DEPTH_COMPONENT24 => RbFormat::Depth(DepthFormat::Z24),
            GL_DEPTH_COMPONENT32 => RbFormat::Depth(DepthFormat::Z32),
            GL_DEPTH_COMPONENT32F => RbFormat::Depth(DepthFormat::Z32F),
            GL_DEPTH_STENCIL | GL_DEPTH24_STENCIL8 => RbFormat::DepthStencil(DepthFormat::Z24),
            GL_DEPTH32F_STENCIL8 => RbFormat::DepthStencil(DepthFormat::Z32F),
            GL_STENCIL_INDEX | GL_STENCIL_INDEX1 | GL_STENCIL_INDEX4 | GL_STENCIL_INDEX8
            | GL_STENCIL_INDEX16 => RbFormat::Stencil8,
            _ => return None,
        })
    }

    /// Bits of red, green, blue, alpha, depth and stencil (glGetRenderbufferParameteriv).
    pub fn sizes(self) -> [i32; 6] {
        match self {
            RbFormat::Rgba8 => [8, 8, 8, 8, 0, 0],
            RbFormat::Rgb8 => [8, 8, 8, 0, 0, 0],
            RbFormat::Legacy(BaseFormat::Alpha) => [0, 0, 0, 8, 0, 0],
            RbFormat::Legacy(BaseFormat::LuminanceAlpha) => [8, 0, 0, 8, 0, 0],
            RbFormat::Legacy(_) => [8, 0, 0, 0, 0, 0],
            RbFormat::Depth(d) => [0, 0, 0, 0, d.bits(), 0],
            RbFormat::DepthStencil(d) => [0, 0, 0, 0, d.bits(), 8],
            RbFormat::Stencil8 => [0, 0, 0, 0, 0, 8],
            RbFormat::Wide(k, alpha) => {
                let b = k.bits();
                [b, b, b, if alpha { b } else { 0 }, 0, 0]
            }
            RbFormat::Srgb(alpha) => [8, 8, 8, if alpha { 8 } else { 0 }, 0, 0],
        }
    }
}

/// The wide precision a float or 16-bit texture image is rendered at (`None` for the
/// 8-bit storages): Mesa's R16G16B16A16_UNORM / *16_FLOAT / *32_FLOAT render targets.
pub fn texture_wide_kind(storage: &crate::texture::Storage) -> Option<WideKind> {
    use crate::texture::Encoding;
    match storage.encoding {
        Encoding::Unorm16 => Some(WideKind::Unorm16),
        Encoding::Float if storage.sizes.iter().max() == Some(&16) => Some(WideKind::Float16),
        Encoding::Float => Some(WideKind::Float32),
        _ => None,
    }
}

/// A renderbuffer object. Its images are rows bottom-up, `width * height` values each,
/// one buffer per sample plane (one plane for a single-sample renderbuffer). While the
/// renderbuffer is attached to the object bound for drawing, a buffer whose layout is the
/// working copy's may be lent to it (`super::fbo_lend`): it is then empty here.
#[derive(Clone, Debug, Default)]
pub struct Renderbuffer {
    /// The internal format as given (GL_RENDERBUFFER_INTERNAL_FORMAT; GL_RGBA initially).
    pub internal: u32,
    /// Width in pixels (0 until storage is given).
    pub width: usize,
    /// Height in pixels.
    pub height: usize,
    /// The layout; `None` until storage is given.
    pub format: Option<RbFormat>,
    /// Colour values per plane (colour formats; no planes otherwise).
    pub color: Vec<HugeBuf<[u8; 4]>>,
    /// Depth values per plane in the depth format's stored form (depth formats).
    pub depth: Vec<HugeBuf<u32>>,
    /// Stencil values per plane (stencil formats).
    pub stencil: Vec<HugeBuf<u8>>,
    /// Wide colour values, stored as the wide plane keeps them ([`RbFormat::Wide`]); the
    /// sample planes one after the other (plane s at `s·w·h`).
    pub wide: Vec<[f32; 4]>,
    /// GL_RENDERBUFFER_SAMPLES: 0, or [`SAMPLES`] planes of `width * height` values each.
    pub samples: u32,
    /// Identifies this storage: new for every glRenderbufferStorage, so that a lent buffer
    /// goes back only to the storage it came from.
    pub storage_id: u64,
}

/// The storage ids handed out so far.
static STORAGE_IDS: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);

/// `planes` buffers of `n` copies of `v`; `None` when the memory is not there.
fn planes_of<T: Plain>(planes: usize, n: usize, v: T) -> Option<Vec<HugeBuf<T>>> {
    (0..planes).map(|_| HugeBuf::try_filled(n, v)).collect()
}

impl Renderbuffer {
    /// Gives the renderbuffer zeroed storage of `format` with `samples` (0 or [`SAMPLES`])
    /// (glRenderbufferStorage(Multisample)); fails with GL_OUT_OF_MEMORY, leaving it
    /// unchanged, when the memory is not there.
    pub fn allocate(
        &mut self,
        internal: u32,
        format: RbFormat,
        w: usize,
        h: usize,
        samples: u32,
    ) -> GlResult<()> {
        let planes = (samples as usize).max(1);
        let n = w * h;
        let (mut color, mut depth, mut stencil) = (Vec::new(), Vec::new(), Vec::new());
        let mut wide = Vec::new();
        let oom = GlError::OutOfMemory;
        let no_alpha = matches!(format, RbFormat::Rgb8 | RbFormat::Srgb(false));
        match format {
            RbFormat::Rgba8 | RbFormat::Rgb8 | RbFormat::Legacy(_) | RbFormat::Srgb(_) => {
                let a = if no_alpha { 255 } else { 0 };
                color = planes_of(planes, n, [0, 0, 0, a]).ok_or(oom)?;
            }
            RbFormat::Depth(_) => depth = planes_of(planes, n, 0).ok_or(oom)?,
            RbFormat::DepthStencil(_) => {
                depth = planes_of(planes, n, 0).ok_or(oom)?;
                stencil = planes_of(planes, n, 0).ok_or(oom)?;
            }
            RbFormat::Stencil8 => stencil = planes_of(planes, n, 0).ok_or(oom)?,
            RbFormat::Wide(k, alpha) => {
                let total = n * planes;
                wide.try_reserve_exact(total).map_err(|_| oom)?;
                wide.resize(total, [0.0, 0.0, 0.0, if alpha { 0.0 } else { k.one() }]);
            }
        }
        *self = Renderbuffer {
            internal,
            width: w,
            height: h,
            format: Some(format),
            color,
            depth,
            stencil,
            wide,
            samples,
            storage_id: STORAGE_IDS.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1,
        };
        Ok(())
    }
}

/// What an attachment point holds.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Attachment {
    /// Nothing (GL_NONE).
    #[default]
    None,
    /// A renderbuffer, by name.
    Renderbuffer(u32),
    /// A texture image.
    Texture(TexImage),
}

/// A texture image as an attachment names it: object name, cube face (0 for other
/// targets), level, and the layer of a 3D texture (0 otherwise).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct TexImage {
    /// The texture object's name.
    pub name: u32,
    /// The cube face (0..6, GL's order), 0 for other targets.
    pub face: usize,
    /// The mipmap level.
    pub level: usize,
    /// The z slice of a 3D texture.
    pub layer: usize,
}

impl TexImage {
    /// The texture object and the level image this names, if both exist.
    pub fn find<'a>(&self, textures: &'a TextureState) -> Option<(&'a TextureObject, &'a Level)> {
        let obj = textures.objects.get(&self.name)?;
        Some((obj, obj.face_levels(self.face).get(self.level)?.as_ref()?))
    }

    /// The level image this names, mutably, if it exists.
    pub fn find_mut<'a>(&self, textures: &'a mut TextureState) -> Option<&'a mut Level> {
        let obj = textures.objects.get_mut(&self.name)?;
        obj.face_levels_mut(self.face).get_mut(self.level)?.as_mut()
    }
}

/// What a working copy is laid out as: size, colour format, depth format, whether it has
/// stencil, wide precision, single-channel wide, sRGB. A kept working copy is reused only
/// for the same layout.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Layout {
    /// Width and height.
    pub size: (usize, usize),
    /// The colour format.
    pub format: crate::framebuffer::ColorFormat,
    /// The depth format.
    pub depth: DepthFormat,
    /// Whether it has a stencil buffer.
    pub stencil: bool,
    /// The wide precision ([`Framebuffer::wide`]).
    pub wide: Option<WideKind>,
    /// [`Framebuffer::wide_single`].
    pub single: bool,
    /// [`Framebuffer::srgb`].
    pub srgb: bool,
}

impl Layout {
    /// The layout of working copy `fb` (while it holds all its buffers).
    pub fn of(fb: &Framebuffer) -> Layout {
        Layout {
            size: (fb.width, fb.height),
            format: fb.format,
            depth: fb.depth_format,
            stencil: !fb.stencil.is_empty(),
            wide: fb.wide,
            single: fb.wide_single,
            srgb: fb.srgb,
        }
    }
}

/// A framebuffer object's working copy, kept while another framebuffer is bound so that
/// binding it again neither allocates nor (when its images have not changed) copies.
#[derive(Clone, Debug)]
pub struct Cached {
    /// The working copy (sample plane 0), written back; the buffers it had on loan are
    /// back in their renderbuffers (empty here).
    pub fb: Framebuffer,
    /// Sample planes 1..4 of a multisample object's working copy (as `fb`).
    pub planes: Vec<Framebuffer>,
    /// The layout it was assembled with.
    pub layout: Layout,
    /// The version ([`FboState::version`]) of each attached image it holds.
    pub seen: Vec<(Attachment, u64)>,
}

/// A framebuffer object's state.
#[derive(Clone, Debug)]
pub struct FramebufferObject {
    /// GL_COLOR_ATTACHMENTi.
    pub color: [Attachment; MAX_COLOR_ATTACHMENTS],
    /// GL_DEPTH_ATTACHMENT.
    pub depth: Attachment,
    /// GL_STENCIL_ATTACHMENT.
    pub stencil: Attachment,
    /// The colour attachment glDrawBuffer selected (`None`: GL_NONE): draw buffer 0.
    pub draw_buffer: Option<usize>,
    /// The colour attachments of draw buffers 1.. (glDrawBuffers; `None` after
    /// glDrawBuffer).
    pub more_draw: [Option<usize>; super::legacy_state::MORE_DRAW_BUFFERS],
    /// The colour attachment glReadBuffer selected (`None`: GL_NONE).
    pub read_buffer: Option<usize>,
    /// The working copy while the object is not bound for drawing.
    pub cache: Option<Box<Cached>>,
}

impl Default for FramebufferObject {
    fn default() -> Self {
        FramebufferObject {
            color: [Attachment::None; MAX_COLOR_ATTACHMENTS],
            depth: Attachment::None,
            stencil: Attachment::None,
            draw_buffer: Some(0),
            more_draw: [None; super::legacy_state::MORE_DRAW_BUFFERS],
            read_buffer: Some(0),
            cache: None,
        }
    }
}

/// What kind of values an attached image holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ImageKind {
    /// Colour, with the base format it is stored as (RGB stores alpha as 1).
    Color(BaseFormat),
    /// Depth of this format, and whether the same image holds stencil.
    Depth(DepthFormat, bool),
    /// Stencil only.
    Stencil,
    /// A format nothing can be rendered into (a compressed or 32-bit depth image).
    Unrenderable,
}

/// The size and kind of an attached image.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ImageInfo {
    /// Width in pixels.
    pub width: usize,
    /// Height in pixels.
    pub height: usize,
    /// What it holds.
    pub kind: ImageKind,
    /// Its sample count (0: single-sample).
    pub samples: u32,
}

/// glCheckFramebufferStatus's answers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// GL_FRAMEBUFFER_COMPLETE.
    Complete,
    /// GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT.
    IncompleteAttachment,
    /// GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT.
    MissingAttachment,
    /// GL_FRAMEBUFFER_UNSUPPORTED.
    Unsupported,
    /// GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: attachments with different sample counts.
    IncompleteMultisample,
}

impl Status {
    /// The GL enum.
    pub fn to_gl(self) -> u32 {
        use crate::gl::glext_enums::*;
        match self {
            Status::Complete => GL_FRAMEBUFFER_COMPLETE,
            Status::IncompleteAttachment => GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT,
            Status::MissingAttachment => GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT,
            Status::Unsupported => GL_FRAMEBUFFER_UNSUPPORTED,
            Status::IncompleteMultisample => GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE,
        }
    }
}

/// The framebuffer-object state of a context.
#[derive(Default)]
pub struct FboState {
    /// Framebuffer objects by name; `None` for names generated but never bound.
    pub framebuffers: HashMap<u32, Option<FramebufferObject>>,
    /// Renderbuffer objects by name; `None` for names generated but never bound.
    pub renderbuffers: HashMap<u32, Option<Renderbuffer>>,
    /// The next name glGenFramebuffers tries.
    next_fb: u32,
    /// The next name glGenRenderbuffers tries.
    next_rb: u32,
    /// GL_DRAW_FRAMEBUFFER_BINDING (0: the OSMesa window).
    pub draw: u32,
    /// GL_READ_FRAMEBUFFER_BINDING.
    pub read: u32,
    /// GL_RENDERBUFFER_BINDING.
    pub renderbuffer: u32,
    /// The window's framebuffer while an object is bound for drawing.
    pub window: Option<Framebuffer>,
    /// The working copy was written back before a texture change and must be assembled
    /// anew when the call ends (see `Context::fbo_touch`).
    pub stale: bool,
    /// The image versions the working copy held when it went stale.
    pub stale_seen: Vec<(Attachment, u64)>,
    /// A copy of the read framebuffer when it is not the draw framebuffer, made by
    /// `Context::prepare_read` for the read that follows.
    pub read_copy: Option<Framebuffer>,
    /// Something was drawn into the working copy since it was assembled or written back.
    pub drawn: bool,
    /// The version of each image ever attached: bumped whenever its contents change
    /// outside the working copy that holds it (a write-back, a texture call, new storage).
    versions: HashMap<Attachment, u64>,
    /// The last version handed out.
    last_version: u64,
    /// Sample planes 1..4 of a 4x draw object's working copy (plane 0 is the context's
    /// `fb`); empty for a single-sample draw framebuffer.
    pub ms_planes: Vec<Framebuffer>,
    /// Planes 1..4 ride along with plane 0 (`Framebuffer::samples`) instead of being in
    /// `ms_planes`: a one-pass multisample draw's batch left drawing on the pool holds
    /// them, and the next such draw takes them over with it; any settle gives them back
    /// ([`super::Context::settle_draws`]).
    pub ms_held: bool,
    /// The renderbuffer buffers the working copy holds on loan (`super::fbo_lend`).
    pub loans: Vec<super::fbo_lend::Loan>,
    /// The image the last multisample resolve of glBlitFramebuffer wrote, kept so that
    /// the next one of the same size writes into it (`crate::pixels::resolve::reuse`).
    pub resolve_scratch: Option<Framebuffer>,
}

/// Names not in `used`, counting up from `*next` (glGen*'s rule: any unused names).
fn gen_names<T>(used: &mut HashMap<u32, Option<T>>, next: &mut u32, n: usize) -> Vec<u32> {
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        *next = next.wrapping_add(1).max(1);
        if !used.contains_key(next) {
            used.insert(*next, None);
            out.push(*next);
        }
    }
    out
}

/// The part of the framebuffer-object state a share group shares: Mesa 22.3 keeps both
/// framebuffer and renderbuffer objects in the shared state (`shared.c`), so a context
/// created with a `sharelist` sees the other's objects of both kinds.
#[derive(Debug, Default)]
pub struct FboTables {
    framebuffers: HashMap<u32, Option<FramebufferObject>>,
    renderbuffers: HashMap<u32, Option<Renderbuffer>>,
    next_fb: u32,
    next_rb: u32,
}

impl FboState {
    /// Moves the shared tables out (into the share group). The objects' cached working
    /// copies are dropped: their image versions are this context's own.
    pub fn take_tables(&mut self) -> FboTables {
        let mut framebuffers = std::mem::take(&mut self.framebuffers);
        for f in framebuffers.values_mut().flatten() {
            f.cache = None;
        }
        FboTables {
            framebuffers,
            renderbuffers: std::mem::take(&mut self.renderbuffers),
            next_fb: std::mem::replace(&mut self.next_fb, 1),
            next_rb: std::mem::replace(&mut self.next_rb, 1),
        }
    }

    /// Moves the share group's tables in.
    pub fn put_tables(&mut self, t: FboTables) {
        self.framebuffers = t.framebuffers;
        self.renderbuffers = t.renderbuffers;
        self.next_fb = t.next_fb;
        self.next_rb = t.next_rb;
    }

    /// The version of image `a` (0 if it never changed).
    pub fn version(&self, a: Attachment) -> u64 {
        self.versions.get(&a).copied().unwrap_or(0)
    }

    /// Marks image `a` changed; returns its new version.
    pub fn bump(&mut self, a: Attachment) -> u64 {
        self.last_version += 1;
        self.versions.insert(a, self.last_version);
        self.last_version
    }

    /// Marks every image of texture `name` changed (a texture call may have changed it).
    pub fn touch_texture(&mut self, name: u32) {
        for (a, v) in self.versions.iter_mut() {
            if matches!(*a, Attachment::Texture(t) if t.name == name) {
                self.last_version += 1;
                *v = self.last_version;
            }
        }
    }

    /// glGenFramebuffers.
    pub fn gen_framebuffers(&mut self, n: usize) -> Vec<u32> {
        gen_names(&mut self.framebuffers, &mut self.next_fb, n)
    }

    /// glGenRenderbuffers.
    pub fn gen_renderbuffers(&mut self, n: usize) -> Vec<u32> {
        gen_names(&mut self.renderbuffers, &mut self.next_rb, n)
    }

    /// The sample count of object `name`'s images (0 for the window, single-sample or
    /// incomplete objects with no image).
    pub fn samples(&self, name: u32, textures: &TextureState) -> u32 {
        let Some(f) = self.object(name) else {
            return 0;
        };
        let every = f.color.iter().chain([&f.depth, &f.stencil]);
        every
            .filter_map(|&a| self.image_info(a, textures))
            .map(|i| i.samples)
            .max()
            .unwrap_or(0)
    }

    /// The object bound to the draw binding, if any.
    pub fn draw_object(&self) -> Option<&FramebufferObject> {
        self.object(self.draw)
    }

    /// The framebuffer object `name` (not the window), if it exists.
    pub fn object(&self, name: u32) -> Option<&FramebufferObject> {
        self.framebuffers.get(&name)?.as_ref()
    }

    /// The framebuffer object `name`, mutably.
    pub fn object_mut(&mut self, name: u32) -> Option<&mut FramebufferObject> {
        self.framebuffers.get_mut(&name)?.as_mut()
    }

    /// The renderbuffer bound to GL_RENDERBUFFER, mutably.
    pub fn bound_renderbuffer_mut(&mut self) -> Option<&mut Renderbuffer> {
        self.renderbuffers.get_mut(&self.renderbuffer)?.as_mut()
    }

    /// The wide precision of the colour image `a` names (a wide renderbuffer, or a float
    /// or 16-bit texture image), if any.
    pub fn wide_kind(&self, a: Option<Attachment>, textures: &TextureState) -> Option<WideKind> {
        match a? {
            Attachment::Renderbuffer(name) => {
                match self.renderbuffers.get(&name)?.as_ref()?.format? {
                    RbFormat::Wide(k, _) => Some(k),
                    _ => None,
                }
            }
            Attachment::Texture(t) => texture_wide_kind(&t.find(textures)?.1.storage),
            Attachment::None => None,
        }
    }

    /// GL_FRAMEBUFFER_ATTACHMENT_RED … ALPHA_SIZE of a wide colour image (a wide
    /// renderbuffer or a float or 16-bit texture image) and whether its components are
    /// floats; `None` for other images. Mesa reports the format's red, green, blue and
    /// alpha bits: a luminance or intensity image has none of them.
    pub fn wide_sizes(&self, a: Attachment, textures: &TextureState) -> Option<([i32; 4], bool)> {
        let k = self.wide_kind(Some(a), textures)?;
        let sizes = match a {
            Attachment::Renderbuffer(name) => {
                let s = self.renderbuffers.get(&name)?.as_ref()?.format?.sizes();
                [s[0], s[1], s[2], s[3]]
            }
            Attachment::Texture(t) => {
                let s = t.find(textures)?.1.storage.sizes;
                [s[0], s[1], s[2], s[3]].map(i32::from)
            }
            Attachment::None => return None,
        };
        Some((sizes, k.is_float()))
    }

    /// Whether the image `a` names is sRGB-encoded (GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING
    /// is GL_SRGB): an sRGB renderbuffer or an sRGB texture image.
    pub fn is_srgb(&self, a: Attachment, textures: &TextureState) -> bool {
        use crate::texture::Encoding;
        match a {
            Attachment::None => false,
            Attachment::Renderbuffer(name) => self
                .renderbuffers
                .get(&name)
                .and_then(|r| r.as_ref()?.format)
                .is_some_and(|f| matches!(f, RbFormat::Srgb(_))),
            Attachment::Texture(t) => t.find(textures).is_some_and(|(_, img)| {
                matches!(img.storage.encoding, Encoding::Srgb | Encoding::SrgbBlocks)
            }),
        }
    }

    /// GL_FRAMEBUFFER_SRGB_CAPABLE_EXT of object `name` (0 is the window, linear): Mesa's
    /// framebuffer visual takes it from the first colour attachment, and only a complete
    /// object has a visual.
    pub fn srgb_capable(&self, name: u32, textures: &TextureState) -> bool {
        let Some(f) = self.object(name) else {
            return false;
        };
        let first = f.color.iter().find(|&&a| a != Attachment::None);
        self.status(name, textures) == Status::Complete
            && first.is_some_and(|&a| self.is_srgb(a, textures))
    }

    /// The size and kind of the image `a` names; `None` when it names nothing or an image
    /// that does not exist (yet).
    pub fn image_info(&self, a: Attachment, textures: &TextureState) -> Option<ImageInfo> {
        match a {
            Attachment::None => None,
            Attachment::Renderbuffer(name) => {
                let rb = self.renderbuffers.get(&name)?.as_ref()?;
                let kind = match rb.format? {
                    RbFormat::Rgba8 => ImageKind::Color(BaseFormat::Rgba),
                    RbFormat::Rgb8 => ImageKind::Color(BaseFormat::Rgb),
                    RbFormat::Legacy(b) => ImageKind::Color(b),
                    RbFormat::Depth(d) => ImageKind::Depth(d, false),
                    RbFormat::DepthStencil(d) => ImageKind::Depth(d, true),
                    RbFormat::Stencil8 => ImageKind::Stencil,
                    RbFormat::Wide(_, true) => ImageKind::Color(BaseFormat::Rgba),
                    RbFormat::Wide(_, false) => ImageKind::Color(BaseFormat::Rgb),
                    RbFormat::Srgb(true) => ImageKind::Color(BaseFormat::Rgba),
                    RbFormat::Srgb(false) => ImageKind::Color(BaseFormat::Rgb),
                };
                Some(ImageInfo {
                    width: rb.width,
                    height: rb.height,
                    kind,
                    samples: rb.samples,
                })
            }
            Attachment::Texture(t) => {
                let (obj, img) = t.find(textures)?;
                if obj.target == Some(crate::texture::Target::Tex3D)
                    && t.layer >= obj.depths[t.level]
                {
                    return None;
                }
                let kind = match img.base {
                    BaseFormat::Depth => match img.storage.depth_bits() {
                        16 => ImageKind::Depth(DepthFormat::Z16, false),
                        24 => ImageKind::Depth(DepthFormat::Z24, false),
                        32 => ImageKind::Depth(DepthFormat::Z32, false),
                        crate::texture::shadow::FLOAT_BITS => {
                            ImageKind::Depth(DepthFormat::Z32F, false)
                        }
                        _ => ImageKind::Unrenderable,
                    },
                    // float and 16-bit images (every base format, as llvmpipe renders
                    // them all) are drawn through the wide plane: `wide_kind`.
                    // sRGB luminance is not a render target format in llvmpipe:
                    // GL_FRAMEBUFFER_UNSUPPORTED (measured)
                    BaseFormat::Luminance | BaseFormat::LuminanceAlpha
                        if img.storage.encoding == crate::texture::Encoding::Srgb =>
                    {
                        ImageKind::Unrenderable
                    }
                    b => ImageKind::Color(b),
                };
                Some(ImageInfo {
                    width: img.width,
                    height: img.height,
                    kind,
                    samples: 0,
                })
            }
        }
    }

    /// glCheckFramebufferStatus of object `name` (the window is always complete).
    pub fn status(&self, name: u32, textures: &TextureState) -> Status {
        let Some(f) = self.object(name) else {
            return Status::Complete;
        };
        let mut any = false;
        let mut check = |a: Attachment, ok: &dyn Fn(ImageKind) -> bool| -> Option<Status> {
            if a == Attachment::None {
                return None;
            }
            any = true;
            match self.image_info(a, textures) {
                Some(i) if i.width > 0 && i.height > 0 && ok(i.kind) => None,
                Some(i) if i.kind == ImageKind::Unrenderable => Some(Status::Unsupported),
                _ => Some(Status::IncompleteAttachment),
            }
        };
        for &a in &f.color {
            if let Some(s) = check(a, &|k| matches!(k, ImageKind::Color(_))) {
                return s;
            }
        }
        if let Some(s) = check(f.depth, &|k| matches!(k, ImageKind::Depth(..))) {
            return s;
        }
        if let Some(s) = check(f.stencil, &|k| {
            matches!(k, ImageKind::Stencil | ImageKind::Depth(_, true))
        }) {
            return s;
        }
        if !any {
            return Status::MissingAttachment;
        }
        let every = f.color.iter().chain([&f.depth, &f.stencil]);
        let mut counts = every.filter_map(|&a| self.image_info(a, textures).map(|i| i.samples));
        if let Some(first) = counts.next() {
            if counts.any(|c| c != first) {
                return Status::IncompleteMultisample;
            }
        }
        // llvmpipe keeps depth and stencil in one surface: separate images are unsupported
        // (as Mesa's st_validate_attachment reports them).
        if f.depth != Attachment::None && f.stencil != Attachment::None && f.depth != f.stencil {
            return Status::Unsupported;
        }
        Status::Complete
    }
}
