#!/usr/bin/env bash
# What the calculation record (CASE.html) costs: whole runs with and without --no-html,
# alternately, REPS times each (default 5), median wall times. Two runs: the strip footing
# as a user runs it (figures on: the record embeds the PNG), and bench/sweep_1000.dat (1000
# small cases, --no-figures, one job). Writes output/bench/html_record_cost.md. Run from the
# project root; builds the release profile.
#   bash scripts/bench_records.sh [REPS]
set -euo pipefail
export SOURCE_DATE_EPOCH=${SOURCE_DATE_EPOCH:-1700000000}
reps=${1:-5}
cd "$(dirname "$0")/.."
fpm build --profile release >/dev/null
bin=$(fpm run --profile release --runner echo 2>/dev/null | tail -n 1)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
t() { local s e; s=$(date +%s.%N); "$@" >/dev/null 2>&1 || true; e=$(date +%s.%N); awk -v a="$s" -v b="$e" 'BEGIN { print b - a }'; }
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
run_pair() {   # label, then the arguments of fricon; prints "label | with | without | bytes"
    local label=$1; shift
    local with=() without=()
    for ((r = 1; r <= reps; r++)); do
        rm -rf "$work/a" "$work/b"
        with+=("$(t "$bin" -q -o "$work/a" "$@")")
        without+=("$(t "$bin" -q --no-html -o "$work/b" "$@")")
    done
    local bytes
    bytes=$(cat "$work"/a/*.html 2>/dev/null | wc -c)
    printf '| %s | %.3f | %.3f | %s |\n' "$label" \
        "$(printf '%s\n' "${with[@]}" | median)" "$(printf '%s\n' "${without[@]}" | median)" "$bytes"
}
{
    echo "# The calculation record's cost: runs with and without --no-html"
    echo
    echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(date -u +%Y-%m-%d); release build; median of $reps runs of each, alternately (\`bash scripts/bench_records.sh $reps\`)."
    echo
    echo "| run | with records [s] | --no-html [s] | bytes of the records |"
    echo "|---|---|---|---|"
    run_pair 'input/strip_footing.dat (one case, figure)' input/strip_footing.dat
    run_pair 'bench/sweep_1000.dat (1000 cases, --no-figures, -j 1)' --no-figures -j 1 bench/sweep_1000.dat
} >"$work/table.md"
mkdir -p output/bench
cp "$work/table.md" output/bench/html_record_cost.md
cat output/bench/html_record_cost.md
