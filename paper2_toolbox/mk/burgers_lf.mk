# burgersLF (section 2.5.1, Figure 14): session h3.
P2_PROGS += burgers_lf
$(P2_BIN)/burgers_lf: $(BUILD)/obj/$(P2)/p2_reach.o $(BUILD)/obj/$(P2)/p2_oshershu.o
$(P2_OUT)/burgers.tsv $(P2_OUT)/burgers_fit.tsv $(P2_OUT)/burgers_1d.dat $(P2_OUT)/burgers_2d.dat $(P2_OUT)/burgers_notes.md &: $(P2_BIN)/burgers_lf
	@mkdir -p $(P2_OUT)
	$< $(QUICKFLAG) --out-dir $(P2_OUT)
$(P2_OUT)/fig14.png: $(P2_OUT)/burgers_1d.dat $(P2_OUT)/burgers_2d.dat $(P2)/plot/fig14.gp
	gnuplot -e "dir='$(P2_OUT)'; out='$(@D)/.tmp-$(@F)'" $(P2)/plot/fig14.gp && mv $(@D)/.tmp-$(@F) $@
P2_RESULTS += $(P2_OUT)/fig14.png $(P2_OUT)/burgers_notes.md
P2_CHECK += $(P2_OUT)/burgers.tsv $(P2_OUT)/burgers_fit.tsv
REPORT_INPUTS += $(P2)/burgers_lf.c $(P2)/plot/fig14.gp
