/* hj_ls_front.c -- measurements of the front; see hj_ls_front.h. */
#include "hj_ls_front.h"

#include <math.h>
#include <stdlib.h>

#include "hj_ls_deriv.h"

void hj_ls_front_error(const hj_ls_grid *g, const double *phi, const double *exact, double band, double *max,
                       double *mean)
{
    double m = 0;
    hj_sum s; /* exact: the mean does not depend on the order */
    hj_sum_init(&s);
    long c = 0;
    long idx[HJ_LS_MAXDIM];
    for (size_t r = 0; r < g->rows; r++) {
        const size_t k = hj_ls_row(g, r, idx);
        for (long j = 0; j < g->N[0]; j++) {
            const size_t q = k + (size_t)j;
            if (!(fabs(exact[q]) < band)) continue;
            const double e = fabs(phi[q] - exact[q]);
            m = e > m ? e : m;
            hj_sum_add(&s, e);
            c++;
        }
    }
    *max = m;
    *mean = c ? hj_sum_value(&s) / (double)c : 0;
}

int hj_ls_front_grad_deviation(const hj_ls_grid *g, double *phi, const double *dist, double band, double *work,
                               double *mean, double *max, hj_error *err)
{
    double *gm = hj_ls_alloc(g);
    if (!gm) return hj_error_set(err, HJ_ENOMEM, "gradient deviation: out of memory");
    int rc = hj_ls_gradient_norm(g, phi, work, gm, err);
    double m = 0;
    hj_sum s; /* exact: the mean does not depend on the order */
    hj_sum_init(&s);
    long c = 0, idx[HJ_LS_MAXDIM];
    for (size_t r = 0; r < g->rows && !rc; r++) {
        const size_t k = hj_ls_row(g, r, idx);
        for (long j = 0; j < g->N[0]; j++) {
            const size_t q = k + (size_t)j;
            if (!(fabs(dist[q]) < band)) continue;
            const double e = fabs(gm[q] - 1);
            m = e > m ? e : m;
            hj_sum_add(&s, e);
            c++;
        }
    }
    hj_ls_free(gm);
    *mean = c ? hj_sum_value(&s) / (double)c : 0;
    *max = m;
    return rc;
}

int hj_ls_front_crossings(const hj_ls_grid *g, const double *phi, double **pts, long *n, hj_error *err)
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
                    if (!q) {
                        free(p);
                        return hj_error_set(err, HJ_ENOMEM, "zero crossings: out of memory");
                    }
                    p = q, cap *= 2;
                }
                p[2 * np] = cand[c][0], p[2 * np + 1] = cand[c][1], np++;
            }
        }
    *pts = p;
    *n = np;
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

void hj_ls_front_distance(const double *p, long np, const double *c, long nc, double *max, double *mean)
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
