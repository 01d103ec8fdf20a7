#!/usr/bin/env bash
# The bash completions as bash-completion loads them: flags, choices and
# files by extension, each offered where it belongs.
#   check_completion.sh COMPLETIONS_FOLDER WORK_FOLDER
set -euo pipefail
completions=$1
work=$2
loader=/usr/share/bash-completion/bash_completion
if [ ! -f "$loader" ]; then
  echo "SKIP: bash-completion is not installed (scripts/install-deps.sh installs it)"; exit 77
fi
rm -rf "$work"; mkdir -p "$work/sub"
cd "$work"
touch a.png b.sf c.txt d.gltf e.exr notes.md

failed=0
# complete TOOL WORDS... : what bash would offer for the last word.
complete_line() {
  local tool=$1; shift
  bash -c '
    source "$0" >/dev/null 2>&1
    source "$1/$2"
    tool=$2; shift 2
    COMP_WORDS=("$tool" "$@"); COMP_CWORD=$(( ${#COMP_WORDS[@]} - 1 ))
    COMP_LINE="${COMP_WORDS[*]}"; COMP_POINT=${#COMP_LINE}
    "_$tool" "$tool" "${COMP_WORDS[COMP_CWORD]}" "${COMP_WORDS[COMP_CWORD-1]}"
    printf "%s\n" "${COMPREPLY[@]}" | sort | tr "\n" " "
  ' "$loader" "$completions" "$tool" "$@"
}
expect() {
  local want=$1; shift
  local got
  got=$(complete_line "$@")
  if [ "$got" != "$want" ]; then
    echo "completing '$*': expected '$want', got '$got'" >&2
    failed=1
  fi
}

expect "--color " sfrender --col
expect "--no-clobber --no-extras --no-lights --no-loss " sfconvert --no-
expect "always auto never " sfcheck --color ""
expect "json " sfcheck --format j
expect "json " sfcheck --format = j
expect "glb gltf " sfconvert in.sf out.gltf --to gl
# Files where a file belongs: scenes for the inputs, images for -o.
expect "b.sf c.txt d.gltf sub " sfcheck ""
expect "a.png e.exr sub " sfrender b.sf -o ""
# A number is typed, not chosen.
expect " " sfrender --width ""
expect "--id-view " sfbuild --id
exit $failed
