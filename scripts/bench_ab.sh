#!/usr/bin/env bash
# Before/after timing of two fricon executables on the same decks, run alternately on one
# thread each (OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1, -j 1, --no-figures): for each deck the
# least wall time and the least processor time (user + system) of REPS runs of each build, and
# whether the two builds wrote the same files, byte for byte. Prints a Markdown table. The
# timer (/usr/bin/time) resolves 10 ms: give decks of about half a second or more (a sweep).
#
#   bash scripts/bench_ab.sh BEFORE_BIN AFTER_BIN REPS DECK...
#
# BEFORE_BIN, AFTER_BIN: e.g. release builds of two commits copied out of build/.
set -euo pipefail
# one run time for the runs compared, so that their outputs can be the same bytes (the
# run's date and time are stamped on the outputs: src/run_identity.f90)
export SOURCE_DATE_EPOCH=${SOURCE_DATE_EPOCH:-1700000000}
if [ $# -lt 4 ]; then
    echo "usage: bash scripts/bench_ab.sh BEFORE_BIN AFTER_BIN REPS DECK..." >&2
    exit 1
fi
# shellcheck source=scripts/bench_binaries.sh
source "$(dirname "$0")/bench_binaries.sh"
two_binaries bench_ab "$1" "$2"    # paths as the caller gave them, before changing folder
reps=$3
shift 3
decks=()
for deck in "$@"; do decks+=("$(readlink -f "$deck")"); done
[ -x /usr/bin/time ] || { echo "bench_ab: /usr/bin/time is missing (Debian package time)" >&2; exit 1; }
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(date -u '+%Y-%m-%d %H:%M UTC'), load average $(cut -d' ' -f1-3 /proc/loadavg)."
echo "Command: \`bash scripts/bench_ab.sh BEFORE AFTER $reps $*\`: the least of $reps runs of each build, alternately."
echo
echo "| deck | before wall s | after wall s | before cpu s | after cpu s | after / before (cpu) | same files |"
echo "|---|---:|---:|---:|---:|---:|---|"
for deck in "${decks[@]}"; do
    : >"$work/times"
    failed=0
    for _ in $(seq "$reps"); do
        for tag in before after; do
            bin=$before
            [ "$tag" = after ] && bin=$after
            rm -rf "${work:?}/$tag"
            # a run that fails (exit status other than 0) is counted and its table row marked
            if ! OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 /usr/bin/time -f "$tag %e %U %S" \
                "$bin" -q --no-figures -j 1 -o "$work/$tag" "$deck" >/dev/null 2>>"$work/times"; then
                failed=$((failed + 1))
            fi
        done
    done
    same=no
    diff -rq "$work/before" "$work/after" >/dev/null 2>&1 && same=yes
    [ "$failed" -gt 0 ] && same="$same; $failed runs FAILED"
    grep -E '^(before|after) ' "$work/times" | awk -v d="${deck#"$PWD"/}" -v same="$same" '
        { c = $3 + $4
          if (!($1 in w) || $2 < w[$1]) w[$1] = $2
          if (!($1 in u) || c < u[$1]) u[$1] = c }
        END { ratio = "-"
              if (u["before"] > 0) ratio = sprintf("%.2f", u["after"] / u["before"])
              printf "| %s | %.2f | %.2f | %.2f | %.2f | %s | %s |\n", d, w["before"], w["after"],
                     u["before"], u["after"], ratio, same }'
done
