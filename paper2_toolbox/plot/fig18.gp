# fig18.gp -- Figure 18 of the toolbox: evolution of the acoustic capture
# game's reachable set (acoustic, accuracy medium, dx = 1/25), the zero
# level set at t = 0, 0.5, ..., 4 (the toolbox's 3 x 3 subplots); the
# target rectangle [-3.5, 3.5] x [-0.2, 0] in grey.
# Variables (gnuplot -e): dir = directory of acoustic_2d.dat, out = PNG.
set terminal pngcairo size 1200,1000 font "Helvetica,10"
set output out
set view map
unset surface
set contour base
set cntrparam levels discrete 0
set size ratio -1
unset key
set xrange [-4:4]; set yrange [-2:3]
set object 1 rect from -3.5,-0.2 to 3.5,0 fc rgb "#bbbbbb" fs solid 0.6 noborder back
set xlabel "x"; set ylabel "y"
set multiplot layout 3,3 title "Figure 18: acoustic capture, W_e = 1.3, W_p = 1.5, R = 0.8, S = 0.5: reachable set boundary"
do for [k=0:8] {
  set title sprintf("t = %.1f", 0.5 * k)
  splot dir.'/acoustic_2d.dat' index k using 1:2:3 with lines lw 2 lc rgb "#2255cc"
}
unset multiplot
