# fig13.gp -- Figure 13 of the toolbox: dumbbell1, motion by mean curvature
# of a 3-D dumbbell.  (a) the zero isosurface at the 9 output times
# t = 0.025 k / 8 (gnuplot 5.4 voxel grids, 41^3 lattice, index blocks
# 0..8 of dumbbell_vox.dat); (b) the zero contours on the slice x_3 = 0 at
# the same times, overlaid (dumbbell_slice.dat).
# Variables (gnuplot -e): dir = directory of dumbbell_*.dat, out = PNG.
set terminal pngcairo size 1200,1250 font "Helvetica,10"
set output out
set multiplot title "Figure 13: motion by mean curvature of a dumbbell (dumbbell1, b = 1)"
# (a) isosurfaces
set xrange [-0.8:0.8]; set yrange [-0.3:0.3]; set zrange [-0.3:0.3]
set view 62, 20, 1.8
set view equal xyz
set xyplane 0
unset key
set border 0
unset xtics; unset ytics; unset ztics
set pm3d depthorder border lc rgb "#2f4f7f" lw 0.25
set pm3d nolighting
set style fill solid 0.9
set vgrid $v size 41
do for [k=0:8] {
    set origin (k % 3) / 3.0, 0.97 - (1 + int(k / 3)) * 0.235
    set size 1 / 3.0, 0.25
    set title sprintf("(a) t = %.5g", 0.025 * k / 8.0) offset 0,-1
    vclear $v
    vfill dir.'/dumbbell_vox.dat' index k using 1:2:3:(0):($4)
    splot $v with isosurface level 0 fc "#a8c4e6"
}
# (b) slice contours
unset view
set view map
unset surface
set contour base
set cntrparam levels discrete 0
set table $S
splot for [k=0:8] dir.'/dumbbell_slice.dat' index k using 1:2:3 with lines
unset table
set surface
set origin 0.05, 0.0
set size 0.9, 0.27
set xrange [-1:1]; set yrange [-0.5:0.5]
set size ratio -1
set xlabel "x_1"; set ylabel "x_2"
set border 31
set xtics 0.25; set ytics 0.25
set key outside right
set title "(b) zero contours on the slice x_3 = 0" offset 0,0
col(k) = hsv2rgb(0.66 * (1 - k / 8.0), 0.9, 0.85)
plot for [k=0:8] $S index k using 1:2 with lines lw 1.3 lc rgb col(k) title sprintf("t = %.5g", 0.025 * k / 8.0)
unset multiplot
