#!/usr/bin/env bash
# Installs what the tests and the demo need on a fresh Debian machine: a C compiler,
# binutils (nm), Mesa's OSMesa (the reference the C scenes are compared against),
# SGI's libGLU (the reference for softglut's GLU), and freeglut with Xvfb and Mesa's
# GLX llvmpipe (the reference for softglut's shapes).
set -euo pipefail
need=()
command -v cc >/dev/null 2>&1 || need+=(gcc libc6-dev)
command -v nm >/dev/null 2>&1 || need+=(binutils)
command -v python3 >/dev/null 2>&1 || need+=(python3)
command -v pkg-config >/dev/null 2>&1 || need+=(pkg-config)
[ -f /usr/include/GL/osmesa.h ] || need+=(libosmesa6-dev)
# libGLU: tests/dropin.rs and tests/glu_reference.rs compare against the system GLU.
[ -f /usr/include/GL/glu.h ] || need+=(libglu1-mesa-dev)
# freeglut, an X server and llvmpipe for GLX: tests/glut_freeglut.rs draws GLUT's shapes
# with the real freeglut under Xvfb.
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
