# fricon sweep figure: run from the project root as  gnuplot output/paper/table1_width_sweep.gp
files = "output/paper/table1_width_001.dat output/paper/table1_width_002.dat output/paper/table1_width_003.dat output/paper/table1_width_004.dat output/paper/table1_width_005.dat output/paper/table1_width_006.dat"
labels = "ZETA=0.05,EPS_BAR=1.0E-1 ZETA=0.05,EPS_BAR=1.0E-4 ZETA=0.05,EPS_BAR=1.0E-7 ZETA=0.1,EPS_BAR=1.0E-1 ZETA=0.1,EPS_BAR=1.0E-4 ZETA=0.1,EPS_BAR=1.0E-7"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/table1_width_sweep.png' 'Table 1 reading b/l 0.1, vertical central point load (sweep)' 'BEAM'
