# fricon sweep figure: run from the project root as  gnuplot output/paper/fig19_sweep.gp
files = "output/paper/fig19_001.dat output/paper/fig19_002.dat output/paper/fig19_003.dat output/paper/fig19_004.dat output/paper/fig19_005.dat"
labels = "F=0.0 F=0.2 F=0.4 F=0.6 F=1.0"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig19_sweep.png' 'Fig. 19: plate rho 0.01, h/a 0.1, f sweep (sweep)' 'PLATE'
