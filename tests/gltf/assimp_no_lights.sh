#!/usr/bin/env bash
# assimp 5.2.5 (Debian's assimp-utils) reads sfconvert's --no-lights glTF of
# the default scene: `assimp info` succeeds, with every mesh and no light;
# the same export with lights shows them to assimp, the difference the flag
# makes. (`assimp export` of any glTF with a KHR_lights_punctual light
# aborts in SceneCombiner.cpp; so does one with node extras: docs/GLTF.md.)
#
# assimp_no_lights.sh SFCONVERT WORKDIR DEFAULT_SCENE.txt
set -euo pipefail
sfconvert=$1 work=$2 source=$3
if ! command -v assimp >/dev/null 2>&1; then
  echo "SKIP: assimp is not installed (apt-get install assimp-utils)"; exit 77
fi
mkdir -p "$work"
field() { sed -n "s/^$1: *//p" "$2" | head -n 1; }

"$sfconvert" "$source" "$work/dark.glb" --no-lights 2>"$work/dark.stderr"
grep -q "LIGHT 1 .* is left out: the glTF is written without lights \[gltf-light-left-out\]" \
  "$work/dark.stderr" || { cat "$work/dark.stderr"; echo "no loss warning for LIGHT 1"; exit 1; }
grep -q "wrote .*dark.glb (a binary glTF 2.0 file, 6 objects, 0 lights)" "$work/dark.stderr" || {
  cat "$work/dark.stderr"; echo "sfconvert does not say the file holds no light"; exit 1; }
assimp info "$work/dark.glb" >"$work/dark.info" 2>&1 || {
  cat "$work/dark.info"; echo "assimp info failed on the --no-lights export"; exit 1; }
meshes=$(field "Meshes" "$work/dark.info") lights=$(field "Lights" "$work/dark.info")
echo "--no-lights: assimp info reads $meshes meshes, $lights lights"
[[ $meshes == 6 && $lights == 0 ]] || { echo "expected 6 meshes and 0 lights"; exit 1; }

"$sfconvert" "$source" "$work/lit.glb" 2>/dev/null
assimp info "$work/lit.glb" >"$work/lit.info" 2>&1 || true
lights=$(field "Lights" "$work/lit.info")
echo "with lights: assimp info reads ${lights:-no} lights"
[[ $lights == 2 ]] || { echo "expected the export with lights to hold 2"; exit 1; }
echo "assimp: the --no-lights export is read without a light"
