# fricon sweep figure: run from the project root as  gnuplot output/paper/fig19_sweep.gp
# columns, labels, units and loads: those of the first solved case
settings_only = 1
load 'output/paper/fig19_001.gp'
undefine settings_only
files = "output/paper/fig19_001.dat output/paper/fig19_002.dat output/paper/fig19_003.dat output/paper/fig19_004.dat output/paper/fig19_005.dat"
labels = "'F=0.0' 'F=0.2' 'F=0.4' 'F=0.6' 'F=1.0'"
# mean contact pressure V / contact area of each case (plotted unit)
p_means = "2.6655560E+000 2.4605921E+000 2.4605921E+000 2.2783909E+000 2.1157025E+000"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig19_sweep.png' 'fricon: Fig. 19: plate rho 0.01, h/a 0.1, f sweep (sweep)' 'PLATE'
