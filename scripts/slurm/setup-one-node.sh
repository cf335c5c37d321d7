#!/usr/bin/env bash
# A one-node Slurm cluster on this machine, for running tessref's verify campaigns as job arrays
# (docs/campaigns.md): installs Debian's slurm-wlm and munge if missing, writes a minimal
# slurm.conf for this host (its CPUs and memory as `slurmd -C` reports them), starts munged,
# slurmctld and slurmd, and waits until `sinfo` shows the node idle. Idempotent: a node already
# idle is left alone. Needs root or sudo. Works without systemd (containers): the daemons are
# started directly, and process tracking uses /proc rather than cgroups.
#
#   scripts/slurm/setup-one-node.sh [--restart]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
restart=0
[ "${1:-}" = "--restart" ] && restart=1
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"

if [ $restart -eq 0 ] && command -v sinfo >/dev/null && sinfo -h -o %T 2>/dev/null | grep -qx idle; then
  echo "setup-one-node: the node is already idle"; sinfo; exit 0
fi
"$here/../install-deps.sh" slurm-wlm munge

host="$(hostname -s)"
conf=/etc/slurm/slurm.conf
# slurmd -C prints this machine's node line (CPUs, sockets, cores, threads, RealMemory).
node_line="$(slurmd -C | head -1)"
node_line="$(echo "$node_line" | sed "s/NodeName=[^ ]*/NodeName=$host NodeAddr=127.0.0.1/")"
$sudo mkdir -p /etc/slurm /var/lib/slurm/slurmctld /var/lib/slurm/slurmd /var/log/slurm /run/slurm
$sudo tee "$conf" >/dev/null <<CONF
# Written by tessref's scripts/slurm/setup-one-node.sh: one node, this host.
ClusterName=tessref
SlurmctldHost=$host(127.0.0.1)
# Root runs the daemons: a one-node test cluster, no slurm user or file ownership to set up.
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
StateSaveLocation=/var/lib/slurm/slurmctld
SlurmdSpoolDir=/var/lib/slurm/slurmd
SlurmctldPidFile=/run/slurm/slurmctld.pid
SlurmdPidFile=/run/slurm/slurmd.pid
SlurmctldLogFile=/var/log/slurm/slurmctld.log
SlurmdLogFile=/var/log/slurm/slurmd.log
# No cgroups in containers: track job processes through /proc, bind no tasks.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
SchedulerType=sched/backfill
# cons_tres hands out single CPUs, so array tasks share the node.
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
SlurmdTimeout=300
$node_line State=UNKNOWN
PartitionName=main Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
echo "setup-one-node: wrote $conf for $host: $node_line"

# munge: the key (the package makes one; older ones need mungekey), then the daemon as user munge.
if [ ! -s /etc/munge/munge.key ]; then
  $sudo mungekey --create --keyfile=/etc/munge/munge.key 2>/dev/null ||
    $sudo dd if=/dev/urandom of=/etc/munge/munge.key bs=1024 count=1 status=none
  $sudo chown munge:munge /etc/munge/munge.key; $sudo chmod 400 /etc/munge/munge.key
fi
$sudo mkdir -p /run/munge; $sudo chown munge:munge /run/munge
if ! munge -n 2>/dev/null | unmunge >/dev/null 2>&1; then
  $sudo runuser -u munge -- /usr/sbin/munged
  sleep 1
fi
munge -n | unmunge >/dev/null || { echo "setup-one-node: munged does not answer" >&2; exit 1; }

# (Re)start the Slurm daemons; -c: a clean controller state, as the config may have changed.
for pidfile in /run/slurm/slurmd.pid /run/slurm/slurmctld.pid; do
  if [ -s "$pidfile" ]; then $sudo kill "$(cat "$pidfile")" 2>/dev/null || true; fi
done
sleep 1
$sudo slurmctld -c
$sudo slurmd
for _ in $(seq 1 60); do
  if sinfo -h -o %T 2>/dev/null | grep -qx idle; then
    echo "setup-one-node: ready"; sinfo; exit 0
  fi
  sleep 1
done
echo "setup-one-node: the node did not become idle within 60 s; sinfo says:" >&2
sinfo >&2 || true
echo "see /var/log/slurm/slurmctld.log and /var/log/slurm/slurmd.log" >&2
exit 1
