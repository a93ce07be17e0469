# Reachability checks (common/hj_reach, common/hj_ctrl): one program,
# studies/reach/reach_checks.c, writes the tables make check holds against
# studies/reach/reference/ (README.md there) and the figure data.
# Included by the top-level Makefile.

RS := studies/reach
RS_OUT := $(RESULTS)/reach
RS_BIN := $(BUILD)/bin/$(RS)
$(BUILD)/obj/$(RS)/%.o: CFLAGS += -fopenmp -O3

RS_TABLES := di_mintime.tsv product6d.tsv trajectories.tsv moving_obstacle.tsv
RS_DATA := di_mintime.dat trajectories.dat moving_obstacle.dat
$(RS_TABLES:%=$(RS_OUT)/%) $(RS_DATA:%=$(RS_OUT)/%) &: $(RS_BIN)/reach_checks
	@mkdir -p $(RS_OUT)
	OMP_WAIT_POLICY=passive $< $(QUICKFLAG) --out-dir $(RS_OUT)

$(eval $(call hj_figure,$(RS),$(RS_OUT),reach,$(RS_DATA)))

PROGRAMS += $(RS_BIN)/reach_checks $(RS_BIN)/hjreach $(RS_BIN)/bench_reach
CHECK_PAPERS += reach=$(RS)
CHECK_INPUTS += $(RS_TABLES:%=$(RS_OUT)/%)
REPORT_INPUTS += $(RS)/reach_checks.c $(RS)/bench_reach.c $(RS_TABLES:%=$(RS_OUT)/%) $(RS)/report.tsv $(RS)/overview.md \
                 $(wildcard $(RS)/notes/*.md)

.PHONY: reach
reach: $(RS_TABLES:%=$(RS_OUT)/%) $(RS_OUT)/reach.png

# Benchmark (make bench, never the tests): 6-D node updates per second of
# the first order and WENO5/RK3 schemes, bytes per node.
BENCHES += bench-reach
.PHONY: bench-reach
bench-reach: $(RS_BIN)/bench_reach
	@mkdir -p $(RS_OUT)
	OMP_WAIT_POLICY=passive $(RS_BIN)/bench_reach --out-dir $(RS_OUT)

# hjreach's outputs as users' tools read them (VTK without inf) and every
# output name checked before the run; part of make reliability.
.PHONY: hjreach-check
hjreach-check: $(RS_BIN)/hjreach
	$(RS)/hjreach-check.sh $(BUILD)/bin
reliability-programs: hjreach-check
