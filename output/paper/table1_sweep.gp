# fricon sweep figure: run from the project root as  gnuplot output/paper/table1_sweep.gp
files = "output/paper/table1_001.dat output/paper/table1_002.dat output/paper/table1_003.dat"
labels = "EPS_BAR=1.0E-1 EPS_BAR=1.0E-4 EPS_BAR=1.0E-7"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/table1_sweep.png' 'Table 1: beam rho 0.0025 f 0.6, load V=1 H=0.1, b/l 0.0055, h/l 0.1 (sweep)' 'BEAM'
