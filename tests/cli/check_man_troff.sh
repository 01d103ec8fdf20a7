#!/usr/bin/env bash
# Every man page read by groff with all its warnings on: a page whose text
# groff takes for requests (a line starting with '.' or ') loses words in
# man, silently.
#   check_man_troff.sh PAGE...
set -uo pipefail
failed=0
for page in "$@"; do
  if [ ! -f "$page" ]; then
    echo "no man page $page" >&2; failed=1; continue
  fi
  warnings=$(groff -man -ww -z "$page" 2>&1 >/dev/null)
  if [ -n "$warnings" ]; then
    echo "groff $page: $warnings" >&2; failed=1
  fi
done
exit $failed
