# fig12.gp -- Figure 12 of the toolbox: tripleSine, normal motion with speed
# 1 - b kappa for b = 0.1, 0.025, 0.  In each panel the zero contours of the
# 12 output times t = 0.5 k / 11 (index blocks 0..11), the initial curve
# lowest, as in the toolbox's single axes.
# Variables (gnuplot -e): dir = directory of triple_sine_b*.dat, out = PNG.
set terminal pngcairo size 1500,560 font "Helvetica,10"
set output out
set view map
unset surface
set contour base
set cntrparam levels discrete 0
set table $A
splot for [k=0:11] dir.'/triple_sine_b0.1.dat' index k using 1:2:3 with lines
unset table
set table $B
splot for [k=0:11] dir.'/triple_sine_b0.025.dat' index k using 1:2:3 with lines
unset table
set table $C
splot for [k=0:11] dir.'/triple_sine_b0.dat' index k using 1:2:3 with lines
unset table
set multiplot layout 1,3 title "Figure 12: the viscous limit, normal motion with speed 1 - b kappa (tripleSine), t = 0 ... 0.5"
set size ratio -1
set xrange [0:2]; set yrange [0:2]
set xlabel "x"; set ylabel "y"
unset key
set title "b = 0.1"
plot for [k=0:11] $A index k using 1:2 with lines lw 1.2 lc rgb "#1f4fb0"
set title "b = 0.025"
plot for [k=0:11] $B index k using 1:2 with lines lw 1.2 lc rgb "#1f4fb0"
set title "b = 0"
plot for [k=0:11] $C index k using 1:2 with lines lw 1.2 lc rgb "#1f4fb0"
unset multiplot
