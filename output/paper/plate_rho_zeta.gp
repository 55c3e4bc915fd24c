# written by scripts/paper.sh: gnuplot output/paper/plate_rho_zeta.gp (from the project root)
set terminal pngcairo size 1400,1000 font 'Sans,11' noenhanced
set output 'output/paper/plate_rho_zeta.png'
set multiplot layout 2,2 title 'Plate: rho sweep (fig11_18, h/a 0.1) against zeta sweep (fig20, rho 0.01); f 0.6' font 'Sans,14'
set grid
set key box opaque font ',9'
set xlabel 't = r/a'
rhos = '0.001 0.01 0.1 1.0 10.0'
zetas = '0.025 0.05 0.1 0.2 0.3'
set title 'settlement in soil units 2 W/rho = w E_f a/((1-nu_f^2) F), rho sweep'
set ylabel '2 W / rho'
set yrange [*:*] reverse
plot for [i = 1:5] sprintf('output/paper/fig11_18_%03d.dat', i) u 1:(2*$3/word(rhos, i)) w l lw 2 t 'rho = '.word(rhos, i)
set title 'settlement in soil units 2 W/rho, zeta sweep at rho = 0.01'
plot for [i = 1:5] sprintf('output/paper/fig20_%03d.dat', i) u 1:(2*$3/0.01) w l lw 2 t 'h/a = '.word(zetas, i)
set yrange [*:*] noreverse
set title 'contact pressure Sigma_z, rho sweep'
set ylabel 'Sigma_z'
set yrange [-2:110]
plot for [i = 1:5] sprintf('output/paper/fig11_18_%03d.dat', i) u 1:6 w l lw 2 t 'rho = '.word(rhos, i)
set title 'contact pressure Sigma_z, zeta sweep at rho = 0.01'
plot for [i = 1:5] sprintf('output/paper/fig20_%03d.dat', i) u 1:6 w l lw 2 t 'h/a = '.word(zetas, i)
unset multiplot
