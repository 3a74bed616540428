//! Unit tests of [`super`]: unpacking and packing texture images against values measured
//! with Mesa 22.3.

use super::*;
use crate::context::pack::tex_format::{base_format, choose_storage};
use crate::texture::Level;

/// A pixel store with tight rows (alignment 1) and every other field at its default.
fn tight() -> PixelStore {
    PixelStore {
        alignment: 1,
        ..Default::default()
    }
}

/// [`unpack`] of `w` x `h` pixels of `bytes` into `base` stored as `storage`, after checking
/// that `bytes` holds every byte the layout reads.
fn unpack_to<T>(
    ps: &PixelStore,
    cf: &ClientFormat,
    (base, storage): (BaseFormat, Storage),
    (w, h): (usize, usize),
    bytes: &[T],
) -> Vec<[u8; 4]> {
    assert!(Layout::new(ps, w, cf).span(w, h) <= std::mem::size_of_val(bytes));
    // SAFETY: the assertion above checks that `bytes` holds the layout's span.
    unsafe { unpack(ps, cf, base, storage, w, h, bytes.as_ptr() as *const u8) }
}

/// [`unpack_to`] into `base` at its own storage.
fn unpack_base<T>(
    ps: &PixelStore,
    cf: &ClientFormat,
    base: BaseFormat,
    size: (usize, usize),
    bytes: &[T],
) -> Vec<[u8; 4]> {
    unpack_to(ps, cf, (base, Storage::of_base(base)), size, bytes)
}

/// [`pack`] of `img` into `out`, after checking that `out` holds every byte the layout writes.
fn pack_into<T>(ps: &PixelStore, cf: &ClientFormat, img: &Level, out: &mut [T]) {
    let span = Layout::new(ps, img.width, cf).span(img.width, img.height);
    assert!(span <= std::mem::size_of_val(out));
    // SAFETY: the assertion above checks that `out` holds the layout's span.
    unsafe { pack(ps, cf, img, out.as_mut_ptr() as *mut u8) }
}

#[test]
fn unpack_alignment_row_length_skip() {
    let cf = ClientFormat::new(GL_RGB, GL_UNSIGNED_BYTE).unwrap();
    // 3 px wide RGB, alignment 4 → stride 12 (9 bytes + 3 padding)
    let ps = PixelStore {
        alignment: 4,
        ..Default::default()
    };
    let data = (0..24u8).collect::<Vec<_>>();
    let t = unpack_base(&ps, &cf, BaseFormat::Rgb, (3, 2), &data);
    assert_eq!(t[2], [6, 7, 8, 255]);
    assert_eq!(t[3], [12, 13, 14, 255]);
    // alignment 1: tight rows
    let t = unpack_base(&tight(), &cf, BaseFormat::Rgb, (3, 2), &data);
    assert_eq!(t[3], [9, 10, 11, 255]);
    // row length 4, skip 1 pixel and 1 row, alignment 1
    let ps2 = PixelStore {
        row_length: 4,
        skip_pixels: 1,
        skip_rows: 1,
        ..tight()
    };
    let data = (0..36u8).collect::<Vec<_>>();
    let t = unpack_base(&ps2, &cf, BaseFormat::Rgb, (2, 2), &data);
    assert_eq!(t[0], [15, 16, 17, 255]);
    assert_eq!(t[2], [27, 28, 29, 255]);
}

#[test]
fn base_format_reduction_and_swizzle() {
    let cf = ClientFormat::new(GL_RGBA, GL_UNSIGNED_BYTE).unwrap();
    let ps = tight();
    let px = [10u8, 20, 30, 40];
    let get = |b| unpack_base(&ps, &cf, b, (1, 1), &px)[0];
    assert_eq!(get(BaseFormat::Luminance), [10, 10, 10, 255]);
    assert_eq!(get(BaseFormat::Alpha), [0, 0, 0, 40]);
    assert_eq!(get(BaseFormat::Intensity), [10, 10, 10, 10]);
    assert_eq!(get(BaseFormat::LuminanceAlpha), [10, 10, 10, 40]);
    assert_eq!(get(BaseFormat::Rgb), [10, 20, 30, 255]);
    let la = ClientFormat::new(GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE).unwrap();
    let t = unpack_base(&ps, &la, BaseFormat::Rgba, (1, 1), &px)[0];
    assert_eq!(t, [10, 10, 10, 20]);
}

#[test]
fn packed_and_swapped() {
    let ps = PixelStore {
        swap_bytes: true,
        ..tight()
    };
    let cf = ClientFormat::new(GL_RGB, GL_UNSIGNED_SHORT_5_6_5).unwrap();
    let v: u16 = (3 << 11) | (1 << 5) | 31;
    let b = v.swap_bytes().to_ne_bytes();
    let t = unpack_base(&ps, &cf, BaseFormat::Rgb, (1, 1), &b)[0];
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
    let px = 0x4411_2233u32.to_ne_bytes();
    let t = unpack_base(&tight(), &bgra, BaseFormat::Rgba, (1, 1), &px)[0];
    assert_eq!(t, [0x11, 0x22, 0x33, 0x44]);
}

#[test]
fn pack_round_trip() {
    let ps = tight();
    let img = Level {
        width: 3,
        height: 1,
        internal_format: GL_RGBA,
        base: BaseFormat::Rgba,
        storage: crate::texture::Storage::of_base(BaseFormat::Rgba),
        texels: vec![[1, 2, 3, 4], [5, 6, 7, 8], [9, 10, 11, 12]].into(),
        blocks: None,
        floats: None,
    };
    let cf = ClientFormat::new(GL_BGRA, GL_UNSIGNED_BYTE).unwrap();
    let mut out = vec![0u8; 12];
    pack_into(&ps, &cf, &img, &mut out);
    assert_eq!(&out[..4], &[3, 2, 1, 4]);
    let back = unpack_base(&ps, &cf, BaseFormat::Rgba, (3, 1), &out);
    assert_eq!(back, img.texels[..]);
    let f = ClientFormat::new(GL_RGBA, GL_FLOAT).unwrap();
    let mut outf = vec![0f32; 12];
    pack_into(&ps, &f, &img, &mut outf);
    let back = unpack_base(&ps, &f, BaseFormat::Rgba, (3, 1), &outf);
    assert_eq!(back, img.texels[..]);
}

/// (internal format, client format, client type) and the component sizes Mesa 22.3 stores;
/// numbered internal formats (3) are never matched to the type.
#[rustfmt::skip]
const STORAGE_CASES: [(u32, u32, u32, [u8; 6]); 12] = [
    (GL_RGB, GL_RGB, GL_UNSIGNED_SHORT_5_6_5_REV, [5, 6, 5, 0, 0, 0]),
    (GL_RGBA, GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4, [4, 4, 4, 4, 0, 0]),
    (GL_RGBA, GL_BGRA, GL_UNSIGNED_SHORT_1_5_5_5_REV, [5, 5, 5, 1, 0, 0]),
    (GL_RGB, GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1, [5, 5, 5, 0, 0, 0]),
    (GL_RGB, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, [8, 8, 8, 0, 0, 0]),
    (GL_LUMINANCE_ALPHA, GL_LUMINANCE_ALPHA, GL_UNSIGNED_SHORT, [0, 0, 0, 16, 16, 0]),
    (GL_RGB, GL_RGB, GL_UNSIGNED_SHORT, [8, 8, 8, 0, 0, 0]),
    (GL_RGBA, GL_RGBA, GL_FLOAT, [8, 8, 8, 8, 0, 0]),
    (3, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, [8, 8, 8, 0, 0, 0]),
    (GL_RGBA2, GL_RGBA, GL_UNSIGNED_BYTE, [4, 4, 4, 4, 0, 0]),
    (GL_LUMINANCE4_ALPHA4, GL_RGBA, GL_UNSIGNED_BYTE, [0, 0, 0, 4, 4, 0]),
    (GL_LUMINANCE4, GL_RGBA, GL_UNSIGNED_BYTE, [0, 0, 0, 0, 8, 0]),
];

#[test]
fn storage_choice_matches_mesa() {
    for (i, f, t, sizes) in STORAGE_CASES {
        let base = base_format(i as i32).unwrap();
        let got = choose_storage(i as i32, base, f, t).sizes;
        assert_eq!(got, sizes, "internal {i:#x}, format {f:#x}, type {t:#x}");
    }
}

#[test]
fn small_formats_round_on_upload() {
    // Mesa 22.3 glGetTexImage of a 0..255 ramp stored as GL_RGBA4 / GL_RGB5
    for (v, bits, stored) in [(8, 4, 0), (9, 4, 17), (4, 5, 0), (5, 5, 8), (200, 8, 200)] {
        assert_eq!(quantise_u8(v, bits), stored, "{v} in {bits} bits");
    }
    // expanded values are kept as they are
    for bits in 1..8 {
        for q in 0..(1u64 << bits) {
            let v = unorm_to_u8(q, bits);
            assert_eq!(quantise_u8(v, bits), v);
        }
    }
    let cf = ClientFormat::new(GL_RGBA, GL_FLOAT).unwrap();
    let st = choose_storage(GL_RGBA4 as i32, BaseFormat::Rgba, GL_RGBA, GL_FLOAT);
    // 0.0333·15 = 0.4995 → 0, 0.0334·15 = 0.501 → 1 (17); a u8 detour would give 9 → 17
    let px = [0.0333f32, 0.0334, 1.5, -1.0];
    let t = unpack_to(&tight(), &cf, (BaseFormat::Rgba, st), (1, 1), &px);
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
