#!/usr/bin/env bash
# piglit as a standing yardstick: builds piglit's GL 1.x tests over softglut and runs
# each one twice, on softgl (its drop-in libOSMesa.so.8) and on Mesa's llvmpipe
# libOSMesa.so.8, through the same softglut. See bench/piglit/README.md. Run by hand,
# never as a test or in CI.
#
#   bash bench/piglit/run.sh [options]
#     --set core|more|all   which tests of bench/piglit/tests.txt (default: all)
#     --only NAME[,NAME]    just these tests (NAME as in tests.txt)
#     --timeout S           seconds before a run is killed (default 60)
#     --build-only          build, do not run
#     --no-build            run what an earlier build left (no cargo, no make)
#     --record              also copy the results table to bench/piglit/results.md
#
# PIGLIT_SRC: a piglit source tree. Default: target/piglit/src, made from the bare
# mirror /work/.mirror/mesa3d+piglit/repo (its HEAD) when that exists. Otherwise clone
# Mesa's piglit repository yourself and set PIGLIT_SRC to it.
# MESA_OSMESA_DIR: the folder holding Mesa's libOSMesa.so.8 (default: Debian's).
# Everything is built under target/piglit/; results in target/piglit/results.{tsv,md}
# and one log per test and side in target/piglit/logs/.
set -euo pipefail
cd "$(dirname "$0")/../.."
repo="$PWD"
here="$repo/bench/piglit"
out="$repo/target/piglit"
mirror=/work/.mirror/mesa3d+piglit/repo
mesa_dir="${MESA_OSMESA_DIR:-/usr/lib/x86_64-linux-gnu}"

set_name=all only="" timeout=60 build=1 run=1 record=0
while [ $# -gt 0 ]; do
  case "$1" in
    --set) set_name="$2"; shift ;;
    --only) only="$2"; shift ;;
    --timeout) timeout="$2"; shift ;;
    --build-only) run=0 ;;
    --no-build) build=0 ;;
    --record) record=1 ;;
    -h|--help) sed -n '2,20p' "$0"; exit 0 ;;
    *) echo "run.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
  esac
  shift
done
case "$set_name" in core|more|all) ;; *) echo "run.sh: --set core|more|all" >&2; exit 2 ;; esac
mkdir -p "$out"

# The tests: "SET NAME EXE ARGS..." lines of tests.txt, filtered by --set and --only.
tests=()
while read -r set name cmd; do
  case "$set" in ''|'#'*) continue ;; esac
  [ "$set_name" = all ] || [ "$set" = "$set_name" ] || continue
  if [ -n "$only" ]; then
    case ",$only," in *",$name,"*) ;; *) continue ;; esac
  fi
  tests+=("$set	$name	$cmd")
done <"$here/tests.txt"
[ ${#tests[@]} -gt 0 ] || { echo "run.sh: no test selected" >&2; exit 2; }
# glinfo (always built) names each side's renderer before the tests run.
targets=$( (echo glinfo; printf '%s\n' "${tests[@]}" | cut -f3 | awk '{print $1}') | sort -u)

# piglit's source.
src="${PIGLIT_SRC:-$out/src}"
if [ -z "${PIGLIT_SRC:-}" ] && [ ! -f "$src/CMakeLists.txt" ]; then
  if [ -d "$mirror" ]; then
    echo "run.sh: unpacking piglit $(git --git-dir="$mirror" rev-parse --short HEAD) from $mirror"
    rm -rf "$src.tmp" && mkdir -p "$src.tmp"
    git --git-dir="$mirror" archive HEAD | tar -x -C "$src.tmp"
    git --git-dir="$mirror" rev-parse HEAD >"$src.tmp/.piglit-commit"
    mv "$src.tmp" "$src"
  else
    echo "run.sh: no piglit source. Clone Mesa's piglit repository and run again with" >&2
    echo "  PIGLIT_SRC=/path/to/piglit bash bench/piglit/run.sh" >&2
    exit 1
  fi
fi
[ -f "$src/tests/util/piglit-framework-gl/piglit_glut_framework.c" ] ||
  { echo "run.sh: $src is not a piglit source tree" >&2; exit 1; }
src="$(cd "$src" && pwd)"
commit=$(cat "$src/.piglit-commit" 2>/dev/null || git -C "$src" rev-parse HEAD 2>/dev/null || echo unknown)

if [ $build -eq 1 ]; then
  t0=$(date +%s)
  # Tools: a C compiler and Mesa's OSMesa (ensure-deps), cmake, and a venv with the
  # Python modules piglit's CMake requires.
  bash scripts/ensure-deps.sh
  command -v cmake >/dev/null 2>&1 || {
    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq cmake
  }
  venv="${SOFTGL_PIGLIT_VENV:-$HOME/.cache/softgl/piglit-venv}"
  if ! cmp -s "$here/requirements.txt" "$venv/.softgl-requirements" 2>/dev/null; then
    echo "run.sh: creating $venv"
    rm -rf "$venv" && mkdir -p "$(dirname "$venv")"
    if ! /usr/bin/python3 -m venv "$venv"; then
      apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq python3-venv
      /usr/bin/python3 -m venv "$venv"
    fi
    "$venv/bin/pip" install -q --disable-pip-version-check -r "$here/requirements.txt"
    cp "$here/requirements.txt" "$venv/.softgl-requirements"
  fi

  # softgl and softglut, installed as scripts/install.sh lays them out.
  nice -n 10 cargo build --release -p softgl -p softglut
  SOFTGL_LIB="$repo/target/release/libsoftgl.so" bash scripts/install.sh "$out/prefix" >/dev/null

  # The GLUT headers piglit compiles with: softglut's, plus freeglut_ext.h (see there).
  rm -rf "$out/include" && mkdir -p "$out/include/GL"
  for h in glut.h freeglut.h glu.h; do cp "$out/prefix/include/GL/$h" "$out/include/GL/"; done
  cp "$here/include/GL/freeglut_ext.h" "$out/include/GL/"
  # piglit's "OpenGL library": glXGetProcAddressARB answered by OSMesa (glx_osmesa.c),
  # linked against Mesa's libOSMesa.so only to record NEEDED libOSMesa.so.8.
  cc -shared -fPIC -O2 -Wall -o "$out/libglx_osmesa.so" "$here/glx_osmesa.c" -lOSMesa

  mkdir -p "$out/build"
  if [ ! -f "$out/build/CMakeCache.txt" ] || ! grep -q "^CMAKE_HOME_DIRECTORY:INTERNAL=$src\$" "$out/build/CMakeCache.txt"; then
    rm -rf "$out/build" && mkdir -p "$out/build"
    echo "run.sh: configuring piglit (log: target/piglit/cmake.log)"
    (cd "$out/build" && nice -n 19 cmake "$src" -Wno-dev \
      -DCMAKE_BUILD_TYPE=Release \
      -DPIGLIT_USE_WAFFLE=OFF \
      -DPIGLIT_BUILD_GLES1_TESTS=OFF -DPIGLIT_BUILD_GLES2_TESTS=OFF \
      -DPIGLIT_BUILD_GLES3_TESTS=OFF -DPIGLIT_BUILD_VK_TESTS=OFF \
      -DPIGLIT_BUILD_CL_TESTS=OFF -DPIGLIT_BUILD_GLX_TESTS=OFF \
      -DPIGLIT_BUILD_DMA_BUF_TESTS=OFF \
      -DOPENGL_gl_LIBRARY="$out/libglx_osmesa.so" \
      -DOPENGL_glx_LIBRARY="$out/libglx_osmesa.so" \
      -DOPENGL_opengl_LIBRARY="$out/libglx_osmesa.so" \
      -DGLUT_glut_LIBRARY="$out/prefix/lib/libsoftglut.so" \
      -DGLUT_INCLUDE_DIR="$out/include" \
      -DPYTHON_EXECUTABLE="$venv/bin/python") >"$out/cmake.log" 2>&1 ||
      { tail -30 "$out/cmake.log"; exit 1; }
  fi
  echo "run.sh: building $(echo "$targets" | wc -l) piglit executables (log: target/piglit/make.log)"
  # shellcheck disable=SC2086
  # -k: a test that does not build is reported as "notbuilt", the others still run.
  (cd "$out/build" && nice -n 19 make -k -j1 $targets) >"$out/make.log" 2>&1 ||
    echo "run.sh: some targets failed to build (errors in target/piglit/make.log)"
  t1=$(date +%s)
  echo "run.sh: build took $((t1 - t0)) s"
fi
[ $run -eq 1 ] || exit 0

# The runs: every test on each side, in a scratch folder (softglut would write frames
# there), killed after --timeout seconds.
[ -f "$mesa_dir/libOSMesa.so.8" ] || { echo "run.sh: no $mesa_dir/libOSMesa.so.8" >&2; exit 1; }
[ -e "$out/prefix/lib/osmesa/libOSMesa.so.8" ] || { echo "run.sh: build first" >&2; exit 1; }
rm -rf "$out/logs" "$out/scratch"
mkdir -p "$out/logs/softgl" "$out/logs/mesa" "$out/scratch"
tsv="$out/results.tsv"
printf 'set\tname\tcommand\tsoftgl\tsoftgl_s\tmesa\tmesa_s\n' >"$tsv"

# result LOG RC: piglit's last reported result, else what the exit code says.
result() {
  local r
  r=$(grep -o '"result": *"[a-z]*"' "$1" | tail -n 1 | sed 's/.*"\([a-z]*\)"$/\1/' || true)
  if [ "$2" -eq 124 ] || [ "$2" -eq 137 ]; then echo timeout
  elif [ -n "$r" ]; then echo "$r"
  elif [ "$2" -gt 128 ]; then echo crash
  else echo "noresult"
  fi
}

run_side() { # SIDE LIBDIR NAME CMD...
  local side="$1" dir="$2" name="$3" log rc t0 t1
  shift 3
  log="$out/logs/$side/$name.log"
  t0=$(date +%s%N)
  rc=0
  (cd "$out/scratch" && LD_LIBRARY_PATH="$dir" GALLIUM_DRIVER=llvmpipe \
    PIGLIT_SOURCE_DIR="$src" \
    timeout -k 5 "$timeout" "$out/build/bin/$@" -auto) >"$log" 2>&1 || rc=$?
  t1=$(date +%s%N)
  [ -x "$out/build/bin/$1" ] || { echo "$1 was not built" >>"$log"; printf 'notbuilt\t0'; return; }
  local cs=$(((t1 - t0) / 10000000))
  printf '%s\t%d.%02d' "$(result "$log" "$rc")" $((cs / 100)) $((cs % 100))
}

# Which GL each side really is: softgl must not say llvmpipe, Mesa must.
run_side softgl "$out/prefix/lib/osmesa" glinfo glinfo >/dev/null
run_side mesa "$mesa_dir" glinfo glinfo >/dev/null
for side in softgl mesa; do
  echo "run.sh: $side: $(grep -m1 '^GL_RENDERER' "$out/logs/$side/glinfo.log" || echo '?')"
done
grep -q '^GL_RENDERER.*llvmpipe' "$out/logs/mesa/glinfo.log" &&
  ! grep -q '^GL_RENDERER.*llvmpipe' "$out/logs/softgl/glinfo.log" ||
  { echo "run.sh: the two sides are not softgl and llvmpipe (see logs/*/glinfo.log)" >&2; exit 1; }
r0=$(date +%s)
n=0
for t in "${tests[@]}"; do
  IFS=$'\t' read -r set name cmd <<<"$t"
  n=$((n + 1))
  # shellcheck disable=SC2086
  s=$(run_side softgl "$out/prefix/lib/osmesa" "$name" $cmd)
  # shellcheck disable=SC2086
  m=$(run_side mesa "$mesa_dir" "$name" $cmd)
  printf '%s\t%s\t%s\t%s\t%s\n' "$set" "$name" "$cmd" "$s" "$m" >>"$tsv"
  printf '[%3d/%d] %-50s softgl %-8s mesa %s\n' "$n" "${#tests[@]}" "$name" "${s%%	*}" "${m%%	*}"
done
r1=$(date +%s)
echo "run.sh: ran ${#tests[@]} tests on both sides in $((r1 - r0)) s"

python3 "$here/report.py" "$tsv" "$out/logs" --piglit "$commit" \
  --softgl "$(git -C "$repo" rev-parse --short HEAD)" --seconds $((r1 - r0)) --src "$src" \
  >"$out/results.md"
sed -n '/^## Totals/,/^## Pass on Mesa, fail/p' "$out/results.md" | sed '$d'
echo "run.sh: wrote target/piglit/results.md and results.tsv"
if [ $record -eq 1 ]; then
  cp "$out/results.md" "$here/results.md"
  echo "run.sh: copied to bench/piglit/results.md"
fi
