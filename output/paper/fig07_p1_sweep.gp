# fricon sweep figure: run from the project root as  gnuplot output/paper/fig07_p1_sweep.gp
files = "output/paper/fig07_p1_001.dat output/paper/fig07_p1_002.dat output/paper/fig07_p1_003.dat output/paper/fig07_p1_004.dat output/paper/fig07_p1_005.dat"
labels = "RHO=0.00025 RHO=0.001 RHO=0.0025 RHO=0.01 RHO=0.1"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig07_p1_sweep.png' 'Fig. 7: beam N_e 20, displacements P1, interactions P1 (sweep)' 'BEAM'
