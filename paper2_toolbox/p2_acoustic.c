/* p2_acoustic.c -- see p2_acoustic.h. */
#include "p2_acoustic.h"

#include <math.h>

#include "hj_ls_accuracy.h"
#include "hj_ls_term.h"
#include "p2_reach.h"

void p2_acoustic_defaults(p2_acoustic_par *p)
{
    p->We = 1.3, p->Wp = 1.5, p->R = 0.8, p->S = 0.5;
    p->cfl_rule = HJ_LS_CFL_NODE;
    p->weno_eps = HJ_LS_WENO_EPS_LOCAL;
}

int p2_acoustic_grid(double dx, hj_ls_grid *g, hj_error *err)
{
    const double lo[2] = {-4, -2}, hi[2] = {4, 3}, dxs[2] = {dx, dx};
    const hj_ls_bc bc[2] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
    return hj_ls_grid_init_dx(g, 2, lo, hi, dxs, bc, err);
}

int p2_acoustic_target(const hj_ls_grid *g, double *phi, hj_error *err)
{
    if (g->dim != 2) return hj_error_set(err, HJ_EINVAL, "acoustic target: a 2-D grid is needed");
    for (long j = 0; j < g->N[1]; j++)
        for (long i = 0; i < g->N[0]; i++) {
            const double x = ((double)i - 0.5 * (double)(g->N[0] - 1)) * g->dx[0], y = g->min[1] + (double)j * g->dx[1];
            const double a = fabs(x) - 3.5, b = fabs(y + 0.1) - 0.1;
            phi[hj_ls_index(g, (long[2]){i, j})] = a > b ? a : b;
        }
    return HJ_OK;
}

typedef struct {
    const p2_acoustic_par *q;
    const hj_ls_grid *g;
} cb_ctx;

/* x of the node nearest to x0 as (i - (N - 1)/2) dx: exactly antisymmetric
 * under i -> N - 1 - i, unlike min + i dx. */
static double xsym(const hj_ls_grid *g, double x0)
{
    const long i = lround((x0 - g->min[0]) / g->dx[0]);
    return ((double)i - 0.5 * (double)(g->N[0] - 1)) * g->dx[0];
}

static double speed_bound(const p2_acoustic_par *q, double x, double y)
{
    const double r = sqrt(x * x + y * y);
    return 2 * q->We * (r < q->S ? r : q->S);
}

/* hamFunc: minus the Hamiltonian of section 2.6.2 (terminal to initial value). */
static double ham(double t, const double *x, double phi, const double *p, void *ctx)
{
    (void)t, (void)phi;
    const cb_ctx *c = ctx;
    const p2_acoustic_par *q = c->q;
    const double xs = xsym(c->g, x[0]);
    const double H = -p[1] * q->Wp - q->Wp / q->R * fabs(p[0] * x[1] - p[1] * xs) +
                     sqrt(p[0] * p[0] + p[1] * p[1]) * speed_bound(q, xs, x[1]);
    return -H;
}

static double partial(double t, const double *x, const double *pmin, const double *pmax, int d, void *ctx)
{
    (void)t, (void)pmin, (void)pmax;
    const cb_ctx *c = ctx;
    const p2_acoustic_par *q = c->q;
    const double xs = xsym(c->g, x[0]), e = speed_bound(q, xs, x[1]);
    return d == 0 ? q->Wp / q->R * fabs(x[1]) + e : q->Wp + q->Wp / q->R * fabs(xs) + e;
}

int p2_acoustic_solve(const hj_ls_grid *g, const p2_acoustic_par *p, int acc, int diss, const double *ts, int nt,
                      double *phi, hj_ls_output_fn out, void *out_ctx, hj_ls_ode_stats *stats, hj_error *err)
{
    cb_ctx c = {p, g};
    hj_ls_lax_friedrichs lf;
    hj_ls_lax_friedrichs_init(&lf, g, hj_ls_accuracy_scheme(acc), diss, ham, partial, &c);
    lf.cfl_rule = p->cfl_rule;
    lf.weno_eps = p->weno_eps;
    return p2_reach_solve(hj_ls_accuracy_order(acc), g, &lf.base, ts, nt, phi, out, out_ctx, stats, err);
}

double p2_acoustic_asymmetry(const hj_ls_grid *g, const double *phi, long *flips)
{
    double m = 0;
    long f = 0;
    for (long j = 0; j < g->N[1]; j++)
        for (long i = 0; i < g->N[0]; i++) {
            const double a = phi[hj_ls_index(g, (long[2]){i, j})], b = phi[hj_ls_index(g, (long[2]){g->N[0] - 1 - i, j})];
            const double e = fabs(a - b);
            m = e > m ? e : m;
            f += (a < 0) != (b < 0);
        }
    if (flips) *flips = f;
    return m;
}
