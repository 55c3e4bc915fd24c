# fricon sweep figure: run from the project root as  gnuplot output/paper/table1_eccentric_sweep.gp
# columns, labels, units and loads: those of the first solved case
settings_only = 1
load 'output/paper/table1_eccentric_001.gp'
undefine settings_only
files = "output/paper/table1_eccentric_001.dat output/paper/table1_eccentric_002.dat output/paper/table1_eccentric_003.dat"
labels = "'EPS_BAR=1.0E-1' 'EPS_BAR=1.0E-4' 'EPS_BAR=1.0E-7'"
# mean contact pressure V / contact area of each case (plotted unit)
p_means = "1.2121212E+000 1.2121212E+000 1.2121212E+000"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/table1_eccentric_sweep.png' 'fricon: Table 1 reading: vertical point load at x = 0.1 l, b/l 0.0055 (sweep)' 'BEAM'
