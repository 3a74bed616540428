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
