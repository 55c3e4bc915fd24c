# written by scripts/paper.sh: gnuplot output/paper/table1_scan_fit.gp (from the project root)
# output/paper/table1_scan_fit.dat: blocks per h/l; columns zeta, b/l, dW%, dSx%, dSz%, max% (from table1.txt)
set terminal pngcairo size 1400,1000 font 'Sans,11' noenhanced
set output 'output/paper/table1_scan_fit.png'
set multiplot layout 2,2 title 'Table 1, reading H/V = 0.1 (table1_scan.dat): deviation from the paper row eps_bar = 1e-4' font 'Sans,14'
set grid
set key box opaque font ',9'
set xlabel 'beta = b/l'
set xzeroaxis lt -1
titles = "'W(0): fricon/paper - 1 (%)' 'Sigma_x(0): fricon/paper - 1 (%)' 'Sigma_z(0): fricon/paper - 1 (%)' 'largest |deviation| of the three (%)'"
do for [c = 3:6] {
    set title word(titles, c - 2)
    set ylabel '%'
    plot for [i = 0:4] 'output/paper/table1_scan_fit.dat' index i u 2:c w lp lw 2 pt 7 t sprintf('h/l = %s', word('0.09 0.095 0.1 0.105 0.11', i + 1))
}
unset multiplot
