//! The executor's precompiled kernels: one function per operation kind and
//! instruction-set level, each running its operation over every chunk of a batch.
//!
//! A kernel body is written once, generic over a [`Lanes`] backend (8 lanes in an AVX2
//! register, or an array of 8 for the portable levels), and instantiated per level by
//! [`level!`] as a `#[target_feature]` function, so that it compiles to that level's
//! instructions and fuses `fmuladd` exactly where the level fuses. A [`Table`] holds one
//! level's function pointers; [`super::exec`] picks one per operation at compile time.

use super::exec::{Ctx, Step};
use super::ir::{FCmp, IOp, Un, FCMPS, IOPS, UNS};
use crate::fixed_function::gallivm_math as gm;
use crate::pipe::CompareFunc;

#[cfg(target_arch = "x86_64")]
pub(super) mod lanes_avx2;
mod lanes_portable;

/// A kernel: runs step `s` over the batch in `c`.
pub(super) type Kernel = unsafe fn(&mut Ctx<'_>, &Step);

/// Eight lanes of one backend: how a kernel loads, computes and stores.
///
/// # Safety
/// The AVX2 backend's methods may only run on a CPU with AVX2 (and FMA when fused); the
/// kernels that use it are compiled with those features and chosen only on such CPUs.
pub(super) trait Lanes {
    /// Whether `fmuladd` fuses at this level.
    const FUSED: bool;
    /// Eight f32.
    type F: Copy;
    /// Eight i32 (also masks).
    type I: Copy;
    /// Loads eight f32.
    unsafe fn ld_f(p: *const [u32; 8]) -> Self::F;
    /// Stores eight f32.
    unsafe fn st_f(p: *mut [u32; 8], v: Self::F);
    /// Loads eight i32.
    unsafe fn ld_i(p: *const [u32; 8]) -> Self::I;
    /// Stores eight i32.
    unsafe fn st_i(p: *mut [u32; 8], v: Self::I);
    /// Every lane `v`.
    unsafe fn splat_i(v: i32) -> Self::I;
    /// `x + lane` for lanes 0..8.
    unsafe fn lane_x(x: f32) -> Self::F;
    /// Every lane `y`.
    unsafe fn splat_f(y: f32) -> Self::F;
    /// `a + b`.
    fn add(a: Self::F, b: Self::F) -> Self::F;
    /// `a - b`.
    fn sub(a: Self::F, b: Self::F) -> Self::F;
    /// `a * b`.
    fn mul(a: Self::F, b: Self::F) -> Self::F;
    /// `a / b`.
    fn div(a: Self::F, b: Self::F) -> Self::F;
    /// `minps`.
    fn min(a: Self::F, b: Self::F) -> Self::F;
    /// `maxps`.
    fn max(a: Self::F, b: Self::F) -> Self::F;
    /// `fmuladd(a, b, c)` at this level.
    unsafe fn mad(a: Self::F, b: Self::F, c: Self::F) -> Self::F;
    /// `cvtps2dq`.
    fn cvt(a: Self::F) -> Self::I;
    /// `cvttps2dq`.
    fn cvtt(a: Self::F) -> Self::I;
    /// `roundps` toward −∞.
    fn floor(a: Self::F) -> Self::F;
    /// `sqrtps`.
    fn sqrt(a: Self::F) -> Self::F;
    /// gallivm's `exp2` ([`gm::exp2`]) in every lane.
    unsafe fn exp2(a: Self::F) -> Self::F;
    /// gallivm's `log2_safe` ([`gm::log2_safe`]) in every lane.
    unsafe fn log2(a: Self::F) -> Self::F;
    /// gallivm's `pow` ([`gm::pow`]) in every lane.
    unsafe fn pow(a: Self::F, b: Self::F) -> Self::F;
    /// The bits of f32 lanes.
    fn fbits(a: Self::F) -> Self::I;
    /// i32 lanes' bits as f32.
    fn ibits(a: Self::I) -> Self::F;
    /// A wrapping integer operation.
    fn ibin(op: IOp, a: Self::I, b: Self::I) -> Self::I;
    /// `a ^ b`.
    fn xor(a: Self::I, b: Self::I) -> Self::I;
    /// Signed `a > b` as a mask.
    fn igt(a: Self::I, b: Self::I) -> Self::I;
    /// `a == b` as a mask.
    fn ieq(a: Self::I, b: Self::I) -> Self::I;
    /// `cvtdq2ps`.
    fn itof(a: Self::I) -> Self::F;
    /// A float comparison as a mask.
    fn fcmp(op: FCmp, a: Self::F, b: Self::F) -> Self::I;
    /// `a FUNC b` as a mask, for values in `0..2^31`.
    unsafe fn icmp(func: CompareFunc, a: Self::I, b: Self::I) -> Self::I;
    /// `a & b`.
    fn and(a: Self::I, b: Self::I) -> Self::I;
    /// `a | b`.
    fn or(a: Self::I, b: Self::I) -> Self::I;
    /// Logical shift right of every lane by `n`.
    unsafe fn shr(a: Self::I, n: u32) -> Self::I;
    /// Shift left of every lane by `n`.
    unsafe fn shl(a: Self::I, n: u32) -> Self::I;
    /// Per lane `a` where `m` is set, else `b`.
    fn select(m: Self::I, a: Self::I, b: Self::I) -> Self::I;
    /// Whether any lane of the mask is set.
    fn any(m: Self::I) -> bool;
    /// The number of set lanes of the mask.
    fn count(m: Self::I) -> u32;
    /// The depth test at `p` (of which `avail` values lie in the buffer): returns the
    /// live lanes that pass, storing `q` there when `write`.
    unsafe fn depth(
        func: CompareFunc,
        write: bool,
        q: Self::I,
        live: Self::I,
        p: *mut u32,
        avail: usize,
    ) -> Self::I;
    /// The packed colours at `p` in the live lanes (others undefined).
    unsafe fn load_color(p: *const u32, live: Self::I) -> Self::I;
    /// Stores `v` at `p` in the live lanes.
    unsafe fn store_color(p: *mut u32, avail: usize, live: Self::I, v: Self::I);
    /// 8-bit blending of `s` over `d` (`over`: the plan is SRC_ALPHA/ONE_MINUS_SRC_ALPHA).
    unsafe fn blend(plan: &super::ir::Blend8, over: bool, s: Self::I, d: Self::I) -> Self::I;
}

/// The generic kernel bodies, one per operation kind.
mod body {
    use super::*;

    /// Defines a binary f32 kernel over [`Lanes::$m`].
    macro_rules! bin_f {
        ($($name:ident => $m:ident;)*) => {$(
            #[inline(always)]
            pub(in super::super) unsafe fn $name<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
                // SAFETY: the step's slots lie in the register file (compile), the
                // backend's features are the caller's (the level's target features).
                unsafe {
                    for k in 0..c.n {
                        let a = V::ld_f(c.reg(s.a[0], k));
                        let b = V::ld_f(c.reg(s.a[1], k));
                        V::st_f(c.reg(s.d, k), V::$m(a, b));
                    }
                }
            }
        )*};
    }

    bin_f! {
        add => add;
        sub => sub;
        mul => mul;
        div => div;
        min => min;
        max => max;
    }

    /// The safety argument shared by the kernels below: every slot a step names lies in
    /// the register file ([`super::super::exec::compile`]), every chunk's live lanes lie
    /// in the buffers ([`super::super::exec::Program::run`] checks), and the kernel runs
    /// compiled with its backend's features.
    macro_rules! each {
        ($c:ident, $k:ident, $body:block) => {
            // SAFETY: see `each!`'s doc.
            unsafe {
                for $k in 0..$c.n $body
            }
        };
    }

    /// A constant in every lane of every chunk slot of the batch.
    #[inline(always)]
    pub(in super::super) unsafe fn constant<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        each!(c, k, { V::st_i(c.reg(s.d, k), V::splat_i(s.imm as i32)) });
    }

    /// The pixels' x.
    #[inline(always)]
    pub(in super::super) unsafe fn frag_x<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        each!(c, k, { V::st_f(c.reg(s.d, k), V::lane_x(c.chunk(k).fx)) });
    }

    /// The pixels' y.
    #[inline(always)]
    pub(in super::super) unsafe fn frag_y<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        each!(c, k, { V::st_f(c.reg(s.d, k), V::splat_f(c.chunk(k).fy)) });
    }

    /// A plane at the pixels: `fmuladd(dady, y, fmuladd(dadx, x, a0))`.
    #[inline(always)]
    pub(in super::super) unsafe fn interp<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        each!(c, k, {
            let ch = c.chunk(k);
            let [a0, dx, dy] = c.planes[ch.planes as usize + s.imm as usize];
            let (a0, dx, dy) = (V::splat_f(a0), V::splat_f(dx), V::splat_f(dy));
            let v = V::mad(dy, V::splat_f(ch.fy), V::mad(dx, V::lane_x(ch.fx), a0));
            V::st_f(c.reg(s.d, k), v)
        });
    }

    /// Input stream `imm`.
    #[inline(always)]
    pub(in super::super) unsafe fn input<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        let src = c.inputs[s.imm as usize];
        each!(c, k, {
            let p = src.as_ptr().add(c.base + k);
            V::st_i(c.reg(s.d, k), V::ld_i(p))
        });
    }

    /// `fmuladd`.
    #[inline(always)]
    pub(in super::super) unsafe fn mad<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        each!(c, k, {
            let a = V::ld_f(c.reg(s.a[0], k));
            let b = V::ld_f(c.reg(s.a[1], k));
            let d = V::ld_f(c.reg(s.a[2], k));
            V::st_f(c.reg(s.d, k), V::mad(a, b, d))
        });
    }

    /// Clamp to [0, 1], NaN → 0.
    #[inline(always)]
    pub(in super::super) unsafe fn sat<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        each!(c, k, {
            let a = V::ld_f(c.reg(s.a[0], k));
            let v = V::min(V::max(a, V::splat_f(0.0)), V::splat_f(1.0));
            V::st_f(c.reg(s.d, k), v)
        });
    }

    /// `cvtps2dq`.
    #[inline(always)]
    pub(in super::super) unsafe fn cvt<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        each!(c, k, {
            V::st_i(c.reg(s.d, k), V::cvt(V::ld_f(c.reg(s.a[0], k))))
        });
    }

    /// The bits of an f32 value.
    #[inline(always)]
    pub(in super::super) unsafe fn bits<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        each!(c, k, { V::st_i(c.reg(s.d, k), V::ld_i(c.reg(s.a[0], k))) });
    }

    /// Float comparison `imm` (its code in [`FCMPS`]).
    #[inline(always)]
    pub(in super::super) unsafe fn fcmp<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        let op = FCMPS[s.imm as usize];
        each!(c, k, {
            let a = V::ld_f(c.reg(s.a[0], k));
            let b = V::ld_f(c.reg(s.a[1], k));
            V::st_i(c.reg(s.d, k), V::fcmp(op, a, b))
        });
    }

    /// A unary f32 function (`imm`: its code in [`UNS`]).
    #[inline(always)]
    pub(in super::super) unsafe fn unary<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        /// The unary kernel's loop with lane function `$f` (a vector expression of `$a`).
        macro_rules! map {
            (|$a:ident| $f:expr) => {
                each!(c, k, {
                    let $a = V::ld_f(c.reg(s.a[0], k));
                    V::st_f(c.reg(s.d, k), $f)
                })
            };
        }
        /// The loop with a scalar gallivm function per lane (a loop, not a closure, so
        /// that it compiles with the kernel's features; see `fog`).
        macro_rules! per_lane {
            ($f:path $(, $e:expr)*) => {
                each!(c, k, {
                    let a = *c.reg(s.a[0], k);
                    let mut out = [0u32; 8];
                    for (o, &v) in out.iter_mut().zip(a.iter()) {
                        *o = $f(f32::from_bits(v), $($e,)* V::FUSED).to_bits();
                    }
                    *c.reg(s.d, k) = out
                })
            };
        }
        // SAFETY: the kernel runs with its backend's features.
        let sign = unsafe { V::splat_i(i32::MIN) };
        /// The sign flipped (a macro, not a closure: see `fog`).
        macro_rules! neg {
            ($a:expr) => {
                V::ibits(V::xor(V::fbits($a), sign))
            };
        }
        match UNS[s.imm as usize] {
            Un::Floor => map!(|a| V::floor(a)),
            Un::Ceil => map!(|a| neg!(V::floor(neg!(a)))),
            Un::Sqrt => map!(|a| V::sqrt(a)),
            Un::Abs => map!(|a| V::ibits(V::and(V::fbits(a), V::splat_i(i32::MAX)))),
            Un::Neg => map!(|a| neg!(a)),
            Un::Exp2 => map!(|a| V::exp2(a)),
            Un::Log2 => map!(|a| V::log2(a)),
            Un::Sin => per_lane!(gm::sin_or_cos, false),
            Un::Cos => per_lane!(gm::sin_or_cos, true),
        }
    }

    /// gallivm's `pow` ([`Lanes::pow`]).
    #[inline(always)]
    pub(in super::super) unsafe fn pow<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        each!(c, k, {
            let a = V::ld_f(c.reg(s.a[0], k));
            let b = V::ld_f(c.reg(s.a[1], k));
            V::st_f(c.reg(s.d, k), V::pow(a, b))
        });
    }

    /// A wrapping integer operation (`imm`: its code in [`IOPS`]).
    #[inline(always)]
    pub(in super::super) unsafe fn ibin<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        let op = IOPS[s.imm as usize];
        each!(c, k, {
            let a = V::ld_i(c.reg(s.a[0], k));
            let b = V::ld_i(c.reg(s.a[1], k));
            V::st_i(c.reg(s.d, k), V::ibin(op, a, b))
        });
    }

    /// `a ^ b`.
    #[inline(always)]
    pub(in super::super) unsafe fn xor<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        each!(c, k, {
            let a = V::ld_i(c.reg(s.a[0], k));
            V::st_i(c.reg(s.d, k), V::xor(a, V::ld_i(c.reg(s.a[1], k))))
        });
    }

    /// Signed integer comparison (`imm`: its code in [`FCMPS`]).
    #[inline(always)]
    pub(in super::super) unsafe fn scmp<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        let op = FCMPS[s.imm as usize];
        // SAFETY: the kernel runs with its backend's features.
        let ones = unsafe { V::splat_i(-1) };
        each!(c, k, {
            let a = V::ld_i(c.reg(s.a[0], k));
            let b = V::ld_i(c.reg(s.a[1], k));
            let m = match op {
                FCmp::Lt => V::igt(b, a),
                FCmp::Gt => V::igt(a, b),
                FCmp::Le => V::xor(V::igt(a, b), ones),
                FCmp::Ge => V::xor(V::igt(b, a), ones),
                FCmp::Eq => V::ieq(a, b),
                FCmp::Ne => V::xor(V::ieq(a, b), ones),
            };
            V::st_i(c.reg(s.d, k), m)
        });
    }

    /// i32 → f32.
    #[inline(always)]
    pub(in super::super) unsafe fn itof<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        each!(c, k, {
            V::st_f(c.reg(s.d, k), V::itof(V::ld_i(c.reg(s.a[0], k))))
        });
    }

    /// f32 → i32, truncated.
    #[inline(always)]
    pub(in super::super) unsafe fn ftoi<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        each!(c, k, {
            V::st_i(c.reg(s.d, k), V::cvtt(V::ld_f(c.reg(s.a[0], k))))
        });
    }

    /// The bits of an i32 value as f32 (a copy).
    #[inline(always)]
    pub(in super::super) unsafe fn from_bits<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        each!(c, k, { V::st_i(c.reg(s.d, k), V::ld_i(c.reg(s.a[0], k))) });
    }

    /// Integer comparison with the function in `imm` ([`super::super::exec::func_of`]).
    #[inline(always)]
    pub(in super::super) unsafe fn icmp<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        let func = super::super::exec::func_of(s.imm);
        each!(c, k, {
            let a = V::ld_i(c.reg(s.a[0], k));
            let b = V::ld_i(c.reg(s.a[1], k));
            V::st_i(c.reg(s.d, k), V::icmp(func, a, b))
        });
    }

    /// Uniform `imm` in every lane.
    #[inline(always)]
    pub(in super::super) unsafe fn uniform<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        let u = c.uniforms[s.imm as usize];
        each!(c, k, { V::st_f(c.reg(s.d, k), V::splat_f(u)) });
    }

    /// `a & b`.
    #[inline(always)]
    pub(in super::super) unsafe fn and<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        each!(c, k, {
            let a = V::ld_i(c.reg(s.a[0], k));
            V::st_i(c.reg(s.d, k), V::and(a, V::ld_i(c.reg(s.a[1], k))))
        });
    }

    /// `a | b`.
    #[inline(always)]
    pub(in super::super) unsafe fn or<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        each!(c, k, {
            let a = V::ld_i(c.reg(s.a[0], k));
            V::st_i(c.reg(s.d, k), V::or(a, V::ld_i(c.reg(s.a[1], k))))
        });
    }

    /// The fog factor of fog plan `imm`, lane by lane (the scalar function itself).
    #[inline(always)]
    pub(in super::super) unsafe fn fog<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        let f = c.fogs[s.imm as usize];
        // A loop, not `map` with a closure: a closure body is compiled without the
        // kernel's target features, and the polynomial's `mul_add` became calls to `fmaf`.
        each!(c, k, {
            let a = *c.reg(s.a[0], k);
            let mut out = [0u32; 8];
            for (o, &v) in out.iter_mut().zip(a.iter()) {
                *o = f.factor(f32::from_bits(v)).to_bits();
            }
            *c.reg(s.d, k) = out
        });
    }

    /// Byte `imm` as an integer.
    #[inline(always)]
    pub(in super::super) unsafe fn byte<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        each!(c, k, {
            let a = V::shr(V::ld_i(c.reg(s.a[0], k)), 8 * s.imm);
            V::st_i(c.reg(s.d, k), V::and(a, V::splat_i(255)))
        });
    }

    /// Byte `imm` as `u8 · f32(1/255)`.
    #[inline(always)]
    pub(in super::super) unsafe fn unpack<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        // SAFETY: the kernel runs with its backend's features.
        let inv = unsafe { V::splat_f(crate::texture::sample::INV_255) };
        each!(c, k, {
            let a = V::shr(V::ld_i(c.reg(s.a[0], k)), 8 * s.imm);
            let f = V::itof(V::and(a, V::splat_i(255)));
            V::st_f(c.reg(s.d, k), V::mul(f, inv))
        });
    }

    /// Four channels to unorm8, packed.
    #[inline(always)]
    pub(in super::super) unsafe fn pack<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        // SAFETY: the kernel runs with its backend's features.
        let (zero, one, scale) = unsafe { (V::splat_f(0.0), V::splat_f(1.0), V::splat_f(255.0)) };
        each!(c, k, {
            let mut acc = V::splat_i(0);
            for ch in 0..4 {
                let v = V::ld_f(c.reg(s.a[ch], k));
                let u = V::cvt(V::mul(V::min(V::max(v, zero), one), scale));
                acc = V::or(acc, V::shl(u, 8 * ch as u32));
            }
            V::st_i(c.reg(s.d, k), acc)
        });
    }

    /// Select.
    #[inline(always)]
    pub(in super::super) unsafe fn select<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        each!(c, k, {
            let m = V::ld_i(c.reg(s.a[0], k));
            let a = V::ld_i(c.reg(s.a[1], k));
            let b = V::ld_i(c.reg(s.a[2], k));
            V::st_i(c.reg(s.d, k), V::select(m, a, b))
        });
    }

    /// Clears the live lanes the mask leaves out.
    #[inline(always)]
    pub(in super::super) unsafe fn kill<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        each!(c, k, {
            let live = V::ld_i(c.reg(0, k));
            let kept = V::and(live, V::ld_i(c.reg(s.a[0], k)));
            c.counts.killed += u64::from(V::count(live) - V::count(kept));
            V::st_i(c.reg(0, k), kept)
        });
    }

    /// The depth test (`imm`: function code, bit 8 = write).
    #[inline(always)]
    pub(in super::super) unsafe fn depth<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        let func = super::super::exec::func_of(s.imm & 0xFF);
        let write = s.imm & 0x100 != 0;
        each!(c, k, {
            let live = V::ld_i(c.reg(0, k));
            if !V::any(live) {
                continue;
            }
            let idx = c.chunk(k).idx;
            let q = V::ld_i(c.reg(s.a[0], k));
            let p = c.depth.add(idx);
            let pass = V::depth(func, write, q, live, p, c.depth_len - idx);
            let (n, m) = (V::count(live), V::count(pass));
            c.counts.depth_reads += u64::from(n);
            c.counts.depth_failed += u64::from(n - m);
            V::st_i(c.reg(0, k), pass)
        });
    }

    /// The stencil test with plan `imm & 0xFFFF` (the run's face) and the depth test
    /// (bits 16–19: function code, bit 20: write, bit 21: depth tested) lane by lane, as
    /// `fragment::span::stencil_depth`.
    #[inline(always)]
    pub(in super::super) unsafe fn stencil_depth<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        let plan = c.stencils[(s.imm & 0xFFFF) as usize];
        let sp = if c.front { plan.front } else { plan.back };
        let func = super::super::exec::func_of(s.imm >> 16 & 0xF);
        let (write, depth) = (s.imm & 1 << 20 != 0, s.imm & 1 << 21 != 0);
        // SAFETY: a live lane lies inside the stencil buffer, and inside the depth buffer
        // when depth is tested (`Program::run` checks both); slots as in every kernel.
        unsafe {
            for k in 0..c.n {
                let mut live = *c.reg(0, k);
                if live == [0; 8] {
                    continue;
                }
                let idx = c.chunk(k).idx;
                let q = *c.reg(s.a[0], k);
                for (i, l) in live.iter_mut().enumerate() {
                    if *l == 0 {
                        continue;
                    }
                    c.counts.stencil_reads += 1;
                    let st = c.stencil.add(idx + i);
                    if !sp.test(*st) {
                        *st = sp.update(sp.fail, *st);
                        *l = 0;
                        c.counts.stencil_failed += 1;
                        continue;
                    }
                    if depth {
                        c.counts.depth_reads += 1;
                        let d = c.depth.add(idx + i);
                        if func.test(q[i], *d) {
                            if write {
                                *d = q[i];
                            }
                        } else {
                            *st = sp.update(sp.zfail, *st);
                            *l = 0;
                            c.counts.depth_failed += 1;
                            continue;
                        }
                    }
                    *st = sp.update(sp.zpass, *st);
                }
                *c.reg(0, k) = live;
            }
        }
    }

    /// The colour buffer at the live lanes.
    #[inline(always)]
    pub(in super::super) unsafe fn load_color<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        each!(c, k, {
            let live = V::ld_i(c.reg(0, k));
            // A chunk without live lanes may lie past the buffer: no access is made.
            let p = c.colors[s.imm as usize].0.wrapping_add(c.chunk(k).idx);
            V::st_i(c.reg(s.d, k), V::load_color(p, live))
        });
    }

    /// Blending with plan `imm` (bit 16: the plan is "over").
    #[inline(always)]
    pub(in super::super) unsafe fn blend<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        let plan = c.blends[(s.imm & 0xFFFF) as usize];
        let over = s.imm & 0x1_0000 != 0;
        each!(c, k, {
            let a = V::ld_i(c.reg(s.a[0], k));
            let b = V::ld_i(c.reg(s.a[1], k));
            V::st_i(c.reg(s.d, k), V::blend(&plan, over, a, b))
        });
    }

    /// Writes the live lanes.
    #[inline(always)]
    pub(in super::super) unsafe fn store_color<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        each!(c, k, {
            let live = V::ld_i(c.reg(0, k));
            if !V::any(live) {
                continue;
            }
            let idx = c.chunk(k).idx;
            let v = V::ld_i(c.reg(s.a[0], k));
            let (p, len) = c.colors[s.imm as usize];
            V::store_color(p.add(idx), len - idx, live, v)
        });
    }

    /// `lp_build_ddx`: per 2x2 quad and row, right minus left (lanes 2j, 2j + 1).
    #[inline(always)]
    pub(in super::super) unsafe fn ddx<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        each!(c, k, {
            let a = *c.reg(s.a[0], k);
            let mut d = [0u32; 8];
            for j in 0..4 {
                let x = f32::from_bits(a[2 * j + 1]) - f32::from_bits(a[2 * j]);
                d[2 * j] = x.to_bits();
                d[2 * j + 1] = x.to_bits();
            }
            *c.reg(s.d, k) = d
        });
    }

    /// `lp_build_ddy`: per 2x2 quad and column, the pair's second chunk (the bottom
    /// row) minus its first (a chunk without its pair gives its own difference, 0).
    #[inline(always)]
    pub(in super::super) unsafe fn ddy<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        // SAFETY: the slots lie in the register file, chunks below `c.n` (compile, run).
        unsafe {
            let mut k = 0;
            while k < c.n {
                let j = (k + 1).min(c.n - 1);
                let (top, bottom) = (*c.reg(s.a[0], k), *c.reg(s.a[0], j));
                let d: [u32; 8] = std::array::from_fn(|i| {
                    (f32::from_bits(bottom[i]) - f32::from_bits(top[i])).to_bits()
                });
                *c.reg(s.d, k) = d;
                *c.reg(s.d, j) = d;
                k += 2;
            }
        }
    }

    /// Samples lookup `imm` at the coordinates in `a[0..3]` with the level-of-detail
    /// argument in `a[3]`, a chunk pair at a time,
    /// into the run's texels (`Ctx::texels`).
    #[inline(always)]
    pub(in super::super) unsafe fn sample<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        use super::super::exec::{QuadCoords, MAX_BATCH};
        let lookup = s.imm as usize;
        let f = |v: [u32; 8]| v.map(f32::from_bits);
        let lanes = |bits: u8| std::array::from_fn(|i| bits >> i & 1 != 0);
        // SAFETY: the slots lie in the register file and chunks below `c.n` (compile,
        // run); the texels hold `TEXEL_STREAMS` streams of `MAX_BATCH` chunks (run) and
        // the lookup's streams are below it (compile).
        unsafe {
            let mut k = 0;
            while k < c.n {
                let j = (k + 1).min(c.n - 1);
                let rows = |slot: u16| [f(*c.reg(slot, k)), f(*c.reg(slot, j))];
                let live1 = if j == k { 0 } else { c.chunk(j).live };
                let q = QuadCoords {
                    s: rows(s.a[0]),
                    t: rows(s.a[1]),
                    r: rows(s.a[2]),
                    l: rows(s.a[3]),
                    live: [lanes(c.chunk(k).live), lanes(live1)],
                };
                let mut out = [[[0.0, 0.0, 0.0, 1.0]; 8]; 2];
                if let Some(sm) = c.sampler {
                    sm.sample(lookup, &q, &mut out);
                }
                let pair = [(0, k), (1, j)];
                for (row, chunk) in pair.into_iter().take(1 + usize::from(j > k)) {
                    let texels = &out[row];
                    let mut at = 4 * lookup * MAX_BATCH + chunk;
                    for ch in 0..4 {
                        *c.texels.add(at) = texels.map(|t| t[ch].to_bits());
                        at += MAX_BATCH;
                    }
                }
                k += 2;
            }
        }
    }

    /// Texel stream `imm` (`Ctx::texels`).
    #[inline(always)]
    pub(in super::super) unsafe fn texel<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        let at = s.imm as usize * super::super::exec::MAX_BATCH;
        each!(c, k, { *c.reg(s.d, k) = *c.texels.add(at + k) });
    }

    /// Copies slot `a[0]` to slot `d` (a mutable variable's load or store).
    #[inline(always)]
    pub(in super::super) unsafe fn copy<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        each!(c, k, { *c.reg(s.d, k) = *c.reg(s.a[0], k) });
    }

    /// The end of a loop's body: jumps back to body step `imm` while any lane of mask
    /// `a[0]` is set in a chunk of the batch and the limiter allows
    /// ([`super::super::exec::LOOP_LIMIT`]; llvmpipe decrements first and goes on while
    /// it stays above zero).
    #[inline(always)]
    pub(in super::super) unsafe fn loop_end<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        let mut any = false;
        each!(c, k, { any |= V::any(V::ld_i(c.reg(s.a[0], k))) });
        c.limiter = c.limiter.saturating_sub(1);
        if any && c.limiter > 0 {
            c.jump = Some(s.imm as usize);
        }
    }

    /// Writes the value to output `imm` of each chunk (`Program::run_streams` sized the
    /// outputs: `outs_per` values per chunk, `imm` below it).
    #[inline(always)]
    pub(in super::super) unsafe fn output<V: Lanes>(c: &mut Ctx<'_>, s: &Step) {
        each!(c, k, {
            let at = (c.base + k) * c.outs_per + s.imm as usize;
            *c.outs.add(at) = *c.reg(s.a[0], k)
        });
    }
}

/// Calls `$cb!` with the kernel names after the tokens `$pre`: the list behind
/// [`Table`] and every level's module.
macro_rules! kernel_list {
    ($cb:ident!($($pre:tt)*)) => {
        $cb!($($pre)* constant, frag_x, frag_y, interp, input, uniform, add, sub, mul, div, min,
            max, mad, sat, cvt, bits, fcmp, icmp, and, or, fog, byte, unpack, pack, select, kill,
            depth, load_color, blend, store_color, unary, pow, ibin, xor, scmp, itof, ftoi,
            from_bits, output, ddx, ddy, sample, texel, stencil_depth, copy, loop_end);
    };
}

/// Declares [`Table`] from the kernel list.
macro_rules! table_type {
    ($($k:ident),*) => {
        /// One level's kernels, a field per operation kind.
        #[derive(Clone, Copy)]
        pub(super) struct Table {
            $(
                #[doc = concat!("The `", stringify!($k), "` kernel.")]
                pub $k: Kernel,
            )*
        }
    };
}
kernel_list!(table_type!());

/// One kernel of a level: the generic body compiled with the level's features.
macro_rules! one_kernel {
    ($v:ty, [$($feat:tt)*], $k:ident) => {
        $($feat)*
        #[inline(never)]
        unsafe fn $k(c: &mut Ctx<'_>, s: &Step) {
            // SAFETY: forwarded; this function is chosen only on CPUs with its features.
            unsafe { super::body::$k::<$v>(c, s) }
        }
    };
}

/// A level's kernels and their [`Table`], `TABLE`.
macro_rules! level_kernels {
    ($v:ty, $feat:tt, $($k:ident),*) => {
        $( one_kernel!($v, $feat, $k); )*
        /// This level's kernels.
        pub(in super::super) const TABLE: super::Table = super::Table { $($k),* };
    };
}

/// Defines module `$m` with the kernels of one level: backend `$v`, features `$feat`.
macro_rules! level {
    ($(#[$doc:meta])* $m:ident, $v:ty, $feat:tt) => {
        $(#[$doc])*
        pub(super) mod $m {
            use super::*;
            kernel_list!(level_kernels!($v, $feat,));
        }
    };
}

level!(
    /// Baseline: portable lanes, not fused.
    base, super::lanes_portable::Portable<false>, []
);
#[cfg(target_arch = "x86_64")]
level!(
    /// FMA without AVX2: portable lanes, fused.
    fma, super::lanes_portable::Portable<true>, [#[target_feature(enable = "fma")]]
);
#[cfg(target_arch = "x86_64")]
level!(
    /// AVX2 and FMA.
    avx2fma, super::lanes_avx2::Avx2<true>, [#[target_feature(enable = "avx2,fma")]]
);

/// The kernels for instruction-set level `isa` (which the CPU must have).
pub(super) fn table(isa: crate::cpu::Isa) -> &'static Table {
    use crate::cpu::Isa;
    match isa {
        #[cfg(target_arch = "x86_64")]
        Isa::Avx2Fma => &avx2fma::TABLE,
        #[cfg(target_arch = "x86_64")]
        Isa::Fma => &fma::TABLE,
        _ => &base::TABLE,
    }
}
