# fricon figure: run from the project root as  gnuplot output/paper/table1_003.gp
call 'scripts/gnuplot/fricon_panels.gp' 'output/paper/table1_003.dat' 'output/paper/table1_003.png' 'Table 1: beam rho 0.0025 f 0.6, load V=1 H=0.1, b/l 0.0055, h/l 0.1' 'BEAM'
