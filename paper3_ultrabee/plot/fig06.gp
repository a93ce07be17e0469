# fig06.gp -- Figure 6 of Bokanowski, Cristiani & Zidani (2010): Example 2,
# the rendez-vous problem theta_t + theta_x1 + |theta_x2| = 0 with the large
# target |x|_inf <= 0.1, N = 101 on [-1, 2]^2, at T = 1: the UB-HJB front
# (0 contour of V), the level set (RK2-ENO2) front (0 contour) and the
# exact front, the boundary of [T - r, T + r] x [-T - r, T + r].
# Data: fig06_rendezvous.dat (x y V_ub V_ls), written by examples2d.
# Variables (gnuplot -e): dir = directory of the data, out = PNG.
set terminal pngcairo size 800,760 font "Helvetica,11"
set output out
f = dir.'/fig06_rendezvous.dat'
set view map
unset surface
set contour base
set cntrparam levels discrete 0
set cntrparam linear
set table $ub
splot f using 1:2:3 with lines
unset table
set table $ls
splot f using 1:2:4 with lines
unset table
T = 1; r = 0.1
set size ratio -1
set xrange [-0.2:1.4]; set yrange [-1.2:1.3]
set xlabel "x_1"; set ylabel "x_2"
set key outside bottom center horizontal
set title "Figure 6 (Example 2): rendez-vous problem, large target r = 0.1, N = 101, T = 1"
# the exact front and the target as closed polygons
set print $ex
print sprintf("%g %g\n%g %g\n%g %g\n%g %g\n%g %g", T-r,-T-r, T+r,-T-r, T+r,T+r, T-r,T+r, T-r,-T-r)
unset print
set print $tg
print sprintf("%g %g\n%g %g\n%g %g\n%g %g\n%g %g", -r,-r, r,-r, r,r, -r,r, -r,-r)
unset print
# the domain [-1, 2]^2 ends at x2 = -1 (the exact set reaches -1.1)
set arrow 1 from graph 0, first -1 to graph 1, first -1 nohead lc rgb "gray60" dt 3
set label 1 "domain edge x_2 = -1" at first -0.15, first -1.05 textcolor rgb "gray40"
plot $tg using 1:2 with lines lw 1.5 dt 2 lc rgb "gray40" title "target (t = 0)", \
     $ex using 1:2 with lines lw 1.5 lc rgb "black" title "exact front", \
     $ub using 1:2 with lines lw 2.5 lc rgb "#1f5fa8" title "UB-HJB (V = 0)", \
     $ls using 1:2 with lines lw 2 dt (6,3) lc rgb "#d62728" title "level set RK2-ENO2 (phi = 0)"
