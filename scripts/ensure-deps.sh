#!/usr/bin/env bash
# Installs what the tests and the demo need on a fresh Debian machine: a C compiler,
# binutils (nm), Mesa's OSMesa (the reference the C scenes are compared against; it brings
# libgl-dev, whose GL/gl.h and GL/glext.h tests/headers.rs compares ours with), SGI's
# libGLU (the reference for softglut's GLU), freeglut with Xvfb and Mesa's GLX llvmpipe
# (the reference for softglut's shapes and menus) and the Khronos registry gl.xml
# (khronos-api), from which tools/gen_glext.py makes GL/glext.h.
set -euo pipefail
need=()
command -v cc >/dev/null 2>&1 || need+=(gcc libc6-dev)
command -v nm >/dev/null 2>&1 || need+=(binutils)
command -v python3 >/dev/null 2>&1 || need+=(python3)
command -v pkg-config >/dev/null 2>&1 || need+=(pkg-config)
[ -f /usr/include/GL/osmesa.h ] || need+=(libosmesa6-dev)
[ -f /usr/include/GL/glext.h ] || need+=(libgl-dev)
# libGLU: tests/dropin.rs and tests/glu_reference.rs compare against the system GLU.
[ -f /usr/include/GL/glu.h ] || need+=(libglu1-mesa-dev)
[ -f /usr/share/khronos-api/gl.xml ] || need+=(khronos-api)
# freeglut, an X server and llvmpipe for GLX: tests/glut_freeglut.rs draws GLUT's shapes
# and tests/glut_reference.rs checks menus with the real freeglut under Xvfb.
[ -f /usr/include/GL/freeglut.h ] || need+=(libglut-dev)
command -v Xvfb >/dev/null 2>&1 || need+=(xvfb)
compgen -G "/usr/lib/*/dri/swrast_dri.so" >/dev/null || need+=(libgl1-mesa-dri)
if [ ${#need[@]} -gt 0 ]; then
  echo "ensure-deps: installing ${need[*]}"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${need[@]}"
fi
