#!/usr/bin/env bash
# Sweep scaling (issue 9): bench/sweep_1000.dat (1000 small cases) solved with --jobs 1 and
# --jobs 2, no figures; writes output/bench/sweep_scaling.md with the machine, the wall times
# and whether the two summaries are identical. Run from the project root after fpm build.
set -euo pipefail
# one run time for the runs compared, so that their outputs can be the same bytes (the
# run's date and time are stamped on the outputs: src/run_identity.f90)
export SOURCE_DATE_EPOCH=${SOURCE_DATE_EPOCH:-1700000000}
cd "$(dirname "$0")/.."
fpm build >/dev/null
bin=$(fpm run --runner echo 2>/dev/null | tail -n 1)
out=output/bench
mkdir -p "$out"
t() { local s e; s=$(date +%s.%N); "$@" >/dev/null 2>&1 || true; e=$(date +%s.%N); awk -v a="$s" -v b="$e" 'BEGIN { print b - a }'; }
rm -rf "$out/sweep_j1" "$out/sweep_j2"
t1=$(t "$bin" --no-figures -q -j 1 -o "$out/sweep_j1" bench/sweep_1000.dat)
t2=$(t "$bin" --no-figures -q -j 2 -o "$out/sweep_j2" bench/sweep_1000.dat)
same=no
cmp -s "$out/sweep_j1/sweep_1000_summary.csv" "$out/sweep_j2/sweep_1000_summary.csv" && same=yes
rows=$(($(wc -l <"$out/sweep_j1/sweep_1000_summary.csv") - 1))
{
    echo "# Sweep scaling: bench/sweep_1000.dat, $rows cases, --no-figures"
    echo
    echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(date -u +%Y-%m-%d)."
    echo
    echo "| jobs | wall time [s] | speed-up |"
    echo "|---|---|---|"
    printf '| 1 | %.1f | 1.00 |\n' "$t1"
    printf '| 2 | %.1f | %.2f |\n' "$t2" "$(awk -v a="$t1" -v b="$t2" 'BEGIN { print a / b }')"
    echo
    echo "Summaries of the two runs identical: $same."
} >"$out/sweep_scaling.md"
rm -rf "$out/sweep_j1" "$out/sweep_j2"
cat "$out/sweep_scaling.md"
