# fig03.gp -- Figure 3 of the toolbox: convectionDemo in other dimensions.
# (a) 1-D 'constantRev', 'veryHigh': phi at the nine output times.
# (b) 3-D 'linear', 'medium': the zero isosurface at the nine output times
#     (gnuplot 5.4 voxel grid on every second node, 51^3).
# Variables: dir, out.
set terminal pngcairo size 1050,2000 font "Helvetica,10"
set output out
f1 = dir.'/convection_1d_constantRev_veryHigh.dat'
f3 = dir.'/convection_3d_linear_medium.dat'
set xlabel "x"; set ylabel "phi"
set multiplot layout 6,3 title "Figure 3: (a) 1-D convectionDemo('constantRev', 'veryHigh'), phi;  (b) 3-D convectionDemo('linear', 'medium'), phi = 0"
set xrange [-1:1]; set yrange [-0.4:1.6]
set grid
unset key
do for [k=0:8] {
    set title sprintf("(a) t = %g", k/8.0)
    plot f1 index k using 1:2 with lines lw 2 lc rgb "#1f5fa8", 0 with lines lc rgb "#888888"
}
unset grid
set xrange [-1:1]; set yrange [-1:1]; set zrange [-1:1]
set xlabel "x"; set ylabel "y"; set zlabel "z"
set view 55, 30
set xyplane 0
set xtics 1; set ytics 1; set ztics 1
set pm3d depthorder border lc "black" lw 0.2
set style fill solid 0.9
set vgrid $v size 51
do for [k=0:8] {
    vclear $v
    vfill f3 index k using 1:2:3:(0):($4)
    set title sprintf("(b) t = %g", k/8.0)
    splot $v with isosurface level 0 fc "#6699cc"
}
unset multiplot
