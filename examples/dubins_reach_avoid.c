/* # Reach-avoid set of a Dubins car with an obstacle
 *
 * **Problem.** x' = v cos th, y' = v sin th, th' = u with |u| <= w,
 * v = w = 1.  The states from which some control brings the car into the
 * disc of radius 0.5 about the origin within T = 1 while never entering the
 * box [-1.4, -0.6] x [0.2, 1.4]: a backward reachable tube with an
 * obstacle on (x, y, th) in [-2, 2]^2 x [0, 2 pi), th periodic.
 *
 * **Method.** phi_t + H(x, grad phi) = 0 with H = -min_u grad phi . f =
 * -v (p_x cos th + p_y sin th) + w |p_th|; Lax-Friedrichs with the exact
 * partial bounds v |cos th|, v |sin th|, w; the update restricted to
 * G <= 0 (a tube: the set only grows); ENO2 with second order TVD
 * Runge-Kutta; after every step phi = max(phi, -obstacle) (the mask keeps
 * the obstacle out of the set).
 *
 * **Checked number.** On the ray y = 0, th = pi (the car heads straight
 * at the target) the set ends exactly at x = 0.5 + v T = 1.5: the zero of
 * phi there must lie within 0.1 (one cell) of 1.5.
 */
#include <hj/hj.h>
#include <math.h>
#include <stdio.h>
#define TRY(call) if (call) return fprintf(stderr, "dubins: %s\n", err.msg), 1

static double ham(double t, const double *x, double phi, const double *p, void *ctx)
{
    (void)t, (void)phi, (void)ctx;
    return -(p[0] * cos(x[2]) + p[1] * sin(x[2])) + fabs(p[2]);
}
static double partial(double t, const double *x, const double *pmin, const double *pmax, int d, void *ctx)
{
    (void)t, (void)pmin, (void)pmax, (void)ctx;
    return d == 0 ? fabs(cos(x[2])) : d == 1 ? fabs(sin(x[2])) : 1.0;
}

int main(void)
{
    const long N[3] = {41, 41, 40};
    const double lo[3] = {-2, -2, 0}, hi[3] = {2, 2, 2 * HJ_PI * 39 / 40}, c[3] = {0, 0, 0};
    const double box_lo[3] = {-1.4, 0.2, -INFINITY}, box_hi[3] = {-0.6, 1.4, INFINITY};
    const int ignore_th = 2;
    const hj_ls_bc bc[3] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_PERIODIC, 0, 0}};
    hj_error err;
    hj_ls_grid g;
    TRY(hj_ls_grid_init(&g, 3, lo, hi, N, bc, &err));
    double *phi = hj_ls_alloc(&g), *obstacle = hj_ls_alloc(&g);
    if (!phi || !obstacle) return fprintf(stderr, "dubins: out of memory\n"), 1;
    TRY(hj_ls_shape_cylinder(&g, &ignore_th, 1, c, 0.5, phi, &err));
    TRY(hj_ls_shape_rectangle_corners(&g, box_lo, box_hi, obstacle, &err));
    hj_ls_shape_complement(&g, obstacle, obstacle);

    hj_ls_lax_friedrichs lf;
    hj_ls_lax_friedrichs_init(&lf, &g, HJ_LS_ENO2, HJ_LS_GLF, ham, partial, NULL);
    hj_ls_restrict tube;
    hj_ls_restrict_init(&tube, &g, &lf.base, 0);
    hj_ls_mask avoid = {&g, obstacle, 1};
    hj_ls_ode_opts opts;
    hj_ls_ode_defaults(&opts);
    opts.post = hj_ls_post_mask, opts.post_ctx = &avoid;
    const double tspan[2] = {0, 1};
    TRY(hj_ls_ode(2, &g, &tube.base, tspan, 2, phi, &opts, NULL, NULL, NULL, &err));

    double x0 = NAN; /* zero of phi on y = 0, th = pi, x > 0, by linear interpolation */
    for (long i = 20; i + 1 < N[0] && isnan(x0); i++) {
        const double a = phi[hj_ls_index(&g, (long[]){i, 20, 20})], b = phi[hj_ls_index(&g, (long[]){i + 1, 20, 20})];
        if (a <= 0 && b > 0) x0 = lo[0] + g.dx[0] * ((double)i + a / (a - b));
    }
    printf("dubins_reach_avoid: set ends at x = %.4f on the ray th = pi (exact 1.5)\n", x0);
    hj_ls_free(phi), hj_ls_free(obstacle);
    return fabs(x0 - 1.5) <= 0.1 ? 0 : 1;
}
