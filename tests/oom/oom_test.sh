#!/bin/bash
# Out of memory and out of threads, end to end: each tool run under an
# address-space or data limit (prlimit, util-linux) that a real allocation
# hits, not a limit of the project's own. Each case checks the exit status,
# the message on standard error and that no temporary (.*.tmp-*) is left.
# Usage: oom_test.sh BIN_DIR WORK_DIR CASE
set -u
bin=$1
work=$2
case=$3
rm -rf "$work"
mkdir -p "$work"
cd "$work" || exit 1

if ! command -v prlimit >/dev/null; then
  echo "prlimit (util-linux) is missing: skipped"
  exit 77
fi

fail() {
  echo "FAIL: $*"
  echo "--- stderr"
  cat err.txt
  exit 1
}

# expect STATUS REGEX COMMAND...: runs COMMAND, checks its status, that its
# standard error matches REGEX (grep -E), and that no temporary stayed.
expect() {
  local status=$1 pattern=$2
  shift 2
  local start=$SECONDS
  "$@" >out.txt 2>err.txt
  local got=$?
  echo "$* -> exit $got in $((SECONDS - start)) s: $(head -c 300 err.txt)"
  [ "$got" -eq "$status" ] || fail "exit status $got, expected $status"
  if [ -n "$pattern" ]; then
    grep -Eq "$pattern" err.txt || fail "standard error does not match '$pattern'"
  fi
  if ls -A | grep -q '^\..*\.tmp-'; then
    fail "a temporary was left: $(ls -A | grep '^\..*\.tmp-')"
  fi
}

case $case in
  sfcheck)
    # A million instruction-file objects (about 30 MB; 300 MiB peak without
    # a limit): under 100 MiB of address space the reading fails, under 250
    # and 400 MiB the checking (the scene's objects, twice while the vector
    # grows). Each limit fails somewhere else, and each must end cleanly.
    {
      echo "OUTPUT_FILE big.ppm"
      printf 'START CAMERA\nLOCATION 0 0 5\nLOOK_AT 0 0 0\nEND CAMERA\n'
      printf 'START LIGHT\nLOCATION 1 1 1\nCOLOUR 1 1 1\nEND LIGHT\n'
      yes 'START OBJECT SPHERE
END OBJECT' | head -n 2000000
    } >big.txt
    for mib in 100 250 400; do
      expect 4 '^sfcheck: error: out of memory while (reading|checking) .*big.txt$' \
        prlimit --as=$((mib << 20)) "$bin/sfcheck" big.txt
    done
    expect 4 '^sfcheck: error: out of memory while' \
      prlimit --as=$((400 << 20)) "$bin/sfcheck" --format json big.txt
    ;;
  sfconvert)
    # 900,000 glTF nodes (about 14 MB of JSON; 710 MiB peak without a
    # limit), half of them children of the others. At each limit the JSON
    # documents of the tree do not fit, and their destruction while the
    # std::bad_alloc unwinds allocates too (nlohmann::json): the tools keep
    # a reserve for that (tools/common/resource_guard.cpp).
    python3 - <<'PY'
n = 450_000
nodes = []
for i in range(n):
    nodes.append('{"children":[%d]}' % (n + i))
nodes += ['{}'] * n
with open("tree.gltf", "w") as f:
    f.write('{"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[%s]}],"nodes":[%s]}'
            % (",".join(str(i) for i in range(n)), ",".join(nodes)))
PY
    for mib in 100 300 500 900; do
      expect 4 '^sfconvert: error: out of memory while (reading|converting) ' \
        prlimit --as=$((mib << 20)) "$bin/sfconvert" --max-nodes 10000000 tree.gltf out.sf
      [ ! -e out.sf ] || fail "out.sf was written"
    done
    ;;
  sfrender)
    # 12000 x 12000: the memory check sees the address-space limit and
    # refuses before rendering.
    expect 4 '^sfrender: error: the render needs about [0-9]+ MiB .* but only [0-9]+ MiB of memory is available' \
      prlimit --as=$((2 << 30)) "$bin/sfrender" --width 12000 --height 12000 \
      --max-pixels 144000000 -o big.ppm
    # A data limit (RLIMIT_DATA) is one the check does not read: the image's
    # allocation itself fails, and is reported, with no temporary left.
    expect 4 '^sfrender: error: out of memory while rendering$' \
      prlimit --data=$((1 << 30)) "$bin/sfrender" --width 12000 --height 12000 \
      --max-pixels 144000000 -o big.ppm
    [ ! -e big.ppm ] || fail "big.ppm was written"
    # 1024 threads want 8 GiB of stacks: under 1 GiB of address space they
    # cannot all start, which is said before rendering.
    expect 4 '^sfrender: error: cannot start 1024 threads: .*; ask for fewer with --threads$' \
      prlimit --as=$((1 << 30)) "$bin/sfrender" --threads 1024 --width 64 --height 48 \
      -o small.ppm
    # Without a limit, 1024 threads start and render.
    expect 0 '' "$bin/sfrender" --quiet --threads 1024 --width 64 --height 48 -o small.ppm
    [ -s small.ppm ] || fail "small.ppm was not written"
    ;;
  *)
    echo "unknown case $case"
    exit 2
    ;;
esac
echo PASS
