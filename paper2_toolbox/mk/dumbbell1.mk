# dumbbell1 (section 2.4.2, Figure 13).
$(eval $(call p2_demo,dumbbell1,motion cli,dumbbell.tsv dumbbell_vox.dat dumbbell_slice.dat dumbbell.vtk dumbbell_runs.tsv dumbbell_orders.tsv,dumbbell.tsv,OMP_WAIT_POLICY=passive))
$(eval $(call p2_figure,fig13,dumbbell_vox.dat dumbbell_slice.dat))
P2_RESULTS += $(P2_OUT)/fig13.png $(P2_OUT)/dumbbell_runs.tsv $(P2_OUT)/dumbbell_orders.tsv $(P2_OUT)/dumbbell.vtk
