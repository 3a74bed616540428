//! Texture specification (GL 1.5 §3.8.1–3.8.3): image targets, the bound object a command
//! changes, glTexImage/glTexSubImage for 1D, 2D and cube-map images (with their proxies) and
//! mipmap regeneration (glGetTexImage is [`super::texture_pack`]). Every command validates all arguments, in Mesa's
//! order, before changing any state; the C boundary (`ffi/textures.rs`) only forwards the
//! arguments and records the error.
//!
//! Borders: Mesa's gallium front end strips texture borders (`StripTextureBorder`), and so
//! do we: border 1 is accepted and the outer ring of texels is dropped; other borders are
//! GL_INVALID_VALUE.

use super::state::PixelStore;
use super::{Context, GlError, GlResult};
use crate::context::pack::depth as shadow;
use crate::context::pack::tex::{self as upload, ClientFormat};
use crate::context::pack::tex_float;
use crate::gl::enums::*;
use crate::gl::types::*;
use crate::texture::{
    float, mipmap, BaseFormat, Level, Storage, Target, TextureObject, MAX_LEVELS, MAX_TEXTURE_SIZE,
};
use std::ffi::c_void;

/// A count or size argument: GL_INVALID_VALUE when negative.
pub(crate) fn non_negative(n: i32) -> GlResult<usize> {
    usize::try_from(n).map_err(|_| GlError::InvalidValue)
}

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

/// The (target, cube face) of a command of `dims` dimensions that writes an existing
/// texture (no proxies): GL_INVALID_ENUM otherwise.
pub(crate) fn sub_image_target(target: GLenum, dims: u8) -> GlResult<(Target, usize)> {
    match image_target(target)? {
        (t, false, face) if dims_match(t, dims) => Ok((t, face)),
        _ => Err(GlError::InvalidEnum),
    }
}

/// A mipmap level number (GL_INVALID_VALUE outside 0..MAX_LEVELS).
pub(crate) fn check_level(level: GLint) -> GlResult<usize> {
    if level < 0 || level as usize >= MAX_LEVELS {
        Err(GlError::InvalidValue)
    } else {
        Ok(level as usize)
    }
}

/// Stores `img` as image (`face`, `level`) of `obj`, with the stencil of a depth-stencil
/// image (see [`super::texture_ds::set`]), and regenerates the mipmaps from it if asked.
pub(crate) fn store_level(
    obj: &mut TextureObject,
    (face, level): (usize, usize),
    img: Level,
    stencil: Vec<u8>,
) {
    super::texture_ds::set(obj, (face, level), img.internal_format, stencil);
    obj.face_levels_mut(face)[level] = Some(img);
    maybe_generate(obj, level);
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
pub(crate) fn image_size(
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

/// GL_INVALID_OPERATION unless a depth image meets depth data and a colour image colour
/// data.
pub(crate) fn depth_match(base: BaseFormat, cf: &ClientFormat) -> GlResult<()> {
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
    match super::texture_compressed::generic_base(internal as GLenum) {
        Some(b) if t == Target::Tex1D => (b as GLint, format, ty),
        Some(b) => (b as GLint, 0, 0),
        None => (internal, format, ty),
    }
}

/// The internal format of a new glTexImage1D/2D/3D level of `internal` on `t` for client
/// data of `format`/`ty` ([`resolve_internal`]), with its base format and storage
/// ([`storage_of`]); an unknown internal format is GL_INVALID_VALUE.
pub(crate) fn level_format(
    internal: GLint,
    t: Target,
    (format, ty): (GLenum, GLenum),
) -> GlResult<(u32, (BaseFormat, Storage))> {
    let (internal, sformat, sty) = resolve_internal(internal, t, (format, ty));
    let base = upload::base_format(internal).ok_or(GlError::InvalidValue)?;
    let storage = storage_of(internal, base, sformat, sty);
    Ok((internal as u32, (base, storage)))
}

/// A `w` x `h` level of `texels` in internal format `internal`, with its base format and
/// storage, and no compressed blocks.
pub(crate) fn new_level(
    internal: u32,
    (base, storage): (BaseFormat, Storage),
    (w, h): (usize, usize),
    texels: Vec<[u8; 4]>,
) -> Level {
    Level {
        width: w,
        height: h,
        internal_format: internal,
        base,
        storage,
        texels: texels.into(),
        blocks: None,
        floats: None,
    }
}

/// The unpack state that skips the one-texel border of a `w` x `h` image (stripped of its
/// border): the first pixel of each row, the first row when `rows`, and the first image
/// with its height when `images` (GL 1.5 §3.8.1).
pub(crate) fn skip_border(
    unpack: PixelStore,
    (w, h): (usize, usize),
    rows: bool,
    images: bool,
) -> PixelStore {
    let mut ps = unpack;
    if ps.row_length == 0 {
        ps.row_length = (w + 2) as i32;
    }
    ps.skip_pixels += 1;
    if rows {
        ps.skip_rows += 1;
    }
    if images {
        if ps.image_height == 0 {
            ps.image_height = (h + 2) as i32;
        }
        ps.skip_images += 1;
    }
    ps
}

/// The storage Mesa picks for an image (depth images: their depth bits).
pub(crate) fn storage_of(internal: GLint, base: BaseFormat, format: GLenum, ty: GLenum) -> Storage {
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
        unsafe { super::texture_ci::unpack(c, ps, ty, texel, size, data) }
    } else {
        // SAFETY: forwarded caller contract.
        unsafe { unpack_any(c, ps, cf, texel, size, data) }
    }
}

/// [`unpack_image`] with the float values of an image that keeps them
/// ([`Storage::has_floats`]): unpacked as floats (the texels are their clamped bytes), or
/// for GL_COLOR_INDEX data made from the texels.
///
/// # Safety
/// `data` (when not null) must hold the described image under `ps`.
pub(crate) unsafe fn unpack_rect(
    c: &Context,
    ps: &PixelStore,
    (cf, format, ty): (&ClientFormat, GLenum, GLenum),
    texel: (BaseFormat, Storage),
    size: (usize, usize),
    data: *const c_void,
) -> (Vec<[u8; 4]>, Option<Vec<[f32; 4]>>) {
    let storage = texel.1;
    if !storage.has_floats() {
        // SAFETY: forwarded caller contract.
        return (
            unsafe { unpack_image(c, ps, (cf, format, ty), texel, size, data) },
            None,
        );
    }
    if format == GL_COLOR_INDEX {
        // SAFETY: forwarded caller contract.
        let texels = unsafe { unpack_image(c, ps, (cf, format, ty), texel, size, data) };
        let floats = texels
            .iter()
            .map(|&t| float::from_bytes(&storage, t))
            .collect();
        return (texels, Some(floats));
    }
    let tr = upload::ColorTransfer::active(&c.pixel_modes.transfer, &c.pixel_maps);
    // SAFETY: forwarded caller contract.
    let floats = unsafe { tex_float::unpack(ps, cf, texel, size, data as *const u8, tr) };
    (
        floats.iter().map(|&v| float::to_bytes(v)).collect(),
        Some(floats),
    )
}

impl Context {
    /// The texture object a command on `target` changes: the proxy, or the object bound to
    /// the active unit (marking a framebuffer object it is attached to as changed).
    pub(crate) fn tex_object_mut(&mut self, target: Target, proxy: bool) -> &mut TextureObject {
        if proxy {
            &mut self.textures.proxies[target.index()]
        } else {
            let unit = self.state.active_texture;
            // The image may be attached to the framebuffer object being drawn.
            let name = self.textures.units[unit].bound[target.index()];
            self.fbo_touch(name);
            self.fbo.touch_texture(name);
            self.textures.bound_mut(unit, target)
        }
    }

    /// The texture object a query of `target` reads: the proxy, or the object bound to the
    /// active unit.
    pub(crate) fn tex_object(&self, target: Target, proxy: bool) -> &TextureObject {
        if proxy {
            &self.textures.proxies[target.index()]
        } else {
            self.textures.bound(self.state.active_texture, target)
        }
    }

    /// glTexImage1D/2D (`dims`) and their proxies, with Mesa's error order.
    ///
    /// # Safety
    /// `data` (when not null) must hold the described image under `unpack`.
    pub(crate) unsafe fn tex_image(
        &mut self,
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
        let cf = super::texture_ci::client_format(format, ty)?;
        let (internal, texel) = level_format(internal, t, (format, ty))?;
        depth_match(texel.0, &cf)?;
        let size = image_size(t, level, w, h, border);
        if proxy {
            let obj = self.tex_object_mut(t, true);
            obj.face_levels_mut(face)[level] = match size {
                Ok(Some(size)) => Some(new_level(internal, texel, size, Vec::new())),
                _ => None,
            };
            return Ok(());
        }
        let Some((tw, th)) = size? else {
            return Ok(());
        };
        // Border stripping: skip the first border pixel and row of the client image.
        let ps = match border {
            1 => skip_border(unpack, (tw, th), t == Target::Tex2D, false),
            _ => unpack,
        };
        // SAFETY: GL's contract: `data` (when not null) holds the described image.
        let (texels, floats) =
            unsafe { unpack_rect(self, &ps, (&cf, format, ty), texel, (tw, th), data) };
        // SAFETY: as above.
        let stencil = unsafe { super::texture_ds::unpack_stencil(self, &ps, &cf, (tw, th), data) };
        let mut img = new_level(internal, texel, (tw, th), texels);
        img.floats = floats;
        store_level(self.tex_object_mut(t, false), (face, level), img, stencil);
        Ok(())
    }

    /// glTexSubImage1D/2D (`dims`).
    ///
    /// # Safety
    /// `data` must hold the described image under `unpack`.
    pub(crate) unsafe fn tex_sub_image(
        &mut self,
        target: GLenum,
        level: GLint,
        (xoff, yoff, w, h, format, ty): (GLint, GLint, GLsizei, GLsizei, GLenum, GLenum),
        data: *const c_void,
        dims: u8,
        unpack: PixelStore,
    ) -> GlResult<()> {
        let (t, face) = sub_image_target(target, dims)?;
        let cf = super::texture_ci::client_format(format, ty)?;
        let level = check_level(level)?;
        let (w, h) = (non_negative(w)?, non_negative(h)?);
        let ps = unpack;
        let (base, storage, width, height, internal) = self
            .tex_object(t, false)
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
            super::texture_compressed::check_sub_rect((width as i32, height as i32), rect)?;
        }
        // SAFETY: GL's contract: `data` holds the described image.
        let (texels, floats) =
            unsafe { unpack_rect(self, &ps, (&cf, format, ty), (base, storage), (w, h), data) };
        let stencil = (shadow::is_depth_stencil(internal) && cf.is_depth_stencil())
            // SAFETY: as above.
            .then(|| unsafe { super::texture_ds::unpack_stencil(self, &ps, &cf, (w, h), data) });
        let obj = self.tex_object_mut(t, false);
        if let Some(s) = stencil {
            let rect = (xoff as usize, yoff as usize, w, h);
            super::texture_ds::update(obj, (face, level), (width, height), rect, &s);
        }
        let img = obj.face_levels_mut(face)[level]
            .as_mut()
            .ok_or(GlError::InvalidOperation)?;
        for y in 0..h {
            let dst = (yoff as usize + y) * img.width + xoff as usize;
            img.texels[dst..dst + w].copy_from_slice(&texels[y * w..(y + 1) * w]);
            if let Some(f) = &floats {
                img.write_floats(dst, &f[y * w..(y + 1) * w]);
            }
        }
        maybe_generate(obj, level);
        Ok(())
    }

    /// glGenerateMipmap: rebuilds levels base+1..=max from the base level with the same
    /// filter GL_GENERATE_MIPMAP uses (Mesa's `st_generate_mipmap` serves both).
    pub(crate) fn generate_mipmap(&mut self, target: GLenum) -> GlResult<()> {
        let t = bind_target(target)?;
        let obj = self.tex_object_mut(t, false);
        let p = obj.params;
        let base = usize::try_from(p.base_level).map_err(|_| GlError::InvalidOperation)?;
        if obj.levels.get(base).is_none_or(|l| l.is_none()) {
            return Err(GlError::InvalidOperation);
        }
        // Mesa: no mipmaps of a packed depth-stencil image
        let internal = obj.levels[base].as_ref().map_or(0, |l| l.internal_format);
        if shadow::is_depth_stencil(internal) {
            return Err(GlError::InvalidOperation);
        }
        regenerate(obj, base);
        Ok(())
    }
}
