# curvatureSpiralDemo (section 2.3.1, Figure 8).
$(eval $(call p2_demo,curvature_spiral_demo,motion cli,curvature_spiral.tsv curvature_spiral.dat curvature_spiral_points.dat curvature_spiral_runs.tsv,curvature_spiral.tsv,OMP_WAIT_POLICY=passive))
$(eval $(call p2_figure,fig08,curvature_spiral.dat))
$(eval $(call p2_figure,fig08b,curvature_spiral_points.dat))
$(P2_OUT)/fig08b.png: $(P2)/plot/fig08.gp
P2_RESULTS += $(P2_OUT)/fig08.png $(P2_OUT)/fig08b.png $(P2_OUT)/curvature_spiral_runs.tsv
