#!/usr/bin/env bash
# Writes the hostile inputs too big to commit (100 MB lines, a million
# unclosed blocks, 10,000,000-digit numbers, a glTF buffer linked to
# /dev/zero...) into OUT_DIR. Their expected diagnostics are committed in
# testdata/hostile/generated/NAME.expect; every name written here has one
# there, and the other way round. Uses only coreutils, so it runs wherever
# the tests do.
#
# Usage: make_big_inputs.sh OUT_DIR [EXPECT_DIR]
# With EXPECT_DIR, fails unless the inputs written and the .expect files
# there match one to one.
set -euo pipefail

out=$1
expect_dir=${2:-}
if [ -n "$expect_dir" ]; then expect_dir=$(cd "$expect_dir" && pwd); fi
mkdir -p "$out"
cd "$out"

camera=$'CAMERA\n0 0 0\n1 0 0 0\n0 1 0 1\n0 0 1 8\n0 0 0 1\n'
light=$'LIGHT\n1 1 1\n1 0 0 5\n0 1 0 5\n0 0 1 5\n0 0 0 1\n'
identity=$'1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n'
head_txt=$'OUTPUT_FILE out.ppm\nSTART CAMERA\n  LOCATION 0 1 8\n  LOOK_AT 0 0 0\nEND CAMERA\n'
head_txt+=$'START LIGHT\n  LOCATION 5 5 5\n  COLOUR 1 1 1\nEND LIGHT\n'
pov_camera=$'camera { location <0, 1, -5> look_at 0 }\nlight_source { <5, 5, -5> color rgb 1 }\n'

# COUNT copies of CHAR.
repeat_char() { head -c "$2" /dev/zero | tr '\0' "$1"; }
# COUNT copies of LINE; yes ends by SIGPIPE, which is no failure here.
repeat_line() { yes "$1" | head -n "$2" || true; }

# 100 MB single lines, one per format.
{
  printf '%s%sSPHERE\n1 1 ' "$camera" "$light"
  repeat_char 7 100000000
  printf '\n%s' "$identity"
} >line-100mb-number.sf
{
  printf '%s' "$head_txt"
  repeat_char A 100000000
  printf ' 1 2 3\n'
} >line-100mb-keyword.txt
{
  printf '%ssphere { 0, ' "$pov_camera"
  repeat_char R 100000000
  printf ' }\n'
} >line-100mb-identifier.pov
{
  printf '{"asset": {"version": "2.0", "extras": "'
  repeat_char A 100000000
  printf '"}, "scene": 5, "scenes": [{"nodes": []}]}\n'
} >line-100mb-string.gltf
{
  printf 'v 1 1 '
  repeat_char 7 100000000
  printf '\n'
} >line-100mb-number.obj
# One face of 2^24 + 3 corners: past the OBJ reader's limit on triangle
# corners (three times its vertex limit), refused before one is kept.
{
  printf 'v 0 0 0\nf'
  yes ' 1' | head -n 16777219 | tr -d '\n' || true
  printf '\n'
} >face-16777219-corners.obj

# Numbers: ten million digits, and a fraction with ten million zeros.
{
  printf '%s%sSPHERE\n1 1 ' "$camera" "$light"
  repeat_char 9 10000000
  printf '\n%s' "$identity"
} >number-10000000-digits.sf
{
  printf '%s%sSPHERE\n1 1 0.' "$camera" "$light"
  repeat_char 0 10000000
  printf '1\n%s' "$identity"
} >number-10000000-zeros-fraction.sf

# A million unterminated blocks, and other lines repeated until the error
# limit must stop the reader.
{
  printf 'OUTPUT_FILE a.ppm\n'
  repeat_line 'START LIGHT' 1000000
} >unterminated-blocks-1000000.txt
{
  printf 'OUTPUT_FILE a.ppm\n'
  repeat_line 'START CAMERA' 1000000
} >start-camera-repeated-1000000.txt
{
  printf '%s' "$head_txt"
  repeat_line 'START OBJECT SPHERE' 100000
} >nested-objects-100000.txt
{
  printf '%s' "$head_txt"
  repeat_line 'END OBJECT' 100000
} >end-without-start-100000.txt
repeat_line CAMERA 100000 >camera-repeated-100000.sf
{
  printf '%s' "$pov_camera"
  repeat_line 'union {' 1000000
} >unclosed-braces-1000000.pov

# A record name of half a million letters.
{
  printf '%s%s' "$camera" "$light"
  repeat_char S 500000
  printf '\n1 0 0\n%s' "$identity"
} >record-name-500000.sf

# 10,000 lights: all valid but for the last (instructions), all negative
# (scene file), all valid and then an unknown record (scene file).
{
  printf '%s' "$head_txt"
  for _ in $(seq 9999); do printf 'START LIGHT\n  LOCATION 5 5 5\n  COLOUR 1 1 1\nEND LIGHT\n'; done
  printf 'START LIGHT\n  LOCATION 5 5 5\n  COLOUR 1 1 -1\nEND LIGHT\n'
} >lights-10000-last-negative.txt
{
  printf '%s' "$camera"
  for _ in $(seq 10000); do printf 'LIGHT\n-1 1 1\n%s' "$identity"; done
} >lights-10000-negative.sf
{
  printf '%s' "$camera"
  for _ in $(seq 10000); do printf '%s' "$light"; done
  printf 'TORUS\n1 0 0\n%s' "$identity"
} >lights-10000-then-unknown-record.sf

# A chain of 100,000 nodes, each the child of the one before, whose last
# node points at a mesh that does not exist.
{
  printf '{"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": ['
  seq 0 99998 | awk '{printf "{\"name\": \"n%d\", \"children\": [%d]}, ", $1, $1 + 1}'
  printf '{"name": "last", "mesh": 7}]}\n'
} >node-chain-100000.gltf

# Nodes without a mesh, which cost three bytes of text each and hundreds of
# bytes once read: two million, past the node limit (refused before any
# parse), and 999,999 with one scene, at the limit of a million objects,
# read whole until the walk meets a cycle at node 0.
{
  printf '{"asset": {"version": "2.0"}, "nodes": ['
  repeat_line '{},' 1999999 | tr -d '\n'
  printf '{}]}\n'
} >gltf-nodes-2000000.gltf
{
  printf '{"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"children": [0]},'
  repeat_line '{},' 999997 | tr -d '\n'
  printf '{}]}\n'
} >gltf-nodes-at-limit-cycle.gltf

# A buffer that is a link, beside the glTF, to /dev/zero: reading it would
# never end.
ln -sf /dev/zero zero.bin
printf '%s\n' '{"asset": {"version": "2.0"}, "buffers": [{"byteLength": 1000000000, "uri": "zero.bin"}]}' \
  >buffer-link-to-dev-zero.gltf

if [ -n "$expect_dir" ]; then
  written=$(find . -maxdepth 1 -type f -printf '%f\n' | sort)
  expected=$(find "$expect_dir" -maxdepth 1 -name '*.expect' -printf '%f\n' | sed 's/\.expect$//' | sort)
  if [ "$written" != "$expected" ]; then
    echo "make_big_inputs: the inputs written and the .expect files in $expect_dir differ:" >&2
    diff <(echo "$expected") <(echo "$written") >&2
    exit 1
  fi
fi
