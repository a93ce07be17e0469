/* hj_mintime.c -- the minimal time function as a stream of records (see
 * hj_mintime.h). */
#include "hj_mintime.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#define DMAX 8

int hj_mintime_put(hj_mintime_stream *s, const int *idx, double t)
{
    int32_t i32[DMAX];
    for (int k = 0; k < s->d; k++) i32[k] = idx[k];
    if (fwrite(i32, sizeof *i32, (size_t)s->d, s->fp) != (size_t)s->d || fwrite(&t, sizeof t, 1, s->fp) != 1) {
        s->failed = 1;
        return HJ_EIO;
    }
    return HJ_OK;
}

int hj_mintime_read(const char *path, int d, int n, double *T, hj_error *err)
{
    if (d < 1 || d > DMAX || n < 1) return hj_error_set(err, HJ_EINVAL, "minimal time: need 1 <= d <= %d, n >= 1", DMAX);
    FILE *f = fopen(path, "rb");
    if (!f) return hj_error_set(err, HJ_EIO, "cannot read %s: %s", path, strerror(errno));
    size_t total = 1;
    for (int k = 0; k < d; k++) total *= (size_t)n;
    for (size_t q = 0; q < total; q++) T[q] = INFINITY;
    int rc = HJ_OK;
    for (long rec = 0;; rec++) {
        int32_t i32[DMAX];
        double t;
        const size_t got = fread(i32, sizeof *i32, (size_t)d, f);
        if (got == 0 && feof(f)) break;
        if (got != (size_t)d || fread(&t, sizeof t, 1, f) != 1) {
            rc = hj_error_set(err, HJ_EFORMAT, "%s: record %ld is truncated", path, rec);
            break;
        }
        size_t lin = 0;
        for (int k = 0; k < d && rc == HJ_OK; k++) {
            if (i32[k] < 0 || i32[k] >= n)
                rc = hj_error_set(err, HJ_EFORMAT, "%s: record %ld: index %ld outside 0..%d", path, rec, (long)i32[k],
                                  n - 1);
            lin = lin * (size_t)n + (size_t)i32[k];
        }
        if (rc) break;
        if (isinf(T[lin])) T[lin] = t;
    }
    if (rc == HJ_OK && ferror(f)) rc = hj_error_set(err, HJ_EIO, "error reading %s", path);
    fclose(f);
    return rc;
}
