# fricon sweep figure: run from the project root as  gnuplot output/paper/fig20_f0_sweep.gp
# columns, labels, units and loads: those of the first solved case
settings_only = 1
load 'output/paper/fig20_f0_001.gp'
undefine settings_only
files = "output/paper/fig20_f0_001.dat output/paper/fig20_f0_002.dat output/paper/fig20_f0_003.dat output/paper/fig20_f0_004.dat output/paper/fig20_f0_005.dat"
labels = "'ZETA=0.025' 'ZETA=0.05' 'ZETA=0.1' 'ZETA=0.2' 'ZETA=0.3'"
# mean contact pressure V / contact area of each case (plotted unit)
p_means = "2.6655560E+000 2.6655560E+000 2.6655560E+000 2.4605921E+000 2.4605921E+000"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig20_f0_sweep.png' 'fricon: Fig. 20 control: plate rho 0.01, f 0 (frictionless), h/a sweep (sweep)' 'PLATE'
