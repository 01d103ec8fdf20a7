# shellcheck shell=bash
# Sourced by sfbatch.sh and batch-task.sh, so that both read a list of
# scenes the same way: one scene a line, a line's CR (a list written on
# Windows) taken off, blank lines and comments (# first) skipped; a line is
# a path as it stands otherwise, spaces and all.

# $1: the list. Prints its scenes, one a line.
read_scene_list() {
  local line
  while IFS= read -r line || [[ -n $line ]]; do
    line=${line%$'\r'}
    [[ $line =~ ^[[:space:]]*(#|$) ]] && continue
    printf '%s\n' "$line"
  done <"$1"
}
