#!/usr/bin/env bash
# Fuzzes every reader and sfconvert's whole path with libFuzzer under
# AddressSanitizer and UndefinedBehaviorSanitizer (tests/fuzz).
#
#   bash scripts/fuzz.sh [SECONDS] [TARGET...]      (make fuzz, make fuzz-ci)
#
# Builds the targets with clang in FUZZ_BUILD_DIR (build-fuzz), then runs each
# for SECONDS (default 600) in FUZZ_JOBS parallel jobs (default 1; each job
# runs SECONDS, so a target gets JOBS x SECONDS of fuzzing), the targets side
# by side, FUZZ_PARALLEL at a time (default: the cores over FUZZ_JOBS). The
# corpus grows in FUZZ_OUT/fuzz-corpus/NAME (FUZZ_OUT defaults to the build
# folder), seeded from testdata/ (the folders in fuzz-seeds.txt, written by
# tests/fuzz/CMakeLists.txt). A crash, a leak, a hang (one input over 10 s) or
# an input that needs more than 2 GiB is a finding: it lands in
# FUZZ_OUT/fuzz-findings/NAME/ and the script fails; the summary, with the executions of
# each target, is FUZZ_OUT/fuzz-summary.txt. A finding, once fixed, goes into
# testdata/fuzz/NAME/, where the fuzz.replay tests run it in every build.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
seconds=${1:-600}
shift || true
build=${FUZZ_BUILD_DIR:-$root/build-fuzz}
out=${FUZZ_OUT:-$build}
jobs=${FUZZ_JOBS:-1}
if [[ ${FUZZ_SKIP_BUILD:-0} != 1 ]]; then
  # A unity build (several sources to a translation unit): each header is
  # compiled a third as often.
  CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSCENEFILE_FUZZ=ON \
    -DCMAKE_UNITY_BUILD=ON >/dev/null
fi
# The targets and their dictionaries, as tests/fuzz/CMakeLists.txt made them
# from the format registry: "TARGET DICTIONARY SEED..." per line.
declare -A dictionary
all_targets=()
while read -r target dict _; do
  all_targets+=("$target")
  dictionary[$target]=$dict
done <"$build/fuzz-seeds.txt"
targets=("$@")
[[ ${#targets[@]} -gt 0 ]] || targets=("${all_targets[@]}")
if [[ ${FUZZ_SKIP_BUILD:-0} != 1 ]]; then
  cmake --build "$build" -j "$(nproc)" --target "${targets[@]/#/fuzz_}"
fi

mkdir -p "$out"
summary=$out/fuzz-summary.txt
: >"$summary"
# fuzz_target TARGET: fuzzes one target, appends its line to the summary;
# fails on a finding.
fuzz_target() {
  local target=$1
  local corpus=$out/fuzz-corpus/$target
  local findings logs seeds existing status runs counted n found line log dir
  findings=$out/fuzz-findings/$target
  logs=$out/fuzz-logs/$target
  mkdir -p "$corpus" "$findings" "$logs"
  rm -f "$logs"/*.log
  read -r -a seeds < <(grep "^$target " "$build/fuzz-seeds.txt" | cut -d' ' -f3-)
  existing=()
  for dir in "${seeds[@]}"; do [[ -d $root/$dir ]] && existing+=("$root/$dir"); done
  echo "fuzz $target: $jobs x ${seconds}s"
  status=0
  # -max_len keeps mutations fast (16 KiB holds a hundred records); the large hostile inputs have tests of
  # their own. Leaks are findings (ASan's leak check runs at each exit).
  (cd "$logs" && "$build/bin/fuzz_$target" "$corpus" "${existing[@]}" \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 \
      -dict="$root/tests/fuzz/${dictionary[$target]}.dict" \
      -artifact_prefix="$findings/" -print_final_stats=1 \
      $([[ $jobs -gt 1 ]] && echo "-jobs=$jobs -workers=$jobs") \
      >"$logs/run.log" 2>&1) || status=$?
  runs=0
  # With jobs, each job's statistics are in fuzz-N.log (run.log repeats them).
  counted=("$logs"/fuzz-*.log)
  [[ -e ${counted[0]} ]] || counted=("$logs/run.log")
  for log in "${counted[@]}"; do
    n=$(grep -h '^stat::number_of_executed_units:' "$log" | awk '{s += $2} END {print s + 0}' || true)
    runs=$((runs + n))
  done
  found=$(find "$findings" -type f | wc -l)
  line="$target: $((jobs * seconds)) s of fuzzing, $runs executions, corpus $(find "$corpus" -type f | wc -l) inputs, findings $found, exit $status"
  echo "$line" | tee -a "$summary"
  if [[ $status -ne 0 || $found -ne 0 ]]; then
    grep -h -A 30 -E 'ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error|fuzz property failed' \
      "$logs"/*.log | head -60 || true
    return 1
  fi
}

# The targets run side by side, as many at a time as there are cores for
# their jobs (FUZZ_PARALLEL overrides): each gets the same seconds of one
# core as when they ran in turn, in a fraction of the time.
parallel=${FUZZ_PARALLEL:-$(($(nproc) / jobs))}
((parallel >= 1)) || parallel=1
failed=0
running=0
for target in "${targets[@]}"; do
  if ((running >= parallel)); then
    wait -n || failed=1
    running=$((running - 1))
  fi
  fuzz_target "$target" &
  running=$((running + 1))
done
while ((running > 0)); do
  wait -n || failed=1
  running=$((running - 1))
done
exit $failed
