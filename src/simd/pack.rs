//! Shuffles of pixel rows: for glReadPixels, RGBA8 pixels packed as RGB bytes
//! ([`rgba_to_rgb`]), 8 pixels per AVX2 shuffle; for the engine's input streams, 8
//! pixels' 4 f32 channels turned channel-major ([`channels_of`]). The same bits as the
//! scalar loops.

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

/// The bits of 8 pixels' 4 channels (`src[pixel][channel]`) channel-major: channel `c`
/// of pixels 0..8 goes to `dst[at + c * stride]` (a sampled chunk row's texels into the
/// engine's input streams). Written in place, not returned: the engine's walk is not
/// compiled for AVX2, and its 16-byte copies of a returned array stalled on the 32-byte
/// stores that made it (a fifth of `Walk::row` in multitex_combine).
///
/// # Panics
/// When `dst` has no element `at + 3 * stride`.
pub fn channels_into(src: &[[f32; 4]; 8], dst: &mut [[u32; 8]], at: usize, stride: usize) {
    assert!(at + 3 * stride < dst.len(), "channels_into: out of bounds");
    #[cfg(target_arch = "x86_64")]
    if super::cpu::isa().avx2() {
        // SAFETY: an AVX2 variant runs only on a CPU with AVX2; the bounds are checked.
        return unsafe { channels_into_avx2(src, dst, at, stride) };
    }
    channels_into_scalar(src, dst, at, stride)
}

/// [`channels_into`] a value at a time.
pub fn channels_into_scalar(src: &[[f32; 4]; 8], dst: &mut [[u32; 8]], at: usize, stride: usize) {
    for c in 0..4 {
        dst[at + c * stride] = std::array::from_fn(|i| src[i][c].to_bits());
    }
}

/// [`channels_into`] as a 4x4 transposition in each 128-bit lane: `vperm2f128` pairs
/// pixel i with pixel i + 4, `vunpcklps`/`vunpckhps` interleave pixel pairs, and
/// `vshufps` gathers each channel (moves only: every bit is kept).
///
/// # Safety
/// The CPU has AVX2, and `dst` has an element `at + 3 * stride`.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn channels_into_avx2(src: &[[f32; 4]; 8], dst: &mut [[u32; 8]], at: usize, stride: usize) {
    use super::F32x8;
    // SAFETY: `src` is 32 contiguous f32, read as four 8-lane loads; each channel takes
    // one 8-lane store into an element of `dst` (in bounds: the caller's promise); the CPU
    // has AVX2 (likewise).
    unsafe {
        let p = src.as_ptr() as *const f32;
        let (a, b) = (F32x8::load(p), F32x8::load(p.add(8)));
        let (c, d) = (F32x8::load(p.add(16)), F32x8::load(p.add(24)));
        // Pixels (0, 4), (1, 5), (2, 6) and (3, 7) in the two lanes.
        let (p04, p15) = (a.perm128::<0x20>(c), a.perm128::<0x31>(c));
        let (p26, p37) = (b.perm128::<0x20>(d), b.perm128::<0x31>(d));
        // r, g of pixels 0, 1 (4, 5); b, a of them; likewise 2, 3 (6, 7).
        let (rg01, ba01) = (p04.unpack_lo(p15), p04.unpack_hi(p15));
        let (rg23, ba23) = (p26.unpack_lo(p37), p26.unpack_hi(p37));
        let rows = [
            rg01.shuffle::<0x44>(rg23),
            rg01.shuffle::<0xEE>(rg23),
            ba01.shuffle::<0x44>(ba23),
            ba01.shuffle::<0xEE>(ba23),
        ];
        let out = dst.as_mut_ptr().add(at);
        for (c, v) in rows.into_iter().enumerate() {
            v.store(out.add(c * stride) as *mut f32);
        }
    }
}

/// 8 pixels' 4 channel registers (`v[channel]`, lane = pixel) made pixel-major: two
/// pixels' RGBA per register, pixels (0, 1), (2, 3), (4, 5), (6, 7), so that the four
/// stored in turn are `[[f32; 4]; 8]`. `vunpcklps`/`vunpckhps` interleave the channel
/// pairs, `vshufps` gathers each pixel, `vperm2f128` pairs the halves (moves only: every
/// bit is kept). The inverse of [`channels_into`]'s transposition.
///
/// # Safety
/// AVX2 context (the caller is compiled with AVX2).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub unsafe fn pixels_of(v: [super::F32x8; 4]) -> [super::F32x8; 4] {
    // (the lane methods are safe: an `F32x8` proves AVX2)
    {
        // r g r g of pixels (0, 1 | 4, 5) and (2, 3 | 6, 7), b a likewise.
        let t0 = v[0].unpack_lo(v[1]);
        let t1 = v[0].unpack_hi(v[1]);
        let t2 = v[2].unpack_lo(v[3]);
        let t3 = v[2].unpack_hi(v[3]);
        // One pixel per 128-bit half: (0 | 4), (1 | 5), (2 | 6), (3 | 7).
        let u0 = t0.shuffle::<0x44>(t2);
        let u1 = t0.shuffle::<0xEE>(t2);
        let u2 = t1.shuffle::<0x44>(t3);
        let u3 = t1.shuffle::<0xEE>(t3);
        [
            u0.perm128::<0x20>(u1),
            u2.perm128::<0x20>(u3),
            u0.perm128::<0x31>(u1),
            u2.perm128::<0x31>(u3),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`pixels_of`] stores each lane's channels as that pixel's RGBA, bit for bit.
    #[test]
    fn pixels_of_is_the_transposition() {
        if !crate::simd::cpu::isa().avx2() {
            return;
        }
        #[target_feature(enable = "avx2")]
        unsafe fn run(ch: &[[f32; 8]; 4]) -> [[f32; 4]; 8] {
            let mut out = [[0f32; 4]; 8];
            // SAFETY: AVX2 (this function's feature); 8-lane loads of 8 f32 and four
            // 8-lane stores into the 32 f32 of `out`.
            unsafe {
                let v = ch.map(|c| super::super::F32x8::load(c.as_ptr()));
                let p = out.as_mut_ptr() as *mut f32;
                for (j, r) in pixels_of(v).iter().enumerate() {
                    r.store(p.add(8 * j));
                }
            }
            out
        }
        let ch: [[f32; 8]; 4] = std::array::from_fn(|c| {
            std::array::from_fn(|i| f32::from_bits(0x3f00_0000 + (c * 8 + i) as u32))
        });
        // SAFETY: AVX2 was detected above.
        let out = unsafe { run(&ch) };
        for (i, px) in out.iter().enumerate() {
            for c in 0..4 {
                assert_eq!(px[c].to_bits(), ch[c][i].to_bits(), "pixel {i} channel {c}");
            }
        }
    }

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

    #[test]
    fn channels_into_every_variant_keeps_the_bits() {
        let mut r = crate::test_rng::xorshift32(17);
        for round in 0..200 {
            // Random bits: NaNs with payloads, infinities, denormals included.
            let mut src = [[0f32; 4]; 8];
            for p in src.iter_mut() {
                for v in p.iter_mut() {
                    *v = f32::from_bits(if round % 4 == 0 {
                        0x7F80_0001 | r()
                    } else {
                        r()
                    });
                }
            }
            // independent of the code: element (c, i) is pixel i's channel c
            let mut want = [[0u32; 8]; 4];
            for (i, p) in src.iter().enumerate() {
                for (c, v) in p.iter().enumerate() {
                    want[c][i] = v.to_bits();
                }
            }
            // Into a strided buffer of 3 + 3·5 + 2 rows, its other rows a marker.
            let (at, stride) = (3, 5);
            let got = |f: &dyn Fn(&mut [[u32; 8]])| {
                let mut dst = vec![[0xDEAD_BEEFu32; 8]; at + 3 * stride + 2];
                f(&mut dst);
                for (k, row) in dst.iter().enumerate() {
                    let c = (k >= at && (k - at) % stride == 0).then(|| (k - at) / stride);
                    match c {
                        Some(c) if c < 4 => assert_eq!(*row, want[c], "row {k}"),
                        _ => assert_eq!(*row, [0xDEAD_BEEF; 8], "row {k} untouched"),
                    }
                }
            };
            got(&|d| channels_into(&src, d, at, stride));
            got(&|d| channels_into_scalar(&src, d, at, stride));
            #[cfg(target_arch = "x86_64")]
            if std::is_x86_feature_detected!("avx2") {
                // SAFETY: the CPU has AVX2; `d` has element `at + 3 * stride`.
                got(&|d| unsafe { channels_into_avx2(&src, d, at, stride) });
            }
        }
    }
}
