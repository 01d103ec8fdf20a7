#!/bin/bash
# One task of sfrender-tiles.sh's array: tile $SLURM_ARRAY_TASK_ID of N of
# the scene, written to WORK/tile-I.exr (a 32-bit float EXR, its data window
# within the image's display window).
# Arguments: SFRENDER N WORK SCENE [SFRENDER FLAGS...]
set -u
sfrender=$1 tiles=$2 work=$3
shift 3
# shellcheck source=scripts/slurm/requeue.sh
source "$SFSLURM_DIR/requeue.sh"
tile=$SLURM_ARRAY_TASK_ID
status=0
"$sfrender" "$@" --tile "$tile/$tiles" -o "$work/tile-$tile.exr" || status=$?
requeue_on_machine_failure "$status"
