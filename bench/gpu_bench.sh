#!/usr/bin/env bash
# The GPU path's benchmark (docs/PERFORMANCE.md, "GPU (Vulkan)"), in one go:
# builds sfrender and sfgen (Release, SCENEFILE_VULKAN=ON) in build-gpu-bench,
# (sfgen is one of the benchmarks' tools), makes floor scenes of 100,000 and 1,000,000 objects (sfgen --layout floor
# -n N -s 1), and renders them and the default scene at 1920x1080, 1 spp, on
# the GPU (sfrender --device gpu --stats: device start, upload, kernel from
# Vulkan timestamp queries, readback) and on the CPU with 2 threads
# (GPU_BENCH_CPU_THREADS), printing a table and writing it to
# $OUT/gpu_bench.md when OUT is set.
#
# Needs no network: every package is Debian's (scripts/install-deps.sh); the
# script says what is missing and stops. Smaller runs, to check the script
# on a CPU driver (lavapipe): GPU_BENCH_WIDTH, GPU_BENCH_HEIGHT,
# GPU_BENCH_SIZES (object counts, "100000 1000000"), GPU_BENCH_CPU=0 to
# leave out the CPU runs, GPU_BENCH_CPU_THREADS (2: the CPU runs' --threads),
# GPU_BENCH_BUILD (the build directory). GPU_BENCH_CROSSOVER=1 adds the
# table `--device auto` is set from: whole runs of the default scene at
# GPU_BENCH_CROSSOVER_SIZES ("960x540 1280x720 1920x1080 3840x2160") and 1,
# 2 and 4 spp, on the GPU and on the CPU with 2 threads and every core,
# medians of 3 wall times, also written to $OUT/gpu_crossover.md.
# GPU_BENCH_BIN names a folder that already holds sfrender and sfgen (built
# with SCENEFILE_VULKAN=ON), for a GPU machine without the build tools: the
# build and its checks are skipped, and the scenes go to GPU_BENCH_BUILD.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
build=${GPU_BENCH_BUILD:-$root/build-gpu-bench}
width=${GPU_BENCH_WIDTH:-1920}
height=${GPU_BENCH_HEIGHT:-1080}
sizes=${GPU_BENCH_SIZES:-100000 1000000}
run_cpu=${GPU_BENCH_CPU:-1}
cpu_threads=${GPU_BENCH_CPU_THREADS:-2}
data=$build/gpu-bench-scenes

bin=${GPU_BENCH_BIN:-}
if [[ -n $bin ]]; then
  for tool in sfrender sfgen; do
    [[ -x $bin/$tool ]] || { echo "gpu_bench: GPU_BENCH_BIN=$bin holds no $tool" >&2; exit 1; }
  done
  bin=$(cd "$bin" && pwd)
else
  missing=()
  command -v cmake >/dev/null || missing+=("cmake (cmake)")
  command -v glslangValidator >/dev/null || missing+=("glslangValidator (glslang-tools)")
  [[ -f /usr/include/vulkan/vulkan.h ]] || missing+=("the Vulkan headers and loader (libvulkan-dev)")
  if ((${#missing[@]})); then
    echo "gpu_bench: missing: ${missing[*]}; apt-get install them (scripts/install-deps.sh)" >&2
    exit 1
  fi
  if command -v vulkaninfo >/dev/null; then
    vulkaninfo 2>/dev/null | grep -E 'deviceName|shaderFloat64' | sed 's/^[[:space:]]*/gpu_bench: /' |
      sort -u >&2 || true
  else
    echo "gpu_bench: vulkaninfo (vulkan-tools) is not installed; sfrender will say which device" >&2
  fi

  if [[ -f /root/.ccache.env ]]; then
    # shellcheck disable=SC1091
    source /root/.ccache.env
  fi
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSCENEFILE_VULKAN=ON \
    -DSCENEFILE_BUILD_TESTS=OFF -DSCENEFILE_BUILD_BENCH=ON -DSCENEFILE_BUILD_PYTHON=OFF \
    -DSCENEFILE_BUILD_DOCS=OFF >/dev/null
  cmake --build "$build" -j"$(nproc)" --target sfrender sfgen >/dev/null
  bin=$build/bin
fi

mkdir -p "$data"
scenes=(default)
for n in $sizes; do
  [[ -f $data/floor-$n.sf ]] ||
    "$bin/sfgen" --layout floor -n "$n" -s 1 --aspect "$(awk -v w="$width" -v h="$height" \
      'BEGIN { printf "%.17g", w / h }')" -o "$data/floor-$n.sf" >/dev/null
  scenes+=("floor-$n")
done

# render SCENE DEVICE: sfrender's --stats lines, and the wall time of the run.
render() {
  local input=() extra=()
  [[ $1 == default ]] || input=("$data/$1.sf")
  if [[ $2 == gpu ]]; then extra=(--device gpu); else extra=(--device cpu --threads "$cpu_threads"); fi
  local start end
  start=$(date +%s.%N)
  "$bin/sfrender" "${input[@]}" --width "$width" --height "$height" --spp 1 --depth 5 \
    "${extra[@]}" --stats -o "$data/$1-$2.png" 2>&1
  end=$(date +%s.%N)
  echo "wall $(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f", b - a }')"
}
field() { sed -n "s/.*$1 \([0-9.]*\) s.*/\1/p" | head -n 1; }

table=$(mktemp)
trap 'rm -f "$table"' EXIT
device=""
{
  echo "| scene | GPU start s | upload s | kernel s | readback s | GPU render s | GPU wall s | CPU ($cpu_threads threads) render s | CPU wall s |"
  echo "|---|---|---|---|---|---|---|---|---|"
} >"$table"
for scene in "${scenes[@]}"; do
  gpu=$(render "$scene" gpu) || {
    echo "gpu_bench: sfrender --device gpu failed:" >&2
    echo "$gpu" >&2
    exit 1
  }
  device=$(sed -n 's/^sfrender: device \(.*\): start.*/\1/p' <<<"$gpu")
  total=$(sed -n 's/.*depth 5: \([0-9.]*\) s,.*/\1/p' <<<"$gpu")
  cpu_total="-" cpu_wall="-"
  if [[ $run_cpu == 1 ]]; then
    cpu=$(render "$scene" cpu)
    cpu_total=$(sed -n 's/.*depth 5: \([0-9.]*\) s,.*/\1/p' <<<"$cpu")
    cpu_wall=$(sed -n 's/^wall //p' <<<"$cpu")
  fi
  echo "| $scene | $(field start <<<"$gpu") | $(field upload <<<"$gpu") | $(field kernel <<<"$gpu") | $(field readback <<<"$gpu") | $total | $(sed -n 's/^wall //p' <<<"$gpu") | $cpu_total | $cpu_wall |" >>"$table"
done

{
  echo "GPU benchmark: ${width}x${height}, 1 spp, depth 5; device: ${device:-unknown}; CPU: $(nproc) cores, $cpu_threads threads used"
  echo
  cat "$table"
} | if [[ -n ${OUT:-} ]]; then tee "$OUT/gpu_bench.md"; else cat; fi

# The crossover: where the GPU's whole run beats the CPU's.
if [[ ${GPU_BENCH_CROSSOVER:-0} == 1 ]]; then
  wall() {
    local start end
    start=$(date +%s.%N)
    "$bin/sfrender" "$@" -q -o "$data/crossover.ppm" || return 1
    end=$(date +%s.%N)
    awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f", b - a }'
  }
  median3() { printf '%s\n' "$@" | sort -n | sed -n 2p; }
  {
    echo "Crossover: the default scene, wall s of whole runs, medians of 3; CPU: $(nproc) cores"
    echo
    echo "| image | spp | GPU | CPU, 2 threads | CPU, every core |"
    echo "|---|---|---|---|---|"
    for size in ${GPU_BENCH_CROSSOVER_SIZES:-960x540 1280x720 1920x1080 3840x2160}; do
      for spp in 1 2 4; do
        row="| $size | $spp |"
        for device in "--device gpu" "--device cpu --threads 2" "--device cpu --threads 0"; do
          times=()
          for _ in 1 2 3; do
            # shellcheck disable=SC2086 # the device's words are meant to split
            times+=("$(wall --width "${size%x*}" --height "${size#*x}" --spp "$spp" $device)")
          done
          row="$row $(median3 "${times[@]}") |"
        done
        echo "$row"
      done
    done
  } | if [[ -n ${OUT:-} ]]; then tee "$OUT/gpu_crossover.md"; else cat; fi
fi
