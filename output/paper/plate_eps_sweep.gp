# fricon sweep figure: run from the project root as  gnuplot output/paper/plate_eps_sweep.gp
files = "output/paper/plate_eps_001.dat output/paper/plate_eps_002.dat output/paper/plate_eps_003.dat"
labels = "EPS_BAR=1.0E-1 EPS_BAR=1.0E-4 EPS_BAR=1.0E-7"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/plate_eps_sweep.png' 'Plate: rho 0.01, h/a 0.1, f 0.6, eps_bar sweep (sweep)' 'PLATE'
