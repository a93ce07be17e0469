/* # Minimum time of a double integrator
 *
 * **Problem.** x' = v, v' = u, |u| <= 1.  The time to reach the target
 * {T0 <= 1}, where T0(x, v) is the minimum time to the origin (bang-bang
 * with one switch: T0 = v + 2 sqrt(x + v^2 / 2) above the switching curve
 * x = -v |v| / 2, -v + 2 sqrt(-x + v^2 / 2) below it), is T0 - 1 exactly.
 *
 * **Method.** hj_reach_solve with the time-to-reach output: a backward
 * reachable tube to tau = 0.8 on [-2, 2]^2, 81 x 81 nodes, ENO2, RK2; the
 * first tau at which each node's value drops to 0 (linear in the step).
 *
 * **Checked number.** The time-to-reach at (0.5, 0), T0 - 1 = 2 sqrt(0.5)
 * - 1 = 0.4142, within 0.05 (the grid sequence and its fitted order are
 * in make check: studies/reach).  With an argument, writes "x v ttr" there
 * (inf where the target is not reached by tau = 0.8).
 */
#include <hj/hj.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#define TRY(call) if (call) return fprintf(stderr, "double_integrator: %s\n", err.msg), 1

static void f(double t, const double *x, double *o, void *c) { (void)t, (void)c, o[0] = x[1], o[1] = 0; }
static void G(double t, const double *x, double *o, void *c) { (void)t, (void)x, (void)c, o[0] = 0, o[1] = 1; }
static double T0(double x, double v) { return x + 0.5 * v * fabs(v) > 0 ? v + 2 * sqrt(x + 0.5 * v * v) : -v + 2 * sqrt(-x + 0.5 * v * v); }
static double target(double t, const double *x, void *c) { (void)t, (void)c; return T0(x[0], x[1]) - 1; }

int main(int argc, char **argv)
{
    if (argc > 2 || (argc > 1 && argv[1][0] == '-')) { /* --help: the usage, exit 0; a bad command line: 2 */
        const int help = argc == 2 && !strcmp(argv[1], "--help");
        return fputs("usage: double_integrator [OUT.dat]\n"
                     "Minimum time of a double integrator, checked against the closed form;\n"
                     "OUT.dat: the time-to-reach on the grid (x v ttr).\n",
                     help ? stdout : stderr), help ? 0 : 2;
    }
    const hj_ls_bc ex = {HJ_LS_BC_EXTRAP_AWAY, 0, 0}, bc[2] = {ex, ex};
    hj_error err; hj_ls_grid g; hj_reach_dyn s; hj_reach_problem pb;
    TRY(hj_ls_grid_init(&g, 2, (double[]){-2, -2}, (double[]){2, 2}, (long[]){81, 81}, bc, &err));
    hj_reach_dyn_init(&s, 2, f, NULL);
    hj_reach_dyn_control_box(&s, G, 1, (double[]){-1}, (double[]){1});
    hj_reach_problem_init(&pb, &g, &s);
    pb.target.fn = target, pb.horizon = 0.8;
    double *phi = hj_ls_alloc(&g), *ttr = hj_ls_alloc(&g);
    TRY(!phi || !ttr || hj_reach_solve(&pb, phi, ttr, NULL, &err));
    const double t = ttr[hj_ls_index(&g, (long[]){50, 40})], exact = T0(0.5, 0) - 1;
    printf("double_integrator: time-to-reach at (0.5, 0) = %.4f, exact %.4f\n", t, exact);
    FILE *fp = argc > 1 ? fopen(argv[1], "w") : NULL;
    if (argc > 1 && !fp) return perror(argv[1]), 1;
    for (long j = 0; fp && j < 81; j++, fputc('\n', fp))
        for (long i = 0; i < 81; i++) fprintf(fp, "%g %g %g\n", -2 + 0.05 * (double)i, -2 + 0.05 * (double)j, ttr[hj_ls_index(&g, (long[]){i, j})]);
    if (fp) fclose(fp);
    hj_ls_free(phi), hj_ls_free(ttr);
    return fabs(t - exact) <= 0.05 ? 0 : 1;
}
