//! Fragment shaders in draws: a linked fragment shader is checked once
//! ([`FragShader::prepare`]) and registered under an id; a draw carries a [`ShaderRef`]
//! (the id, the flip of `gl_FragCoord.y`, the uniform values) in its fragment plan, and
//! each triangle's walk ([`walk`]) takes the variant compiled for the shader and the
//! plan from the engine's per-thread cache, lowering it on a miss.
//!
//! A variant is the lowered shader with its planes renumbered to the triangle's
//! ([`crate::engine::lower::planes_of`]: `gl_Color` is varying 0–3, `gl_TexCoord[n]`
//! varyings `VARY_TEX + 4n…`, which the plan step makes the vertex stage compute), then
//! the fixed per-fragment operations after `gl_FragColor` ([`crate::engine::ff::tail`]:
//! alpha test, depth test, blending, colour mask, store). Uniform values are run inputs,
//! so a glUniform between draws changes no variant.

use crate::engine::cache::{program_of, Key};
use crate::engine::draw::{Walk, MAX_UNIFORMS};
use crate::engine::ir::{Builder, Ir, Op};
use crate::fragment::FragPlan;
use crate::framebuffer::Target;
use crate::geometry::{MAX_VARY, VARY_FOG, VARY_SPEC, VARY_TEX};
use crate::pipe::MAX_TEXTURE_UNITS;
use softgl_glsl::hir;
use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::sync::{Arc, Mutex, Weak};

use super::lower::{lower_fragment_with, Options, Slot, FIRST_VARYING_PLANE, FRONT_FACING};
use super::lower::{PLANE_INV_W, PLANE_Z};

/// A fragment shader a draw can run: registered while it lives.
pub struct FragShader {
    /// Its registration id.
    pub id: u64,
    hir: Arc<hir::Program>,
    /// The uniforms the lowered code reads, in slot order.
    pub uniforms: Vec<Slot>,
    /// Each lowered varying plane's triangle varying (`planes_of` index minus 2).
    vary: Vec<u16>,
    /// The texture coordinate sets the vertex stage must compute (`gl_TexCoord[0..n]`).
    pub tex_coords: usize,
    /// The user varyings read and their first varying (after the texture coordinates).
    pub user: Vec<(String, usize)>,
    /// The varyings a triangle must carry (one past the highest read).
    pub nvary: usize,
    /// The texture lookups the rasterizer samples for the program, in stream order.
    pub textures: Vec<ShaderTexture>,
    /// The uniform word of `gl_FrontFacing`, when the shader reads it.
    facing: Option<u16>,
    /// The triangle varyings the shader reads `flat` (bit v: varying v).
    flat: u64,
    /// The first of the four varyings `gl_PointCoord` occupies (s, t, then the 0 and 1
    /// the point setup writes), when the shader reads it: points replace them
    /// ([`crate::raster::sprite`]), other primitives leave them zero.
    pub point_coord: Option<usize>,
}

/// A texture lookup of a [`FragShader`] in the triangle's terms.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ShaderTexture {
    /// The uniform word holding the sampler's unit.
    pub unit_word: usize,
    /// The target sampled.
    pub target: crate::texture::Target,
    /// The triangle varyings of s, t, r (or the depth reference) and q, each with
    /// whether it is read without the perspective divide.
    pub coords: [Option<(u16, bool)>; 4],
    /// s, t and r are multiplied by `1 / q`.
    pub proj: bool,
    /// The program computes the coordinates and samples them itself (through the walk's
    /// [`crate::engine::exec::TexSampler`]); `coords` is empty.
    pub computed: bool,
    /// The lookup's level-of-detail argument, or the non-sampling lookup it is (only
    /// computed lookups have one).
    pub kind: crate::texture::lookup::LookupKind,
}

impl std::fmt::Debug for FragShader {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "FragShader({})", self.id)
    }
}

/// The ids handed out.
static NEXT_ID: AtomicU64 = AtomicU64::new(1);

/// The live shaders by id (entries of dropped shaders are pruned on registration).
static REGISTRY: Mutex<Option<HashMap<u64, Weak<FragShader>>>> = Mutex::new(None);

impl FragShader {
    /// Checks that `hir` lowers and that the vertex stage feeds every input it reads (the
    /// fixed-function stage, or with `vertex` the program's vertex shader), and registers
    /// it; `Err` says why a draw cannot run it.
    pub fn prepare(hir: Arc<hir::Program>, vertex: bool) -> Result<Arc<FragShader>, String> {
        let l = lower_fragment_with(&hir, Options::default()).map_err(|e| e.0)?;
        let tex_coords = l
            .varyings
            .iter()
            .find(|s| s.name == "gl_TexCoord")
            .map_or(0, |s| s.count as usize / 4);
        let mut vary = Vec::new();
        let mut user = Vec::new();
        let mut flat = 0u64;
        let mut point_coord = None;
        let mut next = VARY_TEX + 4 * tex_coords;
        for s in &l.varyings {
            let base = match s.name.as_str() {
                "gl_Color" => 0,
                "gl_TexCoord" => VARY_TEX,
                "gl_SecondaryColor" if vertex => VARY_SPEC,
                "gl_FogFragCoord" if vertex => VARY_FOG,
                "gl_PointCoord" => {
                    point_coord = Some(next);
                    next += 4;
                    next - 4
                }
                n if vertex && !n.starts_with("gl_") => {
                    user.push((n.to_string(), next));
                    next += s.count as usize;
                    next - s.count as usize
                }
                n => return Err(format!("input {n} is not fed by the fixed-function stage")),
            };
            vary.extend((0..s.count).map(|k| (base + k as usize) as u16));
            if s.linear {
                // `flat` inputs are the provoking vertex's values (constant planes,
                // `raster::prims::flat_varyings`); `noperspective` would need
                // screen-linear planes.
                let interp = hir
                    .vars
                    .iter()
                    .find(|v| v.name == s.name)
                    .and_then(|v| v.interp);
                if interp != Some(softgl_glsl::ast::Interp::Flat) {
                    return Err(format!("noperspective input {}", s.name));
                }
                for k in 0..usize::from(s.count) {
                    flat |= 1u64.checked_shl((base + k) as u32).unwrap_or(0);
                }
            }
        }
        if vary.iter().any(|&v| v as usize >= MAX_VARY) {
            return Err("too many varyings".into());
        }
        let words: usize = l.uniforms.iter().map(|s| s.count as usize).sum();
        if words > MAX_UNIFORMS {
            return Err(format!(
                "{words} uniform components (at most {MAX_UNIFORMS})"
            ));
        }
        let facing = l
            .uniforms
            .iter()
            .find(|s| s.name == FRONT_FACING)
            .map(|s| s.first);
        if let Some(s) = l.uniforms.iter().find(|s| {
            let n = s.name.as_str();
            n.starts_with("gl_") && n != FRONT_FACING && !super::vertex_draw::is_state_uniform(n)
        }) {
            return Err(format!("built-in uniform {} is not supplied", s.name));
        }
        let mut textures = Vec::new();
        for t in &l.textures {
            let unit_word = l
                .uniforms
                .iter()
                .find(|s| s.name == t.sampler)
                .map(|s| s.first as usize + usize::from(t.element))
                .ok_or("a sampler without its uniform")?;
            let mut coords = [None; 4];
            for (d, c) in coords.iter_mut().zip(t.coords) {
                if let Some((plane, linear)) = c {
                    let v = vary.get(usize::from(plane - FIRST_VARYING_PLANE));
                    *d = Some((
                        *v.ok_or("a texture coordinate without its varying")?,
                        linear,
                    ));
                }
            }
            textures.push(ShaderTexture {
                unit_word,
                target: t.target,
                coords,
                proj: t.proj,
                computed: t.computed,
                kind: t.kind,
            });
        }
        let fs = Arc::new(FragShader {
            id: NEXT_ID.fetch_add(1, Relaxed),
            hir,
            uniforms: l.uniforms,
            nvary: vary.iter().map(|&v| v as usize + 1).max().unwrap_or(0),
            vary,
            tex_coords,
            user,
            textures,
            facing,
            flat,
            point_coord,
        });
        let mut r = REGISTRY.lock().unwrap_or_else(|e| e.into_inner());
        let map = r.get_or_insert_with(HashMap::new);
        map.retain(|_, w| w.strong_count() > 0);
        map.insert(fs.id, Arc::downgrade(&fs));
        Ok(fs)
    }

    /// The draw-time reference of this shader with uniform words `uniforms` (in slot
    /// order) into a target of `height` rows (`y_flip`: stored top-down).
    pub fn reference(&self, uniforms: &[u32], height: usize, y_flip: bool) -> ShaderRef {
        let mut u = [0; MAX_UNIFORMS];
        for (d, &s) in u.iter_mut().zip(uniforms) {
            *d = s;
        }
        ShaderRef {
            id: self.id,
            flip: y_flip.then_some(height as u32),
            uniforms: u,
            tex_units: [NO_UNIT; MAX_TEXTURE_UNITS],
            ntex: self.textures.len() as u8,
            facing: self.facing,
            flat: self.flat,
        }
    }

    /// The variant of this shader under `plan` (see the module doc); with `host` the walk
    /// stores its colours ([`crate::engine::draw::host_store`]).
    fn variant(&self, flip: Option<u32>, plan: &FragPlan, host: bool) -> Option<Ir> {
        let opts = Options {
            flip_height: flip.map(|h| h as f32),
            flat_colors: plan.flat,
            centred: plan.ms.is_some(),
        };
        // A lookup sampled before the program runs divides its coordinates by w: not
        // one at a flat colour.
        let colors =
            |v: u16| usize::from(v) < 4 || (VARY_SPEC..VARY_SPEC + 4).contains(&usize::from(v));
        let mut coords = self.textures.iter().flat_map(|t| t.coords.iter().flatten());
        if plan.flat && coords.any(|&(v, _)| colors(v)) {
            return None;
        }
        let l = lower_fragment_with(&self.hir, opts).ok()?;
        let mut ir = l.ir;
        for op in &mut ir.ops {
            if let Op::Interp(n) = op {
                *n = match *n {
                    PLANE_INV_W => crate::engine::lower::PLANE_W,
                    PLANE_Z => crate::engine::lower::PLANE_Z,
                    k => {
                        let v = *self.vary.get((k - FIRST_VARYING_PLANE) as usize)?;
                        crate::engine::lower::PLANE_VARY + v
                    }
                };
            }
        }
        let mut b = Builder::from_ir(ir);
        let colors = match plan.smooth {
            Some(s) => crate::engine::ff::smooth_colors(&mut b, s, &l.colors),
            None => l.colors,
        };
        crate::engine::ff::tail_buffers(&mut b, plan, &colors, l.depth, host)?;
        b.finish().ok()
    }
}

/// A draw's fragment shader: its id, the target height when rows are flipped, the
/// uniform values (words in slot order) and where each texture lookup's unit plan is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShaderRef {
    /// The registration id of the [`FragShader`].
    pub id: u64,
    /// The target's height when its rows are stored top-down.
    pub flip: Option<u32>,
    /// The uniform words.
    pub uniforms: [u32; MAX_UNIFORMS],
    /// Texture lookup `k`'s plan in the draw's units, or [`NO_UNIT`] (an incomplete
    /// texture: the lookup gives (0, 0, 0, 1)); the lookups themselves are the
    /// registered shader's [`FragShader::textures`].
    pub tex_units: [u8; MAX_TEXTURE_UNITS],
    /// The number of texture lookups.
    pub ntex: u8,
    /// The uniform word of `gl_FrontFacing`, set per triangle.
    pub facing: Option<u16>,
    /// The triangle varyings the shader reads `flat` (bit v: varying v).
    pub flat: u64,
}

/// [`ShaderRef::tex_units`] of a lookup whose texture is incomplete.
pub const NO_UNIT: u8 = u8::MAX;

/// The registered shader of `id`, if it still lives.
fn lookup(id: u64) -> Option<Arc<FragShader>> {
    let r = REGISTRY.lock().unwrap_or_else(|e| e.into_inner());
    r.as_ref()?.get(&id)?.upgrade()
}

/// The walk of a triangle (`front`: it faces front) drawn with `sh` under `plan` into
/// `fb`, or `None` when the engine does not draw this plan or target (the caller draws
/// nothing and counts it).
pub fn walk(sh: &ShaderRef, plan: &FragPlan, fb: &Target<'_>, front: bool) -> Option<Walk> {
    let host = crate::engine::draw::host_store(plan, fb);
    let key = Key::Shader {
        id: sh.id,
        flip: sh.flip,
        plan: FragPlan {
            shader: None,
            ..*plan
        },
        host,
    };
    let prog = program_of(&key, || lookup(sh.id)?.variant(sh.flip, plan, host))?;
    let mut uniforms = sh.uniforms;
    if let Some(k) = sh.facing {
        uniforms[usize::from(k)] = u32::from(front);
    }
    Walk::with_program(prog, plan, &uniforms, usize::from(sh.ntex), fb, front)
}

/// The registered shader of a draw's [`ShaderRef`] (for its texture lookups), if it
/// still lives.
pub fn shader_of(sh: &ShaderRef) -> Option<Arc<FragShader>> {
    lookup(sh.id)
}
