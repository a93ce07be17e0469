# laxFriedrichsDemo (section 2.2.2, Figure 6); notes/lax_friedrichs_notes.md presents lax_friedrichs_summary.tsv.
$(eval $(call p2_demo,lax_friedrichs_demo,convection cli,lax_friedrichs.tsv lax_friedrichs_summary.tsv lax_friedrichs_low.dat lax_friedrichs_final.dat,lax_friedrichs.tsv,OMP_WAIT_POLICY=passive))
$(eval $(call p2_figure,fig06,lax_friedrichs_low.dat lax_friedrichs_final.dat))
P2_RESULTS += $(P2_OUT)/fig06.png $(P2_OUT)/lax_friedrichs_summary.tsv
REPORT_INPUTS += $(P2)/notes/lax_friedrichs_notes.md
