# normalStarDemo (section 2.3.2, Figure 10); session h2.
P2_PROGS += normal_star_demo
$(P2_BIN)/normal_star_demo: $(BUILD)/obj/$(P2)/p2_motion.o
$(P2_OUT)/normal_circle.tsv $(P2_OUT)/normal_star_a.dat $(P2_OUT)/normal_star_b.dat $(P2_OUT)/normal_star_notes.md &: $(P2_BIN)/normal_star_demo
	@mkdir -p $(P2_OUT)
	OMP_WAIT_POLICY=passive $< $(QUICKFLAG) --out-dir $(P2_OUT)
$(P2_OUT)/fig10.png: $(P2_OUT)/normal_star_a.dat $(P2_OUT)/normal_star_b.dat $(P2)/plot/fig10.gp
	gnuplot -e "dir='$(P2_OUT)'; out='$(@D)/.tmp-$(@F)'" $(P2)/plot/fig10.gp && mv $(@D)/.tmp-$(@F) $@
P2_RESULTS += $(P2_OUT)/fig10.png $(P2_OUT)/normal_star_notes.md
P2_CHECK += $(P2_OUT)/normal_circle.tsv
REPORT_INPUTS += $(P2)/normal_star_demo.c $(P2)/plot/fig10.gp
