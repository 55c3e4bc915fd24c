# fricon sweep figure: run from the project root as  gnuplot output/paper/table1_b005_sweep.gp
# columns, labels, units and loads: those of the first solved case
settings_only = 1
load 'output/paper/table1_b005_001.gp'
undefine settings_only
files = "output/paper/table1_b005_001.dat output/paper/table1_b005_002.dat output/paper/table1_b005_003.dat"
labels = "'EPS_BAR=1.0E-1' 'EPS_BAR=1.0E-4' 'EPS_BAR=1.0E-7'"
# mean contact pressure V / contact area of each case (plotted unit)
p_means = "1.1111111E+000 1.1764706E+000 1.1764706E+000"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/table1_b005_sweep.png' 'fricon: Table 1 reading H/V 0.1, b/l 0.005, h/l 0.1 (sweep)' 'BEAM'
