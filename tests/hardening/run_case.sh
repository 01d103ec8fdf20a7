#!/bin/bash
# Runs one misuse case (cases/NAME.sh) in an empty folder and compares what
# it printed with cases/NAME.sh.expect. Arguments: BIN_DIR SOURCE_DIR
# WORK_DIR CASE. With UPDATE_EXPECT=1 the .expect file is written instead.
#
# A case is bash, run with `set -u` in WORK_DIR, which holds S.sf (a valid
# scene file, examples/red-sphere.sf). It may call:
#   run CMD ARGS...   runs CMD (standard input: the case's, /dev/null unless
#                     redirected, as in `run $SFCHECK - <S.sf`); prints its
#                     standard error, then its standard output when it
#                     wrote text (else its size), then "exit N"
#   same A B / differs A B / absent PATH / present PATH / temporaries
#                     print what holds, for the expected output to pin down
#   skip WHY          ends the case as skipped (exit 77)
#   needs_address_space_limits
#                     skips the case under the sanitizers (SCENEFILE_SANITIZED
#                     set), whose shadow memory no `ulimit -v` holds
# and $SFRENDER, $SFCONVERT, $SFCHECK (the tools at their usual test size
# for sfrender: 16x12) and $SOURCE (the source folder).
set -uo pipefail
bin=$1 source=$2 work=$3 case=$4
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
cp "$source/examples/red-sphere.sf" S.sf

SFRENDER="$bin/sfrender --width 16 --height 12"
SFCONVERT="$bin/sfconvert"
SFCHECK="$bin/sfcheck"
SOURCE=$source
export SFRENDER SFCONVERT SFCHECK SOURCE

run() {
  local status=0
  "$@" >"$work/.stdout" 2>"$work/.stderr" || status=$?
  cat "$work/.stderr"
  if LC_ALL=C grep -qaP '[^\x09\x0a\x0d\x20-\x7e]' "$work/.stdout"; then
    echo "(standard output: $(wc -c <"$work/.stdout") bytes)"
  else
    cat "$work/.stdout"
  fi
  echo "exit $status"
}
same() { if cmp -s "$1" "$2"; then echo "same: $1 $2"; else echo "DIFFERENT: $1 $2"; fi; }
differs() { if cmp -s "$1" "$2"; then echo "SAME: $1 $2"; else echo "differs: $1 $2"; fi; }
absent() { if [[ -e $1 || -L $1 ]]; then echo "PRESENT: $1"; else echo "absent: $1"; fi; }
present() { if [[ -e $1 ]]; then echo "present: $1"; else echo "ABSENT: $1"; fi; }
temporaries() {
  local left
  left=$(find . -name '.*.tmp-*' | sort)
  echo "temporaries: ${left:-none}"
}
skip() { echo "skipped: $*" >&2; exit 77; }
needs_address_space_limits() {
  [[ -z ${SCENEFILE_SANITIZED:-} ]] || skip "the sanitizers reserve more address space than a limit holds"
}
export -f run same differs absent present temporaries skip needs_address_space_limits

got=$(source "$case" 2>&1 </dev/null)
status=$?
[[ $status == 77 ]] && { echo "$got"; exit 77; }
got+=$'\n'"case exit $status"
if [[ ${UPDATE_EXPECT:-} == 1 ]]; then
  printf '%s\n' "$got" >"$case.expect"
  exit 0
fi
if ! diff -u "$case.expect" <(printf '%s\n' "$got"); then
  echo "hardening case $(basename "$case"): the output above differs from $case.expect" >&2
  exit 1
fi
