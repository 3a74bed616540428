//! Compressed texture images (GL 1.3, GL_ARB_texture_compression) for the S3TC, RGTC
//! and LATC formats (see [`crate::texture::compressed`]): glCompressedTexImage*,
//! glCompressedTexSubImage* and glGetCompressedTexImage with Mesa 22.3's checks in Mesa's
//! order (`teximage.c`: `compressed_texture_error_check`,
//! `compressed_subtexture_error_check`; `texgetimage.c`). Only 2D and cube-map images can
//! be compressed: the 1D and 3D calls end in Mesa's target errors. The generic
//! GL_COMPRESSED_* asked of glTexImage and glCopyTexImage store the texture uncompressed
//! (see [`generic_base`]).

use super::texture_spec::{check_level, image_target, maybe_generate};
use super::{Context, GlError, GlResult};
use crate::gl::enums::*;
use crate::gl::types::*;
use crate::texture::compressed::{self, Format, Info};
use crate::texture::{BaseFormat, Level, Storage, Target, MAX_TEXTURE_SIZE};

/// GL 1.3's generic compressed internal formats and the base internal format each names.
///
/// softgl stores them uncompressed, as their base format (the GL 1.3 spec allows it: "if
/// no specific compressed format is available, internalformat is instead replaced by the
/// corresponding base internal format"), so GL_TEXTURE_INTERNAL_FORMAT answers the base
/// format and GL_TEXTURE_COMPRESSED 0. Mesa 22.3 (llvmpipe) does the same for a 1D
/// texture and for ALPHA and INTENSITY; it compresses RGB, RGBA, LUMINANCE and
/// LUMINANCE_ALPHA of the other targets (DXT1, DXT5, LATC1, LATC2): see README's
/// known differences.
pub(crate) fn generic_base(f: GLenum) -> Option<GLenum> {
    Some(match f {
        GL_COMPRESSED_ALPHA => GL_ALPHA,
        GL_COMPRESSED_LUMINANCE => GL_LUMINANCE,
        GL_COMPRESSED_LUMINANCE_ALPHA => GL_LUMINANCE_ALPHA,
        GL_COMPRESSED_INTENSITY => GL_INTENSITY,
        GL_COMPRESSED_RGB => GL_RGB,
        GL_COMPRESSED_RGBA => GL_RGBA,
        _ => return None,
    })
}

/// The generic compressed formats (glTexImage's GL_COMPRESSED_RGB ...; GL 3.0's RED/RG and
/// EXT_texture_sRGB's too), which glCompressedTexSubImage rejects with GL_INVALID_ENUM.
fn is_generic_compressed(f: GLenum) -> bool {
    generic_base(f).is_some()
        || matches!(
            f,
            0x8225 // GL_COMPRESSED_RED
            | 0x8226 // GL_COMPRESSED_RG
            | 0x8C48 // GL_COMPRESSED_SRGB
            | 0x8C49 // GL_COMPRESSED_SRGB_ALPHA
            | 0x8C4A // GL_COMPRESSED_SLUMINANCE
            | 0x8C4B // GL_COMPRESSED_SLUMINANCE_ALPHA
        )
}

/// The image targets glCompressedTexImage{dims}D takes (`legal_teximage_target`), and
/// whether the target can hold a compressed image (2D and cube maps only).
fn compressed_target(dims: u32, target: GLenum) -> GlResult<(Target, bool, usize)> {
    let legal = match dims {
        1 => matches!(target, GL_TEXTURE_1D | GL_PROXY_TEXTURE_1D),
        2 => {
            target != GL_TEXTURE_CUBE_MAP
                && matches!(image_target(target), Ok((t, _, _)) if t == Target::Tex2D || t == Target::Cube)
        }
        _ => matches!(target, GL_TEXTURE_3D | GL_PROXY_TEXTURE_3D),
    };
    // legal, but `_mesa_target_can_be_compressed` refuses 1D and 3D for these formats
    if !legal || dims != 2 {
        return Err(GlError::InvalidEnum);
    }
    image_target(target)
}

/// Arguments of glCompressedTexImage2D after the target.
pub(crate) struct ImageArgs {
    /// The mipmap level.
    pub(crate) level: GLint,
    /// The compressed internal format.
    pub(crate) internal: GLenum,
    /// Width in texels.
    pub(crate) w: GLsizei,
    /// Height in texels.
    pub(crate) h: GLsizei,
    /// The border (must be 0).
    pub(crate) border: GLint,
    /// The byte count the client gave.
    pub(crate) size: GLsizei,
}

/// The component sizes glGetTexLevelParameter reports for a compressed image (measured on
/// Mesa 22.3): 4 bits for each S3TC channel the base format has, 8 for RGTC and LATC.
fn storage(info: &Info) -> Storage {
    let sizes = match info.base() {
        BaseFormat::Rgb if info.format == Format::One => [8, 0, 0, 0, 0, 0],
        BaseFormat::Rgb if info.format == Format::Two => [8, 8, 0, 0, 0, 0],
        BaseFormat::Rgb => [4, 4, 4, 0, 0, 0],
        BaseFormat::Luminance => [0, 0, 0, 0, 8, 0],
        BaseFormat::LuminanceAlpha => [0, 0, 0, 8, 8, 0],
        _ => [4, 4, 4, 4, 0, 0],
    };
    Storage {
        sizes,
        encoding: info.encoding(),
    }
}

/// Arguments of glCompressedTexSubImage2D after the target.
pub(crate) struct SubArgs {
    /// The mipmap level.
    pub(crate) level: GLint,
    /// X offset in texels.
    pub(crate) x: GLint,
    /// Y offset in texels.
    pub(crate) y: GLint,
    /// Width in texels.
    pub(crate) w: GLsizei,
    /// Height in texels.
    pub(crate) h: GLsizei,
    /// The compressed format of the data.
    pub(crate) format: GLenum,
    /// The byte count the client gave.
    pub(crate) size: GLsizei,
}

/// Mesa's `compressed_subtexture_target_check`: 2D images and cube faces; a 3D texture
/// holds none of these formats.
fn sub_target(dims: u32, target: GLenum) -> GlResult<(Target, usize)> {
    match dims {
        2 if target == GL_TEXTURE_2D => Ok((Target::Tex2D, 0)),
        2 if (GL_TEXTURE_CUBE_MAP_POSITIVE_X..GL_TEXTURE_CUBE_MAP_POSITIVE_X + 6)
            .contains(&target) =>
        {
            Ok((
                Target::Cube,
                (target - GL_TEXTURE_CUBE_MAP_POSITIVE_X) as usize,
            ))
        }
        3 if target == GL_TEXTURE_3D => Err(GlError::InvalidOperation),
        _ => Err(GlError::InvalidEnum),
    }
}

/// Mesa's sub-image rectangle checks for a block-compressed `iw x ih` image
/// (`error_check_subtexture_negative_dimensions`, `error_check_subtexture_dimensions`):
/// negative sizes and rectangles outside the image are GL_INVALID_VALUE; offsets that are
/// not multiples of 4, and sizes that are not unless they reach the image's edge,
/// GL_INVALID_OPERATION. Used by glTexSubImage on a compressed image too.
pub(crate) fn check_sub_rect(
    (iw, ih): (i32, i32),
    (x, y, w, h): (i32, i32, i32, i32),
) -> GlResult<()> {
    if w < 0 || h < 0 || x < 0 || x.wrapping_add(w) > iw || y < 0 || y.wrapping_add(h) > ih {
        return Err(GlError::InvalidValue);
    }
    if x % 4 != 0 || y % 4 != 0 || (w % 4 != 0 && x + w != iw) || (h % 4 != 0 && y + h != ih) {
        return Err(GlError::InvalidOperation);
    }
    Ok(())
}

impl Context {
    /// glCompressedTexImage{1,2,3}D (`dims`), with the client's blocks when they were
    /// readable and of the right size.
    pub(crate) fn compressed_tex_image(
        &mut self,
        dims: u32,
        target: GLenum,
        a: &ImageArgs,
        data: Option<&[u8]>,
    ) -> GlResult<()> {
        let (t, proxy, face) = compressed_target(dims, target)?;
        let info = crate::context::pack::tex_format::compressed_info(a.internal)
            .ok_or(GlError::InvalidEnum)?;
        let level = check_level(a.level)?;
        if a.border != 0 {
            return Err(GlError::InvalidOperation);
        }
        if info.image_size(a.w, a.h) != a.size as u32 {
            return Err(GlError::InvalidValue);
        }
        let max = (MAX_TEXTURE_SIZE >> level).max(1) as i64;
        let (w, h) = (a.w as i64, a.h as i64);
        let dims_ok =
            (0..=max).contains(&w) && (0..=max).contains(&h) && (t != Target::Cube || w == h);
        let (w, h) = (a.w.max(0) as usize, a.h.max(0) as usize);
        let header = |texels, blocks| Level {
            width: w,
            height: h,
            internal_format: a.internal,
            base: info.base(),
            storage: storage(&info),
            texels,
            blocks,
            floats: None,
        };
        if proxy {
            self.tex_object_mut(t, true).face_levels_mut(face)[level] =
                dims_ok.then(|| header(Vec::new().into(), None));
            return Ok(());
        }
        if !dims_ok {
            return Err(GlError::InvalidValue);
        }
        let blocks = data.map_or_else(|| vec![0; a.size as usize], |d| d.to_vec());
        let texels = compressed::decode(&info, w, h, &blocks);
        let obj = self.tex_object_mut(t, false);
        obj.stencil.remove(&(face, level));
        obj.face_levels_mut(face)[level] = Some(header(texels.into(), Some(blocks)));
        maybe_generate(obj, level);
        Ok(())
    }

    /// glCompressedTexSubImage{1,2,3}D (`dims`), with the client's blocks when they were
    /// readable and of the right size.
    pub(crate) fn compressed_tex_sub_image(
        &mut self,
        dims: u32,
        target: GLenum,
        a: &SubArgs,
        data: Option<&[u8]>,
    ) -> GlResult<()> {
        let (t, face) = sub_target(dims, target)?;
        let Some(info) = crate::context::pack::tex_format::compressed_info(a.format) else {
            return Err(if is_generic_compressed(a.format) {
                GlError::InvalidEnum
            } else {
                GlError::InvalidOperation
            });
        };
        let level = check_level(a.level)?;
        if info.image_size(a.w, a.h) != a.size as u32 {
            return Err(GlError::InvalidValue);
        }
        let img = self.tex_object(t, false).face_levels(face)[level]
            .as_ref()
            .ok_or(GlError::InvalidOperation)?;
        if img.internal_format != a.format {
            return Err(GlError::InvalidOperation);
        }
        let (iw, ih) = (img.width as i32, img.height as i32);
        check_sub_rect((iw, ih), (a.x, a.y, a.w, a.h))?;
        let Some(data) = data else { return Ok(()) };
        let rect = (a.x as usize, a.y as usize, a.w as usize, a.h as usize);
        let obj = self.tex_object_mut(t, false);
        let img = obj.face_levels_mut(face)[level].as_mut().expect("checked");
        let (w, h) = (img.width, img.height);
        compressed::write_rect(&info, (w, h), rect, data, &mut img.texels);
        if let Some(b) = img.blocks.as_mut() {
            compressed::replace_blocks(&info, w, rect, data, b);
        }
        maybe_generate(obj, level);
        Ok(())
    }

    /// glGetCompressedTexImage: the target and level are checked, then the image must exist
    /// (Mesa: a missing 1D/2D level has depth 0, GL_INVALID_VALUE) and be compressed; its
    /// blocks are returned for the C boundary to copy out.
    pub(crate) fn compressed_blocks(&self, target: GLenum, level: GLint) -> GlResult<&[u8]> {
        let (t, face) = match image_target(target)? {
            (t, false, face) => (t, face),
            _ => return Err(GlError::InvalidEnum),
        };
        let level = check_level(level)?;
        let Some(image) = self.tex_object(t, false).face_levels(face)[level].as_ref() else {
            return Err(match t {
                Target::Tex1D | Target::Tex2D => GlError::InvalidValue,
                _ => GlError::InvalidOperation,
            });
        };
        image.blocks.as_deref().ok_or(GlError::InvalidOperation)
    }
}
