# burgersLF (section 2.5.1, Figure 14); notes/burgers_notes.md presents burgers_summary.tsv.
$(eval $(call p2_demo,burgers_lf,oshershu cli,burgers.tsv burgers_fit.tsv burgers_1d.dat burgers_2d.dat burgers_summary.tsv,burgers.tsv burgers_fit.tsv))
$(eval $(call p2_figure,fig14,burgers_1d.dat burgers_2d.dat))
P2_RESULTS += $(P2_OUT)/fig14.png $(P2_OUT)/burgers_summary.tsv
REPORT_INPUTS += $(P2)/notes/burgers_notes.md
