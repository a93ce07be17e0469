# fig08.gp -- Figure 8: the same computation as Figure 7 (Example 3,
# UB-HJB and level set fronts at t = 3 and t = 6, CFL 0.9) with N = 50,
# drawn by fig07.gp from fig08_deformation.dat (written by examples2d).
# Variables (gnuplot -e): dir, out.  Run from the top of the repository.
dat = 'fig08_deformation.dat'
N = 50
fignum = 8
load 'paper3_ultrabee/plot/fig07.gp'
