#!/usr/bin/env bash
# The scale benchmark: bash bench/scale_bench.sh [BUILD_DIR]
#
# sfrender on floor scenes of 1,000,000 and 10,000,000 objects (`sfgen
# --layout floor -s 1`), and of 100,000,000 with SCALE_BENCH_100M=1 (a
# 12.3 GB file): 1920x1080, one sample per pixel, two threads, with -v and
# /usr/bin/time. Each scene is rendered once untimed (the file into the
# page cache), then RUNS times (one at 100,000,000); the medians go into a
# markdown table on standard output: the wall, user and system time, the
# peak resident set, and what each stage held (sfrender -v), in bytes an
# object. The limits are raised to the file's size and object count, one
# flag each. Under the table, from bench/first_touch run before the renders:
# the system time a GB of a process's first writes to memory, the floor
# under the table's system times.
#
# A render that fails (one that does not fit in memory is refused, exit 4)
# gets a row with its exit status and its last message.
#
# Environment: SCALE_BENCH_OBJECTS ("1000000 10000000"; empty for none),
# SCALE_BENCH_100M
# (0), SCALE_BENCH_RUNS (3), SCALE_BENCH_THREADS (2), SCALE_BENCH_SCENES
# (where floor-N.sf are taken from if there, else made:
# /tmp/scenefile-scale-bench), SCALE_BENCH_KEEP (0: a 100,000,000-object
# file this script made is deleted when done).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-build}
[[ $build = /* ]] || build=$PWD/$build
bin=$build/bin
sizes=${SCALE_BENCH_OBJECTS-1000000 10000000}
[[ ${SCALE_BENCH_100M:-0} == 1 ]] && sizes="$sizes 100000000"
runs=${SCALE_BENCH_RUNS:-3}
threads=${SCALE_BENCH_THREADS:-2}
scenes=${SCALE_BENCH_SCENES:-/tmp/scenefile-scale-bench}

die() {
  echo "scale_bench: $*" >&2
  exit 1
}
log() { echo "scale_bench: $*" >&2; }
source "$root/bench/common.sh"

for tool in sfgen sfrender; do
  [[ -x $bin/$tool ]] || die "$bin/$tool is missing: build first (cmake --build $build)"
done
[[ -x /usr/bin/time ]] || die "/usr/bin/time is missing (Debian: apt-get install time)"
mkdir -p "$scenes"
case "$(cd "$scenes" && pwd -P)/" in
  "$(cd "$root" && pwd -P)"/*) die "SCALE_BENCH_SCENES $scenes is inside the repository" ;;
esac
warn_unless_release "$build"

work=$(mktemp -d)
made=()
cleanup() {
  rm -rf "$work"
  [[ ${SCALE_BENCH_KEEP:-0} == 1 ]] || for f in "${made[@]}"; do rm -f "$f"; done
}
trap cleanup EXIT

calc() { awk "BEGIN { printf \"%s\", $1 }" </dev/null; }
# held STAGE FILE: the bytes an object sfrender -v says STAGE held.
held() { sed -n "s/.*[:,] $1 [0-9.]* MB (\([0-9]*\) B\/object).*/\1/p" "$2" | head -n 1; }
# took STEP FILE: the seconds sfrender -v says STEP took.
took() { sed -n "s/^sfrender: $1 took \([0-9.]*\) s/\1/p" "$2" | head -n 1; }

# The floor under the system times below: what the kernel charges for a
# process's first writes to memory it has not touched lately, and for
# memory given back and written again at once (bench/first_touch.cpp). It
# runs first, after a pause, before the renders give memory back.
touch_line=
if [[ -x $bin/first_touch ]]; then
  sleep 5
  "$bin/first_touch" --gib 2 --passes 2 >"$work/touch"
  read -r _ wall1 sys1 _ < <(sed -n 2p "$work/touch")
  read -r _ _ sys2 _ < <(sed -n 3p "$work/touch")
  touch_line="First writes to memory (\`first_touch --gib 2 --passes 2\`, 2 MiB pages, before the renders): $(fmt 2 "$(calc "$sys1 / 2.147")") s of system time a GB ($wall1 s wall for 2 GiB); given back and written again at once: $(fmt 2 "$(calc "$sys2 / 2.147")") s a GB."
fi

echo "| objects | file | wall | user | sys | peak | per object | text | model | records | BVH | grids | image | read | prepare | render | write |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
for n in $sizes; do
  scene=$scenes/floor-$n.sf
  if [[ ! -f $scene ]]; then
    log "making $scene"
    "$bin/sfgen" --layout floor -n "$n" -s 1 -o "$scene" >/dev/null
    [[ $n -lt 100000000 ]] || made+=("$scene")
  fi
  bytes=$(stat -c %s "$scene")
  limits=(--max-file-size "$bytes" --max-objects $((n + 10)))
  render=("$bin/sfrender" "$scene" -o "$work/image.png" --width 1920 --height 1080 --spp 1
    --threads "$threads" -v "${limits[@]}")
  count=$runs
  if [[ $n -ge 100000000 ]]; then
    count=1
  else
    "${render[@]}" 2>/dev/null || true
  fi
  walls=() users=() syss=() peaks=()
  failed=0
  for ((r = 1; r <= count; ++r)); do
    /usr/bin/time -f "%e %U %S %M" -o "$work/time" "${render[@]}" 2>"$work/log.$r" || failed=$?
    if ((failed != 0)); then
      echo "| $(thousands "$n") | $(fmt 2 "$(calc "$bytes / 1e9")") GB | exit $failed:" \
        "$(grep -v '^Command exited' "$work/log.$r" | tail -n 1) |"
      break
    fi
    read -r wall user sys peak <"$work/time"
    walls+=("$wall") users+=("$user") syss+=("$sys") peaks+=("$peak")
    log "$n objects, run $r: $wall s wall, $user s user, $sys s sys, $((peak / 1024)) MB"
  done
  ((failed == 0)) || continue
  # The stages of the run of the median wall time.
  mid=$(median "${walls[@]}")
  pick=1
  for ((r = 1; r <= count; ++r)); do [[ ${walls[r - 1]} == "$mid" ]] && pick=$r; done
  log=$work/log.$pick
  peak=$(median "${peaks[@]}")
  echo "| $(thousands "$n") | $(fmt 2 "$(calc "$bytes / 1e9")") GB | $mid s | $(median "${users[@]}") s" \
    "| $(median "${syss[@]}") s | $(fmt 2 "$(calc "$peak * 1024 / 1e9")") GB" \
    "| $(fmt 0 "$(calc "$peak * 1024 / $n")") B | $(held text "$log") B | $(held model "$log") B" \
    "| $(held records "$log") B | $(held BVH "$log") B | $(held grids "$log") B | $(held image "$log") B" \
    "| $(took reading "$log") s | $(took 'preparing the scene' "$log") s | $(took rendering "$log") s" \
    "| $(took writing "$log") s |"
done
echo
echo "$(date -u '+%Y-%m-%d'), $(cpu_model), $(nproc) cores, $(memory_total), load $(cut -d ' ' -f 1-3 /proc/loadavg), commit $(short_commit "$root"), $threads threads"
[[ -z $touch_line ]] || printf '\n%s\n' "$touch_line"
