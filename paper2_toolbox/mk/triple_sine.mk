# tripleSine (section 2.4.1, Figure 12); session h2.
P2_PROGS += triple_sine
$(P2_BIN)/triple_sine: $(BUILD)/obj/$(P2)/p2_motion.o
$(P2_OUT)/triple_sine.tsv $(P2_OUT)/triple_sine_b0.1.dat $(P2_OUT)/triple_sine_b0.025.dat $(P2_OUT)/triple_sine_b0.dat $(P2_OUT)/triple_sine_notes.md &: $(P2_BIN)/triple_sine
	@mkdir -p $(P2_OUT)
	OMP_WAIT_POLICY=passive $< $(QUICKFLAG) --out-dir $(P2_OUT)
$(P2_OUT)/fig12.png: $(P2_OUT)/triple_sine_b0.1.dat $(P2_OUT)/triple_sine_b0.025.dat $(P2_OUT)/triple_sine_b0.dat $(P2)/plot/fig12.gp
	gnuplot -e "dir='$(P2_OUT)'; out='$(@D)/.tmp-$(@F)'" $(P2)/plot/fig12.gp && mv $(@D)/.tmp-$(@F) $@
P2_RESULTS += $(P2_OUT)/fig12.png $(P2_OUT)/triple_sine_notes.md
P2_CHECK += $(P2_OUT)/triple_sine.tsv
REPORT_INPUTS += $(P2)/triple_sine.c $(P2)/plot/fig12.gp
