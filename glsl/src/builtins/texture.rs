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
//! exist for non-array 1D, 2D, 3D and rectangle targets. Mesa's additions, followed
//! here: the 1.10 `*Lod` functions exist in fragment shaders from 1.30, and the 1.10
//! rectangle functions (`texture2DRect`...) exist from 1.10 (ARB_texture_rectangle is
//! always on in Mesa). None of these names is compatibility-only in Mesa: the
//! specifications list them as deprecated, not removed, up to 3.30.

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

/// The 1.10 family: `texture1D`, `texture2DProj`, `shadow2DLod`, `texture2DRect`...
fn old_family(v: &mut Vec<Function>) {
    // (name stem, sampler, coordinate sizes of the plain and projective forms, lod forms)
    let float = |dim, shadow| Sampler {
        dim,
        texel: Scalar::Float,
        array: false,
        shadow,
    };
    let stems: [(&str, Sampler, u8, &[u8], bool); 8] = [
        ("texture1D", float(Dim::D1, false), 1, &[2, 4], true),
        ("texture2D", float(Dim::D2, false), 2, &[3, 4], true),
        ("texture3D", float(Dim::D3, false), 3, &[4], true),
        ("textureCube", float(Dim::Cube, false), 3, &[], true),
        ("shadow1D", float(Dim::D1, true), 3, &[4], true),
        ("shadow2D", float(Dim::D2, true), 3, &[4], true),
        ("texture2DRect", float(Dim::Rect, false), 2, &[3, 4], false),
        ("shadow2DRect", float(Dim::Rect, true), 3, &[4], false),
    ];
    let vec4 = float_vec(4);
    // Vertex shaders from 1.10, fragment shaders from 1.30 (Mesa), geometry from 1.50.
    let lod = Avail {
        since: [Some(110), Some(150), Some(130)],
        compat_only: false,
    };
    for (stem, s, n, proj, has_lod) in stems {
        let st = Type::Sampler(s);
        with_bias(
            v,
            stem,
            vec4.clone(),
            vec![st.clone(), float_vec(n)],
            110,
            has_lod,
        );
        let pname = format!("{stem}Proj");
        for &p in proj {
            with_bias(
                v,
                &pname,
                vec4.clone(),
                vec![st.clone(), float_vec(p)],
                110,
                has_lod,
            );
        }
        if has_lod {
            let params = vec![st.clone(), float_vec(n), Type::FLOAT];
            v.push(sig(&format!("{stem}Lod"), vec4.clone(), params, lod));
            for &p in proj {
                let params = vec![st.clone(), float_vec(p), Type::FLOAT];
                v.push(sig(&format!("{stem}ProjLod"), vec4.clone(), params, lod));
            }
        }
    }
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
    /// no cube maps (nor 2D array shadows but for textureGradOffset).
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
    let (st, ret, p, t) = (&sh.st, &sh.ret, &sh.p, sh.since);
    let bias = sh.has_levels() && !(sh.s.shadow && sh.s.array && sh.s.dim == Dim::D2);
    let size = Type::vec(
        Scalar::Int,
        (sh.d - (sh.s.dim == Dim::Cube) as u8) + sh.s.array as u8,
    );
    let mut size_params = vec![st.clone()];
    if sh.has_levels() {
        size_params.push(Type::INT);
    }
    v.push(sig("textureSize", size, size_params, Avail::all(t)));
    let int = Type::INT;
    let ip = Type::vec(Scalar::Int, sh.s.coords());
    if !sh.s.shadow && sh.s.dim != Dim::Cube {
        let extra = match sh.s.dim {
            Dim::Rect | Dim::Buffer => vec![],
            _ => vec![int.clone()],
        };
        let fetch = [vec![st.clone(), ip.clone()], extra.clone()].concat();
        v.push(sig("texelFetch", ret.clone(), fetch.clone(), Avail::all(t)));
        if !matches!(sh.s.dim, Dim::Buffer | Dim::Ms) {
            let params = [fetch, vec![sh.offset()]].concat();
            v.push(sig("texelFetchOffset", ret.clone(), params, Avail::all(t)));
        }
    }
    if !sh.samples() {
        return;
    }
    let g = [sh.grad(), sh.grad()];
    with_bias(
        v,
        "texture",
        ret.clone(),
        vec![st.clone(), p.clone()],
        t,
        bias,
    );
    v.push(sig(
        "textureGrad",
        ret.clone(),
        [vec![st.clone(), p.clone()], g.to_vec()].concat(),
        Avail::all(t),
    ));
    if sh.lod() {
        v.push(sig(
            "textureLod",
            ret.clone(),
            vec![st.clone(), p.clone(), Type::FLOAT],
            Avail::all(t),
        ));
    }
    if sh.offsets() {
        let o = sh.offset();
        let two_d_array_shadow = sh.s.shadow && sh.s.array && sh.s.dim == Dim::D2;
        if !two_d_array_shadow {
            with_bias(
                v,
                "textureOffset",
                ret.clone(),
                vec![st.clone(), p.clone(), o.clone()],
                t,
                bias,
            );
        }
        if sh.lod() && sh.s.dim != Dim::Cube {
            let params = vec![st.clone(), p.clone(), Type::FLOAT, o.clone()];
            v.push(sig("textureLodOffset", ret.clone(), params, Avail::all(t)));
        }
        let params = [vec![st.clone(), p.clone()], g.to_vec(), vec![o.clone()]].concat();
        v.push(sig("textureGradOffset", ret.clone(), params, Avail::all(t)));
    }
    for q in sh.proj() {
        let o = sh.offset();
        with_bias(
            v,
            "textureProj",
            ret.clone(),
            vec![st.clone(), q.clone()],
            t,
            bias,
        );
        with_bias(
            v,
            "textureProjOffset",
            ret.clone(),
            vec![st.clone(), q.clone(), o.clone()],
            t,
            bias,
        );
        let grad = [vec![st.clone(), q.clone()], g.to_vec()].concat();
        v.push(sig(
            "textureProjGrad",
            ret.clone(),
            grad.clone(),
            Avail::all(t),
        ));
        v.push(sig(
            "textureProjGradOffset",
            ret.clone(),
            [grad, vec![o.clone()]].concat(),
            Avail::all(t),
        ));
        if sh.has_levels() {
            let params = vec![st.clone(), q.clone(), Type::FLOAT];
            v.push(sig(
                "textureProjLod",
                ret.clone(),
                params.clone(),
                Avail::all(t),
            ));
            v.push(sig(
                "textureProjLodOffset",
                ret.clone(),
                [params, vec![o]].concat(),
                Avail::all(t),
            ));
        }
    }
}

/// Every texture lookup signature of every version and stage.
pub fn all() -> Vec<Function> {
    let mut v = Vec::new();
    old_family(&mut v);
    for s in Sampler::all() {
        new_family(&mut v, &Shape::new(s));
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
