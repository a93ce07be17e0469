# convectionDemo (section 2.1, Figures 1-3); its flows (p2_convection) serve
# laxFriedrichsDemo, maskDemo and bench_convection too.  notes/convection_notes.md
# presents convection_summary.tsv.
$(eval $(call p2_demo,convection_demo,convection cli,convection.tsv convection_summary.tsv convection_2d_linear_medium.dat convection_2d_linearRev_low.dat convection_1d_constantRev_veryHigh.dat,convection.tsv,OMP_WAIT_POLICY=passive))
$(P2_BIN)/bench_convection: $(BUILD)/obj/$(P2)/p2_convection.o $(BUILD)/obj/$(P2)/p2_cli.o
$(eval $(call p2_figure,fig01,convection_2d_linear_medium.dat))
$(eval $(call p2_figure,fig02,convection_2d_linearRev_low.dat))
# fig03 needs the 3-D run's convection_3d_linear_medium.dat, written with convection.tsv (full run only)
$(eval $(call p2_figure,fig03,convection.tsv convection_1d_constantRev_veryHigh.dat))
ifneq ($(QUICK),1)
P2_RESULTS += $(P2_OUT)/fig01.png $(P2_OUT)/fig02.png $(P2_OUT)/fig03.png $(P2_OUT)/convection_summary.tsv
else
P2_RESULTS += $(P2_OUT)/fig01.png $(P2_OUT)/fig02.png $(P2_OUT)/convection_summary.tsv
endif
REPORT_INPUTS += $(P2)/notes/convection_notes.md
