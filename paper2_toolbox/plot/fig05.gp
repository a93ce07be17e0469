# fig05.gp -- Figure 5 of the toolbox: the effect of reinitialization
# (reinitDemo('star', 'medium')) on the zero level set and on |grad phi|.
# (a) zero level sets of phi_0 and phi(1); (b) zoom on a point and a valley;
# (c), (d) |grad phi| before and after on one colour scale.
# Variables: dir, out.
set terminal pngcairo size 1100,1100 font "Helvetica,10"
set output out
f = dir.'/reinit_star_medium.dat'
set view map
unset surface
set contour base
set cntrparam levels discrete 0
set table $c0
splot f using 1:2:3 with lines
unset table
set table $c1
splot f using 1:2:4 with lines
unset table
unset contour
set multiplot layout 2,2 title "Figure 5: reinitDemo('star', 'medium'): implicit surface and gradient magnitude"
set size ratio -1
set xlabel "x"; set ylabel "y"
set key bottom right
set title "(a) zero level set: phi_0 (black), phi(1) (red, dashed)"
plot [-1:1][-1:1] $c0 using 1:2 with lines lw 2 lc rgb "black" title "phi_0 = 0", \
     $c1 using 1:2 with lines lw 2 dt 2 lc rgb "#c0392b" title "phi(1) = 0"
set title "(b) zoom: a point (right) and a valley"
plot [0.2:0.8][-0.3:0.3] $c0 using 1:2 with lines lw 2 lc rgb "black" title "phi_0 = 0", \
     $c1 using 1:2 with lines lw 2 dt 2 lc rgb "#c0392b" title "phi(1) = 0"
set palette rgbformulae 22,13,-31
set cbrange [0:3]
set cblabel "|grad phi|"
set xrange [-1:1]; set yrange [-1:1]
set title "(c) |grad phi_0| (centered differences; clipped at 3)"
plot f using 1:2:5 with image notitle, $c0 using 1:2 with lines lc rgb "white" lw 1.5 notitle
set title "(d) |grad phi(1)|"
plot f using 1:2:6 with image notitle, $c1 using 1:2 with lines lc rgb "white" lw 1.5 notitle
unset multiplot
