# acoustic (section 2.6.2, Figure 18); notes/acoustic_notes.md presents acoustic_summary.tsv.
$(eval $(call p2_demo,acoustic,acoustic reach cli,acoustic.tsv acoustic_2d.dat acoustic_summary.tsv,acoustic.tsv))
$(eval $(call p2_figure,fig18,acoustic_2d.dat))
P2_RESULTS += $(P2_OUT)/fig18.png $(P2_OUT)/acoustic_summary.tsv
REPORT_INPUTS += $(P2)/notes/acoustic_notes.md
