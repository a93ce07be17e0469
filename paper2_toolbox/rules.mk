# Paper 2: Mitchell (2004), "A Toolbox of Level Set Methods" -- the level
# set kernel lives in common/hj_ls_*; this fragment builds its programs,
# Figure 22, Table 2 and the convectionDemo benchmark.  Included by the
# top-level Makefile.

P2 := paper2_toolbox

# The paper 2 programs are built as the level set kernel is (Makefile).
$(BUILD)/obj/$(P2)/%.o: CFLAGS += -fopenmp -O3

P2_OUT := $(RESULTS)/paper2
P2_BIN := $(BUILD)/bin/$(P2)
P2_PROGS := fig21_shapes fig22_derivatives bench_table2 bench_convection
$(P2_BIN)/bench_table2: $(BUILD)/obj/$(P2)/p2_cli.o

# Figure 22: errors and fitted orders, then the four-panel figure.
$(P2_OUT)/fig22.tsv $(P2_OUT)/fig22.dat $(P2_OUT)/fig22_orders.tsv &: $(P2_BIN)/fig22_derivatives
	@mkdir -p $(P2_OUT)
	$< $(QUICKFLAG) --out-dir $(P2_OUT)
$(P2_OUT)/fig22.svg: $(P2_OUT)/fig22.dat $(P2)/plot/fig22.gp
	gnuplot -e "dat='$<'; out='$(@D)/.tmp-$(@F)'" $(P2)/plot/fig22.gp && mv $(@D)/.tmp-$(@F) $@

# Figure 21: CSG shapes in 1-3 dimensions (section 2.7.1).
$(P2_OUT)/fig21.tsv $(P2_OUT)/fig21_1d.tsv $(P2_OUT)/fig21_2d.tsv $(P2_OUT)/fig21_3d.dat $(P2_OUT)/fig21_3d.vtk \
  $(P2_OUT)/fig21_checks.tsv &: $(P2_BIN)/fig21_shapes
	@mkdir -p $(P2_OUT)
	$< --out-dir $(P2_OUT)
$(P2_OUT)/fig21.png: $(P2_OUT)/fig21_3d.dat $(P2_OUT)/fig21_2d.tsv $(P2_OUT)/fig21_1d.tsv $(P2)/plot/fig21.gp
	gnuplot -e "dir='$(P2_OUT)'; out='$(@D)/.tmp-$(@F)'" $(P2)/plot/fig21.gp && mv $(@D)/.tmp-$(@F) $@

P2_RESULTS := $(P2_OUT)/fig22.tsv $(P2_OUT)/fig22_orders.tsv $(P2_OUT)/fig22.svg $(P2_OUT)/fig21.png $(P2_OUT)/fig21_checks.tsv
# Table 2 (the schemes' relative costs, about 4 s on one thread) is run by
# the reproduction too, so that the report sets it beside the published
# one (notes/table2.md); make bench runs it again with the other benchmarks.
$(P2_OUT)/table2.tsv: $(P2_BIN)/bench_table2 | $(HJTIME)
	@mkdir -p $(P2_OUT)
	$(call hj_timed,$(P2_OUT),bench_table2) $< --out-dir $(P2_OUT)
P2_RESULTS += $(P2_OUT)/table2.tsv
# Table 1 (convectionDemo('linear') at the four accuracies on 101^3, about
# 80 s on one thread; 41^3 in the quick run) likewise, on one thread so
# that it takes one lane of the reproduction; make bench runs it again
# with 1 and 2 threads and the bitwise comparison between them.
$(P2_OUT)/convection_bench.tsv: $(P2_BIN)/bench_convection | $(HJTIME)
	@mkdir -p $(P2_OUT)
	$(call hj_timed,$(P2_OUT),bench_convection) env OMP_WAIT_POLICY=passive $< $(if $(QUICKFLAG),--n 41) --threads 1 \
	  --out-dir $(P2_OUT)
P2_RESULTS += $(P2_OUT)/convection_bench.tsv
# Tables held by make check against paper2_toolbox/reference/ (README.md there).
P2_CHECK := $(P2_OUT)/fig21.tsv
REPORT_INPUTS += $(P2)/fig21_shapes.c $(P2)/fig22_derivatives.c $(P2)/bench_table2.c $(P2)/bench_convection.c \
                 $(P2)/report.tsv $(P2)/overview.md
# The notes' templates, rendered by the report from the results' tables.
REPORT_INPUTS += $(wildcard $(P2)/notes/*.md)

# The demos of section 2: one fragment each, mk/<demo>.mk, which adds its
# program to P2_PROGS, its outputs to P2_RESULTS, its checked tables to
# P2_CHECK and its source to REPORT_INPUTS, mostly through these two:
#
# $(eval $(call p2_demo,PROG,MODULES,OUTPUTS,CHECKED,ENV)): PROG.c linked
# with the p2_<module>.o of MODULES, run once (with $(QUICKFLAG), under
# ENV, e.g. OMP_WAIT_POLICY=passive, and timed into time/PROG.tsv) for all
# of OUTPUTS (names in P2_OUT); CHECKED are the tables make check holds.
define p2_demo
P2_PROGS += $(1)
$(P2_BIN)/$(1): $(2:%=$(BUILD)/obj/$(P2)/p2_%.o)
$(3:%=$(P2_OUT)/%) &: $(P2_BIN)/$(1) | $(HJTIME)
	@mkdir -p $(P2_OUT)
	$(call hj_timed,$(P2_OUT),$(1)) env $(5) $$< $(QUICKFLAG) --out-dir $(P2_OUT)
P2_CHECK += $(4:%=$(P2_OUT)/%)
REPORT_INPUTS += $(P2)/$(1).c
endef
# $(eval $(call p2_figure,FIG,INPUTS)): FIG.png drawn by plot/FIG.gp from
# INPUTS (names in P2_OUT); the script gets dir = P2_OUT and out.
p2_figure = $(call hj_figure,$(P2),$(P2_OUT),$(1),$(2))
include $(sort $(wildcard $(P2)/mk/*.mk))

PROGRAMS += $(P2_PROGS:%=$(P2_BIN)/%)
CHECK_PAPERS += paper2=$(P2)
CHECK_INPUTS += $(P2_CHECK)
REPORT_INPUTS += $(P2_RESULTS) $(P2_CHECK)

# Benchmarks (never part of the tests): Table 2, convectionDemo 101^3 and
# the kernel's demos against the roofline (bench_kernels.c).
P2_PROGS += bench_kernels
$(P2_BIN)/bench_kernels: $(BUILD)/obj/$(P2)/p2_air3d.o $(BUILD)/obj/$(P2)/p2_reach.o \
  $(BUILD)/obj/$(P2)/p2_convection.o $(BUILD)/obj/$(P2)/p2_cli.o
REPORT_INPUTS += $(P2)/bench_kernels.c
BENCHES += bench-paper2
.PHONY: bench-paper2
bench-paper2: $(P2_BIN)/bench_table2 $(P2_BIN)/bench_convection $(P2_BIN)/bench_kernels
	@mkdir -p $(P2_OUT)
	$(P2_BIN)/bench_table2 --out-dir $(P2_OUT)
	OMP_WAIT_POLICY=passive $(P2_BIN)/bench_convection --out-dir $(P2_OUT)
	OMP_WAIT_POLICY=passive $(P2_BIN)/bench_kernels --out-dir $(P2_OUT)

paper2: $(P2_RESULTS) $(P2_CHECK)
	$(MAKE) --no-print-directory report-now

# Paper 2's own tests (the reference values it computes itself).
UNIT_TESTS += $(patsubst %.c,$(BUILD)/test/%,$(wildcard $(P2)/tests/test_*.c))
