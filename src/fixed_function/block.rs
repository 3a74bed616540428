//! The vertex stage over runs of consecutive vertices (without per-vertex materials or
//! point attenuation): position, clip mask and window position in SSE registers, one
//! vertex after another in a loop whose iterations do not wait for each other, and the
//! lighting of eight vertices at once in AVX2 lanes. Also the position-only pass that
//! gives every vertex's clip mask ahead of the stage ([`VertexStage::clip_masks`]). It writes exactly what
//! [`VertexStage::run_into`] writes (same operations in the same order); per vertex, that
//! function's dependency chain (transform, divide, viewport) was most of its cost when it
//! ran vertex by vertex from the post-transform cache.

use super::fog::vertex_fog_coord;
use super::lighting::eye_position;
use super::texgen::generate;
use super::transform::VertexStage;
use crate::geometry::boxes::{ClipPlanes, PositionBoxes, BOX_VERTS};
use crate::geometry::source::{VertexSlot, VertexSource};
use crate::geometry::{user_clip_mask, ClipMask, ClipVertex, VARY_FOG, VARY_SPEC, VARY_TEX};

/// Vertices lit together, one per lane of an AVX2 register.
#[cfg(target_arch = "x86_64")]
const LANES: usize = 8;

/// The per-run constants of the block transform, in SSE registers.
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy)]
struct Consts {
    col: [crate::simd::F32x4; 4],
    scale: crate::simd::F32x4,
    trans: crate::simd::F32x4,
    zero: crate::simd::F32x4,
    one: crate::simd::F32x4,
}

impl VertexStage {
    /// Whether [`VertexStage::run_block`] may run this stage: anything but per-vertex
    /// materials and point attenuation, on an AVX2 level.
    pub fn block_ok(&self) -> bool {
        self.light
            .as_ref()
            .is_none_or(|l| l.vertex_material.is_none() && l.fma == self.fma)
            && self.point_atten.is_none()
            && crate::cpu::isa().avx2()
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
            use crate::cpu::Isa;
            match (crate::cpu::isa(), self.fma) {
                (Isa::Avx2Fma, true) => {
                    // SAFETY: the level (`cpu::isa`) says the CPU has AVX2 and FMA.
                    return unsafe { self.run_block_fma(verts, first, slot, out) };
                }
                (Isa::Avx2Fma, false) => {
                    // SAFETY: the level says the CPU has AVX2.
                    return unsafe { self.run_block_avx2(verts, first, slot, out) };
                }
                _ => {}
            }
        }
        for (j, o) in out.iter_mut().enumerate() {
            verts.vertex_into(first + j, slot);
            self.run_into(&slot.v, o);
        }
    }

    /// [`VertexStage::run_block`] compiled for AVX2 and FMA, fused.
    ///
    /// # Safety
    /// The CPU has AVX2 and FMA.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn run_block_fma<S: VertexSource + ?Sized>(
        &self,
        verts: &S,
        first: usize,
        slot: &mut VertexSlot,
        out: &mut [ClipVertex],
    ) {
        // SAFETY: forwarded.
        unsafe { self.run_block_x86::<S, true>(verts, first, slot, out) }
    }

    /// [`VertexStage::run_block`] compiled for AVX2, not fused.
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn run_block_avx2<S: VertexSource + ?Sized>(
        &self,
        verts: &S,
        first: usize,
        slot: &mut VertexSlot,
        out: &mut [ClipVertex],
    ) {
        // SAFETY: forwarded.
        unsafe { self.run_block_x86::<S, false>(verts, first, slot, out) }
    }

    /// [`VertexStage::run_block`] in SSE and AVX registers; `FMA` is `self.fma`.
    ///
    /// # Safety
    /// The CPU has AVX2, and FMA when `FMA`.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn run_block_x86<S: VertexSource + ?Sized, const FMA: bool>(
        &self,
        verts: &S,
        first: usize,
        slot: &mut VertexSlot,
        out: &mut [ClipVertex],
    ) {
        use crate::simd::F32x4;
        // SAFETY: forwarded.
        let k = unsafe { self.consts() };
        let Some(lp) = &self.light else {
            for (j, o) in out.iter_mut().enumerate() {
                verts.vertex_into(first + j, slot);
                let v = &slot.v;
                // SAFETY: forwarded.
                unsafe { self.position_x86::<FMA>(&k, v, o) };
                // SAFETY: AVX2; the loads and stores are of 4-float arrays.
                unsafe {
                    let c = clamp4(&k, F32x4::load(v.color.as_ptr()));
                    c.store(o.vary.as_mut_ptr());
                    if self.color_sum {
                        let s = clamp4(&k, F32x4::load(v.secondary.as_ptr()));
                        s.store(o.vary[VARY_SPEC..].as_mut_ptr());
                    }
                }
            }
            return;
        };
        for (c, chunk) in out.chunks_mut(LANES).enumerate() {
            let base = first + c * LANES;
            // The lighting inputs of the chunk's vertices as lanes (unused lanes 0).
            let mut pos = [[0f32; LANES]; 4];
            let mut nrm = [[0f32; LANES]; 3];
            let mut col = [[0f32; LANES]; 4];
            for (j, o) in chunk.iter_mut().enumerate() {
                verts.vertex_into(base + j, slot);
                let v = &slot.v;
                // SAFETY: forwarded.
                unsafe { self.position_x86::<FMA>(&k, v, o) };
                for (lanes, x) in pos.iter_mut().zip(v.pos) {
                    lanes[j] = x;
                }
                for (lanes, x) in col.iter_mut().zip(v.color) {
                    lanes[j] = x;
                }
                for (lanes, x) in nrm.iter_mut().zip(v.normal) {
                    lanes[j] = x;
                }
            }
            // SAFETY: forwarded.
            unsafe { self.light_lanes::<FMA>(lp, &pos, &nrm, &col, chunk) };
        }
    }

    /// The block transform's constants: the columns of the combined matrix and the
    /// viewport's scale and translation in SSE registers.
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn consts(&self) -> Consts {
        use crate::simd::F32x4;
        let m = &self.mvp.0;
        let vp = &self.viewport;
        // SAFETY: AVX2 (the caller's promise); the loads are of 4-float arrays.
        unsafe {
            Consts {
                col: [
                    F32x4::load(m[0..4].as_ptr()),
                    F32x4::load(m[4..8].as_ptr()),
                    F32x4::load(m[8..12].as_ptr()),
                    F32x4::load(m[12..16].as_ptr()),
                ],
                scale: F32x4::new([vp.scale[0], vp.scale[1], vp.scale[2], 0.0]),
                trans: F32x4::new([vp.translate[0], vp.translate[1], vp.translate[2], 0.0]),
                zero: F32x4::zero(),
                one: F32x4::splat(1.0),
            }
        }
    }

    /// The clip-space position of object position `pos` in SSE registers and its clip
    /// mask ([`VertexStage::clip_position`]).
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn clip_x86(&self, k: &Consts, pos: &[f32; 4]) -> (crate::simd::F32x4, ClipMask) {
        use crate::simd::F32x4;
        // Clip mask bits of the lanes x, y, z of `!(c <= w)` and of `!(c + w >= 0)`
        // (see `geometry::clip_mask`: bits 0, 2, 5 and 1, 3, 4; `z + 0` under halfz).
        const ABOVE: [u8; 8] = [0, 1, 4, 5, 32, 33, 36, 37];
        const BELOW: [u8; 8] = [0, 2, 8, 10, 16, 18, 24, 26];
        // SAFETY: (whole body) AVX2, the caller's promise; the load is of 4 floats.
        unsafe {
            let p = F32x4::load(pos.as_ptr());
            // `Mat4::transform`: ((x·C0 + y·C1) + z·C2) + w·C3, each step rounded.
            let x = p.broadcast::<0x00>().mul(k.col[0]);
            let y = p.broadcast::<0x55>().mul(k.col[1]);
            let z = p.broadcast::<0xAA>().mul(k.col[2]);
            let w = p.broadcast::<0xFF>().mul(k.col[3]);
            let clip = x.add(y).add(z).add(w);
            let cw = clip.broadcast::<0xFF>();
            let above = clip.cmp_nle(cw).movemask() & 7;
            // GL_ZERO_TO_ONE's near plane tests z alone: z + 0 has z's sign, so the
            // same comparison gives `!(z >= 0)`; w in the x and y lanes, 0 in z.
            let sum = clip.add(if self.viewport.halfz {
                cw.blend::<0b0100>(k.zero)
            } else {
                cw
            });
            let below = sum.cmp_nge(k.zero).movemask() & 7;
            let mut mask = (ABOVE[above as usize] | BELOW[below as usize]) as ClipMask;
            if self.ucp_enabled != 0 {
                // The user planes as `clip_position` tests them, on the same position.
                let mut c = [0f32; 4];
                clip.store(c.as_mut_ptr());
                mask |= user_clip_mask(c, &self.ucp.planes, self.ucp_enabled, self.fma);
            }
            (clip, mask)
        }
    }

    /// The clip mask of every vertex of `verts` into `out` (cleared first), from the
    /// positions alone: the masks [`VertexStage::run_into`] gives them.
    pub fn clip_masks<S: VertexSource + ?Sized>(&self, verts: &S, out: &mut Vec<ClipMask>) {
        out.clear();
        out.resize(verts.count(), 0);
        self.clip_masks_into(verts, 0, out);
    }

    /// The clip masks of vertices `first..first + out.len()` of `verts` into `out`
    /// ([`VertexStage::clip_masks`] of a part of a draw).
    pub fn clip_masks_into<S: VertexSource + ?Sized>(
        &self,
        verts: &S,
        first: usize,
        out: &mut [ClipMask],
    ) {
        match verts.position_boxes() {
            // User planes are not boxed: their vertices are transformed one by one.
            Some(pb) if self.ucp_enabled == 0 => self.clip_masks_boxed(verts, first, out, pb),
            _ => self.clip_masks_exact(verts, first, out),
        }
    }

    /// [`VertexStage::clip_masks_into`] through the source's boxes: each run of positions
    /// whose box lies outside some frustum plane gets those planes' bits (a subset of each
    /// of its vertices' own masks, see [`crate::geometry::boxes`]), and the other runs
    /// their exact masks.
    fn clip_masks_boxed<S: VertexSource + ?Sized>(
        &self,
        verts: &S,
        first: usize,
        out: &mut [ClipMask],
        pb: PositionBoxes<'_>,
    ) {
        let planes = ClipPlanes::new(&self.mvp.0, self.viewport.halfz);
        let n = out.len();
        let mut i = 0;
        while i < n {
            let at = pb.first + first + i;
            let k = at / BOX_VERTS;
            let end = (i + (k + 1) * BOX_VERTS - at).min(n);
            let bits = pb
                .boxes
                .get(k)
                .copied()
                .flatten()
                .map_or(0, |b| planes.outside(&b));
            if bits != 0 {
                out[i..end].fill(bits);
            } else {
                self.clip_masks_exact(verts, first + i, &mut out[i..end]);
            }
            i = end;
        }
    }

    /// [`VertexStage::clip_masks_into`] one position at a time.
    fn clip_masks_exact<S: VertexSource + ?Sized>(
        &self,
        verts: &S,
        first: usize,
        out: &mut [ClipMask],
    ) {
        #[cfg(target_arch = "x86_64")]
        if crate::cpu::isa().avx2() {
            // SAFETY: the level says the CPU has AVX2.
            return unsafe { self.clip_masks_avx2(verts, first, out) };
        }
        let mask = |p: [f32; 4]| self.clip_position(p).1;
        match verts.float_positions() {
            Some(fp) if fp.count() == verts.count() => {
                for (i, m) in out.iter_mut().enumerate() {
                    *m = mask(fp.get(first + i));
                }
            }
            _ => {
                for (i, m) in out.iter_mut().enumerate() {
                    *m = mask(verts.position(first + i));
                }
            }
        }
    }

    /// [`VertexStage::clip_masks_into`] compiled for AVX2.
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn clip_masks_avx2<S: VertexSource + ?Sized>(
        &self,
        verts: &S,
        first: usize,
        out: &mut [ClipMask],
    ) {
        // Loops, not closures: a closure is compiled without this function's target
        // features.
        // SAFETY: (whole body) AVX2, the caller's promise.
        unsafe {
            let k = self.consts();
            match verts.float_positions() {
                Some(fp) if fp.count() == verts.count() => {
                    for (i, m) in out.iter_mut().enumerate() {
                        *m = self.clip_x86(&k, &fp.get(first + i)).1;
                    }
                }
                _ => {
                    for (i, m) in out.iter_mut().enumerate() {
                        *m = self.clip_x86(&k, &verts.position(first + i)).1;
                    }
                }
            }
        }
    }

    /// Lights the vertices of `out` (at most [`LANES`]) whose object positions, normals
    /// and colours are the lanes of `pos`, `nrm` and `col`, writing the clamped colours
    /// as [`VertexStage::run_into`] does.
    ///
    /// # Safety
    /// The CPU has AVX2, and FMA when `FMA`.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn light_lanes<const FMA: bool>(
        &self,
        lp: &super::lighting::LightPlan,
        pos: &[[f32; LANES]; 4],
        nrm: &[[f32; LANES]; 3],
        col: &[[f32; LANES]; 4],
        out: &mut [ClipVertex],
    ) {
        use super::lighting::lanes;
        use crate::simd::F32x8;
        // SAFETY: (whole body) forwarded; the loads are of 8-float arrays.
        unsafe {
            let zero = F32x8::zero();
            let eye = if lp.needs_eye_position() {
                // `eye_position`: ((x·C0 + y·C1) + z·C2) + w·C3 per row, each step rounded.
                let mv = &self.modelview.0;
                let p = [ld(&pos[0]), ld(&pos[1]), ld(&pos[2]), ld(&pos[3])];
                let mut e = [zero; 3];
                for (r, e) in e.iter_mut().enumerate() {
                    let t = p[0].mul(F32x8::splat(mv[r]));
                    let t = p[1].mul(F32x8::splat(mv[4 + r])).add(t);
                    let t = p[2].mul(F32x8::splat(mv[8 + r])).add(t);
                    *e = p[3].mul(F32x8::splat(mv[12 + r])).add(t);
                }
                e
            } else {
                [zero; 3]
            };
            let n = lanes::eye_normal(lp, [ld(&nrm[0]), ld(&nrm[1]), ld(&nrm[2])]);
            let c = [ld(&col[0]), ld(&col[1]), ld(&col[2]), ld(&col[3])];
            let lit = lanes::light_vertex::<FMA>(lp, eye, n, c);
            // `clamp_color` (see `clamp4`), then each vertex's four colours.
            let one = F32x8::splat(1.0);
            let mut v = [[[0f32; LANES]; 4]; 4];
            let faces = if lp.two_side() { 4 } else { 3 };
            for (dst, src) in v.iter_mut().zip(&lit).take(faces) {
                for (d, s) in dst.iter_mut().zip(src) {
                    s.min(one).max(zero).store(d.as_mut_ptr());
                }
            }
            let b = self.back_offset();
            let [front, back, front_spec, back_spec] = &v;
            for (j, o) in out.iter_mut().enumerate() {
                for i in 0..4 {
                    o.vary[i] = front[i][j];
                    o.vary[VARY_SPEC + i] = front_spec[i][j];
                }
                if faces == 4 {
                    for i in 0..4 {
                        o.vary[b + i] = back[i][j];
                        o.vary[b + 4 + i] = back_spec[i][j];
                    }
                }
            }
        }
    }

    /// The part of [`VertexStage::run_into`] beside the colours for one vertex: clip
    /// position, mask and window position in SSE registers, the fog coordinate and the
    /// texture coordinates (generated, through their matrices) as `run_into` computes
    /// them.
    ///
    /// # Safety
    /// The CPU has AVX2, and FMA when `FMA`.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn position_x86<const FMA: bool>(
        &self,
        k: &Consts,
        v: &crate::geometry::fetch::VertexIn,
        o: &mut ClipVertex,
    ) {
        let tex = &self.tex_units[..self.n_tex];
        // SAFETY: (whole body) AVX2 (and FMA when `FMA`), the caller's promise; the
        // stores are of 4-float arrays.
        unsafe {
            let (clip, mask) = self.clip_x86(k, &v.pos);
            let cw = clip.broadcast::<0xFF>();
            // `Viewport::apply_shader`: fmuladd(c · (1/w), scale, translate), 1/w last.
            let inv = k.one.div(cw);
            let q = clip.mul(inv);
            let win = if FMA {
                q.mul_add(k.scale, k.trans)
            } else {
                q.mul(k.scale).add(k.trans)
            };
            let win = win.blend::<0b1000>(inv);
            clip.store(o.clip.as_mut_ptr());
            win.store(o.win.as_mut_ptr());
            o.mask = mask;
        }
        if let Some(f) = &self.fog {
            // The eye position lighting made, if it made one (it decides the formula).
            let lit_eye = match &self.light {
                Some(lp) if lp.needs_eye_position() => Some(eye_position(&self.modelview, v.pos)),
                _ => None,
            };
            o.vary[VARY_FOG] = vertex_fog_coord(f, &self.modelview, v.pos, lit_eye, v.fog_coord);
        }
        let mut eye = None;
        let n = match &self.normal_xform {
            Some(x) => x.apply(v.normal),
            None => [0.0; 3],
        };
        for (k, (unit, tm)) in tex.iter().enumerate() {
            let mut tc = v.texcoord[*unit];
            if let Some(g) = &self.texgen[k] {
                let e = match eye {
                    Some(e) => e,
                    None => *eye.insert(eye_position(&self.modelview, v.pos)),
                };
                tc = generate(g, tc, v.pos, e, n);
            }
            let tc = match tm {
                Some(tm) => tm.transform(tc),
                None => tc,
            };
            o.vary[VARY_TEX + 4 * k..VARY_TEX + 4 * k + 4].copy_from_slice(&tc);
        }
    }
}

/// Eight lanes from `a`.
///
/// # Safety
/// The CPU has AVX2. (A function, not a closure: a closure is compiled without the
/// kernel's target features, so its intrinsics would be calls.)
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn ld(a: &[f32; LANES]) -> crate::simd::F32x8 {
    // SAFETY: AVX2 (the caller's promise); `a` holds eight floats.
    unsafe { crate::simd::F32x8::load(a.as_ptr()) }
}

/// `clamp_color`: `max(min(v, 1), 0)`, NaN to 1 (`minps` gives its second operand for
/// NaN) and -0.0 to 0.0 (`maxps` gives its second operand for equal values), the
/// comparisons the scalar `clamp_color` makes (the test below checks both).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn clamp4(k: &Consts, c: crate::simd::F32x4) -> crate::simd::F32x4 {
    c.min(k.one).max(k.zero)
}

#[cfg(test)]
mod lit_tests;

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
    /// conventions, with and without user clip planes, and runs that start anywhere in
    /// the source.
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
        for case in 0..32 {
            let fma = case & 1 == 1;
            let vp = if case & 8 == 8 { vp_halfz } else { vp };
            let mut stage = VertexStage::new(mat(), mat(), vp, fma);
            stage.color_sum = case & 2 == 2;
            if case & 16 == 16 {
                // Three user clip planes (of eight), in clip space.
                stage.ucp_enabled = 0b1010_0100;
                for p in stage.ucp.planes.iter_mut() {
                    *p = std::array::from_fn(|i| mat().0[i] * 2.0);
                }
            }
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
