/* hj_reach.c -- control-affine dynamics and reachability problems. */
#include "hj_reach.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "hj_ls_measure.h"
#include "hj_sys.h"

#ifdef _OPENMP
#include <omp.h>
#endif

void hj_reach_dyn_init(hj_reach_dyn *s, int nx, hj_reach_vec_fn f, void *ctx)
{
    memset(s, 0, sizeof *s);
    s->nx = nx;
    s->f = f;
    s->ctx = ctx;
    s->u.mode = HJ_REACH_MIN;
    s->d.mode = HJ_REACH_MAX;
}

static void set_box(hj_reach_input *in, int n, const double *lo, const double *hi)
{
    in->n = n;
    in->shape = HJ_REACH_BOX;
    for (int j = 0; j < n && j < HJ_REACH_MAXIN; j++) in->lo[j] = lo[j], in->hi[j] = hi[j];
}

static void set_ball(hj_reach_input *in, int n, const double *c, double r)
{
    in->n = n;
    in->shape = HJ_REACH_BALL;
    for (int j = 0; j < n && j < HJ_REACH_MAXIN; j++) in->c[j] = c[j];
    in->r = r;
}

void hj_reach_dyn_control_box(hj_reach_dyn *s, hj_reach_vec_fn G, int n, const double *lo, const double *hi)
{
    s->G = G;
    set_box(&s->u, n, lo, hi);
}
void hj_reach_dyn_control_ball(hj_reach_dyn *s, hj_reach_vec_fn G, int n, const double *c, double r)
{
    s->G = G;
    set_ball(&s->u, n, c, r);
}
void hj_reach_dyn_disturbance_box(hj_reach_dyn *s, hj_reach_vec_fn H, int n, const double *lo, const double *hi)
{
    s->H = H;
    set_box(&s->d, n, lo, hi);
}
void hj_reach_dyn_disturbance_ball(hj_reach_dyn *s, hj_reach_vec_fn H, int n, const double *c, double r)
{
    s->H = H;
    set_ball(&s->d, n, c, r);
}

void hj_reach_dyn_goal(hj_reach_dyn *s, int goal)
{
    s->u.mode = goal == HJ_REACH_AVOID ? HJ_REACH_MAX : HJ_REACH_MIN;
    s->d.mode = goal == HJ_REACH_AVOID ? HJ_REACH_MIN : HJ_REACH_MAX;
}

static int check_input(const hj_reach_input *in, const char *who, int have_matrix, hj_error *err)
{
    if (in->n < 0 || in->n > HJ_REACH_MAXIN)
        return hj_error_set(err, HJ_EINVAL, "%s: %d inputs, must be 0..%d", who, in->n, HJ_REACH_MAXIN);
    if (in->n == 0) return HJ_OK;
    if (!have_matrix)
        return hj_error_set(err, HJ_EINVAL, "%s: %d input%s but no input matrix", who, in->n, hj_plural(in->n));
    if (in->mode != HJ_REACH_MIN && in->mode != HJ_REACH_MAX)
        return hj_error_set(err, HJ_EINVAL, "%s: mode must be HJ_REACH_MIN or HJ_REACH_MAX", who);
    if (in->shape == HJ_REACH_BOX) {
        for (int j = 0; j < in->n; j++)
            if (!(in->lo[j] <= in->hi[j]) || !isfinite(in->lo[j]) || !isfinite(in->hi[j]))
                return hj_error_set(err, HJ_EINVAL, "%s: box [%g, %g] of input %d is empty or not finite", who,
                                    in->lo[j], in->hi[j], j);
    } else if (in->shape == HJ_REACH_BALL) {
        if (!(in->r >= 0) || !isfinite(in->r))
            return hj_error_set(err, HJ_EINVAL, "%s: ball radius %g must be finite and >= 0", who, in->r);
        for (int j = 0; j < in->n; j++)
            if (!isfinite(in->c[j])) return hj_error_set(err, HJ_EINVAL, "%s: ball centre is not finite", who);
    } else
        return hj_error_set(err, HJ_EINVAL, "%s: unknown set shape %d", who, in->shape);
    return HJ_OK;
}

int hj_reach_dyn_check(const hj_reach_dyn *s, hj_error *err)
{
    if (s->nx < 1 || s->nx > HJ_LS_MAXDIM)
        return hj_error_set(err, HJ_EINVAL, "dynamics: state dimension %d, must be 1..%d", s->nx, HJ_LS_MAXDIM);
    if (s->f_row && !s->f) return hj_error_set(err, HJ_EINVAL, "dynamics: f_row given without f");
    int rc = check_input(&s->u, "control", s->G != NULL, err);
    return rc ? rc : check_input(&s->d, "disturbance", s->H != NULL, err);
}

/* Centre and half widths of an input set (a ball's w is unused). */
static void centre(const hj_reach_input *in, double *c, double *w)
{
    for (int j = 0; j < in->n; j++) {
        if (in->shape == HJ_REACH_BOX) {
            c[j] = 0.5 * (in->lo[j] + in->hi[j]);
            w[j] = 0.5 * (in->hi[j] - in->lo[j]);
        } else
            c[j] = in->c[j], w[j] = 0;
    }
}

/* q = M^T p for an nx x n matrix M. */
static void mat_tp(const double *M, int nx, int n, const double *p, double *q)
{
    for (int j = 0; j < n; j++) q[j] = 0;
    for (int i = 0; i < nx; i++)
        for (int j = 0; j < n; j++) q[j] += M[i * n + j] * p[i];
}

/* opt_{v in set} q . v, and the optimal v (may be NULL). */
static double input_opt(const hj_reach_input *in, const double *q, double *v)
{
    double c[HJ_REACH_MAXIN], w[HJ_REACH_MAXIN];
    centre(in, c, w);
    const double sg = in->mode == HJ_REACH_MIN ? -1.0 : 1.0;
    double val = 0;
    if (in->shape == HJ_REACH_BOX) {
        for (int j = 0; j < in->n; j++) {
            const double aq = fabs(q[j]);
            val += q[j] * c[j] + sg * aq * w[j];
            if (v) v[j] = q[j] == 0 ? c[j] : c[j] + sg * (q[j] > 0 ? w[j] : -w[j]);
        }
    } else {
        double n2 = 0;
        for (int j = 0; j < in->n; j++) val += q[j] * c[j], n2 += q[j] * q[j];
        const double nq = sqrt(n2);
        val += sg * in->r * nq;
        for (int j = 0; v && j < in->n; j++) v[j] = nq > 0 ? c[j] + sg * in->r * q[j] / nq : c[j];
    }
    return val;
}

#define MATMAX (HJ_LS_MAXDIM * HJ_REACH_MAXIN)

double hj_reach_hamiltonian(const hj_reach_dyn *s, double t, const double *x, const double *p)
{
    double h = 0, q[HJ_REACH_MAXIN], M[MATMAX];
    if (s->f) {
        double fx[HJ_LS_MAXDIM];
        s->f(t, x, fx, s->ctx);
        for (int i = 0; i < s->nx; i++) h += p[i] * fx[i];
    }
    if (s->u.n > 0) {
        s->G(t, x, M, s->ctx);
        mat_tp(M, s->nx, s->u.n, p, q);
        h += input_opt(&s->u, q, NULL);
    }
    if (s->d.n > 0) {
        s->H(t, x, M, s->ctx);
        mat_tp(M, s->nx, s->d.n, p, q);
        h += input_opt(&s->d, q, NULL);
    }
    return h;
}

void hj_reach_dyn_optimal(const hj_reach_dyn *s, double t, const double *x, const double *p, double *u, double *d)
{
    double q[HJ_REACH_MAXIN], M[MATMAX];
    if (u && s->u.n > 0) {
        s->G(t, x, M, s->ctx);
        mat_tp(M, s->nx, s->u.n, p, q);
        input_opt(&s->u, q, u);
    }
    if (d && s->d.n > 0) {
        s->H(t, x, M, s->ctx);
        mat_tp(M, s->nx, s->d.n, p, q);
        input_opt(&s->d, q, d);
    }
}

void hj_reach_dyn_eval(const hj_reach_dyn *s, double t, const double *x, const double *u, const double *d,
                       double *xdot)
{
    double M[MATMAX];
    for (int i = 0; i < s->nx; i++) xdot[i] = 0;
    if (s->f) s->f(t, x, xdot, s->ctx);
    if (u && s->u.n > 0) {
        s->G(t, x, M, s->ctx);
        for (int i = 0; i < s->nx; i++)
            for (int j = 0; j < s->u.n; j++) xdot[i] += M[i * s->u.n + j] * u[j];
    }
    if (d && s->d.n > 0) {
        s->H(t, x, M, s->ctx);
        for (int i = 0; i < s->nx; i++)
            for (int j = 0; j < s->d.n; j++) xdot[i] += M[i * s->d.n + j] * d[j];
    }
}

/* The kernel integrates in tau with the Hamiltonian -H; the ctx of the
 * kernel's callbacks is a struct holding the system and the horizon, so
 * that the system sees the forward time t = T - tau. */
typedef struct {
    int valid;
    double tau;
    size_t k;      /* the row's offset (hj_ls_row_info) */
    double *alpha; /* nx x row_n */
} row_slot;

typedef struct {
    const hj_reach_dyn *dyn;
    double T;
    unsigned long id; /* this solve's number, for the cache of ls_partial */
    row_slot *slots;  /* one per thread, for the batched callbacks */
    int nslots;
    long row_n;
} ham_ctx;

static _Atomic unsigned long solve_count;

/* The kernel asks for alpha_d one dimension at a time at the same node:
 * the bounds of all dimensions are computed at once and kept, per thread,
 * for the next calls at that node of the same solve. */
static _Thread_local struct {
    unsigned long id;
    double tau, x[HJ_LS_MAXDIM], alpha[HJ_LS_MAXDIM];
} cache;

static double ls_ham(double tau, const double *x, double phi, const double *p, void *ctx)
{
    (void)phi;
    const ham_ctx *h = ctx;
    return -hj_reach_hamiltonian(h->dyn, h->T - tau, x, p);
}

/* For the nx x n input matrix M of input set in: a[d] += (M c)_d, the
 * centre's part of dx_d/dt, and b[d] += the set's bound on the rest of
 * |dx_d/dt| (sum_j |M_dj| w_j for a box, r |M_d.| for a ball). */
static void input_part(const hj_reach_input *in, const double *M, int nx, double *a, double *b)
{
    double c[HJ_REACH_MAXIN], w[HJ_REACH_MAXIN];
    const int n = in->n;
    centre(in, c, w);
    for (int d = 0; d < nx; d++) {
        double n2 = 0;
        for (int j = 0; j < n; j++) {
            const double m = M[d * n + j];
            a[d] += m * c[j];
            if (in->shape == HJ_REACH_BOX) b[d] += fabs(m) * w[j];
            else n2 += m * m;
        }
        if (in->shape == HJ_REACH_BALL) b[d] += in->r * sqrt(n2);
    }
}

/* alpha[0..nx-1] at (t, x): the largest |dx_i/dt| over the input sets. */
static void partials(const hj_reach_dyn *s, double t, const double *x, double *alpha)
{
    double a[HJ_LS_MAXDIM] = {0}, b[HJ_LS_MAXDIM] = {0}, M[MATMAX];
    if (s->f) s->f(t, x, a, s->ctx);
    const hj_reach_input *in[2] = {&s->u, &s->d};
    const hj_reach_vec_fn mf[2] = {s->G, s->H};
    for (int k = 0; k < 2; k++) {
        const int n = in[k]->n;
        if (n == 0) continue;
        mf[k](t, x, M, s->ctx);
        input_part(in[k], M, s->nx, a, b);
    }
    for (int d = 0; d < s->nx; d++) alpha[d] = fabs(a[d]) + b[d];
}

static double partial_of(const hj_reach_dyn *s, double t, const double *x, int d)
{
    double alpha[HJ_LS_MAXDIM];
    partials(s, t, x, alpha);
    return alpha[d];
}

static double ls_partial(double tau, const double *x, const double *pmin, const double *pmax, int d, void *ctx)
{
    (void)pmin, (void)pmax;
    const ham_ctx *h = ctx;
    const int nx = h->dyn->nx;
    int hit = cache.id == h->id && cache.tau == tau;
    for (int i = 0; hit && i < nx; i++) hit = cache.x[i] == x[i];
    if (!hit) {
        partials(h->dyn, h->T - tau, x, cache.alpha);
        cache.id = h->id, cache.tau = tau;
        for (int i = 0; i < nx; i++) cache.x[i] = x[i];
    }
    return cache.alpha[d];
}

/* ---- batched rows (hj_ls_ham_row_fn, hj_ls_partial_row_fn).  The kernel
 * calls ham_row for a row, then partial_row for d = 0 .. nx-1 of the same
 * row on the same thread: ham_row evaluates f and G (H) once per node,
 * computes the Hamiltonian and every alpha_d from them, and keeps the
 * alphas in its thread's slice of the row buffer for the partial_row
 * calls.  The arithmetic is that of hj_reach_hamiltonian and partials,
 * operation for operation, so both paths give the same bits. */

/* -H and alpha[0..nx-1] at one node, from one evaluation of f, G and H. */
static double node_ham_partials(const hj_reach_dyn *s, double t, const double *x, const double *p, double *alpha)
{
    double fx[HJ_LS_MAXDIM] = {0}, b[HJ_LS_MAXDIM] = {0}, M[MATMAX], q[HJ_REACH_MAXIN], h = 0;
    if (s->f) {
        s->f(t, x, fx, s->ctx);
        for (int i = 0; i < s->nx; i++) h += p[i] * fx[i];
    }
    const hj_reach_input *in[2] = {&s->u, &s->d};
    const hj_reach_vec_fn mf[2] = {s->G, s->H};
    for (int k = 0; k < 2; k++) {
        const int n = in[k]->n;
        if (n == 0) continue;
        mf[k](t, x, M, s->ctx);
        mat_tp(M, s->nx, n, p, q);
        h += input_opt(in[k], q, NULL);
        input_part(in[k], M, s->nx, fx, b);
    }
    for (int d = 0; d < s->nx; d++) alpha[d] = fabs(fx[d]) + b[d];
    return -h;
}

static int thread_id(void)
{
#ifdef _OPENMP
    return omp_get_thread_num();
#else
    return 0;
#endif
}

/* This thread's slice of the row buffer (nx x n alphas and the key of the
 * row they belong to), or NULL where the buffer has no slice for it. */
static row_slot *slot_of(const ham_ctx *h)
{
    const int tid = thread_id();
    return h->slots && tid < h->nslots ? &h->slots[tid] : NULL;
}

static void ls_ham_row(double tau, const hj_ls_row_info *row, const double *phi, const double *const *P, double *H,
                       void *ctx)
{
    (void)phi;
    const ham_ctx *h = ctx;
    const hj_reach_dyn *s = h->dyn;
    const int nx = s->nx;
    row_slot *sl = row->n <= h->row_n ? slot_of(h) : NULL;
    double x[HJ_LS_MAXDIM], p[HJ_LS_MAXDIM], alpha[HJ_LS_MAXDIM];
    memcpy(x, row->x, sizeof(double) * (size_t)nx);
    for (long j = 0; j < row->n; j++) {
        x[0] = row->x[0] + (double)j * row->dx0;
        for (int d = 0; d < nx; d++) p[d] = P[d][j];
        H[j] = node_ham_partials(s, h->T - tau, x, p, alpha);
        if (sl)
            for (int d = 0; d < nx; d++) sl->alpha[(size_t)d * (size_t)h->row_n + (size_t)j] = alpha[d];
    }
    if (sl) sl->tau = tau, sl->k = row->k, sl->valid = 1;
}

static void ls_partial_row(double tau, const hj_ls_row_info *row, const double *const *pmin,
                           const double *const *pmax, int d, double *A, void *ctx)
{
    (void)pmin, (void)pmax;
    const ham_ctx *h = ctx;
    const row_slot *sl = slot_of(h);
    if (sl && sl->valid && sl->tau == tau && sl->k == row->k && row->n <= h->row_n) {
        memcpy(A, sl->alpha + (size_t)d * (size_t)h->row_n, sizeof(double) * (size_t)row->n);
        return;
    }
    /* Not after ham_row on this row: node by node, as ls_partial. */
    double x[HJ_LS_MAXDIM], alpha[HJ_LS_MAXDIM];
    memcpy(x, row->x, sizeof(double) * (size_t)h->dyn->nx);
    for (long j = 0; j < row->n; j++) {
        x[0] = row->x[0] + (double)j * row->dx0;
        partials(h->dyn, h->T - tau, x, alpha);
        A[j] = alpha[d];
    }
}

double hj_reach_ls_ham(double t, const double *x, double phi, const double *p, void *ctx)
{
    (void)phi;
    return -hj_reach_hamiltonian(ctx, t, x, p);
}

double hj_reach_ls_partial(double t, const double *x, const double *pmin, const double *pmax, int d, void *ctx)
{
    (void)pmin, (void)pmax;
    return partial_of(ctx, t, x, d);
}

void hj_reach_problem_init(hj_reach_problem *pb, const hj_ls_grid *g, const hj_reach_dyn *s)
{
    memset(pb, 0, sizeof *pb);
    pb->grid = g;
    pb->dyn = s;
    pb->kind = HJ_REACH_BRT;
    pb->horizon = NAN;
    pb->scheme = HJ_LS_ENO2;
    pb->order = 2;
    pb->dissipation = HJ_LS_LLF;
    pb->factor_cfl = 0.5;
    pb->keep_derivs = 1;
}



/* State of the post-step projection. */
typedef struct {
    const hj_reach_problem *pb;
    double *prev; /* phi before the step */
    double *ttr;
    double tau_prev;
    double change; /* max |phi - prev| / dt of the last step */
    int converged;
    long steps;
    int bad; /* a set function returned NaN */
    double horizon; /* the caller's (pb holds T, 0 for an infinite one) */
    double span_end; /* the integrator's last time: DBL_MAX / 4 for an
                      * infinite horizon, which only a step where nothing
                      * moves reaches */
    int stop_code;   /* the progress callback's nonzero return */
} post_ctx;

/* Private codes that end the integration: at convergence (not an error),
 * and at the progress callback's request (its code is in stop_code, since
 * any value, these included, may be its own). */
#define STOP_CONVERGED (-1)
#define STOP_PROGRESS (-2)

static int post_step(double tau, double *y, void *ctx, hj_error *err)
{
    post_ctx *c = ctx;
    const hj_reach_problem *pb = c->pb;
    const hj_ls_grid *g = pb->grid;
    const double t = pb->horizon - tau, dt = tau - c->tau_prev;
    const int tube = pb->kind == HJ_REACH_BRT, obst = hj_reach_set_given(&pb->obstacle);
    double change = 0;
    int bad = 0;
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 16) reduction(max : change) reduction(| : bad)
#endif
    for (size_t r = 0; r < g->rows; r++) {
        long i[HJ_LS_MAXDIM];
        double x[HJ_LS_MAXDIM];
        const size_t k0 = hj_ls_row(g, r, i);
        hj_ls_coord(g, i, x);
        double rc = 0;
        int rb = 0;
        for (long j = 0; j < g->N[0]; j++) {
            const size_t k = k0 + (size_t)j;
            x[0] = g->min[0] + (double)j * g->dx[0];
            const double v = hj_reach_set_constrain(&pb->target, &pb->obstacle, tube, obst, t, x, k, y[k], &rb);
            y[k] = v;
            const double old = c->prev[k], dv = fabs(v - old);
            rc = dv > rc ? dv : rc;
            if (c->ttr && old > 0 && v <= 0 && isinf(c->ttr[k])) c->ttr[k] = c->tau_prev + dt * old / (old - v);
            c->prev[k] = v;
        }
        change = rc > change ? rc : change;
        bad |= rb;
    }
    if (g->dist) {
        double v[2] = {change, bad};
        hj_ls_grid_reduce(g, v, 2, HJ_LS_REDUCE_MAX);
        change = v[0], bad = v[1] != 0;
    }
    if (bad) return hj_error_set(err, HJ_ENONFINITE, "a target or obstacle function returned NaN at t = %g", t);
    /* (an infinite horizon runs with pb->horizon 0 here: nothing left) */
    const int rc = hj_reach_check_steps_left(pb->horizon, tau, dt, pb->conv_tol, err);
    if (rc) return rc;
    c->steps++;
    if (isinf(c->horizon) && tau == c->span_end && change == 0) {
        /* Nothing moves under an infinite horizon: the value is the limit
         * from the step's start, which tau stays at (as the fused path). */
        c->change = 0;
        c->converged = 1;
    } else {
        c->change = change / dt;
        c->tau_prev = tau;
        c->converged = pb->conv_tol > 0 && c->change <= pb->conv_tol;
    }
    const int last = c->converged || tau >= c->span_end; /* the step that ends the run is reported too */
    const int code = hj_reach_progress_call(c->pb, c->horizon, c->tau_prev, c->steps, last, err);
    if (code) {
        c->stop_code = code;
        return STOP_PROGRESS;
    }
    return c->converged ? STOP_CONVERGED : HJ_OK;
}

int hj_reach_problem_check(const hj_reach_problem *pb, hj_error *err)
{
    if (!pb || !pb->grid || !pb->dyn) return hj_error_set(err, HJ_EINVAL, "reach: the problem needs a grid and dynamics");
    int rc = hj_reach_dyn_check(pb->dyn, err);
    if (rc) return rc;
    if (pb->dyn->nx != pb->grid->dim)
        return hj_error_set(err, HJ_EINVAL, "reach: %d-D dynamics on a %d-D grid", pb->dyn->nx, pb->grid->dim);
    if (!hj_reach_set_given(&pb->target)) return hj_error_set(err, HJ_EINVAL, "reach: no target");
    if (pb->kind != HJ_REACH_BRS && pb->kind != HJ_REACH_BRT)
        return hj_error_set(err, HJ_EINVAL, "reach: kind must be HJ_REACH_BRS or HJ_REACH_BRT");
    if (!(pb->horizon > 0)) return hj_error_set(err, HJ_EINVAL, "reach: the horizon must be > 0, got %g", pb->horizon);
    if (isinf(pb->horizon) && !(pb->conv_tol > 0))
        return hj_error_set(err, HJ_EINVAL, "reach: an infinite horizon needs a convergence tolerance");
    if (!(pb->discount >= 0) || !isfinite(pb->discount))
        return hj_error_set(err, HJ_EINVAL, "reach: the discount must be finite and >= 0, got %g", pb->discount);
    if (!(pb->conv_tol >= 0)) return hj_error_set(err, HJ_EINVAL, "reach: the convergence tolerance must be >= 0");
    if (!(pb->factor_cfl > 0 && pb->factor_cfl <= 1)) /* as hj_ls_ode: the schemes' stable range */
        return hj_error_set(err, HJ_EINVAL, "reach: the CFL factor must be in (0, 1], got %g", pb->factor_cfl);
    /* Checked here for both paths: the fused one never reads the
     * dissipation (its bounds do not depend on the gradient), so an
     * unknown value passed it silently. */
    if (!hj_ls_scheme_name(pb->scheme)) return hj_error_set(err, HJ_EINVAL, "reach: unknown scheme %d", pb->scheme);
    if (pb->order < 1 || pb->order > 3)
        return hj_error_set(err, HJ_EINVAL, "reach: the RK order must be 1, 2 or 3, got %d", pb->order);
    if (pb->dissipation != HJ_LS_GLF && pb->dissipation != HJ_LS_LLF && pb->dissipation != HJ_LS_LLLF)
        return hj_error_set(err, HJ_EINVAL, "reach: unknown dissipation %d (HJ_LS_GLF, HJ_LS_LLF or HJ_LS_LLLF)",
                            pb->dissipation);
    return HJ_OK;
}

size_t hj_reach_general_bytes(const hj_reach_problem *pb, int threads)
{
    const hj_ls_grid *g = pb->grid;
    /* prev, the integrator's time derivative and stage, the kept
     * derivatives, the row buffers, the sum of terms' array (discount) */
    return sizeof(double) * ((2 + (pb->order > 1)) * g->total +
                             (pb->keep_derivs && pb->dissipation != HJ_LS_LLLF ? hj_ls_lax_friedrichs_work_size(g) : 0) +
                             (pb->per_node ? 0 : (size_t)threads * (size_t)g->dim * (size_t)g->N[0]) +
                             (pb->discount > 0 ? g->total : 0));
}

int hj_reach_check_memory(const hj_reach_problem *pb, int with_ttr, hj_error *err)
{
    /* malloc refuses only a block beyond memory and swap, and a solve over
     * memory would page or be killed: what the solve touches, its own
     * arrays and the caller's value and time-to-reach, against the
     * machine's memory. */
    const hj_ls_grid *g = pb->grid;
    const int fused = hj_reach_fused_applies(pb);
    const double mem = hj_sys_physical_memory();
    const double caller = (double)sizeof(double) * (double)(fused && pb->compact ? g->nodes : g->total);
    const int nth = hj_sys_max_threads();
    const double own = (double)(fused ? hj_reach_fused_bytes(pb, nth) : hj_reach_general_bytes(pb, nth));
    const double need = own + caller * (with_ttr ? 2 : 1);
    if (mem > 0 && need > mem)
        return hj_error_set(err, HJ_ENOMEM,
                            "reach: the solve needs %.3g GB (%zu nodes: its own arrays and the caller's), the machine "
                            "has %.3g GB",
                            need / 1e9, g->nodes, mem / 1e9);
    return HJ_OK;
}

static double wall(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int hj_reach_solve(const hj_reach_problem *pb, double *phi, double *ttr, hj_reach_stats *stats, hj_error *err)
{
    int rc = hj_reach_problem_check(pb, err);
    if (rc) return rc;
    if (!phi) return hj_error_set(err, HJ_EINVAL, "reach: NULL value array");
    if (hj_reach_fused_applies(pb)) return hj_reach_solve_fused(pb, phi, ttr, stats, err);
    if (pb->compact)
        return hj_error_set(err, HJ_EINVAL,
                            "reach: compact arrays need the fused path (no discount, an undivided grid, general "
                            "and per_node 0)");
    if ((rc = hj_reach_check_memory(pb, ttr != NULL, err))) return rc;
    const double start = wall();
    double step_seconds = 0;
    const hj_ls_grid *g = pb->grid;
    /* With an infinite horizon the sets are static: T only shifts time. */
    const double T = isinf(pb->horizon) ? 0 : pb->horizon;
    hj_reach_problem p = *pb;
    p.horizon = T;
    /* An infinite horizon runs until convergence: a long finite span. */
    const double tspan[2] = {0, isinf(pb->horizon) ? DBL_MAX / 4 : T};
    post_ctx pc = {&p, hj_ls_alloc(g), ttr, 0, INFINITY, 0, 0, 0, pb->horizon, tspan[1], 0};
    if (!pc.prev) return hj_error_set(err, HJ_ENOMEM, "reach: out of memory");
    /* tau = 0: max(target(T), -obstacle(T)). */
    const int obst = hj_reach_set_given(&pb->obstacle);
    for (size_t r = 0; r < g->rows; r++) {
        long i[HJ_LS_MAXDIM];
        double x[HJ_LS_MAXDIM];
        const size_t k0 = hj_ls_row(g, r, i);
        hj_ls_coord(g, i, x);
        for (long j = 0; j < g->N[0]; j++) {
            const size_t k = k0 + (size_t)j;
            x[0] = g->min[0] + (double)j * g->dx[0];
            double v = hj_reach_set_at(&pb->target, T, x, k);
            if (isnan(v)) {
                char at[256];
                hj_ls_format_node(g, r, j, at, sizeof at);
                hj_ls_free(pc.prev);
                return hj_error_set(err, HJ_ENONFINITE, "reach: the target is NaN at x = (%s)", at);
            }
            if (ttr) ttr[k] = v <= 0 ? 0 : INFINITY;
            if (obst) {
                const double o = -hj_reach_set_at(&pb->obstacle, T, x, k);
                v = o > v ? o : v;
            }
            phi[k] = pc.prev[k] = v;
        }
    }
    ham_ctx hc = {pb->dyn, T, ++solve_count, NULL, 0, g->N[0]};
    hj_ls_lax_friedrichs lf;
    hj_ls_lax_friedrichs_init(&lf, g, pb->scheme, pb->dissipation, ls_ham, ls_partial, &hc);
    double *alphas = NULL, *derivs = NULL;
    int have_sum = 0;
    if (!pb->per_node) {
        hc.nslots = hj_sys_max_threads();
        hc.slots = calloc((size_t)hc.nslots, sizeof *hc.slots);
        alphas = malloc(sizeof(double) * (size_t)hc.nslots * (size_t)g->dim * (size_t)g->N[0]);
        if (!hc.slots || !alphas) {
            rc = hj_error_set(err, HJ_ENOMEM, "reach: out of memory for the row buffers");
            goto done;
        }
        for (int i = 0; i < hc.nslots; i++) hc.slots[i].alpha = alphas + (size_t)i * (size_t)g->dim * (size_t)g->N[0];
        lf.ham_row = ls_ham_row;
        lf.partial_row = ls_partial_row;
    }
    if (pb->keep_derivs && pb->dissipation != HJ_LS_LLLF) {
        if (!(derivs = malloc(sizeof(double) * hj_ls_lax_friedrichs_work_size(g)))) {
            rc = hj_error_set(err, HJ_ENOMEM, "reach: out of memory for the derivative cache");
            goto done;
        }
        lf.work = derivs;
    }
    hj_ls_discount disc;
    hj_ls_discount_init(&disc, g);
    disc.lambda.value = pb->discount;
    hj_ls_sum sum;
    const hj_ls_term *terms[2] = {&lf.base, &disc.base};
    const hj_ls_term *term = &lf.base;
    if (pb->discount > 0) {
        if ((rc = hj_ls_sum_init(&sum, g, terms, 2, err))) goto done;
        have_sum = 1;
        term = &sum.base;
    }
    hj_ls_ode_opts o;
    hj_ls_ode_defaults(&o);
    o.factor_cfl = pb->factor_cfl;
    o.post = post_step;
    o.post_ctx = &pc;
    o.blowup_factor = 0; /* obstacle and target bound phi; discount decays */
    const double steps_start = wall();
    rc = hj_ls_ode(pb->order, g, term, tspan, 2, phi, &o, NULL, NULL, NULL, err);
    step_seconds = wall() - steps_start;
    if (rc == STOP_CONVERGED) rc = HJ_OK, hj_error_clear(err);
    if (rc == STOP_PROGRESS) hj_ls_fill_ghosts(g, phi), rc = pc.stop_code;
    if (rc == HJ_OK) hj_ls_fill_ghosts(g, phi);
done:
    if (have_sum) hj_ls_sum_free(&sum);
    free(derivs);
    free(alphas);
    free(hc.slots);
    hj_ls_free(pc.prev);
    if (stats) {
        stats->steps = pc.steps;
        stats->tau = pc.tau_prev;
        stats->converged = pc.converged;
        stats->seconds = wall() - start;
        stats->step_seconds = step_seconds;
        stats->bytes = hj_reach_general_bytes(pb, hc.nslots);
    }
    return rc;
}

int hj_reach_measure(const hj_ls_grid *g, const double *phi, double *m, hj_error *err)
{
    if (!g || !phi || !m) return hj_error_set(err, HJ_EINVAL, "measure: NULL grid, array or result");
    int pdim = -1;
    for (int d = 0; d < g->dim; d++)
        if (g->bc[d].type == HJ_LS_BC_PERIODIC) {
            if (pdim >= 0) return hj_error_set(err, HJ_EINVAL, "measure: more than one periodic dimension");
            pdim = d;
        }
    return hj_ls_measure_periodic(g, phi, pdim, m, err);
}

int hj_reach_measure_compact(const hj_ls_grid *g, const double *phi, double *m, hj_error *err)
{
    if (!g || !phi || !m) return hj_error_set(err, HJ_EINVAL, "measure: NULL grid, array or result");
    if (g->dim < 1 || g->dim > 3) return hj_error_set(err, HJ_EINVAL, "measure: dimension %d (1 to 3 only)", g->dim);
    double *a = hj_ls_alloc(g);
    if (!a) return hj_error_set(err, HJ_ENOMEM, "out of memory for the measure");
    long i[HJ_LS_MAXDIM];
    for (size_t r = 0; r < g->rows; r++)
        memcpy(a + hj_ls_row(g, r, i), phi + r * (size_t)g->N[0], (size_t)g->N[0] * sizeof *a);
    const int rc = hj_reach_measure(g, a, m, err);
    hj_ls_free(a);
    return rc;
}
