#!/usr/bin/env bash
# Long fuzz run: scripts/fuzz.sh CALLS [JOBS] [FIRST_SEED]
# Runs JOBS processes (default 1) of CALLS GL calls each, seeds FIRST_SEED.. (default 100),
# through the ignored test robust_fuzz::fuzz_long in release mode. Prints each process's
# summary and the total; exits non-zero when any process crashes or fails.
set -euo pipefail
cd "$(dirname "$0")/.."
calls=${1:-1000000}
jobs=${2:-1}
seed0=${3:-100}
cargo test --release --test robust_fuzz --no-run >/dev/null 2>&1 || cargo test --release --test robust_fuzz --no-run
bin=$(cargo test --release --test robust_fuzz --no-run 2>&1 | grep -o 'target/release/deps/robust_fuzz-[0-9a-f]*' | head -1)
pids=()
logs=()
for ((j = 0; j < jobs; j++)); do
    log=$(mktemp)
    logs+=("$log")
    SOFTGL_FUZZ_CALLS=$calls SOFTGL_FUZZ_SEED=$((seed0 + j)) RUST_BACKTRACE=1 \
        "$bin" --ignored --nocapture --exact fuzz_long >"$log" 2>&1 &
    pids+=($!)
done
fail=0
total=0
for ((j = 0; j < jobs; j++)); do
    if wait "${pids[$j]}"; then
        grep 'fuzz seed' "${logs[$j]}"
        total=$((total + calls))
    else
        echo "seed $((seed0 + j)) FAILED:" >&2
        tail -40 "${logs[$j]}" >&2
        fail=1
    fi
    rm -f "${logs[$j]}"
done
echo "total: $total calls without a crash"
exit $fail
