# fricon sweep figure: run from the project root as  gnuplot output/paper/table1_b005_sweep.gp
files = "output/paper/table1_b005_001.dat output/paper/table1_b005_002.dat output/paper/table1_b005_003.dat"
labels = "EPS_BAR=1.0E-1 EPS_BAR=1.0E-4 EPS_BAR=1.0E-7"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/table1_b005_sweep.png' 'Table 1 reading H/V 0.1, b/l 0.005, h/l 0.1 (sweep)' 'BEAM'
