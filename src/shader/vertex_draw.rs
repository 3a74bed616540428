//! Vertex shaders in draws: a linked vertex shader is lowered and compiled once
//! ([`VertShader::prepare`]); a draw makes a [`VertexRun`] of it (its uniform values, the
//! built-in matrices, where each output goes) and runs it over the draw's vertices 256 at
//! a time ([`VertexRun::run`]): the attributes are copied into the engine's input
//! streams (8 vertices a chunk, 32 chunks a batch), the program runs on the engine
//! ([`crate::engine::exec::Program::run_streams`]), and the outputs land in the
//! [`ClipVertex`] fields the fixed-function stage would have written, which clipping,
//! setup and the fragment stage read as before.
//!
//! Where outputs go: `gl_Position` is the clip position (the window position and clip
//! mask follow from it as for fixed function); `gl_FrontColor` and
//! `gl_FrontSecondaryColor` the primary and secondary colour varyings, clamped to
//! [0, 1] (GL_CLAMP_VERTEX_COLOR's default) as fixed function's are (Mesa's
//! fixed-function stage is a vertex program too: the same clamp, NaN → 1);
//! `gl_FogFragCoord` the fog coordinate; `gl_TexCoord[u]` unit `u`'s coordinates (the
//! fragment shader's `gl_TexCoord[u]`, or under fixed-function fragments the slot of
//! the enabled unit `u`); a user varying the slot its fragment shader reads it from
//! ([`super::draw::FragShader`]'s layout); `gl_PointSize` the vertex's point size when
//! GL_VERTEX_PROGRAM_POINT_SIZE is on (dropped when it is off: points take
//! glPointSize); `gl_BackColor` and `gl_BackSecondaryColor` the back colours after every
//! other varying when GL_VERTEX_PROGRAM_TWO_SIDE is on (setup swaps them in on back
//! faces, as for two-sided lighting; one the shader does not write copies the front
//! one). With user clip planes enabled, `gl_ClipVertex` (or, when the shader does not
//! write it, the clip position) goes to four varyings after the others, which the
//! clipper measures with the eye-space planes, as Mesa's draw module does
//! ([`crate::geometry::clip::UserPlanes`]).

use super::lower::Slot;
use super::vertex::lower_vertex;
use crate::engine::exec::{compile, Program, Scratch, MAX_BATCH};
use crate::fixed_function::transform::clamp_color;
use crate::geometry::source::VertexSource;
use crate::geometry::{clip_mask, user_clip_mask, ClipVertex, Viewport};
use crate::geometry::{VARY_FOG, VARY_SPEC, VARY_TEX};
use crate::pipe::MAX_TEXTURE_UNITS;
use softgl_glsl::hir;
use std::sync::Arc;

/// Where an attribute's values come from.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Source {
    /// The vertex position (`gl_Vertex`, generic attribute 0).
    Position,
    /// `gl_Color`.
    Color,
    /// `gl_SecondaryColor`.
    Secondary,
    /// `gl_Normal`.
    Normal,
    /// `gl_FogCoord`.
    Fog,
    /// `gl_MultiTexCoordN`.
    Tex(usize),
    /// A generic attribute at this location (1..16): its current value.
    Generic(usize),
}

/// A vertex shader a draw can run.
pub struct VertShader {
    program: Program,
    /// The uniforms the lowered code reads, in slot order.
    pub uniforms: Vec<Slot>,
    /// Each attribute's source and first stream.
    attributes: Vec<(Source, Slot)>,
    /// The outputs written.
    pub outputs: Vec<Slot>,
}

impl std::fmt::Debug for VertShader {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "VertShader({} outputs)", self.outputs.len())
    }
}

/// The built-in matrix uniforms the context supplies (`context::builtin_matrices`), in
/// either stage.
pub const MATRIX_UNIFORMS: [&str; 18] = [
    "gl_NormalScale",
    "gl_ModelViewMatrix",
    "gl_ProjectionMatrix",
    "gl_ModelViewProjectionMatrix",
    "gl_TextureMatrix",
    "gl_NormalMatrix",
    "gl_ModelViewMatrixTranspose",
    "gl_ProjectionMatrixTranspose",
    "gl_ModelViewProjectionMatrixTranspose",
    "gl_TextureMatrixTranspose",
    "gl_ModelViewMatrixInverse",
    "gl_ProjectionMatrixInverse",
    "gl_ModelViewProjectionMatrixInverse",
    "gl_TextureMatrixInverse",
    "gl_ModelViewMatrixInverseTranspose",
    "gl_ProjectionMatrixInverseTranspose",
    "gl_ModelViewProjectionMatrixInverseTranspose",
    "gl_TextureMatrixInverseTranspose",
];

/// The built-in state uniforms the context supplies (`context::builtin_uniforms`), in
/// either stage, with the user uniforms' words in slot order.
pub const STATE_UNIFORMS: [&str; 22] = [
    "gl_LightSource",
    "gl_LightModel",
    "gl_FrontMaterial",
    "gl_BackMaterial",
    "gl_FrontLightModelProduct",
    "gl_BackLightModelProduct",
    "gl_FrontLightProduct",
    "gl_BackLightProduct",
    "gl_Fog",
    "gl_DepthRange",
    "gl_ClipPlane",
    "gl_Point",
    "gl_TextureEnvColor",
    "gl_EyePlaneS",
    "gl_EyePlaneT",
    "gl_EyePlaneR",
    "gl_EyePlaneQ",
    "gl_ObjectPlaneS",
    "gl_ObjectPlaneT",
    "gl_ObjectPlaneR",
    "gl_ObjectPlaneQ",
    // `gl_InstanceID`: the instance an instanced draw is drawing (vertex stage only).
    super::lower::INSTANCE_ID,
];

/// Whether the context supplies built-in uniform `name` ([`MATRIX_UNIFORMS`],
/// [`STATE_UNIFORMS`]).
pub fn is_state_uniform(name: &str) -> bool {
    MATRIX_UNIFORMS.contains(&name) || STATE_UNIFORMS.contains(&name)
}

impl VertShader {
    /// Lowers and compiles `hir`, its user attributes at the locations `location` gives
    /// (from the link); `Err` says why a draw cannot run it.
    pub fn prepare(
        hir: &hir::Program,
        location: impl Fn(&str) -> Option<i32>,
    ) -> Result<Arc<VertShader>, String> {
        let l = lower_vertex(hir).map_err(|e| e.0)?;
        if let Some(s) = l.uniforms.iter().find(|s| {
            let n = s.name.as_str();
            n.starts_with("gl_") && !is_state_uniform(n)
        }) {
            return Err(format!("built-in uniform {} is not supplied", s.name));
        }
        let mut attributes = Vec::new();
        for s in l.attributes {
            let src = match s.name.as_str() {
                "gl_Vertex" => Source::Position,
                "gl_Color" => Source::Color,
                "gl_SecondaryColor" => Source::Secondary,
                "gl_Normal" => Source::Normal,
                "gl_FogCoord" => Source::Fog,
                n if n.starts_with("gl_MultiTexCoord") => {
                    let u = n["gl_MultiTexCoord".len()..].parse::<usize>();
                    Source::Tex(
                        u.ok()
                            .filter(|&u| u < MAX_TEXTURE_UNITS)
                            .ok_or("texcoord")?,
                    )
                }
                n if n.starts_with("gl_") => return Err(format!("input {n} is not fed")),
                n => match location(n) {
                    Some(0) => Source::Position,
                    Some(k @ 1..=15) => Source::Generic(k as usize),
                    _ => return Err(format!("attribute {n} has no location")),
                },
            };
            if s.count > 4 {
                return Err(format!("matrix attribute {}", s.name));
            }
            attributes.push((src, s));
        }
        Ok(Arc::new(VertShader {
            program: compile(&l.ir),
            uniforms: l.uniforms,
            attributes,
            outputs: l.outputs,
        }))
    }

    /// Whether the shader reads attribute `name`.
    pub fn reads(&self, name: &str) -> bool {
        self.attributes.iter().any(|(_, s)| s.name == name)
    }

    /// Whether the shader reads a generic attribute other than 0 (the position).
    pub fn reads_generic(&self) -> bool {
        self.attributes
            .iter()
            .any(|(src, _)| matches!(src, Source::Generic(_)))
    }

    /// Whether the shader writes output `name`.
    pub fn writes(&self, name: &str) -> bool {
        self.outputs.iter().any(|s| s.name == name)
    }
}

/// Where one output component goes in a [`ClipVertex`].
#[derive(Clone, Copy, Debug, PartialEq)]
enum Dest {
    /// The clip position's component.
    Clip(usize),
    /// A varying.
    Vary(usize),
    /// A colour varying, clamped to [0, 1].
    Color(usize),
    /// The point size (`gl_PointSize` under GL_VERTEX_PROGRAM_POINT_SIZE).
    PointSize,
}

/// A draw's run of a vertex shader.
pub struct VertexRun<'a> {
    shader: &'a VertShader,
    uniforms: Vec<f32>,
    /// Each output component's destination (by output index).
    dest: Vec<(u16, Dest)>,
    /// The generic attributes' current values.
    generic: [[f32; 4]; 16],
    viewport: Viewport,
    fma: bool,
    /// Where the back colours go, and whether the shader writes the back primary and
    /// the back secondary colour (one it does not write is a copy of the front one, so
    /// that a back face keeps it, as the draw module's two-sided stage copies only the
    /// colours the shader writes).
    back: Option<(usize, bool, bool)>,
    /// [`OutputUse::clip`], and whether the shader writes `gl_ClipVertex` (else the clip
    /// vertex is the clip position).
    clip: Option<(ClipUse, bool)>,
}

/// What a draw does with a vertex shader's outputs beyond the position and varyings.
#[derive(Clone, Copy, Debug, Default)]
pub struct OutputUse {
    /// GL_VERTEX_PROGRAM_POINT_SIZE: vertices carry `gl_PointSize`.
    pub point_size: bool,
    /// GL_VERTEX_PROGRAM_TWO_SIDE with a shader that writes a back colour: the varying
    /// where the back colours start (the primary, then the secondary at +4).
    pub back: Option<usize>,
    /// Enabled user clip planes: the varying where the clip vertex goes, the eye-space
    /// planes and their enable bits (the vertex's clip mask gets their bits).
    pub clip: Option<ClipUse>,
}

/// [`OutputUse::clip`]: the first of the clip vertex's four varyings, the eye-space
/// planes and their enable bits.
pub type ClipUse = (usize, [[f32; 4]; 8], u8);

impl<'a> VertexRun<'a> {
    /// The run of `shader` with uniform words `user` (in its slot order, the built-in
    /// matrices and state included), the generic attributes' current values, and the
    /// varying layout: `vary_of(name, component)` is the varying a user or texture
    /// output component feeds (`None`: nothing reads it); what else the draw takes
    /// (`uses`: the point size, the back colours); the viewport, and whether it
    /// transforms with fused multiply-adds.
    pub fn new(
        shader: &'a VertShader,
        user: &[u32],
        generic: [[f32; 4]; 16],
        vary_of: impl Fn(&str, usize) -> Option<usize>,
        uses: OutputUse,
        (viewport, fma): (Viewport, bool),
    ) -> Self {
        let uniforms = user.iter().map(|&w| f32::from_bits(w)).collect();
        let mut dest = Vec::new();
        for o in &shader.outputs {
            for c in 0..o.count as usize {
                let d = match o.name.as_str() {
                    "gl_Position" => Some(Dest::Clip(c)),
                    "gl_FrontColor" => Some(Dest::Color(c)),
                    "gl_FrontSecondaryColor" => Some(Dest::Color(VARY_SPEC + c)),
                    "gl_FogFragCoord" => Some(Dest::Vary(VARY_FOG)),
                    "gl_PointSize" if uses.point_size => Some(Dest::PointSize),
                    "gl_BackColor" => uses.back.map(|b| Dest::Color(b + c)),
                    "gl_BackSecondaryColor" => uses.back.map(|b| Dest::Color(b + 4 + c)),
                    "gl_ClipVertex" => uses.clip.map(|(b, ..)| Dest::Vary(b + c)),
                    n if n.starts_with("gl_") && n != "gl_TexCoord" => None,
                    n => vary_of(n, c).map(Dest::Vary),
                };
                if let Some(d) = d {
                    dest.push((o.first + c as u16, d));
                }
            }
        }
        let back = uses.back.map(|b| {
            let (front, spec) = (
                shader.writes("gl_BackColor"),
                shader.writes("gl_BackSecondaryColor"),
            );
            (b, front, spec)
        });
        VertexRun {
            shader,
            uniforms,
            dest,
            generic,
            viewport,
            fma,
            back,
            clip: uses.clip.map(|c| (c, shader.writes("gl_ClipVertex"))),
        }
    }

    /// Whether the vertices carry their point size (the shader writes `gl_PointSize`
    /// and GL_VERTEX_PROGRAM_POINT_SIZE is on).
    pub fn sizes_points(&self) -> bool {
        self.dest.iter().any(|(_, d)| matches!(d, Dest::PointSize))
    }

    /// Runs the shader over every vertex of `verts`.
    pub fn run<S: VertexSource + ?Sized>(&self, verts: &S) -> Vec<ClipVertex> {
        let n = verts.count();
        let mut out = vec![ClipVertex::default(); n];
        let sh = self.shader;
        let streams: usize = sh.attributes.iter().map(|(_, s)| s.count as usize).sum();
        let mut inputs = vec![[[0u32; 8]; MAX_BATCH]; streams];
        let nout = sh.program.outputs();
        let mut outputs = vec![[0u32; 8]; MAX_BATCH * nout];
        let mut scratch = Scratch::default();
        let mut slot = verts.new_slot();
        const BLOCK: usize = 8 * MAX_BATCH;
        for (b, outs) in out.chunks_mut(BLOCK).enumerate() {
            let base = b * BLOCK;
            for (j, _) in outs.iter().enumerate() {
                verts.vertex_into(base + j, &mut slot);
                let v = &slot.v;
                for (src, s) in &sh.attributes {
                    let val: [f32; 4] = match *src {
                        Source::Position => v.pos,
                        Source::Color => v.color,
                        Source::Secondary => v.secondary,
                        Source::Normal => [v.normal[0], v.normal[1], v.normal[2], 0.0],
                        Source::Fog => [v.fog_coord, 0.0, 0.0, 0.0],
                        Source::Tex(u) => v.texcoord[u],
                        Source::Generic(k) => verts.generic(base + j, k).unwrap_or(self.generic[k]),
                    };
                    for c in 0..s.count as usize {
                        inputs[s.first as usize + c][j / 8][j % 8] = val[c].to_bits();
                    }
                }
            }
            let chunks = outs.len().div_ceil(8);
            let ins: Vec<&[[u32; 8]]> = inputs.iter().map(|s| &s[..]).collect();
            sh.program
                .run_streams(&mut scratch, &ins, &self.uniforms, &mut outputs, chunks);
            for (j, cv) in outs.iter_mut().enumerate() {
                let at = |o: u16| f32::from_bits(outputs[(j / 8) * nout + o as usize][j % 8]);
                cv.clip = [0.0, 0.0, 0.0, 0.0];
                for &(o, d) in &self.dest {
                    let x = at(o);
                    match d {
                        Dest::Clip(c) => cv.clip[c] = x,
                        Dest::Vary(i) => cv.vary[i] = x,
                        Dest::Color(i) => cv.vary[i] = clamp_color(x),
                        Dest::PointSize => cv.psize = x,
                    }
                }
                if let Some((b, primary, secondary)) = self.back {
                    if !primary {
                        cv.vary.copy_within(0..4, b);
                    }
                    if !secondary {
                        cv.vary.copy_within(VARY_SPEC..VARY_SPEC + 4, b + 4);
                    }
                }
                cv.win = self.viewport.apply_shader(cv.clip, self.fma);
                cv.mask = clip_mask(cv.clip, self.viewport.halfz);
                if let Some(((b, planes, enabled), written)) = &self.clip {
                    if !written {
                        cv.vary[*b..*b + 4].copy_from_slice(&cv.clip);
                    }
                    let mut c = [0.0; 4];
                    c.copy_from_slice(&cv.vary[*b..*b + 4]);
                    cv.mask |= user_clip_mask(c, planes, *enabled, self.fma);
                }
            }
        }
        out
    }
}

/// The varying of texture output component `c` of `gl_TexCoord` (unit `c / 4`) when the
/// units `units` (in their varying order) are read.
pub fn tex_vary(units: &[usize], c: usize) -> Option<usize> {
    let k = units.iter().position(|&u| u == c / 4)?;
    Some(VARY_TEX + 4 * k + c % 4)
}
