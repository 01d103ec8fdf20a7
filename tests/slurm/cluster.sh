# shellcheck shell=bash
# A single-node Slurm cluster on this machine, for the tests: sourced, it
# defines start_cluster and stop_cluster. Everything (munge key and socket,
# slurm.conf, state, spool, logs, pid files) lives under $CLUSTER_DIR, and
# the daemons listen on their own ports, so that a system munged or Slurm
# (stale or running) does not interfere and nothing outside the folder is
# changed. Needs root (slurmd runs jobs as their user) and Debian's
# slurm-wlm and munge (scripts/install-deps.sh).

# The binaries the cluster needs; prints the first that is missing.
cluster_missing_binary() {
  local binary
  for binary in munged mungekey slurmctld slurmd sbatch sinfo squeue scontrol sacct scancel; do
    if ! command -v "$binary" >/dev/null 2>&1 && [[ ! -x /usr/sbin/$binary ]]; then
      echo "$binary"
      return 0
    fi
  done
  return 1
}

# A free TCP port at or above $1, found by binding to it.
cluster_free_port() {
  python3 - "$1" <<'PY'
import socket, sys
port = int(sys.argv[1])
while True:
    with socket.socket() as s:
        try:
            s.bind(("", port))
            print(port)
            break
        except OSError:
            port += 1
PY
}

# Writes slurm.conf and cgroup.conf into $CLUSTER_DIR. The node has this
# machine's real CPUs and memory (slurmd -C). proctrack/linuxproc and
# task/none: no cgroups, which a container rarely lets one use.
# RequeueExit: a batch script that exits 137 (a process of its killed by
# SIGKILL, the OOM killer's signal) is requeued, as on a real cluster an
# administrator may set; scripts/slurm/ does not rely on it (its tasks
# requeue themselves with scontrol), it is here so that both paths work.
cluster_write_config() {
  local node_line controller_port node_port
  node_line=$(/usr/sbin/slurmd -C | head -n 1)
  CLUSTER_NODE=$(sed -n 's/^NodeName=\([^ ]*\).*/\1/p' <<<"$node_line")
  controller_port=$(cluster_free_port 16817)
  node_port=$(cluster_free_port $((controller_port + 1)))
  mkdir -p "$CLUSTER_DIR/state" "$CLUSTER_DIR/spool" "$CLUSTER_DIR/log"
  cat >"$CLUSTER_DIR/slurm.conf" <<CONF
ClusterName=sftest
SlurmctldHost=$CLUSTER_NODE
SlurmctldPort=$controller_port
SlurmdPort=$node_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$CLUSTER_DIR/munge.socket
StateSaveLocation=$CLUSTER_DIR/state
SlurmdSpoolDir=$CLUSTER_DIR/spool
SlurmctldPidFile=$CLUSTER_DIR/slurmctld.pid
SlurmdPidFile=$CLUSTER_DIR/slurmd.pid
SlurmctldLogFile=$CLUSTER_DIR/log/slurmctld.log
SlurmdLogFile=$CLUSTER_DIR/log/slurmd.log
PlugStackConfig=$CLUSTER_DIR/plugstack.conf
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SwitchType=switch/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
SchedulerParameters=sched_interval=1
ReturnToService=2
JobRequeue=1
RequeueExit=137
MinJobAge=600
SlurmctldTimeout=30
SlurmdTimeout=30
InactiveLimit=0
KillWait=2
$node_line
PartitionName=test Nodes=$CLUSTER_NODE Default=YES MaxTime=INFINITE State=UP
CONF
  # Not read with the plugins above; written so that no system one is.
  cat >"$CLUSTER_DIR/cgroup.conf" <<CONF
CgroupAutomount=no
ConstrainCores=no
ConstrainRAMSpace=no
CONF
  : >"$CLUSTER_DIR/plugstack.conf"
}

# Starts munged, slurmctld and slurmd, and waits (at most $1 seconds, 60 by
# default) until sinfo shows the node idle. Exports SLURM_CONF for the
# client commands.
start_cluster() {
  local wait_seconds=${1:-60}
  cluster_write_config
  export SLURM_CONF=$CLUSTER_DIR/slurm.conf
  mungekey --create --keyfile="$CLUSTER_DIR/munge.key" --force >/dev/null
  chmod 600 "$CLUSTER_DIR/munge.key"
  chmod 700 "$CLUSTER_DIR"
  /usr/sbin/munged --force --key-file="$CLUSTER_DIR/munge.key" \
    --socket="$CLUSTER_DIR/munge.socket" --pid-file="$CLUSTER_DIR/munged.pid" \
    --log-file="$CLUSTER_DIR/log/munged.log" --seed-file="$CLUSTER_DIR/munged.seed" ||
    return 1
  # Foreground daemons (-D) in the background, so that their pids are ours.
  /usr/sbin/slurmctld -D -i -f "$SLURM_CONF" >"$CLUSTER_DIR/log/slurmctld.out" 2>&1 &
  CLUSTER_CONTROLLER_PID=$!
  /usr/sbin/slurmd -D -f "$SLURM_CONF" >"$CLUSTER_DIR/log/slurmd.out" 2>&1 &
  CLUSTER_NODE_PID=$!
  local waited=0
  until [[ $(sinfo -h -n "$CLUSTER_NODE" -o %t 2>/dev/null) == idle ]]; do
    if ((waited >= wait_seconds)) || ! kill -0 "$CLUSTER_CONTROLLER_PID" 2>/dev/null ||
      ! kill -0 "$CLUSTER_NODE_PID" 2>/dev/null; then
      echo "the cluster did not come up; its logs:" >&2
      tail -n 20 "$CLUSTER_DIR"/log/* >&2
      return 1
    fi
    sleep 1
    waited=$((waited + 1))
  done
}

# Stops the daemons this file started, by their pids, and waits for them.
stop_cluster() {
  local pid
  if [[ -n ${SLURM_CONF:-} ]]; then scancel --quiet --full --user=root 2>/dev/null || true; fi
  for pid in ${CLUSTER_NODE_PID:-} ${CLUSTER_CONTROLLER_PID:-}; do
    kill -TERM "$pid" 2>/dev/null || true
  done
  for pid in ${CLUSTER_NODE_PID:-} ${CLUSTER_CONTROLLER_PID:-}; do
    wait "$pid" 2>/dev/null || true
  done
  if [[ -f $CLUSTER_DIR/munged.pid ]]; then
    pid=$(cat "$CLUSTER_DIR/munged.pid")
    kill -TERM "$pid" 2>/dev/null || true
    while kill -0 "$pid" 2>/dev/null; do sleep 0.1; done
  fi
}
