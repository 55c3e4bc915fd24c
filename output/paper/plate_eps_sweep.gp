# fricon sweep figure: run from the project root as  gnuplot output/paper/plate_eps_sweep.gp
# columns, labels, units and loads: those of the first solved case
settings_only = 1
load 'output/paper/plate_eps_001.gp'
undefine settings_only
files = "output/paper/plate_eps_001.dat output/paper/plate_eps_002.dat output/paper/plate_eps_003.dat"
labels = "'EPS_BAR=1.0E-1' 'EPS_BAR=1.0E-4' 'EPS_BAR=1.0E-7'"
# mean contact pressure V / contact area of each case (plotted unit)
p_means = "2.1157025E+000 2.2783909E+000 2.2783909E+000"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/plate_eps_sweep.png' 'fricon: Plate: rho 0.01, h/a 0.1, f 0.6, eps_bar sweep (sweep)' 'PLATE'
