# fig08b.gp -- Figure 8 (b): the wound spiral from the original point cloud of
# Osher & Sethian (curvatureSpiralDemo --initial points), drawn by fig08.gp.
# Variables (gnuplot -e): dir, out.
dat = 'curvature_spiral_points.dat'
ttl = "Figure 8 (b): the spiral from the point cloud of Osher and Sethian (b = 0.075)"
load 'paper2_toolbox/plot/fig08.gp'
