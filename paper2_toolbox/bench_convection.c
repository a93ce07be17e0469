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

The velocity is a callback evaluated on the fly (no velocity arrays); rows
on which a velocity component vanishes skip that derivative (here all of
x_3).  Every level is run with each requested number of OpenMP threads and
the final states are compared bit for bit.

**Parameters.** N = 101 nodes per dimension (dx = 0.02, the grid of the
Table 1 caption; the text's "g.dx = 0.01" would give 201^3 on [-1, 1]^3 and
contradicts the caption, so we follow the caption), threads 1 and 2.

**Output.** `convection.md`: wall-clock seconds per level and thread count
next to the published MATLAB seconds (Pentium 4, MATLAB 6.5: compare
ratios, not seconds), steps, whether the states agree bitwise across
thread counts, the error after the full turn (maximum of |phi - phi_0| on
nodes within 2 dx of the initial sphere, and the relative change of the
enclosed volume, counted in grid cells), and the peak resident memory
(getrusage).  Run by `make bench`, never by the tests.
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

    char path[4096];
    snprintf(path, sizeof path, "%s/convection.md", dir);
    hj_out o;
    if (hj_out_open(&o, path, &err)) hj_cli_fail(PROG, HJ_EXIT_RUN, "%s", err.msg);
    fprintf(o.fp, "**Table 1, measured** by `bench_convection` (`make bench`): convectionDemo('linear') on a "
                  "%ld^3 grid, wall-clock seconds of the integration.\n\n",
            n);
    fprintf(o.fp, "| level | published s (relative) |");
    for (int q = 0; q < nthr; q++)
        fprintf(o.fp, " %ld thread%s wall s (relative) | CPU s |", threads[q], threads[q] > 1 ? "s" : "");
    fprintf(o.fp, " steps | bitwise equal across threads | max error near front | volume change |\n|---|---|");
    for (int q = 0; q < nthr; q++) fprintf(o.fp, "---|---|");
    fprintf(o.fp, "---|---|---|---|\n");
    double base[8] = {0}, load0[3] = {0, 0, 0}, load1[3] = {0, 0, 0};
    getloadavg(load0, 3);
    for (int li = 0; li < nlev; li++) {
        const int L = (int)levels[li];
        hj_ls_convection c;
        hj_ls_convection_init(&c, &g, hj_ls_accuracy_scheme(L));
        p2_flow flow = {1, 0, 3}; /* convectionDemo's 'linear' */
        c.velocity_fn = p2_flow_velocity;
        c.ctx = &flow;
        hj_ls_ode_stats st;
        double secs[8], cpu[8];
        int same = 1;
        for (int q = 0; q < nthr; q++) {
#ifdef _OPENMP
            omp_set_num_threads((int)threads[q]);
#endif
            hj_progress("\r%s, %ld thread(s)   ", hj_ls_accuracy_name(L), threads[q]);
            memcpy(y, y0, sizeof(double) * g.total);
            const double c0 = hj_sys_cpu_seconds();
            if (hj_ls_ode(hj_ls_accuracy_order(L), &g, &c.base, tspan, 9, y, NULL, NULL, NULL, &st, &err))
                hj_cli_fail(PROG, HJ_EXIT_RUN, "%s: %s", hj_ls_accuracy_name(L), err.msg);
            secs[q] = st.seconds;
            cpu[q] = hj_sys_cpu_seconds() - c0;
            if (li == 0) base[q] = st.seconds;
            if (q == 0) memcpy(first, y, sizeof(double) * g.total);
            else same &= !memcmp(first, y, sizeof(double) * g.total);
        }
        /* error after the full turn, near the front, and volume change */
        double emax = 0;
        long vol0 = 0, vol = 0;
        for (size_t r = 0; r < g.rows; r++) {
            long idx[3];
            const size_t k = hj_ls_row(&g, r, idx);
            for (long j = 0; j < n; j++) {
                const double a = y0[k + (size_t)j], b = y[k + (size_t)j];
                if (fabs(a) < 2 * g.dx[0]) emax = fabs(a - b) > emax ? fabs(a - b) : emax;
                vol0 += a < 0;
                vol += b < 0;
            }
        }
        fprintf(o.fp, "| %s | %g (%.1f) |", hj_ls_accuracy_name(L), PUBLISHED[L], PUBLISHED[L] / PUBLISHED[0]);
        for (int q = 0; q < nthr; q++) fprintf(o.fp, " %.2f (%.1f) | %.2f |", secs[q], secs[q] / base[q], cpu[q]);
        fprintf(o.fp, " %ld | %s | %.3e | %+.2f %% |\n", st.steps, nthr > 1 ? (same ? "yes" : "**no**") : "-", emax,
                100.0 * (double)(vol - vol0) / (double)vol0);
        printf("%-9s steps %ld", hj_ls_accuracy_name(L), st.steps);
        for (int q = 0; q < nthr; q++) printf("  %ld thr %.2f s (cpu %.2f s)", threads[q], secs[q], cpu[q]);
        printf("  bitwise %s  err %.3e\n", same ? "same" : "DIFFERENT", emax);
        fflush(stdout);
    }
    hj_progress("\n");
    const double peak_mb = hj_sys_peak_rss_mb();
    getloadavg(load1, 3);
    fprintf(o.fp, "\nMachine load (1-minute load average) %.2f at the start and %.2f at the end of the runs on "
                  "this %g-core machine: when it exceeds the thread count, other processes shared the cores and "
                  "wall-clock times are inflated (the CPU seconds are less affected).\n",
            load0[0], load1[0], (double)sysconf(_SC_NPROCESSORS_ONLN));
    const double arr = (double)g.total * sizeof(double) / 1048576.0;
    fprintf(o.fp, "\nPeak resident memory (getrusage ru_maxrss): %.1f MB; one array with ghosts is %.1f MB. "
                  "The integrator holds the state and two more arrays (stage, derivative); the benchmark keeps "
                  "two more (the initial state, and the first thread count's result for the bitwise "
                  "comparison).\n",
            peak_mb, arr);
    if (hj_out_commit(&o, &err)) hj_cli_fail(PROG, HJ_EXIT_RUN, "%s", err.msg);
    printf("peak memory %.1f MB (array %.1f MB)\n", peak_mb, arr);
    hj_ls_free(y0), hj_ls_free(y), hj_ls_free(first);
    return 0;
}
