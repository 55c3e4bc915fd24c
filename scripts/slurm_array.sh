#!/usr/bin/env bash
# README's Slurm job-array example run on a real single-node Slurm: starts munge (if it is not
# running), slurmctld and slurmd on this machine with a throw-away configuration, submits the
# sweep DECK as a job array of TASKS shards (fricon --shard I/TASKS in each task), waits,
# merges the shards (fricon --merge: the summary, the response figure of a SWEEP deck and the
# envelope of a deck with load combinations), checks that every file is byte-identical to a
# serial run of the same deck (the sweep overlay aside: shards draw none), and stops the
# daemons it started. Debian: run as root after
# `apt-get install slurm-wlm munge` (slurmctld, slurmd, the client commands and munged):
#
#   bash scripts/slurm_array.sh [DECK [TASKS]]      (default input/sweep.dat, 3 tasks)
#
# Writes output/slurm/: STEM_summary.csv (merged), STEM_response.png (a SWEEP deck),
# STEM_envelope.txt (a deck with COMBINE cards) and slurm_run.md (what ran, the comparison,
# the machine). The daemons' files live in a temporary folder, removed at
# the end (kept, and named, when something fails).
set -euo pipefail
# one run time for the runs compared, so that their outputs can be the same bytes (the
# run's date and time are stamped on the outputs: src/run_identity.f90)
export SOURCE_DATE_EPOCH=${SOURCE_DATE_EPOCH:-1700000000}
deck_arg=${1:-input/sweep.dat}
tasks=${2:-3}
[ "$(id -u)" -eq 0 ] || { echo "slurm_array: run as root (it starts slurmctld and slurmd)" >&2; exit 1; }
for cmd in slurmctld slurmd sbatch sinfo munged munge gnuplot; do
    command -v "$cmd" >/dev/null || {
        echo "slurm_array: $cmd is missing (apt-get install slurm-wlm munge gnuplot)" >&2; exit 1; }
done
deck=$(readlink -f "$deck_arg")
[ -f "$deck" ] || { echo "slurm_array: no deck $deck_arg" >&2; exit 1; }
cd "$(dirname "$0")/.."
fpm build --profile release >/dev/null
bin=$(readlink -f "$(fpm run --profile release --runner echo 2>/dev/null | tail -n 1)")
stem=$(basename "$deck" .dat)
work=$(mktemp -d /tmp/fricon_slurm.XXXXXX)
chmod 755 "$work"
mkdir -p "$work/state" "$work/spool"
started_munge=no
ok=no

# stop_all: the daemons this script started, each waited for (at most 20 s)
stop_all() {
    local f pids=() pid
    for f in "$work/slurmd.pid" "$work/slurmctld.pid"; do
        [ -s "$f" ] && pids+=("$(cat "$f")")
    done
    if [ "$started_munge" = yes ] && [ -s /run/munge/munged.pid ]; then
        pids+=("$(cat /run/munge/munged.pid)")
    fi
    for pid in "${pids[@]}"; do
        kill "$pid" 2>/dev/null || continue
        for _ in $(seq 100); do
            kill -0 "$pid" 2>/dev/null || break
            sleep 0.2
        done
    done
    if [ "$ok" = yes ]; then rm -rf "$work"; else echo "slurm_array: files kept in $work" >&2; fi
}
trap stop_all EXIT

# --- munge: the credential service Slurm authenticates with --------------------------------
if ! munge -n 2>/dev/null | unmunge >/dev/null 2>&1; then
    mkdir -p /run/munge /var/lib/munge /var/log/munge
    chown munge:munge /run/munge /var/lib/munge /var/log/munge
    if [ ! -s /etc/munge/munge.key ]; then
        mungekey --create --keyfile=/etc/munge/munge.key
        chown munge:munge /etc/munge/munge.key
        chmod 400 /etc/munge/munge.key
    fi
    runuser -u munge -- munged
    started_munge=yes
    munge -n | unmunge >/dev/null
fi

# --- one node, one partition ------------------------------------------------------------------
host=$(hostname -s)
cpus=$(nproc)
memory=$(awk '/MemTotal/ { printf "%d", $2 / 1024 * 0.9 }' /proc/meminfo)
cat >"$work/slurm.conf" <<EOF
ClusterName=fricon
SlurmctldHost=$host
SlurmUser=root
AuthType=auth/munge
CryptoType=crypto/munge
MpiDefault=none
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
NodeName=$host CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=main Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF=$work/slurm.conf
slurmctld -f "$SLURM_CONF"
slurmd -f "$SLURM_CONF"
for _ in $(seq 60); do
    sinfo -h -o '%T' 2>/dev/null | grep -q idle && break
    sleep 1
done
sinfo -h -o '%T' | grep -q idle || { echo "slurm_array: the node did not come up" >&2; exit 1; }

# --- the job array: README's script, one shard per task ----------------------------------
cat >"$work/job.sh" <<EOF
#!/bin/bash
#SBATCH --job-name=fricon-sweep
#SBATCH --array=1-$tasks
#SBATCH --cpus-per-task=1
#SBATCH --output=$work/task_%a.out
date +%s.%N >"$work/task_\$SLURM_ARRAY_TASK_ID.start"
"$bin" --quiet --jobs "\$SLURM_CPUS_PER_TASK" \\
       --shard "\$SLURM_ARRAY_TASK_ID/$tasks" -o "$work/results" "$deck"
status=\$?
date +%s.%N >"$work/task_\$SLURM_ARRAY_TASK_ID.end"
exit \$status
EOF
start=$(date +%s.%N)
sbatch --wait --parsable "$work/job.sh" >"$work/job_id"
end=$(date +%s.%N)
"$bin" --quiet --merge "$work/results/${stem}"_summary.shard-*-of-"$tasks".csv
"$bin" --quiet -o "$work/serial" "$deck" >/dev/null

# --- every file of the serial run, byte for byte (shards draw no sweep overlay) -----------
compared=0
for f in "$work/serial"/*; do
    name=$(basename "$f")
    case $name in "$stem"_sweep.*) continue ;; esac
    cmp -s "$f" "$work/results/$name" || { echo "slurm_array: $name differs" >&2; exit 1; }
    compared=$((compared + 1))
done

# --- the merged summary and the response figure fricon --merge drew from it -----------------
out=output/slurm
mkdir -p "$out"
cp "$work/results/${stem}_summary.csv" "$out/"
merged_files="[${stem}_summary.csv](${stem}_summary.csv) (merged)"
for extra in "${stem}_response.png" "${stem}_envelope.txt"; do
    if [ -f "$work/results/$extra" ]; then
        cp "$work/results/$extra" "$out/"
        merged_files="$merged_files, [$extra]($extra)"
    fi
done
{
    echo "# The Slurm job array on a real single-node Slurm"
    echo
    echo "Command: \`bash scripts/slurm_array.sh $deck_arg $tasks\` ($(date -u '+%Y-%m-%d %H:%M UTC'))."
    echo "Slurm $(sinfo -V | cut -d' ' -f2), $(munged -V 2>&1 | head -n 1 | cut -d' ' -f1), one node ($host, $cpus cores)."
    echo
    echo "Job $(cat "$work/job_id"): $tasks array tasks, each \`fricon --quiet --jobs 1 --shard I/$tasks\`"
    echo "(its cases with their figures); the tasks ran from the first start to the last end in"
    echo "$(cat "$work"/task_*.start "$work"/task_*.end | sort -n | awk 'NR == 1 { a = $1 } { b = $1 } END { printf "%.2f", b - a }') s;"
    echo "\`sbatch --wait\` returned $(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.1f", b - a }') s after submission (it polls the job's state)."
    echo "Merged by \`fricon --merge\` (summary, response figure of a sweep, envelope of combinations); $compared files compared with a serial run of the deck:"
    echo "all byte-identical (the serial run's overlay ${stem}_sweep.* aside: shards draw none)."
    echo
    echo "Files: $merged_files."
} >"$out/slurm_run.md"
ok=yes
cat "$out/slurm_run.md"
