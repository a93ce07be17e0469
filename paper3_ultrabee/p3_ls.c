/* p3_ls.c -- the level set runs of section 4 on the common kernel (p3_ls.h). */
#include "p3_ls.h"

#include <math.h>
#include <string.h>

#include "hj_ls_ode.h"

int p3_ls_init(p3_ls *ls, int d, int n, const double *lo, const double *hi, hj_ls_field_fn phi0, void *ctx,
               hj_error *err)
{
    memset(ls, 0, sizeof *ls);
    long N[HJ_LS_MAXDIM];
    hj_ls_bc bc[HJ_LS_MAXDIM];
    for (int k = 0; k < d; k++) {
        N[k] = n;
        bc[k] = (hj_ls_bc){HJ_LS_BC_EXTRAP_AWAY, 0, 0};
    }
    int rc = hj_ls_grid_init(&ls->g, d, lo, hi, N, bc, err);
    if (rc) return rc;
    if (!(ls->y = hj_ls_alloc(&ls->g))) return hj_error_set(err, HJ_ENOMEM, "out of memory (level set, %d^%d)", n, d);
    hj_ls_fill(&ls->g, ls->y, phi0, ctx);
    ls->d = d;
    ls->n = n;
    ls->lost_t = NAN;
    return HJ_OK;
}

void p3_ls_free(p3_ls *ls)
{
    hj_ls_free(ls->y);
    ls->y = NULL;
}

/* After every step: note when the computed set {V <= 0} first vanishes. */
static int watch_front(double t, double *y, void *ctx, hj_error *err)
{
    (void)err;
    p3_ls *ls = ctx;
    if (!isnan(ls->lost_t)) return HJ_OK;
    const hj_ls_grid *g = &ls->g;
    for (size_t r = 0; r < g->rows; r++) {
        long idx[HJ_LS_MAXDIM];
        const size_t k = hj_ls_row(g, r, idx);
        for (long j = 0; j < g->N[0]; j++)
            if (y[k + (size_t)j] <= 0) return HJ_OK;
    }
    ls->lost_t = t;
    return HJ_OK;
}

int p3_ls_run(p3_ls *ls, const hj_ls_term *term, double t1, double cfl, hj_error *err)
{
    if (!(cfl > 0) || !(cfl <= 1)) return hj_error_set(err, HJ_EINVAL, "level set: bad CFL number %g", cfl);
    if (t1 <= ls->t) return HJ_OK;
    hj_ls_ode_opts o;
    hj_ls_ode_defaults(&o);
    o.factor_cfl = cfl; /* dt sum_d max |f_d| / dx_d = cfl (p3_ls.h) */
    o.post = watch_front;
    o.post_ctx = ls;
    const double span[2] = {ls->t, t1};
    hj_ls_ode_stats st = {0};
    const int rc = hj_ls_ode(2, &ls->g, term, span, 2, ls->y, &o, NULL, NULL, &st, err);
    ls->steps += st.steps;
    ls->t = rc ? st.t : t1;
    return rc;
}

static double value_at(const int *idx, void *vctx)
{
    const p3_ls *ls = vctx;
    long i[HJ_LS_MAXDIM];
    for (int k = 0; k < ls->d; k++) i[k] = idx[k];
    return ls->y[hj_ls_index(&ls->g, i)];
}

void p3_ls_values(const p3_ls *ls, double *out)
{
    int idx[HJ_BAND_DMAX] = {0};
    int64_t total = 1;
    for (int k = 0; k < ls->d; k++) total *= ls->n;
    for (int64_t m = 0; m < total; m++) {
        int64_t r = m;
        for (int k = ls->d - 1; k >= 0; k--) { idx[k] = (int)(r % ls->n); r /= ls->n; }
        out[m] = value_at(idx, (void *)ls);
    }
}
