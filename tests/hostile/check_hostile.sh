#!/usr/bin/env bash
# The hostile-input corpus (testdata/hostile/): files made to crash, hang or
# exhaust a reader (binary garbage, NUL bytes, invalid UTF-8, 100 MB lines,
# 100,000-digit numbers, 1e308 and subnormal matrices, a million unclosed
# blocks, glTF buffers pointing at /dev/zero or out of the folder, GLB chunks
# with false lengths, POV-Ray #include "/etc/passwd", recursive macros,
# endless #while loops...). For each input, sfcheck with its default limits
# must print exactly the diagnostics in NAME.expect, exit with status 1, and
# stay within the stated bounds on wall time and peak resident memory.
#
# Usage: check_hostile.sh SFCHECK INPUT_DIR NAME EXPECT_DIR SECONDS MEMORY_MIB [FACTOR]
# sfcheck runs in INPUT_DIR on NAME, so the diagnostics name the file as the
# .expect does. The memory bound is MEMORY_MIB, or FACTOR times the input's
# size when that is larger. Peak memory is measured with GNU time (/usr/bin/time, Debian
# package `time`); without it the memory bound is enforced with ulimit -v
# instead, a cruder limit on address space.
set -u

sfcheck=$1
input_dir=$2
name=$3
expect_dir=$4
max_seconds=$5
max_mib=$6
factor=${7:-0}

expect="$expect_dir/$name.expect"
if [ ! -f "$expect" ]; then
  echo "check_hostile: $expect is missing: every hostile input needs its expected diagnostics" >&2
  exit 1
fi
if [ ! -e "$input_dir/$name" ]; then
  echo "check_hostile: $input_dir/$name is missing" >&2
  exit 1
fi

if [ "$factor" -gt 0 ]; then
  size_mib=$(($(stat -c %s "$input_dir/$name") / 1048576))
  if [ "$((factor * size_mib))" -gt "$max_mib" ]; then max_mib=$((factor * size_mib)); fi
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

start=$(date +%s%N)
if [ -x /usr/bin/time ]; then
  (cd "$input_dir" &&
    timeout --signal=KILL "$((max_seconds * 3))" \
      /usr/bin/time -f %M -o "$work/peak_kib" "$sfcheck" -v "$name" >"$work/stdout" 2>"$work/stderr")
  status=$?
else
  (cd "$input_dir" && ulimit -v "$((max_mib * 1024))" &&
    timeout --signal=KILL "$((max_seconds * 3))" "$sfcheck" -v "$name" >"$work/stdout" 2>"$work/stderr")
  status=$?
fi
end=$(date +%s%N)
elapsed_ms=$(((end - start) / 1000000))

failed=0
# sfcheck's own lines (what -v tells of the file, the summary) left out,
# the rest are diagnostics, notes too (-v), in the text form with the source
# quoted under each, which the .expect files leave out (they hold the short
# form): sfcheck runs as users run it, so that quoting is held to the same
# time and memory bounds.
sed -e '/^sfcheck: /d' -e '/^ *[0-9]* | /d' "$work/stderr" >"$work/diagnostics"
if ! cmp -s "$work/diagnostics" "$expect"; then
  echo "check_hostile: diagnostics differ for $name (expected < > got):" >&2
  diff "$expect" "$work/diagnostics" | head -40 >&2
  failed=1
fi
if [ "$status" -ne 1 ]; then
  echo "check_hostile: sfcheck $name exited with $status, expected 1" >&2
  failed=1
fi
if [ "$elapsed_ms" -gt "$((max_seconds * 1000))" ]; then
  echo "check_hostile: sfcheck $name took ${elapsed_ms} ms, over the bound of ${max_seconds} s" >&2
  failed=1
fi
peak="unmeasured"
if [ -s "$work/peak_kib" ]; then
  peak_kib=$(tail -n 1 "$work/peak_kib")
  peak="$((peak_kib / 1024)) MiB"
  if [ "$peak_kib" -gt "$((max_mib * 1024))" ]; then
    echo "check_hostile: sfcheck $name peaked at $peak, over the bound of $max_mib MiB" >&2
    failed=1
  fi
fi
echo "check_hostile: $name: exit $status, ${elapsed_ms} ms (bound ${max_seconds} s)," \
  "peak $peak (bound $max_mib MiB)"
exit "$failed"
