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

#include <stdio.h>

#include "hj_error.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Integer in [min, max], whole string, decimal. */
int hj_parse_long(const char *s, const char *what, long min, long max, long *out, hj_error *err);
/* Finite double in [min, max]. */
int hj_parse_double(const char *s, const char *what, double min, double max, double *out, hj_error *err);
/* Comma-separated integers in [min, max]; at most maxn of them. */
int hj_parse_long_list(const char *s, const char *what, long min, long max, long *out, int maxn, int *n, hj_error *err);

/* ---- declarative options ------------------------------------------------
 *
 * A program describes its options in one table; hj_cli_parse() reads the
 * command line against it, and --help, unknown options, missing values,
 * range checks and their messages all come from that one place.  Values
 * are written to the variables the table points to, which hold the
 * defaults beforehand (--help prints them).  Every option takes the form
 * "--name value" (or "--name" alone for a flag).  An option may be given
 * once, except a STRING_LIST, which collects one value per occurrence:
 * its first occurrence replaces the default list, the next ones append. */
typedef enum {
    HJ_OPT_FLAG,      /* int *: set to 1 */
    HJ_OPT_LONG,      /* long *, in [min, max] */
    HJ_OPT_DOUBLE,    /* double *, finite, in [min, max] */
    HJ_OPT_STRING,    /* const char **: the argument itself, non-empty */
    HJ_OPT_LONG_LIST, /* long * array of maxn, count in *count; each in [min, max] */
    HJ_OPT_CHOICE,    /* int *: index in choices (a NULL-terminated list of words) */
    HJ_OPT_STRING_LIST /* const char ** array of maxn, count in *count: one non-empty value per
                        * occurrence, at most maxn occurrences (e.g. --source X,Y given twice) */
} hj_opt_type;

typedef struct {
    const char *name;    /* "--N" */
    hj_opt_type type;
    void *value;
    double min, max;     /* LONG, DOUBLE, LONG_LIST */
    const char *metavar; /* shown in --help: "N", "FILE" */
    const char *help;    /* one line */
    const char *const *choices; /* CHOICE */
    int *count, maxn;    /* LONG_LIST, STRING_LIST */
    const char *dflt;    /* shown as the default instead of the value (e.g. "the paper's") */
    int seen;            /* set by hj_cli_parse when given */
} hj_cli_opt;

typedef struct {
    const char *prog;    /* program name for messages */
    const char *summary; /* one line: what the program does */
    hj_cli_opt *opts;
    int nopts;
    const char *epilog;  /* optional text after the options */
} hj_cli_spec;

/* Parse argv[1..argc-1] against spec.  Returns HJ_OK, with *help =
 * HJ_CLI_HELP if --help was given (the caller prints hj_cli_help and exits
 * 0) or HJ_CLI_LIST for --list-options (hj_cli_list, exit 0), or
 * HJ_EINVAL / HJ_ENONFINITE with one message naming the option.  Giving an
 * option twice is an error, except a STRING_LIST up to its maxn times. */
enum { HJ_CLI_HELP = 1, HJ_CLI_LIST = 2 };
int hj_cli_parse(hj_cli_spec *spec, int argc, char **argv, int *help, hj_error *err);

/* "usage: prog [options]", the summary, and one line per option with its
 * metavariable, range or choices and its current (default) value. */
void hj_cli_help(const hj_cli_spec *spec, FILE *out);

/* The option table for test drivers (--list-options): a header line, then
 * one tab-separated line per option: name, type (flag, long, double,
 * string, long-list, choice), min, max (exact; "-" when the type has
 * none), choices (comma-separated, "-"), maxn (list length, "-"). */
void hj_cli_list(const hj_cli_spec *spec, FILE *out);

/* For main(): parse, print --help or --list-options and exit 0, or print
 * the one message and exit with HJ_EXIT_USAGE.  After a good parse it
 * installs hj_out_remove_on_signal (hj_io.h): an interrupted program
 * leaves no temporary file.  It also checks stdout at exit: a program
 * whose --help, table or other stdout text could not be written (a full
 * disk, /dev/full, a closed stdout) prints "prog: error writing stdout"
 * and exits with HJ_EXIT_RUN instead of 0. */
void hj_cli_parse_or_exit(hj_cli_spec *spec, int argc, char **argv);
/* That check of stdout at exit alone, for a program with a parser of its
 * own. */
void hj_cli_check_stdout(const char *prog);
/* The same check now: flush stdout and, if this or an earlier write to it
 * failed, print "prog: error writing stdout: REASON" (strerror), remove
 * the temporary outputs and exit with HJ_EXIT_RUN.  For a program that
 * writes its result to stdout and must not go on after losing it. */
void hj_cli_flush_stdout(const char *prog);

/* Exit codes used by every program.  hj_cli_fail prints "prog: message"
 * as one line (control bytes in the message escaped: \n, \xHH), removes
 * the temporary files of outputs still open (hj_out_remove_all) and
 * exits. */
enum { HJ_EXIT_RUN = 1, HJ_EXIT_USAGE = 2 };

/* C11 spells "does not return" _Noreturn, C++11 [[noreturn]]. */
#ifdef __cplusplus
[[noreturn]]
#else
_Noreturn
#endif
void hj_cli_fail(const char *prog, int exit_code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

void hj_progress(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

#ifdef __cplusplus
}
#endif

#endif
