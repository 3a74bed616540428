//! The 8-wide samplers of the general textured walks: a unit of a chunk sampled a row
//! (8 pixels) at a time instead of a 2x2 quad at a time through the general sampler
//! (`variants::sample_quad`), where an 8-wide sampler covers the unit's state:
//! - a 2D texture on llvmpipe's 8-bit path (`UnitPlan::aos`): the fast path's chunk
//!   sampler ([`crate::texture::fast::chunk_u8`], the same bytes as the general sampler's
//!   `fast::quad_u8`), its texels then made floats as the general sampler makes them;
//! - a shadow map with its depth comparison
//!   ([`crate::texture::shadow_avx2::Shadow8`]);
//! - a seamless cube map with LINEAR filtering, mipmapped or not
//!   ([`crate::texture::cube_avx2::Cube8`], MuJoCo's skybox): both rows at once, as the
//!   per-pixel LOD reads each quad's two rows; the quads it leaves (a tap across a face
//!   edge, a coordinate that is not finite) are sampled here by the quad sampler;
//! - a cube map without seamless filtering on llvmpipe's 8-bit path, LINEAR, mipmapped
//!   or not ([`crate::texture::cube_aos8::CubeAos8`], scene k's spheres): both rows at
//!   once likewise; the quads it leaves (a coordinate that is not finite) are sampled
//!   here by the quad sampler;
//! - a 3D texture on llvmpipe's 8-bit path without a LOD
//!   ([`crate::texture::volume8::Vol8`]); the quads it leaves (a coordinate that is NaN or
//!   of magnitude 2^30 texels or more) are sampled here by the quad sampler;
//! - any other 2D texture on llvmpipe's float path (GL_CLAMP, CLAMP_TO_BORDER,
//!   MIRRORED_REPEAT wraps, non-power-of-two REPEAT beside them, sRGB and signed texels)
//!   without anisotropy ([`crate::texture::soa_avx2::Soa8`]): both rows at once, each
//!   quad's LOD and levels from the scalar code, then one 8-lane pass per row for each
//!   (filter, level) the quads select; the quads it leaves (a coordinate that is NaN,
//!   infinite or of magnitude 2^16 or more) are sampled here by the quad sampler.
//!
//! These are the units of MuJoCo's multi-unit draws (the floor's mipmapped grid beside
//! the shadow map on unit 1, the light passes' shadow map alone), which the one-unit
//! fast path does not take, of every textured multisample draw, and the float-path units
//! (wraps other than REPEAT and CLAMP_TO_EDGE) of every textured draw. The values are the
//! general sampler's; only the number of instructions changes.
//!
//! The AVX2+FMA level has an out-of-line copy (one call per unit and chunk), compiled
//! with FMA; the other levels keep the quad sampler. `SOFTGL_TEX_PATH=general` turns these off with the fast path.

use crate::fragment::span::{Madd, TexLanes, LANES};
use crate::texture::UnitPlan;

/// A chunk's two rows of texture coordinates for one unit, and which lanes are live.
pub(super) struct Rows<'a> {
    /// s per row and lane.
    pub s: &'a [[f32; LANES]; 2],
    /// t per row and lane.
    pub t: &'a [[f32; LANES]; 2],
    /// The depth comparison's references, for a shadow unit.
    pub r: Option<&'a [[f32; LANES]; 2]>,
    /// The lanes with a fragment.
    pub live: &'a [[bool; LANES]; 2],
}

/// Samples unit `k` (`u`) of a chunk's two rows at `c.s`, `c.t` (with references `c.r`
/// for a depth comparison) into `texels`, for the rows with a live lane; `false` (and the
/// caller samples the quads) when no 8-wide sampler covers the unit or one declines.
/// The quads an 8-wide sampler leaves are sampled here through the quad sampler.
/// Lanes that are not live may receive any value.
#[inline(always)]
#[allow(unused_variables)]
pub(super) fn rows<M: Madd>(
    u: &UnitPlan<'_>,
    k: usize,
    c: &Rows<'_>,
    texels: &mut [TexLanes; 2],
) -> bool {
    // The one AVX2 level fuses; a walk that does not (the scalar level's, or a test's)
    // keeps the quad sampler.
    #[cfg(target_arch = "x86_64")]
    if M::FUSED && crate::texture::fast_avx2::available() && crate::texture::fast::enabled() {
        // SAFETY: the CPU has AVX2 (`fast_avx2::available`: the level is `avx2fma` or
        // above), and so FMA.
        let done = unsafe { rows_avx2fma(u, k, c, texels) };
        let Some(redo) = done else {
            return false;
        };
        // the quads the 8-wide sampler left to the quad sampler
        for j in (0..LANES / 2).filter(|j| redo >> j & 1 != 0) {
            let (l, r) = (2 * j, 2 * j + 1);
            let quad = |v: &[[f32; LANES]; 2]| [v[0][l], v[0][r], v[1][l], v[1][r]];
            let v = super::variants::sample_quad::<M>(u, quad(c.s), quad(c.t), c.r.map(quad));
            texels[0][k][l] = v[0];
            texels[0][k][r] = v[1];
            texels[1][k][l] = v[2];
            texels[1][k][r] = v[3];
        }
        return true;
    }
    false
}

/// [`rows`]' body, inlined into each level's copy.
///
/// # Safety
/// The CPU has AVX2, and FMA when `u.fma`.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
#[allow(clippy::needless_range_loop)]
unsafe fn rows_body(
    u: &UnitPlan<'_>,
    k: usize,
    c: &Rows<'_>,
    texels: &mut [TexLanes; 2],
) -> Option<u32> {
    use crate::texture::{
        cube_aos8::CubeAos8, cube_avx2::Cube8, fast, shadow_avx2::Shadow8, soa_avx2::Soa8, ExtKind,
    };
    let Rows { s, t, r, live } = *c;
    let flat = matches!(u.ext.kind, ExtKind::Flat);
    if u.aos && u.dims == 2 && flat && r.is_none() {
        // The general sampler's 8-bit quads (`UnitPlan::sample_quad`): an AoS plan never
        // has anisotropy.
        let mut tex = [[[0u8; 4]; LANES]; 2];
        fast::chunk_u8::<true>(u, s, t, live, true, &mut tex);
        for (row, tex) in texels.iter_mut().zip(&tex) {
            // SAFETY: forwarded from the caller (AVX2).
            unsafe { bytes_to_floats(tex, &mut row[k]) };
        }
        return Some(0);
    }
    if let (Some(r), Some(sh)) = (r, Shadow8::of(u)) {
        for row in 0..2 {
            if !live[row].iter().any(|&l| l) {
                continue;
            }
            // SAFETY: forwarded from the caller.
            let done =
                unsafe { sh.row(&s[row], &t[row], &r[row], &live[row], &mut texels[row][k]) };
            if !done {
                return None;
            }
        }
        return Some(0);
    }
    if let (Some(r), Some(cube)) = (r, Cube8::of(u)) {
        let [t0, t1] = texels;
        // SAFETY: forwarded from the caller.
        return Some(unsafe { cube.rows(s, t, r, live, [&mut t0[k], &mut t1[k]]) });
    }
    if let (Some(r), Some(cube)) = (r, CubeAos8::of(u)) {
        let [t0, t1] = texels;
        // SAFETY: forwarded from the caller.
        return Some(unsafe { cube.rows([s, t, r], live, [&mut t0[k], &mut t1[k]]) });
    }
    if let (Some(r), Some(vol)) = (r, crate::texture::volume8::Vol8::of(u)) {
        let [t0, t1] = texels;
        // SAFETY: forwarded from the caller.
        return Some(unsafe { vol.rows(s, t, r, live, [&mut t0[k], &mut t1[k]]) });
    }
    if let (None, Some(soa)) = (r, Soa8::of(u)) {
        let [t0, t1] = texels;
        // SAFETY: forwarded from the caller.
        return Some(unsafe { soa.rows(s, t, live, [&mut t0[k], &mut t1[k]]) });
    }
    None
}

/// The 8-bit texels of a row as the general sampler's floats, `u·f32(1/255)` per channel
/// ([`crate::texture::sample::to_float`]: an exact conversion, then the same product), two
/// pixels (8 channels) per 8-lane step. Written per channel by the compiler, the loop took
/// a third of this function's time in multitex_combine.
///
/// # Safety
/// The CPU has AVX2.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn bytes_to_floats(tex: &[[u8; 4]; LANES], out: &mut [[f32; 4]; LANES]) {
    use crate::simd::{F32x8, I32x8};
    // SAFETY: AVX2 (the caller's promise); each step reads the 8 bytes of pixels `2j` and
    // `2j + 1` and writes their 8 floats, both contiguous in `tex` and `out`.
    unsafe {
        let scale = F32x8::splat(crate::texture::sample::INV_255);
        for j in 0..LANES / 2 {
            // One 8-byte load: taken apart and put together again, the bytes were shuffled
            // one at a time.
            let b = std::ptr::read_unaligned(tex.as_ptr().add(2 * j) as *const [u8; 8]);
            I32x8::from_u8(b)
                .to_f32()
                .mul(scale)
                .store(out[2 * j].as_mut_ptr());
        }
    }
}

/// Defines a level's out-of-line copy of [`rows_body`] with the given target features.
#[cfg(target_arch = "x86_64")]
macro_rules! rows_copy {
    ($(#[$attr:meta])* $name:ident) => {
        $(#[$attr])*
        #[inline(never)]
        unsafe fn $name(
            u: &UnitPlan<'_>,
            k: usize,
            c: &Rows<'_>,
            texels: &mut [TexLanes; 2],
        ) -> Option<u32> {
            // SAFETY: forwarded from the caller.
            unsafe { rows_body(u, k, c, texels) }
        }
    };
}

#[cfg(target_arch = "x86_64")]
rows_copy!(
    /// [`rows`] for the AVX2+FMA levels.
    #[target_feature(enable = "avx2,fma,popcnt,bmi1,bmi2,lzcnt")]
    rows_avx2fma
);
