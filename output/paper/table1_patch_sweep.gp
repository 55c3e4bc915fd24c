# fricon sweep figure: run from the project root as  gnuplot output/paper/table1_patch_sweep.gp
files = "output/paper/table1_patch_001.dat output/paper/table1_patch_002.dat output/paper/table1_patch_003.dat"
labels = "EPS_BAR=1.0E-1 EPS_BAR=1.0E-4 EPS_BAR=1.0E-7"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/table1_patch_sweep.png' 'Table 1 reading: central patch of width 0.1 l, b/l 0.0055 (sweep)' 'BEAM'
