#!/usr/bin/env bash
# The README's demo command: builds libsoftgl.so, compiles examples/demo.c against our
# headers exactly as an OSMesa user would, and renders demo.png.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/ensure-deps.sh
cargo build --release
lib="$(pwd)/target/release"
cc -O2 -Wall -Iinclude examples/demo.c -o target/demo -L"$lib" -lsoftgl -Wl,-rpath,"$lib" -lm
./target/demo "${1:-demo.png}"
echo "wrote ${1:-demo.png}"
