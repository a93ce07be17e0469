/*
# Table 1: convectionDemo('linear') on a 101^3 grid

**Problem.** The toolbox's first example (section 2.1) in three
dimensions: the sphere of radius 0.35 centred at (-0.4, 0, 0), as a signed
distance function on [-1, 1]^3, is rotated about the x_3 axis by the
velocity field v(x) = 2 pi (x_2, -x_1, 0) for t in [0, 1], one full turn,
so the exact final state is the initial one.  Extrapolation (away from
zero) boundary conditions.

**Method.** common/hj_ls_term.c's convection term with the toolbox's
accuracy levels, integrated by common/hj_ls_ode.c with FactorCFL 0.5 and
the nine output times 0, 1/8, ..., 1 of the demo (each ends a CFL step):

| level | time | space |
|---|---|---|
| low | TVD RK1 | upwindFirstFirst |
| medium | TVD RK2 | upwindFirstENO2 |
| high | TVD RK3 | upwindFirstENO3a |
| veryHigh | TVD RK3 | upwindFirstWENO5a |

The velocity is a callback, called per row, dimension and stage.  It does
not depend on t, so the term could keep its rows (`velocity_steady`, dim x
nodes doubles, 24 MB here), but reading them from memory each stage cost
more than the rotation's few operations per node: 4-13 % more CPU time at
each level (one thread, alternated runs, 28 November 2026; the same
bits).  Rows on which a velocity component vanishes skip that derivative
(here all of x_3).  Every level is run with each requested number of OpenMP threads and
the final states are compared bit for bit.

**Parameters.** N = 101 nodes per dimension (dx = 0.02, the grid of the
Table 1 caption; the text's "g.dx = 0.01" would give 201^3 on [-1, 1]^3 and
contradicts the caption, so we follow the caption), threads 1 and 2.

**Output.** `convection_bench.tsv`, which `notes/convection.md` presents:
wall-clock seconds per level and thread count next to the published MATLAB
seconds (Pentium 4, MATLAB 6.5: compare ratios, not seconds), steps,
whether the states agree bitwise across thread counts, the error after the
full turn (maximum of |phi - phi_0| on nodes within 2 dx of the initial
sphere, and the relative change of the enclosed volume, counted in grid
cells), the machine's load and the peak resident memory (getrusage).  Run
by `make reproduce` on one thread (about 80 s; 41^3 in `make reproduce
QUICK=1`), so that the report sets Table 1 beside the published one,
and again by `make bench` with 1 and 2 threads; never timed by the tests.
*/
#define _DEFAULT_SOURCE /* getloadavg */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "hj_cli.h"
#include "hj_io.h"
#include "hj_ls_ode.h"
#include "hj_ls_shape.h"
#include "hj_ls_accuracy.h"
#include "hj_ls_seq.h"
#include "hj_sys.h"
#include "p2_cli.h"
#include "p2_convection.h"

static const char *const PROG = "bench_convection";

enum { NLEVEL = HJ_LS_NACC };
static const double PUBLISHED[NLEVEL] = {140, 684, 2433, 2585};

int main(int argc, char **argv)
{
    long n = 101, levels[NLEVEL] = {0, 1, 2, 3}, threads[8] = {1, 2};
    int nlev = NLEVEL, nthr = 2;
    const char *dir = NULL;
    hj_error err;
    hj_cli_opt opts[] = {
        {.name = "--n", .type = HJ_OPT_LONG, .value = &n, .min = 8, .max = 2000, .metavar = "N",
         .help = "nodes per dimension"},
        {.name = "--levels", .type = HJ_OPT_LONG_LIST, .value = levels, .min = 0, .max = 3, .count = &nlev,
         .maxn = NLEVEL, .metavar = "LIST", .help = "accuracy levels 0..3 = low, medium, high, veryHigh"},
        {.name = "--threads", .type = HJ_OPT_LONG_LIST, .value = threads, .min = 1, .max = 256, .count = &nthr,
         .maxn = 8, .metavar = "LIST", .help = "OpenMP thread counts to run"},
        {.name = "--out-dir", .type = HJ_OPT_STRING, .value = &dir, .metavar = "DIR",
         .help = "where the benchmark's table goes (required)"},
    };
    hj_cli_spec spec = {PROG, "Table 1 of Mitchell's toolbox: convectionDemo('linear') on an N^3 grid.", opts,
                        (int)(sizeof opts / sizeof opts[0]), "See the comment at the top of bench_convection.c.\n"};
    hj_cli_parse_or_exit(&spec, argc, argv);
    if (!dir) hj_cli_fail(PROG, HJ_EXIT_USAGE, "--out-dir is required (see --help)");
    if (hj_mkdirs(dir, &err)) hj_cli_fail(PROG, HJ_EXIT_RUN, "%s", err.msg);

    hj_ls_grid g;
    double mn[3] = {-1, -1, -1}, mx[3] = {1, 1, 1};
    long N[3] = {n, n, n};
    hj_ls_bc bc[3];
    for (int d = 0; d < 3; d++) bc[d] = (hj_ls_bc){HJ_LS_BC_EXTRAP_AWAY, 0, 0};
    if (hj_ls_grid_init(&g, 3, mn, mx, N, bc, &err)) hj_cli_fail(PROG, HJ_EXIT_RUN, "%s", err.msg);
    double *y0 = hj_ls_alloc(&g), *y = hj_ls_alloc(&g), *first = hj_ls_alloc(&g);
    if (!y0 || !y || !first) hj_cli_fail(PROG, HJ_EXIT_RUN, "out of memory");
    const double center[3] = {-0.4, 0, 0};
    if (hj_ls_shape_sphere(&g, center, 0.35, y0, &err)) hj_cli_fail(PROG, HJ_EXIT_RUN, "%s", err.msg);
    double tspan[9];
    hj_ls_seq_times(0, 1, 9, tspan);

    /* Timings and checks per level and thread count, written once all are run. */
    double secs[NLEVEL][8], cpu[NLEVEL][8], base[8] = {0}, cpu_base[8] = {0}, emax[NLEVEL], vchange[NLEVEL];
    double load0[3] = {0, 0, 0}, load1[3] = {0, 0, 0};
    long steps[NLEVEL];
    int same[NLEVEL];
    getloadavg(load0, 3);
    for (int li = 0; li < nlev; li++) {
        const int L = (int)levels[li];
        hj_ls_convection c;
        hj_ls_convection_init(&c, &g, hj_ls_accuracy_scheme(L));
        p2_flow flow = {1, 0, 3}; /* convectionDemo's 'linear' */
        c.velocity_fn = p2_flow_velocity;
        c.ctx = &flow;
        c.velocity_steady = 0; /* cheaper than a cache that streams from memory (above) */
        hj_ls_ode_stats st;
        same[li] = 1;
        for (int q = 0; q < nthr; q++) {
#ifdef _OPENMP
            omp_set_num_threads((int)threads[q]);
#endif
            hj_progress("\r%s, %ld thread(s)   ", hj_ls_accuracy_name(L), threads[q]);
            memcpy(y, y0, sizeof(double) * g.total);
            const double c0 = hj_sys_cpu_seconds();
            if (hj_ls_ode(hj_ls_accuracy_order(L), &g, &c.base, tspan, 9, y, NULL, NULL, NULL, &st, &err))
                hj_cli_fail(PROG, HJ_EXIT_RUN, "%s: %s", hj_ls_accuracy_name(L), err.msg);
            hj_ls_convection_free(&c); /* each run fills its own velocity cache */
            secs[li][q] = st.seconds;
            cpu[li][q] = hj_sys_cpu_seconds() - c0;
            if (li == 0) base[q] = st.seconds, cpu_base[q] = cpu[li][q];
            if (q == 0) memcpy(first, y, sizeof(double) * g.total);
            else same[li] &= !memcmp(first, y, sizeof(double) * g.total);
        }
        steps[li] = st.steps;
        /* error after the full turn, near the front, and volume change */
        double e = 0;
        long vol0 = 0, vol = 0;
        for (size_t r = 0; r < g.rows; r++) {
            long idx[3];
            const size_t k = hj_ls_row(&g, r, idx);
            for (long j = 0; j < n; j++) {
                const double a = y0[k + (size_t)j], b = y[k + (size_t)j];
                if (fabs(a) < 2 * g.dx[0]) e = fabs(a - b) > e ? fabs(a - b) : e;
                vol0 += a < 0;
                vol += b < 0;
            }
        }
        emax[li] = e;
        vchange[li] = 100.0 * (double)(vol - vol0) / (double)vol0;
        printf("%-9s steps %ld", hj_ls_accuracy_name(L), st.steps);
        for (int q = 0; q < nthr; q++) printf("  %ld thr %.2f s (cpu %.2f s)", threads[q], secs[li][q], cpu[li][q]);
        printf("  bitwise %s  err %.3e\n", same[li] ? "same" : "DIFFERENT", e);
        fflush(stdout);
    }
    hj_progress("\n");
    const double peak_mb = hj_sys_peak_rss_mb();
    getloadavg(load1, 3);
    const double arr = (double)g.total * sizeof(double) / 1048576.0;

    /* The numbers of the report's note (notes/convection.md), one row per level and thread count. */
    hj_out o;
    p2_fail_if(PROG, p2_open(&o, dir, "convection_bench.tsv", &err), &err);
    fprintf(o.fp, "# bench_convection: convectionDemo('linear') on an n^3 grid; published_s = the document's MATLAB seconds\n"
                  "# (published_rel: relative to low); wall seconds of the integration (wall_rel: relative to the first level\n"
                  "# run with the same thread count) and CPU seconds of the process (cpu_rel: likewise); bitwise = final states equal across the thread counts\n"
                  "# (- for one thread count); front_err = max |phi - phi_0| within 2 dx of the initial sphere; volume change\n"
                  "# in cells, per cent; 1-minute load average at the start and end, cores online, peak resident memory\n"
                  "# (getrusage) and the size of one array with ghosts\n"
                  "level\tthreads\tn\tpublished_s\tpublished_rel\twall_s\twall_rel\tcpu_s\tcpu_rel\tsteps\tbitwise\t"
                  "front_err\tvolume_change_pct\tload_start\tload_end\tcores\tpeak_rss_mb\tarray_mb\n");
    for (int li = 0; li < nlev; li++) {
        const int L = (int)levels[li];
        for (int q = 0; q < nthr; q++)
            fprintf(o.fp, "%s\t%ld\t%ld\t%g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%ld\t%s\t%.17g\t%.17g\t%.17g\t%.17g\t"
                          "%g\t%.17g\t%.17g\n",
                    hj_ls_accuracy_name(L), threads[q], n, PUBLISHED[L], PUBLISHED[L] / PUBLISHED[0], secs[li][q],
                    secs[li][q] / base[q], cpu[li][q], cpu[li][q] / cpu_base[q], steps[li], nthr > 1 ? (same[li] ? "yes" : "no") : "-", emax[li],
                    vchange[li], load0[0], load1[0], (double)sysconf(_SC_NPROCESSORS_ONLN), peak_mb, arr);
    }
    p2_fail_if(PROG, hj_out_commit(&o, &err), &err);
    printf("peak memory %.1f MB (array %.1f MB)\n", peak_mb, arr);
    hj_ls_free(y0), hj_ls_free(y), hj_ls_free(first);
    return 0;
}
