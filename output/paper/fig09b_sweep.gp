# fricon sweep figure: run from the project root as  gnuplot output/paper/fig09b_sweep.gp
# columns, labels, units and loads: those of the first solved case
settings_only = 1
load 'output/paper/fig09b_001.gp'
undefine settings_only
files = "output/paper/fig09b_001.dat output/paper/fig09b_002.dat"
labels = "'RHO=0.00025' 'RHO=0.0025'"
# mean contact pressure V / contact area of each case (plotted unit)
p_means = "1.6326531E+000 1.0596026E+000"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig09b_sweep.png' 'fricon: Fig. 9b: beam N_e 18, U psi P1, W S2 (sweep)' 'BEAM'
