# fricon sweep figure: run from the project root as  gnuplot output/paper/table1_width_sweep.gp
# columns, labels, units and loads: those of the first solved case
settings_only = 1
load 'output/paper/table1_width_001.gp'
undefine settings_only
files = "output/paper/table1_width_001.dat output/paper/table1_width_002.dat output/paper/table1_width_003.dat output/paper/table1_width_004.dat output/paper/table1_width_005.dat output/paper/table1_width_006.dat"
labels = "'ZETA=0.05 EPS_BAR=1.0E-1' 'ZETA=0.05 EPS_BAR=1.0E-4' 'ZETA=0.05 EPS_BAR=1.0E-7' 'ZETA=0.1 EPS_BAR=1.0E-1' 'ZETA=0.1 EPS_BAR=1.0E-4' 'ZETA=0.1 EPS_BAR=1.0E-7'"
# mean contact pressure V / contact area of each case (plotted unit)
p_means = "1.5384615E+000 1.5384615E+000 1.5384615E+000 1.3333333E+000 1.3333333E+000 1.3333333E+000"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/table1_width_sweep.png' 'fricon: Table 1 reading b/l 0.1, vertical central point load (sweep)' 'BEAM'
