//! Texture lookups in fragment shaders: `texture1D`/`2D`/`3D`/`Cube`, their `Proj`
//! forms, `shadow1D`/`2D` (and `Proj`), and the 1.30 `texture`/`textureProj`, when every
//! coordinate the lookup reads is a varying's component as read (a varying, an element
//! of `gl_TexCoord[]`, a swizzle of one, or a local holding one).
//!
//! Such a lookup is what llvmpipe's fixed-function texturing is: the coordinates are the
//! perspective-corrected planes at each pixel of a 2x2 quad (and, projected, times
//! `1 / q`), so the rasterizer samples it before the program runs, with the same samplers
//! and level-of-detail rules as the fixed-function units, and the program reads the
//! texel as four f32 input streams (lookup `k`: streams `4k..4k + 4`). The sampler
//! uniform's value picks the unit at each draw; its type picks the unit's target. An
//! element of a sampler array at a constant index (GLSL 1.10's rule) is a sampler of its
//! own: its unit is the array's word of that element.
//!
//! A lookup whose coordinates the shader computes (any other value, constants included)
//! is sampled by the program itself: [`Op::Sample`] hands the computed values of a chunk
//! pair (two rows of 2x2 quads) to the walk's sampler, which samples them with the same
//! samplers and level-of-detail rules (the quad's differences of the values as
//! computed, which is what llvmpipe's sampler derives them from), and [`Op::Texel`]
//! reads the texel. A projected one multiplies s, t and r by `1 / q` first, as the
//! rasterizer does for varyings (NIR's `lower_txp`). Each such lookup is one of the
//! [`crate::pipe::MAX_TEXTURE_UNITS`] lookups a shader may make (a loop of nine lookups
//! is refused).
//!
//! A lookup with a bias or a level of detail (`texture2D(s, c, bias)`, the `*Lod` and
//! `textureLod` forms), `texelFetch` and `textureSize` are sampled by the program too,
//! whatever their coordinates: the argument (an integer one as f32, and `texelFetch`'s
//! coordinates likewise) is [`Op::Sample`]'s `l`, and the lookup's
//! [`LookupKind`] says what the sampler does with it ([`crate::texture::lookup`]).
//! `textureSize` reads its result back as integers.
//!
//! Not lowered (the shader is refused): `texelFetch` and `textureSize` other than on 1D
//! and 2D samplers, offsets, gradients,
//! rectangle, array, buffer, multisample, integer and cube-shadow samplers, a sampler
//! array indexed by a value that is not constant (GLSL 1.30+ allows it only where it is
//! dynamically uniform), a sampler array element passed to a function, and lookups in
//! vertex shaders.

use super::lower::{no, Lower, R};
use crate::engine::ir::{Op, Val};
use crate::texture::lookup::LookupKind;
use crate::texture::Target;
use softgl_glsl::hir::{Expr, ExprKind, Storage};
use softgl_glsl::types::{Dim, Scalar, Type};

/// One texture lookup of a lowered shader.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TexUse {
    /// The sampler uniform's name (its value, the unit, is a uniform word).
    pub sampler: String,
    /// The element of a sampler array (a constant index; 0 for a single sampler): the
    /// unit is the uniform's word `element`.
    pub element: u16,
    /// The target its type samples.
    pub target: Target,
    /// The varying planes of s, t, r (the depth reference of a shadow lookup) and q,
    /// each with whether it is read without the perspective divide.
    pub coords: [Option<(u16, bool)>; 4],
    /// s, t and r are multiplied by `1 / q`.
    pub proj: bool,
    /// The coordinates are computed in the shader (or the lookup has a level-of-detail
    /// argument): the program samples them itself ([`Op::Sample`]) and `coords` is
    /// empty.
    pub computed: bool,
    /// The level-of-detail argument, or the non-sampling lookup it is.
    pub kind: LookupKind,
}

impl Lower<'_> {
    /// Lowers the built-in lookup `name(args)` returning `ret` (see the module doc).
    pub(super) fn texture(&mut self, name: &str, args: &[Expr], ret: &Type) -> R<Vec<Val>> {
        if self.vertex {
            return no("texture lookups in vertex shaders");
        }
        let (proj, kind) = match name {
            "texelFetch" => (false, LookupKind::Fetch),
            "textureSize" => (false, LookupKind::Size),
            _ => {
                let (stem, lod) = match name.strip_suffix("Lod") {
                    Some(stem) => (stem, true),
                    None => (name, false),
                };
                let (stem, proj) = match stem.strip_suffix("Proj") {
                    Some(stem) => (stem, true),
                    None => (stem, false),
                };
                let family = [
                    "texture1D",
                    "texture2D",
                    "texture3D",
                    "textureCube",
                    "shadow1D",
                    "shadow2D",
                    "texture",
                ];
                if !family.contains(&stem) || (proj && stem == "textureCube") {
                    return no(format!("the texture function {name}"));
                }
                let kind = match (lod, args.len()) {
                    (true, _) => LookupKind::Lod,
                    (false, 3) => LookupKind::Bias,
                    _ => LookupKind::Implicit,
                };
                (proj, kind)
            }
        };
        let Type::Sampler(s) = &args[0].ty else {
            return no("a sampler that is not a uniform variable");
        };
        // A sampler, or an element of an array of them at a constant index.
        let (id, element) = match &args[0].kind {
            ExprKind::Var(id) => (*id, 0),
            ExprKind::Index(base, idx) => {
                let ExprKind::Var(id) = &base.kind else {
                    return no("a sampler that is not a uniform variable");
                };
                let iv = self.expr(idx)?[0];
                match self.cval(iv) {
                    Some(k) => (*id, k as i32),
                    None => return no("a sampler array indexed by a value that is not constant"),
                }
            }
            _ => return no("a sampler that is not a uniform variable"),
        };
        let id = self.sampler_alias.get(&id).copied().unwrap_or(id);
        let var = &self.p.vars[id];
        if var.storage != Storage::Uniform {
            return no("a sampler that is not a uniform variable");
        }
        let len = match &var.ty {
            Type::Array(_, Some(n)) => *n as usize,
            Type::Array(_, None) => return no("an unsized sampler array"),
            _ => 1,
        };
        let element = match usize::try_from(element) {
            Ok(k) if k < len => k as u16,
            _ => return no("a sampler array index out of range"),
        };
        let target = match s.dim {
            _ if s.array || s.texel != Scalar::Float => return no(format!("{}", args[0].ty)),
            Dim::D1 => Target::Tex1D,
            Dim::D2 => Target::Tex2D,
            Dim::D3 => Target::Tex3D,
            Dim::Cube if !s.shadow => Target::Cube,
            _ => return no(format!("{}", args[0].ty)),
        };
        let flat = matches!(target, Target::Tex1D | Target::Tex2D);
        match kind {
            LookupKind::Fetch | LookupKind::Size
                if !flat || s.shadow && kind == LookupKind::Fetch =>
            {
                return no(format!("{name} with {}", args[0].ty))
            }
            _ => {}
        }
        let sampler = var.name.clone();
        // The sampler's unit is a uniform word of the draw (one per array element).
        self.uniform_slot(&sampler, &vec![Scalar::Int; len]);
        if kind == LookupKind::Size {
            let l = self.expr(&args[1])?;
            let l = self.op(Op::ItoF(l[0]));
            let zero = self.f32(0.0);
            let k = self.own_lookup((sampler, element), target, false, kind)?;
            self.op(Op::Sample {
                lookup: k as u8,
                s: zero,
                t: zero,
                r: zero,
                l,
            });
            let n = ret.components() as usize;
            return Ok((0..n)
                .map(|ch| {
                    let v = self.op(Op::Texel((4 * k + ch) as u16));
                    self.op(Op::FtoI(v))
                })
                .collect());
        }
        let mut c = self.expr(&args[1])?;
        let l = match kind {
            LookupKind::Implicit => None,
            _ => Some(self.expr(&args[2])?[0]),
        };
        if kind == LookupKind::Fetch {
            // Integer coordinates and level, exact as f32 inside any texture.
            c = c.into_iter().map(|v| self.op(Op::ItoF(v))).collect();
        }
        let l = match (kind, l) {
            (LookupKind::Fetch, Some(l)) => Some(self.op(Op::ItoF(l))),
            (_, l) => l,
        };
        let n = c.len();
        let two = !matches!(target, Target::Tex1D);
        let three = matches!(target, Target::Tex3D | Target::Cube) || s.shadow;
        let pick = [
            Some(0),
            two.then_some(1),
            three.then_some(2),
            proj.then(|| n - 1),
        ];
        let mut coords = [None; 4];
        let mut computed = false;
        for (slot, k) in coords.iter_mut().zip(pick) {
            if let Some(k) = k {
                let Some(v) = c.get(k) else {
                    return no("a texture coordinate of the wrong size");
                };
                match self.plane_vals.get(v) {
                    Some(&plane) => *slot = Some(plane),
                    None => computed = true,
                }
            }
        }
        if computed || l.is_some() {
            return self.sample_computed((sampler, element), target, &c, pick, (kind, l), ret);
        }
        let lookup = TexUse {
            sampler,
            element,
            target,
            coords,
            proj,
            computed: false,
            kind,
        };
        let k = match self.textures.iter().position(|t| *t == lookup) {
            Some(k) => k,
            None => {
                if self.textures.len() == crate::pipe::MAX_TEXTURE_UNITS {
                    return no("more texture lookups than texture units");
                }
                self.textures.push(lookup);
                self.textures.len() - 1
            }
        };
        Ok(self.texel(ret, |ch| Op::InputF((4 * k + ch) as u16)))
    }

    /// The texel a lookup returns as `ret`: channel `ch` read by `read(ch)` (one channel
    /// for a float result).
    fn texel(&mut self, ret: &Type, read: impl Fn(usize) -> Op) -> Vec<Val> {
        let n = if ret.components() == 1 { 1 } else { 4 };
        (0..n).map(|ch| self.op(read(ch))).collect()
    }

    /// A lookup of its own (the program samples it, [`Op::Sample`]): its index.
    fn own_lookup(
        &mut self,
        (sampler, element): (String, u16),
        target: Target,
        proj: bool,
        kind: LookupKind,
    ) -> R<usize> {
        if self.textures.len() == crate::pipe::MAX_TEXTURE_UNITS {
            return no("more texture lookups than texture units");
        }
        self.textures.push(TexUse {
            sampler,
            element,
            target,
            coords: [None; 4],
            proj,
            computed: true,
            kind,
        });
        Ok(self.textures.len() - 1)
    }

    /// A lookup whose coordinates `c` (components `pick`: s, t, r, q) the shader
    /// computes, or which has a level-of-detail argument (`lod`: its kind and value): a
    /// lookup of its own, sampled by the program ([`Op::Sample`]) at the values as
    /// computed, projected as the rasterizer projects varyings (each of s, t, r times
    /// `1 / q`, NIR's `lower_txp`), absent ones 0.
    fn sample_computed(
        &mut self,
        sampler: (String, u16),
        target: Target,
        c: &[Val],
        pick: [Option<usize>; 4],
        (kind, lod): (LookupKind, Option<Val>),
        ret: &Type,
    ) -> R<Vec<Val>> {
        let zero = self.f32(0.0);
        let mut co = [zero; 3];
        for (d, k) in co.iter_mut().zip(pick) {
            if let Some(k) = k {
                *d = c[k];
            }
        }
        if let Some(q) = pick[3] {
            let one = self.f32(1.0);
            let rq = self.op(Op::Div(one, c[q]));
            for d in &mut co {
                *d = self.op(Op::Mul(*d, rq));
            }
        }
        let k = self.own_lookup(sampler, target, pick[3].is_some(), kind)?;
        let [s, t, r] = co;
        self.op(Op::Sample {
            lookup: k as u8,
            s,
            t,
            r,
            l: lod.unwrap_or(zero),
        });
        Ok(self.texel(ret, |ch| Op::Texel((4 * k + ch) as u16)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shader::lower::{lower_fragment, FIRST_VARYING_PLANE};

    fn check(src: &str) -> softgl_glsl::hir::Program {
        softgl_glsl::compile(&[src], softgl_glsl::Stage::Fragment).expect("compiles")
    }

    #[test]
    fn lookups_at_varyings_lower_to_input_streams() {
        let p = check(
            "uniform sampler2D a; uniform samplerCube c; varying vec3 d;
             vec4 f(sampler2D s, vec2 p) { return texture2D(s, p); }
             void main() {
               gl_FragColor = texture2DProj(a, gl_TexCoord[1].xyw) + textureCube(c, d.zyx)
                 + f(a, gl_TexCoord[1].xy) + texture2DProj(a, gl_TexCoord[1].xyw);
             }",
        );
        let l = lower_fragment(&p).unwrap();
        // The repeated lookup is one; the one through `f` is the sampler passed.
        assert_eq!(l.textures.len(), 3);
        let tc = l.varyings.iter().find(|s| s.name == "gl_TexCoord").unwrap();
        let d = l.varyings.iter().find(|s| s.name == "d").unwrap();
        let (t1, dd) = (tc.first + 4, d.first);
        assert!(tc.first >= FIRST_VARYING_PLANE);
        let at = |p: u16| Some((p, false));
        assert_eq!(
            l.textures[0],
            TexUse {
                sampler: "a".into(),
                element: 0,
                target: Target::Tex2D,
                coords: [at(t1), at(t1 + 1), None, at(t1 + 3)],
                proj: true,
                computed: false,
                kind: LookupKind::Implicit,
            }
        );
        assert_eq!(l.textures[1].target, Target::Cube);
        assert_eq!(l.textures[1].coords, [at(dd + 2), at(dd + 1), at(dd), None]);
        assert_eq!(l.textures[2].coords, [at(t1), at(t1 + 1), None, None]);
        assert!(!l.textures[2].proj);
        // Lookup k's texel is streams 4k..4k + 4.
        let streams: Vec<u16> =
            l.ir.ops
                .iter()
                .filter_map(|op| match op {
                    Op::InputF(n) => Some(*n),
                    _ => None,
                })
                .collect();
        // (the repeated lookup reads lookup 0's streams again)
        let want: Vec<u16> = (0..12).chain(0..4).collect();
        assert_eq!(streams, want);
        // The samplers' units are uniform words.
        assert!(l.uniforms.iter().any(|s| s.name == "a" && s.count == 1));
        assert!(l.uniforms.iter().any(|s| s.name == "c" && s.count == 1));
    }

    #[test]
    fn shadow_lookups_take_the_reference_and_1_30_returns_a_float() {
        let p = check(
            "#version 130
             uniform sampler2DShadow s; out vec4 o;
             void main() { o = vec4(texture(s, gl_TexCoord[0].stp)); }",
        );
        let l = lower_fragment(&p).unwrap();
        let t0 = l.varyings[0].first;
        let at = |p: u16| Some((p, false));
        assert_eq!(l.textures[0].coords, [at(t0), at(t0 + 1), at(t0 + 2), None]);
        assert_eq!(l.color[0], l.color[3], "one channel in every component");
    }

    #[test]
    fn computed_coordinates_are_sampled_by_the_program() {
        let p = check(
            "uniform sampler2D a; uniform sampler2DShadow d;
             void main() {
               gl_FragColor = texture2D(a, gl_TexCoord[0].st * 2.0) + texture2D(a, vec2(0.5))
                 + texture2DProj(a, vec3(gl_TexCoord[0].st, gl_TexCoord[0].q + 1.0))
                 + shadow2D(d, vec3(gl_TexCoord[0].s, 0.5, gl_TexCoord[0].t))
                 + texture2D(a, gl_TexCoord[0].st);
             }",
        );
        let l = lower_fragment(&p).unwrap();
        assert_eq!(l.textures.len(), 5);
        let computed: Vec<bool> = l.textures.iter().map(|t| t.computed).collect();
        assert_eq!(computed, [true, true, true, true, false]);
        assert!(l.textures[..4].iter().all(|t| t.coords == [None; 4]));
        assert!(l.textures[2].proj && !l.textures[0].proj);
        // One Sample per computed lookup, in order, and each lookup's four texel streams.
        let samples: Vec<u8> =
            l.ir.ops
                .iter()
                .filter_map(|op| match op {
                    Op::Sample { lookup, .. } => Some(*lookup),
                    _ => None,
                })
                .collect();
        assert_eq!(samples, [0, 1, 2, 3]);
        let texels =
            l.ir.ops
                .iter()
                .filter(|op| matches!(op, Op::Texel(_)))
                .count();
        assert_eq!(texels, 16);
        // The varyings' `1 / w` and the projected lookup's `1 / q`, once each.
        let divs =
            l.ir.ops
                .iter()
                .filter(|op| matches!(op, Op::Div(..)))
                .count();
        assert_eq!(divs, 2);
    }

    #[test]
    fn lod_arguments_fetches_and_sizes_are_the_programs_own_lookups() {
        let p = check(
            "#version 130
             uniform sampler2D a; uniform sampler1D b; out vec4 o;
             void main() {
               vec4 x = texture(a, gl_TexCoord[0].st, gl_Color.r);
               vec4 y = textureLod(a, gl_TexCoord[0].st, 2.0);
               vec4 z = texture1DProjLod(b, gl_TexCoord[0].sq, 1.0);
               vec4 w = texelFetch(a, ivec2(3, 4), 1);
               ivec2 s = textureSize(a, 0);
               o = x + y + z + w + vec4(s, textureSize(b, 1), 0);
             }",
        );
        let l = lower_fragment(&p).unwrap();
        let kinds: Vec<LookupKind> = l.textures.iter().map(|t| t.kind).collect();
        use LookupKind::*;
        assert_eq!(kinds, [Bias, Lod, Lod, Fetch, Size, Size]);
        assert!(l.textures.iter().all(|t| t.computed));
        assert!(l.textures[2].proj && l.textures[2].target == Target::Tex1D);
        // Each Sample carries its argument: the level 2.0, the fetch's level 1 as f32.
        let ls: Vec<Option<u32>> =
            l.ir.ops
                .iter()
                .filter_map(|op| match op {
                    Op::Sample { l: v, .. } => Some(match l.ir.ops[v.0 as usize] {
                        Op::Const(_, bits) => Some(bits),
                        _ => None,
                    }),
                    _ => None,
                })
                .collect();
        assert_eq!(ls[1], Some(2.0f32.to_bits()));
        assert_eq!(ls[2], Some(1.0f32.to_bits()));
        assert_eq!(ls[3], Some(1.0f32.to_bits()));
        assert_eq!(ls[0], None, "the bias is the varying");
    }

    #[test]
    fn bias_dynamic_sampler_indices_and_vertex_lookups_are_refused() {
        for src in [
            "#version 130
             uniform sampler3D a; out vec4 o; void main() { o = texelFetch(a, ivec3(1), 0); }",
            "#version 130
             uniform sampler2DShadow a; out vec4 o; void main() { o = vec4(textureSize(a, 0), 0, 0) + vec4(textureGrad(a, vec3(0.5), vec2(0.1), vec2(0.1))); }",
            "uniform sampler2D a[2]; uniform int k; void main() { gl_FragColor = texture2D(a[k], gl_TexCoord[0].st); }",
            "uniform sampler2D a; void main() { vec4 c = vec4(0.0);
               for (int i = 0; i < 9; i++) c += texture2D(a, vec2(float(i) * 0.1));
               gl_FragColor = c; }",
        ] {
            assert!(lower_fragment(&check(src)).is_err(), "{src}");
        }
        let v = softgl_glsl::compile(
            &["uniform sampler2D a; void main() { gl_Position = texture2DLod(a, gl_Vertex.xy, 0.0); }"],
            softgl_glsl::Stage::Vertex,
        )
        .expect("compiles");
        assert!(crate::shader::vertex::lower_vertex(&v).is_err());
    }

    #[test]
    fn a_sampler_array_element_is_a_sampler_of_its_own() {
        let p = check(
            "uniform sampler2D a[3]; uniform samplerCube c;
             void main() {
               gl_FragColor = texture2D(a[2], gl_TexCoord[0].st) + texture2D(a[0], gl_TexCoord[0].st)
                 + textureCube(c, gl_TexCoord[0].xyz);
             }",
        );
        let l = lower_fragment(&p).unwrap();
        let e: Vec<_> = l
            .textures
            .iter()
            .map(|t| (t.sampler.as_str(), t.element))
            .collect();
        assert_eq!(e, [("a", 2), ("a", 0), ("c", 0)]);
        let a = l.uniforms.iter().find(|s| s.name == "a").unwrap();
        assert_eq!(a.count, 3, "one unit word per element");
    }
}
