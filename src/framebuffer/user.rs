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
            for (x, o) in out.chunks_exact_mut(px_bytes).enumerate() {
                let c = self.wide_at(row * w + x);
                for (oc, v) in o.chunks_exact_mut(ty.bytes()).zip(c) {
                    match ty {
                        WideType::U16 => oc.copy_from_slice(&kind.to_u16(v).to_ne_bytes()),
                        WideType::F32 => oc.copy_from_slice(&kind.to_float(v).to_ne_bytes()),
                    }
                }
            }
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
