# fricon sweep figure: run from the project root as  gnuplot output/paper/fig09_p2_18_sweep.gp
files = "output/paper/fig09_p2_18_001.dat output/paper/fig09_p2_18_002.dat"
labels = "RHO=0.00025 RHO=0.0025"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig09_p2_18_sweep.png' 'Fig. 9 (P2, 93 unknowns): N_e 18, U P1, W psi P2 (sweep)' 'BEAM'
