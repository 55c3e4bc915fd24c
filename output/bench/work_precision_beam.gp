set terminal pngcairo size 2100,1000 font 'Sans,11' noenhanced
set output 'output/bench/work_precision_beam.png'
set multiplot layout 2,4 title 'Work-precision, BEAM (rho 0.001, f 0.6, H = 0.1 V): error against solve time' font 'Sans,14'
set logscale xy; set grid; set format y "%.0e"; set format x "%.0e"
set linetype 9 lc rgb '#e0007a' lw 3    # the ninth family: magenta (8 is black)
set xlabel 'discretise + solve time [s]'; set key bottom left font ',9'
names = 'P1-UNIFORM P1-EDGES P1-LOADS P2-UNIFORM S2-UNIFORM S2w-P1tr-LOADS S2w-P1tr-UNIFORM P1-ADAPT S2w-P1tr-ADAPT'
set title 'error of W(0)'; plot for [k=0:8] 'output/bench/work_precision_beam.txt' index k u 4:(($5>0)?$5:1/0) w lp pt 7 lw 2 t word(names, k+1)
set title 'error of Sigma_z(0)'; plot for [k=0:8] 'output/bench/work_precision_beam.txt' index k u 4:(($6>0)?$6:1/0) w lp pt 7 lw 2 t word(names, k+1)
set title 'error of max_Sigma_z'; plot for [k=0:8] 'output/bench/work_precision_beam.txt' index k u 4:(($7>0)?$7:1/0) w lp pt 7 lw 2 t word(names, k+1)
set title 'error of max|M|'; plot for [k=0:8] 'output/bench/work_precision_beam.txt' index k u 4:(($8>0)?$8:1/0) w lp pt 7 lw 2 t word(names, k+1)
set title 'error of extent'; plot for [k=0:8] 'output/bench/work_precision_beam.txt' index k u 4:(($9>0)?$9:1/0) w lp pt 7 lw 2 t word(names, k+1)
unset logscale x; set logscale x; set xlabel 'unknowns'
set title 'error of W(0) against unknowns'; plot for [k=0:8] 'output/bench/work_precision_beam.txt' index k u 3:(($5>0)?$5:1/0) w lp pt 7 lw 2 t word(names, k+1)
set title 'error of Sigma_z(0) against unknowns'; plot for [k=0:8] 'output/bench/work_precision_beam.txt' index k u 3:(($6>0)?$6:1/0) w lp pt 7 lw 2 t word(names, k+1)
unset multiplot
