//! The built-in uniform state (GLSL specifications 7.5: the matrices, depth range,
//! clip planes, point, material, light, texture environment, texture generation and fog
//! state, with their struct types) and the built-in constants (7.4).
//!
//! The constants' values are softgl's implementation limits. Where softgl has the limit
//! already, [`CONSTANTS`] names the place; the limits of shader resources softgl does
//! not have yet (uniform components, varyings, image units, geometry shaders) are
//! llvmpipe's, as Mesa 22.3 reports them to a shader, so that softgl accepts the same
//! shaders as the reference. Everything here but `gl_DepthRange` and the
//! non-fixed-function constants is compatibility-only from 1.50.

use super::variables::{declaration, parse, Kind, Variable};
use super::Avail;
use crate::types::{Member, Struct};
use std::sync::Arc;

/// Where a constant's value comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Source {
    /// softgl's own limit, at this place in its `src/`.
    Softgl(&'static str),
    /// llvmpipe's limit as Mesa reports it (softgl has no such resource yet).
    Llvmpipe,
}

/// One built-in constant: name, value, the first version, compatibility-only, source.
pub type Constant = (&'static str, i32, u16, bool, Source);

const GET: &str = "src/context/get.rs";

/// The built-in constants (all `const int`, in every stage).
pub const CONSTANTS: &[Constant] = &[
    ("gl_MaxLights", 8, 110, true, Source::Softgl(GET)),
    ("gl_MaxClipPlanes", 8, 110, true, Source::Softgl(GET)),
    (
        "gl_MaxTextureUnits",
        8,
        110,
        true,
        Source::Softgl("src/pipe/primitive.rs"),
    ),
    // softgl's texture coordinate sets are its texture units (src/ffi/textures.rs).
    (
        "gl_MaxTextureCoords",
        8,
        110,
        true,
        Source::Softgl("src/pipe/primitive.rs"),
    ),
    // GL_MAX_COLOR_ATTACHMENTS: the draw buffers glDrawBuffers will take.
    (
        "gl_MaxDrawBuffers",
        8,
        110,
        false,
        Source::Softgl("src/context/fbo.rs"),
    ),
    ("gl_MaxVertexAttribs", 16, 110, false, Source::Llvmpipe),
    (
        "gl_MaxVertexUniformComponents",
        16384,
        110,
        false,
        Source::Llvmpipe,
    ),
    ("gl_MaxVaryingFloats", 128, 110, false, Source::Llvmpipe),
    (
        "gl_MaxVertexTextureImageUnits",
        32,
        110,
        false,
        Source::Llvmpipe,
    ),
    (
        "gl_MaxCombinedTextureImageUnits",
        192,
        110,
        false,
        Source::Llvmpipe,
    ),
    ("gl_MaxTextureImageUnits", 32, 110, false, Source::Llvmpipe),
    (
        "gl_MaxFragmentUniformComponents",
        16384,
        110,
        false,
        Source::Llvmpipe,
    ),
    ("gl_MaxVaryingComponents", 128, 130, false, Source::Llvmpipe),
    // Clip distances are the clip planes (GL_MAX_CLIP_PLANES).
    ("gl_MaxClipDistances", 8, 130, false, Source::Softgl(GET)),
    (
        "gl_MaxVertexOutputComponents",
        128,
        150,
        false,
        Source::Llvmpipe,
    ),
    (
        "gl_MaxFragmentInputComponents",
        128,
        150,
        false,
        Source::Llvmpipe,
    ),
    (
        "gl_MaxGeometryInputComponents",
        128,
        150,
        false,
        Source::Llvmpipe,
    ),
    (
        "gl_MaxGeometryOutputComponents",
        128,
        150,
        false,
        Source::Llvmpipe,
    ),
    (
        "gl_MaxGeometryTextureImageUnits",
        32,
        150,
        false,
        Source::Llvmpipe,
    ),
    (
        "gl_MaxGeometryOutputVertices",
        1024,
        150,
        false,
        Source::Llvmpipe,
    ),
    (
        "gl_MaxGeometryTotalOutputComponents",
        1024,
        150,
        false,
        Source::Llvmpipe,
    ),
    (
        "gl_MaxGeometryUniformComponents",
        16384,
        150,
        false,
        Source::Llvmpipe,
    ),
    (
        "gl_MaxGeometryVaryingComponents",
        128,
        150,
        false,
        Source::Llvmpipe,
    ),
];

/// The value of the built-in constant `name`.
pub fn constant(name: &str) -> Option<i32> {
    CONSTANTS.iter().find(|c| c.0 == name).map(|c| c.1)
}

/// The built-in constants as variables.
pub fn constants() -> Vec<Variable> {
    CONSTANTS
        .iter()
        .map(|&(name, value, since, compat, _)| {
            let avail = Avail::all(since);
            Variable {
                name: name.into(),
                ty: crate::types::Type::INT,
                kind: Kind::Constant,
                avail: if compat { avail.compat() } else { avail },
                value: Some(value),
            }
        })
        .collect()
}

/// The struct types of the uniform state: name and `;`-separated members.
const STRUCTS: &[(&str, &str)] = &[
    (
        "gl_DepthRangeParameters",
        "float near; float far; float diff",
    ),
    (
        "gl_PointParameters",
        "float size; float sizeMin; float sizeMax; float fadeThresholdSize;
         float distanceConstantAttenuation; float distanceLinearAttenuation;
         float distanceQuadraticAttenuation",
    ),
    (
        "gl_MaterialParameters",
        "vec4 emission; vec4 ambient; vec4 diffuse; vec4 specular; float shininess",
    ),
    (
        "gl_LightSourceParameters",
        "vec4 ambient; vec4 diffuse; vec4 specular; vec4 position; vec4 halfVector;
         vec3 spotDirection; float spotExponent; float spotCutoff; float spotCosCutoff;
         float constantAttenuation; float linearAttenuation; float quadraticAttenuation",
    ),
    ("gl_LightModelParameters", "vec4 ambient"),
    ("gl_LightModelProducts", "vec4 sceneColor"),
    (
        "gl_LightProducts",
        "vec4 ambient; vec4 diffuse; vec4 specular",
    ),
    (
        "gl_FogParameters",
        "vec4 color; float density; float start; float end; float scale",
    ),
];

/// The struct types of the uniform state (`gl_LightSourceParameters`...).
pub fn structs() -> Vec<Arc<Struct>> {
    STRUCTS
        .iter()
        .map(|(name, members)| {
            Arc::new(Struct {
                name: name.to_string(),
                members: members
                    .split(';')
                    .map(|m| {
                        let (name, ty) = declaration(m, &[]).expect("well-formed member");
                        Member { name, ty }
                    })
                    .collect(),
            })
        })
        .collect()
}

/// The compatibility uniform state.
const COMPAT: &str = "mat4 gl_ModelViewMatrix; mat4 gl_ProjectionMatrix;
    mat4 gl_ModelViewProjectionMatrix; mat4 gl_TextureMatrix[gl_MaxTextureCoords];
    mat3 gl_NormalMatrix; float gl_NormalScale; vec4 gl_ClipPlane[gl_MaxClipPlanes];
    gl_PointParameters gl_Point; gl_MaterialParameters gl_FrontMaterial;
    gl_MaterialParameters gl_BackMaterial;
    gl_LightSourceParameters gl_LightSource[gl_MaxLights];
    gl_LightModelParameters gl_LightModel;
    gl_LightModelProducts gl_FrontLightModelProduct;
    gl_LightModelProducts gl_BackLightModelProduct;
    gl_LightProducts gl_FrontLightProduct[gl_MaxLights];
    gl_LightProducts gl_BackLightProduct[gl_MaxLights];
    vec4 gl_TextureEnvColor[gl_MaxTextureUnits];
    vec4 gl_EyePlaneS[gl_MaxTextureCoords]; vec4 gl_EyePlaneT[gl_MaxTextureCoords];
    vec4 gl_EyePlaneR[gl_MaxTextureCoords]; vec4 gl_EyePlaneQ[gl_MaxTextureCoords];
    vec4 gl_ObjectPlaneS[gl_MaxTextureCoords]; vec4 gl_ObjectPlaneT[gl_MaxTextureCoords];
    vec4 gl_ObjectPlaneR[gl_MaxTextureCoords]; vec4 gl_ObjectPlaneQ[gl_MaxTextureCoords];
    gl_FogParameters gl_Fog";

/// Every built-in uniform, in every stage: `gl_DepthRange` in all profiles, the rest
/// compatibility-only; the four matrices also as `Inverse`, `Transpose` and
/// `InverseTranspose` (1.10).
pub fn uniforms() -> Vec<Variable> {
    let structs = structs();
    let mut decls = String::from(COMPAT);
    for m in ["ModelView", "Projection", "ModelViewProjection", "Texture"] {
        for form in ["Inverse", "Transpose", "InverseTranspose"] {
            let size = if m == "Texture" {
                "[gl_MaxTextureCoords]"
            } else {
                ""
            };
            decls += &format!("; mat4 gl_{m}Matrix{form}{size}");
        }
    }
    let all = Avail::all(110);
    let mut v = parse(
        "gl_DepthRangeParameters gl_DepthRange",
        Kind::Uniform,
        all,
        &structs,
    );
    v.extend(parse(&decls, Kind::Uniform, all.compat(), &structs));
    v
}
