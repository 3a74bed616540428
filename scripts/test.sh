#!/usr/bin/env bash
# The README's test command: installs what is missing, builds the library and runs every
# test (unit, API, header, and the C scenes compared against Mesa's OSMesa).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/ensure-deps.sh
cargo fmt --all -- --check
cargo clippy --release --workspace --all-targets -- -D warnings
cargo build --release --workspace
cargo test --release --workspace
