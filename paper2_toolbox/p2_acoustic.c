/* p2_acoustic.c -- see p2_acoustic.h. */
#include "p2_acoustic.h"

#include <math.h>
#include <stdlib.h>

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

static double speed_bound(const p2_acoustic_par *q, double x, double y)
{
    const double r = sqrt(x * x + y * y);
    return 2 * q->We * (r < q->S ? r : q->S);
}

/* Time-independent coefficients, computed once: x of node i as
 * (i - (N - 1)/2) dx (exactly antisymmetric under i -> N - 1 - i, unlike
 * min + i dx) and the evader's speed bound e(x, y) at every node. */
typedef struct {
    const p2_acoustic_par *q;
    double *xs; /* per i */
    double *e;  /* on the grid */
} cb_ctx;

/* hamFunc: minus the Hamiltonian of section 2.6.2 (terminal to initial
 * value), one row per call. */
static void ham_row(double t, const hj_ls_row_info *row, const double *phi, const double *const *p, double *Hr,
                    void *ctx)
{
    (void)t, (void)phi;
    const cb_ctx *c = ctx;
    const double Wp = c->q->Wp, R = c->q->R, y = row->x[1];
    const double *xs = c->xs, *e = c->e + row->k, *p0 = p[0], *p1 = p[1];
    for (long j = 0; j < row->n; j++) {
        const double H = -p1[j] * Wp - Wp / R * fabs(p0[j] * y - p1[j] * xs[j]) + sqrt(p0[j] * p0[j] + p1[j] * p1[j]) * e[j];
        Hr[j] = -H;
    }
}

static void partial_row(double t, const hj_ls_row_info *row, const double *const *pmin, const double *const *pmax,
                        int d, double *alpha, void *ctx)
{
    (void)t, (void)pmin, (void)pmax;
    const cb_ctx *c = ctx;
    const double Wp = c->q->Wp, R = c->q->R, y = row->x[1];
    const double *xs = c->xs, *e = c->e + row->k;
    if (d == 0)
        for (long j = 0; j < row->n; j++) alpha[j] = Wp / R * fabs(y) + e[j];
    else
        for (long j = 0; j < row->n; j++) alpha[j] = Wp + Wp / R * fabs(xs[j]) + e[j];
}

int p2_acoustic_solve(const hj_ls_grid *g, const p2_acoustic_par *p, int acc, int diss, const double *ts, int nt,
                      double *phi, hj_ls_output_fn out, void *out_ctx, hj_ls_ode_stats *stats, hj_error *err)
{
    cb_ctx c = {p, malloc(sizeof(double) * (size_t)g->N[0]), hj_ls_alloc(g)};
    if (!c.xs || !c.e) {
        free(c.xs), hj_ls_free(c.e);
        return hj_error_set(err, HJ_ENOMEM, "acoustic: out of memory");
    }
    for (long i = 0; i < g->N[0]; i++) c.xs[i] = ((double)i - 0.5 * (double)(g->N[0] - 1)) * g->dx[0];
    for (long j = 0; j < g->N[1]; j++) {
        const double y = g->min[1] + (double)j * g->dx[1];
        const size_t k = hj_ls_index(g, (long[2]){0, j});
        for (long i = 0; i < g->N[0]; i++) c.e[k + (size_t)i] = speed_bound(p, c.xs[i], y);
    }
    hj_ls_lax_friedrichs lf;
    hj_ls_lax_friedrichs_init(&lf, g, hj_ls_accuracy_scheme(acc), diss, NULL, NULL, &c);
    lf.ham_row = ham_row;
    lf.partial_row = partial_row;
    lf.cfl_rule = p->cfl_rule;
    lf.weno_eps = p->weno_eps;
    lf.range_free = 1; /* partial_row never reads the gradient box */
    int rc = p2_reach_solve(hj_ls_accuracy_order(acc), g, &lf.base, ts, nt, phi, out, out_ctx, stats, err);
    free(c.xs);
    hj_ls_free(c.e);
    return rc;
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
