# fig09.gp -- Figure 9 of Bokanowski, Cristiani & Zidani (2010): Example 4
# on [-2, 2]^3 with N = 50, f = (-2 pi x2, 2 pi x1, -1) and the ball of
# radius 0.1 centred at (-1, 0, 1): (left) the advection problem at T = 2
# (two turns and a descent by 2: the ball ends at (-1, 0, -1)), (right) the
# target problem (4) at T = 0.5 (the set reached within T: a half turn of
# the helix swept by the ball).  Blue: the UB-HJB set, isosurface V = 0 of
# the computed values; red, translucent: the exact set, isosurface g = 0
# of a continuous function with the exact set {g <= 0} (both on the N = 50
# grid, gnuplot 5.4 voxel grids).
# Data: fig09_advection.dat, fig09_target.dat (x y z V g on an m^3 cube of
# the grid around the sets), written by examples34d.
# Variables (gnuplot -e): dir, out.
set terminal pngcairo size 1300,650 font "Helvetica,11"
set output out
fa = dir.'/fig09_advection.dat'
ft = dir.'/fig09_target.dat'
set multiplot layout 1,2 title "Figure 9 (Example 4): UB-HJB on the 50^3 grid of [-2, 2]^3 (blue: V = 0) and the exact set (red, translucent)"
set xlabel "x_1"; set ylabel "x_2"; set zlabel "x_3" rotate
set xyplane 0
set pm3d depthorder border lc "black" lw 0.2
unset key
set style fill solid 1.0
# gnuplot 5.4.4 colours isosurface facets by line type (fc is ignored):
# 1 the UB-HJB set, 2 the exact set (alpha 0x90: translucent)
set linetype 1 lc rgb "#4477cc"
set linetype 2 lc rgb "#90cc3333"
do for [p=0:1] {
    f = p ? ft : fa
    set xrange [*:*]; set yrange [*:*]; set zrange [*:*]
    stats f using 1 nooutput
    m = int(STATS_records ** (1.0 / 3) + 0.5)
    x0 = STATS_min; x1 = STATS_max
    stats f using 2 nooutput
    y0 = STATS_min; y1 = STATS_max
    stats f using 3 nooutput
    z0 = STATS_min; z1 = STATS_max
    set xrange [x0:x1]; set yrange [y0:y1]; set zrange [z0:z1]
    set view equal xyz
    set view 60, 30 + 30 * p
    if (p) { unset vgrid $vu; unset vgrid $ve }
    set vgrid $vu size m
    vclear $vu
    vfill f using 1:2:3:(0):($4)
    set vgrid $ve size m
    vclear $ve
    vfill f using 1:2:3:(0):($5)
    if (p) { set title "target problem (4), T = 0.5: reachable set {V <= 0}" }
    else { set title "advection problem, T = 2: the ball after two turns" }
    splot $vu with isosurface level 0 lt 1, \
          $ve with isosurface level 0 lt 2
}
unset multiplot
