//! The 8-bit multisample resolve of glBlitFramebuffer without a fresh buffer: the
//! average of 4 RGBA8 sample planes with llvmpipe's resolve-shader arithmetic
//! ([`average_rgba8`]), written into a resolved image kept between frames ([`reuse`]).
//!
//! Per channel: `sum = 0; sum += u_i · f32(1/255)` in sample order in f32, then
//! `unorm8(sum · 0.25)`. The bytes of all four planes are read as one flat run of
//! channels, so the same scalar body compiles to 8-lane (AVX2) or 4-lane (SSE2) float
//! code; no multiply-add is ever fused (Rust does not contract), so every level gives the
//! same bytes. Rows are split over the thread pool in chunks of
//! [`crate::tuning::RESOLVE_CHUNK`] pixels. At 1920×1080 the average reads 32 MB and
//! writes 8 MB; the resolved image (colour, depth, stencil) is the last frame's, so a
//! steady-state frame touches no fresh page (a clone of plane 0 cost about 25 ms of
//! kernel page zeroing per frame).

use crate::framebuffer::Framebuffer;
use rayon::prelude::*;

/// Sample planes a resolve averages.
const PLANES: usize = 4;

/// Channels `out[i] = unorm8(Σ_k planes[k][i] · f32(1/255) · 0.25)`: the loop body every
/// variant compiles.
#[inline(always)]
fn average_body(planes: [&[u8]; PLANES], out: &mut [u8]) {
    let scale = 1.0f32 / 255.0;
    let [a, b, c, d] = planes;
    let n = out.len();
    let (a, b, c, d) = (&a[..n], &b[..n], &c[..n], &d[..n]);
    for i in 0..n {
        let mut sum = 0.0f32;
        sum += a[i] as f32 * scale;
        sum += b[i] as f32 * scale;
        sum += c[i] as f32 * scale;
        sum += d[i] as f32 * scale;
        out[i] = crate::fragment::span::unorm8(sum * 0.25);
    }
}

/// [`average_body`] compiled for baseline x86-64 (or another architecture).
fn average_scalar(planes: [&[u8]; PLANES], out: &mut [u8]) {
    average_body(planes, out)
}

/// [`average_body`] compiled for AVX2 (8 lanes).
///
/// # Safety
/// The CPU has AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn average_avx2(planes: [&[u8]; PLANES], out: &mut [u8]) {
    average_body(planes, out)
}

/// One chunk of channels at the running instruction-set level.
fn average_chunk(planes: [&[u8]; PLANES], out: &mut [u8]) {
    #[cfg(target_arch = "x86_64")]
    if crate::simd::cpu::isa().avx2() {
        // SAFETY: an AVX2 variant runs only on a CPU with AVX2.
        return unsafe { average_avx2(planes, out) };
    }
    average_scalar(planes, out)
}

/// Writes the resolve of the 4 colour planes `planes` into `out` (all of one length),
/// chunks of rows in parallel on the thread pool.
pub fn average_rgba8(planes: [&[[u8; 4]]; PLANES], out: &mut [[u8; 4]]) {
    let flat = planes.map(|p| p.as_flattened());
    let out = out.as_flattened_mut();
    let chunk = crate::tuning::RESOLVE_CHUNK * 4;
    if crate::simd::cpu::threads() <= 1 || out.len() <= chunk {
        return average_chunk(flat, out);
    }
    out.par_chunks_mut(chunk).enumerate().for_each(|(k, o)| {
        let at = k * chunk;
        average_chunk(flat.map(|p| &p[at..at + o.len()]), o);
    });
}

/// The resolved image to write a resolve of `p0`'s planes into: `scratch` (the last
/// resolve's image) when its buffers have `p0`'s sizes, with `p0`'s description, its
/// recorded clears, and the depth and stencil values the blit reads (`depth`, `stencil`)
/// copied in place; else a clone of `p0`. Its colour is left for the caller to write.
pub fn reuse(
    scratch: Option<Framebuffer>,
    p0: &Framebuffer,
    depth: bool,
    stencil: bool,
) -> Framebuffer {
    let fits = |s: &Framebuffer| {
        s.color.len() == p0.color.len()
            && s.depth.len() == p0.depth.len()
            && s.stencil.len() == p0.stencil.len()
            && s.wide.is_none()
            && s.wide_color.is_empty()
            && p0.wide.is_none()
            && p0.wide_color.is_empty()
            && p0.samples.is_empty()
    };
    let Some(mut s) = scratch.filter(fits) else {
        return p0.clone();
    };
    s.width = p0.width;
    s.height = p0.height;
    s.format = p0.format;
    s.depth_format = p0.depth_format;
    s.uniform_color = p0.uniform_color;
    s.pending_color = p0.pending_color;
    s.pending_depth = p0.pending_depth;
    s.pending_rows.clone_from(&p0.pending_rows);
    s.y_flip = p0.y_flip;
    s.wide_single = p0.wide_single;
    s.srgb = p0.srgb;
    if depth {
        s.depth.copy_from_slice(&p0.depth);
    }
    if stencil {
        s.stencil.copy_from_slice(&p0.stencil);
    }
    s
}

/// The depth values of a multisample resolve as llvmpipe's blitter writes them: sample
/// 0's value read as a float (`lp_build_unsigned_norm_to_float` for at most 24 bits:
/// `f32(v) · f32(1 / (2ⁿ − 1))`) and stored back as a shader's depth
/// ([`crate::framebuffer::DepthFormat::quantize`]). The trip moves about 31% of Z24
/// values by one (scene frag_msaa). Float depth comes back exact; Z32 keeps its values
/// (its conversion was not probed).
pub fn depth_through_float(fb: &mut Framebuffer) {
    use crate::framebuffer::DepthFormat;
    let format = fb.depth_format;
    let scale = match format {
        DepthFormat::Z24 => (1.0f64 / 16_777_215.0) as f32,
        DepthFormat::Z16 => (1.0f64 / 65_535.0) as f32,
        _ => return,
    };
    let trip = |v: u32| format.quantize(v as f32 * scale);
    for d in fb.depth.iter_mut() {
        *d = trip(*d);
    }
    fb.pending_depth = fb.pending_depth.map(trip);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The resolve as the blit wrote it before this module: per pixel and channel, a
    /// loop over the planes (the reference the fast paths are compared with).
    fn reference(planes: [&[[u8; 4]]; PLANES], i: usize) -> [u8; 4] {
        std::array::from_fn(|ch| {
            let mut sum = 0.0f32;
            for p in planes {
                sum += p[i][ch] as f32 * (1.0f32 / 255.0);
            }
            crate::fragment::span::unorm8(sum * 0.25)
        })
    }

    fn planes(n: usize, seed: u32) -> Vec<Vec<[u8; 4]>> {
        let mut r = crate::test_rng::xorshift32(seed);
        (0..PLANES)
            .map(|_| (0..n).map(|_| std::array::from_fn(|_| r() as u8)).collect())
            .collect()
    }

    #[test]
    fn every_variant_matches_the_per_pixel_resolve() {
        // Every sum of four bytes, then random pixels over more than one chunk.
        let mut p = planes(crate::tuning::RESOLVE_CHUNK * 2 + 37, 5);
        for (i, s) in (0..=1020u32).enumerate() {
            for (k, plane) in p.iter_mut().enumerate() {
                let v = (s / 4 + u32::from((k as u32) < s % 4)).min(255) as u8;
                plane[i] = [v, 255 - v, v / 2, v ^ 0x55];
            }
        }
        let refs: [&[[u8; 4]]; PLANES] = std::array::from_fn(|k| &p[k][..]);
        let want: Vec<[u8; 4]> = (0..p[0].len()).map(|i| reference(refs, i)).collect();
        let mut out = vec![[0u8; 4]; p[0].len()];
        average_rgba8(refs, &mut out);
        assert_eq!(out, want, "dispatched");
        let flat = refs.map(|p| p.as_flattened());
        let mut o = vec![0u8; out.len() * 4];
        average_scalar(flat, &mut o);
        assert_eq!(o, want.as_flattened(), "scalar");
        #[cfg(target_arch = "x86_64")]
        if std::is_x86_feature_detected!("avx2") {
            let mut o = vec![0u8; out.len() * 4];
            // SAFETY: the CPU has AVX2.
            unsafe { average_avx2(flat, &mut o) };
            assert_eq!(o, want.as_flattened(), "avx2");
        }
        // The averages are not all equal to one plane's (the test can fail).
        assert!(want.iter().zip(&p[0]).any(|(a, b)| a != b));
    }
}
