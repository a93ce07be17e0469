# acoustic (section 2.6.2, Figure 18): session h3.
P2_PROGS += acoustic
$(P2_BIN)/acoustic: $(BUILD)/obj/$(P2)/p2_reach.o
$(P2_OUT)/acoustic.tsv $(P2_OUT)/acoustic_2d.dat $(P2_OUT)/acoustic_notes.md &: $(P2_BIN)/acoustic
	@mkdir -p $(P2_OUT)
	$< $(QUICKFLAG) --out-dir $(P2_OUT)
$(P2_OUT)/fig18.png: $(P2_OUT)/acoustic_2d.dat $(P2)/plot/fig18.gp
	gnuplot -e "dir='$(P2_OUT)'; out='$(@D)/.tmp-$(@F)'" $(P2)/plot/fig18.gp && mv $(@D)/.tmp-$(@F) $@
P2_RESULTS += $(P2_OUT)/fig18.png $(P2_OUT)/acoustic_notes.md
P2_CHECK += $(P2_OUT)/acoustic.tsv
REPORT_INPUTS += $(P2)/acoustic.c $(P2)/plot/fig18.gp
