# fricon sweep figure: the cases of a SWEEP deck overlaid, four panels.
# The calling script (output/STEM_sweep.gp, written by fricon) defines
#   files  = "a.dat b.dat ..."   (whitespace-separated data files)
#   labels = "l1 l2 ..."         (one word per file)
# and calls:  call 'scripts/gnuplot/fricon_sweep.gp' PNG TITLE MODEL
# A variable png_override (gnuplot -e) replaces PNG (fricon renders to a temporary name).
png = exists("png_override") ? png_override : ARG1
title = ARG2
model = ARG3
set terminal pngcairo size 1400,1000 font 'Sans,11' noenhanced
set output png
set multiplot layout 2,2 title title font 'Sans,14'
set grid
set format y '%g'
set key box opaque font ',9' samplen 2
set autoscale fix
set offsets 0, 0, graph 0.08, graph 0.08
set xlabel ((model eq 'BEAM') ? 't = x/l' : 't = r/a')
n = words(files)

set title 'Settlement W (down positive)'
set ylabel 'W'
set yrange [*:*] reverse
plot for [i=1:n] word(files, i) u 1:3 w l lw 2 t word(labels, i)
set yrange [*:*] noreverse

set title 'Contact pressure Sigma_z'
set ylabel 'Sigma_z'
plot for [i=1:n] word(files, i) u 1:6 w l lw 2 t word(labels, i)

set title 'Shear traction Sigma_x'
set ylabel 'Sigma_x'
plot for [i=1:n] word(files, i) u 1:5 w l lw 2 t word(labels, i)

set title 'Horizontal displacement U'
set ylabel 'U'
plot for [i=1:n] word(files, i) u 1:2 w l lw 2 t word(labels, i)
unset multiplot
