# Hamilton-Jacobi numerics: the libhj library and a literate reproduction
# package of three papers built on it.
#
#   make             the library (build/libhj.a, build/libhj.so) and every
#                    program; needs only gcc, make and Ceres
#   make install PREFIX=DIR
#                    libhj.a, libhj.so.VERSION, headers in DIR/include/hj/
#                    (umbrella hj.h) and DIR/lib/pkgconfig/hj.pc
#   make reproduce   run every example at the published sizes, write
#                    results/ and report/out/report.html
#   make test        unit tests (plain and under ASan+UBSan), the examples
#                    built against an installed copy through pkg-config,
#                    `make check QUICK=1`, then `make reliability` (bad
#                    command lines, output safety, signals, short fuzzing:
#                    tests/rules.mk) and its program tests again against
#                    the sanitizer build; with OpenMPI (scripts/ensure-deps
#                    mpi), the kernel over MPI on 1-4 processes, bitwise
#                    against the single-process library (mpi/rules.mk)
#   make fuzz        each fuzz target for FUZZ_SECONDS (300)
#   make check       compare every published cell with the computed one;
#                    fails when a cell is worse than its accepted verdict
#   make paper1 | paper2 | paper3    one paper's results, then the report
#   make bench       benchmarks (timings as ratios against a baseline)
#   make clean
#
# QUICK=1 runs the reduced (coarser) sets into results-quick/.
# SAN=1 builds with AddressSanitizer and UndefinedBehaviorSanitizer into
# build/san/.  Dependencies (Debian packages) are installed on first use by
# scripts/ensure-deps, by group: lib (Ceres) for the library and programs,
# test (cmocka, pkg-config) for the tests, repro (gnuplot, cmark) for
# figures and the report, bench (scikit-fmm) for `make bench`.

SHELL := /bin/bash
.DEFAULT_GOAL := all
.DELETE_ON_ERROR:
.SECONDARY:
# Each object keeps the command that compiled it in OBJ.cmd, written after
# a successful compile; an object whose command differs from the record
# (a flag edited in this Makefile or a rules.mk, CC=...) gets the phony
# prerequisite FORCE and is rebuilt, and nothing else is.  The comparison
# is a secondary expansion of the object's prerequisites, so it sees the
# object's target- and pattern-specific flags; it starts no shell and
# writes nothing (make -n and make -q stay side-effect free).
.SECONDEXPANSION:
.PHONY: FORCE
hj_differ = $(subst $(1),,$(2))$(subst $(2),,$(1))
hj_cmd_force = $$(if $$(call hj_differ,$$(file <$$@.cmd),$$($(1))),FORCE)
hj_cmd_record = printf '%s\n' '$(subst ','\'',$($(1)))' > $@.cmd
HJ_PIC_FLAGS := -fPIC -fno-semantic-interposition
HJ_CC_OBJ = $(CC) $(CPPFLAGS) $(CFLAGS)
HJ_CC_PIC = $(CC) $(CPPFLAGS) $(CFLAGS) $(HJ_PIC_FLAGS)

CC := gcc
BUILD := build
CPPFLAGS := -Icommon -Icommon/tests -D_POSIX_C_SOURCE=200809L -MMD -MP
CFLAGS := -std=c11 -O2 -g -Wall -Wextra -Werror -Wshadow -Wstrict-prototypes
LDFLAGS :=
LDLIBS := -lceres -lm
TESTLIBS := -lcmocka

ifeq ($(SAN),1)
BUILD := build/san
CFLAGS += -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all
LDFLAGS += -fsanitize=address,undefined
endif

ifeq ($(QUICK),1)
RESULTS := results-quick
QUICKFLAG := --quick
CHECKFLAGS := --quick
else
RESULTS := results
QUICKFLAG :=
CHECKFLAGS :=
endif

# Dependency groups this invocation needs (scripts/ensure-deps GROUP).
DEPS_GROUPS := lib
ifneq ($(filter test unit memcheck examples fuzz fuzz-quick reliability reliability-programs,$(MAKECMDGOALS)),)
DEPS_GROUPS += test
endif
ifneq ($(filter reproduce report report-now paper1 paper2 paper3 bench test check,$(MAKECMDGOALS)),)
DEPS_GROUPS += repro
endif
ifneq ($(filter bench bench-eikonal,$(MAKECMDGOALS)),)
DEPS_GROUPS += bench
endif
DEPS_OK := $(DEPS_GROUPS:%=build/.deps-%)

# ---- the library ----------------------------------------------------------
HJ_VERSION := $(shell sed -n 's/^\#define HJ_VERSION_STRING "\(.*\)"/\1/p' common/hj.h)
HJ_SOVERSION := 0
LIB := $(BUILD)/libhj.a
SOLIB := $(BUILD)/libhj.so.$(HJ_VERSION)
COMMON_SRC := $(wildcard common/*.c)
COMMON_HDR := $(wildcard common/*.h)
# The library is compiled once, position independent, for both libhj.a and
# libhj.so (-fno-semantic-interposition: calls inside libhj are bound and
# inlined as in a static build, so libhj.a runs the same code as before).
COMMON_PIC := $(COMMON_SRC:%.c=$(BUILD)/pic/%.o)
PREFIX := /usr/local
HJCHECK := $(BUILD)/bin/common/tools/hjcheck
HJTIME := $(BUILD)/bin/common/tools/hjtime
# $(call hj_timed,DIR,LABEL) COMMAND...: run COMMAND and record its wall
# time, CPU time and peak memory in DIR/time/LABEL.tsv (shown in the
# report beside the example; never compared or tested).
hj_timed = $(HJTIME) $(1)/time/$(2).tsv $(2) --

# $(eval $(call hj_figure,PAPERDIR,OUTDIR,FIG,INPUTS)): OUTDIR/FIG.png drawn
# by PAPERDIR/plot/FIG.gp from INPUTS (names in OUTDIR); the script gets
# dir = OUTDIR and out, a temporary name renamed when the figure is done.
# The one figure rule of every paper.
define hj_figure
$(2)/$(3).png: $(4:%=$(2)/%) $(1)/plot/$(3).gp
	gnuplot -e "dir='$(2)'; out='$$(@D)/.tmp-$$(@F)'" $(1)/plot/$(3).gp && mv $$(@D)/.tmp-$$(@F) $$@
REPORT_INPUTS += $(1)/plot/$(3).gp $(2)/$(3).png
endef

# Filled in by the papers' rules.mk fragments.
PROGRAMS := $(HJCHECK) $(HJTIME)
UNIT_TESTS := $(patsubst %.c,$(BUILD)/test/%,$(wildcard common/tests/test_*.c))
CHECK_PAPERS :=
REPRODUCE_FIRST :=
REPORT_INPUTS :=
BENCHES :=

# OpenMP for the level set kernel; -O3 lets gcc vectorise its row kernels
# (results are bitwise the same for any thread count).  Every program links
# with -fopenmp, since libhj holds the kernel.
LDFLAGS += -fopenmp
$(BUILD)/pic/common/hj_ls_%.o: CFLAGS += -fopenmp -O3
# The terms' row loops select an upwind side per node (v > 0 ? l : r);
# with trapping math gcc keeps each side's arithmetic under a branch, and
# only AVX-512's masked operations vectorise that: the AVX2 and SSE2
# clones of the 2-D convection row ran scalar (convectionDemo 2-D medium
# 1.46 s in the AVX2 clone against 0.44 s with this flag, the same bits;
# the AVX-512 clone is unchanged).  No value changes: no FP exception is
# ever inspected.
$(BUILD)/pic/common/hj_ls_term.o: CFLAGS += -fno-trapping-math
# sqrt in a row loop vectorises only without errno (gcc otherwise keeps a
# call under a branch per node for a negative argument).  Every sqrt in
# hj_ls_term.c takes a sum of squares, never negative: errno is never set
# either way, and sqrt's value is the same (correctly rounded).
$(BUILD)/pic/common/hj_ls_term.o: CFLAGS += -fno-math-errno
# The upwind row kernels (WENO5's windows are one long dependency chain
# per node): instructions also scheduled before register allocation
# (-fsched-pressure: without adding spills) and the short loops unrolled
# (the WENO5 bodies are too large to be): about 2 % less CPU time on
# air3D veryHigh, no case slower.  Neither option reorders arithmetic:
# the same bits.
$(BUILD)/pic/common/hj_ls_deriv.o: CFLAGS += -funroll-loops -fschedule-insns -fsched-pressure
# Exact sums (hj_sum): called once per node by the norms and measures.
$(BUILD)/pic/common/hj_sum.o: CFLAGS += -O3
# The dense Ultra-Bee step likewise (row loops vectorised, rows shared
# among threads, bitwise the same for any thread count).
# -fno-trapping-math lets gcc turn its flux selects (== on doubles) into
# vector blends; it changes no value (no FP exception is ever inspected).
$(BUILD)/pic/common/hj_ub_dense.o: CFLAGS += -fopenmp -O3 -fno-trapping-math
$(BUILD)/obj/common/tests/test_ub_dense.o: CFLAGS += -fopenmp
# The kernel's unit tests use omp_set_num_threads (bitwise determinism test).
$(BUILD)/obj/common/tests/test_ls_%.o: CFLAGS += -fopenmp
$(BUILD)/obj/common/tests/test_sys.o: CFLAGS += -fopenmp
# Reachability runs its per-node passes (projection, time-to-reach) in
# parallel over rows like the kernel.
$(BUILD)/pic/common/hj_reach.o $(BUILD)/pic/common/hj_reach_fused.o: CFLAGS += -fopenmp -O3
$(BUILD)/obj/common/tests/test_reach.o $(BUILD)/obj/common/tests/test_ctrl.o: CFLAGS += -fopenmp
# The Eikonal sweeps run hyperplanes in parallel (bitwise thread-independent).
$(BUILD)/pic/common/hj_eik.o: CFLAGS += -fopenmp -O3
$(BUILD)/obj/common/tests/test_eik.o: CFLAGS += -fopenmp

# The tests of the tools run the built hjcheck and hjtime.
$(BUILD)/obj/common/tests/test_hjcheck.o $(BUILD)/obj/common/tests/test_hjtime.o: CPPFLAGS += -DHJ_BIN_DIR='"$(BUILD)/bin"'
$(BUILD)/test/common/tests/test_hjcheck: | $(HJCHECK)
$(BUILD)/test/common/tests/test_hjtime: | $(HJTIME)

include paper1_fastsweeping/rules.mk
include paper2_toolbox/rules.mk
include paper3_ultrabee/rules.mk
include studies/reach/rules.mk
include studies/defect_correction/rules.mk
include studies/nested_eik/rules.mk
include tests/rules.mk
include mpi/rules.mk

.PHONY: all lib install deps reproduce test unit examples check report paper1 paper2 paper3 bench clean memcheck

all: lib $(PROGRAMS)
lib: $(LIB) $(SOLIB)

deps: $(DEPS_OK)
build/.deps-%: scripts/ensure-deps
	@scripts/ensure-deps $*
	@mkdir -p $(@D) && touch $@

$(BUILD)/obj/%.o: %.c $(call hj_cmd_force,HJ_CC_OBJ) | $(DEPS_OK)
	@mkdir -p $(@D)
	$(HJ_CC_OBJ) -c $< -o $@
	@$(call hj_cmd_record,HJ_CC_OBJ)
$(BUILD)/pic/%.o: %.c $(call hj_cmd_force,HJ_CC_PIC) | $(DEPS_OK)
	@mkdir -p $(@D)
	$(HJ_CC_PIC) -c $< -o $@
	@$(call hj_cmd_record,HJ_CC_PIC)

$(LIB): $(COMMON_PIC)
	@mkdir -p $(@D)
	rm -f $@ && ar rcs $@ $^
$(SOLIB): $(COMMON_PIC)
	@mkdir -p $(@D)
	$(CC) -shared -Wl,-soname,libhj.so.$(HJ_SOVERSION) $(LDFLAGS) $^ $(LDLIBS) -o $@

# Install the library, its headers (under include/hj/, with the umbrella
# hj.h) and hj.pc, which carries every flag a user needs.  Files are
# copied under a temporary name and renamed, so an interrupted install
# leaves no half-written file under a final name.
install: lib
	@case "$(PREFIX)" in /*) ;; *) echo "install: PREFIX must be an absolute path, got '$(PREFIX)'" >&2; exit 2;; esac
	scripts/install-lib "$(PREFIX)" $(HJ_VERSION) $(HJ_SOVERSION) $(LIB) $(SOLIB) $(COMMON_HDR)

$(BUILD)/bin/%: $(BUILD)/obj/%.o $(LIB)
	@mkdir -p $(@D)
	$(CC) $(LDFLAGS) $(filter %.o,$^) $(LIB) $(LDLIBS) -o $@

$(BUILD)/test/%: $(BUILD)/obj/%.o $(LIB)
	@mkdir -p $(@D)
	$(CC) $(LDFLAGS) $(filter %.o,$^) $(LIB) $(TESTLIBS) $(LDLIBS) -o $@

# ---- tests ---------------------------------------------------------------

# Each unit test program is a cmocka group; run them all, count failures.
unit: $(UNIT_TESTS)
	@fail=0; for t in $(UNIT_TESTS); do $$t || fail=$$((fail+1)); done; \
	if [ $$fail -ne 0 ]; then echo "unit ($(BUILD)): $$fail test program(s) failed"; exit 1; fi

test:
	$(MAKE) --no-print-directory unit
	$(MAKE) --no-print-directory SAN=1 unit
	$(MAKE) --no-print-directory examples
	$(MAKE) --no-print-directory QUICK=1 check
	$(MAKE) --no-print-directory reliability
	$(MAKE) --no-print-directory SAN=1 reliability-programs
	@if scripts/ensure-deps mpi; then $(MAKE) --no-print-directory mpi-test; \
	 else echo "make test: OpenMPI not installed, the MPI tests skipped"; fi

# The examples as a user builds them: libhj installed into a temporary
# prefix, every flag from `pkg-config --cflags --libs hj`, run against the
# installed shared library.
EX_PREFIX := $(abspath build/prefix)
examples: | $(DEPS_OK)
	rm -rf $(EX_PREFIX)
	$(MAKE) --no-print-directory install PREFIX=$(EX_PREFIX)
	PKG_CONFIG_PATH=$(EX_PREFIX)/lib/pkgconfig LD_LIBRARY_PATH=$(EX_PREFIX)/lib \
	  $(MAKE) --no-print-directory -C examples OUT=$(abspath build/examples) check

# Every test program runs, and the failing ones are named at the end.
memcheck: $(UNIT_TESTS)
	@fail=""; for t in $(UNIT_TESTS); do \
	  valgrind -q --error-exitcode=1 --leak-check=full --errors-for-leak-kinds=definite $$t >/dev/null || fail="$$fail $${t##*/}"; \
	done; if [ -n "$$fail" ]; then echo "memcheck: errors or definite leaks in$$fail"; exit 1; fi; \
	echo "memcheck: no errors or definite leaks"

# ---- results, check, report -------------------------------------------

# Bless the current verdicts of one table (hjcheck --accept): every cell
# that is not a match is accepted at its verdict with reason REASON (an id
# of PAPERDIR/reasons.tsv, or a new one with REASON_TEXT); a cell already
# accepted at that verdict keeps its own reason.  QUICK=1 writes
# the quick run's own exceptions (accepted-quick.tsv).
.PHONY: accept
accept: $(HJCHECK)
	@if [ -z "$(PAPER)" ] || [ -z "$(TABLE)" ] || [ -z "$(REASON)" ]; then \
	  echo "usage: make accept PAPER=paper1 TABLE=table3.1 REASON=id [REASON_TEXT='...'] [QUICK=1]" >&2; exit 2; fi
	@case " $(CHECK_PAPERS) " in *" $(PAPER)="*) ;; *) echo "accept: PAPER must be one of: $(CHECK_PAPERS)" >&2; exit 2;; esac
	$(HJCHECK) --results $(RESULTS) $(CHECKFLAGS) --accept '$(TABLE)' --reason '$(REASON)' \
	  $(if $(REASON_TEXT),--reason-text '$(REASON_TEXT)') $(filter $(PAPER)=%,$(CHECK_PAPERS))

check: $(HJCHECK) $(CHECK_INPUTS)
	$(HJCHECK) --results $(RESULTS) $(CHECKFLAGS) $(CHECK_PAPERS)

# The full report from results/, the quick one (QUICK=1) from
# results-quick/ into report/out-quick/.
ifeq ($(QUICK),1)
REPORT_DIR := report/out-quick
else
REPORT_DIR := report/out
endif
REPORT := $(REPORT_DIR)/report.html
# A paper may schedule its long runs itself before the report pulls in the
# rest (paper 3 shares its runs between the two cores: REPRODUCE_FIRST).
# The other papers' results go into the same pool (paper3_ultrabee/rules.mk):
# their long runs among paper 3's long ones (the comparison with ToolboxLS's
# arrays, about 45 CPU s, paper 2's 50-70 s demos and its Table 1, about
# 80 s), then every other result the check and the report read (the
# Eikonal and reachability studies too), so that the report's rule below
# finds them made and only assembles the page.
REPRODUCE_BESIDE_LONG := $(filter %/toolboxls.tsv %/curvature_spiral.tsv %/dumbbell.tsv %/convection_bench.tsv, \
                           $(P2_CHECK) $(P2_RESULTS))
REPRODUCE_BESIDE := $(P1_REPORTED) $(P2_RESULTS) $(P2_CHECK) \
    $(filter $(RESULTS)/%,$(CHECK_INPUTS) $(REPORT_INPUTS))
reproduce:
	@for t in $(REPRODUCE_FIRST); do $(MAKE) --no-print-directory $$t REPRODUCE_BESIDE_ON=1 || exit 1; done
	$(MAKE) --no-print-directory $(REPORT)
report: $(REPORT)

# The report from the results as they are; `make reproduce` first brings
# every paper's results up to date, `make paperN` only paper N's.
define build_report
	@mkdir -p $(RESULTS)
	$(HJCHECK) --results $(RESULTS) $(CHECKFLAGS) --no-fail $(CHECK_PAPERS) > $(RESULTS)/check-summary.txt
	report/build.sh $(RESULTS) $(REPORT_DIR) $(HJCHECK) $(if $(filter 1,$(QUICK)),quick)
endef

$(REPORT): $(HJCHECK) $(REPORT_INPUTS) report/build.sh report/intro.md \
          $(wildcard */published/*.tsv */reference/*.tsv */reference/*/*.tsv */accepted.tsv)
	$(build_report)

.PHONY: report-now report-view
report-now: $(HJCHECK)
	$(build_report)

# Render the report in headless Chromium (installed by the view group of
# scripts/ensure-deps) and fail on a figure that does not load or a table
# without a body row; a screenshot of the top lands beside the report.
report-view: $(REPORT)
	@scripts/ensure-deps view
	report/view.sh $(REPORT)

bench: $(BENCHES)

# Test programs need cmocka whatever the goal.
$(UNIT_TESTS:$(BUILD)/test/%=$(BUILD)/obj/%.o): | build/.deps-test

clean:
	rm -rf build results results-quick report/out report/out-quick
	find . -name '*.tmp.[0-9]*' -type f -delete

-include $(shell find build -name '*.d' 2>/dev/null)
