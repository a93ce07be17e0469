/* libFuzzer target: hj_map_read_text (rows of numbers). */
#include "fuzz_map.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_file(data, size);
    if (!path) return 0;
    hj_map m = {0};
    hj_error err;
    const int rc = hj_map_read_text(&m, path, &err);
    fuzz_file_done();
    fuzz_map_use(rc, &m, &err, 0.25, 0.75);
    return 0;
}
