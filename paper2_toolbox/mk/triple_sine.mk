# tripleSine (section 2.4.1, Figure 12).
$(eval $(call p2_demo,triple_sine,motion cli,triple_sine.tsv triple_sine_b0.1.dat triple_sine_b0.025.dat triple_sine_b0.dat triple_sine_runs.tsv,triple_sine.tsv,OMP_WAIT_POLICY=passive))
$(eval $(call p2_figure,fig12,triple_sine_b0.1.dat triple_sine_b0.025.dat triple_sine_b0.dat))
P2_RESULTS += $(P2_OUT)/fig12.png $(P2_OUT)/triple_sine_runs.tsv
