//! The built-in variables of the vertex, geometry and fragment stages (GLSL
//! specifications 7.1 to 7.3 and 7.6 for the compatibility varyings), with the uniform
//! state and the constants of `state`: one description line per variable,
//! `TYPE NAME` or `TYPE NAME[SIZE]`, SIZE a number, a constant's name or empty
//! (an unsized array such as `gl_TexCoord[]`).
//!
//! The table follows Mesa, the tests' reference: the compatibility variables exist in
//! every 1.40 shader (Mesa's `compat_shader`; the 1.40 specification has them only with
//! ARB_compatibility); `gl_FragColor` and `gl_FragData` exist in the 1.50 and 3.30 core
//! profiles; `gl_ClipVertex` is, like the fixed-function varyings, compatibility-only
//! in 1.50 and 3.30; `gl_PointCoord` starts at 1.20.

use super::{state, Avail};
use crate::types::{Member, Struct, Type};
use std::sync::Arc;

/// What a built-in variable is to a shader.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Kind {
    /// A stage input: read-only.
    Input,
    /// A stage output: written, and readable back.
    Output,
    /// Built-in uniform state: read-only.
    Uniform,
    /// A built-in constant (`const int`), usable in constant expressions.
    Constant,
}

/// One built-in variable in the stages and versions of its `avail`.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Variable {
    /// The name (`gl_Position`).
    pub name: String,
    /// The type (arrays sized by the constant they are declared with).
    pub ty: Type,
    /// Input, output, uniform or constant.
    pub kind: Kind,
    /// Where it exists.
    pub avail: Avail,
    /// A constant's value (softgl's limit; see `state`).
    pub value: Option<i32>,
}

impl Variable {
    /// Whether a shader may assign to it: outputs only.
    pub fn writable(&self) -> bool {
        self.kind == Kind::Output
    }
}

const V: Avail = Avail::vertex(110);
const G: Avail = Avail::geometry(150);
const F: Avail = Avail::fragment(110);

/// The compatibility varyings a vertex (or geometry) shader writes.
const COMPAT_OUT: &str = "vec4 gl_ClipVertex; vec4 gl_FrontColor; vec4 gl_BackColor;
    vec4 gl_FrontSecondaryColor; vec4 gl_BackSecondaryColor; vec4 gl_TexCoord[];
    float gl_FogFragCoord";

/// The stage inputs and outputs.
const TABLE: &[(Avail, Kind, &str)] = &[
    (V, Kind::Output, "vec4 gl_Position; float gl_PointSize"),
    (V.compat(), Kind::Output, COMPAT_OUT),
    (
        V.compat(),
        Kind::Input,
        "vec4 gl_Color; vec4 gl_SecondaryColor; vec3 gl_Normal; vec4 gl_Vertex;
         vec4 gl_MultiTexCoord0; vec4 gl_MultiTexCoord1; vec4 gl_MultiTexCoord2;
         vec4 gl_MultiTexCoord3; vec4 gl_MultiTexCoord4; vec4 gl_MultiTexCoord5;
         vec4 gl_MultiTexCoord6; vec4 gl_MultiTexCoord7; float gl_FogCoord",
    ),
    (Avail::vertex(130), Kind::Input, "int gl_VertexID"),
    (Avail::vertex(130), Kind::Output, "float gl_ClipDistance[]"),
    (Avail::vertex(140), Kind::Input, "int gl_InstanceID"),
    (
        Avail::vertex(110).ext("GL_ARB_draw_instanced"),
        Kind::Input,
        "int gl_InstanceIDARB",
    ),
    (G, Kind::Input, "gl_PerVertex gl_in[]; int gl_PrimitiveIDIn"),
    (
        G,
        Kind::Output,
        "vec4 gl_Position; float gl_PointSize; float gl_ClipDistance[]; int gl_PrimitiveID;
         int gl_Layer",
    ),
    (G.compat(), Kind::Output, COMPAT_OUT),
    (F, Kind::Input, "vec4 gl_FragCoord; bool gl_FrontFacing"),
    (
        F,
        Kind::Output,
        "vec4 gl_FragColor; vec4 gl_FragData[gl_MaxDrawBuffers]; float gl_FragDepth",
    ),
    (
        F.compat(),
        Kind::Input,
        "vec4 gl_Color; vec4 gl_SecondaryColor; vec4 gl_TexCoord[]; float gl_FogFragCoord",
    ),
    (Avail::fragment(120), Kind::Input, "vec2 gl_PointCoord"),
    (Avail::fragment(130), Kind::Input, "float gl_ClipDistance[]"),
    (Avail::fragment(150), Kind::Input, "int gl_PrimitiveID"),
];

/// The type a description names: a basic type, a sampler or one of `structs`.
fn type_of(name: &str, structs: &[Arc<Struct>]) -> Option<Type> {
    Type::named(name).or_else(|| {
        structs
            .iter()
            .find(|s| s.name == name)
            .map(|s| Type::Struct(s.clone()))
    })
}

/// Parses `TYPE NAME[SIZE]` (SIZE a number, a constant of `state` or empty).
pub fn declaration(line: &str, structs: &[Arc<Struct>]) -> Option<(String, Type)> {
    let (ty, name) = line.trim().split_once(char::is_whitespace)?;
    let ty = type_of(ty, structs)?;
    let name = name.trim();
    match name.split_once('[') {
        None => Some((name.to_string(), ty)),
        Some((name, size)) => {
            let size = size.strip_suffix(']')?.trim();
            let len = match size {
                "" => None,
                _ => Some(size.parse().ok().or_else(|| state::constant(size))? as u32),
            };
            Some((name.to_string(), ty.array(len)))
        }
    }
}

/// Parses a `;`-separated list of declarations into variables.
pub fn parse(list: &str, kind: Kind, avail: Avail, structs: &[Arc<Struct>]) -> Vec<Variable> {
    list.split(';')
        .map(|d| {
            let (name, ty) = declaration(d, structs).expect("well-formed built-in variable");
            Variable {
                name,
                ty,
                kind,
                avail,
                value: None,
            }
        })
        .collect()
}

/// The geometry shader's `gl_PerVertex` input block, as a struct type.
fn per_vertex() -> Arc<Struct> {
    let members = [
        "vec4 gl_Position",
        "float gl_PointSize",
        "float gl_ClipDistance[]",
    ];
    Arc::new(Struct {
        name: "gl_PerVertex".into(),
        members: members
            .iter()
            .map(|m| {
                let (name, ty) = declaration(m, &[]).expect("well-formed member");
                Member { name, ty }
            })
            .collect(),
    })
}

/// Every built-in variable (inputs, outputs, uniform state and constants) of every
/// version and stage.
pub fn all() -> Vec<Variable> {
    let structs = [per_vertex()];
    let mut v: Vec<Variable> = TABLE
        .iter()
        .flat_map(|(avail, kind, list)| parse(list, *kind, *avail, &structs))
        .collect();
    v.extend(state::uniforms());
    v.extend(state::constants());
    v
}
