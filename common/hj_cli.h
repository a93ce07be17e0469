/* hj_cli.h -- command-line support for the example programs.
 *
 * The parse functions are library code: they return an error code and a
 * message.  hj_cli_fail() and hj_progress() are for main() only: the first
 * prints "prog: message" once on stderr and exits with status 2 (bad usage)
 * or 1 (a run that failed); the second prints progress on stderr when stderr
 * is a terminal, so that logs in CI stay clean.
 */
#ifndef HJ_CLI_H
#define HJ_CLI_H

#include "hj_error.h"

/* Integer in [min, max], whole string, decimal. */
int hj_parse_long(const char *s, const char *what, long min, long max, long *out, hj_error *err);
/* Finite double in [min, max]. */
int hj_parse_double(const char *s, const char *what, double min, double max, double *out, hj_error *err);
/* Comma-separated integers in [min, max]; at most maxn of them. */
int hj_parse_long_list(const char *s, const char *what, long min, long max, long *out, int maxn, int *n, hj_error *err);

/* Exit codes used by every program. */
enum { HJ_EXIT_RUN = 1, HJ_EXIT_USAGE = 2 };

_Noreturn void hj_cli_fail(const char *prog, int exit_code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

void hj_progress(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

#endif
