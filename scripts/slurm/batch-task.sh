#!/bin/bash
# One task of sfbatch.sh's array: its slice of the list of scenes (task k
# of T takes the scenes from k*n/T to (k+1)*n/T - 1, the n scenes in the
# list's order), rendered by one sfrender that goes on past a failed scene.
# Arguments: SFRENDER LIST TASKS PATTERN [SFRENDER FLAGS...]
set -u
sfrender=$1 list=$2 tasks=$3 pattern=$4
shift 4
# shellcheck source=scripts/slurm/requeue.sh
source "$SFSLURM_DIR/requeue.sh"
# shellcheck source=scripts/slurm/scene-list.sh
source "$SFSLURM_DIR/scene-list.sh"
mapfile -t scenes < <(read_scene_list "$list")
count=${#scenes[@]}
task=$SLURM_ARRAY_TASK_ID
first=$((task * count / tasks))
end=$(((task + 1) * count / tasks))
((end > first)) || exit 0
status=0
"$sfrender" "${scenes[@]:first:end-first}" -o "$pattern" "$@" || status=$?
requeue_on_machine_failure "$status"
