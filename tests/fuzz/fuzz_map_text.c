/* libFuzzer target: hj_map_read_text (rows of numbers). */
#include "fuzz_file.h"
#include "hj_map.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_file(data, size);
    if (!path) return 0;
    hj_map m = {0};
    hj_error err;
    const int rc = hj_map_read_text(&m, path, &err);
    fuzz_file_done();
    if (rc == HJ_OK) {
        (void)hj_map_eval(0.25 * m.mx, 0.75 * m.my, &m);
        (void)hj_map_invert(&m, &err);
        hj_map_free(&m);
    } else if (!fuzz_message_ok(err.msg)) {
        abort();
    }
    return 0;
}
