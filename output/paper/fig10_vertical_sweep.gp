# fricon sweep figure: run from the project root as  gnuplot output/paper/fig10_vertical_sweep.gp
files = "output/paper/fig10_vertical_001.dat output/paper/fig10_vertical_002.dat output/paper/fig10_vertical_003.dat output/paper/fig10_vertical_004.dat output/paper/fig10_vertical_005.dat"
labels = "F=0.0 F=0.2 F=0.4 F=0.6 F=1.0"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig10_vertical_sweep.png' 'Fig. 10 variant: beam rho 0.0025, vertical load, f sweep (sweep)' 'BEAM'
