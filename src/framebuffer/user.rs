//! The copy of the colour buffer into the user's OSMesa buffer (glFlush/glFinish): the
//! 8-bit layouts, and the 16-bit and float layouts of GL_UNSIGNED_SHORT and GL_FLOAT
//! buffers, which are read from the wide colour plane at full precision
//! ([`super::wide`]).

use super::{fill_color_bytes, ColorFormat, Framebuffer};

impl Framebuffer {
    /// Copies the whole buffer into the user's memory (bottom-up when `y_up`).
    ///
    /// # Safety
    /// `dst` must be valid for writes of `stride * (height - 1) + width * bpp` bytes.
    pub unsafe fn copy_to_user(&self, dst: *mut u8, stride: usize, y_up: bool) {
        // Memory-bound: measured slower split over two threads (1024² clear + copy 0.686 ms
        // against 0.576 ms on one), so it stays on the calling thread.
        for row in 0..self.height {
            // SAFETY: forwarded from the caller.
            unsafe { self.copy_row(row, dst, stride, y_up) }
        }
        #[cfg(target_arch = "x86_64")]
        if self.streamed() {
            // Orders the streaming stores before whatever the program does next.
            crate::simd::store_fence();
        }
    }

    /// Whether [`Framebuffer::copy_to_user`] copies RGBA rows with streaming stores.
    pub(super) fn streamed(&self) -> bool {
        self.format == ColorFormat::Rgba && self.color.len() * 4 > STREAM_COPY_BYTES
    }

    /// Copies colour row `row` into the user buffer (see [`Framebuffer::copy_to_user`]).
    ///
    /// # Safety
    /// As [`Framebuffer::copy_to_user`].
    unsafe fn copy_row(&self, row: usize, dst: *mut u8, stride: usize, y_up: bool) {
        let bpp = self.format.bytes_per_pixel();
        let w = self.width;
        let dst_row = if y_up { self.height - 1 - row } else { row };
        // Every pixel holds `uniform_color`, or this row still holds the recorded clear (no
        // draw reached it): write the colour's user form without reading the buffer back.
        let fill = self.uniform_color.or(match self.pending_color {
            Some(c) if self.row_pending(row) => Some(c),
            _ => None,
        });
        if let Some(c) = fill {
            let px = self.format.user_bytes(c);
            // SAFETY: as below, `out` is row `dst_row`'s first `width * bpp` bytes.
            let out = unsafe { std::slice::from_raw_parts_mut(dst.add(dst_row * stride), w * bpp) };
            if bpp == 4 {
                fill_color_bytes(out, [px[0], px[1], px[2], px[3]]);
            } else {
                for o in out.chunks_exact_mut(bpp) {
                    o.copy_from_slice(&px[..bpp]);
                }
            }
            return;
        }
        {
            let src = &self.color[row * w..(row + 1) * w];
            // SAFETY: the caller guarantees `height` rows of `stride` bytes, each holding at
            // least `width * bpp` bytes; `out` is exactly that row's first `width * bpp` bytes.
            let out = unsafe { std::slice::from_raw_parts_mut(dst.add(dst_row * stride), w * bpp) };
            match self.format {
                ColorFormat::Rgba if self.streamed() => stream_copy(out, src.as_flattened()),
                ColorFormat::Rgba => out.copy_from_slice(src.as_flattened()),
                ColorFormat::Bgra => {
                    for (o, c) in out.chunks_exact_mut(4).zip(src) {
                        let v = u32::from_le_bytes(*c);
                        let v = (v & 0xFF00_FF00) | ((v >> 16) & 0xFF) | ((v & 0xFF) << 16);
                        o.copy_from_slice(&v.to_le_bytes());
                    }
                }
                ColorFormat::Argb => {
                    for (o, c) in out.chunks_exact_mut(4).zip(src) {
                        let v = u32::from_le_bytes(*c).rotate_left(8);
                        o.copy_from_slice(&v.to_le_bytes());
                    }
                }
                ColorFormat::Rgb => {
                    for (o, c) in out.chunks_exact_mut(3).zip(src) {
                        o.copy_from_slice(&c[..3]);
                    }
                }
                ColorFormat::Rgb565 => {
                    for (o, c) in out.chunks_exact_mut(2).zip(src) {
                        let v = ((c[0] as u16 >> 3) << 11)
                            | ((c[1] as u16 >> 2) << 5)
                            | (c[2] as u16 >> 3);
                        o.copy_from_slice(&v.to_ne_bytes());
                    }
                }
            }
        }
    }
}

/// A user buffer wider than 8 bits per channel (OSMesaMakeCurrent's GL_UNSIGNED_SHORT and
/// GL_FLOAT types). Mesa stores these as R16G16B16A16_UNORM / R32G32B32A32_FLOAT (or the
/// RGB forms) whatever the OSMESA_RGBA/BGRA/ARGB order; softgl renders them into a wide
/// colour plane of that precision ([`super::wide`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WideType {
    /// GL_UNSIGNED_SHORT: native-endian u16 channels.
    U16,
    /// GL_FLOAT: native-endian f32 channels.
    F32,
}

impl WideType {
    /// The precision Mesa renders a buffer of this type in.
    pub fn kind(self) -> super::WideKind {
        match self {
            WideType::U16 => super::WideKind::Unorm16,
            WideType::F32 => super::WideKind::Float32,
        }
    }

    /// Bytes per channel.
    pub fn bytes(self) -> usize {
        match self {
            WideType::U16 => 2,
            WideType::F32 => 4,
        }
    }
}

impl Framebuffer {
    /// Copies the whole buffer into a user buffer of `ty` channels, in R, G, B(, A) order
    /// (4 channels for Rgba, 3 for Rgb), bottom-up when `y_up`.
    ///
    /// # Safety
    /// `dst` must be valid for writes of `stride * (height - 1) + width * channels * bytes`.
    pub unsafe fn copy_to_user_wide(&self, dst: *mut u8, stride: usize, y_up: bool, ty: WideType) {
        let n = if self.format == ColorFormat::Rgb {
            3
        } else {
            4
        };
        let px_bytes = n * ty.bytes();
        let w = self.width;
        let Some(kind) = self.wide else {
            // SAFETY: forwarded from the caller.
            return unsafe { self.copy_widened(dst, stride, y_up, ty) };
        };
        for row in 0..self.height {
            let dst_row = if y_up { self.height - 1 - row } else { row };
            // SAFETY: the caller guarantees `height` rows of `stride` bytes, each holding at
            // least `width * px_bytes` bytes; `out` is that row's first `width * px_bytes`.
            let out =
                unsafe { std::slice::from_raw_parts_mut(dst.add(dst_row * stride), w * px_bytes) };
            let r = row * w..(row + 1) * w;
            let src = WideRow {
                kind,
                wide: &self.wide_color[r.clone()],
                color: &self.color[r],
                pending: self.pending_color_row(row),
            };
            src.copy(ty, n, out);
        }
    }

    /// [`Framebuffer::copy_to_user_wide`] of a buffer without a wide plane: its 8-bit
    /// colour widened (`v * 257`, `v / 255`).
    ///
    /// # Safety
    /// As [`Framebuffer::copy_to_user_wide`].
    unsafe fn copy_widened(&self, dst: *mut u8, stride: usize, y_up: bool, ty: WideType) {
        let n = if self.format == ColorFormat::Rgb {
            3
        } else {
            4
        };
        let px_bytes = n * ty.bytes();
        let w = self.width;
        for row in 0..self.height {
            let dst_row = if y_up { self.height - 1 - row } else { row };
            // SAFETY: as in `copy_to_user_wide`.
            let out =
                unsafe { std::slice::from_raw_parts_mut(dst.add(dst_row * stride), w * px_bytes) };
            for (x, o) in out.chunks_exact_mut(px_bytes).enumerate() {
                let c = self.color_at(row * w + x);
                for (oc, v) in o.chunks_exact_mut(ty.bytes()).zip(c) {
                    match ty {
                        WideType::U16 => oc.copy_from_slice(&(v as u16 * 257).to_ne_bytes()),
                        WideType::F32 => oc.copy_from_slice(&(v as f32 / 255.0).to_ne_bytes()),
                    }
                }
            }
        }
    }
}

/// Colour buffers above this many bytes are copied to the user with non-temporal stores:
/// the copy is larger than a core's L2 cache, so its lines would be evicted before anyone
/// reads them, and streaming them saves reading each destination line first.
const STREAM_COPY_BYTES: usize = 2 << 20;

/// Copies `src` into `out` (the same length) with non-temporal 16-byte stores where `out`
/// is aligned (the caller issues the store fence once the whole copy is done).
pub(super) fn stream_copy(out: &mut [u8], src: &[u8]) {
    crate::simd::stream_copy(out, src);
}

/// One row of a wide buffer as [`Framebuffer::copy_to_user_wide`] reads it: the wide
/// plane's values where their 8-bit mirror is current, else the 8-bit value widened
/// ([`Framebuffer::wide_at`]).
struct WideRow<'a> {
    kind: super::WideKind,
    wide: &'a [[f32; 4]],
    color: &'a [[u8; 4]],
    /// The recorded clear the row's 8-bit pixels hold instead of `color`.
    pending: Option<[u8; 4]>,
}

impl WideRow<'_> {
    /// Writes the row's first `n` channels of each pixel as `ty` into `out`, compiled for
    /// AVX2 where the CPU has it (the per-pixel mirror check vectorises there).
    fn copy(&self, ty: WideType, n: usize, out: &mut [u8]) {
        #[cfg(target_arch = "x86_64")]
        if crate::simd::cpu::isa().avx2() {
            // SAFETY: the AVX2 copy runs only on a CPU with AVX2.
            return unsafe { self.copy_avx2(ty, n, out) };
        }
        self.copy_body(ty, n, out)
    }

    /// [`WideRow::copy_body`] compiled for AVX2, four RGBA pixels at a time on 8 lanes
    /// (two pixels a register) for the layouts of OSMesa's own wide buffers: u16 from a
    /// 16-bit plane, f32 from a float plane. The lane operations are the scalar ones: the
    /// mirror test is [`WideKind::mirror8_lanes`]; `as u16` is `vcvttps2dq` of
    /// `min(65535, v)` (NaN stays NaN and packs to 0, as do negatives).
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn copy_avx2(&self, ty: WideType, n: usize, out: &mut [u8]) {
        use super::WideKind;
        use crate::simd::{F32x8, I32x8};
        let k = self.kind;
        let u16_out = match (ty, k) {
            (WideType::U16, WideKind::Unorm16) => true,
            (WideType::F32, WideKind::Float16 | WideKind::Float32) => false,
            _ => return self.copy_body(ty, n, out),
        };
        if n != 4 {
            return self.copy_body(ty, n, out);
        }
        let px = 4 * ty.bytes();
        let len = self.wide.len().min(self.color.len()).min(out.len() / px);
        let quads = len / 4;
        // SAFETY: (whole block) AVX2 as the caller vouches; every load reads pixels
        // `x..x + 4` of `wide` and `color` and every store bytes `x * px..(x + 4) * px` of
        // `out`, all inside their slices for `x + 4 <= len`.
        unsafe {
            let max16 = F32x8::splat(65535.0);
            let pending = self.pending.map(|c| {
                let b = [c[0], c[1], c[2], c[3], c[0], c[1], c[2], c[3]];
                I32x8::from_u8(b)
            });
            // Pixels `x`, `x + 1` as the wide plane stores them, or widened where their
            // mirror is stale.
            let pair = |x: usize| {
                let w = F32x8::load(self.wide.as_ptr().add(x) as *const f32);
                let c = match pending {
                    Some(c) => c,
                    None => {
                        let p = self.color.as_ptr().add(x) as *const [u8; 8];
                        I32x8::from_u8(p.read_unaligned())
                    }
                };
                let e = k.mirror8_lanes(w).cmpeq(c).as_f32();
                let e = e.and(e.permute::<0xB1>());
                let e = e.and(e.permute::<0x4E>());
                k.from_u8_lanes(c).blendv(w, e)
            };
            for q in 0..quads {
                let x = 4 * q;
                let (a, b) = (pair(x), pair(x + 2));
                let o = out.as_mut_ptr().add(x * px);
                if u16_out {
                    let ia = max16.min(a).to_i32_trunc();
                    let ib = max16.min(b).to_i32_trunc();
                    // Pixels (0, 2 | 1, 3) in 64-bit lanes, put in order.
                    ia.pack_u16(ib).permute_q::<0xD8>().store(o);
                } else {
                    a.store(o as *mut f32);
                    b.store(o.add(32) as *mut f32);
                }
            }
        }
        let done = quads * 4;
        let rest = WideRow {
            kind: k,
            wide: &self.wide[done..],
            color: &self.color[done.min(self.color.len())..],
            pending: self.pending,
        };
        let from = (done * px).min(out.len());
        rest.copy_body(ty, n, &mut out[from..]);
    }

    /// [`WideRow::copy`], one loop per output layout.
    #[inline(always)]
    fn copy_body(&self, ty: WideType, n: usize, out: &mut [u8]) {
        let k = self.kind;
        match (ty, n) {
            (WideType::U16, 4) => self.convert::<4, 2>(out, |v| k.to_u16(v).to_ne_bytes()),
            (WideType::U16, _) => self.convert::<3, 2>(out, |v| k.to_u16(v).to_ne_bytes()),
            (WideType::F32, 4) => self.convert::<4, 4>(out, |v| k.to_float(v).to_ne_bytes()),
            (WideType::F32, _) => self.convert::<3, 4>(out, |v| k.to_float(v).to_ne_bytes()),
        }
    }

    /// Writes channels `0..N` of each pixel, each as the `B` bytes `f` makes of it.
    #[inline(always)]
    fn convert<const N: usize, const B: usize>(&self, out: &mut [u8], f: impl Fn(f32) -> [u8; B]) {
        let k = self.kind;
        let pixels = out.chunks_exact_mut(N * B).zip(self.wide).zip(self.color);
        for ((o, &w), &c) in pixels {
            let c8 = self.pending.unwrap_or(c);
            let v = if k.mirror(w) == c8 { w } else { k.from_u8(c8) };
            for (oc, x) in o.chunks_exact_mut(B).zip(v) {
                oc.copy_from_slice(&f(x));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{WideRow, WideType};
    use crate::framebuffer::WideKind;

    /// The AVX2 copy writes the scalar copy's bytes: stored values of every kind of
    /// bits (NaN, infinities, negatives, out of range), mirrors current and stale, rows
    /// with a recorded clear, and widths that leave a tail.
    #[test]
    fn avx2_copy_matches_the_scalar_copy() {
        #[cfg(target_arch = "x86_64")]
        {
            if !crate::simd::cpu::isa().avx2() {
                return;
            }
            let mut rng = crate::test_rng::xorshift32(7);
            let specials = [
                f32::NAN,
                f32::INFINITY,
                -1.0,
                70000.0,
                0.5,
                65535.0,
                1.0,
                -0.0,
            ];
            for case in 0..200 {
                let kind = [WideKind::Unorm16, WideKind::Float16, WideKind::Float32][case % 3];
                let ty = if kind == WideKind::Unorm16 {
                    WideType::U16
                } else {
                    WideType::F32
                };
                let n = 13 + case % 7;
                let mut wide = Vec::new();
                let mut color = Vec::new();
                for _ in 0..n {
                    let mut p = [0.0f32; 4];
                    for c in &mut p {
                        *c = match rng() % 4 {
                            0 => specials[rng() as usize % specials.len()],
                            1 => f32::from_bits(rng()),
                            2 => (rng() % 65536) as f32,
                            _ => (rng() % 1000) as f32 / 999.0,
                        };
                    }
                    let m = kind.mirror(p);
                    let c = if rng().is_multiple_of(3) {
                        rng().to_ne_bytes()
                    } else {
                        m
                    };
                    wide.push(p);
                    color.push(c);
                }
                let pending = case.is_multiple_of(5).then(|| color[0]);
                let row = WideRow {
                    kind,
                    wide: &wide,
                    color: &color,
                    pending,
                };
                let bytes = n * 4 * ty.bytes();
                let (mut a, mut b) = (vec![0u8; bytes], vec![1u8; bytes]);
                row.copy_body(ty, 4, &mut a);
                // SAFETY: the running level has AVX2 (checked above).
                unsafe { row.copy_avx2(ty, 4, &mut b) };
                assert_eq!(a, b, "case {case}: {kind:?} {ty:?}, {n} pixels");
            }
        }
    }
}
