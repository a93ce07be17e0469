# dumbbell1 (section 2.4.2, Figure 13); session h2.
P2_PROGS += dumbbell1
$(P2_BIN)/dumbbell1: $(BUILD)/obj/$(P2)/p2_motion.o
$(P2_OUT)/dumbbell.tsv $(P2_OUT)/dumbbell_vox.dat $(P2_OUT)/dumbbell_slice.dat $(P2_OUT)/dumbbell.vtk $(P2_OUT)/dumbbell_notes.md &: $(P2_BIN)/dumbbell1
	@mkdir -p $(P2_OUT)
	OMP_WAIT_POLICY=passive $< $(QUICKFLAG) --out-dir $(P2_OUT)
$(P2_OUT)/fig13.png: $(P2_OUT)/dumbbell_vox.dat $(P2_OUT)/dumbbell_slice.dat $(P2)/plot/fig13.gp
	gnuplot -e "dir='$(P2_OUT)'; out='$(@D)/.tmp-$(@F)'" $(P2)/plot/fig13.gp && mv $(@D)/.tmp-$(@F) $@
P2_RESULTS += $(P2_OUT)/fig13.png $(P2_OUT)/dumbbell_notes.md $(P2_OUT)/dumbbell.vtk
P2_CHECK += $(P2_OUT)/dumbbell.tsv
REPORT_INPUTS += $(P2)/dumbbell1.c $(P2)/plot/fig13.gp
