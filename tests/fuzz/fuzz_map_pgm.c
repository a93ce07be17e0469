/* libFuzzer target: hj_map_read_pgm (P2 and P5, 8 and 16 bits). */
#include "fuzz_map.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_file(data, size);
    if (!path) return 0;
    hj_map m = {0};
    hj_error err;
    const int rc = hj_map_read_pgm(&m, path, 1, 3, &err);
    fuzz_file_done();
    fuzz_map_use(rc, &m, &err, 0.5, 0.5);
    return 0;
}
