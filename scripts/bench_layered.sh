#!/usr/bin/env bash
# Layered ground benchmark (the performance targets of the layered ground): first the time to
# build T (example/bench_layered: output/bench/layered.md, .dat, .gp and the figure
# layered.png), then whole cases solved by the release build of fricon, timed as processes
# (wall clock, --no-figures, least of 3 runs), appended to output/bench/layered.md:
#   - bench/layered_plate.dat, a frictional raft on three layers over rock, at N_e = 200
#     against the same deck on the homogeneous half-space of the top layer (SOIL E1 nu1 in
#     place of the LAYER and BASE cards): target at most 3 times the homogeneous time;
#   - the same at N_e = 1000 (MESH 1000): target under 2 s;
#   - bench/layered_sweep_1000.dat, 1000 cases over the layers' moduli and thicknesses (no
#     two share T), the whole process with -j 2: target under 60 s on 2 cores.
# Single cases run with one thread (OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1), with and
# without the error estimates (which re-solve each case on 2 N_e and N_e/2), 5 times each:
# the table gives the median (the machine's 2 cores are shared; the load averages at the
# start and the end are printed with it). With a BEFORE revision the same decks are also
# run by the release build of that commit (checked out in a temporary worktree), the runs of
# the two builds interleaved, and its medians are a column of the table. Run from the
# project root:  bash scripts/bench_layered.sh [BEFORE_REV]   (about 3 minutes, 5 with a
# BEFORE_REV, on 2 shared cores). Each run's wall and processor (user + system) seconds
# are taken by /usr/bin/time; both medians are tabled.
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=scripts/bench_binaries.sh
source scripts/bench_binaries.sh
release_executable bench_layered . || exit 2
bin=$executable
out=output/bench
work=$(mktemp -d "${TMPDIR:-/tmp}/bench_layered.XXXXXX")
trap 'remove_reference_tree "$work/before"; rm -rf "$work"' EXIT
mkdir -p "$out"
# the commit measured (taken before the benchmark rewrites output/bench)
commit="$(git rev-parse --short HEAD)$([ -z "$(git status --porcelain --untracked-files=no)" ] || echo ' + uncommitted changes')"
before_rev=${1:-}
before_bin=''
if [ -n "$before_rev" ]; then
    add_reference_tree bench_layered "$before_rev" "$work/before" || exit 2
    release_executable bench_layered "$work/before" || exit 2
    before_bin=$executable
    before_rev=$(git rev-parse --short "$before_rev")
fi
load_start=$(cut -d' ' -f1-3 /proc/loadavg)

OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 fpm run --profile release --example bench_layered \
    >/dev/null
gnuplot "$out/layered.gp"

# the decks of the single cases: layered and homogeneous, N_e = 200 and 1000
homogeneous() { sed -e 's/^LAYER     4.0       8.0E3     0.45 *$/SOIL      8.0E3     0.45/' \
    -e '/^LAYER/d' -e '/^BASE/d' "$1"; }
mesh1000() { sed -e 's/^MESH      200$/MESH      1000/' "$1"; }
cp bench/layered_plate.dat "$work/layered_200.dat"
homogeneous bench/layered_plate.dat >"$work/homogeneous_200.dat"
mesh1000 "$work/layered_200.dat" >"$work/layered_1000.dat"
mesh1000 "$work/homogeneous_200.dat" >"$work/homogeneous_1000.dat"
for f in homogeneous_200 homogeneous_1000 layered_1000; do
    cmp -s "$work/$f.dat" "$work/layered_200.dat" && { echo "bench_layered: $f unchanged" >&2; exit 2; }
done

# wall SECONDS of one run: wall ARGS...
wall() {
    local s e
    s=$(date +%s.%N)
    "$@" >/dev/null 2>&1 || { echo "bench_layered: failed: $*" >&2; exit 2; }
    e=$(date +%s.%N)
    awk -v a="$s" -v b="$e" 'BEGIN { printf "%.3f", b - a }'
}
# one single-thread run: single BINARY DECK [OPTION...] prints "wall processor" seconds
# (processor: user + system, which other jobs on the cores inflate much less than wall)
single() {
    local program=$1 deck=$2
    shift 2
    rm -rf "$work/out"
    OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 /usr/bin/time -f '%e %U %S' -o "$work/time.txt" \
        "$program" --no-figures -q "$@" -o "$work/out" "$deck" >/dev/null 2>&1 \
        || { echo "bench_layered: failed: $program $deck $*" >&2; exit 2; }
    awk '{ printf "%.3f %.3f", $1, $2 + $3 }' "$work/time.txt"
}
median() { printf '%s\n' "$@" | sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", a / b }'; }

# medians of 5 runs (wall: t, processor: p), this build's and the BEFORE build's (tb, pb)
# interleaved
declare -A t p tb pb
for est in yes no; do
    opt=()
    [ "$est" = no ] && opt=(--no-estimates)
    for f in homogeneous_200 layered_200 homogeneous_1000 layered_1000; do
        walls=()
        procs=()
        walls_before=()
        procs_before=()
        for _ in 1 2 3 4 5; do
            read -r w c <<<"$(single "$bin" "$work/$f.dat" "${opt[@]}")"
            [ -n "$c" ] || exit 2
            walls+=("$w")
            procs+=("$c")
            if [ -n "$before_bin" ]; then
                read -r w c <<<"$(single "$before_bin" "$work/$f.dat" "${opt[@]}")"
                [ -n "$c" ] || exit 2
                walls_before+=("$w")
                procs_before+=("$c")
            fi
        done
        t[$f,$est]=$(median "${walls[@]}")
        p[$f,$est]=$(median "${procs[@]}")
        if [ -n "$before_bin" ]; then
            tb[$f,$est]=$(median "${walls_before[@]}")
            pb[$f,$est]=$(median "${procs_before[@]}")
        fi
    done
done
load_end=$(cut -d' ' -f1-3 /proc/loadavg)
rm -rf "$work/sweep"
sweep_est=$(wall "$bin" --no-figures -q -j 2 -o "$work/sweep" bench/layered_sweep_1000.dat)
rows=$(($(grep -vc '^#' "$work/sweep/layered_sweep_1000_summary.csv") - 1))   # header and # lines out
rm -rf "$work/sweep"
sweep_no=$(wall "$bin" --no-figures -q --no-estimates -j 2 -o "$work/sweep" \
    bench/layered_sweep_1000.dat)

{
    echo
    echo "## Whole cases (scripts/bench_layered.sh)"
    echo
    echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'),"
    echo "$(free -g | awk '/Mem:/ { print $2 }') GB, $(uname -sr), shared with other jobs; commit"
    echo "$commit, $(date -u +%Y-%m-%d). Load averages (1, 5, 15 min) $load_start at the start"
    echo "of the single cases, $load_end at their end. Release build; the whole process (deck"
    echo "read, solve, every output but the PNG: --no-figures), 5 runs each, one thread"
    echo "(OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1). The homogeneous case is"
    echo "bench/layered_plate.dat with SOIL 8000 kPa 0.45 (the top layer) in place of its three"
    echo "layers (h 4, 6, 10 m; E 8, 20, 60 MPa; nu 0.45, 0.35, 0.3) on a ROUGH base."
    [ -n "$before_bin" ] && echo "\"before\": the release build of commit $before_rev, its runs interleaved with these."
    for kind in wall processor; do
        echo
        if [ "$kind" = wall ]; then
            echo "Wall seconds (median of 5):"
        else
            echo "Processor seconds, user + system (median of 5; what a run takes on an idle core):"
        fi
        echo
        if [ -n "$before_bin" ]; then
            echo "| case | N_e | estimates | homogeneous s | layered s | ratio | target | homogeneous s before | layered s before |"
            echo "|---|---:|---|---:|---:|---:|---|---:|---:|"
        else
            echo "| case | N_e | estimates | homogeneous s | layered s | ratio | target |"
            echo "|---|---:|---|---:|---:|---:|---|"
        fi
        for est in yes no; do
            for ne in 200 1000; do
                if [ "$kind" = wall ]; then
                    h=${t[homogeneous_$ne,$est]}
                    l=${t[layered_$ne,$est]}
                    hb=${tb[homogeneous_$ne,$est]:-}
                    lb=${tb[layered_$ne,$est]:-}
                else
                    h=${p[homogeneous_$ne,$est]}
                    l=${p[layered_$ne,$est]}
                    hb=${pb[homogeneous_$ne,$est]:-}
                    lb=${pb[layered_$ne,$est]:-}
                fi
                if [ "$ne" = 200 ]; then
                    target="ratio <= 3: $(awk -v r="$(ratio "$l" "$h")" 'BEGIN { print (r <= 3) ? "met" : "MISSED" }')"
                else
                    target="layered < 2 s: $(awk -v a="$l" 'BEGIN { print (a < 2) ? "met" : "MISSED" }')"
                fi
                row="| frictional raft, 3 layers on rock | $ne | $est | $h | $l | $(ratio "$l" "$h") | $target |"
                [ -n "$before_bin" ] && row="$row $hb | $lb |"
                echo "$row"
            done
        done
    done
    echo
    echo "With estimates a case is solved three times: on its mesh, on 2 N_e and on N_e/2 (the"
    echo "estimate's re-solves, --no-estimates drops them); at N_e = 1000 one of them has 2000"
    echo "elements (T of 4002 unknowns); the rows with and without estimates differ by their time,"
    echo "for the homogeneous half-space as well. The 2 s target holds for the case's one"
    echo "solve; with the estimates' two re-solves it is missed when the row above says MISSED."
    echo
    echo "Sweep bench/layered_sweep_1000.dat: $rows cases (5 E1 x 5 H1 x 5 E2 x 2 H2 x 2 E3 x"
    echo "2 DEPTH, N_e = 40, every case its own T), the whole process with -j 2 --no-figures:"
    echo
    echo "| estimates | wall s | per case ms | target |"
    echo "|---|---:|---:|---|"
    for est in yes no; do
        s=$sweep_est
        [ "$est" = no ] && s=$sweep_no
        echo "| $est | $s | $(awk -v a="$s" -v n="$rows" 'BEGIN { printf "%.1f", 1000 * a / n }') | < 60 s: $(awk -v a="$s" 'BEGIN { print (a < 60) ? "met" : "MISSED" }') |"
    done
} >>"$out/layered.md"
sed -n '/^## Whole cases/,$p' "$out/layered.md"
