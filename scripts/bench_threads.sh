#!/usr/bin/env bash
# Threads of one case (seventh session): the whole program on one deck, as a user runs it
# (no OMP_*/OPENBLAS_* variables: OpenMP and OpenBLAS take every core), wall time of two
# builds run alternately, plus the "before" build on one thread of each for reference.
#
#   bash scripts/bench_threads.sh BEFORE_BIN AFTER_BIN [REPS]
#
# BEFORE_BIN, AFTER_BIN: two fricon executables (e.g. release builds of two commits, copied
# out of build/). Writes output/bench/blas_threads.md (table), blas_threads.dat and
# blas_threads.png (figure), and checks that each case's data file is the same, byte for
# byte, from AFTER_BIN with the default threads and from BEFORE_BIN on one thread.
set -euo pipefail
# one run time for the runs compared, so that their outputs can be the same bytes (the
# run's date and time are stamped on the outputs: src/run_identity.f90)
export SOURCE_DATE_EPOCH=${SOURCE_DATE_EPOCH:-1700000000}
if [ $# -lt 2 ]; then
    echo "usage: bash scripts/bench_threads.sh BEFORE_BIN AFTER_BIN [REPS]" >&2
    exit 1
fi
# shellcheck source=scripts/bench_binaries.sh
source "$(dirname "$0")/bench_binaries.sh"
two_binaries bench_threads "$1" "$2"    # paths as the caller gave them, before changing folder
reps=${3:-7}
cd "$(dirname "$0")/.."
out=output/bench
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
# the results are written in $work and moved into $out only when every run has succeeded
md=$work/blas_threads.md
dat=$work/blas_threads.dat

# wall microseconds of one run; the outputs go to $work/<tag>; a failed run stops the script
# with its messages (the committed results stay as they were)
run() {
    local tag=$1 bin=$2
    shift 2
    local s e
    s=$(date +%s%N)
    if ! env -u OMP_NUM_THREADS -u OPENBLAS_NUM_THREADS "$@" "$bin" -q --no-figures \
        -o "$work/$tag" "$work/deck.dat" >/dev/null 2>"$work/stderr"; then
        echo "bench_threads: $bin failed on $work/deck.dat:" >&2
        cat "$work/stderr" >&2
        exit 1
    fi
    e=$(date +%s%N)
    echo $(((e - s) / 1000))
}

least() { sort -n | head -n 1; }

{
    echo "# Threads of one case: OpenBLAS threads off (seventh session)"
    echo
    echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'),"
    echo "$(date -u '+%Y-%m-%d %H:%M UTC'), load average before: $(cut -d' ' -f1-3 /proc/loadavg)."
    echo "Command: \`bash scripts/bench_threads.sh BEFORE AFTER $reps\`; each cell the least wall time"
    echo "of $reps runs of the whole program (\`fricon -q --no-figures DECK\`: read, solve, error"
    echo "estimates, report and data files; no PNG), the three builds/settings run in turn."
    echo "**before** = the build that let a single case use OpenBLAS's threads (every core), run"
    echo "as a user runs it (no thread variables); **after** = the build whose cases all use one"
    echo "BLAS thread, run the same way; **before, 1 thread** = the before build with"
    echo "\`OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1\`. Same data file: the after build's"
    echo "\`.dat\` byte for byte that of the before build on one thread."
    echo
    echo "| deck | N_e | before ms | after ms | after / before | before, 1 thread ms | same data file |"
    echo "|---|---:|---:|---:|---:|---:|---|"
} >"$md"
echo "# deck_index N_e before_ms after_ms before_1thread_ms" >"$dat"

k=0
for deck in input/plate_nondim.dat input/beam_nondim.dat; do
    k=$((k + 1))
    for ne in 20 50 100 200 500 1000; do
        sed "s/^MESH .*/MESH      $ne/" "$deck" >"$work/deck.dat"
        : >"$work/b"
        : >"$work/a"
        : >"$work/s"
        for _ in $(seq "$reps"); do
            run before "$before" >>"$work/b"
            run after "$after" >>"$work/a"
            run single "$before" OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 >>"$work/s"
        done
        b=$(least <"$work/b")
        a=$(least <"$work/a")
        s=$(least <"$work/s")
        same=no
        cmp -s "$work/after/deck.dat" "$work/single/deck.dat" && same=yes
        awk -v d="$deck" -v n="$ne" -v b="$b" -v a="$a" -v s="$s" -v same="$same" 'BEGIN {
            printf "| %s | %d | %.1f | %.1f | %.2f | %.1f | %s |\n", d, n, b / 1000, a / 1000,
                   a / b, s / 1000, same }' >>"$md"
        echo "$k $ne $(awk -v b="$b" -v a="$a" -v s="$s" 'BEGIN { print b / 1000, a / 1000, s / 1000 }')" \
            >>"$dat"
    done
done
echo >>"$md"
echo "Load average after: $(cut -d' ' -f1-3 /proc/loadavg)." >>"$md"
mv "$md" "$dat" "$out/"

if command -v gnuplot >/dev/null 2>&1; then
    gnuplot <<GP
set terminal pngcairo size 1100,440 noenhanced
set output '$out/blas_threads.png'
set multiplot layout 1,2 title 'One case, whole program (fricon -q --no-figures), as a user runs it'
set logscale x
set xrange [15:1300]
set xtics (20, 50, 100, 200, 500, 1000)
set xlabel 'N_e'
set grid
set key top left
set title 'wall time'
set logscale y
set ylabel 'wall time [ms]'
plot '$out/blas_threads.dat' using (\$1 == 1 ? \$2 : 1/0):3 with linespoints lw 2 pt 6 lc 1 title 'plate, before (OpenBLAS threads)', \
     '' using (\$1 == 1 ? \$2 : 1/0):4 with linespoints lw 2 pt 7 lc 2 title 'plate, after (one BLAS thread)', \
     '' using (\$1 == 2 ? \$2 : 1/0):3 with linespoints lw 2 pt 4 lc 3 title 'beam, before', \
     '' using (\$1 == 2 ? \$2 : 1/0):4 with linespoints lw 2 pt 5 lc 4 title 'beam, after'
set title 'after / before (below 1: faster)'
unset logscale y
set yrange [0.7:1.3]
set ylabel 'wall time after / before'
plot '$out/blas_threads.dat' using (\$1 == 1 ? \$2 : 1/0):(\$4/\$3) with linespoints lw 2 pt 7 lc 2 title 'plate', \
     '' using (\$1 == 2 ? \$2 : 1/0):(\$4/\$3) with linespoints lw 2 pt 5 lc 4 title 'beam', \
     1 with lines dt 2 lc rgb 'black' notitle
unset multiplot
GP
fi
cat "$out/blas_threads.md"
