/* p2_oshershu.c -- see p2_oshershu.h. */
#include "p2_oshershu.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hj_cli.h"
#include "hj_io.h"
#include "hj_ls_io.h"

#include "hj_ls_term.h"
#include "hj_ls_accuracy.h"
#include "hj_ls_seq.h"
#include "p2_cli.h"
#include "hj_math.h"


/* Output times of one run at the most. */
enum { OS_MAXT = 64 };

static double burgers_h(double q) { return 0.5 * (1 + q) * (1 + q); }
static double burgers_dh(double q) { return 1 + q; }
static double nonconvex_h(double q) { return -cos(1 + q); }
static double nonconvex_dh(double q) { return sin(1 + q); }

const p2_os_problem p2_os_burgers = {"burgers", burgers_h, burgers_dh, 1 + HJ_PI, 1};
const p2_os_problem p2_os_nonconvex = {"nonconvex", nonconvex_h, nonconvex_dh, 1, 0};

static double os_ham(double t, const double *x, double phi, const double *p, void *ctx)
{
    (void)t, (void)x, (void)phi;
    const p2_os_ctx *c = ctx;
    double q = 0;
    for (int d = 0; d < c->dim; d++) q += p[d];
    return c->pb->h(q);
}

/* Burgers: the toolbox bounds |1 + sum p| by 1 + sum max(|pmin|, |pmax|);
 * non-convex: the toolbox takes 1.  Tight: max |h'(q)| over q in
 * [sum pmin, sum pmax], exactly. */
static double os_partial(double t, const double *x, const double *pmin, const double *pmax, int dd, void *ctx)
{
    (void)t, (void)x, (void)dd;
    const p2_os_ctx *c = ctx;
    if (!c->tight) {
        if (!c->pb->convex) return 1.0;
        double s = 1;
        for (int d = 0; d < c->dim; d++) s += fabs(pmin[d]) > fabs(pmax[d]) ? fabs(pmin[d]) : fabs(pmax[d]);
        return s;
    }
    double lo = 0, hi = 0;
    for (int d = 0; d < c->dim; d++) lo += pmin[d], hi += pmax[d];
    if (c->pb->convex) return fabs(1 + lo) > fabs(1 + hi) ? fabs(1 + lo) : fabs(1 + hi);
    /* |sin(1 + q)| reaches 1 where 1 + q = pi/2 + k pi */
    const double a = 1 + lo, b = 1 + hi;
    if (floor((b - HJ_PI / 2) / HJ_PI) != floor((a - HJ_PI / 2) / HJ_PI)) return 1.0;
    return fabs(sin(a)) > fabs(sin(b)) ? fabs(sin(a)) : fabs(sin(b));
}

int p2_os_grid(int dim, long N, hj_ls_grid *g, hj_error *err)
{
    double lo[HJ_LS_MAXDIM], hi[HJ_LS_MAXDIM];
    long n[HJ_LS_MAXDIM];
    hj_ls_bc bc[HJ_LS_MAXDIM];
    for (int d = 0; d < dim; d++) {
        lo[d] = -dim;
        hi[d] = -dim + (double)(N - 1) * (2.0 * dim / (double)N);
        n[d] = N;
        bc[d].type = HJ_LS_BC_PERIODIC, bc[d].lo = bc[d].hi = 0;
    }
    return hj_ls_grid_init(g, dim, lo, hi, n, bc, err);
}

static double initial(const double *x, void *ctx)
{
    const int dim = *(const int *)ctx;
    double s = 0;
    for (int d = 0; d < dim; d++) s += x[d];
    return -cos(HJ_PI / dim * s);
}

int p2_os_solve(const p2_os_problem *pb, const p2_os_run *r, hj_ls_grid *g, double **phi, hj_ls_output_fn out,
                void *out_ctx, hj_ls_ode_stats *stats, hj_error *err)
{
    return p2_os_solve_rule(pb, r, HJ_LS_CFL_NODE, HJ_LS_WENO_EPS_LOCAL, g, phi, out, out_ctx, stats, err);
}

int p2_os_solve_rule(const p2_os_problem *pb, const p2_os_run *r, int cfl_rule, int weno_eps, hj_ls_grid *g,
                     double **phi, hj_ls_output_fn out, void *out_ctx, hj_ls_ode_stats *stats, hj_error *err)
{
    *phi = NULL;
    int rc = p2_os_grid(r->dim, r->N, g, err);
    if (rc) return rc;
    double *y = hj_ls_alloc(g);
    if (!y) return hj_error_set(err, HJ_ENOMEM, "out of memory for a %ld^%d grid", r->N, r->dim);
    int dim = r->dim;
    hj_ls_fill(g, y, initial, &dim);
    p2_os_ctx c = {pb, r->dim, r->tight};
    hj_ls_lax_friedrichs lf;
    hj_ls_lax_friedrichs_init(&lf, g, hj_ls_accuracy_scheme(r->acc), r->diss, os_ham, os_partial, &c);
    lf.cfl_rule = cfl_rule;
    lf.weno_eps = weno_eps;
    hj_ls_ode_opts o;
    hj_ls_ode_defaults(&o);
    o.factor_cfl = HJ_LS_FACTOR_CFL; /* burgersLF, nonconvexLF */
    double ts[OS_MAXT];
    const int nint = r->nout < 1 ? 1 : r->nout >= OS_MAXT ? OS_MAXT - 1 : r->nout;
    hj_ls_seq_times(0, r->tmax, nint + 1, ts);
    if (out && (rc = out(0, 0, y, out_ctx, err))) { hj_ls_free(y); return rc; }
    rc = hj_ls_ode(hj_ls_accuracy_order(r->acc), g, &lf.base, ts, nint + 1, y, &o, out, out_ctx, stats, err);
    if (rc) { hj_ls_free(y); return rc; }
    *phi = y;
    return HJ_OK;
}

static double foot_residual(const p2_os_problem *pb, double s0, double s, double t)
{
    return s0 + pb->dh(HJ_PI * sin(HJ_PI * s0)) * t - s;
}

double p2_os_exact(const p2_os_problem *pb, double s, double t, int *nroots)
{
    /* feet lie in [s - dh_max t, s + dh_max t] */
    const int M = 400;
    const double a = s - pb->dh_max * t - 1e-9, b = s + pb->dh_max * t + 1e-9;
    double best = INFINITY;
    int roots = 0;
    double x0 = a, f0 = foot_residual(pb, a, s, t);
    for (int k = 1; k <= M; k++) {
        const double x1 = a + (b - a) * k / M, f1 = foot_residual(pb, x1, s, t);
        double root = NAN;
        if (f0 == 0) root = x0;
        else if ((f0 < 0) != (f1 < 0) && f1 != 0) {
            double lo = x0, hi = x1, flo = f0;
            for (int it = 0; it < 200; it++) {
                const double mid = 0.5 * (lo + hi);
                if (mid <= lo || mid >= hi) break;
                const double fm = foot_residual(pb, mid, s, t);
                if (fm == 0) { lo = hi = mid; break; }
                if ((fm < 0) == (flo < 0)) lo = mid, flo = fm;
                else hi = mid;
            }
            root = 0.5 * (lo + hi);
        }
        if (!isnan(root)) {
            const double u = HJ_PI * sin(HJ_PI * root);
            const double G = -cos(HJ_PI * root) + t * (u * pb->dh(u) - pb->h(u));
            roots++;
            if (pb->convex ? G < best : roots == 1) best = G;
        }
        x0 = x1, f0 = f1;
    }
    if (nroots) *nroots = roots;
    return best;
}

int p2_os_exact_grid(const p2_os_problem *pb, const hj_ls_grid *g, double t, double *out)
{
    int mr = 0;
    for (size_t r = 0; r < g->rows; r++) {
        long i[HJ_LS_MAXDIM] = {0};
        const size_t k = hj_ls_row(g, r, i);
        for (long j = 0; j < g->N[0]; j++) {
            i[0] = j;
            double x[HJ_LS_MAXDIM], s = 0;
            hj_ls_coord(g, i, x);
            for (int d = 0; d < g->dim; d++) s += x[d];
            int nr;
            out[k + (size_t)j] = p2_os_exact(pb, s / g->dim, t, &nr);
            mr = nr > mr ? nr : mr;
        }
    }
    return mr;
}

void p2_os_errors(const hj_ls_grid *g, const double *phi, const double *exact, double *l1, double *linf)
{
    double sum = 0, mx = 0;
    for (size_t r = 0; r < g->rows; r++) {
        long i[HJ_LS_MAXDIM] = {0};
        const size_t k = hj_ls_row(g, r, i);
        double rs = 0;
        for (long j = 0; j < g->N[0]; j++) {
            const double e = fabs(phi[k + (size_t)j] - exact[k + (size_t)j]);
            rs += e;
            mx = e > mx ? e : mx;
        }
        sum += rs;
    }
    *l1 = sum / (double)g->nodes;
    *linf = mx;
}

double *p2_os_solve_to_file(const p2_os_problem *pb, const p2_os_run *r, hj_ls_grid *g, const char *path,
                            hj_error *err)
{
    hj_out out;
    hj_ls_seq seq;
    hj_ls_seq_init(&seq, NULL, g, "phi", 0);
    if (path) {
        if (hj_out_open(&out, path, err)) return NULL;
        seq.fp = out.fp;
    }
    double *phi;
    if (p2_os_solve(pb, r, g, &phi, path ? hj_ls_seq_output : NULL, &seq, NULL, err)) {
        if (path) hj_out_abort(&out);
        return NULL;
    }
    if (path && hj_out_commit(&out, err)) { hj_ls_free(phi); return NULL; }
    return phi;
}

double *p2_os_solve_or_exit(const char *prog, const p2_os_problem *pb, const p2_os_run *r, hj_ls_grid *g,
                            const char *path)
{
    hj_error err;
    double *phi = p2_os_solve_to_file(pb, r, g, path, &err);
    if (!phi) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    return phi;
}

void p2_os_append_block(const char *prog, const p2_os_problem *pb, const p2_os_run *r, FILE *fp, const char *fmt, ...)
{
    hj_ls_grid g = {0}; /* set by the run */
    double *phi = p2_os_solve_or_exit(prog, pb, r, &g, NULL);
    va_list ap;
    va_start(ap, fmt);
    vfprintf(fp, fmt, ap);
    va_end(ap);
    const char *names[1] = {"phi"};
    const double *fields[1] = {phi};
    hj_error err;
    p2_fail_if(prog, hj_ls_write_block(fp, &g, 1, names, fields, &err), &err);
    hj_ls_free(phi);
}

void p2_os_parse_cli(const char *prog, const char *summary, const char *epilog, int argc, char **argv,
                     int allow_partial, p2_os_cli *c)
{
    memset(c, 0, sizeof *c);
    c->run = (p2_os_run){2, 0, HJ_LS_ACC_LOW, HJ_LS_GLF, 0, 1.5 / (HJ_PI * HJ_PI), 10};
    c->out_dir = ".";
    long dim = c->run.dim;
    static const char *const bounds[] = {"toolbox", "tight", NULL};
    /* the run options first (--partial last of them): any makes one run */
    hj_cli_opt opts[] = {
        p2_opt_accuracy(&c->run.acc),
        p2_opt_dissipation("--diss", &c->run.diss),
        {.name = "--dim", .type = HJ_OPT_LONG, .value = &dim, .min = 1, .max = 3, .metavar = "D", .help = "dimension"},
        {.name = "--N", .type = HJ_OPT_LONG, .value = &c->run.N, .min = 4, .max = 100000, .metavar = "N",
         .help = "nodes per dimension", .dflt = "80 / 2^(dim - 1)"},
        {.name = "--tmax", .type = HJ_OPT_DOUBLE, .value = &c->run.tmax, .min = 1e-12, .max = 100, .metavar = "T",
         .help = "final time", .dflt = "1.5/pi^2"},
        {.name = "--partial", .type = HJ_OPT_CHOICE, .value = &c->run.tight, .choices = bounds, .metavar = "P",
         .help = "partial bound of the dissipation: the toolbox's or the exact one"},
        p2_opt_out_dir(&c->out_dir),
        p2_opt_quick(&c->quick, "the reduced grid sequences of CI"),
    };
    enum { NOPT = sizeof opts / sizeof opts[0], PARTIAL = 5 };
    hj_cli_opt all[NOPT];
    int n = 0;
    for (int k = 0; k < (int)NOPT; k++)
        if (k != PARTIAL || allow_partial) all[n++] = opts[k];
    c->single = p2_parse_runs(prog, summary, epilog, all, n, allow_partial ? PARTIAL + 1 : PARTIAL, argc, argv,
                              &c->out_dir);
    c->run.dim = (int)dim;
    if (!c->run.N) c->run.N = 80 >> (c->run.dim - 1);
}
