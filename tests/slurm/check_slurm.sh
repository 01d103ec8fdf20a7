#!/bin/bash
# The Slurm scripts (scripts/slurm/) on a real single-node cluster started
# here (cluster.sh): a 16-tile render of a 100,000-object scene, one of
# whose tasks is killed half-way and comes back, merged and compared bit for
# bit with one process's render; then a batch of 20 scenes. Exits 77
# (ctest's SKIP_RETURN_CODE) when not root or when Slurm or munge is not
# installed. Arguments: BIN_DIR (sfrender, sfgen) SOURCE_DIR.
set -euo pipefail
bin=$1 source=$2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=tests/slurm/cluster.sh
source "$here/cluster.sh"
if (($(id -u) != 0)); then
  echo "skipped: starting Slurm's daemons needs root"
  exit 77
fi
if missing=$(cluster_missing_binary); then
  echo "skipped: $missing is not installed (Debian's slurm-wlm and munge)"
  exit 77
fi

CLUSTER_DIR=$(mktemp -d /tmp/sfslurm.XXXXXX)
cleanup() {
  stop_cluster
  rm -rf "$CLUSTER_DIR"
}
trap cleanup EXIT
start_cluster 60
echo "cluster up: $(sinfo -h -o '%n %c CPUs %m MB %t')"
work=$CLUSTER_DIR/work
mkdir -p "$work"
chmod 755 "$CLUSTER_DIR"

# Waits (at most $2 seconds) until job $1 has left the queue; fails if it did
# not, or if it did not complete.
wait_for_job() {
  local job=$1 limit=$2 waited=0 state
  while [[ -n $(squeue -h -j "$job" 2>/dev/null) ]]; do
    if ((waited >= limit * 10)); then
      echo "job $job still queued after $limit s:" >&2
      squeue >&2
      return 1
    fi
    sleep 0.1
    waited=$((waited + 1))
  done
  state=$(scontrol show job "$job" | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p' | sort -u)
  if [[ $state != COMPLETED ]]; then
    echo "job $job ended $state" >&2
    return 1
  fi
}

# The pid of a running tile task's sfrender, and the task, once one runs.
find_running_sfrender() {
  local job pid
  for job in $(squeue -h -t R -j "$1" -o %A); do
    for pid in $(scontrol listpids "$job" 2>/dev/null | awk 'NR > 1 { print $1 }'); do
      if [[ $(cat "/proc/$pid/comm" 2>/dev/null) == sfrender ]]; then
        echo "$pid $(squeue -h -j "$job" -o %K)"
        return 0
      fi
    done
  done
  return 1
}

"$bin/sfgen" --layout floor -n 100000 -s 1 -o "$work/scene.sf" >/dev/null
size=(--width 640 --height 360)
TIMEFORMAT='%R %U %S'
single=$({ time "$bin/sfrender" "$work/scene.sf" "${size[@]}" -o "$work/single.png" -q; } 2>&1)
"$bin/sfrender" "$work/scene.sf" "${size[@]}" -o "$work/single.exr" -q
echo "one process: $single (wall, user, system seconds)"

# 16 tiles. One task's sfrender is killed with SIGKILL while it renders:
# its task requeues itself (scripts/slurm/requeue.sh), and Slurm's two
# minutes' hold on a requeued job is lifted so that the test stays short.
start=$(date +%s.%N)
jobs=$(bash "$source/scripts/slurm/sfrender-tiles.sh" "$work/scene.sf" -o "$work/merged.png" \
  --tiles 16 --work "$work/tiles" --sfrender "$bin/sfrender" "${size[@]}")
array=$(sed -n 's/.*tiles=\([0-9]*\).*/\1/p' <<<"$jobs")
merge=$(sed -n 's/.*merge=\([0-9]*\).*/\1/p' <<<"$jobs")
echo "submitted: $jobs"
killed='' task=''
for ((try = 0; try < 600; ++try)); do
  if found=$(find_running_sfrender "$array"); then
    read -r pid task <<<"$found"
    kill -KILL "$pid" && killed=$pid && break
  fi
  sleep 0.05
done
[[ -n $killed ]] || { echo "no tile task was seen running" >&2; exit 1; }
echo "killed sfrender $killed of task ${array}_$task"
for ((try = 0; try < 300; ++try)); do
  if [[ $(scontrol show job "${array}_$task" 2>/dev/null) =~ Restarts=1 &&
    $(squeue -h -j "${array}_$task" -o %T) == PENDING ]]; then
    break
  fi
  sleep 0.1
done
scontrol show job "${array}_$task" | grep -q "Restarts=1" ||
  { echo "task ${array}_$task was not requeued" >&2; exit 1; }
scontrol update JobId="${array}_$task" StartTime=now
wait_for_job "$merge" 150
end=$(date +%s.%N)
echo "16 tiles and the merge on the cluster: $(awk "BEGIN { print $end - $start }") s wall"
grep -q "requeueing task ${array}_$task" "$work/tiles/tile-$task.log" ||
  { echo "task $task's log does not say it requeued" >&2; exit 1; }
cmp "$work/merged.png" "$work/single.png"
"$bin/sfrender" --merge "$work"/tiles/tile-*.exr -o "$work/merged.exr" -q
idiff -q -fail 0 -warn 0 "$work/merged.exr" "$work/single.exr"
echo "the merged PNG is the one process's byte for byte, the merged EXR its pixels bit for bit"

# The image's flags reach the merge: a 16-bit PNG from float tiles, and -v
# given to the tiles too (which are quiet otherwise; both would fail them).
jobs=$(bash "$source/scripts/slurm/sfrender-tiles.sh" "$work/scene.sf" -o "$work/deep.png" \
  --tiles 3 --work "$work/deep" --sfrender "$bin/sfrender" --width 64 --height 36 --bits 16 -v)
wait_for_job "$(sed -n 's/.*merge=\([0-9]*\).*/\1/p' <<<"$jobs")" 60
depth=$(od -An -tu1 -j24 -N1 "$work/deep.png" | tr -d ' ')
[[ $depth == 16 ]] || { echo "deep.png has $depth bits a channel, not 16" >&2; exit 1; }
echo "--bits 16 and -v carried: a 16-bit PNG from 3 float tiles"

# A batch of 20 scenes over 4 tasks, listed with CRLF line ends, a comment
# and a blank line.
mkdir -p "$work/batch" "$work/out"
printf '# the scenes\r\n\r\n' >"$work/list.txt"
for seed in $(seq 1 20); do
  "$bin/sfgen" --layout floor -n 200 -s "$seed" -o "$work/batch/scene-$seed.sf" >/dev/null
  printf '%s\r\n' "$work/batch/scene-$seed.sf"
done >>"$work/list.txt"
batch=$(bash "$source/scripts/slurm/sfbatch.sh" "$work/list.txt" -o "$work/out/{stem}.png" \
  --tasks 4 --logs "$work/logs" --sfrender "$bin/sfrender" --width 64 --height 36 -q)
echo "submitted: $batch"
batch=${batch#batch=}
for task in 0 1 2 3; do wait_for_job "${batch}_$task" 60; done
for seed in $(seq 1 20); do
  [[ -s $work/out/scene-$seed.png ]] || { echo "scene-$seed.png is missing" >&2; exit 1; }
done
echo "the batch wrote all 20 images of a CRLF list"
