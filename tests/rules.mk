# tests/rules.mk -- reliability tests run by `make test` (make reliability):
# bad command lines generated from every program's option table, output
# safety (special files, read-only and full disks), interruption by
# signals, and a short run of each fuzz target.  `make fuzz` runs the
# fuzz targets for longer (FUZZ_SECONDS each).

# One libFuzzer target per reader of the library (tests/fuzz/fuzz_T.c),
# built with clang and the library sources it reads with.
FUZZ_CC := clang
FUZZ_FLAGS := -std=c11 -g -O1 -Wall -Wextra -Werror -Icommon -D_POSIX_C_SOURCE=200809L \
  -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all
FUZZ_TARGETS := map_pgm map_text vol table mintime cli
FUZZ_BINS := $(FUZZ_TARGETS:%=build/fuzz/fuzz_%)
FUZZ_SECONDS ?= 300
FUZZ_QUICK_SECONDS ?= 8

define fuzz_target
build/fuzz/fuzz_$(1): tests/fuzz/fuzz_$(1).c tests/fuzz/fuzz_file.h $(2) $(COMMON_HDR) | build/.deps-test
	@mkdir -p $$(@D)
	$$(FUZZ_CC) $$(FUZZ_FLAGS) $$(filter %.c,$$^) -o $$@ -lm
endef
$(eval $(call fuzz_target,map_pgm,common/hj_map.c common/hj_vol.c common/hj_io.c common/hj_error.c))
$(eval $(call fuzz_target,map_text,common/hj_map.c common/hj_vol.c common/hj_io.c common/hj_error.c))
$(eval $(call fuzz_target,vol,common/hj_vol.c common/hj_map.c common/hj_io.c common/hj_error.c))
$(eval $(call fuzz_target,table,common/hj_io.c common/hj_compare.c common/hj_error.c))
$(eval $(call fuzz_target,mintime,common/hj_mintime.c common/hj_error.c))
$(eval $(call fuzz_target,cli,common/hj_cli.c common/hj_io.c common/hj_ls_accuracy.c common/hj_error.c))

.PHONY: fuzz fuzz-quick reliability reliability-programs
fuzz: $(FUZZ_BINS)
	tests/fuzz/run.sh $(FUZZ_SECONDS) $(FUZZ_TARGETS)
fuzz-quick: $(FUZZ_BINS)
	tests/fuzz/run.sh $(FUZZ_QUICK_SECONDS) $(FUZZ_TARGETS)

# The program-level tests; against the sanitizer build with SAN=1 (its
# programs in build/san/bin), as make test also runs them.  The fuzz
# targets carry their own sanitizers.
reliability-programs: all
	tests/cli-matrix.sh $(BUILD)/bin
	tests/output-safety.sh $(BUILD)/bin
	tests/interrupt.sh $(BUILD)/bin
reliability: reliability-programs $(FUZZ_BINS)
	tests/fuzz/run.sh $(FUZZ_QUICK_SECONDS) $(FUZZ_TARGETS)
