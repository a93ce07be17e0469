/* bench_reach -- the speed and memory of 6-D reachability on the level set
 * kernel: three decoupled double integrators with a box target (the
 * system of product6d in reach_checks), a backward reachable set run for a
 * few time steps with hj_reach_solve.
 *
 *   first order: upwind first order, forward Euler: node updates per
 *                second (nodes x steps / seconds);
 *   WENO5/RK3:   node-stage updates per second (nodes x 3 stages x steps / s);
 *   memory:      bytes per interior node of the run's arrays: the value
 *                (with ghost layers on the general path, interior only on
 *                the fused one) and what hj_reach_solve allocates
 *                (hj_reach_stats.bytes: on the general path the previous
 *                value, the integrator's time derivative and stage with
 *                their ghost layers, the kept one-sided derivatives; on
 *                the fused path one interior array and row buffers).
 *
 * Each scheme runs twice, back to back: the general path (the kernel's
 * Lax-Friedrichs term and integrator, pb.general = 1) and the fused path
 * hj_reach_solve takes by itself (compact arrays, G declared constant, f
 * batched over rows),
 * and prints the ratio of their rates; the two values are compared
 * bitwise (nodes that differ: 0 expected).  WENO5/RK3 likewise.  --per-node and --no-keep-derivs run hj_reach's reference
 * variants of the general path (same bits).
 *
 * Writes bench_reach.tsv in --out-dir, with rates per wall-clock second
 * and per CPU second (all threads): the first moves with the machine's
 * load, compare rates of runs made together.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "hj.h"

static const char *prog = "bench_reach";

static void f(double t, const double *x, double *o, void *c)
{
    (void)t, (void)c;
    for (int k = 0; k < 6; k += 2) o[k] = x[k + 1], o[k + 1] = 0;
}
/* f over a row: every component is constant along dimension 0. */
static void f_row(double t, const double *x, double dx0, long n, double *o, void *c)
{
    (void)t, (void)dx0, (void)c;
    for (int k = 0; k < 6; k += 2)
        for (long j = 0; j < n; j++) o[k * n + j] = x[k + 1], o[(k + 1) * n + j] = 0;
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
    for (int k = 0; k < 6; k++) {
        const double v = fabs(x[k]) - 0.5;
        m = v > m ? v : m;
    }
    return m;
}

/* One run: rate (node-stage updates per wall second), per CPU second,
 * bytes per node; the value left in phi. */
typedef struct {
    double rate, cpu_rate, bytes, seconds, cpu, step_rate;
    long steps;
} run_result;

static run_result run(const hj_ls_grid *g, hj_reach_dyn *s, int scheme, int order, int general, int per_node,
                      int no_keep, double horizon, double *phi)
{
    hj_error err;
    hj_reach_problem pb;
    hj_reach_problem_init(&pb, g, s);
    pb.kind = HJ_REACH_BRS, pb.target.fn = box, pb.scheme = scheme, pb.order = order;
    pb.horizon = horizon;
    pb.per_node = per_node, pb.keep_derivs = !no_keep, pb.general = general;
    pb.compact = hj_reach_fused_applies(&pb);
    hj_reach_stats st;
    const clock_t c0 = clock();
    if (hj_reach_solve(&pb, phi, NULL, &st, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    run_result r;
    r.cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
    r.seconds = st.seconds;
    r.steps = st.steps;
    r.rate = (double)g->nodes * (double)st.steps * order / st.seconds;
    r.cpu_rate = (double)g->nodes * (double)st.steps * order / r.cpu;
    r.step_rate = (double)g->nodes * (double)st.steps * order / st.step_seconds;
    r.bytes = ((double)(pb.compact ? g->nodes : g->total) * sizeof(double) + (double)st.bytes) / (double)g->nodes;
    return r;
}

int main(int argc, char **argv)
{
    long N = 13, steps = 10;
    const char *out_dir = ".";
    int per_node = 0, no_keep = 0, fused_only = 0;
    hj_cli_opt opts[] = {
        {.name = "--fused-only", .type = HJ_OPT_FLAG, .value = &fused_only,
         .help = "run the fused first order path only (for profiling)"},
        {.name = "--N", .type = HJ_OPT_LONG, .value = &N, .min = 5, .max = 40, .metavar = "N",
         .help = "nodes in each of the 6 dimensions"},
        {.name = "--steps", .type = HJ_OPT_LONG, .value = &steps, .min = 1, .max = 1000, .metavar = "K",
         .help = "time steps of each run"},
        {.name = "--per-node", .type = HJ_OPT_FLAG, .value = &per_node,
         .help = "general path: the kernel's per-node callbacks instead of batched rows"},
        {.name = "--no-keep-derivs", .type = HJ_OPT_FLAG, .value = &no_keep,
         .help = "general path: compute the one-sided derivatives twice instead of keeping them"},
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
    s.G_const = 1, s.f_row = f_row;
    double *phi = hj_ls_alloc(&g), *cphi = malloc(sizeof(double) * g.nodes);
    if (!phi || !cphi) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory for %zu nodes", g.nodes);
    /* The CFL step of this system: sum_d alpha_d / dx_d with |v| <= 1.5
     * and |u| <= 1, times 0.5; the horizon covers the steps asked for. */
    const double dt = 0.5 / (3 * (1.5 + 1.0) / g.dx[0]);
    const double horizon = dt * ((double)steps - 0.5);
    hj_out o;
    if (hj_out_open(&o, path, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    fprintf(o.fp, "# three double integrators, BRS, %ld^6 = %zu nodes (%zu with ghosts), %ld steps a run, general path "
                  "with %s, %s\n", N, g.nodes, g.total, steps, per_node ? "per-node callbacks" : "batched rows",
            no_keep ? "derivatives computed twice" : "derivatives kept");
    fprintf(o.fp, "scheme\tpath\tnodes\tsteps\tstages\tseconds\tupdates_per_s\tcpu_seconds\tupdates_per_cpu_s\t"
                  "step_updates_per_s\tbytes_per_node\n");
    const int scheme[2] = {HJ_LS_UPWIND_FIRST, HJ_LS_WENO5A}, order[2] = {1, 3};
    const char *name[2] = {"first-order-euler", "weno5-rk3"};
    for (int k = 0; k < 2; k++) {
        run_result r[2];
        const int paths = 2; /* general, then fused */
        for (int q = fused_only; q < paths; q++) {
            hj_progress("%s: %s, %s path\n", prog, name[k], q ? "fused" : "general");
            r[q] = run(&g, &s, scheme[k], order[k], q == 0, per_node, no_keep, horizon, q ? cphi : phi);
            fprintf(o.fp, "%s\t%s\t%zu\t%ld\t%d\t%.3f\t%.3e\t%.3f\t%.3e\t%.3e\t%.1f\n", name[k],
                    q ? "fused" : "general", g.nodes, r[q].steps, order[k], r[q].seconds, r[q].rate, r[q].cpu,
                    r[q].cpu_rate, r[q].step_rate, r[q].bytes);
            printf("%s: %s %ld^6, %s path: %.3e node-stage updates/s (wall; %.3e in the steps alone), %.3e per CPU "
                   "second, %.1f bytes per node\n", prog, name[k], N, q ? "fused" : "general", r[q].rate, r[q].step_rate,
                   r[q].cpu_rate, r[q].bytes);
        }
        if (paths == 2 && !fused_only) {
            long differ = 0;
            for (size_t row = 0; row < g.rows; row++) {
                long i[6];
                const size_t kk = hj_ls_row(&g, row, i);
                for (long j = 0; j < N; j++)
                    differ += memcmp(&phi[kk + (size_t)j], &cphi[row * (size_t)N + (size_t)j], sizeof(double)) != 0;
            }
            for (size_t q = 0; q < g.nodes; q++) cphi[q] = 0; /* the next run starts clean */
            printf("%s: %s fused / general: %.1fx the rate (wall), %.1fx in the steps alone, %.1fx per CPU second, "
                   "%.1fx fewer bytes per node; %ld node%s differ%s\n", prog, name[k], r[1].rate / r[0].rate,
                   r[1].step_rate / r[0].step_rate, r[1].cpu_rate / r[0].cpu_rate, r[0].bytes / r[1].bytes, differ,
                   hj_plural(differ), differ == 1 ? "s" : "");
            fprintf(o.fp, "# %s fused / general: rate ratio %.2f (wall), %.2f (CPU), bytes ratio %.2f, %ld node%s "
                          "differ%s\n", name[k], r[1].rate / r[0].rate, r[1].cpu_rate / r[0].cpu_rate,
                    r[0].bytes / r[1].bytes, differ, hj_plural(differ), differ == 1 ? "s" : "");
        }
    }
    if (hj_out_commit(&o, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    hj_ls_free(phi);
    free(cphi);
    return 0;
}
