/*
# nonconvexLF: a non-convex Hamiltonian with Lax-Friedrichs (Figure 15)

**Problem.** Section 2.5.2, the toolbox's `nonconvexLF`: Osher & Shu's
(1991) example 2 and its two-dimensional version, (14) with the
non-convex Hamiltonian (16),

    D_t phi + H(grad phi) = 0,   H(p) = -cos(alpha + sum_i p_i),  alpha = 1,
    phi(x, 0) = -cos(pi / d * sum_i x_i)   on [-d, d)^d, periodic

(grid, data and time steps as in `burgers_lf.c`; `p2_oshershu.c` holds
what the two demos share).

**Method.** `termLaxFriedrichs` with the toolbox's partial bound alpha_j =
1 (section 2.5.2: it bounds |sin(.)| but ignores the range of p, "so all
of the dissipation methods will give the same result"), any of GLF, LLF,
LLLF; accuracy levels as the toolbox; FactorCFL 0.5.  For the check we add
`--partial tight`: the exact maximum of |sin(1 + q)| over q in [sum_i
pmin_i, sum_i pmax_i], which depends on the range and so makes the three
dissipations differ.

**Options and defaults.** `--accuracy`, `--diss`, `--dim` (1-3), `--N`,
`--tmax`, `--partial toolbox|tight`; defaults as `burgersLF` (the text
gives only tMax = 1.5/pi^2; the rest from the released m-files): low,
global, gridDim 2, gridSize 80 / 2^(gridDim - 1), toolbox partial.  Any of
them: one run, time sequence in `nonconvex_run.dat`.

**Figure 15.** (a) 1-D at t = 1.5/pi^2: the caption compares "the exact
solution" with ENO3-LF on 10 points; H is not convex and after the kink
there is no formula, so the line is a reference computed with WENO5 + RK3
on 2560 nodes (not an exact solution), with
ENO3-LF (accuracy high, global) on 10 (circles) and 40 nodes (crosses).
(b) 2-D, ENO3-LF on 40^2 nodes at t = 1.5/pi^2.

**Check** (`nonconvex.tsv`, held against `published/nonconvex.tsv`).
1. Before the kink, t = 0.5/pi^2, the solution is smooth and the
   characteristics s = s0 + sin(1 + u0(s0)) t do not cross (every node has
   exactly one foot; the program stops otherwise), so the exact solution
   is G0(s0) + t (u0 sin(1 + u0) + cos(1 + u0)): errors in 1-D on N = 20
   ... 1280 for every accuracy; fitted orders 1.00, 1.98, 2.87, 3.28 (L1,
   the note).  Values: regression.
2. After the kink, t = 1.5/pi^2, 1-D (N = 20 ... 640) and 2-D (20 ...
   160), accuracies low and high: with the toolbox bound the three
   dissipations must give the same state, as the text says: `differ`
   (nodes that differ in any bit from GLF) and `spread` (max |phi_diss -
   phi_GLF|) are 0 at every grid.  With the tight bound they differ and
   must converge to one solution: LLLF - GLF goes from 6.5e-3 (N = 20) to
   3.7e-4 (N = 640) in 1-D; `cauchy`, max |phi_N - phi_2N| of GLF over the
   N grid's nodes, falls from 1.4e-2 to 4.5e-4 (about first order: the
   kink).  In 2-D LLF comes close to GLF (2e-9 at N = 20, 9e-15 at 80, 0
   at 160: the global range in the other dimension already reaches the
   maximum of |sin| once the grid resolves it), LLLF does not.
3. Thread-count independence: the 2-D 80^2 high-order run with 1 and 2
   OpenMP threads, `differ` must be 0 (the kernel's promise).

**Outputs.** `nonconvex.tsv`, `nonconvex_1d.dat` (index 0: reference,
1: N = 10, 2: N = 40), `nonconvex_2d.dat` (11 index blocks),
`nonconvex_summary.tsv` (the fitted orders before the kink and the
tight-bound differences after it, which `notes/nonconvex_notes.md`
presents); plotted by `plot/fig15.gp`.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "hj_cli.h"
#include "hj_fit.h"
#include "hj_io.h"
#include "hj_ls_io.h"
#include "hj_ls_term.h"
#include "p2_cli.h"
#include "p2_oshershu.h"
#include "hj_ls_accuracy.h"
#include "hj_math.h"

static const char *prog = "nonconvex_lf";

static const char *summary = "nonconvexLF of Mitchell's toolbox: a non-convex Hamiltonian (section 2.5.2, Figure 15).";
static const char *epilog =
    "With none of the run options (--accuracy .. --partial): Figure 15's data and the checks (nonconvex.tsv,\n"
    "nonconvex_1d.dat, nonconvex_2d.dat, nonconvex_summary.tsv).  With any of them: one run, its time sequence\n"
    "in nonconvex_run.dat.  See the comment at the top of nonconvex_lf.c.\n";

static double *run(const p2_os_run *r, hj_ls_grid *g, const char *path)
{
    return p2_os_solve_or_exit(prog, &p2_os_nonconvex, r, g, path);
}

static double max_diff(const hj_ls_grid *g, const double *a, const double *b)
{
    double m;
    hj_ls_norms(g, a, b, &m, NULL, NULL);
    return m;
}

/* max |fine - coarse| over the coarse nodes (node j of N is node 2j of 2N). */
static double cauchy(const hj_ls_grid *gc, const double *c, const hj_ls_grid *gf, const double *f)
{
    double m = 0;
    for (size_t r = 0; r < gc->rows; r++) {
        long i[HJ_LS_MAXDIM] = {0}, i2[HJ_LS_MAXDIM] = {0};
        const size_t k = hj_ls_row(gc, r, i);
        for (int d = 1; d < gc->dim; d++) i2[d] = 2 * i[d];
        const size_t k2 = hj_ls_index(gf, i2);
        for (long j = 0; j < gc->N[0]; j++) {
            const double e = fabs(c[k + (size_t)j] - f[k2 + 2 * (size_t)j]);
            m = e > m ? e : m;
        }
    }
    return m;
}

#define MAXN 8

int main(int argc, char **argv)
{
    hj_error err;
    p2_os_cli cli;
    p2_os_parse_cli(prog, summary, epilog, argc, argv, 1, &cli);
    const char *out_dir = cli.out_dir;
    const int quick = cli.quick;
    p2_one_thread(); /* small grids; the thread check below sets its own */
    char path[4096];
    hj_ls_grid g, g2;
    if (cli.single) {
        snprintf(path, sizeof path, "%s/nonconvex_run.dat", out_dir);
        hj_ls_free(run(&cli.run, &g, path));
        return 0;
    }
    const double ts = 0.5 / (HJ_PI * HJ_PI), tk = 1.5 / (HJ_PI * HJ_PI);

    /* Figure 15 (a): 1-D at t = 1.5/pi^2: a reference on 2560 nodes (WENO5,
     * RK3) and ENO3-LF (high, global) on 10 and 40 nodes. */
    hj_out out;
    p2_fail_if(prog, p2_open(&out, out_dir, "nonconvex_1d.dat", &err), &err);
    const long fig_n[3] = {2560, 10, 40};
    const int fig_acc[3] = {HJ_LS_ACC_VERYHIGH, HJ_LS_ACC_HIGH, HJ_LS_ACC_HIGH};
    for (int q = 0; q < 3; q++) {
        p2_os_run f = {1, fig_n[q], fig_acc[q], HJ_LS_GLF, 0, tk, 1};
        p2_os_append_block(prog, &p2_os_nonconvex, &f, out.fp,
                           "%s# index %d: accuracy %s, global, %ld nodes, t = 1.5/pi^2\n", q ? "\n\n" : "", q,
                           hj_ls_accuracy_name(fig_acc[q]), fig_n[q]);
    }
    p2_fail_if(prog, hj_out_commit(&out, &err), &err);
    {
        p2_os_run f = {2, 40, HJ_LS_ACC_HIGH, HJ_LS_GLF, 0, tk, 10};
        snprintf(path, sizeof path, "%s/nonconvex_2d.dat", out_dir);
        hj_ls_free(run(&f, &g, path));
    }

    hj_out tab, sum;
    p2_fail_if(prog, p2_open(&tab, out_dir, "nonconvex.tsv", &err), &err);
    /* The numbers of the report's note (notes/nonconvex_notes.md). */
    p2_fail_if(prog, p2_open(&sum, out_dir, "nonconvex_summary.tsv", &err), &err);
    fprintf(sum.fp, "# nonconvexLF.  smooth rows (t = 0.5/pi^2, 1-D, global): L1 error on the finest grid N and the orders of\n"
                    "# e = C h^p fitted over all grids (L1, Linf; nan: not determined).  kink rows (t = 1.5/pi^2, accuracy high,\n"
                    "# tight partial bound): max |phi_LLF - phi_GLF|, max |phi_LLLF - phi_GLF| and cauchy = max |phi_N - phi_2N|\n"
                    "# of GLF on the N grid's nodes\n"
                    "case\tdim\tacc\tN\tL1\tp_L1\tp_Linf\tllf_glf\tlllf_glf\tcauchy\n");
    fprintf(tab.fp, "# nonconvexLF checks: smooth = errors against the exact solution (characteristics) at t = 0.5/pi^2;\n"
                    "# kink (t = 1.5/pi^2): cauchy = max |phi_N - phi_2N| on the N grid's nodes (global),\n"
                    "# spread = max |phi_diss - phi_global|, differ = nodes where phi_diss != phi_global bitwise;\n"
                    "# threads: differ = nodes that differ between 1 and 2 OpenMP threads\n"
                    "case\tdim\tacc\tdiss\tpartial\tN\tL1\tL1_order\tLinf\tLinf_order\tcauchy\tspread\tdiffer\n");

    /* 1. Smooth: errors against the exact solution, 1-D, every accuracy. */
    static const long n1[] = {20, 40, 80, 160, 320, 640, 1280};
    const int nn1 = quick ? 4 : 7;
    for (int acc = 0; acc < HJ_LS_NACC; acc++) {
        double h[MAXN], e1[MAXN], ei[MAXN];
        for (int k = 0; k < nn1; k++) {
            p2_os_run f = {1, n1[k], acc, HJ_LS_GLF, 0, ts, 1};
            double *phi = run(&f, &g, NULL);
            double *ex = hj_ls_alloc(&g);
            if (!ex) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory");
            if (p2_os_exact_grid(&p2_os_nonconvex, &g, ts, ex) != 1)
                hj_cli_fail(prog, HJ_EXIT_RUN, "exact solution: characteristics cross before t = 0.5/pi^2");
            h[k] = g.dx[0];
            p2_os_errors(&g, phi, ex, &e1[k], &ei[k]);
            fprintf(tab.fp, "smooth\t1\t%s\tglobal\ttoolbox\t%ld\t%.4e\t", hj_ls_accuracy_name(acc), n1[k], e1[k]);
            if (k) fprintf(tab.fp, "%.2f\t", hj_pair_order(h[k - 1], e1[k - 1], h[k], e1[k])); else fputs("-\t", tab.fp);
            fprintf(tab.fp, "%.4e\t", ei[k]);
            if (k) fprintf(tab.fp, "%.2f\t-\t-\t-\n", hj_pair_order(h[k - 1], ei[k - 1], h[k], ei[k]));
            else fputs("-\t-\t-\t-\n", tab.fp);
            hj_ls_free(phi);
            hj_ls_free(ex);
        }
        hj_order_fit f1, fi;
        hj_error ferr;
        const int ok1 = !hj_fit_order(h, e1, nn1, &f1, &ferr), oki = !hj_fit_order(h, ei, nn1, &fi, &ferr);
        fprintf(sum.fp, "smooth\t1\t%s\t%ld\t%.17g\t%.17g\t%.17g\t-\t-\t-\n", hj_ls_accuracy_name(acc), n1[nn1 - 1],
                e1[nn1 - 1], ok1 ? f1.p : NAN, oki ? fi.p : NAN);
    }

    /* 2. Kink: the three dissipations, toolbox and tight partial bounds. */
    static const long nk1[] = {20, 40, 80, 160, 320, 640}, nk2[] = {20, 40, 80, 160};
    for (int dim = 1; dim <= 2; dim++) {
        const long *ns = dim == 1 ? nk1 : nk2;
        const int nn = dim == 1 ? (quick ? 4 : 6) : (quick ? 3 : 4);
        for (int ai = 0; ai < 2; ai++) {
            const int acc = ai ? HJ_LS_ACC_HIGH : HJ_LS_ACC_LOW;
            for (int tight = 0; tight < 2; tight++)
                for (int k = 0; k < nn; k++) {
                    hj_progress("nonconvex_lf: kink dim %d %s %s N %ld\n", dim, hj_ls_accuracy_name(acc),
                                tight ? "tight" : "toolbox", ns[k]);
                    double *phi[3];
                    for (int diss = 0; diss < 3; diss++) {
                        p2_os_run f = {dim, ns[k], acc, diss, tight, tk, 1};
                        phi[diss] = run(&f, &g, NULL);
                    }
                    double cy = NAN;
                    if (!tight) {
                        /* the next finer grid (global) */
                        p2_os_run f = {dim, 2 * ns[k], acc, HJ_LS_GLF, 0, tk, 1};
                        double *fine = run(&f, &g2, NULL);
                        cy = cauchy(&g, phi[0], &g2, fine);
                        hj_ls_free(fine);
                    }
                    double sp[3] = {0, 0, 0};
                    long dif[3] = {0, 0, 0};
                    for (int diss = 0; diss < 3; diss++) {
                        sp[diss] = max_diff(&g, phi[diss], phi[0]);
                        dif[diss] = hj_ls_count_differ(&g, phi[0], phi[diss]);
                        fprintf(tab.fp, "kink\t%d\t%s\t%s\t%s\t%ld\t-\t-\t-\t-\t", dim, hj_ls_accuracy_name(acc),
                                hj_ls_dissipation_name(diss), tight ? "tight" : "toolbox", ns[k]);
                        if (!tight && diss == 0) fprintf(tab.fp, "%.4e\t", cy); else fputs("-\t", tab.fp);
                        fprintf(tab.fp, "%.4e\t%ld\n", sp[diss], dif[diss]);
                    }
                    if (tight && acc == HJ_LS_ACC_HIGH) {
                        /* the Cauchy difference of GLF with the tight bound: the next finer grid */
                        p2_os_run f = {dim, 2 * ns[k], acc, HJ_LS_GLF, 1, tk, 1};
                        double *fine = run(&f, &g2, NULL);
                        fprintf(sum.fp, "kink\t%d\t%s\t%ld\t-\t-\t-\t%.17g\t%.17g\t%.17g\n", dim, hj_ls_accuracy_name(acc),
                                ns[k], sp[1], sp[2], cauchy(&g, phi[0], &g2, fine));
                        hj_ls_free(fine);
                    }
                    for (int diss = 0; diss < 3; diss++) hj_ls_free(phi[diss]);
                }
        }
    }

    /* 3. Thread-count independence: 2-D, high, global, 80^2, 1 against 2 threads. */
    long tdiff = -1;
    {
        p2_os_run f = {2, 80, HJ_LS_ACC_HIGH, HJ_LS_GLF, 0, tk, 1};
        double *one = run(&f, &g, NULL);
#ifdef _OPENMP
        omp_set_num_threads(2);
#endif
        double *two = run(&f, &g, NULL);
#ifdef _OPENMP
        omp_set_num_threads(1);
#endif
        tdiff = hj_ls_count_differ(&g, one, two);
        fprintf(tab.fp, "threads\t2\thigh\tglobal\ttoolbox\t80\t-\t-\t-\t-\t-\t%.4e\t%ld\n", max_diff(&g, one, two), tdiff);
        hj_ls_free(one);
        hj_ls_free(two);
    }
    p2_fail_if(prog, hj_out_commit(&tab, &err), &err);
    p2_fail_if(prog, hj_out_commit(&sum, &err), &err);
    return 0;
}
