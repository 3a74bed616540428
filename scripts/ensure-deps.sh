#!/bin/sh
# ensure-deps.sh - install what the C comparison tests need, only if missing:
# a C compiler and Mesa's OSMesa (headers + libOSMesa, package libosmesa6-dev),
# which is the reference softgl is compared against.
# Usage: scripts/ensure-deps.sh   (as root, or with sudo available)
set -e

need=""
[ -f /usr/include/GL/osmesa.h ] || need="$need libosmesa6-dev"
command -v cc >/dev/null 2>&1 || need="$need gcc libc6-dev"

if [ -z "$need" ]; then
    exit 0
fi

if [ "$(id -u)" = 0 ]; then
    SUDO=""
elif command -v sudo >/dev/null 2>&1; then
    SUDO="sudo"
else
    echo "ensure-deps: need$need but not root and no sudo" >&2
    exit 1
fi

echo "ensure-deps: installing$need" >&2
export DEBIAN_FRONTEND=noninteractive
# shellcheck disable=SC2086
if ! $SUDO apt-get install -y $need; then
    $SUDO apt-get update
    $SUDO apt-get install -y $need
fi
test -f /usr/include/GL/osmesa.h
