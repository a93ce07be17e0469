/*
# Benchmark: cost of the fast sweeping solver (make bench)

**What it measures.** Example 1 (point source, Richardson boundary values)
on an N x N grid: the time of a solve that stops after the first order
initial guess (set-up, Richardson boxes and first order sweeps: the
baseline), and of the full third order solve.  Reported: their ratio, and the
cost of one WENO node visit (the extra time over the baseline divided by
iterations x 4 sweeps x nodes) as a ratio to the baseline's time per node.
Absolute times are printed for reference only: compare runs as ratios, on
an otherwise idle machine.

**Parameters.** `--N` (default 640), `--repeat` (default 3, the minimum
time is kept), `--out-dir` for bench.tsv.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "hj_cli.h"
#include "hj_fsm.h"
#include "hj_io.h"
#include "hj_math.h"

static const char *prog = "bench_fsm";

static double speed(double x, double y, void *ctx)
{
    (void)ctx;
    const double sx = sin(HJ_PI * x / 2), sy = sin(HJ_PI * y / 2);
    return HJ_PI / 2 * sqrt(sx * sx + sy * sy);
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* Minimum wall time of `repeat` solves. */
static double timed_solve(const hj_grid2 *g, const hj_fsm_options *o, double *phi, int repeat, hj_fsm_stats *st)
{
    static const hj_inflow src = {.type = HJ_INFLOW_POINT, .x = 0, .y = 0, .value = -2, .richardson = 1};
    const hj_speed sp = {speed, NULL, NULL};
    hj_error err;
    double best = INFINITY;
    for (int r = 0; r < repeat; r++) {
        double t0 = now();
        if (hj_fsm_solve(g, &sp, &src, 1, o, phi, st, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
        double t = now() - t0;
        if (t < best) best = t;
    }
    return best;
}

int main(int argc, char **argv)
{
    long N = 640, repeat = 3;
    const char *out_dir = ".";
    hj_error err;
    hj_cli_opt opts[] = {
        {.name = "--N", .type = HJ_OPT_LONG, .value = &N, .min = 8, .max = 10000, .metavar = "N", .help = "grid nodes per side"},
        {.name = "--repeat", .type = HJ_OPT_LONG, .value = &repeat, .min = 1, .max = 100, .metavar = "R",
         .help = "solves per timing (the minimum is kept)"},
        {.name = "--out-dir", .type = HJ_OPT_STRING, .value = &out_dir, .metavar = "DIR", .help = "where to write bench.tsv"},
    };
    hj_cli_spec spec = {prog, "Cost of the fast sweeping solver: full third order solve against its first order guess.",
                        opts, (int)(sizeof opts / sizeof opts[0]), "See the comment at the top of bench_fsm.c.\n"};
    hj_cli_parse_or_exit(&spec, argc, argv);
    char path[4096];
    snprintf(path, sizeof path, "%s/bench.tsv", out_dir);
    if (hj_mkdirs(out_dir, &err) || hj_out_check(path, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    hj_grid2 g = {(int)N, (int)N, -1, -1, 2.0 / N};
    double *phi = malloc(sizeof(double) * (size_t)(N + 1) * (size_t)(N + 1));
    if (!phi) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory for N=%ld", N);
    hj_fsm_options o = hj_fsm_default_options();
    o.strategy = HJ_BC_RICHARDSON;
    hj_fsm_stats fo, full;
    o.first_order_only = 1;
    const double t_fo = timed_solve(&g, &o, phi, (int)repeat, &fo);
    o.first_order_only = 0;
    const double t_full = timed_solve(&g, &o, phi, (int)repeat, &full);
    free(phi);
    const double nodes = (double)(N + 1) * (N + 1);
    const double weno_visit = (t_full - t_fo) / (full.iterations * 4.0 * nodes);
    const double base_per_node = t_fo / nodes;

    hj_out out;
    if (hj_out_open(&out, path, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    fprintf(out.fp, "# bench_fsm: Example 1, N = %ld, minimum of %ld runs; baseline = the solve stopped after the first order guess\n", N, repeat);
    fprintf(out.fp, "quantity\tratio\tseconds_or_ns\n");
    fprintf(out.fp, "baseline_solve\t1.00\t%.4f s\n", t_fo);
    fprintf(out.fp, "full_solve\t%.2f\t%.4f s\n", t_full / t_fo, t_full);
    fprintf(out.fp, "weno_node_visit_over_baseline_per_node\t%.3f\t%.1f ns\n", weno_visit / base_per_node, 1e9 * weno_visit);
    fprintf(out.fp, "weno_iterations\t-\t%d\n", full.iterations);
    if (hj_out_commit(&out, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    printf("bench_fsm N=%ld: full solve = %.1f x baseline (first order guess); one WENO node visit = %.3f x the "
           "baseline's time per node (%.1f ns); %d WENO iterations\n",
           N, t_full / t_fo, weno_visit / base_per_node, 1e9 * weno_visit, full.iterations);
    return 0;
}
