# curvatureStarDemo (section 2.3.1, Figure 9).
$(eval $(call p2_demo,curvature_star_demo,motion cli,curvature_star.tsv curvature_star_a.dat curvature_star_b.dat curvature_star_runs.tsv,curvature_star.tsv,OMP_WAIT_POLICY=passive))
$(eval $(call p2_figure,fig09,curvature_star_a.dat curvature_star_b.dat))
P2_RESULTS += $(P2_OUT)/fig09.png $(P2_OUT)/curvature_star_runs.tsv
