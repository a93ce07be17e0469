/* libFuzzer target: hj_vol_read (a PGM or a text volume, told by
 * content) and hj_vol_read_raw (the first byte picks the dimensions and
 * the value size), then what the Eikonal tool does with a volume. */
#include "fuzz_file.h"
#include "hj_vol.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1) return 0;
    const char *path = fuzz_file(data, size);
    if (!path) return 0;
    hj_vol v = {0};
    hj_error err;
    int rc = hj_vol_read(&v, path, 1, 3, &err);
    if (rc == HJ_OK) {
        (void)hj_vol_check_nonzero(&v, path, &err);
        hj_vol_free(&v);
    } else if (!fuzz_message_ok(err.msg)) {
        abort();
    }
    const long n[3] = {2 + (data[0] & 3), 2 + (data[0] >> 2 & 3), 1 + (data[0] >> 4 & 3)};
    rc = hj_vol_read_raw(&v, path, n, data[0] & 0x80 ? 8 : 4, &err);
    fuzz_file_done();
    if (rc == HJ_OK) hj_vol_free(&v);
    else if (!fuzz_message_ok(err.msg)) abort();
    return 0;
}
