//! How many bytes of client memory a texture image command reads: while a display list is
//! compiled, the C boundary copies exactly that many (GL 1.5 §5.4: the pixels are unpacked
//! from client memory when the command is compiled), and the compiled command reads the
//! copy with the unpack state of compile time.

use super::pack::tex::{ClientFormat, Layout};
use super::state::PixelStore;
use super::texture_3d::slice_store;
use crate::gl::enums::GL_COLOR_INDEX;
use crate::gl::types::*;
use crate::texture::{MAX_3D_TEXTURE_SIZE, MAX_TEXTURE_SIZE};

/// The bytes a `dims`-dimensional client image of `w x h x d` pixels in `format`/`ty`
/// spans under `unpack` (`d` is read for 3D images only). `None` when there is nothing to
/// copy: a negative or oversized extent (the command fails its checks when it runs), an
/// invalid format/type pair, or an empty 3D image.
pub(crate) fn image_span(
    dims: u8,
    (format, ty): (GLenum, GLenum),
    unpack: &PixelStore,
    (w, h, d): (GLsizei, GLsizei, GLsizei),
) -> Option<usize> {
    let (w, h) = (usize::try_from(w).ok()?, usize::try_from(h).ok()?);
    if dims == 3 {
        let d = usize::try_from(d).ok()?;
        let cf = ClientFormat::new(format, ty).ok()?;
        let lim = MAX_3D_TEXTURE_SIZE + 2;
        if w > lim || h > lim || d > lim || w == 0 || h == 0 || d == 0 {
            return None;
        }
        let last = slice_store(unpack, h, d - 1);
        return Some(Layout::new(&last, w, &cf).span(w, h));
    }
    // Larger images fail validation when the command runs: nothing to copy.
    if w > MAX_TEXTURE_SIZE + 2 || h > MAX_TEXTURE_SIZE + 2 {
        return None;
    }
    if format == GL_COLOR_INDEX {
        super::texture_ci::span(ty, unpack, w, h)
    } else {
        Some(Layout::new(unpack, w, &ClientFormat::new(format, ty).ok()?).span(w, h))
    }
}
