# reinitDemo (section 2.2.1, Figures 4-5).
P2_PROGS += reinit_demo
$(P2_BIN)/reinit_demo: $(BUILD)/obj/$(P2)/p2_basic.o
$(P2_OUT)/reinit.tsv $(P2_OUT)/reinit_notes.md $(P2_OUT)/reinit_star_medium.dat &: $(P2_BIN)/reinit_demo
	@mkdir -p $(P2_OUT)
	OMP_WAIT_POLICY=passive $< $(QUICKFLAG) --out-dir $(P2_OUT)
$(P2_OUT)/fig04.png: $(P2_OUT)/reinit_star_medium.dat $(P2)/plot/fig04.gp
	gnuplot -e "dir='$(P2_OUT)'; out='$(@D)/.tmp-$(@F)'" $(P2)/plot/fig04.gp && mv $(@D)/.tmp-$(@F) $@
$(P2_OUT)/fig05.png: $(P2_OUT)/reinit_star_medium.dat $(P2)/plot/fig05.gp
	gnuplot -e "dir='$(P2_OUT)'; out='$(@D)/.tmp-$(@F)'" $(P2)/plot/fig05.gp && mv $(@D)/.tmp-$(@F) $@
P2_RESULTS += $(P2_OUT)/fig04.png $(P2_OUT)/fig05.png $(P2_OUT)/reinit_notes.md
P2_CHECK += $(P2_OUT)/reinit.tsv
REPORT_INPUTS += $(P2)/reinit_demo.c $(P2)/plot/fig04.gp $(P2)/plot/fig05.gp
