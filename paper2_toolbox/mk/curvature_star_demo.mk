# curvatureStarDemo (section 2.3.1, Figure 9); session h2.
P2_PROGS += curvature_star_demo
$(P2_BIN)/curvature_star_demo: $(BUILD)/obj/$(P2)/p2_motion.o
$(P2_OUT)/curvature_star.tsv $(P2_OUT)/curvature_star_a.dat $(P2_OUT)/curvature_star_b.dat $(P2_OUT)/curvature_star_notes.md &: $(P2_BIN)/curvature_star_demo
	@mkdir -p $(P2_OUT)
	OMP_WAIT_POLICY=passive $< $(QUICKFLAG) --out-dir $(P2_OUT)
$(P2_OUT)/fig09.png: $(P2_OUT)/curvature_star_a.dat $(P2_OUT)/curvature_star_b.dat $(P2)/plot/fig09.gp
	gnuplot -e "dir='$(P2_OUT)'; out='$(@D)/.tmp-$(@F)'" $(P2)/plot/fig09.gp && mv $(@D)/.tmp-$(@F) $@
P2_RESULTS += $(P2_OUT)/fig09.png $(P2_OUT)/curvature_star_notes.md
P2_CHECK += $(P2_OUT)/curvature_star.tsv
REPORT_INPUTS += $(P2)/curvature_star_demo.c $(P2)/plot/fig09.gp
