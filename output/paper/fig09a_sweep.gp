# fricon sweep figure: run from the project root as  gnuplot output/paper/fig09a_sweep.gp
files = "output/paper/fig09a_001.dat output/paper/fig09a_002.dat"
labels = "RHO=0.00025 RHO=0.0025"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig09a_sweep.png' 'Fig. 9a: beam N_e 30, U W psi P1 (sweep)' 'BEAM'
