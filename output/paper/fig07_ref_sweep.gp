# fricon sweep figure: run from the project root as  gnuplot output/paper/fig07_ref_sweep.gp
# columns, labels, units and loads: those of the first solved case
settings_only = 1
load 'output/paper/fig07_ref_001.gp'
undefine settings_only
files = "output/paper/fig07_ref_001.dat output/paper/fig07_ref_002.dat output/paper/fig07_ref_003.dat output/paper/fig07_ref_004.dat output/paper/fig07_ref_005.dat"
labels = "'RHO=0.00025' 'RHO=0.001' 'RHO=0.0025' 'RHO=0.01' 'RHO=0.1'"
# mean contact pressure V / contact area of each case (plotted unit)
p_means = "2.1917808E+000 1.6000000E+000 1.2698413E+000 1.0000000E+000 1.0000000E+000"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig07_ref_sweep.png' 'fricon: Fig. 7 reference: beam N_e 160, all P1 (sweep)' 'BEAM'
