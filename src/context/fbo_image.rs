//! The attached images of a framebuffer object as the working copy sees them, and the
//! copies between them and the working copy ([`load`] on assembly, [`store`] on writing
//! back); see [`super::fbo_bind`].
//!
//! A renderbuffer buffer or depth texture level that is lent to the working copy
//! (`super::fbo_lend`) is empty in its owner meanwhile: the copies skip every image part
//! shorter than the rows they would touch, so a lent or missing buffer is never read or
//! written.

use super::fbo::{Attachment, FboState, RbFormat};
use crate::framebuffer::{ColorFormat, Framebuffer, WideKind};
use crate::texture::{BaseFormat, TextureState};

/// Mutable access to one attached image's values, rows bottom-up with `width` per row.
pub(super) enum ImageMut<'a> {
    /// RGBA8 colour (texture texels or renderbuffer colour), and the base format.
    Color(&'a mut [[u8; 4]], BaseFormat),
    /// Depth texels: the value as a little-endian u32 in each RGBA8 slot.
    DepthTexels(&'a mut [[u8; 4]]),
    /// Renderbuffer depth and (possibly empty) stencil.
    DepthStencil(&'a mut [u32], &'a mut [u8]),
    /// Renderbuffer stencil.
    Stencil(&'a mut [u8]),
    /// Wide renderbuffer colour ([`RbFormat::Wide`]).
    Wide(&'a mut [[f32; 4]]),
    /// A float or 16-bit texture image: its float values (as sampled, after the base
    /// swizzle), its unorm8 texels, its base format and the precision it renders at.
    WideTexels(&'a mut [[f32; 4]], &'a mut [[u8; 4]], BaseFormat, WideKind),
}

/// Sample plane `plane` of a wide renderbuffer's values (`v` itself when it has no
/// planes).
fn plane_of<T>(v: &mut [T], n: usize, samples: u32, plane: usize) -> &mut [T] {
    if samples == 0 || v.is_empty() {
        v
    } else {
        v.get_mut(plane * n..(plane + 1) * n).unwrap_or_default()
    }
}

/// Plane `p` of per-plane buffers, or an empty slice when there is no such buffer.
fn plane_buf<T: crate::memory::Plain>(v: &mut [crate::memory::HugeBuf<T>], p: usize) -> &mut [T] {
    v.get_mut(p).map_or(&mut [], |b| &mut b[..])
}

/// The image `a` names (sample plane `plane` of a multisample renderbuffer), with its row
/// width, for reading and writing.
pub(super) fn image_mut<'a>(
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
            let p = if ns == 0 { 0 } else { plane };
            let img = match rb.format? {
                RbFormat::Wide(..) => ImageMut::Wide(plane_of(&mut rb.wide, n, ns, plane)),
                RbFormat::Depth(_) | RbFormat::DepthStencil(_) => ImageMut::DepthStencil(
                    plane_buf(&mut rb.depth, p),
                    plane_buf(&mut rb.stencil, p),
                ),
                RbFormat::Stencil8 => ImageMut::Stencil(plane_buf(&mut rb.stencil, p)),
                RbFormat::Rgb8 | RbFormat::Srgb(false) => {
                    ImageMut::Color(plane_buf(&mut rb.color, p), BaseFormat::Rgb)
                }
                RbFormat::Legacy(b) => ImageMut::Color(plane_buf(&mut rb.color, p), b),
                RbFormat::Rgba8 | RbFormat::Srgb(true) => {
                    ImageMut::Color(plane_buf(&mut rb.color, p), BaseFormat::Rgba)
                }
            };
            Some((img, w))
        }
        Attachment::Texture(t) => {
            let img = t.find_mut(textures)?;
            let (w, h) = (img.width, img.height);
            let start = t.layer * w * h;
            let wide = super::fbo::texture_wide_kind(&img.storage);
            let texels = img.texels.get_mut(start..start + w * h)?;
            if let (Some(k), Some(f)) = (wide, img.floats.as_mut()) {
                let floats = f.get_mut(start..start + w * h)?;
                return Some((ImageMut::WideTexels(floats, texels, img.base, k), w));
            }
            let v = match img.base {
                BaseFormat::Depth => ImageMut::DepthTexels(texels),
                b => ImageMut::Color(texels, b),
            };
            Some((v, w))
        }
    }
}

/// A float texel of an image rendered at precision `k` as the wide plane keeps it (a
/// 16-bit unorm texel `u·f32(1/65535)` back to its integer `u`).
fn texel_to_wide(k: WideKind, v: [f32; 4]) -> [f32; 4] {
    match k {
        WideKind::Unorm16 => v.map(|c| (c * 65535.0).round()),
        _ => v,
    }
}

/// Whether an image part of `len` values, `iw` per row, holds the `w × h` region the
/// working copy covers (a lent renderbuffer buffer is empty: it does not).
fn covers(len: usize, iw: usize, w: usize, h: usize) -> bool {
    h == 0 || w == 0 || len >= (h - 1) * iw + w
}

/// Copies image `img` (rows bottom-up, `iw` wide) into the working copy `fb`. `stencil`
/// says the attachment is the stencil attachment (a depth-stencil image fills both).
pub(super) fn load(fb: &mut Framebuffer, img: ImageMut<'_>, iw: usize, stencil: bool) {
    let (w, h) = (fb.width, fb.height);
    let ok = |len: usize| covers(len, iw, w, h);
    let n = w * h;
    for y in 0..h {
        let (src, dst) = (y * iw, fb.row(y) * w);
        match &img {
            ImageMut::Color(px, _) if ok(px.len()) && fb.color.len() >= n => {
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
            ImageMut::DepthTexels(px) if !stencil && ok(px.len()) && fb.depth.len() >= n => {
                for x in 0..w {
                    fb.depth[dst + x] = u32::from_le_bytes(px[src + x]);
                }
            }
            ImageMut::Wide(px) if ok(px.len()) && fb.color.len() >= n => {
                if let Some(k) = fb.wide {
                    for x in 0..w {
                        let v = px[src + x];
                        fb.wide_color[dst + x] = v;
                        fb.color[dst + x] = k.mirror(v);
                    }
                }
            }
            ImageMut::WideTexels(f, _, _, k)
                if fb.wide == Some(*k) && ok(f.len()) && fb.color.len() >= n =>
            {
                for x in 0..w {
                    let v = texel_to_wide(*k, f[src + x]);
                    fb.wide_color[dst + x] = v;
                    fb.color[dst + x] = k.mirror(v);
                }
            }
            ImageMut::DepthStencil(d, s) => {
                if !stencil && ok(d.len()) && fb.depth.len() >= n {
                    fb.depth[dst..dst + w].copy_from_slice(&d[src..src + w]);
                }
                if stencil && ok(s.len()) && fb.stencil.len() >= n {
                    fb.stencil[dst..dst + w].copy_from_slice(&s[src..src + w]);
                }
            }
            ImageMut::Stencil(s) if stencil && ok(s.len()) && fb.stencil.len() >= n => {
                fb.stencil[dst..dst + w].copy_from_slice(&s[src..src + w]);
            }
            _ => {}
        }
    }
}

/// Pixels from which a depth texture's write-back is shared by the thread pool. A whole
/// depth level of the working copy's size is lent instead (`super::fbo_lend`: MuJoCo's
/// shadow maps); this is for the others, such as a map larger than the object's other
/// attachments, which 16 MB of write-back would keep on one thread.
const PAR_STORE: usize = 1 << 20;

/// [`store`] of the working copy's depth into depth texels `px` (`iw` per row, covering
/// the working copy): the bottom half of the rows on this thread, the top half on the
/// draw pool's ([`crate::raster::batch::fork2_split`]).
fn store_depth_par(fb: &Framebuffer, px: &mut [[u8; 4]], iw: usize) {
    let (w, h) = (fb.width, fb.height);
    let mid = h / 2;
    crate::raster::batch::fork2_split(px, mid * iw, |k, dst| {
        let (rows, first) = if k == 0 { (0..mid, 0) } else { (mid..h, mid) };
        for y in rows {
            let src = &fb.depth[fb.row(y) * w..][..w];
            let at = (y - first) * iw;
            let Some(d) = dst.get_mut(at..at + w) else {
                return;
            };
            for (d, v) in d.iter_mut().zip(src) {
                *d = v.to_le_bytes();
            }
        }
    });
}

/// Writes the working copy `fb` back into image `img` (the inverse of [`load`]); colour
/// is stored as the image's base format keeps it.
pub(super) fn store(fb: &Framebuffer, img: ImageMut<'_>, iw: usize, stencil: bool) {
    let (w, h) = (fb.width, fb.height);
    let ok = |len: usize| covers(len, iw, w, h);
    let n = w * h;
    let mut img = img;
    if let ImageMut::DepthTexels(px) = &mut img {
        if !stencil && n >= PAR_STORE && w > 0 && iw >= w && ok(px.len()) && fb.depth.len() >= n {
            store_depth_par(fb, px, iw);
            return;
        }
    }
    for y in 0..h {
        let (dst, src) = (y * iw, fb.row(y) * w);
        match &mut img {
            ImageMut::Color(px, base) if ok(px.len()) && fb.color.len() >= n => {
                for x in 0..w {
                    px[dst + x] = base.swizzle(fb.color[src + x], 0, 255);
                }
            }
            ImageMut::DepthTexels(px) if !stencil && ok(px.len()) && fb.depth.len() >= n => {
                for x in 0..w {
                    px[dst + x] = fb.depth[src + x].to_le_bytes();
                }
            }
            ImageMut::Wide(px) if fb.wide.is_some() && ok(px.len()) && fb.color.len() >= n => {
                for x in 0..w {
                    px[dst + x] = fb.wide_at(src + x);
                }
            }
            ImageMut::WideTexels(f, t, base, k)
                if fb.wide == Some(*k) && ok(f.len()) && ok(t.len()) && fb.color.len() >= n =>
            {
                for x in 0..w {
                    let v = base.swizzle(fb.wide_at(src + x).map(|c| k.to_float(c)), 0.0, 1.0);
                    f[dst + x] = v;
                    t[dst + x] = crate::texture::float::to_bytes(v);
                }
            }
            ImageMut::DepthStencil(d, s) => {
                if !stencil && ok(d.len()) && fb.depth.len() >= n {
                    d[dst..dst + w].copy_from_slice(&fb.depth[src..src + w]);
                }
                if stencil && ok(s.len()) && fb.stencil.len() >= n {
                    s[dst..dst + w].copy_from_slice(&fb.stencil[src..src + w]);
                }
            }
            ImageMut::Stencil(s) if stencil && ok(s.len()) && fb.stencil.len() >= n => {
                s[dst..dst + w].copy_from_slice(&fb.stencil[src..src + w]);
            }
            _ => {}
        }
    }
}
