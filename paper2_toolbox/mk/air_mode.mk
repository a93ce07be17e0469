# airMode (section 2.6.3, Figure 20): session h3.
P2_PROGS += air_mode
$(P2_BIN)/air_mode: $(BUILD)/obj/$(P2)/p2_reach.o
$(P2_OUT)/air_mode.tsv $(P2_OUT)/air_mode_2d.dat $(P2_OUT)/air_mode_notes.md &: $(P2_BIN)/air_mode
	@mkdir -p $(P2_OUT)
	$< $(QUICKFLAG) --out-dir $(P2_OUT)
$(P2_OUT)/fig20.png: $(P2_OUT)/air_mode_2d.dat $(P2)/plot/fig20.gp
	gnuplot -e "dir='$(P2_OUT)'; out='$(@D)/.tmp-$(@F)'" $(P2)/plot/fig20.gp && mv $(@D)/.tmp-$(@F) $@
P2_RESULTS += $(P2_OUT)/fig20.png $(P2_OUT)/air_mode_notes.md
P2_CHECK += $(P2_OUT)/air_mode.tsv
REPORT_INPUTS += $(P2)/air_mode.c $(P2)/plot/fig20.gp
