//! Which instruction set the hot loops are compiled for, chosen once at run time, and
//! whether multiply-adds fuse (which must follow the host CPU to match llvmpipe).

use std::sync::OnceLock;

/// The code variant the rasterizer runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Isa {
    /// AVX2 with fused multiply-add (llvmpipe fuses `fmuladd` on such CPUs). Both AVX2
    /// variants also require POPCNT, BMI1, BMI2 and LZCNT (every AVX2 CPU has them).
    Avx2Fma,
    /// AVX2 without fusing (FMA absent or disabled with `SOFTGL_FMA=0`).
    Avx2,
    /// FMA without AVX2 (rare); fused, 128-bit.
    Fma,
    /// Baseline x86-64 (SSE2) or another architecture; not fused.
    Base,
}

impl Isa {
    /// Whether multiply-adds are fused in this variant.
    pub fn fused(self) -> bool {
        matches!(self, Isa::Avx2Fma | Isa::Fma)
    }

    /// Whether this is an AVX2 variant: the CPU has AVX2, POPCNT, BMI1, BMI2 and LZCNT,
    /// so code compiled for them may run.
    pub fn avx2(self) -> bool {
        matches!(self, Isa::Avx2Fma | Isa::Avx2)
    }
}

/// How many threads rasterize large draws: `SOFTGL_THREADS` (1 turns threading off), else
/// the machine's cores. Images are byte-identical either way: every pixel is shaded by one
/// thread, in primitive order.
pub fn threads() -> usize {
    static N: OnceLock<usize> = OnceLock::new();
    *N.get_or_init(|| {
        std::env::var("SOFTGL_THREADS")
            .ok()
            .and_then(|v| v.parse::<usize>().ok())
            .filter(|&n| n >= 1)
            .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
    })
}

/// Whether the AVX2+FMA variant may run its copy compiled for AVX-512 (F, BW, VL, DQ):
/// the CPU has them and `SOFTGL_AVX512=0` is not set.
pub fn avx512() -> bool {
    static AVX512: OnceLock<bool> = OnceLock::new();
    *AVX512.get_or_init(|| {
        #[cfg(target_arch = "x86_64")]
        {
            !std::env::var("SOFTGL_AVX512").is_ok_and(|v| v == "0")
                && std::arch::is_x86_feature_detected!("avx512f")
                && std::arch::is_x86_feature_detected!("avx512bw")
                && std::arch::is_x86_feature_detected!("avx512vl")
                && std::arch::is_x86_feature_detected!("avx512dq")
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            false
        }
    })
}

/// The variant for this CPU. `SOFTGL_FMA=0` turns fusing off, to compare against a
/// reference run with `GALLIUM_OVERRIDE_CPU_CAPS=sse4.1`.
pub fn isa() -> Isa {
    static ISA: OnceLock<Isa> = OnceLock::new();
    *ISA.get_or_init(|| {
        let no_fma = std::env::var("SOFTGL_FMA").is_ok_and(|v| v == "0");
        #[cfg(target_arch = "x86_64")]
        {
            // The AVX2 variants are also compiled for the bit instructions every AVX2 CPU
            // has (POPCNT, BMI1, BMI2, LZCNT): the hot loops count lanes with `count_ones`.
            let avx2 = std::arch::is_x86_feature_detected!("avx2")
                && std::arch::is_x86_feature_detected!("popcnt")
                && std::arch::is_x86_feature_detected!("bmi1")
                && std::arch::is_x86_feature_detected!("bmi2")
                && std::arch::is_x86_feature_detected!("lzcnt");
            let fma = std::arch::is_x86_feature_detected!("fma") && !no_fma;
            match (avx2, fma) {
                (true, true) => Isa::Avx2Fma,
                (true, false) => Isa::Avx2,
                (false, true) => Isa::Fma,
                (false, false) => Isa::Base,
            }
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            let _ = no_fma;
            Isa::Base
        }
    })
}
