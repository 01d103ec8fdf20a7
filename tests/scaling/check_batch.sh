#!/bin/bash
# Batches: sfrender and sfconvert with several inputs and -o PATTERN go on
# past a bad input (its diagnostics printed), end with the summary and exit
# with the first failure's status; a pattern without a placeholder, an
# unknown placeholder and two inputs onto one output are usage errors; one
# input behaves as it always did. Arguments: BIN_DIR SOURCE_DIR WORK_DIR.
set -euo pipefail
bin=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work/in" "$work/out" && cd "$work"
cp "$source/examples/red-sphere.sf" in/a.sf
cp "$source/examples/red-sphere.sf" in/c.sf
printf 'this is no scene\n' >in/b.sf

run() {  # run STATUS TOOL ARGS...: the exit status must be STATUS
  local status=$1 got=0
  shift
  "$@" >out.txt 2>err.txt || got=$?
  if ((got != status)); then
    echo "$*: exit $got, expected $status; it said:" >&2
    cat err.txt >&2
    exit 1
  fi
}
said() {
  grep -q -- "$1" err.txt || { echo "expected '$1' in:" >&2; cat err.txt >&2; exit 1; }
}

sfrender=("$bin/sfrender" --width 16 --height 12)
run 1 "${sfrender[@]}" in/a.sf in/b.sf in/c.sf -o 'out/{stem}.png'
said "in/b.sf:1:1: error: not a scene file"
said "sfrender: 2 of 3 scenes rendered, 1 failed"
[[ -s out/a.png && -s out/c.png && ! -e out/b.png ]]
[[ $(tail -n 1 err.txt) == "sfrender: 2 of 3 scenes rendered, 1 failed" ]]
mkdir -p out/in
run 0 "${sfrender[@]}" in/a.sf in/c.sf -o 'out/{dir}/{name}.ppm' -q
[[ -s out/in/a.sf.ppm && -s out/in/c.sf.ppm && ! -s err.txt ]]
run 3 "${sfrender[@]}" in/a.sf missing.sf -o 'out/{stem}.ppm' -q
said "sfrender: 1 of 2 scenes rendered, 1 failed"
run 2 "${sfrender[@]}" in/a.sf in/c.sf -o out/one.png
said "names one file for 2 inputs"
run 2 "${sfrender[@]}" in/a.sf in/c.sf -o 'out/{base}.png'
said "'{base}' is no placeholder"
run 2 "${sfrender[@]}" in/a.sf in/../in/a.sf -o 'out/{stem}.png'
said "would both write 'out/a.png'"
[[ ! -e out/one.png ]]
# One input: as always (the pattern, if any, names its image).
run 0 "${sfrender[@]}" in/a.sf -o out/single.png -q
[[ -s out/single.png && ! -s err.txt ]]
run 0 "${sfrender[@]}" in/c.sf -o 'out/one-{stem}.png' -q
[[ -s out/one-c.png ]]

sfconvert=("$bin/sfconvert")
run 1 "${sfconvert[@]}" in/a.sf in/b.sf in/c.sf -o 'out/{stem}.pov'
said "in/b.sf:1:1: error: not a scene file"
said "sfconvert: 2 of 3 scenes converted, 1 failed"
[[ -s out/a.pov && -s out/c.pov && ! -e out/b.pov ]]
run 0 "${sfconvert[@]}" in/a.sf out/pair.sf -q
cmp in/a.sf out/pair.sf
run 2 "${sfconvert[@]}" in/a.sf in/c.sf out/x.sf
said "several inputs need -o"
run 2 "${sfconvert[@]}" in/a.sf
said "missing OUTPUT"
run 2 "${sfconvert[@]}" in/a.sf in/c.sf -o out/x.sf
said "names one file for 2 inputs"
echo "batches go on past a bad input and sum up"
