# nonconvexLF (section 2.5.2, Figure 15): session h3.
P2_PROGS += nonconvex_lf
$(P2_BIN)/nonconvex_lf: $(BUILD)/obj/$(P2)/p2_reach.o $(BUILD)/obj/$(P2)/p2_oshershu.o
$(P2_OUT)/nonconvex.tsv $(P2_OUT)/nonconvex_1d.dat $(P2_OUT)/nonconvex_2d.dat $(P2_OUT)/nonconvex_notes.md &: $(P2_BIN)/nonconvex_lf
	@mkdir -p $(P2_OUT)
	$< $(QUICKFLAG) --out-dir $(P2_OUT)
$(P2_OUT)/fig15.png: $(P2_OUT)/nonconvex_1d.dat $(P2_OUT)/nonconvex_2d.dat $(P2)/plot/fig15.gp
	gnuplot -e "dir='$(P2_OUT)'; out='$(@D)/.tmp-$(@F)'" $(P2)/plot/fig15.gp && mv $(@D)/.tmp-$(@F) $@
P2_RESULTS += $(P2_OUT)/fig15.png $(P2_OUT)/nonconvex_notes.md
P2_CHECK += $(P2_OUT)/nonconvex.tsv
REPORT_INPUTS += $(P2)/nonconvex_lf.c $(P2)/plot/fig15.gp
