//! Client vertex array state: the gl*Pointer calls, glEnable/DisableClientState (and
//! glEnable/glDisable/glIsEnabled on a client array) and glInterleavedArrays, Mesa's
//! compound of those calls for one of the 14 fixed layouts.

use super::arrays::{ArrayPointer, DataType};
use super::error::{GlError, GlResult};
use super::state::Cap;
use super::Context;
use crate::gl::enums::*;
use crate::gl::glext_enums::*;
use crate::gl::types::*;

/// Which client array a call names.
#[derive(Clone, Copy)]
pub(crate) enum ClientArray {
    Vertex,
    Color,
    Normal,
    TexCoord,
    EdgeFlag,
    Index,
    SecondaryColor,
    FogCoord,
}

impl ClientArray {
    /// The client array `cap` names, if any.
    pub(crate) fn from_cap(cap: GLenum) -> Option<Self> {
        Some(match cap {
            GL_VERTEX_ARRAY => Self::Vertex,
            GL_COLOR_ARRAY => Self::Color,
            GL_NORMAL_ARRAY => Self::Normal,
            GL_TEXTURE_COORD_ARRAY => Self::TexCoord,
            GL_EDGE_FLAG_ARRAY => Self::EdgeFlag,
            // Kept for glGet; an RGBA context does not read the index array.
            GL_INDEX_ARRAY => Self::Index,
            GL_SECONDARY_COLOR_ARRAY => Self::SecondaryColor,
            GL_FOG_COORD_ARRAY => Self::FogCoord,
            _ => return None,
        })
    }

    /// Whether this array takes elements of type `t`.
    fn accepts(self, t: DataType) -> bool {
        use DataType::*;
        match self {
            Self::Vertex | Self::TexCoord => matches!(t, Short | Int | Float | Double),
            Self::Normal => matches!(t, Byte | Short | Int | Float | Double),
            Self::Color | Self::SecondaryColor => true,
            Self::EdgeFlag => t == UByte,
            Self::Index => matches!(t, UByte | Short | Int | Float | Double),
            Self::FogCoord => matches!(t, Float | Double),
        }
    }

    /// Whether this array takes `size` components.
    fn accepts_size(self, size: GLint) -> bool {
        match self {
            Self::Vertex => (2..=4).contains(&size),
            Self::Color | Self::SecondaryColor => (3..=4).contains(&size),
            Self::TexCoord => (1..=4).contains(&size),
            Self::Normal => size == 3,
            Self::EdgeFlag | Self::Index | Self::FogCoord => size == 1,
        }
    }
}

/// One glInterleavedArrays layout: the texture-coordinate size, colour size and type,
/// whether there is a normal, the vertex size, the colour/normal/vertex offsets and the
/// stride, in bytes.
struct Interleaved {
    tc: i32,
    cc: i32,
    ctype: GLenum,
    normal: bool,
    vc: i32,
    pc: i32,
    pn: i32,
    pv: i32,
    stride: i32,
}

/// The layout of a glInterleavedArrays format (`None` for an invalid one).
fn interleaved(format: GLenum) -> Option<Interleaved> {
    const F: i32 = 4;
    const C: i32 = 4;
    const UB: GLenum = GL_UNSIGNED_BYTE;
    let l = |tc, cc, ctype, normal, vc, (pc, pn, pv), stride| Interleaved {
        tc,
        cc,
        ctype,
        normal,
        vc,
        pc,
        pn,
        pv,
        stride,
    };
    Some(match format {
        GL_V2F => l(0, 0, 0, false, 2, (0, 0, 0), 2 * F),
        GL_V3F => l(0, 0, 0, false, 3, (0, 0, 0), 3 * F),
        GL_C4UB_V2F => l(0, 4, UB, false, 2, (0, 0, C), C + 2 * F),
        GL_C4UB_V3F => l(0, 4, UB, false, 3, (0, 0, C), C + 3 * F),
        GL_C3F_V3F => l(0, 3, GL_FLOAT, false, 3, (0, 0, 3 * F), 6 * F),
        GL_N3F_V3F => l(0, 0, 0, true, 3, (0, 0, 3 * F), 6 * F),
        GL_C4F_N3F_V3F => l(0, 4, GL_FLOAT, true, 3, (0, 4 * F, 7 * F), 10 * F),
        GL_T2F_V3F => l(2, 0, 0, false, 3, (0, 0, 2 * F), 5 * F),
        GL_T4F_V4F => l(4, 0, 0, false, 4, (0, 0, 4 * F), 8 * F),
        GL_T2F_C4UB_V3F => l(2, 4, UB, false, 3, (2 * F, 0, C + 2 * F), C + 5 * F),
        GL_T2F_C3F_V3F => l(2, 3, GL_FLOAT, false, 3, (2 * F, 0, 5 * F), 8 * F),
        GL_T2F_N3F_V3F => l(2, 0, 0, true, 3, (0, 2 * F, 5 * F), 8 * F),
        GL_T2F_C4F_N3F_V3F => l(2, 4, GL_FLOAT, true, 3, (2 * F, 6 * F, 9 * F), 12 * F),
        GL_T4F_C4F_N3F_V4F => l(4, 4, GL_FLOAT, true, 4, (4 * F, 8 * F, 11 * F), 15 * F),
        _ => return None,
    })
}

impl Context {
    /// The state of client array `w` (the texture-coordinate array of the client-active
    /// unit).
    fn client_array_mut(&mut self, w: ClientArray) -> &mut ArrayPointer {
        match w {
            ClientArray::Vertex => &mut self.arrays.vao.vertex,
            ClientArray::Color => &mut self.arrays.vao.color,
            ClientArray::Normal => &mut self.arrays.vao.normal,
            ClientArray::TexCoord => {
                &mut self.arrays.vao.texcoord[self.state.client_active_texture]
            }
            ClientArray::EdgeFlag => &mut self.arrays.vao.edge_flag,
            ClientArray::Index => &mut self.arrays.vao.index,
            ClientArray::SecondaryColor => &mut self.arrays.vao.secondary_color,
            ClientArray::FogCoord => &mut self.arrays.vao.fog_coord,
        }
    }

    /// gl*Pointer: validates as Mesa does (the stride, the type and the size, in that
    /// order) and stores the pointer ([`Context::store_array_pointer`]). Mesa 22.3 still
    /// stores a negative stride after reporting it; we keep the old state, as GL requires.
    pub(crate) fn set_array_pointer(
        &mut self,
        w: ClientArray,
        format: (GLint, GLenum, GLsizei),
        ptr: usize,
    ) -> GlResult<()> {
        let checks = (|t: DataType| w.accepts(t), w.accepts_size(format.0));
        self.store_array_pointer(|c| c.client_array_mut(w), format, ptr, checks)?;
        Ok(())
    }

    /// The checks and the store of gl*Pointer and glVertexAttribPointer: GL_INVALID_VALUE
    /// for a negative stride, GL_INVALID_OPERATION for client memory while a named vertex
    /// array object is bound, GL_INVALID_ENUM for a type not a [`DataType`] or one that
    /// `accepts` refuses, GL_INVALID_VALUE when not `size_ok` (Mesa's order); then the
    /// size, type, stride and pointer (an offset while a buffer is bound to
    /// GL_ARRAY_BUFFER) stored into the array `pick` gives, which is returned.
    pub(crate) fn store_array_pointer(
        &mut self,
        pick: impl FnOnce(&mut Self) -> &mut ArrayPointer,
        (size, ty, stride): (GLint, GLenum, GLsizei),
        ptr: usize,
        (accepts, size_ok): (impl Fn(DataType) -> bool, bool),
    ) -> GlResult<&mut ArrayPointer> {
        if stride < 0 {
            return Err(GlError::InvalidValue);
        }
        // A named vertex array object takes no client memory (Mesa's "non-VBO array",
        // checked in its order: after the stride, before the type).
        if self.arrays.vao_binding != 0 && self.arrays.array_buffer == 0 && ptr != 0 {
            return Err(GlError::InvalidOperation);
        }
        let t = DataType::from_gl(ty)?;
        if !accepts(t) {
            return Err(GlError::InvalidEnum);
        }
        if !size_ok {
            return Err(GlError::InvalidValue);
        }
        let buffer = self.arrays.array_buffer;
        let a = pick(self);
        a.size = size;
        a.ty = t;
        a.stride = stride;
        a.ptr = ptr;
        a.buffer = buffer;
        Ok(a)
    }

    /// glEnableClientState/glDisableClientState.
    pub(crate) fn set_client_array(&mut self, cap: GLenum, on: bool) -> GlResult<()> {
        let w = ClientArray::from_cap(cap).ok_or(GlError::InvalidEnum)?;
        self.client_array_mut(w).enabled = on;
        Ok(())
    }

    /// Whether the client array `cap` names is enabled (None when `cap` names none).
    pub(crate) fn client_array_enabled(&mut self, cap: GLenum) -> Option<bool> {
        ClientArray::from_cap(cap).map(|w| self.client_array_mut(w).enabled)
    }

    /// glInterleavedArrays: GL_INVALID_ENUM for an unknown format, GL_INVALID_VALUE for a
    /// negative stride; then, as Mesa's compound of entry points, disables the edge-flag
    /// and index arrays, and sets and enables (or disables) the texture-coordinate,
    /// colour, normal and vertex arrays of the layout at `base` (stride 0: the layout's).
    pub(crate) fn interleaved_arrays(
        &mut self,
        format: GLenum,
        stride: GLsizei,
        base: usize,
    ) -> GlResult<()> {
        let l = interleaved(format).ok_or(GlError::InvalidEnum)?;
        if stride < 0 {
            return Err(GlError::InvalidValue);
        }
        let stride = if stride == 0 { l.stride } else { stride };
        let at = |off: i32| base + off as usize;
        self.set_client_array(GL_EDGE_FLAG_ARRAY, false)?;
        self.set_client_array(GL_INDEX_ARRAY, false)?;
        self.set_client_array(GL_TEXTURE_COORD_ARRAY, l.tc > 0)?;
        if l.tc > 0 {
            self.set_array_pointer(ClientArray::TexCoord, (l.tc, GL_FLOAT, stride), at(0))?;
        }
        self.set_client_array(GL_COLOR_ARRAY, l.cc > 0)?;
        if l.cc > 0 {
            self.set_array_pointer(ClientArray::Color, (l.cc, l.ctype, stride), at(l.pc))?;
        }
        self.set_client_array(GL_NORMAL_ARRAY, l.normal)?;
        if l.normal {
            self.set_array_pointer(ClientArray::Normal, (3, GL_FLOAT, stride), at(l.pn))?;
        }
        self.set_client_array(GL_VERTEX_ARRAY, true)?;
        self.set_array_pointer(ClientArray::Vertex, (l.vc, GL_FLOAT, stride), at(l.pv))
    }

    /// glEnable/glDisable. Like Mesa's compatibility profile (and unlike the GL 1.5 spec,
    /// which makes them INVALID_ENUM), the client arrays are accepted as
    /// glEnableClientState / glDisableClientState: real programs rely on it (README, known
    /// differences).
    pub(crate) fn enable(&mut self, cap: GLenum, on: bool) -> GlResult<()> {
        if ClientArray::from_cap(cap).is_some() {
            return self.set_client_array(cap, on);
        }
        if cap == GL_TEXTURE_CUBE_MAP_SEAMLESS {
            self.textures.cube_seamless = on;
            return Ok(());
        }
        if cap == GL_PRIMITIVE_RESTART {
            self.arrays.primitive_restart = on;
            return Ok(());
        }
        self.set_cap(Cap::from_gl(cap)?, on)
    }

    /// glIsEnabled (also answers the client array states).
    pub(crate) fn is_enabled(&mut self, cap: GLenum) -> GlResult<bool> {
        match self.client_array_enabled(cap) {
            Some(on) => Ok(on),
            None if cap == GL_TEXTURE_CUBE_MAP_SEAMLESS => Ok(self.textures.cube_seamless),
            None if cap == GL_PRIMITIVE_RESTART => Ok(self.arrays.primitive_restart),
            None => Ok(self.state.caps.get(Cap::from_gl(cap)?)),
        }
    }
}
