//! The pipeline's vocabulary, a leaf of the crate: compare functions, blend factors,
//! primitives, limits and the parameter blocks (lighting, fog, texgen, rasterization) that
//! the state owns and the plan hands to the pipeline.
//!
//! Nothing here speaks GL: the conversions from and to GL tokens live beside the state
//! (`from_gl`/`to_gl` impls in `context`), so the pipeline, which imports only this module
//! for its vocabulary, never sees a GL enum.

/// An enum whose variants are written once and also listed, in declaration order, in its
/// `ALL` constant (what a contiguous range of GL tokens maps onto, by position).
macro_rules! listed_enum {
    (
        $(#[$m:meta])*
        pub enum $t:ident { $($v:ident,)+ }
    ) => {
        $(#[$m])*
        pub enum $t {
            $($v,)+
        }

        impl $t {
            /// Every variant, in declaration order (`ALL[v as usize] == v`).
            pub const ALL: &'static [$t] = &[$($t::$v),+];
        }
    };
}

pub mod arrays;
pub mod caps;
pub mod fragment;
pub mod lighting;
pub mod primitive;
pub mod raster;
pub mod texgen;
pub mod vertex;

pub use arrays::*;
pub use caps::*;
pub use fragment::*;
pub use lighting::*;
pub use primitive::*;
pub use raster::*;
pub use texgen::*;
pub use vertex::*;
