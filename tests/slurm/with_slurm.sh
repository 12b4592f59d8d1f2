#!/usr/bin/env bash
# Runs one command against a real single-node Slurm cluster started only for it, then stops it:
#   bash tests/slurm/with_slurm.sh COMMAND [ARGS...]
# munged, slurmctld and slurmd (Debian's `munge` and `slurm-wlm`) run as the calling user (root
# in CI) from a fresh temporary folder: their own munge key, a minimal slurm.conf (one node on the
# loopback, 2 CPUs, no cgroups, no accounting, no systemd), free TCP ports. The command sees
# SLURM_CONF (sbatch, squeue, scancel and scontrol find the cluster through it) and
# PENUMBRA_SLURM_DIR (the temporary folder). The exit status is the command's. When the cluster
# cannot start, this fails loudly (status 1) and prints every daemon's log: a test that needs
# Slurm must never pass without one.
set -euo pipefail

if (($# == 0)); then
  echo "usage: bash tests/slurm/with_slurm.sh COMMAND [ARGS...]" >&2
  exit 2
fi

for tool in munged mungekey slurmctld slurmd sinfo; do
  if ! command -v "${tool}" >/dev/null && [[ ! -x "/usr/sbin/${tool}" ]]; then
    echo "with_slurm: ${tool} is missing: install slurm-wlm and munge (scripts/setup.sh does)" >&2
    exit 1
  fi
done
# Exported: under `env -i` bash has a default PATH but does not pass it on, and the jobs (PoCL
# links kernels with `ld`) and the Slurm commands need one. The daemons live in /usr/sbin.
export PATH="${PATH:-/usr/bin:/bin}:/usr/sbin:/sbin"

# slurmd 22.05 (Debian 12) initialises its cgroup plugin even with proctrack/linuxproc and
# task/none, and stops without a cgroup file system ("No filesystem mounted on /sys/fs/cgroup"),
# or with one of the other kind than the kernel gives this process ("Hybrid mode is not
# supported"). A chroot whose /sys was bind-mounted without its submounts has none: mount what
# /proc/self/cgroup says this process is in (v2: one cgroup2; v1: a tmpfs and one hierarchy per
# line), as systemd or a container runtime would, and unmount it afterwards.
MOUNTED_CGROUP=()
mount_cgroups() {
  [[ -d /sys/fs/cgroup ]] && ! grep -qs " /sys/fs/cgroup" /proc/self/mounts || return 0
  if [[ "$(cat /proc/self/cgroup)" == 0::* ]]; then
    mount -t cgroup2 none /sys/fs/cgroup 2>/dev/null && MOUNTED_CGROUP=(/sys/fs/cgroup)
  else
    mount -t tmpfs cgroup-root /sys/fs/cgroup 2>/dev/null || return 0
    MOUNTED_CGROUP=(/sys/fs/cgroup)
    local id controllers path dir options
    while IFS=: read -r id controllers path; do
      [[ "${id}" == 0 || -z "${controllers}" ]] && continue
      dir="${controllers#name=}"
      options="${controllers}"
      [[ "${controllers}" == name=* ]] && options="none,${controllers}"
      mkdir -p "/sys/fs/cgroup/${dir}"
      mount -t cgroup -o "${options}" cgroup "/sys/fs/cgroup/${dir}" 2>/dev/null &&
        MOUNTED_CGROUP=("/sys/fs/cgroup/${dir}" "${MOUNTED_CGROUP[@]}")
    done </proc/self/cgroup
  fi
  ((${#MOUNTED_CGROUP[@]} == 0)) ||
    echo "with_slurm: mounted the cgroup file system slurmd needs on /sys/fs/cgroup" >&2
}
mount_cgroups

DIR="$(mktemp -d "${TMPDIR:-/tmp}/penumbra-slurm.XXXXXX")"
chmod 700 "${DIR}"
NODE="penumbra-node"
# slurmctld runs only where SlurmctldHost names this machine (its short name).
HOST="$(hostname -s 2>/dev/null || cat /proc/sys/kernel/hostname)"
HOST="${HOST%%.*}"

print_logs() {
  local log
  for log in "${DIR}"/munged.log "${DIR}"/slurmctld.log "${DIR}"/slurmd.log "${DIR}"/*.out; do
    [[ -f "${log}" ]] || continue
    echo "----- ${log##*/} -----" >&2
    tail -n 60 "${log}" >&2
  done
}

# Stops what this script started (by the pids they wrote), then removes the folder. Jobs left
# over (a test that failed midway) are cancelled first, so that no job step outlives slurmd.
stop_cluster() {
  local pidfile pid
  if [[ -n "${SLURM_CONF:-}" && -s "${DIR}/slurmctld.pid" ]]; then
    scancel --user="$(id -un)" >/dev/null 2>&1 || true
    for _ in $(seq 50); do
      [[ -z "$(squeue --noheader 2>/dev/null)" ]] && break
      sleep 0.2
    done
  fi
  for pidfile in "${DIR}/slurmd.pid" "${DIR}/slurmctld.pid" "${DIR}/munged.pid"; do
    [[ -s "${pidfile}" ]] || continue
    pid="$(cat "${pidfile}")"
    kill "${pid}" 2>/dev/null || true
    for _ in $(seq 50); do
      kill -0 "${pid}" 2>/dev/null || break
      sleep 0.1
    done
    kill -9 "${pid}" 2>/dev/null || true
  done
  rm -rf "${DIR}"
  local mounted
  for mounted in "${MOUNTED_CGROUP[@]}"; do umount "${mounted}" 2>/dev/null || true; done
}
trap stop_cluster EXIT

fail() {
  echo "with_slurm: $*" >&2
  print_logs
  exit 1
}

# A TCP port nothing listens on (bash's /dev/tcp: a refused connection means free).
free_port() {
  local port
  for _ in $(seq 100); do
    port=$((20000 + RANDOM % 40000))
    if ! (exec 3<>"/dev/tcp/127.0.0.1/${port}") 2>/dev/null; then
      echo "${port}"
      return
    fi
  done
  fail "no free TCP port found"
}

CTLD_PORT="$(free_port)"
SLURMD_PORT="$(free_port)"
while [[ "${SLURMD_PORT}" == "${CTLD_PORT}" ]]; do SLURMD_PORT="$(free_port)"; done
USER_NAME="$(id -un)"
mkdir -p "${DIR}/state" "${DIR}/spool"

# munge: a key of our own and a socket in the folder, so that a munged of the machine (if any) is
# neither needed nor disturbed.
mungekey --create --keyfile="${DIR}/munge.key" >/dev/null 2>&1 || fail "mungekey failed"
chmod 600 "${DIR}/munge.key"
munged --key-file="${DIR}/munge.key" --socket="${DIR}/munge.socket" \
  --pid-file="${DIR}/munged.pid" --log-file="${DIR}/munged.log" \
  --seed-file="${DIR}/munged.seed" --origin=127.0.0.1 --force ||
  fail "munged did not start"

cat >"${DIR}/slurm.conf" <<CONF
# A single-node cluster for penumbra's tests (tests/slurm/with_slurm.sh).
ClusterName=penumbra-test
SlurmctldHost=${HOST}(127.0.0.1)
SlurmctldPort=${CTLD_PORT}
SlurmdPort=${SLURMD_PORT}
SlurmUser=${USER_NAME}
SlurmdUser=${USER_NAME}
AuthType=auth/munge
AuthInfo=socket=${DIR}/munge.socket
CredType=cred/munge
StateSaveLocation=${DIR}/state
SlurmdSpoolDir=${DIR}/spool
SlurmctldPidFile=${DIR}/slurmctld.pid
SlurmdPidFile=${DIR}/slurmd.pid
SlurmctldLogFile=${DIR}/slurmctld.log
SlurmdLogFile=${DIR}/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
# No cgroups and no systemd (a chroot, a container): processes are tracked through /proc.
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
# Short intervals: a test waits for jobs, not for the scheduler.
SchedulerParameters=sched_interval=1
MinJobAge=600
NodeName=${NODE} NodeHostname=${HOST} NodeAddr=127.0.0.1 CPUs=2 RealMemory=1000 State=UNKNOWN
PartitionName=test Nodes=${NODE} Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="${DIR}/slurm.conf"
export PENUMBRA_SLURM_DIR="${DIR}"

slurmctld -i -f "${SLURM_CONF}" >"${DIR}/slurmctld.out" 2>&1 || fail "slurmctld did not start"
slurmd -N "${NODE}" -f "${SLURM_CONF}" >"${DIR}/slurmd.out" 2>&1 || fail "slurmd did not start"

# Ready when the node is idle (sinfo's state "idle", not "idle*" = not responding).
state=""
for _ in $(seq 120); do
  state="$(sinfo --noheader --nodes="${NODE}" --format=%T 2>/dev/null || true)"
  [[ "${state}" == "idle" ]] && break
  sleep 0.5
done
[[ "${state}" == "idle" ]] || fail "the node is not idle after 60 s (sinfo says '${state}')"

set +e
"$@"
status=$?
set -e
if ((status != 0)); then print_logs; fi
exit "${status}"
