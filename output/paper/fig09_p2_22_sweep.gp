# fricon sweep figure: run from the project root as  gnuplot output/paper/fig09_p2_22_sweep.gp
# columns, labels, units and loads: those of the first solved case
settings_only = 1
load 'output/paper/fig09_p2_22_001.gp'
undefine settings_only
files = "output/paper/fig09_p2_22_001.dat output/paper/fig09_p2_22_002.dat"
labels = "'RHO=0.00025' 'RHO=0.0025'"
# mean contact pressure V / contact area of each case (plotted unit)
p_means = "1.7021277E+000 1.1034483E+000"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig09_p2_22_sweep.png' 'fricon: Fig. 9 (P2, 91 unknowns): N_e 22, U psi P1, W P2 (sweep)' 'BEAM'
