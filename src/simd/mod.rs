//! The only home of CPU intrinsics and CPU detection: [`cpu`] decides once which
//! instruction set the hot loops run, and the wide types here ([`F32x8`], [`I32x8`],
//! [`U16x16`], [`I64x4`], [`F32x4`]) are what the pipeline's SIMD kernels compute with
//! instead of raw `std::arch` intrinsics. Each method is one intrinsic (or a fixed
//! short sequence of them), `#[inline(always)]`, so that inside a kernel compiled with
//! `#[target_feature(enable = "avx2", ...)]` it becomes the instruction itself.
//!
//! ## Why the methods are safe
//! An AVX2 instruction may only run on a CPU that has AVX2. Every way to *make* a value
//! of a wide type (`splat`, `zero`, `new`, `load`, ...) is `unsafe` and requires that
//! the CPU has AVX2; a value therefore exists only once some code has checked that, and
//! the operations on values (`add`, `cmpgt`, `to_array`, ...) are safe. The exceptions
//! are the memory accesses through raw pointers (`load`, `store`, `maskload`, `gather`:
//! the caller vouches for the addresses) and the fused multiply-adds (`mul_add`: the
//! caller vouches for FMA), which stay `unsafe`.
//!
//! A wrapper is `#[inline(always)]` without a `target_feature` of its own: inlined into
//! an AVX2 kernel, the intrinsic it calls is then inlined there too. Called from code
//! compiled without AVX2 it would still be correct (the value proves the CPU has AVX2),
//! only slow: an out-of-line call per operation. Kernels keep their intrinsic-using
//! helpers as `#[inline(always)]` functions, not closures, for that reason.
//!
//! The scalar helpers at the bottom ([`prefetch`], [`stream_copy`], [`store_fence`],
//! [`rsqrt_approx`], [`mul_add_fused`]) use only baseline x86-64 (SSE, SSE2) or check
//! the CPU themselves, and have plain fallbacks off x86-64.

pub mod cpu;
pub mod scan;

#[cfg(target_arch = "x86_64")]
mod f32x4;
#[cfg(target_arch = "x86_64")]
mod f32x8;
#[cfg(target_arch = "x86_64")]
mod i32x8;
#[cfg(target_arch = "x86_64")]
mod i64x4;
#[cfg(target_arch = "x86_64")]
mod u16x16;

#[cfg(target_arch = "x86_64")]
pub use f32x4::F32x4;
#[cfg(target_arch = "x86_64")]
pub use f32x8::F32x8;
#[cfg(target_arch = "x86_64")]
pub use i32x8::I32x8;
#[cfg(target_arch = "x86_64")]
pub use i64x4::I64x4;
#[cfg(target_arch = "x86_64")]
pub use u16x16::U16x16;

/// Runs an intrinsic on operands that are values of the wide types: sound because such
/// a value exists only on a CPU with AVX2 (see the module doc).
#[cfg(target_arch = "x86_64")]
macro_rules! avx2 {
    ($e:expr) => {{
        // SAFETY: an operand of this operation is a value of a wide type, and those are
        // made only by `unsafe` constructors whose callers vouch that the CPU has AVX2.
        unsafe { $e }
    }};
}
#[cfg(target_arch = "x86_64")]
use avx2;

/// A wide type: the newtype over its register (documented by the doc lines before the
/// invocation) and its two constructors that read no memory, `splat` (every lane `v`) and
/// `zero` (every bit 0), both `unsafe` because a value may only exist where the CPU has
/// AVX2.
#[cfg(target_arch = "x86_64")]
macro_rules! wide_type {
    ($(#[$doc:meta])* $t:ident($reg:ident, $lane:ty): splat => $splat:ident, zero => $zero:ident) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug)]
        #[repr(transparent)]
        pub struct $t(pub(super) std::arch::x86_64::$reg);

        impl $t {
            /// Every lane `v`.
            ///
            /// # Safety
            /// The CPU has AVX2.
            #[inline(always)]
            pub unsafe fn splat(v: $lane) -> Self {
                // SAFETY: the caller vouches for AVX2.
                Self(unsafe { std::arch::x86_64::$splat(v) })
            }

            /// Every lane 0.
            ///
            /// # Safety
            /// The CPU has AVX2.
            #[inline(always)]
            pub unsafe fn zero() -> Self {
                // SAFETY: the caller vouches for AVX2.
                Self(unsafe { std::arch::x86_64::$zero() })
            }
        }
    };
}
#[cfg(target_arch = "x86_64")]
use wide_type;

/// The lane-wise operations of a wide type that are one intrinsic of `self` and `o`:
/// `name => intrinsic,` after the operation's doc lines, each an `#[inline(always)]`
/// `fn name(self, o: Self) -> Self` (safe, as every [`avx2!`] operation).
#[cfg(target_arch = "x86_64")]
macro_rules! binary_ops {
    ($t:ident; $($(#[$doc:meta])* $name:ident => $intr:ident,)+) => {
        // Named methods rather than `std::ops` operators: a kernel reads as the sequence
        // of instructions it compiles to.
        #[allow(clippy::should_implement_trait)]
        impl $t {
            $(
                $(#[$doc])*
                #[inline(always)]
                pub fn $name(self, o: Self) -> Self {
                    Self(avx2!(std::arch::x86_64::$intr(self.0, o.0)))
                }
            )+
        }
    };
}
#[cfg(target_arch = "x86_64")]
use binary_ops;

/// `and` and `or` of a 256-bit integer type: the same instructions whatever the lanes.
#[cfg(target_arch = "x86_64")]
macro_rules! bitwise_256 {
    ($t:ident) => {
        impl $t {
            /// Bitwise and.
            #[inline(always)]
            pub fn and(self, o: Self) -> Self {
                Self(avx2!(std::arch::x86_64::_mm256_and_si256(self.0, o.0)))
            }

            /// Bitwise or.
            #[inline(always)]
            pub fn or(self, o: Self) -> Self {
                Self(avx2!(std::arch::x86_64::_mm256_or_si256(self.0, o.0)))
            }
        }
    };
}
#[cfg(target_arch = "x86_64")]
use bitwise_256;

/// Hints the CPU to bring the cache line holding `p` into all cache levels. Never faults,
/// whatever `p` is.
#[inline(always)]
pub fn prefetch<T>(p: *const T) {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{_mm_prefetch, _MM_HINT_T0};
        // SAFETY: a prefetch is a hint that never faults on any address, and SSE is part
        // of the x86-64 baseline.
        unsafe { _mm_prefetch::<_MM_HINT_T0>(p.cast()) }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = p;
}

/// Copies `src` into `out` (the same length) with non-temporal 16-byte stores where `out`
/// is aligned (the caller issues [`store_fence`] once the whole copy is done).
pub fn stream_copy(out: &mut [u8], src: &[u8]) {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{_mm_loadu_si128, _mm_stream_si128};
        let n = out.len().min(src.len());
        let head = out.as_ptr().align_offset(16).min(n);
        out[..head].copy_from_slice(&src[..head]);
        let mut i = head;
        while i + 16 <= n {
            // SAFETY: `i + 16 <= n` keeps both 16-byte accesses inside the slices, and
            // `out + i` is 16-byte aligned (from `head` on, in steps of 16) as the
            // streaming store requires; SSE2 is part of x86-64.
            unsafe {
                let v = _mm_loadu_si128(src.as_ptr().add(i).cast());
                _mm_stream_si128(out.as_mut_ptr().add(i).cast(), v);
            }
            i += 16;
        }
        out[i..n].copy_from_slice(&src[i..n]);
    }
    #[cfg(not(target_arch = "x86_64"))]
    out.copy_from_slice(src);
}

/// Orders earlier streaming stores ([`stream_copy`]) before later stores.
#[inline]
pub fn store_fence() {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: sfence has no preconditions (SSE is part of x86-64).
    unsafe {
        std::arch::x86_64::_mm_sfence()
    };
}

/// The CPU's approximate reciprocal square root (`rsqrtss`) on x86-64; an exact
/// `1/sqrt` elsewhere.
#[inline]
pub fn rsqrt_approx(x: f32) -> f32 {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{_mm_cvtss_f32, _mm_rsqrt_ss, _mm_set_ss};
        // SAFETY: SSE is part of the x86-64 baseline.
        unsafe { _mm_cvtss_f32(_mm_rsqrt_ss(_mm_set_ss(x))) }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        1.0 / x.sqrt()
    }
}

/// `a * b + c` with one rounding: the CPU's FMA instruction, inline, when it has one
/// (code compiled without the `fma` target feature would otherwise call libm's `fmaf`,
/// which gives the same result), else `f32::mul_add`.
#[inline(always)]
pub fn mul_add_fused(a: f32, b: f32, c: f32) -> f32 {
    #[cfg(target_arch = "x86_64")]
    if cpu::has_fma_instructions() {
        let mut r = a;
        // SAFETY: the CPU has FMA (checked just above); the instruction reads and writes
        // only these registers (r = r * b + c).
        unsafe {
            std::arch::asm!(
                "vfmadd213ss {r}, {b}, {c}",
                r = inout(xmm_reg) r,
                b = in(xmm_reg) b,
                c = in(xmm_reg) c,
                options(pure, nomem, nostack, preserves_flags)
            );
        }
        return r;
    }
    a.mul_add(b, c)
}
