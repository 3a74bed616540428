//! Pixel rectangles of `GL/gl.h`: glDrawPixels, glCopyPixels, glBitmap, glPixelTransfer,
//! glPixelMap and glGetPixelMap. Images are decoded with the unpack state when the call
//! is made (so display lists keep an owned copy); the commands are validated, when they
//! execute, by [`crate::context::pixel_api`].
#![allow(non_snake_case)]

use super::client::unpack_buffer_bytes;
use super::enums::*;
use super::types::*;
use super::{with_ctx, with_ctx_list};
use crate::context::bitmap_read::bitmap_bits;
use crate::context::pack::draw_image::Layout;
use crate::context::pixel_transfer::{is_index_map, map_index};
use crate::pixels::image::Image;

/// Reads the current unpack state from the context (default state without one).
fn unpack_state() -> crate::context::state::PixelStore {
    with_ctx(|c| Ok(c.state.unpack))
}

/// A glDrawPixels image decoded at the call from client memory, or from the unpack buffer
/// at offset `pixels` ([`unpack_buffer_bytes`]); `Some(None)` when the arguments describe
/// no image (the command fails on them), `None` when the buffer's checks failed (the error
/// is recorded; the command must do nothing).
///
/// # Safety
/// Without an unpack buffer, `pixels` must be null or readable for the image.
unsafe fn decode_image(
    layout: Option<&Layout>,
    (width, height): (GLsizei, GLsizei),
    type_: GLenum,
    pixels: *const GLvoid,
) -> Option<Option<Image>> {
    let (Some(l), Ok(w), Ok(h)) = (layout, usize::try_from(width), usize::try_from(height)) else {
        return Some(None);
    };
    let ps = unpack_state();
    let copy = unpack_buffer_bytes(pixels, Some(type_), l.span(&ps, w, h))?;
    let src = copy.as_ref().map_or(pixels as *const u8, |b| b.as_ptr());
    // SAFETY: GL's contract: `pixels` holds the image the unpack state describes (or `src`
    // is the unpack buffer's copy of it).
    Some(unsafe { l.decode(&ps, w, h, src) })
}

/// A glBitmap bitmap read at the call from client memory or from the unpack buffer; `None`
/// when the buffer's checks failed (the error is recorded; the command must do nothing).
///
/// # Safety
/// Without an unpack buffer, `bitmap` must be null or readable for the bitmap.
unsafe fn decode_bitmap(
    (width, height): (GLsizei, GLsizei),
    bitmap: *const GLubyte,
) -> Option<Vec<bool>> {
    let ps = unpack_state();
    let span = match (usize::try_from(width), usize::try_from(height)) {
        (Ok(w), Ok(h)) => Layout::new(GL_COLOR_INDEX, GL_BITMAP).map_or(0, |l| l.span(&ps, w, h)),
        _ => 0,
    };
    let copy = unpack_buffer_bytes(bitmap as *const GLvoid, None, span)?;
    let src = copy.as_ref().map_or(bitmap, |b| b.as_ptr());
    // SAFETY: GL's contract: `bitmap` holds the bitmap the unpack state describes (or `src`
    // is the unpack buffer's copy of it).
    Some(unsafe { bitmap_bits(&ps, (width, height), src) })
}

/// glDrawPixels.
///
/// # Safety
/// `pixels` must be null or readable for the image the unpack state describes.
#[no_mangle]
pub unsafe extern "C" fn glDrawPixels(
    width: GLsizei,
    height: GLsizei,
    format: GLenum,
    type_: GLenum,
    pixels: *const GLvoid,
) {
    let layout = Layout::new(format, type_);
    // SAFETY: forwarded caller contract.
    let Some(img) = (unsafe { decode_image(layout.as_ref().ok(), (width, height), type_, pixels) })
    else {
        return;
    };
    with_ctx_list(move |c| c.draw_pixel_rect((width, height), layout, img.as_ref()))
}

/// glCopyPixels.
#[no_mangle]
pub extern "C" fn glCopyPixels(x: GLint, y: GLint, width: GLsizei, height: GLsizei, type_: GLenum) {
    with_ctx_list(move |c| c.copy_pixel_rect((x, y), (width, height), type_))
}

/// glBitmap.
///
/// # Safety
/// `bitmap` must be null or readable for the bitmap the unpack state describes.
#[no_mangle]
pub unsafe extern "C" fn glBitmap(
    width: GLsizei,
    height: GLsizei,
    xorig: GLfloat,
    yorig: GLfloat,
    xmove: GLfloat,
    ymove: GLfloat,
    bitmap_: *const GLubyte,
) {
    // SAFETY: forwarded caller contract.
    let Some(bits) = (unsafe { decode_bitmap((width, height), bitmap_) }) else {
        return;
    };
    let (orig, mv) = ([xorig, yorig], [xmove, ymove]);
    with_ctx_list(move |c| c.draw_bitmap((width, height), orig, mv, &bits))
}

/// glPixelTransferf.
#[no_mangle]
pub extern "C" fn glPixelTransferf(pname: GLenum, param: GLfloat) {
    with_ctx_list(move |c| c.pixel_modes.transfer.set(pname, param))
}

/// glPixelTransferi.
#[no_mangle]
pub extern "C" fn glPixelTransferi(pname: GLenum, param: GLint) {
    glPixelTransferf(pname, param as f32)
}

fn pixel_map(map: GLenum, values: Vec<f32>) {
    with_ctx_list(move |c| c.pixel_maps.set(map, &values))
}

/// Reads `n` values (none for a null pointer or a count outside 1..=256).
///
/// # Safety
/// `p` must be null or readable for `n` values.
unsafe fn read_values<T: Copy>(p: *const T, n: GLsizei) -> Option<Vec<T>> {
    if p.is_null() || !(1..=256).contains(&n) {
        return None;
    }
    // SAFETY: the caller promises `n` readable values.
    Some(
        (0..n as usize)
            .map(|i| unsafe { p.add(i).read_unaligned() })
            .collect(),
    )
}

/// The float values glPixelMap stores for `map` from integers scaled by `max`.
fn from_ints(map: GLenum, v: &[f64], max: f64) -> Vec<f32> {
    let index = map_index(map).is_ok_and(is_index_map);
    v.iter()
        .map(|&x| if index { x as f32 } else { (x / max) as f32 })
        .collect()
}

fn bad_size(map: GLenum) {
    with_ctx_list(move |c| c.pixel_map_size_error(map))
}

/// glPixelMapfv.
///
/// # Safety
/// `values` must be null or readable for `mapsize` values.
#[no_mangle]
pub unsafe extern "C" fn glPixelMapfv(map: GLenum, mapsize: GLsizei, values: *const GLfloat) {
    // SAFETY: the caller promises `mapsize` values.
    match unsafe { read_values(values, mapsize) } {
        Some(v) => pixel_map(map, v),
        None if !(1..=256).contains(&mapsize) => bad_size(map),
        None => {}
    }
}

/// glPixelMapuiv and glPixelMapusv: integers scaled by `max` (the type's largest value),
/// except for the index maps.
///
/// # Safety
/// `values` must be null or readable for `mapsize` values.
unsafe fn pixel_map_ints<T: Copy + Into<f64>>(
    map: GLenum,
    mapsize: GLsizei,
    values: *const T,
    max: f64,
) {
    // SAFETY: the caller promises `mapsize` values.
    match unsafe { read_values(values, mapsize) } {
        Some(v) => {
            let v: Vec<f64> = v.into_iter().map(Into::into).collect();
            pixel_map(map, from_ints(map, &v, max))
        }
        None if !(1..=256).contains(&mapsize) => bad_size(map),
        None => {}
    }
}

/// glPixelMapuiv.
///
/// # Safety
/// `values` must be null or readable for `mapsize` values.
#[no_mangle]
pub unsafe extern "C" fn glPixelMapuiv(map: GLenum, mapsize: GLsizei, values: *const GLuint) {
    // SAFETY: forwarded caller contract.
    unsafe { pixel_map_ints(map, mapsize, values, u32::MAX as f64) }
}

/// glPixelMapusv.
///
/// # Safety
/// `values` must be null or readable for `mapsize` values.
#[no_mangle]
pub unsafe extern "C" fn glPixelMapusv(map: GLenum, mapsize: GLsizei, values: *const GLushort) {
    // SAFETY: forwarded caller contract.
    unsafe { pixel_map_ints(map, mapsize, values, u16::MAX as f64) }
}

/// Writes map `map`'s values through `put(i, value, is_index_map)`.
fn get_map(map: GLenum, mut put: impl FnMut(usize, f32, bool)) {
    with_ctx(|c| {
        let (values, index) = c.pixel_map_values(map)?;
        for (k, &v) in values.iter().enumerate() {
            put(k, v, index);
        }
        Ok(())
    })
}

/// Mesa's `FLOAT_TO_UINT`: `(GLuint)(v * 4294967295.0)` in double, which on x86-64 keeps
/// the low 32 bits of the 64-bit truncation (so -1.0 reads back as 1).
fn float_to_uint(v: f32) -> u32 {
    (v as f64 * 4294967295.0) as i64 as u32
}

/// glGetPixelMapfv.
///
/// # Safety
/// `values` must be null or writable for the map's size.
#[no_mangle]
pub unsafe extern "C" fn glGetPixelMapfv(map: GLenum, values: *mut GLfloat) {
    get_map(map, |k, v, _| {
        if !values.is_null() {
            // SAFETY: the caller provides room for the whole map.
            unsafe { values.add(k).write_unaligned(v) }
        }
    })
}

/// glGetPixelMapuiv.
///
/// # Safety
/// `values` must be null or writable for the map's size.
#[no_mangle]
pub unsafe extern "C" fn glGetPixelMapuiv(map: GLenum, values: *mut GLuint) {
    get_map(map, |k, v, _| {
        // Mesa copies S_TO_S's stored float bits; every other map goes through
        // FLOAT_TO_UINT, I_TO_I included.
        let u = if map == GL_PIXEL_MAP_S_TO_S {
            v.to_bits()
        } else {
            float_to_uint(v)
        };
        if !values.is_null() {
            // SAFETY: the caller provides room for the whole map.
            unsafe { values.add(k).write_unaligned(u) }
        }
    })
}

/// glGetPixelMapusv.
///
/// # Safety
/// `values` must be null or writable for the map's size.
#[no_mangle]
pub unsafe extern "C" fn glGetPixelMapusv(map: GLenum, values: *mut GLushort) {
    get_map(map, |k, v, index| {
        let u = if index {
            v.clamp(0.0, 65535.0) as u16
        } else {
            (v * 65535.0).round_ties_even() as u16
        };
        if !values.is_null() {
            // SAFETY: the caller provides room for the whole map.
            unsafe { values.add(k).write_unaligned(u) }
        }
    })
}
