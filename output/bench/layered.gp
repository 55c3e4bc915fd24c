# bench_layered: run from the project folder: gnuplot output/bench/layered.gp
set terminal pngcairo size 1400,600 font 'Sans,11' noenhanced
set output 'output/bench/layered.png'
set multiplot layout 1,2 title 'fricon: time to build T on layered ground (P1, EDGES, 1 thread)' font 'Sans,14'
set logscale xy; set grid; set format y "%.0e"
set xtics (20, 50, 100, 200, 500, 1000); set xrange [15:1300]
set xlabel 'N_e'; set ylabel 'processor time [s]'
set key left top box opaque
set title 'PLATE'
plot 'output/bench/layered.dat' index 0 using 1:2 with linespoints lw 2 pt 4 lc rgb 'black' title 'homogeneous T', 'output/bench/layered.dat' index 0 using 1:3 with linespoints lw 2 pt 5 lc rgb '#1f77b4' title 'layered T, 1 layer', 'output/bench/layered.dat' index 1 using 1:3 with linespoints lw 2 pt 7 lc rgb '#ff7f0e' title 'layered T, 3 layers', 'output/bench/layered.dat' index 2 using 1:3 with linespoints lw 2 pt 9 lc rgb '#2ca02c' title 'layered T, 10 layers', 'output/bench/layered.dat' index 0 using 1:4 with linespoints lw 2 dt 2 pt 6 lc rgb 'gray40' title 'one LU of T'
set title 'BEAM'
plot 'output/bench/layered.dat' index 3 using 1:2 with linespoints lw 2 pt 4 lc rgb 'black' title 'homogeneous T', 'output/bench/layered.dat' index 3 using 1:3 with linespoints lw 2 pt 5 lc rgb '#1f77b4' title 'layered T, 1 layer', 'output/bench/layered.dat' index 4 using 1:3 with linespoints lw 2 pt 7 lc rgb '#ff7f0e' title 'layered T, 3 layers', 'output/bench/layered.dat' index 5 using 1:3 with linespoints lw 2 pt 9 lc rgb '#2ca02c' title 'layered T, 10 layers', 'output/bench/layered.dat' index 3 using 1:4 with linespoints lw 2 dt 2 pt 6 lc rgb 'gray40' title 'one LU of T'
unset multiplot
