/* p2_reach.c -- see p2_reach.h. */
#include "p2_reach.h"

#include <string.h>

#include "hj_ls_accuracy.h"
#include "hj_ls_measure.h"

int p2_reach_log_init(p2_reach_log *log, const hj_ls_grid *g, int periodic_dim, double t0, const double *y0,
                      hj_ls_output_fn user, void *user_ctx, hj_error *err)
{
    memset(log, 0, sizeof *log);
    log->g = g;
    log->periodic_dim = periodic_dim;
    log->user = user;
    log->user_ctx = user_ctx;
    log->prev = hj_ls_alloc(g);
    if (!log->prev) return hj_error_set(err, HJ_ENOMEM, "reach log: out of memory");
    hj_ls_copy(g, log->prev, y0);
    log->t[0] = t0;
    log->increased[0] = 0;
    log->n = 1;
    int rc = hj_ls_measure_periodic(g, y0, periodic_dim, &log->measure[0], err);
    if (!rc && user) rc = user(0, t0, y0, user_ctx, err);
    return rc;
}

int p2_reach_output(int k, double t, const double *y, void *ctx, hj_error *err)
{
    p2_reach_log *log = ctx;
    if (log->n >= P2_MAXT) return hj_error_set(err, HJ_EINVAL, "reach log: more than %d output times", P2_MAXT);
    const int n = log->n;
    log->t[n] = t;
    log->increased[n] = hj_ls_count_increase(log->g, log->prev, y);
    int rc = hj_ls_measure_periodic(log->g, y, log->periodic_dim, &log->measure[n], err);
    if (rc) return rc;
    hj_ls_copy(log->g, log->prev, y);
    log->n = n + 1;
    return log->user ? log->user(k, t, y, log->user_ctx, err) : HJ_OK;
}

void p2_reach_log_free(p2_reach_log *log)
{
    hj_ls_free(log->prev);
    log->prev = NULL;
}

int p2_reach_solve(int order, const hj_ls_grid *g, const hj_ls_term *term, const double *ts, int nt, double *phi,
                   hj_ls_output_fn out, void *out_ctx, hj_ls_ode_stats *stats, hj_error *err)
{
    hj_ls_restrict rs;
    hj_ls_restrict_init(&rs, g, term, 0);
    hj_ls_ode_opts o;
    hj_ls_ode_defaults(&o);
    o.factor_cfl = HJ_LS_FACTOR_CFL_REACH;
    return hj_ls_ode(order, g, &rs.base, ts, nt, phi, &o, out, out_ctx, stats, err);
}
