//! The compiled copies of the row walks, one per instruction-set level, each variant its
//! own function.
//!
//! A row walk is monomorphised over the plan's booleans (depth test, flat, perspective,
//! …) so that its per-pixel loop has no state branches, and compiled once per
//! [`crate::cpu::Isa`] so that it uses that level's instructions and fuses exactly when
//! llvmpipe does. Each (level, variant) pair is one `#[inline(never)]` function here,
//! generated from one body by [`walks!`]: the dispatch that picks it is a few matches and
//! one call, made once per triangle (or line, or span of a line).
//!
//! ## Why each variant is its own function
//! These walks used to be inlined whole into one entry function per level. LLVM optimises
//! a function on one thread and its cost grows faster than the function: four entry
//! points of 2.4–2.9 MB of machine code each made the release build take 20 minutes on
//! two cores, and unoptimised they needed stack frames of 4–6 MB (a test thread has 2).
//! As separate functions the same code compiles in parallel codegen units, each frame
//! holds one variant's locals, and the call costs one jump per triangle.

use super::prim_spans::RowSpans;
use super::textured::Chunk;
use crate::fragment::span::{Fused, Unfused};
use crate::fragment::FragPlan;
use crate::framebuffer::Target;
use crate::geometry::setup::SetupTriangle;
use crate::stats::Stats;
use crate::texture::fast::FastEnv;
use crate::texture::UnitPlan;

/// Expands `$body` once for each value of the three run-time booleans, with `$a`, `$b`
/// and `$c` bound to them as constants: how a row walk's variant is chosen.
macro_rules! with_flags {
    (($x:expr, $y:expr, $z:expr), |$a:ident, $b:ident, $c:ident| $body:expr) => {
        match ($x, $y, $z) {
            (false, false, false) => with_flags!(@ false, false, false, $a, $b, $c, $body),
            (false, false, true) => with_flags!(@ false, false, true, $a, $b, $c, $body),
            (false, true, false) => with_flags!(@ false, true, false, $a, $b, $c, $body),
            (false, true, true) => with_flags!(@ false, true, true, $a, $b, $c, $body),
            (true, false, false) => with_flags!(@ true, false, false, $a, $b, $c, $body),
            (true, false, true) => with_flags!(@ true, false, true, $a, $b, $c, $body),
            (true, true, false) => with_flags!(@ true, true, false, $a, $b, $c, $body),
            (true, true, true) => with_flags!(@ true, true, true, $a, $b, $c, $body),
        }
    };
    (@ $va:literal, $vb:literal, $vc:literal, $a:ident, $b:ident, $c:ident, $body:expr) => {{
        const $a: bool = $va;
        const $b: bool = $vb;
        const $c: bool = $vc;
        $body
    }};
}
pub(crate) use with_flags;

/// Expands `$body` once for each variant of the AVX2 span shader that `$plan` (a
/// `&FragPlan`) can take on a triangle with perspective flag `$persp`, with `$d` (depth
/// code), `$f` (flat), `$p` (perspective) and `$b` (blend code) bound to it as constants:
/// how the triangles' and the lines' AVX2 walks are chosen. Callers import it (it names
/// itself unqualified).
#[cfg(target_arch = "x86_64")]
macro_rules! with_simd_variant {
    (($plan:expr, $persp:expr), |$d:ident, $f:ident, $p:ident, $b:ident| $body:expr) => {{
        use crate::fragment::simd::{blend_code, depth_code, B_ANY, B_NONE, B_OVER};
        use crate::fragment::simd::{D_ANY, D_LEQUAL, D_LESS, D_NONE};
        let plan: &crate::fragment::FragPlan = $plan;
        let shape = (plan.flat, !plan.flat && $persp);
        with_simd_variant!(@pick depth_code(plan), [D_NONE, D_LESS, D_LEQUAL] D_ANY, $d: u8,
            with_simd_variant!(@pick blend_code(plan), [B_NONE, B_OVER] B_ANY, $b: u8,
                match shape {
                    (true, _) => with_simd_variant!(@shape true, false, $f, $p, $body),
                    (false, true) => with_simd_variant!(@shape false, true, $f, $p, $body),
                    (false, false) => with_simd_variant!(@shape false, false, $f, $p, $body),
                }
            )
        )
    }};
    (@pick $v:expr, [$($c:ident),*] $last:ident, $n:ident: $t:ty, $body:expr) => {
        match $v {
            $($c => {
                const $n: $t = $c;
                $body
            })*
            _ => {
                const $n: $t = $last;
                $body
            }
        }
    };
    (@shape $fv:literal, $pv:literal, $f:ident, $p:ident, $body:expr) => {{
        const $f: bool = $fv;
        const $p: bool = $pv;
        $body
    }};
}
#[cfg(target_arch = "x86_64")]
pub(crate) use with_simd_variant;

/// Expands `$body` with `$f` bound as a constant to whether the level's arithmetic `$m`
/// (a [`crate::fragment::span::Madd`]) fuses: how the 8-lane walks pick their FMA copy.
macro_rules! with_fused {
    ($m:ty, |$f:ident| $body:expr) => {
        if <$m as crate::fragment::span::Madd>::FUSED {
            const $f: bool = true;
            $body
        } else {
            const $f: bool = false;
            $body
        }
    };
}
pub(crate) use with_fused;

/// The row walks, listed once: each entry's doc, name, generic parameters, the generic
/// arguments that forward them, the arguments, and the walk it runs (with `M`, the level's
/// fusing, and `AVX2`, whether the level has AVX2). Calls `$callback!` with the list
/// after the tokens `$pre`; the trait [`Walks`] and each level's functions are made from it.
macro_rules! walk_list {
    ($callback:ident!($($pre:tt)*)) => {
        $callback!($($pre)* {
            /// Untextured triangle rows onto any target, 8 lanes at a time where they
            /// cover the plan ([`super::untextured`]).
            untextured [const DEPTH: bool, const FLAT: bool, const PERSP: bool] [DEPTH, FLAT, PERSP]
                (t: &SetupTriangle, b: [i64; 4], plan: &FragPlan, fb: &mut Target<'_>, stats: &mut Stats)
                => { crate::raster::untextured::rows_untextured::<M, AVX2, DEPTH, FLAT, PERSP> };
            /// Textured triangle rows in 2x2 quads ([`super::rows_textured`]).
            textured [const DEPTH: bool, const FLAT: bool, const PERSP: bool] [DEPTH, FLAT, PERSP]
                (t: &SetupTriangle, b: [i64; 4], plan: &FragPlan, units: &[UnitPlan<'_>], fb: &mut Target<'_>, stats: &mut Stats)
                => { crate::raster::rows_textured::<M, AVX2, DEPTH, FLAT, PERSP> };
            /// Triangle rows through the one-unit texture fast path
            /// ([`super::textured::rows_tex_fast`]).
            tex_fast [const DEPTH: bool, const FLAT: bool, const PERSP: bool] [DEPTH, FLAT, PERSP]
                (t: &SetupTriangle, b: [i64; 4], plan: &FragPlan, u: &UnitPlan<'_>, env: FastEnv, fb: &mut Target<'_>, stats: &mut Stats)
                => { crate::raster::textured::rows_tex_fast::<M, AVX2, DEPTH, FLAT, PERSP> };
            /// Rows of a one-pass multisample triangle, textured or not
            /// ([`super::multisample::rows`]).
            multisample [const DEPTH: bool, const FLAT: bool, const PERSP: bool] [DEPTH, FLAT, PERSP]
                (t: &SetupTriangle, b: [i64; 4], plan: &FragPlan, units: &[UnitPlan<'_>], fb: &mut Target<'_>, stats: &mut Stats)
                => { crate::raster::multisample::rows::<M, AVX2, DEPTH, FLAT, PERSP> };
            /// Textured rows of a line, point or stippled polygon ([`super::prim_tex`]).
            covered [const DEPTH: bool, const FLAT: bool, const PERSP: bool] [DEPTH, FLAT, PERSP]
                (t: &SetupTriangle, chunks: &mut dyn Iterator<Item = Chunk>, plan: &FragPlan, units: &[UnitPlan<'_>], fb: &mut Target<'_>, stats: &mut Stats)
                => { crate::raster::prim_tex::rows::<M, AVX2, DEPTH, FLAT, PERSP> };
            /// The spans of an untextured line, point or stippled polygon through the 8-lane
            /// fragment shader where it covers the plan, else the general span shader
            /// ([`super::prim_spans`]).
            spans [const DEPTH: bool, const FLAT: bool, const PERSP: bool] [DEPTH, FLAT, PERSP]
                (t: &SetupTriangle, rs: &RowSpans, plan: &FragPlan, fb: &mut Target<'_>, stats: &mut Stats)
                => { crate::raster::prim_spans::rows::<M, AVX2, DEPTH, FLAT, PERSP> };
        });
    };
}

/// Declares the trait [`Walks`] from the list of [`walk_list!`].
macro_rules! walks_trait {
    ({ $($(#[$doc:meta])* $walk:ident [$($gen:tt)*] [$($garg:tt)*] ($($arg:ident: $ty:ty),*) => { $($call:tt)* };)* }) => {
        /// The row walks of one instruction-set level.
        ///
        /// # Safety
        /// Every method is compiled for the level's instruction set: call it only when
        /// [`crate::cpu::isa`] reports that level (or one with all of its features).
        pub(crate) trait Walks {
            $(
                $(#[$doc])*
                ///
                /// # Safety
                /// See the trait.
                #[allow(clippy::too_many_arguments)]
                unsafe fn $walk<$($gen)*>($($arg: $ty),*);
            )*
        }
    };
}

walk_list!(walks_trait!());

/// The AVX2 span shader's row walk ([`super::rows_simd_walk`]), for the AVX2 levels.
///
/// # Safety
/// As [`Walks`]; the caller also checked [`super::simd_ok`].
#[cfg(target_arch = "x86_64")]
pub(crate) trait SimdWalks {
    /// The rows of one span-shader variant: depth code `D`, blend code `B`.
    ///
    /// # Safety
    /// See the trait.
    unsafe fn simd<const D: u8, const FLAT: bool, const PERSP: bool, const B: u8>(
        t: &SetupTriangle,
        b: [i64; 4],
        plan: &FragPlan,
        fb: &mut Target<'_>,
        stats: &mut Stats,
    );

    /// The rows of an untextured line or point through one span-shader variant
    /// ([`super::prim_spans`]).
    ///
    /// # Safety
    /// See the trait.
    unsafe fn simd_spans<const D: u8, const FLAT: bool, const PERSP: bool, const B: u8>(
        t: &SetupTriangle,
        rs: &RowSpans,
        plan: &FragPlan,
        fb: &mut Target<'_>,
        stats: &mut Stats,
    );
}

/// Defines the levels' [`Walks`]: each walk is a thin `#[inline(never)]` function compiled
/// with the level's target features around the one inlined body, in a module of its own
/// (`$module::walk::run`) so that it lands in a codegen unit of its own: rustc places a
/// generic function's instances in its defining module's unit, and LLVM compiles a unit
/// on one thread, so one module holding every variant compiled on one core. The trait's
/// methods only forward. A level is written `Name, module, fusing, avx2, [features];`;
/// all but the first are x86-64 only.
macro_rules! walks {
    ($(#[$bdoc:meta])* $base:ident, $bmod:ident, $bm:ident, $bavx2:literal, $bfeat:tt;
     $($(#[$doc:meta])* $name:ident, $module:ident, $m:ident, $avx2:literal, $feat:tt;)*) => {
        walk_list!(level_walks!([$(#[$bdoc])*] $base, $bmod, $bm, $bavx2, $bfeat));
        $(
            #[cfg(target_arch = "x86_64")]
            walk_list!(level_walks!([$(#[$doc])*] $name, $module, $m, $avx2, $feat));
        )*
    };
}

/// One level of [`walks!`], given the list of [`walk_list!`].
macro_rules! level_walks {
    ([$(#[$ldoc:meta])*] $name:ident, $module:ident, $m:ident, $avx2:literal, $feat:tt {
        $($(#[$doc:meta])* $walk:ident [$($gen:tt)*] [$($garg:tt)*] ($($arg:ident: $ty:ty),*) => { $($call:tt)* };)*
    }) => {
        $(#[$ldoc])*
        pub(crate) struct $name;

        /// The walks of one level, a module (and codegen unit) each.
        mod $module {
            /// The level's fusing.
            type M = super::$m;
            /// Whether the level has AVX2.
            #[allow(dead_code)]
            const AVX2: bool = $avx2;
            $(
                level_walks!(@walk $feat $walk [$($gen)*] ($($arg: $ty),*) => { $($call)* });
            )*
        }

        impl Walks for $name {
            $(
                #[inline(always)]
                unsafe fn $walk<$($gen)*>($($arg: $ty),*) {
                    // SAFETY: forwarded from the caller.
                    unsafe { $module::$walk::run::<$($garg)*>($($arg),*) }
                }
            )*
        }
    };
    (@walk [$($feat:tt)*] $walk:ident [$($gen:tt)*] ($($arg:ident: $ty:ty),*) => { $($call:tt)* }) => {
        pub(super) mod $walk {
            use super::super::*;
            use super::*;
            $($feat)*
            #[inline(never)]
            #[allow(clippy::too_many_arguments)]
            pub(crate) unsafe fn run<$($gen)*>($($arg: $ty),*) {
                $($call)*($($arg),*)
            }
        }
    };
}

/// Defines a level's [`SimdWalks`] like [`walks!`], in module `$module`.
#[cfg(target_arch = "x86_64")]
macro_rules! simd_walks {
    ($($name:ident, $module:ident, fma = $fma:literal, [$($feat:tt)*];)*) => {$(
        /// The AVX2 span shader's walk of one level, a module (and codegen unit) of its own.
        mod $module {
            use super::*;
            $($feat)*
            #[inline(never)]
            pub(crate) unsafe fn run<const D: u8, const FLAT: bool, const PERSP: bool, const B: u8>(t: &SetupTriangle, b: [i64; 4], plan: &FragPlan, fb: &mut Target<'_>, stats: &mut Stats) {
                // SAFETY: this function is compiled with AVX2 (and FMA when `$fma`).
                unsafe {
                    crate::raster::rows_simd_walk::<$fma, D, FLAT, PERSP, B>(t, b, plan, fb, stats)
                }
            }

            $($feat)*
            #[inline(never)]
            pub(crate) unsafe fn spans<const D: u8, const FLAT: bool, const PERSP: bool, const B: u8>(t: &SetupTriangle, rs: &RowSpans, plan: &FragPlan, fb: &mut Target<'_>, stats: &mut Stats) {
                // SAFETY: this function is compiled with AVX2 (and FMA when `$fma`).
                unsafe {
                    crate::raster::prim_spans::rows_simd::<$fma, D, FLAT, PERSP, B>(t, rs, plan, fb, stats)
                }
            }
        }

        impl SimdWalks for $name {
            #[inline(always)]
            unsafe fn simd<const D: u8, const FLAT: bool, const PERSP: bool, const B: u8>(t: &SetupTriangle, b: [i64; 4], plan: &FragPlan, fb: &mut Target<'_>, stats: &mut Stats) {
                // SAFETY: forwarded from the caller.
                unsafe { $module::run::<D, FLAT, PERSP, B>(t, b, plan, fb, stats) }
            }

            #[inline(always)]
            unsafe fn simd_spans<const D: u8, const FLAT: bool, const PERSP: bool, const B: u8>(t: &SetupTriangle, rs: &RowSpans, plan: &FragPlan, fb: &mut Target<'_>, stats: &mut Stats) {
                // SAFETY: forwarded from the caller.
                unsafe { $module::spans::<D, FLAT, PERSP, B>(t, rs, plan, fb, stats) }
            }
        }
    )*};
}

walks! {
    /// Baseline x86-64 (SSE2), or another architecture: not fused.
    Base, base, Unfused, false, [];
    /// FMA without AVX2: fused, 128-bit.
    Fma, fma, Fused, false, [#[target_feature(enable = "fma")]];
    /// AVX2 and FMA: the common case.
    Avx2Fma, avx2fma, Fused, true, [#[target_feature(enable = "avx2,fma,popcnt,bmi1,bmi2,lzcnt")]];
}

/// The untextured span shader of [`Avx2Fma`] compiled for CPUs with AVX-512 (F, BW, VL,
/// DQ): the same 256-bit code, which the compiler may then give masked moves and 32
/// registers (measured 2–5% faster on the blend and depth scenes; the textured path,
/// compiled the same way, measured slower and keeps the AVX2 copy). The arithmetic that
/// reaches the pixels is the same instructions (no contraction), so the bytes are the same.
#[cfg(target_arch = "x86_64")]
pub(crate) struct Avx512;

#[cfg(target_arch = "x86_64")]
simd_walks! {
    Avx2Fma, avx2fma_simd, fma = true, [#[target_feature(enable = "avx2,fma,popcnt,bmi1,bmi2,lzcnt")]];
    Avx512, avx512_simd, fma = true, [#[target_feature(enable = "avx2,fma,avx512f,avx512bw,avx512vl,avx512dq,popcnt,bmi1,bmi2,lzcnt")]];
}

/// Samples a 2x2 quad of unit `u` (with `r` for 3D, cube-map and depth textures) through
/// the sampler compiled once per fusing and called out of line: the sampler serves every
/// target, filter and wrap mode, and inlined into each of the textured walks' variants
/// it was most of their code. One call per quad (four pixels) costs little beside the
/// sampling; the bytes do not change (the sampler fuses by `u.fma` either way, and the
/// FMA copy only makes the fused lerps an instruction instead of a call).
#[inline(always)]
pub(crate) fn sample_quad<M: crate::fragment::span::Madd>(
    u: &UnitPlan<'_>,
    s: [f32; 4],
    t: [f32; 4],
    r: Option<[f32; 4]>,
) -> [[f32; 4]; 4] {
    #[cfg(target_arch = "x86_64")]
    if M::FUSED {
        // SAFETY: fused walks run only on the levels with FMA (`cpu::isa`).
        return unsafe { sample_quad_fma(u, s, t, r) };
    }
    sample_quad_base(u, s, t, r)
}

/// Defines a copy of [`sample_quad`]'s body, `sample_any`, as an `#[inline(never)]`
/// function with the given attributes (and `unsafe` when given).
macro_rules! sampler_copy {
    ($(#[$attr:meta])* $name:ident $($unsafe:tt)?) => {
        $(#[$attr])*
        #[inline(never)]
        $($unsafe)? fn $name(u: &UnitPlan<'_>, s: [f32; 4], t: [f32; 4], r: Option<[f32; 4]>) -> [[f32; 4]; 4] {
            match r {
                None => u.sample_quad(s, t),
                Some(r) => u.sample_quad_str(s, t, r),
            }
        }
    };
}

sampler_copy!(
    /// [`sample_quad`] for baseline x86-64.
    sample_quad_base
);

sampler_copy!(
    /// [`sample_quad`] compiled with FMA.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "fma")]
    sample_quad_fma unsafe
);
