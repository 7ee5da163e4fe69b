#!/usr/bin/env bash
# A one-node Slurm cluster on this machine, for tests: munged + slurmctld + slurmd as root, every
# file (slurm.conf, munge key, state, logs, sockets) in one temporary folder.
#
#   tests/cluster/slurm_cluster.sh start [DIR]   starts it (DIR default /tmp/graspsim-slurm), waits
#                                                until the node is idle, prints `export SLURM_CONF=...`
#   tests/cluster/slurm_cluster.sh stop [DIR]    stops the three daemons it started and removes DIR
#
# Needs Debian's slurm-wlm and munge (.ci/install) and root. Exits non-zero with one line saying
# what failed when the cluster does not come up within 30 s (logs in DIR/*.log).
set -euo pipefail

action=${1:-}
dir=${2:-/tmp/graspsim-slurm}

fail() { echo "slurm_cluster: $*" >&2; exit 1; }

stop_cluster() {
  for daemon in slurmd slurmctld munged; do
    if [ -f "$dir/$daemon.pid" ]; then
      pid=$(cat "$dir/$daemon.pid")
      kill "$pid" 2>/dev/null || true
      for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
      kill -9 "$pid" 2>/dev/null || true
    fi
  done
  rm -rf "$dir"
}

write_config() {
  local host cpus
  host=$(hostname -s)
  cpus=$(nproc)
  mkdir -p "$dir/state" "$dir/spool"
  cat >"$dir/slurm.conf" <<CONF
ClusterName=graspsim-test
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
SlurmctldPort=${GRASPSIM_SLURMCTLD_PORT:-16817}
SlurmdPort=${GRASPSIM_SLURMD_PORT:-16818}
AuthType=auth/munge
AuthInfo=socket=$dir/munge.socket
CredType=cred/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SwitchType=switch/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
SlurmdTimeout=30
InactiveLimit=0
KillWait=5
MinJobAge=300
NodeName=$host CPUs=$cpus State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
}

start_cluster() {
  [ "$(id -u)" -eq 0 ] || fail "must run as root (the daemons run as root)"
  for tool in munged slurmctld slurmd sinfo; do
    command -v "$tool" >/dev/null || [ -x "/usr/sbin/$tool" ] || fail "$tool not found; install slurm-wlm and munge (.ci/install)"
  done
  stop_cluster
  mkdir -p "$dir"
  chmod 700 "$dir"
  dd if=/dev/urandom of="$dir/munge.key" bs=1024 count=1 status=none
  chmod 400 "$dir/munge.key"
  /usr/sbin/munged --force --key-file="$dir/munge.key" --socket="$dir/munge.socket" \
    --pid-file="$dir/munged.pid" --log-file="$dir/munged.log" --seed-file="$dir/munge.seed" \
    || fail "munged did not start (see $dir/munged.log)"
  write_config
  export SLURM_CONF="$dir/slurm.conf"
  /usr/sbin/slurmctld -i || fail "slurmctld did not start (see $dir/slurmctld.log)"
  /usr/sbin/slurmd || fail "slurmd did not start (see $dir/slurmd.log)"
  for _ in $(seq 300); do
    state=$(sinfo -h -N -o %T 2>/dev/null | head -1 || true)
    if [ "$state" = "idle" ]; then
      echo "export SLURM_CONF=$dir/slurm.conf"
      return 0
    fi
    sleep 0.1
  done
  fail "the node did not become idle within 30 s (state '${state:-none}'; logs in $dir)"
}

case "$action" in
  start) start_cluster ;;
  stop) stop_cluster ;;
  *) fail "usage: $0 start|stop [DIR]" ;;
esac
