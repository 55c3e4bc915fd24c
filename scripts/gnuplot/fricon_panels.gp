# fricon figure: four panels from a station data file (columns as in README / SPEC 9).
# usage (from the project root):
#   gnuplot -c scripts/gnuplot/fricon_panels.gp DATA PNG TITLE MODEL
# MODEL is BEAM or PLATE (decides the resultant columns).
data = ARG1
png = ARG2
title = ARG3
model = ARG4
set terminal pngcairo size 1400,1000 font 'Sans,11' noenhanced
set output png
set multiplot layout 2,2 title title font 'Sans,14'
set grid
set format y '%g'
set key box opaque font ',9' samplen 2
set autoscale fix
set offsets 0, 0, graph 0.08, graph 0.08
xlab = (model eq 'BEAM') ? 't = x/l' : 't = r/a'
set xlabel xlab

set title 'Settlement W (down positive) and soil surface W + gap'
set ylabel 'W'
set yrange [*:*] reverse
plot data u 1:3 w lp pt 7 ps 0.5 lw 2 lc rgb '#1f77b4' t 'W (structure)', \
     data u 1:($3+$7) w l dt 2 lw 1.5 lc rgb '#7f7f7f' t 'W + gap (soil surface)'
set yrange [*:*] noreverse

set title 'Contact tractions on the soil'
set autoscale y
set key outside bottom center horizontal
set bmargin 6
set ylabel 'Sigma'
plot data u 1:6 w lp pt 7 ps 0.5 lw 2 lc rgb '#d62728' t 'Sigma_z (pressure)', \
     data u 1:5 w lp pt 5 ps 0.5 lw 2 lc rgb '#2ca02c' t 'Sigma_x (shear)', \
     data u 1:(($9==0)?0:1/0) w p pt 6 ps 1.2 lc rgb '#000000' t 'lift-off', \
     data u 1:(($9==2)?$5:1/0) w p pt 4 ps 1.2 lc rgb '#ff7f0e' t 'slip'

set title 'Bending moment'
unset bmargin
set autoscale y
set key inside top right vertical
if (model eq 'BEAM') {
    set ylabel 'M/(F l)   (> 0 hogging)'
    plot data u 1:11 w lp pt 7 ps 0.5 lw 2 lc rgb '#9467bd' t 'M/(F l)'
} else {
    set ylabel 'M/F   (> 0 top in tension)'
    plot data u 1:12 w lp pt 7 ps 0.5 lw 2 lc rgb '#9467bd' t 'M_r/F', \
         data u 1:13 w lp pt 5 ps 0.5 lw 2 lc rgb '#8c564b' t 'M_theta/F'
}

set title 'Horizontal displacement and slip'
set autoscale y
set ylabel 'U, slip'
plot data u 1:2 w lp pt 7 ps 0.5 lw 2 lc rgb '#17becf' t 'U (mid-plane)', \
     data u 1:8 w l lw 2 dt 2 lc rgb '#bcbd22' t 'slip = u_b - u_f'
unset multiplot
