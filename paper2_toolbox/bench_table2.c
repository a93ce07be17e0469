/*
# Table 2: relative cost of the upwind first derivatives

**Problem.** The relative execution times of the six upwind schemes of
section 3.4.1, as `firstDerivSpatialConverge` reports them for its largest
grid: the kinked test function of Figure 22 on a 1280 x 1280 periodic grid,
left and right derivatives in x_1.

**Method.** Each scheme of common/hj_ls_deriv.c (`hj_ls_upwind`, which also
fills the ghost layer) is timed on one thread with a monotonic clock; every
scheme runs repeatedly until at least `--min-time` seconds have passed and
the fastest run counts.  Costs are relative to `upwindFirstFirst`.  The
toolbox timed single MATLAB calls with `cputime` on a Pentium 4; we compare
ratios only, and expect the ordering rather than the values to carry over:
MATLAB's cost grows with the number of whole-array operations and
temporaries a scheme creates, ours (vectorised C over rows, no temporaries
beyond a few rows) with its floating point work, of which the WENO weights
(two divisions per side) and the direct forms' divisions by constants are
the dearest.  The machine is shared: the fastest of repeated runs is
reported to reduce the effect of other processes.

**Parameters.** N = 1280 (`--n`), `--min-time` 0.5 s.

**Output.** `table2.tsv`: published and measured relative costs, and the
absolute time per call (notes/table2.md presents them).  Run by `make
reproduce` (about 4 s, so that the report sets Table 2 beside the
published one) and again by `make bench`; never by the tests.
*/
#include <math.h>
#include <stdio.h>
#include <time.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "hj_cli.h"
#include "hj_io.h"
#include "hj_ls_deriv.h"
#include "hj_math.h"
#include "p2_cli.h"

static const char *const PROG = "bench_table2";
/* Table 2 as published (rows in the order of enum HJ_LS_*). */
static const double PUBLISHED[6] = {1, 5, 12, 25, 20, 28};

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double kinked(const double *x, void *ctx)
{
    (void)ctx;
    const double w = 2 * HJ_PI * x[0];
    return x[0] < 0.25 ? sin(w + HJ_PI / 2) : x[0] < 0.5 ? sin(w - HJ_PI / 2) : sin(w) + 1;
}

int main(int argc, char **argv)
{
    long n = 1280;
    double min_time = 0.5;
    const char *dir = NULL;
    hj_error err;
    hj_cli_opt opts[] = {
        {.name = "--n", .type = HJ_OPT_LONG, .value = &n, .min = 8, .max = 100000, .metavar = "N",
         .help = "grid size"},
        {.name = "--min-time", .type = HJ_OPT_DOUBLE, .value = &min_time, .min = 1e-3, .max = 3600,
         .metavar = "SECONDS", .help = "minimum time per scheme"},
        {.name = "--out-dir", .type = HJ_OPT_STRING, .value = &dir, .metavar = "DIR", .help = "where table2.tsv goes",
         .dflt = "none: required"},
    };
    hj_cli_spec spec = {PROG,
                        "Table 2 of Mitchell's toolbox: relative cost of the upwind schemes\n"
                        "on an N x N grid (one thread).",
                        opts, 3, NULL};
    hj_cli_parse_or_exit(&spec, argc, argv);
    if (!dir) hj_cli_fail(PROG, HJ_EXIT_USAGE, "--out-dir is required (see --help)");
    if (hj_mkdirs(dir, &err)) hj_cli_fail(PROG, HJ_EXIT_RUN, "%s", err.msg);
#ifdef _OPENMP
    omp_set_num_threads(1);
#endif
    hj_ls_grid g;
    double mn[2] = {0, 0}, mx[2] = {1 - 1.0 / (double)n, 1 - 1.0 / (double)n};
    long N[2] = {n, n};
    hj_ls_bc bc[2] = {{HJ_LS_BC_PERIODIC, 0, 0}, {HJ_LS_BC_PERIODIC, 0, 0}};
    if (hj_ls_grid_init(&g, 2, mn, mx, N, bc, &err)) hj_cli_fail(PROG, HJ_EXIT_RUN, "%s", err.msg);
    double *a = hj_ls_alloc(&g), *l = hj_ls_alloc(&g), *r = hj_ls_alloc(&g);
    if (!a || !l || !r) hj_cli_fail(PROG, HJ_EXIT_RUN, "out of memory");
    hj_ls_fill(&g, a, kinked, NULL);

    double best[HJ_LS_NSCHEMES];
    for (int s = 0; s < HJ_LS_NSCHEMES; s++) {
        hj_progress("\r%-20s", hj_ls_scheme_name(s));
        best[s] = INFINITY;
        const double start = now();
        int runs = 0;
        while (runs < 3 || now() - start < min_time) {
            const double t0 = now();
            if (hj_ls_upwind(&g, s, a, 0, l, r, &err)) hj_cli_fail(PROG, HJ_EXIT_RUN, "%s", err.msg);
            const double t = now() - t0;
            best[s] = t < best[s] ? t : best[s];
            runs++;
        }
    }
    hj_progress("\n");

    hj_out o;
    p2_fail_if(PROG, p2_open(&o, dir, "table2.tsv", &err), &err);
    fprintf(o.fp, "# bench_table2: left and right derivatives in x_1 on an N x N periodic grid, one thread, fastest of "
                  "repeated runs; published: Table 2's relative time (- for the section 4 extra)\n"
                  "scheme\tN\tpublished\trelative_time\tms_per_call\n");
    for (int s = 0; s < HJ_LS_NSCHEMES; s++) {
        fprintf(o.fp, "%s\t%ld\t", hj_ls_scheme_name(s), n);
        if (s < 6) fprintf(o.fp, "%.17g", PUBLISHED[s]);
        else fputc('-', o.fp);
        fprintf(o.fp, "\t%.17g\t%.17g\n", best[s] / best[0], 1e3 * best[s]);
    }
    p2_fail_if(PROG, hj_out_commit(&o, &err), &err);
    for (int s = 0; s < HJ_LS_NSCHEMES; s++)
        printf("%-20s %8.2f ms  x%.1f\n", hj_ls_scheme_name(s), 1e3 * best[s], best[s] / best[0]);
    hj_ls_free(a), hj_ls_free(l), hj_ls_free(r);
    return 0;
}
