//! GL_TEXTURE_3D images (GL 1.2, GL_EXT_texture3D): glTexImage3D, glTexSubImage3D,
//! glCopyTexSubImage3D and the packing of 3D levels for glGetTexImage. A 3D image is
//! unpacked slice by slice: slice z starts `(SKIP_IMAGES + z)·IMAGE_HEIGHT` rows after the
//! first (IMAGE_HEIGHT 0 = the height), GL 1.5 §3.8.1. Borders are stripped as for 1D/2D
//! images.

use super::state::PixelStore;
use super::texture_copy::read_texels;
use super::texture_spec::{
    check_level, image_target, level_format, maybe_generate, new_level, non_negative, skip_border,
    unpack_rect,
};
use super::{Context, GlError, GlResult};
use crate::context::pack::tex::{self as upload, ClientFormat};
use crate::gl::types::*;
use crate::texture::{BaseFormat, Level, Storage, Target, MAX_3D_LEVELS, MAX_3D_TEXTURE_SIZE};
use std::ffi::c_void;

/// The unpack state of slice `z` of a 3D client image of `h` rows per image.
pub(crate) fn slice_store(ps: &PixelStore, h: usize, z: usize) -> PixelStore {
    let rows = if ps.image_height > 0 {
        ps.image_height as usize
    } else {
        h
    };
    let mut s = *ps;
    s.skip_rows += ((ps.skip_images.max(0) as usize + z) * rows) as i32;
    s.skip_images = 0;
    s
}

/// Unpacks a `w x h x d` client image into slice-major texels.
///
/// # Safety
/// `data` (when not null) must hold the described image.
#[allow(clippy::too_many_arguments)]
unsafe fn unpack_3d(
    c: &Context,
    ps: &PixelStore,
    cf: &ClientFormat,
    (base, storage): (BaseFormat, Storage),
    (w, h, d): (usize, usize, usize),
    data: *const c_void,
) -> (Vec<[u8; 4]>, Option<Vec<[f32; 4]>>) {
    let mut out = Vec::with_capacity(w * h * d);
    let mut floats = storage.has_floats().then(|| Vec::with_capacity(w * h * d));
    for z in 0..d {
        let s = slice_store(ps, h, z);
        // SAFETY: forwarded caller contract (slice z lies inside the image).
        let (t, f) = unsafe { unpack_rect(c, &s, (cf, 0, 0), (base, storage), (w, h), data) };
        out.extend(t);
        if let (Some(all), Some(f)) = (&mut floats, f) {
            all.extend(f);
        }
    }
    (out, floats)
}

/// Packs every slice of a 3D level for glGetTexImage.
///
/// # Safety
/// `dst` must be writable for the packed image.
pub(crate) unsafe fn pack_3d(
    ps: &PixelStore,
    cf: &ClientFormat,
    img: &Level,
    d: usize,
    dst: *mut c_void,
) {
    if dst.is_null() {
        return;
    }
    let n = img.width * img.height;
    for z in 0..d {
        let texels = img.texels[z * n..(z + 1) * n].to_vec();
        let mut slice = new_level(
            img.internal_format,
            (img.base, img.storage),
            (img.width, img.height),
            texels,
        );
        slice.floats = img.floats.as_ref().map(|f| f[z * n..(z + 1) * n].to_vec());
        let s = slice_store(ps, img.height, z);
        // SAFETY: forwarded caller contract.
        unsafe { upload::pack(&s, cf, &slice, dst as *mut u8) };
    }
}

/// Validated 3D sizes after border stripping.
fn size_3d(
    level: usize,
    w: GLsizei,
    h: GLsizei,
    d: GLsizei,
    border: GLint,
) -> GlResult<(usize, usize, usize)> {
    if border != 0 && border != 1 {
        return Err(GlError::InvalidValue);
    }
    let (w, h, d) = (non_negative(w)?, non_negative(h)?, non_negative(d)?);
    let b = 2 * border as usize;
    if w < b || h < b || d < b || level >= MAX_3D_LEVELS {
        return Err(GlError::InvalidValue);
    }
    let max = (MAX_3D_TEXTURE_SIZE >> level).max(1);
    let (w, h, d) = (w - b, h - b, d - b);
    if w > max || h > max || d > max {
        return Err(GlError::InvalidValue);
    }
    // llvmpipe refuses resources over 1 GiB (LP_MAX_TEXTURE_SIZE): GL_OUT_OF_MEMORY, and a
    // proxy that does not fit
    if w * h * d * 4 > 1 << 30 {
        return Err(GlError::OutOfMemory);
    }
    Ok((w, h, d))
}

impl Context {
    /// glTexImage3D and its proxy, in Mesa's error order.
    ///
    /// # Safety
    /// `data` (when not null) must hold the described image under `unpack`.
    #[allow(clippy::too_many_arguments)]
    pub(crate) unsafe fn tex_image_3d(
        &mut self,
        target: GLenum,
        level: GLint,
        (internal, w, h, d, border): (GLint, GLsizei, GLsizei, GLsizei, GLint),
        (format, ty): (GLenum, GLenum),
        data: *const c_void,
        unpack: PixelStore,
    ) -> GlResult<()> {
        let (t, proxy, _) = image_target(target)?;
        if t != Target::Tex3D {
            return Err(GlError::InvalidEnum);
        }
        // As glTexImage2D (and Mesa): a bad level, border or negative size is an error for
        // a proxy too, and comes before the format and type checks.
        let level = check_level(level)?;
        if level >= MAX_3D_LEVELS || !(0..=1).contains(&border) || w < 0 || h < 0 || d < 0 {
            return Err(GlError::InvalidValue);
        }
        let cf = ClientFormat::new(format, ty)?;
        let (internal, texel) = level_format(internal, t, (format, ty))?;
        // Mesa: no 3D depth textures; depth data for a colour image is an error too
        if cf.is_depth() || texel.0 == BaseFormat::Depth {
            return Err(GlError::InvalidOperation);
        }
        let size = size_3d(level, w, h, d, border);
        if proxy {
            let obj = self.tex_object_mut(t, true);
            (obj.levels[level], obj.depths[level]) = match size {
                Ok((w, h, d)) => (Some(new_level(internal, texel, (w, h), Vec::new())), d),
                Err(_) => (None, 0),
            };
            return Ok(());
        }
        let (tw, th, td) = size?;
        let ps = match border {
            1 => skip_border(unpack, (tw, th), true, true),
            _ => unpack,
        };
        // SAFETY: forwarded caller contract.
        let (texels, floats) = unsafe { unpack_3d(self, &ps, &cf, texel, (tw, th, td), data) };
        let obj = self.tex_object_mut(t, false);
        let mut img = new_level(internal, texel, (tw, th), texels);
        img.floats = floats;
        obj.levels[level] = Some(img);
        obj.depths[level] = td;
        maybe_generate(obj, level);
        Ok(())
    }

    /// glTexSubImage3D.
    ///
    /// # Safety
    /// `data` must hold the described image under `unpack`.
    #[allow(clippy::too_many_arguments)]
    pub(crate) unsafe fn tex_sub_image_3d(
        &mut self,
        target: GLenum,
        level: GLint,
        off: [GLint; 3],
        (w, h, d): (GLsizei, GLsizei, GLsizei),
        (format, ty): (GLenum, GLenum),
        data: *const c_void,
        unpack: PixelStore,
    ) -> GlResult<()> {
        if !matches!(image_target(target)?, (Target::Tex3D, false, _)) {
            return Err(GlError::InvalidEnum);
        }
        let cf = ClientFormat::new(format, ty)?;
        if cf.is_depth() {
            return Err(GlError::InvalidOperation);
        }
        let level = check_level(level)?;
        let (w, h, d) = (non_negative(w)?, non_negative(h)?, non_negative(d)?);
        self.prepare_read()?;
        let img = self.sub_box_3d(level, off, (w, h, d))?;
        let format = (img.base, img.storage);
        // SAFETY: forwarded caller contract.
        let (texels, floats) = unsafe { unpack_3d(self, &unpack, &cf, format, (w, h, d), data) };
        let obj = self.tex_object_mut(Target::Tex3D, false);
        let img = obj.levels[level]
            .as_mut()
            .ok_or(GlError::InvalidOperation)?;
        let [x0, y0, z0] = off.map(|o| o as usize);
        for z in 0..d {
            for y in 0..h {
                let dst = ((z0 + z) * img.height + y0 + y) * img.width + x0;
                let src = (z * h + y) * w;
                img.texels[dst..dst + w].copy_from_slice(&texels[src..src + w]);
                if let Some(f) = &floats {
                    img.write_floats(dst, &f[src..src + w]);
                }
            }
        }
        maybe_generate(obj, level);
        Ok(())
    }

    /// The 3D level a sub-image command writes, after checking that the `w x h x d` box at
    /// `off` lies inside it (GL_INVALID_OPERATION without the level, GL_INVALID_VALUE
    /// outside it).
    fn sub_box_3d(
        &self,
        level: usize,
        off: [GLint; 3],
        (w, h, d): (usize, usize, usize),
    ) -> GlResult<&Level> {
        let obj = self.tex_object(Target::Tex3D, false);
        let depth = obj.depths[level];
        let img = obj.levels[level]
            .as_ref()
            .ok_or(GlError::InvalidOperation)?;
        let fits = |o: GLint, n: usize, size: usize| o >= 0 && o as usize + n <= size;
        if !(fits(off[0], w, img.width) && fits(off[1], h, img.height) && fits(off[2], d, depth)) {
            return Err(GlError::InvalidValue);
        }
        Ok(img)
    }

    /// glCopyTexSubImage3D: a framebuffer rectangle into slice `zoff`.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn copy_tex_sub_image_3d(
        &mut self,
        target: GLenum,
        level: GLint,
        off: [GLint; 3],
        (x, y): (GLint, GLint),
        (w, h): (GLsizei, GLsizei),
    ) -> GlResult<()> {
        if !matches!(image_target(target)?, (Target::Tex3D, false, _)) {
            return Err(GlError::InvalidEnum);
        }
        let level = check_level(level)?;
        let (w, h) = (non_negative(w)?, non_negative(h)?);
        let img = self.sub_box_3d(level, off, (w, h, 1))?;
        let src = read_texels(self, (x, y, w, h), img.base, &img.storage)?;
        let obj = self.tex_object_mut(Target::Tex3D, false);
        let img = obj.levels[level]
            .as_mut()
            .ok_or(GlError::InvalidOperation)?;
        let [x0, y0, z0] = off.map(|o| o as usize);
        for row in 0..h {
            let dst = ((z0 * img.height) + y0 + row) * img.width + x0;
            img.texels[dst..dst + w].copy_from_slice(&src[row * w..(row + 1) * w]);
            img.refresh_floats(dst, w);
        }
        maybe_generate(obj, level);
        Ok(())
    }
}
