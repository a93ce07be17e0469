# Paper 1: Huang, Shu & Zhang (2008), fast sweeping WENO with inflow
# boundary treatments.  Included by the top-level Makefile.

P1 := paper1_fastsweeping
P1_EXAMPLES := example1 example2 example3 example4
P1_BINS := $(P1_EXAMPLES:%=$(BUILD)/bin/$(P1)/%) $(BUILD)/bin/$(P1)/eikonal $(BUILD)/bin/$(P1)/bench_fsm \
           $(BUILD)/bin/$(P1)/bench_eik $(BUILD)/bin/$(P1)/eik_convergence
P1_LIBOBJ := $(BUILD)/obj/$(P1)/p1_study.o
$(P1_BINS): $(P1_LIBOBJ)
$(BUILD)/obj/$(P1)/%.o: CPPFLAGS += -I$(P1)

PROGRAMS += $(P1_BINS)
UNIT_TESTS += $(patsubst %.c,$(BUILD)/test/%,$(wildcard $(P1)/tests/test_*.c))
$(patsubst %.c,$(BUILD)/test/%,$(wildcard $(P1)/tests/test_*.c)): $(P1_LIBOBJ)

P1_OUT := $(RESULTS)/paper1
P1_TABLES := table3.1 table3.2 table3.3 table3.4 table3.5
P1_RESULTS := $(P1_TABLES:%=$(P1_OUT)/%.tsv)

$(P1_OUT)/table3.1.tsv: $(BUILD)/bin/$(P1)/example1 | $(HJTIME)
	@mkdir -p $(@D)
	$(call hj_timed,$(@D),example1.table3.1) $< $(QUICKFLAG) --out-dir $(@D)
$(P1_OUT)/table3.2.tsv: $(BUILD)/bin/$(P1)/example2 | $(HJTIME)
	@mkdir -p $(@D)
	$(call hj_timed,$(@D),example2.table3.2) $< $(QUICKFLAG) --strategy richardson --out-dir $(@D)
$(P1_OUT)/table3.3.tsv: $(BUILD)/bin/$(P1)/example2 | $(HJTIME)
	@mkdir -p $(@D)
	$(call hj_timed,$(@D),example2.table3.3) $< $(QUICKFLAG) --strategy lax-wendroff --out-dir $(@D)
$(P1_OUT)/table3.4.tsv: $(BUILD)/bin/$(P1)/example3 | $(HJTIME)
	@mkdir -p $(@D)
	$(call hj_timed,$(@D),example3.table3.4) $< $(QUICKFLAG) --out-dir $(@D)
$(P1_OUT)/table3.5.tsv: $(BUILD)/bin/$(P1)/example4 | $(HJTIME)
	@mkdir -p $(@D)
	$(call hj_timed,$(@D),example4.table3.5) $< $(QUICKFLAG) --out-dir $(@D)

# Figures: convergence (with the Ceres fit) and contours of the solution.
P1_FIGS := $(P1_TABLES:%=$(P1_OUT)/fig/%.conv.png) $(P1_TABLES:%=$(P1_OUT)/fig/%.contour.png)
$(P1_OUT)/fig/%.conv.png: $(P1_OUT)/%.tsv common/plot/convergence.gp
	@mkdir -p $(@D)
	gnuplot -e "table='$(P1_OUT)/$*'; out='$(@D)/.tmp-$(@F)'; title='Table $(subst table,,$*): errors against N'" common/plot/convergence.gp && mv $(@D)/.tmp-$(@F) $@
$(P1_OUT)/fig/%.contour.png: $(P1_OUT)/%.tsv common/plot/contour.gp
	@mkdir -p $(@D)
	gnuplot -e "table='$(P1_OUT)/$*'; out='$(@D)/.tmp-$(@F)'; title='Table $(subst table,,$*): contours of the computed solution (N = 80)'" common/plot/contour.gp && mv $(@D)/.tmp-$(@F) $@

# Studies shown in the report: studies.sh writes each one's data (a TSV);
# the prose and tables are notes/<study>.md, rendered by report/build.sh.
P1_STUDIES := $(P1_OUT)/eps-scan.tsv $(P1_OUT)/richardson-box.tsv $(P1_OUT)/exclude.tsv $(P1_OUT)/guess.tsv $(P1_OUT)/roundoff.tsv $(P1_OUT)/treatments.tsv
$(P1_OUT)/eps-scan.tsv: $(BUILD)/bin/$(P1)/example2 $(P1)/studies.sh
	@mkdir -p $(@D)
	$(P1)/studies.sh eps-scan $(<D) $(P1)/published/table3.3.tsv > $@.tmp && mv $@.tmp $@
$(P1_OUT)/richardson-box.tsv: $(BUILD)/bin/$(P1)/example2 $(P1)/studies.sh
	@mkdir -p $(@D)
	$(P1)/studies.sh richardson-box $(<D) $(P1)/published/table3.2.tsv > $@.tmp && mv $@.tmp $@
$(P1_OUT)/exclude.tsv: $(BUILD)/bin/$(P1)/example3 $(BUILD)/bin/$(P1)/example4 $(P1)/studies.sh \
                       $(P1_OUT)/table3.4.tsv $(P1_OUT)/table3.5.tsv
	@mkdir -p $(@D)
	$(P1)/studies.sh exclude $(<D) $(P1)/published/table3.4.tsv $(P1)/published/table3.5.tsv $(@D) > $@.tmp && mv $@.tmp $@
$(P1_OUT)/guess.tsv: $(BUILD)/bin/$(P1)/example2 $(P1)/studies.sh
	@mkdir -p $(@D)
	$(P1)/studies.sh guess $(<D) $(P1)/published/table3.2.tsv $(P1)/published/table3.3.tsv > $@.tmp && mv $@.tmp $@
$(P1_OUT)/roundoff.tsv: $(BUILD)/bin/$(P1)/example2 $(P1)/studies.sh $(P1_OUT)/table3.2.tsv $(P1_OUT)/table3.3.tsv
	@mkdir -p $(@D)
	$(P1)/studies.sh roundoff $(<D) $(P1)/published/table3.2.tsv $(P1)/published/table3.3.tsv $(@D) > $@.tmp && mv $@.tmp $@
$(P1_OUT)/treatments.tsv: $(BUILD)/bin/$(P1)/example1 $(BUILD)/bin/$(P1)/example2 $(P1)/studies.sh
	@mkdir -p $(@D)
	$(P1)/studies.sh treatments $(<D) > $@.tmp && mv $@.tmp $@

CHECK_PAPERS += paper1=$(P1)
CHECK_INPUTS += $(P1_RESULTS)
# The studies run at the published sizes only: the quick path (QUICK=1)
# leaves them out, and its report says so.
ifeq ($(QUICK),1)
P1_REPORTED := $(P1_RESULTS) $(P1_FIGS)
else
P1_REPORTED := $(P1_RESULTS) $(P1_FIGS) $(P1_STUDIES)
endif
REPORT_INPUTS += $(P1_REPORTED) $(P1_EXAMPLES:%=$(P1)/%.c) $(P1)/report.tsv $(P1)/overview.md $(wildcard $(P1)/notes/*.md)

paper1: $(P1_REPORTED)
	$(MAKE) --no-print-directory report-now

# The command-line tests run the built programs of the same build.
$(BUILD)/obj/$(P1)/tests/test_cli.o: CPPFLAGS += -DHJ_BIN_DIR='"$(BUILD)/bin"'
$(BUILD)/test/$(P1)/tests/test_cli: | $(P1_BINS)

# Benchmark (never part of the tests): timings as ratios, see bench_fsm.c.
.PHONY: bench-paper1
BENCHES += bench-paper1
bench-paper1: $(BUILD)/bin/$(P1)/bench_fsm
	$< --N 640 --out-dir results/paper1

# The Eikonal solver against scikit-fmm (Debian's python3-scikit-fmm), one
# process at a time, one thread each: CPU ratios at equal N and at equal
# accuracy, see bench_eik.c.  The peer runs first; its table feeds ours.
.PHONY: bench-eikonal
BENCHES += bench-eikonal
bench-eikonal: $(BUILD)/bin/$(P1)/bench_eik
	@mkdir -p results/bench
	OMP_NUM_THREADS=1 /usr/bin/python3 $(P1)/bench_skfmm.py results/bench/skfmm.tsv 200,400,800,1600 100,200
	OMP_NUM_THREADS=1 $< --sizes 25,50,100,200,400,800,1600 --max-high 400 --sizes3 25,50,100 --sizes3-order1 200 \
	    --peer results/bench/skfmm.tsv --out-dir results/bench

# The general Eikonal solver (common/hj_eik) beyond paper 1: convergence of
# orders 1, 3, 5 in 2-D and 3-D; its fitted orders are checked against the
# design orders (paper1_fastsweeping/eik/reference/) as the check "eik".
EIK := $(P1)/eik
EIK_OUT := $(RESULTS)/eik
EIK_RESULTS := $(EIK_OUT)/eik_convergence.tsv $(EIK_OUT)/eik_orders.tsv $(EIK_OUT)/eik_sources.tsv
$(EIK_OUT)/eik_orders.tsv $(EIK_OUT)/eik_sources.tsv: $(EIK_OUT)/eik_convergence.tsv
$(EIK_OUT)/eik_convergence.tsv: $(BUILD)/bin/$(P1)/eik_convergence | $(HJTIME)
	@mkdir -p $(@D)
	$(call hj_timed,$(@D),eik_convergence) $< $(QUICKFLAG) --out-dir $(@D)
CHECK_PAPERS += eik=$(EIK)
CHECK_INPUTS += $(EIK_RESULTS)
REPORT_INPUTS += $(EIK_RESULTS) $(EIK)/report.tsv $(EIK)/overview.md $(wildcard $(EIK)/notes/*.md) $(P1)/eik_convergence.c
paper1: $(EIK_RESULTS)
