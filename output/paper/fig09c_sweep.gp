# fricon sweep figure: run from the project root as  gnuplot output/paper/fig09c_sweep.gp
# columns, labels, units and loads: those of the first solved case
settings_only = 1
load 'output/paper/fig09c_001.gp'
undefine settings_only
files = "output/paper/fig09c_001.dat output/paper/fig09c_002.dat"
labels = "'RHO=0.00025' 'RHO=0.0025'"
# mean contact pressure V / contact area of each case (plotted unit)
p_means = "1.7021277E+000 1.1034483E+000"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig09c_sweep.png' 'fricon: Fig. 9c: beam N_e 22, U P1, W psi S2 (sweep)' 'BEAM'
