//! GL_COLOR_INDEX images for glTexImage and glTexSubImage. There are no colour-index
//! textures, but GL 1.x uploads index data (any index type, GL_BITMAP included) by turning
//! each index into RGBA through GL_INDEX_SHIFT/OFFSET and the GL_PIXEL_MAP_I_TO_* maps.
//! As Mesa's `texstore_rgba` does, the result is clamped to RGBA8 first and then stored
//! like GL_RGBA/GL_UNSIGNED_BYTE data, with no further pixel transfer.

use crate::context::error::GlResult;
use crate::context::pack::draw_image::Layout;
use crate::context::pack::tex::{self as upload, ClientFormat};
use crate::context::state::PixelStore;
use crate::context::Context;
use crate::framebuffer::float_to_ubyte;
use crate::gl::enums::{GL_COLOR_INDEX, GL_RGBA, GL_UNSIGNED_BYTE};
use crate::pixels::image::Pixels;
use crate::texture::{BaseFormat, Storage};
use std::ffi::c_void;

/// The client format a glTexImage/glTexSubImage of `format`/`ty` is stored as: for
/// GL_COLOR_INDEX, after Mesa's checks of the pair (GL_BITMAP allowed, a packed type
/// GL_INVALID_OPERATION), RGBA8; any other format as [`ClientFormat::new`] sees it.
pub(crate) fn client_format(format: u32, ty: u32) -> GlResult<ClientFormat> {
    if format == GL_COLOR_INDEX {
        Layout::new(format, ty)?;
        ClientFormat::new(GL_RGBA, GL_UNSIGNED_BYTE)
    } else {
        ClientFormat::new(format, ty)
    }
}

/// The bytes a display list must copy for a `w` x `h` GL_COLOR_INDEX image of type `ty`
/// under `ps`; `None` for a type the index format does not take.
pub(crate) fn span(ty: u32, ps: &PixelStore, w: usize, h: usize) -> Option<usize> {
    Some(Layout::new(GL_COLOR_INDEX, ty).ok()?.span(ps, w, h))
}

/// The texels of a `w` x `h` GL_COLOR_INDEX image of type `ty` (validated by
/// [`client_format`]) at `data` under `ps`, stored as `base`.
///
/// # Safety
/// `data` must be null or hold the described image.
pub(crate) unsafe fn unpack(
    c: &Context,
    ps: &PixelStore,
    ty: u32,
    (base, storage): (BaseFormat, Storage),
    (w, h): (usize, usize),
    data: *const c_void,
) -> Vec<[u8; 4]> {
    let decoded = Layout::new(GL_COLOR_INDEX, ty)
        .ok()
        // SAFETY: forwarded caller contract.
        .and_then(|l| unsafe { l.decode(ps, w, h, data as *const u8) });
    let rgba: Option<Vec<u8>> = decoded.and_then(|img| match img.pixels {
        Pixels::Index(ix) => Some(
            ix.iter()
                .flat_map(|&i| crate::context::pixel_ops::index_to_rgba(c, i).map(float_to_ubyte))
                .collect(),
        ),
        _ => None,
    });
    let cf = ClientFormat::new(GL_RGBA, GL_UNSIGNED_BYTE).expect("RGBA8 is a client format");
    let tight = PixelStore::default();
    let ptr = rgba.as_ref().map_or(std::ptr::null(), |v| v.as_ptr());
    // SAFETY: `ptr` is null or holds w*h tightly packed RGBA8 pixels (rows of 4·w bytes
    // meet the default 4-byte alignment).
    unsafe { upload::unpack_transfer(&tight, &cf, (base, storage), w, h, ptr, None) }
}
