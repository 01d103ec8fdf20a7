#!/usr/bin/env bash
# Exports every valid corpus scene and a set of seeded random scenes as
# .gltf (embedded and external buffer) and .glb, and runs the Khronos glTF
# Validator on every file: no error and no warning may remain.
# Usage: validate_exports.sh SFCONVERT MAKE_RANDOM_SCENES TESTDATA WORKDIR
# EVERY_NTH_SCENE=N (default 1) keeps every Nth scene.
# Exits 77 (skipped) when Node.js or the validator is not installed.
set -euo pipefail
sfconvert=$1 make_random=$2 testdata=$3 work=$4
here=$(cd "$(dirname "$0")" && pwd)
source "$here/every_nth_scene.sh"
if ! command -v node >/dev/null 2>&1; then
  echo "SKIP: node is not installed (scripts/install-deps.sh installs it)"; exit 77
fi
if [ ! -d "$here/node_modules/gltf-validator" ]; then
  echo "SKIP: tests/gltf/node_modules is missing (scripts/install-deps.sh runs npm ci)"; exit 77
fi
rm -rf "$work" && mkdir -p "$work/in" "$work/out"
cp "$testdata"/valid/*.sf "$testdata"/valid/*.txt "$work/in/"
"$make_random" "$work/in" 60 4242
keep_every_nth_scene "$work/in"
files=()
for input in "$work"/in/*; do
  name=$(basename "$input"); name=${name%.*}-${input##*.}
  "$sfconvert" "$input" "$work/out/$name.gltf" 2>/dev/null
  "$sfconvert" "$input" "$work/out/$name.glb" --fov 45 --width 640 --height 480 2>/dev/null
  "$sfconvert" "$input" "$work/out/$name-ext.gltf" --external-buffers --tessellation 5 2>/dev/null
  files+=("$work/out/$name.gltf" "$work/out/$name.glb" "$work/out/$name-ext.gltf")
done
node "$here/validate.js" "${files[@]}"
