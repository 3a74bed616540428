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
        let format = fb.format;
        for y in y0..y1 {
            let row = y * w + x0..y * w + x1;
            let accs = &mut acc[row.clone()];
            let colors = &mut fb.color[row];
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
                AccumOp::Load | AccumOp::Accum => {
                    let scale = value * 32767.0f32;
                    for (a, c) in accs.iter_mut().zip(colors.iter()) {
                        for k in 0..4 {
                            let v = (c[k] as f32 * (1.0f32 / 255.0f32) * scale) as i32 as i16;
                            a[k] = if op == AccumOp::Load {
                                v
                            } else {
                                a[k].wrapping_add(v)
                            };
                        }
                    }
                }
                AccumOp::Return => {
                    let scale = value / 32767.0f32;
                    for (a, c) in accs.iter().zip(colors.iter_mut()) {
                        let v = format.pack_float(
                            a.map(|x| super::clamp01((x as f32 * scale) as f64) as f32),
                        );
                        for k in 0..4 {
                            if mask[k] {
                                c[k] = v[k];
                            }
                        }
                    }
                }
            }
        }
        if op == AccumOp::Return {
            self.dirty = true;
            self.fbo.drawn = true;
        }
        Ok(())
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
