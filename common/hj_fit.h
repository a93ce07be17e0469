/* hj_fit.h -- convergence orders.
 *
 * Pairwise order between two resolutions (the papers' "order" columns):
 *     p_k = log(e_k / e_{k+1}) / log(h_k / h_{k+1}).
 *
 * Fitted order: the model e = C h^p is fitted to all points of a
 * convergence study by nonlinear least squares with Ceres Solver (its C API,
 * ceres/c_api.h).  Residuals are taken in log space,
 *     r_k = log e_k - (c + p log(h_k / h_ref)),  c = log C(h_ref),
 * so that every point weighs by its relative deviation, and they pass
 * through a Huber loss with scale a = 0.2 (quadratic for |r| <= a, i.e. a
 * deviation up to about 20 %, linear beyond), so that one pre-asymptotic
 * point pulls the slope with a bounded force.  Huber was chosen over Cauchy
 * because it keeps the problem convex: the fit is unique and independent of
 * the starting point, and Ceres converges in a few steps (with Cauchy it
 * converged only linearly here and the C API, whose tolerances cannot be
 * set, stopped it with the slope still ~1e-3 off).  h_ref is the geometric mean of the h_k, which makes c and p nearly
 * uncorrelated.  The standard error of p comes from the Gauss-Newton
 * covariance s^2 (J^T W J)^{-1} at the solution, with W the loss weights
 * rho'(r_k^2) and s^2 = sum W r^2 / (n - 2); it is NaN for n = 2 (the fit
 * is then exact and carries no error estimate).
 *
 * Ceres' C API prints its progress on stdout and cannot be configured; the
 * fit therefore redirects file descriptor 1 to /dev/null around the solve
 * (not thread-safe: call it from one thread).  The C API also fixes the
 * stopping tolerances; convergence is checked here with an exact Newton
 * step of the Huber objective: the fit is accepted when that step would
 * move p by less than HJ_FIT_P_TOL = 1e-3 (orders are printed with two
 * decimals), and HJ_ENOCONV is returned otherwise.
 */
#ifndef HJ_FIT_H
#define HJ_FIT_H

#include "hj_error.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    double p;      /* fitted order */
    double p_se;   /* standard error of p (NaN when n = 2) */
    double C;      /* fitted constant: e = C h^p */
    double p_ls;   /* plain least-squares slope, for comparison */
    int n;         /* number of points used */
} hj_order_fit;

/* Scale of the Huber loss in log units (see above). */
#define HJ_FIT_HUBER_SCALE 0.2
/* Accuracy to which the fitted order is checked (see above). */
#define HJ_FIT_P_TOL 1e-3

/* Pairwise order between (h1, e1) and (h2, e2); NaN if not defined. */
double hj_pair_order(double h1, double e1, double h2, double e2);

/* Fit e = C h^p to n >= 2 points with h > 0, e > 0, all finite.  When the
 * robust fit does not converge (HJ_ENOCONV: its Newton check moves p by
 * more than HJ_FIT_P_TOL, or cannot be made because fewer than two points
 * lie within the Huber scale of the line, as when they scatter about any
 * line by more than it), fit->p_ls and fit->n are still set: the plain
 * least-squares slope of the same points, which the caller may show as
 * such; p, p_se and C are not set. */
int hj_fit_order(const double *h, const double *e, int n, hj_order_fit *fit, hj_error *err);

#ifdef __cplusplus
}
#endif

#endif
