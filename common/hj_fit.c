#include "hj_fit.h"

#include <ceres/c_api.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

double hj_pair_order(double h1, double e1, double h2, double e2)
{
    if (!(h1 > 0 && h2 > 0 && e1 > 0 && e2 > 0) || h1 == h2) return NAN;
    return log(e1 / e2) / log(h1 / h2);
}

typedef struct {
    double x; /* log(h / h_ref) */
    double y; /* log e */
} fit_point;

/* Ceres cost: one residual per point, one parameter block (c, p). */
static int cost_fn(void *user, double **params, double *res, double **jac)
{
    const fit_point *pt = user;
    const double c = params[0][0], p = params[0][1];
    res[0] = pt->y - (c + p * pt->x);
    if (jac && jac[0]) {
        jac[0][0] = -1.0;
        jac[0][1] = -pt->x;
    }
    return 1;
}

/* Weight rho'(r^2) of the Huber loss (Ceres' convention:
 * rho(s) = s for s <= a^2, 2 a sqrt(s) - a^2 beyond). */
static double huber_weight(double r)
{
    const double a = HJ_FIT_HUBER_SCALE;
    return fabs(r) <= a ? 1.0 : a / fabs(r);
}

static int ceres_initialised = 0;



/* Run ceres_solve with stdout silenced; returns 0 if the silence could not be
 * arranged (the solve is then not run, so nothing is printed). */
static int solve_quietly(ceres_problem_t *problem)
{
    fflush(stdout);
    int saved = dup(STDOUT_FILENO);
    if (saved < 0) return 0;
    int devnull = open("/dev/null", O_WRONLY);
    if (devnull < 0) { close(saved); return 0; }
    dup2(devnull, STDOUT_FILENO);
    close(devnull);
    ceres_solve(problem);
    fflush(stdout); /* Ceres writes through C stdio buffers: drop them here */
    dup2(saved, STDOUT_FILENO);
    close(saved);
    return 1;
}

int hj_fit_order(const double *h, const double *e, int n, hj_order_fit *fit, hj_error *err)
{
    if (n < 2) return hj_error_set(err, HJ_EFIT, "order fit needs at least 2 points, got %d", n);
    double logref = 0;
    for (int k = 0; k < n; k++) {
        if (!isfinite(h[k]) || !isfinite(e[k]))
            return hj_error_set(err, HJ_ENONFINITE, "order fit: point %d is not finite", k);
        if (h[k] <= 0 || e[k] <= 0)
            return hj_error_set(err, HJ_EFIT, "order fit: point %d has h=%g, e=%g (both must be > 0)", k, h[k], e[k]);
        logref += log(h[k]) / n;
    }
    fit_point *pts = malloc(sizeof *pts * (size_t)n);
    if (!pts) return hj_error_set(err, HJ_ENOMEM, "order fit: out of memory");
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (int k = 0; k < n; k++) {
        pts[k].x = log(h[k]) - logref;
        pts[k].y = log(e[k]);
        sx += pts[k].x; sy += pts[k].y;
        sxx += pts[k].x * pts[k].x; sxy += pts[k].x * pts[k].y;
    }
    double den = n * sxx - sx * sx;
    if (!(den > 1e-14 * n * sxx)) {
        free(pts);
        return hj_error_set(err, HJ_EFIT, "order fit: all h are equal");
    }
    /* Least-squares start, then the robust fit. */
    double theta[2];
    theta[1] = (n * sxy - sx * sy) / den;
    theta[0] = (sy - theta[1] * sx) / n;
    fit->p_ls = theta[1];
    fit->n = n;

    if (!ceres_initialised) { ceres_init(); ceres_initialised = 1; }
    ceres_problem_t *problem = ceres_create_problem();
    void *loss = ceres_create_huber_loss_function_data(HJ_FIT_HUBER_SCALE);
    int sizes[1] = {2};
    double *blocks[1] = {theta};
    for (int k = 0; k < n; k++)
        ceres_problem_add_residual_block(problem, cost_fn, &pts[k], ceres_stock_loss_function, loss, 1, 1, sizes, blocks);
    int ran = solve_quietly(problem);
    ceres_free_problem(problem);
    ceres_free_stock_loss_function_data(loss);
    if (!ran) {
        free(pts);
        return hj_error_set(err, HJ_EFIT, "order fit: could not silence the solver's output");
    }

    /* Our own convergence check.  Ceres' C API stops at its fixed function
     * tolerance (1e-6 relative change of the cost) and its robust-loss
     * corrector converges only linearly here, so we measure how far the
     * answer is from the optimum: one exact Newton step of the Huber
     * objective, whose Hessian is the sum over the inlier points only
     * (rho is linear in |r| beyond the scale).  Accept when that step moves
     * p by less than HJ_FIT_P_TOL.  Meanwhile accumulate J^T W J and the
     * weighted residual variance for the standard error. */
    double g0 = 0, g1 = 0, h00 = 0, h01 = 0, h11 = 0;
    double a00 = 0, a01 = 0, a11 = 0, s2 = 0;
    for (int k = 0; k < n; k++) {
        double r = pts[k].y - (theta[0] + theta[1] * pts[k].x);
        double w = huber_weight(r), x = pts[k].x;
        g0 += -w * r; g1 += -w * r * x;
        if (fabs(r) <= HJ_FIT_HUBER_SCALE) { h00 += 1; h01 += x; h11 += x * x; }
        a00 += w; a01 += w * x; a11 += w * x * x;
        s2 += w * r * r;
    }
    free(pts);
    double hdet = h00 * h11 - h01 * h01;
    double dp = hdet > 0 ? fabs((h00 * g1 - h01 * g0) / hdet) : INFINITY;
    if (!isfinite(theta[0]) || !isfinite(theta[1]) || !(dp <= HJ_FIT_P_TOL))
        return hj_error_set(err, HJ_ENOCONV, "order fit did not converge (remaining Newton step in p: %.3g)", dp);
    double det = a00 * a11 - a01 * a01;
    fit->n = n;
    fit->p = theta[1];
    fit->C = exp(theta[0] - theta[1] * logref);
    fit->p_se = (n > 2 && det > 0) ? sqrt(s2 / (n - 2) * a00 / det) : NAN;
    return HJ_OK;
}
