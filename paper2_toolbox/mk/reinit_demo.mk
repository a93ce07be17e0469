# reinitDemo (section 2.2.1, Figures 4-5).
$(eval $(call p2_demo,reinit_demo,reinit convection cli,reinit.tsv reinit_runs.tsv reinit_star_medium.dat,reinit.tsv,OMP_WAIT_POLICY=passive))
$(eval $(call p2_figure,fig04,reinit_star_medium.dat))
$(eval $(call p2_figure,fig05,reinit_star_medium.dat))
P2_RESULTS += $(P2_OUT)/fig04.png $(P2_OUT)/fig05.png $(P2_OUT)/reinit_runs.tsv
