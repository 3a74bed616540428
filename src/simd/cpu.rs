//! Which instruction set the hot loops run, chosen once at run time: the one place that
//! asks the CPU what it has, and the one switch, `SOFTGL_ISA`, that caps it. It also says
//! how many threads rasterize (`SOFTGL_THREADS`) and how the test harnesses pin llvmpipe
//! to the same arithmetic ([`reference_cpu_caps`]).
//!
//! ## Levels
//! | `SOFTGL_ISA` | code that runs | multiply-adds | needs |
//! |---|---|---|---|
//! | `scalar` | baseline x86-64 (SSE2) | two roundings | nothing |
//! | `fma` | baseline, with `vfmadd` | fused | FMA |
//! | `avx2fma` | the 8-wide AVX2 span shaders, setup, sampler | fused | AVX2, POPCNT, BMI1, BMI2, LZCNT, FMA |
//! | `avx512` (default) | as `avx2fma`, the untextured span shader compiled for AVX-512 | fused | the above and AVX-512 F, BW, VL, DQ |
//!
//! A level is a cap: the library runs the best variant whose features the level allows
//! *and* the CPU has, so `SOFTGL_ISA=avx2fma` on an FMA CPU without AVX2 runs `fma`, and
//! an unset (or unknown) value runs the best the CPU has. `scripts/test.sh` runs the
//! comparisons against OSMesa under every level the CPU supports.
//!
//! ## Why there is no unfused AVX2 level
//! Every x86-64 CPU with AVX2 (Intel from Haswell, AMD from Excavator) also has FMA3, so an
//! AVX2 copy that does not fuse would run only where a virtual machine hides FMA or
//! `SOFTGL_ISA` asks for it. It was 7.2 MB of the library's 25 MB of machine code (the
//! raster variants are compiled once per level) and about a quarter of its release build
//! time, so it was removed (stop 61): such a CPU runs `scalar`, which gives the same bytes
//! as llvmpipe there, more slowly.
//!
//! ## Why fusing follows the level
//! llvmpipe emits `llvm.fmuladd` for the viewport transform, attribute interpolation and
//! float texel lerps, and gallivm hands LLVM `+fma` only when the CPU has it, so those are
//! fused exactly on FMA CPUs; plain products and sums are never fused. To match
//! it bit for bit we fuse at the same places when, and only when, the level has FMA. A
//! level without FMA is compared against llvmpipe pinned the same way:
//! `GALLIUM_OVERRIDE_CPU_CAPS=sse4.1` turns off its AVX, AVX2 and FMA. All levels with the
//! same fusing give the same bytes.

use std::sync::OnceLock;

/// The code variant the rasterizer runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Isa {
    /// AVX2 with fused multiply-add (llvmpipe fuses `fmuladd` on such CPUs). Both AVX2
    /// variants also require POPCNT, BMI1, BMI2 and LZCNT (every AVX2 CPU has them).
    Avx2Fma,
    /// FMA without AVX2 (rare, or `SOFTGL_ISA=fma`); fused, 128-bit.
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
        self == Isa::Avx2Fma
    }
}

/// A value of `SOFTGL_ISA`: a cap on the instruction set, lowest first.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Level {
    /// Baseline x86-64, not fused.
    Scalar,
    /// Baseline with fused multiply-adds.
    Fma,
    /// AVX2 (with POPCNT, BMI1, BMI2, LZCNT) and FMA.
    Avx2Fma,
    /// AVX2, FMA and AVX-512 F/BW/VL/DQ.
    Avx512,
}

/// The features a level allows or a CPU has.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Features {
    /// AVX2 and the bit instructions every AVX2 CPU has.
    avx2: bool,
    /// FMA3.
    fma: bool,
    /// AVX-512 F, BW, VL and DQ.
    avx512: bool,
}

impl Features {
    /// Whether every feature of `need` is in `self`.
    fn has_all(self, need: Features) -> bool {
        (!need.avx2 || self.avx2) && (!need.fma || self.fma) && (!need.avx512 || self.avx512)
    }
}

impl Level {
    /// Every level, lowest first.
    pub const ALL: [Level; 4] = [Level::Scalar, Level::Fma, Level::Avx2Fma, Level::Avx512];

    /// The level's name, as `SOFTGL_ISA` spells it.
    pub fn name(self) -> &'static str {
        match self {
            Level::Scalar => "scalar",
            Level::Fma => "fma",
            Level::Avx2Fma => "avx2fma",
            Level::Avx512 => "avx512",
        }
    }

    /// The level named `s` (as [`Level::name`] spells it, any case), if any.
    pub fn parse(s: &str) -> Option<Level> {
        let s = s.trim().to_ascii_lowercase();
        Level::ALL.into_iter().find(|l| l.name() == s)
    }

    /// Whether this level fuses multiply-adds (then it must be compared against llvmpipe on
    /// an FMA CPU; the others against `GALLIUM_OVERRIDE_CPU_CAPS=sse4.1`).
    pub fn fused(self) -> bool {
        self.features().fma
    }

    fn features(self) -> Features {
        let (avx2, fma, avx512) = match self {
            Level::Scalar => (false, false, false),
            Level::Fma => (false, true, false),
            Level::Avx2Fma => (true, true, false),
            Level::Avx512 => (true, true, true),
        };
        Features { avx2, fma, avx512 }
    }

    /// The best level whose features all are in `f`.
    fn best_within(f: Features) -> Level {
        Level::ALL
            .into_iter()
            .rev()
            .find(|l| f.has_all(l.features()))
            .unwrap_or(Level::Scalar)
    }

    /// The variant this level runs.
    fn isa(self) -> Isa {
        match self {
            Level::Scalar => Isa::Base,
            Level::Fma => Isa::Fma,
            Level::Avx2Fma | Level::Avx512 => Isa::Avx2Fma,
        }
    }
}

/// What this CPU has (nothing off x86-64), detected once. The AVX-512 span shader is
/// AVX2+FMA code compiled with AVX-512 enabled, so AVX-512 counts only with AVX2 and FMA.
fn cpu_features() -> Features {
    static CPU: OnceLock<Features> = OnceLock::new();
    *CPU.get_or_init(detect)
}

fn detect() -> Features {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::is_x86_feature_detected as has;
        // The AVX2 variants are also compiled for the bit instructions every AVX2 CPU has
        // (POPCNT, BMI1, BMI2, LZCNT): the hot loops count lanes with `count_ones`.
        let avx2 = has!("avx2") && has!("popcnt") && has!("bmi1") && has!("bmi2") && has!("lzcnt");
        let fma = has!("fma");
        let avx512 = avx2
            && fma
            && has!("avx512f")
            && has!("avx512bw")
            && has!("avx512vl")
            && has!("avx512dq");
        Features { avx2, fma, avx512 }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        Features {
            avx2: false,
            fma: false,
            avx512: false,
        }
    }
}

/// The levels this CPU can run, lowest first (always at least [`Level::Scalar`]).
pub fn supported_levels() -> Vec<Level> {
    let cpu = Level::best_within(cpu_features()).features();
    Level::ALL
        .into_iter()
        .filter(|l| cpu.has_all(l.features()))
        .collect()
}

/// The level the library runs: the best the CPU has within the cap `SOFTGL_ISA`
/// ([`crate::tuning::Tuning::isa`]; an unknown value is reported on stderr once and ignored).
#[inline]
pub fn level() -> Level {
    static LEVEL: OnceLock<Level> = OnceLock::new();
    *LEVEL.get_or_init(|| {
        let cpu = cpu_features();
        let cap = match &crate::tuning::tuning().isa {
            Some(v) => Level::parse(v).unwrap_or_else(|| {
                let names: Vec<_> = Level::ALL.iter().map(|l| l.name()).collect();
                eprintln!(
                    "softgl: {}={v:?} is not one of {}; using the CPU's best",
                    crate::tuning::ISA_VAR,
                    names.join(", ")
                );
                Level::Avx512
            }),
            None => Level::Avx512,
        }
        .features();
        Level::best_within(Features {
            avx2: cap.avx2 && cpu.avx2,
            fma: cap.fma && cpu.fma,
            avx512: cap.avx512 && cpu.avx512,
        })
    })
}

/// Whether the CPU has the FMA instructions, whatever the level: the guard of code that
/// issues `vfmadd` when a caller asks for fused arithmetic explicitly (a level without FMA
/// never asks). Inlined: it guards per-vertex arithmetic, and the standard library's check
/// is one load of a cached word.
#[inline(always)]
pub fn has_fma_instructions() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        std::arch::is_x86_feature_detected!("fma")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

/// The variant for this CPU and [`level`].
#[inline]
pub fn isa() -> Isa {
    level().isa()
}

/// Whether the AVX2+FMA variant may run its copy compiled for AVX-512 (F, BW, VL, DQ):
/// the CPU has them and the level is `avx512`.
#[inline]
pub fn avx512() -> bool {
    level() == Level::Avx512
}

/// The `GALLIUM_OVERRIDE_CPU_CAPS` that pins llvmpipe to this [`level`]'s arithmetic, for
/// the harnesses that compare against it: `SOFTGL_REF_CPU_CAPS` when set (empty for none),
/// else `sse4.1` (no AVX, AVX2 or FMA, so nothing fuses) for a level without FMA, else
/// none ([`crate::tuning::Tuning::ref_cpu_caps`]).
pub fn reference_cpu_caps() -> Option<String> {
    match &crate::tuning::tuning().ref_cpu_caps {
        Some(v) => Some(v.clone()).filter(|v| !v.is_empty()),
        None => (!level().fused()).then(|| "sse4.1".to_string()),
    }
}

/// How many threads rasterize large draws: `SOFTGL_THREADS` (1 turns threading off), else
/// the machine's cores ([`crate::tuning::Tuning::threads`]). Images are byte-identical
/// either way: every pixel is shaded by one thread, in primitive order.
pub fn threads() -> usize {
    crate::tuning::tuning().threads
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_unknown_names_are_none() {
        for l in Level::ALL {
            assert_eq!(Level::parse(l.name()), Some(l));
            assert_eq!(Level::parse(&l.name().to_ascii_uppercase()), Some(l));
        }
        assert_eq!(Level::parse("sse4"), None);
        assert_eq!(Level::parse(""), None);
    }

    #[test]
    fn a_cap_keeps_only_what_the_cpu_has_too() {
        let f = |avx2, fma, avx512| Features { avx2, fma, avx512 };
        // An AVX2 CPU without FMA runs scalar (there is no unfused AVX2 level).
        assert_eq!(Level::best_within(f(true, false, false)), Level::Scalar);
        assert_eq!(Level::best_within(f(false, true, false)), Level::Fma);
        assert_eq!(Level::best_within(f(true, true, false)), Level::Avx2Fma);
        assert_eq!(Level::best_within(f(true, true, true)), Level::Avx512);
        assert_eq!(Level::best_within(f(false, false, true)), Level::Scalar);
        assert_eq!(Level::Avx512.isa(), Isa::Avx2Fma);
        assert!(Level::Fma.fused() && Level::Avx2Fma.fused() && !Level::Scalar.fused());
    }

    #[test]
    fn the_running_level_is_supported_and_matches_the_variant() {
        let l = level();
        assert!(supported_levels().contains(&l));
        assert_eq!(isa().fused(), l.fused());
        assert_eq!(avx512(), l == Level::Avx512);
        assert_eq!(supported_levels()[0], Level::Scalar);
    }
}
