#!/usr/bin/env bash
# The README's test command: installs what is missing, builds the library and runs every
# test (unit, API, header, and the C scenes compared against Mesa's OSMesa).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/ensure-deps.sh
cargo fmt --all -- --check
cargo clippy --release --workspace --all-targets -- -D warnings
cargo build --release --workspace
# Integration tests (the C scenes against OSMesa among them) and examples on the release
# library, as it ships; then the doc tests.
cargo test --release --workspace --test '*' --examples
cargo test --release --workspace --doc
# The libraries' own unit tests, unoptimised with debug assertions and overflow checks
# (Cargo.toml's `unit` profile): a release build of the unit-test harness is a second
# full optimised compile of the library, half of CI's time.
cargo test --profile unit --workspace --lib
