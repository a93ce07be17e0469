#include "hj_cli.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "hj_io.h"

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

static hj_cli_opt *find_opt(hj_cli_spec *spec, const char *name)
{
    for (int k = 0; k < spec->nopts; k++)
        if (!strcmp(spec->opts[k].name, name)) return &spec->opts[k];
    return NULL;
}

static int parse_value(hj_cli_opt *o, const char *v, hj_error *err)
{
    switch (o->type) {
    case HJ_OPT_LONG:
        return hj_parse_long(v, o->name, (long)o->min, (long)o->max, (long *)o->value, err);
    case HJ_OPT_DOUBLE:
        return hj_parse_double(v, o->name, o->min, o->max, (double *)o->value, err);
    case HJ_OPT_STRING:
        if (v[0] == '\0') return hj_error_set(err, HJ_EINVAL, "%s needs a non-empty value", o->name);
        *(const char **)o->value = v;
        return HJ_OK;
    case HJ_OPT_LONG_LIST:
        return hj_parse_long_list(v, o->name, (long)o->min, (long)o->max, (long *)o->value, o->maxn, o->count, err);
    case HJ_OPT_STRING_LIST:
        if (v[0] == '\0') return hj_error_set(err, HJ_EINVAL, "%s needs a non-empty value", o->name);
        if (*o->count >= o->maxn) return hj_error_set(err, HJ_EINVAL, "%s is given more than %d times", o->name, o->maxn);
        ((const char **)o->value)[(*o->count)++] = v;
        return HJ_OK;
    case HJ_OPT_CHOICE:
        for (int c = 0; o->choices[c]; c++)
            if (!strcmp(o->choices[c], v)) {
                *(int *)o->value = c;
                return HJ_OK;
            }
        {
            char list[512] = "";
            for (int c = 0; o->choices[c]; c++) {
                size_t n = strlen(list);
                snprintf(list + n, sizeof list - n, "%s%s", c ? ", " : "", o->choices[c]);
            }
            return hj_error_set(err, HJ_EINVAL, "%s: '%s' is not one of %s", o->name, v, list);
        }
    case HJ_OPT_FLAG:
        break;
    }
    return hj_error_set(err, HJ_EINVAL, "%s: unknown option type", o->name);
}

int hj_cli_parse(hj_cli_spec *spec, int argc, char **argv, int *help, hj_error *err)
{
    *help = 0;
    for (int k = 0; k < spec->nopts; k++) spec->opts[k].seen = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--help") || !strcmp(a, "--list-options")) {
            *help = strcmp(a, "--help") ? HJ_CLI_LIST : HJ_CLI_HELP;
            return HJ_OK;
        }
        hj_cli_opt *o = find_opt(spec, a);
        if (!o) {
            if (a[0] == '-' && a[1] == '-')
                return hj_error_set(err, HJ_EINVAL, "unknown option '%.200s' (see %s --help)", a, spec->prog);
            return hj_error_set(err, HJ_EINVAL, "unexpected argument '%.200s' (see %s --help)", a, spec->prog);
        }
        if (o->seen && o->type != HJ_OPT_STRING_LIST) return hj_error_set(err, HJ_EINVAL, "%s is given twice", o->name);
        /* The first occurrence of a list replaces its default values. */
        if (!o->seen && o->type == HJ_OPT_STRING_LIST) *o->count = 0;
        o->seen = 1;
        if (o->type == HJ_OPT_FLAG) {
            *(int *)o->value = 1;
            continue;
        }
        if (i + 1 >= argc) return hj_error_set(err, HJ_EINVAL, "%s needs a value", o->name);
        int rc = parse_value(o, argv[++i], err);
        if (rc) return rc;
    }
    return HJ_OK;
}

void hj_cli_help(const hj_cli_spec *spec, FILE *out)
{
    fprintf(out, "usage: %s [options]\n%s\n\noptions:\n", spec->prog, spec->summary);
    for (int k = 0; k < spec->nopts; k++) {
        const hj_cli_opt *o = &spec->opts[k];
        char head[128], range[256] = "", dflt[256] = "";
        snprintf(head, sizeof head, "%s%s%s", o->name, o->metavar ? " " : "", o->metavar ? o->metavar : "");
        switch (o->type) {
        case HJ_OPT_LONG:
            snprintf(range, sizeof range, " [%ld..%ld]", (long)o->min, (long)o->max);
            snprintf(dflt, sizeof dflt, " (default %ld)", *(const long *)o->value);
            break;
        case HJ_OPT_DOUBLE:
            snprintf(range, sizeof range, " [%g..%g]", o->min, o->max);
            snprintf(dflt, sizeof dflt, " (default %g)", *(const double *)o->value);
            break;
        case HJ_OPT_STRING:
            if (*(const char *const *)o->value) snprintf(dflt, sizeof dflt, " (default %s)", *(const char *const *)o->value);
            break;
        case HJ_OPT_LONG_LIST:
            snprintf(range, sizeof range, " [%ld..%ld, at most %d]", (long)o->min, (long)o->max, o->maxn);
            if (o->count && *o->count > 0) {
                size_t n = (size_t)snprintf(dflt, sizeof dflt, " (default ");
                for (int c = 0; c < *o->count && n < sizeof dflt; c++)
                    n += (size_t)snprintf(dflt + n, sizeof dflt - n, "%s%ld", c ? "," : "", ((const long *)o->value)[c]);
                if (n < sizeof dflt) snprintf(dflt + n, sizeof dflt - n, ")");
            }
            break;
        case HJ_OPT_STRING_LIST:
            snprintf(range, sizeof range, " [repeatable, at most %d]", o->maxn);
            if (*o->count > 0) {
                size_t n = (size_t)snprintf(dflt, sizeof dflt, " (default");
                for (int c = 0; c < *o->count && n < sizeof dflt; c++)
                    n += (size_t)snprintf(dflt + n, sizeof dflt - n, " %s", ((const char *const *)o->value)[c]);
                if (n < sizeof dflt) snprintf(dflt + n, sizeof dflt - n, ")");
            }
            break;
        case HJ_OPT_CHOICE: {
            size_t n = (size_t)snprintf(range, sizeof range, " {");
            for (int c = 0; o->choices[c] && n < sizeof range; c++)
                n += (size_t)snprintf(range + n, sizeof range - n, "%s%s", c ? "|" : "", o->choices[c]);
            if (n < sizeof range) snprintf(range + n, sizeof range - n, "}");
            snprintf(dflt, sizeof dflt, " (default %s)", o->choices[*(const int *)o->value]);
            break;
        }
        case HJ_OPT_FLAG:
            break;
        }
        if (o->dflt) snprintf(dflt, sizeof dflt, " (default %s)", o->dflt);
        fprintf(out, "  %-22s %s%s%s\n", head, o->help ? o->help : "", range, dflt);
    }
    fprintf(out, "  %-22s %s\n", "--help", "this text");
    if (spec->epilog) fputs(spec->epilog, out);
}

/* The type's word in hj_cli_list; a type without one is listed as
 * "other", which a driver tests only for unknown and missing values. */
static const char *type_word(hj_opt_type t)
{
    switch (t) {
    case HJ_OPT_FLAG: return "flag";
    case HJ_OPT_LONG: return "long";
    case HJ_OPT_DOUBLE: return "double";
    case HJ_OPT_STRING: return "string";
    case HJ_OPT_LONG_LIST: return "long-list";
    case HJ_OPT_CHOICE: return "choice";
    case HJ_OPT_STRING_LIST: return "string-list";
    default: return "other";
    }
}

void hj_cli_list(const hj_cli_spec *spec, FILE *out)
{
    fputs("name\ttype\tmin\tmax\tchoices\tmaxn\n", out);
    for (int k = 0; k < spec->nopts; k++) {
        const hj_cli_opt *o = &spec->opts[k];
        fprintf(out, "%s\t%s\t", o->name, type_word(o->type));
        /* Bounds as the parser compares them: longs truncated, doubles
         * to all 17 digits. */
        if (o->type == HJ_OPT_LONG || o->type == HJ_OPT_LONG_LIST)
            fprintf(out, "%ld\t%ld\t", (long)o->min, (long)o->max);
        else if (o->type == HJ_OPT_DOUBLE)
            fprintf(out, "%.17g\t%.17g\t", o->min, o->max);
        else
            fputs("-\t-\t", out);
        if (o->type == HJ_OPT_CHOICE && o->choices)
            for (int c = 0; o->choices[c]; c++) fprintf(out, "%s%s", c ? "," : "", o->choices[c]);
        else
            fputs("-", out);
        if (o->type == HJ_OPT_LONG_LIST || o->type == HJ_OPT_STRING_LIST) fprintf(out, "\t%d\n", o->maxn);
        else fputs("\t-\n", out);
    }
}

/* The program's name for the check of stdout at exit, and whether the
 * program already failed with its own message (then nothing is added). */
static const char *stdout_prog;
static int failing;

void hj_cli_flush_stdout(const char *prog)
{
    errno = 0;
    /* glibc keeps the bytes a failed write could not take, so this flush
     * fails again and errno gives the reason of the first failure */
    const int flush_failed = fflush(stdout) != 0;
    if (!flush_failed && !ferror(stdout)) return;
    failing = 1;
    if (flush_failed && errno) fprintf(stderr, "%s: error writing stdout: %s\n", prog, strerror(errno));
    else fprintf(stderr, "%s: error writing stdout\n", prog);
    hj_out_remove_all();
    _exit(HJ_EXIT_RUN);
}

/* At exit: what went to stdout (--help, tables) is only buffered until
 * now, so a full disk or a closed pipe shows here.  A write error is then
 * one message and exit status HJ_EXIT_RUN instead of a silent 0. */
static void check_stdout(void)
{
    if (failing) return;
    hj_cli_flush_stdout(stdout_prog);
}

void hj_cli_check_stdout(const char *prog)
{
    if (!stdout_prog) atexit(check_stdout);
    stdout_prog = prog;
}

void hj_cli_parse_or_exit(hj_cli_spec *spec, int argc, char **argv)
{
    hj_error err;
    int help = 0;
    hj_cli_check_stdout(spec->prog);
    if (hj_cli_parse(spec, argc, argv, &help, &err)) hj_cli_fail(spec->prog, HJ_EXIT_USAGE, "%s", err.msg);
    if (help) {
        if (help == HJ_CLI_LIST) hj_cli_list(spec, stdout);
        else hj_cli_help(spec, stdout);
        exit(0);
    }
    hj_out_remove_on_signal();
}

void hj_cli_fail(const char *prog, int exit_code, const char *fmt, ...)
{
    /* The message may quote what the user typed: control bytes are
     * escaped, so that it stays one line and cannot drive the terminal. */
    char msg[2048];
    failing = 1;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    fprintf(stderr, "%s: ", prog);
    for (const unsigned char *p = (const unsigned char *)msg; *p; p++) {
        if (*p == '\n') fputs("\\n", stderr);
        else if (*p < 0x20 || *p == 0x7f) fprintf(stderr, "\\x%02x", *p);
        else fputc(*p, stderr);
    }
    fputc('\n', stderr);
    /* outputs still being written belong to the failed run */
    hj_out_remove_all();
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
