# maskDemo (section 2.2.3, Figure 7); notes/mask_notes.md presents mask_summary.tsv.
$(eval $(call p2_demo,mask_demo,convection cli,mask.tsv mask_summary.tsv mask_seq.dat mask_min.dat,mask.tsv,OMP_WAIT_POLICY=passive))
$(eval $(call p2_figure,fig07,mask_seq.dat mask_min.dat))
P2_RESULTS += $(P2_OUT)/fig07.png $(P2_OUT)/mask_summary.tsv
REPORT_INPUTS += $(P2)/notes/mask_notes.md
