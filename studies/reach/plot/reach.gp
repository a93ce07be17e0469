# The reachability checks' figure (studies/reach): gnuplot -e "dir='...'; out='...'" reach.gp
# Left: double integrator time-to-reach (contours 0.1 .. 0.7) against the
# closed form T0 - 1; middle: Dubins car with wind, closed-loop paths from
# states inside (blue) and outside (red) the reach-avoid set; right: the
# set with the moving bar obstacle (time-varying) and frozen at t = 0.
set terminal pngcairo size 1500,520 font ",10"
set output out
set multiplot layout 1,3

set view map
unset surface
set contour base
set cntrparam levels incremental 0.1, 0.2, 0.7
set size ratio -1
set xlabel "x"; set ylabel "v"
set title "double integrator: time-to-reach (solid) vs T0 - 1 (dashed)"
set table $c1
splot dir.'/di_mintime.dat' using 1:2:3 with lines
unset table
set table $c2
splot dir.'/di_mintime.dat' using 1:2:4 with lines
unset table
plot $c1 using 1:2 with lines lw 1.5 lc rgb "#1f77b4" title "computed", \
     $c2 using 1:2 with lines dt 2 lc rgb "black" title "exact"

set xrange [-2:2]; set yrange [-2:2]
set xlabel "x"; set ylabel "y"
set title "Dubins car with wind: closed-loop paths"
set object 1 rect from -1.4,0.2 to -0.6,1.4 fc rgb "#999999" fs solid 0.5 noborder
set object 2 circle at 0,0 size 0.5 fc rgb "#2ca02c" fs transparent solid 0.3 noborder
plot dir.'/trajectories.dat' using 1:2:($5 > 0 ? 0x1f77b4 : 0xd62728) with lines lc rgb variable notitle
unset object 1; unset object 2

set cntrparam levels discrete 0
set title "moving bar obstacle: reach-avoid set"
set table $m1
splot dir.'/moving_obstacle.dat' using 1:2:3 with lines
unset table
set table $m2
splot dir.'/moving_obstacle.dat' using 1:2:4 with lines
unset table
set object 3 circle at 0,0 size 0.3 fc rgb "#2ca02c" fs transparent solid 0.3 noborder
plot $m1 using 1:2 with lines lw 2 lc rgb "#1f77b4" title "obstacle moving (ours)", \
     $m2 using 1:2 with lines dt 2 lw 2 lc rgb "#d62728" title "obstacle frozen at t = 0"
unset multiplot
