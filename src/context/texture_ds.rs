//! The stencil half of packed depth-stencil textures (GL_EXT_packed_depth_stencil, GL 3.0):
//! GL_DEPTH_STENCIL / GL_DEPTH24_STENCIL8 images.
//!
//! Such an image is a depth image (`BaseFormat::Depth`, 24 depth bits in its texels, so
//! sampling and framebuffer attachment treat it as Z24); its stencil indices are kept
//! beside the levels in [`TextureObject::stencil`], because nothing samples them and
//! glGetTexImage(GL_DEPTH_STENCIL) must return them. Mesa 22.3 behaviour (measured):
//! - glTexImage/glTexSubImage with GL_DEPTH_STENCIL/GL_UNSIGNED_INT_24_8 data store both
//!   parts; the stencil goes through GL_INDEX_SHIFT/OFFSET and GL_MAP_STENCIL. With
//!   GL_DEPTH_COMPONENT data the stencil is undefined (Mesa leaves uninitialised memory);
//!   here it is 0, or unchanged by glTexSubImage.
//! - glCopyTexImage/glCopyTexSubImage copy the read framebuffer's stencil as well.
//! - glGetTexImage(GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8) returns `z24 << 8 | s` exactly.
//! - GL_DEPTH32F_STENCIL8 images (GL_ARB_depth_buffer_float) keep float depth texels the
//!   same way; their data may also be GL_FLOAT_32_UNSIGNED_INT_24_8_REV (docs/fbo-rules.md
//!   §7.4).

use super::texture_copy::each_fb_pixel;
use crate::context::pack::depth as shadow;
use crate::context::pack::tex::ClientFormat;
use crate::context::pixel_transfer::stencil_transfer;
use crate::context::state::PixelStore;
use crate::context::Context;
use crate::gl::types::*;
use crate::texture::TextureObject;
use libc::c_void;

/// The stencil indices of a client image for a depth-stencil image (zeros unless the
/// data is GL_DEPTH_STENCIL), with `c`'s stencil transfer.
///
/// # Safety
/// `data` (when not null) must hold the described image.
pub(crate) unsafe fn unpack_stencil(
    c: &Context,
    ps: &PixelStore,
    cf: &ClientFormat,
    (w, h): (usize, usize),
    data: *const c_void,
) -> Vec<u8> {
    let (tr, maps) = (&c.pixel_modes.transfer, &c.pixel_maps);
    let f = |s: u32| stencil_transfer(tr, maps, s as i64) as u8;
    // SAFETY: forwarded caller contract.
    unsafe { shadow::unpack_stencil(ps, cf, (w, h), data as *const u8, &f) }
}

/// Records the stencil of a new image of `internal` format at (`face`, `level`):
/// `stencil` for a depth-stencil image, nothing (and any old record dropped) otherwise.
pub(crate) fn set(
    obj: &mut TextureObject,
    (face, level): (usize, usize),
    internal: GLenum,
    stencil: Vec<u8>,
) {
    if shadow::is_depth_stencil(internal) {
        obj.stencil.insert((face, level), stencil);
    } else {
        obj.stencil.remove(&(face, level));
    }
}

/// Writes the `w x h` indices `src` at (`x`, `y`) of the stencil of image (`face`,
/// `level`), `iw x ih` texels (creating a zero stencil first if there is none).
pub(crate) fn update(
    obj: &mut TextureObject,
    (face, level): (usize, usize),
    (iw, ih): (usize, usize),
    (x, y, w, h): (usize, usize, usize, usize),
    src: &[u8],
) {
    let dst = obj.stencil.entry((face, level)).or_default();
    if dst.len() != iw * ih {
        *dst = vec![0; iw * ih];
    }
    for row in 0..h {
        let d = (y + row) * iw + x;
        dst[d..d + w].copy_from_slice(&src[row * w..(row + 1) * w]);
    }
}

/// A GL-window rectangle (y up) of the read framebuffer's stencil; 0 outside it or
/// without a stencil buffer.
pub(crate) fn read_fb_stencil(c: &Context, x: i32, y: i32, w: usize, h: usize) -> Vec<u8> {
    let mut out = vec![0u8; w * h];
    let Some(fb) = c.read_fb() else { return out };
    if fb.stencil.is_empty() {
        return out;
    }
    each_fb_pixel(fb, (x, y, w, h), |i, j| {
        out[i] = fb.stencil[j];
    });
    out
}

/// The depth texels glCopyTexImage/glCopyTexSubImage store into a depth-stencil image
/// when Mesa copies the buffer as is: a read framebuffer of the same format (24-bit depth
/// with stencil) and no GL_DEPTH_SCALE/BIAS (`st_CopyTexSubImage` then copies the region,
/// so the stored values are the buffer's; measured: the blit's float round trip would
/// raise some by one). `None`: the general path ([`read_texels`](super::texture_copy::read_texels)) applies.
pub(crate) fn read_fb_depth_exact(
    c: &Context,
    internal: GLenum,
    (x, y, w, h): (i32, i32, usize, usize),
) -> Option<Vec<[u8; 4]>> {
    let fb = c.read_fb()?;
    // The same format: a 24-bit depth-stencil image (GL_DEPTH32F_STENCIL8 stores floats,
    // which the general path converts to).
    let z24s8 = shadow::is_depth_stencil(internal)
        && internal != crate::gl::glext_enums::GL_DEPTH32F_STENCIL8;
    if !z24s8
        || fb.depth_format.bits() != 24
        || fb.stencil.is_empty()
        || c.pixel_modes.transfer.depth_scale_bias().is_some()
    {
        return None;
    }
    let mut out = vec![shadow::texel(0); w * h];
    each_fb_pixel(fb, (x, y, w, h), |i, j| {
        out[i] = shadow::texel(fb.depth_at(j));
    });
    Some(out)
}
