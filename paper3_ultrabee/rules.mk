# Paper 3: Bokanowski, Cristiani & Zidani (2010), Ultra-Bee HJB scheme with
# sparse semi-dynamic storage.  Included by the top-level Makefile.

P3 := paper3_ultrabee
P3_PROGS := examples2d examples34d storage hjbstep
P3_BINS := $(P3_PROGS:%=$(BUILD)/bin/$(P3)/%)
P3_LIBOBJ := $(addprefix $(BUILD)/obj/$(P3)/,p3_store.o p3_ub.o p3_errors.o p3_prog.o p3_front.o)
$(P3_BINS): $(P3_LIBOBJ)
$(BUILD)/obj/$(P3)/%.o: CPPFLAGS += -I$(P3)

PROGRAMS += $(P3_BINS)
P3_TESTS := $(patsubst %.c,$(BUILD)/test/%,$(wildcard $(P3)/tests/test_*.c))
UNIT_TESTS += $(P3_TESTS)
$(P3_TESTS): $(P3_LIBOBJ)

P3_OUT := $(RESULTS)/paper3
P3_2D := $(addprefix $(P3_OUT)/,table6.tsv table7.tsv table8.tsv table9.tsv table10.tsv)
P3_ND := $(addprefix $(P3_OUT)/,table11.tsv table12.tsv table13.tsv)
P3_STORE := $(addprefix $(P3_OUT)/,table1.tsv table2.tsv table3.tsv table4.tsv)
P3_HJB := $(P3_OUT)/table5.tsv
P3_RESULTS := $(P3_STORE) $(P3_HJB) $(P3_2D) $(P3_ND)

# One run of each program writes its group of tables.
$(P3_2D) &: $(BUILD)/bin/$(P3)/examples2d
	@mkdir -p $(P3_OUT)
	$< $(QUICKFLAG) --out-dir $(P3_OUT)
$(P3_ND) &: $(BUILD)/bin/$(P3)/examples34d
	@mkdir -p $(P3_OUT)
	$< $(QUICKFLAG) --out-dir $(P3_OUT)

$(P3_STORE) &: $(BUILD)/bin/$(P3)/storage
	@mkdir -p $(P3_OUT)
	$< $(QUICKFLAG) --out-dir $(P3_OUT)
$(P3_HJB): $(BUILD)/bin/$(P3)/hjbstep
	@mkdir -p $(P3_OUT)
	$< $(QUICKFLAG) --out-dir $(P3_OUT)

CHECK_PAPERS += paper3=$(P3)
CHECK_INPUTS += $(P3_RESULTS)
REPORT_INPUTS += $(P3_RESULTS) $(P3_PROGS:%=$(P3)/%.c)

.PHONY: bench-paper3
BENCHES += bench-paper3
# The timing tables (ratios between grids and between structures).
bench-paper3: $(P3_STORE) $(P3_HJB)

paper3: $(P3_RESULTS)
	$(MAKE) --no-print-directory report-now
