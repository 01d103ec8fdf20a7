#!/usr/bin/env bash
# `make run`: checks the bundled examples and converts one into the other
# format, so that a first run shows what the tools do.
set -euo pipefail
build=${1:-build}
bin="$build/bin"
out="$build/examples"
mkdir -p "$out"

echo "== sfcheck examples/blue-cube.txt examples/red-sphere.sf"
"$bin/sfcheck" examples/blue-cube.txt examples/red-sphere.sf
echo
echo "== sfconvert examples/blue-cube.txt $out/blue-cube.sf"
"$bin/sfconvert" examples/blue-cube.txt "$out/blue-cube.sf"
echo
echo "== sfconvert examples/red-sphere.sf $out/red-sphere.txt"
"$bin/sfconvert" examples/red-sphere.sf "$out/red-sphere.txt"
echo
echo "Wrote $out/blue-cube.sf and $out/red-sphere.txt."
