#!/usr/bin/env bash
# Renders MuJoCo models (mujoco.Renderer, MUJOCO_GL=osmesa) through Mesa's llvmpipe
# libOSMesa.so.8 and through softgl's libsoftgl.so as a drop-in, and compares the images
# and the time per frame. See bench/mujoco/README.md. Run by hand, never as a test.
#
#   bash scripts/mujoco.sh [--reference-only] [compare.py options...]
#   bash scripts/mujoco.sh --trace [SAMPLES...]   GL call trace of MuJoCo (default on
#       Mesa; GLTRACE_LIB=path/to/libsoftgl.so traces another libOSMesa), written to
#       target/mujoco/trace-SIDE-MODEL-sN.txt by the shim bench/mujoco/gltrace/ generates
#
# --reference-only renders Mesa on both sides (a determinism check; no cargo build).
# Other options go to bench/mujoco/compare.py (--models, --sizes 640x480,1920x1080,
# --samples 0,4, --frames N, --lp-threads N, --diff, --out DIR; see its --help).
# The venv (mujoco and its pinned dependencies from bench/mujoco/requirements.txt) is
# made once at ${SOFTGL_MUJOCO_VENV:-$HOME/.cache/softgl/mujoco-venv}.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/ensure-deps.sh

venv="${SOFTGL_MUJOCO_VENV:-$HOME/.cache/softgl/mujoco-venv}"
req=bench/mujoco/requirements.txt
if ! cmp -s "$req" "$venv/.softgl-requirements" 2>/dev/null; then
  echo "mujoco.sh: creating $venv"
  rm -rf "$venv"
  mkdir -p "$(dirname "$venv")"
  if ! python3 -m venv "$venv"; then
    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq python3-venv
    python3 -m venv "$venv"
  fi
  "$venv/bin/pip" install -q --disable-pip-version-check -r "$req"
  cp "$req" "$venv/.softgl-requirements"
fi
py="$venv/bin/python"

if [ "${1:-}" = "--trace" ]; then
  shift
  out=target/mujoco
  mkdir -p "$out/lib-trace"
  python3 bench/mujoco/gltrace/gen_gltrace.py "$out/gltrace.c"
  cc -shared -fPIC -O1 -w "$out/gltrace.c" -o "$out/gltrace.so" -ldl -lpthread
  for n in libOSMesa.so libOSMesa.so.8; do
    ln -sfn "$(realpath "${GLTRACE_LIB:-/usr/lib/x86_64-linux-gnu/libOSMesa.so.8}")" "$out/lib-trace/$n"
  done
  side=mesa
  [ -z "${GLTRACE_LIB:-}" ] || side=$(basename "$GLTRACE_LIB" .so)
  samples=("$@")
  [ ${#samples[@]} -gt 0 ] || samples=(0 4)
  for s in "${samples[@]}"; do
    for model in humanoid showcase; do
      GLTRACE_FILE="$out/trace-$side-$model-s$s.txt" LD_PRELOAD="$PWD/$out/gltrace.so" \
        MUJOCO_GL=osmesa PYOPENGL_PLATFORM=osmesa GALLIUM_DRIVER=llvmpipe \
        LD_LIBRARY_PATH="$PWD/$out/lib-trace${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" \
        "$py" bench/mujoco/render.py --model "$model" --samples "$s" --frames 1 --warmup 0 \
        --out "$out/trace-$side-$model-s$s.png" >/dev/null || true
      echo "wrote $out/trace-$side-$model-s$s.txt"
    done
  done
  exit 0
fi

build=1
for a in "$@"; do
  case "$a" in --reference-only|--softgl-lib|--softgl-lib=*|-h|--help) build=0 ;; esac
done
[ $build -eq 0 ] || cargo build --release
exec "$py" bench/mujoco/compare.py "$@"
