#!/usr/bin/env bash
# Memory-safety checks of the unsafe-heavy paths.
#
# Miri needs a nightly toolchain with the miri component, and AddressSanitizer needs
# nightly `-Zsanitizer`; neither is used by default here. Instead everything runs under
# valgrind memcheck (invalid reads/writes, uninitialised values, definite leaks):
#   1. every C scene in c_tests/ linked against target/release/libsoftgl.so;
#   2. the Rust robustness tests (hostile API table, regressions, threads, and a
#      20 000-call fuzz run) as test binaries.
# Set SANITIZE_ASAN=1 to also run the robust tests with nightly AddressSanitizer when
# `cargo +nightly` is installed. Exits non-zero on the first tool error.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v valgrind >/dev/null || { echo "valgrind not installed (apt-get install valgrind)"; exit 2; }
VG=(valgrind -q --error-exitcode=1 --leak-check=full --errors-for-leak-kinds=definite
    --show-leak-kinds=definite)
cargo build --release --lib
lib="$PWD/target/release"
out=target/sanitize
mkdir -p "$out"
fail=0
n=0
for src in c_tests/*.c; do
    name=$(basename "$src" .c)
    "${CC:-cc}" -O1 -g -Wall -Iinclude "$src" -o "$out/$name" -L"$lib" -lsoftgl \
        -Wl,-rpath,"$lib" -lm
    if "${VG[@]}" "$out/$name" "$out/$name.out" >"$out/$name.vg" 2>&1; then
        n=$((n + 1))
    else
        echo "valgrind: C scene $name FAILED:"; cat "$out/$name.vg"; fail=1
    fi
done
echo "valgrind: $n C scenes clean"
for t in robust_api robust_regress robust_threads robust_fuzz; do
    bin=$(cargo test --release --test "$t" --no-run 2>&1 | grep -o "target/release/deps/$t-[0-9a-f]*" | head -1)
    if [ "$t" = robust_fuzz ]; then
        args=(--ignored --exact fuzz_long)
    else
        args=()
    fi
    if SOFTGL_FUZZ_CALLS=20000 SOFTGL_FUZZ_SEED=7 RUST_BACKTRACE=0 "${VG[@]}" "$bin" \
        --test-threads=1 "${args[@]}" >"$out/$t.vg" 2>&1; then
        echo "valgrind: $t clean ($(grep -h 'test result' "$out/$t.vg" | head -1))"
    else
        echo "valgrind: $t FAILED:"; tail -60 "$out/$t.vg"; fail=1
    fi
done
if [ "${SANITIZE_ASAN:-0}" = 1 ] && cargo +nightly --version >/dev/null 2>&1; then
    RUSTFLAGS="-Zsanitizer=address" cargo +nightly test --target x86_64-unknown-linux-gnu \
        --release --test robust_api --test robust_regress --test robust_threads \
        --test robust_fuzz || fail=1
fi
exit $fail
