# fig20.gp -- Figure 20 of the toolbox: reachable set in the first mode of
# the three-mode collision avoidance protocol (airMode, accuracy medium,
# N = 201 on [-25, 25]^2).  Filled: the set where collision is inevitable
# (reach < 0); solid red: the boundary of the set where initiating the
# protocol is unsafe (avoid = 0; outside it the protocol can be safely
# initiated); dashed: the unsafe set if no protocol is initiated (mode3 = 0).
# As airMode.m, the axes are clipped by 5 to hide the artificial boundary.
# Variables (gnuplot -e): dir = directory of air_mode_2d.dat, out = PNG.
set terminal pngcairo size 800,800 font "Helvetica,11"
set output out
f = dir.'/air_mode_2d.dat'
set view map
unset surface
set contour base
set cntrparam levels discrete 0
set table $avoid
splot f using 1:2:4
unset table
set table $mode3
splot f using 1:2:5
unset table
set table $reach
splot f using 1:2:3
unset table
set size ratio -1
set xrange [-20:20]; set yrange [-20:20]
set xlabel "x_r"; set ylabel "y_r"
set title "Figure 20: three-mode collision avoidance, v_a = 3, v_b = 4, psi = -4pi/3, omega = 1"
set key bottom left opaque
plot f using 1:($3 < 0 ? $2 : 1/0) with points pt 5 ps 0.45 lc rgb "#9999aa" title "collision inevitable (reach < 0)", \
     $reach using 1:2 with lines lw 1.5 lc rgb "#333344" notitle, \
     $avoid using 1:2 with lines lw 2 lc rgb "#cc2222" title "unsafe to initiate the protocol (avoid = 0)", \
     $mode3 using 1:2 with lines lw 2 dt 2 lc rgb "#2255cc" title "unsafe without the protocol (mode 3)"
