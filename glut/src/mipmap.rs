//! GLU's image calls: gluScaleImage, gluBuild1D/2D/3DMipmaps and
//! gluBuild1D/2D/3DMipmapLevels.
//!
//! Images are read under the unpack parameters into f64 components (in their type's
//! own scale). The `Mipmaps` calls first scale an image to the nearest powers of two
//! (a dimension whose two leading bits are both set rounds up: 6 → 8, 5 → 4, as SGI's
//! GLU does) within the GL's maximum size; every smaller level halves each dimension
//! above 1 (rounding down), averaging the 2, 4 or 8 texels 2i, 2i+1 of the level
//! above (a last odd row or column is dropped), integer types rounded half up. The
//! `MipmapLevels` calls take the image as level `level` as it is (a size that is not
//! a power of two counts as having no levels) and load levels `base` to `max`.

#![allow(non_snake_case)]

use crate::gl::{self, GLenum, GLint, GLsizei};
use std::ffi::{c_int, c_void};

const GLU_INVALID_ENUM: c_int = 100900;
const GLU_INVALID_VALUE: c_int = 100901;
const GL_MAX_3D_TEXTURE_SIZE: GLenum = 0x8073;
const GL_UNPACK_SKIP_IMAGES: GLenum = 0x806D;
const GL_UNPACK_IMAGE_HEIGHT: GLenum = 0x806E;

extern "C" {
    fn glTexImage3D(
        target: GLenum,
        level: GLint,
        internal: GLint,
        width: GLsizei,
        height: GLsizei,
        depth: GLsizei,
        border: GLint,
        format: GLenum,
        ty: GLenum,
        pixels: *const c_void,
    );
}

/// Components per pixel of a client format, None when GLU does not know it.
fn components(format: GLenum) -> Option<usize> {
    Some(match format {
        0x1903..=0x1906 | 0x1909 | 0x1901 => 1, // RED..ALPHA, LUMINANCE, STENCIL_INDEX
        0x1902 => 1,                            // DEPTH_COMPONENT
        0x190A => 2,                            // LUMINANCE_ALPHA
        0x1907 | 0x80E0 => 3,                   // RGB, BGR
        0x1908 | 0x80E1 => 4,                   // RGBA, BGRA
        _ => return None,
    })
}

/// Bytes per component of a supported type.
fn type_size(ty: GLenum) -> Option<usize> {
    match ty {
        gl::GL_UNSIGNED_BYTE | gl::GL_BYTE => Some(1),
        gl::GL_SHORT | gl::GL_UNSIGNED_SHORT => Some(2),
        gl::GL_INT | gl::GL_UNSIGNED_INT | gl::GL_FLOAT => Some(4),
        _ => None,
    }
}

/// Reads one component as f64 in the type's own scale.
///
/// # Safety
/// `p` must point to a readable value of type `ty`.
unsafe fn read_comp(p: *const u8, ty: GLenum) -> f64 {
    // SAFETY: the caller guarantees p points to a value of `ty` (unaligned reads).
    unsafe {
        match ty {
            gl::GL_BYTE => f64::from(p.cast::<i8>().read()),
            gl::GL_UNSIGNED_SHORT => f64::from(p.cast::<u16>().read_unaligned()),
            gl::GL_SHORT => f64::from(p.cast::<i16>().read_unaligned()),
            gl::GL_UNSIGNED_INT => f64::from(p.cast::<u32>().read_unaligned()),
            gl::GL_INT => f64::from(p.cast::<i32>().read_unaligned()),
            gl::GL_FLOAT => f64::from(p.cast::<f32>().read_unaligned()),
            _ => f64::from(p.read()),
        }
    }
}

/// Converts an f64 in the type's scale back (clamped for integer types; the value is
/// already whole for them).
fn to_bytes(v: f64, ty: GLenum) -> Vec<u8> {
    match ty {
        gl::GL_BYTE => vec![v.clamp(-128.0, 127.0) as i8 as u8],
        gl::GL_UNSIGNED_SHORT => (v.clamp(0.0, 65535.0) as u16).to_ne_bytes().to_vec(),
        gl::GL_SHORT => (v.clamp(-32768.0, 32767.0) as i16).to_ne_bytes().to_vec(),
        gl::GL_UNSIGNED_INT => (v.clamp(0.0, u32::MAX as f64) as u32)
            .to_ne_bytes()
            .to_vec(),
        gl::GL_INT => (v.clamp(i32::MIN as f64, i32::MAX as f64) as i32)
            .to_ne_bytes()
            .to_vec(),
        gl::GL_FLOAT => (v as f32).to_ne_bytes().to_vec(),
        _ => vec![v.clamp(0.0, 255.0) as u8],
    }
}

/// An image as f64 components, tightly packed, in its type's scale.
#[derive(Clone, Debug, PartialEq)]
struct Img {
    w: usize,
    h: usize,
    d: usize,
    n: usize,
    data: Vec<f64>,
}

/// Byte offset of each row under pixel-store parameters.
fn row_stride(ps: &gl::PixelStore, w: usize, n: usize, size: usize) -> usize {
    let len = if ps.row_length > 0 {
        ps.row_length as usize
    } else {
        w
    };
    let bytes = len * n * size;
    let a = ps.alignment.max(1) as usize;
    if size >= a {
        bytes
    } else {
        bytes.div_ceil(a) * a
    }
}

/// Reads a client image (w x h x d) under the current unpack parameters.
fn read_image(data: *const c_void, w: usize, h: usize, d: usize, n: usize, ty: GLenum) -> Img {
    let size = type_size(ty).unwrap_or(1);
    let ps = gl::PixelStore::unpack();
    let stride = row_stride(&ps, w, n, size);
    let (image_height, skip_images) = if d > 1 {
        (
            gl::get_int(GL_UNPACK_IMAGE_HEIGHT).max(0) as usize,
            gl::get_int(GL_UNPACK_SKIP_IMAGES).max(0) as usize,
        )
    } else {
        (0, 0)
    };
    let slice = stride * if image_height > 0 { image_height } else { h };
    let skip = skip_images * slice
        + ps.skip_rows.max(0) as usize * stride
        + ps.skip_pixels.max(0) as usize * n * size;
    let mut out = Vec::with_capacity(w * h * d * n);
    for z in 0..d {
        for y in 0..h {
            for x in 0..w * n {
                let at = skip + z * slice + y * stride + x * size;
                // SAFETY: GLU's contract: data holds the image described by the sizes,
                // format, type and the unpack parameters; the offset stays inside it.
                out.push(unsafe { read_comp(data.cast::<u8>().add(at), ty) });
            }
        }
    }
    Img {
        w,
        h,
        d,
        n,
        data: out,
    }
}

/// Writes a 2D image under the current pack parameters.
fn write_image(img: &Img, out: *mut c_void, ty: GLenum) {
    let size = type_size(ty).unwrap_or(1);
    let ps = gl::PixelStore::pack();
    let stride = row_stride(&ps, img.w, img.n, size);
    let skip =
        ps.skip_rows.max(0) as usize * stride + ps.skip_pixels.max(0) as usize * img.n * size;
    for y in 0..img.h {
        for x in 0..img.w * img.n {
            let bytes = to_bytes(img.data[y * img.w * img.n + x], ty);
            // SAFETY: GLU's contract: out has room for the image under the pack
            // parameters; the offset stays inside it.
            unsafe {
                std::ptr::copy_nonoverlapping(
                    bytes.as_ptr(),
                    out.cast::<u8>().add(skip + y * stride + x * size),
                    bytes.len(),
                )
            };
        }
    }
}

/// Box-filter weights: for each output index, (first input index, weights).
fn box_weights(n_in: usize, n_out: usize) -> Vec<(usize, Vec<f64>)> {
    let ratio = n_in as f64 / n_out as f64;
    (0..n_out)
        .map(|o| {
            let (a, b) = (o as f64 * ratio, (o + 1) as f64 * ratio);
            let first = a.floor() as usize;
            let last = (b.ceil() as usize).min(n_in).max(first + 1);
            let ws = (first..last)
                .map(|i| {
                    let lo = a.max(i as f64);
                    let hi = b.min(i as f64 + 1.0);
                    (hi - lo).max(0.0) / (b - a)
                })
                .collect();
            (first, ws)
        })
        .collect()
}

/// Scales an image with an area-weighted box filter (separable, in all three
/// dimensions); integer types are truncated as SGI's GLU truncates.
fn scale_image(img: &Img, w: usize, h: usize, d: usize, integer: bool) -> Img {
    let (wx, wy, wz) = (
        box_weights(img.w, w),
        box_weights(img.h, h),
        box_weights(img.d, d),
    );
    let n = img.n;
    let mut data = vec![0.0; w * h * d * n];
    for (oz, (fz, wzs)) in wz.iter().enumerate() {
        for (oy, (fy, wys)) in wy.iter().enumerate() {
            for (ox, (fx, wxs)) in wx.iter().enumerate() {
                for c in 0..n {
                    let mut acc = 0.0;
                    for (dz, wzv) in wzs.iter().enumerate() {
                        for (dy, wyv) in wys.iter().enumerate() {
                            for (dx, wxv) in wxs.iter().enumerate() {
                                let at = (((fz + dz) * img.h + fy + dy) * img.w + fx + dx) * n;
                                acc += wzv * wyv * wxv * img.data[at + c];
                            }
                        }
                    }
                    // A hair above, so that sums meant to be whole stay whole.
                    data[((oz * h + oy) * w + ox) * n + c] =
                        if integer { (acc + 1e-9).floor() } else { acc };
                }
            }
        }
    }
    Img { w, h, d, n, data }
}

/// The next mipmap level: each dimension above 1 halved (rounding down), texels
/// 2i and 2i+1 averaged along it. Integer types: four texels round half up, two or
/// eight truncate. As in SGI's GLU, an odd width (with rows to pair) does not skip
/// the row's last texel when moving to the next pair of rows: the source drifts back
/// one texel per output row.
fn halve(img: &Img, integer: bool) -> Img {
    let half = |v: usize| if v > 1 { v / 2 } else { 1 };
    let (w, h, d) = (half(img.w), half(img.h), half(img.d));
    let span = |v: usize| if v > 1 { 2 } else { 1 };
    let (sx, sy, sz) = (span(img.w), span(img.h), span(img.d));
    let n = img.n;
    let count = sx * sy * sz;
    let drift = usize::from(img.w % 2 == 1 && sx == 2 && sy == 2 && sz == 1);
    let mut data = Vec::with_capacity(w * h * d * n);
    for z in 0..d {
        for y in 0..h {
            for x in 0..w {
                for c in 0..n {
                    let mut sum = 0.0;
                    for dz in 0..sz {
                        for dy in 0..sy {
                            for dx in 0..sx {
                                let (ix, iy, iz) = (x * sx + dx, y * sy + dy, z * sz + dz);
                                let texel = (iz * img.h + iy) * img.w + ix - y * drift;
                                sum += img.data[texel * n + c];
                            }
                        }
                    }
                    let avg = sum / count as f64;
                    data.push(match (integer, count) {
                        (false, _) => avg,
                        (true, 4) => (avg + 0.5).floor(),
                        (true, _) => avg.floor(),
                    });
                }
            }
        }
    }
    Img { w, h, d, n, data }
}

/// `gluScaleImage`: scales a client image with a box filter; 0 on success or a GLU
/// error code.
///
/// SGI's GLU does this in 16-bit: each component becomes a u16 (`ubyte·257`,
/// `byte·516`, `short·2`, `uint>>16`, `int>>15`, `float·65535` in f32, wrapping as C's
/// conversions do; index formats keep the raw value), is scaled by [`scale_u16`], and goes
/// back (`>>8`, `>>9`, `>>1`, `·65537`, `·65537/2`, `/65535` in f32). The pixels that
/// result are what programs linked with libGLU upload, so they are reproduced here.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn gluScaleImage(
    format: GLenum,
    w_in: GLsizei,
    h_in: GLsizei,
    type_in: GLenum,
    data_in: *const c_void,
    w_out: GLsizei,
    h_out: GLsizei,
    type_out: GLenum,
    data_out: *mut c_void,
) -> GLint {
    if w_in == 0 || h_in == 0 || w_out == 0 || h_out == 0 {
        return 0;
    }
    if w_in < 0 || h_in < 0 || w_out < 0 || h_out < 0 {
        return GLU_INVALID_VALUE;
    }
    let (Some(n), Some(_), Some(_)) = (components(format), type_size(type_in), type_size(type_out))
    else {
        return GLU_INVALID_ENUM;
    };
    if data_in.is_null() || data_out.is_null() {
        return 0;
    }
    // GL_COLOR_INDEX and GL_STENCIL_INDEX carry raw values.
    let index = matches!(format, 0x1900 | 0x1901);
    let img = read_image(data_in, w_in as usize, h_in as usize, 1, n, type_in);
    let wide: Vec<u16> = img
        .data
        .iter()
        .map(|&v| to_u16(v, type_in, index))
        .collect();
    let scaled = scale_u16(
        n,
        (w_in as usize, h_in as usize),
        &wide,
        (w_out as usize, h_out as usize),
    );
    let data = scaled
        .iter()
        .map(|&v| from_u16(v, type_out, index))
        .collect();
    let out = Img {
        w: w_out as usize,
        h: h_out as usize,
        d: 1,
        n,
        data,
    };
    write_image(&out, data_out, type_out);
    0
}

/// A component (in its type's scale) as SGI's GLU widens it to 16 bits.
fn to_u16(v: f64, ty: GLenum, index: bool) -> u16 {
    // Integer values are whole; C's conversions to unsigned short keep the low 16 bits.
    let wrap = |x: i64| x as u16;
    match (ty, index) {
        (gl::GL_UNSIGNED_BYTE, false) => wrap(v as i64 * 257),
        (gl::GL_BYTE, false) => wrap(v as i64 * 516),
        (gl::GL_SHORT, false) => wrap(v as i64 * 2),
        (gl::GL_UNSIGNED_INT, false) => wrap(v as i64 >> 16),
        (gl::GL_INT, false) => wrap(v as i64 >> 15),
        (gl::GL_FLOAT, false) => float_to_u16(65535.0 * v as f32),
        (gl::GL_FLOAT, true) => float_to_u16(v as f32),
        _ => wrap(v as i64),
    }
}

/// C's float → unsigned short on x86-64: truncated through a 32-bit integer (values that
/// do not fit come out as its "indefinite" value, whose low bits are 0).
fn float_to_u16(f: f32) -> u16 {
    if f.is_finite() && f > -2147483648.0 && f < 2147483648.0 {
        f as i32 as u16
    } else {
        0
    }
}

/// A 16-bit component back in `ty`'s scale, as SGI's GLU narrows it.
fn from_u16(v: u16, ty: GLenum, index: bool) -> f64 {
    let v32 = u32::from(v);
    match (ty, index) {
        (gl::GL_UNSIGNED_BYTE, false) => f64::from(v >> 8),
        (gl::GL_UNSIGNED_BYTE, true) => f64::from(v as u8),
        (gl::GL_BYTE, false) => f64::from((v >> 9) as i8),
        (gl::GL_BYTE, true) => f64::from(v as i8),
        (gl::GL_SHORT, false) => f64::from((v >> 1) as i16),
        (gl::GL_SHORT, true) => f64::from(v as i16),
        (gl::GL_UNSIGNED_INT, false) => f64::from(v32 * 65537),
        (gl::GL_INT, false) => f64::from((v32 * 65537 / 2) as i32),
        (gl::GL_FLOAT, false) => f64::from(f32::from(v) / 65535.0),
        _ => f64::from(v),
    }
}

/// SGI GLU's 16-bit box filter (`scale_internal`): an exact halving averages 2×2 texels
/// rounding half up; otherwise each output texel integrates the input over its footprint
/// (f32 coordinates and weights, wrapping around the edges when enlarging), and the f32
/// total plus 0.5 is divided by the covered area in f64 and truncated.
fn scale_u16(
    n: usize,
    (wi, hi): (usize, usize),
    src: &[u16],
    (wo, ho): (usize, usize),
) -> Vec<u16> {
    let mut out = vec![0u16; wo * ho * n];
    if wi == wo * 2 && hi == ho * 2 {
        for (o, px) in out.chunks_mut(n).enumerate() {
            let (x, y) = (o % wo * 2, o / wo * 2);
            for (c, v) in px.iter_mut().enumerate() {
                let at = |xx: usize, yy: usize| u32::from(src[(yy * wi + xx) * n + c]);
                *v = ((at(x, y) + at(x + 1, y) + at(x, y + 1) + at(x + 1, y + 1) + 2) / 4) as u16;
            }
        }
        return out;
    }
    // The footprint of output index `o` along an axis: [low, high) in input texels.
    let span = |o: usize, size_in: usize, size_out: usize| {
        let conv = size_in as f32 / size_out as f32;
        let centre = (f64::from(conv) * (o as f64 + 0.5)) as f32;
        if size_in > size_out {
            (centre - conv / 2.0, centre + conv / 2.0)
        } else {
            (
                (f64::from(centre) - 0.5) as f32,
                (f64::from(centre) + 0.5) as f32,
            )
        }
    };
    // Pieces of [low, high) cut at whole texels: (input index, f32 fraction).
    let pieces = |(low, high): (f32, f32), size: usize| {
        let mut v = Vec::new();
        let mut at = low;
        let mut whole = f64::from(low).floor() as i64;
        while at < high {
            let index = (whole + size as i64).rem_euclid(size as i64) as usize;
            let next = (whole + 1) as f32;
            v.push((index, if high < next { high - at } else { next - at }));
            whole += 1;
            at = whole as f32;
        }
        v
    };
    for oy in 0..ho {
        let ys = pieces(span(oy, hi, ho), hi);
        for ox in 0..wo {
            let xs = pieces(span(ox, wi, wo), wi);
            let mut totals = [0f32; 4];
            let mut area = 0f32;
            for &(iy, py) in &ys {
                for &(ix, px) in &xs {
                    let w = px * py;
                    area += w;
                    for (c, t) in totals.iter_mut().enumerate().take(n) {
                        *t += f32::from(src[(iy * wi + ix) * n + c]) * w;
                    }
                }
            }
            for c in 0..n {
                let v = (f64::from(totals[c]) + 0.5) / f64::from(area);
                out[(oy * wo + ox) * n + c] = v as i32 as u16;
            }
        }
    }
    out
}

/// The power of two GLU scales a size to: the nearer one, 1.5 × 2^k rounding up.
fn nearest_pow2(v: usize) -> usize {
    let p = if v <= 1 {
        1
    } else {
        1 << (usize::BITS - 1 - v.leading_zeros())
    };
    if p > 1 && v >= p + p / 2 {
        p * 2
    } else {
        p
    }
}

/// log2 of a power of two, -1 for other sizes.
fn log2_exact(v: usize) -> i32 {
    if v.is_power_of_two() {
        v.trailing_zeros() as i32
    } else {
        -1
    }
}

/// Which texture call a mipmap chain goes to.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Dims {
    One,
    Two,
    Three,
}

/// Loads one level.
fn upload(
    dims: Dims,
    target: GLenum,
    level: i32,
    internal: GLint,
    img: &Img,
    format: GLenum,
    ty: GLenum,
) {
    let bytes: Vec<u8> = img.data.iter().flat_map(|&v| to_bytes(v, ty)).collect();
    let (w, h, d) = (img.w as GLsizei, img.h as GLsizei, img.d as GLsizei);
    let p = bytes.as_ptr().cast();
    // SAFETY: bytes holds img.w x img.h x img.d pixels of `format`/`ty`, tightly
    // packed as the caller's unpack state (TIGHT) says.
    unsafe {
        match dims {
            Dims::One => gl::glTexImage1D(target, level, internal, w, 0, format, ty, p),
            Dims::Two => gl::glTexImage2D(target, level, internal, w, h, 0, format, ty, p),
            Dims::Three => glTexImage3D(target, level, internal, w, h, d, 0, format, ty, p),
        }
    }
}

/// Loads levels `base..=max` of the chain starting with `img` as level `level`.
#[allow(clippy::too_many_arguments)]
fn load_chain(
    dims: Dims,
    target: GLenum,
    internal: GLint,
    mut img: Img,
    format: GLenum,
    ty: GLenum,
    level: i32,
    base: i32,
    max: i32,
) {
    let saved = gl::PixelStore::unpack();
    gl::PixelStore::TIGHT.set_unpack();
    let integer = ty != gl::GL_FLOAT;
    let mut l = level;
    while l <= max {
        if l >= base {
            upload(dims, target, l, internal, &img, format, ty);
        }
        if img.w == 1 && img.h == 1 && img.d == 1 {
            break;
        }
        img = halve(&img, integer);
        l += 1;
    }
    saved.set_unpack();
}

/// Reads the image for a mipmap call after checking format, type and sizes.
fn checked_image(
    w: GLsizei,
    h: GLsizei,
    d: GLsizei,
    format: GLenum,
    ty: GLenum,
    data: *const c_void,
) -> Result<Option<Img>, GLint> {
    let (Some(n), Some(_)) = (components(format), type_size(ty)) else {
        return Err(GLU_INVALID_ENUM);
    };
    if w < 1 || h < 1 || d < 1 {
        return Err(GLU_INVALID_VALUE);
    }
    if data.is_null() {
        return Ok(None);
    }
    Ok(Some(read_image(
        data, w as usize, h as usize, d as usize, n, ty,
    )))
}

/// The `Mipmaps` calls: scale to the nearest powers of two (within the GL's maximum),
/// then load every level.
fn build_mipmaps(
    (dims, target, internal): (Dims, GLenum, GLint),
    (w, h, d): (GLsizei, GLsizei, GLsizei),
    format: GLenum,
    ty: GLenum,
    data: *const c_void,
) -> GLint {
    let img = match checked_image(w, h, d, format, ty, data) {
        Ok(Some(img)) => img,
        Ok(None) => return 0,
        Err(e) => return e,
    };
    let max_size = if dims == Dims::Three {
        gl::get_int(GL_MAX_3D_TEXTURE_SIZE)
    } else {
        gl::get_int(gl::GL_MAX_TEXTURE_SIZE)
    }
    .max(1) as usize;
    let fit = |v: usize| {
        let mut p = nearest_pow2(v);
        while p > max_size {
            p /= 2;
        }
        p
    };
    let (nw, nh, nd) = (fit(img.w), fit(img.h), fit(img.d));
    let img = if (nw, nh, nd) == (img.w, img.h, img.d) {
        img
    } else {
        scale_image(&img, nw, nh, nd, ty != gl::GL_FLOAT)
    };
    let top = log2_exact(nw.max(nh).max(nd));
    load_chain(dims, target, internal, img, format, ty, 0, 0, top);
    0
}

/// The `MipmapLevels` calls: the image is level `level`, levels `base..=max` load.
#[allow(clippy::too_many_arguments)]
fn build_levels(
    dims: Dims,
    target: GLenum,
    internal: GLint,
    (w, h, d): (GLsizei, GLsizei, GLsizei),
    format: GLenum,
    ty: GLenum,
    (level, base, max): (GLint, GLint, GLint),
    data: *const c_void,
) -> GLint {
    if components(format).is_none() || type_size(ty).is_none() {
        return GLU_INVALID_ENUM;
    }
    if w < 1 || h < 1 || d < 1 {
        return GLU_INVALID_VALUE;
    }
    let levels = log2_exact(w as usize)
        .max(log2_exact(h as usize))
        .max(log2_exact(d as usize))
        + level;
    if base < 0 || base < level || max < base || levels < max {
        return GLU_INVALID_VALUE;
    }
    match checked_image(w, h, d, format, ty, data) {
        Ok(Some(img)) => {
            load_chain(dims, target, internal, img, format, ty, level, base, max);
            0
        }
        Ok(None) => 0,
        Err(e) => e,
    }
}

/// `gluBuild1DMipmaps`: scales to the nearest power of two and loads every level.
#[no_mangle]
pub extern "C" fn gluBuild1DMipmaps(
    target: GLenum,
    internal: GLint,
    w: GLsizei,
    format: GLenum,
    ty: GLenum,
    data: *const c_void,
) -> GLint {
    build_mipmaps((Dims::One, target, internal), (w, 1, 1), format, ty, data)
}

/// `gluBuild2DMipmaps`: scales to the nearest powers of two and loads every level.
#[no_mangle]
pub extern "C" fn gluBuild2DMipmaps(
    target: GLenum,
    internal: GLint,
    w: GLsizei,
    h: GLsizei,
    format: GLenum,
    ty: GLenum,
    data: *const c_void,
) -> GLint {
    build_mipmaps((Dims::Two, target, internal), (w, h, 1), format, ty, data)
}

/// `gluBuild3DMipmaps`: scales to the nearest powers of two and loads every level.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn gluBuild3DMipmaps(
    target: GLenum,
    internal: GLint,
    w: GLsizei,
    h: GLsizei,
    d: GLsizei,
    format: GLenum,
    ty: GLenum,
    data: *const c_void,
) -> GLint {
    build_mipmaps((Dims::Three, target, internal), (w, h, d), format, ty, data)
}

/// `gluBuild1DMipmapLevels`: `data` is level `level`; levels `base..=max` load.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn gluBuild1DMipmapLevels(
    target: GLenum,
    internal: GLint,
    w: GLsizei,
    format: GLenum,
    ty: GLenum,
    level: GLint,
    base: GLint,
    max: GLint,
    data: *const c_void,
) -> GLint {
    let lv = (level, base, max);
    build_levels(Dims::One, target, internal, (w, 1, 1), format, ty, lv, data)
}

/// `gluBuild2DMipmapLevels`: `data` is level `level`; levels `base..=max` load.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn gluBuild2DMipmapLevels(
    target: GLenum,
    internal: GLint,
    w: GLsizei,
    h: GLsizei,
    format: GLenum,
    ty: GLenum,
    level: GLint,
    base: GLint,
    max: GLint,
    data: *const c_void,
) -> GLint {
    let lv = (level, base, max);
    build_levels(Dims::Two, target, internal, (w, h, 1), format, ty, lv, data)
}

/// `gluBuild3DMipmapLevels`: `data` is level `level`; levels `base..=max` load.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn gluBuild3DMipmapLevels(
    target: GLenum,
    internal: GLint,
    w: GLsizei,
    h: GLsizei,
    d: GLsizei,
    format: GLenum,
    ty: GLenum,
    level: GLint,
    base: GLint,
    max: GLint,
    data: *const c_void,
) -> GLint {
    let lv = (level, base, max);
    build_levels(
        Dims::Three,
        target,
        internal,
        (w, h, d),
        format,
        ty,
        lv,
        data,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn img(w: usize, h: usize, data: &[f64]) -> Img {
        Img {
            w,
            h,
            d: 1,
            n: 1,
            data: data.to_vec(),
        }
    }

    #[test]
    fn box_halve_and_sizes() {
        let row = img(4, 1, &[0.0, 2.0, 4.0, 6.0]);
        assert_eq!(scale_image(&row, 2, 1, 1, false).data, vec![1.0, 5.0]);
        assert_eq!(scale_image(&row, 8, 1, 1, false).data[..3], [0.0, 0.0, 2.0]);
        // Odd widths drop the last column; halves round up.
        let odd = img(3, 2, &[66.0, 114.0, 202.0, 186.0, 154.0, 162.0]);
        assert_eq!(halve(&odd, true).data, vec![130.0]);
        assert_eq!(halve(&img(2, 1, &[1.0, 2.0]), true).data, vec![1.0]);
        assert_eq!(
            [1, 3, 5, 6, 7, 12, 100].map(nearest_pow2),
            [1, 4, 4, 8, 8, 16, 128]
        );
        assert_eq!([1, 8, 12].map(log2_exact), [0, 3, -1]);
    }
}
