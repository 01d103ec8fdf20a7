#!/usr/bin/env bash
# `make run`: renders the built-in default scene, then checks the bundled
# examples and converts one into the other format, so that a first run shows
# what each tool does.
set -euo pipefail
build=${1:-build}
bin="$build/bin"
out="$build/examples"
mkdir -p "$out"

# Adaptive anti-aliasing at docs/RENDERING.md's threshold: smooth edges at
# some 1.3 samples a pixel, twice the time of one.
echo "== sfrender -o $build/default-scene.png --adaptive 0.03 --spp 16"
"$bin/sfrender" -o "$build/default-scene.png" --adaptive 0.03 --spp 16 --stats
echo
echo "== sfcheck examples/blue-cube.txt examples/red-sphere.sf"
"$bin/sfcheck" examples/blue-cube.txt examples/red-sphere.sf
echo
echo "== sfconvert examples/red-sphere.sf $out/red-sphere.txt"
"$bin/sfconvert" examples/red-sphere.sf "$out/red-sphere.txt"
echo
echo "== sfrender examples/blue-cube.txt -o $out/blue-cube.png"
"$bin/sfrender" examples/blue-cube.txt -o "$out/blue-cube.png"
echo
echo "The default scene is in $build/default-scene.png."
