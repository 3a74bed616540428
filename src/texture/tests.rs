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
        texels,
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
