#!/usr/bin/env bash
# Two experiments on sfrender's tracing: bash bench/tracers.sh [BUILD_DIR]
# (also `make bench`, and render_suite.sh's parts `embree` and `float`).
#
# 1. embree: bench/embree_trace (built when CMake finds Embree 3) traces the
#    primary rays of 1920x1080 pixel centres on floor scenes of 1,000,
#    100,000 and 1,000,000 objects, and the shadow rays from their hits toward
#    each light, with Embree's user geometry (the renderer's own object test
#    in its callbacks) one ray at a time and in packets of 4 and 8, and with
#    sfrender's own camera path (render::traceCameraRays: eye grid, packets),
#    primary rays both as ids only and with each hit made in full,
#    and render::Tracer::shadowed (light grids), on 1 and 2 threads; section
#    "Against Embree" of docs/perf/RESULTS.md.
# 2. float: bench/float_trace, a single-precision tracer of primary and
#    shadow rays against the double renderer: time per ray on floor-1000,
#    exact ids, self-intersection, acne and RMSE there and on the hard scenes
#    of the accuracy tests; section "Single precision".
#
# Environment: TRACERS_PARTS ("embree float"), TRACERS_SIZES ("1000 100000
# 1000000"), TRACERS_RUNS (3, median), TRACERS_WIDTH (1920), TRACERS_HEIGHT
# (1080), TRACERS_DIR (the scenes; /tmp/scenefile-render-suite, shared with
# render_suite.sh, never inside the repository).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-build}
[[ $build = /* ]] || build=$PWD/$build
bin=$build/bin
parts=${TRACERS_PARTS:-embree float}
sizes=${TRACERS_SIZES:-1000 100000 1000000}
runs=${TRACERS_RUNS:-3}
width=${TRACERS_WIDTH:-1920}
height=${TRACERS_HEIGHT:-1080}
data=${TRACERS_DIR:-/tmp/scenefile-render-suite}
doc=$root/docs/perf/RESULTS.md

die() {
  echo "tracers: $*" >&2
  exit 1
}
log() { echo "tracers: $(date -u +%H:%M:%S) $*" >&2; }
source "$root/bench/common.sh"

[[ -x $bin/sfgen ]] || die "$bin/sfgen is missing: build first (cmake --build $build)"
[[ -f $doc ]] || die "$doc is missing: run bench/run.sh first, which writes its introduction"
mkdir -p "$data"
data=$(cd "$data" && pwd -P)
case "$data/" in
  "$(cd "$root" && pwd -P)"/*) die "TRACERS_DIR $data is inside the repository" ;;
esac
warn_unless_release "$build"
has_part() { [[ " $parts " == *" $1 "* ]]; }
load() { cut -d ' ' -f 1-3 /proc/loadavg 2>/dev/null || echo unknown; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
machine="$(nproc) logical CPUs, CPU \"$(cpu_model)\", $(memory_total) of memory, Linux $(uname -r),
$(compiler_of "$build"), ${build_type:-unknown} build of commit $(short_commit "$root")"

# floor N: the path of floor-N.sf, generated as render_suite.sh does (16:9).
floor() {
  local f=$data/floor-$1.sf
  if [[ ! -f $f || $bin/sfgen -nt $f ]]; then
    log "generating floor-$1"
    "$bin/sfgen" --layout floor -n "$1" -s 1 --aspect "$(awk -v w="$width" -v h="$height" \
      'BEGIN { printf "%.17g", w / h }')" -o "$f" >/dev/null
  fi
  echo "$f"
}

# === 1. Against Embree ========================================================
if has_part embree; then
  if [[ ! -x $bin/embree_trace ]]; then
    log "skipping embree: $bin/embree_trace is not built (install libembree-dev and reconfigure)"
  else
    load_start=$(load)
    for n in $sizes; do
      f=$(floor "$n")
      log "embree: floor-$n"
      "$bin/embree_trace" "$f" --width "$width" --height "$height" --runs "$runs" \
        >"$work/embree-$n.txt" || die "embree_trace failed on floor-$n"
    done
    load_end=$(load)
    embree_version=$(dpkg-query -W -f '${Version}' libembree-dev 2>/dev/null || echo unknown)
    section=$work/embree.md
    {
      echo '<!-- BEGIN tracers-embree: written by bench/tracers.sh; edits here are lost -->'
      echo "## Against Embree"
      echo
      echo "Measured on $(date -u +%Y-%m-%d) with \`bash bench/tracers.sh\` (part \`embree\`): $machine;" \
        "Embree $embree_version from Debian. Load average $load_start at the start, $load_end at the end."
      echo
      echo "\`bench/embree_trace floor-N.sf\` traces the primary rays of a ${width}x${height} image" \
        "(render::PinholeCamera through the pixel centres) of \`sfgen --layout floor -n N -s 1\`," \
        "and the shadow rays from their hits toward each light, in one process: sfrender's own" \
        "camera path (\`render::traceCameraRays\`: the camera's rays, the eye's direction grid" \
        "where it pays, packets of 4 down its BVH, tiles in turn; each hit made in full, point," \
        "error bound and normal) and shadow rays (\`render::Tracer::shadowed\`: the lights' grids," \
        "\`shadowCell\`, the occluder hint), against Embree 3 one ray at a time (\`rtcIntersect1\`," \
        "\`rtcOccluded1\`) and in packets of 4 and 8 (2x2 and 4x2 pixels; shadow rays of" \
        "consecutive hits of a tile's row). Embree gets one user geometry whose boxes are the" \
        "objects' world bounds (widened by 4 float steps, as its boxes and rays are float) and" \
        "whose callbacks run the renderer's exact double-precision test of the object (with the" \
        "shadow ray's source, as sfrender's); planes are tested before Embree is called, as" \
        "sfrender tests its planes first. *Hits*: each tracer makes every pixel's hit in full" \
        "inside its pass, Embree's by the renderer's own code (\`RenderScene::hitsOnObjects\`) on" \
        "the closest object it found, as a renderer built on Embree would; *ids*: Embree's" \
        "callbacks find distances and ids only, sfrender's camera path still makes its hits." \
        "Mrays/s = rays over the wall time of the pass, median of" \
        "$runs, the variants taking turns in each run; *1 thread, CPU*: over the thread's CPU" \
        "time instead, which other work on the machine moves less. *differing*: pixels whose" \
        "object id differs from \`render::renderObjectIds\` (one ray at a time), hits not" \
        "bit for bit sfrender's, and shadow rays whose answer differs from sfrender's."
      echo
      echo "| objects | eye grid | primary hits: sfrender | Embree 1 / 4 / 8 | sfrender / Embree 8 | 1 thread, CPU | differing |"
      echo "|---|---|---|---|---|---|---|"
      for n in $sizes; do
        t=$work/embree-$n.txt
        ratio() { fmt 2 "$(awk -v a="$(value "$1" "$t")" -v b="$(value "$2" "$t")" 'BEGIN { print a / b }')"; }
        row="| $(thousands "$n") | $([[ $(value sfrender_eye_grid "$t") = 1 ]] && echo yes || echo no) |"
        row+=" $(fmt 2 "$(value sfrender_hits_2t_mrays "$t")") |"
        row+=" $(fmt 2 "$(value embree1_hits_2t_mrays "$t")") / $(fmt 2 "$(value embree4_hits_2t_mrays "$t")") / $(fmt 2 "$(value embree8_hits_2t_mrays "$t")") |"
        row+=" **$(ratio sfrender_hits_2t_mrays embree8_hits_2t_mrays)x** |"
        row+=" $(ratio sfrender_hits_1t_cpu_mrays embree8_hits_1t_cpu_mrays)x |"
        diffs=0
        for v in sfrender_hits sfrender_packets_hits embree1_hits embree4_hits embree8_hits; do
          d=$(value ${v}_differences "$t")
          diffs=$((diffs + ${d:-0}))
        done
        echo "$row $diffs |"
      done
      echo
      echo "| objects | eye grid | primary ids: sfrender | Embree 1 / 4 / 8 | sfrender / Embree 8 | 1 thread, CPU | shadow: sfrender | Embree 1 / 4 / 8 | sfrender / Embree 8 | 1 thread, CPU | differing |"
      echo "|---|---|---|---|---|---|---|---|---|---|---|"
      total_diffs=0
      for n in $sizes; do
        t=$work/embree-$n.txt
        ratio() { fmt 2 "$(awk -v a="$(value "$1" "$t")" -v b="$(value "$2" "$t")" 'BEGIN { print a / b }')"; }
        row="| $(thousands "$n") | $([[ $(value sfrender_eye_grid "$t") = 1 ]] && echo yes || echo no) |"
        for kind in "" _shadow; do
          row+=" $(fmt 2 "$(value sfrender${kind}_2t_mrays "$t")") |"
          row+=" $(fmt 2 "$(value embree1${kind}_2t_mrays "$t")") / $(fmt 2 "$(value embree4${kind}_2t_mrays "$t")") / $(fmt 2 "$(value embree8${kind}_2t_mrays "$t")") |"
          row+=" **$(ratio sfrender${kind}_2t_mrays embree8${kind}_2t_mrays)x** |"
          row+=" $(ratio sfrender${kind}_1t_cpu_mrays embree8${kind}_1t_cpu_mrays)x |"
        done
        diffs=0
        for v in sfrender sfrender_packets embree1 embree4 embree8 sfrender_hits sfrender_packets_hits embree1_hits embree4_hits embree8_hits sfrender_shadow embree1_shadow embree4_shadow embree8_shadow; do
          d=$(value ${v}_differences "$t")
          diffs=$((diffs + ${d:-0}))
        done
        echo "$row $diffs |"
        total_diffs=$((total_diffs + diffs))
      done
      echo
      if ((total_diffs == 0)); then
        echo "Every primary ray found the same object and the same hit to the bit, and every shadow ray the same answer, in every tracer."
      else
        echo "**$total_diffs rays differ** between the tracers (column *differing*)."
      fi
      echo
      echo "Mrays/s on 2 threads (10^6 rays a second); the ratios are sfrender's over Embree's" \
        "8-wide packets'. BVH build, after parsing, not in the figures: sfrender's whole" \
        "\`render::RenderScene\` against Embree's scene build, $(for n in $sizes; do
          t=$work/embree-$n.txt
          printf '%s s / %s s at %s; ' "$(fmt 3 "$(value sfrender_build_s "$t")")" \
            "$(fmt 3 "$(value embree_build_s "$t")")" "$(thousands "$n")"
        done)the eye's grid is built inside sfrender's timed pass. The machine is shared: 2" \
        "threads may gain less than 2x for either."
      echo
      echo "Raw output:"
      echo
      echo '```'
      for n in $sizes; do
        echo "floor-$n:"
        sed -n '/^primary/,$p' "$work/embree-$n.txt"
      done
      echo '```'
      echo '<!-- END tracers-embree -->'
    } >"$section"
    replace_section tracers-embree "$section"
    grep -q '^Every primary ray' "$section" || log "warning: the tracers differ on some rays (see the section)"
    log "wrote the section Against Embree"
  fi
fi

# === 2. Single precision =======================================================
if has_part float; then
  [[ -x $bin/float_trace ]] || die "$bin/float_trace is missing: build it (it needs the tests' targets)"
  f=$(floor 1000)
  load_start=$(load)
  log "float: floor-1000, $runs runs"
  "$bin/float_trace" scene "$f" --width "$width" --height "$height" --runs "$runs" \
    >"$work/float-floor.txt" || die "float_trace scene failed"
  # Instructions of one pass of each tracer (callgrind, counting inside the
  # pass only), at a quarter of the width and height: a figure the other
  # work on a shared machine does not move.
  : >"$work/float-instructions.txt"
  if command -v valgrind >/dev/null 2>&1; then
    for x in double float_fixed float_bound; do
      log "float: instructions of $x"
      valgrind --tool=callgrind --callgrind-out-file="$work/cg.$x" --toggle-collect='*traceDouble*' \
        --toggle-collect='*traceFloat*' "$bin/float_trace" scene "$f" --only "$x" \
        --width $((width / 4)) --height $((height / 4)) >"$work/cg-$x.txt" 2>"$work/cg-$x.log" ||
        die "callgrind on float_trace failed: $(tail -n 3 "$work/cg-$x.log")"
      echo "$x $(sed -n 's/.*Collected : \([0-9]*\).*/\1/p' "$work/cg-$x.log") $(value ${x}_rays "$work/cg-$x.txt")" \
        >>"$work/float-instructions.txt"
    done
  fi
  log "float: the hard scenes"
  "$bin/float_trace" hard >"$work/float-hard.txt" || die "float_trace hard failed"
  load_end=$(load)
  t=$work/float-floor.txt
  # Per hard scene and tracer: ids differing, self-shadowed / lit points,
  # drawn dark / must be lit, drawn lit / must be dark, RMSE.
  awk -F': ' '
    /^scene: / { scene = $2; next }
    { split($1, k, "_"); tracer = k[1]; if (k[1] == "float") tracer = k[1] "_" k[2]
      key = substr($1, length(tracer) + 2); v[scene, tracer, key] = $2
      if (!(scene in seen)) { seen[scene] = 1; order[++n] = scene } }
    END {
      for (i = 1; i <= n; i++) {
        s = order[i]; row = "| " s " |"
        split("double float_fixed float_bound", tr, " ")
        for (j = 1; j <= 3; j++) {
          x = tr[j]
          self = (x == "double") ? "0 (excluded)" : v[s, x, "self_shadowed"] "/" v[s, x, "lit_points"]
          row = row sprintf(" %s; %s; %s/%s; %s/%s; %.4f |", v[s, x, "ids_differing"], self,
            v[s, x, "drawn_dark"], v[s, x, "must_be_lit"], v[s, x, "drawn_lit"], v[s, x, "must_be_dark"],
            v[s, x, "rmse"])
        }
        print row
      }
    }' "$work/float-hard.txt" >"$work/float-hard.md"
  ins_saving=""
  float_errors=$(awk -F': ' '/^float_(fixed|bound)_(ids_differing|drawn_dark|drawn_lit|self_shadowed): / { s += $2 } END { print s + 0 }' "$work/float-hard.txt")
  double_errors=$(awk -F': ' '/^double_(ids_differing|drawn_dark|drawn_lit): / { s += $2 } END { print s + 0 }' "$work/float-hard.txt")
  gain_fixed=$(awk -v a="$(value double_ns_per_ray "$t")" -v b="$(value float_fixed_ns_per_ray "$t")" 'BEGIN { printf "%.2f", a / b }')
  gain_bound=$(awk -v a="$(value double_ns_per_ray "$t")" -v b="$(value float_bound_ns_per_ray "$t")" 'BEGIN { printf "%.2f", a / b }')
  section=$work/float.md
  {
    echo '<!-- BEGIN tracers-float: written by bench/tracers.sh; edits here are lost -->'
    echo "## Single precision"
    echo
    echo "Measured on $(date -u +%Y-%m-%d) with \`bash bench/tracers.sh\` (part \`float\`): $machine." \
      "Load average $load_start at the start, $load_end at the end."
    echo
    echo "Would sfrender be faster in float, and what would it cost? \`bench/float_trace\` (with" \
      "\`bench/float_tracer.h\`) traces primary rays and their shadow rays with direct Phong" \
      "lighting (docs/RENDERING.md: ambient per light, diffuse and specular for each light with a" \
      "clear path; no reflection or refraction) in single precision: the ray goes to object space" \
      "with float matrices, meets the unit shape with the same formulas as" \
      "\`renderer/unit_shapes.h\` in float, the hit point is the float o + t d, and a shadow ray" \
      "is not told which object it left but starts off the surface by an offset along the normal:" \
      "*float, fixed*: 1e-4 world units, as float tracers usually do; *float, bound*: a float" \
      "error bound, 32 float steps of the larger of |o| and |t d|. The search is sfrender's own" \
      "BVH in both (its boxes are float already), so what differs is the object tests, hit" \
      "points, normals, offsets and shading. *double* is sfrender: \`RenderScene::closestHit\`" \
      "and \`Tracer::shadeSurface\` (its error-bounded offsets, and shadow rays that cannot meet" \
      "the surface they leave). One thread, the same pixel centres."
    echo
    echo "### Speed: floor-1000, ${width}x${height}"
    echo
    echo "Median of $runs passes each, alternating. A ray is a primary or a shadow ray."
    echo
    echo "| tracer | pass | per primary ray (with its shadow rays) | per ray | shadow rays | ids differing from renderObjectIds | lit points meeting their own object | RMSE against double |"
    echo "|---|---|---|---|---|---|---|---|"
    for x in double float_fixed float_bound; do
      self="$(value ${x}_self_shadowed "$t")/$(value ${x}_lit_points "$t")"
      [[ $x == double ]] && self="0 (excluded by construction)"
      echo "| ${x/_/, } | $(fmt 3 "$(value ${x}_seconds "$t")") s | $(fmt 1 "$(value ${x}_ns_per_primary "$t")") ns |" \
        "$(fmt 1 "$(value ${x}_ns_per_ray "$t")") ns | $(thousands "$(value ${x}_shadow_rays "$t")") |" \
        "$(value ${x}_ids_differing "$t") of $(thousands "$(value ${x}_pixels "$t")") | $self |" \
        "$(fmt 5 "$(value ${x}_rmse "$t")") |"
    done
    echo
    echo "Per ray, double took ${gain_fixed}× the time of float with the fixed offset and" \
      "${gain_bound}× that of float with the error bound (wall time on a shared machine: a few" \
      "percent either way is noise)."
    if [[ -s $work/float-instructions.txt ]]; then
      echo
      echo "Instructions, which other work does not move: one pass of each tracer alone at" \
        "$((width / 4))x$((height / 4)) (\`float_trace scene --only\`), counted by \`valgrind" \
        "--tool=callgrind\` inside the pass only:"
      echo
      echo "| tracer | instructions | per ray | against double |"
      echo "|---|---|---|---|"
      base=$(awk '$1 == "double" { print $2 }' "$work/float-instructions.txt")
      while read -r x ins rays; do
        echo "| ${x/_/, } | $(thousands "$ins") | $(fmt 0 "$(awk -v i="$ins" -v r="$rays" 'BEGIN { print i / r }')") |" \
          "$(fmt 3 "$(awk -v i="$ins" -v b="$base" 'BEGIN { print i / b }')") |"
      done <"$work/float-instructions.txt"
      ins_saving=$(awk '$1 == "double" { b = $2 } $1 != "double" { if (!m || $2 < m) m = $2 } END { printf "%.0f%%", (1 - m / b) * 100 }' "$work/float-instructions.txt")
    fi
    echo
    echo "### Accuracy: the hard scenes, 160x120"
    echo
    echo "The acne scene of docs/ACCURACY.md (a plane, a sphere, a cube and two cylinders, one" \
      "light) at each of its layouts: scaled by 1e-6 to 1e6 about the origin, and at scale 1 and" \
      "1e-3 moved (1e6, 1e6, 1e6) away (tiny objects far from the origin); and the grazing scene" \
      "of tests/geometry (the eye 0.01 above a long box and cylinder, looking along them), lit" \
      "from low behind the eye. Each cell: ids differing from \`renderObjectIds\` (the exact" \
      "reference); lit points whose shadow ray meets their own object; acne by the accuracy" \
      "tests' judge (\`acne::evaluate\`: pixels that must be lit drawn at ambient level, of those" \
      "that must be lit); light leaks (pixels that must be dark drawn lit, of those that must be" \
      "dark); RMSE of the image against double's (channels clamped to [0, 1])."
    echo
    echo "| scene | double | float, fixed 1e-4 | float, error bound |"
    echo "|---|---|---|---|"
    cat "$work/float-hard.md"
    echo
    echo "### The decision"
    echo
    ins_phrase=""
    [[ -n $ins_saving ]] && ins_phrase=" and at most $ins_saving of the instructions"
    if [[ $float_errors -gt 0 && $double_errors -eq 0 ]]; then
      echo "**Double stays the default.** Float saves $(awk -v g="$gain_fixed" -v h="$gain_bound" \
        'BEGIN { a = (1 - 1 / g) * 100; b = (1 - 1 / h) * 100; printf "%.0f%% to %.0f%%", (a < b ? a : b), (a < b ? b : a) }')" \
        "of the time per ray on the floor scene (a negative figure: it costs more)${ins_phrase}, where its" \
        "object ids are $(value float_fixed_ids_differing "$t") and $(value float_bound_ids_differing "$t")" \
        "pixels off. On the hard scenes, summed over them, the two float tracers get $float_errors" \
        "object ids, self-intersections, acne pixels and light leaks wrong, where double gets" \
        "$double_errors: the rows above say where (a fixed offset fails with the scale one way or" \
        "the other, an error bound fails away from the origin, and far from it float cannot find" \
        "the right object at all). sfrender's contract (docs/RENDERING.md) is the exact reference" \
        "and no acne at every scale; a saving of this size does not pay for breaking it."
    elif [[ $float_errors -eq 0 ]]; then
      echo "**Float made no error on these scenes** (ids, self-intersections, acne, leaks), and" \
        "saves per ray: double takes ${gain_fixed}× / ${gain_bound}× its time. Double stays the" \
        "default until float passes the accuracy tests themselves; this table says it might."
    else
      echo "**Both tracers made errors on the hard scenes** (double: $double_errors, float:" \
        "$float_errors): see the table; double stays the default, as the renderer the accuracy" \
        "tests hold to the exact reference."
    fi
    echo '<!-- END tracers-float -->'
  } >"$section"
  replace_section tracers-float "$section"
  log "wrote the section Single precision"
fi
