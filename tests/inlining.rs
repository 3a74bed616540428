//! A guard on the shipped library's machine code: the SIMD and FMA copies of the hot loops
//! must not call small helpers out of line.
//!
//! A function compiled with `#[target_feature]` (the AVX2 and FMA levels, see
//! `src/simd/cpu.rs`) can inline only callees whose features are a subset of its own. When
//! LLVM instead leaves a generic helper out of line (a closure given to `array::map`, a
//! function grown too large to inline), that helper is compiled for the baseline CPU:
//! an intrinsic in it becomes a call to a one-instruction function, and a `mul_add` or
//! `floor` becomes a call into the soft-float library. The images stay right, so no pixel
//! test notices, but the loop slows by tens of percent (stop 57 lost 35% on two scenes to
//! `FogPlan::factor` calling `fmaf`). This test disassembles `libsoftgl.so` with `objdump`
//! (binutils, which the C toolchain brings) and fails on:
//! - any call to a `core::arch` intrinsic, from anywhere (an intrinsic is one instruction:
//!   a call to it is always a lost inlining), except the pairs in [`ALLOWED`];
//! - from a function of an instruction-set level (its name carries the level, as the
//!   variant macros name them), any call to the float helpers in [`HELPERS`].

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::process::Command;

// Only `profile_dir` is used here.
#[allow(dead_code)]
#[path = "support/paths.rs"]
mod paths;

/// Out-of-line intrinsic calls that are known and harmless, as (caller, callee) name
/// fragments, each with its reason.
const ALLOWED: &[(&str, &str, &str)] = &[
    (
        "detect_and_initialize",
        "_xgetbv",
        "the standard library's CPU detection, run once",
    ),
    (
        "load_x86_features",
        "_xgetbv",
        "the compiler builtins' CPU detection, run once",
    ),
    (
        "sample8::rows_avx2",
        "_mm256_fmadd_ps",
        "the unfused AVX2 copy of the 8-wide samplers keeps their fused branches, which run only \
     when the unit's plan fuses (never at this level)",
    ),
];

/// Float helpers that an instruction-set level's function must inline.
const HELPERS: &[&str] = &[
    "<f32>::clamp",
    "<f32>::mul_add",
    "<f32>::floor",
    "<f32>::round_ties_even",
    "fmaf",
    "floorf",
    "roundevenf",
];

/// Name fragments that mark a function compiled for an instruction-set level.
const LEVEL_MARKS: &[&str] = &["avx2", "avx512", "_fma", "::fma::"];

/// The folder holding the library the tests run (`SOFTGL_LIB_DIR`, else the profile's).
fn lib_path() -> PathBuf {
    let dir = std::env::var_os("SOFTGL_LIB_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(paths::profile_dir);
    dir.join("libsoftgl.so")
}

/// Every call instruction's (caller, callee) pair, counted, from `objdump -d -C`.
fn calls() -> BTreeMap<(String, String), usize> {
    let lib = lib_path();
    assert!(
        lib.exists(),
        "{} is missing: build the library first",
        lib.display()
    );
    let out = Command::new("objdump")
        .args(["-d", "--no-show-raw-insn", "-C"])
        .arg(&lib)
        .output()
        .expect("objdump (binutils) is needed for this test");
    assert!(out.status.success(), "objdump failed");
    let text = String::from_utf8_lossy(&out.stdout);
    let mut caller = String::new();
    let mut pairs = BTreeMap::new();
    for line in text.lines() {
        // "0000000000eebbc0 <softgl::pixels::rect::raster_fma>:"
        if line.ends_with(">:") && !line.starts_with(' ') {
            if let Some(i) = line.find(" <") {
                caller = line[i + 2..line.len() - 2].to_string();
            }
            continue;
        }
        // "  efea65:\tcall   eebbc0 <softgl::pixels::rect::raster_fma>"
        let Some(i) = line.find("\tcall ") else {
            continue;
        };
        let rest = &line[i..];
        let (Some(a), Some(b)) = (rest.find('<'), rest.rfind('>')) else {
            continue;
        };
        let callee = rest[a + 1..b].trim_end_matches("@plt").to_string();
        *pairs.entry((caller.clone(), callee)).or_insert(0) += 1;
    }
    pairs
}

#[test]
fn hot_loops_inline_their_intrinsics_and_float_helpers() {
    let pairs = calls();
    assert!(
        pairs.len() > 10_000,
        "only {} call sites parsed: has objdump's output format changed?",
        pairs.len()
    );
    let mut bad = Vec::new();
    for ((caller, callee), n) in &pairs {
        let intrinsic = callee.starts_with("core::core_arch::");
        let allowed = ALLOWED
            .iter()
            .any(|(c, e, _)| caller.ends_with(c) && callee.ends_with(e));
        let level = LEVEL_MARKS.iter().any(|m| caller.contains(m));
        let helper = HELPERS.iter().any(|h| callee == h || callee.starts_with(h));
        if (intrinsic && !allowed) || (level && helper) {
            bad.push(format!("{n:4} × {caller}  ->  {callee}"));
        }
    }
    assert!(
        bad.is_empty(),
        "out-of-line calls in the hot loops (see this test's module doc):\n{}",
        bad.join("\n")
    );
}

/// The guard can fail only if the parser sees demangled names: a call from one of the
/// library's functions to another (a dispatcher calling its level's copy) must be found.
#[test]
fn the_parser_sees_demangled_calls() {
    let pairs = calls();
    assert!(pairs
        .keys()
        .any(|(caller, callee)| caller.starts_with("softgl::") && callee.starts_with("softgl::")));
}
