# fricon sweep figure: run from the project root as  gnuplot output/paper/fig09_p2_22_sweep.gp
files = "output/paper/fig09_p2_22_001.dat output/paper/fig09_p2_22_002.dat"
labels = "RHO=0.00025 RHO=0.0025"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig09_p2_22_sweep.png' 'Fig. 9 (P2, 91 unknowns): N_e 22, U psi P1, W P2 (sweep)' 'BEAM'
