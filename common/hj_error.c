#include "hj_error.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* The library's codes and their names; NULL for any other value. */
static const char *code_name(int code)
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
    default: return NULL;
    }
}

const char *hj_strerror(int code)
{
    const char *s = code_name(code);
    return s ? s : "unknown error";
}

int hj_error_known(int code) { return code_name(code) != NULL; }

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

const char *hj_plural(long n) { return n == 1 ? "" : "s"; }

void hj_error_clear(hj_error *err)
{
    if (err) {
        err->code = HJ_OK;
        err->msg[0] = '\0';
    }
}

const char *hj_error_quote(const char *s, size_t n, char *buf, size_t cap)
{
    size_t k = 0;
    for (size_t i = 0; i < n; i++) {
        const unsigned char c = (unsigned char)s[i];
        if (k + 8 >= cap) { /* each byte takes at most 4: "..." fits */
            strcpy(buf + k, "...");
            return buf;
        }
        if (c >= 0x20 && c < 0x7f && c != '\\') buf[k++] = (char)c;
        else k += (size_t)snprintf(buf + k, cap - k, c == '\\' ? "\\\\" : "\\x%02x", c);
    }
    buf[k] = '\0';
    return buf;
}
