/*
# Benchmark: the Eikonal solver against scikit-fmm (make bench)

**Problems.** A point source at the origin of [-1, 1]^2 (and [-1, 1]^3),
N intervals per side:

- distance: speed 1, T = r.  A factored solver (T = r tau near the
  source) is exact here, to rounding, at any N: its errors say nothing
  about its order, and the equal-accuracy ratio is a bound (below);
- linear: speed v = 2 + g.x, g = (0.5, 1) in 2-D, (0.5, 0.5, 0.5) in
  3-D, the closed form T = arccosh(1 + |g|^2 r^2 / (2 v(0) v(x))) / |g|:
  both solvers have real errors.

Ours: common/hj_eik.h at orders 1, 3 and 5 with its default options (what
the `eikonal` tool runs).  The peer: scikit-fmm at orders 1 and 2 on the
same grids (bench_skfmm.py, run before this program, one process at a
time; its table is --peer).

**Measured.** CPU time (not wall) of the solve only, and the max and
mean |T - T_exact| over every node.  The time is the least of 3 batches,
a batch repeating the solve until it has taken 0.05 s (one solve when it
takes longer; up to 3 while they take under a second): the small grids
solve in a millisecond, below what one reading of the clock resolves.
Orders 3 and 5 run up to --max-high in 2-D and on --ladder, small sizes
a factor about 1.4 apart, so that two of our runs bracket every error
scikit-fmm reaches on N = 400 .. 1600.

**Ratios** (scikit-fmm's CPU over ours: above 1, ours is cheaper):
at equal N; and at equal accuracy, where our log CPU against log mean
error, piecewise linear between consecutive sizes of ours, is read at
each error scikit-fmm reaches.  When every size of ours is more accurate than
scikit-fmm's run, the ratio is written ">=R": R against our cheapest run,
already more accurate (a lower bound); "-" when none of ours reaches it.

Output: --out-dir/bench_eik.tsv (every run, ours and the peer's) and
bench_eik_ratios.tsv; the ratio table also on stdout.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hj_cli.h"
#include "hj_eik.h"
#include "hj_io.h"
#include "hj_sys.h"

static const char *prog = "bench_eik";

enum { MAX_SIZES = 16, MAX_ROWS = 256 };

typedef struct {
    char problem[16];
    char solver[16];
    int dim, order;
    long N;
    double cpu, emax, emean;
    long iterations;
    int converged; /* 0: the last iterate after max_iter (kept out of the ratios) */
} run_row;

static const double g2[3] = {0.5, 1, 0}, g3[3] = {0.5, 0.5, 0.5};

/* Speed and exact travel time of the linear problem at x. */
static void linear_at(int dim, const double x[3], double *v, double *t)
{
    const double *gv = dim == 2 ? g2 : g3, origin[3] = {0, 0, 0};
    *v = 2;
    for (int d = 0; d < dim; d++) *v += gv[d] * x[d];
    *t = hj_eik_linear_time(dim, 2, gv, origin, x);
}

/* One solve of a problem (0 distance, 1 linear): CPU seconds, errors. */
static int run_ours(int problem, int dim, long N, int order, run_row *r, hj_error *err)
{
    hj_eik_grid g = {.dim = dim};
    long total = 1;
    for (int d = 0; d < 3; d++) {
        g.n[d] = d < dim ? N + 1 : 1;
        g.x0[d] = d < dim ? -1 : 0;
        g.dx[d] = d < dim ? 2.0 / (double)N : 1;
        total *= g.n[d];
    }
    double *T = malloc(sizeof *T * (size_t)total), *f = NULL, *exact = malloc(sizeof *exact * (size_t)total);
    if (problem == 1) f = malloc(sizeof *f * (size_t)total);
    if (!T || !exact || (problem == 1 && !f)) {
        free(T), free(exact), free(f);
        return hj_error_set(err, HJ_ENOMEM, "out of memory for N = %ld", N);
    }
    for (long k = 0; k < total; k++) {
        const long ix[3] = {k % g.n[0], k / g.n[0] % g.n[1], k / (g.n[0] * g.n[1])};
        double x[3] = {0, 0, 0}, v, t;
        for (int d = 0; d < dim; d++) x[d] = -1 + (double)ix[d] * g.dx[d];
        if (problem == 1) {
            linear_at(dim, x, &v, &t);
            f[k] = 1 / v;
            exact[k] = t;
        } else {
            exact[k] = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
        }
    }
    hj_eik_source src = {.x = {0, 0, 0}, .t0 = 0};
    hj_eik_options opt = hj_eik_default_options();
    opt.order = order;
    hj_eik_stats st;
    double best = INFINITY, spent = 0;
    int rc = HJ_OK;
    /* up to 3 batches while they take under 1 s; a batch repeats the
     * solve until 0.05 s have passed */
    for (int k = 0; k < 3 && spent < 1 && rc == HJ_OK; k++) {
        const double t0 = hj_sys_cpu_seconds();
        long reps = 0;
        double cpu = 0;
        do {
            rc = hj_eik_solve(&g, f, 1.0, NULL, &src, 1, NULL, &opt, T, &st, err);
            reps++;
            cpu = hj_sys_cpu_seconds() - t0;
        } while (rc == HJ_OK && cpu < 0.05);
        best = cpu / (double)reps < best ? cpu / (double)reps : best;
        spent += cpu;
    }
    double emax = 0, esum = 0;
    for (long k = 0; k < total && rc == HJ_OK; k++) {
        const double e = fabs(T[k] - exact[k]);
        emax = e > emax ? e : emax;
        esum += e;
    }
    free(T), free(exact), free(f);
    if (rc && rc != HJ_ENOCONV) return rc;
    *r = (run_row){.converged = rc == HJ_OK, .dim = dim, .order = order, .N = N, .cpu = best, .emax = emax, .emean = esum / (double)total,
                   .iterations = st.iterations};
    snprintf(r->solver, sizeof r->solver, "ours");
    snprintf(r->problem, sizeof r->problem, "%s", problem ? "linear" : "distance");
    return HJ_OK;
}

/* Our CPU at mean error e on the curve of (dim, order): log-log linear
 * between two consecutive sizes whose errors bracket e; NAN outside. */
static int ours_for(const run_row *p, const char *problem, int dim, int order)
{
    return !strcmp(p->solver, "ours") && p->converged && !strcmp(p->problem, problem) && p->dim == dim &&
           p->order == order;
}

static double cpu_at_error(const run_row *rows, int n, const char *problem, int dim, int order, double e)
{
    double best = NAN;
    for (int a = 0; a < n; a++)
        for (int b = 0; b < n; b++) {
            const run_row *p = rows + a, *q = rows + b;
            if (!ours_for(p, problem, dim, order) || !ours_for(q, problem, dim, order) || q->N <= p->N) continue;
            int between = 0; /* q must be the next size after p */
            for (int c = 0; c < n; c++)
                between += ours_for(rows + c, problem, dim, order) && rows[c].N > p->N && rows[c].N < q->N;
            if (between) continue;
            /* p coarse (larger error), q fine */
            if (!(e <= p->emean && e >= q->emean) || !(p->emean > q->emean)) continue;
            const double s = log(e / p->emean) / log(q->emean / p->emean);
            best = exp(log(p->cpu) + s * (log(q->cpu) - log(p->cpu)));
        }
    return best;
}

static void print_ratios(FILE *fp, const run_row *rows, int n, const int *orders, int norders)
{
    fprintf(fp, "problem\tdim\tN\tpeer_order\tpeer_err_mean\tours_order\tours_err_mean\tratio_equal_N\t"
                "ratio_equal_accuracy\n");
    for (int a = 0; a < n; a++) {
        const run_row *s = rows + a;
        if (strcmp(s->solver, "scikit-fmm")) continue;
        for (int k = 0; k < norders; k++) {
            double eq_n = NAN, ours_e = NAN, cheapest = INFINITY;
            int all_better = 0, nours = 0;
            for (int b = 0; b < n; b++) {
                const run_row *o = rows + b;
                if (!ours_for(o, s->problem, s->dim, orders[k])) continue;
                nours++;
                all_better += o->emean <= s->emean;
                if (o->emean <= s->emean && o->cpu < cheapest) cheapest = o->cpu;
                if (o->N == s->N) eq_n = s->cpu / o->cpu, ours_e = o->emean;
            }
            const double eq_acc = s->cpu / cpu_at_error(rows, n, s->problem, s->dim, orders[k], s->emean);
            fprintf(fp, "%s\t%d\t%ld\t%d\t%.3g\t%d\t", s->problem, s->dim, s->N, s->order, s->emean, orders[k]);
            if (isnan(ours_e)) fputs("-\t", fp); /* no run of ours at this N */
            else fprintf(fp, "%.3g\t", ours_e);
            if (isnan(eq_n)) fputs("-\t", fp);
            else fprintf(fp, "%.3g\t", eq_n);
            if (!isnan(eq_acc)) fprintf(fp, "%.3g\n", eq_acc);
            else if (nours > 0 && all_better == nours) fprintf(fp, ">=%.3g\n", s->cpu / cheapest);
            else fputs("-\n", fp);
        }
    }
}

/* The peer's rows (bench_skfmm.py's table) appended to rows. */
static int read_peer(const char *path, run_row *rows, int *n, hj_error *err)
{
    hj_table t;
    int rc = hj_table_read(&t, path, err);
    if (rc) return rc;
    const int c[8] = {hj_table_col(&t, "solver"), hj_table_col(&t, "dim"),     hj_table_col(&t, "order"),
                      hj_table_col(&t, "N"),      hj_table_col(&t, "cpu_s"),   hj_table_col(&t, "err_max"),
                      hj_table_col(&t, "err_mean"), hj_table_col(&t, "problem")};
    for (int k = 0; k < 8; k++)
        if (c[k] < 0) {
            hj_table_free(&t);
            return hj_error_set(err, HJ_EFORMAT,
                                "%s: a column is missing (problem solver dim order N cpu_s err_max err_mean)", path);
        }
    for (int r = 0; r < t.nrows && rc == HJ_OK; r++) {
        if (*n == MAX_ROWS) { rc = hj_error_set(err, HJ_EINVAL, "%s: too many rows", path); break; }
        run_row *p = rows + (*n)++;
        char **cell = t.cells[r];
        snprintf(p->solver, sizeof p->solver, "%s", cell[c[0]]);
        snprintf(p->problem, sizeof p->problem, "%s", cell[c[7]]);
        p->dim = atoi(cell[c[1]]);
        p->order = atoi(cell[c[2]]);
        p->N = atol(cell[c[3]]);
        p->cpu = strtod(cell[c[4]], NULL);
        p->emax = strtod(cell[c[5]], NULL);
        p->emean = strtod(cell[c[6]], NULL);
        p->iterations = -1;
        p->converged = 1;
        if (!(p->cpu > 0) || !(p->emean > 0)) rc = hj_error_set(err, HJ_EFORMAT, "%s: row %d has no positive time or error", path, r + 1);
    }
    hj_table_free(&t);
    return rc;
}

int main(int argc, char **argv)
{
    long n2[MAX_SIZES] = {25, 50, 100, 200, 400, 800, 1600}, n3[MAX_SIZES] = {25, 50, 100}, n31[MAX_SIZES] = {200};
    long ladder[MAX_SIZES] = {4, 6, 8, 11, 16, 23, 32};
    long orders_l[3] = {1, 3, 5};
    int nn2 = 7, nn3 = 3, nn31 = 1, nlad = 7, norders = 3;
    long max_high = 100000;
    const char *peer = NULL, *out_dir = "results/bench";
    hj_error err;
    hj_cli_opt opts[] = {
        {.name = "--sizes", .type = HJ_OPT_LONG_LIST, .value = n2, .min = 4, .max = 100000, .metavar = "N,...",
         .help = "2-D sizes (intervals per side; each the double of the one before, for the interpolation)",
         .count = &nn2, .maxn = MAX_SIZES},
        {.name = "--sizes3", .type = HJ_OPT_LONG_LIST, .value = n3, .min = 0, .max = 2000, .metavar = "N,...",
         .help = "3-D sizes (0: no 3-D runs)", .count = &nn3, .maxn = MAX_SIZES},
        {.name = "--sizes3-order1", .type = HJ_OPT_LONG_LIST, .value = n31, .min = 0, .max = 2000, .metavar = "N,...",
         .help = "more 3-D sizes at order 1 only (the cheapest; 0: none)", .count = &nn31, .maxn = MAX_SIZES},
        {.name = "--ladder", .type = HJ_OPT_LONG_LIST, .value = ladder, .min = 0, .max = 100000, .metavar = "N,...",
         .help = "more 2-D sizes at orders 3 and 5 (increasing), for the equal-accuracy interpolation (0: none)",
         .count = &nlad, .maxn = MAX_SIZES},
        {.name = "--max-high", .type = HJ_OPT_LONG, .value = &max_high, .min = 4, .max = 100000, .metavar = "N",
         .help = "2-D sizes above N run at order 1 only", .dflt = "no limit"},
        {.name = "--orders", .type = HJ_OPT_LONG_LIST, .value = orders_l, .min = 1, .max = 5, .metavar = "P,...",
         .help = "our orders (1, 3, 5)", .count = &norders, .maxn = 3},
        {.name = "--peer", .type = HJ_OPT_STRING, .value = &peer, .metavar = "FILE",
         .help = "scikit-fmm's table (bench_skfmm.py)", .dflt = "none: our rows only"},
        {.name = "--out-dir", .type = HJ_OPT_STRING, .value = &out_dir, .metavar = "DIR", .help = "for the tables"},
    };
    hj_cli_spec spec = {.prog = prog,
                        .summary = "CPU time and errors of the Eikonal solver on the distance from a point, with the CPU\n"
                                   "ratios against scikit-fmm at equal N and at equal accuracy; see bench_eik.c.",
                        .opts = opts,
                        .nopts = (int)(sizeof opts / sizeof opts[0])};
    hj_cli_parse_or_exit(&spec, argc, argv);
    int orders[3];
    for (int k = 0; k < norders; k++) {
        if (orders_l[k] != 1 && orders_l[k] != 3 && orders_l[k] != 5)
            hj_cli_fail(prog, HJ_EXIT_USAGE, "--orders: %ld is not 1, 3 or 5", orders_l[k]);
        orders[k] = (int)orders_l[k];
    }
    static run_row rows[MAX_ROWS];
    int n = 0;
    if (peer && read_peer(peer, rows, &n, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    if (hj_mkdirs(out_dir, &err)) hj_cli_fail(prog, HJ_EXIT_USAGE, "%s", err.msg);
    char path[1024], rpath[1024];
    snprintf(path, sizeof path, "%s/bench_eik.tsv", out_dir);
    snprintf(rpath, sizeof rpath, "%s/bench_eik_ratios.tsv", out_dir);
    if (hj_out_check(path, &err) || hj_out_check(rpath, &err)) hj_cli_fail(prog, HJ_EXIT_USAGE, "%s", err.msg);
    for (int problem = 0; problem < 2; problem++)
        for (int dim = 2; dim <= 3; dim++) {
            for (int k = 0; k < norders; k++)
                for (int s = 0; s < (dim == 2 ? nlad + nn2 : nn3 + nn31); s++) {
                    /* 2-D: the ladder (orders 3 and 5) below the first size, then the sizes */
                    const long N = dim == 3 ? (s < nn3 ? n3[s] : n31[s - nn3]) : s < nlad ? ladder[s] : n2[s - nlad];
                    if (N < 4 || (dim == 3 && s >= nn3 && orders[k] != 1)) continue; /* 0: none */
                    if (dim == 2 && s < nlad && (orders[k] == 1 || N >= n2[0])) continue;
                    if (dim == 2 && N > max_high && orders[k] != 1) continue;
                    if (n == MAX_ROWS) hj_cli_fail(prog, HJ_EXIT_USAGE, "too many runs");
                    if (run_ours(problem, dim, N, orders[k], rows + n, &err))
                        hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
                    fprintf(stderr, "%s: %s %d-D N = %ld order %d: %.3g s CPU, %ld iterations, mean error %.3g%s\n", prog,
                            rows[n].problem, dim, N, orders[k], rows[n].cpu, rows[n].iterations, rows[n].emean,
                            rows[n].converged ? "" : " (NOT CONVERGED: left out of the ratios)");
                    n++;
                }
        }
    hj_out out;
    if (hj_out_open(&out, path, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    fprintf(out.fp, "# CPU seconds of the solve only (the least of up to 3 runs); errors |T - T_exact| over "
                    "every node\nproblem\tsolver\tdim\torder\tN\tcpu_s\terr_max\terr_mean\titerations\tconverged\n");
    for (int k = 0; k < n; k++)
        fprintf(out.fp, "%s\t%s\t%d\t%d\t%ld\t%.6g\t%.6g\t%.6g\t%ld\t%d\n", rows[k].problem, rows[k].solver, rows[k].dim,
                rows[k].order, rows[k].N, rows[k].cpu, rows[k].emax, rows[k].emean, rows[k].iterations, rows[k].converged);
    if (hj_out_commit(&out, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    if (peer) {
        if (hj_out_open(&out, rpath, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
        fprintf(out.fp, "# scikit-fmm CPU / our CPU (above 1: ours cheaper), at equal N and at equal mean error\n");
        print_ratios(out.fp, rows, n, orders, norders);
        if (hj_out_commit(&out, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
        print_ratios(stdout, rows, n, orders, norders);
    }
    return 0;
}
