/* # Avoid tube of a Dubins car, with the level set kernel and a Hamiltonian of one's own
 *
 * **Problem.** x' = v cos th, y' = v sin th, th' = u with |u| <= w (v = w =
 * 1).  The states from which the car cannot keep out of the disc of radius
 * 0.5 about the origin for T = 1, whatever it steers: the backward
 * reachable tube of the disc with the control maximising (avoiding), on
 * (x, y, th) in [-2, 2]^2 x [0, 2 pi), th periodic, given by its period.
 *
 * **Method.** The kernel integrates D_t phi + H(x, grad phi) = 0 forward
 * in the time to go from phi_0 = the signed distance to the disc (a
 * cylinder in th).  The control maximises p . f, so
 * H(x, p) = -max_u p . f = -(v (p_x cos th + p_y sin th) + w |p_th|);
 * the Lax-Friedrichs bounds |dH/dp_d| are v |cos th|, v |sin th| and w,
 * independent of p (`range_free = 1`).  WENO5, local Lax-Friedrichs,
 * third order TVD Runge-Kutta; the term is wrapped in `hj_ls_restrict`
 * (D_t phi <= 0: a tube, the set only grows).  The volume counts the
 * heading's full period (`hj_ls_measure_periodic`).  Grids 21 x 21 x 20
 * and 41 x 41 x 40 (N nodes per period in th).
 *
 * **Checked number.** Heading straight at the disc (y = 0, th = pi), the
 * car escapes by turning at once, on a circle of radius v / w = 1 about
 * (x, 1) or (x, -1); it misses the disc when sqrt(x^2 + 1) - 1 >= 0.5, so the
 * tube's edge on that ray is at x = sqrt(1.25) = 1.1180.  The fine grid's
 * edge (the zero of the interpolated phi) must lie within a tenth of a
 * cell (0.01) of it: measured 1.1216 (1.1250 on the coarse grid, 1.1192
 * on 81 x 81 x 80).  The two volumes are printed (7.230 and 7.306; 7.327
 * on 81 x 81 x 80): they differ by 1 %, then 0.3 %, so compare two grids
 * before trusting the third digit.  With an argument, writes the fine
 * grid's slice th = pi (x y phi, gnuplot's grid format) there.
 */
#include <hj/hj.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#define TRY(call) if (call) return fprintf(stderr, "dubins_avoid_kernel: %s\n", err.msg), 1

static const double v = 1, w = 1;

static double ham(double t, const double *x, double phi, const double *p, void *ctx)
{
    (void)t, (void)phi, (void)ctx;
    return -(v * (p[0] * cos(x[2]) + p[1] * sin(x[2])) + w * fabs(p[2]));
}

static double partial(double t, const double *x, const double *pmin, const double *pmax, int d, void *ctx)
{
    (void)t, (void)pmin, (void)pmax, (void)ctx;
    return d == 0 ? v * fabs(cos(x[2])) : d == 1 ? v * fabs(sin(x[2])) : w;
}

/* The tube on n x n x (n - 1) nodes: its volume and where phi turns
 * positive along y = 0, th = pi (bisection of the interpolant on [0.6, 2]). */
static int tube(long n, const char *slice, double *vol, double *edge)
{
    const hj_ls_bc ex = {HJ_LS_BC_EXTRAP_AWAY, 0, 0}, bc[3] = {ex, ex, {HJ_LS_BC_PERIODIC, 0, 0}};
    hj_error err; hj_ls_grid g; hj_ls_lax_friedrichs lf; hj_ls_restrict r;
    TRY(hj_ls_grid_init_period(&g, 3, (double[]){-2, -2, 0}, (double[]){2, 2, 2 * HJ_PI}, (long[]){n, n, n - 1}, bc, &err));
    double *phi = hj_ls_alloc(&g);
    TRY(!phi || hj_ls_shape_cylinder(&g, (int[]){2}, 1, (double[]){0, 0, 0}, 0.5, phi, &err));
    hj_ls_lax_friedrichs_init(&lf, &g, HJ_LS_WENO5A, HJ_LS_LLF, ham, partial, NULL);
    lf.range_free = 1;
    hj_ls_restrict_init(&r, &g, &lf.base, 0);
    TRY(hj_ls_ode(3, &g, &r.base, (double[]){0, 1}, 2, phi, NULL, NULL, NULL, NULL, &err));
    TRY(hj_ls_measure_periodic(&g, phi, 2, vol, &err));
    double a = 0.6, b = 2;
    for (int k = 0; k < 40; k++) {
        const double m = (a + b) / 2;
        *(hj_ctrl_value(&g, phi, (double[]){m, 0, HJ_PI}) < 0 ? &a : &b) = m;
    }
    *edge = (a + b) / 2;
    FILE *fp = slice ? fopen(slice, "w") : NULL; /* th = pi is node (n - 1) / 2 */
    if (slice && !fp) return perror(slice), hj_ls_free(phi), 1;
    for (long j = 0; fp && j < n; j++, fputc('\n', fp))
        for (long i = 0; i < n; i++)
            fprintf(fp, "%g %g %g\n", g.min[0] + g.dx[0] * (double)i, g.min[1] + g.dx[1] * (double)j,
                    phi[hj_ls_index(&g, (long[]){i, j, (n - 1) / 2})]);
    if (fp) fclose(fp);
    hj_ls_free(phi);
    return 0;
}

int main(int argc, char **argv)
{
    double v21, e21, v41, e41;
    if (argc > 2 || (argc > 1 && argv[1][0] == '-')) { /* --help: the usage, exit 0; a bad command line: 2 */
        const int help = argc == 2 && !strcmp(argv[1], "--help");
        return fputs("usage: dubins_avoid_kernel [SLICE.dat]\n"
                     "Avoid tube of a Dubins car on the level set kernel; checks the edge of the set;\n"
                     "SLICE.dat: the fine grid's slice th = pi (x y phi).\n",
                     help ? stdout : stderr), help ? 0 : 2;
    }
    if (tube(21, NULL, &v21, &e21) || tube(41, argc > 1 ? argv[1] : NULL, &v41, &e41)) return 1;
    printf("dubins_avoid_kernel: volume %.4f (21^2 x 20), %.4f (41^2 x 40); edge at y = 0, th = pi: %.4f, %.4f "
           "(exact sqrt(1.25) = %.4f)\n", v21, v41, e21, e41, sqrt(1.25));
    return fabs(e41 - sqrt(1.25)) < 0.01 ? 0 : 1;
}
