# fricon figure: run from the project root as  gnuplot output/paper/table1_003.gp
call 'scripts/gnuplot/fricon_panels.gp' 'output/paper/table1_003.dat' 'output/paper/table1_003.png' 'Paper Table 1: beam, H/V 0.1, b/l 0.005, zeta 0.1' 'BEAM'
