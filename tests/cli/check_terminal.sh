#!/usr/bin/env bash
# The tools on a real terminal (a pseudo-terminal from script(1)) and on a
# pipe: colour when standard error is a terminal, none under NO_COLOR or on
# a pipe, --color always and never over both; binary output refused on a
# terminal.
#   check_terminal.sh BIN_FOLDER EXAMPLES_FOLDER WORK_FOLDER
set -uo pipefail
bin=$1
examples=$2
work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
printf 'CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 5\n0 0 0 1\nsphere\n' >bad.sf
export TERM=xterm
unset NO_COLOR
red=$'\e[1;31merror:'
failed=0

# on_terminal COMMAND: runs it with its standard streams on a terminal,
# and prints what the terminal showed.
on_terminal() { script -qec "$1" /dev/null; }
has_colour() { grep -qF "$red" <<<"$1"; }
check() {  # check WHAT WANT(colour|plain) OUTPUT
  local what=$1 want=$2 output=$3
  if [ "$want" = colour ] && ! has_colour "$output"; then
    echo "$what: expected colour, got: $output" >&2; failed=1
  elif [ "$want" = plain ] && grep -qF $'\e[' <<<"$output"; then
    echo "$what: expected no colour, got: $output" >&2; failed=1
  fi
}

check "sfcheck on a terminal" colour "$(on_terminal "$bin/sfcheck bad.sf")"
check "NO_COLOR=1 on a terminal" plain "$(NO_COLOR=1 on_terminal "$bin/sfcheck bad.sf")"
check "NO_COLOR empty on a terminal" colour "$(NO_COLOR= on_terminal "$bin/sfcheck bad.sf")"
check "TERM=dumb on a terminal" plain "$(TERM=dumb on_terminal "$bin/sfcheck bad.sf")"
check "--color always over NO_COLOR" colour \
  "$(NO_COLOR=1 on_terminal "$bin/sfcheck --color always bad.sf")"
check "--color never on a terminal" plain "$(on_terminal "$bin/sfcheck --color=never bad.sf")"
check "sfcheck on a pipe" plain "$("$bin/sfcheck" bad.sf 2>&1)"
check "--color always on a pipe" colour "$("$bin/sfcheck" --color always bad.sf 2>&1)"
check "sfconvert on a terminal" colour "$(on_terminal "$bin/sfconvert bad.sf out.sf")"
check "sfrender on a terminal" colour "$(on_terminal "$bin/sfrender bad.sf -o out.ppm")"

# Binary glTF and a PPM are refused on a terminal, with a hint, and go
# through a pipe.
shown=$(on_terminal "$bin/sfconvert $examples/red-sphere.sf - --to glb; echo status=\$?")
if ! grep -q "standard output is a terminal" <<<"$shown" || ! grep -q "status=2" <<<"$shown"; then
  echo "sfconvert --to glb to a terminal was not refused: $shown" >&2; failed=1
fi
shown=$(on_terminal "$bin/sfrender $examples/red-sphere.sf -o - --width 8 --height 6; echo status=\$?")
if ! grep -q "status=2" <<<"$shown"; then
  echo "sfrender -o - to a terminal was not refused: $shown" >&2; failed=1
fi
# sfrender's progress: on a terminal one line, rewritten, that ends with the
# time taken; none on a pipe.
shown=$(on_terminal "$bin/sfrender $examples/red-sphere.sf -o progress.png --width 64 --height 48")
if ! grep -qE $'\rsfrender: rendering 100%, [0-9]+:[0-9]{2} elapsed' <<<"$shown"; then
  echo "sfrender on a terminal showed no progress with the time taken: $shown" >&2; failed=1
fi
shown=$("$bin/sfrender" "$examples/red-sphere.sf" -o progress.png --width 64 --height 48 2>&1)
if grep -q "rendering" <<<"$shown"; then
  echo "sfrender on a pipe showed its progress: $shown" >&2; failed=1
fi
magic=$("$bin/sfconvert" -q "$examples/red-sphere.sf" - --to glb | head -c 4)
[ "$magic" = glTF ] || { echo "sfconvert --to glb to a pipe wrote '$magic'" >&2; failed=1; }
exit $failed
