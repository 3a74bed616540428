//! Vertex fetch: reads one vertex's attributes from client arrays or buffer objects (or the
//! current values when an array is off) and converts them to f32 as llvmpipe's draw module
//! does (`float(u) * f32(1/255)` for normalised unsigned bytes).
//!
//! Reads from buffer objects are bounds-checked: an element past the end of its buffer
//! reads as (0, 0, 0, 1) rather than outside the store.

use crate::context::arrays::{ArrayPointer, ArrayState, DataType};
use crate::context::state::{CurrentAttribs, MAX_TEXTURE_UNITS};

/// One vertex as the vertex stage receives it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VertexIn {
    /// Object-space position.
    pub pos: [f32; 4],
    /// Primary colour.
    pub color: [f32; 4],
    /// Normal.
    pub normal: [f32; 3],
    /// Texture coordinates, per texture unit.
    pub texcoord: [[f32; 4]; MAX_TEXTURE_UNITS],
    /// Fog coordinate (GL_FOG_COORD).
    pub fog_coord: f32,
    /// Edge flag (glEdgeFlag): whether the polygon edge starting here is a boundary edge.
    pub edge_flag: bool,
    /// Secondary colour (GL_COLOR_SUM without lighting).
    pub secondary: [f32; 4],
}

impl VertexIn {
    /// A vertex at `pos` with the current attributes.
    pub fn with_current(pos: [f32; 4], cur: &CurrentAttribs) -> Self {
        VertexIn {
            pos,
            color: cur.color,
            normal: cur.normal,
            texcoord: cur.texcoord,
            fog_coord: cur.fog_coord,
            edge_flag: cur.edge_flag,
            secondary: cur.secondary_color,
        }
    }
}

/// Reads a component of `ty` at `p` as f32, normalised or not.
///
/// # Safety
/// `p` must be readable for `ty.size()` bytes (any alignment).
#[inline]
unsafe fn read_component(p: *const u8, ty: DataType, normalized: bool) -> f32 {
    // SAFETY: the caller guarantees `p` is readable for the component's size; unaligned
    // reads are used because client arrays need not be aligned.
    unsafe {
        match ty {
            DataType::Byte => {
                let v = p.cast::<i8>().read_unaligned() as f32;
                if normalized {
                    (v * (1.0 / 127.0)).max(-1.0)
                } else {
                    v
                }
            }
            DataType::UByte => {
                let v = p.read_unaligned() as f32;
                if normalized {
                    v * (1.0f32 / 255.0)
                } else {
                    v
                }
            }
            DataType::Short => {
                let v = p.cast::<i16>().read_unaligned() as f32;
                if normalized {
                    (v * (1.0 / 32767.0)).max(-1.0)
                } else {
                    v
                }
            }
            DataType::UShort => {
                let v = p.cast::<u16>().read_unaligned() as f32;
                if normalized {
                    v * (1.0f32 / 65535.0)
                } else {
                    v
                }
            }
            DataType::Int => {
                let v = p.cast::<i32>().read_unaligned();
                if normalized {
                    ((v as f64 / 2147483647.0) as f32).max(-1.0)
                } else {
                    v as f32
                }
            }
            DataType::UInt => {
                let v = p.cast::<u32>().read_unaligned();
                if normalized {
                    (v as f64 / 4294967295.0) as f32
                } else {
                    v as f32
                }
            }
            DataType::Float => p.cast::<f32>().read_unaligned(),
            DataType::Double => p.cast::<f64>().read_unaligned() as f32,
        }
    }
}

/// Client "pointers" below this address are null plus an offset, never real memory.
const NULL_PAGE: usize = 4096;

/// Reads element `index` of `arr` into a vec4 whose missing components come from `fill`.
/// Returns `None` when the array has no data (null pointer, deleted buffer, past the end).
///
/// # Safety
/// For client-memory arrays (`arr.buffer == 0`) the pointer must be valid for the element,
/// as the GL API requires of the calling program.
pub unsafe fn fetch_attr(
    arrays: &ArrayState,
    arr: &ArrayPointer,
    index: u32,
    normalized: bool,
    fill: [f32; 4],
) -> Option<[f32; 4]> {
    let esize = arr.size as usize * arr.ty.size();
    let off = (index as usize).checked_mul(arr.byte_stride())?;
    let base: *const u8 = if arr.buffer != 0 {
        let data = arrays.buffer_data(arr.buffer)?;
        let start = arr.ptr.checked_add(off)?;
        if start.checked_add(esize)? > data.len() {
            return None;
        }
        // SAFETY: start + esize <= data.len() was checked above.
        unsafe { data.as_ptr().add(start) }
    } else {
        // A null pointer plus a small offset (glInterleavedArrays(fmt, 0, NULL), or a VBO
        // offset given with no buffer bound) is never client memory: treat it as null.
        if arr.ptr < NULL_PAGE {
            return None;
        }
        arr.ptr.checked_add(off)? as *const u8
    };
    let mut out = fill;
    for (c, o) in out.iter_mut().enumerate().take(arr.size as usize) {
        // SAFETY: buffer reads were bounds-checked; client pointers are the program's promise.
        *o = unsafe { read_component(base.add(c * arr.ty.size()), arr.ty, normalized) };
    }
    Some(out)
}

/// Fetches vertex `index` from the enabled arrays; disabled arrays give the current values.
///
/// # Safety
/// As [`fetch_attr`]: enabled client-memory arrays must be valid for `index`.
pub unsafe fn fetch_vertex(arrays: &ArrayState, cur: &CurrentAttribs, index: u32) -> VertexIn {
    let mut v = VertexIn::with_current([0.0, 0.0, 0.0, 1.0], cur);
    // SAFETY: forwarded from the caller.
    unsafe {
        if arrays.vertex.enabled {
            v.pos = fetch_attr(arrays, &arrays.vertex, index, false, [0.0, 0.0, 0.0, 1.0])
                .unwrap_or([0.0, 0.0, 0.0, 1.0]);
        }
        if arrays.color.enabled {
            v.color = fetch_attr(arrays, &arrays.color, index, true, [0.0, 0.0, 0.0, 1.0])
                .unwrap_or([0.0, 0.0, 0.0, 1.0]);
        }
        if arrays.normal.enabled {
            if let Some(n) = fetch_attr(arrays, &arrays.normal, index, true, [0.0; 4]) {
                v.normal = [n[0], n[1], n[2]];
            }
        }
        for (u, arr) in arrays.texcoord.iter().enumerate() {
            if arr.enabled {
                v.texcoord[u] = fetch_attr(arrays, arr, index, false, [0.0, 0.0, 0.0, 1.0])
                    .unwrap_or([0.0, 0.0, 0.0, 1.0]);
            }
        }
        if arrays.edge_flag.enabled {
            if let Some(e) = fetch_attr(arrays, &arrays.edge_flag, index, false, [1.0; 4]) {
                v.edge_flag = e[0] != 0.0;
            }
        }
        if arrays.secondary_color.enabled {
            let s = &arrays.secondary_color;
            v.secondary = fetch_attr(arrays, s, index, true, [0.0, 0.0, 0.0, 1.0])
                .unwrap_or([0.0, 0.0, 0.0, 1.0]);
        }
        if arrays.fog_coord.enabled {
            v.fog_coord =
                fetch_attr(arrays, &arrays.fog_coord, index, false, [0.0; 4]).map_or(0.0, |f| f[0]);
        }
    }
    v
}
