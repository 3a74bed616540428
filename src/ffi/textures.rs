//! Texture calls (GL 1.1–1.3): objects, images, parameters, environment, texture units and
//! glMultiTexCoord*. Every function validates all arguments before changing any state.
//!
//! Borders: Mesa's gallium front end strips texture borders (`StripTextureBorder`), and so
//! do we: border 1 is accepted and the outer ring of texels is dropped; other borders are
//! GL_INVALID_VALUE.
#![allow(non_snake_case)]

use super::enums::*;
use super::glext_enums::*;
use super::types::*;
use super::{compiling_list, non_negative, with_ctx, with_ctx_list};
use crate::context::fbo::Attachment;
use crate::context::pack::depth as shadow;
use crate::context::pack::tex::{self as upload, ClientFormat, Layout};
use crate::context::state::{Cap, PixelStore, MAX_TEXTURE_UNITS};
use crate::context::{Context, GlError, GlResult};
use crate::texture::env::{CombineFn, EnvMode, Operand, Source};
use crate::texture::shadow::{CompareFunc, DepthMode, ShadowParams};
use crate::texture::{
    mipmap, BaseFormat, Filter, Level, MipFilter, Storage, Target, TextureObject, Wrap,
    MAX_ANISOTROPY, MAX_LEVELS, MAX_TEXTURE_SIZE,
};
use libc::c_void;

/// (target, is proxy, cube face) of a texture-image target.
pub(crate) fn image_target(target: GLenum) -> GlResult<(Target, bool, usize)> {
    Ok(match target {
        GL_TEXTURE_1D => (Target::Tex1D, false, 0),
        GL_TEXTURE_2D => (Target::Tex2D, false, 0),
        GL_TEXTURE_3D => (Target::Tex3D, false, 0),
        GL_PROXY_TEXTURE_1D => (Target::Tex1D, true, 0),
        GL_PROXY_TEXTURE_2D => (Target::Tex2D, true, 0),
        GL_PROXY_TEXTURE_3D => (Target::Tex3D, true, 0),
        GL_PROXY_TEXTURE_CUBE_MAP => (Target::Cube, true, 0),
        f if (GL_TEXTURE_CUBE_MAP_POSITIVE_X..GL_TEXTURE_CUBE_MAP_POSITIVE_X + 6).contains(&f) => (
            Target::Cube,
            false,
            (f - GL_TEXTURE_CUBE_MAP_POSITIVE_X) as usize,
        ),
        _ => return Err(GlError::InvalidEnum),
    })
}

/// A bindable target (also the target of glTexParameter).
pub(crate) fn bind_target(target: GLenum) -> GlResult<Target> {
    Ok(match target {
        GL_TEXTURE_1D => Target::Tex1D,
        GL_TEXTURE_2D => Target::Tex2D,
        GL_TEXTURE_3D => Target::Tex3D,
        GL_TEXTURE_CUBE_MAP => Target::Cube,
        _ => return Err(GlError::InvalidEnum),
    })
}

/// Whether an image target of `t` is taken by a call of `dims` dimensions (cube faces
/// are 2D images).
pub(crate) fn dims_match(t: Target, dims: u8) -> bool {
    dims == match t {
        Target::Tex1D => 1,
        Target::Tex2D | Target::Cube => 2,
        Target::Tex3D => 3,
    }
}

pub(crate) fn check_level(level: GLint) -> GlResult<usize> {
    if level < 0 || level as usize >= MAX_LEVELS {
        Err(GlError::InvalidValue)
    } else {
        Ok(level as usize)
    }
}

pub(crate) fn object_mut(c: &mut Context, target: Target, proxy: bool) -> &mut TextureObject {
    if proxy {
        &mut c.textures.proxies[target.index()]
    } else {
        let unit = c.state.active_texture;
        // The image may be attached to the framebuffer object being drawn.
        let name = c.textures.units[unit].bound[target.index()];
        c.fbo_touch(name);
        c.fbo.touch_texture(name);
        c.textures.bound_mut(unit, target)
    }
}

pub(crate) fn object(c: &Context, target: Target, proxy: bool) -> &TextureObject {
    if proxy {
        &c.textures.proxies[target.index()]
    } else {
        c.textures.bound(c.state.active_texture, target)
    }
}

/// Regenerates the mipmaps after the base level changed, if GL_GENERATE_MIPMAP is set.
pub(crate) fn maybe_generate(obj: &mut TextureObject, level: usize) {
    let p = obj.params;
    if p.generate_mipmap && p.base_level >= 0 && level == p.base_level as usize {
        regenerate(obj, level);
    }
}

/// Rebuilds the levels after `base` (every face of a cube map, every slice of a 3D
/// texture) as Mesa's `st_generate_mipmap` does.
pub(crate) fn regenerate(obj: &mut TextureObject, base: usize) {
    let max = obj.params.max_level.max(0) as usize;
    match obj.target {
        Some(Target::Tex3D) => crate::texture::volume::generate(obj, base, max),
        Some(Target::Cube) => {
            for f in 0..6 {
                mipmap::generate(obj.face_levels_mut(f), base, max);
            }
        }
        _ => mipmap::generate(&mut obj.levels, base, max),
    }
}

/// Validated sizes of a glTexImage/glCopyTexImage: (width, height) after border stripping,
/// or `None` when a proxy query should answer "does not fit".
fn image_size(
    target: Target,
    level: usize,
    w: GLsizei,
    h: GLsizei,
    border: GLint,
) -> GlResult<Option<(usize, usize)>> {
    if border != 0 && border != 1 {
        return Err(GlError::InvalidValue);
    }
    let h = if target == Target::Tex1D {
        1 + 2 * border
    } else {
        h
    };
    let (w, h) = (non_negative(w)?, non_negative(h)?);
    let b = 2 * border as usize;
    if w < b || h < b {
        return Err(GlError::InvalidValue);
    }
    let max = (MAX_TEXTURE_SIZE >> level).max(1);
    let (w, h) = (w - b, if target == Target::Tex1D { 1 } else { h - b });
    if w > max || h > max || (target == Target::Cube && w != h) {
        return Err(GlError::InvalidValue);
    }
    Ok(Some((w, h)))
}

unsafe fn tex_image(
    c: &mut Context,
    target: GLenum,
    level: GLint,
    (internal, w, h, border, format, ty): (GLint, GLsizei, GLsizei, GLint, GLenum, GLenum),
    data: *const c_void,
    dims: u8,
    unpack: PixelStore,
) -> GlResult<()> {
    let (t, proxy, face) = image_target(target)?;
    if !dims_match(t, dims) {
        return Err(GlError::InvalidEnum);
    }
    // Mesa's order: level, border and negative sizes (errors for proxies too), then the
    // format and type; only a size too large for the level leaves a proxy silently empty.
    let level = check_level(level)?;
    if !(0..=1).contains(&border) || w < 0 || h < 0 {
        return Err(GlError::InvalidValue);
    }
    let cf = super::textures_ci::client_format(format, ty)?;
    let (internal, sformat, sty) = resolve_internal(internal, t, (format, ty));
    let base = upload::base_format(internal).ok_or(GlError::InvalidValue)?;
    depth_match(base, &cf)?;
    let storage = storage_of(internal, base, sformat, sty);
    let size = image_size(t, level, w, h, border);
    if proxy {
        let obj = object_mut(c, t, true);
        obj.face_levels_mut(face)[level] = match size {
            Ok(Some((w, h))) => Some(Level {
                width: w,
                height: h,
                internal_format: internal as u32,
                base,
                storage,
                texels: Vec::new(),
                blocks: None,
            }),
            _ => None,
        };
        return Ok(());
    }
    let Some((tw, th)) = size? else {
        return Ok(());
    };
    // Border stripping: skip the first border pixel and row of the client image.
    let mut ps = unpack;
    let (fw, _fh) = (tw + 2 * border as usize, th + 2 * border as usize);
    if border == 1 {
        if ps.row_length == 0 {
            ps.row_length = fw as i32;
        }
        ps.skip_pixels += 1;
        if t == Target::Tex2D {
            ps.skip_rows += 1;
        }
    }
    // SAFETY: GL's contract: `data` (when not null) holds the described image.
    let texels =
        unsafe { unpack_image(c, &ps, (&cf, format, ty), (base, storage), (tw, th), data) };
    // SAFETY: as above.
    let stencil = unsafe { super::textures_ds::unpack_stencil(c, &ps, &cf, (tw, th), data) };
    let obj = object_mut(c, t, false);
    super::textures_ds::set(obj, (face, level), internal as u32, stencil);
    obj.face_levels_mut(face)[level] = Some(Level {
        width: tw,
        height: th,
        internal_format: internal as u32,
        base,
        storage,
        texels,
        blocks: None,
    });
    maybe_generate(obj, level);
    Ok(())
}

unsafe fn tex_sub_image(
    c: &mut Context,
    target: GLenum,
    level: GLint,
    (xoff, yoff, w, h, format, ty): (GLint, GLint, GLsizei, GLsizei, GLenum, GLenum),
    data: *const c_void,
    dims: u8,
    unpack: PixelStore,
) -> GlResult<()> {
    let (t, face) = match image_target(target)? {
        (t, false, face) if dims_match(t, dims) => (t, face),
        _ => return Err(GlError::InvalidEnum),
    };
    let cf = super::textures_ci::client_format(format, ty)?;
    let level = check_level(level)?;
    let (w, h) = (non_negative(w)?, non_negative(h)?);
    let ps = unpack;
    let (base, storage, width, height, internal) = object(c, t, false)
        .face_levels(face)
        .get(level)
        .and_then(|l| l.as_ref())
        .map(|i| (i.base, i.storage, i.width, i.height, i.internal_format))
        .ok_or(GlError::InvalidOperation)?;
    let yoff = if dims == 1 { 0 } else { yoff };
    depth_match(base, &cf)?;
    if xoff < 0 || yoff < 0 || xoff as usize + w > width || yoff as usize + h > height {
        return Err(GlError::InvalidValue);
    }
    if crate::context::pack::tex_format::compressed_info(internal).is_some() {
        // whole blocks only (the data is then stored uncompressed: see the README)
        let rect = (xoff, yoff, w as i32, h as i32);
        super::textures_compressed::check_sub_rect((width as i32, height as i32), rect)?;
    }
    // SAFETY: GL's contract: `data` holds the described image.
    let texels = unsafe { unpack_image(c, &ps, (&cf, format, ty), (base, storage), (w, h), data) };
    let stencil = (shadow::is_depth_stencil(internal) && cf.is_depth_stencil())
        // SAFETY: as above.
        .then(|| unsafe { super::textures_ds::unpack_stencil(c, &ps, &cf, (w, h), data) });
    let obj = object_mut(c, t, false);
    if let Some(s) = stencil {
        let rect = (xoff as usize, yoff as usize, w, h);
        super::textures_ds::update(obj, (face, level), (width, height), rect, &s);
    }
    let img = obj.face_levels_mut(face)[level]
        .as_mut()
        .ok_or(GlError::InvalidOperation)?;
    for y in 0..h {
        let dst = (yoff as usize + y) * img.width + xoff as usize;
        img.texels[dst..dst + w].copy_from_slice(&texels[y * w..(y + 1) * w]);
    }
    maybe_generate(obj, level);
    Ok(())
}

/// A client image copied while a display list is being compiled (GL 1.5 §5.4: the pixels
/// are unpacked from client memory when the command is compiled), with the pixel-store
/// state that describes the copy.
struct ClientImage {
    /// The bytes the image spans, or `None` for a null pointer or an invalid description
    /// (whose error the compiled command raises when it runs).
    bytes: Option<Vec<u8>>,
    /// The unpack state at compile time.
    unpack: PixelStore,
}

impl ClientImage {
    /// Copies the `w` x `h` image at `data` under the current unpack state.
    ///
    /// # Safety
    /// `data` (if not null) must hold the image the arguments and unpack state describe.
    unsafe fn read(
        format: GLenum,
        ty: GLenum,
        w: GLsizei,
        h: GLsizei,
        data: *const c_void,
    ) -> Self {
        let unpack = super::with_ctx_raw(|c| Ok(c.state.unpack));
        let bytes = (|| {
            let (w, h) = (usize::try_from(w).ok()?, usize::try_from(h).ok()?);
            // Larger images fail validation when the command runs: nothing to copy.
            if data.is_null() || w > MAX_TEXTURE_SIZE + 2 || h > MAX_TEXTURE_SIZE + 2 {
                return None;
            }
            let span = if format == GL_COLOR_INDEX {
                super::textures_ci::span(ty, &unpack, w, h)?
            } else {
                Layout::new(&unpack, w, &ClientFormat::new(format, ty).ok()?).span(w, h)
            };
            // SAFETY: the caller promises the described image is readable.
            Some(unsafe { std::slice::from_raw_parts(data as *const u8, span) }.to_vec())
        })();
        ClientImage { bytes, unpack }
    }

    /// The copy's address (null when there is none).
    fn ptr(&self) -> *const c_void {
        self.bytes
            .as_ref()
            .map_or(std::ptr::null(), |b| b.as_ptr() as *const c_void)
    }
}

/// Whether a display list is being compiled on the current context.
pub(crate) fn compiling() -> bool {
    super::with_ctx_raw(|c| Ok(c.lists.compile_mode().is_some()))
}

/// Reads a GL-window rectangle (y up) of the framebuffer as RGBA8; outside pixels are 0.
pub(crate) fn read_fb(c: &Context, x: i32, y: i32, w: usize, h: usize) -> Vec<[u8; 4]> {
    let mut out = vec![[0u8; 4]; w * h];
    let Some(fb) = c.read_fb() else { return out };
    for row in 0..h {
        let gy = y as i64 + row as i64;
        if gy < 0 || gy >= fb.height as i64 {
            continue;
        }
        let fy = fb.row(gy as usize);
        for col in 0..w {
            let gx = x as i64 + col as i64;
            if gx < 0 || gx >= fb.width as i64 {
                continue;
            }
            out[row * w + col] = fb.color_at(fy * fb.width + gx as usize);
        }
    }
    out
}

/// GL_INVALID_OPERATION unless a depth image meets depth data and a colour image colour
/// data.
fn depth_match(base: BaseFormat, cf: &ClientFormat) -> GlResult<()> {
    if (base == BaseFormat::Depth) != cf.is_depth() {
        return Err(GlError::InvalidOperation);
    }
    Ok(())
}

/// A glTexImage internal format as softgl stores it, with the client format and type its
/// storage is chosen by: a generic compressed format (GL_COMPRESSED_RGB ...) becomes its
/// base format. A 1D image then takes the storage of that unsized format, as Mesa's
/// `st_ChooseTextureFormat` does; on other targets Mesa takes a fixed format (A8 and I8
/// for ALPHA and INTENSITY, blocks for the rest), so the client type plays no part.
pub(crate) fn resolve_internal(
    internal: GLint,
    t: Target,
    (format, ty): (GLenum, GLenum),
) -> (GLint, GLenum, GLenum) {
    match super::textures_compressed::generic_base(internal as GLenum) {
        Some(b) if t == Target::Tex1D => (b as GLint, format, ty),
        Some(b) => (b as GLint, 0, 0),
        None => (internal, format, ty),
    }
}

/// The storage Mesa picks for an image (depth images: their depth bits).
fn storage_of(internal: GLint, base: BaseFormat, format: GLenum, ty: GLenum) -> Storage {
    if base == BaseFormat::Depth {
        Storage {
            sizes: [shadow::depth_bits(internal as u32, ty), 0, 0, 0, 0, 0],
            encoding: crate::texture::Encoding::Unorm,
        }
    } else {
        upload::choose_storage(internal, base, format, ty)
    }
}

/// Unpacks a colour or depth client image with `c`'s pixel transfer (colour scale, bias
/// and maps, or depth scale and bias).
///
/// # Safety
/// `data` (when not null) must hold the described image.
pub(crate) unsafe fn unpack_any(
    c: &Context,
    ps: &PixelStore,
    cf: &ClientFormat,
    (base, storage): (BaseFormat, Storage),
    (w, h): (usize, usize),
    data: *const c_void,
) -> Vec<[u8; 4]> {
    let data = data as *const u8;
    let tr = &c.pixel_modes.transfer;
    // SAFETY: forwarded caller contract.
    unsafe {
        if base == BaseFormat::Depth {
            let depth = tr.depth_scale_bias();
            shadow::unpack(ps, cf, storage.depth_bits(), (w, h), data, depth)
        } else {
            let color = upload::ColorTransfer::active(tr, &c.pixel_maps);
            upload::unpack_transfer(ps, cf, (base, storage), w, h, data, color)
        }
    }
}

/// [`unpack_any`] for glTexImage/glTexSubImage data of `format`/`ty` (validated as
/// `cf`), GL_COLOR_INDEX data included.
///
/// # Safety
/// `data` (when not null) must hold the described image under `ps`.
unsafe fn unpack_image(
    c: &Context,
    ps: &PixelStore,
    (cf, format, ty): (&ClientFormat, GLenum, GLenum),
    texel: (BaseFormat, Storage),
    size: (usize, usize),
    data: *const c_void,
) -> Vec<[u8; 4]> {
    if format == GL_COLOR_INDEX {
        // SAFETY: forwarded caller contract.
        unsafe { super::textures_ci::unpack(c, ps, ty, texel, size, data) }
    } else {
        // SAFETY: forwarded caller contract.
        unsafe { unpack_any(c, ps, cf, texel, size, data) }
    }
}

/// A framebuffer rectangle (GL window coordinates) as texels of `base`: colours, or for a
/// depth image the depth buffer (GL_INVALID_OPERATION without one).
///
/// Pixel transfer applies as in Mesa's CPU copy: colours go through RGBA float
/// (`u·f32(1/255)`) with scale, bias and the maps; depth through [`shadow::convert_scaled`].
pub(crate) fn read_texels(
    c: &Context,
    (x, y, w, h): (GLint, GLint, usize, usize),
    base: BaseFormat,
    storage: &Storage,
) -> GlResult<Vec<[u8; 4]>> {
    let tr = &c.pixel_modes.transfer;
    if base != BaseFormat::Depth {
        let pixels = read_fb(c, x, y, w, h).into_iter();
        return Ok(match upload::ColorTransfer::active(tr, &c.pixel_maps) {
            Some(ct) => pixels
                .map(|p| ct.store(p.map(|u| u as f32 * (1.0f32 / 255.0)), base, storage))
                .collect(),
            None => pixels
                .map(|p| upload::to_texel(base, upload::quantise_rgba(p, storage)))
                .collect(),
        });
    }
    let scale_bias = tr.depth_scale_bias();
    let fb = c.read_fb().ok_or(GlError::InvalidOperation)?;
    if fb.depth_format == crate::framebuffer::DepthFormat::None {
        return Err(GlError::InvalidOperation);
    }
    let fb_bits = fb.depth_format.texel_bits();
    let mut out = vec![shadow::texel(0); w * h];
    for row in 0..h {
        let gy = y as i64 + row as i64;
        if gy < 0 || gy >= fb.height as i64 {
            continue;
        }
        let fy = fb.row(gy as usize);
        for col in 0..w {
            let gx = x as i64 + col as i64;
            if gx < 0 || gx >= fb.width as i64 {
                continue;
            }
            let z = fb.depth_at(fy * fb.width + gx as usize);
            let z = match scale_bias {
                Some(sb) => shadow::convert_scaled(z, fb_bits, storage.depth_bits(), sb),
                None => shadow::convert(z, fb_bits, storage.depth_bits()),
            };
            out[row * w + col] = shadow::texel(z);
        }
    }
    Ok(out)
}

/// glTexParameter of GL_TEXTURE_COMPARE_MODE, GL_TEXTURE_COMPARE_FUNC,
/// GL_DEPTH_TEXTURE_MODE.
fn shadow_parameter(p: &mut ShadowParams, pname: GLenum, e: GLenum) -> GlResult<()> {
    match pname {
        GL_TEXTURE_COMPARE_MODE => {
            p.compare = match e {
                GL_NONE => false,
                GL_COMPARE_R_TO_TEXTURE => true,
                _ => return Err(GlError::InvalidEnum),
            }
        }
        GL_TEXTURE_COMPARE_FUNC => {
            p.func = match e {
                GL_NEVER => CompareFunc::Never,
                GL_LESS => CompareFunc::Less,
                GL_EQUAL => CompareFunc::Equal,
                GL_LEQUAL => CompareFunc::Lequal,
                GL_GREATER => CompareFunc::Greater,
                GL_NOTEQUAL => CompareFunc::Notequal,
                GL_GEQUAL => CompareFunc::Gequal,
                GL_ALWAYS => CompareFunc::Always,
                _ => return Err(GlError::InvalidEnum),
            }
        }
        _ => {
            p.depth_mode = match e {
                GL_LUMINANCE => DepthMode::Luminance,
                GL_INTENSITY => DepthMode::Intensity,
                GL_ALPHA => DepthMode::Alpha,
                GL_RED => DepthMode::Red,
                _ => return Err(GlError::InvalidEnum),
            }
        }
    }
    Ok(())
}

/// glGetTexParameter of the comparison state.
fn get_shadow_parameter(p: &ShadowParams, pname: GLenum) -> GLenum {
    match pname {
        GL_TEXTURE_COMPARE_MODE if p.compare => GL_COMPARE_R_TO_TEXTURE,
        GL_TEXTURE_COMPARE_MODE => GL_NONE,
        GL_TEXTURE_COMPARE_FUNC => match p.func {
            CompareFunc::Never => GL_NEVER,
            CompareFunc::Less => GL_LESS,
            CompareFunc::Equal => GL_EQUAL,
            CompareFunc::Lequal => GL_LEQUAL,
            CompareFunc::Greater => GL_GREATER,
            CompareFunc::Notequal => GL_NOTEQUAL,
            CompareFunc::Gequal => GL_GEQUAL,
            CompareFunc::Always => GL_ALWAYS,
        },
        _ => match p.depth_mode {
            DepthMode::Luminance => GL_LUMINANCE,
            DepthMode::Intensity => GL_INTENSITY,
            DepthMode::Alpha => GL_ALPHA,
            DepthMode::Red => GL_RED,
        },
    }
}

#[allow(clippy::too_many_arguments)]
fn copy_tex_image(
    c: &mut Context,
    target: GLenum,
    level: GLint,
    internal: GLenum,
    x: GLint,
    y: GLint,
    w: GLsizei,
    h: GLsizei,
    border: GLint,
    dims: u8,
) -> GlResult<()> {
    let (t, face) = match image_target(target)? {
        (t, false, face) if dims_match(t, dims) => (t, face),
        _ => return Err(GlError::InvalidEnum),
    };
    let level = check_level(level)?;
    // Mesa: an unknown internal format of a copy is GL_INVALID_ENUM (not VALUE as for
    // glTexImage), and so are the legacy component counts 1-4, which only glTexImage
    // takes (GL 1.5 spec, section 3.8.2)
    if (1..=4).contains(&internal) {
        return Err(GlError::InvalidEnum);
    }
    let (internal, _, _) = resolve_internal(internal as GLint, t, (0, 0));
    let internal = internal as GLenum;
    let base = upload::base_format(internal as i32).ok_or(GlError::InvalidEnum)?;
    let Some((tw, th)) = image_size(t, level, w, h, border)? else {
        return Ok(());
    };
    let b = border;
    let storage = storage_of(internal as i32, base, 0, 0);
    let (sx, sy) = (x + b, y + if dims == 2 { b } else { 0 });
    c.prepare_read()?;
    let exact = super::textures_ds::read_fb_depth_exact(c, internal, (sx, sy, tw, th));
    let texels = match exact {
        Some(t) => t,
        None => read_texels(c, (sx, sy, tw, th), base, &storage)?,
    };
    let stencil = match shadow::is_depth_stencil(internal) {
        true => super::textures_ds::read_fb_stencil(c, sx, sy, tw, th),
        false => Vec::new(),
    };
    let obj = object_mut(c, t, false);
    super::textures_ds::set(obj, (face, level), internal, stencil);
    obj.face_levels_mut(face)[level] = Some(Level {
        width: tw,
        height: th,
        internal_format: internal,
        base,
        storage,
        texels,
        blocks: None,
    });
    maybe_generate(obj, level);
    Ok(())
}

#[allow(clippy::too_many_arguments)]
fn copy_tex_sub_image(
    c: &mut Context,
    target: GLenum,
    level: GLint,
    xoff: GLint,
    yoff: GLint,
    x: GLint,
    y: GLint,
    w: GLsizei,
    h: GLsizei,
    dims: u8,
) -> GlResult<()> {
    let (t, face) = match image_target(target)? {
        (t, false, face) if dims_match(t, dims) => (t, face),
        _ => return Err(GlError::InvalidEnum),
    };
    let level = check_level(level)?;
    let (w, h) = (non_negative(w)?, non_negative(h)?);
    let (base, storage, internal) = object(c, t, false)
        .face_levels(face)
        .get(level)
        .and_then(|l| l.as_ref())
        .map(|i| (i.base, i.storage, i.internal_format))
        .ok_or(GlError::InvalidOperation)?;
    c.prepare_read()?;
    let src = match super::textures_ds::read_fb_depth_exact(c, internal, (x, y, w, h)) {
        Some(t) => t,
        None => read_texels(c, (x, y, w, h), base, &storage)?,
    };
    let stencil = shadow::is_depth_stencil(internal)
        .then(|| super::textures_ds::read_fb_stencil(c, x, y, w, h));
    let obj = object_mut(c, t, false);
    let img = obj.face_levels_mut(face)[level]
        .as_mut()
        .ok_or(GlError::InvalidOperation)?;
    if xoff < 0 || yoff < 0 || xoff as usize + w > img.width || yoff as usize + h > img.height {
        return Err(GlError::InvalidValue);
    }
    for row in 0..h {
        let d = (yoff as usize + row) * img.width + xoff as usize;
        img.texels[d..d + w].copy_from_slice(&src[row * w..(row + 1) * w]);
    }
    if let Some(s) = stencil {
        let (size, rect) = (
            (img.width, img.height),
            (xoff as usize, yoff as usize, w, h),
        );
        super::textures_ds::update(obj, (face, level), size, rect, &s);
    }
    maybe_generate(obj, level);
    Ok(())
}

/// glGenTextures.
///
/// # Safety
/// `textures` must be writable for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glGenTextures(n: GLsizei, textures: *mut GLuint) {
    with_ctx(|c| {
        let n = non_negative(n)?;
        if textures.is_null() {
            return Ok(());
        }
        for (i, name) in c.textures.gen(n).into_iter().enumerate() {
            // SAFETY: the caller promises room for n names.
            unsafe { *textures.add(i) = name };
        }
        Ok(())
    })
}

/// glDeleteTextures (bindings of deleted names revert to 0).
///
/// # Safety
/// `textures` must be readable for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glDeleteTextures(n: GLsizei, textures: *const GLuint) {
    with_ctx(|c| {
        let n = non_negative(n)?;
        if textures.is_null() {
            return Ok(());
        }
        // SAFETY: the caller promises n readable names.
        let names = unsafe { std::slice::from_raw_parts(textures, n) };
        for &name in names {
            c.fbo_touch(name);
            c.fbo.touch_texture(name);
        }
        c.detach_bound(|a| matches!(a, Attachment::Texture { name, .. } if names.contains(&name)));
        c.textures.delete(names);
        Ok(())
    })
}

/// glBindTexture (a name first bound to another target: GL_INVALID_OPERATION).
#[no_mangle]
pub extern "C" fn glBindTexture(target: GLenum, texture: GLuint) {
    with_ctx_list(move |c| {
        let t = bind_target(target)?;
        let unit = c.state.active_texture;
        c.textures.bind(unit, t, texture)
    })
}

/// glIsTexture.
#[no_mangle]
pub extern "C" fn glIsTexture(texture: GLuint) -> GLboolean {
    with_ctx(|c| Ok(c.textures.is_texture(texture) as GLboolean))
}

/// glTexImage1D.
///
/// # Safety
/// `pixels` (if not null) must hold the image described by the arguments and unpack state.
#[no_mangle]
pub unsafe extern "C" fn glTexImage1D(
    target: GLenum,
    level: GLint,
    internalformat: GLint,
    width: GLsizei,
    border: GLint,
    format: GLenum,
    type_: GLenum,
    pixels: *const GLvoid,
) {
    if compiling() {
        // SAFETY: forwarded caller contract.
        let img = unsafe { ClientImage::read(format, type_, width, 1, pixels) };
        // SAFETY: the copy holds the described image.
        return with_ctx_list(move |c| unsafe {
            let args = (internalformat, width, 1, border, format, type_);
            tex_image(c, target, level, args, img.ptr(), 1, img.unpack)
        });
    }
    // SAFETY: forwarded caller contract.
    with_ctx(|c| unsafe {
        let args = (internalformat, width, 1, border, format, type_);
        tex_image(c, target, level, args, pixels, 1, c.state.unpack)
    })
}

/// glTexImage2D.
///
/// # Safety
/// `pixels` (if not null) must hold the image described by the arguments and unpack state.
#[no_mangle]
pub unsafe extern "C" fn glTexImage2D(
    target: GLenum,
    level: GLint,
    internalformat: GLint,
    width: GLsizei,
    height: GLsizei,
    border: GLint,
    format: GLenum,
    type_: GLenum,
    pixels: *const GLvoid,
) {
    if compiling() {
        // SAFETY: forwarded caller contract.
        let img = unsafe { ClientImage::read(format, type_, width, height, pixels) };
        // SAFETY: the copy holds the described image.
        return with_ctx_list(move |c| unsafe {
            let args = (internalformat, width, height, border, format, type_);
            tex_image(c, target, level, args, img.ptr(), 2, img.unpack)
        });
    }
    // SAFETY: forwarded caller contract.
    with_ctx(|c| unsafe {
        let args = (internalformat, width, height, border, format, type_);
        tex_image(c, target, level, args, pixels, 2, c.state.unpack)
    })
}

/// glTexSubImage1D.
///
/// # Safety
/// `pixels` must hold the image described by the arguments and unpack state.
#[no_mangle]
pub unsafe extern "C" fn glTexSubImage1D(
    target: GLenum,
    level: GLint,
    xoffset: GLint,
    width: GLsizei,
    format: GLenum,
    type_: GLenum,
    pixels: *const GLvoid,
) {
    if compiling() {
        // SAFETY: forwarded caller contract.
        let img = unsafe { ClientImage::read(format, type_, width, 1, pixels) };
        // SAFETY: the copy holds the described image.
        return with_ctx_list(move |c| unsafe {
            let args = (xoffset, 0, width, 1, format, type_);
            tex_sub_image(c, target, level, args, img.ptr(), 1, img.unpack)
        });
    }
    // SAFETY: forwarded caller contract.
    with_ctx(|c| unsafe {
        let args = (xoffset, 0, width, 1, format, type_);
        tex_sub_image(c, target, level, args, pixels, 1, c.state.unpack)
    })
}

/// glTexSubImage2D.
///
/// # Safety
/// `pixels` must hold the image described by the arguments and unpack state.
#[no_mangle]
pub unsafe extern "C" fn glTexSubImage2D(
    target: GLenum,
    level: GLint,
    xoffset: GLint,
    yoffset: GLint,
    width: GLsizei,
    height: GLsizei,
    format: GLenum,
    type_: GLenum,
    pixels: *const GLvoid,
) {
    if compiling() {
        // SAFETY: forwarded caller contract.
        let img = unsafe { ClientImage::read(format, type_, width, height, pixels) };
        // SAFETY: the copy holds the described image.
        return with_ctx_list(move |c| unsafe {
            let args = (xoffset, yoffset, width, height, format, type_);
            tex_sub_image(c, target, level, args, img.ptr(), 2, img.unpack)
        });
    }
    // SAFETY: forwarded caller contract.
    with_ctx(|c| unsafe {
        let args = (xoffset, yoffset, width, height, format, type_);
        tex_sub_image(c, target, level, args, pixels, 2, c.state.unpack)
    })
}

/// glCopyTexImage1D.
#[no_mangle]
pub extern "C" fn glCopyTexImage1D(
    target: GLenum,
    level: GLint,
    internalformat: GLenum,
    x: GLint,
    y: GLint,
    width: GLsizei,
    border: GLint,
) {
    with_ctx_list(move |c| {
        copy_tex_image(c, target, level, internalformat, x, y, width, 1, border, 1)
    })
}

/// glCopyTexImage2D.
#[no_mangle]
pub extern "C" fn glCopyTexImage2D(
    target: GLenum,
    level: GLint,
    internalformat: GLenum,
    x: GLint,
    y: GLint,
    width: GLsizei,
    height: GLsizei,
    border: GLint,
) {
    with_ctx_list(move |c| {
        copy_tex_image(
            c,
            target,
            level,
            internalformat,
            x,
            y,
            width,
            height,
            border,
            2,
        )
    })
}

/// glCopyTexSubImage1D.
#[no_mangle]
pub extern "C" fn glCopyTexSubImage1D(
    target: GLenum,
    level: GLint,
    xoffset: GLint,
    x: GLint,
    y: GLint,
    width: GLsizei,
) {
    with_ctx_list(move |c| copy_tex_sub_image(c, target, level, xoffset, 0, x, y, width, 1, 1))
}

/// glCopyTexSubImage2D.
#[no_mangle]
pub extern "C" fn glCopyTexSubImage2D(
    target: GLenum,
    level: GLint,
    xoffset: GLint,
    yoffset: GLint,
    x: GLint,
    y: GLint,
    width: GLsizei,
    height: GLsizei,
) {
    with_ctx_list(move |c| {
        copy_tex_sub_image(c, target, level, xoffset, yoffset, x, y, width, height, 2)
    })
}

/// glGetTexImage.
///
/// # Safety
/// `pixels` must be writable for the packed image of the level.
#[no_mangle]
pub unsafe extern "C" fn glGetTexImage(
    target: GLenum,
    level: GLint,
    format: GLenum,
    type_: GLenum,
    pixels: *mut GLvoid,
) {
    with_ctx(|c| {
        let (t, face) = match image_target(target)? {
            (t, false, face) => (t, face),
            _ => return Err(GlError::InvalidEnum),
        };
        let level = check_level(level)?;
        let cf = ClientFormat::new(format, type_)?;
        let ps = c.state.pack;
        let obj = object(c, t, false);
        let Some(Some(img)) = obj.face_levels(face).get(level) else {
            return Ok(());
        };
        depth_match(img.base, &cf)?;
        if cf.is_depth_stencil() {
            if !shadow::is_depth_stencil(img.internal_format) {
                return Err(GlError::InvalidOperation);
            }
            let stencil = obj.stencil.get(&(face, level)).map_or(&[][..], |s| s);
            // SAFETY: the caller promises room for the packed image.
            unsafe { shadow::pack_depth_stencil(&ps, &cf, img, stencil, pixels as *mut u8) };
            return Ok(());
        }
        if img.base == BaseFormat::Depth {
            // SAFETY: the caller promises room for the packed image.
            unsafe { shadow::pack(&ps, &cf, img, pixels as *mut u8) };
            return Ok(());
        }
        if t == Target::Tex3D {
            // SAFETY: the caller promises room for the packed image.
            unsafe { super::textures_3d::pack_3d(&ps, &cf, img, obj.depths[level], pixels) };
            return Ok(());
        }
        let _ = Layout::new(&ps, img.width, &cf);
        // SAFETY: the caller promises room for the packed image.
        unsafe { upload::pack(&ps, &cf, img, pixels as *mut u8) };
        Ok(())
    })
}

fn wrap_from_gl(v: u32) -> GlResult<Wrap> {
    Ok(match v {
        GL_REPEAT => Wrap::Repeat,
        GL_CLAMP => Wrap::Clamp,
        GL_CLAMP_TO_EDGE => Wrap::ClampToEdge,
        GL_CLAMP_TO_BORDER => Wrap::ClampToBorder,
        GL_MIRRORED_REPEAT => Wrap::MirroredRepeat,
        _ => return Err(GlError::InvalidEnum),
    })
}

fn wrap_to_gl(w: Wrap) -> u32 {
    match w {
        Wrap::Repeat => GL_REPEAT,
        Wrap::Clamp => GL_CLAMP,
        Wrap::ClampToEdge => GL_CLAMP_TO_EDGE,
        Wrap::ClampToBorder => GL_CLAMP_TO_BORDER,
        Wrap::MirroredRepeat => GL_MIRRORED_REPEAT,
    }
}

fn min_filter_to_gl(f: Filter, m: MipFilter) -> u32 {
    match (f, m) {
        (Filter::Nearest, MipFilter::None) => GL_NEAREST,
        (Filter::Linear, MipFilter::None) => GL_LINEAR,
        (Filter::Nearest, MipFilter::Nearest) => GL_NEAREST_MIPMAP_NEAREST,
        (Filter::Linear, MipFilter::Nearest) => GL_LINEAR_MIPMAP_NEAREST,
        (Filter::Nearest, MipFilter::Linear) => GL_NEAREST_MIPMAP_LINEAR,
        (Filter::Linear, MipFilter::Linear) => GL_LINEAR_MIPMAP_LINEAR,
    }
}

/// glTexParameter*: `v` holds the values as floats; `ints` says they came from an integer
/// call (GL_TEXTURE_BORDER_COLOR is then normalised).
fn tex_parameter(
    c: &mut Context,
    target: GLenum,
    pname: GLenum,
    v: &[f64],
    ints: bool,
) -> GlResult<()> {
    let t = bind_target(target)?;
    let mut p = object(c, t, false).params;
    let e = v[0] as i64 as u32;
    match pname {
        GL_TEXTURE_MIN_FILTER => {
            (p.min_filter, p.mip_filter) = match e {
                GL_NEAREST => (Filter::Nearest, MipFilter::None),
                GL_LINEAR => (Filter::Linear, MipFilter::None),
                GL_NEAREST_MIPMAP_NEAREST => (Filter::Nearest, MipFilter::Nearest),
                GL_LINEAR_MIPMAP_NEAREST => (Filter::Linear, MipFilter::Nearest),
                GL_NEAREST_MIPMAP_LINEAR => (Filter::Nearest, MipFilter::Linear),
                GL_LINEAR_MIPMAP_LINEAR => (Filter::Linear, MipFilter::Linear),
                _ => return Err(GlError::InvalidEnum),
            }
        }
        GL_TEXTURE_MAG_FILTER => {
            p.mag_filter = match e {
                GL_NEAREST => Filter::Nearest,
                GL_LINEAR => Filter::Linear,
                _ => return Err(GlError::InvalidEnum),
            }
        }
        GL_TEXTURE_WRAP_S => p.wrap_s = wrap_from_gl(e)?,
        GL_TEXTURE_WRAP_T => p.wrap_t = wrap_from_gl(e)?,
        GL_TEXTURE_WRAP_R => p.wrap_r = wrap_from_gl(e)?,
        GL_TEXTURE_BORDER_COLOR => {
            if v.len() < 4 {
                return Err(GlError::InvalidEnum);
            }
            p.border_color = std::array::from_fn(|i| {
                let x = if ints {
                    (2.0 * v[i] + 1.0) / 4294967295.0
                } else {
                    v[i]
                };
                crate::context::clamp01(x) as f32
            });
        }
        GL_TEXTURE_MIN_LOD => p.min_lod = v[0] as f32,
        GL_TEXTURE_MAX_LOD => p.max_lod = v[0] as f32,
        GL_TEXTURE_BASE_LEVEL => {
            if v[0] < 0.0 {
                return Err(GlError::InvalidValue);
            }
            p.base_level = v[0] as i32;
        }
        GL_TEXTURE_MAX_LEVEL => {
            if v[0] < 0.0 {
                return Err(GlError::InvalidValue);
            }
            p.max_level = v[0] as i32;
        }
        GL_TEXTURE_LOD_BIAS => p.lod_bias = v[0] as f32,
        GL_GENERATE_MIPMAP => p.generate_mipmap = v[0] != 0.0,
        GL_TEXTURE_MAX_ANISOTROPY_EXT => {
            if v[0] < 1.0 {
                return Err(GlError::InvalidValue);
            }
            p.max_anisotropy = (v[0] as f32).min(MAX_ANISOTROPY);
        }
        GL_TEXTURE_PRIORITY => p.priority = crate::context::clamp01(v[0]) as f32,
        GL_TEXTURE_COMPARE_MODE | GL_TEXTURE_COMPARE_FUNC | GL_DEPTH_TEXTURE_MODE => {
            shadow_parameter(&mut p.shadow, pname, e)?
        }
        _ => return Err(GlError::InvalidEnum),
    }
    object_mut(c, t, false).params = p;
    Ok(())
}

fn get_tex_parameter(c: &mut Context, target: GLenum, pname: GLenum) -> GlResult<(Vec<f64>, bool)> {
    let t = bind_target(target)?;
    let p = &object(c, t, false).params;
    let one = |x: f64| Ok((vec![x], false));
    match pname {
        GL_TEXTURE_MIN_FILTER => one(min_filter_to_gl(p.min_filter, p.mip_filter) as f64),
        GL_TEXTURE_MAG_FILTER => one(match p.mag_filter {
            Filter::Nearest => GL_NEAREST,
            Filter::Linear => GL_LINEAR,
        } as f64),
        GL_TEXTURE_WRAP_S => one(wrap_to_gl(p.wrap_s) as f64),
        GL_TEXTURE_WRAP_T => one(wrap_to_gl(p.wrap_t) as f64),
        GL_TEXTURE_WRAP_R => one(wrap_to_gl(p.wrap_r) as f64),
        GL_TEXTURE_BORDER_COLOR => Ok((p.border_color.map(|x| x as f64).to_vec(), true)),
        GL_TEXTURE_MIN_LOD => one(p.min_lod as f64),
        GL_TEXTURE_MAX_LOD => one(p.max_lod as f64),
        GL_TEXTURE_BASE_LEVEL => one(p.base_level as f64),
        GL_TEXTURE_MAX_LEVEL => one(p.max_level as f64),
        GL_TEXTURE_LOD_BIAS => one(p.lod_bias as f64),
        GL_GENERATE_MIPMAP => one(p.generate_mipmap as u8 as f64),
        GL_TEXTURE_MAX_ANISOTROPY_EXT => one(p.max_anisotropy as f64),
        GL_TEXTURE_PRIORITY => one(p.priority as f64),
        GL_TEXTURE_RESIDENT => one(1.0),
        GL_TEXTURE_COMPARE_MODE | GL_TEXTURE_COMPARE_FUNC | GL_DEPTH_TEXTURE_MODE => {
            one(get_shadow_parameter(&p.shadow, pname) as f64)
        }
        _ => Err(GlError::InvalidEnum),
    }
}

fn get_level_parameter(
    c: &mut Context,
    target: GLenum,
    level: GLint,
    pname: GLenum,
) -> GlResult<f64> {
    let (t, proxy, face) = image_target(target)?;
    let level = check_level(level)?;
    let obj = object(c, t, proxy);
    let img = obj.face_levels(face).get(level).and_then(|l| l.as_ref());
    let depth = if t == Target::Tex3D {
        obj.depths[level]
    } else {
        1
    };
    // the sizes of the storage format Mesa chose (upload::choose_storage)
    let is_depth = img.is_some_and(|i| i.base == BaseFormat::Depth);
    let compressed =
        img.and_then(|i| crate::context::pack::tex_format::compressed_info(i.internal_format));
    let size = |k: usize| img.filter(|_| !is_depth).map_or(0, |i| i.storage.sizes[k]) as f64;
    Ok(match pname {
        GL_TEXTURE_WIDTH => img.map_or(0, |i| i.width) as f64,
        GL_TEXTURE_HEIGHT => img.map_or(0, |i| i.height) as f64,
        GL_TEXTURE_DEPTH => img.map_or(0, |_| depth) as f64,
        GL_TEXTURE_BORDER => 0.0,
        // Mesa reports GL_RGBA for a level that was never specified
        GL_TEXTURE_INTERNAL_FORMAT => img.map_or(GL_RGBA, |i| i.internal_format) as f64,
        GL_TEXTURE_RED_SIZE => size(0),
        GL_TEXTURE_GREEN_SIZE => size(1),
        GL_TEXTURE_BLUE_SIZE => size(2),
        GL_TEXTURE_ALPHA_SIZE => size(3),
        GL_TEXTURE_LUMINANCE_SIZE => size(4),
        GL_TEXTURE_INTENSITY_SIZE => size(5),
        GL_TEXTURE_COMPRESSED => compressed.is_some() as u8 as f64,
        // Mesa: GL_INVALID_OPERATION unless the image is compressed and not a proxy
        GL_TEXTURE_COMPRESSED_IMAGE_SIZE => match (compressed, img) {
            (Some(f), Some(i)) if !proxy => f.image_size(i.width as i32, i.height as i32) as f64,
            _ => return Err(GlError::InvalidOperation),
        },
        GL_TEXTURE_DEPTH_SIZE => {
            img.filter(|_| is_depth)
                .map_or(0, |i| shadow::depth_size(i.storage.depth_bits())) as f64
        }
        GL_TEXTURE_STENCIL_SIZE => img
            .filter(|i| shadow::is_depth_stencil(i.internal_format))
            .map_or(0, |_| 8) as f64,
        _ => return Err(GlError::InvalidEnum),
    })
}

/// glTexParameterf.
#[no_mangle]
pub extern "C" fn glTexParameterf(target: GLenum, pname: GLenum, param: GLfloat) {
    // Mesa compiles the scalar forms as glTexParameterfv with (param, 0, 0, 0)
    // (`save_TexParameter*`), so in a display list GL_TEXTURE_BORDER_COLOR is accepted.
    let v = [param as f64, 0.0, 0.0, 0.0];
    if pname == GL_TEXTURE_BORDER_COLOR && compiling_list() {
        return with_ctx_list(move |c| tex_parameter(c, target, pname, &v, false));
    }
    with_ctx_list(move |c| {
        if pname == GL_TEXTURE_BORDER_COLOR {
            return Err(GlError::InvalidEnum);
        }
        tex_parameter(c, target, pname, &v[..1], false)
    })
}

/// glTexParameteri.
#[no_mangle]
pub extern "C" fn glTexParameteri(target: GLenum, pname: GLenum, param: GLint) {
    // Mesa compiles the scalar forms as glTexParameterfv with (param, 0, 0, 0)
    // (`save_TexParameter*`), so in a display list GL_TEXTURE_BORDER_COLOR is accepted.
    let v = [param as f64, 0.0, 0.0, 0.0];
    if pname == GL_TEXTURE_BORDER_COLOR && compiling_list() {
        // (as glTexParameterfv: the integer is converted, not normalised)
        return with_ctx_list(move |c| tex_parameter(c, target, pname, &v, false));
    }
    with_ctx_list(move |c| {
        if pname == GL_TEXTURE_BORDER_COLOR {
            return Err(GlError::InvalidEnum);
        }
        tex_parameter(c, target, pname, &v[..1], true)
    })
}

/// glTexParameterfv.
///
/// # Safety
/// `params` must hold the parameter's values (4 for GL_TEXTURE_BORDER_COLOR).
#[no_mangle]
pub unsafe extern "C" fn glTexParameterfv(target: GLenum, pname: GLenum, params: *const GLfloat) {
    if params.is_null() {
        return;
    }
    let n = if pname == GL_TEXTURE_BORDER_COLOR {
        4
    } else {
        1
    };
    // SAFETY: the caller promises n readable values.
    let v = unsafe { std::slice::from_raw_parts(params, n) };
    let v: Vec<f64> = v.iter().map(|&x| x as f64).collect();
    with_ctx_list(move |c| tex_parameter(c, target, pname, &v, false))
}

/// glTexParameteriv.
///
/// # Safety
/// `params` must hold the parameter's values (4 for GL_TEXTURE_BORDER_COLOR).
#[no_mangle]
pub unsafe extern "C" fn glTexParameteriv(target: GLenum, pname: GLenum, params: *const GLint) {
    if params.is_null() {
        return;
    }
    let n = if pname == GL_TEXTURE_BORDER_COLOR {
        4
    } else {
        1
    };
    // SAFETY: the caller promises n readable values.
    let v = unsafe { std::slice::from_raw_parts(params, n) };
    let v: Vec<f64> = v.iter().map(|&x| x as f64).collect();
    with_ctx_list(move |c| tex_parameter(c, target, pname, &v, true))
}

/// glGetTexParameterfv.
///
/// # Safety
/// `params` must be writable for the parameter's values.
#[no_mangle]
pub unsafe extern "C" fn glGetTexParameterfv(target: GLenum, pname: GLenum, params: *mut GLfloat) {
    with_ctx(|c| {
        let (v, _) = get_tex_parameter(c, target, pname)?;
        if !params.is_null() {
            for (i, x) in v.iter().enumerate() {
                // SAFETY: the caller promises room for the values.
                unsafe { *params.add(i) = *x as f32 };
            }
        }
        Ok(())
    })
}

/// glGetTexParameteriv.
///
/// # Safety
/// `params` must be writable for the parameter's values.
#[no_mangle]
pub unsafe extern "C" fn glGetTexParameteriv(target: GLenum, pname: GLenum, params: *mut GLint) {
    with_ctx(|c| {
        let (v, normalized) = get_tex_parameter(c, target, pname)?;
        if !params.is_null() {
            for (i, x) in v.iter().enumerate() {
                let iv = if normalized {
                    // Mesa's FLOAT_TO_INT truncates: 0.25 → 536870911
                    (x * 2147483647.0) as i32
                } else {
                    x.round() as i32
                };
                // SAFETY: the caller promises room for the values.
                unsafe { *params.add(i) = iv };
            }
        }
        Ok(())
    })
}

/// glGetTexLevelParameterfv.
///
/// # Safety
/// `params` must be writable.
#[no_mangle]
pub unsafe extern "C" fn glGetTexLevelParameterfv(
    target: GLenum,
    level: GLint,
    pname: GLenum,
    params: *mut GLfloat,
) {
    with_ctx(|c| {
        let v = get_level_parameter(c, target, level, pname)?;
        if !params.is_null() {
            // SAFETY: the caller promises a writable value.
            unsafe { *params = v as f32 };
        }
        Ok(())
    })
}

/// glGetTexLevelParameteriv.
///
/// # Safety
/// `params` must be writable.
#[no_mangle]
pub unsafe extern "C" fn glGetTexLevelParameteriv(
    target: GLenum,
    level: GLint,
    pname: GLenum,
    params: *mut GLint,
) {
    with_ctx(|c| {
        let v = get_level_parameter(c, target, level, pname)?;
        if !params.is_null() {
            // SAFETY: the caller promises a writable value.
            unsafe { *params = v as i32 };
        }
        Ok(())
    })
}

fn scale_from(v: f64) -> GlResult<f32> {
    if v == 1.0 || v == 2.0 || v == 4.0 {
        Ok(v as f32)
    } else {
        Err(GlError::InvalidValue)
    }
}

/// glTexEnv*: `v` holds the values (4 for GL_TEXTURE_ENV_COLOR); `ints` normalises colours.
fn tex_env(c: &mut Context, target: GLenum, pname: GLenum, v: &[f64], ints: bool) -> GlResult<()> {
    let unit = c.state.active_texture;
    match target {
        GL_TEXTURE_FILTER_CONTROL => {
            if pname != GL_TEXTURE_LOD_BIAS {
                return Err(GlError::InvalidEnum);
            }
            c.textures.units[unit].lod_bias = v[0] as f32;
            return Ok(());
        }
        GL_TEXTURE_ENV => {}
        _ => return Err(GlError::InvalidEnum),
    }
    let mut env = c.textures.units[unit].env;
    let e = v[0] as i64 as u32;
    let idx = |base: u32| (pname - base) as usize;
    match pname {
        GL_TEXTURE_ENV_MODE => env.mode = EnvMode::from_gl(e).ok_or(GlError::InvalidEnum)?,
        GL_TEXTURE_ENV_COLOR => {
            if v.len() < 4 {
                return Err(GlError::InvalidEnum);
            }
            env.color = std::array::from_fn(|i| {
                let x = if ints {
                    (2.0 * v[i] + 1.0) / 4294967295.0
                } else {
                    v[i]
                };
                crate::context::clamp01(x) as f32
            });
        }
        GL_COMBINE_RGB => {
            env.combine_rgb = CombineFn::from_gl(e, true).ok_or(GlError::InvalidEnum)?
        }
        GL_COMBINE_ALPHA => {
            env.combine_alpha = CombineFn::from_gl(e, false).ok_or(GlError::InvalidEnum)?
        }
        GL_SOURCE0_RGB..=GL_SOURCE2_RGB => {
            env.source_rgb[idx(GL_SOURCE0_RGB)] =
                Source::from_gl(e, MAX_TEXTURE_UNITS).ok_or(GlError::InvalidEnum)?
        }
        GL_SOURCE0_ALPHA..=GL_SOURCE2_ALPHA => {
            env.source_alpha[idx(GL_SOURCE0_ALPHA)] =
                Source::from_gl(e, MAX_TEXTURE_UNITS).ok_or(GlError::InvalidEnum)?
        }
        GL_OPERAND0_RGB..=GL_OPERAND2_RGB => {
            env.operand_rgb[idx(GL_OPERAND0_RGB)] =
                Operand::from_gl(e, false).ok_or(GlError::InvalidEnum)?
        }
        GL_OPERAND0_ALPHA..=GL_OPERAND2_ALPHA => {
            env.operand_alpha[idx(GL_OPERAND0_ALPHA)] =
                Operand::from_gl(e, true).ok_or(GlError::InvalidEnum)?
        }
        GL_RGB_SCALE => env.rgb_scale = scale_from(v[0])?,
        GL_ALPHA_SCALE => env.alpha_scale = scale_from(v[0])?,
        _ => return Err(GlError::InvalidEnum),
    }
    c.textures.units[unit].env = env;
    Ok(())
}

fn get_tex_env(c: &mut Context, target: GLenum, pname: GLenum) -> GlResult<(Vec<f64>, bool)> {
    let u = &c.textures.units[c.state.active_texture];
    let one = |x: u32| Ok((vec![x as f64], false));
    match target {
        GL_TEXTURE_FILTER_CONTROL if pname == GL_TEXTURE_LOD_BIAS => {
            return Ok((vec![u.lod_bias as f64], false))
        }
        GL_TEXTURE_ENV => {}
        _ => return Err(GlError::InvalidEnum),
    }
    let env = &u.env;
    let idx = |base: u32| (pname - base) as usize;
    match pname {
        GL_TEXTURE_ENV_MODE => one(env.mode.to_gl()),
        GL_TEXTURE_ENV_COLOR => Ok((env.color.map(|x| x as f64).to_vec(), true)),
        GL_COMBINE_RGB => one(env.combine_rgb.to_gl()),
        GL_COMBINE_ALPHA => one(env.combine_alpha.to_gl()),
        GL_SOURCE0_RGB..=GL_SOURCE2_RGB => one(env.source_rgb[idx(GL_SOURCE0_RGB)].to_gl()),
        GL_SOURCE0_ALPHA..=GL_SOURCE2_ALPHA => one(env.source_alpha[idx(GL_SOURCE0_ALPHA)].to_gl()),
        GL_OPERAND0_RGB..=GL_OPERAND2_RGB => one(env.operand_rgb[idx(GL_OPERAND0_RGB)].to_gl()),
        GL_OPERAND0_ALPHA..=GL_OPERAND2_ALPHA => {
            one(env.operand_alpha[idx(GL_OPERAND0_ALPHA)].to_gl())
        }
        GL_RGB_SCALE => Ok((vec![env.rgb_scale as f64], false)),
        GL_ALPHA_SCALE => Ok((vec![env.alpha_scale as f64], false)),
        _ => Err(GlError::InvalidEnum),
    }
}

/// glTexEnvf.
#[no_mangle]
pub extern "C" fn glTexEnvf(target: GLenum, pname: GLenum, param: GLfloat) {
    with_ctx_list(move |c| {
        if pname == GL_TEXTURE_ENV_COLOR {
            return Err(GlError::InvalidEnum);
        }
        tex_env(c, target, pname, &[param as f64], false)
    })
}

/// glTexEnvi.
#[no_mangle]
pub extern "C" fn glTexEnvi(target: GLenum, pname: GLenum, param: GLint) {
    with_ctx_list(move |c| {
        if pname == GL_TEXTURE_ENV_COLOR {
            return Err(GlError::InvalidEnum);
        }
        tex_env(c, target, pname, &[param as f64], true)
    })
}

/// glTexEnvfv.
///
/// # Safety
/// `params` must hold the parameter's values (4 for GL_TEXTURE_ENV_COLOR).
#[no_mangle]
pub unsafe extern "C" fn glTexEnvfv(target: GLenum, pname: GLenum, params: *const GLfloat) {
    if params.is_null() {
        return;
    }
    let n = if pname == GL_TEXTURE_ENV_COLOR { 4 } else { 1 };
    // SAFETY: the caller promises n readable values.
    let v = unsafe { std::slice::from_raw_parts(params, n) };
    let v: Vec<f64> = v.iter().map(|&x| x as f64).collect();
    with_ctx_list(move |c| tex_env(c, target, pname, &v, false))
}

/// glTexEnviv.
///
/// # Safety
/// `params` must hold the parameter's values (4 for GL_TEXTURE_ENV_COLOR).
#[no_mangle]
pub unsafe extern "C" fn glTexEnviv(target: GLenum, pname: GLenum, params: *const GLint) {
    if params.is_null() {
        return;
    }
    let n = if pname == GL_TEXTURE_ENV_COLOR { 4 } else { 1 };
    // SAFETY: the caller promises n readable values.
    let v = unsafe { std::slice::from_raw_parts(params, n) };
    let v: Vec<f64> = v.iter().map(|&x| x as f64).collect();
    with_ctx_list(move |c| tex_env(c, target, pname, &v, true))
}

/// glGetTexEnvfv.
///
/// # Safety
/// `params` must be writable for the parameter's values.
#[no_mangle]
pub unsafe extern "C" fn glGetTexEnvfv(target: GLenum, pname: GLenum, params: *mut GLfloat) {
    with_ctx(|c| {
        let (v, _) = get_tex_env(c, target, pname)?;
        if !params.is_null() {
            for (i, x) in v.iter().enumerate() {
                // SAFETY: the caller promises room for the values.
                unsafe { *params.add(i) = *x as f32 };
            }
        }
        Ok(())
    })
}

/// glGetTexEnviv.
///
/// # Safety
/// `params` must be writable for the parameter's values.
#[no_mangle]
pub unsafe extern "C" fn glGetTexEnviv(target: GLenum, pname: GLenum, params: *mut GLint) {
    with_ctx(|c| {
        let (v, normalized) = get_tex_env(c, target, pname)?;
        if !params.is_null() {
            for (i, x) in v.iter().enumerate() {
                let iv = if normalized {
                    (x * 2147483647.0).round() as i32
                } else {
                    x.round() as i32
                };
                // SAFETY: the caller promises room for the values.
                unsafe { *params.add(i) = iv };
            }
        }
        Ok(())
    })
}

/// glActiveTexture (GL_TEXTUREi, i < GL_MAX_TEXTURE_UNITS). Mesa's rule is i < the larger
/// of the combined image-unit and texture-coordinate limits; softgl has no shader image
/// units, so both are GL_MAX_TEXTURE_UNITS (8), where llvmpipe's combined limit is 192 (piglit's
/// `texunits` expects GL_INVALID_ENUM at the limit the implementation reports).
/// `state.caps` for GL_TEXTURE_1D/2D follows the unit.
#[no_mangle]
pub extern "C" fn glActiveTexture(texture: GLenum) {
    with_ctx_list(move |c| {
        let u = texture.wrapping_sub(GL_TEXTURE0) as usize;
        if u >= MAX_TEXTURE_UNITS {
            return Err(GlError::InvalidEnum);
        }
        c.state.active_texture = u;
        let unit = &c.textures.units[u];
        let (e1, e2) = (unit.enabled_1d, unit.enabled_2d);
        let (e3, ec) = (unit.enabled_3d, unit.enabled_cube);
        c.state.caps.set(Cap::Texture1D, e1);
        c.state.caps.set(Cap::Texture2D, e2);
        c.state.caps.set(Cap::Texture3D, e3);
        c.state.caps.set(Cap::TextureCubeMap, ec);
        c.sync_texgen_caps();
        Ok(())
    })
}

/// glClientActiveTexture.
#[no_mangle]
pub extern "C" fn glClientActiveTexture(texture: GLenum) {
    with_ctx(|c| {
        let u = texture.wrapping_sub(GL_TEXTURE0) as usize;
        if u >= MAX_TEXTURE_UNITS {
            return Err(GlError::InvalidEnum);
        }
        c.state.client_active_texture = u;
        Ok(())
    })
}

/// glPrioritizeTextures (priorities are stored; residency is always true).
///
/// # Safety
/// `textures` and `priorities` must be readable for `n` values.
#[no_mangle]
pub unsafe extern "C" fn glPrioritizeTextures(
    n: GLsizei,
    textures: *const GLuint,
    priorities: *const GLclampf,
) {
    let read = || -> Result<(Vec<GLuint>, Vec<GLclampf>), GlError> {
        let n = non_negative(n)?;
        if textures.is_null() || priorities.is_null() {
            return Ok((Vec::new(), Vec::new()));
        }
        // SAFETY: the caller promises n readable values in each array.
        Ok(unsafe {
            (
                std::slice::from_raw_parts(textures, n).to_vec(),
                std::slice::from_raw_parts(priorities, n).to_vec(),
            )
        })
    };
    let arrays = read();
    with_ctx_list(move |c| {
        let (names, prios) = arrays.as_ref().map_err(|e| *e)?;
        for (&name, &p) in names.iter().zip(prios) {
            if let Some(o) = c.textures.objects.get_mut(&name) {
                o.params.priority = crate::context::clamp01(p as f64) as f32;
            }
        }
        Ok(())
    })
}

/// glAreTexturesResident: GL_TRUE for valid names (software textures are always resident);
/// GL_INVALID_VALUE for 0 or an unknown name.
///
/// # Safety
/// `textures` must be readable for `n` names; `residences` writable for `n` values.
#[no_mangle]
pub unsafe extern "C" fn glAreTexturesResident(
    n: GLsizei,
    textures: *const GLuint,
    residences: *mut GLboolean,
) -> GLboolean {
    with_ctx(|c| {
        let n = non_negative(n)?;
        if textures.is_null() {
            return Ok(GL_TRUE as GLboolean);
        }
        // SAFETY: the caller promises n readable names.
        let names = unsafe { std::slice::from_raw_parts(textures, n) };
        if names.iter().any(|&t| !c.textures.is_texture(t)) {
            return Err(GlError::InvalidValue);
        }
        let _ = residences;
        Ok(GL_TRUE as GLboolean)
    })
}

/// Sets the current texture coordinate of unit `target - GL_TEXTURE0`.
fn multi_texcoord(target: GLenum, v: [f32; 4]) {
    // As Mesa (immediate mode and display lists alike): the unit is the target's low three
    // bits, with no error for a target outside GL_TEXTURE0..7.
    let u = (target & 7) as u8;
    super::with_ctx_vertex(crate::context::dlist::VertexOp::TexCoord(u, v))
}

/// glMultiTexCoord1s.
#[no_mangle]
pub extern "C" fn glMultiTexCoord1s(target: GLenum, s: GLshort) {
    multi_texcoord(target, [s as f32, 0.0, 0.0, 1.0])
}

/// glMultiTexCoord1sv.
///
/// # Safety
/// `v` must point to 1 values.
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord1sv(target: GLenum, v: *const GLshort) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 1 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 1) };
    multi_texcoord(target, [v[0] as f32, 0.0, 0.0, 1.0])
}

/// glMultiTexCoord1i.
#[no_mangle]
pub extern "C" fn glMultiTexCoord1i(target: GLenum, s: GLint) {
    multi_texcoord(target, [s as f32, 0.0, 0.0, 1.0])
}

/// glMultiTexCoord1iv.
///
/// # Safety
/// `v` must point to 1 values.
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord1iv(target: GLenum, v: *const GLint) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 1 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 1) };
    multi_texcoord(target, [v[0] as f32, 0.0, 0.0, 1.0])
}

/// glMultiTexCoord1f.
#[no_mangle]
pub extern "C" fn glMultiTexCoord1f(target: GLenum, s: GLfloat) {
    multi_texcoord(target, [s, 0.0, 0.0, 1.0])
}

/// glMultiTexCoord1fv.
///
/// # Safety
/// `v` must point to 1 values.
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord1fv(target: GLenum, v: *const GLfloat) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 1 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 1) };
    multi_texcoord(target, [v[0], 0.0, 0.0, 1.0])
}

/// glMultiTexCoord1d.
#[no_mangle]
pub extern "C" fn glMultiTexCoord1d(target: GLenum, s: GLdouble) {
    multi_texcoord(target, [s as f32, 0.0, 0.0, 1.0])
}

/// glMultiTexCoord1dv.
///
/// # Safety
/// `v` must point to 1 values.
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord1dv(target: GLenum, v: *const GLdouble) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 1 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 1) };
    multi_texcoord(target, [v[0] as f32, 0.0, 0.0, 1.0])
}

/// glMultiTexCoord2s.
#[no_mangle]
pub extern "C" fn glMultiTexCoord2s(target: GLenum, s: GLshort, t: GLshort) {
    multi_texcoord(target, [s as f32, t as f32, 0.0, 1.0])
}

/// glMultiTexCoord2sv.
///
/// # Safety
/// `v` must point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord2sv(target: GLenum, v: *const GLshort) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 2 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 2) };
    multi_texcoord(target, [v[0] as f32, v[1] as f32, 0.0, 1.0])
}

/// glMultiTexCoord2i.
#[no_mangle]
pub extern "C" fn glMultiTexCoord2i(target: GLenum, s: GLint, t: GLint) {
    multi_texcoord(target, [s as f32, t as f32, 0.0, 1.0])
}

/// glMultiTexCoord2iv.
///
/// # Safety
/// `v` must point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord2iv(target: GLenum, v: *const GLint) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 2 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 2) };
    multi_texcoord(target, [v[0] as f32, v[1] as f32, 0.0, 1.0])
}

/// glMultiTexCoord2f.
#[no_mangle]
pub extern "C" fn glMultiTexCoord2f(target: GLenum, s: GLfloat, t: GLfloat) {
    multi_texcoord(target, [s, t, 0.0, 1.0])
}

/// glMultiTexCoord2fv.
///
/// # Safety
/// `v` must point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord2fv(target: GLenum, v: *const GLfloat) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 2 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 2) };
    multi_texcoord(target, [v[0], v[1], 0.0, 1.0])
}

/// glMultiTexCoord2d.
#[no_mangle]
pub extern "C" fn glMultiTexCoord2d(target: GLenum, s: GLdouble, t: GLdouble) {
    multi_texcoord(target, [s as f32, t as f32, 0.0, 1.0])
}

/// glMultiTexCoord2dv.
///
/// # Safety
/// `v` must point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord2dv(target: GLenum, v: *const GLdouble) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 2 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 2) };
    multi_texcoord(target, [v[0] as f32, v[1] as f32, 0.0, 1.0])
}

/// glMultiTexCoord3s.
#[no_mangle]
pub extern "C" fn glMultiTexCoord3s(target: GLenum, s: GLshort, t: GLshort, r: GLshort) {
    multi_texcoord(target, [s as f32, t as f32, r as f32, 1.0])
}

/// glMultiTexCoord3sv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord3sv(target: GLenum, v: *const GLshort) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 3) };
    multi_texcoord(target, [v[0] as f32, v[1] as f32, v[2] as f32, 1.0])
}

/// glMultiTexCoord3i.
#[no_mangle]
pub extern "C" fn glMultiTexCoord3i(target: GLenum, s: GLint, t: GLint, r: GLint) {
    multi_texcoord(target, [s as f32, t as f32, r as f32, 1.0])
}

/// glMultiTexCoord3iv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord3iv(target: GLenum, v: *const GLint) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 3) };
    multi_texcoord(target, [v[0] as f32, v[1] as f32, v[2] as f32, 1.0])
}

/// glMultiTexCoord3f.
#[no_mangle]
pub extern "C" fn glMultiTexCoord3f(target: GLenum, s: GLfloat, t: GLfloat, r: GLfloat) {
    multi_texcoord(target, [s, t, r, 1.0])
}

/// glMultiTexCoord3fv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord3fv(target: GLenum, v: *const GLfloat) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 3) };
    multi_texcoord(target, [v[0], v[1], v[2], 1.0])
}

/// glMultiTexCoord3d.
#[no_mangle]
pub extern "C" fn glMultiTexCoord3d(target: GLenum, s: GLdouble, t: GLdouble, r: GLdouble) {
    multi_texcoord(target, [s as f32, t as f32, r as f32, 1.0])
}

/// glMultiTexCoord3dv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord3dv(target: GLenum, v: *const GLdouble) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 3) };
    multi_texcoord(target, [v[0] as f32, v[1] as f32, v[2] as f32, 1.0])
}

/// glMultiTexCoord4s.
#[no_mangle]
pub extern "C" fn glMultiTexCoord4s(
    target: GLenum,
    s: GLshort,
    t: GLshort,
    r: GLshort,
    q: GLshort,
) {
    multi_texcoord(target, [s as f32, t as f32, r as f32, q as f32])
}

/// glMultiTexCoord4sv.
///
/// # Safety
/// `v` must point to 4 values.
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord4sv(target: GLenum, v: *const GLshort) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 4 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 4) };
    multi_texcoord(target, [v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32])
}

/// glMultiTexCoord4i.
#[no_mangle]
pub extern "C" fn glMultiTexCoord4i(target: GLenum, s: GLint, t: GLint, r: GLint, q: GLint) {
    multi_texcoord(target, [s as f32, t as f32, r as f32, q as f32])
}

/// glMultiTexCoord4iv.
///
/// # Safety
/// `v` must point to 4 values.
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord4iv(target: GLenum, v: *const GLint) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 4 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 4) };
    multi_texcoord(target, [v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32])
}

/// glMultiTexCoord4f.
#[no_mangle]
pub extern "C" fn glMultiTexCoord4f(
    target: GLenum,
    s: GLfloat,
    t: GLfloat,
    r: GLfloat,
    q: GLfloat,
) {
    multi_texcoord(target, [s, t, r, q])
}

/// glMultiTexCoord4fv.
///
/// # Safety
/// `v` must point to 4 values.
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord4fv(target: GLenum, v: *const GLfloat) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 4 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 4) };
    multi_texcoord(target, [v[0], v[1], v[2], v[3]])
}

/// glMultiTexCoord4d.
#[no_mangle]
pub extern "C" fn glMultiTexCoord4d(
    target: GLenum,
    s: GLdouble,
    t: GLdouble,
    r: GLdouble,
    q: GLdouble,
) {
    multi_texcoord(target, [s as f32, t as f32, r as f32, q as f32])
}

/// glMultiTexCoord4dv.
///
/// # Safety
/// `v` must point to 4 values.
#[no_mangle]
pub unsafe extern "C" fn glMultiTexCoord4dv(target: GLenum, v: *const GLdouble) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 4 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 4) };
    multi_texcoord(target, [v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32])
}
