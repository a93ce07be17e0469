/* p1_study.c -- see p1_study.h. */
#include "p1_study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "hj_cli.h"
#include "hj_fit.h"
#include "hj_io.h"
#include "hj_sys.h"

enum { MAX_SIZES = 16, MAX_CASES = 4 };

typedef struct {
    long N;
    double h, l1, linf, seconds, change;
    int iter, fo_iter;
    long ncat3, measured;
} row;

typedef struct {
    const char *out_dir;
    long sizes[MAX_SIZES];
    int nsizes;
    double delta, eps;        /* eps < 0: the case's own */
    int eps_h2;               /* eps given as a multiple of h^2 */
    hj_stop_norm stop_norm;
    int l1_integral;
    int exclude_mode; /* EXCL_* */
    double band;
    hj_rich_box richardson_box;
    hj_fsm_guess guess;
    double guess_noise;       /* relative perturbation of the guess, 0: none */
    long seed;
    int max_iter;
    long grid_N;
    hj_bc_strategy strategy;
} settings;

enum { EXCL_DISTANCE, EXCL_LITERAL, EXCL_CLOSED, EXCL_OPEN };

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* Is (x, y) excluded from the error?
 *   EXCL_DISTANCE (the default) a box around a singular point (around_point)
 *                 excludes the nodes closer to the point than its
 *                 half-width w, i.e. at distance < 0.15 from the centres
 *                 of Examples 3 and 4; other boxes (Example 4's bisector
 *                 band) as EXCL_LITERAL.  The paper writes "outside the
 *                 box [-0.15, 0.15]^2"; its numbers are those of the
 *                 distance: Table 3.4 agrees within 0.5 % in L-infinity
 *                 and 2.2 % in L1 at every N, the box does not (see the
 *                 overview).  The distance is computed from the node
 *                 coordinates as computed, with no tolerance: the nodes
 *                 at exactly 0.15 on the axes of Example 3 fall either
 *                 side by rounding (their errors are below 1e-6);
 *   EXCL_LITERAL  the closed box tested on the coordinates x0 + i h as
 *                 computed, with no tolerance: the paper's "measured
 *                 outside the box" implemented as written.  In Example 3
 *                 the nodes at x, y = +0.15 come out as 0.15000000000000013
 *                 and are measured, those at -0.15 as -0.1499999999999999
 *                 and are not; Example 4's nodes at y = +-3 are exact and
 *                 excluded (see the overview);
 *   EXCL_OPEN     only nodes strictly inside a box (edges measured);
 *   EXCL_CLOSED   nodes on the edges excluded too.
 * For open and closed a node counts as on an edge within 1e-9 h. */
static int excluded(const p1_case *c, double x, double y, double h, int mode)
{
    for (int b = 0; b < c->nexclude; b++) {
        const p1_box *e = &c->exclude[b];
        if (mode == EXCL_DISTANCE && e->around_point) {
            const double w = 0.5 * (e->xmax - e->xmin);
            const double dx = x - 0.5 * (e->xmin + e->xmax), dy = y - 0.5 * (e->ymin + e->ymax);
            if (dx * dx + dy * dy < w * w) return 1;
        } else if (mode == EXCL_DISTANCE || mode == EXCL_LITERAL) {
            if (x >= e->xmin && x <= e->xmax && y >= e->ymin && y <= e->ymax) return 1;
        } else {
            const double t = mode == EXCL_OPEN ? 1e-9 * h : -1e-9 * h;
            if (x > e->xmin + t && x < e->xmax - t && y > e->ymin + t && y < e->ymax - t) return 1;
        }
    }
    return 0;
}

static const char *strategy_name(hj_bc_strategy s)
{
    return s == HJ_BC_RICHARDSON ? "richardson" : s == HJ_BC_LAX_WENDROFF ? "lax-wendroff" : "first-order";
}

typedef struct {
    const char *prog, *cname;
    long N;
} progress_ctx;

static void show_progress(int iter, double change, void *vctx)
{
    const progress_ctx *p = vctx;
    hj_progress("\r%s: case %s N=%ld iteration %d change %.2e   ", p->prog, p->cname, p->N, iter, change);
}

static int write_grid(const char *path, const hj_grid2 *g, const p1_case *c, const double *phi, hj_error *err)
{
    hj_out out;
    int rc = hj_out_open(&out, path, err);
    if (rc) return rc;
    fprintf(out.fp, "# x\ty\tphi\texact\terror (blank line between rows: gnuplot grid format)\n");
    for (int j = 0; j <= g->ny; j++) {
        for (int i = 0; i <= g->nx; i++) {
            const double x = g->x0 + i * g->h, y = g->y0 + j * g->h, p = phi[(long)j * (g->nx + 1) + i];
            const double e = c->exact(x, y);
            fprintf(out.fp, "%.6f\t%.6f\t%.10g\t%.10g\t%.3e\n", x, y, p, e, fabs(p - e));
        }
        fputc('\n', out.fp);
    }
    return hj_out_commit(&out, err);
}

/* Solve one case at one N and measure it. */
static int run_one(const p1_study *st, const settings *s, const p1_case *c, long N, row *r, hj_error *err)
{
    hj_grid2 g;
    g.nx = g.ny = (int)N;
    g.h = (c->domain.xmax - c->domain.xmin) / (double)N;
    g.x0 = c->domain.xmin;
    g.y0 = c->domain.ymin;
    const double need = hj_fsm_memory(&g) + sizeof(double) * (double)(N + 1) * (N + 1);
    const double have = hj_sys_physical_memory();
    if (have > 0 && need > 0.8 * have)
        return hj_error_set(err, HJ_ENOMEM, "N=%ld needs %.3g GB, more than this machine has (%.3g GB)", N, need / 1e9,
                            have / 1e9);
    double *phi = malloc(sizeof(double) * (size_t)((N + 1) * (N + 1)));
    if (!phi) return hj_error_set(err, HJ_ENOMEM, "out of memory for N=%ld", N);
    hj_fsm_options opt = hj_fsm_default_options();
    opt.strategy = s->strategy;
    opt.eps = s->eps > 0 ? (s->eps_h2 ? s->eps * g.h * g.h : s->eps) : c->eps_times_h2 ? c->eps * g.h * g.h : c->eps;
    opt.delta = s->delta;
    opt.stop_norm = s->stop_norm;
    opt.max_iter = s->max_iter;
    opt.band = s->band;
    opt.richardson_box = s->richardson_box;
    opt.guess = s->guess;
    opt.guess_noise = s->guess_noise;
    opt.guess_seed = (unsigned long)s->seed;
    progress_ctx pc = {st->program, c->name, N};
    opt.progress = show_progress;
    opt.progress_ctx = &pc;
    hj_fsm_stats stats;
    double t0 = now();
    int rc = hj_fsm_solve(&g, &c->speed, c->inflow, c->ninflow, &opt, phi, &stats, err);
    r->seconds = now() - t0;
    hj_progress("\n");
    if (rc) {
        free(phi);
        return rc;
    }
    r->N = N;
    r->h = g.h;
    r->iter = stats.iterations;
    r->fo_iter = stats.fo_iterations;
    r->change = stats.change;
    r->ncat3 = stats.ncat[2];
    double sum = 0, mx = 0;
    long count = 0;
    for (int j = 0; j <= g.ny; j++)
        for (int i = 0; i <= g.nx; i++) {
            const double x = g.x0 + i * g.h, y = g.y0 + j * g.h;
            if (excluded(c, x, y, g.h, s->exclude_mode)) continue;
            const double e = fabs(phi[(long)j * (g.nx + 1) + i] - c->exact(x, y));
            sum += e;
            if (e > mx) mx = e;
            count++;
        }
    r->measured = count;
    r->l1 = s->l1_integral ? sum * g.h * g.h : sum / (double)count;
    r->linf = mx;
    if (N == s->grid_N) {
        char path[4096];
        snprintf(path, sizeof path, "%s/%s.%s.grid.tsv", s->out_dir, st->table, c->name[0] == '-' ? "sol" : c->name);
        rc = write_grid(path, &g, c, phi, err);
    }
    free(phi);
    return rc;
}

static void put_order(FILE *fp, const row *a, const row *b, int linf)
{
    double o = hj_pair_order(a->h, linf ? a->linf : a->l1, b->h, linf ? b->linf : b->l1);
    if (isfinite(o)) fprintf(fp, "\t%.2f", o);
    else fputs("\t-", fp);
}

static int write_outputs(const p1_study *st, const settings *s, row rows[][MAX_SIZES], hj_error *err)
{
    char path[4096];
    hj_out tab, fit, gp;
    snprintf(path, sizeof path, "%s/%s.fit.tsv", s->out_dir, st->table);
    int rc = hj_out_open(&fit, path, err);
    if (rc) return rc;
    snprintf(path, sizeof path, "%s/%s.fit.gp", s->out_dir, st->table);
    if ((rc = hj_out_open(&gp, path, err))) { hj_out_abort(&fit); return rc; }
    fprintf(fit.fp, "# fitted orders e = C h^p (Ceres, Huber loss, see common/hj_fit.h)\ncase\tquantity\tp\tp_se\tC\tp_lsq\tn\n");
    fprintf(gp.fp, "# gnuplot variables for the convergence figure of %s\n", st->table);
    fprintf(gp.fp, "hN = %.17g\ncase_keys = \"", st->cases[0].domain.xmax - st->cases[0].domain.xmin);
    for (int ci = 0; ci < st->ncases; ci++) fprintf(gp.fp, "%s%s", ci ? " " : "", st->cases[ci].name);
    fprintf(gp.fp, "\"\ncase_names = \"");
    for (int ci = 0; ci < st->ncases; ci++) fprintf(gp.fp, "%s%s", ci ? " " : "", st->cases[ci].name[0] == '-' ? "sol" : st->cases[ci].name);
    fprintf(gp.fp, "\"\n");
    for (int ci = 0; ci < st->ncases; ci++) {
        const char *cn = st->cases[ci].name;
        const char *gn = cn[0] == '-' ? "sol" : cn;
        for (int q = 0; q < 2; q++) {
            double h[MAX_SIZES], e[MAX_SIZES];
            int n = 0;
            for (int k = 0; k < s->nsizes; k++)
                if (rows[ci][k].l1 > 0 && rows[ci][k].linf > 0) {
                    h[n] = rows[ci][k].h;
                    e[n] = q ? rows[ci][k].linf : rows[ci][k].l1;
                    n++;
                }
            hj_order_fit f;
            hj_error ferr;
            const char *qn = q ? "Linf" : "L1";
            if (n >= 2 && hj_fit_order(h, e, n, &f, &ferr) == HJ_OK) {
                fprintf(fit.fp, "%s\t%s\t%.4f\t%.4f\t%.6g\t%.4f\t%d\n", cn, qn, f.p, f.p_se, f.C, f.p_ls, f.n);
                fprintf(gp.fp, "fit_%s_%s_p = %.6f\nfit_%s_%s_se = %.6f\nfit_%s_%s_C = %.10g\n", gn, qn, f.p, gn, qn,
                        isfinite(f.p_se) ? f.p_se : -1.0, gn, qn, f.C);
            } else {
                fprintf(fit.fp, "%s\t%s\tnan\tnan\tnan\tnan\t%d\n", cn, qn, n);
                fprintf(gp.fp, "fit_%s_%s_p = NaN\nfit_%s_%s_se = -1\nfit_%s_%s_C = NaN\n", gn, qn, gn, qn, gn, qn);
            }
        }
    }
    snprintf(path, sizeof path, "%s/%s.tsv", s->out_dir, st->table);
    if ((rc = hj_out_open(&tab, path, err))) { hj_out_abort(&fit); hj_out_abort(&gp); return rc; }
    fprintf(tab.fp, "# %s computed by %s: strategy %s, delta %.3g, stop norm %s, L1 %s, guess %s\n", st->table, st->program,
            strategy_name(s->strategy), s->delta, s->stop_norm == HJ_STOP_LINF ? "max" : s->stop_norm == HJ_STOP_L1_INTEGRAL ? "h^2 sum" : "mean",
            s->l1_integral ? "h^2 sum|e|" : "mean |e|", s->guess == HJ_GUESS_WITH_III ? "category-iii" : "physical");
    if (s->guess_noise > 0)
        fprintf(tab.fp, "# guess perturbed: relative noise %.3g, seed %ld (round-off sensitivity study)\n", s->guess_noise, s->seed);
    fprintf(tab.fp, "case\tN\th\tL1\tL1_order\tLinf\tLinf_order\titer\tfo_iter\tchange\tseconds\tcat3\tmeasured\n");
    for (int ci = 0; ci < st->ncases; ci++)
        for (int k = 0; k < s->nsizes; k++) {
            const row *r = &rows[ci][k];
            fprintf(tab.fp, "%s\t%ld\t%.6g\t%.3e", st->cases[ci].name, r->N, r->h, r->l1);
            if (k) put_order(tab.fp, &rows[ci][k - 1], r, 0); else fputs("\t-", tab.fp);
            fprintf(tab.fp, "\t%.3e", r->linf);
            if (k) put_order(tab.fp, &rows[ci][k - 1], r, 1); else fputs("\t-", tab.fp);
            fprintf(tab.fp, "\t%d\t%d\t%.2e\t%.3f\t%ld\t%ld\n", r->iter, r->fo_iter, r->change, r->seconds, r->ncat3,
                    r->measured);
        }
    /* the table last: its presence means the run is complete */
    if ((rc = hj_out_commit(&fit, err)) || (rc = hj_out_commit(&gp, err))) { hj_out_abort(&tab); return rc; }
    return hj_out_commit(&tab, err);
}

/* The options that take a value (all others but --help, --quick are unknown). */
static int takes_value(const char *a)
{
    static const char *const opts[] = {"--sizes", "--out-dir", "--delta", "--eps", "--eps-h2", "--band", "--grid-N", "--max-iter", "--stop-norm", "--exclude", "--l1", "--strategy", "--richardson-box", "--guess", "--guess-noise", "--seed"};
    for (size_t k = 0; k < sizeof opts / sizeof opts[0]; k++)
        if (!strcmp(a, opts[k])) return 1;
    return 0;
}

static void usage(FILE *f, const p1_study *st, const char *extra)
{
    fprintf(f,
            "usage: %s [options]\n"
            "Reproduces %s of Huang, Shu & Zhang (2008); see the comment at the top of its source.\n"
            "  --sizes N1,N2,...   grid sizes (intervals per direction; default the published ones)\n"
            "  --quick             only the %d coarsest published sizes\n"
            "  --out-dir DIR       where to write %s.tsv and companions (default .)\n"
            "  --strategy S        richardson | lax-wendroff | first-order (default: the paper's)\n"
            "  --delta X           stopping threshold of (2.8) (default 1e-11)\n"
            "  --stop-norm N       l1int (h^2 sum |change|, default) | l1 (mean |change|) | linf\n"
            "  --eps X             WENO epsilon (default: the paper's for this example)\n"
            "  --eps-h2 C          WENO epsilon = C h^2\n"
            "  --l1 M              integral (h^2 sum |e|, default) | mean (mean |e| over measured nodes)\n"
            "  --exclude M         distance (default: nodes closer than 0.15 to a singular centre are not measured;\n"
            "                      a band as in literal) | literal (the paper's boxes, edges tested on the computed\n"
            "                      coordinates) | closed (nodes within 1e-9 h of a box edge are not measured) | open (they are)\n"
            "  --band B            Category III: horizontal/vertical distance < B h to a curve (default 3)\n"
            "  --richardson-box M  node (default: [-2h, 2h]^2 around each Category III node of a curve, widened\n"
            "                      by one node of each grid h, h/2, h/4) | tight (the same box without that node)\n"
            "                      | piece (one box per inflow curve: exact where first order sweeps are)\n"
            "  --guess G           initial guess: first order sweeps from the boundary condition alone (physical)\n"
            "                      or also holding the Category III values (category-iii); default: %s\n"
            "  --guess-noise R     multiply each Category IV value of the guess by 1 + R u, u uniform in [-1, 1)\n"
            "                      (round-off sensitivity; default 0: no perturbation)\n"
            "  --seed S            seed of that perturbation (default 1)\n"
            "  --max-iter N        at most N iterations (default 10000)\n"
            "  --grid-N N          write the solution grid of this N (default 80)\n"
            "  --help              this text\n%s",
            st->program, st->table, st->nquick, st->table,
            st->guess == HJ_GUESS_PHYSICAL ? "physical" : "category-iii", extra ? extra : "");
}

int p1_main(int argc, char **argv, const p1_study *st, const char *usage_extra)
{
    const char *prog = st->program;
    settings s;
    memset(&s, 0, sizeof s);
    s.out_dir = ".";
    s.delta = 1e-11;
    s.band = 3;
    s.exclude_mode = EXCL_DISTANCE; /* see excluded() and the overview */
    s.l1_integral = 1;
    s.eps = -1;
    s.stop_norm = HJ_STOP_L1_INTEGRAL;
    s.max_iter = 10000;
    s.grid_N = 80;
    s.strategy = st->strategy;
    s.guess = st->guess;
    s.seed = 1;
    s.nsizes = st->nsizes;
    memcpy(s.sizes, st->sizes, sizeof(long) * (size_t)st->nsizes);
    hj_error err;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        int rc = HJ_OK;
        if (!strcmp(a, "--help")) { usage(stdout, st, usage_extra); return 0; }
        if (!strcmp(a, "--quick")) { s.nsizes = st->nquick; continue; }
        if (strncmp(a, "--", 2) != 0) hj_cli_fail(prog, HJ_EXIT_USAGE, "unexpected argument '%s' (see --help)", a);
        if (!takes_value(a)) hj_cli_fail(prog, HJ_EXIT_USAGE, "unknown option '%s' (see --help)", a);
        if (!v) hj_cli_fail(prog, HJ_EXIT_USAGE, "option %s needs a value (see --help)", a);
        i++;
        if (!strcmp(a, "--sizes")) rc = hj_parse_long_list(v, "--sizes", 8, 10000, s.sizes, MAX_SIZES, &s.nsizes, &err);
        else if (!strcmp(a, "--out-dir")) s.out_dir = v;
        else if (!strcmp(a, "--delta")) rc = hj_parse_double(v, "--delta", 0, 1, &s.delta, &err);
        else if (!strcmp(a, "--eps")) rc = hj_parse_double(v, "--eps", 1e-300, 1, &s.eps, &err), s.eps_h2 = 0;
        else if (!strcmp(a, "--eps-h2")) rc = hj_parse_double(v, "--eps-h2", 1e-300, 1e6, &s.eps, &err), s.eps_h2 = 1;
        else if (!strcmp(a, "--band")) rc = hj_parse_double(v, "--band", 1, 10, &s.band, &err);
        else if (!strcmp(a, "--guess-noise")) rc = hj_parse_double(v, "--guess-noise", 0, 0.5, &s.guess_noise, &err);
        else if (!strcmp(a, "--seed")) rc = hj_parse_long(v, "--seed", 0, 2147483647L, &s.seed, &err);
        else if (!strcmp(a, "--grid-N")) rc = hj_parse_long(v, "--grid-N", 8, 10000, &s.grid_N, &err);
        else if (!strcmp(a, "--max-iter")) {
            long m;
            rc = hj_parse_long(v, "--max-iter", 1, 10000000, &m, &err);
            s.max_iter = (int)m;
        } else if (!strcmp(a, "--stop-norm")) {
            if (!strcmp(v, "l1")) s.stop_norm = HJ_STOP_L1_MEAN;
            else if (!strcmp(v, "l1int")) s.stop_norm = HJ_STOP_L1_INTEGRAL;
            else if (!strcmp(v, "linf")) s.stop_norm = HJ_STOP_LINF;
            else hj_cli_fail(prog, HJ_EXIT_USAGE, "--stop-norm must be l1, l1int or linf, got '%s'", v);
        } else if (!strcmp(a, "--exclude")) {
            if (!strcmp(v, "open")) s.exclude_mode = EXCL_OPEN;
            else if (!strcmp(v, "closed")) s.exclude_mode = EXCL_CLOSED;
            else if (!strcmp(v, "literal")) s.exclude_mode = EXCL_LITERAL;
            else if (!strcmp(v, "distance")) s.exclude_mode = EXCL_DISTANCE;
            else hj_cli_fail(prog, HJ_EXIT_USAGE, "--exclude must be distance, literal, open or closed, got '%s'", v);
        } else if (!strcmp(a, "--l1")) {
            if (!strcmp(v, "mean")) s.l1_integral = 0;
            else if (!strcmp(v, "integral")) s.l1_integral = 1;
            else hj_cli_fail(prog, HJ_EXIT_USAGE, "--l1 must be mean or integral, got '%s'", v);
        } else if (!strcmp(a, "--richardson-box")) {
            if (!strcmp(v, "node")) s.richardson_box = HJ_RICH_BOX_NODE;
            else if (!strcmp(v, "tight")) s.richardson_box = HJ_RICH_BOX_TIGHT;
            else if (!strcmp(v, "piece")) s.richardson_box = HJ_RICH_BOX_PIECE;
            else hj_cli_fail(prog, HJ_EXIT_USAGE, "--richardson-box must be node, tight or piece, got '%s'", v);
        } else if (!strcmp(a, "--guess")) {
            if (!strcmp(v, "physical")) s.guess = HJ_GUESS_PHYSICAL;
            else if (!strcmp(v, "category-iii")) s.guess = HJ_GUESS_WITH_III;
            else hj_cli_fail(prog, HJ_EXIT_USAGE, "--guess must be physical or category-iii, got '%s'", v);
        } else if (!strcmp(a, "--strategy")) {
            if (!strcmp(v, "richardson")) s.strategy = HJ_BC_RICHARDSON;
            else if (!strcmp(v, "lax-wendroff")) s.strategy = HJ_BC_LAX_WENDROFF;
            else if (!strcmp(v, "first-order")) s.strategy = HJ_BC_FIRST_ORDER;
            else hj_cli_fail(prog, HJ_EXIT_USAGE, "--strategy must be richardson, lax-wendroff or first-order, got '%s'", v);
        } else {
            hj_cli_fail(prog, HJ_EXIT_USAGE, "unknown option '%s' (see --help)", a);
        }
        if (rc) hj_cli_fail(prog, HJ_EXIT_USAGE, "%s", err.msg);
    }
    if (hj_mkdirs(s.out_dir, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    static row rows[MAX_CASES][MAX_SIZES];
    for (int ci = 0; ci < st->ncases; ci++)
        for (int k = 0; k < s.nsizes; k++)
            if (run_one(st, &s, &st->cases[ci], s.sizes[k], &rows[ci][k], &err))
                hj_cli_fail(prog, HJ_EXIT_RUN, "case %s, N=%ld: %s", st->cases[ci].name, s.sizes[k], err.msg);
    if (write_outputs(st, &s, rows, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    return 0;
}

/* ---- geometry helpers ---------------------------------------------------- */

double p1_unit_speed(double x, double y, void *ctx)
{
    (void)x, (void)y, (void)ctx;
    return 1.0;
}

void p1_unit_speed_grad(double x, double y, double g[2], void *ctx)
{
    (void)x, (void)y, (void)ctx;
    g[0] = g[1] = 0;
}
