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
# The flags of the image go to the merge: --bits and --no-clobber to it
# alone (the tiles stay 32-bit float EXR), -q and -v to both (the tiles are
# quiet unless -v). The merge checks them itself before anything is
# submitted. Refused before submitting (exit 2): --alpha (the merge puts
# RGB together); --tile, --region, --merge and a second -o, which are the
# script's to give; an -o pattern ({stem}): one image is merged.
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

refuse() {
  echo "$0: error: $*" >&2
  exit 2
}

scene='' output='' tiles='' work='' sfrender=sfrender verbosity=''
sbatch_args=() flags=() merge_flags=()
while (($#)); do
  case $1 in
    -o | --output | --output=*)
      [[ -z $output ]] || refuse "-o given twice"
      if [[ $1 == --output=* ]]; then output=${1#*=}; shift; else output=${2:?}; shift 2; fi ;;
    --tiles) tiles=${2:?}; shift 2 ;;
    --bits) merge_flags+=(--bits "${2:?}"); shift 2 ;;
    --bits=* | --no-clobber) merge_flags+=("$1"); shift ;;
    -q | --quiet | -v | --verbose)
      given=-v
      [[ $1 == -q || $1 == --quiet ]] && given=-q
      [[ -z $verbosity || $verbosity == "$given" ]] || refuse "-q and -v exclude each other"
      verbosity=$given; shift ;;
    --alpha) refuse "--alpha cannot be merged (the merge puts RGB tiles together); render an" \
      "image with alpha in one piece" ;;
    --tile | --tile=* | --region | --region=* | --merge)
      refuse "${1%%=*} is for the script to give: it renders the tiles and merges them" ;;
    --work) work=${2:?}; shift 2 ;;
    --sfrender) sfrender=${2:?}; shift 2 ;;
    --sbatch) sbatch_args+=("${2:?}"); shift 2 ;;
    -h | --help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    -*) flags+=("$1"); shift ;;
    *) if [[ -z $scene ]]; then scene=$1; else flags+=("$1"); fi; shift ;;
  esac
done
[[ -n $scene && -n $output && $tiles =~ ^[1-9][0-9]*$ ]] || usage
[[ $output != *'{'*'}'* ]] || refuse "-o names the one image; a pattern ('$output') is for sfbatch.sh"
[[ -f $scene ]] || { echo "$0: error: '$scene' is not a file" >&2; exit 3; }
sfrender=$(command -v "$sfrender") || { echo "$0: error: no sfrender to run" >&2; exit 3; }
scene=$(realpath "$scene")
output=$(realpath -m "$output")
work=$(realpath -m "${work:-$output.tiles}")
# The tiles' logs hold their errors only, unless -v.
if [[ -n $verbosity ]]; then merge_flags+=("$verbosity"); fi
if [[ $verbosity == -v ]]; then flags+=(-v); else flags+=(--quiet); fi
# The merge's own checks of its flags and output, run now on a tile that is
# not there: a usage error (exit 2) there would fail the merge after every
# tile was rendered. It reads nothing and writes nothing.
status=0
check=$("$sfrender" --merge "$work/.no-tile.exr" -o "$output" "${merge_flags[@]}" 2>&1) || status=$?
((status != 2)) || { printf '%s\n' "$check" >&2; exit 2; }
if [[ " ${merge_flags[*]} " == *" --no-clobber "* ]] && [[ -e $output || -L $output ]]; then
  echo "$0: error: '$output' exists, and --no-clobber keeps it" >&2
  exit 3
fi
mkdir -p "$work"
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

array=$(sbatch --parsable --requeue --open-mode=append --array="0-$((tiles - 1))" --job-name=sfrender-tile \
  --output="$work/tile-%a.log" --export="ALL,SFSLURM_DIR=$here" "${sbatch_args[@]}" \
  "$here/tile-task.sh" "$sfrender" "$tiles" "$work" "$scene" "${flags[@]}")
array=${array%%;*}
merge=$(sbatch --parsable --dependency="afterok:$array" --kill-on-invalid-dep=yes \
  --job-name=sfrender-merge --output="$work/merge.log" "${sbatch_args[@]}" \
  "$here/merge-task.sh" "$sfrender" "$tiles" "$work" "$output" "${merge_flags[@]}")
merge=${merge%%;*}
echo "tiles=$array merge=$merge"
