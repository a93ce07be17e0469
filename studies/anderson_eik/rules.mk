# The Anderson acceleration experiment (paper1_fastsweeping/eik/notes/
# anderson.md): included by the Makefile only after
# `git apply studies/anderson_eik/hj_eik_anderson.patch` (the option it
# measures was not kept); run by hand only.
AE := studies/anderson_eik
$(BUILD)/obj/$(AE)/%.o: CFLAGS += -fopenmp -O3
PROGRAMS += $(BUILD)/bin/$(AE)/anderson_eik
