# fig21.gp -- Figure 21 of the toolbox: CSG shapes in 2-D (zero contours)
# and 3-D (isosurfaces on gnuplot 5.4 voxel grids), and the 1-D functions.
# Variables (gnuplot -e): dir = directory of fig21_*.tsv/dat, out = PNG.
set terminal pngcairo size 1100,1400 font "Helvetica,11"
set output out
set datafile separator whitespace
set multiplot layout 3,2 title "Figure 21: shapes and constructive solid geometry"

# 1-D: the implicit surface functions (the sets are where they are < 0)
set title "1-D: interval, half-line"
set xlabel "x"; set ylabel "phi"; set grid
plot dir.'/fig21_1d.tsv' using 1:2 with lines lw 2 title "[-0.4, 0.6]", \
     '' using 1:3 with lines lw 2 title "(-inf, 0.3]", 0 with lines lc rgb "#888888" notitle
set title "1-D: difference and complement"
plot dir.'/fig21_1d.tsv' using 1:4 with lines lw 2 title "[-0.4, 0.6] minus [-0.4, 0]", \
     '' using 1:5 with lines lw 2 title "complement of [-0.4, 0.6]", 0 with lines lc rgb "#888888" notitle
unset grid

# 2-D: zero level sets
set view map
set size ratio -1
unset surface
set contour base
set cntrparam levels discrete 0
unset key
set xrange [-1:1]; set yrange [-1:1]
set xlabel "x"; set ylabel "y"
set title "(a) square subtracted from a circle"
splot dir.'/fig21_2d.tsv' using 1:2:3 with lines lw 2
set title "(b) non-convex polygon from hyperplanes"
splot dir.'/fig21_2d.tsv' using 1:2:4 with lines lw 2

# 3-D: isosurfaces phi = 0
unset contour
set surface
set view 60, 35
set size ratio 0
set xrange [-1:1]; set yrange [-1:1]; set zrange [-1:1]
set xyplane 0
set zlabel "z"
set vgrid $vc size 81
set vgrid $vd size 81
vclear $vc
vclear $vd
set vgrid $vc
vfill dir.'/fig21_3d.dat' using 1:2:3:(0):($4)
set vgrid $vd
vfill dir.'/fig21_3d.dat' using 1:2:3:(0):($5)
set pm3d depthorder border lc "black" lw 0.3
set style fill solid 0.9
set title "(c) union of a sphere and a cube"
splot $vc with isosurface level 0 fc "#6699cc"
set title "(d) octahedron from eight hyperplanes"
splot $vd with isosurface level 0 fc "#cc9966"
unset multiplot
