#!/usr/bin/env bash
# glTF-Transform's operations that keep geometry (copy, dedup, prune, weld,
# resample, instance, reorder; transform.mjs), each on the files sfconvert
# wrote for every valid corpus scene, seeded random scenes and scenes of many
# alike objects (which `instance` batches), as .gltf with an external buffer
# and as .glb: sfconvert must read every result back to the same .sf bytes as
# the file it was made from.
# Usage: transform_roundtrip.sh SFCONVERT MAKE_RANDOM_SCENES TESTDATA SCENES WORKDIR
# EVERY_NTH_SCENE=N (default 1) keeps SCENES and every Nth of the others.
# Exits 77 (skipped) when Node.js or glTF-Transform is not installed.
set -euo pipefail
sfconvert=$1 make_random=$2 testdata=$3 scenes=$4 work=$5
here=$(cd "$(dirname "$0")" && pwd)
source "$here/every_nth_scene.sh"
if ! command -v node >/dev/null 2>&1; then
  echo "SKIP: node is not installed (scripts/install-deps.sh installs it)"; exit 77
fi
if [ ! -d "$here/node_modules/@gltf-transform/functions" ]; then
  echo "SKIP: tests/gltf/node_modules lacks glTF-Transform (scripts/install-deps.sh runs npm ci)"
  exit 77
fi
rm -rf "$work" && mkdir -p "$work/in" "$work/gltf" "$work/direct" "$work/back"
cp "$testdata"/valid/*.sf "$testdata"/valid/*.txt "$work/in/"
"$make_random" "$work/in" 30 2612
keep_every_nth_scene "$work/in"
cp "$scenes"/*.sf "$work/in/"
for input in "$work"/in/*; do
  name=$(basename "$input"); name=${name%.*}-${input##*.}
  "$sfconvert" "$input" "$work/gltf/$name.glb" 2>/dev/null
  "$sfconvert" "$input" "$work/gltf/$name.gltf" --external-buffers --tessellation 7 2>/dev/null
done
for file in "$work"/gltf/*.gltf "$work"/gltf/*.glb; do
  "$sfconvert" "$file" "$work/direct/$(basename "$file").sf" 2>/dev/null
done
node "$here/transform.mjs" "$work/out" "$work"/gltf/*.gltf "$work"/gltf/*.glb
failed=0 checked=0
for operation in copy dedup prune weld resample instance reorder; do
  for file in "$work/out/$operation"/*.gltf "$work/out/$operation"/*.glb; do
    name=$(basename "$file")
    back="$work/back/$operation-$name.sf"
    checked=$((checked + 1))
    if ! "$sfconvert" "$file" "$back" 2>"$back.log" ||
       ! cmp -s "$work/direct/$name.sf" "$back"; then
      echo "FAIL: $operation $name does not read back as sfconvert's own file ($back.log)"
      failed=$((failed + 1))
    fi
  done
done
echo "$checked files checked, $failed differ"
[ "$failed" -eq 0 ]
