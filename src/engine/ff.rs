//! Lowering of the general textured walk's per-fragment state into the IR: any number of
//! units with any texture environment or GL_COMBINE state (the crossbar included), the
//! separate specular colour, fog of every mode, the alpha test, the depth test on Z16,
//! Z24 and Z32F buffers, blending, the colour mask and the RGBA8 store.
//!
//! The operations and their order are those of `fragment::simd_gen::colors8` and
//! `shade_row` (and the per-lane `fragment::span::shade_chunk`, which they match): each
//! varying is its plane, times `1 / w` when perspective-correct; every unit's combiner as
//! [`Combine::apply`] evaluates it (separate multiplies and adds, `fsat` only where the
//! function saturates or a scale applies, NIR's two rewrites); the colour sum and the fog
//! mix unfused; the fog factor by [`crate::fixed_function::fog::FogPlan::factor`] itself
//! ([`Op::Fog`]); unorm8 as clamp, ·255 and `cvtps2dq`.
//!
//! The program's inputs: the planes of [`super::lower::planes_of`], the units' texels as
//! f32 input streams (unit k's channel c is stream `4k + c`), and the triangle's flat
//! varyings ([`crate::geometry::setup::SetupTriangle::flat`]) as uniforms. The sampled
//! values come from today's samplers; the per-fragment work after them is the program.

use super::ir::{Builder, FCmp, Ir, Op, Ty, Un, Val};
use super::lower::{PLANE_VARY, PLANE_W, PLANE_Z};
use crate::fragment::FragPlan;
use crate::framebuffer::draw_buffers::MORE_COLORS;
use crate::framebuffer::DepthFormat;
use crate::geometry::{VARY_FOG, VARY_SPEC};
use crate::pipe::FogMode;
use crate::texture::env::{Arg, Combine, CombineFn, Operand, Source};
use std::collections::HashMap;

/// The [`Op::Output`] of a written `gl_FragDepth` in a variant whose walk runs the
/// stencil and depth tests ([`tests_in_walk`]), after the draw buffers' colours.
pub const DEPTH_OUTPUT: u16 = 4 * (1 + MORE_COLORS) as u16;

/// What the lowering reads: the fragment plan, the units' combiners, whether varyings take
/// the perspective divide. Per-triangle values (planes, flat colours, texels) are run
/// inputs, so one program serves every triangle of a state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FfState {
    /// The per-fragment plan.
    pub plan: FragPlan,
    /// The active units' combiners, in unit order (`units` of them).
    pub envs: [Option<Combine>; crate::pipe::MAX_TEXTURE_UNITS],
    /// The number of active units.
    pub units: u8,
    /// Perspective-correct varyings.
    pub persp: bool,
}

/// Whether the lowering of a fixed-function state covers `plan` ([`covers_tail`]; the
/// stencil test, which [`tail`] lowers for shader draws, stays on the hand-written paths
/// here, so that their routing is unchanged).
pub fn covers(plan: &FragPlan) -> bool {
    plan.stencil.is_none() && covers_tail(plan)
}

/// Whether [`tail`] lowers `plan`'s per-fragment operations (logic ops, smoothing,
/// multisampling, sRGB and Z32 unorm depth do not).
pub fn covers_tail(plan: &FragPlan) -> bool {
    plan.logic.is_none() && !plan.srgb && plan.smooth.is_none() && covers_tests(plan)
}

/// Whether [`tail_buffers`] lowers `plan`'s per-fragment operations when the colour
/// store is the caller's (`host`): logic ops and sRGB writes are then the store's, and
/// so are the stencil and depth tests the program does not run ([`tests_in_walk`]).
pub fn covers_host_tail(plan: &FragPlan) -> bool {
    plan.smooth.is_none()
}

/// Whether the walk runs `plan`'s stencil and depth tests after a host-store program
/// (`super::draw`): per sample under multisampling, and for a depth format the program
/// does not quantise (Z32 unorm, compared unsigned).
pub fn tests_in_walk(plan: &FragPlan) -> bool {
    plan.ms.is_some() || (plan.smooth.is_none() && !covers_tests(plan))
}

/// Whether the program lowers `plan`'s depth test (and without multisampling).
fn covers_tests(plan: &FragPlan) -> bool {
    plan.ms.is_none()
        && plan.depth.is_none_or(|d| {
            matches!(
                d.format,
                DepthFormat::Z24 | DepthFormat::Z16 | DepthFormat::Z32F
            )
        })
}

/// A builder that shares equal pure operations (constants, planes, arithmetic), so that
/// e.g. `1 − x` of one operand is computed once, as the compiled shader's CSE does;
/// sharing never changes a value.
struct L {
    b: Builder,
    cse: HashMap<(u8, u32, u32, u32), Val>,
    oow: Option<Val>,
}

impl L {
    /// `op` through the CSE table when it is pure and simple.
    fn op(&mut self, op: Op) -> Val {
        let key = match op {
            Op::Const(Ty::F32, v) => Some((0, v, 0, 0)),
            Op::Const(Ty::I32, v) => Some((1, v, 0, 0)),
            Op::Interp(n) => Some((2, n as u32, 0, 0)),
            Op::InputF(n) => Some((3, n as u32, 0, 0)),
            Op::Uniform(n) => Some((4, n as u32, 0, 0)),
            Op::Add(a, b) => Some((5, a.0 as u32, b.0 as u32, 0)),
            Op::Sub(a, b) => Some((6, a.0 as u32, b.0 as u32, 0)),
            Op::Mul(a, b) => Some((7, a.0 as u32, b.0 as u32, 0)),
            Op::Sat(a) => Some((8, a.0 as u32, 0, 0)),
            _ => None,
        };
        match key {
            Some(k) => {
                if let Some(&v) = self.cse.get(&k) {
                    return v;
                }
                let v = self.b.push(op);
                self.cse.insert(k, v);
                v
            }
            None => self.b.push(op),
        }
    }
    fn k(&mut self, v: f32) -> Val {
        self.op(Op::Const(Ty::F32, v.to_bits()))
    }
    fn add(&mut self, a: Val, b: Val) -> Val {
        self.op(Op::Add(a, b))
    }
    fn sub(&mut self, a: Val, b: Val) -> Val {
        self.op(Op::Sub(a, b))
    }
    fn mul(&mut self, a: Val, b: Val) -> Val {
        self.op(Op::Mul(a, b))
    }
    fn sat(&mut self, a: Val) -> Val {
        self.op(Op::Sat(a))
    }
    fn one_minus(&mut self, a: Val) -> Val {
        let one = self.k(1.0);
        self.sub(one, a)
    }
    /// Varying `k`: its plane, times `1 / w` when perspective-correct.
    fn vary(&mut self, k: usize) -> Val {
        let a = self.op(Op::Interp(PLANE_VARY + k as u16));
        match self.oow {
            Some(o) => self.mul(a, o),
            None => a,
        }
    }
}

/// Four channels of eight fragments.
type V4 = [Val; 4];

/// What a unit's combiner reads.
struct Inputs<'a> {
    frag: V4,
    tex: V4,
    prev: V4,
    /// Every unit's texels when some unit reads the crossbar, else none.
    textures: &'a [V4],
}

/// `CombineFn::num_args` (private to the texture module).
fn num_args(f: CombineFn) -> usize {
    match f {
        CombineFn::Replace => 1,
        CombineFn::Interpolate => 3,
        _ => 2,
    }
}

/// `CombineFn::saturates`.
fn saturates(f: CombineFn) -> bool {
    !matches!(
        f,
        CombineFn::Replace | CombineFn::Modulate | CombineFn::Interpolate
    )
}

/// The value of source `s`.
fn value(l: &mut L, c: &Combine, s: Source, inp: &Inputs<'_>) -> V4 {
    match s {
        Source::Texture => inp.tex,
        Source::TextureN(n) => match inp.textures.get(n as usize) {
            Some(&v) => v,
            None => [l.k(0.0); 4],
        },
        Source::Constant => c.color.map(|v| l.k(v)),
        Source::PrimaryColor => inp.frag,
        Source::Previous => inp.prev,
    }
}

/// Channel `ch` of argument `a`.
fn arg(l: &mut L, c: &Combine, a: Arg, ch: usize, inp: &Inputs<'_>) -> Val {
    let v = value(l, c, a.0, inp);
    match a.1 {
        Operand::SrcColor => v[ch],
        Operand::OneMinusSrcColor => l.one_minus(v[ch]),
        Operand::SrcAlpha => v[3],
        Operand::OneMinusSrcAlpha => l.one_minus(v[3]),
    }
}

/// The value x of a ONE_MINUS operand (its argument is `1 − x`).
fn minus_of(l: &mut L, c: &Combine, a: Arg, ch: usize, inp: &Inputs<'_>) -> Option<Val> {
    let v = value(l, c, a.0, inp);
    match a.1 {
        Operand::OneMinusSrcColor => Some(v[ch]),
        Operand::OneMinusSrcAlpha => Some(v[3]),
        _ => None,
    }
}

/// `Combine::eval` of one channel.
fn eval(
    l: &mut L,
    c: &Combine,
    f: CombineFn,
    args: &[Arg; 3],
    ch: usize,
    reassoc: bool,
    inp: &Inputs<'_>,
) -> Val {
    let mut a = [Val(0); 3];
    for (i, ai) in a.iter_mut().enumerate().take(num_args(f)) {
        *ai = arg(l, c, args[i], ch, inp);
    }
    match f {
        CombineFn::AddSigned if reassoc => match minus_of(l, c, args[0], ch, inp) {
            Some(x) => {
                let h = l.k(0.5);
                let d = l.sub(h, x);
                l.add(d, a[1])
            }
            None => {
                let h = l.k(0.5);
                let d = l.sub(a[0], h);
                l.add(d, a[1])
            }
        },
        CombineFn::Interpolate => match minus_of(l, c, args[2], ch, inp) {
            Some(x) => {
                let p = l.mul(a[0], a[2]);
                let q = l.mul(a[1], x);
                l.add(p, q)
            }
            None => combine(l, f, a),
        },
        _ => combine(l, f, a),
    }
}

/// `combine` of one channel's arguments.
fn combine(l: &mut L, f: CombineFn, a: [Val; 3]) -> Val {
    match f {
        CombineFn::Replace => a[0],
        CombineFn::Modulate => l.mul(a[0], a[1]),
        CombineFn::Add => l.add(a[0], a[1]),
        CombineFn::AddSigned => {
            let s = l.add(a[0], a[1]);
            let h = l.k(0.5);
            l.sub(s, h)
        }
        CombineFn::Interpolate => {
            let p = l.mul(a[0], a[2]);
            let m = l.one_minus(a[2]);
            let q = l.mul(a[1], m);
            l.add(p, q)
        }
        CombineFn::Subtract => l.sub(a[0], a[1]),
        CombineFn::Dot3Rgb | CombineFn::Dot3Rgba => unreachable!("handled by the caller"),
    }
}

/// [`Combine::apply`] of one unit.
fn apply(l: &mut L, c: &Combine, inp: &Inputs<'_>) -> V4 {
    if let Some(sm) = &c.simple {
        let r0 = value(l, c, sm.rgb.0, inp);
        let a0 = value(l, c, sm.a.0, inp)[3];
        let mut out = [r0[0], r0[1], r0[2], a0];
        if let Some(s1) = sm.rgb.1 {
            let r1 = value(l, c, s1, inp);
            for ch in 0..3 {
                out[ch] = l.mul(out[ch], r1[ch]);
            }
        }
        if let Some(s1) = sm.a.1 {
            let a1 = value(l, c, s1, inp)[3];
            out[3] = l.mul(out[3], a1);
        }
        return out;
    }
    let (reassoc_rgb, reassoc_a) = c.reassoc;
    let shift = c.scale_rgb != 1.0 || c.scale_a != 1.0;
    let mut out = [Val(0); 4];
    if matches!(c.mode_rgb, CombineFn::Dot3Rgb | CombineFn::Dot3Rgba) {
        let (two, m1) = (l.k(2.0), l.k(1.0));
        let mut t = [[Val(0); 3]; 2];
        for (i, ti) in t.iter_mut().enumerate() {
            for (ch, v) in ti.iter_mut().enumerate() {
                let a = arg(l, c, c.args_rgb[i], ch, inp);
                let a2 = l.mul(a, two);
                *v = l.sub(a2, m1);
            }
        }
        let p0 = l.mul(t[0][0], t[1][0]);
        let p1 = l.mul(t[0][1], t[1][1]);
        let p2 = l.mul(t[0][2], t[1][2]);
        let s = l.add(p0, p1);
        let mut d = l.add(s, p2);
        if c.scale_rgb == 1.0 {
            d = l.sat(d);
        }
        out = [d, d, d, out[3]];
        if c.mode_rgb == CombineFn::Dot3Rgba {
            out[3] = d;
        }
    } else {
        for (ch, o) in out.iter_mut().enumerate().take(3) {
            let mut v = eval(l, c, c.mode_rgb, &c.args_rgb, ch, reassoc_rgb, inp);
            if !shift && saturates(c.mode_rgb) {
                v = l.sat(v);
            }
            *o = v;
        }
    }
    if c.mode_rgb != CombineFn::Dot3Rgba {
        let mut v = eval(l, c, c.mode_a, &c.args_a, 3, reassoc_a, inp);
        if !shift && saturates(c.mode_a) {
            v = l.sat(v);
        }
        out[3] = v;
    }
    if shift {
        let (sr, sa) = (l.k(c.scale_rgb), l.k(c.scale_a));
        for o in out.iter_mut().take(3) {
            let m = l.mul(*o, sr);
            *o = l.sat(m);
        }
        let m = l.mul(out[3], sa);
        out[3] = l.sat(m);
    }
    out
}

/// The alpha test on the packed colour `px`: kills the lanes whose alpha byte fails.
pub(super) fn alpha_test(b: &mut Builder, p: &FragPlan, px: Val) {
    if let Some((func, reference)) = p.alpha {
        let a = b.push(Op::Byte(px, 3));
        let r = b.i32(reference as i32);
        let m = b.push(Op::ICmp(func, a, r));
        b.push(Op::Kill(m));
    }
}

/// The IR of `s` (see the module doc), or `None` when [`covers`] refuses its plan.
pub fn lower(s: &FfState) -> Option<Ir> {
    let p = &s.plan;
    if !covers(p) {
        return None;
    }
    let mut l = L {
        b: Builder::new(),
        cse: HashMap::new(),
        oow: None,
    };
    if s.persp {
        let one = l.k(1.0);
        let w = l.op(Op::Interp(PLANE_W));
        l.oow = Some(l.b.push(Op::Div(one, w)));
    }
    let mut frag = [Val(0); 4];
    for (ch, f) in frag.iter_mut().enumerate() {
        *f = if p.flat {
            l.op(Op::Uniform(ch as u16))
        } else {
            l.vary(ch)
        };
    }
    let n = s.units as usize;
    let texs: Vec<V4> = (0..n)
        .map(|k| std::array::from_fn(|ch| l.op(Op::InputF((4 * k + ch) as u16))))
        .collect();
    let crossbar = s.envs[..n].iter().flatten().any(|c| c.crossbar);
    let mut prev = frag;
    for (k, env) in s.envs[..n].iter().enumerate() {
        let env = env.as_ref()?;
        let inp = Inputs {
            frag,
            tex: texs[k],
            prev,
            textures: if crossbar { &texs } else { &[] },
        };
        prev = apply(&mut l, env, &inp);
    }
    if p.separate_specular {
        for (ch, c) in prev.iter_mut().enumerate().take(3) {
            let k = VARY_SPEC + ch;
            let sv = if p.flat && k < VARY_FOG {
                l.op(Op::Uniform(k as u16))
            } else {
                l.vary(k)
            };
            *c = l.add(*c, sv);
        }
    }
    if let Some(fog) = &p.fog {
        let coord = l.vary(VARY_FOG);
        let f = if fog.mode == FogMode::Linear {
            // `factor`'s LINEAR branch: coord · scale + bias unfused, then `fsat`, whose
            // NaN → 0 and −0 → +0 are `Sat`'s.
            let (scale, bias) = (l.k(fog.scale), l.k(fog.bias));
            let m = l.mul(coord, scale);
            let a = l.add(m, bias);
            l.sat(a)
        } else {
            l.b.push(Op::Fog(coord, *fog))
        };
        let g = l.one_minus(f);
        for (ch, c) in prev.iter_mut().enumerate().take(3) {
            let k = l.k(fog.color[ch]);
            let kg = l.mul(k, g);
            let cf = l.mul(*c, f);
            *c = l.add(kg, cf);
        }
    }
    tail(&mut l.b, p, prev)?;
    l.b.finish().ok()
}

/// The depth plane at the pixel clamped to [0, 1] (NaN to 0), or the shader's depth
/// `written` clamped as `lp_build_depth_clamp` does (`lp_build_clamp`: `minps` with 1,
/// then `maxps` with 0, so NaN becomes 1, as probed against llvmpipe), quantised as
/// `format` stores it (`fragment::span::quantize_depth`); `None` for a format the engine
/// does not draw.
fn quantised_depth(b: &mut Builder, format: DepthFormat, written: Option<Val>) -> Option<Val> {
    let z = match written {
        Some(z) => {
            let (one, zero) = (b.f32(1.0), b.f32(0.0));
            let z = b.push(Op::Min(z, one));
            b.push(Op::Max(z, zero))
        }
        None => {
            let z = b.push(Op::Interp(PLANE_Z));
            b.push(Op::Sat(z))
        }
    };
    Some(match format {
        DepthFormat::Z24 => {
            let scale = b.f32(16_777_215.0);
            let z = b.mul(z, scale);
            b.push(Op::CvtRne(z))
        }
        DepthFormat::Z32F => b.push(Op::Bits(z)),
        DepthFormat::Z16 => {
            // f32(f32(z · 65535/65536) + 128) keeps the rounded value in the low bits.
            let (k, h) = (b.f32(65535.0 / 65536.0), b.f32(128.0));
            let v = b.mul(z, k);
            let v = b.add(v, h);
            let v = b.push(Op::Bits(v));
            let m = b.i32(0xFFFF);
            b.push(Op::And(v, m))
        }
        _ => return None,
    })
}

/// The per-fragment operations after the colour, in the order of [`lower`]: the unorm8
/// pack of `color`, the alpha test, the stencil and depth tests (plane [`PLANE_Z`];
/// [`Op::StencilDepth`] when the plan tests stencil), blending, the colour mask and the
/// store, into every draw buffer the plan has (fixed function writes its colour to
/// each). `None` when the depth format is not lowered.
pub fn tail(b: &mut Builder, p: &FragPlan, color: [Val; 4]) -> Option<()> {
    tail_buffers(b, p, &[color; 1 + MORE_COLORS], None, false)
}

/// [`tail`] with draw buffer k's colour `colors[k]` (a fragment shader's
/// `gl_FragData[k]`); the alpha test reads draw buffer 0's. Each draw buffer is blended
/// and masked alike (GL 2.0 has one blend state and one colour mask). A shader's
/// `gl_FragDepth` value `written` replaces the interpolated depth in the tests.
///
/// With `host` the program stops after the tests: draw buffer k's colour channel c is
/// its [`Op::Output`] `4k + c` (unclamped), and the caller stores the live lanes; a
/// plan of [`tests_in_walk`] (`host` only) leaves the stencil and depth tests to the
/// caller too
/// (`engine::draw`: wide, sRGB and logic-op targets and the formats without a packed
/// RGBA8 word, through the per-fragment stores of `crate::fragment`).
pub fn tail_buffers(
    b: &mut Builder,
    p: &FragPlan,
    colors: &[[Val; 4]; 1 + MORE_COLORS],
    written: Option<Val>,
    host: bool,
) -> Option<()> {
    let px = b.push(Op::PackUnorm8(colors[0]));
    alpha_test(b, p, px);
    if tests_in_walk(p) {
        // The walk tests each sample ([`DEPTH_OUTPUT`]).
        assert!(host, "a variant whose walk tests also stores there");
        if let Some(z) = written {
            b.push(Op::Output(DEPTH_OUTPUT, z));
        }
    } else if let Some(stencil) = p.stencil {
        let depth = p.depth.map(|d| (d.func, d.write));
        let z = match p.depth {
            Some(d) => quantised_depth(b, d.format, written)?,
            None => b.i32(0),
        };
        b.push(Op::StencilDepth { stencil, depth, z });
    } else if let Some(d) = p.depth {
        let q = quantised_depth(b, d.format, written)?;
        b.push(Op::DepthTest {
            func: d.func,
            write: d.write,
            z: q,
        });
    }
    let mut mask = 0u32;
    for (ch, &m) in p.color_mask.iter().enumerate() {
        if m {
            mask |= 0xFF << (8 * ch);
        }
    }
    if mask == 0 {
        return Some(());
    }
    for (n, c) in colors.iter().enumerate() {
        if n > 0 && p.more_buffers & 1 << (n - 1) == 0 {
            continue;
        }
        if host {
            for (ch, &v) in c.iter().enumerate() {
                b.push(Op::Output((4 * n + ch) as u16, v));
            }
            continue;
        }
        let px = match n > 0 && *c != colors[0] {
            true => b.push(Op::PackUnorm8(*c)),
            false => px,
        };
        store(b, p, mask, n as u8, px);
    }
    Some(())
}

/// A program's colours with a smooth line's or point's coverage (the draw module's aaline
/// and aapoint stages, which rewrite the fragment shader): every colour's alpha times the
/// coverage computed from the stage's four varyings at [`PLANE_VARY`]` + k` (read as a
/// program reads a varying: the plane times `1 / w_plane`), and a point's lanes outside
/// the unit disc killed. The arithmetic is [`crate::raster::smooth::coverage`]'s.
pub fn smooth_colors(
    b: &mut Builder,
    s: crate::raster::smooth::Smooth,
    colors: &[[Val; 4]; 1 + MORE_COLORS],
) -> [[Val; 4]; 1 + MORE_COLORS] {
    use crate::raster::smooth::Smooth;
    let k = match s {
        Smooth::Line(k) | Smooth::Point(k) => k as u16,
    };
    let one = b.f32(1.0);
    let w_plane = b.push(Op::Interp(PLANE_W));
    let oow = b.push(Op::Div(one, w_plane));
    let [x, y, z, w] = [0, 1, 2, 3].map(|c| {
        let a = b.push(Op::Interp(PLANE_VARY + k + c));
        b.push(Op::Mul(a, oow))
    });
    let cov = match s {
        Smooth::Line(_) => {
            let ax = b.push(Op::Un(Un::Abs, x));
            let az = b.push(Op::Un(Un::Abs, z));
            let (dy, dw) = (b.push(Op::Sub(y, ax)), b.push(Op::Sub(w, az)));
            let (sy, sw) = (b.push(Op::Sat(dy)), b.push(Op::Sat(dw)));
            b.push(Op::Mul(sy, sw))
        }
        Smooth::Point(_) => {
            let (xx, yy) = (b.push(Op::Mul(x, x)), b.push(Op::Mul(y, y)));
            let d = b.push(Op::Add(xx, yy));
            // Kill where `w < d` (a NaN keeps the lane): the complement of that mask.
            let out = b.push(Op::FCmp(FCmp::Lt, w, d));
            let (eq, ne) = (
                b.push(Op::FCmp(FCmp::Eq, w, w)),
                b.push(Op::FCmp(FCmp::Ne, w, w)),
            );
            let all = b.push(Op::Or(eq, ne));
            let keep = b.push(Op::Xor(out, all));
            b.push(Op::Kill(keep));
            let inner = b.push(Op::FCmp(FCmp::Ge, z, d));
            let wz = b.push(Op::Sub(w, z));
            let r = b.push(Op::Div(one, wz));
            let wd = b.push(Op::Sub(w, d));
            let scaled = b.push(Op::Mul(r, wd));
            b.push(Op::Select(inner, scaled, w))
        }
    };
    let mut out = *colors;
    let first = b.push(Op::Mul(colors[0][3], cov));
    for (o, c) in out.iter_mut().zip(colors) {
        o[3] = match c[3] == colors[0][3] {
            true => first,
            false => b.push(Op::Mul(c[3], cov)),
        };
    }
    out
}

/// Blends packed colour `px` into draw buffer `n`, keeps the channels `mask` leaves out,
/// and stores it.
fn store(b: &mut Builder, p: &FragPlan, mask: u32, n: u8, px: Val) {
    let full = mask == u32::MAX;
    let mut out = px;
    if p.blend.is_some() || !full {
        let dst = b.push(Op::LoadColor(n));
        if let Some(bl) = p.blend {
            out = b.push(Op::Blend(bl, px, dst));
        }
        if !full {
            let (m, keep) = (b.i32(mask as i32), b.i32(!mask as i32));
            let o = b.push(Op::And(out, m));
            let d = b.push(Op::And(dst, keep));
            out = b.push(Op::Or(o, d));
        }
    }
    b.push(Op::StoreColor(n, out));
}
