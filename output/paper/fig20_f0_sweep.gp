# fricon sweep figure: run from the project root as  gnuplot output/paper/fig20_f0_sweep.gp
files = "output/paper/fig20_f0_001.dat output/paper/fig20_f0_002.dat output/paper/fig20_f0_003.dat output/paper/fig20_f0_004.dat output/paper/fig20_f0_005.dat"
labels = "ZETA=0.025 ZETA=0.05 ZETA=0.1 ZETA=0.2 ZETA=0.3"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig20_f0_sweep.png' 'Fig. 20 control: plate rho 0.01, f 0 (frictionless), h/a sweep (sweep)' 'PLATE'
