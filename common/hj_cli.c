#include "hj_cli.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int hj_parse_long(const char *s, const char *what, long min, long max, long *out, hj_error *err)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (end == s || *end != '\0' || errno == ERANGE)
        return hj_error_set(err, HJ_EINVAL, "%s: '%s' is not an integer", what, s);
    if (v < min || v > max)
        return hj_error_set(err, HJ_EINVAL, "%s must be between %ld and %ld, got %ld", what, min, max, v);
    *out = v;
    return HJ_OK;
}

int hj_parse_double(const char *s, const char *what, double min, double max, double *out, hj_error *err)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || *end != '\0')
        return hj_error_set(err, HJ_EINVAL, "%s: '%s' is not a number", what, s);
    if (!isfinite(v))
        return hj_error_set(err, HJ_ENONFINITE, "%s must be finite, got '%s'", what, s);
    if (v < min || v > max)
        return hj_error_set(err, HJ_EINVAL, "%s must be between %g and %g, got %g", what, min, max, v);
    *out = v;
    return HJ_OK;
}

int hj_parse_long_list(const char *s, const char *what, long min, long max, long *out, int maxn, int *n, hj_error *err)
{
    char buf[64];
    int count = 0;
    const char *p = s;
    if (*s == '\0') return hj_error_set(err, HJ_EINVAL, "%s: empty list", what);
    for (;;) {
        const char *c = strchr(p, ',');
        size_t len = c ? (size_t)(c - p) : strlen(p);
        if (len == 0 || len >= sizeof buf)
            return hj_error_set(err, HJ_EINVAL, "%s: malformed list '%s'", what, s);
        if (count >= maxn)
            return hj_error_set(err, HJ_EINVAL, "%s: at most %d values", what, maxn);
        memcpy(buf, p, len);
        buf[len] = '\0';
        int rc = hj_parse_long(buf, what, min, max, &out[count], err);
        if (rc) return rc;
        count++;
        if (!c) break;
        p = c + 1;
    }
    *n = count;
    return HJ_OK;
}

void hj_cli_fail(const char *prog, int exit_code, const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "%s: ", prog);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    exit(exit_code);
}

void hj_progress(const char *fmt, ...)
{
    if (!isatty(STDERR_FILENO)) return;
    va_list ap;
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fflush(stderr);
}
