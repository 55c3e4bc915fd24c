# cross-deck overlay written by scripts/paper.sh: gnuplot output/paper/fig07_compare_rho0.0025.gp (from the project root)
# tractions: the finite-element values Sigma_x^h (column 13), Sigma_z^h (column 14)
c_s = 13; c_p = 14
files = "output/paper/fig07_p1_003.dat output/paper/fig07_s2_003.dat output/paper/fig07_ref_003.dat"
labels = "P1,N_e=20 S2,N_e=20 P1,N_e=160"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig07_compare_rho0.0025.png' 'Fig. 7, rho 0.0025: interactions P1 vs S2 (N_e 20) and reference (N_e 160)' 'BEAM'
