//! glCopyTexImage and glCopyTexSubImage (GL 1.5 §3.8.2): reading the read framebuffer's
//! colours or depth as texels, with pixel transfer as Mesa's CPU copy applies it.

use super::texture_spec::{
    check_level, image_size, maybe_generate, new_level, non_negative, resolve_internal, storage_of,
    store_level, sub_image_target,
};
use super::{Context, GlError, GlResult};
use crate::context::pack::depth as shadow;
use crate::context::pack::tex as upload;
use crate::framebuffer::Framebuffer;
use crate::gl::types::*;
use crate::texture::{BaseFormat, Storage};

/// Calls `f(i, j)` for each pixel of the GL-window rectangle `(x, y, w, h)` (y up) that
/// lies inside `fb`: `i` is its index in the row-major `w`-wide rectangle, `j` its index in
/// the framebuffer's planes.
pub(crate) fn each_fb_pixel(
    fb: &Framebuffer,
    (x, y, w, h): (i32, i32, usize, usize),
    mut f: impl FnMut(usize, usize),
) {
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
            f(row * w + col, fy * fb.width + gx as usize);
        }
    }
}

/// Reads a GL-window rectangle (y up) of the framebuffer as RGBA8; outside pixels are 0.
pub(crate) fn read_fb(c: &Context, x: i32, y: i32, w: usize, h: usize) -> Vec<[u8; 4]> {
    let mut out = vec![[0u8; 4]; w * h];
    let Some(fb) = c.read_fb() else { return out };
    each_fb_pixel(fb, (x, y, w, h), |i, j| {
        out[i] = fb.color_at(j);
    });
    out
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
    each_fb_pixel(fb, (x, y, w, h), |i, j| {
        let z = fb.depth_at(j);
        let z = match scale_bias {
            Some(sb) => shadow::convert_scaled(z, fb_bits, storage.depth_bits(), sb),
            None => shadow::convert(z, fb_bits, storage.depth_bits()),
        };
        out[i] = shadow::texel(z);
    });
    Ok(out)
}

/// A framebuffer rectangle of a wide read buffer (16-bit or float colour) as the float
/// values of an image of `storage` (one that keeps floats), or `None` when the read
/// buffer is 8-bit, the image keeps no floats or pixel transfer is active (the CPU copy).
///
/// Mesa copies these with `pipe->blit` (`st_CopyTexSubImage`): the source texel as the
/// sampler returns it, unclamped, stored with the texture format's shader output
/// conversion (half floats toward zero, unorm16 `c·(65535/65536) + 128`); outside pixels
/// are 0.
pub(crate) fn read_wide_texels(
    c: &Context,
    (x, y, w, h): (GLint, GLint, usize, usize),
    base: BaseFormat,
    storage: &Storage,
) -> Option<Vec<[f32; 4]>> {
    let fb = c.read_fb().filter(|f| f.wide.is_some())?;
    let active = upload::ColorTransfer::active(&c.pixel_modes.transfer, &c.pixel_maps);
    if base == BaseFormat::Depth || !storage.has_floats() || active.is_some() {
        return None;
    }
    let store = |v: [f32; 4]| match storage.encoding {
        crate::texture::Encoding::Unorm16 => {
            v.map(|x| crate::framebuffer::wide::unorm16(x) as f32 * (1.0f32 / 65535.0))
        }
        _ => crate::texture::float::quantise(storage, v),
    };
    let mut out = vec![[0.0f32; 4]; w * h];
    each_fb_pixel(fb, (x, y, w, h), |i, j| {
        out[i] = base.swizzle(store(fb.float_at(j)), 0.0, 1.0);
    });
    Some(out)
}

impl Context {
    /// glCopyTexImage1D/2D (`dims`): a read-framebuffer rectangle becomes a new level.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn copy_tex_image(
        &mut self,
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
        let (t, face) = sub_image_target(target, dims)?;
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
        self.prepare_read()?;
        let exact = super::texture_ds::read_fb_depth_exact(self, internal, (sx, sy, tw, th));
        let wide = read_wide_texels(self, (sx, sy, tw, th), base, &storage);
        let texels = match (exact, &wide) {
            (Some(t), _) => t,
            (None, Some(f)) => f
                .iter()
                .map(|&v| crate::texture::float::to_bytes(v))
                .collect(),
            (None, None) => read_texels(self, (sx, sy, tw, th), base, &storage)?,
        };
        let stencil = match shadow::is_depth_stencil(internal) {
            true => super::texture_ds::read_fb_stencil(self, sx, sy, tw, th),
            false => Vec::new(),
        };
        let mut img = new_level(internal, (base, storage), (tw, th), texels);
        img.set_floats(wide);
        store_level(self.tex_object_mut(t, false), (face, level), img, stencil);
        Ok(())
    }

    /// glCopyTexSubImage1D/2D (`dims`): a read-framebuffer rectangle replaces part of a level.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn copy_tex_sub_image(
        &mut self,
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
        let (t, face) = sub_image_target(target, dims)?;
        let level = check_level(level)?;
        let (w, h) = (non_negative(w)?, non_negative(h)?);
        let (base, storage, internal) = self
            .tex_object(t, false)
            .face_levels(face)
            .get(level)
            .and_then(|l| l.as_ref())
            .map(|i| (i.base, i.storage, i.internal_format))
            .ok_or(GlError::InvalidOperation)?;
        self.prepare_read()?;
        let wide = read_wide_texels(self, (x, y, w, h), base, &storage);
        let src = match super::texture_ds::read_fb_depth_exact(self, internal, (x, y, w, h)) {
            Some(t) => t,
            None => read_texels(self, (x, y, w, h), base, &storage)?,
        };
        let stencil = shadow::is_depth_stencil(internal)
            .then(|| super::texture_ds::read_fb_stencil(self, x, y, w, h));
        let obj = self.tex_object_mut(t, false);
        let img = obj.face_levels_mut(face)[level]
            .as_mut()
            .ok_or(GlError::InvalidOperation)?;
        if xoff < 0 || yoff < 0 || xoff as usize + w > img.width || yoff as usize + h > img.height {
            return Err(GlError::InvalidValue);
        }
        for row in 0..h {
            let d = (yoff as usize + row) * img.width + xoff as usize;
            img.texels[d..d + w].copy_from_slice(&src[row * w..(row + 1) * w]);
            match &wide {
                Some(f) => img.write_floats(d, &f[row * w..(row + 1) * w]),
                None => img.refresh_floats(d, w),
            }
        }
        if let Some(s) = stencil {
            let (size, rect) = (
                (img.width, img.height),
                (xoff as usize, yoff as usize, w, h),
            );
            super::texture_ds::update(obj, (face, level), size, rect, &s);
        }
        maybe_generate(obj, level);
        Ok(())
    }
}
