# fricon sweep figure: run from the project root as  gnuplot output/paper/fig06_sweep.gp
files = "output/paper/fig06_001.dat output/paper/fig06_002.dat output/paper/fig06_003.dat output/paper/fig06_004.dat output/paper/fig06_005.dat"
labels = "NE=10 NE=20 NE=40 NE=80 NE=160"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig06_sweep.png' 'Fig. 6: beam rho 0.00025, all P1, N_e sweep (sweep)' 'BEAM'
