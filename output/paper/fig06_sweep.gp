# fricon sweep figure: run from the project root as  gnuplot output/paper/fig06_sweep.gp
# columns, labels, units and loads: those of the first solved case
settings_only = 1
load 'output/paper/fig06_001.gp'
undefine settings_only
files = "output/paper/fig06_001.dat output/paper/fig06_002.dat output/paper/fig06_003.dat output/paper/fig06_004.dat output/paper/fig06_005.dat"
labels = "'NE=10' 'NE=20' 'NE=40' 'NE=80' 'NE=160'"
# mean contact pressure V / contact area of each case (plotted unit)
p_means = "1.6666667E+000 2.0000000E+000 2.0000000E+000 2.1052632E+000 2.1917808E+000"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig06_sweep.png' 'fricon: Fig. 6: beam rho 0.00025, all P1, N_e sweep (sweep)' 'BEAM'
