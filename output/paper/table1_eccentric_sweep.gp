# fricon sweep figure: run from the project root as  gnuplot output/paper/table1_eccentric_sweep.gp
files = "output/paper/table1_eccentric_001.dat output/paper/table1_eccentric_002.dat output/paper/table1_eccentric_003.dat"
labels = "EPS_BAR=1.0E-1 EPS_BAR=1.0E-4 EPS_BAR=1.0E-7"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/table1_eccentric_sweep.png' 'Table 1 reading: vertical point load at x = 0.1 l, b/l 0.0055 (sweep)' 'BEAM'
