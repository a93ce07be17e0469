/* p2_basic.c -- see p2_basic.h. */
#include "p2_basic.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hj_ls_deriv.h"
#include "hj_ls_helper.h"
#include "hj_ls_io.h"
#include "hj_ls_measure.h"
#include "hj_ls_shape.h"
#include "hj_math.h"


const char *const p2b_acc_name[P2B_NACC] = {"low", "medium", "high", "veryHigh"};
const int p2b_acc_scheme[P2B_NACC] = {HJ_LS_UPWIND_FIRST, HJ_LS_ENO2, HJ_LS_ENO3A, HJ_LS_WENO5A};
const int p2b_acc_order[P2B_NACC] = {1, 2, 3, 3};
const char *const p2b_flow_name[P2B_NFLOW] = {"constant", "linear", "constantRev", "linearRev"};

int p2b_parse_choice(const char *s, const char *what, const char *const *names, int n, int *out, hj_error *err)
{
    char list[512] = "";
    for (int k = 0; k < n; k++) {
        if (!strcmp(s, names[k])) { *out = k; return HJ_OK; }
        size_t len = strlen(list);
        snprintf(list + len, sizeof list - len, "%s%s", k ? ", " : "", names[k]);
    }
    return hj_error_set(err, HJ_EINVAL, "unknown %s '%s' (one of: %s)", what, s, list);
}

void p2b_flow_velocity(double t, const double *x, double dx0, long n, int d, double *v, void *ctx)
{
    (void)t;
    const p2b_flow *f = ctx;
    const double s = f->sign;
    if (!f->linear) {
        for (long j = 0; j < n; j++) v[j] = d == 0 ? 2 * s : 0;
    } else if (f->dim < 2) {
        for (long j = 0; j < n; j++) v[j] = 0;
    } else if (d == 0) {
        for (long j = 0; j < n; j++) v[j] = s * 2 * HJ_PI * x[1];
    } else if (d == 1) {
        for (long j = 0; j < n; j++) v[j] = -s * 2 * HJ_PI * (x[0] + (double)j * dx0);
    } else {
        for (long j = 0; j < n; j++) v[j] = 0;
    }
}

int p2b_seq_open(p2b_seq *s, const char *path, const hj_ls_grid *g, const char *name, hj_error *err)
{
    memset(s, 0, sizeof *s);
    s->g = g;
    s->name = name;
    s->t_switch = INFINITY;
    if (!path) return HJ_OK;
    int rc = hj_out_open(&s->out, path, err);
    s->open = rc == HJ_OK;
    return rc;
}

int p2b_seq_block(p2b_seq *s, double t, const double *y, hj_error *err)
{
    if (s->open) {
        const char *names[4] = {s->name, s->extra_name[0], s->extra_name[1], s->extra_name[2]};
        const double *f[4] = {y, s->extra[0], s->extra[1], s->extra[2]};
        fprintf(s->out.fp, "%s# t = %.10g\n", ftell(s->out.fp) > 0 ? "\n\n" : "", t);
        int rc = hj_ls_write_block(s->out.fp, s->g, 1 + s->nextra, names, f, err);
        if (rc) return rc;
    }
    return HJ_OK;
}

int p2b_seq_out(int k, double t, const double *y, void *ctx, hj_error *err)
{
    p2b_seq *s = ctx;
    int rc = p2b_seq_block(s, t, y, err);
    if (rc) return rc;
    if (s->flip && t >= s->t_switch) {
        s->flip->sign = -1;
        s->flip = NULL; /* once */
    }
    return s->hook ? s->hook(k, t, y, s->hook_ctx, err) : HJ_OK;
}

int p2b_seq_commit(p2b_seq *s, hj_error *err)
{
    if (!s->open) return HJ_OK;
    s->open = 0;
    return hj_out_commit(&s->out, err);
}

void p2b_seq_abort(p2b_seq *s)
{
    if (s->open) hj_out_abort(&s->out);
    s->open = 0;
}

void p2b_times(double t0, double t1, int n, double *tspan)
{
    for (int k = 0; k < n; k++) tspan[k] = k == n - 1 ? t1 : t0 + (t1 - t0) * (double)k / (double)(n - 1);
}

void p2b_front_error(const hj_ls_grid *g, const double *phi, const double *exact, double band, double *max,
                     double *mean)
{
    double m = 0, s = 0;
    long c = 0;
    long idx[HJ_LS_MAXDIM];
    for (size_t r = 0; r < g->rows; r++) {
        const size_t k = hj_ls_row(g, r, idx);
        for (long j = 0; j < g->N[0]; j++) {
            const size_t q = k + (size_t)j;
            if (!(fabs(exact[q]) < band)) continue;
            const double e = fabs(phi[q] - exact[q]);
            m = e > m ? e : m;
            s += e;
            c++;
        }
    }
    *max = m;
    *mean = c ? s / (double)c : 0;
}

int p2b_grad_magnitude(const hj_ls_grid *g, double *phi, double *work, double *out, hj_error *err)
{
    long idx[HJ_LS_MAXDIM];
    for (size_t r = 0; r < g->rows; r++) {
        const size_t k = hj_ls_row(g, r, idx);
        for (long j = 0; j < g->N[0]; j++) out[k + (size_t)j] = 0;
    }
    for (int d = 0; d < g->dim; d++) {
        int rc = hj_ls_centered_first(g, phi, d, work, err);
        if (rc) return rc;
        for (size_t r = 0; r < g->rows; r++) {
            const size_t k = hj_ls_row(g, r, idx);
            for (long j = 0; j < g->N[0]; j++) out[k + (size_t)j] += work[k + (size_t)j] * work[k + (size_t)j];
        }
    }
    for (size_t r = 0; r < g->rows; r++) {
        const size_t k = hj_ls_row(g, r, idx);
        for (long j = 0; j < g->N[0]; j++) out[k + (size_t)j] = sqrt(out[k + (size_t)j]);
    }
    return HJ_OK;
}

int p2b_grad_deviation(const hj_ls_grid *g, double *phi, const double *dist, double band, double *work,
                       double *mean, double *max, hj_error *err)
{
    double *gm = hj_ls_alloc(g);
    if (!gm) return hj_error_set(err, HJ_ENOMEM, "gradient deviation: out of memory");
    int rc = p2b_grad_magnitude(g, phi, work, gm, err);
    double m = 0, s = 0;
    long c = 0, idx[HJ_LS_MAXDIM];
    for (size_t r = 0; r < g->rows && !rc; r++) {
        const size_t k = hj_ls_row(g, r, idx);
        for (long j = 0; j < g->N[0]; j++) {
            const size_t q = k + (size_t)j;
            if (!(fabs(dist[q]) < band)) continue;
            const double e = fabs(gm[q] - 1);
            m = e > m ? e : m;
            s += e;
            c++;
        }
    }
    hj_ls_free(gm);
    *mean = c ? s / (double)c : 0;
    *max = m;
    return rc;
}

int p2b_crossings(const hj_ls_grid *g, const double *phi, double **pts, long *n, hj_error *err)
{
    if (g->dim != 2) return hj_error_set(err, HJ_EINVAL, "zero crossings: 2-D grids only");
    long cap = 1024, np = 0;
    double *p = malloc(sizeof(double) * 2 * (size_t)cap);
    if (!p) return hj_error_set(err, HJ_ENOMEM, "zero crossings: out of memory");
    for (long b = 0; b < g->N[1]; b++)
        for (long a = 0; a < g->N[0]; a++) {
            const long i[2] = {a, b};
            double x[2];
            hj_ls_coord(g, i, x);
            const size_t k = hj_ls_index(g, i);
            const double v = phi[k];
            double cand[3][2];
            int nc = 0;
            if (v == 0) cand[nc][0] = x[0], cand[nc][1] = x[1], nc++;
            for (int d = 0; d < 2; d++) {
                if (i[d] + 1 >= g->N[d]) continue;
                const double w = phi[k + (size_t)g->stride[d]];
                if ((v < 0 && w > 0) || (v > 0 && w < 0)) {
                    const double f = v / (v - w);
                    cand[nc][0] = x[0] + (d == 0 ? f * g->dx[0] : 0);
                    cand[nc][1] = x[1] + (d == 1 ? f * g->dx[1] : 0);
                    nc++;
                }
            }
            for (int c = 0; c < nc; c++) {
                if (np == cap) {
                    double *q = realloc(p, sizeof(double) * 4 * (size_t)cap);
                    if (!q) { free(p); return hj_error_set(err, HJ_ENOMEM, "zero crossings: out of memory"); }
                    p = q, cap *= 2;
                }
                p[2 * np] = cand[c][0], p[2 * np + 1] = cand[c][1], np++;
            }
        }
    *pts = p;
    *n = np;
    return HJ_OK;
}

double p2b_star_phi(const double *x, void *ctx)
{
    const p2b_star *s = ctx;
    const double th = atan2(x[1], x[0]);
    return sqrt(x[0] * x[0] + x[1] * x[1]) - s->scale * (cos(s->points * th) + s->shift);
}

double p2b_star_area(const p2b_star *s) { return HJ_PI * s->scale * s->scale * (0.5 + s->shift * s->shift); }

int p2b_curve_sample(const p2b_star *star, const double *center, double radius, long n, double **pts, hj_error *err)
{
    double *p = malloc(sizeof(double) * 2 * (size_t)n);
    if (!p) return hj_error_set(err, HJ_ENOMEM, "curve samples: out of memory");
    for (long k = 0; k < n; k++) {
        const double th = 2 * HJ_PI * (double)k / (double)n;
        if (star) {
            const double r = star->scale * (cos(star->points * th) + star->shift);
            p[2 * k] = r * cos(th), p[2 * k + 1] = r * sin(th);
        } else {
            p[2 * k] = center[0] + radius * cos(th), p[2 * k + 1] = center[1] + radius * sin(th);
        }
    }
    *pts = p;
    return HJ_OK;
}

/* Squared distance from (px, py) to the segment a-b. */
static double seg_dist2(double px, double py, const double *a, const double *b)
{
    const double ux = b[0] - a[0], uy = b[1] - a[1], wx = px - a[0], wy = py - a[1];
    const double uu = ux * ux + uy * uy;
    double f = uu > 0 ? (wx * ux + wy * uy) / uu : 0;
    f = f < 0 ? 0 : f > 1 ? 1 : f;
    const double dx = wx - f * ux, dy = wy - f * uy;
    return dx * dx + dy * dy;
}

void p2b_point_curve_distance(const double *p, long np, const double *c, long nc, double *max, double *mean)
{
    double m = 0, s = 0;
    for (long i = 0; i < np; i++) {
        double best = INFINITY;
        long kb = 0;
        for (long k = 0; k < nc; k++) {
            const double a = p[2 * i] - c[2 * k], b = p[2 * i + 1] - c[2 * k + 1];
            const double d2 = a * a + b * b;
            if (d2 < best) best = d2, kb = k;
        }
        /* refine on the two chords of the closed polygon at the nearest sample */
        const long kp = (kb + nc - 1) % nc, kn = (kb + 1) % nc;
        const double d1 = seg_dist2(p[2 * i], p[2 * i + 1], c + 2 * kp, c + 2 * kb);
        const double d2 = seg_dist2(p[2 * i], p[2 * i + 1], c + 2 * kb, c + 2 * kn);
        best = d1 < best ? d1 : best;
        best = d2 < best ? d2 : best;
        const double d = sqrt(best);
        m = d > m ? d : m;
        s += d;
    }
    *max = m;
    *mean = np ? s / (double)np : 0;
}

const char *const p2b_shape_name[P2B_NSHAPE] = {"circle", "star"};

int p2b_reinit_setup(p2b_reinit_case *c, int shape, hj_error *err)
{
    memset(c, 0, sizeof *c);
    c->shape = shape;
    c->star = (p2b_star){0.25, 2.0, 7};
    c->center[0] = -0.4, c->center[1] = 0, c->radius = 0.35;
    const double dx = 0.02, lo[2] = {-1, -1}, hi[2] = {1 - dx, 1 - dx};
    const long n[2] = {100, 100};
    const hj_ls_bc bc[2] = {{HJ_LS_BC_PERIODIC, 0, 0}, {HJ_LS_BC_PERIODIC, 0, 0}};
    int rc = hj_ls_grid_init(&c->g, 2, lo, hi, n, bc, err);
    if (rc) return rc;
    c->phi0 = hj_ls_alloc(&c->g), c->dist = hj_ls_alloc(&c->g), c->work = hj_ls_alloc(&c->g);
    if (!c->phi0 || !c->dist || !c->work) {
        p2b_reinit_free(c);
        return hj_error_set(err, HJ_ENOMEM, "reinit case: out of memory");
    }
    if (shape == P2B_STAR) {
        hj_ls_fill(&c->g, c->phi0, p2b_star_phi, &c->star);
        c->exact_area = p2b_star_area(&c->star);
    } else {
        rc = hj_ls_shape_sphere(&c->g, c->center, c->radius, c->phi0, err);
        c->exact_area = HJ_PI * c->radius * c->radius;
    }
    if (!rc) rc = p2b_curve_sample(shape == P2B_STAR ? &c->star : NULL, c->center, c->radius, P2B_CURVE_SAMPLES,
                                   &c->curve, err);
    if (!rc) rc = hj_ls_unsigned_distance(&c->g, c->curve, P2B_CURVE_SAMPLES, c->dist, err);
    if (!rc && !(c->coarse = malloc(sizeof(double) * 2 * (P2B_CURVE_SAMPLES / P2B_CURVE_STRIDE))))
        rc = hj_error_set(err, HJ_ENOMEM, "reinit case: out of memory");
    if (rc) { p2b_reinit_free(c); return rc; }
    for (long k = 0; k < P2B_CURVE_SAMPLES / P2B_CURVE_STRIDE; k++)
        c->coarse[2 * k] = c->curve[2 * k * P2B_CURVE_STRIDE], c->coarse[2 * k + 1] = c->curve[2 * k * P2B_CURVE_STRIDE + 1];
    long idx[2];
    for (size_t r = 0; r < c->g.rows; r++) {
        const size_t k = hj_ls_row(&c->g, r, idx);
        for (long j = 0; j < c->g.N[0]; j++)
            if (c->phi0[k + (size_t)j] < 0) c->dist[k + (size_t)j] = -c->dist[k + (size_t)j];
    }
    return HJ_OK;
}

void p2b_reinit_free(p2b_reinit_case *c)
{
    hj_ls_free(c->phi0), hj_ls_free(c->dist), hj_ls_free(c->work);
    free(c->curve), free(c->coarse);
    c->phi0 = c->dist = c->work = c->curve = c->coarse = NULL;
}

int p2b_reinit_measure(const p2b_reinit_case *c, double *phi, p2b_reinit_meas *m, hj_error *err)
{
    const double band = 5 * c->g.dx[0];
    int rc = p2b_grad_deviation(&c->g, phi, c->dist, band, c->work, &m->grad_mean, &m->grad_max, err);
    if (rc) return rc;
    double mean;
    p2b_front_error(&c->g, phi, c->dist, band, &m->sd_err, &mean);
    double *pts;
    long np;
    if ((rc = p2b_crossings(&c->g, phi, &pts, &np, err))) return rc;
    p2b_point_curve_distance(pts, np, c->coarse, P2B_CURVE_SAMPLES / P2B_CURVE_STRIDE, &m->shift_max, &m->shift_mean);
    free(pts);
    return hj_ls_measure(&c->g, phi, &m->area, err);
}

void p2b_reinit_header(FILE *fp)
{
    fprintf(fp, "shape\tacc\tgrad_before\tgrad_after\tgrad_max_after\tsd_err_before\tsd_err_after\tshift_floor\t"
                "shift_max\tshift_mean\tarea_before\tarea_after\texact_area\tsteps\n");
}

void p2b_reinit_row(FILE *fp, const p2b_reinit_case *c, int acc, const p2b_reinit_meas *b, const p2b_reinit_meas *a,
                    long steps)
{
    fprintf(fp, "%s\t%s\t%.4e\t%.4e\t%.4e\t%.4e\t%.4e\t%.4e\t%.4e\t%.4e\t%.6g\t%.6g\t%.6g\t%ld\n",
            p2b_shape_name[c->shape], p2b_acc_name[acc], b->grad_mean, a->grad_mean, a->grad_max, b->sd_err, a->sd_err,
            b->shift_max, a->shift_max, a->shift_mean, b->area, a->area, c->exact_area, steps);
}

void p2b_reinit_note_row(FILE *fp, const p2b_reinit_case *c, int acc, const p2b_reinit_meas *b,
                         const p2b_reinit_meas *a, long steps)
{
    fprintf(fp, "| %s | %s | %.3f -> %.4f | %.3f -> %.4f | %.4f (%.4f) -> %.4f (%.4f) | %+.3f %% | %ld |",
            p2b_shape_name[c->shape], p2b_acc_name[acc], b->grad_mean, a->grad_mean, b->sd_err, a->sd_err,
            b->shift_max, b->shift_mean, a->shift_max, a->shift_mean, 100 * (a->area / b->area - 1), steps);
}

int p2b_reinit_options(int argc, char **argv, p2b_reinit_opts *o, hj_error *err)
{
    *o = (p2b_reinit_opts){P2B_STAR, P2B_LOW, 0, 0, "."};
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--help")) { o->help = 1; return HJ_OK; }
        if (!strcmp(a, "--quick")) continue;
        if (strcmp(a, "--shape") && strcmp(a, "--accuracy") && strcmp(a, "--out-dir"))
            return hj_error_set(err, HJ_EINVAL, "unknown option '%s' (see --help)", a);
        if (i + 1 >= argc) return hj_error_set(err, HJ_EINVAL, "option %s needs a value (see --help)", a);
        const char *v = argv[++i];
        int rc = HJ_OK;
        if (!strcmp(a, "--out-dir")) o->dir = v;
        else if (!strcmp(a, "--shape")) rc = p2b_parse_choice(v, "shape", p2b_shape_name, P2B_NSHAPE, &o->shape, err), o->single = 1;
        else rc = p2b_parse_choice(v, "accuracy", p2b_acc_name, P2B_NACC, &o->acc, err), o->single = 1;
        if (rc) return rc;
    }
    return HJ_OK;
}
