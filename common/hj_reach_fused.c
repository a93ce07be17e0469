/* hj_reach_fused.c -- the fused first order path of hj_reach_solve.
 *
 * Upwind first order differences, forward Euler, the exact control-affine
 * Hamiltonian and its Lax-Friedrichs bounds, in one pass over each row of
 * dimension 0: the 2 dim one-sided differences, f and G (H) at the node,
 * the Hamiltonian, the dissipation and the time derivative, written
 * straight into the next state; then one streaming pass that takes the
 * Euler step and applies the target and obstacle (hj_reach.h).  The state
 * is two interior-sized arrays (no ghost layers): a neighbour across a
 * face of the grid is the value the kernel's ghost node would hold
 * (hj_ls_grid.h), made per row: by index for a periodic dimension, from
 * the boundary row and its inward neighbour otherwise.  The first order
 * stencil reaches only face ghosts, never corner ones, so these are all
 * the ghosts it reads.
 *
 * The arithmetic per node is that of the general path (hj_ls_upwind_row,
 * hj_ls_lax_friedrichs, hj_ls_ode's combine, hj_reach's post step), in the
 * same order, so both give the same bits: the partial bounds of a
 * control-affine system do not depend on the gradient, so the three
 * Lax-Friedrichs dissipations coincide.  Matrices declared constant
 * (G_const, H_const) are evaluated once and their zero entries skipped:
 * a product with an exact zero adds +-0, which changes no finite sum but
 * the sign of a zero, and these sums reach the result only through
 * fabs or through a sum that also holds a nonzero term.
 */
#include "hj_reach.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#define MATMAX (HJ_LS_MAXDIM * HJ_REACH_MAXIN)

/* One player's input set as the node loop uses it. */
typedef struct {
    int n;      /* inputs, 0: no player */
    int box;    /* 1 box, 0 ball */
    double sg;  /* -1 minimising, +1 maximising */
    double c[HJ_REACH_MAXIN], w[HJ_REACH_MAXIN], r;
    hj_reach_vec_fn fn; /* the matrix, when not constant */
    int cnst;
    double M[MATMAX]; /* the constant matrix */
    /* constant: q_j = sum over the nonzero M_ij (i increasing) of M_ij p_i */
    int nq[HJ_REACH_MAXIN], qi[HJ_REACH_MAXIN][HJ_LS_MAXDIM];
    double qm[HJ_REACH_MAXIN][HJ_LS_MAXDIM];
    /* constant: the nonzero products M_dj c_j added to f_d (j increasing) */
    int nf[HJ_LS_MAXDIM];
    double fc[HJ_LS_MAXDIM][HJ_REACH_MAXIN];
} player;

typedef struct {
    int nx;
    hj_reach_vec_fn f;
    void *ctx;
    player in[2];
    int b_const;              /* every matrix constant: b below is final */
    double b[HJ_LS_MAXDIM];   /* the input part of alpha_d */
} fused_dyn;

/* b[d] += the bound of player P's inputs on |dx_d/dt| (hj_reach.c's order). */
static void add_bounds(const player *P, int nx, const double *M, double *b)
{
    for (int d = 0; d < nx; d++) {
        double n2 = 0;
        for (int j = 0; j < P->n; j++) {
            const double m = M[d * P->n + j];
            if (P->box) b[d] += fabs(m) * P->w[j];
            else n2 += m * m;
        }
        if (!P->box) b[d] += P->r * sqrt(n2);
    }
}

static void fused_dyn_init(fused_dyn *F, const hj_reach_dyn *s, double t0)
{
    memset(F, 0, sizeof *F);
    F->nx = s->nx, F->f = s->f, F->ctx = s->ctx;
    const hj_reach_input *in[2] = {&s->u, &s->d};
    const hj_reach_vec_fn mf[2] = {s->G, s->H};
    const int cn[2] = {s->G_const, s->H_const};
    F->b_const = 1;
    for (int k = 0; k < 2; k++) {
        player *P = &F->in[k];
        P->n = in[k]->n;
        if (P->n == 0) continue;
        P->box = in[k]->shape == HJ_REACH_BOX;
        P->sg = in[k]->mode == HJ_REACH_MIN ? -1.0 : 1.0;
        for (int j = 0; j < P->n; j++) {
            if (P->box) {
                P->c[j] = 0.5 * (in[k]->lo[j] + in[k]->hi[j]);
                P->w[j] = 0.5 * (in[k]->hi[j] - in[k]->lo[j]);
            } else
                P->c[j] = in[k]->c[j], P->w[j] = 0;
        }
        P->r = in[k]->r;
        P->fn = mf[k];
        P->cnst = cn[k] != 0;
        F->b_const &= P->cnst;
        if (!P->cnst) continue;
        double x[HJ_LS_MAXDIM] = {0};
        mf[k](t0, x, P->M, s->ctx);
        for (int j = 0; j < P->n; j++)
            for (int i = 0; i < s->nx; i++) {
                const double m = P->M[i * P->n + j];
                if (m != 0) P->qi[j][P->nq[j]] = i, P->qm[j][P->nq[j]++] = m;
            }
        for (int d = 0; d < s->nx; d++)
            for (int j = 0; j < P->n; j++) {
                const double pc = P->M[d * P->n + j] * P->c[j];
                if (pc != 0) P->fc[d][P->nf[d]++] = pc;
            }
    }
    if (F->b_const)
        for (int k = 0; k < 2; k++)
            if (F->in[k].n) add_bounds(&F->in[k], s->nx, F->in[k].M, F->b);
}

/* -H(t, x, p) and alpha[0..nx-1]: hj_reach.c's node_ham_partials. */
static inline double node_ham(const fused_dyn *F, double t, const double *x, const double *p, double *alpha)
{
    const int nx = F->nx;
    double fx[HJ_LS_MAXDIM] = {0}, b[HJ_LS_MAXDIM] = {0}, h = 0, Mloc[MATMAX];
    if (F->f) {
        F->f(t, x, fx, F->ctx);
        for (int i = 0; i < nx; i++) h += p[i] * fx[i];
    }
    for (int k = 0; k < 2; k++) {
        const player *P = &F->in[k];
        const int n = P->n;
        if (n == 0) continue;
        double q[HJ_REACH_MAXIN];
        const double *M = P->M;
        if (P->cnst)
            for (int j = 0; j < n; j++) {
                double a = 0;
                for (int e = 0; e < P->nq[j]; e++) a += P->qm[j][e] * p[P->qi[j][e]];
                q[j] = a;
            }
        else {
            P->fn(t, x, Mloc, F->ctx);
            M = Mloc;
            for (int j = 0; j < n; j++) q[j] = 0;
            for (int i = 0; i < nx; i++)
                for (int j = 0; j < n; j++) q[j] += M[i * n + j] * p[i];
        }
        double val = 0;
        if (P->box)
            for (int j = 0; j < n; j++) {
                const double aq = fabs(q[j]);
                val += q[j] * P->c[j] + P->sg * aq * P->w[j];
            }
        else {
            double n2 = 0;
            for (int j = 0; j < n; j++) val += q[j] * P->c[j], n2 += q[j] * q[j];
            val += P->sg * P->r * sqrt(n2);
        }
        h += val;
        if (P->cnst)
            for (int d = 0; d < nx; d++)
                for (int e = 0; e < P->nf[d]; e++) fx[d] += P->fc[d][e];
        else
            for (int d = 0; d < nx; d++)
                for (int j = 0; j < n; j++) fx[d] += M[d * n + j] * P->c[j];
        if (!F->b_const) add_bounds(P, nx, M, b);
    }
    const double *bb = F->b_const ? F->b : b;
    for (int d = 0; d < nx; d++) alpha[d] = fabs(fx[d]) + bb[d];
    return -h;
}

/* The ghost node at distance 1 beyond the face: hj_ls_grid.c's fill_line
 * for k = 1, from the boundary value v and its inward neighbour w (the
 * opposite boundary value for a periodic dimension). */
static inline double ghost(const hj_ls_bc *bc, int hi, double v, double w, double dx)
{
    switch (bc->type) {
    case HJ_LS_BC_PERIODIC: return w;
    case HJ_LS_BC_DIRICHLET: return hi ? bc->hi : bc->lo;
    case HJ_LS_BC_NEUMANN: return v + (double)1 * dx * (hi ? bc->hi : bc->lo);
    default: {
        const double dir = bc->type == HJ_LS_BC_EXTRAP_AWAY ? 1.0 : -1.0;
        const double sv = v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0);
        return v + (double)1 * dir * sv * fabs(v - w);
    }
    }
}

typedef struct {
    const hj_reach_problem *pb;
    const fused_dyn *F;
    const hj_ls_grid *g;
    size_t cs[HJ_LS_MAXDIM]; /* strides of the interior-only layout */
    double T;
} fused;

/* Per thread: the row with its two ghosts along dimension 0, and the
 * ghost rows of the faces of the other dimensions. */
static size_t row_work(const hj_ls_grid *g) { return (size_t)g->N[0] + 2 + 2 * (size_t)g->dim * (size_t)g->N[0]; }

/* One row of ydot = -(H(x, (p+ + p-)/2) - sum_d alpha_d (p+_d - p-_d)/2)
 * into out; *inv = max_j sum_d alpha_d / dx_d; the first node with a
 * non-finite H or alpha in *bad (-1: none). */
static void row_ydot(const fused *fs, double tau, const double *y, size_t r, double *out, double *ws, double *inv,
                     long *bad)
{
    const hj_ls_grid *g = fs->g;
    const int dim = g->dim;
    const long n = g->N[0];
    long idx[HJ_LS_MAXDIM];
    double x[HJ_LS_MAXDIM], rx[HJ_LS_MAXDIM], idx_inv[HJ_LS_MAXDIM];
    hj_ls_row(g, r, idx);
    hj_ls_coord(g, idx, rx);
    memcpy(x, rx, sizeof x);
    const size_t k0 = r * (size_t)n;
    const double *row = y + k0;
    /* dimension 0: row with its ghosts, pad[j + 1] = node j */
    double *pad = ws, *gr = ws + n + 2;
    memcpy(pad + 1, row, sizeof(double) * (size_t)n);
    pad[0] = ghost(&g->bc[0], 0, row[0], g->bc[0].type == HJ_LS_BC_PERIODIC ? row[n - 1] : row[1], g->dx[0]);
    pad[n + 1] = ghost(&g->bc[0], 1, row[n - 1], g->bc[0].type == HJ_LS_BC_PERIODIC ? row[0] : row[n - 2], g->dx[0]);
    /* other dimensions: the neighbouring rows, or ghost rows at a face */
    const double *lo[HJ_LS_MAXDIM], *hi[HJ_LS_MAXDIM];
    for (int d = 0; d < dim; d++) idx_inv[d] = 1.0 / g->dx[d];
    for (int d = 1; d < dim; d++) {
        const size_t s = fs->cs[d], span = s * (size_t)(g->N[d] - 1);
        const int per = g->bc[d].type == HJ_LS_BC_PERIODIC;
        if (idx[d] > 0) lo[d] = row - s;
        else if (per) lo[d] = row + span;
        else {
            double *q = gr + (size_t)(2 * d) * (size_t)n;
            const double *in = row + s;
            for (long j = 0; j < n; j++) q[j] = ghost(&g->bc[d], 0, row[j], in[j], g->dx[d]);
            lo[d] = q;
        }
        if (idx[d] < g->N[d] - 1) hi[d] = row + s;
        else if (per) hi[d] = row - span;
        else {
            double *q = gr + (size_t)(2 * d + 1) * (size_t)n;
            const double *in = row - s;
            for (long j = 0; j < n; j++) q[j] = ghost(&g->bc[d], 1, row[j], in[j], g->dx[d]);
            hi[d] = q;
        }
    }
    const double t = fs->T - tau;
    double m = 0;
    long b = -1;
    for (long j = 0; j < n; j++) {
        double l[HJ_LS_MAXDIM], rr[HJ_LS_MAXDIM], p[HJ_LS_MAXDIM], alpha[HJ_LS_MAXDIM];
        const double v = row[j];
        l[0] = (v - pad[j]) * idx_inv[0];
        rr[0] = (pad[j + 2] - v) * idx_inv[0];
        for (int d = 1; d < dim; d++) {
            l[d] = (v - lo[d][j]) * idx_inv[d];
            rr[d] = (hi[d][j] - v) * idx_inv[d];
        }
        for (int d = 0; d < dim; d++) p[d] = 0.5 * (l[d] + rr[d]);
        x[0] = rx[0] + (double)j * g->dx[0];
        const double H = node_ham(fs->F, t, x, p, alpha);
        double DS = 0, S = 0;
        int fin = H - H == 0;
        for (int d = 0; d < dim; d++) {
            const double a = fabs(alpha[d]);
            fin &= alpha[d] - alpha[d] == 0;
            DS += a * 0.5 * (rr[d] - l[d]);
            S += a / g->dx[d];
        }
        if (!fin && b < 0) b = j;
        out[j] = -(H - DS);
        m = S > m || S != S ? S : m;
    }
    *inv = m;
    *bad = b;
}

static int set_given(const hj_reach_set *s) { return s->fn || s->array; }
static double set_at(const hj_reach_set *s, double t, const double *x, size_t k)
{
    return s->fn ? s->fn(t, x, s->ctx) : s->array[k];
}

/* The offset of interior row r's first node in the caller's arrays. */
static size_t user_row(const hj_ls_grid *g, int compact, size_t r)
{
    long idx[HJ_LS_MAXDIM];
    return compact ? r * (size_t)g->N[0] : hj_ls_row(g, r, idx);
}

int hj_reach_fused_applies(const hj_reach_problem *pb)
{
    return !pb->general && !pb->per_node && pb->scheme == HJ_LS_UPWIND_FIRST && pb->order == 1 &&
           pb->discount == 0 && pb->grid && !pb->grid->dist;
}

size_t hj_reach_fused_bytes(const hj_ls_grid *g, int compact, int threads)
{
    return sizeof(double) * ((compact ? 1 : 2) * g->nodes + (size_t)threads * row_work(g));
}

static double wall(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int max_threads(void)
{
#ifdef _OPENMP
    return omp_get_max_threads();
#else
    return 1;
#endif
}

/* The error of the first row (in row order) with a non-finite H or alpha. */
static int report_bad(const hj_ls_grid *g, size_t r, long j, double tau, hj_error *err)
{
    long idx[HJ_LS_MAXDIM];
    double x[HJ_LS_MAXDIM];
    hj_ls_row(g, r, idx);
    idx[0] = j;
    hj_ls_coord(g, idx, x);
    char pos[256];
    int len = 0;
    for (int d = 0; d < g->dim && len < 200; d++)
        len += snprintf(pos + len, sizeof pos - (size_t)len, "%s%g", d ? ", " : "", x[d]);
    return hj_error_set(err, HJ_ENONFINITE,
                        "Hamiltonian or partial callback returned a non-finite value at x = (%s), t = %g", pos, tau);
}

int hj_reach_solve_fused(const hj_reach_problem *pb, double *phi, double *ttr, hj_reach_stats *stats, hj_error *err)
{
    if (!hj_reach_fused_applies(pb))
        return hj_error_set(err, HJ_EINVAL,
                            "reach: the fused path needs first order upwinding, forward Euler, no discount and an "
                            "undivided grid");
    const double start = wall();
    const hj_ls_grid *g = pb->grid;
    const int compact = pb->compact != 0, tube = pb->kind == HJ_REACH_BRT, obst = set_given(&pb->obstacle);
    const double T = isinf(pb->horizon) ? 0 : pb->horizon;
    const long n = g->N[0];
    fused_dyn F;
    fused_dyn_init(&F, pb->dyn, T);
    fused fs = {pb, &F, g, {1}, T};
    for (int d = 1; d < g->dim; d++) fs.cs[d] = fs.cs[d - 1] * (size_t)g->N[d - 1];
    double *own = malloc(sizeof(double) * g->nodes * (compact ? 1 : 2));
    if (!own) return hj_error_set(err, HJ_ENOMEM, "reach: out of memory for %zu nodes", g->nodes);
    double *y = compact ? phi : own, *next = compact ? own : own + g->nodes;
    long steps = 0;
    double tau = 0, change = INFINITY;
    int converged = 0, rc = HJ_OK;
    /* tau = 0: max(target(T), -obstacle(T)). */
    for (size_t r = 0; r < g->rows && rc == HJ_OK; r++) {
        long i[HJ_LS_MAXDIM];
        double x[HJ_LS_MAXDIM];
        hj_ls_row(g, r, i);
        hj_ls_coord(g, i, x);
        const size_t ku = user_row(g, compact, r), kc = r * (size_t)n;
        for (long j = 0; j < n; j++) {
            const size_t k = ku + (size_t)j;
            x[0] = g->min[0] + (double)j * g->dx[0];
            double v = set_at(&pb->target, T, x, k);
            if (isnan(v)) {
                rc = hj_error_set(err, HJ_ENONFINITE, "reach: the target is NaN at a node");
                break;
            }
            if (ttr) ttr[k] = v <= 0 ? 0 : INFINITY;
            if (obst) {
                const double o = -set_at(&pb->obstacle, T, x, k);
                v = o > v ? o : v;
            }
            y[kc + (size_t)j] = v;
        }
    }
    const double tk = isinf(pb->horizon) ? DBL_MAX / 4 : T;
    const double small = 100 * DBL_EPSILON * (fabs(tk) > 1 ? fabs(tk) : 1);
    const size_t wsz = row_work(g);
    while (rc == HJ_OK && tk - tau > small) {
        /* pass 1: the time derivative into next, the CFL bound */
        double m = 0;
        int nomem = 0;
        size_t bad_r = (size_t)-1;
        long bad_j = -1;
#ifdef _OPENMP
#pragma omp parallel reduction(max : m) reduction(| : nomem)
#endif
        {
            double *ws = malloc(sizeof(double) * wsz);
            if (!ws) nomem = 1;
            else {
                int nan_seen = 0;
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 16)
#endif
                for (size_t r = 0; r < g->rows; r++) {
                    double inv;
                    long bj;
                    row_ydot(&fs, tau, y, r, next + r * (size_t)n, ws, &inv, &bj);
                    if (bj >= 0) {
#ifdef _OPENMP
#pragma omp critical(hj_reach_fused_bad)
#endif
                        if (r < bad_r) bad_r = r, bad_j = bj;
                    }
                    if (inv != inv) nan_seen = 1;
                    else m = inv > m ? inv : m;
                }
                if (nan_seen) m = NAN;
            }
            free(ws);
        }
        if (nomem) {
            rc = hj_error_set(err, HJ_ENOMEM, "reach: out of memory for the row workspace");
            break;
        }
        if (bad_r != (size_t)-1) {
            rc = report_bad(g, bad_r, bad_j, tau, err);
            break;
        }
        if (m != m || m == INFINITY) {
            rc = hj_error_set(err, HJ_ENONFINITE, "Hamiltonian or partial callback: non-finite CFL bound at t = %g", tau);
            break;
        }
        if (!(m > 0)) {
            rc = hj_error_set(err, HJ_ENONFINITE, "infinite CFL bound at t = %g and no MaxStep", tau);
            break;
        }
        /* hj_ls_ode's step: factor_cfl times the bound, the last one cut */
        double dt = pb->factor_cfl * (1 / m);
        dt = dt < DBL_MAX ? dt : DBL_MAX;
        int last = 0;
        if (dt >= tk - tau) dt = tk - tau, last = 1;
        const double tau_new = last ? tk : tau + dt, t = T - tau_new, dtp = tau_new - tau;
        /* pass 2: Euler step, target and obstacle, change, time-to-reach */
        double ch = 0;
        int bad_state = 0, bad_set = 0;
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 16) reduction(max : ch) reduction(| : bad_state, bad_set)
#endif
        for (size_t r = 0; r < g->rows; r++) {
            long i[HJ_LS_MAXDIM];
            double x[HJ_LS_MAXDIM];
            hj_ls_row(g, r, i);
            hj_ls_coord(g, i, x);
            const size_t ku = user_row(g, compact, r), kc = r * (size_t)n;
            const double *yo = y + kc;
            double *yn = next + kc, rch = 0;
            int rb = 0, rs = 0;
            for (long j = 0; j < n; j++) {
                const double old = yo[j];
                double v = 0.0 * old + 1.0 * (old + dt * yn[j]);
                rb |= !(v - v == 0);
                if (tube || obst) {
                    const size_t k = ku + (size_t)j;
                    x[0] = g->min[0] + (double)j * g->dx[0];
                    if (tube) {
                        const double l = set_at(&pb->target, t, x, k);
                        rs |= isnan(l);
                        v = l < v ? l : v;
                    }
                    if (obst) {
                        const double o = -set_at(&pb->obstacle, t, x, k);
                        rs |= isnan(o);
                        v = o > v ? o : v;
                    }
                }
                yn[j] = v;
                const double dv = fabs(v - old);
                rch = dv > rch ? dv : rch;
                if (ttr) {
                    const size_t k = ku + (size_t)j;
                    if (old > 0 && v <= 0 && isinf(ttr[k])) ttr[k] = tau + dtp * old / (old - v);
                }
            }
            ch = rch > ch ? rch : ch;
            bad_state |= rb;
            bad_set |= rs;
        }
        steps++;
        if (bad_state) {
            rc = hj_error_set(err, HJ_ENONFINITE, "blow-up: NaN or Inf in the state at t = %.17g after step %ld",
                              tau_new, steps);
            break;
        }
        if (bad_set) {
            rc = hj_error_set(err, HJ_ENONFINITE, "a target or obstacle function returned NaN at t = %g", t);
            break;
        }
        double *sw = y;
        y = next, next = sw;
        tau = tau_new;
        change = ch / dtp;
        if (pb->conv_tol > 0 && change <= pb->conv_tol) {
            converged = 1;
            break;
        }
    }
    /* the value into the caller's array */
    if (rc == HJ_OK) {
        if (compact) {
            if (y != phi) memcpy(phi, y, sizeof(double) * g->nodes);
        } else {
            for (size_t r = 0; r < g->rows; r++)
                memcpy(phi + user_row(g, 0, r), y + r * (size_t)n, sizeof(double) * (size_t)n);
            hj_ls_fill_ghosts(g, phi);
        }
    }
    free(own);
    if (stats) {
        stats->steps = steps;
        stats->tau = tau;
        stats->converged = converged;
        stats->seconds = wall() - start;
        stats->bytes = hj_reach_fused_bytes(g, compact, max_threads());
    }
    return rc;
}
