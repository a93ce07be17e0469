# air3D (section 2.6.1, Figure 17) and its benchmark; notes/air3d_notes.md presents air3d_summary.tsv.
$(eval $(call p2_demo,air3d,reach air3d cli,air3d.tsv air3d.vtk air3d_vox.dat air3d_summary.tsv,air3d.tsv,OMP_WAIT_POLICY=passive))
$(eval $(call p2_figure,fig17,air3d_vox.dat))
P2_RESULTS += $(P2_OUT)/fig17.png $(P2_OUT)/air3d_summary.tsv $(P2_OUT)/air3d.vtk
REPORT_INPUTS += $(P2)/notes/air3d_notes.md

# Benchmark (make bench, never the tests): air3D at low and medium, 1 and 2 threads;
# notes/air3d_bench.md presents its air3d_bench.tsv.
P2_PROGS += bench_air3d
$(P2_BIN)/bench_air3d: $(BUILD)/obj/$(P2)/p2_air3d.o $(BUILD)/obj/$(P2)/p2_reach.o
REPORT_INPUTS += $(P2)/bench_air3d.c $(P2)/notes/air3d_bench.md
BENCHES += bench-air3d
.PHONY: bench-air3d
bench-air3d: $(P2_BIN)/bench_air3d
	@mkdir -p $(P2_OUT)
	OMP_WAIT_POLICY=passive $(P2_BIN)/bench_air3d --out-dir $(P2_OUT)
