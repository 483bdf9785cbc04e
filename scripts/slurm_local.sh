#!/usr/bin/env bash
# A single-node Slurm on this machine, without systemd, for the tests and for trying the
# distributed sweep (scripts/sweep_slurm.sh):
#   scripts/slurm_local.sh start [STATEDIR]    munged, slurmctld and slurmd; waits until the node is idle
#   scripts/slurm_local.sh stop [STATEDIR]     stops the daemons this script started (their pid files)
#   scripts/slurm_local.sh status [STATEDIR]   0 when the node answers, 1 otherwise
#   scripts/slurm_local.sh env [STATEDIR]      prints "export SLURM_CONF=..." for the client commands
# STATEDIR (default $TRIRAST_SLURM_DIR or /tmp/trirast-slurm) holds slurm.conf, the munge socket,
# the pid files, the logs and the spool and state directories. The Slurm client commands need
# SLURM_CONF=STATEDIR/slurm.conf. Debian's slurm-wlm and munge; the munge key is /etc/munge/munge.key
# (created when missing). The configuration is minimal: proctrack/linuxproc, task/none, no cgroups,
# select/cons_tres by core, one partition "local", the node line from `slurmd -C`. Needs root
# (slurmd runs jobs as their submitter).
set -euo pipefail
CMD="${1:-}"
D="${2:-${TRIRAST_SLURM_DIR:-/tmp/trirast-slurm}}"
CONF="$D/slurm.conf"
export SLURM_CONF="$CONF"
die() { echo "slurm_local.sh: $*" >&2; exit 1; }

pid_alive() { [ -f "$1" ] && kill -0 "$(cat "$1")" 2>/dev/null; }

node_idle() { sinfo -h -N -o '%T' 2>/dev/null | grep -qE '^(idle|mixed|allocated)'; }

start() {
  [ "$(id -u)" = 0 ] || die "start: needs root (slurmd runs jobs as their submitter)"
  for t in munged slurmctld slurmd sinfo sbatch; do
    command -v "$t" >/dev/null || die "start: '$t' not found (Debian packages slurm-wlm, munge: scripts/deps.sh)"
  done
  mkdir -p "$D/spool" "$D/state" "$D/log"
  chmod 755 "$D"
  local key=/etc/munge/munge.key
  if [ ! -f "$key" ]; then
    mkdir -p /etc/munge
    dd if=/dev/urandom of="$key" bs=1 count=1024 status=none
  fi
  chmod 0400 "$key"
  if ! pid_alive "$D/munged.pid"; then
    munged --force --socket="$D/munge.socket" --key-file="$key" --pid-file="$D/munged.pid" \
      --log-file="$D/log/munged.log" --seed-file="$D/munge.seed" ||
      die "start: munged failed (see $D/log/munged.log)"
  fi
  local node cpus
  node=$(slurmd -C | head -1) || die "start: slurmd -C failed"
  cpus=$(echo "$node" | grep -o 'CPUs=[0-9]*' | cut -d= -f2)
  local host
  host=$(echo "$node" | sed 's/^NodeName=\([^ ]*\).*/\1/')
  cat > "$CONF" <<EOF
# Written by scripts/slurm_local.sh: a single-node Slurm for this machine ($cpus CPUs).
ClusterName=trirast-local
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
SlurmctldPort=${TRIRAST_SLURMCTLD_PORT:-6817}
SlurmdPort=${TRIRAST_SLURMD_PORT:-6818}
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$D/munge.socket
StateSaveLocation=$D/state
SlurmdSpoolDir=$D/spool
SlurmctldPidFile=$D/slurmctld.pid
SlurmdPidFile=$D/slurmd.pid
SlurmctldLogFile=$D/log/slurmctld.log
SlurmdLogFile=$D/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
SlurmdTimeout=300
InactiveLimit=0
KillWait=5
MinJobAge=300
MaxArraySize=100001
$node
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
  # The node line of slurmd -C carries UpTime=...: not a slurm.conf key.
  sed -i 's/ *UpTime=[^ ]*//' "$CONF"
  if ! pid_alive "$D/slurmctld.pid"; then
    slurmctld -f "$CONF" || die "start: slurmctld failed (see $D/log/slurmctld.log)"
  fi
  if ! pid_alive "$D/slurmd.pid"; then
    slurmd -f "$CONF" || die "start: slurmd failed (see $D/log/slurmd.log)"
  fi
  local i
  for i in $(seq 1 60); do
    if node_idle; then
      echo "slurm_local.sh: node $host up ($cpus CPUs); export SLURM_CONF=$CONF"
      return 0
    fi
    # A node that was down in an earlier run of the same state directory comes back.
    scontrol update nodename="$host" state=resume >/dev/null 2>&1 || true
    sleep 1
  done
  die "start: the node did not become idle in 60 s (logs: $D/log)"
}

stop() {
  local f n
  for n in slurmd slurmctld munged; do
    f="$D/$n.pid"
    if pid_alive "$f"; then
      kill "$(cat "$f")" 2>/dev/null || true
      for _ in $(seq 1 50); do pid_alive "$f" || break; sleep 0.2; done
      pid_alive "$f" && kill -9 "$(cat "$f")" 2>/dev/null || true
    fi
    rm -f "$f"
  done
  echo "slurm_local.sh: stopped ($D)"
}

case "$CMD" in
  start) start ;;
  stop) stop ;;
  status)
    if pid_alive "$D/slurmctld.pid" && pid_alive "$D/slurmd.pid" && node_idle; then
      sinfo -N; exit 0
    fi
    echo "slurm_local.sh: not running ($D)"; exit 1 ;;
  env) echo "export SLURM_CONF=$CONF" ;;
  *) sed -n '2,13p' "$0"; exit 2 ;;
esac
