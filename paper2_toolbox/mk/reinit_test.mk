# reinitTest (section 2.7.3): signedDistanceIterative on reinitDemo's cases.
P2_PROGS += reinit_test
$(P2_BIN)/reinit_test: $(BUILD)/obj/$(P2)/p2_basic.o
$(P2_OUT)/reinit_test.tsv $(P2_OUT)/reinit_test_notes.md &: $(P2_BIN)/reinit_test
	@mkdir -p $(P2_OUT)
	OMP_WAIT_POLICY=passive $< $(QUICKFLAG) --out-dir $(P2_OUT)
P2_RESULTS += $(P2_OUT)/reinit_test_notes.md
P2_CHECK += $(P2_OUT)/reinit_test.tsv
REPORT_INPUTS += $(P2)/reinit_test.c
