#!/usr/bin/env bash
# Standard input and output as files: "-" reads a scene from standard
# input in every tool (the format from the content), and sfrender -o -
# writes a PPM to standard output; sfbuild without a display says so, exit 5.
#   check_pipes.sh BIN_FOLDER EXAMPLES_FOLDER WORK_FOLDER
set -uo pipefail
bin=$1
examples=$2
work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
failed=0
fail() { echo "$*" >&2; failed=1; }

summary=$(cat "$examples/red-sphere.sf" | "$bin/sfcheck" - 2>&1) ||
  fail "sfcheck - failed: $summary"
[ "$summary" = "sfcheck: 1 file checked, 0 errors, 0 warnings" ] || fail "sfcheck -: $summary"
"$bin/sfconvert" -q "$examples/blue-cube.txt" - --to gltf | "$bin/sfcheck" -q - ||
  fail "glTF through a pipe does not check"
"$bin/sfconvert" -q - from-stdin.pov <"$examples/red-sphere.sf" || fail "sfconvert - failed"
grep -q "sphere {" from-stdin.pov || fail "sfconvert - wrote no sphere"
"$bin/sfrender" -q - -o from-stdin.ppm --width 8 --height 6 <"$examples/red-sphere.sf" ||
  fail "sfrender - failed"
[ "$(head -c 2 from-stdin.ppm)" = P6 ] || fail "sfrender - wrote no PPM"
"$bin/sfrender" -q "$examples/red-sphere.sf" -o - --width 8 --height 6 >to-stdout.ppm ||
  fail "sfrender -o - failed"
cmp -s from-stdin.ppm to-stdout.ppm || fail "sfrender -o - differs from the file it writes"

if [ -x "$bin/sfbuild" ]; then
  message=$(env -u DISPLAY -u WAYLAND_DISPLAY "$bin/sfbuild" 2>&1)
  status=$?
  [ "$status" -eq 5 ] || fail "sfbuild without a display exited $status, not 5: $message"
  grep -q "^sfbuild: error: no display to open a window on" <<<"$message" ||
    fail "sfbuild without a display said: $message"
fi
exit $failed
