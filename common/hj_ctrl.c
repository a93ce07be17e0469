/* hj_ctrl.c -- interpolated value, optimal inputs, closed-loop RK4. */
#include "hj_ctrl.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* The multilinear interpolant of phi at x; with finite_only, over the
 * cell's nodes that are not infinite, their weights renormalised
 * (INFINITY when every node of positive weight is). */
static double interpolate(const hj_ls_grid *g, const double *phi, const double *x, int finite_only)
{
    long i0[HJ_LS_MAXDIM];
    double w[HJ_LS_MAXDIM];
    const int dim = g->dim;
    for (int d = 0; d < dim; d++) {
        double s = (x[d] - g->min[d]) / g->dx[d];
        const long n = g->N[d];
        if (g->bc[d].type == HJ_LS_BC_PERIODIC) {
            s = fmod(s, (double)n);
            if (s < 0) s += (double)n;
            long k = (long)floor(s);
            if (k >= n) k = n - 1;
            i0[d] = k;
            w[d] = s - (double)k;
        } else {
            s = s < 0 ? 0 : (s > (double)(n - 1) ? (double)(n - 1) : s);
            long k = (long)floor(s);
            if (k > n - 2) k = n - 2;
            i0[d] = k;
            w[d] = s - (double)k;
        }
    }
    double v = 0, wsum = 0;
    for (unsigned c = 0; c < (1u << dim); c++) {
        long i[HJ_LS_MAXDIM];
        double wt = 1;
        for (int d = 0; d < dim; d++) {
            const int up = (c >> d) & 1;
            i[d] = i0[d] + up;
            if (i[d] == g->N[d]) i[d] = 0; /* periodic wrap (clamped dims never get here) */
            wt *= up ? w[d] : 1 - w[d];
        }
        if (wt == 0) continue;
        const double a = phi[hj_ls_index(g, i)];
        if (finite_only && isinf(a)) continue; /* a NaN still propagates */
        v += wt * a, wsum += wt;
    }
    if (finite_only) return wsum > 0 ? v / wsum : INFINITY;
    return v;
}

double hj_ctrl_value(const hj_ls_grid *g, const double *phi, const double *x)
{
    return interpolate(g, phi, x, 0);
}

/* The value the gradient differences: the interpolant, or where a node of
 * the cell is infinite (a time-to-reach beside an obstacle or the reached
 * set's edge) that of the cell's other nodes, so that a state there keeps
 * a gradient (the time-optimal path runs along the obstacle); the
 * interpolant's bits wherever it is finite. */
static double steering_value(const hj_ls_grid *g, const double *phi, const double *x)
{
    const double v = interpolate(g, phi, x, 0);
    return isfinite(v) ? v : interpolate(g, phi, x, 1);
}

void hj_ctrl_gradient(const hj_ls_grid *g, const double *phi, const double *x, double *p)
{
    double y[HJ_LS_MAXDIM];
    for (int d = 0; d < g->dim; d++) y[d] = x[d];
    double c = NAN; /* the value at x, interpolated only when a side is not finite */
    int have_c = 0;
    for (int d = 0; d < g->dim; d++) {
        const double h = g->dx[d];
        y[d] = x[d] + h;
        const double a = steering_value(g, phi, y);
        y[d] = x[d] - h;
        const double b = steering_value(g, phi, y);
        y[d] = x[d];
        /* A time-to-reach is INFINITY where nothing arrives: where a side's
         * cell has only such nodes the one-sided difference on the finite
         * side, and NaN where neither side is finite (an infinite p made
         * G^T p = 0 * inf). */
        if (isfinite(a) && isfinite(b)) {
            p[d] = (a - b) / (2 * h);
            continue;
        }
        if (!have_c) c = steering_value(g, phi, x), have_c = 1;
        if (isfinite(c) && isfinite(a))
            p[d] = (a - c) / h;
        else if (isfinite(c) && isfinite(b))
            p[d] = (c - b) / h;
        else
            p[d] = NAN;
    }
}

static int all_finite(const double *v, int n)
{
    for (int k = 0; k < n; k++)
        if (!isfinite(v[k])) return 0;
    return 1;
}

/* The inputs for gradient p, NaN when p is not finite (no value to steer
 * by: the argument of the optima would be an arbitrary corner). */
static void optimal_from(const hj_reach_dyn *s, double t, const double *x, const double *p, double *u, double *d)
{
    if (all_finite(p, s->nx)) {
        hj_reach_dyn_optimal(s, t, x, p, u, d);
        return;
    }
    for (int j = 0; u && j < s->u.n; j++) u[j] = NAN;
    for (int j = 0; d && j < s->d.n; j++) d[j] = NAN;
}

void hj_ctrl_optimal(const hj_reach_dyn *s, const hj_ls_grid *g, const double *phi, double t, const double *x,
                     double *u, double *d)
{
    double p[HJ_LS_MAXDIM];
    hj_ctrl_gradient(g, phi, x, p);
    optimal_from(s, t, x, p, u, d);
}

int hj_ctrl_traj_alloc(hj_ctrl_traj *tr, int nx, int nu, int nd, long cap, hj_error *err)
{
    memset(tr, 0, sizeof *tr);
    if (nx < 1 || nx > HJ_LS_MAXDIM || nu < 0 || nu > HJ_REACH_MAXIN || nd < 0 || nd > HJ_REACH_MAXIN || cap < 1)
        return hj_error_set(err, HJ_EINVAL, "trajectory: bad sizes (nx %d of 1..%d, nu %d and nd %d of 0..%d, %ld steps)",
                            nx, HJ_LS_MAXDIM, nu, nd, HJ_REACH_MAXIN, cap);
    /* The largest array's byte count must not wrap around size_t: a
     * wrapped product gave small arrays for a huge cap. */
    const size_t widest = (size_t)(nx > nu ? nx : nu > 0 ? nu : 1);
    if ((size_t)cap >= SIZE_MAX / sizeof(double) / widest)
        return hj_error_set(err, HJ_ENOMEM, "trajectory: out of memory for %ld steps", cap);
    const size_t n = (size_t)cap + 1;
    tr->nx = nx, tr->nu = nu, tr->nd = nd, tr->cap = cap;
    tr->t = malloc(n * sizeof *tr->t);
    tr->x = malloc(n * (size_t)nx * sizeof *tr->x);
    tr->u = malloc(n * (size_t)(nu ? nu : 1) * sizeof *tr->u);
    tr->value = malloc(n * sizeof *tr->value);
    if (!tr->t || !tr->x || !tr->u || !tr->value) {
        hj_ctrl_traj_free(tr);
        return hj_error_set(err, HJ_ENOMEM, "trajectory: out of memory for %ld steps", cap);
    }
    return HJ_OK;
}

void hj_ctrl_traj_free(hj_ctrl_traj *tr)
{
    free(tr->t), free(tr->x), free(tr->u), free(tr->value);
    tr->t = tr->x = tr->u = tr->value = NULL;
}

void hj_ctrl_sim_defaults(hj_ctrl_sim_opts *o)
{
    memset(o, 0, sizeof *o);
    o->dt = 0.01;
    o->t_max = 1;
    o->disturbance = HJ_CTRL_D_ZERO;
}

static double set_value(const hj_reach_set *s, double t, const double *x)
{
    return s->fn ? s->fn(t, x, s->ctx) : INFINITY;
}

/* The first non-periodic dimension in which x lies outside the grid's box
 * [min, min + (N - 1) dx] (where the interpolant is clamped), or -1. */
static int outside_box(const hj_ls_grid *g, const double *x)
{
    for (int d = 0; d < g->dim; d++)
        if (g->bc[d].type != HJ_LS_BC_PERIODIC &&
            !(x[d] >= g->min[d] && x[d] <= g->min[d] + (double)(g->N[d] - 1) * g->dx[d]))
            return d;
    return -1;
}

int hj_ctrl_simulate(const hj_reach_dyn *s, const hj_ls_grid *g, const double *phi, const double *x0,
                     const hj_ctrl_sim_opts *o, hj_ctrl_traj *tr, hj_error *err)
{
    if (!s || !g || !phi || !x0 || !o || !tr || !tr->t)
        return hj_error_set(err, HJ_EINVAL, "simulate: NULL system, grid, value, initial state, options or trajectory");
    int rc = hj_reach_dyn_check(s, err);
    if (rc) return rc;
    if (s->nx != g->dim) return hj_error_set(err, HJ_EINVAL, "simulate: %d-D dynamics on a %d-D grid", s->nx, g->dim);
    if (!(o->dt > 0) || !(o->t_max > 0) || !isfinite(o->t_max))
        return hj_error_set(err, HJ_EINVAL, "simulate: dt and t_max must be positive and finite");
    const double steps = ceil(o->t_max / o->dt - 1e-9);
    if (steps > (double)tr->cap)
        return hj_error_set(err, HJ_EINVAL, "simulate: %g steps, the trajectory holds %ld", steps, tr->cap);
    if (tr->nx != s->nx || tr->nu != s->u.n)
        return hj_error_set(err, HJ_EINVAL, "simulate: the trajectory's sizes do not match the system");
    if (o->disturbance != HJ_CTRL_D_ZERO && o->disturbance != HJ_CTRL_D_OPTIMAL && o->disturbance != HJ_CTRL_D_FN)
        return hj_error_set(err, HJ_EINVAL, "simulate: unknown disturbance mode %d", o->disturbance);
    if (o->disturbance == HJ_CTRL_D_FN && !o->d_fn)
        return hj_error_set(err, HJ_EINVAL, "simulate: a disturbance function is needed");
    if ((o->target.array && !o->target.fn) || (o->obstacle.array && !o->obstacle.fn))
        return hj_error_set(err, HJ_EINVAL, "simulate: give the target and obstacle as functions of (t, x)");
    const int nx = s->nx, nu = s->u.n;
    const int out0 = all_finite(x0, nx) ? outside_box(g, x0) : -1; /* a NaN state: HJ_ENONFINITE below */
    if (out0 >= 0)
        return hj_error_set(err, HJ_EINVAL,
                            "simulate: the initial state is outside the grid (coordinate %d = %g, the grid spans "
                            "[%g, %g] there): the value is not known there (hj_ctrl_value clamps to the box)",
                            out0, x0[out0], g->min[out0], g->min[out0] + (double)(g->N[out0] - 1) * g->dx[out0]);
    double x[HJ_LS_MAXDIM], u[HJ_REACH_MAXIN] = {0}, d[HJ_REACH_MAXIN] = {0};
    memcpy(x, x0, (size_t)nx * sizeof *x);
    tr->n = 0;
    tr->reached = tr->collided = 0;
    tr->min_obstacle = INFINITY;
    tr->t_left = INFINITY;
    double t = 0;
    for (long k = 0;; k++) {
        const double ob = set_value(&o->obstacle, t, x);
        tr->min_obstacle = ob < tr->min_obstacle ? ob : tr->min_obstacle;
        tr->collided |= ob <= 0;
        tr->t[k] = t;
        memcpy(tr->x + (size_t)k * (size_t)nx, x, (size_t)nx * sizeof *x);
        tr->value[k] = hj_ctrl_value(g, phi, x);
        tr->n = k + 1;
        for (int j = 0; j < nu; j++) tr->u[(size_t)k * (size_t)nu + (size_t)j] = 0;
        for (int j = 0; j < nx; j++)
            if (!isfinite(x[j])) return hj_error_set(err, HJ_ENONFINITE, "simulate: the state is not finite at t = %g", t);
        if (tr->t_left == INFINITY && outside_box(g, x) >= 0) tr->t_left = t;
        if (set_value(&o->target, t, x) <= 0) {
            tr->reached = 1;
            break;
        }
        if (k >= (long)steps) break;
        const double h = (double)(k + 1) * o->dt > o->t_max ? o->t_max - t : o->dt;
        double p[HJ_LS_MAXDIM];
        hj_ctrl_gradient(g, phi, x, p);
        if (!all_finite(p, nx))
            return hj_error_set(err, HJ_ENONFINITE,
                                "simulate: no finite gradient of the value at t = %g (a node near the state is not "
                                "finite: outside the reached set of a time-to-reach?)",
                                t);
        hj_reach_dyn_optimal(s, t, x, p, u, o->disturbance == HJ_CTRL_D_OPTIMAL ? d : NULL);
        if (o->disturbance == HJ_CTRL_D_FN) o->d_fn(t, x, d, o->d_ctx);
        for (int j = 0; j < nu; j++) tr->u[(size_t)k * (size_t)nu + (size_t)j] = u[j];
        /* RK4 with u and d held over the step. */
        double k1[HJ_LS_MAXDIM], k2[HJ_LS_MAXDIM], k3[HJ_LS_MAXDIM], k4[HJ_LS_MAXDIM], y[HJ_LS_MAXDIM];
        hj_reach_dyn_eval(s, t, x, u, d, k1);
        for (int j = 0; j < nx; j++) y[j] = x[j] + 0.5 * h * k1[j];
        hj_reach_dyn_eval(s, t + 0.5 * h, y, u, d, k2);
        for (int j = 0; j < nx; j++) y[j] = x[j] + 0.5 * h * k2[j];
        hj_reach_dyn_eval(s, t + 0.5 * h, y, u, d, k3);
        for (int j = 0; j < nx; j++) y[j] = x[j] + h * k3[j];
        hj_reach_dyn_eval(s, t + h, y, u, d, k4);
        for (int j = 0; j < nx; j++) x[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
        t = (k + 1 == (long)steps) ? o->t_max : t + h;
    }
    return HJ_OK;
}
