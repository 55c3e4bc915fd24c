#!/usr/bin/env bash
# Joins the summaries of a sweep run in shards (fricon --shard I/N DECK, e.g. the tasks of a
# Slurm job array) into the summary a single run writes:
#   bash scripts/merge_shards.sh output/STEM
# reads output/STEM_summary.shard-*-of-N.csv (all N present, each with a '#' line of the
# program, version and run time and the header) and writes output/STEM_summary.csv: the
# first shard's two lines once, then the rows in case order (case names are
# zero-padded, so their text order is their number order). Refuses a missing shard.
# `fricon --merge SHARD...` does the same with more checks and draws the response figure.
set -euo pipefail
base=${1:?usage: merge_shards.sh OUTPUT/STEM}
shopt -s nullglob
shards=("$base"_summary.shard-*-of-*.csv)
[ ${#shards[@]} -gt 0 ] || { echo "merge_shards.sh: no $base""_summary.shard-*.csv" >&2; exit 1; }
n=${shards[0]##*-of-}; n=${n%.csv}
for ((i = 1; i <= n; i++)); do
    [ -f "$base"_summary.shard-$i-of-$n.csv ] || { echo "merge_shards.sh: shard $i of $n missing" >&2; exit 1; }
done
out="$base"_summary.csv
{
    head -n 2 "$base"_summary.shard-1-of-$n.csv
    for ((i = 1; i <= n; i++)); do tail -n +3 "$base"_summary.shard-$i-of-$n.csv; done | LC_ALL=C sort -t, -k1,1
} >"$out.tmp"
mv "$out.tmp" "$out"
echo "merge_shards.sh: $n shards -> $out"
