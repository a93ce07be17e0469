/* p2_air3d.c -- see p2_air3d.h. */
#include "p2_air3d.h"

#include <math.h>
#include <stdlib.h>

#include "hj_ls_term.h"
#include "hj_ls_accuracy.h"
#include "hj_math.h"
#include "p2_reach.h"


void p2_air3d_defaults(p2_air3d_par *p)
{
    p->r = 5, p->va = 5, p->vb = 5, p->A = 1, p->B = 1;
    p->cfl_rule = HJ_LS_CFL_NODE;
    p->weno_eps = HJ_LS_WENO_EPS_LOCAL;
}

int p2_air3d_grid(long Nx, hj_ls_grid *g, hj_error *err)
{
    const long N[3] = {Nx, (long)ceil((double)Nx * 20.0 / 26.0), Nx - 1};
    const double lo[3] = {-6, -10, 0}, hi[3] = {20, 10, 2 * HJ_PI * (1 - 1.0 / (double)N[2])};
    const hj_ls_bc bc[3] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_PERIODIC, 0, 0}};
    return hj_ls_grid_init(g, 3, lo, hi, N, bc, err);
}

/* sqrt(x^2 + y^2) - r with y_j = (j - (N_y - 1) / 2) dy, exactly
 * antisymmetric under j -> N_y - 1 - j (hj_ls_shape_cylinder's
 * coordinates min + j dy are so only to round-off, which seeds an
 * asymmetry that the ENO stencil choices can amplify). */
int p2_air3d_target(const hj_ls_grid *g, const p2_air3d_par *p, double *phi, hj_error *err)
{
    return p2_air3d_target_block(g, g, p, phi, err);
}

int p2_air3d_target_block(const hj_ls_grid *global, const hj_ls_grid *g, const p2_air3d_par *p, double *phi,
                          hj_error *err)
{
    if (g->dim != 3 || p->r <= 0) return hj_error_set(err, HJ_EINVAL, "air3D target: a 3-D grid and r > 0 are needed");
    for (size_t r = 0; r < g->rows; r++) {
        long i[3] = {0, 0, 0};
        const size_t k = hj_ls_row(g, r, i);
        const double y = ((double)(i[1] + g->origin[1]) - 0.5 * (double)(global->N[1] - 1)) * g->dx[1];
        for (long a = 0; a < g->N[0]; a++) {
            const double x = g->min[0] + (double)a * g->dx[0];
            phi[k + (size_t)a] = sqrt(x * x + y * y) - p->r;
        }
    }
    return HJ_OK;
}

/* AVX-512 and AVX2 clones of the callbacks where the CPU has them, as the
 * kernel's row loops (-std=c11 contracts no multiply-add: the same bits). */
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__SANITIZE_ADDRESS__) && !defined(__clang__)
#define CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define CLONES
#endif

/* The callbacks read cos psi, sin psi and y by node index (time
 * independent: computed once, in p2_air3d_solve), from tables built
 * mirror-symmetric (cos(-psi) = cos psi, sin(-psi) = -sin psi,
 * y_{N-1-j} = -y_j exactly), so that the reflection symmetry of the game
 * is not broken by the rounding of the coordinates.  One call per row of
 * x: the loops vectorise. */
typedef struct {
    const p2_air3d_par *q;
    double *cs, *sn, *ys, *xs; /* xs[j] = min[0] + j dx[0]: no int-to-double conversion per node */
    double *axs;               /* A |xs[j]|, alpha_2's term in x (time independent) */
} cb_ctx;

/* The loops of the callbacks, every array a restrict argument: so gcc
 * vectorises them without checking at run time whether they overlap. */
static inline __attribute__((always_inline)) void ham_loop(long n, double cs, double sn, double y, double va,
                                                          double vb, double A, double B, const double *restrict xs,
                                                          const double *restrict p0, const double *restrict p1,
                                                          const double *restrict p2, double *restrict Hr)
{
#define HAM(j0, j1)                                                                                                \
    for (long j = (j0); j < (j1); j++) {                                                                           \
        const double x = xs[j];                                                                                    \
        const double h = -va * p0[j] + vb * (cs * p0[j] + sn * p1[j]) + A * fabs(y * p0[j] - x * p1[j] - p2[j]) - \
                         B * fabs(p2[j]);                                                                          \
        Hr[j] = -h;                                                                                                \
    }
    HJ_LS_ROW_BLOCKS8(n, HAM);
#undef HAM
}

CLONES
static void ham_row(double t, const hj_ls_row_info *row, const double *phi, const double *const *p, double *H,
                    void *ctx)
{
    (void)t, (void)phi;
    const cb_ctx *c = ctx;
    const p2_air3d_par *q = c->q;
    ham_loop(row->n, c->cs[row->idx[2]], c->sn[row->idx[2]], c->ys[row->idx[1]], q->va, q->vb, q->A, q->B, c->xs,
             p[0], p[1], p[2], H);
}

static inline __attribute__((always_inline)) void partial1_loop(long n, double s, const double *restrict axs,
                                                               double *restrict al)
{
#define PARTIAL(j0, j1) \
    for (long j = (j0); j < (j1); j++) al[j] = s + axs[j];
    HJ_LS_ROW_BLOCKS8(n, PARTIAL);
#undef PARTIAL
}

CLONES
static void partial_row(double t, const hj_ls_row_info *row, const double *const *pmin, const double *const *pmax,
                        int d, double *alpha, void *ctx)
{
    (void)t, (void)pmin, (void)pmax;
    const cb_ctx *c = ctx;
    const p2_air3d_par *q = c->q;
    const long n = row->n;
    if (d == 1) {
        partial1_loop(n, fabs(q->vb * c->sn[row->idx[2]]), c->axs, alpha);
        return;
    }
    /* constant along the row (row_const): node 0's alone is read */
    alpha[0] = d == 0 ? fabs(-q->va + q->vb * c->cs[row->idx[2]]) + q->A * fabs(c->ys[row->idx[1]]) : q->A + q->B;
}

/* ham_loop and partial1_loop in one loop: each node's H and alpha_2 (the
 * same expressions, the same bits), alpha_1 and alpha_3 at node 0. */
static inline __attribute__((always_inline)) void ham_partial_loop(long n, double cs, double sn, double y,
                                                                  double va, double vb, double A, double B,
                                                                  double s, const double *restrict xs,
                                                                  const double *restrict axs,
                                                                  const double *restrict p0,
                                                                  const double *restrict p1,
                                                                  const double *restrict p2, double *restrict Hr,
                                                                  double *restrict al)
{
#define HAM_PARTIAL(j0, j1)                                                                                        \
    for (long j = (j0); j < (j1); j++) {                                                                           \
        const double x = xs[j];                                                                                    \
        const double h = -va * p0[j] + vb * (cs * p0[j] + sn * p1[j]) + A * fabs(y * p0[j] - x * p1[j] - p2[j]) - \
                         B * fabs(p2[j]);                                                                          \
        Hr[j] = -h;                                                                                                \
        al[j] = s + axs[j];                                                                                        \
    }
    HJ_LS_ROW_BLOCKS8(n, HAM_PARTIAL);
#undef HAM_PARTIAL
}

CLONES
static void ham_partial_row(double t, const hj_ls_row_info *row, const double *phi, const double *const *p,
                            const double *const *pmin, const double *const *pmax, double *H, double *const *alpha,
                            void *ctx)
{
    (void)t, (void)phi, (void)pmin, (void)pmax;
    const cb_ctx *c = ctx;
    const p2_air3d_par *q = c->q;
    const double cs = c->cs[row->idx[2]], sn = c->sn[row->idx[2]], y = c->ys[row->idx[1]];
    ham_partial_loop(row->n, cs, sn, y, q->va, q->vb, q->A, q->B, fabs(q->vb * sn), c->xs, c->axs, p[0], p[1], p[2],
                     H, alpha[1]);
    /* constant along the row (row_const): node 0's alone is read */
    alpha[0][0] = fabs(-q->va + q->vb * cs) + q->A * fabs(y);
    alpha[2][0] = q->A + q->B;
}

int p2_air3d_solve(const hj_ls_grid *g, const p2_air3d_par *p, int acc, int diss, const double *ts, int nt,
                   double *phi, hj_ls_output_fn out, void *out_ctx, hj_ls_ode_stats *stats, hj_error *err)
{
    return p2_air3d_solve_block(g, g, p, acc, diss, ts, nt, phi, out, out_ctx, stats, err);
}

int p2_air3d_solve_block(const hj_ls_grid *global, const hj_ls_grid *g, const p2_air3d_par *p, int acc, int diss,
                         const double *ts, int nt, double *phi, hj_ls_output_fn out, void *out_ctx,
                         hj_ls_ode_stats *stats, hj_error *err)
{
    cb_ctx c = {p, NULL, NULL, NULL, NULL, NULL};
    const long n3 = global->N[2], n2 = global->N[1], n1 = g->N[0];
    double *tab = malloc(sizeof(double) * (size_t)(2 * n3 + n2 + 2 * n1));
    if (!tab) return hj_error_set(err, HJ_ENOMEM, "air3D: out of memory");
    double *cs = tab, *sn = cs + n3, *ys = sn + n3, *xs = ys + n2, *axs = xs + n1;
    {
        /* the bits of row->x[0] + j dx0, row->x[0] as hj_ls_coord has it */
        const long i0[3] = {0, 0, 0};
        double x0[3];
        hj_ls_coord(g, i0, x0);
        for (long j = 0; j < n1; j++) xs[j] = x0[0] + (double)j * g->dx[0], axs[j] = p->A * fabs(xs[j]);
    }
    for (long k = 0; k <= n3 / 2; k++) {
        const double a = 2 * HJ_PI * (double)k / (double)n3;
        cs[k] = cos(a), sn[k] = k == 0 || 2 * k == n3 ? 0.0 : sin(a);
        if (k) cs[n3 - k] = cs[k], sn[n3 - k] = -sn[k];
    }
    for (long j = 0; j < n2; j++) ys[j] = ((double)j - 0.5 * (double)(n2 - 1)) * g->dx[1];
    /* The callbacks index the tables by the block's node index. */
    c.cs = cs + g->origin[2], c.sn = sn + g->origin[2], c.ys = ys + g->origin[1], c.xs = xs, c.axs = axs;
    hj_ls_lax_friedrichs lf;
    hj_ls_lax_friedrichs_init(&lf, g, hj_ls_accuracy_scheme(acc), diss, NULL, NULL, &c);
    lf.ham_row = ham_row;
    lf.partial_row = partial_row;
    lf.ham_partial_row = ham_partial_row; /* GLF, LLLF: one loop for H and alpha_2 */
    lf.cfl_rule = p->cfl_rule;
    lf.weno_eps = p->weno_eps;
    lf.range_free = 1; /* partial_row reads the tables, never the gradient box */
    lf.row_const = 1u << 0 | 1u << 2; /* alpha_1 and alpha_3 depend on y and psi only */
    int rc = p2_reach_solve(hj_ls_accuracy_order(acc), g, &lf.base, ts, nt, phi, out, out_ctx, stats, err);
    free(tab);
    return rc;
}

double p2_air3d_asymmetry(const hj_ls_grid *g, const double *phi, long *flips)
{
    double m = 0;
    long f = 0;
    for (size_t r = 0; r < g->rows; r++) {
        long i[3] = {0, 0, 0};
        const size_t k = hj_ls_row(g, r, i);
        long j[3] = {0, g->N[1] - 1 - i[1], (g->N[2] - i[2]) % g->N[2]};
        const size_t kr = hj_ls_index(g, j);
        for (long a = 0; a < g->N[0]; a++) {
            const double e = fabs(phi[k + (size_t)a] - phi[kr + (size_t)a]);
            m = e > m ? e : m;
            f += (phi[k + (size_t)a] < 0) != (phi[kr + (size_t)a] < 0);
        }
    }
    if (flips) *flips = f;
    return m;
}
