# fig09.gp -- Figure 9 of the toolbox: curvatureStarDemo, motion by mean
# curvature of a star; top row (a) constant b0 = 0.02, bottom row (b) the
# time and space varying b(x, t) (splitFlow).  Zero contour at the output
# times 0, 0.25, 0.5, 1 (index blocks 0..3), the initial star in grey.
# Variables (gnuplot -e): dir = directory of curvature_star_[ab].dat, out = PNG.
set terminal pngcairo size 1300,700 font "Helvetica,10"
set output out
set view map
unset surface
set contour base
set cntrparam levels discrete 0
set table $A
splot for [k=0:3] dir.'/curvature_star_a.dat' index k using 1:2:3 with lines
unset table
set table $B
splot for [k=0:3] dir.'/curvature_star_b.dat' index k using 1:2:3 with lines
unset table
array T[4] = [0, 0.25, 0.5, 1]
set xlabel "x"; set ylabel "y"
set multiplot layout 2,4 title "Figure 9: motion by mean curvature (curvatureStarDemo); top (a) constant b_0 = 0.02, bottom (b) splitFlow b(x,t)"
set size ratio -1
set xrange [-1:1]; set yrange [-1:1]
set xtics 0.5; set ytics 0.5
unset key
do for [k=0:3] {
    set title sprintf("(a) t = %.3g", T[k + 1])
    plot $A index 0 using 1:2 with lines lc rgb "#bbbbbb", $A index k using 1:2 with lines lw 1.5 lc rgb "#1f4fb0"
}
do for [k=0:3] {
    set title sprintf("(b) t = %.3g", T[k + 1])
    plot $B index 0 using 1:2 with lines lc rgb "#bbbbbb", $B index k using 1:2 with lines lw 1.5 lc rgb "#b03020"
}
unset multiplot
