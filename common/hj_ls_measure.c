/* hj_ls_measure.c -- measure of {phi < 0}; see hj_ls_measure.h. */
#include "hj_ls_measure.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hj_math.h"

/* t_ax = a / (a - x): the fraction of the edge from a (< 0) to x (>= 0) on
 * which the interpolant is negative. */
static double edge_t(double a, double x) { return a / (a - x); }

/* h(x) = x^3 / ((x - c)(x - d)) and its derivative, for the 2-2 split of a
 * tetrahedron (see below). */
static double h22(double x, double c, double d) { return x * x * x / ((x - c) * (x - d)); }
static double h22_prime(double x, double c, double d)
{
    const double p = (x - c) * (x - d);
    return (3 * x * x * p - x * x * x * (2 * x - c - d)) / (p * p);
}

/* Vertex values beyond +-MEASURE_BIG count as +-MEASURE_BIG: an infinite
 * value (a level set set to +-inf far from the front) then gives the
 * limit of the finite formulas (the interface at the finite vertex; half
 * way on an edge from -inf to +inf) instead of inf / inf, and the cubes
 * of the tetrahedron's 2-2 split and the square of its derivative's
 * denominator stay finite ((2e60)^4 = 1.6e241). */
#define MEASURE_BIG 1e60

double hj_ls_simplex_fraction(int d, const double *vin)
{
    double v[4];
    for (int k = 0; k <= d && k < 4; k++)
        v[k] = vin[k] > MEASURE_BIG ? MEASURE_BIG : vin[k] < -MEASURE_BIG ? -MEASURE_BIG : vin[k];
    int neg[4], pos[4], nn = 0, np = 0;
    for (int k = 0; k <= d; k++) {
        if (v[k] < 0) neg[nn++] = k;
        else pos[np++] = k;
    }
    if (nn == 0) return 0.0;
    if (np == 0) return 1.0;
    if (d == 1) return edge_t(v[neg[0]], v[pos[0]]);
    /* One vertex alone on its side: the corner simplex it cuts off has
     * the product of the edge fractions as its share. */
    if (nn == 1 || np == 1) {
        const int lone = nn == 1 ? neg[0] : pos[0];
        const double a = nn == 1 ? v[lone] : -v[lone];
        double f = 1;
        for (int k = 0; k <= d; k++)
            if (k != lone) f *= edge_t(a, nn == 1 ? v[k] : -v[k]);
        return nn == 1 ? f : 1 - f;
    }
    /* Tetrahedron, two vertices on each side.  With g = -v (positive at
     * the negative vertices a, b), the fraction where g > 0 is
     *   sum_{i in {a,b}} g_i^3 / prod_{j != i} (g_i - g_j)
     * = (h(g_a) - h(g_b)) / (g_a - g_b),  h(x) = x^3 / ((x - g_c)(x - g_d)),
     * a divided difference; when g_a and g_b nearly coincide, h' at their
     * midpoint replaces it (error O((g_a - g_b)^2)). */
    const double ga = -v[neg[0]], gb = -v[neg[1]], gc = -v[pos[0]], gd = -v[pos[1]];
    if (fabs(ga - gb) > 1e-4 * fmax(ga, gb)) return (h22(ga, gc, gd) - h22(gb, gc, gd)) / (ga - gb);
    return h22_prime(0.5 * (ga + gb), gc, gd);
}

/* Sum of the simplex fractions of the cell whose lowest corner is node
 * index base (offset into phi), times 1/d!: the cell's fraction. */
static double cell_fraction(const hj_ls_grid *g, const double *phi, size_t base)
{
    const int d = g->dim;
    if (d == 1) {
        const double v[2] = {phi[base], phi[base + 1]};
        return hj_ls_simplex_fraction(1, v);
    }
    /* Kuhn simplices: for each permutation p of the axes, the path
     * 0 -> e_p0 -> e_p0 + e_p1 -> ... -> (1, ..., 1). */
    static const int perm2[2][2] = {{0, 1}, {1, 0}};
    static const int perm3[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    const int np = d == 2 ? 2 : 6;
    double sum = 0;
    for (int p = 0; p < np; p++) {
        double v[4];
        size_t k = base;
        v[0] = phi[k];
        for (int s = 0; s < d; s++) {
            k += (size_t)g->stride[d == 2 ? perm2[p][s] : perm3[p][s]];
            v[s + 1] = phi[k];
        }
        sum += hj_ls_simplex_fraction(d, v);
    }
    return sum / np;
}

/* The first NaN among the nodes a row's cells read (the row and its upper
 * neighbours in dimensions 1..d-1, nodes 0..n0 along dimension 0): its
 * offset in phi, or SIZE_MAX.  A NaN vertex would count as positive and
 * leave a finite, wrong measure, or make it NaN. */
static size_t row_nan(const hj_ls_grid *g, const double *phi, size_t k0, long n0)
{
    size_t first = SIZE_MAX;
    for (unsigned c = 0; c < 1u << (g->dim - 1); c++) {
        size_t k = k0;
        for (int e = 1; e < g->dim; e++)
            if (c >> (e - 1) & 1) k += (size_t)g->stride[e];
        int any = 0;
        for (long a = 0; a <= n0; a++) any |= isnan(phi[k + (size_t)a]);
        if (!any) continue;
        for (long a = 0; a <= n0; a++)
            if (isnan(phi[k + (size_t)a]) && k + (size_t)a < first) first = k + (size_t)a;
    }
    return first;
}

/* HJ_ENONFINITE naming the node at offset k of phi (a ghost index when the
 * cells reach into the ghost layer). */
static int nan_error(const hj_ls_grid *g, size_t k, hj_error *err)
{
    long i[HJ_LS_MAXDIM];
    double x[HJ_LS_MAXDIM];
    for (int e = 0; e < g->dim; e++) i[e] = (long)(k / (size_t)g->stride[e] % (size_t)g->ext[e]) - HJ_LS_GHOST;
    hj_ls_coord(g, i, x);
    char pos[256];
    size_t len = 0;
    pos[0] = 0;
    for (int e = 0; e < g->dim && len < sizeof pos; e++) {
        const int w = snprintf(pos + len, sizeof pos - len, "%s%g", e ? ", " : "", x[e]);
        if (w < 0) break;
        len += (size_t)w;
    }
    return hj_error_set(err, HJ_ENONFINITE, "measure: phi is NaN at x = (%s)", pos);
}

int hj_ls_measure_add(const hj_ls_grid *g, const double *phi, const long *ncell, hj_sum *s, hj_error *err)
{
    if (!g || !phi || !ncell || !s)
        return hj_error_set(err, HJ_EINVAL, "measure: the %s is NULL", !g ? "grid" : !phi ? "array phi" : !ncell ? "cell count" : "sum");
    if (g->dim < 1 || g->dim > 3) return hj_error_set(err, HJ_EINVAL, "measure: dimension %d (1 to 3 only)", g->dim);
    for (int e = 0; e < g->dim; e++)
        if (ncell[e] < 0 || ncell[e] > g->N[e])
            return hj_error_set(err, HJ_EINVAL, "measure: %ld cells along dimension %d of %ld nodes", ncell[e], e,
                                g->N[e]);
    for (int e = 0; e < g->dim; e++)
        if (ncell[e] == 0) return HJ_OK; /* no cell, no node read */
    /* Cell rows: the cells along dimension 0 of the interior rows whose
     * other indices are below ncell; one exact accumulator per thread.
     * The first NaN node (lowest offset) is the one reported, whatever
     * the number of threads. */
    size_t nan_at = SIZE_MAX;
    hj_sum total;
    hj_sum_init(&total);
#pragma omp parallel
    {
        hj_sum t;
        hj_sum_init(&t);
        size_t t_nan = SIZE_MAX;
#pragma omp for schedule(static) nowait
        for (size_t r = 0; r < g->rows; r++) {
            long i[HJ_LS_MAXDIM] = {0};
            const size_t k0 = hj_ls_row(g, r, i);
            int out = 0;
            for (int e = 1; e < g->dim; e++) out |= i[e] >= ncell[e];
            if (out) continue;
            const size_t bad = row_nan(g, phi, k0, ncell[0]);
            if (bad != SIZE_MAX) {
                t_nan = bad < t_nan ? bad : t_nan;
                continue;
            }
            for (long a = 0; a < ncell[0]; a++) hj_sum_add(&t, cell_fraction(g, phi, k0 + (size_t)a));
        }
#pragma omp critical(hj_ls_measure_merge)
        {
            hj_sum_merge(&total, &t);
            nan_at = t_nan < nan_at ? t_nan : nan_at;
        }
    }
    if (nan_at != SIZE_MAX) return nan_error(g, nan_at, err);
    hj_sum_merge(s, &total);
    return HJ_OK;
}

int hj_ls_measure(const hj_ls_grid *g, const double *phi, double *m, hj_error *err)
{
    if (!g || !m) return hj_error_set(err, HJ_EINVAL, "measure: the %s is NULL", !g ? "grid" : "result pointer");
    long ncell[HJ_LS_MAXDIM] = {0};
    for (int e = 0; e < g->dim && e < HJ_LS_MAXDIM; e++) ncell[e] = g->N[e] - 1;
    hj_sum s;
    hj_sum_init(&s);
    const int rc = hj_ls_measure_add(g, phi, ncell, &s, err);
    if (rc) return rc;
    double cell = 1;
    for (int e = 0; e < g->dim; e++) cell *= g->dx[e];
    *m = hj_sum_value(&s) * cell;
    return HJ_OK;
}

int hj_ls_measure_periodic(const hj_ls_grid *g, const double *phi, int periodic_dim, double *m, hj_error *err)
{
    if (!g || !phi || !m)
        return hj_error_set(err, HJ_EINVAL, "measure: the %s is NULL", !g ? "grid" : !phi ? "array phi" : "result pointer");
    if (periodic_dim < 0) return hj_ls_measure(g, phi, m, err);
    if (periodic_dim >= g->dim)
        return hj_error_set(err, HJ_EINVAL, "measure: periodic dimension %d of a %d-D grid", periodic_dim, g->dim);
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

int hj_ls_measure_radius(const hj_ls_grid *g, const double *phi, double *r, hj_error *err)
{
    if (!g || !r) return hj_error_set(err, HJ_EINVAL, "radius: the %s is NULL", !g ? "grid" : "result pointer");
    if (g->dim != 2 && g->dim != 3) return hj_error_set(err, HJ_EINVAL, "radius: 2-D or 3-D grids only");
    double m;
    int rc = hj_ls_measure(g, phi, &m, err);
    if (rc) return rc;
    *r = g->dim == 2 ? sqrt(m / HJ_PI) : cbrt(3 * m / (4 * HJ_PI));
    return HJ_OK;
}
