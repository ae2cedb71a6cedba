#!/usr/bin/env bash
# A one-node Slurm cluster on loopback, for the tests of the Slurm recipe
# (docs/guide/cluster-sweeps.md "Slurm"): munged with a fresh key, slurmctld and slurmd
# (Debian's slurm-wlm) with a generated slurm.conf, every file of theirs in a
# temporary folder. It runs COMMAND with SLURM_CONF set, then stops what it
# started, by PID, and removes the folder, also when COMMAND fails or the
# script is interrupted.
#
#   tests/slurm/start-cluster.sh COMMAND [ARGS...]   run COMMAND on the cluster
#   tests/slurm/start-cluster.sh                     a shell on it (exit to stop it)
#
# The node is this machine with all its cores (proctrack/linuxproc, task/none:
# no cgroups needed), one partition "debug". Exit 77 with the reason on stderr
# when the cluster cannot start (not root, Slurm or munge missing, a daemon
# that does not come up): the test is then skipped, and says why.
set -euo pipefail

skip() { echo "start-cluster.sh: SKIPPED: $*" >&2; exit 77; }

[ "$(id -u)" -eq 0 ] || skip "slurmd must run as root to start jobs (run the tests as root)"
for tool in munged mungekey slurmctld slurmd sbatch sinfo squeue scontrol; do
  command -v "$tool" >/dev/null 2>&1 || PATH="$PATH:/usr/sbin:/sbin" command -v "$tool" >/dev/null 2>&1 ||
    skip "$tool not found (Debian packages slurm-wlm and munge; scripts/test.sh installs them)"
done
export PATH="$PATH:/usr/sbin:/sbin"

state="$(mktemp -d "${TMPDIR:-/tmp}/pita-slurm.XXXXXX")"
chmod 755 "$state"
pids=()
# The processes of this cluster other than the daemons: slurmstepd and the
# jobs' own, which inherit SLURM_CONF=$state/slurm.conf from slurmd or from
# sbatch's environment (this script and its parents excepted).
cluster_processes() {
  local environ pid
  for environ in /proc/[0-9]*/environ; do
    pid="${environ#/proc/}"
    pid="${pid%/environ}"
    [ "$pid" = $$ ] || [ "$pid" = "$BASHPID" ] && continue
    grep -qzx "SLURM_CONF=$state/slurm.conf" "$environ" 2>/dev/null && echo "$pid"
  done
  return 0
}
stop() {
  local code=$?
  trap - EXIT INT TERM
  unset SLURM_CONF  # what stop starts is not the cluster's
  # Jobs first (their processes are slurmstepd's children), then the daemons.
  if [ -f "$state/slurm.conf" ] && [ -n "${slurmctld_up:-}" ]; then
    SLURM_CONF="$state/slurm.conf" scancel --full --quiet --user="$(id -un)" >/dev/null 2>&1 || true
  fi
  local pid left
  if [ -n "${child:-}" ]; then kill -TERM "$child" 2>/dev/null || true; fi
  for pid in "${pids[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
  for _ in $(seq 50); do
    local alive=0
    for pid in "${pids[@]}"; do kill -0 "$pid" 2>/dev/null && alive=1; done
    [ $alive -eq 0 ] && break
    sleep 0.1
  done
  for pid in "${pids[@]}"; do kill -KILL "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
  # Then the jobs and steps, until none is left (a dying step may start nothing new, but check).
  for _ in 1 2 3 4 5; do
    left="$(cluster_processes)"
    [ -z "$left" ] && break
    kill -KILL $left 2>/dev/null || true
    sleep 0.2
  done
  if [ -n "$left" ]; then
    echo "start-cluster.sh: processes of the cluster still running after the stop: $left" >&2
    code=1
  fi
  rm -rf "$state"
  exit "$code"
}
trap stop EXIT
child=""
trap 'exit 130' INT
trap 'exit 143' TERM

# A free TCP port on loopback (the kernel picks it).
free_port() { /usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'; }

# Wait until `check` succeeds, or fail naming what did not come up and its log.
wait_for() {
  local what="$1" log="$2"
  shift 2
  for _ in $(seq 150); do
    "$@" >/dev/null 2>&1 && return 0
    sleep 0.2
  done
  echo "start-cluster.sh: $what did not come up in 30 s; its log ($log):" >&2
  tail -n 20 "$log" >&2 2>/dev/null || true
  skip "$what did not start"
}

# munge: a fresh key, its own socket.
mkdir -p "$state/munge"
chmod 755 "$state/munge"
mungekey --create --keyfile="$state/munge/munge.key" >/dev/null 2>&1 || skip "mungekey could not create a key"
munged --key-file="$state/munge/munge.key" --socket="$state/munge/socket" --pid-file="$state/munge/munged.pid" \
  --log-file="$state/munge/munged.log" --seed-file="$state/munge/seed" --force --foreground \
  >"$state/munge/munged.out" 2>&1 &
pids+=($!)
wait_for munged "$state/munge/munged.log" test -S "$state/munge/socket"

# slurm.conf: this host as controller and as the one node.
cpus="$(nproc)"
memory=$(( $(awk '/MemTotal/ {print $2}' /proc/meminfo) / 1024 / 2 ))
host="$(hostname -s)"
mkdir -p "$state/ctld" "$state/spool"
cat >"$state/slurm.conf" <<CONF
ClusterName=pita-test
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$(free_port)
SlurmdPort=$(free_port)
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$state/munge/socket
StateSaveLocation=$state/ctld
SlurmdSpoolDir=$state/spool/%n
SlurmctldPidFile=$state/slurmctld.pid
SlurmdPidFile=$state/slurmd.pid
SlurmctldLogFile=$state/slurmctld.log
SlurmdLogFile=$state/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
ReturnToService=2
MinJobAge=3600
KillWait=5
SchedulerParameters=defer_batch=false
MailProg=/bin/true
NodeName=pita-node NodeAddr=127.0.0.1 NodeHostname=$host CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=debug Nodes=pita-node Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$state/slurm.conf"

slurmctld -D -i -f "$SLURM_CONF" >"$state/slurmctld.out" 2>&1 &
pids+=($!)
slurmctld_up=1
wait_for slurmctld "$state/slurmctld.log" scontrol ping
slurmd -D -N pita-node -f "$SLURM_CONF" >"$state/slurmd.out" 2>&1 &
pids+=($!)
node_idle() { sinfo -h -N -o '%T' | grep -qx idle; }
wait_for "slurmd (the node idle in sinfo)" "$state/slurmd.log" node_idle
echo "start-cluster.sh: a one-node Slurm cluster is up ($cpus CPUs, SLURM_CONF=$SLURM_CONF)" >&2

if [ $# -eq 0 ]; then
  "${SHELL:-bash}" || true  # interactive: in the foreground
  exit 0
fi
# The command in the background, so that a signal reaches the traps at once;
# and within a time limit, so that the cluster is stopped before a harness's
# own timeout kills this script without a chance to (PITA_SLURM_TIMEOUT s).
timeout --signal=TERM --kill-after=10 "${PITA_SLURM_TIMEOUT:-780}" "$@" &
child=$!
set +e
wait "$child"
code=$?
set -e
child=""
[ $code -eq 124 ] && echo "start-cluster.sh: $1 took more than ${PITA_SLURM_TIMEOUT:-780} s: stopped" >&2
exit $code
