//! The built-ins of GLSL 1.10 to 3.30: functions (`functions`, `texture`), variables
//! (`variables`) and the uniform state and constants (`state`), each with the versions,
//! stages and profile that have it.
//!
//! Sources: the GLSL specifications 1.10 to 3.30, chapter 7 (built-in variables, uniform
//! state, constants) and chapter 8 (built-in functions). Where Mesa, the tests'
//! reference, differs from a specification, the tables follow Mesa and the entry says
//! so. The differences found by the tests:
//! - every 1.40 shader has the compatibility built-ins (Mesa's `compat_shader`);
//! - the 1.10 `*Lod` texture functions exist in fragment shaders from 1.30;
//! - ARB_texture_rectangle is always on: the float rectangle samplers and
//!   `texture2DRect`, `texture2DRectProj`, `shadow2DRect`... exist from 1.10;
//! - the integer `abs`, `sign`, `min`, `max`, `clamp` exist from 1.10, `determinant`
//!   from 1.20, `textureOffset(sampler2DArrayShadow, vec4, ivec2)` from 1.30;
//! - overloads resolve by the 4.00 rules (best inexact match) in every version.
//!
//! Mesa keeps the deprecated names (`texture2D`, `shadow2D`, `gl_FragColor`,
//! `gl_FragData`, `noise1`...) in the 1.50 and 3.30 core profiles, and so do the
//! tables; what the compatibility profile alone has (`ftransform`, `gl_Vertex`, the
//! varyings and uniform state of fixed function) is marked [`Avail::compat_only`].
//!
//! Five extensions' built-ins are in the tables, marked [`Avail::ext`] and present only
//! when enabled: ARB_shader_texture_lod (`texture2DLod` in fragment shaders,
//! `texture2DGradARB`...), ARB_shader_bit_encoding (`floatBitsToInt`... before 3.30),
//! EXT_texture_array (`sampler2DArray`, `texture2DArray`... before 1.30),
//! ARB_texture_multisample (`sampler2DMS`, its `texelFetch` and `textureSize`, before
//! 1.50) and ARB_draw_instanced (`gl_InstanceIDARB`). ARB_texture_rectangle's are
//! always there. (EXT_gpu_shader4's are not in the tables.)
//!
//! Functions are described compactly (one line for `genType sin(genType)`) and the
//! signatures generated from the descriptions: see [`functions::all`].

pub mod functions;
pub mod state;
pub mod texture;
pub mod variables;

use crate::types::{Stage, Type, Version};
use std::sync::OnceLock;

/// Where a built-in exists: the first version per stage, whether only the
/// compatibility profile has it, and the extension that must be enabled for it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Avail {
    /// The first version with the built-in in the vertex, geometry and fragment stage
    /// (`None`: never in that stage).
    pub since: [Option<u16>; 3],
    /// Only where the compatibility built-ins exist (see [`Version::compatibility`]).
    pub compat_only: bool,
    /// Only with this extension enabled (`#extension NAME : enable` or `require`).
    pub ext: Option<&'static str>,
}

impl Avail {
    /// In every stage from version `v` (geometry shaders start at 1.50).
    pub const fn all(v: u16) -> Avail {
        Avail {
            since: [Some(v), Some(if v > 150 { v } else { 150 }), Some(v)],
            compat_only: false,
            ext: None,
        }
    }

    /// Only in vertex shaders, from `v`.
    pub const fn vertex(v: u16) -> Avail {
        Avail {
            since: [Some(v), None, None],
            compat_only: false,
            ext: None,
        }
    }

    /// Only in fragment shaders, from `v`.
    pub const fn fragment(v: u16) -> Avail {
        Avail {
            since: [None, None, Some(v)],
            compat_only: false,
            ext: None,
        }
    }

    /// Only in geometry shaders, from `v` (at least 1.50).
    pub const fn geometry(v: u16) -> Avail {
        Avail {
            since: [None, Some(v), None],
            compat_only: false,
            ext: None,
        }
    }

    /// The same, restricted to the compatibility built-ins.
    pub const fn compat(self) -> Avail {
        Avail {
            compat_only: true,
            ..self
        }
    }

    /// The same, only with the extension `name` enabled.
    pub const fn ext(self, name: &'static str) -> Avail {
        Avail {
            ext: Some(name),
            ..self
        }
    }

    /// The first version in `stage`.
    pub fn since_in(&self, stage: Stage) -> Option<u16> {
        self.since[stage_index(stage)]
    }

    /// Whether the built-in exists in `version` and `stage` with no extension enabled.
    pub fn exists(&self, version: Version, stage: Stage) -> bool {
        self.exists_with(version, stage, &[])
    }

    /// Whether the built-in exists in `version` and `stage` with the extensions `exts`
    /// enabled.
    pub fn exists_with(&self, version: Version, stage: Stage, exts: &[&str]) -> bool {
        self.ext.is_none_or(|e| exts.contains(&e))
            && (!self.compat_only || version.compatibility)
            && self.since_in(stage).is_some_and(|v| version.number >= v)
    }
}

/// The index of a stage in [`Avail::since`].
pub fn stage_index(stage: Stage) -> usize {
    match stage {
        Stage::Vertex => 0,
        Stage::Geometry => 1,
        Stage::Fragment => 2,
    }
}

/// A parameter of a built-in function.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Param {
    /// The parameter's type.
    pub ty: Type,
    /// An `out` parameter (`modf`'s second): the argument must be an l-value.
    pub out: bool,
    /// The argument must be a constant expression (the texel offsets of the `*Offset`
    /// lookups).
    pub constant: bool,
}

/// One signature of a built-in function.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Function {
    /// The function's name.
    pub name: String,
    /// The return type.
    pub ret: Type,
    /// The parameters.
    pub params: Vec<Param>,
    /// Where this signature exists.
    pub avail: Avail,
}

impl Function {
    /// Whether this signature exists in `version` and `stage` with no extension
    /// enabled: its entry's availability and every type it names (a `uvec2` signature
    /// starts at 1.30 whatever the entry).
    pub fn exists(&self, version: Version, stage: Stage) -> bool {
        self.exists_with(version, stage, &[])
    }

    /// Whether this signature exists in `version` and `stage` with the extensions
    /// `exts` enabled.
    pub fn exists_with(&self, version: Version, stage: Stage, exts: &[&str]) -> bool {
        self.avail.exists_with(version, stage, exts)
            && self.ret.exists_with(version, exts)
            && self.params.iter().all(|p| p.ty.exists_with(version, exts))
    }

    /// Whether a call with arguments of types `args` matches this signature in
    /// `version`, exactly or through the version's implicit conversions (an `out`
    /// parameter converts the other way, from the parameter to the argument).
    pub fn accepts(&self, args: &[Type], version: Version) -> bool {
        args.len() == self.params.len()
            && self.params.iter().zip(args).all(|(p, a)| {
                if p.out {
                    p.ty.converts_to(a, version)
                } else {
                    a.converts_to(&p.ty, version)
                }
            })
    }

    /// The prototype as Mesa prints candidates: `vec4 texture2D(sampler2D, vec2)`.
    pub fn prototype(&self) -> String {
        let params: Vec<String> = self
            .params
            .iter()
            .map(|p| format!("{}{}", if p.out { "out " } else { "" }, p.ty))
            .collect();
        format!("{} {}({})", self.ret, self.name, params.join(", "))
    }
}

/// Every built-in function signature of every version, stage and profile.
pub fn all_functions() -> &'static [Function] {
    static ALL: OnceLock<Vec<Function>> = OnceLock::new();
    ALL.get_or_init(|| {
        let mut v = functions::all();
        v.extend(texture::all());
        v.extend(texture::lod_extension());
        v.extend(texture::array_extension());
        v
    })
}

/// The signatures of `name` in `version` and `stage` with the extensions `exts`
/// enabled (empty: no such built-in there). An extension's signature that the version
/// also has on its own counts once.
pub fn overloads(
    name: &str,
    version: Version,
    stage: Stage,
    exts: &[&str],
) -> Vec<&'static Function> {
    let mut v: Vec<&'static Function> = all_functions()
        .iter()
        .filter(|f| f.name == name && f.exists_with(version, stage, exts))
        .collect();
    let mut seen = std::collections::HashSet::new();
    v.retain(|f| seen.insert(&f.params));
    v
}

/// Why a call to a built-in function resolves to no signature.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unresolved {
    /// No built-in of that name in this version and stage (Mesa: "no function with
    /// name").
    NoFunction,
    /// No signature accepts the arguments (Mesa: "no matching function for call").
    NoMatch,
    /// Several accept them through conversions and none is best.
    Ambiguous,
}

/// The signature a call of `name` with arguments of types `args` selects, by the GLSL
/// 4.00 rules that Mesa applies to every version (the 1.20 to 3.30 specifications call
/// any call with several inexact matches ambiguous): an exact match; else, among the
/// signatures that accept the arguments through implicit conversions, the one whose
/// every parameter matches at least as well as the others' (exactly rather than
/// converted) and one better.
pub fn resolve(
    name: &str,
    args: &[Type],
    version: Version,
    stage: Stage,
    exts: &[&str],
) -> Result<&'static Function, Unresolved> {
    let all = overloads(name, version, stage, exts);
    if all.is_empty() {
        return Err(Unresolved::NoFunction);
    }
    let exact = |f: &Function, i: usize| f.params[i].ty == args[i];
    if let Some(f) = all
        .iter()
        .find(|f| f.params.len() == args.len() && (0..args.len()).all(|i| exact(f, i)))
    {
        return Ok(f);
    }
    let fits: Vec<&'static Function> = all
        .into_iter()
        .filter(|f| f.accepts(args, version))
        .collect();
    let better = |a: &Function, b: &Function| {
        (0..args.len()).all(|i| exact(a, i) || !exact(b, i))
            && (0..args.len()).any(|i| exact(a, i) && !exact(b, i))
    };
    match fits.as_slice() {
        [] => Err(Unresolved::NoMatch),
        [f] => Ok(f),
        _ => fits
            .iter()
            .find(|a| fits.iter().all(|b| std::ptr::eq(**a, *b) || better(a, b)))
            .copied()
            .ok_or(Unresolved::Ambiguous),
    }
}

/// Every built-in variable, uniform and constant of every version, stage and profile.
pub fn all_variables() -> &'static [variables::Variable] {
    static ALL: OnceLock<Vec<variables::Variable>> = OnceLock::new();
    ALL.get_or_init(variables::all)
}

/// The built-in variable `name` in `version` and `stage` with the extensions `exts`
/// enabled, if it exists there.
pub fn variable(
    name: &str,
    version: Version,
    stage: Stage,
    exts: &[&str],
) -> Option<&'static variables::Variable> {
    all_variables()
        .iter()
        .find(|v| v.name == name && v.avail.exists_with(version, stage, exts))
}
