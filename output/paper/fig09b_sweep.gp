# fricon sweep figure: run from the project root as  gnuplot output/paper/fig09b_sweep.gp
files = "output/paper/fig09b_001.dat output/paper/fig09b_002.dat"
labels = "RHO=0.00025 RHO=0.0025"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig09b_sweep.png' 'Fig. 9b: beam N_e 18, U psi P1, W S2 (sweep)' 'BEAM'
