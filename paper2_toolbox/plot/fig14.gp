# fig14.gp -- Figure 14 of the toolbox: burgersLF.  (a) 1-D, exact solution
# at t = 1.5/pi^2 (line) and ENO3-LLF on 10 and 40 nodes; (b) 2-D ENO3-LLF
# on 40^2 nodes at t = 1.5/pi^2 (surface), from burgers_lf's data.
# Variables (gnuplot -e): dir = directory of burgers_1d.dat, burgers_2d.dat; out = PNG.
set terminal pngcairo size 1300,560 font "Helvetica,11"
set output out
set multiplot layout 1,2 title "Figure 14: Burgers' equation D_t phi + (1 + sum_i D_i phi)^2 / 2 = 0 with Lax-Friedrichs, t = 1.5/pi^2"
set title "(a) 1-D: exact (line), ENO3-LLF on 10 nodes (circles) and 40 nodes (crosses)"
set xlabel "x"; set ylabel "phi"; set grid
set key top center
plot dir.'/burgers_1d.dat' index 0 using 1:2 with lines lw 2 lc rgb "#000000" title "exact", \
     '' index 1 using 1:2 with points pt 6 ps 1.6 lc rgb "#cc2222" title "N = 10", \
     '' index 2 using 1:2 with points pt 2 ps 1.0 lc rgb "#2255cc" title "N = 40"
unset grid
set title "(b) 2-D: ENO3-LLF on 40^2 nodes"
set xlabel "x"; set ylabel "y"; set zlabel "phi" rotate
set view 55, 35
set hidden3d
unset key
set xrange [-2:2]; set yrange [-2:2]
splot dir.'/burgers_2d.dat' index 10 using 1:2:3 with lines lc rgb "#2255cc"
unset multiplot
