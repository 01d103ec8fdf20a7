#!/bin/bash
# Renders one scene on a Slurm cluster as a job array of tiles, then merges
# them (docs/SCALING.md):
#
#   scripts/slurm/sfrender-tiles.sh SCENE -o OUT --tiles N [options] [SFRENDER FLAGS...]
#
# Task i of the array (sbatch --array=0-(N-1)) runs `sfrender SCENE --tile
# i/N -o WORK/tile-i.exr FLAGS...`; a task that dies of the machine's failure
# requeues itself (requeue.sh). A merge job that depends on the whole array
# (--dependency=afterok) runs `sfrender --merge WORK/tile-*.exr -o OUT`.
# Prints "tiles=ARRAY_JOB_ID merge=MERGE_JOB_ID" on standard output.
#
# Options (before the sfrender flags):
#   --work DIR        where the tiles and the logs go (default: OUT.tiles)
#   --sfrender PATH   the sfrender to run (default: the one on PATH)
#   --sbatch ARG      one more argument for both sbatch calls (repeatable:
#                     --sbatch --partition=render --sbatch --time=10)
# Every path must be visible from the compute nodes (a shared file system).
set -euo pipefail

usage() {
  echo "usage: $0 SCENE -o OUT --tiles N [--work DIR] [--sfrender PATH] [--sbatch ARG]..." \
    "[SFRENDER FLAGS...]" >&2
  exit 2
}

scene='' output='' tiles='' work='' sfrender=sfrender
sbatch_args=() flags=()
while (($#)); do
  case $1 in
    -o | --output) output=${2:?}; shift 2 ;;
    --tiles) tiles=${2:?}; shift 2 ;;
    --work) work=${2:?}; shift 2 ;;
    --sfrender) sfrender=${2:?}; shift 2 ;;
    --sbatch) sbatch_args+=("${2:?}"); shift 2 ;;
    -h | --help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    -*) flags+=("$1"); shift ;;
    *) if [[ -z $scene ]]; then scene=$1; else flags+=("$1"); fi; shift ;;
  esac
done
[[ -n $scene && -n $output && $tiles =~ ^[1-9][0-9]*$ ]] || usage
[[ -f $scene ]] || { echo "$0: error: '$scene' is not a file" >&2; exit 3; }
sfrender=$(command -v "$sfrender") || { echo "$0: error: no sfrender to run" >&2; exit 3; }
scene=$(realpath "$scene")
output=$(realpath -m "$output")
work=$(realpath -m "${work:-$output.tiles}")
mkdir -p "$work"
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

array=$(sbatch --parsable --requeue --open-mode=append --array="0-$((tiles - 1))" --job-name=sfrender-tile \
  --output="$work/tile-%a.log" --export="ALL,SFSLURM_DIR=$here" "${sbatch_args[@]}" \
  "$here/tile-task.sh" "$sfrender" "$tiles" "$work" "$scene" "${flags[@]}")
array=${array%%;*}
merge=$(sbatch --parsable --dependency="afterok:$array" --kill-on-invalid-dep=yes \
  --job-name=sfrender-merge --output="$work/merge.log" "${sbatch_args[@]}" \
  "$here/merge-task.sh" "$sfrender" "$tiles" "$work" "$output")
merge=${merge%%;*}
echo "tiles=$array merge=$merge"
