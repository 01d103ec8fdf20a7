#!/usr/bin/env bash
# f3d, a second glTF viewer: renders sfconvert's export of each scene and
# prints its mean brightness beside sfrender's, as the Blender check does
# (docs/GLTF.md, "Lights"). A measurement, not a test: f3d 1.3.1 (VTK 9.1)
# gives a point light no falloff and takes its intensity as a plain factor,
# which the export's --light-falloff none writes (docs/GLTF_VIEWERS.md).
#
# f3d_brightness.sh SFCONVERT SFRENDER WORKDIR WIDTH HEIGHT SCENE...
# (a SCENE written "default=FILE.txt" as for blender_brightness_check.py)
# Exits 77 when f3d or xvfb-run is missing (scripts/install-deps.sh installs
# both). f3d needs an OpenGL context: Xvfb and Mesa's software rasteriser.
set -euo pipefail
sfconvert=$1 sfrender=$2 work=$3 width=$4 height=$5
shift 5
for tool in f3d xvfb-run pngtopnm python3; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    echo "SKIP: $tool is not installed (apt-get install f3d; install-deps.sh installs the rest)"
    exit 77
  fi
done
mkdir -p "$work"

# The mean of every channel of a binary 8-bit PPM, over 255.
mean() {
  python3 -c '
import re, sys
data = open(sys.argv[1], "rb").read()
h = re.match(rb"P6\s+(\d+)\s+(\d+)\s+255\s", data)
pixels = data[h.end():h.end() + int(h.group(1)) * int(h.group(2)) * 3]
print(f"{sum(pixels) / len(pixels):.1f}")' "$1"
}

printf '%-36s %10s %10s %8s\n' scene sfrender f3d ratio
for spec in "$@"; do
  if [[ $spec == default=* ]]; then
    source=${spec#default=} name=default-scene
    "$sfrender" -o "$work/$name.sfrender.ppm" --width "$width" --height "$height" --fov 60 --quiet
  else
    source=$spec name=$(basename "$spec")
    "$sfrender" "$source" -o "$work/$name.sfrender.ppm" --width "$width" --height "$height" \
      --fov 60 --quiet
  fi
  "$sfconvert" "$source" "$work/$name.glb" --width "$width" --height "$height" --fov 60 \
    --light-falloff none 2>/dev/null
  # The file's camera and lights alone, on black, as sfrender draws.
  xvfb-run -a -s "-screen 0 1024x768x24" f3d "$work/$name.glb" --output "$work/$name.f3d.png" \
    --resolution "$width,$height" --camera-index 0 --bg-color 0,0,0 --quiet
  pngtopnm "$work/$name.f3d.png" >"$work/$name.f3d.ppm"
  ours=$(mean "$work/$name.sfrender.ppm")
  theirs=$(mean "$work/$name.f3d.ppm")
  ratio=$(python3 -c "print(f'{$theirs / $ours:.3f}' if $ours > 0 else 'inf')")
  printf '%-36s %10s %10s %8s\n' "$name" "$ours" "$theirs" "$ratio"
done
