#!/usr/bin/env bash
# The render benchmark: bash bench/render_bench.sh [BUILD_DIR]   (or `make bench`)
#
# sfrender side by side with POV-Ray 3.7 at the same settings: 1920x1080, one
# sample per pixel (no anti-aliasing), two threads, depth 5, on scenes of
# 1,000 and 100,000 random objects over a floor plane with two lights
# (`sfgen --layout floor`, which writes the same scene for both programs).
# For each scene it makes one untimed run of each program (so that both
# start with their libraries and the scene in the page cache), then RUNS
# rounds of one timed run of each, alternating which goes first, under
# /usr/bin/time -v (wall time and peak RSS). It then checks that the two
# images show the same scene (image_compare), and writes the figures into
# docs/perf/RESULTS.md, between the markers of its own section.
#
# Environment: RENDER_BENCH_OBJECTS ("1000 100000"), RENDER_BENCH_RUNS (3),
# RENDER_BENCH_SEED (1), RENDER_BENCH_THREADS (2),
# RENDER_BENCH_DIR (/tmp/scenefile-render-bench; never inside the repository).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-build}
[[ $build = /* ]] || build=$PWD/$build
bin=$build/bin
sizes=${RENDER_BENCH_OBJECTS:-1000 100000}
runs=${RENDER_BENCH_RUNS:-3}
seed=${RENDER_BENCH_SEED:-1}
threads=${RENDER_BENCH_THREADS:-2}
width=1920
height=1080
depth=5
data=${RENDER_BENCH_DIR:-/tmp/scenefile-render-bench}
doc=$root/docs/perf/RESULTS.md

die() {
  echo "render_bench: $*" >&2
  exit 1
}
log() { echo "render_bench: $*" >&2; }
source "$root/bench/common.sh"

for tool in sfgen sfrender image_compare; do
  [[ -x $bin/$tool ]] || die "$bin/$tool is missing: build first (cmake --build $build)"
done
command -v povray >/dev/null 2>&1 ||
  die "povray is not installed (Debian: apt-get install povray; make deps installs it)"
[[ -x /usr/bin/time ]] || die "/usr/bin/time is missing (Debian: apt-get install time)"
mkdir -p "$data"
data=$(cd "$data" && pwd -P)
case "$data/" in
  "$(cd "$root" && pwd -P)"/*) die "RENDER_BENCH_DIR $data is inside the repository" ;;
esac

warn_unless_release "$build"

# --- Helpers ----------------------------------------------------------------
calc() { awk "BEGIN { printf \"%s\", $1 }" </dev/null; }
load() { cut -d ' ' -f 1-3 /proc/loadavg 2>/dev/null || echo unknown; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

sf_args=(--width "$width" --height "$height" --spp 1 --threads "$threads" --depth "$depth" --stats)
# -A: no anti-aliasing (one ray per pixel); +FP: PPM; -D: no display; -V: no
# progress (the statistics still come); File_Gamma=1.0: linear values, as
# sfrender writes them (assumed_gamma 1.0 is in the scene file).
pov_args=(+FP "+W$width" "+H$height" -A "+WT$threads" -D -V File_Gamma=1.0)

# run_sf N TAG and run_pov N TAG: one run, its output in $work/TAG-*.
run_sf() {
  (cd "$data" && /usr/bin/time -v -o "$work/$2-sf.time" "$bin/sfrender" "floor-$1.sf" \
    -o "floor-$1-sfrender.ppm" "${sf_args[@]}" >"$work/$2-sf.log" 2>&1) ||
    die "sfrender failed; see its output: $(tail -n 5 "$work/$2-sf.log")"
}
run_pov() {
  # POV-Ray runs in the scene's folder, where its I/O restrictions allow
  # reading and writing.
  (cd "$data" && /usr/bin/time -v -o "$work/$2-pov.time" povray "+Ifloor-$1.pov" \
    "+Ofloor-$1-povray.ppm" "${pov_args[@]}" >"$work/$2-pov.log" 2>&1) ||
    die "povray failed; see its output: $(tail -n 5 "$work/$2-pov.log")"
}

aspect=$(awk -v w="$width" -v h="$height" 'BEGIN { printf "%.17g", w / h }')
load_start=$(load)
declare -A sf_cpu_med pov_cpu_med sf_wall_med sf_render_med sf_peak pov_wall_med pov_parse_med pov_bound_med \
  pov_trace_med pov_peak ratio raw agree compare sf_rays pov_total sf_bytes pov_bytes
for n in $sizes; do
  sf=$data/floor-$n.sf
  pov=$data/floor-$n.pov
  if [[ ! -f $sf || ! -f $pov || $bin/sfgen -nt $sf ]]; then
    log "generating $sf and $pov"
    "$bin/sfgen" --layout floor -n "$n" -s "$seed" --aspect "$aspect" -o "$sf" \
      --pov "$pov" >&2
  fi
  cat "$sf" "$pov" >/dev/null
  sf_bytes[$n]=$(stat -c %s "$sf")
  pov_bytes[$n]=$(stat -c %s "$pov")

  log "$n objects: warm-up run of each"
  run_sf "$n" "warm-$n"
  run_pov "$n" "warm-$n"

  sf_cpus=() pov_cpus=() sf_walls=() sf_renders=() sf_peaks=() pov_walls=() pov_parses=() pov_bounds=() pov_traces=()
  pov_peaks=()
  raw[$n]=""
  for ((run = 1; run <= runs; run++)); do
    tag=$n-$run
    if ((run % 2)); then
      log "$n objects, round $run of $runs: sfrender, then povray"
      run_sf "$n" "$tag"
      run_pov "$n" "$tag"
    else
      log "$n objects, round $run of $runs: povray, then sfrender"
      run_pov "$n" "$tag"
      run_sf "$n" "$tag"
    fi
    sf_walls+=("$(time_wall "$work/$tag-sf.time")")
    sf_peaks+=("$(time_peak_mb "$work/$tag-sf.time")")
    sf_cpus+=("$(time_cpu "$work/$tag-sf.time")")
    pov_cpus+=("$(time_cpu "$work/$tag-pov.time")")
    sf_renders+=("$(sed -n 's/^sfrender: .*: \([0-9.]*\) s, .*/\1/p' "$work/$tag-sf.log")")
    pov_walls+=("$(time_wall "$work/$tag-pov.time")")
    pov_peaks+=("$(time_peak_mb "$work/$tag-pov.time")")
    pov_parses+=("$(pov_seconds Parse "$work/$tag-pov.log")")
    pov_bounds+=("$(pov_seconds Bounding "$work/$tag-pov.log")")
    pov_traces+=("$(pov_seconds Trace "$work/$tag-pov.log")")
    [[ -n ${sf_renders[-1]} ]] || die "no render time in sfrender's --stats output"
    [[ -n ${pov_traces[-1]} ]] || die "no trace time in POV-Ray's statistics"
    raw[$n]+="$n objects, round $run: sfrender wall ${sf_walls[-1]} cpu ${sf_cpus[-1]} render ${sf_renders[-1]} peak ${sf_peaks[-1]} MB;"
    raw[$n]+=" povray wall ${pov_walls[-1]} cpu ${pov_cpus[-1]} parse ${pov_parses[-1]} bounding ${pov_bounds[-1]} trace ${pov_traces[-1]} peak ${pov_peaks[-1]} MB"$'\n'
  done
  sf_wall_med[$n]=$(median "${sf_walls[@]}")
  sf_render_med[$n]=$(median "${sf_renders[@]}")
  sf_cpu_med[$n]=$(median "${sf_cpus[@]}")
  pov_cpu_med[$n]=$(median "${pov_cpus[@]}")
  sf_peak[$n]=$(maximum "${sf_peaks[@]}")
  pov_wall_med[$n]=$(median "${pov_walls[@]}")
  pov_parse_med[$n]=$(median "${pov_parses[@]}")
  pov_bound_med[$n]=$(median "${pov_bounds[@]}")
  pov_trace_med[$n]=$(median "${pov_traces[@]}")
  pov_peak[$n]=$(maximum "${pov_peaks[@]}")
  ratio[$n]=$(calc "${pov_wall_med[$n]} / ${sf_wall_med[$n]}")
  sf_rays[$n]=$(sed -n 's/^sfrender: .* s, \([0-9,]*\) rays.*/\1/p' "$work/$n-1-sf.log")
  pov_total[$n]=$(sed -n 's/^Total: *\([0-9]*\).*/\1/p' "$work/$n-1-pov.log")

  # The same scene? Compare the last round's images, and keep a side-by-side
  # view (half size) beside them for a look.
  "$bin/image_compare" "$data/floor-$n-sfrender.ppm" "$data/floor-$n-povray.ppm" \
    --side-by-side "$data/floor-$n-side-by-side.png" >"$work/compare-$n.txt" ||
    die "image_compare failed"
  compare[$n]=$work/compare-$n.txt
  agree[$n]=$(awk -v c="$(value close_8 "${compare[$n]}")" -v f="$(value far_64 "${compare[$n]}")" \
    -v m="$(value far_64_mirrored "${compare[$n]}")" \
    'BEGIN { print (c >= 0.95 && f <= 0.02 && f < m) ? "yes" : "no" }')
  [[ ${agree[$n]} == yes ]] ||
    log "warning: the images of $n objects differ more than expected: $(tr '\n' ' ' <"${compare[$n]}")"
  log "$n objects: sfrender ${sf_wall_med[$n]} s, povray ${pov_wall_med[$n]} s (povray/sfrender $(fmt 2 "${ratio[$n]}")); images agree: ${agree[$n]}"
done
load_end=$(load)

# --- The section --------------------------------------------------------------
cpu=$(cpu_model)
mem_total=$(memory_total)
compiler_version=$(compiler_of "$build")
pov_version=$(povray_version)
commit=$(short_commit "$root")
if [[ -n $(git -C "$root" status --porcelain 2>/dev/null) ]]; then commit="$commit (with uncommitted changes)"; fi

faster_all=yes
barely=""
for n in $sizes; do
  awk -v r="${ratio[$n]}" 'BEGIN { exit !(r > 1) }' || faster_all=no
  awk -v r="${ratio[$n]}" 'BEGIN { exit !(r > 1 && r < 1.1) }' && barely+=" $(thousands "$n")"
done

section=$work/section.md
{
  echo '<!-- BEGIN render-benchmark: written by bench/render_bench.sh; edits here are lost -->'
  echo "## Rendering against POV-Ray"
  echo
  echo "Measured on $(date -u +%Y-%m-%d) with \`bash bench/render_bench.sh\`: $(nproc) logical CPUs" \
    "(\`nproc\`), CPU \"${cpu:-unknown}\", ${mem_total:-unknown} of memory, Linux $(uname -r)," \
    "${compiler_version:-unknown compiler}, ${build_type:-unknown} build, commit $commit;" \
    "${pov_version:-POV-Ray} from Debian. Load average (1, 5, 15 minutes) $load_start at the" \
    "start and $load_end at the end: the machine is shared, so other work may have run beside" \
    "the benchmark."
  echo
  echo "The scenes are \`sfgen --layout floor -n N -s $seed\`: a floor plane (y = 0), two lights" \
    "above it, and N spheres, cubes and cylinders with random colours, rotations and scales" \
    "(0.5 to 2 per axis), resting 0 to 2 units above the floor over a square of side" \
    "5 sqrt(N), seen from above one side. Every object has the default material of a scene" \
    "file (ambient 0.1, diffuse 0.9, specular 0.9, shininess 200): opaque, nothing reflects." \
    "\`sfgen --pov\` writes the same scene for POV-Ray: the same camera (explicit" \
    "\`direction\`, \`right\` and \`up\` vectors for the 60-degree vertical field of view at" \
    "16:9), \`sphere{0,1}\`, \`box{-1,1}\` and \`cylinder{<0,-1,0>,<0,1,0>,1}\` with the same" \
    "\`matrix\` numbers, \`plane{y,0}\`, \`light_source\`s without fading, \`#default{finish{ambient" \
    "0.1 diffuse 0.9 phong 0.9 phong_size 200}}\`, and \`ambient_light\` equal to the sum of" \
    "the lights (sfrender adds the ambient term once per light)."
  echo
  echo "Command lines, run in the scenes' folder:"
  echo
  echo '```'
  echo "sfrender floor-N.sf -o floor-N-sfrender.ppm ${sf_args[*]}"
  echo "povray +Ifloor-N.pov +Ofloor-N-povray.ppm ${pov_args[*]}"
  echo '```'
  echo
  echo "Each program ran once untimed, then $runs times, alternating with the other (which one" \
    "went first alternated too), under \`/usr/bin/time -v\`. Wall time is the median of the" \
    "$runs runs: the whole process, from start to exit, with reading the scene, building the" \
    "bounding hierarchy, rendering and writing the image. Peak RSS is the largest of the" \
    "$runs. CPU time is user plus system time, over all threads (median): less sensitive than" \
    "wall time to other work on the machine. *sfrender render* is the time its \`--stats\` reports for rendering alone;" \
    "POV-Ray's parse, bounding and trace times are the ones its statistics report (medians)."
  echo
  echo "| objects | sfrender wall | POV-Ray wall | POV-Ray / sfrender | CPU time, sfrender / POV-Ray | sfrender render | POV-Ray parse | POV-Ray bounding | POV-Ray trace | sfrender peak RSS | POV-Ray peak RSS |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|"
  for n in $sizes; do
    echo "| $(thousands "$n") | $(fmt 2 "${sf_wall_med[$n]}") s | $(fmt 2 "${pov_wall_med[$n]}") s |" \
      "**$(fmt 2 "${ratio[$n]}")×** | $(fmt 2 "${sf_cpu_med[$n]}") s / $(fmt 2 "${pov_cpu_med[$n]}") s |" \
      "$(fmt 2 "${sf_render_med[$n]}") s | $(fmt 2 "${pov_parse_med[$n]}") s |" \
      "$(fmt 2 "${pov_bound_med[$n]}") s | $(fmt 2 "${pov_trace_med[$n]}") s | ${sf_peak[$n]} MB | ${pov_peak[$n]} MB |"
  done
  echo
  if [[ $faster_all == yes ]]; then
    echo -n "sfrender takes less wall time than POV-Ray on both scenes: **yes**"
    [[ -n $barely ]] && echo -n " (but by less than 10% at${barely} objects)"
    echo "."
  else
    echo "sfrender takes less wall time than POV-Ray on both scenes: **no**."
  fi
  echo
  echo "The two programs draw the same images: \`image_compare\` on the last run's images" \
    "(fraction of pixels that are not black; of pixels whose channels all lie within 8 of" \
    "255 of the other image's; of pixels where some channel differs by more than 64, against" \
    "POV-Ray's image as it is and mirrored left to right, which would be the smaller one if" \
    "POV-Ray's image were mirrored)."
  echo
  echo "| objects | scene files (.sf / .pov) | non-black, sfrender / POV-Ray | within 8/255 | differ by > 64 | same, POV-Ray's mirrored | agree |"
  echo "|---|---|---|---|---|---|---|"
  for n in $sizes; do
    c=${compare[$n]}
    echo "| $(thousands "$n") | $(fmt 1 "$(calc "${sf_bytes[$n]} / 1e6")") MB / $(fmt 1 "$(calc "${pov_bytes[$n]} / 1e6")") MB |" \
      "$(fmt 1 "$(calc "$(value nonblack_a "$c") * 100")")% / $(fmt 1 "$(calc "$(value nonblack_b "$c") * 100")")% |" \
      "$(fmt 2 "$(calc "$(value close_8 "$c") * 100")")% | $(fmt 2 "$(calc "$(value far_64 "$c") * 100")")% |" \
      "$(fmt 1 "$(calc "$(value far_64_mirrored "$c") * 100")")% | ${agree[$n]} |"
  done
  echo
  echo "At $(thousands "${sizes##* }") objects sfrender traced ${sf_rays[${sizes##* }]} rays" \
    "(primary and shadow rays), and POV-Ray's statistics" \
    "counted $(thousands "${pov_total[${sizes##* }]:-0}") objects and lights, so it read the whole scene." \
    "The images and a side-by-side view (\`floor-N-side-by-side.png\`) stay in \`$data\`."
  echo
  echo "Raw figures of each run (seconds; MB = 10^6 bytes):"
  echo
  echo '```'
  for n in $sizes; do printf '%s' "${raw[$n]}"; done
  echo '```'
  echo '<!-- END render-benchmark -->'
} >"$section"

# --- docs/perf/RESULTS.md ------------------------------------------------------
[[ -f $doc ]] || die "$doc is missing: run bench/run.sh first, which writes its introduction"
if grep -q '^<!-- BEGIN render-benchmark' "$doc"; then
  awk -v section="$section" '
    /^<!-- BEGIN render-benchmark/ { while ((getline line < section) > 0) print line; skip = 1; next }
    /^<!-- END render-benchmark/ { skip = 0; next }
    !skip { print }' "$doc" >"$work/doc.md"
  cat "$work/doc.md" >"$doc"
else
  { echo; cat "$section"; } >>"$doc"
fi

log "wrote ${doc#"$root"/}"
sed -n '/^| objects | sfrender wall/,/^$/p' "$section" >&2
log "sfrender faster on every scene: $faster_all"
