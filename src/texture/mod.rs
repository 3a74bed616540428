//! Texturing: texture objects and units, image upload, mipmap generation, sampling with
//! llvmpipe's arithmetic, and the fixed-function texture environment.
//!
//! # Shape
//! GL values are converted into Rust enums at the C boundary (`ffi/textures.rs`); this module
//! holds plain data. [`TextureState`] owns every texture object and the eight texture units.
//! Texels are stored as RGBA8 *after* the base-format swizzle Mesa's sampler view applies
//! (L→(L,L,L,1), A→(0,0,0,A), I→(I,I,I,I), LA→(L,L,L,A), RGB→(R,G,B,1)), so sampling never
//! looks at the format; the base format is kept for the texture environment. Two kinds of
//! image are told apart by their internal format instead: sRGB images (decoded when
//! sampled, see [`srgb`]) and packed depth-stencil ones (depth texels, stencil in
//! [`TextureObject::stencil`], see `context/texture_ds.rs`).
//!
//! # Interface for the rasterizer
//! - [`TextureState::unit_plan`]`(unit) -> Option<UnitPlan>`: `None` when the unit is
//!   disabled or its texture incomplete (Mesa disables such a unit, docs/llvmpipe-rules.md §9.2).
//!   Build it once per draw; it borrows the levels and holds the sampler state as enums,
//!   the precomputed LOD parameters, whether the LOD is needed at all
//!   ([`UnitPlan::needs_lod`]) and the texture environment in combiner form.
//! - [`UnitPlan::sample_quad`]`(s, t)` samples a 2x2 quad (TL, TR, BL, BR, y-down) with one
//!   LOD from TL/TR/BL, as llvmpipe does; [`UnitPlan::sample_one`] samples with a given
//!   [`Lod`].
//! - `UnitPlan::env.apply(frag, tex, prev, textures)` ([`env::Combine::apply`]) applies the
//!   unit's environment (f32, Mesa's order).
//!
//! Coordinates are already divided by q (`s * (1/q)`). Returned colours are what the
//! fragment shader sees: `u8 as f32 * (1/255)` on the 8-bit (AoS) path.

/// `[e(0), e(1), e(2), e(3)]` for `each4!(|i| e)`, written out: the four pixels of a quad
/// without a closure. `std::array::from_fn` calls its closure, and a closure the compiler
/// leaves out of line loses the caller's target features (its floors and fused lerps become
/// library calls) and costs a call per pixel; expanded here, the body is inlined by
/// construction. The values are the same either way.
macro_rules! each4 {
    (|$i:ident| $body:expr) => {
        [
            {
                let $i = 0usize;
                $body
            },
            {
                let $i = 1usize;
                $body
            },
            {
                let $i = 2usize;
                $body
            },
            {
                let $i = 3usize;
                $body
            },
        ]
    };
}

pub mod compressed;
pub mod cube;
#[cfg(target_arch = "x86_64")]
pub mod cube_aos8;
#[cfg(target_arch = "x86_64")]
pub mod cube_avx2;
pub mod cube_seamless;
pub mod env;
pub mod fast;
pub mod fast_avx2;
pub mod float;
pub mod lod;
pub mod lookup;
pub mod mipmap;
pub mod sample;
pub mod shadow;
#[cfg(target_arch = "x86_64")]
pub mod shadow_avx2;
#[cfg(target_arch = "x86_64")]
pub mod soa_avx2;
pub mod srgb;
pub mod unit;
pub mod upload;
pub mod volume;
#[cfg(target_arch = "x86_64")]
pub mod volume8;
pub mod wrap;

use crate::pipe::MAX_TEXTURE_UNITS;
use env::{Combine, TexEnv};
use lod::LodParams;
use std::collections::HashMap;

/// GL_MAX_3D_TEXTURE_SIZE (llvmpipe's value).
pub const MAX_3D_TEXTURE_SIZE: usize = 2048;
/// Number of mipmap levels of the largest 3D texture (log2(2048) + 1).
pub const MAX_3D_LEVELS: usize = 12;
/// GL_MAX_CUBE_MAP_TEXTURE_SIZE (llvmpipe's value).
pub const MAX_CUBE_MAP_TEXTURE_SIZE: usize = 16384;
/// GL_MAX_TEXTURE_SIZE (llvmpipe's 2D limit).
pub const MAX_TEXTURE_SIZE: usize = 16384;
/// Number of mipmap levels of the largest texture (log2(16384) + 1).
pub const MAX_LEVELS: usize = 15;
/// GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT (llvmpipe's value).
pub const MAX_ANISOTROPY: f32 = 16.0;
/// GL_MAX_TEXTURE_LOD_BIAS (llvmpipe's value).
pub const MAX_LOD_BIAS: f32 = 16.0;

/// A texture target this implementation supports.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Target {
    /// GL_TEXTURE_1D.
    Tex1D,
    /// GL_TEXTURE_2D.
    Tex2D,
    /// GL_TEXTURE_3D.
    Tex3D,
    /// GL_TEXTURE_CUBE_MAP.
    Cube,
}

/// Number of [`Target`]s (per-target arrays).
pub const NUM_TARGETS: usize = 4;

/// Every target, in index order.
pub const ALL_TARGETS: [Target; NUM_TARGETS] =
    [Target::Tex1D, Target::Tex2D, Target::Tex3D, Target::Cube];

impl Target {
    /// Index into per-target arrays.
    pub fn index(self) -> usize {
        self as usize
    }
}

/// The base internal format of a texture image.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BaseFormat {
    /// GL_ALPHA.
    Alpha,
    /// GL_LUMINANCE.
    Luminance,
    /// GL_LUMINANCE_ALPHA.
    LuminanceAlpha,
    /// GL_INTENSITY.
    Intensity,
    /// GL_RGB.
    Rgb,
    /// GL_RGBA.
    Rgba,
    /// GL_DEPTH_COMPONENT: texels hold the depth value as a little-endian u32 of
    /// [`Storage::depth_bits`] bits (see [`shadow`]).
    Depth,
    /// GL_RED (GL_ARB_texture_rg): sampled as (R, 0, 0, 1).
    Red,
    /// GL_RG (GL_ARB_texture_rg): sampled as (R, G, 0, 1).
    Rg,
}

impl BaseFormat {
    /// Applies the sampler-view swizzle of this base format to an RGBA value (also used for
    /// the border colour, as Mesa's `st_translate_color` does).
    pub fn swizzle<T: Copy>(self, v: [T; 4], zero: T, one: T) -> [T; 4] {
        match self {
            BaseFormat::Alpha => [zero, zero, zero, v[3]],
            BaseFormat::Luminance => [v[0], v[0], v[0], one],
            BaseFormat::LuminanceAlpha => [v[0], v[0], v[0], v[3]],
            BaseFormat::Intensity => [v[0], v[0], v[0], v[0]],
            BaseFormat::Rgb => [v[0], v[1], v[2], one],
            BaseFormat::Rgba | BaseFormat::Depth => v,
            BaseFormat::Red => [v[0], zero, zero, one],
            BaseFormat::Rg => [v[0], v[1], zero, one],
        }
    }

    /// The base format the texture environment sees: Mesa's `calculate_derived_texenv`
    /// treats GL_RED and GL_RG images as GL_RGB ones.
    pub fn env_base(self) -> BaseFormat {
        match self {
            BaseFormat::Red | BaseFormat::Rg => BaseFormat::Rgb,
            b => b,
        }
    }
}

impl BaseFormat {
    /// What glReadPixels takes from a colour image of this base format whose working
    /// RGBA8 value is `v`: Mesa's `_mesa_readpixels` rebases luminance and intensity
    /// images to (L, 0, 0, 1) and luminance-alpha to (L, 0, 0, A), not (L, L, L, …);
    /// alpha images read as (0, 0, 0, A) and RGB ones with alpha 1.
    pub fn read_rebase(self, v: [u8; 4]) -> [u8; 4] {
        match self {
            BaseFormat::Luminance | BaseFormat::Intensity => [v[0], 0, 0, 255],
            BaseFormat::LuminanceAlpha => [v[0], 0, 0, v[3]],
            BaseFormat::Alpha => [0, 0, 0, v[3]],
            BaseFormat::Rgb => [v[0], v[1], v[2], 255],
            BaseFormat::Rgba | BaseFormat::Depth => v,
            BaseFormat::Red => [v[0], 0, 0, 255],
            BaseFormat::Rg => [v[0], v[1], 0, 255],
        }
    }
}

/// The storage format Mesa chose for an image (by `context::pack::tex_format`), as the
/// component sizes glGetTexLevelParameter reports and the encoding. Texels are still kept
/// as RGBA8; components of fewer than 8 bits are quantised on upload and expanded back by
/// bit replication, which is what llvmpipe samples and glGetTexImage returns.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Storage {
    /// GL_TEXTURE_RED_SIZE, GREEN, BLUE, ALPHA, LUMINANCE, INTENSITY.
    pub sizes: [u8; 6],
    /// How the stored bytes are read.
    pub encoding: Encoding,
}

/// How the bytes of a stored texel are read when sampled.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Encoding {
    /// Unsigned normalized bytes.
    #[default]
    Unorm,
    /// sRGB colour of an uncompressed image: linearised when sampled, and mipmaps are
    /// filtered in linear space (see [`srgb`]).
    Srgb,
    /// sRGB colour of a compressed image: linearised when sampled; mipmaps filter the
    /// stored bytes.
    SrgbBlocks,
    /// Signed bytes (signed RGTC/LATC, see [`compressed`]).
    Snorm,
    /// Float components (GL_ARB_texture_float, GL_R16F … GL_RG32F): the values are in
    /// [`Level::floats`], 16-bit ones already rounded to half precision (see [`float`]).
    Float,
    /// 16-bit unsigned normalized components (GL_R16, GL_RG16): `u·f32(1/65535)` in
    /// [`Level::floats`] (see [`float`]).
    Unorm16,
}

impl Storage {
    /// 8 bits for every component of `base`.
    pub fn of_base(base: BaseFormat) -> Storage {
        use BaseFormat as B;
        let sizes = match base {
            B::Alpha => [0, 0, 0, 8, 0, 0],
            B::Luminance => [0, 0, 0, 0, 8, 0],
            B::LuminanceAlpha => [0, 0, 0, 8, 8, 0],
            B::Intensity => [0, 0, 0, 0, 0, 8],
            B::Rgb => [8, 8, 8, 0, 0, 0],
            B::Rgba => [8, 8, 8, 8, 0, 0],
            B::Depth => [24, 0, 0, 0, 0, 0],
            B::Red => [8, 0, 0, 0, 0, 0],
            B::Rg => [8, 8, 0, 0, 0, 0],
        };
        Storage {
            sizes,
            encoding: Encoding::Unorm,
        }
    }
    /// Whether images of this storage keep float values ([`Level::floats`]) and are
    /// sampled from them on the float path.
    pub fn has_floats(&self) -> bool {
        matches!(self.encoding, Encoding::Float | Encoding::Unorm16)
    }

    /// GL_TEXTURE_DEPTH_SIZE of a depth image (kept in the first slot, whose colour size
    /// a depth image does not have).
    pub fn depth_bits(&self) -> u8 {
        self.sizes[0]
    }

    /// Bits kept of each client RGBA component before the base swizzle (luminance and
    /// intensity are taken from red); 8 or more means no quantisation.
    pub fn bits(&self) -> [u32; 4] {
        let [r, g, b, a, l, i] = self.sizes.map(|x| x as u32);
        let c = |x: u32| if x == 0 { 8 } else { x };
        if l != 0 {
            [l, l, l, c(a)]
        } else if i != 0 {
            [i; 4]
        } else {
            [c(r), c(g), c(b), c(a)]
        }
    }
}

/// One mipmap image: RGBA8 texels, row 0 first (GL's t = 0 row), after the base swizzle.
#[derive(Clone, Debug, PartialEq)]
pub struct Level {
    /// Width in texels.
    pub width: usize,
    /// Height in texels (1 for 1D).
    pub height: usize,
    /// The internal format as the program gave it (for GL_TEXTURE_INTERNAL_FORMAT).
    pub internal_format: u32,
    /// Base internal format.
    pub base: BaseFormat,
    /// The storage format (reported component sizes, upload precision).
    pub storage: Storage,
    /// `width * height` texels (on huge pages when large: a depth image can then be lent
    /// to a framebuffer object's working copy, see `context::fbo_lend`).
    pub texels: crate::memory::HugeBuf<[u8; 4]>,
    /// The blocks of a compressed image as the program gave them (see [`compressed`]);
    /// `None` for every other image.
    pub blocks: Option<Vec<u8>>,
    /// The texel values of a float or 16-bit image ([`Storage::has_floats`]), after the
    /// base swizzle, one per texel; `texels` then hold them as unorm8 (clamped) for the
    /// commands that only read bytes. `None` for every other image.
    pub floats: Option<Vec<[f32; 4]>>,
}

impl Level {
    /// A level derived from `src` (a mipmap level made from it): `src`'s formats with new
    /// texels, and no compressed blocks.
    pub fn derived(src: &Level, width: usize, height: usize, texels: Vec<[u8; 4]>) -> Level {
        Level {
            width,
            height,
            internal_format: src.internal_format,
            base: src.base,
            storage: src.storage,
            texels: texels.into(),
            blocks: None,
            floats: None,
        }
    }

    /// Whether the level holds all its texels for `depth` slices: not while a framebuffer
    /// object's working copy holds them on loan (see `context::fbo_lend`), when the
    /// texture is incomplete.
    #[inline]
    pub fn has_texels(&self, depth: usize) -> bool {
        self.texels.len() >= self.width * self.height * depth
    }

    /// The texel at (x, y), which must be in range.
    #[inline]
    pub fn texel(&self, x: usize, y: usize) -> [u8; 4] {
        self.texels[y * self.width + x]
    }

    /// The float value of texel `i` (`y·width + x`, slices after each other): from
    /// [`Level::floats`], or the unorm8 texel as the float path reads it.
    #[inline(always)]
    pub fn ftexel(&self, i: usize) -> [f32; 4] {
        match &self.floats {
            Some(f) => f[i],
            None => sample::to_float(self.texels[i]),
        }
    }
}

/// Magnification / minification image filter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Filter {
    /// GL_NEAREST.
    Nearest,
    /// GL_LINEAR.
    Linear,
}

/// Mipmap filter of the minification filter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MipFilter {
    /// No mipmapping (GL_NEAREST / GL_LINEAR).
    None,
    /// GL_*_MIPMAP_NEAREST.
    Nearest,
    /// GL_*_MIPMAP_LINEAR.
    Linear,
}

/// Texture wrap mode.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Wrap {
    /// GL_REPEAT.
    Repeat,
    /// GL_CLAMP.
    Clamp,
    /// GL_CLAMP_TO_EDGE.
    ClampToEdge,
    /// GL_CLAMP_TO_BORDER.
    ClampToBorder,
    /// GL_MIRRORED_REPEAT.
    MirroredRepeat,
}

impl Wrap {
    /// Whether llvmpipe's 8-bit AoS path handles this mode (`lp_is_simple_wrap_mode`).
    pub fn is_simple(self) -> bool {
        matches!(self, Wrap::Repeat | Wrap::ClampToEdge)
    }
}

/// Sampler parameters of a texture object (glTexParameter).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SamplerParams {
    /// GL_TEXTURE_MIN_FILTER: image filter part.
    pub min_filter: Filter,
    /// GL_TEXTURE_MIN_FILTER: mipmap part.
    pub mip_filter: MipFilter,
    /// GL_TEXTURE_MAG_FILTER.
    pub mag_filter: Filter,
    /// GL_TEXTURE_WRAP_S.
    pub wrap_s: Wrap,
    /// GL_TEXTURE_WRAP_T.
    pub wrap_t: Wrap,
    /// GL_TEXTURE_WRAP_R (3D textures).
    pub wrap_r: Wrap,
    /// GL_TEXTURE_BORDER_COLOR (clamped to [0,1] when set, GL 1.5).
    pub border_color: [f32; 4],
    /// GL_TEXTURE_MIN_LOD.
    pub min_lod: f32,
    /// GL_TEXTURE_MAX_LOD.
    pub max_lod: f32,
    /// GL_TEXTURE_BASE_LEVEL.
    pub base_level: i32,
    /// GL_TEXTURE_MAX_LEVEL.
    pub max_level: i32,
    /// GL_TEXTURE_LOD_BIAS (texture object part).
    pub lod_bias: f32,
    /// GL_GENERATE_MIPMAP.
    pub generate_mipmap: bool,
    /// GL_TEXTURE_MAX_ANISOTROPY_EXT.
    pub max_anisotropy: f32,
    /// GL_TEXTURE_PRIORITY.
    pub priority: f32,
    /// GL_TEXTURE_COMPARE_MODE, GL_TEXTURE_COMPARE_FUNC and GL_DEPTH_TEXTURE_MODE.
    pub shadow: shadow::ShadowParams,
}

impl Default for SamplerParams {
    fn default() -> Self {
        SamplerParams {
            min_filter: Filter::Nearest,
            mip_filter: MipFilter::Linear,
            mag_filter: Filter::Linear,
            wrap_s: Wrap::Repeat,
            wrap_t: Wrap::Repeat,
            wrap_r: Wrap::Repeat,
            border_color: [0.0; 4],
            min_lod: -1000.0,
            max_lod: 1000.0,
            base_level: 0,
            max_level: 1000,
            lod_bias: 0.0,
            generate_mipmap: false,
            max_anisotropy: 1.0,
            priority: 1.0,
            shadow: shadow::ShadowParams::default(),
        }
    }
}

/// A texture object.
#[derive(Clone, Debug, Default)]
pub struct TextureObject {
    /// The target it was first bound to (`None`: generated but never bound).
    pub target: Option<Target>,
    /// Mipmap images, indexed by level.
    pub levels: Vec<Option<Level>>,
    /// Sampler parameters.
    pub params: SamplerParams,
    /// Depth of each level of a 3D texture (its texels hold `depth` slices one after the
    /// other); kept beside the levels so proxies without texels know it too.
    pub depths: [usize; MAX_LEVELS],
    /// The other five faces of a cube map (+X is `levels`; then -X, +Y, -Y, +Z, -Z),
    /// empty for the other targets.
    pub faces: Vec<Vec<Option<Level>>>,
    /// The stencil indices of GL_DEPTH24_STENCIL8 images, by (cube face, level), row 0
    /// first; the texels of those images hold only the depth (see [`shadow`]).
    pub stencil: HashMap<(usize, usize), Vec<u8>>,
}

impl TextureObject {
    /// A new object for `target`.
    pub fn new(target: Option<Target>) -> Self {
        let mut o = TextureObject {
            target,
            levels: vec![None; MAX_LEVELS],
            params: SamplerParams::default(),
            depths: [0; MAX_LEVELS],
            faces: Vec::new(),
            stencil: HashMap::new(),
        };
        if target == Some(Target::Cube) {
            o.faces = vec![vec![None; MAX_LEVELS]; 5];
        }
        o
    }

    /// The level array of cube face `face` (0..6, GL's order); face 0 (and every other
    /// target) is `levels`.
    pub fn face_levels(&self, face: usize) -> &[Option<Level>] {
        if face == 0 || self.faces.len() < face {
            &self.levels
        } else {
            &self.faces[face - 1]
        }
    }

    /// [`TextureObject::face_levels`], mutably (creating the faces on first use).
    pub fn face_levels_mut(&mut self, face: usize) -> &mut Vec<Option<Level>> {
        if face == 0 {
            return &mut self.levels;
        }
        if self.faces.len() < 5 {
            self.faces = vec![vec![None; MAX_LEVELS]; 5];
        }
        &mut self.faces[face - 1]
    }

    /// The image of `level`, if specified with a non-zero size.
    pub fn level(&self, level: usize) -> Option<&Level> {
        self.levels.get(level).and_then(|l| l.as_ref())
    }

    /// The range of levels sampling uses, `(base, last)`, when the texture is complete
    /// (GL 1.5 §3.8.10); `None` when incomplete. `last` is Mesa's `_MaxLevel`.
    pub fn complete_range(&self) -> Option<(usize, usize)> {
        match self.target {
            Some(Target::Tex3D) => volume::complete_range(self),
            Some(Target::Cube) => cube::complete_range(self),
            _ => self.complete_range_2d(),
        }
    }

    /// [`TextureObject::complete_range`] of a 1D or 2D texture.
    pub fn complete_range_2d(&self) -> Option<(usize, usize)> {
        self.complete_chain(|_| 1)
    }

    /// [`TextureObject::complete_range`] of a texture whose level `l` has depth `depth(l)`
    /// (1 for 1D and 2D textures): the base level is non-empty, and every level up to the
    /// last has the base's format and its size halved per level (floored, at least 1).
    pub(crate) fn complete_chain(&self, depth: impl Fn(usize) -> usize) -> Option<(usize, usize)> {
        let p = &self.params;
        if p.base_level < 0 || p.base_level > p.max_level || p.base_level as usize >= MAX_LEVELS {
            return None;
        }
        let base = p.base_level as usize;
        let b = self.level(base)?;
        let d = depth(base);
        if b.width == 0 || b.height == 0 || d == 0 || !b.has_texels(d) {
            return None;
        }
        let log2 = usize::BITS - 1 - b.width.max(b.height).max(d).leading_zeros();
        let last = (base + log2 as usize)
            .min(p.max_level as usize)
            .min(MAX_LEVELS - 1);
        if p.mip_filter == MipFilter::None {
            return Some((base, base));
        }
        for l in base + 1..=last {
            let img = self.level(l)?;
            let k = l - base;
            if img.width != (b.width >> k).max(1)
                || img.height != (b.height >> k).max(1)
                || depth(l) != (d >> k).max(1)
                || img.base != b.base
                || !img.has_texels(depth(l))
            {
                return None;
            }
        }
        Some((base, last))
    }
}

/// One texture unit's server-side state.
#[derive(Clone, Debug)]
pub struct TexUnit {
    /// glEnable(GL_TEXTURE_1D) on this unit.
    pub enabled_1d: bool,
    /// glEnable(GL_TEXTURE_2D) on this unit.
    pub enabled_2d: bool,
    /// glEnable(GL_TEXTURE_3D) on this unit.
    pub enabled_3d: bool,
    /// glEnable(GL_TEXTURE_CUBE_MAP) on this unit.
    pub enabled_cube: bool,
    /// Bound texture names per target (0 = the default texture).
    pub bound: [u32; NUM_TARGETS],
    /// Texture environment (glTexEnv).
    pub env: TexEnv,
    /// GL_TEXTURE_LOD_BIAS of the texture environment (GL_TEXTURE_FILTER_CONTROL).
    pub lod_bias: f32,
}

impl Default for TexUnit {
    fn default() -> Self {
        TexUnit {
            enabled_1d: false,
            enabled_2d: false,
            enabled_3d: false,
            enabled_cube: false,
            bound: [0; NUM_TARGETS],
            env: TexEnv::default(),
            lod_bias: 0.0,
        }
    }
}

/// All texture objects and units of a context.
#[derive(Clone, Debug)]
pub struct TextureState {
    /// Named objects (name > 0).
    pub objects: HashMap<u32, TextureObject>,
    /// The default textures (name 0) of each target.
    pub defaults: [TextureObject; NUM_TARGETS],
    /// The texture units.
    pub units: [TexUnit; MAX_TEXTURE_UNITS],
    /// The next name glGenTextures tries.
    pub next_name: u32,
    /// The proxy textures (GL_PROXY_TEXTURE_1D/2D/3D/CUBE_MAP): level sizes only.
    pub proxies: [TextureObject; NUM_TARGETS],
    /// GL_TEXTURE_CUBE_MAP_SEAMLESS (context-wide; not part of any attribute group, as in
    /// Mesa).
    pub cube_seamless: bool,
}

impl Default for TextureState {
    fn default() -> Self {
        TextureState {
            objects: HashMap::new(),
            defaults: ALL_TARGETS.map(|t| TextureObject::new(Some(t))),
            units: std::array::from_fn(|_| TexUnit::default()),
            next_name: 1,
            proxies: ALL_TARGETS.map(|t| TextureObject::new(Some(t))),
            cube_seamless: false,
        }
    }
}

impl TextureState {
    /// The object bound to `target` on `unit`.
    pub fn bound(&self, unit: usize, target: Target) -> &TextureObject {
        let name = self.units[unit].bound[target.index()];
        if name == 0 {
            &self.defaults[target.index()]
        } else {
            self.objects
                .get(&name)
                .unwrap_or(&self.defaults[target.index()])
        }
    }

    /// The object bound to `target` on `unit`, mutably.
    pub fn bound_mut(&mut self, unit: usize, target: Target) -> &mut TextureObject {
        let name = self.units[unit].bound[target.index()];
        if name == 0 || !self.objects.contains_key(&name) {
            &mut self.defaults[target.index()]
        } else {
            self.objects.get_mut(&name).expect("checked")
        }
    }

    /// glGenTextures: `n` unused names, reserved (they are not textures until bound).
    pub fn gen(&mut self, n: usize) -> Vec<u32> {
        let mut out = Vec::with_capacity(n);
        while out.len() < n {
            let name = self.next_name;
            self.next_name = self.next_name.wrapping_add(1).max(1);
            if name != 0 && !self.objects.contains_key(&name) {
                self.objects.insert(name, TextureObject::new(None));
                out.push(name);
            }
        }
        out
    }

    /// glDeleteTextures: deletes the objects and rebinds 0 wherever they were bound.
    pub fn delete(&mut self, names: &[u32]) {
        for &name in names {
            if name == 0 || self.objects.remove(&name).is_none() {
                continue;
            }
            for u in &mut self.units {
                for b in &mut u.bound {
                    if *b == name {
                        *b = 0;
                    }
                }
            }
        }
    }

    /// glIsTexture: a name that has been bound at least once and not deleted.
    pub fn is_texture(&self, name: u32) -> bool {
        name != 0 && self.objects.get(&name).is_some_and(|o| o.target.is_some())
    }

    /// Whether `unit` has an enabled target with a complete texture (`unit_plan` is
    /// `Some`).
    fn unit_active(&self, unit: usize) -> bool {
        self.current_target(unit).is_some()
    }

    /// The target `unit` samples: the first enabled target, in the order cube map, 3D, 2D,
    /// 1D, whose texture is complete (Mesa's `update_ff_texture_state` passes over an
    /// incomplete one to the next enabled target).
    pub fn current_target(&self, unit: usize) -> Option<Target> {
        let u = self.units.get(unit)?;
        [
            (u.enabled_cube, Target::Cube),
            (u.enabled_3d, Target::Tex3D),
            (u.enabled_2d, Target::Tex2D),
            (u.enabled_1d, Target::Tex1D),
        ]
        .into_iter()
        .find(|&(on, t)| on && self.bound(unit, t).complete_range().is_some())
        .map(|(_, t)| t)
    }

    /// The sampling plan of `unit` for one draw; `None` when the unit is disabled or its
    /// texture incomplete.
    pub fn unit_plan(&self, unit: usize) -> Option<UnitPlan<'_>> {
        self.unit_plan_target(unit, self.current_target(unit)?)
    }

    /// The sampling plan of the texture bound to `target` of `unit`, whatever the
    /// unit's enables (a shader's sampler names its target); `None` when that texture is
    /// incomplete.
    pub fn unit_plan_target(&self, unit: usize, target: Target) -> Option<UnitPlan<'_>> {
        let u = self.units.get(unit)?;
        let obj = self.bound(unit, target);
        let (first, last) = obj.complete_range()?;
        let p = &obj.params;
        let base_img = obj.level(first)?;
        let base = base_img.base;
        let dims = match target {
            Target::Tex1D => 1,
            Target::Tex3D => 3,
            _ => 2,
        };
        // GL_CLAMP with nearest-only filtering never reads the border: llvmpipe treats it as
        // CLAMP_TO_EDGE (derived sampler state).
        let nearest_only = p.min_filter == Filter::Nearest && p.mag_filter == Filter::Nearest;
        let fix = |w: Wrap| {
            if nearest_only && w == Wrap::Clamp {
                Wrap::ClampToEdge
            } else {
                w
            }
        };
        // Cube maps: every wrap mode becomes CLAMP_TO_EDGE (llvmpipe's derived state).
        let fix = |w: Wrap| {
            if target == Target::Cube {
                Wrap::ClampToEdge
            } else {
                fix(w)
            }
        };
        let wrap_s = fix(p.wrap_s);
        let wrap_t = if dims >= 2 {
            fix(p.wrap_t)
        } else {
            Wrap::Repeat
        };
        let wrap_r = fix(p.wrap_r);
        let aniso = p.max_anisotropy > 1.0;
        // llvmpipe filters a seamless cube map on the float path when a filter is LINEAR
        let seamless = target == Target::Cube
            && self.cube_seamless
            && (p.min_filter == Filter::Linear || p.mag_filter == Filter::Linear);
        let depth = (base == BaseFormat::Depth).then(|| shadow::DepthPlan {
            func: p.shadow.compare.then_some(p.shadow.func),
            mode: p.shadow.depth_mode,
            bits: base_img.storage.depth_bits(),
        });
        // sRGB and signed textures: decoded per texel, then filtered on the float path
        let decode = unit::texel_decode(base_img.storage.encoding);
        // a depth texture is always sampled on the float path
        // float and 16-bit textures: float texels, filtered on the float path
        let floats = base_img.storage.has_floats();
        // components of fewer than 8 bits have float values of their own on the float path
        let narrow = match base_img.blocks {
            None => unit::narrow_decode(&base_img.storage),
            Some(_) => None,
        };
        // llvmpipe picks its path before a nearest-only GL_CLAMP acts as CLAMP_TO_EDGE
        // ("could force CLAMP to CLAMP_TO_EDGE ... not sure it's worth the trouble",
        // lp_bld_sample_soa.c): GL_CLAMP samples on the float path. 8-bit texels give the
        // same nearest value on both paths and stay on the 8-bit one; narrow ones cannot.
        let clamp_float = narrow.is_some()
            && target != Target::Cube
            && [p.wrap_s, p.wrap_t, p.wrap_r][..dims as usize].contains(&Wrap::Clamp);
        let aos = depth.is_none()
            && decode.is_none()
            && !floats
            && wrap_s.is_simple()
            && wrap_t.is_simple()
            && (dims < 3 || wrap_r.is_simple())
            && !aniso
            && !seamless
            && !clamp_float;
        let narrow_ops = match (aos, decode, narrow) {
            (false, None, Some(_)) => Some(unit::narrow_ops(&base_img.storage)),
            _ => None,
        };
        let decode = if aos { None } else { decode.or(narrow) };
        let lod = LodParams::new(p, u.lod_bias, dims == 1);
        let border = base.swizzle(p.border_color, 0.0, 1.0);
        let needs_lod = !(p.min_filter == p.mag_filter && p.mip_filter == MipFilter::None);
        // llvmpipe chooses the REPEAT code from the resource's level-0 size.
        let l0 = obj.level(0).filter(|l| l.base == base).unwrap_or(base_img);
        let pot = [l0.width.is_power_of_two(), l0.height.is_power_of_two()];
        let kind = match target {
            Target::Tex3D => ExtKind::Volume(volume::VolumePlan {
                wrap_r,
                pot_r: obj.depths[0].is_power_of_two() || obj.level(0).is_none(),
                depths: &obj.depths,
            }),
            Target::Cube if seamless => {
                ExtKind::CubeSeamless(std::array::from_fn(|f| obj.face_levels(f)))
            }
            Target::Cube => ExtKind::Cube(std::array::from_fn(|f| obj.face_levels(f))),
            _ => ExtKind::Flat,
        };
        let mut env = Combine::derive(&u.env, depth.map_or(base, |d| d.mode.base()));
        let slot = |n: usize| {
            let before = (0..n).filter(|&j| self.unit_active(j)).count();
            self.unit_active(n).then_some(before)
        };
        env.canonicalise(unit, !(0..unit).any(|j| self.unit_active(j)), slot);
        let fast = if fast::enabled() && aos && dims == 2 && matches!(kind, ExtKind::Flat) {
            fast::FastEnv::classify(&env)
        } else {
            None
        };
        Some(UnitPlan {
            levels: &obj.levels,
            first,
            last,
            dims,
            min_filter: p.min_filter,
            mag_filter: p.mag_filter,
            mip_filter: p.mip_filter,
            wrap_s,
            wrap_t,
            border,
            aos,
            pot,
            max_anisotropy: if aniso { p.max_anisotropy } else { 1.0 },
            lod,
            needs_lod,
            base_format: base,
            env,
            fast,
            fma: sample::has_fma(),
            ext: PlanExt {
                kind,
                depth,
                decode,
                narrow: narrow_ops,
                floats,
            },
        })
    }
}

pub use unit::{ExtKind, PlanExt, UnitPlan};

pub use lod::Lod;

#[cfg(test)]
mod tests;
