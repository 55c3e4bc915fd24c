#!/usr/bin/env bash
# Peak resident memory (GNU time's "Maximum resident set size") of one case per model kind,
# against its unknowns n = 5 (N_e + 1) (P1 fields), to fit the memory model of
# src/resource_limits.f90: bytes ~ base + c n^2 per kind and method. Cases (NONDIM, rho 0.01,
# zeta 0.1, --no-figures --no-estimates): a frictional plate (f 0.6, disk patch r <= 0.5 a),
# a symmetric beam (f 0.6, central point load: solved on half the beam), an asymmetric beam
# (f 0.6, point load at 0.1 l with F_x 0.1), the plate at f 0 (no sigma_x), and the plate
# with the two-loop method. Run from the project root after fpm build:
#   bash scripts/memory_table.sh [N_E...]     (default 250 500 1000 2000 3000; prints a table)
set -uo pipefail
cd "$(dirname "$0")/.."
bin=$(readlink -f "$(fpm run --runner echo 2>/dev/null | tail -n 1)")
sizes=${*:-250 500 1000 2000 3000}
dir=$(mktemp -d)
deck() { # deck KIND NE -> the deck text
    local solver=''
    case $1 in
        plate)   printf '%-10s%s\n' MODEL PLATE NONDIM '0.01      0.1' FRICTION 0.6 \
                     LOAD 'PATCH     1.0                 0.0       0.5' ;;
        plate_f0) printf '%-10s%s\n' MODEL PLATE NONDIM '0.01      0.1' FRICTION 0.0 \
                     LOAD 'PATCH     1.0                 0.0       0.5' ;;
        plate_twoloop) printf '%-10s%s\n' MODEL PLATE NONDIM '0.01      0.1' FRICTION 0.6 \
                     LOAD 'PATCH     1.0                 0.0       0.5' \
                     SOLVER '                                                            TWOLOOP' ;;
        beam_sym) printf '%-10s%s\n' MODEL BEAM NONDIM '0.01      0.1                           0.1' \
                     FRICTION 0.6 LOAD 'POINT     1.0' ;;
        beam_asym) printf '%-10s%s\n' MODEL BEAM NONDIM '0.01      0.1                           0.1' \
                     FRICTION 0.6 LOAD 'POINT     1.0       0.1       0.1' ;;
    esac
    printf '%-10s%s\n' MESH "$2" END ''
}
echo "| case | N_e | n | exit | wall [s] | peak RSS [MB] | (RSS - base)/n^2 [bytes] |"
echo "|---|---|---|---|---|---|---|"
base_kb=
for kind in plate beam_sym beam_asym plate_f0 plate_twoloop; do
    for ne in 10 $sizes; do
        # the two-loop method takes minutes from N_e 1000 (290 s): its slope from N_e <= 500
        [ "$kind" = plate_twoloop ] && [ "$ne" -gt 500 ] && continue
        deck $kind $ne > "$dir/case.dat"
        /usr/bin/time -v "$bin" -q --no-figures --no-estimates -o "$dir/out" "$dir/case.dat" \
            > /dev/null 2> "$dir/time.log"
        rc=$?
        kb=$(awk -F': ' '/Maximum resident set size/ {print $2}' "$dir/time.log")
        wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {print $2}' "$dir/time.log" | awk -F: '{print $(NF-1)*60 + $NF}')
        if [ "$ne" -eq 10 ]; then base_kb=$kb; continue; fi
        n=$((5 * (ne + 1)))
        per=$(awk -v kb="$kb" -v b="$base_kb" -v n="$n" 'BEGIN { printf "%.2f", (kb - b) * 1024 / (n * n) }')
        echo "| $kind | $ne | $n | $rc | $wall | $(awk -v kb="$kb" 'BEGIN { printf "%.1f", kb/1024 }') | $per |"
    done
    echo "| $kind base (N_e 10) | | | | | $(awk -v kb="$base_kb" 'BEGIN { printf "%.1f", kb/1024 }') | |"
done
rm -rf "$dir"
