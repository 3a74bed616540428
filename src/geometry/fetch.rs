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
    let data = if arr.buffer != 0 {
        Some(arrays.buffer_data(arr.buffer)?)
    } else {
        None
    };
    // SAFETY: forwarded from the caller.
    unsafe { fetch_from(data, arr, index, normalized, fill) }
}

/// [`fetch_attr`] with the array's buffer object already looked up: `data` is the
/// buffer's store when `arr.buffer != 0` (`None` for client memory).
///
/// # Safety
/// As [`fetch_attr`].
#[inline]
unsafe fn fetch_from(
    data: Option<&[u8]>,
    arr: &ArrayPointer,
    index: u32,
    normalized: bool,
    fill: [f32; 4],
) -> Option<[f32; 4]> {
    let esize = arr.size as usize * arr.ty.size();
    let off = (index as usize).checked_mul(arr.byte_stride())?;
    let base: *const u8 = if let Some(data) = data {
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
    let n = arr.size as usize;
    // SAFETY (all three loops): buffer reads were bounds-checked; client pointers are the
    // program's promise. The two common types get their own loops (the same conversion
    // as `read_component`) instead of a type match per component.
    unsafe {
        match arr.ty {
            DataType::Float => {
                for (c, o) in out.iter_mut().enumerate().take(n) {
                    *o = base.add(c * 4).cast::<f32>().read_unaligned();
                }
            }
            DataType::UByte if normalized => {
                for (c, o) in out.iter_mut().enumerate().take(n) {
                    *o = base.add(c).read() as f32 * (1.0f32 / 255.0);
                }
            }
            ty => {
                for (c, o) in out.iter_mut().enumerate().take(n) {
                    *o = read_component(base.add(c * ty.size()), ty, normalized);
                }
            }
        }
    }
    Some(out)
}

/// One enabled array of a draw with its buffer object looked up once.
#[derive(Clone, Copy)]
struct Source<'a> {
    arr: &'a ArrayPointer,
    /// The buffer's store (`None` for client memory).
    data: Option<&'a [u8]>,
}

impl<'a> Source<'a> {
    /// The array `arr` when enabled and readable; `Err(())` when its buffer object is gone
    /// (every element then reads as missing).
    fn new(arrays: &'a ArrayState, arr: &'a ArrayPointer) -> Option<Result<Self, ()>> {
        if !arr.enabled {
            return None;
        }
        if arr.buffer == 0 {
            return Some(Ok(Source { arr, data: None }));
        }
        Some(
            arrays
                .buffer_data(arr.buffer)
                .map(|d| Source { arr, data: Some(d) })
                .ok_or(()),
        )
    }

    /// Element `index`, as [`fetch_attr`].
    ///
    /// # Safety
    /// As [`fetch_attr`].
    #[inline]
    unsafe fn get(
        src: &Result<Self, ()>,
        index: u32,
        normalized: bool,
        fill: [f32; 4],
    ) -> Option<[f32; 4]> {
        let s = src.as_ref().ok()?;
        // SAFETY: forwarded from the caller.
        unsafe { fetch_from(s.data, s.arr, index, normalized, fill) }
    }
}

/// The enabled arrays of a draw, resolved once (buffer objects looked up per draw, not
/// per vertex and attribute).
pub struct VertexFetcher<'a> {
    /// A vertex at the origin with the current attributes, what every fetch starts from.
    base: VertexIn,
    /// Whether any texture-coordinate array is enabled.
    any_texcoord: bool,
    vertex: Option<Result<Source<'a>, ()>>,
    color: Option<Result<Source<'a>, ()>>,
    normal: Option<Result<Source<'a>, ()>>,
    texcoord: [Option<Result<Source<'a>, ()>>; MAX_TEXTURE_UNITS],
    edge_flag: Option<Result<Source<'a>, ()>>,
    secondary: Option<Result<Source<'a>, ()>>,
    fog_coord: Option<Result<Source<'a>, ()>>,
}

impl<'a> VertexFetcher<'a> {
    /// Resolves the enabled arrays of `arrays`; disabled ones read from `cur`.
    pub fn new(arrays: &'a ArrayState, cur: &'a CurrentAttribs) -> Self {
        let texcoord: [_; MAX_TEXTURE_UNITS] =
            std::array::from_fn(|u| Source::new(arrays, &arrays.texcoord[u]));
        VertexFetcher {
            base: VertexIn::with_current([0.0, 0.0, 0.0, 1.0], cur),
            any_texcoord: texcoord.iter().any(Option::is_some),
            texcoord,
            vertex: Source::new(arrays, &arrays.vertex),
            color: Source::new(arrays, &arrays.color),
            normal: Source::new(arrays, &arrays.normal),
            edge_flag: Source::new(arrays, &arrays.edge_flag),
            secondary: Source::new(arrays, &arrays.secondary_color),
            fog_coord: Source::new(arrays, &arrays.fog_coord),
        }
    }

    /// The position of vertex `index` (what [`Self::fetch`] gives as `pos`).
    ///
    /// # Safety
    /// As [`fetch_attr`]: an enabled client-memory vertex array must be valid for `index`.
    #[inline]
    pub unsafe fn position(&self, index: u32) -> [f32; 4] {
        const ORIGIN: [f32; 4] = [0.0, 0.0, 0.0, 1.0];
        match &self.vertex {
            // SAFETY: forwarded from the caller.
            Some(s) => unsafe { Source::get(s, index, false, ORIGIN) }.unwrap_or(ORIGIN),
            None => self.base.pos,
        }
    }

    /// Fetches vertex `index` from the enabled arrays; disabled arrays give the current
    /// values.
    ///
    /// # Safety
    /// As [`fetch_attr`]: enabled client-memory arrays must be valid for `index`.
    #[inline]
    pub unsafe fn fetch(&self, index: u32) -> VertexIn {
        const ORIGIN: [f32; 4] = [0.0, 0.0, 0.0, 1.0];
        let mut v = self.base;
        // SAFETY: forwarded from the caller.
        unsafe {
            v.pos = self.position(index);
            if let Some(s) = &self.color {
                v.color = Source::get(s, index, true, ORIGIN).unwrap_or(ORIGIN);
            }
            if let Some(s) = &self.normal {
                if let Some(n) = Source::get(s, index, true, [0.0; 4]) {
                    v.normal = [n[0], n[1], n[2]];
                }
            }
            if self.any_texcoord {
                for (u, s) in self.texcoord.iter().enumerate() {
                    if let Some(s) = s {
                        v.texcoord[u] = Source::get(s, index, false, ORIGIN).unwrap_or(ORIGIN);
                    }
                }
            }
            if let Some(s) = &self.edge_flag {
                if let Some(e) = Source::get(s, index, false, [1.0; 4]) {
                    v.edge_flag = e[0] != 0.0;
                }
            }
            if let Some(s) = &self.secondary {
                v.secondary = Source::get(s, index, true, ORIGIN).unwrap_or(ORIGIN);
            }
            if let Some(s) = &self.fog_coord {
                v.fog_coord = Source::get(s, index, false, [0.0; 4]).map_or(0.0, |f| f[0]);
            }
        }
        v
    }
}

/// Fetches vertex `index` from the enabled arrays; disabled arrays give the current values.
///
/// # Safety
/// As [`fetch_attr`]: enabled client-memory arrays must be valid for `index`.
pub unsafe fn fetch_vertex(arrays: &ArrayState, cur: &CurrentAttribs, index: u32) -> VertexIn {
    // SAFETY: forwarded from the caller.
    unsafe { VertexFetcher::new(arrays, cur).fetch(index) }
}
