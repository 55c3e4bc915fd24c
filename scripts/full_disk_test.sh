#!/usr/bin/env bash
# Faults: input/sweep.dat (6 cases) written into tmpfs folders too small for it (16 to 120 kB
# in steps of 8 kB; needs root for mount), then checked against a run on a roomy disk (the
# output is deterministic): every file left under its final name is byte for byte the
# reference's (no partial file, even one cut at a line end), no .tmp is left, and a run that
# ends with exit 1 (a case could not write its files) leaves no sweep summary CSV or overlay
# script (they would summarise part of the sweep). Run from the project root after fpm build:
#   sudo bash scripts/full_disk_test.sh [BINARY]     (writes output/bench/full_disk_test.txt)
set -uo pipefail
# one run time for the runs compared, so that their outputs can be the same bytes (the
# run's date and time are stamped on the outputs: src/run_identity.f90)
export SOURCE_DATE_EPOCH=${SOURCE_DATE_EPOCH:-1700000000}
cd "$(dirname "$0")/.."
bin=${1:-$(fpm run --runner echo 2>/dev/null | tail -n 1)}
bin=$(readlink -f "$bin")
deck=$(readlink -f input/sweep.dat)
work=$(mktemp -d)
log=output/bench/full_disk_test.txt
mkdir -p output/bench "$work/ref" "$work/disk"
"$bin" -q --no-figures -o "$work/ref" "$deck" > /dev/null 2>&1 || { echo "reference run failed"; exit 1; }
bad_runs=0
{
    echo "# Full-disk test: input/sweep.dat (--no-figures) into tmpfs folders of 16 to 120 kB, and 400 kB (room for all)"
    echo "# machine: $(nproc) cores; $(date -u +%Y-%m-%d); reference: $(ls "$work/ref" | wc -l) files, $(du -sk "$work/ref" | cut -f1) kB"
    for kb in $(seq 16 8 120) 400; do
        mount -t tmpfs -o size=${kb}k tmpfs "$work/disk" || { echo "cannot mount a tmpfs (root?)"; exit 1; }
        "$bin" -q --no-figures -o "$work/disk" "$deck" > /dev/null 2> "$work/stderr"
        rc=$?
        problems=""
        for f in $(ls "$work/disk"); do
            case "$f" in
                *.tmp) problems="$problems $f(temporary)" ;;
                *) cmp -s "$work/disk/$f" "$work/ref/$f" || problems="$problems $f(differs)" ;;
            esac
        done
        if [ "$rc" -ne 0 ]; then
            for f in sweep_summary.csv sweep_sweep.gp; do
                [ -e "$work/disk/$f" ] && problems="$problems $f(left after exit $rc)"
            done
        fi
        echo "${kb} kB: exit $rc, $(ls "$work/disk" | wc -l) files left;${problems:- ok}"
        [ -n "$problems" ] && bad_runs=$((bad_runs + 1))
        umount "$work/disk"
    done
    echo "runs with a partial, temporary or summary file left: $bad_runs"
} | tee "$log"
rm -rf "$work"
! grep -q "summary file left: [1-9]" "$log"
