# fricon sweep figure: run from the project root as  gnuplot output/paper/table1_eps_scale_sweep.gp
# columns, labels, units and loads: those of the first solved case
settings_only = 1
load 'output/paper/table1_eps_scale_001.gp'
undefine settings_only
files = "output/paper/table1_eps_scale_001.dat output/paper/table1_eps_scale_002.dat output/paper/table1_eps_scale_003.dat output/paper/table1_eps_scale_004.dat output/paper/table1_eps_scale_005.dat output/paper/table1_eps_scale_006.dat"
labels = "'EPS_BAR=1.0E-1' 'EPS_BAR=5.0E-2' 'EPS_BAR=2.0E-2' 'EPS_BAR=1.0E-2' 'EPS_BAR=5.0E-3' 'EPS_BAR=2.0E-3'"
# mean contact pressure V / contact area of each case (plotted unit)
p_means = "1.1111111E+000 1.1111111E+000 1.1764706E+000 1.1764706E+000 1.1764706E+000 1.1764706E+000"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/table1_eps_scale_sweep.png' 'fricon: Table 1 chosen reading: eps_bar scale (sweep)' 'BEAM'
