# fricon sweep figure: run from the project root as  gnuplot output/paper/fig09a_sweep.gp
# columns, labels, units and loads: those of the first solved case
settings_only = 1
load 'output/paper/fig09a_001.gp'
undefine settings_only
files = "output/paper/fig09a_001.dat output/paper/fig09a_002.dat"
labels = "'RHO=0.00025' 'RHO=0.0025'"
# mean contact pressure V / contact area of each case (plotted unit)
p_means = "1.7777778E+000 1.2030075E+000"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig09a_sweep.png' 'fricon: Fig. 9a: beam N_e 30, U W psi P1 (sweep)' 'BEAM'
