//! The std140 uniform-block layout: base alignment, size, array and matrix strides and
//! struct member offsets, in bytes.
//!
//! Source: the OpenGL 3.1 to 3.3 specifications, section 2.11.4 ("Standard Uniform Block
//! Layout"; 7.6.2.2 in 4.5, whose worked example the tests check). The rules, with N
//! the size of a scalar (4 bytes; a bool takes 4 too):
//! - rule 1: a scalar has base alignment N;
//! - rules 2, 3: a two-component vector 2N, a three- or four-component vector 4N;
//! - rule 4: an array of scalars or vectors: the element's base alignment rounded up
//!   to a vec4 (16), which is also the array stride; the array ends padded to that;
//! - rules 5, 7: a column-major matrix of C columns and R rows is an array of C vectors
//!   of R components (rule 4); row-major, an array of R vectors of C components;
//! - rules 6, 8: arrays of matrices are arrays of their column (row) vectors;
//! - rule 9: a struct's base alignment is the largest of its members' rounded up to 16;
//!   members at offsets by these rules; its size rounded up to its base alignment;
//! - rule 10: an array of structs lays out each element by rule 9.

use super::{Struct, Type};

/// The std140 layout of one type.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Layout {
    /// The base alignment.
    pub align: u32,
    /// The bytes the value spans, trailing padding included (what the next member
    /// starts after): for a vec3 12, for an array or struct a multiple of `align`.
    pub size: u32,
}

fn round_up(x: u32, to: u32) -> u32 {
    x.div_ceil(to) * to
}

/// The base alignment and size of `ty` in std140 (`row_major` for matrices, also
/// inside arrays). None for types a uniform block cannot hold (void, samplers, unsized
/// arrays).
pub fn layout(ty: &Type, row_major: bool) -> Option<Layout> {
    match ty {
        Type::Scalar(_) => Some(Layout { align: 4, size: 4 }),
        Type::Vector(_, n) => Some(Layout {
            align: if *n == 2 { 8 } else { 16 },
            size: 4 * *n as u32,
        }),
        Type::Matrix { .. } => {
            let stride = matrix_stride(ty, row_major)?;
            let (vectors, _) = matrix_vectors(ty, row_major)?;
            Some(Layout {
                align: stride,
                size: stride * vectors,
            })
        }
        Type::Array(_, Some(n)) => {
            let stride = array_stride(ty, row_major)?;
            Some(Layout {
                align: round_up(element_align(ty, row_major)?, 16),
                size: stride * n,
            })
        }
        Type::Struct(s) => {
            let offsets = struct_offsets(s, row_major)?;
            let align = struct_align(s, row_major)?;
            let end = s
                .members
                .iter()
                .zip(&offsets)
                .map(|(m, o)| Some(o + layout(&m.ty, row_major)?.size))
                .try_fold(0, |acc, e| e.map(|e| acc.max(e)))?;
            Some(Layout {
                align,
                size: round_up(end, align),
            })
        }
        Type::Void | Type::Sampler(_) | Type::Array(_, None) => None,
    }
}

fn element_align(ty: &Type, row_major: bool) -> Option<u32> {
    match ty {
        Type::Array(e, _) => Some(layout(e, row_major)?.align),
        _ => None,
    }
}

/// The number of column (or, row-major, row) vectors of a matrix and their size.
fn matrix_vectors(ty: &Type, row_major: bool) -> Option<(u32, u8)> {
    match ty {
        Type::Matrix { cols, rows } if row_major => Some((*rows as u32, *cols)),
        Type::Matrix { cols, rows } => Some((*cols as u32, *rows)),
        _ => None,
    }
}

/// The matrix stride of a matrix type (rules 5 and 7): its column (row) vector's
/// alignment rounded up to 16, so always 16 for 32-bit matrices.
pub fn matrix_stride(ty: &Type, row_major: bool) -> Option<u32> {
    let (_, n) = matrix_vectors(ty, row_major)?;
    let v = layout(&Type::Vector(super::Scalar::Float, n), row_major)?;
    Some(round_up(v.align, 16))
}

/// The array stride of a sized array type (rules 4, 6, 8, 10): the element's size
/// rounded up to its base alignment rounded up to 16.
pub fn array_stride(ty: &Type, row_major: bool) -> Option<u32> {
    match ty {
        Type::Array(e, _) => {
            let l = layout(e, row_major)?;
            Some(round_up(l.size, round_up(l.align, 16)))
        }
        _ => None,
    }
}

fn struct_align(s: &Struct, row_major: bool) -> Option<u32> {
    let mut align = 16;
    for m in &s.members {
        align = align.max(round_up(layout(&m.ty, row_major)?.align, 16));
    }
    Some(align)
}

/// The offsets of a struct's members from the struct's start (rule 9), or of a
/// uniform block's members from the block's start (a block lays out like a struct).
pub fn struct_offsets(s: &Struct, row_major: bool) -> Option<Vec<u32>> {
    let mut offsets = Vec::with_capacity(s.members.len());
    let mut at = 0;
    for m in &s.members {
        let l = layout(&m.ty, row_major)?;
        at = round_up(at, l.align);
        offsets.push(at);
        at += l.size;
    }
    Some(offsets)
}
