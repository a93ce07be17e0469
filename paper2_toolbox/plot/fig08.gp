# fig08.gp -- Figure 8 of the toolbox: curvatureSpiralDemo, motion by mean
# curvature of a wound spiral.  Zero contour at the 9 output times
# t = k/8 (index blocks 0..8), one subplot each as in the toolbox.
# Variables (gnuplot -e): dir = directory of curvature_spiral.dat, out = PNG;
# fig08b.gp sets dat and ttl to draw the point-cloud spiral with this file.
if (!exists("dat")) dat = 'curvature_spiral.dat'
if (!exists("ttl")) ttl = "Figure 8 (a): motion by mean curvature of a wound spiral (curvatureSpiralDemo, b = 0.075)"
set terminal pngcairo size 1000,1050 font "Helvetica,10"
set output out
set view map
unset surface
set contour base
set cntrparam levels discrete 0
set table $S
splot for [k=0:8] dir.'/'.dat index k using 1:2:3 with lines
unset table
set xlabel "x"; set ylabel "y"
set multiplot layout 3,3 title ttl
set size ratio -1
set xrange [-1:1]; set yrange [-1:1]
set xtics 0.5; set ytics 0.5
unset key
do for [k=0:8] {
    set title sprintf("t = %.3g", k / 8.0)
    plot $S index k using 1:2 with lines lw 1.5 lc rgb "#1f4fb0"
}
unset multiplot
