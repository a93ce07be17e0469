/* p2_reach.c -- see p2_reach.h. */
#include "p2_reach.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

#include "hj_ls_deriv.h"
#include "hj_ls_io.h"
#include "hj_ls_measure.h"
#include "hj_ls_term.h"

static const char *const acc_names[P2_NACC] = {"low", "medium", "high", "veryHigh"};
static const int acc_scheme[P2_NACC] = {HJ_LS_UPWIND_FIRST, HJ_LS_ENO2, HJ_LS_ENO3A, HJ_LS_WENO5A};
static const int acc_order[P2_NACC] = {1, 2, 3, 3};
static const char *const diss_names[3] = {"global", "local", "locallocal"};

const char *p2_accuracy_name(int acc) { return acc >= 0 && acc < P2_NACC ? acc_names[acc] : "?"; }
int p2_accuracy_scheme(int acc) { return acc_scheme[acc]; }
int p2_accuracy_order(int acc) { return acc_order[acc]; }

int p2_parse_accuracy(const char *s, int *acc, hj_error *err)
{
    for (int k = 0; k < P2_NACC; k++)
        if (!strcmp(s, acc_names[k])) { *acc = k; return HJ_OK; }
    return hj_error_set(err, HJ_EINVAL, "unknown accuracy '%s' (low, medium, high, veryHigh)", s);
}

const char *p2_dissipation_name(int diss) { return diss >= HJ_LS_GLF && diss <= HJ_LS_LLLF ? diss_names[diss] : "?"; }

int p2_parse_dissipation(const char *s, int *diss, hj_error *err)
{
    const int v[3] = {HJ_LS_GLF, HJ_LS_LLF, HJ_LS_LLLF};
    for (int k = 0; k < 3; k++)
        if (!strcmp(s, diss_names[k])) { *diss = v[k]; return HJ_OK; }
    return hj_error_set(err, HJ_EINVAL, "unknown dissipation '%s' (global, local, locallocal)", s);
}

int p2_measure(const hj_ls_grid *g, const double *phi, int periodic_dim, double *m, hj_error *err)
{
    if (periodic_dim < 0) return hj_ls_measure(g, phi, m, err);
    /* A grid with one more node in the periodic dimension, its last plane
     * a copy of the first. */
    hj_ls_grid e;
    long N[HJ_LS_MAXDIM];
    double lo[HJ_LS_MAXDIM], hi[HJ_LS_MAXDIM];
    for (int d = 0; d < g->dim; d++) N[d] = g->N[d], lo[d] = g->min[d], hi[d] = g->max[d];
    N[periodic_dim] += 1;
    hi[periodic_dim] = g->min[periodic_dim] + (double)g->N[periodic_dim] * g->dx[periodic_dim];
    int rc = hj_ls_grid_init(&e, g->dim, lo, hi, N, g->bc, err);
    if (rc) return rc;
    double *a = hj_ls_alloc(&e);
    if (!a) return hj_error_set(err, HJ_ENOMEM, "measure: out of memory");
    for (size_t r = 0; r < e.rows; r++) {
        long i[HJ_LS_MAXDIM] = {0};
        const size_t k = hj_ls_row(&e, r, i);
        if (i[periodic_dim] == g->N[periodic_dim]) i[periodic_dim] = 0;
        const size_t ks = hj_ls_index(g, i);
        if (periodic_dim == 0) {
            memcpy(a + k, phi + ks, sizeof(double) * (size_t)g->N[0]);
            a[k + (size_t)g->N[0]] = phi[ks];
        } else
            memcpy(a + k, phi + ks, sizeof(double) * (size_t)e.N[0]);
    }
    rc = hj_ls_measure(&e, a, m, err);
    hj_ls_free(a);
    return rc;
}

static long count_rows(const hj_ls_grid *g, const double *a, const double *b, int differ)
{
    long c = 0;
    for (size_t r = 0; r < g->rows; r++) {
        long i[HJ_LS_MAXDIM] = {0};
        const size_t k = hj_ls_row(g, r, i);
        for (long j = 0; j < g->N[0]; j++) {
            const double x = a[k + (size_t)j], y = b[k + (size_t)j];
            c += differ ? memcmp(&x, &y, sizeof x) != 0 : y > x;
        }
    }
    return c;
}

long p2_count_increase(const hj_ls_grid *g, const double *a, const double *b) { return count_rows(g, a, b, 0); }
long p2_count_differ(const hj_ls_grid *g, const double *a, const double *b) { return count_rows(g, a, b, 1); }

int p2_reach_log_init(p2_reach_log *log, const hj_ls_grid *g, int periodic_dim, double t0, const double *y0,
                      p2_snapshot_fn user, void *user_ctx, hj_error *err)
{
    memset(log, 0, sizeof *log);
    log->g = g;
    log->periodic_dim = periodic_dim;
    log->user = user;
    log->user_ctx = user_ctx;
    log->prev = hj_ls_alloc(g);
    if (!log->prev) return hj_error_set(err, HJ_ENOMEM, "reach log: out of memory");
    hj_ls_copy(g, log->prev, y0);
    log->t[0] = t0;
    log->increased[0] = 0;
    log->n = 1;
    int rc = p2_measure(g, y0, periodic_dim, &log->measure[0], err);
    if (!rc && user) rc = user(0, t0, y0, user_ctx, err);
    return rc;
}

int p2_reach_output(int k, double t, const double *y, void *ctx, hj_error *err)
{
    p2_reach_log *log = ctx;
    if (log->n >= P2_MAXT) return hj_error_set(err, HJ_EINVAL, "reach log: more than %d output times", P2_MAXT);
    const int n = log->n;
    log->t[n] = t;
    log->increased[n] = p2_count_increase(log->g, log->prev, y);
    int rc = p2_measure(log->g, y, log->periodic_dim, &log->measure[n], err);
    if (rc) return rc;
    hj_ls_copy(log->g, log->prev, y);
    log->n = n + 1;
    return log->user ? log->user(k, t, y, log->user_ctx, err) : HJ_OK;
}

void p2_reach_log_free(p2_reach_log *log)
{
    hj_ls_free(log->prev);
    log->prev = NULL;
}

void p2_times(double t0, double tmax, int nint, double *ts)
{
    for (int k = 0; k <= nint; k++) ts[k] = k == nint ? tmax : t0 + (tmax - t0) * (double)k / (double)nint;
}

double p2_peak_rss_mb(void)
{
    struct rusage ru;
    if (getrusage(RUSAGE_SELF, &ru)) return NAN;
    return (double)ru.ru_maxrss / 1024.0;
}

int p2_write_block(int k, double t, const double *y, void *ctx, hj_error *err)
{
    p2_blocks *b = ctx;
    char name[64];
    snprintf(name, sizeof name, "phi(t=%.6g)", t);
    const char *names[1] = {name};
    const double *f[1] = {y};
    if (k) fputs("\n\n", b->fp);
    return hj_ls_write_block(b->fp, b->g, 1, names, f, err);
}

int p2_write_voxels(FILE *fp, const hj_ls_grid *g, int nfields, const double *const *fields, int M, int periodic_dim,
                    hj_error *err)
{
    if (g->dim != 3 || M < 2) return hj_error_set(err, HJ_EINVAL, "voxels: a 3-D grid and M >= 2 are needed");
    double hi[3];
    for (int d = 0; d < 3; d++) hi[d] = d == periodic_dim ? g->min[d] + (double)g->N[d] * g->dx[d] : g->max[d];
    fprintf(fp, "# %d^3 lattice on [%.10g, %.10g] x [%.10g, %.10g] x [%.10g, %.10g]: x y z fields\n", M, g->min[0],
            hi[0], g->min[1], hi[1], g->min[2], hi[2]);
    for (int c = 0; c < M; c++)
        for (int b = 0; b < M; b++)
            for (int a = 0; a < M; a++) {
                const int l[3] = {a, b, c};
                double x[3], w[3];
                long i0[3], i1[3];
                for (int d = 0; d < 3; d++) {
                    x[d] = g->min[d] + (hi[d] - g->min[d]) * l[d] / (M - 1);
                    double s = (x[d] - g->min[d]) / g->dx[d];
                    long i = (long)floor(s);
                    const long last = d == periodic_dim ? g->N[d] - 1 : g->N[d] - 2;
                    i = i < 0 ? 0 : i > last ? last : i;
                    w[d] = s - (double)i;
                    w[d] = w[d] < 0 ? 0 : w[d] > 1 ? 1 : w[d];
                    i0[d] = i;
                    i1[d] = d == periodic_dim ? (i + 1) % g->N[d] : i + 1;
                }
                fprintf(fp, "%.9g %.9g %.9g", x[0], x[1], x[2]);
                for (int f = 0; f < nfields; f++) {
                    double v = 0;
                    for (int corner = 0; corner < 8; corner++) {
                        long i[3];
                        double wt = 1;
                        for (int d = 0; d < 3; d++) {
                            const int up = corner >> d & 1;
                            i[d] = up ? i1[d] : i0[d];
                            wt *= up ? w[d] : 1 - w[d];
                        }
                        v += wt * fields[f][hj_ls_index(g, i)];
                    }
                    fprintf(fp, " %.6g", v);
                }
                fputc('\n', fp);
            }
    return ferror(fp) ? hj_error_set(err, HJ_EIO, "voxels: write error") : HJ_OK;
}

int p2_next_option(int argc, char **argv, int *i, const char *const *valued, int nvalued, int *opt, const char **value,
                   hj_error *err)
{
    const char *a = argv[*i];
    *value = NULL;
    if (!strcmp(a, "--help")) { *opt = P2_OPT_HELP; return HJ_OK; }
    if (!strcmp(a, "--quick")) { *opt = P2_OPT_QUICK; return HJ_OK; }
    for (int k = 0; k < nvalued; k++)
        if (!strcmp(a, valued[k])) {
            if (*i + 1 >= argc) return hj_error_set(err, HJ_EINVAL, "option %s needs a value", a);
            *opt = k;
            *value = argv[++*i];
            return HJ_OK;
        }
    return hj_error_set(err, HJ_EINVAL, "unknown option '%s' (see --help)", a);
}
