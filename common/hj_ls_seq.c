/* hj_ls_seq.c -- output times and time sequences; see hj_ls_seq.h. */
#include "hj_ls_seq.h"

#include <string.h>

#include "hj_io.h"
#include "hj_ls_io.h"

void hj_ls_seq_times(double t0, double t1, int n, double *tspan)
{
    for (int k = 0; k < n; k++) tspan[k] = k == n - 1 ? t1 : t0 + (t1 - t0) * (double)k / (double)(n - 1);
}

void hj_ls_seq_init(hj_ls_seq *s, FILE *fp, const hj_ls_grid *g, const char *name, int digits)
{
    memset(s, 0, sizeof *s);
    s->fp = fp;
    s->g = g;
    s->name = name;
    s->digits = digits;
}

int hj_ls_seq_write(hj_ls_seq *s, double t, const double *y, hj_error *err)
{
    if (!s->fp) return HJ_OK;
    char timed[128];
    const char *names[1 + HJ_LS_SEQ_MAXEXTRA] = {s->name};
    const double *fields[1 + HJ_LS_SEQ_MAXEXTRA] = {y};
    for (int e = 0; e < s->nextra; e++) names[1 + e] = s->extra_name[e], fields[1 + e] = s->extra[e];
    if (s->blocks) fputs("\n\n", s->fp);
    if (s->digits > 0) {
        fprintf(s->fp, "# t = %.*g\n", s->digits, t);
    } else {
        snprintf(timed, sizeof timed, "%s(t=%.6g)", s->name, t);
        names[0] = timed;
    }
    s->blocks++;
    return hj_ls_write_block(s->fp, s->g, 1 + s->nextra, names, fields, err);
}

int hj_ls_seq_output(int k, double t, const double *y, void *ctx, hj_error *err)
{
    hj_ls_seq *s = ctx;
    int rc = hj_ls_seq_write(s, t, y, err);
    if (rc) return rc;
    if (s->flag && !*s->flag && t >= s->t_switch) *s->flag = 1;
    return s->hook ? s->hook(k, t, y, s->hook_ctx, err) : HJ_OK;
}

int hj_ls_seq_solve(int order, const hj_ls_grid *g, const hj_ls_term *term, const double *tspan, int n, double *y,
                    const hj_ls_ode_opts *opts, hj_ls_seq *s, hj_ls_ode_stats *stats, hj_error *err)
{
    int rc = hj_ls_seq_output(0, tspan[0], y, s, err);
    if (rc) return rc;
    return hj_ls_ode(order, g, term, tspan, n, y, opts, hj_ls_seq_output, s, stats, err);
}

int hj_ls_seq_solve_file(const char *path, int order, const hj_ls_grid *g, const hj_ls_term *term, const double *tspan,
                         int n, double *y, const hj_ls_ode_opts *opts, hj_ls_seq *s, hj_ls_ode_stats *stats,
                         hj_error *err)
{
    if (!path) return hj_ls_seq_solve(order, g, term, tspan, n, y, opts, s, stats, err);
    hj_out out;
    int rc = hj_out_open(&out, path, err);
    if (rc) return rc;
    s->fp = out.fp;
    rc = hj_ls_seq_solve(order, g, term, tspan, n, y, opts, s, stats, err);
    s->fp = NULL;
    if (rc) {
        hj_out_abort(&out);
        return rc;
    }
    return hj_out_commit(&out, err);
}
