# convectionDemo (section 2.1, Figures 1-3); shares p2_basic with the other
# section 2.1-2.2 demos and with bench_convection.
P2_PROGS += convection_demo
$(P2_BIN)/convection_demo $(P2_BIN)/bench_convection: $(BUILD)/obj/$(P2)/p2_basic.o
$(P2_OUT)/convection.tsv $(P2_OUT)/convection_notes.md $(P2_OUT)/convection_2d_linear_medium.dat $(P2_OUT)/convection_2d_linearRev_low.dat $(P2_OUT)/convection_1d_constantRev_veryHigh.dat &: $(P2_BIN)/convection_demo
	@mkdir -p $(P2_OUT)
	OMP_WAIT_POLICY=passive $< $(QUICKFLAG) --out-dir $(P2_OUT)
$(P2_OUT)/fig01.png: $(P2_OUT)/convection_2d_linear_medium.dat $(P2)/plot/fig01.gp
	gnuplot -e "dir='$(P2_OUT)'; out='$(@D)/.tmp-$(@F)'" $(P2)/plot/fig01.gp && mv $(@D)/.tmp-$(@F) $@
$(P2_OUT)/fig02.png: $(P2_OUT)/convection_2d_linearRev_low.dat $(P2)/plot/fig02.gp
	gnuplot -e "dir='$(P2_OUT)'; out='$(@D)/.tmp-$(@F)'" $(P2)/plot/fig02.gp && mv $(@D)/.tmp-$(@F) $@
# fig03 needs the 3-D run's convection_3d_linear_medium.dat, written with convection.tsv (full run only)
$(P2_OUT)/fig03.png: $(P2_OUT)/convection.tsv $(P2_OUT)/convection_1d_constantRev_veryHigh.dat $(P2)/plot/fig03.gp
	gnuplot -e "dir='$(P2_OUT)'; out='$(@D)/.tmp-$(@F)'" $(P2)/plot/fig03.gp && mv $(@D)/.tmp-$(@F) $@
P2_CHECK += $(P2_OUT)/convection.tsv
REPORT_INPUTS += $(P2)/convection_demo.c $(P2)/plot/fig01.gp $(P2)/plot/fig02.gp $(P2)/plot/fig03.gp
ifneq ($(QUICK),1)
P2_RESULTS += $(P2_OUT)/fig01.png $(P2_OUT)/fig02.png $(P2_OUT)/fig03.png $(P2_OUT)/convection_notes.md
else
P2_RESULTS += $(P2_OUT)/fig01.png $(P2_OUT)/fig02.png $(P2_OUT)/convection_notes.md
endif
