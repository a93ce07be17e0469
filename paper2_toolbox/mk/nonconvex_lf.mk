# nonconvexLF (section 2.5.2, Figure 15); notes/nonconvex_notes.md presents nonconvex_summary.tsv.
$(eval $(call p2_demo,nonconvex_lf,oshershu cli,nonconvex.tsv nonconvex_1d.dat nonconvex_2d.dat nonconvex_summary.tsv,nonconvex.tsv))
$(eval $(call p2_figure,fig15,nonconvex_1d.dat nonconvex_2d.dat))
P2_RESULTS += $(P2_OUT)/fig15.png $(P2_OUT)/nonconvex_summary.tsv
REPORT_INPUTS += $(P2)/notes/nonconvex_notes.md
