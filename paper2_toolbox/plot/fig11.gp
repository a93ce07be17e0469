# fig11.gp -- Figure 11 of the toolbox: spinStarDemo, normal motion (a = 0.2)
# plus rotation of a star; top row (a) rigid rotation, bottom row (b)
# rotation speed times |x|^2.  Zero contours at t = 0, 0.25, 0.5, 0.75, 1
# (index blocks 0, 2, 4, 6, 8 of the 9 output times), the initial star in
# grey behind each.
# Variables (gnuplot -e): dir = directory of spin_star_[ab].dat, out = PNG.
set terminal pngcairo size 1500,680 font "Helvetica,10"
set output out
set view map
unset surface
set contour base
set cntrparam levels discrete 0
set table $A
splot for [k=0:8] dir.'/spin_star_a.dat' index k using 1:2:3 with lines
unset table
set table $B
splot for [k=0:8] dir.'/spin_star_b.dat' index k using 1:2:3 with lines
unset table
set xlabel "x"; set ylabel "y"
set multiplot layout 2,5 title "Figure 11: normal motion (a = 0.2) plus rotation (omega = 0.75 pi); top (a) rigid, bottom (b) speed times |x|^2 (Osher-Fedkiw figure 6.2)"
set size ratio -1
set xrange [-1:1]; set yrange [-1:1]
set xtics 0.5; set ytics 0.5
unset key
do for [k=0:8:2] {
    set title sprintf("(a) t = %.3g", k / 8.0)
    plot $A index 0 using 1:2 with lines lc rgb "#bbbbbb", $A index k using 1:2 with lines lw 1.5 lc rgb "#1f4fb0"
}
do for [k=0:8:2] {
    set title sprintf("(b) t = %.3g", k / 8.0)
    plot $B index 0 using 1:2 with lines lc rgb "#bbbbbb", $B index k using 1:2 with lines lw 1.5 lc rgb "#b03020"
}
unset multiplot
