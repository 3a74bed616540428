//! glGetTexParameter{f,i}v and glGetTexEnv{f,i}v: the values of
//! [`Context::get_tex_parameter`] and [`Context::get_tex_env`] in the type each form
//! returns.

use super::{Context, GlResult};
use crate::gl::types::*;

/// Mesa's FLOAT_TO_INT for a normalized value, truncating: 0.25 → 536870911.
fn float_to_int_trunc(x: f64) -> i32 {
    (x * 2147483647.0) as i32
}

/// A normalized value as glGetTexEnviv rounds it.
fn float_to_int_round(x: f64) -> i32 {
    (x * 2147483647.0).round() as i32
}

/// `v` as integers: normalized values through `norm`, others rounded.
fn to_ints((v, normalized): (Vec<f64>, bool), norm: fn(f64) -> i32) -> Vec<i32> {
    v.into_iter()
        .map(|x| {
            if normalized {
                norm(x)
            } else {
                x.round() as i32
            }
        })
        .collect()
}

impl Context {
    /// glGetTexParameterfv's values.
    pub(crate) fn get_tex_parameter_f(&self, target: GLenum, pname: GLenum) -> GlResult<Vec<f64>> {
        Ok(self.get_tex_parameter(target, pname)?.0)
    }

    /// glGetTexParameteriv's values (normalized ones truncated, as Mesa's FLOAT_TO_INT).
    pub(crate) fn get_tex_parameter_i(&self, target: GLenum, pname: GLenum) -> GlResult<Vec<i32>> {
        Ok(to_ints(
            self.get_tex_parameter(target, pname)?,
            float_to_int_trunc,
        ))
    }

    /// glGetTexEnvfv's values.
    pub(crate) fn get_tex_env_f(&self, target: GLenum, pname: GLenum) -> GlResult<Vec<f64>> {
        Ok(self.get_tex_env(target, pname)?.0)
    }

    /// glGetTexEnviv's values (normalized ones rounded).
    pub(crate) fn get_tex_env_i(&self, target: GLenum, pname: GLenum) -> GlResult<Vec<i32>> {
        Ok(to_ints(
            self.get_tex_env(target, pname)?,
            float_to_int_round,
        ))
    }
}
