/* p3_front.c -- fixed fronts and their band (see p3_front.h). */
#include "p3_front.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NSPHERES 6
static const double SPHERE_STEP = 0.3, CYL_R = 0.5, CYL_H = 1.6;

static double coord(const p3_front *f, int i) { return -2 + i * f->dx; }

static int side_of(const p3_front *f, double rho2, double x)
{
    if (f->example == 2) return (rho2 <= CYL_R * CYL_R && fabs(x) <= CYL_H) ? -1 : 1;
    const double r2 = rho2 + x * x;
    int inside = 0;
    for (int k = 1; k <= NSPHERES; k++) inside += r2 <= (SPHERE_STEP * k) * (SPHERE_STEP * k);
    return inside % 2 ? -1 : 1;
}

static double rho2_of(const p3_front *f, const int *idx)
{
    double s = 0;
    for (int k = 0; k < f->d - 1; k++) {
        const double x = coord(f, idx[k]);
        s += x * x;
    }
    return s;
}

int p3_front_side(const p3_front *f, const int *idx) { return side_of(f, rho2_of(f, idx), coord(f, idx[f->d - 1])); }

/* Mark the indices i with |x_i| in [a, b] (widened by one node). */
static void mark_abs(const p3_front *f, unsigned char *mark, double a, double b)
{
    if (a < 0) a = 0;
    for (int s = -1; s <= 1; s += 2) {
        const double lo = s > 0 ? a : -b, hi = s > 0 ? b : -a;
        int i0 = (int)floor((lo + 2) / f->dx) - 1, i1 = (int)ceil((hi + 2) / f->dx) + 1;
        i0 = i0 < 0 ? 0 : i0;
        i1 = i1 > f->n - 1 ? f->n - 1 : i1;
        for (int i = i0; i <= i1; i++) mark[i] = 1;
    }
}

int p3_front_band(const p3_front *f, p3_front_fn fn, void *ctx, hj_error *err)
{
    const int d = f->d, n = f->n;
    unsigned char *mark = calloc((size_t)n, 1);
    if (!mark) return hj_error_set(err, HJ_ENOMEM, "out of memory (front band)");
    int64_t nl = 1;
    for (int k = 0; k < d - 1; k++) nl *= n;
    int idx[HJ_BAND_DMAX], rc = 0;
    for (int64_t l = 0; l < nl && !rc; l++) {
        int64_t r = l;
        for (int k = d - 2; k >= 0; k--) { idx[k] = (int)(r % n); r /= n; }
        /* rho^2 of this line and of its face neighbour lines */
        double q[2 * HJ_BAND_DMAX + 1];
        int nq = 0;
        q[nq++] = rho2_of(f, idx);
        for (int k = 0; k < d - 1; k++)
            for (int s = -1; s <= 1; s += 2) {
                if (idx[k] + s < 0 || idx[k] + s >= n) continue;
                idx[k] += s;
                q[nq++] = rho2_of(f, idx);
                idx[k] -= s;
            }
        double qmin = q[0], qmax = q[0];
        for (int i = 1; i < nq; i++) { qmin = q[i] < qmin ? q[i] : qmin; qmax = q[i] > qmax ? q[i] : qmax; }
        /* candidate positions: where the side changes along a line or
         * between this line and a neighbour */
        int any = 0;
        if (f->example == 1) {
            for (int k = 1; k <= NSPHERES; k++) {
                const double r2 = (SPHERE_STEP * k) * (SPHERE_STEP * k);
                if (qmin > r2) continue;
                mark_abs(f, mark, qmax >= r2 ? 0 : sqrt(r2 - qmax), sqrt(r2 - qmin));
                any = 1;
            }
        } else {
            if (qmin <= CYL_R * CYL_R && qmax >= CYL_R * CYL_R) { mark_abs(f, mark, 0, CYL_H); any = 1; }
            if (qmin <= CYL_R * CYL_R) { mark_abs(f, mark, CYL_H, CYL_H); any = 1; }
        }
        if (!any) continue;
        for (int i = 0; i < n && !rc; i++) {
            if (!mark[i]) continue;
            mark[i] = 0;
            idx[d - 1] = i;
            const int s0 = p3_front_side(f, idx);
            int border = 0;
            for (int k = 0; k < d && !border; k++)
                for (int s = -1; s <= 1 && !border; s += 2) {
                    if (idx[k] + s < 0 || idx[k] + s >= n) continue;
                    idx[k] += s;
                    border = p3_front_side(f, idx) != s0;
                    idx[k] -= s;
                }
            if (border) rc = fn(idx, s0, ctx);
        }
        memset(mark, 0, (size_t)n);
    }
    free(mark);
    return rc;
}
