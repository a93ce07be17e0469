/* # Convergence of the general Eikonal solver (hj_eik)
 *
 * Beyond paper 1: `hj_eik_solve` (common/hj_eik.h) at orders 1, 3 and 5,
 * in 2-D and 3-D, for a point source off the grid nodes at
 * s = (0.1234, -0.0567, 0.0311) on [-1, 1]^dim:
 *
 * - `const`: constant speed (T = |x - s|).  The factored unknown tau is 1
 *   everywhere, so every order is exact up to round-off; the row shows it.
 * - `linear`: a linear velocity v = v0 + g.x, v0 = 2, g = (0.5, -0.3, 0.2),
 *   whose travel time is T = acosh(1 + |g|^2 |x - s|^2 / (2 v(s) v(x))) / |g|.
 * - `obstacle` (2-D, order 3): a wall |x| < 0.05, y < 0.5 and the source
 *   at (-0.5, 0.1), against the same solver on a finer grid whose nodes
 *   include the coarse ones: N = 480, three times the finest size 160 (the
 *   quick run: 192, four times its finest size 48).
 * - `two_joint` and `two_separate`: two sources in the linear velocity,
 *   s_1 = (-0.4123, -0.3567, 0.2311) at time 0 and s_2 = (0.3789, 0.3133,
 *   -0.1689) at time 0.1, T = min_k (t0_k + T_k) with T_k the closed form
 *   above.  T has a kink where the fronts meet; `two_joint` is one solve
 *   with both sources, `two_separate` solves each alone and takes the
 *   minimum (hj_eik_options.separate_sources).  The table
 *   eik_sources.tsv sets them side by side with the CPU time of each
 *   solve (one run, clock(): the ratio is indicative on a shared machine).
 *
 * Errors are the mean over the nodes (L1) and the maximum (Linf), over all
 * nodes and "away" from the source (|x - s| >= 0.25); iter counts the
 * iterations (convergence tests) of the first order start and of the
 * higher order phase, where an iteration is one orthant pass for
 * `const` and `linear` (one point source, no obstacle: hj_eik.h) and
 * 2^dim full sweeps for `obstacle`; sweeps counts the work in whole-grid
 * sweeps (an iteration of 2^dim full sweeps is 2^dim, a pass one);
 * solves are the local solves per node (hj_eik_stats.updates / nodes:
 * locking skips the nodes whose stencil did not change).
 * Orders e = C h^p are fitted with Ceres (common/hj_fit.h) over the sizes
 * run; `make check` compares them with the design order (eik table of
 * paper1_fastsweeping/eik/).
 *
 * Output: OUT_DIR/eik_convergence.tsv (one row per case, dim, order, N),
 * OUT_DIR/eik_orders.tsv (the fitted orders, checked by make check) and
 * OUT_DIR/eik_sources.tsv (two sources: joint against separate).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "hj_cli.h"
#include "hj_eik.h"
#include "hj_fit.h"
#include "hj_io.h"

enum { CONST, LINEAR, OBSTACLE, TWO_JOINT, TWO_SEP, NCASE };
static const char *case_names[] = {"const", "linear", "obstacle", "two_joint", "two_separate"};
static const double V0 = 2.0, G[3] = {0.5, -0.3, 0.2}, S[3] = {0.1234, -0.0567, 0.0311};
static const double S2[2][3] = {{-0.4123, -0.3567, 0.2311}, {0.3789, 0.3133, -0.1689}}, T2[2] = {0, 0.1};
static const double AWAY = 0.25;

typedef struct {
    int cs, dim, order;
    long N;
    double h, l1, linf, l1a, linfa;
    long iter, fo_iter, sweeps;
    double solves; /* local solves per node (locking skips the others) */
    int converged;
    double cpu;    /* CPU seconds of the solve */
} row;

static double vel(const double *x, int dim)
{
    double v = V0;
    for (int d = 0; d < dim; d++) v += G[d] * x[d];
    return v;
}

static double exact_from(int cs, const double *x, const double *s, int dim)
{
    if (cs == CONST) {
        double r2 = 0;
        for (int d = 0; d < dim; d++) r2 += (x[d] - s[d]) * (x[d] - s[d]);
        return sqrt(r2);
    }
    return hj_eik_linear_time(dim, V0, G, s, x);
}

static double exact(int cs, const double *x, int dim)
{
    if (cs == TWO_JOINT || cs == TWO_SEP)
        return fmin(T2[0] + exact_from(LINEAR, x, S2[0], dim), T2[1] + exact_from(LINEAR, x, S2[1], dim));
    return exact_from(cs, x, S, dim);
}

static void node(const hj_eik_grid *g, size_t u, double x[3])
{
    const long a = (long)(u % (size_t)g->n[0]), b = (long)((u / (size_t)g->n[0]) % (size_t)g->n[1]),
               c = (long)(u / (size_t)(g->n[0] * g->n[1]));
    x[0] = g->x0[0] + a * g->dx[0];
    x[1] = g->x0[1] + b * g->dx[1];
    x[2] = g->dim == 3 ? g->x0[2] + c * g->dx[2] : 0;
}

/* Solve one case on N intervals; T (caller frees) holds the solution. */
static int solve(int cs, int dim, int order, long N, double **Tout, hj_eik_stats *st, double *cpu, hj_error *err)
{
    hj_eik_grid g = {dim, {N + 1, N + 1, dim == 3 ? N + 1 : 1}, {-1, -1, -1}, {2.0 / N, 2.0 / N, 2.0 / N}};
    const size_t n = (size_t)(g.n[0] * g.n[1] * g.n[2]);
    double *T = malloc(n * sizeof *T), *f = malloc(n * sizeof *f);
    unsigned char *ob = cs == OBSTACLE ? calloc(n, 1) : NULL;
    if (!T || !f || (cs == OBSTACLE && !ob)) {
        free(T), free(f), free(ob);
        return hj_error_set(err, HJ_ENOMEM, "out of memory for N = %ld", N);
    }
    for (size_t u = 0; u < n; u++) {
        double x[3];
        node(&g, u, x);
        f[u] = cs == CONST || cs == OBSTACLE ? 1 : 1 / vel(x, dim);
        if (ob) ob[u] = fabs(x[0]) < 0.05 + 1e-12 && x[1] < 0.5 + 1e-12;
    }
    hj_eik_source src[2] = {{{S[0], S[1], S[2]}, 0}};
    if (cs == OBSTACLE) src[0].x[0] = -0.5, src[0].x[1] = 0.1;
    const int two = cs == TWO_JOINT || cs == TWO_SEP;
    for (int k = 0; two && k < 2; k++) src[k] = (hj_eik_source){{S2[k][0], S2[k][1], S2[k][2]}, T2[k]};
    hj_eik_options o = hj_eik_default_options();
    o.order = order;
    o.tol = 1e-12;
    o.separate_sources = cs == TWO_SEP;
    const clock_t c0 = clock();
    int rc = hj_eik_solve(&g, f, 0, ob, src, two ? 2 : 1, NULL, &o, T, st, err);
    *cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
    free(f), free(ob);
    if (rc != HJ_OK) {
        free(T);
        return rc;
    }
    *Tout = T;
    return HJ_OK;
}

/* ref: the obstacle case's fine-grid solution, computed on first use. */
static int run(int cs, int dim, int order, long N, long Nref, double **ref_cache, row *r, hj_error *err)
{
    hj_eik_stats st;
    double *T = NULL, cpu, cpu_ref;
    int rc = solve(cs, dim, order, N, &T, &st, &cpu, err);
    if (rc == HJ_OK && cs == OBSTACLE && !*ref_cache) {
        hj_eik_stats sr;
        rc = solve(cs, dim, order, Nref, ref_cache, &sr, &cpu_ref, err);
    }
    const double *ref = *ref_cache;
    if (rc != HJ_OK) {
        free(T);
        return rc;
    }
    memset(r, 0, sizeof *r);
    r->cs = cs, r->dim = dim, r->order = order, r->N = N, r->h = 2.0 / N;
    r->iter = st.iterations, r->fo_iter = st.fo_iterations, r->sweeps = st.sweeps, r->converged = st.converged;
    r->cpu = cpu;
    const hj_eik_grid g = {dim, {N + 1, N + 1, dim == 3 ? N + 1 : 1}, {-1, -1, -1}, {2.0 / N, 2.0 / N, 2.0 / N}};
    const size_t n = (size_t)(g.n[0] * g.n[1] * g.n[2]);
    r->solves = (double)st.updates / (double)n;
    size_t cnt = 0, cnta = 0;
    const long m = cs == OBSTACLE ? Nref / N : 1;
    for (size_t u = 0; u < n; u++) {
        if (!isfinite(T[u])) continue; /* obstacle nodes */
        double x[3];
        node(&g, u, x);
        double e;
        if (cs == OBSTACLE) {
            const long a = (long)(u % (size_t)g.n[0]), b = (long)(u / (size_t)g.n[0]);
            e = fabs(T[u] - ref[(size_t)(a * m) + (size_t)(Nref + 1) * (size_t)(b * m)]);
        } else {
            e = fabs(T[u] - exact(cs, x, dim));
        }
        /* away from every source */
        const int two = cs == TWO_JOINT || cs == TWO_SEP;
        double r2 = INFINITY;
        for (int k = 0; k < (two ? 2 : 1); k++) {
            const double *s = two ? S2[k] : cs == OBSTACLE ? (const double[]){-0.5, 0.1, 0} : S;
            double rk = 0;
            for (int d = 0; d < dim; d++) rk += (x[d] - s[d]) * (x[d] - s[d]);
            r2 = fmin(r2, rk);
        }
        r->l1 += e;
        if (e > r->linf) r->linf = e;
        cnt++;
        if (r2 >= AWAY * AWAY) {
            r->l1a += e;
            if (e > r->linfa) r->linfa = e;
            cnta++;
        }
    }
    r->l1 /= (double)(cnt ? cnt : 1);
    r->l1a /= (double)(cnta ? cnta : 1);
    free(T);
    return HJ_OK;
}

int main(int argc, char **argv)
{
    const char *out_dir = "results/paper1";
    int quick = 0;
    hj_cli_opt opts[] = {
        {"--quick", HJ_OPT_FLAG, &quick, 0, 0, NULL, "reduced sizes (seconds): 2-D N = 24, 48, 96; 3-D N = 12, 24 (two sources 12, 16, 20)", NULL,
         NULL, 0, NULL, 0},
        {"--out-dir", HJ_OPT_STRING, &out_dir, 0, 0, "DIR", "directory of eik_convergence.tsv, eik_orders.tsv and eik_sources.tsv", NULL, NULL,
         0, NULL, 0},
    };
    hj_cli_spec spec = {"eik_convergence", "convergence of hj_eik (orders 1, 3, 5; 2-D and 3-D; point sources)", opts,
                        (int)(sizeof opts / sizeof opts[0]),
                        "Full sizes: 2-D N = 40, 80, 160, 320; 3-D N = 20, 40, 80 (two sources: 2-D N = 40, 80, 160, 3-D 16, 24, 32); obstacle N = 40, 80, 160 against N = 480."};
    hj_cli_parse_or_exit(&spec, argc, argv);

    static const long n2_full[] = {40, 80, 160, 320}, n3_full[] = {20, 40, 80}, nob_full[] = {40, 80, 160};
    static const long n2_quick[] = {24, 48, 96}, n3_quick[] = {12, 24}, nob_quick[] = {24, 48};
    /* two sources (about two single-source solves each, joint and
     * separate alike): sizes that keep the whole study near 40 s of CPU */
    static const long n3t_full[] = {16, 24, 32}, n3t_quick[] = {12, 16, 20};
    const long *n2 = quick ? n2_quick : n2_full, *n3 = quick ? n3_quick : n3_full, *nob = quick ? nob_quick : nob_full;
    const long *n3t = quick ? n3t_quick : n3t_full;
    const int k2 = quick ? 3 : 4, k3 = quick ? 2 : 3, kob = quick ? 2 : 3, k2t = 3, k3t = 3;
    const long Nref = quick ? 192 : 480;

    char path[4096], fpath[4096], spath[4096];
    hj_error err;
    snprintf(path, sizeof path, "%s/eik_convergence.tsv", out_dir);
    snprintf(fpath, sizeof fpath, "%s/eik_orders.tsv", out_dir);
    snprintf(spath, sizeof spath, "%s/eik_sources.tsv", out_dir);
    if (hj_out_check(path, &err) != HJ_OK || hj_out_check(fpath, &err) != HJ_OK || hj_out_check(spath, &err) != HJ_OK)
        hj_cli_fail(spec.prog, HJ_EXIT_USAGE, "%s", err.msg);

    row rows[128];
    int nr = 0;
    double *ref = NULL;
    for (int cs = CONST; cs < NCASE; cs++)
        for (int dim = 2; dim <= 3; dim++)
            for (int order = 1; order <= 5; order += 2) {
                if (cs == OBSTACLE && (dim == 3 || order != 3)) continue;
                const int two = cs == TWO_JOINT || cs == TWO_SEP;
                const long *ns = cs == OBSTACLE ? nob : dim == 2 ? n2 : two ? n3t : n3;
                const int k = cs == OBSTACLE ? kob : dim == 2 ? (two ? k2t : k2) : two ? k3t : k3;
                for (int i = 0; i < k; i++) {
                    hj_progress("eik_convergence: %s %d-D order %d N = %ld\n", case_names[cs], dim, order, ns[i]);
                    if (run(cs, dim, order, ns[i], Nref, &ref, &rows[nr], &err) != HJ_OK)
                        hj_cli_fail(spec.prog, HJ_EXIT_RUN, "%s %d-D order %d N = %ld: %s", case_names[cs], dim, order,
                                    ns[i], err.msg);
                    nr++;
                }
            }

    free(ref);
    hj_out tab, fit, two;
    if (hj_out_open(&tab, path, &err) != HJ_OK) hj_cli_fail(spec.prog, HJ_EXIT_RUN, "%s", err.msg);
    fprintf(tab.fp, "# hj_eik convergence (paper1_fastsweeping/eik_convergence.c); away: |x - s| >= %g\n", AWAY);
    fprintf(tab.fp, "case\tdim\torder\tN\th\tL1\tLinf\tL1_away\tLinf_away\titer\tfo_iter\tsweeps\tsolves\tconverged\tcpu_s\n");
    for (int i = 0; i < nr; i++) {
        const row *r = &rows[i];
        fprintf(tab.fp, "%s\t%d\t%d\t%ld\t%.6g\t%.3e\t%.3e\t%.3e\t%.3e\t%ld\t%ld\t%ld\t%.1f\t%d\t%.3f\n",
                case_names[r->cs], r->dim, r->order, r->N, r->h, r->l1, r->linf, r->l1a, r->linfa, r->iter, r->fo_iter,
                r->sweeps, r->solves, r->converged, r->cpu);
    }
    if (hj_out_open(&fit, fpath, &err) != HJ_OK) hj_cli_fail(spec.prog, HJ_EXIT_RUN, "%s", err.msg);
    fprintf(fit.fp, "# fitted orders e = C h^p (Ceres, Huber loss, see common/hj_fit.h)\n");
    fprintf(fit.fp, "case\tdim\torder\tnorm\tp\tp_se\tC\tp_lsq\tn\n");
    for (int i = 0; i < nr;) {
        int j = i;
        while (j < nr && rows[j].cs == rows[i].cs && rows[j].dim == rows[i].dim && rows[j].order == rows[i].order) j++;
        static const char *norms[] = {"L1", "Linf", "L1_away", "Linf_away"};
        for (int q = 0; q < 4; q++) {
            double h[16], e[16];
            int n = 0;
            for (int k = i; k < j; k++) {
                const double v = q == 0 ? rows[k].l1 : q == 1 ? rows[k].linf : q == 2 ? rows[k].l1a : rows[k].linfa;
                if (v > 0) h[n] = rows[k].h, e[n++] = v;
            }
            hj_order_fit f;
            hj_error ferr;
            /* const: errors at round-off, no order to fit */
            if (rows[i].cs != CONST && n >= 2 && hj_fit_order(h, e, n, &f, &ferr) == HJ_OK)
                fprintf(fit.fp, "%s\t%d\t%d\t%s\t%.4f\t%.4f\t%.6g\t%.4f\t%d\n", case_names[rows[i].cs], rows[i].dim,
                        rows[i].order, norms[q], f.p, f.p_se, f.C, f.p_ls, f.n);
        }
        i = j;
    }
    /* two sources: each joint row beside the separate row of its size */
    if (hj_out_open(&two, spath, &err) != HJ_OK) hj_cli_fail(spec.prog, HJ_EXIT_RUN, "%s", err.msg);
    fprintf(two.fp, "# two sources in the linear velocity: one joint solve against each source solved alone "
                    "(separate); CPU seconds of one run each\n");
    fprintf(two.fp, "dim\torder\tN\tL1_joint\tL1_separate\tLinf_joint\tLinf_separate\tsweeps_joint\tsweeps_separate"
                    "\tsolves_joint\tsolves_separate\tcpu_joint_s\tcpu_separate_s\tcpu_ratio\n");
    for (int i = 0; i < nr; i++) {
        const row *a = &rows[i];
        if (a->cs != TWO_JOINT) continue;
        for (int j = 0; j < nr; j++) {
            const row *b = &rows[j];
            if (b->cs != TWO_SEP || b->dim != a->dim || b->order != a->order || b->N != a->N) continue;
            fprintf(two.fp, "%d\t%d\t%ld\t%.3e\t%.3e\t%.3e\t%.3e\t%ld\t%ld\t%.1f\t%.1f\t%.3f\t%.3f\t%.2f\n", a->dim,
                    a->order, a->N, a->l1, b->l1, a->linf, b->linf, a->sweeps, b->sweeps, a->solves, b->solves, a->cpu,
                    b->cpu, a->cpu > 0 ? b->cpu / a->cpu : NAN);
        }
    }
    if (hj_out_commit(&tab, &err) != HJ_OK || hj_out_commit(&fit, &err) != HJ_OK || hj_out_commit(&two, &err) != HJ_OK)
        hj_cli_fail(spec.prog, HJ_EXIT_RUN, "%s", err.msg);
    return 0;
}
