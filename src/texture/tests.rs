//! Unit tests of `texture/mod.rs`, and the texture tests' shared helpers.

use super::*;

/// An RGBA level of `w`x`h` (or, for a 3D level, of `texels.len() / (w·h)` slices)
/// holding `texels`.
pub(crate) fn rgba_level(w: usize, h: usize, texels: Vec<[u8; 4]>) -> Level {
    Level {
        width: w,
        height: h,
        internal_format: 0x1908,
        base: BaseFormat::Rgba,
        storage: Storage::of_base(BaseFormat::Rgba),
        texels: texels.into(),
        blocks: None,
        floats: None,
    }
}

/// A 2D texture whose levels 0, 1, ... have the sizes `sizes`.
fn chain(sizes: &[(usize, usize)]) -> TextureObject {
    let mut o = TextureObject::new(Some(Target::Tex2D));
    for (l, &(w, h)) in sizes.iter().enumerate() {
        o.levels[l] = Some(rgba_level(w, h, vec![[0; 4]; w * h]));
    }
    o
}

#[test]
fn default_min_filter_makes_single_level_incomplete() {
    let mut o = chain(&[(4, 4)]);
    assert_eq!(o.complete_range(), None);
    o.params.mip_filter = MipFilter::None;
    assert_eq!(o.complete_range(), Some((0, 0)));
}

#[test]
fn full_chain_is_complete_and_npot_halves_floor() {
    assert_eq!(chain(&[(5, 3), (2, 1)]).complete_range(), None);
    let mut o = chain(&[(5, 3), (2, 1), (1, 1)]);
    assert_eq!(o.complete_range(), Some((0, 2)));
    o.params.max_level = 1;
    assert_eq!(o.complete_range(), Some((0, 1)));
    o.params.base_level = 2;
    assert_eq!(o.complete_range(), None);
    o.params.max_level = 5;
    assert_eq!(o.complete_range(), Some((2, 2)));
}

#[test]
fn wrong_level_size_is_incomplete() {
    assert_eq!(chain(&[(4, 4), (2, 2), (2, 1)]).complete_range(), None);
}

#[test]
fn narrow_tables_read_the_stored_component() {
    // every n-bit value as uploads keep it (bit-replicated) reads back as c / (2^n - 1)
    // in f32, the way llvmpipe's float path converts the packed component
    for bits in 1..8u32 {
        let max = (1u32 << bits) - 1;
        let scale = (1.0f64 / max as f64) as f32;
        let t = unit::narrow_table(bits);
        for c in 0..=max {
            let byte = upload::unorm_to_u8(c as u64, bits);
            assert_eq!(t[byte as usize], c as f32 * scale, "{c} of {bits} bits");
        }
        assert_eq!((t[0], t[255]), (0.0, 1.0));
    }
    // 3 of 5 bits: 3/31 (the 8-bit path's byte 24 is 24/255)
    assert_eq!(unit::narrow_table(5)[24], 3.0 * (1.0f64 / 31.0) as f32);
    assert_ne!(unit::narrow_table(5)[24], 24.0 * sample::INV_255);
    assert_eq!(unit::narrow_table(8)[24], 24.0 * sample::INV_255);
}

#[test]
fn narrow_decode_only_for_unorm_components_under_8_bits() {
    let st = |sizes: [u8; 6], encoding| Storage { sizes, encoding };
    let d = unit::narrow_decode(&st([3, 3, 2, 0, 0, 0], Encoding::Unorm)).unwrap();
    assert_eq!(d[0], unit::narrow_table(3));
    assert_eq!(d[2], unit::narrow_table(2));
    assert_eq!(d[3], unit::narrow_table(8)); // no alpha: 255 reads 1.0
    let d = unit::narrow_decode(&st([0, 0, 0, 4, 4, 0], Encoding::Unorm)).unwrap();
    assert_eq!(d, [unit::narrow_table(4); 4]);
    let d = unit::narrow_decode(&st([10, 10, 10, 2, 0, 0], Encoding::Unorm)).unwrap();
    assert_eq!((d[0], d[3]), (unit::narrow_table(8), unit::narrow_table(2)));
    assert!(unit::narrow_decode(&Storage::of_base(BaseFormat::Rgba)).is_none());
    assert!(unit::narrow_decode(&st([16, 16, 16, 16, 0, 0], Encoding::Unorm16)).is_none());
    assert!(unit::narrow_decode(&st([4, 4, 4, 4, 0, 0], Encoding::SrgbBlocks)).is_none());
}
