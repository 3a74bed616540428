//! Unit tests of `framebuffer.rs`.

use super::*;

#[test]
fn ubyte_rounds_half_to_even() {
    // f32(c*255) = k + 0.5 exactly: 0.5 -> 0, 1.5 -> 2, 2.5 -> 2.
    assert_eq!(float_to_ubyte(0.5 / 255.0), 0);
    assert_eq!(float_to_ubyte(1.5 / 255.0), 2);
    assert_eq!(float_to_ubyte(2.5 / 255.0), 2);
    assert_eq!(float_to_ubyte(f32::NAN), 0);
    assert_eq!(float_to_ubyte(2.0), 255);
}

#[test]
fn z16_is_round_of_z_times_65535() {
    for z in [0.0f32, 1.0, 0.5, 0.25, 0.123_456] {
        let q = DepthFormat::Z16.quantize(z);
        assert!(
            (q as f64 - z as f64 * 65535.0).abs() <= 0.5 + 1e-3,
            "{z} {q}"
        );
    }
    assert_eq!(DepthFormat::Z24.quantize(1.0), 0xFF_FFFF);
}

/// Z32_UNORM values llvmpipe wrote and cleared (read back as GL_UNSIGNED_INT from Mesa
/// 22.3.6 OSMesa: docs/fbo-rules.md §7.2, scene `fbo_depth32`).
#[test]
fn z32_matches_llvmpipe() {
    let z32 = DepthFormat::Z32;
    assert_eq!(z32.quantize(1.0), 0xFFFF_FFFF);
    assert_eq!(z32.quantize(0.0), 0);
    assert_eq!(z32.quantize(0.244_833_11), 0x3EAD_6200);
    // the scissored clear's quad: f32(f32(2d - 1)·0.5 + 0.5) for d = 1/3
    let z = (2.0 / 3.0f64 - 1.0) as f32;
    assert_eq!(z32.quantize(z * 0.5 + 0.5), 0x5555_5500);
    assert_eq!(z32.quantize_clear(1.0 / 3.0), 0x5555_5555);
    assert_eq!(z32.quantize_clear(0.999_999_99), 0xFFFF_FFD4);
    assert_eq!(z32.quantize_clear(2.5e-10), 1);
    assert_eq!(z32.quantize_clear(1.0), 0xFFFF_FFFF);
}

/// A uniform buffer copied through the fill shortcut gives the bytes of the copy.
#[test]
fn uniform_copy_matches_copy() {
    for format in [
        ColorFormat::Rgba,
        ColorFormat::Bgra,
        ColorFormat::Argb,
        ColorFormat::Rgb,
        ColorFormat::Rgb565,
    ] {
        let (w, h) = (5usize, 3usize);
        let mut fb = Framebuffer::new(w, h, format, DepthFormat::Z24, false);
        let v = fb.clear_value([0.2, 0.4, 0.6, 0.8]);
        fb.clear_rows(0..h, Some(v), Some(7));
        assert!(fb.depth.iter().all(|&d| d == 7));
        let stride = w * format.bytes_per_pixel() + 3;
        let mut copied = vec![0xAAu8; stride * h + 1];
        let mut filled = copied.clone();
        // SAFETY: both buffers hold `h` rows of `stride` bytes.
        unsafe { fb.copy_to_user(copied.as_mut_ptr().add(1), stride, true) };
        fb.uniform_color = Some(v);
        // SAFETY: as above.
        unsafe { fb.copy_to_user(filled.as_mut_ptr().add(1), stride, true) };
        assert_eq!(copied, filled, "{format:?}");
        assert!(fb.target().color.iter().all(|&c| c == v));
        assert_eq!(fb.uniform_color, None, "a target may write colour");
    }
}

/// A recorded clear reads back as the clear values everywhere, is written by
/// `target`, and is shared with the bands of `bands`, each writing only its rows; rows
/// no band wrote stay pending through the draw and are copied as the clear colour.
#[test]
fn deferred_clear_reads_and_resolves() {
    let (w, h) = (7usize, 9usize);
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba, DepthFormat::Z24, false);
    fb.defer_clear(Some([1, 2, 3, 4]), Some(77));
    assert!(
        fb.color.iter().all(|&c| c == [0, 0, 0, 0]),
        "not written yet"
    );
    assert!((0..w * h).all(|i| fb.color_at(i) == [1, 2, 3, 4] && fb.depth_at(i) == 77));
    let mut out = vec![0u8; w * h * 4];
    // SAFETY: `out` holds `h` rows of `w * 4` bytes.
    unsafe { fb.copy_to_user(out.as_mut_ptr(), w * 4, true) };
    assert!(out.chunks(4).all(|p| p == [1, 2, 3, 4]));
    {
        let mut bands = fb.bands(4);
        assert_eq!(fb_pending(&bands[0]), (Some([1, 2, 3, 4]), Some(77)));
        bands[1].resolve();
        // A draw into band 1 (rows 4..8).
        bands[1].color.fill([9, 9, 9, 9]);
        bands[1].depth.fill(5);
    }
    // Only band 1 was written; the other rows are still pending.
    assert_eq!(
        (fb.pending_color, fb.pending_depth),
        (Some([1, 2, 3, 4]), Some(77))
    );
    assert!((0..h).all(|y| fb.pending_rows[y] != (4..8).contains(&y)));
    assert!((0..w * h).all(|i| (fb.color[i] == [9; 4]) == (4 * w..8 * w).contains(&i)));
    for i in 0..w * h {
        let drawn = (4 * w..8 * w).contains(&i);
        assert_eq!(fb.color_at(i), if drawn { [9; 4] } else { [1, 2, 3, 4] });
        assert_eq!(fb.depth_at(i), if drawn { 5 } else { 77 });
    }
    // The copy: drawn rows from memory, pending rows as the clear colour (bottom-up).
    // SAFETY: as above.
    unsafe { fb.copy_to_user(out.as_mut_ptr(), w * 4, true) };
    for (y, row) in out.chunks(w * 4).enumerate() {
        let drawn = (4..8).contains(&(h - 1 - y));
        let want = if drawn { [9; 4] } else { [1, 2, 3, 4] };
        assert!(row.chunks(4).all(|p| p == want), "user row {y}");
    }
    // A depth-only clear while colour is partly pending: colour keeps its values.
    fb.defer_clear(None, Some(5));
    assert!((0..w * h).all(|i| fb.depth_at(i) == 5));
    let t = fb.target();
    assert!(t.depth.iter().all(|&d| d == 5));
    assert!(t
        .color
        .chunks(w)
        .enumerate()
        .all(|(y, r)| r.iter().all(|&c| c
            == if (4..8).contains(&y) {
                [9; 4]
            } else {
                [1, 2, 3, 4]
            })));
}

/// A second clear of both buffers after a partial draw makes every row pending again.
#[test]
fn full_clear_after_partial_draw_is_pending_everywhere() {
    let (w, h) = (4usize, 8usize);
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba, DepthFormat::Z24, false);
    fb.defer_clear(Some([1, 1, 1, 1]), Some(1));
    {
        let mut bands = fb.bands(2);
        bands[0].resolve();
        bands[0].color.fill([7; 4]);
    }
    fb.defer_clear(Some([2, 2, 2, 2]), None);
    // Depth was pending in rows 2.. and is still 1 everywhere; colour is 2 everywhere.
    assert!((0..w * h).all(|i| fb.color_at(i) == [2; 4] && fb.depth_at(i) == 1));
    fb.resolve();
    assert!(fb.color.iter().all(|&c| c == [2; 4]) && fb.depth.iter().all(|&d| d == 1));
    assert!(fb.pending_rows.iter().all(|&p| !p));
}

/// A colour buffer above `STREAM_COPY_BYTES` is copied with streaming stores, at any
/// destination alignment, to the same bytes as a plain copy.
#[test]
fn streamed_copy_matches_plain_copy() {
    for n in [0usize, 1, 15, 16, 17, 100, 4096 + 7] {
        let src: Vec<u8> = (0..n).map(|i| (i * 7 + 3) as u8).collect();
        for off in 0..16 {
            let mut out = vec![0u8; n + 16];
            stream_copy(&mut out[off..off + n], &src);
            assert_eq!(&out[off..off + n], &src[..], "n {n} off {off}");
            assert!(out[..off].iter().chain(&out[off + n..]).all(|&b| b == 0));
        }
    }
    let (w, h) = (1024usize, 600usize);
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba, DepthFormat::None, false);
    assert!(fb.streamed());
    for (i, c) in fb.color.iter_mut().enumerate() {
        *c = (i as u32).wrapping_mul(2_654_435_761).to_le_bytes();
    }
    let stride = w * 4 + 5;
    let mut out = vec![0u8; stride * h + 1];
    // SAFETY: `out` holds `h` rows of `stride` bytes after its first byte.
    unsafe { fb.copy_to_user(out.as_mut_ptr().add(1), stride, true) };
    for y in 0..h {
        let row = &out[1 + (h - 1 - y) * stride..][..w * 4];
        assert_eq!(row, fb.color[y * w..(y + 1) * w].as_flattened(), "row {y}");
    }
}

/// `target_rows` writes the recorded clears of its rows only.
#[test]
fn target_rows_resolves_only_its_rows() {
    let (w, h) = (3usize, 6usize);
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba, DepthFormat::Z24, false);
    fb.defer_clear(Some([4, 3, 2, 1]), Some(9));
    let t = fb.target_rows(2..4);
    assert!(t.pending_rows.is_empty() && t.pending_color.is_none());
    let written = |i: usize| (2 * w..4 * w).contains(&i);
    assert!((0..w * h).all(|i| (fb.color[i] == [4, 3, 2, 1]) == written(i)));
    assert!((0..w * h).all(|i| (fb.depth[i] == 9) == written(i)));
    assert!((0..h).all(|y| fb.pending_rows[y] != (2..4).contains(&y)));
    assert!((0..w * h).all(|i| fb.color_at(i) == [4, 3, 2, 1] && fb.depth_at(i) == 9));
    assert_eq!(fb.uniform_color, None, "a target may write colour");
}

fn fb_pending(t: &Target<'_>) -> (Option<[u8; 4]>, Option<u32>) {
    (t.pending_color, t.pending_depth)
}

#[test]
fn rgb565_store_truncates_and_replicates() {
    let fb = Framebuffer::new(1, 1, ColorFormat::Rgb565, DepthFormat::None, false);
    assert_eq!(fb.store_rgba8([8 * 3 + 7, 255, 0, 9]), [24, 255, 0, 255]);
}
