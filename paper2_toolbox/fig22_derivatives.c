/*
# Figure 22: convergence of the upwind first derivatives

**Problem.** The test function of the toolbox's `firstDerivSpatialTest1`
(section 2.7.2) on the periodic unit square, constant in x_2:

    f(x) = sin(2 pi x_1 + pi/2)   for 0   <= x_1 < 1/4,
           sin(2 pi x_1 - pi/2)   for 1/4 <= x_1 < 1/2,
           sin(2 pi x_1) + 1      for 1/2 <= x_1 < 1.

It is continuous with derivative jumps at x_1 = 0, 1/4 and 1/2.  The
transcribed paper prints the phase shifts as pi/4, which would make f
itself jump at 1/2 and at 0, against the text ("continuous but with
discontinuities in the derivative"); the released toolbox source uses pi/2,
and so do we.

**Method.** Every upwind scheme of section 3.4.1 (`upwindFirstFirst`,
`ENO2`, `ENO3a`, `ENO3b`, `WENO5a`, `WENO5b`) and the section 4 extra
`WENO3`, from the kernel in common/hj_ls_deriv.c, differentiates f in x_1 on
an N x N grid with dx = 1/N.  As in `firstDerivSpatialConverge`, the error
is that of the left approximation D-, against the derivative of the segment
of the left neighbour (so at a kink, the one-sided derivative from the
left).  Four measures: maximum, average and root mean square over all
nodes, and the average over the three nodes on the jumps.  Fitted orders
come from the Ceres fit of common/hj_fit.h over all sizes.  As a control,
the same schemes differentiate the smooth f(x) = sin(2 pi x_1) +
0.3 cos(4 pi x_1 + 1) (maximum error only).

**Parameters.** N = 20, 40, 80, 160, 320, 640, 1280 (the toolbox script's
sizes; N must be a multiple of 4 so that the kinks are nodes).  `--quick`
runs N = 20 ... 160.

**Output.** `fig22.svg` (four panels like Figure 22, with reference slopes
1, 2, 3 and 5), `fig22.tsv` (all errors), `fig22_orders.tsv` (fitted orders
and the differences between the two forms of ENO3 and WENO5, which
notes/fig22_orders.md presents).
The relative costs of the schemes (Table 2) are measured by
`bench_table2` in `make bench`.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "hj_cli.h"
#include "hj_fit.h"
#include "hj_io.h"
#include "hj_ls_deriv.h"
#include "hj_math.h"

static const char *const PROG = "fig22_derivatives";
enum { NSCH = HJ_LS_NSCHEMES, MAXN = 16, NMEAS = 4 };

/* Segment of node i on a grid of n nodes per unit length. */
static int segment(long i, long n) { return i < n / 4 ? 0 : (i < n / 2 ? 1 : 2); }
static double piece(int seg, double x)
{
    const double w = 2 * HJ_PI * x;
    return seg == 0 ? sin(w + HJ_PI / 2) : seg == 1 ? sin(w - HJ_PI / 2) : sin(w) + 1;
}
static double dpiece(int seg, double x)
{
    const double w = 2 * HJ_PI * x;
    return 2 * HJ_PI * (seg == 0 ? cos(w + HJ_PI / 2) : seg == 1 ? cos(w - HJ_PI / 2) : cos(w));
}

/* Errors of the left derivative of the kinked (smooth = 0) or smooth test
 * function on an n x n periodic grid; e[NMEAS]. */
static int run(int scheme, long n, int smooth, double *e, hj_error *err)
{
    hj_ls_grid g;
    double mn[2] = {0, 0}, mx[2] = {1 - 1.0 / (double)n, 1 - 1.0 / (double)n};
    long N[2] = {n, n};
    hj_ls_bc bc[2] = {{HJ_LS_BC_PERIODIC, 0, 0}, {HJ_LS_BC_PERIODIC, 0, 0}};
    int rc = hj_ls_grid_init(&g, 2, mn, mx, N, bc, err);
    if (rc) return rc;
    double *a = hj_ls_alloc(&g), *l = hj_ls_alloc(&g), *r = hj_ls_alloc(&g);
    if (!a || !l || !r) {
        hj_ls_free(a), hj_ls_free(l), hj_ls_free(r);
        return hj_error_set(err, HJ_ENOMEM, "out of memory for N = %ld", n);
    }
    double *ex = malloc(sizeof(double) * (size_t)n);
    for (long i = 0; i < n; i++) {
        const double x = (double)i / (double)n;
        const double v = smooth ? sin(2 * HJ_PI * x) + 0.3 * cos(4 * HJ_PI * x + 1) : piece(segment(i, n), x);
        ex[i] = smooth ? 2 * HJ_PI * cos(2 * HJ_PI * x) - 1.2 * HJ_PI * sin(4 * HJ_PI * x + 1)
                       : dpiece(segment(i == 0 ? n - 1 : i - 1, n), x);
        for (long j = 0; j < n; j++) a[g.offset + (size_t)(i + j * g.stride[1])] = v;
    }
    rc = hj_ls_upwind(&g, scheme, a, 0, l, r, err);
    if (!rc) {
        double m = 0, s1 = 0, s2 = 0;
        for (long j = 0; j < n; j++)
            for (long i = 0; i < n; i++) {
                const double d = fabs(l[g.offset + (size_t)(i + j * g.stride[1])] - ex[i]);
                m = d > m ? d : m;
                s1 += d;
                s2 += d * d;
            }
        e[0] = m;
        e[1] = s1 / (double)(n * n);
        e[2] = sqrt(s2 / (double)(n * n));
        e[3] = 0;
        for (int k = 0; k < 3; k++) e[3] += fabs(l[g.offset + (size_t)(k * n / 4)] - ex[k * n / 4]) / 3;
    }
    free(ex);
    hj_ls_free(a), hj_ls_free(l), hj_ls_free(r);
    return rc;
}

/* One cell of fig22_orders.tsv: v to full precision, or "-" (NaN). */
static void cell(FILE *fp, double v)
{
    if (isnan(v)) fputs("\t-", fp);
    else fprintf(fp, "\t%.17g", v);
}

static int write_outputs(const char *dir, const long *sizes, int ns, double e[NSCH][MAXN][NMEAS],
                         double es[NSCH][MAXN], hj_error *err)
{
    char path[4096];
    hj_out tsv, dat, ord;
    int rc;
    snprintf(path, sizeof path, "%s/fig22.tsv", dir);
    if ((rc = hj_out_open(&tsv, path, err))) return rc;
    snprintf(path, sizeof path, "%s/fig22.dat", dir);
    if ((rc = hj_out_open(&dat, path, err))) { hj_out_abort(&tsv); return rc; }
    snprintf(path, sizeof path, "%s/fig22_orders.tsv", dir);
    if ((rc = hj_out_open(&ord, path, err))) { hj_out_abort(&tsv); hj_out_abort(&dat); return rc; }

    fprintf(tsv.fp, "# source: fig22_derivatives (left approximation, 2-D, derivative in x_1)\n");
    fprintf(tsv.fp, "scheme\tN\th\tmaximum\taverage\trms\tjumps\tsmooth_maximum\n");
    /* gnuplot data: one block per scheme (index k), columns N max avg rms jumps */
    for (int s = 0; s < NSCH; s++) {
        fprintf(dat.fp, "# %s\n", hj_ls_scheme_name(s));
        for (int k = 0; k < ns; k++) {
            fprintf(tsv.fp, "%s\t%ld\t%.17g", hj_ls_scheme_name(s), sizes[k], 1.0 / (double)sizes[k]);
            fprintf(dat.fp, "%ld", sizes[k]);
            for (int m = 0; m < NMEAS; m++) {
                fprintf(tsv.fp, "\t%.6e", e[s][k][m]);
                fprintf(dat.fp, "\t%.6e", e[s][k][m]);
            }
            fprintf(tsv.fp, "\t%.6e\n", es[s][k]);
            fprintf(dat.fp, "\n");
        }
        fprintf(dat.fp, "\n\n");
    }

    /* The two forms of ENO3 and of WENO5 (a, b): their largest relative
     * and absolute differences over all sizes and measures. */
    double rel[2] = {0, 0}, ab[2] = {0, 0};
    for (int q = 0; q < 2; q++) {
        const int a = q ? HJ_LS_WENO5A : HJ_LS_ENO3A, b = q ? HJ_LS_WENO5B : HJ_LS_ENO3B;
        for (int k = 0; k < ns; k++)
            for (int m = 0; m < NMEAS; m++) {
                const double r = fabs(e[a][k][m] - e[b][k][m]) / e[a][k][m], d = fabs(e[a][k][m] - e[b][k][m]);
                rel[q] = r > rel[q] ? r : rel[q];
                ab[q] = d > ab[q] ? d : ab[q];
            }
    }
    fprintf(ord.fp, "# fig22: fitted orders p of e = C h^p (Ceres fit over all sizes, p_*_se its standard error; - "
                    "where there is none), kinked test function, left approximation; p_smooth_maximum: the smooth "
                    "control; pair_*: the largest difference between the two forms (a, b) of ENO3 and of WENO5\n"
                    "scheme\tp_maximum\tp_maximum_se\tp_average\tp_average_se\tp_rms\tp_rms_se\tp_jumps\t"
                    "p_jumps_se\tp_smooth_maximum\tp_smooth_maximum_se\tpair_max_rel_diff\tpair_max_abs_diff\n");
    double h[MAXN], v[MAXN];
    for (int k = 0; k < ns; k++) h[k] = 1.0 / (double)sizes[k];
    for (int s = 0; s < NSCH; s++) {
        fprintf(ord.fp, "%s", hj_ls_scheme_name(s));
        for (int m = 0; m <= NMEAS; m++) {
            int npos = 0;
            for (int k = 0; k < ns; k++) {
                v[npos] = m < NMEAS ? e[s][k][m] : es[s][k];
                if (v[npos] > 0) h[npos] = 1.0 / (double)sizes[k], npos++;
            }
            hj_order_fit f;
            hj_error ferr;
            if (npos >= 2 && hj_fit_order(h, v, npos, &f, &ferr) == HJ_OK) {
                cell(ord.fp, f.p);
                cell(ord.fp, f.p_se);
            } else {
                cell(ord.fp, NAN);
                cell(ord.fp, NAN);
            }
        }
        const int q = s == HJ_LS_ENO3A || s == HJ_LS_ENO3B ? 0 : s == HJ_LS_WENO5A || s == HJ_LS_WENO5B ? 1 : -1;
        cell(ord.fp, q < 0 ? NAN : rel[q]);
        cell(ord.fp, q < 0 ? NAN : ab[q]);
        fputc('\n', ord.fp);
    }
    if ((rc = hj_out_commit(&tsv, err))) { hj_out_abort(&dat); hj_out_abort(&ord); return rc; }
    if ((rc = hj_out_commit(&dat, err))) { hj_out_abort(&ord); return rc; }
    return hj_out_commit(&ord, err);
}

int main(int argc, char **argv)
{
    long sizes[MAXN] = {20, 40, 80, 160, 320, 640, 1280};
    int ns = 7, quick = 0;
    const char *dir = NULL;
    hj_error err;
    hj_cli_opt opts[] = {
        {.name = "--quick", .type = HJ_OPT_FLAG, .value = &quick, .help = "N = 20, 40, 80, 160"},
        {.name = "--sizes", .type = HJ_OPT_LONG_LIST, .value = sizes, .min = 4, .max = 100000, .count = &ns,
         .maxn = MAXN, .metavar = "N1,N2,...", .help = "grid sizes, multiples of 4, at least two; overrides --quick"},
        {.name = "--out-dir", .type = HJ_OPT_STRING, .value = &dir, .metavar = "DIR",
         .help = "where fig22.tsv, fig22.dat, fig22_orders.tsv go", .dflt = "none: required"},
    };
    hj_cli_spec spec = {PROG,
                        "Figure 22 of Mitchell's toolbox: convergence of the upwind first\n"
                        "derivatives on the kinked test function of firstDerivSpatialTest1.",
                        opts, 3, NULL};
    hj_cli_parse_or_exit(&spec, argc, argv);
    if (quick && !opts[1].seen) ns = 4;
    if (!dir) hj_cli_fail(PROG, HJ_EXIT_USAGE, "--out-dir is required (see --help)");
    if (ns < 2) hj_cli_fail(PROG, HJ_EXIT_USAGE, "--sizes needs at least two sizes");
    for (int k = 0; k < ns; k++)
        if (sizes[k] % 4) hj_cli_fail(PROG, HJ_EXIT_USAGE, "--sizes: %ld is not a multiple of 4", sizes[k]);
    if (hj_mkdirs(dir, &err)) hj_cli_fail(PROG, HJ_EXIT_RUN, "%s", err.msg);

    static double e[NSCH][MAXN][NMEAS], es[NSCH][MAXN];
    for (int s = 0; s < NSCH; s++)
        for (int k = 0; k < ns; k++) {
            hj_progress("\r%s N = %ld   ", hj_ls_scheme_name(s), sizes[k]);
            double tmp[NMEAS] = {0};
            if (run(s, sizes[k], 0, e[s][k], &err) || run(s, sizes[k], 1, tmp, &err))
                hj_cli_fail(PROG, HJ_EXIT_RUN, "%s", err.msg);
            es[s][k] = tmp[0];
        }
    hj_progress("\n");
    if (write_outputs(dir, sizes, ns, e, es, &err)) hj_cli_fail(PROG, HJ_EXIT_RUN, "%s", err.msg);
    return 0;
}
