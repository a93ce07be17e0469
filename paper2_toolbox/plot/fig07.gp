# fig07.gp -- Figure 7 of the toolbox: maskDemo.  (a) the set {phi < 0}
# convected to the right through the masked disc S (dashed), zero level set
# at the nine output times; (b) S and min_t phi recorded by the
# post-timestep function (colour; white: its zero level set).
# Variables: dir, out.
set terminal pngcairo size 1100,1500 font "Helvetica,10"
set output out
fa = dir.'/mask_seq.dat'
fb = dir.'/mask_min.dat'
set view map
unset surface
set contour base
set cntrparam levels discrete 0
do for [k=0:8] {
    eval sprintf('set table $a%d', k)
    splot fa index k using 1:2:3 with lines
    unset table
}
set table $s
splot fb using 1:2:3 with lines
unset table
set table $m
splot fb using 1:2:4 with lines
unset table
set size ratio -1
set xrange [-1:1]; set yrange [-1:1]
set xtics 0.5; set ytics 0.5
unset key
set xlabel "x"; set ylabel "y"
set multiplot title "Figure 7: maskDemo('low'): constraint phi >= psi applied by the PostTimestep function"
do for [k=0:8] {
    set origin (k % 3) / 3.0, 0.74 - (k / 3) * 0.2
    set size 1/3.0, 0.2
    set title sprintf("(a) t = %.3g", 0.6 * k / 8.0)
    eval sprintf('plot $s using 1:2 with lines lw 1.5 dt 2 lc rgb "black", $a%d using 1:2 with lines lw 2 lc rgb "#1f5fa8"', k)
}
set origin 0.15, 0.0
set size 0.7, 0.34
set palette rgbformulae 22,13,-31
set cbrange [-0.35:0.6]
set cblabel "min_t phi"
set key outside right
set title "(b) masked disc S (black) and min_t phi (zero level set white)"
plot fb using 1:2:4 with image notitle, $m using 1:2 with lines lw 2 lc rgb "white" title "min_t phi = 0", \
     $s using 1:2 with lines lw 2 lc rgb "black" title "psi = 0 (edge of S)"
unset multiplot
