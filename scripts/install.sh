#!/usr/bin/env bash
# Builds libsoftgl.so (release) and installs it under PREFIX (default:
# target/release/dist; a relative PREFIX is taken from the current folder):
#
#   PREFIX/lib/libsoftgl.so
#   PREFIX/lib/osmesa/libOSMesa.so.8   -> ../libsoftgl.so  (the binary drop-in)
#   PREFIX/lib/osmesa/libOSMesa.so        linker script: -lOSMesa links libOSMesa.so.8
#   PREFIX/include/GL/{gl.h,glext.h,osmesa.h}
#   PREFIX/lib/pkgconfig/softgl.pc        -I/-L/-l/-rpath for libsoftgl.so
#   PREFIX/lib/pkgconfig/osmesa.pc        Debian's osmesa.pc, pointing at lib/osmesa
#   PREFIX/lib/libsoftglut.so             GLUT + GLU (the `glut/` workspace member)
#   PREFIX/include/GL/{glut,freeglut,glu}.h
#   PREFIX/lib/pkgconfig/softgl-glut.pc   -lsoftglut -lsoftgl, for GLUT programs
#
# A program linked against Mesa's OSMesa then runs on softgl with
#   LD_LIBRARY_PATH=PREFIX/lib/osmesa ./prog
#
# SOFTGL_LIB=/path/to/libsoftgl.so installs that file instead of building (the tests
# use it to install the library `cargo test` just built); SOFTGLUT_LIB likewise names
# libsoftglut.so (default: next to SOFTGL_LIB; GLUT is skipped when it is absent).
set -euo pipefail

usage() {
  echo "usage: bash scripts/install.sh [PREFIX]   (default: target/release/dist)" >&2
  exit 2
}
[ $# -le 1 ] || usage
case "${1:-}" in -h|--help) usage ;; esac

repo="$(cd "$(dirname "$0")/.." && pwd)"
target="${CARGO_TARGET_DIR:-$repo/target}"
case "$target" in /*) ;; *) target="$repo/$target" ;; esac
prefix="${1:-$target/release/dist}"
mkdir -p "$prefix"
prefix="$(cd "$prefix" && pwd)"   # .pc files need an absolute prefix

if [ -n "${SOFTGL_LIB:-}" ]; then
  lib="$SOFTGL_LIB"
  glut="${SOFTGLUT_LIB:-$(dirname "$lib")/libsoftglut.so}"
else
  (cd "$repo" && cargo build --release --workspace)
  lib="$target/release/libsoftgl.so"
  glut="$target/release/libsoftglut.so"
fi
[ -f "$lib" ] || { echo "install.sh: $lib does not exist" >&2; exit 1; }

version="$(sed -n 's/^version *= *"\(.*\)"/\1/p' "$repo/Cargo.toml" | head -n 1)"

mkdir -p "$prefix/lib/osmesa" "$prefix/lib/pkgconfig" "$prefix/include/GL"
# Write-then-rename, so a program running from an earlier install keeps its mapping.
install -m 0755 "$lib" "$prefix/lib/.libsoftgl.so.new"
mv -f "$prefix/lib/.libsoftgl.so.new" "$prefix/lib/libsoftgl.so"

# The drop-in: executables linked with -lOSMesa need "libOSMesa.so.8" (Mesa's SONAME)
# and the loader looks it up by file name only, so a link to libsoftgl.so is enough.
# A symlink (not a copy) lets a process that loads both names share one softgl.
ln -sfn ../libsoftgl.so "$prefix/lib/osmesa/libOSMesa.so.8"
# libsoftgl.so has no SONAME, so linking through a plain libOSMesa.so symlink would
# record "libOSMesa.so" as NEEDED; this script makes -lOSMesa record libOSMesa.so.8,
# exactly like Mesa's libOSMesa.so.
rm -f "$prefix/lib/osmesa/libOSMesa.so"
printf '/* GNU ld script: link against the softgl drop-in as libOSMesa.so.8 */\nINPUT(-l:libOSMesa.so.8)\n' \
  >"$prefix/lib/osmesa/libOSMesa.so"

install -m 0644 "$repo"/include/GL/gl.h "$repo"/include/GL/glext.h "$repo"/include/GL/osmesa.h \
  "$prefix/include/GL/"

if [ -f "$glut" ]; then
  install -m 0755 "$glut" "$prefix/lib/.libsoftglut.so.new"
  mv -f "$prefix/lib/.libsoftglut.so.new" "$prefix/lib/libsoftglut.so"
  install -m 0644 "$repo"/glut/include/GL/glut.h "$repo"/glut/include/GL/freeglut.h \
    "$repo"/glut/include/GL/glu.h "$prefix/include/GL/"
  pcs="softgl osmesa softgl-glut"
else
  pcs="softgl osmesa"
fi

# sed replacement text: escape \, & and the | delimiter.
esc="$(printf '%s' "$prefix" | sed -e 's/[\\&|]/\\&/g')"
for pc in $pcs; do
  sed -e "s|@PREFIX@|$esc|g" -e "s|@VERSION@|$version|g" \
    "$repo/pkgconfig/$pc.pc.in" >"$prefix/lib/pkgconfig/$pc.pc"
done

echo "installed softgl $version into $prefix"
echo "  run an OSMesa program on softgl: LD_LIBRARY_PATH=$prefix/lib/osmesa ./prog"
echo "  build against softgl:            PKG_CONFIG_PATH=$prefix/lib/pkgconfig pkg-config --cflags --libs softgl"
[ -f "$prefix/lib/libsoftglut.so" ] &&
  echo "  build a GLUT program:            PKG_CONFIG_PATH=$prefix/lib/pkgconfig pkg-config --cflags --libs softgl-glut"
true
