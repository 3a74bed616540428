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
pub mod pack;
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

/// A wide type: the newtype over its register of `$n` lanes (documented by the doc lines
/// before the invocation) and its constructors that read no memory, `splat` (every lane `v`), `zero`
/// (every bit 0) and `new` (lane `i` from `a[i]`: the set intrinsic takes the array's
/// elements in the order listed), all `unsafe` because a value may only exist where the
/// CPU has AVX2. With `memory(*lane) => load, store` it also has the unaligned `load` and
/// `store` of its lanes through a typed pointer, and `to_array`; with `float => fmadd,
/// movemask` the fused `mul_add` and the lanes' sign bits.
#[cfg(target_arch = "x86_64")]
macro_rules! wide_type {
    (
        $(#[$doc:meta])*
        $t:ident($reg:ident, [$lane:ty; $n:literal]):
            splat => $splat:ident, zero => $zero:ident, new => $set:ident($($i:literal),+)
            $(, memory(*lane) => $load:ident, $store:ident)?
            $(, float => $fma:ident, $movemask:ident)?
    ) => {
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

            /// Lane `i` is `a[i]`.
            ///
            /// # Safety
            /// The CPU has AVX2.
            #[inline(always)]
            pub unsafe fn new(a: [$lane; $n]) -> Self {
                // SAFETY: the caller vouches for AVX2.
                Self(unsafe { std::arch::x86_64::$set($(a[$i]),+) })
            }
        }

        $(
            impl $t {
                #[doc = concat!("The ", stringify!($n), " lanes at `p` (unaligned).")]
                ///
                /// # Safety
                #[doc = concat!("The CPU has AVX2 and `p..p + ", stringify!($n), "` is readable.")]
                #[inline(always)]
                pub unsafe fn load(p: *const $lane) -> Self {
                    // SAFETY: forwarded from the caller.
                    Self(unsafe { std::arch::x86_64::$load(p.cast()) })
                }

                /// Stores the lanes at `p` (unaligned).
                ///
                /// # Safety
                #[doc = concat!("`p..p + ", stringify!($n), "` is writable.")]
                #[inline(always)]
                pub unsafe fn store(self, p: *mut $lane) {
                    // SAFETY: AVX2 as `self` proves; the caller vouches for the address.
                    unsafe { std::arch::x86_64::$store(p.cast(), self.0) }
                }

                /// The lanes as an array.
                #[inline(always)]
                pub fn to_array(self) -> [$lane; $n] {
                    let mut a = [<$lane>::default(); $n];
                    // SAFETY: AVX2 as `self` proves; `a` holds the register's bytes.
                    unsafe { self.store(a.as_mut_ptr()) };
                    a
                }
            }
        )?

        $(
            impl $t {
                /// `self * b + c` with one rounding (`vfmadd`).
                ///
                /// # Safety
                /// The CPU has FMA.
                #[inline(always)]
                pub unsafe fn mul_add(self, b: Self, c: Self) -> Self {
                    // SAFETY: AVX2 as `self` proves; the caller vouches for FMA.
                    Self(unsafe { std::arch::x86_64::$fma(self.0, b.0, c.0) })
                }

                /// The sign bits of the lanes, bit `i` for lane `i`.
                #[inline(always)]
                pub fn movemask(self) -> u32 {
                    $crate::simd::avx2!(std::arch::x86_64::$movemask(self.0)) as u32
                }
            }
        )?
    };
}
#[cfg(target_arch = "x86_64")]
use wide_type;

/// The operations of a wide type that are one intrinsic of `self`'s register and those of
/// its operands: after the operation's doc lines, `fn name(o, ...) -> Ret = intrinsic;`
/// becomes the `#[inline(always)]` `fn name(self, o: Self, ...) -> Ret` that returns
/// `Ret(intrinsic(self.0, o.0, ...))` (safe, as every [`avx2!`] operation; `Ret` is `Self`
/// or another wide type). An immediate goes after the intrinsic, `= intrinsic::<IMM>`,
/// either a constant or the operation's own `<const IMM>` parameter.
#[cfg(target_arch = "x86_64")]
macro_rules! lane_ops {
    ($t:ident; $(
        $(#[$doc:meta])*
        fn $name:ident $(<const $n:ident>)? ($($o:ident),*) -> $ret:ident
            = $intr:ident $(::<$imm:tt>)?;
    )+) => {
        // Named methods rather than `std::ops` operators: a kernel reads as the sequence
        // of instructions it compiles to.
        #[allow(clippy::should_implement_trait)]
        impl $t {
            $(
                $(#[$doc])*
                #[inline(always)]
                pub fn $name $(<const $n: i32>)? (self $(, $o: Self)*) -> $ret {
                    $ret($crate::simd::avx2!(std::arch::x86_64::$intr $(::<$imm>)? (self.0 $(, $o.0)*)))
                }
            )+
        }
    };
}
#[cfg(target_arch = "x86_64")]
use lane_ops;

/// `and` and `or` of a 256-bit integer type: the same instructions whatever the lanes.
#[cfg(target_arch = "x86_64")]
macro_rules! bitwise_256 {
    ($t:ident) => {
        $crate::simd::lane_ops! {
            $t;
            /// Bitwise and.
            fn and(o) -> Self = _mm256_and_si256;
            /// Bitwise or.
            fn or(o) -> Self = _mm256_or_si256;
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
