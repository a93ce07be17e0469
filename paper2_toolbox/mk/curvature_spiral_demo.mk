# curvatureSpiralDemo (section 2.3.1, Figure 8); session h2.
P2_PROGS += curvature_spiral_demo
$(P2_BIN)/curvature_spiral_demo: $(BUILD)/obj/$(P2)/p2_motion.o
$(P2_OUT)/curvature_spiral.tsv $(P2_OUT)/curvature_spiral.dat $(P2_OUT)/curvature_spiral_notes.md &: $(P2_BIN)/curvature_spiral_demo
	@mkdir -p $(P2_OUT)
	OMP_WAIT_POLICY=passive $< $(QUICKFLAG) --out-dir $(P2_OUT)
$(P2_OUT)/fig08.png: $(P2_OUT)/curvature_spiral.dat $(P2)/plot/fig08.gp
	gnuplot -e "dir='$(P2_OUT)'; out='$(@D)/.tmp-$(@F)'" $(P2)/plot/fig08.gp && mv $(@D)/.tmp-$(@F) $@
P2_RESULTS += $(P2_OUT)/fig08.png $(P2_OUT)/curvature_spiral_notes.md
P2_CHECK += $(P2_OUT)/curvature_spiral.tsv
REPORT_INPUTS += $(P2)/curvature_spiral_demo.c $(P2)/plot/fig08.gp
