# fricon sweep figure: run from the project root as  gnuplot output/paper/fig10_sweep.gp
# columns, labels, units and loads: those of the first solved case
settings_only = 1
load 'output/paper/fig10_001.gp'
undefine settings_only
files = "output/paper/fig10_001.dat output/paper/fig10_002.dat output/paper/fig10_003.dat output/paper/fig10_004.dat output/paper/fig10_005.dat"
labels = "'F=0.2' 'F=0.3' 'F=0.4' 'F=0.6' 'F=1.0'"
# mean contact pressure V / contact area of each case (plotted unit)
p_means = "1.1764706E+000 1.1764706E+000 1.1764706E+000 1.1764706E+000 1.1764706E+000"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig10_sweep.png' 'fricon: Fig. 10: beam rho 0.0025, V=1 H=0.1, f sweep (sweep)' 'BEAM'
