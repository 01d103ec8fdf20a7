#!/usr/bin/env bash
# The mirrors' and glasses' own pixels in Blender 3.4's Cycles and in f3d
# 1.3, beside sfrender's (bench/gltf_materials_check.py; docs/GLTF_VIEWERS.md,
# "Materials in PBR viewers, measured"). A measurement, not a test: about 30
# seconds a scene on two cores.
#
# bench/gltf_materials_bench.sh [BUILD [WORKDIR [WIDTH HEIGHT SAMPLES]]]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
build=${1:-$root/build}
work=${2:-$build/bench/gltf-materials}
width=${3:-320} height=${4:-240} samples=${5:-128}
for tool in blender pnmtopng; do
  command -v "$tool" >/dev/null 2>&1 || { echo "SKIP: $tool is not installed"; exit 77; }
done
mkdir -p "$work"
"$build/bin/write_default_scene" "$work/default-scene.txt"
exec blender -b --factory-startup --python-exit-code 1 --python "$here/gltf_materials_check.py" \
  -- "$build/bin/sfconvert" "$build/bin/sfrender" "$work" "$width" "$height" "$samples" \
  "default=$work/default-scene.txt" \
  "$root/bench/scenes/glass-mirror.txt" \
  "$root/testdata/pov/export/glass-and-mirror.txt" \
  "$root/testdata/render-cost/glass-room.txt" 2>&1 | grep -v "^Fra:\|^Saved\|^ Time\|^Blender\|^Read\|^$"
