# spinStarDemo (section 2.3.3, Figure 11).
$(eval $(call p2_demo,spin_star_demo,motion cli,spin_circle.tsv spin_star_a.dat spin_star_b.dat spin_circle_runs.tsv,spin_circle.tsv,OMP_WAIT_POLICY=passive))
$(eval $(call p2_figure,fig11,spin_star_a.dat spin_star_b.dat))
P2_RESULTS += $(P2_OUT)/fig11.png $(P2_OUT)/spin_circle_runs.tsv
