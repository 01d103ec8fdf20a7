# shellcheck shell=bash
# Sourced by the array tasks (tile-task.sh, batch-task.sh): what a task does
# when sfrender fails. A failure of the machine (killed by a signal: the OOM
# killer, a node's trouble, a pre-emption; or sfrender's exit status 4, out
# of memory or threads) requeues the task with `scontrol requeue`, which any
# user may do to their own job and which needs nothing of slurm.conf (Slurm
# 22.05 requeues by itself only when a node fails, or, where the
# administrator set RequeueExit, on the exit statuses listed there). A
# failure of the scene (1, 2, 3) would fail again, and is not requeued; nor
# is a task that has been requeued SFSLURM_MAX_RESTARTS times (3 unless
# set). Slurm holds a requeued task back for about two minutes (its begin
# time) before it runs again. Since every output is written beside its
# target and renamed into place, a task killed half-way leaves nothing half
# written, and running it again is harmless.

# $1: sfrender's exit status. Returns it, after asking for the requeue when
# it is the machine's.
requeue_on_machine_failure() {
  local status=$1
  local restarts=${SLURM_RESTART_COUNT:-0}
  if ((status != 0 && (status == 4 || status > 128) &&
    restarts < ${SFSLURM_MAX_RESTARTS:-3})); then
    echo "sfslurm: sfrender ended with status $status; requeueing task" \
      "${SLURM_ARRAY_JOB_ID}_${SLURM_ARRAY_TASK_ID} (restart $((restarts + 1)))" >&2
    scontrol requeue "${SLURM_ARRAY_JOB_ID}_${SLURM_ARRAY_TASK_ID}"
  fi
  return "$status"
}
