//! The one translation from GL state to pipeline values, done once per draw (the role
//! Mesa's state tracker plays).
//!
//! The state gathers references to its parameter blocks into a [`DrawState`] and calls
//! [`build`], which returns one [`DrawPlan`]: the vertex stage (transforms, user clip
//! planes, lighting, fog, texgen, point attenuation), the texture units, the primitive
//! stages (culling, polygon offset, the polygon pipeline), lines, points and the
//! fragment operations. The pipeline then runs that plan without looking at the state
//! again. This module imports only the pipeline and `pipe/`; the state calls it.

mod fragment;

pub use fragment::{fragment, srgb_store, FragState};

use crate::fixed_function::fog::FogPlan;
use crate::fixed_function::lighting::{LightEnables, LightPlan};
use crate::fixed_function::matrix::{MatrixStack, IDENTITY};
use crate::fixed_function::point_size::PointAtten;
use crate::fixed_function::transform::VertexStage;
use crate::fragment::MsPass;
use crate::framebuffer::DepthFormat;
use crate::geometry::setup::CullMode;
use crate::geometry::{cpu_has_fma, ClipConvention, Viewport, MAX_VARY};
use crate::pipe::{Cap, Caps, ClipPlanes, Face, FillMode, LightingState, RasterState, TexGenState};
use crate::pipe::{MAX_LIGHTS, MAX_TEXTURE_UNITS};
use crate::raster::prims::{point_size, LinePlan, PolyPipeline, PrimEnables};
use crate::raster::sprite::Sprite;
use crate::render::DrawPlan;
use crate::shader::draw::FragShader;
use crate::shader::vertex_draw::{tex_vary, OutputUse, VertShader, VertexRun};
use crate::texture::{TextureState, UnitPlan};

/// The buffers a draw goes into, as far as the plan depends on them.
#[derive(Clone, Copy, Debug)]
pub struct Target {
    /// Rows (window y is flipped with it).
    pub height: usize,
    /// Whether rows are stored top-down (the OSMesa default).
    pub y_flip: bool,
    /// The depth buffer's format.
    pub depth_format: DepthFormat,
    /// Whether a stencil buffer exists.
    pub has_stencil: bool,
    /// Whether the colour buffer is sRGB-encoded ([`crate::framebuffer::Framebuffer::srgb`]).
    pub srgb: bool,
    /// The draw buffers after the first that have a colour buffer
    /// ([`crate::framebuffer::Framebuffer::more_color_mask`]).
    pub more_buffers: u8,
}

/// What a draw is planned from: the state's parameter blocks, borrowed for the draw.
pub struct DrawState<'a> {
    /// glEnable bits.
    pub caps: &'a Caps,
    /// glViewport.
    pub viewport: [i32; 4],
    /// glDepthRange.
    pub depth_range: [f64; 2],
    /// glClipControl.
    pub clip_control: ClipConvention,
    /// The fragment operations' state.
    pub frag: FragState<'a>,
    /// glCullFace.
    pub cull_face: Face,
    /// glFrontFace: true for GL_CCW.
    pub front_ccw: bool,
    /// The current colour (lit through colour material).
    pub current_color: [f32; 4],
    /// The modelview stack.
    pub modelview: &'a MatrixStack,
    /// The projection stack.
    pub projection: &'a MatrixStack,
    /// The texture matrix stack of each unit.
    pub texture: &'a [MatrixStack],
    /// User clip planes (eye space) and their enable bits.
    pub clip_planes: &'a ClipPlanes,
    /// Lights, materials and fog.
    pub light: &'a LightingState,
    /// Texture coordinate generation.
    pub texgen: &'a TexGenState,
    /// Lines, points and polygons.
    pub raster: &'a RasterState,
    /// Texture units and their objects.
    pub textures: &'a TextureState,
    /// The buffers drawn into.
    pub target: Target,
    /// Feedback or selection mode: the vertex and primitive stages only.
    pub feedback: bool,
    /// An occlusion query is counting samples.
    pub count_samples: bool,
    /// A one-pass multisample draw (all four sample planes at once).
    pub ms: Option<MsPass>,
    /// The draw's primitives are points or lines (the polygon pipeline plays no part).
    pub points_lines: bool,
    /// The current program's fragment shader, when it has one a draw can run.
    pub shader: Option<ShaderInput<'a>>,
}

/// A program's shaders for a draw: the fragment shader and its uniform words in slot
/// order, the vertex shader (each `None` when the stage is fixed function).
#[derive(Clone, Copy, Debug)]
pub struct ShaderInput<'a> {
    /// The fragment shader and its uniform values, [`FragShader::uniforms`]' components
    /// in order.
    pub frag: Option<(&'a FragShader, &'a [u32])>,
    /// The vertex shader.
    pub vert: Option<VertInput<'a>>,
}

/// A vertex shader for a draw.
#[derive(Clone, Copy, Debug)]
pub struct VertInput<'a> {
    /// The shader.
    pub shader: &'a VertShader,
    /// Its user uniforms' words in slot order.
    pub uniforms: &'a [u32],
    /// The generic attributes' current values.
    pub generic: [[f32; 4]; 16],
}

/// Plans a draw of `s`.
pub fn build<'a>(s: &DrawState<'a>) -> DrawPlan<'a> {
    let fma = cpu_has_fma();
    let caps = s.caps;
    let t = s.target;
    let cc = s.clip_control;
    let viewport = Viewport::with_convention(s.viewport, s.depth_range, t.height, t.y_flip, cc);
    let modelview = *s.modelview.top();
    let mvp = s.projection.top().mul(&modelview);
    let mut stage = VertexStage::new(mvp, modelview, viewport, fma);
    let ucp = s.clip_planes;
    stage.set_user_planes(&ucp.eye, ucp.enabled, s.projection);
    stage.fog = caps.get(Cap::Fog).then_some(s.light.fog);
    // Mesa's feedback vertex program always writes unit 0's texture coordinates; the
    // texture matrix and texgen apply only when the unit has a complete enabled texture.
    let feedback = s.feedback;
    let feedback_tex0 = feedback && s.textures.unit_plan(0).is_some();
    if feedback_tex0 {
        stage.add_texture_unit(0, s.texture[0].top());
    }
    // A fragment shader replaces texturing: the vertex stage computes the coordinate
    // sets it reads instead (with each unit's matrix and texgen, as Mesa's fixed-function
    // vertex program does for the inputs a fragment program reads).
    let shader = s.shader.and_then(|sh| sh.frag).filter(|_| !feedback);
    let vert = s.shader.and_then(|sh| sh.vert);
    if let Some((fs, _)) = &shader {
        for u in 0..fs.tex_coords.min(MAX_TEXTURE_UNITS) {
            stage.add_texture_unit(u, s.texture[u].top());
        }
        stage.min_vary = fs.nvary;
    }
    let mut tex: Vec<UnitPlan<'a>> = (0..MAX_TEXTURE_UNITS)
        .filter(|_| !feedback && shader.is_none())
        .filter_map(|u| {
            let p = s.textures.unit_plan(u)?;
            stage.add_texture_unit(u, s.texture[u].top());
            Some(p)
        })
        .collect();
    // A fragment shader's texture lookups: the texture bound to the target of the
    // sampler's type on the unit its uniform names, whatever the unit's enables; a unit
    // out of range or an incomplete texture gives the lookup (0, 0, 0, 1).
    let mut tex_units = [crate::shader::draw::NO_UNIT; MAX_TEXTURE_UNITS];
    if let Some((fs, u)) = &shader {
        for (d, lk) in tex_units.iter_mut().zip(&fs.textures) {
            let unit = u.get(lk.unit_word).map_or(-1, |&w| w as i32);
            let plan = usize::try_from(unit)
                .ok()
                .filter(|&n| n < MAX_TEXTURE_UNITS)
                .and_then(|n| s.textures.unit_plan_target(n, lk.target));
            if let Some(p) = plan {
                *d = tex.len() as u8;
                tex.push(p);
            }
        }
    }
    // the offset's view of the depth buffer: its bits, or the float tag
    let depth_bits = t.depth_format.texel_bits() as i32;
    let mv_flags = s.modelview.top_flags();
    let (normalize, rescale) = (caps.get(Cap::Normalize), caps.get(Cap::RescaleNormal));
    let texgen_eye = stage.add_texgen(s.texgen, mv_flags, normalize, rescale);
    if feedback && !feedback_tex0 {
        stage.add_texture_unit(0, &IDENTITY);
    }
    stage.point_atten = PointAtten::new(&s.raster.point);
    stage.light = LightPlan::new(
        s.light,
        &light_enables(caps),
        s.current_color,
        &modelview,
        Some(mv_flags),
        texgen_eye || stage.point_atten.is_some(),
        fma,
    );
    // The vertex shader replaces lighting and point attenuation (GL 2.0 §2.15). Mesa
    // still adds the secondary colour under lighting with GL_SEPARATE_SPECULAR_COLOR or
    // when the shader reads gl_SecondaryColor (`_mesa_need_secondary_color`).
    let vs_sum = vert.map(|v| {
        let lit = stage.light.as_ref().is_some_and(|l| l.separate_specular());
        lit || v.shader.reads("gl_SecondaryColor")
    });
    if vs_sum.is_some() {
        stage.light = None;
        stage.point_atten = None;
    }
    let mut frag = fragment(&s.frag, t.depth_format, t.has_stencil, fma);
    frag.ms = s.ms;
    frag.srgb = fragment::srgb_store(caps, t.srgb);
    frag.more_buffers = t.more_buffers;
    stage.color_sum = (stage.light.is_none() && caps.get(Cap::ColorSum)) || vs_sum == Some(true);
    frag.separate_specular =
        stage.color_sum || stage.light.as_ref().is_some_and(|l| l.separate_specular());
    frag.fog = stage.fog.map(|f| FogPlan::new(&f, fma));
    frag.count_samples = s.count_samples;
    if let Some((fs, u)) = &shader {
        // The shader replaces the colour sum and fog.
        frag.separate_specular = false;
        frag.fog = None;
        let mut r = fs.reference(u, t.height, t.y_flip);
        r.tex_units = tex_units;
        frag.shader = Some(r);
    }
    // GL_VERTEX_PROGRAM_TWO_SIDE: back faces take the colours the shader writes for
    // them (Mesa's `_TwoSideEnabled` with a vertex program), after every other varying.
    let back = |v: &VertInput<'_>| {
        v.shader.writes("gl_BackColor") || v.shader.writes("gl_BackSecondaryColor")
    };
    // Varyings that do not fit leave the draw unfit: nothing is drawn.
    let mut unfit = false;
    if caps.get(Cap::VertexProgramTwoSide) && vert.as_ref().is_some_and(back) {
        let b = stage.nvary();
        unfit |= b + 8 > MAX_VARY;
        stage.vs_back = (b + 8 <= MAX_VARY).then_some(b);
    }
    // A vertex shader's user clip planes: Mesa passes the eye-space planes
    // (`st_update_clip`), and the draw module measures each vertex's clip vertex with
    // them (`getclipdist`), kept in four varyings after the others.
    if vert.is_some() && ucp.enabled != 0 {
        let b = stage.nvary();
        unfit |= b + 4 > MAX_VARY;
        if b + 4 <= MAX_VARY {
            stage.ucp.planes = ucp.eye;
            stage.ucp.clip_vertex = Some(b);
            stage.min_vary = b + 4;
        }
    }
    let vertex = vert.map(|v| vertex_run(v, s, &stage, shader.map(|(f, _)| f)));
    // Filled triangles that take the polygon pipeline (stippled, offset with two-sided
    // lighting …) are drawn with the single-sample rules in every plane.
    let mut prims = prim_enables(caps);
    prims.coords = point_coords(
        &s.raster.point,
        prims.sprite,
        &stage,
        shader.and_then(|(f, _)| f.point_coord),
        t.y_flip,
    );
    if frag.ms.is_some() {
        // Multisampling turns point and line smoothing off (st_atom_rasterizer.c).
        prims.point_smooth = false;
        prims.line_smooth = false;
    }
    let poly = PolyPipeline::needed(s.raster, &prims, stage.two_side());
    // Polygons drawn as lines or points (both faces) become multisample lines and points.
    let polygon = &s.raster.polygon;
    let unfilled = polygon.mode_front != FillMode::Fill && polygon.mode_back != FillMode::Fill;
    if poly && !s.points_lines && !unfilled {
        frag.ms = None;
    }
    let cull_on = caps.get(Cap::CullFace);
    let cull = CullMode {
        front: cull_on && matches!(s.cull_face, Face::Front | Face::FrontAndBack),
        back: cull_on && matches!(s.cull_face, Face::Back | Face::FrontAndBack),
        // Unflipped (object) rows turn the winding over, and so does GL_UPPER_LEFT; each
        // also toggles llvmpipe's `bottom_edge_rule` (st_atom_rasterizer.c).
        front_ccw: (s.front_ccw == t.y_flip) != cc.upper_left,
        top_left: t.y_flip == cc.upper_left,
    };
    // llvmpipe's own polygon offset (filled triangles outside the draw pipeline).
    let lp_offset = (caps.get(Cap::PolygonOffsetFill)
        && (polygon.offset_factor != 0.0 || polygon.offset_units != 0.0))
        .then(|| {
            let units = crate::geometry::unfilled::scaled_units(
                polygon.offset_units,
                depth_bits.max(0) as u32,
            );
            let float = depth_bits == crate::texture::shadow::FLOAT_BITS as i32;
            (polygon.offset_factor, (units, float))
        });
    // llvmpipe takes a vertex's size unclamped (`point_size_per_vertex`).
    let per_vertex =
        stage.point_atten.is_some() || vertex.as_ref().is_some_and(|v| v.sizes_points());
    let point_size = (!per_vertex).then(|| point_size(s.raster));
    let nvary = stage.nvary();
    let mut lines = LinePlan {
        ucp: stage.ucp,
        top_left: cull.top_left,
        ..LinePlan::new(s.raster, &prims, nvary)
    };
    if frag.ms.is_some() {
        // Multisampled lines are rectangles (`line_rectangular`): the stipple stage
        // measures them by their Euclidean length, and GL_LINE_SMOOTH is ignored.
        lines.smooth = false;
        if let Some(st) = lines.stipple.as_mut() {
            st.rectangular = true;
        }
    }
    DrawPlan {
        stage,
        frag,
        tex,
        viewport,
        cull,
        poly,
        lp_offset,
        lines,
        point_size,
        unfit,
        depth_bits: depth_bits.max(0) as u32,
        raster: s.raster,
        prims,
        feedback,
        vertex,
    }
}

/// The run of vertex shader `v` in a draw of `s` whose fixed-function stage is `stage`
/// (its viewport, its texture units in varying order) and fragment shader `fs`.
fn vertex_run<'a>(
    v: VertInput<'a>,
    s: &DrawState<'_>,
    stage: &VertexStage,
    fs: Option<&FragShader>,
) -> VertexRun<'a> {
    let units: Vec<usize> = stage.tex_units[..stage.n_tex].iter().map(|t| t.0).collect();
    let vary_of = |name: &str, c: usize| match (name, fs) {
        ("gl_TexCoord", Some(f)) => (c < 4 * f.tex_coords).then_some(crate::geometry::VARY_TEX + c),
        ("gl_TexCoord", None) => tex_vary(&units, c),
        (n, Some(f)) => f.user.iter().find(|u| u.0 == n).map(|u| u.1 + c),
        _ => None,
    };
    VertexRun::new(
        v.shader,
        v.uniforms,
        v.generic,
        vary_of,
        OutputUse {
            point_size: s.caps.get(Cap::VertexProgramPointSize),
            back: stage.vs_back,
            clip: stage
                .ucp
                .clip_vertex
                .map(|b| (b, stage.ucp.planes, stage.ucp_enabled)),
        },
        (stage.viewport, stage.fma),
    )
}

/// The enables lighting reads.
pub fn light_enables(caps: &Caps) -> LightEnables {
    const LIGHTS: [Cap; MAX_LIGHTS] = [
        Cap::Light0,
        Cap::Light1,
        Cap::Light2,
        Cap::Light3,
        Cap::Light4,
        Cap::Light5,
        Cap::Light6,
        Cap::Light7,
    ];
    LightEnables {
        lighting: caps.get(Cap::Lighting),
        lights: LIGHTS.map(|c| caps.get(c)),
        normalize: caps.get(Cap::Normalize),
        rescale_normal: caps.get(Cap::RescaleNormal),
        color_material: caps.get(Cap::ColorMaterial),
    }
}

/// The enables the primitive stages read.
fn prim_enables(caps: &Caps) -> PrimEnables {
    PrimEnables {
        // Sprites are never smoothed (st_atom_rasterizer.c).
        point_smooth: caps.get(Cap::PointSmooth) && !caps.get(Cap::PointSprite),
        line_smooth: caps.get(Cap::LineSmooth),
        line_stipple: caps.get(Cap::LineStipple),
        polygon_stipple: caps.get(Cap::PolygonStipple),
        offset: [
            caps.get(Cap::PolygonOffsetFill),
            caps.get(Cap::PolygonOffsetLine),
            caps.get(Cap::PolygonOffsetPoint),
        ],
        sprite: caps.get(Cap::PointSprite),
        coords: Sprite::default(),
    }
}

/// The coordinates points replace (st_atom_rasterizer.c and llvmpipe's point setup).
/// Under GL_POINT_SPRITE, Mesa's `sprite_coord_mode` is upper-left when the origin is
/// GL_UPPER_LEFT on flipped (window) rows or GL_LOWER_LEFT on unflipped (object) rows,
/// and each unit with GL_COORD_REPLACE replaces the varyings its coordinates occupy
/// (fixed-function units compacted in the stage's order). Without sprites the mode stays
/// zero (upper-left). A shader's `gl_PointCoord` (varying `point_coord`) is replaced on
/// every point, sprite or not.
fn point_coords(
    point: &crate::pipe::PointState,
    sprite: bool,
    stage: &VertexStage,
    point_coord: Option<usize>,
    y_flip: bool,
) -> Sprite {
    let mut replace = 0u64;
    if sprite {
        for (k, &(unit, _)) in stage.tex_units[..stage.n_tex].iter().enumerate() {
            if point.coord_replace >> unit & 1 == 1 {
                replace |= 1 << (crate::geometry::VARY_TEX + 4 * k);
            }
        }
    }
    if let Some(v) = point_coord {
        replace |= 1u64.checked_shl(v as u32).unwrap_or(0);
    }
    Sprite {
        lower_left: sprite && point.sprite_upper_left != y_flip,
        replace,
    }
}
