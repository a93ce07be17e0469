# fig15.gp -- Figure 15 of the toolbox: nonconvexLF.  (a) 1-D at t = 1.5/pi^2:
# a WENO5 reference on 2560 nodes (line), ENO3-LF on 10 and 40 nodes; (b) 2-D ENO3-LF
# on 40^2 nodes (surface), from nonconvex_lf's data.
# Variables (gnuplot -e): dir = directory of nonconvex_1d.dat, nonconvex_2d.dat; out = PNG.
set terminal pngcairo size 1300,560 font "Helvetica,11"
set output out
set multiplot layout 1,2 title "Figure 15: D_t phi - cos(1 + sum_i D_i phi) = 0 with Lax-Friedrichs, t = 1.5/pi^2"
set title "(a) 1-D: WENO5 on 2560 nodes (line), ENO3-LF on 10 (circles) and 40 nodes (crosses)"
set xlabel "x"; set ylabel "phi"; set grid
set key top center
plot dir.'/nonconvex_1d.dat' index 0 using 1:2 with lines lw 2 lc rgb "#000000" title "reference", \
     '' index 1 using 1:2 with points pt 6 ps 1.6 lc rgb "#cc2222" title "N = 10", \
     '' index 2 using 1:2 with points pt 2 ps 1.0 lc rgb "#2255cc" title "N = 40"
unset grid
set title "(b) 2-D: ENO3-LF on 40^2 nodes"
set xlabel "x"; set ylabel "y"; set zlabel "phi" rotate
set view 55, 35
set hidden3d
unset key
set xrange [-2:2]; set yrange [-2:2]
splot dir.'/nonconvex_2d.dat' index 10 using 1:2:3 with lines lc rgb "#2255cc"
unset multiplot
