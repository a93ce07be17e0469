# fig01.gp -- Figure 1 of the toolbox: convectionDemo('linear', 'medium'),
# the zero contour at the nine output times t = 0, 1/8, ..., 1 (one
# clockwise turn), as the demo's 3 x 3 subplots.
# Variables (gnuplot -e): dir = directory of convection_2d_linear_medium.dat, out = PNG.
set terminal pngcairo size 1050,1050 font "Helvetica,10"
set output out
f = dir.'/convection_2d_linear_medium.dat'
set view map
set size ratio -1
unset surface
set contour base
set cntrparam levels discrete 0
unset key
set xrange [-1:1]; set yrange [-1:1]
set xtics 0.5; set ytics 0.5
set xlabel "x"; set ylabel "y"
set multiplot layout 3,3 title "Figure 1: convectionDemo('linear', 'medium'), zero level set of phi"
do for [k=0:8] {
    set title sprintf("t = %g", k/8.0)
    splot f index k using 1:2:3 with lines lw 2 lc rgb "#1f5fa8"
}
unset multiplot
