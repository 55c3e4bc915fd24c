# cross-deck overlay written by scripts/paper.sh: gnuplot output/paper/fig09_compare_rho0.00025.gp (from the project root)
# tractions: the finite-element values Sigma_x^h (column 13), Sigma_z^h (column 14)
c_s = 13; c_p = 14
files = "output/paper/fig09a_001.dat output/paper/fig09b_001.dat output/paper/fig09c_001.dat output/paper/fig09_p2_18_001.dat output/paper/fig09_p2_22_001.dat output/paper/fig07_ref_001.dat"
labels = "(a)P1,N_e=30 (b)W:S2,N_e=18 (c)W,psi:S2,N_e=22 W,psi:P2,N_e=18 W:P2,N_e=22 ref,P1,N_e=160"
call 'scripts/gnuplot/fricon_sweep.gp' 'output/paper/fig09_compare_rho0.00025.png' 'Fig. 9, rho 0.00025: displacement interpolations (interactions P1)' 'BEAM'
