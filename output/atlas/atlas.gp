set terminal pngcairo size 1600,1000 font 'Sans,11' noenhanced
set output 'output/atlas/atlas.png'
set multiplot layout 2,3 title "Hard-case atlas: green solved, blue status 2 for the true reason (sliding), red failed;\nmarker size: linear solves; each point is the worst of eps_bar x nu_f" font 'Sans,13'
set logscale y; set xrange [-6.8:6.8]; set yrange [0.0006:0.9]; set grid
set xlabel 'log10 rho'; set ylabel 'zeta = h/l or h/a'
set palette defined (0 '#2ca02c', 1 '#1f77b4', 2 '#d62728'); set cbrange [0:2]; unset colorbox
set key off
fs = '0 0.6 2'
do for [m in 'beam plate'] {
  do for [i = 0:2] {
    set title sprintf('%s, f = %s', m, word(fs, i + 1))
    plot 'output/atlas/'.m.'_map.dat' index i u 1:2:(1 + sqrt($4)/1.5):3 w p pt 7 ps variable lc palette
  }
}
unset multiplot
