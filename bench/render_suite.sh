#!/usr/bin/env bash
# The rendering suite: bash bench/render_suite.sh [BUILD_DIR]   (or `make bench`)
#
# Four parts, each written into its own section of docs/perf/RESULTS.md, with
# plots (gnuplot, PNG) under docs/perf/:
#
# 1. Against POV-Ray 3.7 at 1920x1080, 1 sample per pixel, depth 5, 2 threads,
#    through the POV-Ray export: the default scene, floor scenes of 10, 1,000,
#    100,000 and 1,000,000 objects, and a glass-and-mirror scene
#    (bench/scenes/glass-mirror.txt). One untimed run of each program, then
#    RUNS timed runs of each, alternating (which goes first alternates too);
#    the million-object scene gets BIG_RUNS and no untimed run. Wall time and
#    peak RSS from /usr/bin/time -v; sfrender's render time from --stats (the
#    rest of its wall time is "time to first pixel": start, parse, build);
#    POV-Ray's parse, bounding and trace times from its statistics.
# 2. Scaling: render_probe (one process: parse, BVH build and render timed
#    apart) on floor scenes of 10 to 1,000,000 objects: build and render time
#    against N, time per primary ray against log N, parse time against size.
# 3. Speed against error: on three scenes, sfrender at samples per pixel 1,
#    4, 16, 64 and depth 1 to 8 against a converged reference (REF_SPP
#    samples, depth 8) at a small size (SVE_WIDTH x SVE_HEIGHT); RMSE and PSNR
#    through OpenImageIO (render_probe compare). POV-Ray's points: no
#    anti-aliasing (1 sample), max_trace_level = depth + 1.
# 4. Where the time goes: perf record on sfrender for the main scenes.
#
# Three more parts, not run unless SUITE_PARTS names them (make bench runs
# their scripts itself): `embree` and `float` run bench/tracers.sh (Against
# Embree; Single precision), `equal-error` runs bench/equal_error.sh (Equal
# error), each with its own settings from the environment.
#
# Everything generated goes under SUITE_DIR (/tmp/scenefile-render-suite),
# never into the repository, except the plots under docs/perf/.
#
# Environment: SUITE_RUNS (3), SUITE_BIG_RUNS (2), SUITE_THREADS (2),
# SUITE_SIZES ("10 100 1000 10000 100000 1000000"), SUITE_REF_SPP (256),
# SUITE_SVE_WIDTH (256), SUITE_SVE_HEIGHT (144), SUITE_DIR,
# SUITE_PARTS ("compare scaling error profile"; also "embree", "float",
# "equal-error").
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-build}
[[ $build = /* ]] || build=$PWD/$build
bin=$build/bin
runs=${SUITE_RUNS:-3}
big_runs=${SUITE_BIG_RUNS:-2}
threads=${SUITE_THREADS:-2}
sizes=${SUITE_SIZES:-10 100 1000 10000 100000 1000000}
ref_spp=${SUITE_REF_SPP:-256}
sve_w=${SUITE_SVE_WIDTH:-256}
sve_h=${SUITE_SVE_HEIGHT:-144}
parts=${SUITE_PARTS:-compare scaling error profile}
seed=1
width=1920
height=1080
depth=5
data=${SUITE_DIR:-/tmp/scenefile-render-suite}
doc=$root/docs/perf/RESULTS.md
plots=$root/docs/perf

die() {
  echo "render_suite: $*" >&2
  exit 1
}
log() { echo "render_suite: $(date -u +%H:%M:%S) $*" >&2; }
source "$root/bench/common.sh"

for tool in sfgen sfrender sfconvert render_probe; do
  [[ -x $bin/$tool ]] || die "$bin/$tool is missing: build first (cmake --build $build)"
done
command -v povray >/dev/null 2>&1 || die "povray is not installed (make deps installs it)"
command -v gnuplot >/dev/null 2>&1 || die "gnuplot is not installed (make deps installs gnuplot-nox)"
[[ -x /usr/bin/time ]] || die "/usr/bin/time is missing (Debian: apt-get install time)"
[[ -f $doc ]] || die "$doc is missing: run bench/run.sh first, which writes its introduction"
mkdir -p "$data" "$plots"
data=$(cd "$data" && pwd -P)
case "$data/" in
  "$(cd "$root" && pwd -P)"/*) die "SUITE_DIR $data is inside the repository" ;;
esac
warn_unless_release "$build"
has_part() { [[ " $parts " == *" $1 "* ]]; }
suite_start=$(date +%s)

# --- Helpers ----------------------------------------------------------------
# Six significant digits: enough for the plots' data files.
calc() { awk "BEGIN { printf \"%.6g\", $1 }" </dev/null; }
sf_render_s() { sed -n 's/^sfrender: .*: \([0-9.]*\) s, .*/\1/p' "$1" | head -n 1; }
load() { cut -d ' ' -f 1-3 /proc/loadavg 2>/dev/null || echo unknown; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT


cpu=$(cpu_model)
mem_total=$(memory_total)
compiler_version=$(compiler_of "$build")
pov_version=$(povray_version)
commit=$(short_commit "$root")
dirty=$(git -C "$root" status --porcelain -- renderer tools libscene 2>/dev/null | awk '{ print $2 }' | tr '\n' ' ')
if [[ -n $dirty ]]; then commit="$commit with uncommitted changes in: ${dirty% }"; fi
built=$(date -u -r "$bin/sfrender" '+%Y-%m-%d %H:%M UTC')
newer=$(find "$root/renderer" "$root/libscene" "$root/tools/sfrender" -newer "$bin/sfrender" -type f 2>/dev/null | sed "s|^$root/||" | tr '\n' ' ')
commit="$commit (sfrender built $built"
if [[ -n $newer ]]; then commit="$commit; sources changed since, not measured: ${newer% })"; else commit="$commit)"; fi
machine="$(nproc) logical CPUs (\`nproc\`), CPU \"${cpu:-unknown}\", ${mem_total:-unknown} of memory,
Linux $(uname -r), ${compiler_version:-unknown compiler}, ${build_type:-unknown} build of commit
$commit; ${pov_version:-POV-Ray} from Debian"

# --- The scenes ---------------------------------------------------------------
# Only parts 1 to 4 need them: the others make their own.
if has_part compare || has_part scaling || has_part error || has_part profile; then
  aspect=$(awk -v w="$width" -v h="$height" 'BEGIN { printf "%.17g", w / h }')
  log "preparing the scenes in $data"
  "$bin/render_probe" default-scene "$data/default.txt"
  cp "$root/bench/scenes/glass-mirror.txt" "$data/glass-mirror.txt"
  for s in default glass-mirror; do
    "$bin/sfconvert" "$data/$s.txt" "$data/$s.pov" --width "$width" --height "$height" --fov 60 \
      2>"$work/convert-$s.log" || die "sfconvert $s failed: $(tail -n 3 "$work/convert-$s.log")"
  done
  all_sizes=$(printf "%s\n" $sizes $(printf "%s\n" ${SUITE_COMPARE_SCENES:-floor-10 floor-1000 floor-100000 floor-1000000} | sed -n "s/^floor-//p") 1000 1000000 | sort -gu | tr "\n" " ")
  for n in $all_sizes; do
    if [[ ! -f $data/floor-$n.sf || ! -f $data/floor-$n.pov || $bin/sfgen -nt $data/floor-$n.sf ]]; then
      log "generating floor-$n"
      "$bin/sfgen" --layout floor -n "$n" -s "$seed" --aspect "$aspect" -o "$data/floor-$n.sf" \
        --pov "$data/floor-$n.pov" >/dev/null
    fi
  done
fi
# scene_file NAME: the file sfrender reads.
scene_file() { if [[ -f $data/$1.txt ]]; then echo "$data/$1.txt"; else echo "$data/$1.sf"; fi; }
# pov_at_depth NAME DEPTH: a copy of NAME.pov with max_trace_level DEPTH + 1
# (POV-Ray counts the camera ray as level 1).
pov_at_depth() {
  local out=$data/$1-d$2.pov
  sed -E "s/max_trace_level [0-9]+/max_trace_level $(($2 + 1))/" "$data/$1.pov" >"$out"
  grep -q "max_trace_level $(($2 + 1))" "$out" || die "no max_trace_level in $1.pov"
  echo "$(basename "$out")"
}

# run_sf TAG SCENE IMAGE ARGS...: one sfrender run under /usr/bin/time.
run_sf() {
  local tag=$1 scene=$2 image=$3
  shift 3
  (cd "$data" && /usr/bin/time -v -o "$work/$tag-sf.time" "$bin/sfrender" "$scene" -o "$image" \
    --threads "$threads" --stats "$@" >"$work/$tag-sf.log" 2>&1) ||
    die "sfrender failed; see its output: $(tail -n 5 "$work/$tag-sf.log")"
}
# run_pov TAG POVFILE IMAGE W H ARGS...: one POV-Ray run, no anti-aliasing.
run_pov() {
  local tag=$1 pov=$2 image=$3 w=$4 h=$5
  shift 5
  (cd "$data" && /usr/bin/time -v -o "$work/$tag-pov.time" povray "+I$pov" "+O$image" +FP "+W$w" \
    "+H$h" -A "+WT$threads" -D -V File_Gamma=1.0 "$@" >"$work/$tag-pov.log" 2>&1) ||
    die "povray failed; see its output: $(tail -n 5 "$work/$tag-pov.log")"
}

plot_common="set terminal pngcairo size 900,560 font 'DejaVu Sans,10'; set grid; set key outside right top"

# === 1. Against POV-Ray =======================================================
if has_part compare; then
  compare_scenes=${SUITE_COMPARE_SCENES:-default glass-mirror floor-10 floor-1000 floor-100000 floor-1000000}
  load_start=$(load)
  declare -A S_wall S_render S_ttfp S_peak P_wall P_ttfp P_trace P_peak RAW S_walls_all
  : >"$work/compare.dat"
  for s in $compare_scenes; do
    sf=$(scene_file "$s")
    pov=$(pov_at_depth "$s" "$depth")
    cat "$sf" "$data/$pov" >/dev/null
    r=$runs
    if [[ $s == floor-1000000 ]]; then
      r=$big_runs
    else
      log "$s: untimed run of each"
      run_sf "warm" "$sf" "$s-sfrender.ppm" --width "$width" --height "$height" --spp 1 --depth "$depth"
      run_pov "warm" "$pov" "$s-povray.ppm" "$width" "$height"
    fi
    sw=() sr=() st=() sp=() pw=() pt=() ptr=() pp=()
    RAW[$s]=""
    for ((i = 1; i <= r; i++)); do
      order="sf pov"
      ((i % 2)) || order="pov sf"
      log "$s, round $i of $r: $order"
      for who in $order; do
        if [[ $who == sf ]]; then
          run_sf "$s-$i" "$sf" "$s-sfrender.ppm" --width "$width" --height "$height" --spp 1 --depth "$depth"
        else
          run_pov "$s-$i" "$pov" "$s-povray.ppm" "$width" "$height"
        fi
      done
      w=$(time_wall "$work/$s-$i-sf.time" 3)
      rs=$(sf_render_s "$work/$s-$i-sf.log")
      [[ -n $rs ]] || die "no render time in sfrender's --stats output"
      sw+=("$w") sr+=("$rs") st+=("$(calc "$w - $rs")") sp+=("$(time_peak_mb "$work/$s-$i-sf.time")")
      pwall=$(time_wall "$work/$s-$i-pov.time" 3)
      ptrace=$(pov_seconds Trace "$work/$s-$i-pov.log")
      [[ -n $ptrace ]] || die "no trace time in POV-Ray's statistics"
      pw+=("$pwall") ptr+=("$ptrace") pt+=("$(calc "$pwall - $ptrace")")
      pp+=("$(time_peak_mb "$work/$s-$i-pov.time")")
      RAW[$s]+="$s round $i: sfrender wall $w render $rs peak ${sp[-1]} MB; povray wall $pwall parse $(pov_seconds Parse "$work/$s-$i-pov.log") bounding $(pov_seconds Bounding "$work/$s-$i-pov.log") trace $ptrace peak ${pp[-1]} MB"$'\n'
    done
    S_wall[$s]=$(median "${sw[@]}") S_render[$s]=$(median "${sr[@]}") S_ttfp[$s]=$(median "${st[@]}")
    S_peak[$s]=$(maximum "${sp[@]}")
    P_wall[$s]=$(median "${pw[@]}") P_trace[$s]=$(median "${ptr[@]}") P_ttfp[$s]=$(median "${pt[@]}")
    P_peak[$s]=$(maximum "${pp[@]}")
    S_walls_all[$s]=$(maximum "${sw[@]}")
    echo "$s ${S_ttfp[$s]} ${S_render[$s]} ${P_ttfp[$s]} ${P_trace[$s]}" >>"$work/compare.dat"
    log "$s: sfrender ${S_wall[$s]} s (${S_peak[$s]} MB), povray ${P_wall[$s]} s (${P_peak[$s]} MB)"
  done
  load_end=$(load)

  gnuplot <<EOF
$plot_common
set output '$plots/against-povray.png'
set title '1920x1080, 1 spp, depth 5, 2 threads: first pixel and render apart (medians)'
set key inside left top
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.85 border -1
set ylabel 'seconds (log scale)'
set logscale y 10
set yrange [0.01:*]
set xtics rotate by -20
plot '$work/compare.dat' using 2:xtic(1) title 'sfrender: first pixel (start, parse, build)' lc rgb '#9ecae1', \
  '' using 3 title 'sfrender: render' lc rgb '#08519c', \
  '' using 4 title 'POV-Ray: first pixel (start, parse, bounding)' lc rgb '#fdae6b', \
  '' using 5 title 'POV-Ray: trace' lc rgb '#d94801'
EOF

  big=${compare_scenes##* }
  big_ok=$(awk -v w="${S_walls_all[$big]}" -v m="${S_peak[$big]}" 'BEGIN { print (w < 10 && m < 1500) ? "yes" : "no" }')
  section=$work/compare.md
  {
    echo '<!-- BEGIN suite-compare: written by bench/render_suite.sh; edits here are lost -->'
    echo "## sfrender against POV-Ray, first pixel and render apart"
    echo
    echo "Measured on $(date -u +%Y-%m-%d) with \`bash bench/render_suite.sh\`: $machine." \
      "Load average (1, 5, 15 min) $load_start at the start of this part and $load_end at its" \
      "end: the machine is shared, and other work may have run beside the benchmark."
    echo
    echo "Both programs render the same scene at 1920x1080, 1 sample per pixel (POV-Ray: \`-A\`)," \
      "depth $depth (POV-Ray: \`max_trace_level $((depth + 1))\`, which counts the camera ray)," \
      "$threads threads. The default scene is the one \`sfrender\` draws with no input, written" \
      "out by \`render_probe default-scene\`; it and the glass-and-mirror scene" \
      "(\`bench/scenes/glass-mirror.txt\`) reach POV-Ray through \`sfconvert --width $width" \
      "--height $height --fov 60\`; the floor scenes are \`sfgen --layout floor -n N\` (random" \
      "spheres, cubes and cylinders over a plane, two lights), which writes both files." \
      "Each program ran once untimed, then $runs times, alternating with the other (which went" \
      "first alternated too); the 1,000,000-object scene ran $big_runs times each, with no" \
      "untimed run. Figures are medians; peak RSS is the largest run."
    echo
    echo "*First pixel* is everything before the render: for sfrender its wall time minus the" \
      "render time \`--stats\` reports (start, reading, parsing, building the BVH; writing the" \
      "image is in it too); for POV-Ray its wall time minus the trace time its statistics report" \
      "(start, parse, bounding; writing the image too)."
    echo
    echo "| scene | sfrender wall | POV-Ray wall | POV-Ray / sfrender | sfrender first pixel | POV-Ray first pixel | ratio | sfrender render | POV-Ray trace | ratio | sfrender peak RSS | POV-Ray peak RSS |"
    echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
    for s in $compare_scenes; do
      echo "| $s | $(fmt 2 "${S_wall[$s]}") s | $(fmt 2 "${P_wall[$s]}") s | **$(fmt 2 "$(calc "${P_wall[$s]} / ${S_wall[$s]}")")×** |" \
        "$(fmt 2 "${S_ttfp[$s]}") s | $(fmt 2 "${P_ttfp[$s]}") s | $(fmt 1 "$(calc "${P_ttfp[$s]} / (${S_ttfp[$s]} > 0 ? ${S_ttfp[$s]} : 0.001)")")× |" \
        "$(fmt 2 "${S_render[$s]}") s | $(fmt 2 "${P_trace[$s]}") s | $(fmt 2 "$(calc "${P_trace[$s]} / ${S_render[$s]}")")× |" \
        "${S_peak[$s]} MB | ${P_peak[$s]} MB |"
    done
    echo
    echo "![First pixel and render time of both programs](against-povray.png)"
    echo
    echo "**1,000,000 objects, 1920x1080 at 1 spp, parsed, built and rendered in under 10 s with" \
      "a peak under 1.5 GB: $big_ok** — slowest of the $big_runs runs $(fmt 2 "${S_walls_all[$big]}") s" \
      "wall (median $(fmt 2 "${S_wall[$big]}") s: $(fmt 2 "${S_ttfp[$big]}") s to the first pixel," \
      "$(fmt 2 "${S_render[$big]}") s rendering), peak RSS ${S_peak[$big]} MB. MB = 10^6 bytes."
    echo
    echo "Raw figures (seconds):"
    echo
    echo '```'
    for s in $compare_scenes; do printf '%s' "${RAW[$s]}"; done
    echo '```'
    echo '<!-- END suite-compare -->'
  } >"$section"
  replace_section suite-compare "$section"
fi

# === 2. Scaling ==============================================================
if has_part scaling; then
  load_start=$(load)
  : >"$work/scaling.dat"
  declare -A K_parse K_build K_render K_ray K_bytes K_peak K_raw
  for n in $sizes; do
    f=$data/floor-$n.sf
    cat "$f" >/dev/null
    r=$runs
    [[ $n -ge 1000000 ]] && r=$big_runs
    ps=() bs=() rs=() ys=() pk=()
    K_raw[$n]=""
    for ((i = 1; i <= r; i++)); do
      log "scaling: $n objects, run $i of $r"
      "$bin/render_probe" time "$f" --width "$width" --height "$height" --spp 1 --depth "$depth" \
        --threads "$threads" >"$work/probe-$n-$i.txt" || die "render_probe failed on $f"
      ps+=("$(value parse_s "$work/probe-$n-$i.txt")") bs+=("$(value build_s "$work/probe-$n-$i.txt")")
      rs+=("$(value render_s "$work/probe-$n-$i.txt")") ys+=("$(value ns_per_primary_ray "$work/probe-$n-$i.txt")")
      pk+=("$(value peak_rss_bytes "$work/probe-$n-$i.txt")")
      K_raw[$n]+="$n objects run $i: parse ${ps[-1]} build ${bs[-1]} render ${rs[-1]} ns/primary ray ${ys[-1]} peak ${pk[-1]} B"$'\n'
    done
    K_parse[$n]=$(median "${ps[@]}") K_build[$n]=$(median "${bs[@]}") K_render[$n]=$(median "${rs[@]}")
    K_ray[$n]=$(median "${ys[@]}") K_peak[$n]=$(maximum "${pk[@]}")
    K_bytes[$n]=$(value file_bytes "$work/probe-$n-1.txt")
    echo "$n ${K_parse[$n]} ${K_build[$n]} ${K_render[$n]} ${K_ray[$n]} ${K_bytes[$n]}" >>"$work/scaling.dat"
  done
  load_end=$(load)
  first=${sizes%% *}
  last=${sizes##* }
  growth=$(calc "${K_ray[$last]} / ${K_ray[$first]}")
  growth_ok=$(awk -v g="$growth" 'BEGIN { print (g <= 3) ? "yes" : "no" }')

  gnuplot <<EOF
$plot_common
set output '$plots/scaling.png'
set title 'sfrender on floor scenes: parse, BVH build and render time against object count'
set logscale xy 10
set format x '10^{%L}'
set xlabel 'objects'
set ylabel 'seconds'
set key left top inside
plot '$work/scaling.dat' using 1:2 with linespoints lw 2 title 'parse (scene::parseScene)', \
  '' using 1:3 with linespoints lw 2 title 'BVH build (render::RenderScene)', \
  '' using 1:4 with linespoints lw 2 title 'render 1920x1080, 1 spp, 2 threads'
EOF
  gnuplot <<EOF
$plot_common
set output '$plots/ray-time.png'
set title 'CPU time per primary ray (with its shading and shadow rays) against log N'
set logscale x 10
set format x '10^{%L}'
set xlabel 'objects (log scale)'
set ylabel 'ns per primary ray (render time x threads / primary rays)'
set yrange [0:*]
set key left top inside
plot '$work/scaling.dat' using 1:5 with linespoints lw 2 pt 7 title 'sfrender', \
  ${K_ray[$first]} * 3 with lines dt 2 lc rgb 'red' title '3x the time at $first objects'
EOF
  gnuplot <<EOF
$plot_common
set output '$plots/parse-size.png'
set title 'Parse time against scene file size (floor scenes)'
set logscale xy 10
set xlabel 'file size, MB'
set ylabel 'parse time, seconds'
set key left top inside
plot '$work/scaling.dat' using (\$6/1e6):2 with linespoints lw 2 pt 7 title 'scene::parseScene', \
  '' using (\$6/1e6):(\$6/1e6/200) with lines dt 2 title '200 MB/s'
EOF

  section=$work/scaling.md
  {
    echo '<!-- BEGIN suite-scaling: written by bench/render_suite.sh; edits here are lost -->'
    echo "## Scaling with the object count"
    echo
    echo "Measured on $(date -u +%Y-%m-%d) with \`bash bench/render_suite.sh\`: $machine." \
      "Load average $load_start at the start of this part, $load_end at its end."
    echo
    echo "\`render_probe time floor-N.sf --width $width --height $height --spp 1 --depth $depth" \
      "--threads $threads\`: one process reads the file, then times apart \`scene::parseScene\`" \
      "(the file already in memory), the construction of \`render::RenderScene\` (object" \
      "records and the BVH) and \`render::renderImage\`. Medians of $runs runs" \
      "($big_runs for 1,000,000). *Per primary ray* is the render time times the $threads" \
      "threads over the primary rays (one a pixel): CPU time per pixel, with the pixel's shading" \
      "and its shadow rays. The floor scenes keep the same density of objects (the square grows" \
      "as sqrt N and the camera with it), so each pixel sees a similar picture at every N."
    echo
    echo "| objects | file size | parse | BVH build | render | per primary ray | peak RSS |"
    echo "|---|---|---|---|---|---|---|"
    for n in $sizes; do
      echo "| $(thousands "$n") | $(fmt 2 "$(calc "${K_bytes[$n]} / 1e6")") MB | $(fmt 4 "${K_parse[$n]}") s |" \
        "$(fmt 4 "${K_build[$n]}") s | $(fmt 3 "${K_render[$n]}") s | $(fmt 0 "${K_ray[$n]}") ns |" \
        "$(fmt 1 "$(calc "${K_peak[$n]} / 1e6")") MB |"
    done
    echo
    echo "**Time per primary ray grows by at most 3x from $(thousands "$first") to" \
      "$(thousands "$last") objects: $growth_ok** ($(fmt 0 "${K_ray[$first]}") ns to" \
      "$(fmt 0 "${K_ray[$last]}") ns, $(fmt 2 "$growth")×)."
    echo
    echo "![Parse, build and render time against N](scaling.png)"
    echo
    echo "![Time per primary ray against log N](ray-time.png)"
    echo
    echo "![Parse time against file size](parse-size.png)"
    echo
    echo '```'
    for n in $sizes; do printf '%s' "${K_raw[$n]}"; done
    echo '```'
    echo '<!-- END suite-scaling -->'
  } >"$section"
  replace_section suite-scaling "$section"
fi

# === 3. Speed against error ====================================================
if has_part error; then
  load_start=$(load)
  error_scenes="default glass-mirror floor-1000"
  spps="1 4 16 64"
  depths="1 2 3 4 5 6 7 8"
  size_args=(--width "$sve_w" --height "$sve_h")
  section=$work/error.md
  {
    echo '<!-- BEGIN suite-error: written by bench/render_suite.sh; edits here are lost -->'
    echo "## Speed against error"
    echo
  } >"$section"
  for s in $error_scenes; do
    sf=$(scene_file "$s")
    ref=$s-reference.ppm
    log "error: $s: reference, $ref_spp spp, depth 8"
    run_sf "ref-$s" "$sf" "$ref" "${size_args[@]}" --spp "$ref_spp" --depth 8
    ref_time=$(sf_render_s "$work/ref-$s-sf.log")
    : >"$work/error-$s.dat"
    for spp in $spps; do
      for d in $depths; do
        run_sf "e-$s" "$sf" "$s-e.ppm" "${size_args[@]}" --spp "$spp" --depth "$d"
        t=$(sf_render_s "$work/e-$s-sf.log")
        "$bin/render_probe" compare "$data/$s-e.ppm" "$data/$ref" >"$work/cmp.txt"
        echo "$spp $d $t $(value rmse "$work/cmp.txt") $(value psnr_db "$work/cmp.txt")" >>"$work/error-$s.dat"
      done
      echo >>"$work/error-$s.dat"
      echo >>"$work/error-$s.dat"
      log "error: $s: $spp spp done"
    done
    : >"$work/pov-$s.dat"
    for d in $depths; do
      pov=$(pov_at_depth "$s" "$d")
      run_pov "e-$s" "$pov" "$s-pov.ppm" "$sve_w" "$sve_h"
      t=$(pov_seconds Trace "$work/e-$s-pov.log")
      "$bin/render_probe" compare "$data/$s-pov.ppm" "$data/$ref" >"$work/cmp.txt"
      echo "1 $d $t $(value rmse "$work/cmp.txt") $(value psnr_db "$work/cmp.txt")" >>"$work/pov-$s.dat"
    done
    cp "$work/error-$s.dat" "$data/error-$s.dat"
    cp "$work/pov-$s.dat" "$data/pov-$s.dat"

    gnuplot <<EOF
$plot_common
set output '$plots/error-$s.png'
set title "$s, ${sve_w}x${sve_h}: RMSE to a $ref_spp-spp depth-8 reference against render time (labels: depth)"
set logscale xy 10
set xlabel 'render time, seconds (sfrender --stats; POV-Ray: trace time)'
set ylabel 'RMSE (values 0 to 1)'
set key outside right top
plot for [i=0:3] '$work/error-$s.dat' index i using 3:4 with linespoints lw 2 pt 7 title sprintf('sfrender %d spp', 4**i), \
  '$work/error-$s.dat' index 3 using 3:4:2 with labels offset 0,0.8 font ',8' notitle, \
  '$work/error-$s.dat' index 0 using 3:4:2 with labels offset 0,-0.8 font ',8' notitle, \
  '$work/pov-$s.dat' using 3:4 with points pt 5 ps 1.3 lc rgb 'black' title 'POV-Ray, no AA (1 spp)', \
  '$work/pov-$s.dat' using 3:4:2 with labels offset 1.2,0 font ',8' notitle
EOF
    # The sentences: where depth stops mattering, and what 4x the samples buys
    # against what more depth buys.
    summary=$(awk -v scene="$s" '
      NF == 5 { t[$1, $2] = $3; e[$1, $2] = $4; p[$1, $2] = $5 }
      END {
        # depth at which 64 spp is within 2% of depth 8
        sat = 8
        for (d = 8; d >= 1; d--) if (e[64, d] <= e[64, 8] * 1.02) sat = d
        printf "depth_sat %d\n", sat
        # at 16 spp (times large enough to measure): depth 1 to sat, against
        # 16 to 64 spp at depth sat
        dE_depth = e[16, 1] - e[16, sat]; dT_depth = t[16, sat] - t[16, 1]
        if (dT_depth < 0.01) dT_depth = 0.01
        dE_spp = e[16, sat] - e[64, sat]; dT_spp = t[64, sat] - t[16, sat]
        if (dT_spp < 0.01) dT_spp = 0.01
        printf "e11 %.5f esat1 %.5f esat4 %.5f esat64 %.5f e648 %.5f\n", e[1,1], e[1,sat], e[4,sat], e[64,sat], e[64,8]
        printf "t11 %.3f tsat1 %.3f tsat4 %.3f tsat64 %.3f t161 %.3f tsat16 %.3f\n", t[1,1], t[1,sat], t[4,sat], t[64,sat], t[16,1], t[16,sat]
        printf "e161 %.5f esat16 %.5f\n", e[16,1], e[16,sat]
        printf "p11 %.1f psat1 %.1f psat4 %.1f psat16 %.1f psat64 %.1f\n", p[1,1], p[1,sat], p[4,sat], p[16,sat], p[64,sat]
        printf "rate_depth %.5f rate_spp %.5f\n", (dT_depth > 0 ? dE_depth / dT_depth : 0), (dT_spp > 0 ? dE_spp / dT_spp : 0)
      }' "$work/error-$s.dat")
    get() { printf '%s\n' "$summary" | tr ' ' '\n' | awk -v k="$1" 'prev == k { print; exit } { prev = $0 }'; }
    sat=$(get depth_sat)
    pov_e=$(awk -v d="$sat" '$2 == d { print $4 }' "$work/pov-$s.dat")
    pov_t=$(awk -v d="$sat" '$2 == d { print $3 }' "$work/pov-$s.dat")
    sf_e1=$(awk -v d="$sat" '$1 == 1 && $2 == d { print $4 }' "$work/error-$s.dat")
    {
      echo "### $s"
      echo
      echo "![Error against time, $s](error-$s.png)"
      echo
      echo "Reference: $ref_spp spp, depth 8, $(fmt 1 "$ref_time") s. Each point is one run."
      echo
      echo "| spp \\ depth | $(echo $depths | sed 's/ / | /g') |"
      echo "|---|$(for d in $depths; do printf -- '---|'; done)"
      for spp in $spps; do
        printf '| %s |' "$spp"
        for d in $depths; do
          awk -v a="$spp" -v b="$d" 'NF == 5 && $1 == a && $2 == b { printf " %.4f, %.1f dB, %.2f s |", $4, $5, $3 }' "$work/error-$s.dat"
        done
        echo
      done
      printf '| POV-Ray, 1 |'
      for d in $depths; do
        awk -v b="$d" '$2 == b { printf " %.4f, %.1f dB, %.2f s |", $4, $5, $3 }' "$work/pov-$s.dat"
      done
      echo
      echo
      echo "Cells: RMSE, PSNR, render time."
      if [[ $sat -le 1 ]]; then
        echo "Depth buys nothing here: at 64 spp every depth from 1 up is within 2% of depth 8's" \
          "error, so rays beyond the first bounce do not change the picture. Samples are what" \
          "buy accuracy: RMSE $(get esat1) at 1 spp, $(get esat4) at 4, $(get esat64) at 64" \
          "(PSNR $(get psat1), $(get psat4), $(get psat64) dB), for $(get tsat1), $(get tsat4)," \
          "$(get tsat64) s; each 4x of the samples costs about 4x the time and halves the error" \
          "at best (noise falls as 1/sqrt(spp)), so the first step, 1 to 4 spp, buys the most" \
          "per second."
      else
        echo "Depth matters up to $sat (at 64 spp, depth $sat is within 2% of depth 8's error)," \
          "and it is cheap: at 16 spp, depth 1 to $sat takes RMSE from $(get e161) to $(get esat16)" \
          "while the render time goes from $(get t161) s to $(get tsat16) s (few rays survive" \
          "several bounces). Samples cost in proportion: at depth $sat, RMSE $(get esat1) at 1 spp," \
          "$(get esat4) at 4, $(get esat16) at 16, $(get esat64) at 64 (PSNR $(get psat1)," \
          "$(get psat4), $(get psat16), $(get psat64) dB) for $(get tsat1), $(get tsat4)," \
          "$(get tsat16), $(get tsat64) s. Per second, raising the depth to $sat buys" \
          "$(awk -v a="$(get rate_depth)" -v b="$(get rate_spp)" -v t0="$(get t161)" -v t1="$(get tsat16)" 'BEGIN { if (t1 - t0 < 0.15 * t0) print "far more (its cost is within the run-to-run noise) than going from 16 to 64 spp"; else if (b > 0) printf "about %.0f times as much error reduction per second as going from 16 to 64 spp", a / b; else print "far more than going from 16 to 64 spp" }'):" \
          "**set the depth to $sat first" \
          "(beyond it time grows and the error does not move), then spend on samples**, where" \
          "each 4x of the time roughly halves the error."
      fi
      if awk -v p="$pov_e" -v e="$sf_e1" 'BEGIN { exit !(p <= e * 1.05) }'; then
        echo "POV-Ray (1 spp, any depth) lands on sfrender's 1-spp points: RMSE $(fmt 4 "$pov_e")" \
          "in $(fmt 2 "$pov_t") s against $(fmt 4 "$sf_e1"): with nothing reflecting or refracting" \
          "the two draw the same picture, and both alias the same way at one ray a pixel."
      else
      echo "POV-Ray at depth $sat (1 spp) lands at RMSE $(fmt 4 "$pov_e") in $(fmt 2 "$pov_t") s," \
        "against sfrender's $(fmt 4 "$sf_e1"): its error includes the differences between the two" \
        "renderers' models (docs/POVRAY.md lists them: transparency, Fresnel weighting, Phong" \
        "highlights), so it levels off above sfrender's 1-spp points however deep it traces."
      fi
      echo
    } >>"$section"
  done
  load_end=$(load)
  tmp=$work/error-head.md
  {
    echo '<!-- BEGIN suite-error: written by bench/render_suite.sh; edits here are lost -->'
    echo "## Speed against error"
    echo
    echo "Measured on $(date -u +%Y-%m-%d) with \`bash bench/render_suite.sh\`: $machine." \
      "Load average $load_start at the start of this part, $load_end at its end."
    echo
    echo "For each scene, sfrender renders a converged reference ($ref_spp samples per pixel," \
      "depth 8) at ${sve_w}x${sve_h}, then every combination of 1, 4, 16 and 64 spp and depth" \
      "1 to 8 ($threads threads). Each image is compared with the reference by" \
      "\`render_probe compare\` (OpenImageIO's \`ImageBufAlgo::compare\`): RMSE over all pixels and" \
      "channels of the 8-bit linear images as values 0 to 1, and PSNR = 20 log10(1 / RMSE)." \
      "FLIP is not packaged for Debian 12 and is left out. Time is the render time" \
      "\`--stats\` reports (parse and build do not depend on these settings). POV-Ray's" \
      "points are its trace time and its image (\`-A\`: one ray a pixel, like 1 spp;" \
      "\`max_trace_level\` = depth + 1) against the same sfrender reference. Note that at 1 spp" \
      "both programs shoot through the pixel centre, so the 1-spp error is aliasing, not noise," \
      "and the 8-bit images cap PSNR near 59 dB."
    echo
    tail -n +4 "$section"
    echo '<!-- END suite-error -->'
  } >"$tmp"
  replace_section suite-error "$tmp"
fi

# === 4. Where the time goes ====================================================
if has_part profile; then
  section=$work/profile.md
  {
    echo '<!-- BEGIN suite-profile: written by bench/render_suite.sh; edits here are lost -->'
    echo "## Where the time goes"
    echo
    echo "Measured on $(date -u +%Y-%m-%d) with \`bash bench/render_suite.sh\`: $machine."
    echo "\`perf record -F 499\` on one sfrender run per scene (1920x1080, 1 spp, depth $depth," \
      "$threads threads); the functions with at least 1.5% of the samples, by" \
      "\`perf report --no-children --sort dso,symbol\` (self time; inlined functions count in" \
      "their callers)."
    echo
  } >"$section"
  if command -v perf >/dev/null 2>&1 && perf record -q -o "$work/probe.data" true >/dev/null 2>&1; then
    for s in floor-1000000 floor-1000 glass-mirror default; do
      log "profile: $s"
      sf=$(scene_file "$s")
      (cd "$data" && perf record -q -F 499 -o "$work/perf-$s.data" "$bin/sfrender" "$sf" -o "$s-perf.ppm" \
        --width "$width" --height "$height" --spp 1 --depth "$depth" --threads "$threads" --stats \
        >"$work/perf-$s.log" 2>&1) || die "perf record failed on $s: $(tail -n 3 "$work/perf-$s.log")"
      {
        echo "### $s"
        echo
        echo "$(grep '^sfrender: [0-9]' "$work/perf-$s.log" | head -n 1)"
        echo
        echo '```'
        perf report -i "$work/perf-$s.data" --stdio --no-children --sort dso,symbol --percent-limit 1.5 \
          2>/dev/null | grep -v '^#' | grep '%' | sed -E 's/^ +//; s/  +/  /g' | cut -c 1-120 | sed -E 's/ +$//' | head -n 16
        echo '```'
        echo
      } >>"$section"
      cp "$work/perf-$s.data" "$data/perf-$s.data"
    done
    echo "The perf data stay in \`$data/perf-*.data\` (\`perf report -i\`)." >>"$section"
  else
    echo "perf is not available here (install linux-perf, and allow it: kernel.perf_event_paranoid <= 2)." >>"$section"
  fi
  echo '<!-- END suite-profile -->' >>"$section"
  replace_section suite-profile "$section"
fi

# === 5. Against Embree, single precision, equal error ==========================
tracer_parts=""
has_part embree && tracer_parts+=" embree"
has_part float && tracer_parts+=" float"
if [[ -n $tracer_parts ]]; then
  TRACERS_PARTS=$tracer_parts TRACERS_DIR=$data bash "$root/bench/tracers.sh" "$build" ||
    die "bench/tracers.sh failed"
fi
if has_part equal-error; then
  bash "$root/bench/equal_error.sh" "$build" || die "bench/equal_error.sh failed"
fi

elapsed=$(($(date +%s) - suite_start))
log "done in $((elapsed / 60)) min $((elapsed % 60)) s; wrote ${doc#"$root"/} and ${plots#"$root"/}/"
