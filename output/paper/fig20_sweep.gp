# fricon sweep figure: run from the project root as  gnuplot output/paper/fig20_sweep.gp
# columns, labels, units and loads: those of the first solved case
settings_only = 1
load 'output/paper/fig20_001.gp'
undefine settings_only
files = "output/paper/fig20_001.dat output/paper/fig20_002.dat output/paper/fig20_003.dat output/paper/fig20_004.dat output/paper/fig20_005.dat"
labels = "'ZETA=0.025' 'ZETA=0.05' 'ZETA=0.1' 'ZETA=0.2' 'ZETA=0.3'"
# mean contact pressure V / contact area of each case (plotted unit)
p_means = "2.4605921E+000 2.4605921E+000 2.2783909E+000 1.9698369E+000 1.6124969E+000"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig20_sweep.png' 'fricon: Fig. 20: plate rho 0.01, f 0.6, h/a sweep (sweep)' 'PLATE'
