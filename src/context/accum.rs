//! The accumulation buffer (glAccum, glClearAccum, GL_ACCUM_BUFFER_BIT of glClear) with
//! Mesa's software arithmetic (`main/accum.c`): the buffer is R16G16B16A16_SNORM (16 bits
//! per channel, whatever accumBits asked for), values are `i16` steps of 1/32767, and every
//! conversion truncates toward zero:
//!
//! - clear: `((i32)(65535 * c) - 1) / 2` (C integer division), the colour clamped to [-1,1];
//! - LOAD / ACCUM: `(i16)(colour * (value * 32767))` with the colour unpacked from 8 bits as
//!   `v * (1/255)`; ACCUM adds with 16-bit wrap-around;
//! - ADD: `acc += (i16)(value * 32767)`; MULT: `acc = (i16)(acc * value)`;
//! - RETURN: `acc * (value / 32767)` packed like a clear colour (clamp, round half even),
//!   channels off in glColorMask keep the colour buffer's value.
//!
//! Every operation covers the drawable rectangle (the buffer clipped to the scissor box).
//!
//! Wide colour buffers (16-bit and float) are unpacked and packed with their format's
//! helpers instead (see [`accum_wide`]).

use super::{Context, GlError, GlResult};

/// glAccum's operation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AccumOp {
    /// GL_ACCUM: acc += colour · value.
    Accum,
    /// GL_LOAD: acc = colour · value.
    Load,
    /// GL_RETURN: colour = acc · value.
    Return,
    /// GL_MULT: acc *= value.
    Mult,
    /// GL_ADD: acc += value.
    Add,
}

/// The GL_ACCUM_BUFFER_BIT attribute group (for glPushAttrib).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct AccumAttrib {
    /// GL_ACCUM_CLEAR_VALUE, clamped to [-1, 1].
    pub clear_color: [f32; 4],
}

/// The accumulation state of a context.
#[derive(Clone, Debug, Default)]
pub struct AccumState {
    /// The GL_ACCUM_BUFFER_BIT group.
    pub attrib: AccumAttrib,
    /// The buffer, y-down rows like the colour buffer (allocated at first use, zeroed as
    /// llvmpipe allocates it; a new framebuffer size gives a new buffer).
    pub buffer: Vec<[i16; 4]>,
    /// The size `buffer` was made for.
    pub size: (usize, usize),
}

/// Mesa's FLOAT_TO_SHORT.
fn float_to_short(c: f32) -> i16 {
    (((65535.0f32 * c) as i32 - 1) / 2) as i16
}

impl Context {
    /// Whether the context has an accumulation buffer (OSMesaCreateContextExt accumBits).
    pub fn has_accum(&self) -> bool {
        self.visual.accum_bits > 0
    }

    /// glClearAccum.
    pub fn clear_accum(&mut self, c: [f32; 4]) -> GlResult<()> {
        self.accum.attrib.clear_color = c.map(|v| v.clamp(-1.0, 1.0));
        Ok(())
    }

    /// The accumulation buffer sized to the framebuffer, and the drawable rectangle.
    fn accum_target(&mut self) -> Option<[usize; 4]> {
        let fb = self.fb.as_ref()?;
        let size = (fb.width, fb.height);
        let region = self.draw_region()?.map(|v| v as usize);
        let a = &mut self.accum;
        if a.size != size || a.buffer.len() != size.0 * size.1 {
            a.buffer = vec![[0; 4]; size.0 * size.1];
            a.size = size;
        }
        Some(region)
    }

    /// The GL_ACCUM_BUFFER_BIT part of glClear (no error without a buffer).
    pub fn clear_accum_buffer(&mut self) {
        if !self.has_accum() {
            return;
        }
        let Some([x0, y0, x1, y1]) = self.accum_target() else {
            return;
        };
        let v = self.accum.attrib.clear_color.map(float_to_short);
        let w = self.accum.size.0;
        for y in y0..y1 {
            self.accum.buffer[y * w + x0..y * w + x1].fill(v);
        }
    }

    /// glAccum.
    pub fn accum(&mut self, op: AccumOp, value: f32) -> GlResult<()> {
        if !self.has_accum() {
            return Err(GlError::InvalidOperation);
        }
        // Mesa skips the no-op cases.
        let noop = match op {
            AccumOp::Add | AccumOp::Accum => value == 0.0,
            AccumOp::Mult => value == 1.0,
            _ => false,
        };
        if noop {
            return Ok(());
        }
        let Some([x0, y0, x1, y1]) = self.accum_target() else {
            return Ok(());
        };
        let w = self.accum.size.0;
        let mask = self.state.color_write_mask();
        let (Some(fb), acc) = (self.fb.as_mut(), &mut self.accum.buffer) else {
            return Ok(());
        };
        fb.resolve();
        fb.uniform_color = None;
        if fb.wide.is_some() && matches!(op, AccumOp::Load | AccumOp::Accum | AccumOp::Return) {
            accum_wide(fb, acc, w, [x0, y0, x1, y1], op, value, mask);
            if op == AccumOp::Return {
                self.dirty = true;
                self.fbo.drawn = true;
            }
            return Ok(());
        }
        let rows = AccumRow::new(op, value, fb.format, mask, (x1 - x0) * (y1 - y0));
        for y in y0..y1 {
            let row = y * w + x0..y * w + x1;
            rows.run(&mut acc[row.clone()], &mut fb.color[row]);
        }
        if op == AccumOp::Return {
            self.dirty = true;
            self.fbo.drawn = true;
        }
        Ok(())
    }
}

/// One glAccum operation on the 8-bit colour buffer, applied a row at a time.
///
/// LOAD and ACCUM convert an 8-bit channel and RETURN an `i16` accumulation value, each
/// channel on its own, so those conversions are tabulated once per call (256 entries, and
/// 65,536 for a RETURN over more pixels than that) and the rows only look values up: the
/// same expressions on every possible input. The per-channel float-to-int conversions
/// had cost 12% of query_accum_feedback; they do not vectorise (`as i32` saturates).
struct AccumRow {
    op: AccumOp,
    value: f32,
    format: crate::framebuffer::ColorFormat,
    mask: [bool; 4],
    /// LOAD / ACCUM: the accumulation step of each 8-bit channel value.
    load: [i16; 256],
    /// RETURN (formats packed channel by channel): each accumulation value's channel.
    ret: Option<Vec<u8>>,
}

impl AccumRow {
    /// The operation's tables for `pixels` pixels of rows.
    fn new(
        op: AccumOp,
        value: f32,
        format: crate::framebuffer::ColorFormat,
        mask: [bool; 4],
        pixels: usize,
    ) -> AccumRow {
        let scale = value * 32767.0f32;
        let load = std::array::from_fn(|c| (c as f32 * (1.0f32 / 255.0f32) * scale) as i32 as i16);
        let per_channel = format != crate::framebuffer::ColorFormat::Rgb565;
        let ret = (op == AccumOp::Return && per_channel && pixels > 1 << 16).then(|| {
            (0..=u16::MAX)
                .map(|bits| Self::return_channel(bits as i16, value))
                .collect()
        });
        AccumRow {
            op,
            value,
            format,
            mask,
            load,
            ret,
        }
    }

    /// RETURN's packing of one channel's accumulation value (formats other than RGB565).
    #[inline(always)]
    fn return_channel(x: i16, value: f32) -> u8 {
        let scale = value / 32767.0f32;
        crate::framebuffer::clear_float_to_ubyte(super::clamp01((x as f32 * scale) as f64) as f32)
    }

    /// Applies the operation to the accumulation values `accs` and colours `colors` of
    /// one row (Mesa's `accum.c` arithmetic, see the module doc).
    fn run(&self, accs: &mut [[i16; 4]], colors: &mut [[u8; 4]]) {
        let (op, value, mask) = (self.op, self.value, self.mask);
        match op {
            AccumOp::Add => {
                let incr = (value * 32767.0f32) as i16;
                for a in accs.iter_mut().flatten() {
                    *a = a.wrapping_add(incr);
                }
            }
            AccumOp::Mult => {
                for a in accs.iter_mut().flatten() {
                    *a = (*a as f32 * value) as i32 as i16;
                }
            }
            AccumOp::Load => {
                for (a, c) in accs.iter_mut().zip(colors.iter()) {
                    *a = c.map(|c| self.load[c as usize]);
                }
            }
            AccumOp::Accum => {
                for (a, c) in accs.iter_mut().zip(colors.iter()) {
                    for k in 0..4 {
                        a[k] = a[k].wrapping_add(self.load[c[k] as usize]);
                    }
                }
            }
            AccumOp::Return => {
                let format = self.format;
                let alpha = format.has_alpha();
                for (a, c) in accs.iter().zip(colors.iter_mut()) {
                    let v = match &self.ret {
                        Some(t) => {
                            let q = a.map(|x| t[x as u16 as usize]);
                            [q[0], q[1], q[2], if alpha { q[3] } else { 255 }]
                        }
                        None => {
                            let scale = value / 32767.0f32;
                            format.pack_float(
                                a.map(|x| super::clamp01((x as f32 * scale) as f64) as f32),
                            )
                        }
                    };
                    for k in 0..4 {
                        if mask[k] {
                            c[k] = v[k];
                        }
                    }
                }
            }
        }
    }
}

/// glAccum's LOAD, ACCUM and RETURN on a wide colour buffer (16-bit or float): Mesa
/// unpacks the colour with the format's unpack (unorm16 `q·f32(1/65535)`, floats as
/// stored, unclamped) and packs RETURN's `acc·(value/32767)` with the format's pack
/// (`util_format_pack_rgba`, as the fast clear: [`crate::framebuffer::WideKind::from_clear`]).
fn accum_wide(
    fb: &mut crate::framebuffer::Framebuffer,
    acc: &mut [[i16; 4]],
    w: usize,
    [x0, y0, x1, y1]: [usize; 4],
    op: AccumOp,
    value: f32,
    mask: [bool; 4],
) {
    let Some(k) = fb.wide else { return };
    for y in y0..y1 {
        let row = y * w + x0..y * w + x1;
        for (i, a) in row.clone().zip(&mut acc[row]) {
            if op == AccumOp::Return {
                let scale = value / 32767.0f32;
                let mut v = fb.wide_at(i);
                for c in 0..4 {
                    if mask[c] {
                        v[c] = k.from_clear(a[c] as f32 * scale);
                    }
                }
                if !fb.format.has_alpha() {
                    v[3] = k.one();
                }
                fb.wide_color[i] = v;
                fb.color[i] = k.mirror(v);
                continue;
            }
            let scale = value * 32767.0f32;
            let c = fb.float_at(i);
            for ch in 0..4 {
                let v = (c[ch] * scale) as i32 as i16;
                a[ch] = if op == AccumOp::Load {
                    v
                } else {
                    a[ch].wrapping_add(v)
                };
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{AccumOp, AccumRow};
    use crate::framebuffer::ColorFormat;

    /// The tabulated conversions give what the expressions of the module doc give, for
    /// every 8-bit channel, every accumulation value and values of every kind.
    #[test]
    fn tables_match_the_direct_conversions() {
        let values = [0.25f32, 1.0, -0.7, 3.5, 1e9, -1e-3, f32::NAN, f32::INFINITY];
        for &value in &values {
            let colors: Vec<[u8; 4]> = (0..256).map(|c| [c as u8, 255 - c as u8, 7, 128]).collect();
            let start: Vec<[i16; 4]> = (0..256)
                .map(|i| [i * 97, -i * 31, i16::MAX, i16::MIN])
                .collect();
            let scale = value * 32767.0f32;
            let step = |c: u8| (c as f32 * (1.0f32 / 255.0f32) * scale) as i32 as i16;
            let mut a = start.clone();
            AccumRow::new(AccumOp::Accum, value, ColorFormat::Rgba, [true; 4], 256)
                .run(&mut a, &mut colors.clone());
            for i in 0..256 {
                let want: [i16; 4] =
                    std::array::from_fn(|k| start[i][k].wrapping_add(step(colors[i][k])));
                assert_eq!(a[i], want, "ACCUM {value} at {i}");
            }
            let accs: Vec<[i16; 4]> = (0..=u16::MAX)
                .step_by(4)
                .map(|b| [b as i16, (b + 1) as i16, (b + 2) as i16, (b + 3) as i16])
                .collect();
            for format in [ColorFormat::Rgba, ColorFormat::Rgb, ColorFormat::Bgra] {
                let mask = [true, false, true, true];
                let mut tab = vec![[9u8; 4]; accs.len()];
                let mut direct = tab.clone();
                let t = AccumRow::new(AccumOp::Return, value, format, mask, 1 << 20);
                assert!(t.ret.is_some());
                t.run(&mut accs.clone(), &mut tab);
                AccumRow::new(AccumOp::Return, value, format, mask, 1)
                    .run(&mut accs.clone(), &mut direct);
                assert_eq!(tab, direct, "RETURN {value} {format:?}");
            }
        }
    }
}
