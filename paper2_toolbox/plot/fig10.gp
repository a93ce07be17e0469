# fig10.gp -- Figure 10 of the toolbox: normalStarDemo, motion in the normal
# direction of a star; (a) constant speed, (b) speed reversed at t = 0.5.
# Zero contours of the 9 output times (index blocks 0..8) overlaid, from
# blue (t = 0) to red (t = 1).
# Variables (gnuplot -e): dir = directory of normal_star_[ab].dat, out = PNG.
set terminal pngcairo size 1200,640 font "Helvetica,11"
set output out
set view map
unset surface
set contour base
set cntrparam levels discrete 0
set table $A
splot for [k=0:8] dir.'/normal_star_a.dat' index k using 1:2:3 with lines
unset table
set table $B
splot for [k=0:8] dir.'/normal_star_b.dat' index k using 1:2:3 with lines
unset table
col(k) = hsv2rgb(0.66 * (1 - k / 8.0), 0.9, 0.85)
set multiplot layout 1,2 title "Figure 10: motion in the normal direction (normalStarDemo, |a| = 0.25, 101^2 nodes)"
set size ratio -1
set xrange [-1:1]; set yrange [-1:1]
set xlabel "x"; set ylabel "y"
set key outside right top
set title "(a) constant speed a = +0.25"
plot for [k=0:8] $A index k using 1:2 with lines lw 1.5 lc rgb col(k) title sprintf("t = %.3g", k / 8.0)
set title "(b) a = +0.25 for t <= 0.5, -0.25 after"
plot for [k=0:8] $B index k using 1:2 with lines lw 1.5 lc rgb col(k) title sprintf("t = %.3g", k / 8.0)
unset multiplot
