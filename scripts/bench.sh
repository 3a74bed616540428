#!/usr/bin/env bash
# The benchmark (run by hand, never as a test): installs what is missing, builds
# libsoftgl.so and the runner, compiles the C scenes in bench/scenes/ against softgl and
# against Mesa's OSMesa, and times softgl, llvmpipe (1 thread) and llvmpipe (default
# threads) in alternation. Results: target/bench/results.md (also printed), results.csv,
# process.csv, clear_memset.csv, time_vs_error.png. See bench/README.md.
#
# Options are passed to the runner: --reps N (default 9), --frames N (10),
# --sizes 512,1024, --scenes a,c,big_triangles, --timeout S (120), --wall-reps N,
# --wall-size N (512); or the env vars BENCH_REPS, BENCH_FRAMES, ... of the same names.
# --filter-study runs the filter study instead (bench/filter_study.md, docs/filter_study.png).
# --sweep N [--sweep-seed S] runs the seeded state sweep instead (bench/sweep.md).
# Then MuJoCo's models through the drop-in against llvmpipe, every size and sample count
# (scripts/mujoco.sh, results in target/mujoco/results.md); BENCH_MUJOCO=0 leaves it out.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/ensure-deps.sh
cargo build --release
cargo build --release --example bench
target/release/examples/bench "$@"
case " $* " in *" --filter-study "* | *" --sweep "*) exit 0 ;; esac
if [ "${BENCH_MUJOCO:-1}" != 0 ]; then
  bash scripts/mujoco.sh
fi
