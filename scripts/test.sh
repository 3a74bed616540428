#!/usr/bin/env bash
# The README's test command: installs what is missing, builds the library and runs every
# test (unit, API, header, and the C scenes compared against Mesa's OSMesa) under every
# instruction-set level this CPU supports (SOFTGL_ISA, see src/simd/cpu.rs).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/ensure-deps.sh
cargo fmt --all -- --check
# Clippy and the unit tests' (unoptimised) build run beside the release build, each in a
# target folder of its own (cargo locks a folder per build): the release build keeps one
# core busy for minutes of its own (the front end, local ThinLTO, the link), which they
# fill. Their output goes to target/side-builds.log, shown if they fail.
unit_dir=target/unit-tests
mkdir -p target
(
  set -e
  CARGO_TARGET_DIR=target/clippy cargo clippy --release --workspace --all-targets -- -D warnings
  CARGO_TARGET_DIR=$unit_dir cargo test --profile unit --workspace --exclude softglut --lib \
    --no-run
) >target/side-builds.log 2>&1 &
side=$!
echo "test.sh: [${SECONDS}s] release build (clippy and the unit tests' build beside it)"
cargo build --release --workspace
# The examples have no tests; clippy (--all-targets) type-checks them all, and only the
# level lister is needed here (bench.sh builds the benchmark runner).
cargo build --release --example isa_levels
if ! wait "$side"; then
  cat target/side-builds.log
  echo "test.sh: clippy or the unit tests' build failed (above)"
  exit 1
fi
echo "test.sh: [${SECONDS}s] clippy clean, unit tests built"

# The levels softgl can run here, lowest first ("scalar ... avx512"); the last is the
# default. Every dispatched path of the library is one of them.
read -r -a levels <<<"$(target/release/examples/isa_levels)"
best="${levels[${#levels[@]}-1]}"
echo "test.sh: [${SECONDS}s] ISA levels on this CPU: ${levels[*]} (default $best)"

# Integration tests (the C scenes against OSMesa among them) on the release library, as it
# ships, once per level, the default first. A level without FMA runs the
# reference llvmpipe with GALLIUM_OVERRIDE_CPU_CAPS=sse4.1, so that both sides fuse alike
# (src/simd/cpu.rs); the reference's output is reused between levels that pin it alike. Each
# level's raw outputs are kept for the cross-level check below.
outs=target/ctests/levels
rm -rf "$outs"
order=("$best")
for level in "${levels[@]}"; do
  [ "$level" != "$best" ] && order+=("$level")
done
# Every integration test runs at the default level. The other levels run the tests that
# draw through the dispatched paths and check pixels against a reference or an exact
# count (the C scenes against OSMesa, lighting, anisotropic filtering, rasterisation
# properties) and the 256 KiB-stack frame; `scalar`, the fallback of every path, also runs
# the robustness suites. The API, header, layering, GLU, GLUT, GLSL front-end and
# disassembly tests do not depend on the level, and would add minutes.
# (`--workspace` everywhere: the same package set, so the same features and one build.)
per_level=(--test osmesa_compare --test lighting_osmesa --test aniso_truth --test prop_raster
  --test small_stack)
for level in "${order[@]}"; do
  echo "test.sh: [${SECONDS}s] integration tests with SOFTGL_ISA=$level"
  if [ "$level" = "$best" ]; then
    SOFTGL_ISA=$level cargo test --release --workspace --test '*'
  elif [ "$level" = scalar ]; then
    SOFTGL_ISA=$level cargo test --release --workspace "${per_level[@]}" --test robust_api \
      --test robust_fuzz --test robust_regress --test robust_stress --test robust_threads \
      --test program_draw --test feedback --test shader_mesa
  else
    SOFTGL_ISA=$level cargo test --release --workspace "${per_level[@]}"
  fi
  mkdir -p "$outs/$level"
  cp target/ctests/out/*.out "$outs/$level/"
done
bash scripts/isa-compare.sh "$outs" "${levels[@]}"

# A real third-party client through the drop-in (bench/mujoco/README.md): MuJoCo from PyPI,
# in a venv made once and cached, renders its two test models at 640x480, single-sample and
# 4x multisample, through Mesa's llvmpipe and through softgl; every case must have 99.5% of
# its pixels within 2/255 of llvmpipe's. (Frame times are printed, never judged here.)
echo "test.sh: [${SECONDS}s] MuJoCo through the drop-in"
bash scripts/mujoco.sh --sizes 640x480 --samples 0,4 --frames 1 --min-within 99.5

# The libraries' own unit tests with debug assertions and overflow checks (Cargo.toml's
# `unit` profile, unoptimised), once per level. GLUT's unit tests link softgl's rlib (a
# dev-dependency); in the `unit` profile that would compile the library a second time (as
# a plain rlib beside its test harness), so they run once on the release rlib built above.
# (The crates have no doctests, so `cargo test --doc` is not run.)
cargo test --release -p softglut --lib
for level in "${levels[@]}"; do
  echo "test.sh: [${SECONDS}s] unit tests with SOFTGL_ISA=$level"
  SOFTGL_ISA=$level CARGO_TARGET_DIR=$unit_dir cargo test --profile unit --workspace \
    --exclude softglut --lib
done
echo "test.sh: [${SECONDS}s] all tests passed at the levels ${levels[*]}"
