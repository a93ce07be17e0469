# laxFriedrichsDemo (section 2.2.2, Figure 6).
P2_PROGS += lax_friedrichs_demo
$(P2_BIN)/lax_friedrichs_demo: $(BUILD)/obj/$(P2)/p2_basic.o
$(P2_OUT)/lax_friedrichs.tsv $(P2_OUT)/lax_friedrichs_notes.md $(P2_OUT)/lax_friedrichs_low.dat $(P2_OUT)/lax_friedrichs_final.dat &: $(P2_BIN)/lax_friedrichs_demo
	@mkdir -p $(P2_OUT)
	OMP_WAIT_POLICY=passive $< $(QUICKFLAG) --out-dir $(P2_OUT)
$(P2_OUT)/fig06.png: $(P2_OUT)/lax_friedrichs_low.dat $(P2_OUT)/lax_friedrichs_final.dat $(P2)/plot/fig06.gp
	gnuplot -e "dir='$(P2_OUT)'; out='$(@D)/.tmp-$(@F)'" $(P2)/plot/fig06.gp && mv $(@D)/.tmp-$(@F) $@
P2_RESULTS += $(P2_OUT)/fig06.png $(P2_OUT)/lax_friedrichs_notes.md
P2_CHECK += $(P2_OUT)/lax_friedrichs.tsv
REPORT_INPUTS += $(P2)/lax_friedrichs_demo.c $(P2)/plot/fig06.gp
