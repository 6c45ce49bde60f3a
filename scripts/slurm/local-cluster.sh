#!/usr/bin/env bash
# A one-node Slurm cluster for tests and trials: munged, slurmctld and slurmd
# started in the foreground inside private network, PID and mount namespaces
# (loopback only), COMMAND run with SLURM_CONF pointing at it, then everything
# stopped. Nothing outside the namespaces is touched: the daemons' ports,
# sockets and state live in the namespace and in WORK; when COMMAND ends, the
# namespace's first process exits and the kernel ends every process it holds,
# so the cluster cannot outlive the script. docs/scale.md.
#
#   scripts/slurm/local-cluster.sh [--work DIR] [--cpus N] [--keep] COMMAND [ARGS...]
#   scripts/slurm/local-cluster.sh sbatch --wait scripts/slurm/tiled-frame.sbatch ...
#
# COMMAND runs in the caller's directory with SLURM_CONF set, so sbatch,
# squeue, scontrol and scancel reach the cluster. Exit status: COMMAND's;
# 77 when namespaces are not permitted here or Slurm is not installed (one
# line on stderr says which); 2 for a usage error; 3 when the cluster did not
# come up (its logs are printed). WORK (default: a fresh temporary folder,
# removed afterwards unless --keep) holds slurm.conf, the munge key and
# socket, state and logs. Needs root (exit 77 otherwise).
set -euo pipefail

work="" cpus="" keep=0
while [ $# -gt 0 ]; do
  case "$1" in
    --work) work="$2"; shift 2 ;;
    --cpus) cpus="$2"; shift 2 ;;
    --keep) keep=1; shift ;;
    -h|--help) sed -n 2,19p "$0"; exit 0 ;;
    --) shift; break ;;
    -*) echo "local-cluster: unknown option '$1' (see --help)" >&2; exit 2 ;;
    *) break ;;
  esac
done
[ $# -gt 0 ] || { echo "local-cluster: no COMMAND given (see --help)" >&2; exit 2; }

# --- inside the namespaces: start the daemons, run COMMAND, report ---------
if [ "${UMBRA_LOCAL_CLUSTER_INSIDE:-}" = 1 ]; then
  conf="$work/slurm.conf"
  ip link set lo up
  # Slurm finds the address to listen on with getaddrinfo(NULL, port) and
  # AI_ADDRCONFIG, which glibc answers with nothing while only loopback has
  # an address (tried: "Unable to bind listen port (6818)"): give a dummy
  # interface one.
  if ip link add umbra0 type dummy 2> /dev/null; then
    ip addr add 10.254.0.1/32 dev umbra0
    ip link set umbra0 up
  else  # no dummy driver: loopback takes the address instead
    ip addr add 10.254.0.1/32 dev lo
  fi

  daemons=()
  stop_daemons() {
    # The daemons in reverse order of starting; whatever is left dies with
    # the PID namespace when this shell exits.
    local i
    for ((i = ${#daemons[@]} - 1; i >= 0; i--)); do kill "${daemons[i]}" 2>/dev/null || true; done
    for ((i = ${#daemons[@]} - 1; i >= 0; i--)); do wait "${daemons[i]}" 2>/dev/null || true; done
  }
  show_logs() {
    local f
    for f in "$work"/log/*.log; do echo "--- $f" >&2; tail -n 20 "$f" >&2; done
  }
  trap stop_daemons EXIT

  munged --foreground --force --socket="$work/munge/munge.socket" \
    --key-file="$work/munge/munge.key" --pid-file="$work/munge/munged.pid" \
    --seed-file="$work/munge/munged.seed" --log-file="$work/log/munged.log" \
    > "$work/log/munged.out" 2>&1 &
  daemons+=($!)
  slurmctld -D -i -f "$conf" > "$work/log/slurmctld.out" 2>&1 &
  daemons+=($!)
  slurmd -D -f "$conf" -N umbra-node > "$work/log/slurmd.out" 2>&1 &
  daemons+=($!)

  export SLURM_CONF="$conf"
  # Up when a one-task job runs on the node end to end (munge, controller,
  # slurmd, slurmstepd): sinfo can call the node idle before slurmd has
  # registered. srun waits for the node; give up after 60 s.
  if ! timeout 60 srun --quiet --job-name=umbra-probe true 2> "$work/log/probe.err"; then
    echo "local-cluster: the node did not come up within 60 s" >&2
    show_logs
    exit 3
  fi
  set +e
  "$@"
  status=$?
  set -e
  exit "$status"
fi

# --- outside: check what is needed, write the configuration, enter --------
for program in munged slurmctld slurmd sbatch sinfo unshare ip; do
  if ! command -v "$program" > /dev/null; then
    echo "local-cluster: skipped: '$program' is not installed (apt-get install slurmctld slurmd slurm-client munge iproute2)" >&2
    exit 77
  fi
done
# Root only: slurmctld and slurmd set and drop supplementary groups, which a
# user namespace of an unprivileged caller forbids (setgroups is denied
# there; tried: "fatal: Failed to drop supplementary groups").
if [ "$(id -u)" -ne 0 ]; then
  echo "local-cluster: skipped: needs root (slurmctld and slurmd change groups, which an unprivileged user namespace forbids)" >&2
  exit 77
fi
enter=(unshare --net --pid --mount --fork --mount-proc)
if ! "${enter[@]}" true 2> /dev/null; then
  echo "local-cluster: skipped: this machine does not permit private namespaces (unshare --net --pid --mount)" >&2
  exit 77
fi

[ -n "$cpus" ] || cpus=$(nproc)
if [ -z "$work" ]; then
  work=$(mktemp -d "${TMPDIR:-/tmp}/umbra-slurm.XXXXXX")
  [ "$keep" = 1 ] || trap 'rm -rf "$work"' EXIT
else
  mkdir -p "$work"
fi
work=$(cd "$work" && pwd)
# munged refuses a key or socket under a folder others may write to.
chmod 0700 "$work"
mkdir -p "$work/munge" "$work/log" "$work/state" "$work/spool"
# Clients need to reach the socket; only the owner may write the folder.
chmod 0711 "$work/munge"
[ -f "$work/munge/munge.key" ] || {
  head -c 1024 /dev/urandom > "$work/munge/munge.key"
  chmod 0400 "$work/munge/munge.key"
}
memory=$(awk '/MemTotal/ { print int($2 / 1024 * 0.8) }' /proc/meminfo)
cat > "$work/slurm.conf" << EOF
# Written by scripts/slurm/local-cluster.sh: one node on loopback.
ClusterName=umbra-local
SlurmctldHost=localhost(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$work/munge/munge.socket
CredType=cred/munge
SlurmctldPort=6817
SlurmdPort=6818
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
ReturnToService=2
SchedulerType=sched/backfill
# Batch jobs start as soon as they are submitted (the default waits up to 3 s).
SchedulerParameters=batch_sched_delay=0
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
# Finished jobs stay visible to scontrol for an hour (no accounting database).
MinJobAge=3600
NodeName=umbra-node NodeAddr=127.0.0.1 NodeHostname=umbra-node CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=local Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF

set +e
UMBRA_LOCAL_CLUSTER_INSIDE=1 "${enter[@]}" "$0" --work "$work" --cpus "$cpus" -- "$@"
status=$?
set -e
exit "$status"
