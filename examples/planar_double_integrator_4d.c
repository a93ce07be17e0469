/* # A 4-D system: a point mass in the plane with bounded acceleration
 *
 * **Problem.** (x, y, vx, vy)' = (vx, vy, ax, ay) with |a| <= 1 (a ball,
 * not a box: the two axes share one thrust).  Target: the disc of radius
 * 0.5 about the origin in position, any velocity.  From rest at distance
 * d the fastest way in is full thrust straight at it: T = sqrt(2 (d - 0.5)).
 *
 * **Method.** hj_reach_solve with the time-to-reach output on [-1.6, 1.6]^2
 * x [-1.2, 1.2]^2, 13^4 nodes (ENO2, RK2, Lax-Friedrichs bounds from the
 * ball: |a_i| <= 1 in each axis), tube to tau = 1.
 *
 * **Checked number.** Time-to-reach from rest at (0.8, 0):
 * sqrt(2 * 0.3) = 0.7746, within 0.1.
 * With an argument, writes the slice vx = vy = 0 (x y ttr) there.
 */
#include <hj/hj.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#define TRY(call) if (call) return fprintf(stderr, "planar_double_integrator_4d: %s\n", err.msg), 1

static void f(double t, const double *x, double *o, void *c) { (void)t, (void)c, o[0] = x[2], o[1] = x[3], o[2] = o[3] = 0; }
static void G(double t, const double *x, double *o, void *c) { (void)t, (void)x, (void)c, o[0] = o[1] = o[2] = o[3] = o[5] = o[6] = 0, o[4] = o[7] = 1; }
static double target(double t, const double *x, void *c) { (void)t, (void)c; return hypot(x[0], x[1]) - 0.5; }

int main(int argc, char **argv)
{
    if (argc > 2 || (argc > 1 && argv[1][0] == '-')) { /* --help: the usage, exit 0; a bad command line: 2 */
        const int help = argc == 2 && !strcmp(argv[1], "--help");
        return fputs("usage: planar_double_integrator_4d [SLICE.dat]\n"
                     "4-D point mass with a thrust disc; checks the time from rest;\n"
                     "SLICE.dat: the slice vx = vy = 0 (x y ttr).\n",
                     help ? stdout : stderr), help ? 0 : 2;
    }
    const hj_ls_bc ex = {HJ_LS_BC_EXTRAP_AWAY, 0, 0}, bc[4] = {ex, ex, ex, ex};
    hj_error err; hj_ls_grid g; hj_reach_dyn s; hj_reach_problem pb;
    TRY(hj_ls_grid_init(&g, 4, (double[]){-1.6, -1.6, -1.2, -1.2}, (double[]){1.6, 1.6, 1.2, 1.2}, (long[]){13, 13, 13, 13}, bc, &err));
    hj_reach_dyn_init(&s, 4, f, NULL);
    hj_reach_dyn_control_ball(&s, G, 2, (double[]){0, 0}, 1);
    hj_reach_problem_init(&pb, &g, &s);
    pb.target.fn = target, pb.horizon = 1;
    double *phi = hj_ls_alloc(&g), *ttr = hj_ls_alloc(&g);
    TRY(!phi || !ttr || hj_reach_solve(&pb, phi, ttr, NULL, &err));
    const double t = ttr[hj_ls_index(&g, (long[]){9, 6, 6, 6})], exact = sqrt(2 * (0.8 - 0.5)); /* x = 0.8 */
    printf("planar_double_integrator_4d: time-to-reach from rest at (0.8, 0) = %.4f, exact %.4f\n", t, exact);
    FILE *fp = argc > 1 ? fopen(argv[1], "w") : NULL;
    if (argc > 1 && !fp) return perror(argv[1]), 1;
    for (long j = 0; fp && j < 13; j++, fputc('\n', fp))
        for (long i = 0; i < 13; i++) fprintf(fp, "%g %g %g\n", g.min[0] + g.dx[0] * (double)i, g.min[1] + g.dx[1] * (double)j, ttr[hj_ls_index(&g, (long[]){i, j, 6, 6})]);
    if (fp) fclose(fp);
    hj_ls_free(phi), hj_ls_free(ttr);
    return fabs(t - exact) <= 0.1 ? 0 : 1;
}
