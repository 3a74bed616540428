//! Vertex-array vocabulary: component data types, array pointers and buffer storage.

#[allow(unused_imports)]
use super::*;

/// The component type of an array or index buffer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DataType {
    /// GL_BYTE
    Byte,
    /// GL_UNSIGNED_BYTE
    UByte,
    /// GL_SHORT
    Short,
    /// GL_UNSIGNED_SHORT
    UShort,
    /// GL_INT
    Int,
    /// GL_UNSIGNED_INT
    UInt,
    /// GL_FLOAT
    Float,
    /// GL_DOUBLE
    Double,
}

impl DataType {
    /// Size in bytes.
    pub fn size(self) -> usize {
        match self {
            Self::Byte | Self::UByte => 1,
            Self::Short | Self::UShort => 2,
            Self::Int | Self::UInt | Self::Float => 4,
            Self::Double => 8,
        }
    }
}

/// One client array (gl*Pointer plus its enable bit).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArrayPointer {
    /// glEnableClientState.
    pub enabled: bool,
    /// Components per element (1-4).
    pub size: i32,
    /// Component type.
    pub ty: DataType,
    /// The stride the user gave (0 = tightly packed).
    pub stride: i32,
    /// The pointer, or the offset into `buffer`.
    pub ptr: usize,
    /// The GL_ARRAY_BUFFER bound when the pointer was set (0 = client memory).
    pub buffer: u32,
    /// glVertexAttribPointer's `normalized` (integer components mapped to [0, 1] or
    /// [-1, 1]); false for the fixed-function arrays, whose own rule the fetch applies.
    pub normalized: bool,
    /// glVertexAttribIPointer's array (GL 3.0): its integers reach the shader unconverted,
    /// as the bits of the attribute's words.
    pub integer: bool,
}

impl ArrayPointer {
    /// A disabled array of `size` components of type `ty` (GL's initial array state).
    pub fn new(size: i32, ty: DataType) -> Self {
        ArrayPointer {
            enabled: false,
            size,
            ty,
            stride: 0,
            ptr: 0,
            buffer: 0,
            normalized: false,
            integer: false,
        }
    }
    /// The effective stride in bytes.
    pub fn byte_stride(&self) -> usize {
        if self.stride > 0 {
            self.stride as usize
        } else {
            self.size as usize * self.ty.size()
        }
    }
}
