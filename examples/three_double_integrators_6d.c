/* # A 6-D system with a known answer: three double integrators
 *
 * **Problem.** Three decoupled double integrators x_k' = v_k, v_k' = u_k,
 * |u_k| <= 1 (a box of three controls), target the box |x_k|, |v_k| <= 0.5.
 * The states from which the target is reached at T = 0.5 (a backward
 * reachable set) form the product of three copies of the 2-D set, since
 * each control steers its own pair.
 *
 * **Method.** hj_reach_solve in 6-D on [-1.5, 1.5]^6 with 7^6 nodes and in
 * 2-D on the same 7 x 7 nodes (ENO2, RK2); the 6-D set is compared node
 * by node with the product of the 2-D sets.
 *
 * **Checked number.** The number of nodes where the two sets differ: 0 on
 * this grid.  With an argument, writes the slice x2 = v2 = x3 = v3 = 0 of
 * the 6-D value and the 2-D value (x v phi6 phi2) there.
 */
#include <hj/hj.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#define TRY(call) if (call) return fprintf(stderr, "three_double_integrators_6d: %s\n", err.msg), 1

static void f(double t, const double *x, double *o, void *c) { (void)t, (void)c; for (int k = 0; k < 6; k += 2) o[k] = x[k + 1], o[k + 1] = 0; }
static void G(double t, const double *x, double *o, void *c) { (void)t, (void)x, (void)c; for (int q = 0; q < 18; q++) o[q] = q == 3 || q == 10 || q == 17; }
static void G2(double t, const double *x, double *o, void *c) { (void)t, (void)x, (void)c, o[0] = 0, o[1] = 1; }
static double box(double t, const double *x, void *c) { (void)t; double m = -INFINITY; for (int k = 0; k < *(int *)c; k++) m = fmax(m, fabs(x[k]) - 0.5); return m; }

int main(int argc, char **argv)
{
    if (argc > 2 || (argc > 1 && argv[1][0] == '-')) { /* --help: the usage, exit 0; a bad command line: 2 */
        const int help = argc == 2 && !strcmp(argv[1], "--help");
        return fputs("usage: three_double_integrators_6d [SLICE.dat]\n"
                     "6-D: three double integrators; checks the set against the product of the 2-D sets;\n"
                     "SLICE.dat: the slice x2 = v2 = x3 = v3 = 0 (x v phi6 phi2).\n",
                     help ? stdout : stderr), help ? 0 : 2;
    }
    const long N = 7;
    hj_ls_bc bc[6];
    double lo[6], hi[6];
    long n[6];
    int dims[2] = {6, 2};
    for (int d = 0; d < 6; d++) bc[d] = (hj_ls_bc){HJ_LS_BC_EXTRAP_AWAY, 0, 0}, lo[d] = -1.5, hi[d] = 1.5, n[d] = N;
    hj_error err; hj_ls_grid g6, g2; hj_reach_dyn s6, s2; hj_reach_problem pb;
    TRY(hj_ls_grid_init(&g6, 6, lo, hi, n, bc, &err) || hj_ls_grid_init(&g2, 2, lo, hi, n, bc, &err));
    hj_reach_dyn_init(&s6, 6, f, NULL);
    hj_reach_dyn_control_box(&s6, G, 3, (double[]){-1, -1, -1}, (double[]){1, 1, 1});
    hj_reach_dyn_init(&s2, 2, f, NULL);
    hj_reach_dyn_control_box(&s2, G2, 1, (double[]){-1}, (double[]){1});
    double *phi6 = hj_ls_alloc(&g6), *phi2 = hj_ls_alloc(&g2);
    TRY(!phi6 || !phi2);
    hj_reach_problem_init(&pb, &g6, &s6);
    pb.kind = HJ_REACH_BRS, pb.target.fn = box, pb.target.ctx = &dims[0], pb.horizon = 0.5;
    TRY(hj_reach_solve(&pb, phi6, NULL, NULL, &err));
    hj_reach_problem_init(&pb, &g2, &s2);
    pb.kind = HJ_REACH_BRS, pb.target.fn = box, pb.target.ctx = &dims[1], pb.horizon = 0.5;
    TRY(hj_reach_solve(&pb, phi2, NULL, NULL, &err));
    long differ = 0, inside = 0;
    for (size_t r = 0; r < g6.rows; r++) {
        long i[6];
        const size_t k = hj_ls_row(&g6, r, i);
        for (i[0] = 0; i[0] < N; i[0]++) {
            int prod = 1;
            for (int q = 0; q < 6; q += 2) prod &= phi2[hj_ls_index(&g2, (long[]){i[q], i[q + 1]})] <= 0;
            const int in6 = phi6[k + (size_t)i[0]] <= 0;
            inside += in6, differ += in6 != prod;
        }
    }
    printf("three_double_integrators_6d: %ld of %zu nodes inside the 6-D set, %ld differ from the product of the 2-D sets\n", inside, g6.nodes, differ);
    FILE *fp = argc > 1 ? fopen(argv[1], "w") : NULL;
    if (argc > 1 && !fp) return perror(argv[1]), 1;
    for (long j = 0; fp && j < N; j++, fputc('\n', fp))
        for (long i = 0; i < N; i++) fprintf(fp, "%g %g %g %g\n", -1.5 + g2.dx[0] * (double)i, -1.5 + g2.dx[1] * (double)j, phi6[hj_ls_index(&g6, (long[]){i, j, 3, 3, 3, 3})], phi2[hj_ls_index(&g2, (long[]){i, j})]);
    if (fp) fclose(fp);
    hj_ls_free(phi6), hj_ls_free(phi2);
    return differ == 0 && inside > 0 ? 0 : 1;
}
