/* p3_prog.c -- shared command line and output helpers (see p3_prog.h). */
#include "p3_prog.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "hj_cli.h"

void p3_args_parse(p3_args *a, int argc, char **argv, const char *summary, const char *extra)
{
    hj_error err;
    a->out_dir = ".";
    a->quick = 0;
    a->nsizes = 0;
    a->max_n = 0;
    a->ntables = 0;
    for (int i = 1; i < argc; i++) {
        const char *o = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(o, "--help")) {
            printf("Usage: %s [options]\n%s\n"
                   "  --quick           reduced sizes (CI)\n"
                   "  --out-dir DIR     where to write the tables (default .)\n"
                   "  --sizes N,N,...   the grid sizes to run instead of the published ones\n"
                   "  --max-n N         skip the sizes above N\n"
                   "  --tables T,T,...  only these tables (numbers, e.g. 2,3)\n"
                   "  --help            this text\n%s",
                   a->prog, summary, extra ? extra : "");
            exit(0);
        }
        if (!strcmp(o, "--quick")) { a->quick = 1; continue; }
        if (strncmp(o, "--", 2)) hj_cli_fail(a->prog, HJ_EXIT_USAGE, "unexpected argument '%s' (see --help)", o);
        if (strcmp(o, "--out-dir") && strcmp(o, "--sizes") && strcmp(o, "--max-n") && strcmp(o, "--tables"))
            hj_cli_fail(a->prog, HJ_EXIT_USAGE, "unknown option '%s' (see --help)", o);
        if (!v) hj_cli_fail(a->prog, HJ_EXIT_USAGE, "option %s needs a value (see --help)", o);
        i++;
        int rc = HJ_OK;
        if (!strcmp(o, "--out-dir")) a->out_dir = v;
        else if (!strcmp(o, "--sizes")) rc = hj_parse_long_list(v, "--sizes", 3, 100000, a->sizes, P3_MAX_SIZES, &a->nsizes, &err);
        else if (!strcmp(o, "--tables")) rc = hj_parse_long_list(v, "--tables", 1, 13, a->tables, P3_MAX_SIZES, &a->ntables, &err);
        else rc = hj_parse_long(v, "--max-n", 3, 100000, &a->max_n, &err);
        if (rc) hj_cli_fail(a->prog, HJ_EXIT_USAGE, "%s", err.msg);
    }
}

int p3_want(const p3_args *a, long t)
{
    if (a->ntables == 0) return 1;
    for (int i = 0; i < a->ntables; i++)
        if (a->tables[i] == t) return 1;
    return 0;
}

_Noreturn void p3_die(const char *prog, const hj_error *err) { hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err->msg); }

int p3_open(hj_out *out, const char *dir, const char *name, hj_error *err)
{
    int rc = hj_mkdirs(dir, err);
    if (rc) return rc;
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    return hj_out_open(out, path, err);
}

const char *p3_num(char *buf, double v)
{
    if (isnan(v)) strcpy(buf, "-");
    else snprintf(buf, 32, "%.4g", v);
    return buf;
}

int p3_fig_block(FILE *fp, int d, int n, double lo, double dx, const int *i0, const int *m, int nf,
                 const double *const *f, hj_error *err)
{
    int64_t total = 1;
    for (int k = 0; k < d; k++) total *= m[k];
    for (int64_t q = 0; q < total; q++) {
        int idx[4];
        int64_t r = q, lin = 0;
        for (int k = d - 1; k >= 0; k--) { idx[k] = i0[k] + (int)(r % m[k]); r /= m[k]; }
        for (int k = 0; k < d; k++) {
            lin = lin * n + idx[k];
            fprintf(fp, "%s%.6g", k ? " " : "", lo + idx[k] * dx);
        }
        for (int j = 0; j < nf; j++) fprintf(fp, " %.6g", f[j][lin]);
        fputc('\n', fp);
        if ((idx[d - 1] - i0[d - 1]) == m[d - 1] - 1) fputc('\n', fp);
    }
    fputs("\n", fp);
    if (ferror(fp)) return hj_error_set(err, HJ_EIO, "write error (figure data)");
    return HJ_OK;
}
