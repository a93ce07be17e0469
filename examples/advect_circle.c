/* # Level set advection: a circle carried by a constant wind
 *
 * **Problem.** phi_t + v . grad phi = 0 on [-1, 1]^2, periodic, with
 * v = (1, 0.5) and phi_0 the signed distance to the circle of radius 0.3
 * centred at (-0.4, -0.2).  At t = 0.8 the circle has moved to (0.4, 0.2)
 * without changing shape: its area stays pi 0.3^2.
 *
 * **Method.** The level set kernel (Mitchell's toolbox, section 3):
 * convection term with fifth order WENO upwinding (hj_ls_convection),
 * third order TVD Runge-Kutta with CFL factor 0.5 (hj_ls_ode), area of
 * {phi < 0} by linear interpolation on simplices (hj_ls_measure).
 *
 * **Parameters.** N = 101 nodes per dimension (change `N` below).
 *
 * **Checked number.** The relative area error at t = 0.8: below 1e-3
 * (exit status 1 otherwise).
 */
#include <hj/hj.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

int main(int argc, char **argv)
{
    if (argc > 1) { /* --help: the usage, exit 0; a bad command line: 2 */
        const int help = argc == 2 && !strcmp(argv[1], "--help");
        return fputs("usage: advect_circle\n"
                     "A circle carried by a constant wind (WENO5, TVD RK3); checks its area. No arguments.\n",
                     help ? stdout : stderr), help ? 0 : 2;
    }
    enum { N = 101 };
    const double lo[2] = {-1, -1}, hi[2] = {1, 1}, c0[2] = {-0.4, -0.2}, r = 0.3;
    const hj_ls_bc bc[2] = {{HJ_LS_BC_PERIODIC, 0, 0}, {HJ_LS_BC_PERIODIC, 0, 0}};
    const long n[2] = {N, N};
    hj_error err;
    hj_ls_grid g;
    /* Periodic: max is the last node before the period repeats. */
    const double max[2] = {hi[0] - (hi[0] - lo[0]) / N, hi[1] - (hi[1] - lo[1]) / N};
    if (hj_ls_grid_init(&g, 2, lo, max, n, bc, &err)) return fprintf(stderr, "%s\n", err.msg), 1;
    double *phi = hj_ls_alloc(&g);
    if (!phi) return fprintf(stderr, "out of memory\n"), 1;
    if (hj_ls_shape_sphere(&g, c0, r, phi, &err)) return fprintf(stderr, "%s\n", err.msg), 1;

    hj_ls_convection wind;
    hj_ls_convection_init(&wind, &g, HJ_LS_WENO5A);
    wind.velocity[0] = 1.0;
    wind.velocity[1] = 0.5;
    const double tspan[2] = {0.0, 0.8};
    hj_ls_ode_stats st;
    if (hj_ls_ode(3, &g, &wind.base, tspan, 2, phi, NULL, NULL, NULL, &st, &err))
        return fprintf(stderr, "%s\n", err.msg), 1;

    double area;
    if (hj_ls_measure(&g, phi, &area, &err)) return fprintf(stderr, "%s\n", err.msg), 1;
    const double exact = HJ_PI * r * r, rel = fabs(area - exact) / exact;
    printf("advect_circle: N = %d, %ld steps, area %.6f, exact %.6f, relative error %.2e\n", N, st.steps, area,
           exact, rel);
    hj_ls_free(phi);
    return rel < 1e-3 ? 0 : 1;
}
