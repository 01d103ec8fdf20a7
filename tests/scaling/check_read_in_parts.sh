#!/bin/bash
# A scene file big enough to be read in parts (4 MiB and more;
# docs/history/PERFORMANCE.md, "Reading in parts, and the build's boxes in
# order") renders the same image at 1 and 3
# threads, and a damaged one gets the same diagnostics, at the same line, and
# the same exit status. Arguments: BIN_DIR WORK_DIR.
set -euo pipefail
bin=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$bin/sfgen" -o big.sf -n 40000 -s 5 --layout floor >/dev/null
size=$(stat -c %s big.sf)
((size >= 4 * 1024 * 1024)) || { echo "big.sf is $size bytes, under 4 MiB" >&2; exit 1; }

for threads in 1 3; do
  "$bin/sfrender" big.sf -o "big-$threads.ppm" --width 96 --height 54 --threads "$threads" --quiet
done
cmp big-1.ppm big-3.ppm

# A bad number in the last record: the last part finds it, the file is read
# whole, and the error is reported where it is.
# The last line is the last record's fourth row, 0 0 0 1.
lines=$(wc -l <big.sf)
sed "${lines}s/^0 /0x /" big.sf >damaged.sf
cmp -s big.sf damaged.sf && { echo "the damage did not take" >&2; exit 1; }
for threads in 1 3; do
  status=0
  "$bin/sfrender" damaged.sf -o damaged.ppm --width 96 --height 54 --threads "$threads" --quiet \
    2>"damaged-$threads.txt" || status=$?
  ((status == 1)) || { echo "--threads $threads: exit $status, expected 1" >&2; exit 1; }
done
cmp damaged-1.txt damaged-3.txt
grep -q "damaged.sf:$lines:1: error" damaged-1.txt ||
  { echo "no error at line $lines:" >&2; cat damaged-1.txt >&2; exit 1; }
[[ ! -e damaged.ppm ]]
echo "read in parts: the same image and the same diagnostics at 1 and 3 threads"
