//! The semantic types of GLSL 1.10 to 3.30: scalars, vectors, matrices, samplers,
//! structs, arrays and void, with the language versions that have them, their names as
//! Mesa prints them in errors, and each version's implicit conversions.
//!
//! Sources: the GLSL specifications 1.10 to 3.30, chapter 4.1 (basic types, implicit
//! conversions 4.1.10). Where Mesa, the tests' reference, differs from the letter of a
//! specification the rule here follows Mesa and says so: version 1.40 always has the
//! compatibility built-ins (Mesa's `compat_shader` is true below 1.50), and a uint
//! converts implicitly to float from 1.30 on. The std140 layout is in `std140`.

pub mod std140;

use std::fmt;
use std::sync::Arc;

/// A GLSL version with its profile, as `#version` selects it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Version {
    /// The version number: 110, 120, 130, 140, 150 or 330.
    pub number: u16,
    /// Whether the compatibility built-ins (`gl_Vertex`, `ftransform`, the matrix
    /// state...) exist: always below 1.50, and with `#version 150 compatibility` or
    /// `330 compatibility`.
    pub compatibility: bool,
}

impl Version {
    /// The version numbers the front end supports, in order.
    pub const NUMBERS: [u16; 6] = [110, 120, 130, 140, 150, 330];

    /// The version `number` with the profile `#version number [compatibility]` gives:
    /// below 1.50 the profile is always compatibility.
    pub fn new(number: u16, compatibility: bool) -> Version {
        Version {
            number,
            compatibility: compatibility || number < 150,
        }
    }

    /// Every distinct version and profile: 1.10 to 1.40, then 1.50 and 3.30 core and
    /// compatibility.
    pub fn all() -> Vec<Version> {
        let mut v = Vec::new();
        for n in Self::NUMBERS {
            v.push(Version::new(n, false));
            if n >= 150 {
                v.push(Version::new(n, true));
            }
        }
        v
    }

    /// Whether this version is at least `number` (any profile).
    pub fn at_least(self, number: u16) -> bool {
        self.number >= number
    }

    /// The `#version` line of this version.
    pub fn directive(self) -> String {
        if self.number >= 150 && self.compatibility {
            format!("#version {} compatibility", self.number)
        } else {
            format!("#version {}", self.number)
        }
    }
}

/// The shader stages of these versions.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Stage {
    /// The vertex shader.
    Vertex,
    /// The geometry shader (from 1.50).
    Geometry,
    /// The fragment shader.
    Fragment,
}

impl Stage {
    /// The stage's name as Mesa's messages print it.
    pub fn name(self) -> &'static str {
        match self {
            Stage::Vertex => "vertex",
            Stage::Geometry => "geometry",
            Stage::Fragment => "fragment",
        }
    }
}

/// A scalar base type.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Scalar {
    /// `bool`.
    Bool,
    /// `int` (32-bit signed).
    Int,
    /// `uint` (32-bit unsigned, from 1.30).
    Uint,
    /// `float`.
    Float,
}

impl Scalar {
    /// The scalar's name.
    pub fn name(self) -> &'static str {
        match self {
            Scalar::Bool => "bool",
            Scalar::Int => "int",
            Scalar::Uint => "uint",
            Scalar::Float => "float",
        }
    }

    /// The prefix of the scalar's vector names (`b`vec, `i`vec, `u`vec, vec).
    pub fn vector_prefix(self) -> &'static str {
        match self {
            Scalar::Bool => "b",
            Scalar::Int => "i",
            Scalar::Uint => "u",
            Scalar::Float => "",
        }
    }

    /// The first version with this scalar type.
    pub fn since(self) -> u16 {
        if self == Scalar::Uint {
            130
        } else {
            110
        }
    }
}

/// The dimensionality (target) of a sampler.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Dim {
    /// 1D textures.
    D1,
    /// 2D textures.
    D2,
    /// 3D textures.
    D3,
    /// Cube maps.
    Cube,
    /// Rectangle textures (`sampler2DRect`).
    Rect,
    /// Buffer textures (`samplerBuffer`).
    Buffer,
    /// Multisample 2D textures (`sampler2DMS`).
    Ms,
}

/// A sampler type: `[iu]sampler{1D,2D,3D,Cube,2DRect,Buffer,2DMS}[Array][Shadow]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Sampler {
    /// The target.
    pub dim: Dim,
    /// The type of the texels returned: `Float`, `Int` (`isampler`) or `Uint` (`usampler`).
    pub texel: Scalar,
    /// An array texture.
    pub array: bool,
    /// A depth-comparison sampler.
    pub shadow: bool,
}

impl Sampler {
    /// Every sampler type of GLSL 1.10 to 3.30 (cube arrays are 4.00 and not here).
    pub fn all() -> Vec<Sampler> {
        let mut v = Vec::new();
        let combos: [(Dim, bool, bool); 15] = [
            (Dim::D1, false, false),
            (Dim::D2, false, false),
            (Dim::D3, false, false),
            (Dim::Cube, false, false),
            (Dim::D1, false, true),
            (Dim::D2, false, true),
            (Dim::Cube, false, true),
            (Dim::D1, true, false),
            (Dim::D2, true, false),
            (Dim::D1, true, true),
            (Dim::D2, true, true),
            (Dim::Rect, false, false),
            (Dim::Rect, false, true),
            (Dim::Buffer, false, false),
            (Dim::Ms, false, false),
        ];
        for (dim, array, shadow) in combos {
            for texel in [Scalar::Float, Scalar::Int, Scalar::Uint] {
                if shadow && texel != Scalar::Float {
                    continue;
                }
                v.push(Sampler {
                    dim,
                    texel,
                    array,
                    shadow,
                });
            }
        }
        for texel in [Scalar::Float, Scalar::Int, Scalar::Uint] {
            v.push(Sampler {
                dim: Dim::Ms,
                texel,
                array: true,
                shadow: false,
            });
        }
        v
    }

    /// The first version with this sampler type: 1.10 for the float 1D/2D/3D/cube and
    /// 1D/2D shadow samplers, 1.30 for array, cube-shadow and integer samplers, 1.40
    /// for rectangle and buffer samplers, 1.50 for multisample ones; but the float
    /// rectangle samplers from 1.10, as in Mesa, where ARB_texture_rectangle is always
    /// enabled.
    pub fn since(self) -> u16 {
        match self.dim {
            Dim::Ms => 150,
            Dim::Rect if self.texel == Scalar::Float => 110,
            Dim::Rect | Dim::Buffer => 140,
            _ if self.array || self.texel != Scalar::Float => 130,
            Dim::Cube if self.shadow => 130,
            _ => 110,
        }
    }

    /// The extension that brings this sampler type to versions before its `since`
    /// (from 1.10 in Mesa): EXT_texture_array for the float array samplers,
    /// ARB_texture_multisample for the multisample ones.
    pub fn extension(self) -> Option<&'static str> {
        match self.dim {
            Dim::Ms => Some("GL_ARB_texture_multisample"),
            _ if self.array && self.texel == Scalar::Float => Some("GL_EXT_texture_array"),
            _ => None,
        }
    }

    /// The number of coordinates that address a texel (array layer included, the
    /// shadow reference not): 1 for 1D and buffer, 2 for 2D, 1D arrays and rectangle...
    pub fn coords(self) -> u8 {
        let base = match self.dim {
            Dim::D1 | Dim::Buffer => 1,
            Dim::D2 | Dim::Rect | Dim::Ms => 2,
            Dim::D3 | Dim::Cube => 3,
        };
        base + self.array as u8
    }

    /// The sampler's name, e.g. `usampler2DArray`, `sampler2DRectShadow`.
    pub fn name(self) -> String {
        let dim = match self.dim {
            Dim::D1 => "1D",
            Dim::D2 => "2D",
            Dim::D3 => "3D",
            Dim::Cube => "Cube",
            Dim::Rect => "2DRect",
            Dim::Buffer => "Buffer",
            Dim::Ms => "2DMS",
        };
        format!(
            "{}sampler{dim}{}{}",
            self.texel.vector_prefix(),
            if self.array { "Array" } else { "" },
            if self.shadow { "Shadow" } else { "" }
        )
    }
}

/// A member of a struct type.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Member {
    /// The member's name.
    pub name: String,
    /// The member's type.
    pub ty: Type,
}

/// A named struct type with its members, in declaration order.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Struct {
    /// The struct's name (`gl_LightSourceParameters`, or the user's).
    pub name: String,
    /// The members.
    pub members: Vec<Member>,
}

/// The semantic type of a GLSL value.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Type {
    /// `void`: only a function's return type.
    Void,
    /// A scalar.
    Scalar(Scalar),
    /// A vector of 2 to 4 components.
    Vector(Scalar, u8),
    /// A float matrix of `cols` columns of `rows` rows (2 to 4 each; non-square from 1.20).
    Matrix {
        /// The number of columns.
        cols: u8,
        /// The number of rows (the size of a column vector).
        rows: u8,
    },
    /// A sampler (only as a uniform or a function parameter).
    Sampler(Sampler),
    /// A struct, shared by every value of its type.
    Struct(Arc<Struct>),
    /// An array of `len` elements (`None`: unsized, as a built-in like `gl_TexCoord[]`
    /// or an array declared without size before its size is known).
    Array(Box<Type>, Option<u32>),
}

impl Type {
    /// `float`.
    pub const FLOAT: Type = Type::Scalar(Scalar::Float);
    /// `int`.
    pub const INT: Type = Type::Scalar(Scalar::Int);
    /// `uint`.
    pub const UINT: Type = Type::Scalar(Scalar::Uint);
    /// `bool`.
    pub const BOOL: Type = Type::Scalar(Scalar::Bool);

    /// The type a built-in type name names (`float`, `ivec3`, `mat2x4`, `mat2`,
    /// `sampler2D`...), whatever the version (see [`Type::exists_in`]).
    pub fn named(name: &str) -> Option<Type> {
        if name == "void" {
            return Some(Type::Void);
        }
        for s in [Scalar::Float, Scalar::Int, Scalar::Uint, Scalar::Bool] {
            if name == s.name() {
                return Some(Type::Scalar(s));
            }
            for n in 2..=4u8 {
                if name == format!("{}vec{n}", s.vector_prefix()) {
                    return Some(Type::Vector(s, n));
                }
            }
        }
        for c in 2..=4u8 {
            for r in 2..=4u8 {
                if name == format!("mat{c}x{r}") || (c == r && name == format!("mat{c}")) {
                    return Some(Type::mat(c, r));
                }
            }
        }
        Sampler::all()
            .into_iter()
            .find(|s| s.name() == name)
            .map(Type::Sampler)
    }

    /// The scalar (size 1) or vector of `n` components of `s`.
    pub fn vec(s: Scalar, n: u8) -> Type {
        if n == 1 {
            Type::Scalar(s)
        } else {
            Type::Vector(s, n)
        }
    }

    /// The matrix of `cols` columns and `rows` rows.
    pub fn mat(cols: u8, rows: u8) -> Type {
        Type::Matrix { cols, rows }
    }

    /// An array of `len` elements of `self` (`None`: unsized).
    pub fn array(self, len: Option<u32>) -> Type {
        Type::Array(Box::new(self), len)
    }

    /// The scalar base type of a scalar, vector or matrix.
    pub fn scalar(&self) -> Option<Scalar> {
        match self {
            Type::Scalar(s) | Type::Vector(s, _) => Some(*s),
            Type::Matrix { .. } => Some(Scalar::Float),
            _ => None,
        }
    }

    /// The number of scalar components of a scalar, vector or matrix (0 otherwise).
    pub fn components(&self) -> u32 {
        match self {
            Type::Scalar(_) => 1,
            Type::Vector(_, n) => *n as u32,
            Type::Matrix { cols, rows } => (*cols * *rows) as u32,
            _ => 0,
        }
    }

    /// The first version that has this type (and everything it is made of).
    pub fn since(&self) -> u16 {
        match self {
            Type::Void => 110,
            Type::Scalar(s) | Type::Vector(s, _) => s.since(),
            Type::Matrix { cols, rows } => 110 + 10 * (cols != rows) as u16,
            Type::Sampler(s) => s.since(),
            Type::Struct(s) => s.members.iter().map(|m| m.ty.since()).max().unwrap_or(110),
            // Array constructors, unsized declarations and `.length()` are 1.20; the
            // array type itself is 1.10.
            Type::Array(e, _) => e.since(),
        }
    }

    /// Whether `version` has this type.
    pub fn exists_in(&self, version: Version) -> bool {
        version.number >= self.since()
    }

    /// Whether `version` has this type with the extensions `exts` enabled.
    pub fn exists_with(&self, version: Version, exts: &[&str]) -> bool {
        let ext = match self {
            Type::Sampler(s) => s.extension(),
            Type::Array(e, _) => return e.exists_with(version, exts),
            _ => None,
        };
        self.exists_in(version) || ext.is_some_and(|e| exts.contains(&e))
    }

    /// Whether a value of type `self` converts implicitly to `to` in `version`: never
    /// before 1.20; from 1.20 int to float (and the ivecN to vecN); from 1.30, as Mesa
    /// does, also uint to float. Never between arrays or structs, nor int to uint
    /// (that is GLSL 4.00).
    pub fn converts_to(&self, to: &Type, version: Version) -> bool {
        if self == to {
            return true;
        }
        if version.number < 120 {
            return false;
        }
        let same_shape = match (self, to) {
            (Type::Scalar(_), Type::Scalar(_)) => true,
            (Type::Vector(_, a), Type::Vector(_, b)) => a == b,
            _ => false,
        };
        same_shape
            && to.scalar() == Some(Scalar::Float)
            && matches!(self.scalar(), Some(Scalar::Int | Scalar::Uint))
    }
}

impl fmt::Display for Type {
    /// The type's name as Mesa prints it: `vec4`, `mat2x3`, `mat3` (a square matrix by
    /// its short name), `float[3]`, `float[]` for an unsized array, a struct by its name.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Type::Void => f.write_str("void"),
            Type::Scalar(s) => f.write_str(s.name()),
            Type::Vector(s, n) => write!(f, "{}vec{n}", s.vector_prefix()),
            Type::Matrix { cols, rows } if cols == rows => write!(f, "mat{cols}"),
            Type::Matrix { cols, rows } => write!(f, "mat{cols}x{rows}"),
            Type::Sampler(s) => f.write_str(&s.name()),
            Type::Struct(s) => f.write_str(&s.name),
            Type::Array(e, Some(n)) => write!(f, "{e}[{n}]"),
            Type::Array(e, None) => write!(f, "{e}[]"),
        }
    }
}

/// Every non-sampler, non-aggregate type of `version`: the scalars, vectors and
/// matrices (for generating tests and signature families).
pub fn basic_types(version: Version) -> Vec<Type> {
    let mut v = Vec::new();
    for s in [Scalar::Float, Scalar::Int, Scalar::Uint, Scalar::Bool] {
        for n in 1..=4 {
            v.push(Type::vec(s, n));
        }
    }
    for cols in 2..=4 {
        for rows in 2..=4 {
            v.push(Type::mat(cols, rows));
        }
    }
    v.retain(|t| t.exists_in(version));
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_and_conversions() {
        assert_eq!(Type::mat(2, 2).to_string(), "mat2");
        assert_eq!(Type::mat(3, 2).to_string(), "mat3x2");
        assert_eq!(Type::Vector(Scalar::Uint, 3).to_string(), "uvec3");
        assert_eq!(Type::FLOAT.array(Some(3)).to_string(), "float[3]");
        let s = Sampler {
            dim: Dim::Rect,
            texel: Scalar::Int,
            array: false,
            shadow: false,
        };
        assert_eq!(s.name(), "isampler2DRect");
        assert_eq!(s.since(), 140);
        let (v110, v120, v130) = (
            Version::new(110, false),
            Version::new(120, false),
            Version::new(130, false),
        );
        let ivec2 = Type::Vector(Scalar::Int, 2);
        let vec2 = Type::Vector(Scalar::Float, 2);
        assert!(!ivec2.converts_to(&vec2, v110));
        assert!(ivec2.converts_to(&vec2, v120));
        assert!(!Type::INT.converts_to(&Type::UINT, v130));
        assert!(Type::UINT.converts_to(&Type::FLOAT, v130));
        assert!(!Type::INT.converts_to(&vec2, v130));
        assert_eq!(Version::all().len(), 8);
        assert!(Version::new(140, false).compatibility);
        assert_eq!(
            Version::new(330, true).directive(),
            "#version 330 compatibility"
        );
    }
}
