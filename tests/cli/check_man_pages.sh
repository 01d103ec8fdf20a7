#!/usr/bin/env bash
# The man pages: one per tool, made from its --help, so that every option
# --help lists is in the page; and man renders each without a warning.
#   check_man_pages.sh BIN_FOLDER MAN_FOLDER TOOL...
set -uo pipefail
bin=$1
man_folder=$2
shift 2
failed=0
for tool in "$@"; do
  page=$man_folder/$tool.1
  if [ ! -f "$page" ]; then
    echo "no man page $page" >&2; failed=1; continue
  fi
  shown=$(MANWIDTH=80 man -l "$page" 2>"$page.warnings")
  if [ -s "$page.warnings" ]; then
    echo "man $tool: $(cat "$page.warnings")" >&2; failed=1
  fi
  grep -q "^NAME" <<<"$shown" && grep -q "^OPTIONS" <<<"$shown" && grep -q "^EXAMPLES\|^DESCRIPTION" <<<"$shown" ||
    { echo "man $tool lacks a section" >&2; failed=1; }
  for option in $("$bin/$tool" --help | grep -o -- '--[a-z][a-z-]*' | sort -u); do
    grep -qF -- "$option" <<<"$shown" || { echo "man $tool lacks $option" >&2; failed=1; }
  done
done
exit $failed
