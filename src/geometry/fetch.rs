//! Vertex fetch: reads one vertex's attributes from client arrays or buffer objects (or the
//! current values when an array is off) and converts them to f32 as llvmpipe's draw module
//! does (`float(u) * f32(1/255)` for normalised unsigned bytes).
//!
//! Reads from buffer objects are bounds-checked: an element past the end of its buffer
//! reads as (0, 0, 0, 1) rather than outside the store.

use crate::pipe::arrays::MAX_GENERIC;
use crate::pipe::{ArrayInput, ArrayPointer, DataType, VertexArrays};
use crate::pipe::{CurrentAttribs, MAX_TEXTURE_UNITS};

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

/// A component read as f32 (`v`), normalised when `normalized`: times `scale` as an f32
/// product, clamped at −1 when `SIGNED`.
#[inline(always)]
fn norm_f32<const SIGNED: bool>(v: f32, normalized: bool, scale: f32) -> f32 {
    match (normalized, SIGNED) {
        (false, _) => v,
        (true, false) => v * scale,
        (true, true) => (v * scale).max(-1.0),
    }
}

/// A 32-bit integer component (`v`, exact in f64) as f32, normalised when `normalized`:
/// divided by `max` in f64, clamped at −1 when `SIGNED`.
#[inline(always)]
fn norm_f64<const SIGNED: bool>(v: f64, normalized: bool, max: f64) -> f32 {
    match (normalized, SIGNED) {
        (false, _) => v as f32,
        (true, false) => (v / max) as f32,
        (true, true) => ((v / max) as f32).max(-1.0),
    }
}

/// Reads a component of `ty` at `p` as f32, normalised or not.
///
/// # Safety
/// `p` must be readable for `ty.size()` bytes (any alignment).
#[inline]
unsafe fn read_component(p: *const u8, ty: DataType, normalized: bool) -> f32 {
    let n = normalized;
    // SAFETY: the caller guarantees `p` is readable for the component's size; unaligned
    // reads are used because client arrays need not be aligned.
    unsafe {
        match ty {
            DataType::Byte => {
                norm_f32::<true>(p.cast::<i8>().read_unaligned() as f32, n, 1.0 / 127.0)
            }
            DataType::UByte => norm_f32::<false>(p.read_unaligned() as f32, n, 1.0 / 255.0),
            DataType::Short => {
                norm_f32::<true>(p.cast::<i16>().read_unaligned() as f32, n, 1.0 / 32767.0)
            }
            DataType::UShort => {
                norm_f32::<false>(p.cast::<u16>().read_unaligned() as f32, n, 1.0 / 65535.0)
            }
            DataType::Int => {
                norm_f64::<true>(p.cast::<i32>().read_unaligned() as f64, n, 2147483647.0)
            }
            DataType::UInt => {
                norm_f64::<false>(p.cast::<u32>().read_unaligned() as f64, n, 4294967295.0)
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
    input: ArrayInput<'_>,
    index: u32,
    normalized: bool,
    fill: [f32; 4],
) -> Option<[f32; 4]> {
    let arr = input.arr;
    let data = if arr.buffer != 0 {
        Some(input.data?)
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
///
/// Always inlined: called out of line, its `Option<[f32; 4]>` went back through memory in
/// two 8-byte stores read as one 16-byte load (a store-forwarding stall), and that load
/// was 70% of its samples in a frame of 10k sprites. The rare layouts are converted out of
/// line ([`convert_other`]).
#[inline(always)]
unsafe fn fetch_from(
    data: Option<&[u8]>,
    arr: &ArrayPointer,
    index: u32,
    normalized: bool,
    fill: [f32; 4],
) -> Option<[f32; 4]> {
    let base = element(data, arr, index)?;
    let n = arr.size as usize;
    // SAFETY: (all arms) buffer reads were bounds-checked; client pointers are the
    // program's promise. The common layouts are read as whole vectors: filled component
    // by component, `out` went through the stack in four 4-byte stores read back as one
    // 16-byte load, a store-forwarding stall that was 5% of a 200k-triangle frame. The
    // conversions are the same as `read_component`'s.
    unsafe {
        match (arr.ty, n) {
            (DataType::Float, 2..=4) => Some(floats(base, n, fill)),
            (DataType::UByte, 4) if normalized => {
                let b = base.cast::<[u8; 4]>().read_unaligned();
                Some(b.map(|c| c as f32 * (1.0f32 / 255.0)))
            }
            (DataType::UByte, 3) if normalized => {
                let [r, g, b] = base.cast::<[u8; 3]>().read_unaligned();
                let s = 1.0f32 / 255.0;
                Some([r as f32 * s, g as f32 * s, b as f32 * s, fill[3]])
            }
            _ => Some(convert_other(base, arr.ty, n, normalized, fill)),
        }
    }
}

/// Where element `index` of `arr` starts: in `data` (the buffer's store) when it lies
/// inside it, else in client memory (`None` for a null pointer plus a small offset).
#[inline(always)]
fn element(data: Option<&[u8]>, arr: &ArrayPointer, index: u32) -> Option<*const u8> {
    let esize = arr.size as usize * arr.ty.size();
    let off = (index as usize).checked_mul(arr.byte_stride())?;
    if let Some(data) = data {
        let start = arr.ptr.checked_add(off)?;
        if start.checked_add(esize)? > data.len() {
            return None;
        }
        // SAFETY: start + esize <= data.len() was checked above.
        return Some(unsafe { data.as_ptr().add(start) });
    }
    // A null pointer plus a small offset (glInterleavedArrays(fmt, 0, NULL), or a VBO
    // offset given with no buffer bound) is never client memory: treat it as null.
    if arr.ptr < NULL_PAGE {
        return None;
    }
    Some(arr.ptr.checked_add(off)? as *const u8)
}

/// Element `index` of integer array `arr` (glVertexAttribIPointer) as the bits of its
/// integers, sign- or zero-extended by type, over (0, 0, 0, 1); `None` as [`fetch_from`].
///
/// # Safety
/// As [`fetch_attr`].
unsafe fn fetch_int(data: Option<&[u8]>, arr: &ArrayPointer, index: u32) -> Option<[f32; 4]> {
    let p = element(data, arr, index)?;
    let mut out = [0, 0, 0, 1u32];
    for (k, o) in out.iter_mut().enumerate().take(arr.size as usize) {
        // SAFETY: `element` checked the element against a buffer's store, or client
        // memory is the program's promise; reads are unaligned.
        *o = unsafe {
            match arr.ty {
                DataType::Byte => p.cast::<i8>().add(k).read() as i32 as u32,
                DataType::UByte => p.add(k).read() as u32,
                DataType::Short => p.cast::<i16>().add(k).read_unaligned() as i32 as u32,
                DataType::UShort => p.cast::<u16>().add(k).read_unaligned() as u32,
                DataType::Int | DataType::UInt => p.cast::<u32>().add(k).read_unaligned(),
                // glVertexAttribIPointer takes no float type.
                DataType::Float | DataType::Double => 0,
            }
        };
    }
    Some(out.map(f32::from_bits))
}

/// The `n` (2 to 4) floats at `p` over `fill`, read as one vector: the float layouts of
/// [`fetch_from`] and [`FloatPositions::get`].
///
/// # Safety
/// `p` must be readable for `n` floats.
#[inline(always)]
unsafe fn floats(p: *const u8, n: usize, fill: [f32; 4]) -> [f32; 4] {
    // SAFETY: (all arms) forwarded from the caller.
    unsafe {
        match n {
            4 => p.cast::<[f32; 4]>().read_unaligned(),
            3 => {
                let [x, y, z] = p.cast::<[f32; 3]>().read_unaligned();
                [x, y, z, fill[3]]
            }
            _ => {
                let [x, y] = p.cast::<[f32; 2]>().read_unaligned();
                [x, y, fill[2], fill[3]]
            }
        }
    }
}

/// The `n` components of type `ty` at `base` over `fill`: [`fetch_from`]'s layouts other
/// than its vector fast paths.
///
/// # Safety
/// `base` must be readable for `n` components of `ty`.
#[inline(never)]
unsafe fn convert_other(
    base: *const u8,
    ty: DataType,
    n: usize,
    normalized: bool,
    fill: [f32; 4],
) -> [f32; 4] {
    let mut out = fill;
    // SAFETY: (all arms) forwarded from the caller.
    unsafe {
        match ty {
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
    out
}

/// A draw's positions stored as 2 to 4 floats per element, readable without checks
/// ([`VertexFetcher::float_positions`]).
pub struct FloatPositions<'a> {
    /// The first element's first byte.
    start: *const u8,
    /// Bytes from one element to the next.
    stride: usize,
    /// Floats per element (2 to 4).
    size: usize,
    /// Elements readable from `start`.
    count: usize,
    /// The buffer store or client memory read.
    _data: std::marker::PhantomData<&'a [u8]>,
}

impl FloatPositions<'_> {
    /// The number of positions.
    pub fn count(&self) -> usize {
        self.count
    }

    /// Position `i` (`i < count()`, checked), with z = 0 and w = 1 where the array has
    /// no such component: the value [`VertexFetcher::position`] reads.
    #[inline(always)]
    pub fn get(&self, i: usize) -> [f32; 4] {
        assert!(i < self.count);
        // SAFETY: `float_positions` checked that `count` elements of `size` floats at
        // `stride` bytes from `start` are inside the store, or its caller promised that
        // client memory holds them.
        unsafe {
            floats(
                self.start.add(i * self.stride),
                self.size,
                [0.0, 0.0, 0.0, 1.0],
            )
        }
    }
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
    fn new(input: &ArrayInput<'a>) -> Option<Result<Self, ()>> {
        let arr = input.arr;
        if !arr.enabled {
            return None;
        }
        if arr.buffer == 0 {
            return Some(Ok(Source { arr, data: None }));
        }
        Some(input.data.map(|d| Source { arr, data: Some(d) }).ok_or(()))
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
    generic: [Option<Result<Source<'a>, ()>>; MAX_GENERIC],
}

impl<'a> VertexFetcher<'a> {
    /// Resolves the enabled arrays of `arrays`; disabled ones read from `cur`.
    pub fn new(arrays: &VertexArrays<'a>, cur: &'a CurrentAttribs) -> Self {
        let texcoord: [_; MAX_TEXTURE_UNITS] =
            std::array::from_fn(|u| Source::new(&arrays.texcoord[u]));
        VertexFetcher {
            base: VertexIn::with_current([0.0, 0.0, 0.0, 1.0], cur),
            any_texcoord: texcoord.iter().any(Option::is_some),
            texcoord,
            vertex: Source::new(&arrays.vertex),
            color: Source::new(&arrays.color),
            normal: Source::new(&arrays.normal),
            edge_flag: Source::new(&arrays.edge_flag),
            secondary: Source::new(&arrays.secondary_color),
            fog_coord: Source::new(&arrays.fog_coord),
            generic: std::array::from_fn(|k| Source::new(arrays.generic.as_ref()?.get(k)?)),
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
            Some(s) => {
                // Only a generic attribute-0 array standing for the positions is normalised.
                let norm = matches!(s, Ok(src) if src.arr.normalized);
                // SAFETY: forwarded from the caller.
                unsafe { Source::get(s, index, norm, ORIGIN) }.unwrap_or(ORIGIN)
            }
            None => self.base.pos,
        }
    }

    /// The positions of elements `base..base + count` as a [`FloatPositions`] when the
    /// vertex array holds 2 to 4 floats per element and the whole range can be read
    /// (inside its buffer object's store, or past the null page in client memory): read
    /// that way, a pass over the positions costs no conversion, bounds check or
    /// `Option` per vertex. `None` otherwise (read them with [`Self::position`]).
    ///
    /// # Safety
    /// As [`fetch_attr`]: an enabled client-memory vertex array must be valid for every
    /// index in the range.
    pub unsafe fn float_positions(&self, base: u32, count: usize) -> Option<FloatPositions<'a>> {
        let Some(Ok(src)) = &self.vertex else {
            return None;
        };
        let arr = src.arr;
        if arr.ty != DataType::Float || !(2..=4).contains(&arr.size) || count == 0 {
            return None;
        }
        u32::try_from(count - 1).ok()?.checked_add(base)?;
        let size = arr.size as usize;
        let stride = arr.byte_stride();
        let first = (base as usize).checked_mul(stride)?;
        // Bytes from the first element's start to the last element's end.
        let span = (count - 1).checked_mul(stride)?.checked_add(size * 4)?;
        let start: *const u8 = match src.data {
            Some(data) => {
                let start = arr.ptr.checked_add(first)?;
                if start.checked_add(span)? > data.len() {
                    return None;
                }
                // SAFETY: start + span <= data.len() was checked above.
                unsafe { data.as_ptr().add(start) }
            }
            None => {
                if arr.ptr < NULL_PAGE {
                    return None;
                }
                arr.ptr.checked_add(first)?.checked_add(span)?;
                (arr.ptr + first) as *const u8
            }
        };
        Some(FloatPositions {
            start,
            stride,
            size,
            count,
            _data: std::marker::PhantomData,
        })
    }

    /// Element `index` of generic attribute array `loc`, when it is enabled (a vertex
    /// shader's attribute; missing components and elements read as (0, 0, 0, 1)).
    ///
    /// # Safety
    /// As [`fetch_attr`]: an enabled client-memory array must be valid for `index`.
    #[inline]
    pub unsafe fn generic(&self, loc: usize, index: u32) -> Option<[f32; 4]> {
        const ORIGIN: [f32; 4] = [0.0, 0.0, 0.0, 1.0];
        let s = self.generic.get(loc)?.as_ref()?;
        if let Ok(src) = s {
            if src.arr.integer {
                const INT_ORIGIN: [f32; 4] = [0.0, 0.0, 0.0, f32::from_bits(1)];
                // SAFETY: forwarded from the caller.
                return Some(unsafe { fetch_int(src.data, src.arr, index) }.unwrap_or(INT_ORIGIN));
            }
        }
        let norm = matches!(s, Ok(src) if src.arr.normalized);
        // SAFETY: forwarded from the caller.
        Some(unsafe { Source::get(s, index, norm, ORIGIN) }.unwrap_or(ORIGIN))
    }

    /// The vertex every fetch starts from: the origin with the current attributes.
    pub fn base(&self) -> VertexIn {
        self.base
    }

    /// Fetches vertex `index` from the enabled arrays; disabled arrays give the current
    /// values.
    ///
    /// # Safety
    /// As [`fetch_attr`]: enabled client-memory arrays must be valid for `index`.
    #[inline]
    pub unsafe fn fetch(&self, index: u32) -> VertexIn {
        let mut v = self.base;
        // SAFETY: forwarded from the caller; `v` is the base vertex.
        unsafe { self.fetch_into(index, &mut v) };
        v
    }

    /// [`Self::fetch`] into `v`, writing only the attributes that have an enabled array:
    /// `v`'s other attributes must already hold [`Self::base`]'s values (a `v` that only
    /// this method writes keeps them).
    ///
    /// # Safety
    /// As [`fetch_attr`]: enabled client-memory arrays must be valid for `index`.
    #[inline]
    pub unsafe fn fetch_into(&self, index: u32, v: &mut VertexIn) {
        const ORIGIN: [f32; 4] = [0.0, 0.0, 0.0, 1.0];
        // SAFETY: forwarded from the caller.
        unsafe {
            v.pos = self.position(index);
            if let Some(s) = &self.color {
                v.color = Source::get(s, index, true, ORIGIN).unwrap_or(ORIGIN);
            }
            if let Some(s) = &self.normal {
                v.normal = match Source::get(s, index, true, [0.0; 4]) {
                    Some(n) => [n[0], n[1], n[2]],
                    None => self.base.normal,
                };
            }
            if self.any_texcoord {
                for (u, s) in self.texcoord.iter().enumerate() {
                    if let Some(s) = s {
                        v.texcoord[u] = Source::get(s, index, false, ORIGIN).unwrap_or(ORIGIN);
                    }
                }
            }
            if let Some(s) = &self.edge_flag {
                v.edge_flag = match Source::get(s, index, false, [1.0; 4]) {
                    Some(e) => e[0] != 0.0,
                    None => self.base.edge_flag,
                };
            }
            if let Some(s) = &self.secondary {
                v.secondary = Source::get(s, index, true, ORIGIN).unwrap_or(ORIGIN);
            }
            if let Some(s) = &self.fog_coord {
                v.fog_coord = Source::get(s, index, false, [0.0; 4]).map_or(0.0, |f| f[0]);
            }
        }
    }
}

/// Fetches vertex `index` from the enabled arrays; disabled arrays give the current values.
///
/// # Safety
/// As [`fetch_attr`]: enabled client-memory arrays must be valid for `index`.
pub unsafe fn fetch_vertex(
    arrays: &VertexArrays<'_>,
    cur: &CurrentAttribs,
    index: u32,
) -> VertexIn {
    // SAFETY: forwarded from the caller.
    unsafe { VertexFetcher::new(arrays, cur).fetch(index) }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Element `index` of `arr` component by component with `read_component`, the plain
    /// reading the vector fast paths of `fetch_from` must agree with. `data` is the
    /// buffer object's store (elements past its end are `None`), `None` for client memory.
    fn reference(
        data: Option<&[u8]>,
        arr: &ArrayPointer,
        index: u32,
        normalized: bool,
        fill: [f32; 4],
    ) -> Option<[f32; 4]> {
        let start = arr.ptr + index as usize * arr.byte_stride();
        let base = match data {
            Some(d) if start + arr.size as usize * arr.ty.size() > d.len() => return None,
            Some(d) => d[start..].as_ptr(),
            None => start as *const u8,
        };
        let mut out = fill;
        for (c, o) in out.iter_mut().enumerate().take(arr.size as usize) {
            // SAFETY: inside the store (checked above) or the test's client bytes.
            *o = unsafe { read_component(base.add(c * arr.ty.size()), arr.ty, normalized) };
        }
        Some(out)
    }

    /// A draw's arrays (initially GL's) and the bytes of buffer object 1, if any.
    struct Arrays {
        vertex: ArrayPointer,
        color: ArrayPointer,
        normal: ArrayPointer,
        texcoord: [ArrayPointer; MAX_TEXTURE_UNITS],
        edge_flag: ArrayPointer,
        secondary_color: ArrayPointer,
        fog_coord: ArrayPointer,
        buffer: Option<Vec<u8>>,
    }

    impl Arrays {
        /// The store of buffer `name` (only 1 exists).
        fn buffer_data(&self, name: u32) -> Option<&[u8]> {
            self.buffer.as_deref().filter(|_| name == 1)
        }

        /// `arr` with its buffer's bytes.
        fn input<'a>(&'a self, arr: &'a ArrayPointer) -> ArrayInput<'a> {
            ArrayInput {
                arr,
                data: self.buffer_data(arr.buffer),
            }
        }

        /// What a draw hands the fetch.
        fn inputs(&self) -> VertexArrays<'_> {
            VertexArrays {
                vertex: self.input(&self.vertex),
                color: self.input(&self.color),
                normal: self.input(&self.normal),
                texcoord: std::array::from_fn(|u| self.input(&self.texcoord[u])),
                edge_flag: self.input(&self.edge_flag),
                secondary_color: self.input(&self.secondary_color),
                fog_coord: self.input(&self.fog_coord),
                generic: None,
            }
        }
    }

    /// Initial arrays whose buffer object 1 holds a copy of `bytes` when `in_buffer`.
    fn arrays_over(bytes: &[u8], in_buffer: bool) -> Arrays {
        Arrays {
            vertex: ArrayPointer::new(4, DataType::Float),
            color: ArrayPointer::new(4, DataType::Float),
            normal: ArrayPointer::new(3, DataType::Float),
            texcoord: [ArrayPointer::new(4, DataType::Float); MAX_TEXTURE_UNITS],
            edge_flag: ArrayPointer::new(1, DataType::UByte),
            secondary_color: ArrayPointer::new(3, DataType::Float),
            fog_coord: ArrayPointer::new(1, DataType::Float),
            buffer: in_buffer.then(|| bytes.to_vec()),
        }
    }

    #[test]
    fn fetch_and_slot_reads_match_component_reads() {
        const TYPES: [DataType; 5] = [
            DataType::Float,
            DataType::UByte,
            DataType::Short,
            DataType::Byte,
            DataType::UShort,
        ];
        let mut next = crate::test_rng::xorshift32(0x5107_f00d);
        let bits = |v: &VertexIn| {
            let mut b: Vec<u32> = v.pos.iter().chain(&v.color).map(|f| f.to_bits()).collect();
            b.extend(
                v.normal
                    .iter()
                    .chain(v.texcoord.as_flattened())
                    .map(|f| f.to_bits()),
            );
            b.extend(v.secondary.iter().map(|f| f.to_bits()));
            b.extend([v.fog_coord.to_bits(), v.edge_flag as u32]);
            b
        };
        let mut seen_missing = 0;
        for case in 0..300 {
            // 40 vertices of 96 bytes: random bytes (so floats include NaNs and infinities).
            let bytes: Vec<u8> = (0..40 * 96).map(|_| next() as u8).collect();
            let in_buffer = case % 2 == 1;
            // A buffer object holds a shorter copy, so the last elements read as missing.
            let len = if in_buffer { 30 * 96 + 7 } else { bytes.len() };
            let mut arrays = arrays_over(&bytes[..len], in_buffer);
            let mut offset = 0;
            let mut setup =
                |arr: &mut ArrayPointer, sizes: &[i32], next: &mut dyn FnMut() -> u32| {
                    arr.enabled = !next().is_multiple_of(3);
                    arr.size = sizes[next() as usize % sizes.len()];
                    arr.ty = TYPES[next() as usize % TYPES.len()];
                    arr.stride = 96;
                    arr.buffer = in_buffer as u32;
                    let at = if in_buffer {
                        0
                    } else {
                        bytes.as_ptr() as usize
                    };
                    arr.ptr = at + offset;
                    offset += 16;
                };
            setup(&mut arrays.vertex, &[2, 3, 4], &mut next);
            setup(&mut arrays.color, &[3, 4], &mut next);
            setup(&mut arrays.normal, &[3], &mut next);
            let unit = next() as usize % 8;
            setup(&mut arrays.texcoord[unit], &[1, 2, 3, 4], &mut next);
            setup(&mut arrays.secondary_color, &[3], &mut next);
            arrays.edge_flag.enabled = next().is_multiple_of(2);
            arrays.edge_flag.stride = 96;
            arrays.edge_flag.buffer = in_buffer as u32;
            arrays.edge_flag.ptr = offset
                + if in_buffer {
                    0
                } else {
                    bytes.as_ptr() as usize
                };
            let cur = crate::pipe::CurrentAttribs {
                normal: [0.5, -0.25, 2.0],
                edge_flag: next().is_multiple_of(2),
                ..Default::default()
            };
            let inputs = arrays.inputs();
            let fetcher = VertexFetcher::new(&inputs, &cur);
            let data = arrays.buffer_data(1);
            let origin = [0.0, 0.0, 0.0, 1.0];
            let mut slot = fetcher.base();
            for _ in 0..60 {
                let i = next() % 40;
                // SAFETY: client arrays point into `bytes`, 40 elements of 96 bytes.
                let v = unsafe { fetcher.fetch(i) };
                // SAFETY: as above.
                unsafe { fetcher.fetch_into(i, &mut slot) };
                assert_eq!(bits(&slot), bits(&v), "case {case} vertex {i}");
                let read = |arr: &ArrayPointer, norm: bool, fill: [f32; 4]| {
                    reference(data, arr, i, norm, fill)
                };
                let fb = |a: Option<[f32; 4]>, f: [f32; 4]| a.unwrap_or(f).map(f32::to_bits);
                if arrays.vertex.enabled {
                    let want = read(&arrays.vertex, false, origin);
                    seen_missing += want.is_none() as u32;
                    assert_eq!(v.pos.map(f32::to_bits), fb(want, origin));
                }
                if arrays.color.enabled {
                    let want = read(&arrays.color, true, origin);
                    assert_eq!(v.color.map(f32::to_bits), fb(want, origin));
                }
                if arrays.normal.enabled {
                    let want = read(&arrays.normal, true, [0.0; 4])
                        .map_or(cur.normal, |n| [n[0], n[1], n[2]]);
                    assert_eq!(v.normal.map(f32::to_bits), want.map(f32::to_bits));
                } else {
                    assert_eq!(v.normal, cur.normal);
                }
            }
        }
        assert!(seen_missing > 50, "{seen_missing}");
    }

    /// `float_positions` reads every position of a range as `position` does, and is
    /// offered exactly when the array is 2 to 4 floats per element and the whole range is
    /// readable (for a buffer object: inside its store).
    #[test]
    fn float_positions_read_what_position_reads() {
        let mut next = crate::test_rng::xorshift32(0x0f1e_a7e5);
        let (mut offered, mut refused_range) = (0, 0);
        for case in 0..400 {
            // 64 elements of up to 24 bytes: random bytes (floats include NaNs and
            // infinities, compared bit for bit).
            let bytes: Vec<u8> = (0..64 * 24).map(|_| next() as u8).collect();
            let in_buffer = case % 2 == 1;
            let len = if in_buffer { 40 * 24 + 5 } else { bytes.len() };
            let mut arrays = arrays_over(&bytes[..len], in_buffer);
            let arr = &mut arrays.vertex;
            arr.enabled = true;
            arr.size = [1, 2, 3, 4][next() as usize % 4];
            arr.ty = [DataType::Float, DataType::Float, DataType::Short][next() as usize % 3];
            // 0 (tight) or 16 to 24 bytes.
            arr.stride = [0, 16, 20, 24][next() as usize % 4];
            arr.buffer = in_buffer as u32;
            arr.ptr = (next() % 8) as usize * 4
                + if in_buffer {
                    0
                } else {
                    bytes.as_ptr() as usize
                };
            let (base, count) = (next() % 24, 1 + next() as usize % 40);
            let cur = crate::pipe::CurrentAttribs::default();
            let inputs = arrays.inputs();
            let fetcher = VertexFetcher::new(&inputs, &cur);
            let a = &arrays.vertex;
            let floats = a.ty == DataType::Float && a.size >= 2;
            let end = a.ptr + (base as usize + count - 1) * a.byte_stride() + a.size as usize * 4;
            let inside = !in_buffer || end <= len;
            // SAFETY: client arrays point into `bytes`, whose 1536 bytes hold every
            // element of the range (offset ≤ 28, 63 strides of ≤ 24, ≤ 16 bytes).
            let fp = unsafe { fetcher.float_positions(base, count) };
            assert_eq!(fp.is_some(), floats && inside, "case {case}");
            refused_range += (floats && !inside) as u32;
            let Some(fp) = fp else { continue };
            offered += 1;
            assert_eq!(fp.count(), count);
            for i in 0..count {
                // SAFETY: as above.
                let want = unsafe { fetcher.position(base + i as u32) };
                assert_eq!(
                    fp.get(i).map(f32::to_bits),
                    want.map(f32::to_bits),
                    "case {case} {i}"
                );
            }
        }
        assert!(
            offered > 100 && refused_range > 10,
            "{offered} {refused_range}"
        );
    }
}
