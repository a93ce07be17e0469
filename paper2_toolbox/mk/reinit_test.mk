# reinitTest (section 2.7.3): signedDistanceIterative on reinitDemo's cases.
$(eval $(call p2_demo,reinit_test,reinit cli,reinit_test.tsv reinit_test_runs.tsv,reinit_test.tsv,OMP_WAIT_POLICY=passive))
P2_RESULTS += $(P2_OUT)/reinit_test_runs.tsv
