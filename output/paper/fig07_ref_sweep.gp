# fricon sweep figure: run from the project root as  gnuplot output/paper/fig07_ref_sweep.gp
files = "output/paper/fig07_ref_001.dat output/paper/fig07_ref_002.dat output/paper/fig07_ref_003.dat output/paper/fig07_ref_004.dat output/paper/fig07_ref_005.dat"
labels = "RHO=0.00025 RHO=0.001 RHO=0.0025 RHO=0.01 RHO=0.1"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig07_ref_sweep.png' 'Fig. 7 reference: beam N_e 160, all P1 (sweep)' 'BEAM'
