//! Unit tests of `texture/mod.rs`.

use super::*;

fn level(w: usize, h: usize) -> Option<Level> {
    Some(Level {
        width: w,
        height: h,
        internal_format: 0x1908,
        base: BaseFormat::Rgba,
        storage: crate::texture::Storage::of_base(BaseFormat::Rgba),
        texels: vec![[0; 4]; w * h],
        blocks: None,
    })
}

#[test]
fn default_min_filter_makes_single_level_incomplete() {
    let mut o = TextureObject::new(Some(Target::Tex2D));
    o.levels[0] = level(4, 4);
    assert_eq!(o.complete_range(), None);
    o.params.mip_filter = MipFilter::None;
    assert_eq!(o.complete_range(), Some((0, 0)));
}

#[test]
fn full_chain_is_complete_and_npot_halves_floor() {
    let mut o = TextureObject::new(Some(Target::Tex2D));
    o.levels[0] = level(5, 3);
    o.levels[1] = level(2, 1);
    assert_eq!(o.complete_range(), None);
    o.levels[2] = level(1, 1);
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
    let mut o = TextureObject::new(Some(Target::Tex2D));
    o.levels[0] = level(4, 4);
    o.levels[1] = level(2, 2);
    o.levels[2] = level(2, 1);
    assert_eq!(o.complete_range(), None);
}
