//! Lowering of a fixed-function fragment state into the IR: the prototype's state, one
//! 8-bit RGBA texture unit with MODULATE on the interpolated colour, then linear fog, the
//! alpha test, the depth test on a Z24 buffer, blending, and the RGBA8 store. The same
//! operations in the same order as [`crate::fragment::span::shade_chunk`] on its
//! textured path, so the bytes are the same.
//!
//! The run's planes follow [`planes_of`]: the window z, the `1/w` plane, then the
//! triangle's varyings. The texture's RGBA8 values are input stream 0 (sampled by
//! today's sampler; sampling is not in the IR yet).

use super::ir::{Builder, Ir, Op, Ty, Val};
use crate::fragment::FragPlan;
use crate::framebuffer::DepthFormat;
use crate::geometry::setup::SetupTriangle;
use crate::geometry::{MAX_VARY, VARY_FOG};
use crate::pipe::FogMode;

/// Plane index of the window z in [`planes_of`].
pub const PLANE_Z: u16 = 0;
/// Plane index of `1/w`.
pub const PLANE_W: u16 = 1;
/// Plane index of varying 0; varying k is `PLANE_VARY + k`.
pub const PLANE_VARY: u16 = 2;

/// The planes a lowered program evaluates, for triangle `t`.
pub fn planes_of(t: &SetupTriangle) -> [[f32; 3]; 2 + MAX_VARY] {
    let mut out = [[0.0; 3]; 2 + MAX_VARY];
    planes_into(t, &mut out);
    out
}

/// The first `out.len()` planes of [`planes_of`] into `out` (a walk copies only the
/// planes its program reads).
pub fn planes_into(t: &SetupTriangle, out: &mut [[f32; 3]]) {
    let p = |p: &crate::geometry::setup::Plane| [p.a0, p.dadx, p.dady];
    // Two loops, not one over a chained iterator: the chain's per-item branch was a third
    // of `Walk::begin`, which runs once per triangle.
    let (head, vary) = out.split_at_mut(out.len().min(2));
    for (o, v) in head.iter_mut().zip([&t.z, &t.w]) {
        *o = p(v);
    }
    for (o, v) in vary.iter_mut().zip(&t.vary) {
        *o = p(v);
    }
}

/// The state the prototype lowers: a fragment plan and whether attributes take the
/// perspective divide.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexturedState {
    /// The per-fragment plan.
    pub plan: FragPlan,
    /// Perspective-correct varyings (the triangle's `persp`).
    pub persp: bool,
}

/// The IR of `s`, or `None` when it needs something the prototype does not lower yet
/// (flat shading, separate specular, fog other than LINEAR, stencil, logic op, colour
/// masks, depth formats other than Z24, smooth lines and points, multisampling, sRGB,
/// occlusion counting).
pub fn lower_textured(s: &TexturedState) -> Option<Ir> {
    let p = &s.plan;
    let unsupported = p.flat
        || p.separate_specular
        || p.stencil.is_some()
        || p.logic.is_some()
        || p.color_mask != [true; 4]
        || p.count_samples
        || p.smooth.is_some()
        || p.ms.is_some()
        || p.srgb
        || p.fog.is_some_and(|f| f.mode != FogMode::Linear)
        || p.depth.is_some_and(|d| d.format != DepthFormat::Z24);
    if unsupported {
        return None;
    }
    let mut b = Builder::new();
    let oow = s.persp.then(|| {
        let one = b.f32(1.0);
        let w = b.push(Op::Interp(PLANE_W));
        b.push(Op::Div(one, w))
    });
    let vary = |b: &mut Builder, k: usize| -> Val {
        let a = b.push(Op::Interp(PLANE_VARY + k as u16));
        match oow {
            Some(o) => b.mul(a, o),
            None => a,
        }
    };
    let tex = b.push(Op::Input(0));
    let mut c = [Val(0); 4];
    for (ch, out) in c.iter_mut().enumerate() {
        let f = vary(&mut b, ch);
        let t = b.push(Op::UnpackUnorm8(tex, ch as u8));
        *out = b.mul(f, t);
    }
    if let Some(fog) = &p.fog {
        let coord = vary(&mut b, VARY_FOG);
        let (scale, bias) = (b.f32(fog.scale), b.f32(fog.bias));
        let lin = b.mul(coord, scale);
        let lin = b.add(lin, bias);
        let f = b.push(Op::Sat(lin));
        let one = b.f32(1.0);
        let g = b.sub(one, f);
        for (ch, out) in c.iter_mut().take(3).enumerate() {
            let k = b.f32(fog.color[ch]);
            let kg = b.mul(k, g);
            let cf = b.mul(*out, f);
            *out = b.add(kg, cf);
        }
    }
    let mut px = b.push(Op::PackUnorm8(c));
    super::ff::alpha_test(&mut b, p, px);
    if let Some(d) = p.depth {
        let z = b.push(Op::Interp(PLANE_Z));
        let z = b.push(Op::Sat(z));
        let scale = b.f32(16_777_215.0);
        let z = b.mul(z, scale);
        let q = b.push(Op::CvtRne(z));
        b.push(Op::DepthTest {
            func: d.func,
            write: d.write,
            z: q,
        });
    }
    if let Some(bl) = p.blend {
        let dst = b.push(Op::LoadColor(0));
        px = b.push(Op::Blend(bl, px, dst));
    }
    b.push(Op::StoreColor(0, px));
    let ir = b.finish().ok()?;
    debug_assert!(ir.types[tex.0 as usize] == Some(Ty::I32));
    Some(ir)
}
