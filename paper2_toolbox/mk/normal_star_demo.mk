# normalStarDemo (section 2.3.2, Figure 10).
$(eval $(call p2_demo,normal_star_demo,motion cli,normal_circle.tsv normal_star_a.dat normal_star_b.dat normal_circle_runs.tsv,normal_circle.tsv,OMP_WAIT_POLICY=passive))
$(eval $(call p2_figure,fig10,normal_star_a.dat normal_star_b.dat))
P2_RESULTS += $(P2_OUT)/fig10.png $(P2_OUT)/normal_circle_runs.tsv
