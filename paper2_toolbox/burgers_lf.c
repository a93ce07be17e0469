/*
# burgersLF: Burgers' equation as a general HJ PDE with Lax-Friedrichs (Figure 14)

**Problem.** Section 2.5.1, the toolbox's `burgersLF`: Osher & Shu's
(1991) example 1 and its two-dimensional version,

    D_t phi + H(grad phi) = 0,   H(p) = (alpha + sum_i p_i)^2 / 2   (15),  alpha = 1,
    phi(x, 0) = -cos(pi / d * sum_i x_i)   on [-d, d)^d, periodic.

The text prints the 1-D data -cos(pi x) on -1 <= x < 1 in (14) (its "1 <=
x" is a transcription slip); for d dimensions we divide by d, as the
released `burgersLF.m` does, so that the data stays periodic on
[-d, d)^d.  With u = phi_x this is Burgers' equation for u; u0 = pi sin(pi
x) steepens into a shock at t = 1/pi^2, where phi gets a kink.

**Method.** `termLaxFriedrichs` (`hj_ls_lax_friedrichs`) with H and the
toolbox's partial bound alpha_j = 1 + sum_i max(|pmin_i|, |pmax_i|) (an
overestimate of max |1 + sum_i p_i| over the box, as in section 2.5.1), the
dissipation 'global', 'local' or 'locallocal' (GLF, LLF, LLLF of section
3.6.2), the accuracy levels of the toolbox (low: first order upwind + RK1,
medium: ENO2 + RK2, high: ENO3 + RK3, veryHigh: WENO5 + RK3), TVD RK with
FactorCFL 0.5.  N nodes per dimension, dx = 2d / N (the toolbox's periodic
grid), output every tMax / 10.

**Options and defaults.** `--accuracy`, `--diss`, `--dim` (1-3), `--N`
(gridSize), `--tmax`, as `burgersLF(accuracy, dissType, gridDim,
gridSize, tMax)`.  The text gives only tMax's default, 1.5/pi^2; for the
others we take those of the released m-file: low, global, gridDim 2,
gridSize 80 / 2^(gridDim - 1).  With any of these options the program
makes one run (time sequence in `burgers_run.dat`, errors on stdout).

**Figure 14.** (a) 1-D at t = 1.5/pi^2: the exact solution (line) and the
third order ENO-LLF approximation (accuracy high, local).  The caption says
"a grid of 10 points"; we show that grid (circles) and 40 nodes (crosses)
beside it, since 10 nodes resolve the kink only to a cell.  (b) 2-D,
ENO3-LLF on 40^2 nodes at t = 1.5/pi^2 (surface).

**Exact solution.** phi depends on s = sum_i x_i / d only; G(s, t) solves
G_t + (1 + G_s)^2 / 2 = 0, G(s, 0) = -cos(pi s).  Along characteristics
s = s0 + (1 + u0(s0)) t with u0 = pi sin(pi s0), and G = G0(s0) + t (u0^2 -
1) / 2.  After t = 1/pi^2 up to three feet s0 reach a point (three are
found at t = 1.5/pi^2); H is convex, so the viscosity solution is the
minimum over them (Hopf-Lax).  Feet are bracketed on 400 sub-intervals and
bisected to adjacent doubles (`p2_oshershu.c`).

**Check.** `burgers.tsv`: the average (L1) and maximum (Linf) error over
the nodes at t = 0.5/pi^2 (smooth) and 1.5/pi^2 (kink), in 1-D on N = 20,
40, ..., 1280 and in 2-D on N = 20, ..., 160 nodes per dimension, for every
accuracy and dissipation, with pairwise orders; `burgers_fit.tsv`: the
order fitted by Ceres (e = C h^p, Huber loss, `common/hj_fit.h`) over the
coarse grids (1-D 20-160, 2-D 20-80: the quick run) and over all grids.
For the smooth solution the reference is the formal order of the accuracy
level, 1, 2, 3 and 3 (WENO5 with TVD RK3 at dt proportional to dx is third
order in the limit): a wrong stencil, RK stage or dissipation would lower
it.  Measured over 1-D N = 20-1280 (L1, global): 0.99, 1.99, 2.96 and 3.42,
the last because WENO5's spatial error dominates on the coarse grids
(pairwise orders 4.1, 4.0, 3.5, 3.1, 3.0, 3.0: RK3 takes over).  After the
kink there is no theory for the order: L1 comes out near 1 (low) and 2
(the others), Linf near 1.1-1.2 (the kink is smeared over a few cells), and
these fitted orders and all error values are regression values of our own
run.  In 1-D LLF and LLLF are the same scheme (the local range is taken in
the only dimension): every 1-D run gives bitwise identical states
(the note).  With GLF and LLLF the 2-D errors equal the 1-D
ones at the same N (the data depend on (x + y)/2 only and the 2-D scheme
reduces to the 1-D one); LLF, which takes the global gradient range in the
other dimension, is more dissipative in 2-D (errors up to 1.4 times
larger).

**Outputs.** `burgers.tsv`, `burgers_fit.tsv` (checked against
`published/burgers*.tsv`), `burgers_1d.dat` (gnuplot index 0: exact,
1: N = 10, 2: N = 40), `burgers_2d.dat` (11 index blocks, t = 0 ...
1.5/pi^2), `burgers_summary.tsv` (per case and dimension: the orders
fitted over all grids with global dissipation, the characteristic feet and
the LLF-LLLF comparison, which `notes/burgers_notes.md` presents); plotted
by `plot/fig14.gp`.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


#include "hj_cli.h"
#include "hj_fit.h"
#include "hj_io.h"
#include "hj_ls_io.h"
#include "hj_ls_term.h"
#include "hj_ls_accuracy.h"
#include "p2_cli.h"
#include "p2_oshershu.h"
#include "hj_math.h"

static const char *prog = "burgers_lf";

static const char *summary = "burgersLF of Mitchell's toolbox: Burgers' equation as a general Hamiltonian (section 2.5.1, Figure 14).";
static const char *epilog =
    "With none of the first five options: Figure 14's data and the convergence study against the exact\n"
    "solution (burgers.tsv, burgers_fit.tsv, burgers_1d.dat, burgers_2d.dat, burgers_summary.tsv).\n"
    "With any of them: one run, its time sequence in burgers_run.dat and its errors on stdout.\n"
    "See the comment at the top of burgers_lf.c.\n";

static double *run(const p2_os_run *r, hj_ls_grid *g, const char *path)
{
    return p2_os_solve_or_exit(prog, &p2_os_burgers, r, g, path);
}

#define NCASE 2
#define MAXN 8
static const char *const case_name[NCASE] = {"smooth", "kink"};
static const double case_t[NCASE] = {0.5, 1.5}; /* times pi^-2 */

int main(int argc, char **argv)
{
    hj_error err;
    p2_os_cli cli;
    p2_os_parse_cli(prog, summary, epilog, argc, argv, 0, &cli);
    const char *out_dir = cli.out_dir;
    const int quick = cli.quick;
    p2_os_run r = cli.run;
    p2_one_thread(); /* grids of at most 1280 or 160^2 nodes */
    char path[4096];
    hj_ls_grid g;

    if (cli.single) {
        snprintf(path, sizeof path, "%s/burgers_run.dat", out_dir);
        double *phi = run(&r, &g, path);
        double *ex = hj_ls_alloc(&g);
        if (!ex) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory");
        const int nr = p2_os_exact_grid(&p2_os_burgers, &g, r.tmax, ex);
        double l1, linf;
        p2_os_errors(&g, phi, ex, &l1, &linf);
        printf("burgersLF accuracy=%s diss=%s dim=%d N=%ld tmax=%.6g: L1 (average) %.3e, Linf %.3e "
               "(exact by characteristics, up to %d feet)\n",
               hj_ls_accuracy_name(r.acc), hj_ls_dissipation_name(r.diss), r.dim, r.N, r.tmax, l1, linf, nr);
        hj_ls_free(phi);
        hj_ls_free(ex);
        return 0;
    }

    /* Figure 14 (a): exact and ENO3-LLF on 10 and 40 nodes, 1-D, t = 1.5/pi^2. */
    const double tk = 1.5 / (HJ_PI * HJ_PI);
    hj_out out;
    p2_fail_if(prog, p2_open(&out, out_dir, "burgers_1d.dat", &err), &err);
    fprintf(out.fp, "# index 0: exact solution at t = 1.5/pi^2 (x phi)\n");
    for (int k = 0; k <= 400; k++) {
        const double x = -1 + 2.0 * k / 400;
        fprintf(out.fp, "%.6f %.10g\n", x, p2_os_exact(&p2_os_burgers, x, tk, NULL));
    }
    const long fig_n[2] = {10, 40};
    for (int q = 0; q < 2; q++) {
        p2_os_run f = {1, fig_n[q], HJ_LS_ACC_HIGH, HJ_LS_LLF, 0, tk, 1};
        p2_os_append_block(prog, &p2_os_burgers, &f, out.fp,
                           "\n\n# index %d: ENO3-LLF (accuracy high, local) on %ld nodes\n", q + 1, fig_n[q]);
    }
    p2_fail_if(prog, hj_out_commit(&out, &err), &err);
    /* Figure 14 (b): 2-D, ENO-LLF on 40^2, the toolbox's 10 output steps. */
    {
        p2_os_run f = {2, 40, HJ_LS_ACC_HIGH, HJ_LS_LLF, 0, tk, 10};
        snprintf(path, sizeof path, "%s/burgers_2d.dat", out_dir);
        hj_ls_free(run(&f, &g, path));
    }

    /* The convergence study. */
    static const long n1[] = {20, 40, 80, 160, 320, 640, 1280}, n2[] = {20, 40, 80, 160};
    const int nn1 = quick ? 4 : 7, nn2 = quick ? 3 : 4;
    typedef struct { double h, l1, linf; } res;
    static res R[NCASE][2][HJ_LS_NACC][3][MAXN];
    int feet[NCASE][2] = {{0, 0}, {0, 0}}; /* most characteristic feet at a node, per case and dimension */
    long identical_llf[NCASE] = {0, 0}, compared_llf[NCASE] = {0, 0};
    for (int dim = 1; dim <= 2; dim++) {
        const long *ns = dim == 1 ? n1 : n2;
        const int nn = dim == 1 ? nn1 : nn2;
        for (int ci = 0; ci < NCASE; ci++)
            for (int k = 0; k < nn; k++) {
                hj_ls_grid ge;
                p2_fail_if(prog, p2_os_grid(dim, ns[k], &ge, &err), &err);
                double *ex = hj_ls_alloc(&ge);
                if (!ex) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory");
                const int mr = p2_os_exact_grid(&p2_os_burgers, &ge, case_t[ci] / (HJ_PI * HJ_PI), ex);
                feet[ci][dim - 1] = mr > feet[ci][dim - 1] ? mr : feet[ci][dim - 1];
                hj_progress("burgers_lf: %s dim %d N %ld\n", case_name[ci], dim, ns[k]);
                for (int acc = 0; acc < HJ_LS_NACC; acc++) {
                    double *prev = NULL;
                    for (int diss = 0; diss < 3; diss++) {
                        p2_os_run f = {dim, ns[k], acc, diss, 0, case_t[ci] / (HJ_PI * HJ_PI), 1};
                        double *phi = run(&f, &g, NULL);
                        res *o = &R[ci][dim - 1][acc][diss][k];
                        o->h = g.dx[0];
                        p2_os_errors(&g, phi, ex, &o->l1, &o->linf);
                        if (dim == 1 && diss == HJ_LS_LLLF) {
                            compared_llf[ci]++;
                            identical_llf[ci] += hj_ls_count_differ(&g, prev, phi) == 0;
                        }
                        hj_ls_free(prev);
                        prev = phi;
                    }
                    hj_ls_free(prev);
                }
                hj_ls_free(ex);
            }
    }

    /* burgers.tsv: errors and pairwise orders. */
    p2_fail_if(prog, p2_open(&out, out_dir, "burgers.tsv", &err), &err);
    fprintf(out.fp, "# burgersLF against the exact solution by characteristics; L1 = average |error| over the nodes,"
                    " Linf = maximum; smooth: t = 0.5/pi^2, kink: t = 1.5/pi^2\n"
                    "case\tdim\tacc\tdiss\tN\th\tL1\tL1_order\tLinf\tLinf_order\n");
    for (int ci = 0; ci < NCASE; ci++)
        for (int dim = 1; dim <= 2; dim++)
            for (int acc = 0; acc < HJ_LS_NACC; acc++)
                for (int diss = 0; diss < 3; diss++)
                    for (int k = 0; k < (dim == 1 ? nn1 : nn2); k++) {
                        const res *o = &R[ci][dim - 1][acc][diss][k];
                        fprintf(out.fp, "%s\t%d\t%s\t%s\t%ld\t%.6g\t%.4e\t", case_name[ci], dim,
                                hj_ls_accuracy_name(acc), hj_ls_dissipation_name(diss), (dim == 1 ? n1 : n2)[k], o->h,
                                o->l1);
                        if (k) fprintf(out.fp, "%.2f\t", hj_pair_order(o[-1].h, o[-1].l1, o->h, o->l1));
                        else fputs("-\t", out.fp);
                        fprintf(out.fp, "%.4e\t", o->linf);
                        if (k) fprintf(out.fp, "%.2f\n", hj_pair_order(o[-1].h, o[-1].linf, o->h, o->linf));
                        else fputs("-\n", out.fp);
                    }
    p2_fail_if(prog, hj_out_commit(&out, &err), &err);

    /* burgers_fit.tsv: orders fitted over the quick range and (full run) all grids. */
    hj_out fit, sum;
    p2_fail_if(prog, p2_open(&fit, out_dir, "burgers_fit.tsv", &err), &err);
    fprintf(fit.fp, "# burgersLF: orders p of e = C h^p fitted by Ceres (common/hj_fit.h) over the grids N in range\n"
                    "case\tdim\tacc\tdiss\trange\tnorm\tp\tp_se\tp_lsq\n");
    /* The numbers of the report's note (notes/burgers_notes.md), one row per case and dimension. */
    p2_fail_if(prog, p2_open(&sum, out_dir, "burgers_summary.tsv", &err), &err);
    fprintf(sum.fp, "# burgersLF: orders p of e = C h^p (L1, Linf) fitted over all grids of the run, global dissipation, per\n"
                    "# accuracy; feet = the most characteristic feet of the exact solution at a node; in 1-D, llf_identical of\n"
                    "# llf_compared runs gave bitwise identical states with LLF and LLLF (- in 2-D)\ncase\tdim\tgrids");
    for (int acc = 0; acc < HJ_LS_NACC; acc++)
        fprintf(sum.fp, "\tp_L1_%s\tp_Linf_%s", hj_ls_accuracy_name(acc), hj_ls_accuracy_name(acc));
    fputs("\tfeet\tllf_identical\tllf_compared\n", sum.fp);
    for (int ci = 0; ci < NCASE; ci++)
        for (int dim = 1; dim <= 2; dim++) {
            const long *ns = dim == 1 ? n1 : n2;
            const int nn = dim == 1 ? nn1 : nn2, nq = dim == 1 ? 4 : 3;
            double pglf[HJ_LS_NACC][2];
            for (int acc = 0; acc < HJ_LS_NACC; acc++)
                for (int diss = 0; diss < 3; diss++)
                    for (int span = 0; span < 2; span++) {
                        const int m = span ? nn : nq;
                        if (span && m == nq) continue;
                        double pl[2];
                        for (int q = 0; q < 2; q++) {
                            double h[MAXN], e[MAXN];
                            for (int k = 0; k < m; k++) {
                                const res *o = &R[ci][dim - 1][acc][diss][k];
                                h[k] = o->h, e[k] = q ? o->linf : o->l1;
                            }
                            hj_order_fit f;
                            hj_error ferr;
                            const char *qn = q ? "Linf" : "L1";
                            if (hj_fit_order(h, e, m, &f, &ferr) == HJ_OK) {
                                fprintf(fit.fp, "%s\t%d\t%s\t%s\t%ld-%ld\t%s\t%.2f\t%.2f\t%.2f\n", case_name[ci], dim,
                                        hj_ls_accuracy_name(acc), hj_ls_dissipation_name(diss), ns[0], ns[m - 1], qn,
                                        f.p, f.p_se, f.p_ls);
                                pl[q] = f.p;
                            } else {
                                fprintf(fit.fp, "%s\t%d\t%s\t%s\t%ld-%ld\t%s\tnan\tnan\tnan\n", case_name[ci], dim,
                                        hj_ls_accuracy_name(acc), hj_ls_dissipation_name(diss), ns[0], ns[m - 1], qn);
                                pl[q] = NAN;
                            }
                        }
                        if (diss == HJ_LS_GLF && m == nn) pglf[acc][0] = pl[0], pglf[acc][1] = pl[1];
                    }
            fprintf(sum.fp, "%s\t%d\t%ld-%ld", case_name[ci], dim, ns[0], ns[nn - 1]);
            for (int acc = 0; acc < HJ_LS_NACC; acc++) fprintf(sum.fp, "\t%.17g\t%.17g", pglf[acc][0], pglf[acc][1]);
            fprintf(sum.fp, "\t%d", feet[ci][dim - 1]);
            if (dim == 1) fprintf(sum.fp, "\t%ld\t%ld\n", identical_llf[ci], compared_llf[ci]);
            else fputs("\t-\t-\n", sum.fp);
        }
    p2_fail_if(prog, hj_out_commit(&fit, &err), &err);
    p2_fail_if(prog, hj_out_commit(&sum, &err), &err);
    return 0;
}
