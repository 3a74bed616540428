//! Byte shuffles of pixel rows for glReadPixels: RGBA8 pixels packed as RGB bytes
//! ([`rgba_to_rgb`]), 8 pixels per AVX2 shuffle, the same bytes as the scalar loop.

/// Writes the red, green and blue bytes of each pixel of `src` into `dst` (3 bytes per
/// pixel; `dst.len() == 3 · src.len()`).
pub fn rgba_to_rgb(src: &[[u8; 4]], dst: &mut [u8]) {
    assert_eq!(dst.len(), src.len() * 3, "rgba_to_rgb: 3 bytes per pixel");
    #[cfg(target_arch = "x86_64")]
    if super::cpu::isa().avx2() {
        // SAFETY: an AVX2 variant runs only on a CPU with AVX2.
        return unsafe { rgba_to_rgb_avx2(src, dst) };
    }
    rgba_to_rgb_scalar(src, dst)
}

/// [`rgba_to_rgb`] a pixel at a time (any level, and the tails of the AVX2 loop).
pub fn rgba_to_rgb_scalar(src: &[[u8; 4]], dst: &mut [u8]) {
    for (o, p) in dst.chunks_exact_mut(3).zip(src) {
        o.copy_from_slice(&p[..3]);
    }
}

/// [`rgba_to_rgb`] 8 pixels at a time: `vpshufb` packs each 128-bit lane's 4 pixels
/// into its low 12 bytes, `vpermd` joins the two lanes' 24 bytes, and a 32-byte store
/// writes them (its last 8 bytes are rewritten by the next step or the scalar tail, and
/// it runs only while 32 bytes fit in `dst`).
///
/// # Safety
/// The CPU has AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn rgba_to_rgb_avx2(src: &[[u8; 4]], dst: &mut [u8]) {
    use std::arch::x86_64::*;
    let n = src.len().min(dst.len() / 3);
    let mut i = 0;
    // SAFETY: register-only intrinsics; the CPU has AVX2 (the caller's promise).
    let (shuf, perm) = unsafe {
        let lane = [0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, -1, -1, -1, -1i8];
        (
            _mm256_loadu_si256([lane, lane].as_ptr().cast()),
            _mm256_setr_epi32(0, 1, 2, 4, 5, 6, 7, 7),
        )
    };
    while i + 8 <= n && i * 3 + 32 <= dst.len() {
        // SAFETY: pixels i..i + 8 are inside `src` (32 bytes) and bytes
        // 3i..3i + 32 inside `dst`; unaligned loads and stores; AVX2 as above.
        unsafe {
            let v = _mm256_loadu_si256(src.as_ptr().add(i).cast());
            let p = _mm256_permutevar8x32_epi32(_mm256_shuffle_epi8(v, shuf), perm);
            _mm256_storeu_si256(dst.as_mut_ptr().add(i * 3).cast(), p);
        }
        i += 8;
    }
    rgba_to_rgb_scalar(&src[i..], &mut dst[i * 3..]);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_variant_packs_as_the_scalar_loop() {
        let mut r = crate::test_rng::xorshift32(9);
        let src: Vec<[u8; 4]> = (0..300).map(|_| r().to_le_bytes()).collect();
        for n in (0..40).chain([299, 300]) {
            let s = &src[..n];
            // independent of the code: each pixel's first three bytes in order
            let want: Vec<u8> = s.iter().flat_map(|p| [p[0], p[1], p[2]]).collect();
            let mut out = vec![0xAB; n * 3];
            rgba_to_rgb(s, &mut out);
            assert_eq!(out, want, "dispatched, {n} pixels");
            let mut out = vec![0xAB; n * 3];
            rgba_to_rgb_scalar(s, &mut out);
            assert_eq!(out, want, "scalar, {n} pixels");
            #[cfg(target_arch = "x86_64")]
            if std::is_x86_feature_detected!("avx2") {
                let mut out = vec![0xAB; n * 3];
                // SAFETY: the CPU has AVX2.
                unsafe { rgba_to_rgb_avx2(s, &mut out) };
                assert_eq!(out, want, "avx2, {n} pixels");
            }
        }
    }
}
