# The defect correction experiment (paper1_fastsweeping/eik/notes/
# defect-correction.md): built with everything so that it stays compiled,
# run by hand only (never by the tests or the reproduction).
DC := studies/defect_correction
$(BUILD)/obj/$(DC)/%.o: CFLAGS += -fopenmp -O3
PROGRAMS += $(BUILD)/bin/$(DC)/dc_eik
