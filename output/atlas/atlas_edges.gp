set terminal pngcairo size 1600,1000 font 'Sans,11' noenhanced
set output 'output/atlas/atlas_edges.png'
set multiplot layout 2,3 title "Hard-case atlas, edges: utilisation up to and beyond 1, a small contact zone, meshes to N_e = 2000; solid lines f = 0, dashed f = 0.6" font 'Sans,13'
set grid
set palette defined (0 '#2ca02c', 1 '#1f77b4', 2 '#d62728'); set cbrange [0:2]; unset colorbox
set title 'beam, H = 0.3 V: green solved, blue sliding (status 2), red failed'
set xlabel 'utilisation H/(f V)  (f = 0 drawn at 2.5)'; set ylabel 'log10 rho'
set xrange [0.3:2.7]; set yrange [-4.8:6.8]; set key off
set arrow 1 from 1, graph 0 to 1, graph 1 nohead dt 2 lc 'black'
plot 'output/atlas/utilisation.dat' u 1:2:(1 + sqrt($4)/1.5):3 w p pt 7 ps variable lc palette
unset arrow 1
set xrange [*:*]; set yrange [*:*]; set logscale x; set key top right font 'Sans,9'
rhos = '1e-4 1e-2 1 1e2 1e4 1e6'
set title 'beam, load 0.05 l from the end: contact length'
set xlabel 'N_e'; set ylabel 'contact length / l'
plot for [i = 0:11] 'output/atlas/beam_eccentric.dat' index i u 1:2 w lp lt (i/2 + 1) pt 7 dt i%2+1 title (i % 2 == 0 ? 'rho '.word(rhos, i/2 + 1) : '')
set title 'beam, load 0.05 l from the end: linear solves'
set ylabel 'linear solves of the case'
plot for [i = 0:11] 'output/atlas/beam_eccentric.dat' index i u 1:3 w lp lt (i/2 + 1) pt 7 dt i%2+1 title (i % 2 == 0 ? 'rho '.word(rhos, i/2 + 1) : '')
prhos = '1e-6 1e-3 1 1e3'
set title 'plate, disk load: contact extent'
set ylabel 'contact extent r/a'
plot for [i = 0:7] 'output/atlas/plate_meshes.dat' index i u 1:2 w lp lt (i/2 + 1) pt 7 dt i%2+1 title (i % 2 == 0 ? 'rho '.word(prhos, i/2 + 1) : '')
set title 'plate, disk load: linear solves (failures: missing points)'
set ylabel 'linear solves of the case'
plot for [i = 0:7] 'output/atlas/plate_meshes.dat' index i u 1:3 w lp lt (i/2 + 1) pt 7 dt i%2+1 title (i % 2 == 0 ? 'rho '.word(prhos, i/2 + 1) : '')
unset multiplot
