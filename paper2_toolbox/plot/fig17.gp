# fig17.gp -- Figure 17 of the toolbox: the game of two identical vehicles
# (air3D).  (a) the target cylinder (collision set, radius 5), (b) the
# reachable set at t = 2.8 (accuracy medium), as isosurfaces phi = 0 on
# gnuplot 5.4 voxel grids (air3d_vox.dat: x y psi target reach, resampled on
# a 51^3 lattice spanning [-6, 20] x [-10, 10] x [0, 2 pi]).
# Variables (gnuplot -e): dir = directory of air3d_vox.dat, out = PNG.
set terminal pngcairo size 1300,620 font "Helvetica,11"
set output out
set multiplot layout 1,2 title "Figure 17: game of two identical vehicles, r = 5, v_a = v_b = 5, turn rates 1"
set xrange [-6:20]; set yrange [-10:10]; set zrange [0:2*pi]
set xlabel "x"; set ylabel "y"; set zlabel "psi" rotate
set view 60, 30
set xyplane 0
set ztics ("0" 0, "pi/2" pi/2, "pi" pi, "3pi/2" 3*pi/2, "2pi" 2*pi)
set vgrid $vt size 51
set vgrid $vr size 51
vclear $vt
vclear $vr
set vgrid $vt
vfill dir.'/air3d_vox.dat' using 1:2:3:(0):($4)
set vgrid $vr
vfill dir.'/air3d_vox.dat' using 1:2:3:(0):($5)
set pm3d depthorder border lc "black" lw 0.2
set style fill solid 0.9
unset key
set title "(a) target set: collision cylinder x^2 + y^2 <= 5^2"
splot $vt with isosurface level 0 fc "#cc6666"
set title "(b) reachable set at t = 2.8 (accuracy medium)"
splot $vr with isosurface level 0 fc "#6699cc"
unset multiplot
