# The nested iteration experiment (paper1_fastsweeping/eik/notes/
# nested-iteration.md): built with everything so that it stays compiled,
# run by hand only (never by the tests or the reproduction).
NE := studies/nested_eik
$(BUILD)/obj/$(NE)/%.o: CFLAGS += -fopenmp -O3
PROGRAMS += $(BUILD)/bin/$(NE)/nested_eik
