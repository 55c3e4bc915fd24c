#!/usr/bin/env bash
# A deck too large for the machine is refused before anything is built that costs more than
# linear time in N_e: P1, P2 and S2 beams at N_e 99999 (every field of the interpolation)
# must end with exit 1 and the memory message within a limit of 5 s each (the refusal itself
# takes well under a second; 5 s leaves room for a loaded machine, and an S2 knot vector grown
# one entry at a time took 8 to 30 s). Run from the project root after fpm build:
#   bash scripts/large_mesh_refusal.sh [BINARY]   (writes output/bench/large_mesh_refusal.md)
set -uo pipefail
cd "$(dirname "$0")/.."
bin=${1:-$(fpm run --runner echo 2>/dev/null | tail -n 1)}
bin=$(readlink -f "$bin")
dir=$(mktemp -d)
log=output/bench/large_mesh_refusal.md
limit=5
failed=0
mkdir -p output/bench
{
    echo "# Refusal of a mesh too large for memory (N_e 99999, BEAM, NONDIM)"
    echo
    echo "machine: $(nproc) cores, $(awk '/MemTotal/ {printf "%.0f GB", $2/1048576}' /proc/meminfo); $(date -u +%Y-%m-%d); limit $limit s"
    echo
    echo "| interpolation | exit | wall time [s] | refused by the memory check |"
    echo "|---|---|---|---|"
    for p in P1 P2 S2; do
        deck=$dir/big_$p.dat
        printf '%-10s%s\n' MODEL BEAM NONDIM '0.01      0.1                           1.0' \
            FRICTION 0.0 LOAD 'POINT     1.0' \
            MESH "99999               $p        $p        $p        $p        $p" END "" > "$deck"
        start=$(date +%s.%N)
        timeout "$limit" "$bin" -q -o "$dir/out" "$deck" > /dev/null 2> "$dir/err_$p"
        rc=$?
        wall=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.3f", b - a }')
        memory=no
        grep -q 'GB usable on this machine' "$dir/err_$p" && memory=yes
        [ "$rc" -eq 1 ] && [ "$memory" = yes ] || failed=$((failed + 1))
        echo "| $p | $rc$([ "$rc" -eq 124 ] && echo ' (timed out)') | $wall | $memory |"
    done
    echo
    echo "cases not refused by the memory check within $limit s: $failed"
} | tee "$log"
rm -rf "$dir"
! grep -q 'within [0-9]* s: [1-9]' "$log"
