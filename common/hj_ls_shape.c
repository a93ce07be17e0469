/* hj_ls_shape.c -- basic shapes and set operations. */
#include "hj_ls_shape.h"

#include <math.h>
#include <stdlib.h>

#include "hj_math.h"

/* Parameters of a shape, evaluated node by node through hj_ls_fill. */
typedef struct {
    int dim;
    int use[HJ_LS_MAXDIM];
    const double *c, *lo, *hi, *n; /* center or point, box corners, normal */
    double r, nn;
} shape;

static double cylinder_at(const double *x, void *ctx)
{
    const shape *s = ctx;
    double q = 0;
    for (int d = 0; d < s->dim; d++)
        if (s->use[d]) q += (x[d] - s->c[d]) * (x[d] - s->c[d]);
    return sqrt(q) - s->r;
}

/* Intersection of the two hyperplanes of every dimension; an infinite
 * bound gives -inf, which the maximum ignores. */
static double rectangle_at(const double *x, void *ctx)
{
    const shape *s = ctx;
    double m = -INFINITY;
    for (int d = 0; d < s->dim; d++) {
        const double lo = s->lo[d] - x[d], hi = x[d] - s->hi[d];
        m = lo > m ? lo : m;
        m = hi > m ? hi : m;
    }
    return m;
}

static double hyperplane_at(const double *x, void *ctx)
{
    const shape *s = ctx;
    double q = 0;
    for (int d = 0; d < s->dim; d++) q += s->n[d] * (x[d] - s->c[d]);
    return q / s->nn;
}

/* The first d in [0, n) with x[d] not finite (use[d] nonzero, or every d
 * when use is NULL), or -1: a NaN parameter would otherwise fill the whole
 * array with NaN and return success. */
static int first_nonfinite(const double *x, int n, const int *use)
{
    for (int d = 0; d < n; d++)
        if ((!use || use[d]) && !isfinite(x[d])) return d;
    return -1;
}

/* NULL arguments of a shape: the grid, the output and its vectors. */
static int null_args(const char *what, const hj_ls_grid *g, const double *out, const void *a, const char *aname,
                     const void *b, const char *bname, hj_error *err)
{
    const char *which = !g ? "grid" : !out ? "output array" : !a ? aname : !b ? bname : NULL;
    if (which) return hj_error_set(err, HJ_EINVAL, "%s: the %s is NULL", what, which);
    return HJ_OK;
}

int hj_ls_shape_cylinder(const hj_ls_grid *g, const int *ignore, int nignore, const double *center, double radius,
                         double *out, hj_error *err)
{
    int rc = null_args("sphere", g, out, center, "centre", nignore > 0 ? (const void *)ignore : out, "ignore list", err);
    if (rc) return rc;
    if (!isfinite(radius)) return hj_error_set(err, HJ_ENONFINITE, "sphere radius %g is not finite", radius);
    if (!(radius > 0)) return hj_error_set(err, HJ_EINVAL, "sphere radius must be positive");
    shape s = {.dim = g->dim, .c = center, .r = radius};
    for (int d = 0; d < g->dim; d++) s.use[d] = 1;
    for (int q = 0; q < nignore; q++) {
        if (ignore[q] < 0 || ignore[q] >= g->dim)
            return hj_error_set(err, HJ_EINVAL, "dimension mismatch: cylinder ignores dimension %d of a %d-D grid",
                                ignore[q], g->dim);
        s.use[ignore[q]] = 0;
    }
    /* The centre matters only in the dimensions not ignored. */
    const int bad = first_nonfinite(center, g->dim, s.use);
    if (bad >= 0)
        return hj_error_set(err, HJ_ENONFINITE, "sphere centre %g in dimension %d is not finite", center[bad], bad);
    hj_ls_fill(g, out, cylinder_at, &s);
    return HJ_OK;
}

int hj_ls_shape_sphere(const hj_ls_grid *g, const double *center, double radius, double *out, hj_error *err)
{
    return hj_ls_shape_cylinder(g, NULL, 0, center, radius, out, err);
}

int hj_ls_shape_rectangle_corners(const hj_ls_grid *g, const double *lower, const double *upper, double *out,
                                  hj_error *err)
{
    int rc = null_args("rectangle", g, out, lower, "lower corner", upper, "upper corner", err);
    if (rc) return rc;
    for (int d = 0; d < g->dim; d++)
        if (isnan(lower[d]) || isnan(upper[d]))
            return hj_error_set(err, HJ_ENONFINITE, "rectangle corner is NaN in dimension %d", d);
    for (int d = 0; d < g->dim; d++)
        if (!(lower[d] < upper[d]) || lower[d] == INFINITY || upper[d] == -INFINITY)
            return hj_error_set(err, HJ_EINVAL, "rectangle needs lower < upper in dimension %d", d);
    shape s = {.dim = g->dim, .lo = lower, .hi = upper};
    hj_ls_fill(g, out, rectangle_at, &s);
    return HJ_OK;
}

int hj_ls_shape_rectangle_center(const hj_ls_grid *g, const double *center, const double *widths, double *out,
                                 hj_error *err)
{
    int rc = null_args("rectangle", g, out, center, "centre", widths, "widths", err);
    if (rc) return rc;
    double lo[HJ_LS_MAXDIM], hi[HJ_LS_MAXDIM];
    const int bad = first_nonfinite(center, g->dim, NULL);
    if (bad >= 0)
        return hj_error_set(err, HJ_ENONFINITE, "rectangle centre %g in dimension %d is not finite", center[bad], bad);
    for (int d = 0; d < g->dim; d++) {
        if (isnan(widths[d])) return hj_error_set(err, HJ_ENONFINITE, "rectangle width is NaN in dimension %d", d);
        if (!(widths[d] > 0))
            return hj_error_set(err, HJ_EINVAL, "rectangle width must be positive in dimension %d", d);
        lo[d] = center[d] - 0.5 * widths[d];
        hi[d] = center[d] + 0.5 * widths[d];
    }
    return hj_ls_shape_rectangle_corners(g, lo, hi, out, err);
}

int hj_ls_shape_hyperplane(const hj_ls_grid *g, const double *normal, const double *point, double *out, hj_error *err)
{
    int rc = null_args("hyperplane", g, out, normal, "normal", point, "point", err);
    if (rc) return rc;
    int bad = first_nonfinite(normal, g->dim, NULL);
    if (bad >= 0) return hj_error_set(err, HJ_ENONFINITE, "hyperplane normal is not finite in dimension %d", bad);
    bad = first_nonfinite(point, g->dim, NULL);
    if (bad >= 0) return hj_error_set(err, HJ_ENONFINITE, "hyperplane point is not finite in dimension %d", bad);
    double nn = 0;
    for (int d = 0; d < g->dim; d++) nn += normal[d] * normal[d];
    nn = sqrt(nn);
    if (!(nn > 0) || !isfinite(nn)) return hj_error_set(err, HJ_EINVAL, "hyperplane normal must be nonzero and finite");
    shape s = {.dim = g->dim, .c = point, .n = normal, .nn = nn};
    hj_ls_fill(g, out, hyperplane_at, &s);
    return HJ_OK;
}

/* out = op(a, b) over interior nodes. */
#define SETOP(name, expr)                                                            \
    void name(const hj_ls_grid *g, const double *a, const double *b, double *out)    \
    {                                                                                \
        long idx[HJ_LS_MAXDIM];                                                      \
        for (size_t r = 0; r < g->rows; r++) {                                       \
            const size_t k0 = hj_ls_row(g, r, idx);                                  \
            for (long j = 0; j < g->N[0]; j++) {                                     \
                const double p = a[k0 + (size_t)j], q = b[k0 + (size_t)j];           \
                out[k0 + (size_t)j] = (expr);                                        \
            }                                                                        \
        }                                                                            \
    }

SETOP(hj_ls_shape_union, p < q ? p : q)
SETOP(hj_ls_shape_intersection, p > q ? p : q)
SETOP(hj_ls_shape_difference, p > -q ? p : -q)

void hj_ls_shape_complement(const hj_ls_grid *g, const double *a, double *out)
{
    long idx[HJ_LS_MAXDIM];
    for (size_t r = 0; r < g->rows; r++) {
        const size_t k0 = hj_ls_row(g, r, idx);
        for (long j = 0; j < g->N[0]; j++) out[k0 + (size_t)j] = -a[k0 + (size_t)j];
    }
}

/* phi of the star at x given |x| = r. */
static double star_at(const hj_ls_star *s, double r, const double *x)
{
    return r - s->scale * (cos(s->points * atan2(x[1], x[0])) + s->shift);
}

double hj_ls_star_fn(const double *x, void *ctx) { return star_at(ctx, hypot(x[0], x[1]), x); }

/* |x| as every grid shape here takes it, the root of the sum of squares. */
static double star_grid_at(const double *x, void *ctx) { return star_at(ctx, sqrt(x[0] * x[0] + x[1] * x[1]), x); }

static int star_finite(const hj_ls_star *s)
{
    return isfinite(s->scale) && isfinite(s->shift) && isfinite(s->points);
}

int hj_ls_shape_star(const hj_ls_grid *g, const hj_ls_star *s, double *out, hj_error *err)
{
    int rc = null_args("star", g, out, s, "star", s, "star", err);
    if (rc) return rc;
    if (g->dim != 2) return hj_error_set(err, HJ_EINVAL, "star: 2-D grids only");
    if (!star_finite(s)) return hj_error_set(err, HJ_ENONFINITE, "star: scale, shift and points must be finite");
    hj_ls_fill(g, out, star_grid_at, (void *)s);
    return HJ_OK;
}

double hj_ls_star_area(const hj_ls_star *s) { return HJ_PI * s->scale * s->scale * (0.5 + s->shift * s->shift); }

int hj_ls_shape_curve(const hj_ls_star *star, const double *center, double radius, long n, double **pts, hj_error *err)
{
    if (n < 1) return hj_error_set(err, HJ_EINVAL, "curve samples: %ld points (1 or more)", n);
    if (star && !star_finite(star))
        return hj_error_set(err, HJ_ENONFINITE, "curve samples: star scale, shift and points must be finite");
    if (!star && (first_nonfinite(center, 2, NULL) >= 0 || !isfinite(radius)))
        return hj_error_set(err, HJ_ENONFINITE, "curve samples: circle centre and radius must be finite");
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
