# ToolboxLS equivalence: our kernel against the toolbox's own final arrays
# (toolboxls/arrays, gzipped text, decompressed into the build tree).
P2_TB_ARRAYS := $(patsubst $(P2)/toolboxls/arrays/%.txt.gz,$(BUILD)/toolboxls/%.txt,$(wildcard $(P2)/toolboxls/arrays/*.txt.gz))
$(BUILD)/toolboxls/%.txt: $(P2)/toolboxls/arrays/%.txt.gz
	@mkdir -p $(@D)
	gzip -dc $< > $@.tmp && mv $@.tmp $@
P2_PROGS += toolboxls
$(P2_BIN)/toolboxls: $(patsubst %,$(BUILD)/obj/$(P2)/p2_%.o,air3d acoustic reach oshershu convection reinit cli)
$(P2_OUT)/toolboxls.tsv: $(P2_BIN)/toolboxls $(P2_TB_ARRAYS) | $(HJTIME)
	@mkdir -p $(P2_OUT)
	$(call hj_timed,$(P2_OUT),toolboxls) env OMP_WAIT_POLICY=passive $< $(QUICKFLAG) --toolbox-dir $(BUILD)/toolboxls --out-dir $(P2_OUT)
P2_CHECK += $(P2_OUT)/toolboxls.tsv
REPORT_INPUTS += $(P2)/toolboxls.c
