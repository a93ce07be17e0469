/*
# Benchmark: air3D at accuracy low and medium, 1 and 2 threads

The game of two identical vehicles (section 2.6.1, `air3d.c`, shared set-up
in `p2_air3d.c`) on the toolbox's default grid (air3D.m: 51 x 40 x 50 nodes
on [-6, 20] x [-10, 10] x [0, 2 pi)) to t = 2.8 with the global
Lax-Friedrichs dissipation, timed with the wall clock (omp_get_wtime) at
accuracy low (first order upwind + RK1) and medium (ENO2 + RK2), with 1 and
2 OpenMP threads, each configuration run `--repeat` times (default 3) and
the fastest kept.  The peak resident memory of the process (getrusage
ru_maxrss) is reported at the end; one array with ghost cells is
57 x 46 x 56 doubles = 1.2 MB.  The states of the 1- and 2-thread runs are
compared bitwise (the kernel promises thread-count independent results).

Output: air3d_bench.tsv, which notes/air3d_bench.md presents in the
report.  Timings depend on the machine and its load; `make bench` runs
this, the tests never do.  Run it with OMP_WAIT_POLICY=passive on a shared machine (spinning
threads otherwise steal the other thread's core).
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "hj_cli.h"
#include "hj_io.h"
#include "p2_air3d.h"
#include "hj_ls_accuracy.h"
#include "hj_sys.h"

static const char *prog = "bench_air3d";

static double now(void)
{
#ifdef _OPENMP
    return omp_get_wtime();
#else
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
#endif
}

int main(int argc, char **argv)
{
    const char *out_dir = ".";
    long repeat = 3;
    int quick = 0;
    hj_error err;
    hj_cli_opt opts[] = {
        {.name = "--repeat", .type = HJ_OPT_LONG, .value = &repeat, .min = 1, .max = 100, .metavar = "K",
         .help = "runs of each configuration (the fastest is kept)"},
        {.name = "--out-dir", .type = HJ_OPT_STRING, .value = &out_dir, .metavar = "DIR",
         .help = "where to write the benchmark's table"},
        /* the benchmark has one size: --quick is accepted as by every program, and changes nothing */
        {.name = "--quick", .type = HJ_OPT_FLAG, .value = &quick, .help = "accepted; changes nothing"},
    };
    hj_cli_spec spec = {prog, "Benchmark: air3D (section 2.6.1) at accuracy low and medium, 1 and 2 threads.", opts,
                        (int)(sizeof opts / sizeof opts[0]), "See the comment at the top of bench_air3d.c.\n"};
    hj_cli_parse_or_exit(&spec, argc, argv);
    if (hj_mkdirs(out_dir, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    p2_air3d_par par;
    p2_air3d_defaults(&par);
    hj_ls_grid g;
    if (p2_air3d_grid(51, &g, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    double *y = hj_ls_alloc(&g), *keep = hj_ls_alloc(&g);
    if (!y || !keep) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory");
    const double ts[2] = {0, 2.8};
    const int accs[2] = {HJ_LS_ACC_LOW, HJ_LS_ACC_MEDIUM};
    double best[2][2];
    long steps[2], differ[2];
    for (int a = 0; a < 2; a++) {
        for (int th = 0; th < 2; th++) {
#ifdef _OPENMP
            omp_set_num_threads(th + 1);
#endif
            best[a][th] = 1e300;
            for (long r = 0; r < repeat; r++) {
                hj_progress("bench_air3d: %s, %d thread(s), run %ld of %ld\n", hj_ls_accuracy_name(accs[a]), th + 1,
                            r + 1, repeat);
                if (p2_air3d_target(&g, &par, y, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
                hj_ls_ode_stats st;
                const double t0 = now();
                if (p2_air3d_solve(&g, &par, accs[a], 0, ts, 2, y, NULL, NULL, &st, &err))
                    hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
                const double dt = now() - t0;
                best[a][th] = dt < best[a][th] ? dt : best[a][th];
                steps[a] = st.steps;
            }
            if (th == 0) hj_ls_copy(&g, keep, y);
            else differ[a] = hj_ls_count_differ(&g, keep, y);
        }
    }
    /* The numbers of the report's note (notes/air3d_bench.md), one row per accuracy. */
    char path[4096];
    snprintf(path, sizeof path, "%s/air3d_bench.tsv", out_dir);
    hj_out out;
    if (hj_out_open(&out, path, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    const double peak_mb = hj_sys_peak_rss_mb();
    fprintf(out.fp, "# bench_air3d: air3D to t = 2.8 on the toolbox grid nx x ny x npsi, global Lax-Friedrichs; wall-clock\n"
                    "# seconds with 1 and 2 threads, the best of `repeat` runs, their ratio, ns per node and RK stage (1 thread),\n"
                    "# nodes whose final state differs between 1 and 2 threads, the process's peak resident memory (getrusage)\n"
                    "acc\tnx\tny\tnpsi\tnodes\trepeat\tsteps\twall_s_1thread\twall_s_2threads\tspeedup\tns_per_node_stage\t"
                    "differ\tpeak_rss_mb\n");
    for (int a = 0; a < 2; a++) {
        const double stages = (double)steps[a] * (a ? 2.0 : 1.0) * (double)g.nodes;
        fprintf(out.fp, "%s\t%ld\t%ld\t%ld\t%zu\t%ld\t%ld\t%.17g\t%.17g\t%.17g\t%.17g\t%ld\t%.17g\n",
                hj_ls_accuracy_name(accs[a]), g.N[0], g.N[1], g.N[2], g.nodes, repeat, steps[a], best[a][0], best[a][1],
                best[a][0] / best[a][1], 1e9 * best[a][0] / stages, differ[a], peak_mb);
    }
    if (hj_out_commit(&out, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    hj_ls_free(y);
    hj_ls_free(keep);
    return 0;
}
