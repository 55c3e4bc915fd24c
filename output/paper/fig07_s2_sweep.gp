# fricon sweep figure: run from the project root as  gnuplot output/paper/fig07_s2_sweep.gp
files = "output/paper/fig07_s2_001.dat output/paper/fig07_s2_002.dat output/paper/fig07_s2_003.dat output/paper/fig07_s2_004.dat output/paper/fig07_s2_005.dat"
labels = "RHO=0.00025 RHO=0.001 RHO=0.0025 RHO=0.01 RHO=0.1"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig07_s2_sweep.png' 'Fig. 7: beam N_e 20, displacements P1, interactions S2 (sweep)' 'BEAM'
