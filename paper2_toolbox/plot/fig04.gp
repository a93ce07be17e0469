# fig04.gp -- Figure 4 of the toolbox: reinitDemo('star', 'medium', 'surf'),
# phi_0 and phi(t_max) as surfaces (the slope of the final phi is much more
# uniform).  Variables: dir = directory of reinit_star_medium.dat, out = PNG.
set terminal pngcairo size 1200,560 font "Helvetica,10"
set output out
f = dir.'/reinit_star_medium.dat'
set multiplot layout 1,2 title "Figure 4: reinitDemo('star', 'medium'): phi_0 (left) and phi(1) (right)"
set view 55, 35
set xrange [-1:1]; set yrange [-1:1]; set zrange [-0.8:1.5]
set xlabel "x"; set ylabel "y"
set pm3d depthorder
set palette rgbformulae 33,13,10
set cbrange [-0.8:1.5]
unset colorbox
unset key
set contour base
set cntrparam levels discrete 0
set title "phi_0 (13), star with 7 points"
splot f using 1:2:3 with pm3d, f using 1:2:3 with lines lc rgb "black" nosurface
set title "phi(1) after reinitialization"
splot f using 1:2:4 with pm3d, f using 1:2:4 with lines lc rgb "black" nosurface
unset multiplot
