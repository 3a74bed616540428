//! The vertex stage over runs of consecutive vertices, for a plain stage (no lighting,
//! fog, texture coordinate generation, point attenuation or user clip planes): position,
//! clip mask and window position in SSE registers, one vertex after another in a loop
//! whose iterations do not wait for each other. It writes exactly what
//! [`VertexStage::run_into`] writes (same operations in the same order); per vertex, that
//! function's dependency chain (transform, divide, viewport) was most of its cost when it
//! ran vertex by vertex from the post-transform cache.

use super::transform::VertexStage;
use crate::geometry::source::{VertexSlot, VertexSource};
use crate::geometry::{ClipVertex, VARY_SPEC, VARY_TEX};

impl VertexStage {
    /// Whether [`VertexStage::run_block`] may run this stage: nothing beyond the position,
    /// the colours and the texture coordinates through their matrices, and a CPU with
    /// AVX2 and FMA.
    pub fn block_ok(&self) -> bool {
        self.light.is_none()
            && self.fog.is_none()
            && self.point_atten.is_none()
            && self.ucp_enabled == 0
            && self.texgen[..self.n_tex].iter().all(Option::is_none)
            && matches!(crate::cpu::isa(), crate::cpu::Isa::Avx2Fma)
    }

    /// Runs vertices `first..first + out.len()` of `verts` through the stage into `out`,
    /// reading each through `slot` ([`VertexSource::vertex_into`]): what
    /// [`VertexStage::run_into`] writes for each. The caller has checked
    /// [`VertexStage::block_ok`].
    pub fn run_block<S: VertexSource + ?Sized>(
        &self,
        verts: &S,
        first: usize,
        slot: &mut VertexSlot,
        out: &mut [ClipVertex],
    ) {
        #[cfg(target_arch = "x86_64")]
        {
            // SAFETY: `block_ok` found AVX2 and FMA on this CPU (`cpu::isa`).
            unsafe {
                if self.fma {
                    self.run_block_x86::<S, true>(verts, first, slot, out)
                } else {
                    self.run_block_x86::<S, false>(verts, first, slot, out)
                }
            }
        }
        #[cfg(not(target_arch = "x86_64"))]
        for (j, o) in out.iter_mut().enumerate() {
            verts.vertex_into(first + j, slot);
            self.run_into(&slot.v, o);
        }
    }

    /// [`VertexStage::run_block`] in SSE registers; `FMA` is `self.fma`.
    ///
    /// # Safety
    /// The CPU has AVX2 and FMA.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn run_block_x86<S: VertexSource + ?Sized, const FMA: bool>(
        &self,
        verts: &S,
        first: usize,
        slot: &mut VertexSlot,
        out: &mut [ClipVertex],
    ) {
        use crate::simd::F32x4;
        // Clip mask bits of the lanes x, y, z of `!(c <= w)` and of `!(c + w >= 0)`
        // (see `geometry::clip_mask`: bits 0, 2, 5 and 1, 3, 4; `z + 0` under halfz).
        const ABOVE: [u8; 8] = [0, 1, 4, 5, 32, 33, 36, 37];
        const BELOW: [u8; 8] = [0, 2, 8, 10, 16, 18, 24, 26];
        let m = &self.mvp.0;
        let vp = &self.viewport;
        let tex = &self.tex_units[..self.n_tex];
        // SAFETY: (whole body) AVX2/FMA context (this function's features, the caller's
        // promise); the loads and stores are of 4-float arrays.
        unsafe {
            let col = [0, 4, 8, 12].map(|c| F32x4::load(m[c..c + 4].as_ptr()));
            let scale = F32x4::new([vp.scale[0], vp.scale[1], vp.scale[2], 0.0]);
            let trans = F32x4::new([vp.translate[0], vp.translate[1], vp.translate[2], 0.0]);
            let (zero, one) = (F32x4::zero(), F32x4::splat(1.0));
            let halfz = vp.halfz;
            // w in the x and y lanes, 0 in the z lane.
            let cw_halfz = |w: F32x4| w.blend::<0b0100>(zero);
            // `clamp_color`: `max(min(v, 1), 0)`, NaN to 1 (`minps` gives its second
            // operand for NaN) and -0.0 to 0.0 (`maxps` gives its second operand for equal
            // values), the comparisons the scalar `clamp_color` makes (the test below
            // checks both).
            let clamp = |c: F32x4| c.min(one).max(zero);
            for (j, o) in out.iter_mut().enumerate() {
                verts.vertex_into(first + j, slot);
                let v = &slot.v;
                let p = F32x4::load(v.pos.as_ptr());
                // `Mat4::transform`: ((x·C0 + y·C1) + z·C2) + w·C3, each step rounded.
                let x = p.broadcast::<0x00>().mul(col[0]);
                let y = p.broadcast::<0x55>().mul(col[1]);
                let z = p.broadcast::<0xAA>().mul(col[2]);
                let w = p.broadcast::<0xFF>().mul(col[3]);
                let clip = x.add(y).add(z).add(w);
                let cw = clip.broadcast::<0xFF>();
                let above = clip.cmp_nle(cw).movemask() & 7;
                // GL_ZERO_TO_ONE's near plane tests z alone: z + 0 has z's sign, so
                // the same comparison gives `!(z >= 0)`.
                let sum = clip.add(if halfz { cw_halfz(cw) } else { cw });
                let below = sum.cmp_nge(zero).movemask() & 7;
                // `Viewport::apply_shader`: fmuladd(c · (1/w), scale, translate), 1/w last.
                let inv = one.div(cw);
                let q = clip.mul(inv);
                let win = if FMA {
                    q.mul_add(scale, trans)
                } else {
                    q.mul(scale).add(trans)
                };
                let win = win.blend::<0b1000>(inv);
                clip.store(o.clip.as_mut_ptr());
                win.store(o.win.as_mut_ptr());
                o.mask = (ABOVE[above as usize] | BELOW[below as usize]) as _;
                let c = clamp(F32x4::load(v.color.as_ptr()));
                c.store(o.vary.as_mut_ptr());
                if self.color_sum {
                    let s = clamp(F32x4::load(v.secondary.as_ptr()));
                    s.store(o.vary[VARY_SPEC..].as_mut_ptr());
                }
                for (k, (unit, tm)) in tex.iter().enumerate() {
                    let tc = v.texcoord[*unit];
                    let tc = match tm {
                        Some(tm) => tm.transform(tc),
                        None => tc,
                    };
                    o.vary[VARY_TEX + 4 * k..VARY_TEX + 4 * k + 4].copy_from_slice(&tc);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fixed_function::matrix::{Mat4, IDENTITY};
    use crate::geometry::fetch::VertexIn;
    use crate::geometry::Viewport;
    use crate::pipe::CurrentAttribs;

    /// Values that exercise the rounding, the clip tests and the colour clamp: ordinary
    /// coordinates, zeros of both signs, values at and beyond ±w, huge values, infinities
    /// and NaN.
    fn value(r: u32) -> f32 {
        const SPECIAL: [f32; 12] = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            0.5,
            1.0000001,
            -1.0000001,
            1e30,
            -1e30,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
        ];
        if r.is_multiple_of(4) {
            SPECIAL[(r / 4) as usize % SPECIAL.len()]
        } else {
            f32::from_bits((r >> 2 & 0x00ff_ffff) | 0x3e00_0000)
                * if r & 2 == 0 { 1.0 } else { -3.0 }
        }
    }

    /// Every field `run_block` writes equals what `run_into` writes, bit for bit, for
    /// random and special positions and colours, fused and not, with and without the
    /// secondary colour and texture units (one through a matrix), under both clip-control
    /// conventions, and runs that start anywhere in the source.
    #[test]
    fn run_block_writes_what_run_into_writes() {
        let vp = Viewport::new([3, -2, 333, 277], [0.25, 0.9], 300);
        // GL_ZERO_TO_ONE and GL_UPPER_LEFT: another near plane and z and y transforms.
        let cc = crate::geometry::ClipConvention {
            upper_left: true,
            zero_to_one: true,
        };
        let vp_halfz = Viewport::with_convention([3, -2, 333, 277], [0.25, 0.9], 300, true, cc);
        if !VertexStage::new(IDENTITY, IDENTITY, vp, false).block_ok() {
            return;
        }
        let mut rng = crate::test_rng::xorshift32(0x5eed_1234);
        let mut next = || value(rng());
        let cur = CurrentAttribs::default();
        let verts: Vec<VertexIn> = (0..997)
            .map(|_| {
                let mut v = VertexIn::with_current([next(), next(), next(), next()], &cur);
                v.color = [next(), next(), next(), next()];
                v.secondary = [next(), next(), next(), next()];
                v.texcoord[0] = [next(), next(), next(), next()];
                v.texcoord[2] = [next(), next(), next(), next()];
                v
            })
            .collect();
        let mut rng2 = crate::test_rng::xorshift32(0xabcd_0123);
        let mut mat = || {
            let mut m = [0f32; 16];
            for (i, e) in m.iter_mut().enumerate() {
                let r = rng2();
                *e = if r.is_multiple_of(3) {
                    (i % 5 == 0) as u32 as f32
                } else {
                    f32::from_bits((r >> 2 & 0x007f_ffff) | 0x3f00_0000) - 1.0
                };
            }
            Mat4(m)
        };
        for case in 0..16 {
            let fma = case & 1 == 1;
            let vp = if case & 8 == 8 { vp_halfz } else { vp };
            let mut stage = VertexStage::new(mat(), mat(), vp, fma);
            stage.color_sum = case & 2 == 2;
            if case & 4 == 4 {
                stage.add_texture_unit(0, &IDENTITY);
                stage.add_texture_unit(2, &mat());
            }
            assert!(stage.block_ok());
            let mut slot = verts.new_slot();
            let mut want = vec![ClipVertex::default(); verts.len()];
            for (i, o) in want.iter_mut().enumerate() {
                verts.vertex_into(i, &mut slot);
                stage.run_into(&slot.v, o);
            }
            let first = case * 7;
            let mut got = vec![ClipVertex::default(); verts.len() - first];
            let mut slot = verts.new_slot();
            stage.run_block(&verts[..], first, &mut slot, &mut got);
            // NaN compares as one value: Rust leaves the sign and payload of a NaN that an
            // operation produces unspecified (the compiler may swap the operands of an
            // addition), and nothing downstream reads them.
            let bits = |v: &ClipVertex| {
                let mut b: Vec<u32> = v
                    .clip
                    .iter()
                    .chain(&v.win)
                    .chain(&v.vary)
                    .map(|f| {
                        if f.is_nan() {
                            f32::NAN.to_bits()
                        } else {
                            f.to_bits()
                        }
                    })
                    .collect();
                b.push(v.mask as u32);
                b
            };
            for (j, g) in got.iter().enumerate() {
                let w = &want[first + j];
                assert_eq!(
                    bits(g),
                    bits(w),
                    "case {case}, vertex {}: {g:?} instead of {w:?}",
                    first + j
                );
            }
        }
    }
}
