//! Unit tests of [`super`]: unpacking and packing texture images against values measured
//! with Mesa 22.3.

use super::*;
use crate::context::pack::tex_format::{base_format, choose_storage};
use crate::texture::Level;

#[test]
fn unpack_alignment_row_length_skip() {
    let cf = ClientFormat::new(GL_RGB, GL_UNSIGNED_BYTE).unwrap();
    // 3 px wide RGB, alignment 4 → stride 12 (9 bytes + 3 padding)
    let ps = PixelStore {
        alignment: 4,
        ..Default::default()
    };
    let mut data = [0u8; 24];
    for (i, b) in data.iter_mut().enumerate() {
        *b = i as u8;
    }
    // SAFETY: the test buffers hold every pixel the layout describes.
    let t = unsafe {
        unpack(
            &ps,
            &cf,
            BaseFormat::Rgb,
            Storage::of_base(BaseFormat::Rgb),
            3,
            2,
            data.as_ptr(),
        )
    };
    assert_eq!(t[2], [6, 7, 8, 255]);
    assert_eq!(t[3], [12, 13, 14, 255]);
    // alignment 1: tight rows
    let ps1 = PixelStore {
        alignment: 1,
        ..Default::default()
    };
    // SAFETY: the test buffers hold every pixel the layout describes.
    let t = unsafe {
        unpack(
            &ps1,
            &cf,
            BaseFormat::Rgb,
            Storage::of_base(BaseFormat::Rgb),
            3,
            2,
            data.as_ptr(),
        )
    };
    assert_eq!(t[3], [9, 10, 11, 255]);
    // row length 4, skip 1 pixel and 1 row, alignment 1
    let ps2 = PixelStore {
        alignment: 1,
        row_length: 4,
        skip_pixels: 1,
        skip_rows: 1,
        ..Default::default()
    };
    let data = (0..36u8).collect::<Vec<_>>();
    // SAFETY: the test buffers hold every pixel the layout describes.
    let t = unsafe {
        unpack(
            &ps2,
            &cf,
            BaseFormat::Rgb,
            Storage::of_base(BaseFormat::Rgb),
            2,
            2,
            data.as_ptr(),
        )
    };
    assert_eq!(t[0], [15, 16, 17, 255]);
    assert_eq!(t[2], [27, 28, 29, 255]);
}

#[test]
fn base_format_reduction_and_swizzle() {
    let cf = ClientFormat::new(GL_RGBA, GL_UNSIGNED_BYTE).unwrap();
    let ps = PixelStore {
        alignment: 1,
        ..Default::default()
    };
    let px = [10u8, 20, 30, 40];
    // SAFETY: the test buffers hold every pixel the layout describes.
    let get = |b| unsafe { unpack(&ps, &cf, b, Storage::of_base(b), 1, 1, px.as_ptr()) }[0];
    assert_eq!(get(BaseFormat::Luminance), [10, 10, 10, 255]);
    assert_eq!(get(BaseFormat::Alpha), [0, 0, 0, 40]);
    assert_eq!(get(BaseFormat::Intensity), [10, 10, 10, 10]);
    assert_eq!(get(BaseFormat::LuminanceAlpha), [10, 10, 10, 40]);
    assert_eq!(get(BaseFormat::Rgb), [10, 20, 30, 255]);
    let la = ClientFormat::new(GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE).unwrap();
    // SAFETY: the test buffers hold every pixel the layout describes.
    let t = unsafe {
        unpack(
            &ps,
            &la,
            BaseFormat::Rgba,
            Storage::of_base(BaseFormat::Rgba),
            1,
            1,
            px.as_ptr(),
        )
    }[0];
    assert_eq!(t, [10, 10, 10, 20]);
}

#[test]
fn packed_and_swapped() {
    let ps = PixelStore {
        alignment: 1,
        swap_bytes: true,
        ..Default::default()
    };
    let cf = ClientFormat::new(GL_RGB, GL_UNSIGNED_SHORT_5_6_5).unwrap();
    let v: u16 = (3 << 11) | (1 << 5) | 31;
    let b = v.swap_bytes().to_ne_bytes();
    // SAFETY: the test buffers hold every pixel the layout describes.
    let t = unsafe {
        unpack(
            &ps,
            &cf,
            BaseFormat::Rgb,
            Storage::of_base(BaseFormat::Rgb),
            1,
            1,
            b.as_ptr(),
        )
    }[0];
    assert_eq!(t, [24, 4, 255, 255]);
    assert_eq!(
        ClientFormat::new(GL_RGBA, GL_UNSIGNED_SHORT_5_6_5).err(),
        Some(GlError::InvalidOperation)
    );
    assert_eq!(
        ClientFormat::new(GL_INTENSITY, GL_UNSIGNED_BYTE).err(),
        Some(GlError::InvalidEnum)
    );
    let bgra = ClientFormat::new(GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV).unwrap();
    let ps = PixelStore {
        alignment: 1,
        ..Default::default()
    };
    let px = 0x4411_2233u32.to_ne_bytes();
    // SAFETY: the test buffers hold every pixel the layout describes.
    let t = unsafe {
        unpack(
            &ps,
            &bgra,
            BaseFormat::Rgba,
            Storage::of_base(BaseFormat::Rgba),
            1,
            1,
            px.as_ptr(),
        )
    }[0];
    assert_eq!(t, [0x11, 0x22, 0x33, 0x44]);
}

#[test]
fn pack_round_trip() {
    let ps = PixelStore {
        alignment: 1,
        ..Default::default()
    };
    let img = Level {
        width: 3,
        height: 1,
        internal_format: GL_RGBA,
        base: BaseFormat::Rgba,
        storage: crate::texture::Storage::of_base(BaseFormat::Rgba),
        texels: vec![[1, 2, 3, 4], [5, 6, 7, 8], [9, 10, 11, 12]],
        blocks: None,
    };
    let cf = ClientFormat::new(GL_BGRA, GL_UNSIGNED_BYTE).unwrap();
    let mut out = vec![0u8; 12];
    // SAFETY: the test buffers hold every pixel the layout describes.
    unsafe { pack(&ps, &cf, &img, out.as_mut_ptr()) };
    assert_eq!(&out[..4], &[3, 2, 1, 4]);
    // SAFETY: the test buffers hold every pixel the layout describes.
    let back = unsafe {
        unpack(
            &ps,
            &cf,
            BaseFormat::Rgba,
            Storage::of_base(BaseFormat::Rgba),
            3,
            1,
            out.as_ptr(),
        )
    };
    assert_eq!(back, img.texels);
    let f = ClientFormat::new(GL_RGBA, GL_FLOAT).unwrap();
    let mut outf = vec![0f32; 12];
    // SAFETY: the test buffers hold every pixel the layout describes.
    unsafe { pack(&ps, &f, &img, outf.as_mut_ptr() as *mut u8) };
    // SAFETY: the test buffers hold every pixel the layout describes.
    let back = unsafe {
        unpack(
            &ps,
            &f,
            BaseFormat::Rgba,
            Storage::of_base(BaseFormat::Rgba),
            3,
            1,
            outf.as_ptr() as *const u8,
        )
    };
    assert_eq!(back, img.texels);
}

#[test]
fn storage_choice_matches_mesa() {
    let sz = |i: u32, f: u32, t: u32| {
        choose_storage(i as i32, base_format(i as i32).unwrap(), f, t).sizes
    };
    assert_eq!(
        sz(GL_RGB, GL_RGB, GL_UNSIGNED_SHORT_5_6_5_REV),
        [5, 6, 5, 0, 0, 0]
    );
    assert_eq!(
        sz(GL_RGBA, GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4),
        [4, 4, 4, 4, 0, 0]
    );
    assert_eq!(
        sz(GL_RGBA, GL_BGRA, GL_UNSIGNED_SHORT_1_5_5_5_REV),
        [5, 5, 5, 1, 0, 0]
    );
    assert_eq!(
        sz(GL_RGB, GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1),
        [5, 5, 5, 0, 0, 0]
    );
    assert_eq!(
        sz(GL_RGB, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4),
        [8, 8, 8, 0, 0, 0]
    );
    assert_eq!(
        sz(GL_LUMINANCE_ALPHA, GL_LUMINANCE_ALPHA, GL_UNSIGNED_SHORT),
        [0, 0, 0, 16, 16, 0]
    );
    assert_eq!(sz(GL_RGB, GL_RGB, GL_UNSIGNED_SHORT), [8, 8, 8, 0, 0, 0]);
    assert_eq!(sz(GL_RGBA, GL_RGBA, GL_FLOAT), [8, 8, 8, 8, 0, 0]);
    // numbered internal formats are never matched to the type
    assert_eq!(sz(3, GL_RGB, GL_UNSIGNED_SHORT_5_6_5), [8, 8, 8, 0, 0, 0]);
    assert_eq!(sz(GL_RGBA2, GL_RGBA, GL_UNSIGNED_BYTE), [4, 4, 4, 4, 0, 0]);
    assert_eq!(
        sz(GL_LUMINANCE4_ALPHA4, GL_RGBA, GL_UNSIGNED_BYTE),
        [0, 0, 0, 4, 4, 0]
    );
    assert_eq!(
        sz(GL_LUMINANCE4, GL_RGBA, GL_UNSIGNED_BYTE),
        [0, 0, 0, 0, 8, 0]
    );
}

#[test]
fn small_formats_round_on_upload() {
    // Mesa 22.3 glGetTexImage of a 0..255 ramp stored as GL_RGBA4 / GL_RGB5
    assert_eq!(quantise_u8(8, 4), 0);
    assert_eq!(quantise_u8(9, 4), 17);
    assert_eq!(quantise_u8(4, 5), 0);
    assert_eq!(quantise_u8(5, 5), 8);
    assert_eq!(quantise_u8(200, 8), 200);
    // expanded values are kept as they are
    for bits in 1..8 {
        for q in 0..(1u64 << bits) {
            let v = unorm_to_u8(q, bits);
            assert_eq!(quantise_u8(v, bits), v);
        }
    }
    let cf = ClientFormat::new(GL_RGBA, GL_FLOAT).unwrap();
    let ps = PixelStore {
        alignment: 1,
        ..Default::default()
    };
    let st = choose_storage(GL_RGBA4 as i32, BaseFormat::Rgba, GL_RGBA, GL_FLOAT);
    // 0.0333·15 = 0.4995 → 0, 0.0334·15 = 0.501 → 1 (17); a u8 detour would give 9 → 17
    let px = [0.0333f32, 0.0334, 1.5, -1.0];
    // SAFETY: the test buffers hold every pixel the layout describes.
    let t = unsafe {
        unpack(
            &ps,
            &cf,
            BaseFormat::Rgba,
            st,
            1,
            1,
            px.as_ptr() as *const u8,
        )
    };
    assert_eq!(t[0], [0, 17, 255, 0]);
}

#[test]
fn intensity_reads_back_like_luminance() {
    // Mesa 22.3: glGetTexImage(GL_RGBA) of GL_INTENSITY* gives (I, 0, 0, 255)
    assert_eq!(
        readback_rgba(BaseFormat::Intensity, [7, 7, 7, 7]),
        [7, 0, 0, 255]
    );
}
