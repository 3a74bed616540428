#!/usr/bin/env bash
# Compares softgl's raw outputs of the C scenes across instruction-set levels (the
# folders scripts/test.sh fills, one per level): usage DIR LEVEL... (the last level is
# the reference). A scene may differ between two levels where llvmpipe, pinned the same
# way (GALLIUM_OVERRIDE_CPU_CAPS=sse4.1 for the levels without FMA), differs too: that is
# where fusing multiply-adds changes a rounding. Otherwise it may differ only in a scene
# that is not byte-exact against llvmpipe at one of the two levels, i.e. one that passed
# its comparison through its stated tolerance (tests/osmesa_compare.rs); anything else
# fails.
set -euo pipefail
dir=$1
shift
levels=("$@")
ref="${levels[${#levels[@]}-1]}"
status=0
for level in "${levels[@]}"; do
  [ "$level" = "$ref" ] && continue
  same=0 both=0 tolerated=0 n=0
  bad=() tol=()
  for f in "$dir/$ref"/*.softgl.out; do
    name=$(basename "$f" .softgl.out)
    n=$((n + 1))
    if cmp -s "$f" "$dir/$level/$name.softgl.out"; then
      same=$((same + 1))
    elif ! cmp -s "$dir/$ref/$name.osmesa.out" "$dir/$level/$name.osmesa.out"; then
      both=$((both + 1))
    elif cmp -s "$f" "$dir/$ref/$name.osmesa.out" &&
      cmp -s "$dir/$level/$name.softgl.out" "$dir/$level/$name.osmesa.out"; then
      bad+=("$name")
    else
      tolerated=$((tolerated + 1))
      tol+=("$name")
    fi
  done
  echo "isa-compare: $level vs $ref: $n scenes, $same byte-identical, $both differ where llvmpipe differs too, $tolerated differ within their tolerance against llvmpipe (${tol[*]:-none}), ${#bad[@]} differ otherwise"
  if [ "${#bad[@]}" -gt 0 ]; then
    echo "isa-compare: FAILED: softgl differs between $level and $ref where llvmpipe does not: ${bad[*]}"
    status=1
  fi
done
exit $status
