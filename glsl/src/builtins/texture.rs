//! The texture lookup functions (GLSL specifications 8.7), generated from the sampler
//! types: the 1.10 family named after the target (`texture2D`, `shadow2DProj`,
//! `textureCubeLod`...), and the 1.30 overloaded family (`texture`, `textureProj`,
//! `textureLod`, `textureOffset`, `texelFetch`, `textureSize`, `textureGrad`... and their
//! combinations) over every `[iu]sampler` the version has.
//!
//! Rules taken from the specifications' tables: the optional `bias` argument exists in
//! fragment shaders only; rectangle, buffer and multisample samplers take no bias and no
//! level of detail; a shadow sampler's coordinate carries the depth reference after the
//! coordinates, at least in `.z` (so `sampler1DShadow` takes a vec3); projective lookups
//! exist for non-array 1D, 2D, 3D and rectangle targets; texel offsets must be
//! constant expressions ([`Param::constant`]). Mesa's additions, followed here: the 1.10
//! `*Lod` functions exist in fragment shaders from 1.30, the 1.10 rectangle functions
//! (`texture2DRect`...) from 1.10 (ARB_texture_rectangle is always on in Mesa), and
//! `textureOffset(sampler2DArrayShadow, vec4, ivec2)` from 1.30. None of these names is
//! compatibility-only in Mesa: the 1.50 and 3.30 core profiles have them all (tested).
//! The lookups of ARB_shader_texture_lod and EXT_texture_array are generated from the
//! same stems as the 1.10 family.

use super::{Avail, Function, Param};
use crate::types::{Dim, Sampler, Scalar, Type};

fn float_vec(n: u8) -> Type {
    Type::vec(Scalar::Float, n)
}

fn sig(name: &str, ret: Type, params: Vec<Type>, avail: Avail) -> Function {
    Function {
        name: name.to_string(),
        ret,
        params: params
            .into_iter()
            .map(|ty| Param {
                ty,
                out: false,
                constant: false,
            })
            .collect(),
        avail,
    }
}

/// Adds `name(params)` and, where `bias` is true, `name(params, float bias)` (the bias
/// form only in fragment shaders).
fn with_bias(
    v: &mut Vec<Function>,
    name: &str,
    ret: Type,
    params: Vec<Type>,
    since: u16,
    bias: bool,
) {
    if bias {
        let mut b = params.clone();
        b.push(Type::FLOAT);
        v.push(sig(name, ret.clone(), b, Avail::fragment(since)));
    }
    v.push(sig(name, ret, params, Avail::all(since)));
}

/// Where the 1.10 family's `*Lod` forms exist: vertex shaders from 1.10, fragment
/// shaders from 1.30 (Mesa), geometry shaders from 1.50.
const OLD_LOD: Avail = Avail {
    since: [Some(110), Some(150), Some(130)],
    compat_only: false,
    ext: None,
};

/// One stem of the 1.10 family: its name, sampler, the size of its coordinate, of its
/// projective coordinates, of its gradients, and whether it has bias and Lod forms.
type Stem = (&'static str, Sampler, u8, &'static [u8], u8, bool);

/// The stems of the 1.10 family (and of ARB_texture_rectangle's).
fn stems() -> [Stem; 8] {
    let float = |dim, shadow| Sampler {
        dim,
        texel: Scalar::Float,
        array: false,
        shadow,
    };
    [
        ("texture1D", float(Dim::D1, false), 1, &[2, 4], 1, true),
        ("texture2D", float(Dim::D2, false), 2, &[3, 4], 2, true),
        ("texture3D", float(Dim::D3, false), 3, &[4], 3, true),
        ("textureCube", float(Dim::Cube, false), 3, &[], 3, true),
        ("shadow1D", float(Dim::D1, true), 3, &[4], 1, true),
        ("shadow2D", float(Dim::D2, true), 3, &[4], 2, true),
        (
            "texture2DRect",
            float(Dim::Rect, false),
            2,
            &[3, 4],
            2,
            false,
        ),
        ("shadow2DRect", float(Dim::Rect, true), 3, &[4], 2, false),
    ]
}

/// Adds `{stem}{suffix}` and `{stem}Proj{suffix}` with the trailing parameters `rest`.
fn plain_and_proj(v: &mut Vec<Function>, stem: &Stem, suffix: &str, rest: &[Type], avail: Avail) {
    let (name, s, n, proj, ..) = *stem;
    for (p, size) in std::iter::once(("", n)).chain(proj.iter().map(|&p| ("Proj", p))) {
        let params = [&[Type::Sampler(s), float_vec(size)], rest].concat();
        v.push(sig(
            &format!("{name}{p}{suffix}"),
            float_vec(4),
            params,
            avail,
        ));
    }
}

/// The 1.10 family: `texture1D`, `texture2DProj`, `shadow2DLod`, `texture2DRect`...
fn old_family(v: &mut Vec<Function>) {
    for stem in stems() {
        plain_and_proj(v, &stem, "", &[], Avail::all(110));
        if stem.5 {
            plain_and_proj(v, &stem, "", &[Type::FLOAT], Avail::fragment(110));
            plain_and_proj(v, &stem, "Lod", &[Type::FLOAT], OLD_LOD);
        }
    }
}

/// ARB_shader_texture_lod: the 1.10 family's `*Lod` forms in fragment shaders, and
/// `*GradARB` forms with explicit gradients in every stage, from 1.10.
pub fn lod_extension() -> Vec<Function> {
    let ext = "GL_ARB_shader_texture_lod";
    let mut v = Vec::new();
    for stem in stems() {
        if stem.5 {
            let lod = Avail::fragment(110).ext(ext);
            plain_and_proj(&mut v, &stem, "Lod", &[Type::FLOAT], lod);
        }
        let g = float_vec(stem.4);
        plain_and_proj(
            &mut v,
            &stem,
            "GradARB",
            &[g.clone(), g],
            Avail::all(110).ext(ext),
        );
    }
    v
}

/// EXT_texture_array: `texture1DArray`, `texture2DArray`, `shadow1DArray`,
/// `shadow2DArray` with their bias forms, and the `*Lod` forms but `shadow2DArrayLod`
/// (vertex shaders, fragment shaders from 1.30, as the 1.10 family's).
pub fn array_extension() -> Vec<Function> {
    let ext = "GL_EXT_texture_array";
    let array = |dim, shadow| Sampler {
        dim,
        texel: Scalar::Float,
        array: true,
        shadow,
    };
    let stems: [Stem; 4] = [
        ("texture1DArray", array(Dim::D1, false), 2, &[], 1, true),
        ("texture2DArray", array(Dim::D2, false), 3, &[], 2, true),
        ("shadow1DArray", array(Dim::D1, true), 3, &[], 1, true),
        ("shadow2DArray", array(Dim::D2, true), 4, &[], 2, false),
    ];
    let mut v = Vec::new();
    for stem in stems {
        plain_and_proj(&mut v, &stem, "", &[], Avail::all(110).ext(ext));
        plain_and_proj(
            &mut v,
            &stem,
            "",
            &[Type::FLOAT],
            Avail::fragment(110).ext(ext),
        );
        if stem.5 {
            plain_and_proj(&mut v, &stem, "Lod", &[Type::FLOAT], OLD_LOD.ext(ext));
        }
    }
    v
}

/// The shape of the 1.30 lookups on one sampler.
struct Shape {
    s: Sampler,
    st: Type,
    /// The lookup's result: float for shadow samplers, else the g-typed vec4.
    ret: Type,
    /// The coordinate (with the shadow reference).
    p: Type,
    /// The size of an offset and of a gradient (the non-array dimensions).
    d: u8,
    since: u16,
}

impl Shape {
    fn new(s: Sampler) -> Shape {
        let c = s.coords();
        let d = c - s.array as u8;
        Shape {
            s,
            st: Type::Sampler(s),
            ret: if s.shadow {
                Type::FLOAT
            } else {
                Type::vec(s.texel, 4)
            },
            p: float_vec(if s.shadow { (c + 1).max(3) } else { c }),
            d,
            since: s.since().max(130),
        }
    }

    /// The projective coordinates: one more than the coordinate, and vec4.
    fn proj(&self) -> Vec<Type> {
        let s = self.s;
        let projective = !s.array && matches!(s.dim, Dim::D1 | Dim::D2 | Dim::D3 | Dim::Rect);
        match () {
            _ if !projective => vec![],
            _ if s.shadow || s.dim == Dim::D3 => vec![float_vec(4)],
            _ => vec![float_vec(self.d + 1), float_vec(4)],
        }
    }

    fn offset(&self) -> Type {
        Type::vec(Scalar::Int, self.d)
    }

    fn grad(&self) -> Type {
        float_vec(self.d)
    }

    /// Rectangle, buffer and multisample samplers have one level.
    fn has_levels(&self) -> bool {
        !matches!(self.s.dim, Dim::Rect | Dim::Buffer | Dim::Ms)
    }

    /// Whether the sampler takes the lookups with a float coordinate at all.
    fn samples(&self) -> bool {
        !matches!(self.s.dim, Dim::Buffer | Dim::Ms)
    }

    /// The targets `textureOffset`, `textureLodOffset` and `textureGradOffset` take:
    /// no cube maps.
    fn offsets(&self) -> bool {
        self.samples() && self.s.dim != Dim::Cube
    }

    /// `textureLod`: not on cube or 2D-array shadow samplers.
    fn lod(&self) -> bool {
        self.has_levels() && !(self.s.shadow && self.p == float_vec(4))
    }
}

/// The 1.30 family over one sampler.
fn new_family(v: &mut Vec<Function>, sh: &Shape) {
    let (s, t) = (sh.s, sh.since);
    let bias = sh.has_levels() && !(s.shadow && s.array && s.dim == Dim::D2);
    let size = Type::vec(
        Scalar::Int,
        sh.d - (s.dim == Dim::Cube) as u8 + s.array as u8,
    );
    let lod: &[Type] = if sh.has_levels() { &[Type::INT] } else { &[] };
    v.push(sig(
        "textureSize",
        size,
        [std::slice::from_ref(&sh.st), lod].concat(),
        Avail::all(t),
    ));
    // `name(sampler, rest...)`, with the bias form when `b`.
    let mut add = |name: &str, rest: &[Type], b: bool| {
        let params = [std::slice::from_ref(&sh.st), rest].concat();
        with_bias(v, name, sh.ret.clone(), params, t, b);
    };
    let (p, o, g, f) = (sh.p.clone(), sh.offset(), sh.grad(), Type::FLOAT);
    if !s.shadow && s.dim != Dim::Cube {
        let ip = Type::vec(Scalar::Int, s.coords());
        // The level, or the sample of a multisample texture.
        let level: &[Type] = if sh.has_levels() || s.dim == Dim::Ms {
            &[Type::INT]
        } else {
            &[]
        };
        add(
            "texelFetch",
            &[std::slice::from_ref(&ip), level].concat(),
            false,
        );
        if sh.samples() {
            add(
                "texelFetchOffset",
                &[&[ip], level, std::slice::from_ref(&o)].concat(),
                false,
            );
        }
    }
    if !sh.samples() {
        return;
    }
    add("texture", std::slice::from_ref(&p), bias);
    add("textureGrad", &[p.clone(), g.clone(), g.clone()], false);
    if sh.lod() {
        add("textureLod", &[p.clone(), f.clone()], false);
    }
    if sh.offsets() {
        // Mesa also has textureOffset on sampler2DArrayShadow (no bias), from 1.30.
        add("textureOffset", &[p.clone(), o.clone()], bias);
        if sh.lod() {
            add(
                "textureLodOffset",
                &[p.clone(), f.clone(), o.clone()],
                false,
            );
        }
        add(
            "textureGradOffset",
            &[p, g.clone(), g.clone(), o.clone()],
            false,
        );
    }
    for q in sh.proj() {
        add("textureProj", std::slice::from_ref(&q), bias);
        add("textureProjOffset", &[q.clone(), o.clone()], bias);
        add("textureProjGrad", &[q.clone(), g.clone(), g.clone()], false);
        add(
            "textureProjGradOffset",
            &[q.clone(), g.clone(), g.clone(), o.clone()],
            false,
        );
        if sh.has_levels() {
            add("textureProjLod", &[q.clone(), f.clone()], false);
            add("textureProjLodOffset", &[q, f.clone(), o.clone()], false);
        }
    }
}

/// Every texture lookup signature of every version and stage.
pub fn all() -> Vec<Function> {
    let mut v = Vec::new();
    old_family(&mut v);
    for s in Sampler::all() {
        new_family(&mut v, &Shape::new(s));
        // ARB_texture_multisample: the multisample lookups in any version (Mesa).
        if let Some(ext @ "GL_ARB_texture_multisample") = s.extension() {
            let mut w = Vec::new();
            new_family(
                &mut w,
                &Shape {
                    since: 110,
                    ..Shape::new(s)
                },
            );
            v.extend(w.into_iter().map(|f| Function {
                avail: f.avail.ext(ext),
                ..f
            }));
        }
    }
    // The offset of an `*Offset` lookup is its last parameter but the bias, and must be
    // a constant expression.
    for f in v.iter_mut().filter(|f| f.name.ends_with("Offset")) {
        let bias = f.avail == Avail::fragment(f.avail.since[2].unwrap_or(0));
        let at = f.params.len() - 1 - bias as usize;
        f.params[at].constant = true;
    }
    v
}
