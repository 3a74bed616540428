//! Array draws (GL 1.5 §2.8): glDrawArrays, glDrawElements and glDrawRangeElements on the
//! current state — validation in Mesa's order, reading the indices from the element
//! buffer or client memory, and choosing how the vertices are fetched (a compact range of
//! the arrays, or a list of distinct vertices) before the draw runs.

use super::arrays::{ArrayState, DataType};
use super::dlist::Elements;
use super::state::Primitive;
use super::texture_spec::non_negative;
use super::{Context, GlError, GlResult};
use crate::geometry::fetch::VertexFetcher;
use crate::geometry::source::{FetchSource, Gathered};
use crate::gl::enums::*;
use crate::gl::types::*;
use std::collections::HashMap;
use std::panic::{catch_unwind, resume_unwind, AssertUnwindSafe};

/// The index type of glDrawElements (GL_UNSIGNED_BYTE, _SHORT or _INT).
fn index_type(type_: GLenum) -> GlResult<DataType> {
    Ok(match type_ {
        GL_UNSIGNED_BYTE => DataType::UByte,
        GL_UNSIGNED_SHORT => DataType::UShort,
        GL_UNSIGNED_INT => DataType::UInt,
        _ => return Err(GlError::InvalidEnum),
    })
}

/// GL_INVALID_OPERATION when an array or index buffer the draw reads is mapped.
fn check_unmapped(c: &Context, indexed: bool) -> GlResult<()> {
    let a = &c.arrays;
    let mapped = |name: u32| {
        name != 0
            && a.buffers
                .get(&name)
                .and_then(|b| b.as_ref())
                .is_some_and(|b| b.mapped.is_some())
    };
    if a.all_arrays().any(|p| p.enabled && mapped(p.buffer))
        || (indexed && mapped(a.vao.element_buffer))
    {
        return Err(GlError::InvalidOperation);
    }
    Ok(())
}

/// glDrawArrays on the current context (shared by the multi-draw call).
pub(crate) fn draw_arrays(
    c: &mut Context,
    mode: GLenum,
    first: GLint,
    count: GLsizei,
) -> GlResult<()> {
    let mode = Primitive::from_gl(mode)?;
    let count = non_negative(count)?;
    if first < 0 {
        return Err(GlError::InvalidValue);
    }
    check_unmapped(c, false)?;
    c.check_draw_framebuffer()?;
    c.check_program_samplers()?;
    if !c.arrays.position().enabled || count == 0 {
        return Ok(());
    }
    // Elements past u32::MAX do not exist.
    let count = count.min((u32::MAX - first as u32) as usize + 1);
    with_arrays(c, |c, arrays| {
        let cur = c.state.current;
        let fetch = VertexFetcher::new(&arrays.inputs(), &cur);
        // SAFETY: enabled client arrays are the program's promise; buffers are bounds-checked.
        let src = unsafe { FetchSource::new(fetch, first as u32, count) };
        crate::context::draw::draw(c, mode, &src, None);
    });
    Ok(())
}

/// Runs `f` with the context's vertex-array state moved out, so that a draw reads the
/// arrays while it renders into the context; the state is put back even if `f` panics.
fn with_arrays<R>(c: &mut Context, f: impl FnOnce(&mut Context, &ArrayState) -> R) -> R {
    let arrays = std::mem::take(&mut c.arrays);
    let r = catch_unwind(AssertUnwindSafe(|| f(c, &arrays)));
    c.arrays = arrays;
    r.unwrap_or_else(|p| resume_unwind(p))
}

/// Reads `count` indices of `ty` from the bound element buffer (offset `ptr`) or client
/// memory; indices beyond the end of a buffer are dropped.
fn read_indices(c: &Context, count: usize, ty: DataType, ptr: usize) -> GlResult<Vec<u32>> {
    let size = ty.size();
    let bytes: &[u8] = if c.arrays.vao.element_buffer != 0 {
        let data = c
            .arrays
            .buffer_data(c.arrays.vao.element_buffer)
            .unwrap_or(&[]);
        let avail = data.len().saturating_sub(ptr) / size;
        let n = count.min(avail);
        // An offset at or past the end gives no indices (n == 0), not a slice panic.
        let start = ptr.min(data.len());
        &data[start..start + n * size]
    } else {
        // Null, or an element-buffer offset given with no buffer bound (null + offset):
        // never client memory.
        if ptr < 4096 {
            return Ok(Vec::new());
        }
        // SAFETY: the program promises `count` indices at a non-null client pointer.
        unsafe { std::slice::from_raw_parts(ptr as *const u8, count * size) }
    };
    let mut out = Vec::new();
    out.try_reserve_exact(bytes.len() / size)
        .map_err(|_| GlError::OutOfMemory)?;
    // One loop per type (not a type match per index), so each is a plain widening copy.
    match ty {
        DataType::UByte => out.extend(bytes.iter().map(|&b| b as u32)),
        DataType::UShort => out.extend(
            bytes
                .chunks_exact(2)
                .map(|b| u16::from_ne_bytes([b[0], b[1]]) as u32),
        ),
        _ => out.extend(
            bytes
                .chunks_exact(4)
                .map(|b| u32::from_ne_bytes([b[0], b[1], b[2], b[3]])),
        ),
    }
    Ok(out)
}

/// Whether indices `lo..=hi` (`n` of them) are read as a range of the arrays rather than
/// as a list of their distinct vertices.
fn compact(lo: u32, hi: u32, n: usize) -> bool {
    ((hi - lo) as usize) < n * 4 + 1024
}

/// Draws vertices `lo + idx[k]` of the arrays (`idx` relative to `lo`, each below
/// `range`).
fn draw_range(
    c: &mut Context,
    arrays: &ArrayState,
    mode: Primitive,
    lo: u32,
    range: usize,
    idx: &[u32],
) {
    let cur = c.state.current;
    let fetch = VertexFetcher::new(&arrays.inputs(), &cur);
    // SAFETY: as in draw_arrays.
    let src = unsafe { FetchSource::new(fetch, lo, range) };
    crate::context::draw::draw(c, mode, &src, Some(idx));
}

/// The `count` 32-bit indices at byte offset `ptr` of the bound element buffer, borrowed
/// from its store (those past its end dropped, as [`read_indices`] drops them); `None`
/// without a bound buffer or when the offset is not 4-byte aligned in memory.
fn buffer_indices_u32(arrays: &ArrayState, count: usize, ptr: usize) -> Option<&[u32]> {
    if arrays.vao.element_buffer == 0 {
        return None;
    }
    let data = arrays.buffer_data(arrays.vao.element_buffer).unwrap_or(&[]);
    let start = ptr.min(data.len());
    let n = count.min((data.len() - start) / 4);
    // SAFETY: every bit pattern is a valid u32; `align_to` reinterprets only the aligned
    // middle part.
    let (head, mid, _) = unsafe { data[start..start + n * 4].align_to::<u32>() };
    (head.is_empty() && mid.len() == n).then_some(mid)
}

/// glDrawElements and glDrawElementsBaseVertex (ARB_draw_elements_base_vertex) on the
/// current context (shared by the range and multi-draw calls): `base` is added to every
/// index after it is read. Under GL_PRIMITIVE_RESTART an index equal to the restart index (compared before `base` is
/// added, as GL 3.2 says) ends the primitive: the runs between such indices are drawn
/// as draws of their own.
pub(crate) fn draw_elements_base(
    c: &mut Context,
    mode: GLenum,
    count: GLsizei,
    type_: GLenum,
    indices: *const GLvoid,
    base: GLint,
) -> GlResult<()> {
    let mode = Primitive::from_gl(mode)?;
    let count = non_negative(count)?;
    let ty = index_type(type_)?;
    check_unmapped(c, true)?;
    c.check_draw_framebuffer()?;
    c.check_program_samplers()?;
    if !c.arrays.position().enabled || count == 0 {
        return Ok(());
    }
    // 32-bit indices in a buffer object, from 0 and compact (the usual mesh), are drawn
    // from the buffer's store without a copy.
    let restart = c.arrays.primitive_restart.then_some(c.arrays.restart_index);
    if ty == DataType::UInt && c.arrays.vao.element_buffer != 0 && base == 0 && restart.is_none() {
        let drawn = with_arrays(c, |c, arrays| {
            let Some(idx) = buffer_indices_u32(arrays, count, indices as usize) else {
                return false;
            };
            match crate::simd::scan::min_max(idx) {
                None => true,
                Some((0, hi)) if compact(0, hi, idx.len()) => {
                    draw_range(c, arrays, mode, 0, hi as usize + 1, idx);
                    true
                }
                Some(_) => false,
            }
        });
        if drawn {
            return Ok(());
        }
    }
    let idx = read_indices(c, count, ty, indices as usize)?;
    let Some(r) = restart else {
        return draw_list(c, mode, idx, base);
    };
    for run in idx.split(|&i| i == r).filter(|run| !run.is_empty()) {
        draw_list(c, mode, run.to_vec(), base)?;
    }
    Ok(())
}

/// Draws the vertices `idx` names, each plus `base` (wrapping: a negative result is
/// undefined in GL and reads nothing from a buffer).
fn draw_list(c: &mut Context, mode: Primitive, mut idx: Vec<u32>, base: GLint) -> GlResult<()> {
    if base != 0 {
        idx.iter_mut()
            .for_each(|i| *i = i.wrapping_add_signed(base));
    }
    let Some((lo, hi)) = crate::simd::scan::min_max(&idx) else {
        return Ok(());
    };
    // A compact index range is read straight from the arrays (vertex `i - lo` of the
    // range); a sparse one is fetched into a list of its distinct vertices.
    if compact(lo, hi, idx.len()) {
        if lo != 0 {
            idx.iter_mut().for_each(|i| *i -= lo);
        }
        let range = (hi - lo) as usize + 1;
        with_arrays(c, |c, arrays| draw_range(c, arrays, mode, lo, range, &idx));
        return Ok(());
    }
    let fetch = VertexFetcher::new(&c.arrays.inputs(), &c.state.current);
    // Generic attribute arrays (a vertex shader's) are gathered with the vertices.
    let generic = c.arrays.vao.generic[1..].iter().any(|a| a.enabled);
    let (verts, local): (Gathered, Vec<u32>) = {
        let mut map: HashMap<u32, u32> = HashMap::new();
        let mut v = Gathered::default();
        let mut local = Vec::with_capacity(idx.len());
        for &i in &idx {
            let k = *map.entry(i).or_insert_with(|| {
                // SAFETY: as in draw_arrays.
                v.verts.push(unsafe { fetch.fetch(i) });
                if generic {
                    // SAFETY: as in draw_arrays.
                    v.generic
                        .push(std::array::from_fn(|k| unsafe { fetch.generic(k, i) }));
                }
                (v.verts.len() - 1) as u32
            });
            local.push(k);
        }
        (v, local)
    };
    crate::context::draw::draw(c, mode, &verts, Some(&local));
    Ok(())
}

/// The elements glDrawArrays(first, count) reads, validated as it validates them.
pub(crate) fn array_range(first: GLint, count: GLsizei) -> GlResult<Elements> {
    let count = non_negative(count)?;
    if first < 0 {
        return Err(GlError::InvalidValue);
    }
    Ok(Elements::Range(first as u32, count))
}

/// The indices glDrawElements reads, validated as it validates them (none are read while
/// the vertex array is disabled, since nothing is drawn).
pub(crate) fn element_list(
    c: &Context,
    count: GLsizei,
    type_: GLenum,
    indices: *const GLvoid,
) -> GlResult<Elements> {
    let count = non_negative(count)?;
    let ty = index_type(type_)?;
    if count == 0 || !c.arrays.position().enabled {
        return Ok(Elements::List(Vec::new()));
    }
    read_indices(c, count, ty, indices as usize).map(Elements::List)
}

#[cfg(test)]
mod tests {
    use super::buffer_indices_u32;
    use crate::context::arrays::{ArrayState, BufferObject};

    #[test]
    fn borrowed_indices_are_the_copied_ones() {
        let words: Vec<u32> = (0..64u32).map(|i| i.wrapping_mul(0x9e37_79b9)).collect();
        let bytes: Vec<u8> = words.iter().flat_map(|w| w.to_ne_bytes()).collect();
        let mut a = ArrayState::default();
        assert_eq!(buffer_indices_u32(&a, 4, 0), None);
        let b = BufferObject {
            data: crate::context::store::Store::copy_of(&bytes).unwrap(),
            ..Default::default()
        };
        a.buffers.insert(3, Some(b));
        a.vao.element_buffer = 3;
        let store = a.buffer_data(3).unwrap();
        for ptr in 0..300 {
            for count in [0, 1, 5, 63, 64, 65, 1000] {
                // What `read_indices` copies.
                let avail = store.len().saturating_sub(ptr) / 4;
                let start = ptr.min(store.len());
                let want: Vec<u32> = store[start..start + count.min(avail) * 4]
                    .chunks_exact(4)
                    .map(|b| u32::from_ne_bytes([b[0], b[1], b[2], b[3]]))
                    .collect();
                match buffer_indices_u32(&a, count, ptr) {
                    Some(got) => assert_eq!(got, want.as_slice(), "{ptr} {count}"),
                    // Only a misaligned start is refused.
                    None => assert!(
                        !(store.as_ptr() as usize + start).is_multiple_of(4) && !want.is_empty()
                    ),
                }
            }
        }
    }
}
