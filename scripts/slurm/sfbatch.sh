#!/bin/bash
# Renders a list of scenes on a Slurm cluster as a job array (docs/SCALING.md):
#
#   scripts/slurm/sfbatch.sh LIST -o 'out/{stem}.png' [options] [SFRENDER FLAGS...]
#
# LIST holds one scene a line (CRLF line ends taken as LF, blank lines and
# lines starting with # skipped; relative paths from the folder this is run
# in: scene-list.sh). The array has --tasks tasks (default: one a scene,
# at most 1000); each renders its slice of the list with one sfrender, which
# goes on past a failed scene and exits non-zero if any failed, so that
# `sacct -j JOB` shows which slices had a failure and their logs say which
# scene. A task that dies of the machine's failure requeues itself
# (requeue.sh). Prints "batch=ARRAY_JOB_ID" on standard output.
#
# Options (before the sfrender flags):
#   --tasks T         array tasks (default: the scenes, at most 1000)
#   --logs DIR        the tasks' logs (default: sfbatch-logs)
#   --sfrender PATH   the sfrender to run (default: the one on PATH)
#   --sbatch ARG      one more argument for sbatch (repeatable)
# --merge and a second -o are refused before submitting (exit 2).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=scripts/slurm/scene-list.sh
source "$here/scene-list.sh"

usage() {
  echo "usage: $0 LIST -o PATTERN [--tasks T] [--logs DIR] [--sfrender PATH] [--sbatch ARG]..." \
    "[SFRENDER FLAGS...]" >&2
  exit 2
}

list='' pattern='' tasks='' logs=sfbatch-logs sfrender=sfrender
sbatch_args=() flags=()
while (($#)); do
  case $1 in
    -o | --output | --output=*)
      [[ -z $pattern ]] || { echo "$0: error: -o given twice" >&2; exit 2; }
      if [[ $1 == --output=* ]]; then pattern=${1#*=}; shift; else pattern=${2:?}; shift 2; fi ;;
    --merge) echo "$0: error: --merge is for sfrender-tiles.sh's tiles, not a list of scenes" >&2
      exit 2 ;;
    --tasks) tasks=${2:?}; shift 2 ;;
    --logs) logs=${2:?}; shift 2 ;;
    --sfrender) sfrender=${2:?}; shift 2 ;;
    --sbatch) sbatch_args+=("${2:?}"); shift 2 ;;
    -h | --help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    -*) flags+=("$1"); shift ;;
    *) if [[ -z $list ]]; then list=$1; else flags+=("$1"); fi; shift ;;
  esac
done
[[ -n $list && -n $pattern ]] || usage
[[ $pattern == *'{'* ]] || { echo "$0: error: -o needs a placeholder, as 'out/{stem}.png'" >&2; exit 2; }
[[ -f $list ]] || { echo "$0: error: '$list' is not a file" >&2; exit 3; }
sfrender=$(command -v "$sfrender") || { echo "$0: error: no sfrender to run" >&2; exit 3; }
count=$(read_scene_list "$list" | wc -l)
((count > 0)) || { echo "$0: error: '$list' names no scene" >&2; exit 1; }
tasks=${tasks:-$((count < 1000 ? count : 1000))}
[[ $tasks =~ ^[1-9][0-9]*$ ]] || usage
((tasks <= count)) || tasks=$count
list=$(realpath "$list")
mkdir -p "$logs"
# The images' folder, when the pattern names one (and not by placeholder).
[[ $(dirname "$pattern") == *'{'* ]] || mkdir -p "$(dirname "$pattern")"
logs=$(realpath "$logs")

batch=$(sbatch --parsable --requeue --open-mode=append --array="0-$((tasks - 1))" --job-name=sfbatch \
  --output="$logs/batch-%A-%a.log" --export="ALL,SFSLURM_DIR=$here" "${sbatch_args[@]}" \
  "$here/batch-task.sh" "$sfrender" "$list" "$tasks" "$pattern" "${flags[@]}")
echo "batch=${batch%%;*}"
