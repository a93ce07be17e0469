# maskDemo (section 2.2.3, Figure 7).
P2_PROGS += mask_demo
$(P2_BIN)/mask_demo: $(BUILD)/obj/$(P2)/p2_basic.o
$(P2_OUT)/mask.tsv $(P2_OUT)/mask_notes.md $(P2_OUT)/mask_seq.dat $(P2_OUT)/mask_min.dat &: $(P2_BIN)/mask_demo
	@mkdir -p $(P2_OUT)
	OMP_WAIT_POLICY=passive $< $(QUICKFLAG) --out-dir $(P2_OUT)
$(P2_OUT)/fig07.png: $(P2_OUT)/mask_seq.dat $(P2_OUT)/mask_min.dat $(P2)/plot/fig07.gp
	gnuplot -e "dir='$(P2_OUT)'; out='$(@D)/.tmp-$(@F)'" $(P2)/plot/fig07.gp && mv $(@D)/.tmp-$(@F) $@
P2_RESULTS += $(P2_OUT)/fig07.png $(P2_OUT)/mask_notes.md
P2_CHECK += $(P2_OUT)/mask.tsv
REPORT_INPUTS += $(P2)/mask_demo.c $(P2)/plot/fig07.gp
