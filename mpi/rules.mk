# The kernel over MPI (mpi/hj_mpi.[ch], mpi/mpi_reach.c), built only when
# OpenMPI's compiler wrapper is installed (scripts/ensure-deps mpi: the
# Debian packages libopenmpi-dev and openmpi-bin).  libhj.a is the same
# with or without it: hj_mpi.o goes into build/libhj_mpi.a, linked by the
# MPI programs only.  Included by the top-level Makefile.
#
#   make mpi-test   hj_mpi's unit tests (mpi/tests/test_mpi.c) and air3D
#                   and the 6-D double integrators on 1-4 processes, each
#                   result file compared byte for byte with the
#                   single-process library's (mpi/test-mpi.sh)
#   make mpi-bench  per-step time, communication fraction and weak scaling
#                   at 1, 2, 4 processes, and the scaling model for 64 and
#                   1,024 nodes (mpi/bench-mpi.sh; part of make bench)

MPICC := $(shell command -v mpicc 2>/dev/null)
MPI_BIN := $(BUILD)/bin/mpi
MPI_LIB := $(BUILD)/libhj_mpi.a
MPI_PROGS := $(MPI_BIN)/mpi_reach

.PHONY: mpi mpi-test mpi-bench

ifneq ($(MPICC),)
HAVE_MPI := 1
HJ_CC_MPI = $(MPICC) $(CPPFLAGS) -Impi -I$(P2) $(CFLAGS) -fopenmp
$(BUILD)/obj/mpi/%.o: mpi/%.c $(call hj_cmd_force,HJ_CC_MPI) | $(DEPS_OK)
	@mkdir -p $(@D)
	$(HJ_CC_MPI) -c $< -o $@
	@$(call hj_cmd_record,HJ_CC_MPI)
$(MPI_LIB): $(BUILD)/obj/mpi/hj_mpi.o
	rm -f $@ && ar rcs $@ $^
$(MPI_BIN)/mpi_reach: $(BUILD)/obj/mpi/mpi_reach.o $(BUILD)/obj/$(P2)/p2_air3d.o $(BUILD)/obj/$(P2)/p2_reach.o \
                      $(MPI_LIB) $(LIB)
	@mkdir -p $(@D)
	$(MPICC) $(LDFLAGS) $(filter %.o,$^) $(MPI_LIB) $(LIB) $(LDLIBS) -o $@
MPI_TEST := $(BUILD)/test/mpi/test_mpi
$(BUILD)/obj/mpi/tests/%.o: CPPFLAGS += -Icommon/tests
$(BUILD)/obj/mpi/tests/%.o: | build/.deps-test
$(MPI_TEST): $(BUILD)/obj/mpi/tests/test_mpi.o $(MPI_LIB) $(LIB)
	@mkdir -p $(@D)
	$(MPICC) $(LDFLAGS) $(filter %.o,$^) $(MPI_LIB) $(LIB) $(TESTLIBS) $(LDLIBS) -o $@
mpi: $(MPI_PROGS)
mpi-test: $(MPI_PROGS) $(MPI_TEST)
	mpi/test-mpi.sh $(MPI_BIN)/mpi_reach $(BUILD)/mpi-test $(MPI_TEST)
mpi-bench: $(MPI_PROGS)
	mpi/bench-mpi.sh $(MPI_BIN)/mpi_reach $(RESULTS)/mpi
BENCHES += mpi-bench
else
mpi mpi-test mpi-bench:
	@echo "$@: OpenMPI not installed (scripts/ensure-deps mpi), skipped"
endif
