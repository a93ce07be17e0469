# fig05.gp -- Figure 5 of Bokanowski, Cristiani & Zidani (2010): the fixed
# fronts of the storage comparison (section 3.3) in d = 2, with their band
# F+ u F- on the 100^2 grid of [-2, 2]^2: (left) Example 1, six nested
# circles of radii 0.3 k, k = 1..6; (right) Example 2, the rectangle
# (cylinder in d = 3, 4) |x_1| <= 0.5, |x_2| <= 1.6.  F- (inside nodes with
# a face neighbour outside) blue, F+ red, the exact fronts black.
# Data: fig05_fronts.dat (x y side; index 0, 1), written by storage.
# Variables (gnuplot -e): dir, out.
set terminal pngcairo size 1200,640 font "Helvetica,11"
set output out
f = dir.'/fig05_fronts.dat'
set size ratio -1
set xrange [-2:2]; set yrange [-2:2]
set xtics 1; set ytics 1
set xlabel "x_1"; set ylabel "x_2"
set key outside bottom center horizontal
set parametric
set trange [0:2*pi]
set samples 400
set multiplot layout 1,2 title "Figure 5: fronts of the storage tests and their band F+ u F- (N = 100, d = 2)"
set title "Example 1: six nested circles, radii 0.3 k"
plot f index 0 using 1:($3 < 0 ? $2 : NaN) with points pt 7 ps 0.35 lc rgb "#1f5fa8" title "F- (inside)", \
     f index 0 using 1:($3 > 0 ? $2 : NaN) with points pt 7 ps 0.35 lc rgb "#d62728" title "F+ (outside)", \
     for [k=1:6] 0.3*k*cos(t), 0.3*k*sin(t) with lines lw 1 lc rgb "black" title (k == 1 ? "exact front" : "")
set title "Example 2: rectangle |x_1| <= 0.5, |x_2| <= 1.6"
set print $rect
print "-0.5 -1.6\n0.5 -1.6\n0.5 1.6\n-0.5 1.6\n-0.5 -1.6"
unset print
unset parametric
plot f index 1 using 1:($3 < 0 ? $2 : NaN) with points pt 7 ps 0.35 lc rgb "#1f5fa8" title "F- (inside)", \
     f index 1 using 1:($3 > 0 ? $2 : NaN) with points pt 7 ps 0.35 lc rgb "#d62728" title "F+ (outside)", \
     $rect using 1:2 with lines lw 1 lc rgb "black" title "exact front"
unset multiplot
