/* libFuzzer target: hj_table_read, the TSV reader of the published,
 * accepted and computed tables, and what hjcheck does with the cells. */
#include "fuzz_file.h"
#include "hj_compare.h"
#include "hj_io.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_file(data, size);
    if (!path) return 0;
    hj_table t;
    hj_error err;
    const int rc = hj_table_read(&t, path, &err);
    fuzz_file_done();
    if (rc != HJ_OK) {
        if (!fuzz_message_ok(err.msg)) abort();
        return 0;
    }
    (void)hj_table_meta(&t, "kind");
    (void)hj_table_col(&t, "key");
    for (int r = 0; r < t.nrows; r++)
        for (int c = 0; c < t.ncols; c++) {
            const char *cell = t.cells[r][c];
            (void)hj_verdict_from_name(cell);
            hj_kind k = hj_kind_from_name(t.cols[c]);
            char *end;
            double v = strtod(cell, &end);
            if (k != HJ_KIND_UNKNOWN) (void)hj_compare(k, v, v * 1.01, NULL);
        }
    hj_table_free(&t);
    return 0;
}
