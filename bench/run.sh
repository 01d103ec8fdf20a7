#!/usr/bin/env bash
# The reading benchmark: bash bench/run.sh [BUILD_DIR]   (or `make bench`)
#
# Generates a 1,000,000-object scene (sfgen, fixed seed) into a folder under
# /tmp unless it is already there, then runs three rounds, each of:
#   read_bench --runs 5   parse+validate timed in-process, median of 5
#   read_bench --once     one parse in a fresh process: its peak memory
#   povray                the same scene as POV-Ray SDL, rendered at 1x1 pixel
# so that both programs see the same machine state. It writes the figures
# into docs/perf/RESULTS.md, between the markers of its own section.
#
# Environment: BENCH_OBJECTS (1000000), BENCH_SEED (1), BENCH_ROUNDS (3),
# BENCH_DIR (/tmp/scenefile-bench; never inside the repository),
# BENCH_NO_POVRAY=1 to leave POV-Ray out.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-build}
[[ $build = /* ]] || build=$PWD/$build
bin=$build/bin
objects=${BENCH_OBJECTS:-1000000}
seed=${BENCH_SEED:-1}
rounds=${BENCH_ROUNDS:-3}
runs=5
data=${BENCH_DIR:-/tmp/scenefile-bench}
doc=$root/docs/perf/RESULTS.md

die() {
  echo "bench: $*" >&2
  exit 1
}
log() { echo "bench: $*" >&2; }
source "$root/bench/common.sh"

for tool in sfgen read_bench; do
  [[ -x $bin/$tool ]] || die "$bin/$tool is missing: build first (cmake --build $build)"
done
mkdir -p "$data"
data=$(cd "$data" && pwd -P)
case "$data/" in
  "$(cd "$root" && pwd -P)"/*) die "BENCH_DIR $data is inside the repository; the scene files are large" ;;
esac

warn_unless_release "$build"

use_pov=0
if [[ ${BENCH_NO_POVRAY:-0} != 1 ]] && command -v povray >/dev/null 2>&1; then use_pov=1; fi
gnu_time=""
[[ -x /usr/bin/time ]] && gnu_time=/usr/bin/time

# --- The scene ------------------------------------------------------------
sf=$data/scene-$objects-s$seed.sf
pov=$data/scene-$objects-s$seed.pov
if [[ ! -f $sf || $bin/sfgen -nt $sf || ($use_pov == 1 && ! -f $pov) ]]; then
  log "generating $sf"
  args=(-n "$objects" -s "$seed" -o "$sf")
  [[ $use_pov == 1 ]] && args+=(--pov "$pov")
  "$bin/sfgen" "${args[@]}" >&2
fi
# Both programs then read from the page cache, not the disk.
cat "$sf" >/dev/null
[[ $use_pov == 1 ]] && cat "$pov" >/dev/null

# --- Helpers ----------------------------------------------------------------
# calc EXPR: floating-point arithmetic.
calc() { awk "BEGIN { printf \"%s\", $1 }" </dev/null; }
mb() { fmt "${2:-1}" "$(calc "$1 / 1e6")"; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# --- The rounds -------------------------------------------------------------
medians=() mins=() maxes=() peaks=()
pov_parse=() pov_bound=() pov_wall=() pov_peak=() pov_total=""
for ((round = 1; round <= rounds; round++)); do
  log "round $round of $rounds: read_bench --runs $runs"
  "$bin/read_bench" --runs "$runs" "$sf" >"$work/bench-$round.txt"
  medians+=("$(value median_s "$work/bench-$round.txt")")
  mins+=("$(value min_s "$work/bench-$round.txt")")
  maxes+=("$(value max_s "$work/bench-$round.txt")")

  log "round $round of $rounds: read_bench --once"
  "$bin/read_bench" --once "$sf" >"$work/once-$round.txt"
  peaks+=("$(value peak_rss_bytes "$work/once-$round.txt")")

  if [[ $use_pov == 1 ]]; then
    log "round $round of $rounds: povray"
    # -F: no output file; -D: no display; +WT1: one render thread (parsing
    # uses one thread anyway). POV-Ray parses the whole scene before it
    # renders; its statistics give the parse time and the object count. It
    # runs in the scene's folder, where its I/O restrictions allow reading.
    start=$(date +%s.%N)
    if [[ -n $gnu_time ]]; then
      (cd "$data" && $gnu_time -f '%e %M' -o "$work/time-$round.txt" \
        povray -D -F +W1 +H1 +WT1 "+I$(basename "$pov")" >"$work/pov-$round.txt" 2>&1) ||
        die "povray failed; see its output: $(tail -n 5 "$work/pov-$round.txt")"
      read -r wall peak_kb <"$work/time-$round.txt"
      pov_peak+=("$((peak_kb * 1024))")
    else
      (cd "$data" && povray -D -F +W1 +H1 +WT1 "+I$(basename "$pov")" >"$work/pov-$round.txt" 2>&1) ||
        die "povray failed; see its output: $(tail -n 5 "$work/pov-$round.txt")"
      wall=$(calc "$(date +%s.%N) - $start")
    fi
    pov_wall+=("$wall")
    pov_parse+=("$(sed -n 's/.*Parse Time:.*(\([0-9.]*\) seconds).*/\1/p' "$work/pov-$round.txt")")
    pov_bound+=("$(sed -n 's/.*Bounding Time:.*(\([0-9.]*\) seconds).*/\1/p' "$work/pov-$round.txt")")
    pov_total=$(sed -n 's/^Total: *\([0-9]*\).*/\1/p' "$work/pov-$round.txt")
    [[ -n ${pov_parse[-1]} ]] || die "no parse time in POV-Ray's statistics"
  fi
done

# --- Summary ----------------------------------------------------------------
first=$work/once-1.txt
file_bytes=$(value file_bytes "$first")
n_objects=$(value objects "$first")
n_lights=$(value lights "$first")
model=$(value model_bytes "$first")
sizeof_object=$(value sizeof_object_bytes "$first")
sizeof_light=$(value sizeof_light_bytes "$first")
rss_file=$(value rss_with_file_bytes "$first")
rss_start=$(value rss_at_start_bytes "$first")
med=$(median "${medians[@]}")
lo=$(minimum "${mins[@]}")
hi=$(maximum "${maxes[@]}")
peak=$(maximum "${peaks[@]}")
mbps=$(calc "$file_bytes / 1e6 / $med")
ratio=$(calc "$peak / $model")
speed_ok=$(awk -v v="$mbps" 'BEGIN { print (v >= 200) ? "yes" : "no" }')
memory_ok=$(awk -v v="$ratio" 'BEGIN { print (v <= 2) ? "yes" : "no" }')

cpu=$(cpu_model)
mem_total=$(memory_total)
compiler_version=$(compiler_of "$build")
commit=$(short_commit "$root")
if [[ -n $(git -C "$root" status --porcelain 2>/dev/null) ]]; then commit="$commit (with uncommitted changes)"; fi

section=$work/section.md
{
  echo '<!-- BEGIN read-benchmark: written by bench/run.sh; edits here are lost -->'
  echo "## Reading a scene file of $(thousands "$n_objects") objects"
  echo
  echo "Measured on $(date -u +%Y-%m-%d) with \`bash bench/run.sh\`: $(nproc) logical CPUs" \
    "(\`nproc\`), CPU \"${cpu:-unknown}\", ${mem_total:-unknown} of memory, Linux $(uname -r)," \
    "${compiler_version:-unknown compiler}, ${build_type:-unknown} build, commit $commit."
  echo "The scene is \`sfgen -n $objects -s $seed\`: a camera, $n_lights lights and" \
    "$(thousands "$n_objects") objects of the four kinds with random colours and random" \
    "rotation, scale (0.1 to 10) and translation, printed with 3 to 4 significant digits."
  echo "MB means 10^6 bytes."
  echo
  echo "| file size | objects | parse+validate, median (min–max) | throughput | peak RSS | model size | peak / model |"
  echo "|---|---|---|---|---|---|---|"
  echo "| $(mb "$file_bytes") MB | $(thousands "$n_objects") | $(fmt 3 "$med") s ($(fmt 3 "$lo")–$(fmt 3 "$hi") s) |" \
    "$(fmt 0 "$mbps") MB/s | $(mb "$peak") MB | $(mb "$model") MB | $(fmt 2 "$ratio") |"
  echo
  echo "- At least 200 MB/s on one core: **$speed_ok** ($(fmt 0 "$mbps") MB/s)."
  echo "- Peak memory at most twice the model: **$memory_ok** ($(fmt 2 "$ratio") times)."
  echo
  echo "How the figures are taken:"
  echo
  echo "- *Parse+validate* is one call of \`scene::parseSceneFile\` on the file already in" \
    "memory, on one thread; \`read_bench\` times $runs calls and reports their median. The" \
    "figure above is the median of the $rounds rounds' medians; min and max are over all" \
    "$((rounds * runs)) calls. Throughput is the file size over that median."
  echo "- *Peak RSS* is the peak resident memory of \`read_bench --once\`, a fresh process" \
    "that reads the file and parses it once: \`VmHWM\` of \`/proc/self/status\` (the counter" \
    "\`getrusage\`'s \`ru_maxrss\` reports too, which the kernel updates lazily, so the" \
    "larger of it and the \`VmRSS\` sampled after reading and after parsing is taken); the" \
    "largest of the $rounds rounds. It includes the whole process: the file buffer" \
    "($(mb "$file_bytes") MB; the process held $(mb "$rss_file") MB once the file was read," \
    "$(mb "$rss_start") MB before)."
  echo "- *Model size* is \`sizeof(scene::Object)\` ($sizeof_object bytes) times the objects," \
    "plus \`sizeof(scene::Light)\` ($sizeof_light bytes) times the lights, plus" \
    "\`sizeof(scene::Scene)\` and the heap blocks the records own (none for a scene file:" \
    "its objects carry no transform list)."
  if [[ $use_pov == 1 ]]; then
    pov_bytes=$(stat -c %s "$pov")
    pmed=$(median "${pov_parse[@]}")
    pbound=$(median "${pov_bound[@]}")
    pwall=$(median "${pov_wall[@]}")
    pov_version=$(povray_version)
    echo
    echo "### Against POV-Ray"
    echo
    echo "The same scene in POV-Ray's scene language (\`sfgen --pov\`: \`sphere\`, \`box\`," \
      "\`cylinder\` and \`plane\` with the same \`matrix\` numbers and a \`pigment\` each;" \
      "$(mb "$pov_bytes") MB), read by ${pov_version:-POV-Ray} rendering 1x1 pixel" \
      "(\`povray -D -F +W1 +H1 +WT1\`), in the same run, alternating with \`read_bench\`." \
      "Its statistics counted $(thousands "${pov_total:-0}") objects and lights, so it read the whole file." \
      "Parse time is the one POV-Ray reports (median of $rounds); wall time adds its start," \
      "the bounding hierarchy (median $(fmt 2 "$pbound") s), the one pixel and its exit."
    echo
    echo "| | parse time | throughput | wall time | peak RSS |"
    echo "|---|---|---|---|---|"
    echo "| \`scene::parseSceneFile\` (parse+validate) | $(fmt 3 "$med") s | $(fmt 0 "$mbps") MB/s | – | $(mb "$peak") MB |"
    if ((${#pov_peak[@]})); then
      ppeak=$(maximum "${pov_peak[@]}")
      ppeak_text="$(mb "$ppeak") MB"
      pratio_text="$(fmt 1 "$(calc "$ppeak / $peak")")×"
    else
      ppeak_text="n/a (no /usr/bin/time)"
      pratio_text="n/a"
    fi
    echo "| POV-Ray | $(fmt 3 "$pmed") s | $(fmt 0 "$(calc "$pov_bytes / 1e6 / $pmed")") MB/s |" \
      "$(fmt 2 "$pwall") s | $ppeak_text |"
    echo "| POV-Ray / ours | $(fmt 1 "$(calc "$pmed / $med")")× | | | $pratio_text |"
    echo
    echo "POV-Ray's peak RSS is \`/usr/bin/time\`'s maximum resident set size, the largest of" \
      "the $rounds runs."
  fi
  echo
  echo "Raw figures of each round (seconds; bytes):"
  echo
  echo '```'
  for ((round = 1; round <= rounds; round++)); do
    line="round $round: read_bench median ${medians[round - 1]} min ${mins[round - 1]} max ${maxes[round - 1]}; --once peak ${peaks[round - 1]}"
    if [[ $use_pov == 1 ]]; then
      line+="; povray parse ${pov_parse[round - 1]} bounding ${pov_bound[round - 1]} wall ${pov_wall[round - 1]}"
      ((${#pov_peak[@]})) && line+=" peak ${pov_peak[round - 1]}"
    fi
    echo "$line"
  done
  echo '```'
  echo '<!-- END read-benchmark -->'
} >"$section"

# --- docs/perf/RESULTS.md ------------------------------------------------------
if [[ ! -f $doc ]]; then
  mkdir -p "$(dirname "$doc")"
  cat >"$doc" <<'EOF'
# Benchmark results

Every benchmark's last run in full, with its raw figures: each section is
written by the script it names (`make bench`) and rewritten by its next run.
[PERFORMANCE.md](../PERFORMANCE.md) sums them up.

EOF
fi
if grep -q '^<!-- BEGIN read-benchmark' "$doc"; then
  awk -v section="$section" '
    /^<!-- BEGIN read-benchmark/ { while ((getline line < section) > 0) print line; skip = 1; next }
    /^<!-- END read-benchmark/ { skip = 0; next }
    !skip { print }' "$doc" >"$work/doc.md"
  cat "$work/doc.md" >"$doc"
else
  cat "$section" >>"$doc"
fi

log "wrote ${doc#"$root"/}"
sed -n '/^| file size/,/^$/p' "$section" >&2
log "at least 200 MB/s: $speed_ok ($(fmt 0 "$mbps") MB/s); peak at most twice the model: $memory_ok ($(fmt 2 "$ratio")x)"
