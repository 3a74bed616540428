//! What one texture unit samples during a draw: the bound image levels, sampler state and
//! texture environment, gathered once per draw ([`UnitPlan`]), and the sampling calls the
//! span code makes through it.

#[allow(unused_imports)]
use super::*;

/// What a unit's plan adds for the targets beyond 1D/2D.
#[derive(Clone, Copy, Debug, Default)]
pub struct PlanExt<'a> {
    /// The target's sampling kind.
    pub kind: ExtKind<'a>,
    /// A depth texture's comparison and mode.
    pub depth: Option<shadow::DepthPlan>,
    /// The float value of each byte of R, G, B and A (one table per component) for
    /// textures that are not plain unorm8 on the float path: sRGB ones (see [`srgb`]),
    /// signed ones (see [`compressed`]), and those stored with components of fewer than 8
    /// bits ([`narrow_decode`]). Every float-path texel conversion goes through these
    /// tables ([`sample::texel_float`]); a plan with sRGB or signed ones is never `aos`,
    /// and an `aos` plan has none.
    pub decode: Option<Decode>,
    /// When `decode` holds [`narrow_decode`]'s tables: the same values as arithmetic
    /// ([`narrow_ops`]), for the 8-wide samplers (no table gathers).
    pub narrow: Option<NarrowOps>,
    /// The texture keeps float values ([`super::float`]): texels are read from
    /// [`Level::floats`]; such a plan is never `aos`.
    pub floats: bool,
}

/// The float value of each stored byte, per component R, G, B, A ([`PlanExt::decode`]).
pub type Decode = [&'static [f32; 256]; 4];

/// The per-byte decode tables of an image's encoding ([`PlanExt::decode`]): sRGB and
/// signed images, which llvmpipe always samples on its float path.
pub(super) fn texel_decode(encoding: Encoding) -> Option<Decode> {
    match encoding {
        Encoding::Srgb | Encoding::SrgbBlocks => {
            let rgb = srgb::table(sample::has_fma());
            Some([rgb, rgb, rgb, compressed::unorm_table()])
        }
        Encoding::Snorm => Some([compressed::snorm_table(); 4]),
        // float and 16-bit images are read from their float values instead
        Encoding::Unorm | Encoding::Float | Encoding::Unorm16 => None,
    }
}

/// The decode tables of an uncompressed unorm image stored with components of fewer than
/// 8 bits (GL_R3_G3_B2, GL_RGB5, GL_RGB5_A1, GL_RGBA4, 5_6_5, the 2 alpha bits of
/// GL_RGB10_A2 …; [`Storage::bits`]) on llvmpipe's float path, `None` when every component
/// has 8 bits or more. llvmpipe fetches such a texel from its packed format and converts
/// each n-bit component c as `float(c) · f32(1/(2^n − 1))` (`lp_bld_format_soa.c`,
/// `lp_build_extract_soa_chan` → `lp_build_unsigned_norm_to_float`), where softgl keeps
/// the bit-replicated byte; its 8-bit path (and glGetTexImage) sees that byte.
pub(super) fn narrow_decode(storage: &Storage) -> Option<Decode> {
    if storage.encoding != Encoding::Unorm {
        return None;
    }
    let bits = storage.bits();
    if bits.iter().all(|&b| b >= 8) {
        return None;
    }
    Some(bits.map(narrow_table))
}

/// [`narrow_decode`]'s tables as arithmetic, per component R, G, B, A: `(max, scale)`,
/// where byte u decodes to `float((u·max + 127) / 255) · scale` ([`narrow_table`] with
/// `max = 2^n − 1`), or `max = 0` where the table is `u · f32(1/255)`.
pub type NarrowOps = [(i32, f32); 4];

/// The [`NarrowOps`] of an image stored as `storage` ([`narrow_decode`]'s tables).
pub(super) fn narrow_ops(storage: &Storage) -> NarrowOps {
    storage.bits().map(|bits| {
        if (1..8).contains(&bits) {
            let max = (1u32 << bits) - 1;
            (max as i32, (1.0f64 / max as f64) as f32)
        } else {
            (0, sample::INV_255)
        }
    })
}

/// The float value of each byte holding an n-bit component ([`narrow_decode`]): the
/// component `c = round(u·(2^n − 1)/255)` (exactly the stored c for the bit-replicated
/// bytes uploads keep, `upload::quantise_u8`) as `float(c) · f32(1/(2^n − 1))`;
/// `u · f32(1/255)` for 8 bits and more.
pub fn narrow_table(bits: u32) -> &'static [f32; 256] {
    static T: std::sync::OnceLock<[[f32; 256]; 7]> = std::sync::OnceLock::new();
    if !(1..8).contains(&bits) {
        return compressed::unorm_table();
    }
    let tables = T.get_or_init(|| {
        std::array::from_fn(|k| {
            let max = (1u32 << (k + 1)) - 1;
            let scale = (1.0f64 / max as f64) as f32;
            std::array::from_fn(|u| ((u as u32 * max + 127) / 255) as f32 * scale)
        })
    });
    &tables[bits as usize - 1]
}

/// The sampling kind of a unit's target.
#[derive(Clone, Copy, Debug, Default)]
pub enum ExtKind<'a> {
    /// GL_TEXTURE_1D / GL_TEXTURE_2D: (s, t) only.
    #[default]
    Flat,
    /// GL_TEXTURE_3D.
    Volume(volume::VolumePlan<'a>),
    /// GL_TEXTURE_CUBE_MAP: the six faces' levels.
    Cube(cube::Faces<'a>),
    /// GL_TEXTURE_CUBE_MAP with GL_TEXTURE_CUBE_MAP_SEAMLESS and a LINEAR filter.
    CubeSeamless(cube::Faces<'a>),
}

/// Everything sampling and the environment of one unit need for one draw.
#[derive(Clone, Debug)]
pub struct UnitPlan<'a> {
    /// All level slots of the texture; `first..=last` are present and consistent.
    pub levels: &'a [Option<Level>],
    /// Base level.
    pub first: usize,
    /// Last level sampling may use.
    pub last: usize,
    /// 1 for GL_TEXTURE_1D, 2 for GL_TEXTURE_2D.
    pub dims: u8,
    /// Minification image filter.
    pub min_filter: Filter,
    /// Magnification filter.
    pub mag_filter: Filter,
    /// Mipmap filter.
    pub mip_filter: MipFilter,
    /// Wrap mode of s (after llvmpipe's GL_CLAMP→CLAMP_TO_EDGE for nearest-only sampling).
    pub wrap_s: Wrap,
    /// Wrap mode of t (REPEAT for 1D, unused).
    pub wrap_t: Wrap,
    /// Border colour after the base-format swizzle.
    pub border: [f32; 4],
    /// llvmpipe's 8-bit fixed-point AoS path (else the float SoA path).
    pub aos: bool,
    /// Whether the level-0 width and height are powers of two (selects the REPEAT code).
    pub pot: [bool; 2],
    /// Max anisotropy (1 = off).
    pub max_anisotropy: f32,
    /// LOD bias/clamp parameters.
    pub lod: LodParams,
    /// Whether a LOD must be computed at all (false: min == mag and no mipmapping).
    pub needs_lod: bool,
    /// Base internal format of the base level.
    pub base_format: BaseFormat,
    /// The texture environment in combiner form.
    pub env: Combine,
    /// The fast path's form of this unit (8-bit 2D sampling with a simple environment),
    /// when it qualifies (see [`fast`]).
    pub fast: Option<fast::FastEnv>,
    /// Whether float lerps fuse (llvmpipe uses `llvm.fmuladd`, fused on FMA CPUs).
    pub fma: bool,
    /// 3D and cube-map sampling.
    pub ext: PlanExt<'a>,
}

impl UnitPlan<'_> {
    /// The image of `level` (which must be in `first..=last`).
    #[inline]
    pub fn image(&self, level: usize) -> &Level {
        self.levels[level].as_ref().expect("complete texture")
    }

    /// The LOD of a 2x2 quad (TL, TR, BL, BR, y-down), computed only when the filters
    /// need it (magnification at the base level otherwise).
    #[inline(always)]
    pub fn quad_lod(&self, s: [f32; 4], t: [f32; 4]) -> Lod {
        if !self.needs_lod {
            return Lod::MAG;
        }
        let b = self.image(self.first);
        let (w, h) = (b.width as f32, b.height as f32);
        lod::compute(&self.lod, self.mip_filter, self.dims, w, h, s, t)
    }

    /// Samples a 2x2 quad (TL, TR, BL, BR in y-down order) with one LOD computed from
    /// TL/TR/BL, as llvmpipe does.
    #[inline(always)]
    #[allow(clippy::needless_range_loop)]
    pub fn sample_quad(&self, s: [f32; 4], t: [f32; 4]) -> [[f32; 4]; 4] {
        if self.max_anisotropy > 1.0 {
            return sample::sample_quad_aniso(self, s, t);
        }
        if self.aos && self.dims == 2 {
            // The 8-bit filter on packed channels: the same bytes as `sample_one`'s
            // per-channel lerps (see `fast::quad_u8`), in fewer instructions.
            let q = fast::quad_u8(self, s, t);
            return each4!(|i| sample::to_float(q[i]));
        }
        let lod = self.quad_lod(s, t);
        let mut out = [[0.0f32; 4]; 4];
        for i in 0..4 {
            out[i] = self.sample_one(s[i], t[i], lod);
        }
        out
    }

    /// Whether sampling reads the r coordinate (3D and cube-map textures).
    #[inline(always)]
    pub fn needs_r(&self) -> bool {
        !matches!(self.ext.kind, ExtKind::Flat) || self.ext.depth.is_some()
    }

    /// [`UnitPlan::sample_quad`] with r (3D textures, cube maps).
    #[inline(always)]
    pub fn sample_quad_str(&self, s: [f32; 4], t: [f32; 4], r: [f32; 4]) -> [[f32; 4]; 4] {
        if let (Some(d), ExtKind::Flat) = (&self.ext.depth, &self.ext.kind) {
            return shadow::sample_quad(self, d, s, t, r);
        }
        match &self.ext.kind {
            ExtKind::Flat => self.sample_quad(s, t),
            ExtKind::Volume(v) => volume::sample_quad(self, v, s, t, r),
            ExtKind::Cube(f) => cube::sample_quad(self, f, s, t, r),
            ExtKind::CubeSeamless(f) => cube_seamless::sample_quad(self, f, s, t, r),
        }
    }

    /// Samples one coordinate with a given LOD.
    #[inline(always)]
    pub fn sample_one(&self, s: f32, t: f32, lod: Lod) -> [f32; 4] {
        sample::sample(self, s, t, lod)
    }
}
