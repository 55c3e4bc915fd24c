# fricon sweep figure: run from the project root as  gnuplot output/paper/fig11_18_sweep.gp
# columns, labels, units and loads: those of the first solved case
settings_only = 1
load 'output/paper/fig11_18_001.gp'
undefine settings_only
files = "output/paper/fig11_18_001.dat output/paper/fig11_18_002.dat output/paper/fig11_18_003.dat output/paper/fig11_18_004.dat output/paper/fig11_18_005.dat"
labels = "'RHO=0.001' 'RHO=0.01' 'RHO=0.1' 'RHO=1.0' 'RHO=10.0'"
# mean contact pressure V / contact area of each case (plotted unit)
p_means = "6.6597294E+000 2.2783909E+000 1.0000000E+000 1.0000000E+000 1.0000000E+000"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig11_18_sweep.png' 'fricon: Figs. 11-18: plate, rho sweep, f 0.6, h/a 0.1 (sweep)' 'PLATE'
