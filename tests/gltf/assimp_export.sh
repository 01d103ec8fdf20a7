#!/usr/bin/env bash
# assimp 5.2.5 (Debian's assimp-utils) converts sfconvert's glTF of the
# default scene written with --no-lights --no-extras: `assimp export` to OBJ
# succeeds with one object per scene object. The same export with extras
# (still without lights) aborts, so --no-extras is what makes it pass.
#
# assimp_export.sh SFCONVERT WORKDIR DEFAULT_SCENE.txt
set -euo pipefail
sfconvert=$1 work=$2 source=$3
if ! command -v assimp >/dev/null 2>&1; then
  echo "SKIP: assimp is not installed (apt-get install assimp-utils)"; exit 77
fi
mkdir -p "$work"
rm -f "$work"/plain.* "$work"/exact.*

"$sfconvert" "$source" "$work/plain.gltf" --no-lights --no-extras 2>"$work/plain.stderr"
grep -q "the glTF is written without extras.* \[gltf-extras-left-out\]" "$work/plain.stderr" || {
  cat "$work/plain.stderr"; echo "no loss warning for the extras"; exit 1; }
[[ $(grep -c "gltf-extras-left-out" "$work/plain.stderr") == 1 ]] || {
  cat "$work/plain.stderr"; echo "the extras' loss is not reported once"; exit 1; }
if grep -q '"extras"' "$work/plain.gltf"; then echo "plain.gltf holds extras"; exit 1; fi
assimp export "$work/plain.gltf" "$work/plain.obj" >"$work/plain.log" 2>&1 || {
  cat "$work/plain.log"; echo "assimp export failed on the --no-lights --no-extras export"; exit 1; }
objects=$(grep -c '^[og] ' "$work/plain.obj" || true)
echo "--no-lights --no-extras: assimp export writes $objects objects"
[[ $objects == 6 ]] || { echo "expected 6 objects (o or g lines) in plain.obj"; exit 1; }

"$sfconvert" "$source" "$work/exact.gltf" --no-lights 2>/dev/null
if (assimp export "$work/exact.gltf" "$work/exact.obj") >"$work/exact.log" 2>&1; then
  echo "assimp export converted the export with extras: --no-extras is not what makes it pass"
  exit 1
fi
echo "with extras: assimp export fails ($(tail -n 1 "$work/exact.log"))"
echo "assimp: the --no-lights --no-extras export converts to OBJ"
