# Paper 3: Bokanowski, Cristiani & Zidani (2010), Ultra-Bee HJB scheme with
# sparse semi-dynamic storage.  Included by the top-level Makefile.

P3 := paper3_ultrabee
P3_PROGS := examples2d examples34d storage hjbstep
P3_BINS := $(P3_PROGS:%=$(BUILD)/bin/$(P3)/%)
# The scheme, the band stores and the error measures are in libhj
# (common/hj_ub, hj_band, hj_front, hj_mintime); these are the programs'.
P3_LIBOBJ := $(addprefix $(BUILD)/obj/$(P3)/,p3_prog.o p3_front.o p3_ls.o)
$(P3_BINS): $(P3_LIBOBJ)
$(BUILD)/obj/$(P3)/%.o: CPPFLAGS += -I$(P3)

PROGRAMS += $(P3_BINS)
P3_TESTS := $(patsubst %.c,$(BUILD)/test/%,$(wildcard $(P3)/tests/test_*.c))
UNIT_TESTS += $(P3_TESTS)
$(P3_TESTS): $(P3_LIBOBJ)

P3_OUT := $(RESULTS)/paper3
P3_2D := $(addprefix $(P3_OUT)/,table6.tsv table7.tsv table8.tsv table9.tsv table10.tsv \
           fig06_rendezvous.dat fig07_deformation.dat fig08_deformation.dat)
P3_ND := $(addprefix $(P3_OUT)/,table11.tsv table12.tsv table13.tsv)
P3_STORE := $(addprefix $(P3_OUT)/,table1.tsv table2.tsv table3.tsv table4.tsv fig05_fronts.dat)
P3_HJB := $(P3_OUT)/table5.tsv
P3_RESULTS := $(P3_STORE) $(P3_HJB) $(P3_2D) $(P3_ND)

# One run of each program writes its group of tables; examples34d runs
# once per table and storage once per search table (1, 2) and once for
# Tables 3-4, so that `make paper3` can share the long runs between two
# cores (below).  Each program measures its own CPU time
# (CLOCK_PROCESS_CPUTIME_ID), so the side-by-side runs do not enter each
# other's timings.  The programs that hold gigabytes may run side by
# side: storage builds a full store above 1 GB (FLS at 200^4: 14.4 GB)
# only under a lock on $(P3_OUT)/.memlock, so that two of its runs never
# hold two (storage.c); hjbstep holds 4.6 GB (19 GB together on this 24
# GB machine).  examples2d's level set runs
# use one OpenMP thread: its 2-D grids are small, and spinning threads on
# a shared machine cost more CPU than they save.
$(P3_2D) &: $(BUILD)/bin/$(P3)/examples2d | $(HJTIME)
	@mkdir -p $(P3_OUT)
	$(call hj_timed,$(P3_OUT),examples2d) env OMP_NUM_THREADS=1 $< $(QUICKFLAG) --out-dir $(P3_OUT)
$(P3_ND): $(P3_OUT)/table%.tsv: $(BUILD)/bin/$(P3)/examples34d | $(HJTIME)
	@mkdir -p $(P3_OUT)
	$(call hj_timed,$(P3_OUT),examples34d.table$*) $< $(QUICKFLAG) --tables $* --out-dir $(P3_OUT)
	$(if $(filter 11,$*),touch $(P3_FIG09_DATA))
# Figure 9's data come from the N = 50 runs of Table 11 (quick and full),
# written before table11.tsv is complete: the recipe above touches them.
P3_FIG09_DATA := $(P3_OUT)/fig09_advection.dat $(P3_OUT)/fig09_target.dat
$(P3_FIG09_DATA): $(P3_OUT)/table11.tsv
	@test -f $@ || { echo "$@ missing: rerun table 11 (rm $<)"; exit 1; }

# storage: Table 1 (with Figure 5's data), Table 2, Tables 3-4.
P3_STORE1 := $(P3_OUT)/table1.tsv $(P3_OUT)/fig05_fronts.dat
P3_STORE2 := $(P3_OUT)/table2.tsv
P3_STORE34 := $(P3_OUT)/table3.tsv $(P3_OUT)/table4.tsv
$(P3_STORE1) &: $(BUILD)/bin/$(P3)/storage | $(HJTIME)
	@mkdir -p $(P3_OUT)
	$(call hj_timed,$(P3_OUT),storage.table1) $< $(QUICKFLAG) $(P3_EXTRAFLAG) --tables 1 --out-dir $(P3_OUT)
$(P3_STORE2): $(BUILD)/bin/$(P3)/storage | $(HJTIME)
	@mkdir -p $(P3_OUT)
	$(call hj_timed,$(P3_OUT),storage.table2) $< $(QUICKFLAG) $(P3_EXTRAFLAG) --tables 2 --out-dir $(P3_OUT)
$(P3_STORE34) &: $(BUILD)/bin/$(P3)/storage | $(HJTIME)
	@mkdir -p $(P3_OUT)
	$(call hj_timed,$(P3_OUT),storage.table3-4) $< $(QUICKFLAG) $(P3_EXTRAFLAG) --tables 3,4 --out-dir $(P3_OUT)
$(P3_HJB): $(BUILD)/bin/$(P3)/hjbstep | $(HJTIME)
	@mkdir -p $(P3_OUT)
	$(call hj_timed,$(P3_OUT),hjbstep) $< $(QUICKFLAG) $(P3_EXTRAFLAG) --out-dir $(P3_OUT)

# Figures 5-9 (gnuplot, plot/figNN.gp): drawn from the data the programs
# write during their table runs (storage: fig05_fronts.dat; examples2d:
# fig06-08 at N = 101, 100, 50; examples34d: fig09 at N = 50), after the
# lanes of `make paper3`.  $(eval $(call p3_figure,FIG,INPUTS)): the top
# Makefile's hj_figure for paper 3 (FIG.png from plot/FIG.gp with
# dir = P3_OUT and out).
p3_figure = $(call hj_figure,$(P3),$(P3_OUT),$(1),$(2))
$(eval $(call p3_figure,fig05,fig05_fronts.dat))
$(eval $(call p3_figure,fig06,fig06_rendezvous.dat))
$(eval $(call p3_figure,fig07,fig07_deformation.dat))
$(eval $(call p3_figure,fig08,fig08_deformation.dat))
$(P3_OUT)/fig08.png: $(P3)/plot/fig07.gp
$(eval $(call p3_figure,fig09,fig09_advection.dat fig09_target.dat))
P3_FIGS := $(addprefix $(P3_OUT)/,fig05.png fig06.png fig07.png fig08.png fig09.png)

CHECK_PAPERS += paper3=$(P3)
CHECK_INPUTS += $(P3_RESULTS)
REPORT_INPUTS += $(P3_RESULTS) $(P3_PROGS:%=$(P3)/%.c)

.PHONY: bench-paper3
BENCHES += bench-paper3
# The timing tables (ratios between grids and between structures), and the
# dense and band UB steps against a measured triad bandwidth (bench_ub.c).
P3_BENCH := $(BUILD)/bin/$(P3)/bench_ub
PROGRAMS += $(P3_BENCH)
$(P3_BENCH): $(P3_LIBOBJ)
# -O3: the row dynamics (dyn_row) vectorise, as a user's batched callback should
$(BUILD)/obj/$(P3)/bench_ub.o: CFLAGS += -fopenmp -O3
bench-paper3: $(P3_STORE) $(P3_HJB) bench-ub
# On its own (seconds, no full-size run first): make bench-ub [QUICK=1].
.PHONY: bench-ub
bench-ub: $(P3_BENCH)
	@mkdir -p $(P3_OUT)
	OMP_WAIT_POLICY=passive $(P3_BENCH) $(QUICKFLAG) --out-dir $(P3_OUT)

# `make paper3` shares its runs between the two cores: one make -j2 over
# the runs in order of decreasing run time, so that each core takes the
# next run as soon as it is free (longest first keeps the last run short).
# `make reproduce` adds the other papers' results to the same pool: their
# long runs (REPRODUCE_BESIDE_LONG, the top Makefile) after paper 3's
# long ones, the rest (REPRODUCE_BESIDE: every result the check and the
# report read, paper 3's figures too) at the end, so that nothing is left
# for one core after the pool.  Run times in CPU seconds (user + system,
# 26 November 2026, the cells without a published value left out:
# storage.c, hjbstep.c): storage Table 1 442, Tables 11 and 12 about 230
# and 200 (321 and 313 before the segment searches of hj_ub.c), hjbstep
# 88, storage Tables 3-4 44, Table 13 about 35, examples2d 26, storage
# Table 2 18; paper 2's longest 45-65 s, the other runs 5-50 s.  The
# binaries are built first, two at a time, then the runs.
# P3_EXTRA=1 (`make paper3 P3_EXTRA=1`) also runs the cells without a
# published value that storage and hjbstep leave out as too costly
# (--extra: FS and FLS at 800^3 and 200^4, Table 2's FS, LS and CRS, ...;
# about 14 more CPU minutes: 2116 s of paper 3 runs before, about 1200 after).
P3_EXTRAFLAG := $(if $(filter 1,$(P3_EXTRA)),--extra)
P3_RUNS_FIRST := $(P3_STORE1)
P3_RUNS_LONG := $(P3_OUT)/table11.tsv $(P3_OUT)/table12.tsv $(P3_HJB)
P3_RUNS_SHORT := $(P3_STORE34) $(P3_OUT)/table13.tsv $(P3_2D) $(P3_STORE2)
.PHONY: paper3-results
paper3-results:
	$(MAKE) --no-print-directory -j2 $(P3_BINS) $(HJTIME)
	$(MAKE) --no-print-directory -j2 $(P3_RUNS_FIRST) $(P3_RUNS_LONG) $(if $(REPRODUCE_BESIDE_ON),$(REPRODUCE_BESIDE_LONG)) \
	    $(P3_RUNS_SHORT) $(P3_FIGS) $(if $(REPRODUCE_BESIDE_ON),$(REPRODUCE_BESIDE))
	$(MAKE) --no-print-directory $(P3_FIGS)
REPRODUCE_FIRST += paper3-results
paper3:
	$(MAKE) --no-print-directory paper3-results
	$(MAKE) --no-print-directory report-now
