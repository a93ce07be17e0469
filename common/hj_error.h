/* hj_error.h -- error codes and messages of the hj library.
 *
 * Library code never prints and never exits: every function that can fail
 * returns one of the codes below and, when the caller passes an hj_error,
 * fills in a one-line human readable message.  Programs print that message
 * once and exit non-zero (see hj_cli.h).
 */
#ifndef HJ_ERROR_H
#define HJ_ERROR_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

enum {
    HJ_OK = 0,
    HJ_EINVAL,     /* an argument is out of range or inconsistent */
    HJ_ENOMEM,     /* allocation failed or the request exceeds memory */
    HJ_EIO,        /* a file could not be opened, read or written */
    HJ_EFORMAT,    /* a file was read but its contents are malformed */
    HJ_ENONFINITE, /* NaN or Inf where a finite number is required */
    HJ_ENOCONV,    /* an iteration did not converge */
    HJ_EFIT        /* a least-squares fit failed or is not determined */
};

typedef struct {
    int code;
    char msg[512];
} hj_error;

/* Human readable name of an error code. */
const char *hj_strerror(int code);

/* 1 if code is one of the codes above (HJ_OK included), 0 otherwise: a
 * caller's callback may return any int, and only the library's codes have
 * a name. */
int hj_error_known(int code);

/* Record code and a printf-style message in err (which may be NULL) and
 * return code, so that `return hj_error_set(err, HJ_EINVAL, "...")` works. */
int hj_error_set(hj_error *err, int code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* What a message quotes from a file, in buf (cap >= 8): printable ASCII
 * as it is, every other byte as \xHH and a backslash as \\ (a file may
 * hold anything; a message is one line of text), cut with "..." to fit.
 * Returns buf. */
const char *hj_error_quote(const char *s, size_t n, char *buf, size_t cap);

/* The ending of a count word in a message: "" for 1, "s" otherwise
 * ("%ld value%s", n, hj_plural(n)). */
const char *hj_plural(long n);

/* Reset err to HJ_OK with an empty message (err may be NULL). */
void hj_error_clear(hj_error *err);

#ifdef __cplusplus
}
#endif

#endif
