#!/usr/bin/env bash
# Equal error: bash bench/equal_error.sh [BUILD_DIR]   (also `make bench`, and
# render_suite.sh's part `equal-error`)
#
# How much CPU time (user + system, /usr/bin/time) sfrender and POV-Ray 3.7
# each need to reach a given RMSE against their own converged image, on
# floor-1000 (sfgen --layout floor -n 1000 -s 1), the default scene (the one
# sfrender draws with no input, written out by render_probe default-scene)
# and bench/scenes/glass-mirror.txt, at EQ_WIDTH x EQ_HEIGHT:
#
# - sfrender: --spp 1 2 4 8 16 (EQ_SPPS) and, when its --help lists
#   --adaptive, --adaptive T --spp N for each T:N of EQ_ADAPTIVE; its
#   reference is --spp EQ_REF_SPP.
# - POV-Ray, through sfconvert --to pov: +A<threshold> +AM<method> +R<depth>
#   for each A:AM:R of EQ_POV_POINTS; its reference is EQ_POV_REF.
#
# RMSE through OpenImageIO (render_probe compare; 8-bit images as values 0
# to 1). Writes docs/perf/equal-error.dat and docs/perf/equal-error.png
# (error against CPU time, log-log, a panel per scene) and the section
# "Equal error" of docs/perf/RESULTS.md: a table per scene and, for POV-Ray's
# +A0.3 +AM2 +R3, the ratio of its CPU time to the time sfrender needs for
# the same RMSE, interpolated in log-log between sfrender's points.
#
# Environment: EQ_RUNS (3: the runs of each point, whose median CPU time is
# quoted), EQ_WIDTH (1280), EQ_HEIGHT (720), EQ_THREADS (2),
# EQ_SCENES ("floor-1000 default glass-mirror"), EQ_REF_SPP (256),
# EQ_POV_REF ("+AM2 +A0.0 +R4"), EQ_SPPS ("1 2 4 8 16"),
# EQ_ADAPTIVE ("0.3:16 0.2:16 0.15:16 0.1:16 0.05:16 0.03:16 0.1:64
# 0.03:64"; the thresholds between 0.3 and 0.05 put points near the RMSE of
# POV-Ray's +A0.3, where the ratio is read, rather than interpolating across
# a gap),
# EQ_POV_POINTS ("0.3:2:3 0.3:2:2 0.3:2:4 0.3:1:3 0.1:1:3 0.1:2:3 0.03:1:3
# 0.03:2:3"), EQ_DIR
# (/tmp/scenefile-equal-error; never inside the repository). At the
# defaults it takes about 15 minutes on 2 cores (the references 6, a round 3).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-build}
[[ $build = /* ]] || build=$PWD/$build
bin=$build/bin
width=${EQ_WIDTH:-1280}
height=${EQ_HEIGHT:-720}
threads=${EQ_THREADS:-2}
runs=${EQ_RUNS:-3}
scenes=${EQ_SCENES:-floor-1000 default glass-mirror}
ref_spp=${EQ_REF_SPP:-256}
pov_ref=${EQ_POV_REF:-+AM2 +A0.0 +R4}
spps=${EQ_SPPS:-1 2 4 8 16}
adaptive_points=${EQ_ADAPTIVE:-0.3:16 0.2:16 0.15:16 0.1:16 0.05:16 0.03:16 0.1:64 0.03:64}
pov_points=${EQ_POV_POINTS:-0.3:2:3 0.3:2:2 0.3:2:4 0.3:1:3 0.1:1:3 0.1:2:3 0.03:1:3 0.03:2:3}
data=${EQ_DIR:-/tmp/scenefile-equal-error}
doc=$root/docs/perf/RESULTS.md
plots=$root/docs/perf

die() {
  echo "equal_error: $*" >&2
  exit 1
}
log() { echo "equal_error: $(date -u +%H:%M:%S) $*" >&2; }
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
  "$(cd "$root" && pwd -P)"/*) die "EQ_DIR $data is inside the repository" ;;
esac
warn_unless_release "$build"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
start=$(date +%s)
# The commit as the run starts, the one nearest the binaries measured:
# commits made during the run are not in them.
commit=$(short_commit "$root")
load_start=$(cut -d ' ' -f 1-3 /proc/loadavg 2>/dev/null || echo unknown)

has_adaptive=no
# The help is read whole before it is searched: with pipefail, grep -q
# leaving at the first match could end sfrender on SIGPIPE mid-help, and
# the pipe then fail.
sfrender_help=$("$bin/sfrender" --help 2>/dev/null || true)
if [[ $sfrender_help == *--adaptive* ]]; then has_adaptive=yes; fi
[[ $has_adaptive == yes ]] || log "sfrender --help lists no --adaptive: its adaptive points are left out"

# --- The scenes: each as sfrender reads it and as POV-Ray's .pov -------------
log "preparing ${scenes// /, } in $data"
for s in $scenes; do
  case $s in
    floor-*)
      "$bin/sfgen" --layout floor -n "${s#floor-}" -s 1 --aspect "$(awk -v w="$width" -v h="$height" \
        'BEGIN { printf "%.17g", w / h }')" -o "$data/$s.sf" >/dev/null
      src=$data/$s.sf
      ;;
    default)
      "$bin/render_probe" default-scene "$data/$s.txt"
      src=$data/$s.txt
      ;;
    *)
      [[ -f $root/bench/scenes/$s.txt ]] || die "no scene $s (bench/scenes/$s.txt)"
      cp "$root/bench/scenes/$s.txt" "$data/$s.txt"
      src=$data/$s.txt
      ;;
  esac
  echo "$src" >"$work/$s.src"
  "$bin/sfconvert" "$src" "$data/$s.pov" --to pov --width "$width" --height "$height" --fov 60 \
    2>"$work/convert-$s.log" || die "sfconvert $s failed: $(tail -n 3 "$work/convert-$s.log")"
done

# run_sf SCENE IMAGE ARGS... and run_pov SCENE IMAGE ARGS...: one render under
# /usr/bin/time; print its CPU time (user + system).
run_sf() {
  local s=$1 image=$2
  shift 2
  /usr/bin/time -v -o "$work/run.time" "$bin/sfrender" "$(cat "$work/$s.src")" -o "$data/$image" \
    --width "$width" --height "$height" --threads "$threads" "$@" >"$work/run.log" 2>&1 ||
    die "sfrender $s $* failed: $(tail -n 5 "$work/run.log")"
  time_cpu "$work/run.time"
}
run_pov() {
  local s=$1 image=$2
  shift 2
  # In the scenes' folder, where POV-Ray's I/O restrictions let it read and
  # write; +FP: PPM, as sfrender writes here, so that neither pays for
  # compressing its image (libpng at its defaults: 0.06 to 0.14 s on these
  # images at 1280x720); -D: no display, -V: no progress, linear values.
  (cd "$data" && /usr/bin/time -v -o "$work/run.time" povray "+I$s.pov" "+O$image" +FP "+W$width" \
    "+H$height" "+WT$threads" -D -V File_Gamma=1.0 "$@" >"$work/run.log" 2>&1) ||
    die "povray $s $* failed: $(tail -n 5 "$work/run.log")"
  time_cpu "$work/run.time"
}
rmse_of() {
  "$bin/render_probe" compare "$data/$1" "$data/$2" >"$work/cmp.txt" || die "render_probe compare $1 $2 failed"
  value rmse "$work/cmp.txt"
}

# --- The runs: one line per point in the data file ----------------------------
# Every point runs EQ_RUNS times, in rounds (each round renders every point
# once), and its CPU time is the median of its runs: single runs on these
# machines move by a third, and rounds spread each point over the whole run,
# so that a slow spell weighs on both renderers alike. Both renderers are
# deterministic here (POV-Ray's anti-aliasing without jitter), so the RMSE
# is the first round's.
dat=$work/equal-error.dat
times=$work/times.txt
rmses=$work/rmses.txt
: >"$times"
: >"$rmses"
# point ROUND SCENE WHO SETTINGS IMAGE REFERENCE RUNNER ARGS...: one run of a
# point, its CPU time kept; in the first round also its RMSE.
point() {
  local round=$1 s=$2 who=$3 settings=$4 image=$5 reference=$6 runner=$7
  shift 7
  local cpu
  cpu=$("$runner" "$s" "$image" "$@")
  echo "$s $who $settings $cpu" >>"$times"
  if [[ $round == 1 ]]; then
    echo "$s $who $settings $(rmse_of "$image" "$reference")" >>"$rmses"
  fi
}
declare -A ref_cpu
for s in $scenes; do
  log "$s: sfrender reference, $ref_spp spp"
  ref_cpu[$s.sf]=$(run_sf "$s" "$s-sf-ref.ppm" --spp "$ref_spp")
  log "$s: POV-Ray reference, $pov_ref"
  # shellcheck disable=SC2086 # the settings are several words
  ref_cpu[$s.pov]=$(run_pov "$s" "$s-pov-ref.ppm" $pov_ref)
done
for round in $(seq 1 "$runs"); do
  for s in $scenes; do
    for spp in $spps; do
      point "$round" "$s" sfrender "--spp_$spp" "$s-sf.ppm" "$s-sf-ref.ppm" run_sf --spp "$spp"
    done
    if [[ $has_adaptive == yes ]]; then
      for p in $adaptive_points; do
        point "$round" "$s" sfrender-adaptive "--adaptive_${p%%:*}_--spp_${p##*:}" "$s-sf.ppm" \
          "$s-sf-ref.ppm" run_sf --adaptive "${p%%:*}" --spp "${p##*:}"
      done
    fi
    for p in $pov_points; do
      IFS=: read -r a am r <<<"$p"
      point "$round" "$s" povray "+A${a}_+AM${am}_+R${r}" "$s-pov.ppm" "$s-pov-ref.ppm" run_pov \
        "+A$a" "+AM$am" "+R$r"
    done
    log "round $round of $runs, $s: done ($(($(date +%s) - start)) s so far)"
  done
done
# The data file: each point's median CPU time, its RMSE and its runs' range.
{
  echo "# scene renderer settings cpu_s rmse cpu_min cpu_max   (settings with '_' for spaces; cpu_s the median of $runs runs; RMSE against the renderer's own reference)"
  while read -r s who settings e; do
    awk -v key="$s $who $settings" -v e="$e" '
      $1 " " $2 " " $3 == key { n++; t[n] = $4 }
      END {
        for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (t[j] < t[i]) { x = t[i]; t[i] = t[j]; t[j] = x }
        median = n % 2 ? t[(n + 1) / 2] : (t[n / 2] + t[n / 2 + 1]) / 2
        print key, median, e, t[1], t[n]
      }' "$times"
  done <"$rmses"
} >"$dat"
cp "$dat" "$plots/equal-error.dat"
load_end=$(cut -d ' ' -f 1-3 /proc/loadavg 2>/dev/null || echo unknown)

# sf_cpu_at SCENE E: sfrender's CPU time for RMSE E, on the lower envelope of
# its points (uniform and adaptive: for each point, none both faster and
# more accurate), interpolated linearly in log(time) against log(RMSE)
# between the two envelope points whose errors bracket E; outside them, the
# nearest segment extended, and the answer marked "extrapolated".
sf_cpu_at() {
  awk -v scene="$1" -v target="$2" '
    $1 == scene && $2 ~ /^sfrender/ && $5 > 0 { n++; c[n] = $4 > 0 ? $4 : 0.005; e[n] = $5 }
    END {
      # The envelope: sorted by time, keep a point only if its error is below
      # every faster one.
      for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (c[j] < c[i]) {
        t = c[i]; c[i] = c[j]; c[j] = t; t = e[i]; e[i] = e[j]; e[j] = t }
      m = 0; best = 1e300
      for (i = 1; i <= n; i++) if (e[i] < best) { m++; C[m] = c[i]; E[m] = e[i]; best = e[i] }
      if (m == 0) { print "nan none"; exit }
      if (m == 1) { print C[1], "single"; exit }
      k = 0
      for (i = 1; i < m; i++) if (E[i] >= target && target >= E[i + 1]) { k = i; break }
      how = "interpolated"
      if (k == 0) { how = "extrapolated"; k = (target > E[1]) ? 1 : m - 1 }
      lc = log(C[k]) + (log(target) - log(E[k])) * (log(C[k + 1]) - log(C[k])) / (log(E[k + 1]) - log(E[k]))
      printf "%.4g %s\n", exp(lc), how
    }' "$dat"
}

# --- The plot -------------------------------------------------------------------
count=$(wc -w <<<"$scenes")
{
  echo "set terminal pngcairo size $((480 * count)),520 font 'DejaVu Sans,10'"
  echo "set output '$plots/equal-error.png'"
  echo "set multiplot layout 1,$count title 'RMSE against each renderer''s own converged image vs CPU time, ${width}x${height}, $threads threads'"
  echo "set termoption noenhanced; set logscale xy 10; set grid; set key bottom left font ',8'"
  echo "set xlabel 'CPU time, s (user + system)'; set ylabel 'RMSE (values 0 to 1)'"
  for s in $scenes; do
    echo "set title '$s'"
    echo "plot '$dat' using (strcol(1) eq '$s' && strcol(2) eq 'sfrender' ? \$4 : 1/0):5 with linespoints lw 2 pt 7 title 'sfrender --spp ${spps// /,}', \\"
    echo "  '' using (strcol(1) eq '$s' && strcol(2) eq 'sfrender-adaptive' ? \$4 : 1/0):5 with points pt 9 ps 1.5 title 'sfrender --adaptive', \\"
    echo "  '' using (strcol(1) eq '$s' && strcol(2) eq 'povray' ? \$4 : 1/0):5 with points pt 5 ps 1.2 lc rgb 'black' title 'POV-Ray +A +AM +R (table)', \\"
    echo "  '' using (strcol(1) eq '$s' && strcol(3) eq '+A0.3_+AM2_+R3' ? \$4 : 1/0):5:('+A0.3 +AM2 +R3') with labels offset 0,-0.9 font ',8' notitle"
  done
  echo "unset multiplot"
} >"$work/plot.gp"
gnuplot "$work/plot.gp" || die "gnuplot failed"

# --- The section ------------------------------------------------------------------
machine="$(nproc) logical CPUs, CPU \"$(cpu_model)\", $(memory_total) of memory, Linux $(uname -r),
$(compiler_of "$build"), ${build_type:-unknown} build of commit $commit;
$(povray_version) from Debian"
section=$work/equal-error.md
{
  echo '<!-- BEGIN equal-error: written by bench/equal_error.sh; edits here are lost -->'
  echo "## Equal error"
  echo
  echo "Measured on $(date -u +%Y-%m-%d) with \`bash bench/equal_error.sh\`: $machine. Load" \
    "average $load_start at the start, $load_end at the end; the whole run took" \
    "$(($(date +%s) - start)) s."
  echo
  echo "What does each renderer pay, in CPU time (user + system from \`/usr/bin/time\`, the" \
    "whole process: start, parse, render, write), for a given error? Each renders each scene at" \
    "${width}x${height} on $threads threads at several settings, and each image is compared with" \
    "the same renderer's own converged image (\`render_probe compare\`, OpenImageIO: RMSE over" \
    "all pixels and channels of the 8-bit images as values 0 to 1), so the error is what the" \
    "setting leaves out, not a difference between the two renderers' models. sfrender's" \
    "reference is \`--spp $ref_spp\`; POV-Ray's is \`$pov_ref\`, through \`sfconvert --to pov" \
    "--width $width --height $height --fov 60\`. sfrender's points: \`--spp\` $spps$(
      [[ $has_adaptive == yes ]] && echo " and \`--adaptive T --spp N\` at T:N = $adaptive_points" ||
        echo " (its \`--help\` listed no \`--adaptive\`, so no adaptive points)")." \
    "POV-Ray's: \`+A\` threshold, \`+AM\` method, \`+R\` depth at A:AM:R = $pov_points. Each" \
    "point ran $runs times, in rounds (every point once a round), and its CPU time is the median" \
    "of its runs (the data file has each point's fastest and slowest run too); the references ran" \
    "once. Data: \`docs/perf/equal-error.dat\`."
  echo
  echo "*sfrender at this RMSE* is the CPU time sfrender needs for a POV-Ray point's RMSE: on" \
    "the lower envelope of sfrender's points (those that no other point beats on both time and" \
    "error), linear in log(time) against log(RMSE) between the two points whose errors bracket" \
    "it; beyond the envelope's ends, its nearest segment extended (marked *extrapolated*)."
  echo
  echo "![Error against CPU time](equal-error.png)"
  echo
  for s in $scenes; do
    echo "### $s"
    echo
    echo "References: sfrender \`--spp $ref_spp\` $(fmt 1 "${ref_cpu[$s.sf]}") s of CPU," \
      "POV-Ray \`$pov_ref\` $(fmt 1 "${ref_cpu[$s.pov]}") s."
    echo
    echo "| renderer | settings | CPU time (median; fastest to slowest run) | RMSE | PSNR | sfrender at this RMSE | POV-Ray / sfrender |"
    echo "|---|---|---|---|---|---|---|"
    while read -r scene who settings cpu e lo hi; do
      [[ $scene == "$s" ]] || continue
      psnr=$(awk -v e="$e" 'BEGIN { if (e > 0) printf "%.1f dB", 20 * log(1 / e) / log(10); else print "exact" }')
      if [[ $who == povray ]]; then
        read -r at how < <(sf_cpu_at "$s" "$e")
        ratio=$(awk -v p="$cpu" -v q="$at" 'BEGIN { if (q > 0) printf "%.2f×", p / q; else print "—" }')
        [[ $how == interpolated ]] || ratio="$ratio ($how)"
        echo "| POV-Ray | \`${settings//_/ }\` | $(fmt 2 "$cpu") s ($(fmt 2 "$lo") to $(fmt 2 "$hi")) | $(fmt 5 "$e") | $psnr | $(fmt 2 "$at") s | $ratio |"
      else
        echo "| $who | \`${settings//_/ }\` | $(fmt 2 "$cpu") s ($(fmt 2 "$lo") to $(fmt 2 "$hi")) | $(fmt 5 "$e") | $psnr | | |"
      fi
    done < <(grep -v '^#' "$dat")
    e=$(awk -v s="$s" '$1 == s && $2 == "povray" && $3 == "+A0.3_+AM2_+R3" { print $5 }' "$dat")
    cpu=$(awk -v s="$s" '$1 == s && $2 == "povray" && $3 == "+A0.3_+AM2_+R3" { print $4 }' "$dat")
    echo
    if [[ -n $e ]]; then
      read -r at how < <(sf_cpu_at "$s" "$e")
      echo "**POV-Ray \`+A0.3 +AM2 +R3\` reaches RMSE $(fmt 5 "$e") in $(fmt 2 "$cpu") s of CPU;" \
        "sfrender needs $(fmt 2 "$at") s for the same RMSE ($how): POV-Ray / sfrender =" \
        "$(awk -v p="$cpu" -v q="$at" 'BEGIN { printf "%.2f", (q > 0 ? p / q : 0) }').**"
    else
      echo "(\`+A0.3 +AM2 +R3\` was not among EQ_POV_POINTS.)"
    fi
    echo
  done
  echo '<!-- END equal-error -->'
} >"$section"
replace_section equal-error "$section"
log "done in $(($(date +%s) - start)) s; wrote ${doc#"$root"/}, docs/perf/equal-error.png and .dat"
