/* anderson_eik.c -- Anderson acceleration of the high order Eikonal fast
 * sweeping (an experiment; paper1_fastsweeping/eik/notes/anderson.md).
 *
 * Case `linear` of paper1_fastsweeping/eik_convergence.c: speed
 * v = 2 + g.x, g = (0.5, -0.3, 0.2), source s = (0.1234, -0.0567, 0.0311)
 * (its first dim coordinates) on [-1, 1]^dim, (N + 1)^dim nodes,
 * h = 2 / N, closed form T = acosh(1 + |g|^2 |x - s|^2 / (2 v(s) v(x))) / |g|.
 *
 * Solves it with hj_eik_solve plain and with hj_eik_options.anderson = m
 * (anderson_start as given), `rounds` times each, alternated (plain
 * first in odd rounds, AA first in even ones).  Per run: passes
 * (stats.iterations, fo_iterations), grid sweeps, local solves per node,
 * last change, L1 (mean over the nodes) and Linf errors against the
 * closed form, CPU seconds (clock()); then the minimum and largest CPU
 * time of each and max |T_aa - T_plain| / max T.
 *
 * The option was not kept: this program needs the measured build,
 * `git apply studies/anderson_eik/hj_eik_anderson.patch` (it adds
 * hj_eik_options.anderson and anderson_start to common/hj_eik.[ch] and
 * this program to the Makefile), then `make
 * build/bin/studies/anderson_eik/anderson_eik`; run by hand only, with
 * OMP_NUM_THREADS=1.  anderson_eik --help for the arguments.  The
 * patched solver also reads, for the side experiments of the note, the
 * environment variables HJ_AA_BETA (damping, default 1), HJ_AA_UNLOCK
 * (1: unlock every free node after an AA step), HJ_AA_RESTART (drop the
 * history when the change grows by more than this factor; 0: never),
 * HJ_AA_EVERY (the map is this many passes; default 1), HJ_AA_W (weight
 * the least squares by (|f| / max |f|)^w) and HJ_AA_VERBOSE (per AA step
 * the least squares' residual reduction, on stderr).
 */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "hj_cli.h"
#include "hj_eik.h"
#include "../eik_study.h"

static const double V0 = EIK_STUDY_V0, S[3] = EIK_STUDY_S, G[3] = EIK_STUDY_G;
static int dim = 3;
static int verbose = 0;

static double vel(const double *x) { return eik_study_vel(dim, V0, G, x); }
static double exact(const double *x) { return hj_eik_linear_time(dim, V0, G, S, x); }

typedef struct {
    long iterations, fo_iterations, sweeps;
    double solves, change, l1, linf, cpu;
    int rc;
} result;

static void progress(long it, double change, void *ctx)
{
    double *last = ctx;
    if (verbose) fprintf(stderr, "  pass %3ld change %.3e ratio %.3f\n", it, change, *last > 0 ? change / *last : 0);
    *last = change;
}

static int solve(const hj_eik_grid *g, const double *f, size_t n, const hj_eik_options *o, double *T, result *r)
{
    hj_eik_options oo = *o;
    double last = 0;
    oo.progress = progress;
    oo.progress_ctx = &last;
    hj_eik_stats st;
    hj_error err;
    hj_error_clear(&err);
    const hj_eik_source src = {{S[0], S[1], dim == 3 ? S[2] : 0}, 0};
    const clock_t c0 = clock();
    r->rc = hj_eik_solve(g, f, 0, NULL, &src, 1, NULL, &oo, T, &st, &err);
    r->cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
    if (r->rc != HJ_OK && r->rc != HJ_ENOCONV) {
        fprintf(stderr, "anderson_eik: %s\n", err.msg);
        return 0;
    }
    if (r->rc == HJ_ENOCONV) fprintf(stderr, "anderson_eik: %s\n", err.msg);
    r->iterations = st.iterations;
    r->fo_iterations = st.fo_iterations;
    r->sweeps = st.sweeps;
    r->solves = (double)st.updates / (double)n;
    r->change = st.change;
    double l1 = 0, linf = 0;
    for (size_t u = 0; u < n; u++) {
        const long a = (long)(u % (size_t)g->n[0]), b = (long)((u / (size_t)g->n[0]) % (size_t)g->n[1]),
                   c = (long)(u / (size_t)(g->n[0] * g->n[1]));
        const double x[3] = {-1 + a * g->dx[0], -1 + b * g->dx[1], dim == 3 ? -1 + c * g->dx[2] : 0};
        const double e = fabs(T[u] - exact(x));
        l1 += e;
        if (e > linf) linf = e;
    }
    r->l1 = l1 / (double)n;
    r->linf = linf;
    return 1;
}

static void print_row(const char *what, long N, const result *r)
{
    printf("%-6s %2d %5ld %5ld %3ld %6ld %8.2f %10.3e %12.5e %12.5e %8.3f\n", what, dim, N, r->iterations,
           r->fo_iterations, r->sweeps, r->solves, r->change, r->l1, r->linf, r->cpu);
}


static void usage(FILE *fp)
{
    fprintf(fp,
            "usage: anderson_eik [--dim 2|3] [--order 3|5] [--tol t] [--m M] [--start s] [--rounds R]\n"
            "                    [--run both|plain|aa] [--verbose] N\n"
            "  Solves the `linear` case on [-1,1]^dim with N intervals per axis by hj_eik_solve plain\n"
            "  and with Anderson acceleration AA(M) (anderson_start s), R rounds alternated.\n"
            "  Defaults: dim 3, order 3, tol 1e-12, M 3, s 1e-6, R 1, run both.  --verbose: every\n"
            "  pass's change (stderr).  Columns: run, dim, N, passes, first order passes, grid\n"
            "  sweeps, local solves per node, last change / max T, L1, Linf, CPU s.\n");
}

int main(int argc, char **argv)
{
    long N = 0, ord = 3, dm = 3, m = 3, rounds = 1;
    double tol = 1e-12, start = 1e-6;
    int run_plain = 1, run_aa = 1;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const int more = i + 1 < argc;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage(stdout);
            return 0;
        } else if (!strcmp(a, "--verbose")) verbose = 1;
        else if (!strcmp(a, "--dim") && more) {
            if (!eik_study_long(argv[++i], &dm) || (dm != 2 && dm != 3)) goto bad;
        } else if (!strcmp(a, "--order") && more) {
            if (!eik_study_long(argv[++i], &ord) || (ord != 1 && ord != 3 && ord != 5)) goto bad;
        } else if (!strcmp(a, "--tol") && more) {
            if (!eik_study_double(argv[++i], &tol) || !(tol > 0)) goto bad;
        } else if (!strcmp(a, "--start") && more) {
            if (!eik_study_double(argv[++i], &start) || !(start > 0)) goto bad;
        } else if (!strcmp(a, "--m") && more) {
            if (!eik_study_long(argv[++i], &m) || m < 1 || m > 8) goto bad;
        } else if (!strcmp(a, "--rounds") && more) {
            if (!eik_study_long(argv[++i], &rounds) || rounds < 1 || rounds > 100) goto bad;
        } else if (!strcmp(a, "--run") && more) {
            const char *v = argv[++i];
            run_plain = run_aa = 1;
            if (!strcmp(v, "plain")) run_aa = 0;
            else if (!strcmp(v, "aa")) run_plain = 0;
            else if (strcmp(v, "both")) goto bad;
        } else if (a[0] != '-' && N == 0) {
            if (!eik_study_long(a, &N) || N < 6 || N > 4000) goto bad;
        } else goto bad;
    }
    if (N == 0) goto bad;
    dim = (int)dm;
    const long nn[3] = {N + 1, N + 1, dim == 3 ? N + 1 : 1};
    const size_t n = (size_t)(nn[0] * nn[1] * nn[2]);
    const hj_eik_grid g = {dim, {nn[0], nn[1], nn[2]}, {-1, -1, -1}, {2.0 / N, 2.0 / N, 2.0 / N}};
    double *f = malloc(n * sizeof(double)), *Tp = malloc(n * sizeof(double)), *Ta = malloc(n * sizeof(double));
    if (!f || !Tp || !Ta) {
        fprintf(stderr, "anderson_eik: out of memory\n");
        return 1;
    }
    for (size_t u = 0; u < n; u++) {
        const long a = (long)(u % (size_t)nn[0]), b = (long)((u / (size_t)nn[0]) % (size_t)nn[1]),
                   c = (long)(u / (size_t)(nn[0] * nn[1]));
        const double x[3] = {-1 + a * g.dx[0], -1 + b * g.dx[1], dim == 3 ? -1 + c * g.dx[2] : 0};
        f[u] = 1 / vel(x);
    }
    hj_eik_options op = hj_eik_default_options();
    op.order = (int)ord;
    op.tol = tol;
    hj_eik_options oa = op;
    oa.anderson = (int)m;
    oa.anderson_start = start;
    printf("# linear, order %ld, tol %g, AA m %ld start %g, %ld round%s\n", ord, tol, m, start, rounds,
           rounds > 1 ? "s" : "");
    printf("# run  dim     N  pass  fo sweeps  solves/n     change           L1         Linf    cpu_s\n");
    double pmin = INFINITY, pmax = 0, amin = INFINITY, amax = 0;
    for (long r = 0; r < rounds; r++) {
        for (int k = 0; k < 2; k++) {
            const int aa = (k == 0) == (r % 2 == 1);
            if (aa ? !run_aa : !run_plain) continue;
            result res;
            if (!solve(&g, f, n, aa ? &oa : &op, aa ? Ta : Tp, &res)) return 1;
            print_row(aa ? "aa" : "plain", N, &res);
            fflush(stdout);
            if (aa) {
                amin = fmin(amin, res.cpu);
                amax = fmax(amax, res.cpu);
            } else {
                pmin = fmin(pmin, res.cpu);
                pmax = fmax(pmax, res.cpu);
            }
        }
    }
    if (run_plain) printf("cpu plain %.3f (%.3f-%.3f)\n", pmin, pmin, pmax);
    if (run_aa) printf("cpu aa    %.3f (%.3f-%.3f)\n", amin, amin, amax);
    if (run_plain && run_aa) {
        double d = 0, sc = 0;
        for (size_t u = 0; u < n; u++) {
            if (fabs(Tp[u] - Ta[u]) > d) d = fabs(Tp[u] - Ta[u]);
            if (fabs(Tp[u]) > sc) sc = fabs(Tp[u]);
        }
        printf("max |T_aa - T_plain| / max T = %.3e (tol %g)\n", d / sc, tol);
    }
    free(f);
    free(Tp);
    free(Ta);
    return 0;
bad:
    fprintf(stderr, "anderson_eik: bad arguments (need N in 6 .. 4000, --dim 2|3, --order 1|3|5, --tol > 0, --m 1..8, "
                    "--start > 0, --rounds 1..100, --run both|plain|aa); see --help\n");
    return 2;
}
