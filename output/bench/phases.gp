# bench_phases: run from the project folder: gnuplot output/bench/phases.gp
set terminal pngcairo size 1500,620 font 'Sans,11' noenhanced
set output 'output/bench/phases.png'
set datafile missing '?'
set multiplot title 'fricon: processor time per phase against N_e (P1, least of repetitions, 1 thread)' font 'Sans,14'
set logscale xy; set grid; set format y "%.0e"
set xrange [15:1300]; set yrange [1e-6:30]
set xtics (20, 50, 100, 200, 500, 1000, 2000)
set xlabel 'N_e (elements; n = 5 N_e + 5 unknowns)'
set ylabel 'processor time [s]'
set tmargin at screen 0.88; set bmargin at screen 0.12
set lmargin at screen 0.06; set rmargin at screen 0.39
unset key
set title 'PLATE: rho 0.01, zeta 0.1, f 0.5, central point load'
plot 'output/bench/phases.dat' index 0 using 1:2 with linespoints lw 2 pt 4 lc rgb '#1f77b4' title 'discretisation', 'output/bench/phases.dat' index 0 using 1:3 with linespoints lw 2 pt 5 lc rgb '#ff7f0e' title 'T assembly', 'output/bench/phases.dat' index 0 using 1:4 with linespoints lw 2 pt 6 lc rgb '#2ca02c' title 'K, M assembly', 'output/bench/phases.dat' index 0 using 1:5 with linespoints lw 2 pt 7 lc rgb '#d62728' title 'rest of system set-up (*)', 'output/bench/phases.dat' index 0 using 1:6 with linespoints lw 2 pt 8 lc rgb '#9467bd' title 'Newton iterations', 'output/bench/phases.dat' index 0 using 1:7 with linespoints lw 2 pt 9 lc rgb '#8c564b' title 'final checks', 'output/bench/phases.dat' index 0 using 1:8 with linespoints lw 2 pt 10 lc rgb '#e377c2' title 'tabulation (stations)', 'output/bench/phases.dat' index 0 using 1:9 with linespoints lw 2 pt 11 lc rgb '#7f7f7f' title 'design summary', 'output/bench/phases.dat' index 0 using 1:10 with linespoints lw 2 pt 12 lc rgb '#bcbd22' title 'error estimate', 'output/bench/phases.dat' index 0 using 1:11 with linespoints lw 2 pt 13 lc rgb '#17becf' title 'report writing', 'output/bench/phases.dat' index 0 using 1:12 with linespoints lw 3 pt 7 lc rgb 'black' title 'total', 1e-3 with lines dt 2 lc rgb 'gray40' title '1 ms (fit floor)'
set lmargin at screen 0.45; set rmargin at screen 0.78
set key at screen 0.80, 0.88 left top box opaque title 'phase'
set title 'BEAM: rho 0.0025, zeta 0.1, f 0.6, central point load, H = 0.1 V'
plot 'output/bench/phases.dat' index 1 using 1:2 with linespoints lw 2 pt 4 lc rgb '#1f77b4' title 'discretisation', 'output/bench/phases.dat' index 1 using 1:3 with linespoints lw 2 pt 5 lc rgb '#ff7f0e' title 'T assembly', 'output/bench/phases.dat' index 1 using 1:4 with linespoints lw 2 pt 6 lc rgb '#2ca02c' title 'K, M assembly', 'output/bench/phases.dat' index 1 using 1:5 with linespoints lw 2 pt 7 lc rgb '#d62728' title 'rest of system set-up (*)', 'output/bench/phases.dat' index 1 using 1:6 with linespoints lw 2 pt 8 lc rgb '#9467bd' title 'Newton iterations', 'output/bench/phases.dat' index 1 using 1:7 with linespoints lw 2 pt 9 lc rgb '#8c564b' title 'final checks', 'output/bench/phases.dat' index 1 using 1:8 with linespoints lw 2 pt 10 lc rgb '#e377c2' title 'tabulation (stations)', 'output/bench/phases.dat' index 1 using 1:9 with linespoints lw 2 pt 11 lc rgb '#7f7f7f' title 'design summary', 'output/bench/phases.dat' index 1 using 1:10 with linespoints lw 2 pt 12 lc rgb '#bcbd22' title 'error estimate', 'output/bench/phases.dat' index 1 using 1:11 with linespoints lw 2 pt 13 lc rgb '#17becf' title 'report writing', 'output/bench/phases.dat' index 1 using 1:12 with linespoints lw 3 pt 7 lc rgb 'black' title 'total', 1e-3 with lines dt 2 lc rgb 'gray40' title '1 ms (fit floor)'
unset multiplot
