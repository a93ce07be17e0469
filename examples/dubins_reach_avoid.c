/* # Reach-avoid set of a Dubins car with an obstacle
 *
 * **Problem.** x' = cos th, y' = sin th, th' = u with |u| <= 1 (a
 * control-affine system: f = (cos th, sin th, 0), G = (0, 0, 1)).  The
 * states from which some control brings the car into the disc of radius
 * 0.5 about the origin within T = 1 while never entering the box
 * [-1.4, -0.6] x [0.2, 1.4]: a backward reachable tube with an obstacle on
 * (x, y, th) in [-2, 2]^2 x [0, 2 pi), th periodic, given by its period.
 *
 * **Method.** hj_reach_solve: the Hamiltonian and the Lax-Friedrichs
 * bounds follow from the dynamics object (the control minimises, it
 * reaches); ENO2 with second order TVD Runge-Kutta; after every step
 * phi = max(min(phi, target), -obstacle).  Grid 41 x 41 x 40.
 *
 * **Checked number.** On the ray y = 0, th = pi (heading at the target)
 * the set ends at x = 0.5 + T = 1.5: phi(1.4, 0, pi) < 0 < phi(1.6, 0, pi).
 * With an argument, writes the slice th = pi (x y phi) there for a figure.
 */
#include <hj/hj.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#define TRY(call) if (call) return fprintf(stderr, "dubins: %s\n", err.msg), 1

static void f(double t, const double *x, double *o, void *c) { (void)t, (void)c, o[0] = cos(x[2]), o[1] = sin(x[2]), o[2] = 0; }
static void G(double t, const double *x, double *o, void *c) { (void)t, (void)x, (void)c, o[0] = o[1] = 0, o[2] = 1; }
static double target(double t, const double *x, void *c) { (void)t, (void)c; return hypot(x[0], x[1]) - 0.5; }
static double obstacle(double t, const double *x, void *c) { (void)t, (void)c; return fmax(fabs(x[0] + 1) - 0.4, fabs(x[1] - 0.8) - 0.6); }

int main(int argc, char **argv)
{
    if (argc > 2 || (argc > 1 && argv[1][0] == '-')) { /* --help: the usage, exit 0; a bad command line: 2 */
        const int help = argc == 2 && !strcmp(argv[1], "--help");
        return fputs("usage: dubins_reach_avoid [SLICE.dat]\n"
                     "Reach-avoid tube of a Dubins car with an obstacle; checks the edge of the set;\n"
                     "SLICE.dat: the slice th = pi (x y phi).\n",
                     help ? stdout : stderr), help ? 0 : 2;
    }
    const hj_ls_bc ex = {HJ_LS_BC_EXTRAP_AWAY, 0, 0}, bc[3] = {ex, ex, {HJ_LS_BC_PERIODIC, 0, 0}};
    hj_error err; hj_ls_grid g; hj_reach_dyn car; hj_reach_problem pb;
    TRY(hj_ls_grid_init_period(&g, 3, (double[]){-2, -2, 0}, (double[]){2, 2, 2 * HJ_PI}, (long[]){41, 41, 40}, bc, &err));
    hj_reach_dyn_init(&car, 3, f, NULL);
    hj_reach_dyn_control_box(&car, G, 1, (double[]){-1}, (double[]){1});
    hj_reach_problem_init(&pb, &g, &car);
    pb.target.fn = target, pb.obstacle.fn = obstacle, pb.horizon = 1;
    double *phi = hj_ls_alloc(&g);
    TRY(!phi || hj_reach_solve(&pb, phi, NULL, NULL, &err));
    const double in = hj_ctrl_value(&g, phi, (double[]){1.4, 0, HJ_PI}), out = hj_ctrl_value(&g, phi, (double[]){1.6, 0, HJ_PI});
    printf("dubins_reach_avoid: phi(1.4, 0, pi) = %.4f, phi(1.6, 0, pi) = %.4f (the set ends at 1.5)\n", in, out);
    FILE *fp = argc > 1 ? fopen(argv[1], "w") : NULL; /* the slice th = pi (node 20) */
    if (argc > 1 && !fp) return perror(argv[1]), 1;
    for (long j = 0; fp && j < 41; j++, fputc('\n', fp))
        for (long i = 0; i < 41; i++) fprintf(fp, "%g %g %g\n", g.min[0] + g.dx[0] * (double)i, g.min[1] + g.dx[1] * (double)j, phi[hj_ls_index(&g, (long[]){i, j, 20})]);
    if (fp) fclose(fp);
    hj_ls_free(phi);
    return in < 0 && out > 0 ? 0 : 1;
}
