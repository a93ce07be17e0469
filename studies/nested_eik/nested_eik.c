/* nested_eik.c -- nested iteration for the high order Eikonal fast
 * sweeping (an experiment; paper1_fastsweeping/eik/notes/
 * nested-iteration.md).
 *
 * Case `linear` of paper1_fastsweeping/eik_convergence.c: speed
 * v = 2 + g.x, g = (0.5, -0.3, 0.2), source s = (0.1234, -0.0567, 0.0311)
 * (its first dim coordinates) on [-1, 1]^dim, (N + 1)^dim nodes,
 * h = 2 / N, closed form T = acosh(1 + |g|^2 |x - s|^2 / (2 v(s) v(x))) / |g|.
 *
 * Nested: the level N0 (= N / 2^k) is solved by hj_eik_solve as usual;
 * each finer level 2 N' is started (hj_eik_options.start) from the level
 * N' solution interpolated to its nodes: q = T / |x - s| (smooth near the
 * source, where T is a cone; --interp T interpolates T itself) by 4-point
 * Lagrange interpolation per dimension (the fine nodes between two coarse
 * ones take the points i-1 .. i+2 around them, shifted inwards at the
 * faces: one-sided there; the fine nodes on coarse nodes take their
 * values), then T = q |x - s|.  The options are the same on every level.
 * Plain: hj_eik_solve on the fine grid alone, the same options.
 *
 * Per level: passes (stats.iterations, fo_iterations), grid sweeps,
 * local solves per node, the last change, the start's distance to the
 * level's result (max |start - T| / max T), the L1 (mean over the nodes)
 * and Linf errors against the closed form, CPU seconds (clock(); the
 * interpolation included) and those to the end of the solver's first order
 * start (from the progress callback).  The
 * total work is the sum over the levels of their sweeps (and local
 * solves) weighted by their node counts, in fine-grid sweeps.  With both
 * runs: the largest difference of the two fine results / max T.
 *
 * Built by `make` (build/bin/studies/nested_eik/nested_eik), run by hand
 * only, with OMP_NUM_THREADS=1.  nested_eik --help for the arguments.
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

static double vel(const double *x) { return eik_study_vel(dim, V0, G, x); }
static double dist(const double *x)
{
    double r2 = 0;
    for (int d = 0; d < dim; d++) r2 += (x[d] - S[d]) * (x[d] - S[d]);
    return sqrt(r2);
}
static double exact(const double *x) { return hj_eik_linear_time(dim, V0, G, S, x); }

typedef struct {
    long N;
    size_t n;        /* nodes */
    long nn[3];
    hj_eik_grid g;
    double *T, *f;
} level;

static void node_x(const level *L, size_t u, double x[3])
{
    const long a = (long)(u % (size_t)L->nn[0]), b = (long)((u / (size_t)L->nn[0]) % (size_t)L->nn[1]),
               c = (long)(u / (size_t)(L->nn[0] * L->nn[1]));
    x[0] = -1 + a * L->g.dx[0];
    x[1] = -1 + b * L->g.dx[1];
    x[2] = dim == 3 ? -1 + c * L->g.dx[2] : 0;
}

static int level_init(level *L, long N)
{
    L->N = N;
    for (int d = 0; d < 3; d++) L->nn[d] = d < dim ? N + 1 : 1;
    L->n = (size_t)(L->nn[0] * L->nn[1] * L->nn[2]);
    L->g = (hj_eik_grid){dim, {L->nn[0], L->nn[1], L->nn[2]}, {-1, -1, -1}, {2.0 / N, 2.0 / N, 2.0 / N}};
    L->T = malloc(L->n * sizeof(double));
    L->f = malloc(L->n * sizeof(double));
    if (!L->T || !L->f) return 0;
    for (size_t u = 0; u < L->n; u++) {
        double x[3];
        node_x(L, u, x);
        L->f[u] = 1 / vel(x);
    }
    return 1;
}
static void level_free(level *L)
{
    free(L->T);
    free(L->f);
}

/* 4-point Lagrange weights at the points p0 .. p0+3 for the position t
 * (in coarse index units). */
static void lagrange4(double t, long p0, double w[4])
{
    for (int i = 0; i < 4; i++) {
        double v = 1;
        for (int j = 0; j < 4; j++)
            if (j != i) v *= (t - (double)(p0 + j)) / (double)(i - j);
        w[i] = v;
    }
}

/* Interpolate the coarse values qc (nc nodes per dimension) to the fine
 * grid (2 (nc - 1) + 1 per dimension), dimension by dimension, into qf.
 * tmp: scratch of the fine size. */
static void prolong(const double *qc, long nc, double *qf, double *tmp)
{
    const long nf = 2 * (nc - 1) + 1;
    long cur[3] = {nc, nc, dim == 3 ? nc : 1};
    const double *src = qc;
    for (int d = 0; d < dim; d++) {
        /* along d: cur[d] = nc -> nf; the other dimensions as they are */
        long out[3] = {cur[0], cur[1], cur[2]};
        out[d] = nf;
        double *dst = d % 2 == 0 ? tmp : qf; /* 3-D: the last pass into tmp, copied below */
        const long s_in[3] = {1, cur[0], cur[0] * cur[1]}, s_out[3] = {1, out[0], out[0] * out[1]};
        for (long c = 0; c < out[2]; c++)
            for (long b = 0; b < out[1]; b++)
                for (long a = 0; a < out[0]; a++) {
                    const long io[3] = {a, b, c};
                    const long i = io[d];
                    long base = 0;
                    for (int e = 0; e < 3; e++)
                        if (e != d) base += io[e] * s_in[e];
                    double v;
                    if (i % 2 == 0) v = src[base + (i / 2) * s_in[d]];
                    else {
                        long p0 = (i - 1) / 2 - 1;
                        if (p0 < 0) p0 = 0;
                        if (p0 + 3 > nc - 1) p0 = nc - 4;
                        double w[4];
                        lagrange4(0.5 * (double)i, p0, w);
                        v = 0;
                        for (int j = 0; j < 4; j++) v += w[j] * src[base + (p0 + j) * s_in[d]];
                    }
                    dst[a * s_out[0] + b * s_out[1] + c * s_out[2]] = v;
                }
        for (int e = 0; e < 3; e++) cur[e] = out[e];
        src = dst;
    }
    if (src != qf) memcpy(qf, src, (size_t)(cur[0] * cur[1] * cur[2]) * sizeof(double));
}

typedef struct {
    long iterations, fo_iterations, sweeps;
    double solves, change, l1, linf, cpu, start_dist, scale;
    double fo_cpu; /* CPU seconds to the end of the first order start */
    int rc;
} result;

static int verbose = 0;
/* progress: the CPU time at each pass's end (for the first order start's
 * share) */
typedef struct {
    clock_t c0;
    double t[1001];
    double last;
} prog;
static void progress(long it, double change, void *ctx)
{
    prog *p = ctx;
    if (it >= 1 && it <= 1000) p->t[it] = (double)(clock() - p->c0) / CLOCKS_PER_SEC;
    if (verbose) fprintf(stderr, "  pass %3ld change %.3e ratio %.3f\n", it, change, p->last > 0 ? change / p->last : 0);
    p->last = change;
}

static void errors(const level *L, result *r)
{
    double l1 = 0, linf = 0, sc = 0;
    for (size_t u = 0; u < L->n; u++) {
        double x[3];
        node_x(L, u, x);
        const double e = fabs(L->T[u] - exact(x));
        l1 += e;
        if (e > linf) linf = e;
        if (fabs(L->T[u]) > sc) sc = fabs(L->T[u]);
    }
    r->l1 = l1 / (double)L->n;
    r->linf = linf;
    r->scale = sc;
}

static int solve(level *L, const hj_eik_options *base, const double *start, result *r)
{
    hj_eik_options o = *base;
    o.start = start;
    prog pc;
    memset(&pc, 0, sizeof pc);
    o.progress = progress;
    o.progress_ctx = &pc;
    hj_eik_stats st;
    hj_error err;
    hj_error_clear(&err);
    const clock_t c0 = clock();
    pc.c0 = c0;
    const hj_eik_source src = {{S[0], S[1], dim == 3 ? S[2] : 0}, 0};
    r->rc = hj_eik_solve(&L->g, L->f, 0, NULL, &src, 1, NULL, &o, L->T, &st, &err);
    r->cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
    if (r->rc != HJ_OK && r->rc != HJ_ENOCONV) {
        fprintf(stderr, "nested_eik: N = %ld: %s\n", L->N, err.msg);
        return 0;
    }
    if (r->rc == HJ_ENOCONV) fprintf(stderr, "nested_eik: N = %ld: %s\n", L->N, err.msg);
    r->iterations = st.iterations;
    r->fo_iterations = st.fo_iterations;
    r->sweeps = st.sweeps;
    r->solves = (double)st.updates / (double)L->n;
    r->change = st.change;
    r->fo_cpu = st.fo_iterations >= 1 && st.fo_iterations <= 1000 ? pc.t[st.fo_iterations] : NAN;
    errors(L, r);
    r->start_dist = NAN;
    if (start) {
        double m = 0;
        for (size_t u = 0; u < L->n; u++)
            if (isfinite(start[u]) && fabs(start[u] - L->T[u]) > m) m = fabs(start[u] - L->T[u]);
        r->start_dist = m / r->scale;
    }
    return 1;
}

static void print_row(const char *what, long N, const result *r)
{
    printf("%-6s %2d %5ld %5ld %3ld %6ld %8.2f %10.3e %10.3e %12.5e %12.5e %8.3f %8.3f\n", what, dim, N, r->iterations,
           r->fo_iterations, r->sweeps, r->solves, r->change, r->start_dist, r->l1, r->linf, r->cpu, r->fo_cpu);
}


static void usage(FILE *fp)
{
    fprintf(fp,
            "usage: nested_eik [--dim 2|3] [--order 3|5] [--tol t] [--n0 N0] [--run nested|plain|both|plain-first]\n"
            "                  [--interp tau|T] [--verbose] N\n"
            "  Solves the `linear` case on [-1,1]^dim with N intervals per axis by nested iteration\n"
            "  (levels N0, 2 N0, ..., N; N = N0 2^k; default N0 the smallest N / 2^k >= 10) and/or\n"
            "  by the plain hj_eik_solve.  Defaults: dim 3, order 3, tol 1e-12, run both (nested\n"
            "  first; plain-first swaps them), interp tau (T / |x - s|).  --verbose: every pass's\n"
            "  change (stderr).  Columns: run, dim, N, passes, first order passes, grid sweeps,\n"
            "  local solves per node, last change / max T, max |start - T| / max T, L1, Linf, CPU s\n"
            "  (the interpolation's included), CPU s of the first order start.\n");
}

int main(int argc, char **argv)
{
    long N = 0, N0 = 0, ord = 3, dm = 3;
    double tol = 1e-12;
    int run_nested = 1, run_plain = 1, plain_first = 0, interp_T = 0;
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
            if (!eik_study_long(argv[++i], &ord) || (ord != 3 && ord != 5)) goto bad;
        } else if (!strcmp(a, "--tol") && more) {
            if (!eik_study_double(argv[++i], &tol) || !(tol > 0)) goto bad;
        } else if (!strcmp(a, "--n0") && more) {
            if (!eik_study_long(argv[++i], &N0) || N0 < 6) goto bad;
        } else if (!strcmp(a, "--interp") && more) {
            const char *v = argv[++i];
            if (!strcmp(v, "tau")) interp_T = 0;
            else if (!strcmp(v, "T")) interp_T = 1;
            else goto bad;
        } else if (!strcmp(a, "--run") && more) {
            const char *v = argv[++i];
            run_nested = run_plain = 1;
            plain_first = 0;
            if (!strcmp(v, "nested")) run_plain = 0;
            else if (!strcmp(v, "plain")) run_nested = 0;
            else if (!strcmp(v, "plain-first")) plain_first = 1;
            else if (strcmp(v, "both")) goto bad;
        } else if (a[0] != '-' && N == 0) {
            if (!eik_study_long(a, &N) || N < 6 || N > 4000) goto bad;
        } else goto bad;
    }
    if (N == 0) goto bad;
    dim = (int)dm;
    if (N0 == 0) {
        N0 = N;
        while (N0 % 2 == 0 && N0 / 2 >= 10) N0 /= 2;
    }
    {
        long m = N0;
        while (m < N) m *= 2;
        if (m != N) {
            fprintf(stderr, "nested_eik: N = %ld is not N0 = %ld times a power of 2\n", N, N0);
            return 2;
        }
    }
    hj_eik_options o = hj_eik_default_options();
    o.order = (int)ord;
    o.tol = tol;
    printf("# linear, order %ld, tol %g, N0 %ld, interp %s\n", ord, tol, N0, interp_T ? "T" : "tau");
    printf("# run  dim     N  pass  fo sweeps  solves/n     change  start-dist           L1         Linf    cpu_s fo_cpu_s\n");

    double *Tplain = NULL;
    double *Tnest = NULL;
    for (int pass = 0; pass < 2; pass++) {
        const int do_plain = (pass == 0) == plain_first;
        if (do_plain && run_plain) {
            level L;
            result r;
            if (!level_init(&L, N)) goto oom;
            if (!solve(&L, &o, NULL, &r)) return 1;
            print_row("plain", N, &r);
            Tplain = L.T;
            L.T = NULL;
            level_free(&L);
        }
        if (!do_plain && run_nested) {
            level C;
            result r;
            if (!level_init(&C, N0)) goto oom;
            if (!solve(&C, &o, NULL, &r)) return 1;
            print_row("level", N0, &r);
            const double fine_n = pow((double)(N + 1), dim);
            double work = (double)r.sweeps * (double)C.n / fine_n, solves = r.solves * (double)C.n / fine_n,
                   cpu = r.cpu;
            while (C.N < N) {
                level F;
                if (!level_init(&F, 2 * C.N)) goto oom;
                double *q = malloc(C.n * sizeof(double)), *start = malloc(F.n * sizeof(double)),
                       *tmp = malloc(F.n * sizeof(double));
                if (!q || !start || !tmp) goto oom;
                const clock_t c0 = clock();
                for (size_t u = 0; u < C.n; u++) {
                    double x[3];
                    node_x(&C, u, x);
                    q[u] = interp_T ? C.T[u] : C.T[u] / dist(x);
                }
                prolong(q, C.N + 1, start, tmp);
                for (size_t u = 0; u < F.n && !interp_T; u++) {
                    double x[3];
                    node_x(&F, u, x);
                    start[u] *= dist(x);
                }
                const double ci = (double)(clock() - c0) / CLOCKS_PER_SEC;
                if (!solve(&F, &o, start, &r)) return 1;
                r.cpu += ci;
                print_row("level", F.N, &r);
                work += (double)r.sweeps * (double)F.n / fine_n;
                solves += r.solves * (double)F.n / fine_n;
                cpu += r.cpu;
                free(q);
                free(start);
                free(tmp);
                level_free(&C);
                C = F;
            }
            printf("nested %d %5ld fine passes %ld (fo %ld), total work %.2f fine sweeps, %.2f solves per fine node, "
                   "cpu %.3f s\n", dim, N, r.iterations, r.fo_iterations, work, solves, cpu);
            Tnest = C.T;
            C.T = NULL;
            level_free(&C);
        }
    }
    if (Tplain && Tnest) {
        level L;
        if (!level_init(&L, N)) goto oom;
        double m = 0, sc = 0;
        for (size_t u = 0; u < L.n; u++) {
            if (fabs(Tplain[u] - Tnest[u]) > m) m = fabs(Tplain[u] - Tnest[u]);
            if (fabs(Tplain[u]) > sc) sc = fabs(Tplain[u]);
        }
        printf("max |T_nested - T_plain| / max T = %.3e (tol %g)\n", m / sc, tol);
        level_free(&L);
    }
    free(Tplain);
    free(Tnest);
    return 0;
bad:
    fprintf(stderr, "nested_eik: bad arguments (need N >= 6 a multiple of N0 2^k, --dim 2|3, --order 3|5, --tol > 0, "
                    "--n0 >= 6, --interp tau|T, --run nested|plain|both|plain-first); see --help\n");
    return 2;
oom:
    fprintf(stderr, "nested_eik: out of memory\n");
    return 1;
}
