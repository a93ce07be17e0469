# air3D (section 2.6.1, Figure 17) and its benchmark: session h3.
P2_PROGS += air3d bench_air3d
$(P2_BIN)/air3d $(P2_BIN)/bench_air3d: $(BUILD)/obj/$(P2)/p2_reach.o $(BUILD)/obj/$(P2)/p2_air3d.o
$(P2_OUT)/air3d.tsv $(P2_OUT)/air3d.vtk $(P2_OUT)/air3d_vox.dat $(P2_OUT)/air3d_notes.md &: $(P2_BIN)/air3d
	@mkdir -p $(P2_OUT)
	OMP_WAIT_POLICY=passive $< $(QUICKFLAG) --out-dir $(P2_OUT)
$(P2_OUT)/fig17.png: $(P2_OUT)/air3d_vox.dat $(P2)/plot/fig17.gp
	gnuplot -e "dir='$(P2_OUT)'; out='$(@D)/.tmp-$(@F)'" $(P2)/plot/fig17.gp && mv $(@D)/.tmp-$(@F) $@
P2_RESULTS += $(P2_OUT)/fig17.png $(P2_OUT)/air3d_notes.md $(P2_OUT)/air3d.vtk
P2_CHECK += $(P2_OUT)/air3d.tsv
REPORT_INPUTS += $(P2)/air3d.c $(P2)/bench_air3d.c $(P2)/plot/fig17.gp

# Benchmark (make bench, never the tests): air3D at low and medium, 1 and 2 threads.
BENCHES += bench-air3d
.PHONY: bench-air3d
bench-air3d: $(P2_BIN)/bench_air3d
	@mkdir -p $(P2_OUT)
	OMP_WAIT_POLICY=passive $(P2_BIN)/bench_air3d --out-dir $(P2_OUT)
