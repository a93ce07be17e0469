/* bench_reach -- the speed and memory of 6-D reachability on the level set
 * kernel: three decoupled double integrators with a box target (the
 * system of product6d in reach_checks), a backward reachable set run for a
 * few time steps with hj_reach_solve.
 *
 *   first order: upwind first order, forward Euler: node updates per
 *                second (nodes x steps / seconds);
 *   WENO5/RK3:   node-stage updates per second (nodes x 3 steps / s);
 *   memory:      bytes per interior node of the run's arrays (the value,
 *                the previous value, the integrator's stage and time
 *                derivative: 4 arrays with their ghost layers; and the
 *                one-sided derivatives the Lax-Friedrichs term keeps,
 *                2 x 6 interior arrays).
 *
 * --per-node and --no-keep-derivs run hj_reach's reference paths (the
 * kernel's per-node callbacks, derivatives computed twice), same bits, to
 * measure what the batched rows and the kept derivatives gain.
 *
 * Writes bench_reach.tsv in --out-dir, with rates per wall-clock second
 * and per CPU second (all threads): the first moves with the machine's
 * load, compare rates of runs made together.
 */
#include <math.h>
#include <stdio.h>
#include <time.h>

#include "hj.h"

static const char *prog = "bench_reach";

static void f(double t, const double *x, double *o, void *c)
{
    (void)t, (void)c;
    for (int k = 0; k < 6; k += 2) o[k] = x[k + 1], o[k + 1] = 0;
}
static void G(double t, const double *x, double *o, void *c)
{
    (void)t, (void)x, (void)c;
    for (int q = 0; q < 18; q++) o[q] = q == 3 || q == 10 || q == 17;
}
static double box(double t, const double *x, void *c)
{
    (void)t, (void)c;
    double m = -INFINITY;
    for (int k = 0; k < 6; k++) m = fmax(m, fabs(x[k]) - 0.5);
    return m;
}

int main(int argc, char **argv)
{
    long N = 11, steps = 3;
    const char *out_dir = ".";
    int per_node = 0, no_keep = 0;
    hj_cli_opt opts[] = {
        {.name = "--N", .type = HJ_OPT_LONG, .value = &N, .min = 5, .max = 40, .metavar = "N",
         .help = "nodes in each of the 6 dimensions"},
        {.name = "--steps", .type = HJ_OPT_LONG, .value = &steps, .min = 1, .max = 1000, .metavar = "K",
         .help = "time steps of each run"},
        {.name = "--per-node", .type = HJ_OPT_FLAG, .value = &per_node,
         .help = "the kernel's per-node callbacks instead of batched rows"},
        {.name = "--no-keep-derivs", .type = HJ_OPT_FLAG, .value = &no_keep,
         .help = "compute the one-sided derivatives twice instead of keeping them"},
        {.name = "--out-dir", .type = HJ_OPT_STRING, .value = &out_dir, .metavar = "DIR",
         .help = "where to write bench_reach.tsv"},
    };
    hj_cli_spec spec = {prog, "6-D reachability: node updates per second and bytes per node", opts,
                        (int)(sizeof opts / sizeof opts[0]), NULL};
    hj_cli_parse_or_exit(&spec, argc, argv);
    hj_error err;
    char path[1024];
    snprintf(path, sizeof path, "%s/bench_reach.tsv", out_dir);
    if (hj_out_check(path, &err)) hj_cli_fail(prog, HJ_EXIT_USAGE, "%s", err.msg);
    hj_ls_bc bc[6];
    double lo[6], hi[6];
    long n[6];
    for (int d = 0; d < 6; d++) bc[d] = (hj_ls_bc){HJ_LS_BC_EXTRAP_AWAY, 0, 0}, lo[d] = -1.5, hi[d] = 1.5, n[d] = N;
    hj_ls_grid g;
    if (hj_ls_grid_init(&g, 6, lo, hi, n, bc, &err)) hj_cli_fail(prog, HJ_EXIT_USAGE, "%s", err.msg);
    hj_reach_dyn s;
    hj_reach_dyn_init(&s, 6, f, NULL);
    hj_reach_dyn_control_box(&s, G, 3, (double[]){-1, -1, -1}, (double[]){1, 1, 1});
    double *phi = hj_ls_alloc(&g);
    if (!phi) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory for %zu nodes", g.nodes);
    /* The CFL step of this system: sum_d alpha_d / dx_d with |v| <= 1.5
     * and |u| <= 1, times 0.5; the horizon covers the steps asked for. */
    const double dt = 0.5 / (3 * (1.5 + 1.0) / g.dx[0]);
    hj_out o;
    if (hj_out_open(&o, path, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    fprintf(o.fp, "# three double integrators, BRS, %ld^6 = %zu nodes (%zu with ghosts), %ld steps a run, %s, %s\n", N,
            g.nodes, g.total, steps, per_node ? "per-node callbacks" : "batched rows",
            no_keep ? "derivatives computed twice" : "derivatives kept");
    fprintf(o.fp, "scheme\tnodes\tsteps\tstages\tseconds\tupdates_per_s\tcpu_seconds\tupdates_per_cpu_s\tbytes_per_node\n");
    const int scheme[2] = {HJ_LS_UPWIND_FIRST, HJ_LS_WENO5A}, order[2] = {1, 3};
    const char *name[2] = {"first-order-euler", "weno5-rk3"};
    for (int k = 0; k < 2; k++) {
        hj_reach_problem pb;
        hj_reach_problem_init(&pb, &g, &s);
        pb.kind = HJ_REACH_BRS, pb.target.fn = box, pb.scheme = scheme[k], pb.order = order[k];
        pb.horizon = dt * ((double)steps - 0.5);
        pb.per_node = per_node, pb.keep_derivs = !no_keep;
        hj_reach_stats st;
        hj_progress("%s: %s\n", prog, name[k]);
        const clock_t c0 = clock();
        if (hj_reach_solve(&pb, phi, NULL, &st, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
        const double cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
        const double rate = (double)g.nodes * (double)st.steps * order[k] / st.seconds;
        const double cpu_rate = (double)g.nodes * (double)st.steps * order[k] / cpu;
        const double kept = pb.keep_derivs ? (double)hj_ls_lax_friedrichs_work_size(&g) : 0;
        const double bytes = (4.0 * (double)g.total + kept) * sizeof(double) / (double)g.nodes;
        fprintf(o.fp, "%s\t%zu\t%ld\t%d\t%.3f\t%.3e\t%.3f\t%.3e\t%.1f\n", name[k], g.nodes, st.steps, order[k],
                st.seconds, rate, cpu, cpu_rate, bytes);
        printf("%s: %s %ld^6: %.3e node-stage updates/s (wall), %.3e per CPU second, %.1f bytes per node\n", prog,
               name[k], N, rate, cpu_rate, bytes);
    }
    if (hj_out_commit(&o, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    hj_ls_free(phi);
    return 0;
}
