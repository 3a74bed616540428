//! Uniform locations and values of a linked program: glGetUniformLocation,
//! glGetActiveUniform/glGetActiveAttrib, glGetAttribLocation, the glUniform* and
//! glUniformMatrix* families and glGetUniform{f,i}v, with Mesa's error rules
//! (`uniform_query.cpp`, `validate_uniform_parameters`):
//! - no current program: GL_INVALID_OPERATION; a negative count: GL_INVALID_VALUE;
//! - location -1: ignored without error; any other unknown location: GL_INVALID_OPERATION;
//! - a count above 1 for a non-array: GL_INVALID_OPERATION; past an array's end the
//!   count is cut to the elements left;
//! - a type or size mismatch (a `glUniform3f` for a `vec4`, an `i` call for a float or
//!   an `f` call for an int, a matrix call of other dimensions): GL_INVALID_OPERATION; a
//!   bool takes either, as nonzero → true;
//! - a sampler takes glUniform1i{v} only, each unit below
//!   [`MAX_COMBINED_TEXTURE_IMAGE_UNITS`] (GL_INVALID_VALUE otherwise).
//!
//! Locations number each element of each active uniform from 0 (see
//! [`super::program_link`]); the numbers differ from Mesa's, which GL leaves to the
//! implementation.

use super::program_link::{ActiveAttrib, Linked, Uniform};
use super::shader_objects::ProgramObject;
use super::Context;
use crate::gl::error::{GlError, GlResult};
use softgl_glsl::types::{Scalar, Type};

/// The sampler unit bound a sampler uniform takes (Mesa llvmpipe's
/// GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS).
pub const MAX_COMBINED_TEXTURE_IMAGE_UNITS: i32 = 192;

/// The values of one glUniform* call.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UniformShape {
    /// glUniform{N}{f,i}: `N` components, integers when `int`.
    Vector {
        /// Components per element.
        n: u8,
        /// The `i` forms.
        int: bool,
    },
    /// glUniformMatrix{C}x{R}fv.
    Matrix {
        /// Columns.
        cols: u8,
        /// Rows.
        rows: u8,
        /// The `transpose` argument.
        transpose: bool,
    },
}

impl UniformShape {
    /// Words per element.
    pub fn components(self) -> usize {
        match self {
            UniformShape::Vector { n, .. } => n as usize,
            UniformShape::Matrix { cols, rows, .. } => cols as usize * rows as usize,
        }
    }
}

/// A linked program's uniform `name`'s location or -1: `a`, `a[2]`, `s.f`, `sa[1].f`.
fn location_of(l: &Linked, name: &str) -> i32 {
    let (base, index) = match name.strip_suffix(']').and_then(|n| n.rsplit_once('[')) {
        Some((b, i)) if !i.is_empty() && i.bytes().all(|c| c.is_ascii_digit()) => {
            (b, i.parse::<u32>().ok())
        }
        Some(_) => return -1,
        None => (name, Some(0)),
    };
    let Some(index) = index else { return -1 };
    let Some(u) = l
        .uniforms
        .iter()
        .find(|u| u.name == base && u.location >= 0)
    else {
        return -1;
    };
    if name.len() != base.len() && u.array.is_none() && index != 0 {
        return -1;
    }
    if index as usize >= u.size() {
        return -1;
    }
    u.location + index as i32
}

impl Context {
    /// The linked program `program` (GL_INVALID_OPERATION when the last link failed).
    fn linked(&self, program: u32) -> GlResult<&Linked> {
        let p: &ProgramObject = self.shaders.table.program(program)?;
        p.linked
            .as_ref()
            .filter(|_| p.link_status)
            .ok_or(GlError::InvalidOperation)
    }

    /// glGetUniformLocation.
    pub fn uniform_location(&self, program: u32, name: &str) -> GlResult<i32> {
        let l = self.linked(program)?;
        if name.starts_with("gl_") {
            return Ok(-1);
        }
        Ok(location_of(l, name))
    }

    /// glGetAttribLocation.
    pub fn attrib_location(&self, program: u32, name: &str) -> GlResult<i32> {
        let l = self.linked(program)?;
        if name.starts_with("gl_") {
            return Ok(-1);
        }
        Ok(l.attributes
            .iter()
            .find(|a| a.name == name)
            .map_or(-1, |a| a.location))
    }

    /// glGetActiveUniform: (name, size, type); `buf_size` is checked first.
    pub fn active_uniform(
        &self,
        program: u32,
        index: u32,
        buf_size: i32,
    ) -> GlResult<(String, i32, u32)> {
        if buf_size < 0 {
            return Err(GlError::InvalidValue);
        }
        let p = self.shaders.table.program(program)?;
        let u: &Uniform = p
            .linked
            .as_ref()
            .and_then(|l| l.uniforms.get(index as usize))
            .ok_or(GlError::InvalidValue)?;
        Ok((
            u.active_name(),
            u.size() as i32,
            super::program_link::gl_type(&u.ty),
        ))
    }

    /// glGetActiveAttrib: (name, size, type); `buf_size` is checked first.
    pub fn active_attrib(
        &self,
        program: u32,
        index: u32,
        buf_size: i32,
    ) -> GlResult<(String, i32, u32)> {
        if buf_size < 0 {
            return Err(GlError::InvalidValue);
        }
        let p = self.shaders.table.program(program)?;
        let a: &ActiveAttrib = p
            .linked
            .as_ref()
            .and_then(|l| l.attributes.get(index as usize))
            .ok_or(GlError::InvalidValue)?;
        Ok((a.name.clone(), 1, a.gl_type))
    }

    /// glUniform* / glUniformMatrix*: checks the call against the current program's
    /// uniform at `location` and stores `count` elements read by `read` (given the number
    /// of words to read: it is asked only once the call is known to be valid, and never
    /// for more than the uniform holds).
    pub fn set_uniform(
        &mut self,
        location: i32,
        count: i32,
        shape: UniformShape,
        read: &dyn Fn(usize) -> Vec<u32>,
    ) -> GlResult<()> {
        let current = self.shaders.current;
        if current == 0 {
            return Err(GlError::InvalidOperation);
        }
        if count < 0 {
            return Err(GlError::InvalidValue);
        }
        let p = self.shaders.table.program_mut(current)?;
        let l = p.linked.as_mut().ok_or(GlError::InvalidOperation)?;
        if location == -1 {
            return Ok(());
        }
        let &(ui, element) = usize::try_from(location)
            .ok()
            .and_then(|loc| l.locations.get(loc))
            .ok_or(GlError::InvalidOperation)?;
        let u = &mut l.uniforms[ui];
        if u.array.is_none() && count > 1 {
            return Err(GlError::InvalidOperation);
        }
        let float_bits = match (shape, &u.ty) {
            (UniformShape::Matrix { cols, rows, .. }, Type::Matrix { cols: c, rows: r })
                if cols == *c && rows == *r =>
            {
                true
            }
            (UniformShape::Vector { n, int }, ty) => {
                let ok_n = super::program_link::words_per_element(ty) == n as usize
                    && !matches!(ty, Type::Matrix { .. });
                let ok_kind = match ty {
                    Type::Sampler(_) => int && n == 1,
                    t => match t.scalar() {
                        Some(Scalar::Bool) => true,
                        Some(Scalar::Float) => !int,
                        Some(Scalar::Int | Scalar::Uint) => int,
                        None => false,
                    },
                };
                if !ok_n || !ok_kind {
                    return Err(GlError::InvalidOperation);
                }
                !int
            }
            _ => return Err(GlError::InvalidOperation),
        };
        let n = (count as usize).min(u.size() - element);
        let c = shape.components();
        let mut data = read(n * c);
        data.resize(n * c, 0);
        if let UniformShape::Matrix {
            cols,
            rows,
            transpose: true,
        } = shape
        {
            let (cols, rows) = (cols as usize, rows as usize);
            for m in data.chunks_mut(c) {
                let src = m.to_vec();
                for col in 0..cols {
                    for row in 0..rows {
                        // The application gave rows; element (col, row) is its
                        // `row * cols + col`.
                        m[col * rows + row] = src[row * cols + col];
                    }
                }
            }
        }
        if matches!(u.ty, Type::Sampler(_))
            && data
                .iter()
                .any(|&v| !(0..MAX_COMBINED_TEXTURE_IMAGE_UNITS).contains(&(v as i32)))
        {
            return Err(GlError::InvalidValue);
        }
        if u.ty.scalar() == Some(Scalar::Bool) {
            for v in &mut data {
                *v = if float_bits {
                    (f32::from_bits(*v) != 0.0) as u32
                } else {
                    (*v != 0) as u32
                };
            }
        }
        u.values[element * c..(element + n) * c].copy_from_slice(&data);
        Ok(())
    }

    /// glGetUniform{f,i}v: the element at `location` as floats or integers (floats
    /// round to the nearest integer, as Mesa).
    pub fn get_uniform(&self, program: u32, location: i32, int: bool) -> GlResult<Vec<f64>> {
        let l = self.linked(program)?;
        let &(ui, element) = usize::try_from(location)
            .ok()
            .and_then(|loc| l.locations.get(loc))
            .ok_or(GlError::InvalidOperation)?;
        let u = &l.uniforms[ui];
        let c = u.components();
        let scalar = match &u.ty {
            Type::Sampler(_) => Scalar::Int,
            t => t.scalar().unwrap_or(Scalar::Float),
        };
        Ok(u.values[element * c..(element + 1) * c]
            .iter()
            .map(|&w| {
                let v = match scalar {
                    Scalar::Float => f32::from_bits(w) as f64,
                    Scalar::Int => w as i32 as f64,
                    Scalar::Uint | Scalar::Bool => w as f64,
                };
                if int {
                    v.round()
                } else {
                    v
                }
            })
            .collect())
    }
}
