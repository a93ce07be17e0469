#include "hj_error.h"

#include <stdarg.h>
#include <stdio.h>

const char *hj_strerror(int code)
{
    switch (code) {
    case HJ_OK: return "success";
    case HJ_EINVAL: return "invalid argument";
    case HJ_ENOMEM: return "out of memory";
    case HJ_EIO: return "input/output error";
    case HJ_EFORMAT: return "malformed input";
    case HJ_ENONFINITE: return "non-finite value";
    case HJ_ENOCONV: return "no convergence";
    case HJ_EFIT: return "fit failed";
    default: return "unknown error";
    }
}

int hj_error_set(hj_error *err, int code, const char *fmt, ...)
{
    if (err) {
        va_list ap;
        err->code = code;
        va_start(ap, fmt);
        vsnprintf(err->msg, sizeof err->msg, fmt, ap);
        va_end(ap);
    }
    return code;
}

void hj_error_clear(hj_error *err)
{
    if (err) {
        err->code = HJ_OK;
        err->msg[0] = '\0';
    }
}
