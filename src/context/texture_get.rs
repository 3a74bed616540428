//! glGetTexParameteriv and glGetTexEnviv: the values of [`super::Context::get_tex_parameter`]
//! and [`super::Context::get_tex_env`] as integers. Values that are not normalized are
//! rounded; normalized ones are scaled to the integer range, truncated for texture
//! parameters (Mesa's FLOAT_TO_INT: 0.25 → 536870911) and rounded for the environment.

/// `v` as integers: normalized values through `norm`, others rounded.
fn to_ints((v, normalized): (Vec<f64>, bool), norm: fn(f64) -> f64) -> Vec<i32> {
    v.into_iter()
        .map(|x| {
            if normalized {
                norm(x * 2147483647.0) as i32
            } else {
                x.round() as i32
            }
        })
        .collect()
}

/// glGetTexParameteriv's values (normalized ones truncated).
pub(crate) fn ints_truncated(values: (Vec<f64>, bool)) -> Vec<i32> {
    to_ints(values, |x| x)
}

/// glGetTexEnviv's values (normalized ones rounded).
pub(crate) fn ints_rounded(values: (Vec<f64>, bool)) -> Vec<i32> {
    to_ints(values, f64::round)
}

/// GL_SIGNED_NORMALIZED (GL 3.1; glext.h lists it outside the sections softgl takes).
const GL_SIGNED_NORMALIZED: u32 = 0x8F9C;

/// glGetTexLevelParameter's GL_TEXTURE_{RED,GREEN,BLUE,ALPHA,LUMINANCE,INTENSITY,DEPTH}_TYPE
/// (`pname`) of `img`: GL_NONE for a channel its base format lacks (Mesa's
/// `_mesa_base_format_has_channel`), else the data type of its storage
/// (`_mesa_get_format_datatype`): GL_FLOAT for float colour and depth, GL_SIGNED_NORMALIZED
/// for signed compressed images, GL_UNSIGNED_NORMALIZED for the rest.
pub(crate) fn channel_type(img: &crate::texture::Level, pname: u32) -> u32 {
    use crate::gl::enums::{GL_FLOAT, GL_NONE};
    use crate::gl::glext_enums::{GL_TEXTURE_RED_TYPE, GL_UNSIGNED_NORMALIZED};
    use crate::texture::{BaseFormat as B, Encoding};
    let b = img.base;
    let has = match pname.wrapping_sub(GL_TEXTURE_RED_TYPE) {
        0 => matches!(b, B::Red | B::Rg | B::Rgb | B::Rgba),
        1 => matches!(b, B::Rg | B::Rgb | B::Rgba),
        2 => matches!(b, B::Rgb | B::Rgba),
        3 => matches!(b, B::Rgba | B::Alpha | B::LuminanceAlpha),
        4 => matches!(b, B::Luminance | B::LuminanceAlpha),
        5 => b == B::Intensity,
        _ => b == B::Depth,
    };
    let float_depth =
        b == B::Depth && img.storage.depth_bits() == crate::texture::shadow::FLOAT_BITS;
    match img.storage.encoding {
        _ if !has => GL_NONE,
        Encoding::Float => GL_FLOAT,
        _ if float_depth => GL_FLOAT,
        Encoding::Snorm => GL_SIGNED_NORMALIZED,
        _ => GL_UNSIGNED_NORMALIZED,
    }
}
