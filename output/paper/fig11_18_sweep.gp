# fricon sweep figure: run from the project root as  gnuplot output/paper/fig11_18_sweep.gp
files = "output/paper/fig11_18_001.dat output/paper/fig11_18_002.dat output/paper/fig11_18_003.dat output/paper/fig11_18_004.dat output/paper/fig11_18_005.dat"
labels = "RHO=0.001 RHO=0.01 RHO=0.1 RHO=1.0 RHO=10.0"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig11_18_sweep.png' 'Figs. 11-18: plate, rho sweep, f 0.6, h/a 0.1 (sweep)' 'PLATE'
