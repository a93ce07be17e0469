/* libFuzzer target: hj_mintime_read, paper 3's minimal time records
 * (binary).  The first two bytes choose the dimension (1-4) and the
 * nodes per dimension (1-16); the rest is the file. */
#include "fuzz_file.h"
#include "hj_mintime.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 2) return 0;
    const int d = 1 + data[0] % 4, n = 1 + data[1] % 16;
    const char *path = fuzz_file(data + 2, size - 2);
    if (!path) return 0;
    size_t total = 1;
    for (int k = 0; k < d; k++) total *= (size_t)n;
    double *T = malloc(total * sizeof *T);
    hj_error err;
    const int rc = T ? hj_mintime_read(path, d, n, T, &err) : HJ_OK;
    fuzz_file_done();
    if (rc != HJ_OK && !fuzz_message_ok(err.msg)) abort();
    free(T);
    return 0;
}
