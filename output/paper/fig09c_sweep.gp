# fricon sweep figure: run from the project root as  gnuplot output/paper/fig09c_sweep.gp
files = "output/paper/fig09c_001.dat output/paper/fig09c_002.dat"
labels = "RHO=0.00025 RHO=0.0025"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig09c_sweep.png' 'Fig. 9c: beam N_e 22, U P1, W psi S2 (sweep)' 'BEAM'
