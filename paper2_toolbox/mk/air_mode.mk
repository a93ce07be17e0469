# airMode (section 2.6.3, Figure 20); notes/air_mode_notes.md presents air_mode_summary.tsv.
$(eval $(call p2_demo,air_mode,reach cli,air_mode.tsv air_mode_2d.dat air_mode_summary.tsv,air_mode.tsv))
$(eval $(call p2_figure,fig20,air_mode_2d.dat))
P2_RESULTS += $(P2_OUT)/fig20.png $(P2_OUT)/air_mode_summary.tsv
REPORT_INPUTS += $(P2)/notes/air_mode_notes.md
