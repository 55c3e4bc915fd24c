#!/usr/bin/env bash
# Figures of the solver benchmark (issue 7): from output/bench/bench_table.txt (written by
# `fpm run --profile release --example fricon_bench -- input/paper/*.dat`) draws
# output/bench/bench_solves.png: the distribution of linear solves per case, NEWTON against
# TWOLOOP (paper decks and the hard grid), and the time per case against N_e.
set -euo pipefail
cd "$(dirname "$0")/.."
t=output/bench/bench_table.txt
# columns after the 48-character case label: N_e, method, solves, nested, time, outcome
awk '$1 !~ /^#/ { n = split(substr($0, 56), f, " "); if (f[6] == "solved") print f[1], f[2], f[3], f[5], f[3] + f[4] }' "$t" >/tmp/bench_rows.txt
gnuplot <<GP
set terminal pngcairo size 1500,600 font 'Sans,11' noenhanced
set output 'output/bench/bench_solves.png'
set multiplot layout 1,2 title 'Solver benchmark (output/bench/bench_table.txt): solved cases, NEWTON (default) against TWOLOOP (the paper)' font 'Sans,13'
set grid; set key top left
set title 'linear solves per case (sorted)'
set xlabel 'cases, sorted by solves'; set ylabel 'linear solves'; set logscale y
plot '< grep NEWTON /tmp/bench_rows.txt | sort -n -k3' u 0:3 w lp pt 7 ps 0.6 lw 2 lc rgb '#9400d3' t 'NEWTON', \
     '< grep NEWTON /tmp/bench_rows.txt | sort -n -k5' u 0:5 w l lw 1 dt 3 lc rgb '#9400d3' t 'NEWTON, with the solves on nested coarser meshes', \
     '< grep TWOLOOP /tmp/bench_rows.txt | sort -n -k3' u 0:3 w lp pt 5 ps 0.6 lw 2 lc rgb '#56b4e9' t 'TWOLOOP', \
     30 w l dt 2 lc rgb '#7f7f7f' t 'target: none over 30'
set title 'time per case against N_e'
set xlabel 'N_e'; set ylabel 'discretise + solve [s]'; set logscale xy
set key bottom right; set offsets 0, 0, graph 0.08, 0
plot '< grep NEWTON /tmp/bench_rows.txt' u 1:4 w p pt 7 ps 0.8 lc rgb '#9400d3' t 'NEWTON', \
     '< grep TWOLOOP /tmp/bench_rows.txt' u 1:4 w p pt 5 ps 0.8 lc rgb '#56b4e9' t 'TWOLOOP'
unset multiplot
GP
echo "bench_figures.sh: output/bench/bench_solves.png"
