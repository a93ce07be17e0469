# fig02.gp -- Figure 2 of the toolbox: convectionDemo('linearRev', 'low')
# with useSubplots = 0: the zero contours of all nine output times in one
# axis.  Clockwise for t <= 1/2 (red), counter-clockwise after (blue): the
# first order scheme's area loss keeps the circles of the two halves from
# overlapping.  Variables: dir, out.
set terminal pngcairo size 800,800 font "Helvetica,11"
set output out
f = dir.'/convection_2d_linearRev_low.dat'
# contour lines of each output time into datablocks $c0 .. $c8, then one 2-D plot
set view map
unset surface
set contour base
set cntrparam levels discrete 0
do for [k=0:8] {
    eval sprintf('set table $c%d', k)
    splot f index k using 1:2:3 with lines
    unset table
}
set size ratio -1
set xrange [-1:1]; set yrange [-1:1]
set xlabel "x"; set ylabel "y"
set key outside right top
set title "Figure 2: convectionDemo('linearRev', 'low'), zero level sets at t = 0, 1/8, ..., 1"
# t = 0 black; forward half (t <= 1/2) red; return blue; t = 1 dashed blue
cmd = 'plot '
do for [k=0:8] {
    style = k == 0 ? 'lc rgb "black" lw 3' : k <= 4 ? 'lc rgb "#c0392b" lw 1.5' : k < 8 ? 'lc rgb "#1f5fa8" lw 1.5' : 'lc rgb "#1f5fa8" lw 3 dt 2'
    cmd = cmd.sprintf('$c%d using 1:2 with lines %s title "t = %g"%s', k, style, k/8.0, k < 8 ? ', ' : '')
}
eval cmd
