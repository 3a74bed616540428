//! The built-in functions other than texture lookups (GLSL specifications chapter 8:
//! 8.1 angle and trigonometry, 8.2 exponential, 8.3 common, 8.4 geometric, 8.5 matrix,
//! 8.6 vector relational, 8.8 fragment processing (derivatives), 8.9 noise, and the 1.50
//! geometry-shader functions), described one prototype per line and expanded.
//!
//! A description reads like the specification: `genType clamp(genType, float, float)`.
//! The placeholders of one prototype vary together:
//! - `genType`, `genIType`, `genUType`, `genBType`: the float, int, uint or bool scalar
//!   and vectors of 2 to 4 components;
//! - `vec`, `ivec`, `uvec`, `bvec`: the vectors of 2 to 4 components only;
//! - `mat`: every matrix, `matT` its transpose; `sqmat`: the square ones.
//!
//! A signature naming a type its version lacks (`uint`, `mat2x3` in 1.10) does not
//! exist there ([`super::Function::exists`]), so one entry serves every version.

use super::{Avail, Function, Param};
use crate::types::{Scalar, Type};

/// The bit-casting functions of 3.30 and of ARB_shader_bit_encoding (any version in
/// Mesa; the uint ones need uint, so 1.30).
const BIT_ENCODING: &str = "genIType floatBitsToInt(genType); genUType floatBitsToUint(genType);
    genType intBitsToFloat(genIType); genType uintBitsToFloat(genUType)";

/// The descriptions: where each group exists, and its prototypes.
const TABLE: &[(Avail, &str)] = &[
    // 8.1 Angle and trigonometry.
    (
        Avail::all(110),
        "genType radians(genType); genType degrees(genType); genType sin(genType);
         genType cos(genType); genType tan(genType); genType asin(genType);
         genType acos(genType); genType atan(genType, genType); genType atan(genType)",
    ),
    (
        Avail::all(130),
        "genType sinh(genType); genType cosh(genType); genType tanh(genType);
         genType asinh(genType); genType acosh(genType); genType atanh(genType)",
    ),
    // 8.2 Exponential.
    (
        Avail::all(110),
        "genType pow(genType, genType); genType exp(genType); genType log(genType);
         genType exp2(genType); genType log2(genType); genType sqrt(genType);
         genType inversesqrt(genType)",
    ),
    // 8.3 Common.
    (
        Avail::all(110),
        "genType abs(genType); genType sign(genType); genType floor(genType);
         genType ceil(genType); genType fract(genType);
         genType mod(genType, float); genType mod(genType, genType);
         genType min(genType, genType); genType min(genType, float);
         genType max(genType, genType); genType max(genType, float);
         genType clamp(genType, genType, genType); genType clamp(genType, float, float);
         genType mix(genType, genType, genType); genType mix(genType, genType, float);
         genType step(genType, genType); genType step(float, genType);
         genType smoothstep(genType, genType, genType);
         genType smoothstep(float, float, genType)",
    ),
    // The integer abs, sign, min, max and clamp are 1.30 in the specifications; Mesa
    // has them from 1.10 (the uint ones need uint, so 1.30).
    (
        Avail::all(110),
        "genIType abs(genIType); genIType sign(genIType);
         genIType min(genIType, genIType); genIType min(genIType, int);
         genUType min(genUType, genUType); genUType min(genUType, uint);
         genIType max(genIType, genIType); genIType max(genIType, int);
         genUType max(genUType, genUType); genUType max(genUType, uint);
         genIType clamp(genIType, genIType, genIType); genIType clamp(genIType, int, int);
         genUType clamp(genUType, genUType, genUType); genUType clamp(genUType, uint, uint)",
    ),
    (
        Avail::all(130),
        "genType trunc(genType); genType round(genType); genType roundEven(genType);
         genType modf(genType, out genType); genType mix(genType, genType, genBType);
         genBType isnan(genType); genBType isinf(genType)",
    ),
    (Avail::all(330), BIT_ENCODING),
    (
        Avail::all(110).ext("GL_ARB_shader_bit_encoding"),
        BIT_ENCODING,
    ),
    // 8.4 Geometric.
    (
        Avail::all(110),
        "float length(genType); float distance(genType, genType);
         float dot(genType, genType); vec3 cross(vec3, vec3);
         genType normalize(genType); genType faceforward(genType, genType, genType);
         genType reflect(genType, genType); genType refract(genType, genType, float)",
    ),
    (Avail::vertex(110).compat(), "vec4 ftransform()"),
    // 8.5 Matrix (`mat` is square only in 1.10 since 1.10 has no other matrices).
    (Avail::all(110), "mat matrixCompMult(mat, mat)"),
    (Avail::all(120), "matT transpose(mat)"),
    (Avail::all(140), "sqmat inverse(sqmat)"),
    // determinant is 1.50 in the specifications; Mesa has it from 1.20.
    (Avail::all(120), "float determinant(sqmat)"),
    // 8.6 Vector relational.
    (
        Avail::all(110),
        "bvec lessThan(vec, vec); bvec lessThan(ivec, ivec);
         bvec lessThanEqual(vec, vec); bvec lessThanEqual(ivec, ivec);
         bvec greaterThan(vec, vec); bvec greaterThan(ivec, ivec);
         bvec greaterThanEqual(vec, vec); bvec greaterThanEqual(ivec, ivec);
         bvec equal(vec, vec); bvec equal(ivec, ivec); bvec equal(bvec, bvec);
         bvec notEqual(vec, vec); bvec notEqual(ivec, ivec); bvec notEqual(bvec, bvec);
         bool any(bvec); bool all(bvec); bvec not(bvec)",
    ),
    (
        Avail::all(130),
        "bvec lessThan(uvec, uvec); bvec lessThanEqual(uvec, uvec);
         bvec greaterThan(uvec, uvec); bvec greaterThanEqual(uvec, uvec);
         bvec equal(uvec, uvec); bvec notEqual(uvec, uvec)",
    ),
    // 8.8 Fragment processing.
    (
        Avail::fragment(110),
        "genType dFdx(genType); genType dFdy(genType); genType fwidth(genType)",
    ),
    // 8.9 Noise.
    (
        Avail::all(110),
        "float noise1(genType); vec2 noise2(genType); vec3 noise3(genType);
         vec4 noise4(genType)",
    ),
    // 8.10 Geometry shader functions.
    (
        Avail::geometry(150),
        "void EmitVertex(); void EndPrimitive()",
    ),
];

/// The type a placeholder or type name stands for at expansion index `i`, and the
/// number of indices its family has (1 for a plain type name).
fn resolve(word: &str, i: usize) -> Option<(Type, usize)> {
    let gen = |s: Scalar| (Type::vec(s, i as u8 + 1), 4);
    let vec = |s: Scalar| (Type::Vector(s, i as u8 + 2), 3);
    let mat = |t: bool| {
        let (c, r) = (i as u8 / 3 + 2, i as u8 % 3 + 2);
        (if t { Type::mat(r, c) } else { Type::mat(c, r) }, 9)
    };
    Some(match word {
        "genType" => gen(Scalar::Float),
        "genIType" => gen(Scalar::Int),
        "genUType" => gen(Scalar::Uint),
        "genBType" => gen(Scalar::Bool),
        "vec" => vec(Scalar::Float),
        "ivec" => vec(Scalar::Int),
        "uvec" => vec(Scalar::Uint),
        "bvec" => vec(Scalar::Bool),
        "mat" => mat(false),
        "matT" => mat(true),
        "sqmat" => (Type::mat(i as u8 + 2, i as u8 + 2), 3),
        _ => (Type::named(word)?, 1),
    })
}

/// Expands one prototype into its signatures (None: a malformed description).
pub fn expand(proto: &str, avail: Avail) -> Option<Vec<Function>> {
    let (head, rest) = proto.trim().split_once('(')?;
    let (ret, name) = head.trim().split_once(' ')?;
    let params: Vec<&str> = rest
        .strip_suffix(')')?
        .split(',')
        .map(str::trim)
        .filter(|p| !p.is_empty())
        .collect();
    let words = std::iter::once(ret).chain(params.iter().map(|p| p.trim_start_matches("out ")));
    let count = words
        .map(|w| resolve(w, 0).map(|(_, n)| n))
        .try_fold(1, |acc, n| n.map(|n| acc.max(n)))?;
    (0..count)
        .map(|i| {
            Some(Function {
                name: name.trim().to_string(),
                ret: resolve(ret, i)?.0,
                params: params
                    .iter()
                    .map(|p| {
                        let out = p.starts_with("out ");
                        let ty = resolve(p.trim_start_matches("out "), i)?.0;
                        Some(Param {
                            ty,
                            out,
                            constant: false,
                        })
                    })
                    .collect::<Option<_>>()?,
                avail,
            })
        })
        .collect()
}

/// Every signature of the non-texture built-in functions, of every version and stage.
pub fn all() -> Vec<Function> {
    let mut v = Vec::new();
    for (avail, protos) in TABLE {
        for proto in protos.split(';') {
            v.extend(expand(proto, *avail).expect("well-formed built-in description"));
        }
    }
    // outerProduct(c, r): a column vector of R and a row vector of C components make a
    // matrix of C columns and R rows (mat2x3 outerProduct(vec3, vec2)).
    for r in 2..=4u8 {
        for c in 2..=4u8 {
            v.push(Function {
                name: "outerProduct".into(),
                ret: Type::mat(c, r),
                params: [r, c]
                    .map(|n| Param {
                        ty: Type::Vector(Scalar::Float, n),
                        out: false,
                        constant: false,
                    })
                    .to_vec(),
                avail: Avail::all(120),
            });
        }
    }
    // `genType min(genType, float)` repeats `min(float, float)` of `min(genType,
    // genType)`: keep the first of each name, parameter list and extension.
    let mut seen = std::collections::HashSet::new();
    v.retain(|f| seen.insert((f.name.clone(), f.params.clone(), f.avail.ext)));
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_description_many_signatures() {
        let sigs = expand("genType clamp(genType, float, float)", Avail::all(110)).unwrap();
        let protos: Vec<String> = sigs.iter().map(Function::prototype).collect();
        assert_eq!(
            protos,
            [
                "float clamp(float, float, float)",
                "vec2 clamp(vec2, float, float)",
                "vec3 clamp(vec3, float, float)",
                "vec4 clamp(vec4, float, float)"
            ]
        );
        let t = expand("matT transpose(mat)", Avail::all(120)).unwrap();
        assert_eq!(t.len(), 9);
        assert_eq!(t[1].prototype(), "mat3x2 transpose(mat2x3)");
        let m = expand("genType modf(genType, out genType)", Avail::all(130)).unwrap();
        assert_eq!(m[3].prototype(), "vec4 modf(vec4, out vec4)");
        assert!(expand("genType nothing", Avail::all(110)).is_none());
        assert!(expand("genType f(quux)", Avail::all(110)).is_none());
    }

    #[test]
    fn outer_product_shapes() {
        let v = all();
        let f = v
            .iter()
            .find(|f| f.name == "outerProduct" && f.ret == Type::mat(2, 3))
            .unwrap();
        assert_eq!(f.prototype(), "mat2x3 outerProduct(vec3, vec2)");
        assert_eq!(v.iter().filter(|f| f.name == "outerProduct").count(), 9);
    }
}
