/* hj_ls_shape.h -- implicit surface functions of basic shapes and their
 * constructive solid geometry (Mitchell's toolbox, section 3.3).
 *
 * Shapes are negative inside.  Sphere, cylinder and hyperplane are signed
 * distance functions; rectangles are intersections of axis-aligned
 * hyperplanes (signed distance inside, not in the cones around the corners
 * outside).  Set operations, for implicit surface functions phi_1, phi_2:
 *   union         min(phi_1, phi_2)
 *   intersection  max(phi_1, phi_2)
 *   difference    max(phi_1, -phi_2)   (G_1 minus G_2)
 *   complement    -phi_1
 * All functions write the interior nodes of out, which may alias an input.
 */
#ifndef HJ_LS_SHAPE_H
#define HJ_LS_SHAPE_H

#include "hj_error.h"
#include "hj_ls_grid.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Every shape checks its parameters: a NaN or infinite one where a finite
 * value is required (a centre, a point, a normal, a radius, a star's
 * numbers) is HJ_ENONFINITE, and the array is left untouched. */

/* |x - center| - radius; radius > 0. */
int hj_ls_shape_sphere(const hj_ls_grid *g, const double *center, double radius, double *out, hj_error *err);

/* A sphere in the dimensions not listed in ignore[0..nignore-1] (an
 * unbounded cylinder; nignore = 0 gives the sphere). */
int hj_ls_shape_cylinder(const hj_ls_grid *g, const int *ignore, int nignore, const double *center, double radius,
                         double *out, hj_error *err);

/* Axis-aligned box lower < upper; entries of lower may be -INFINITY and of
 * upper +INFINITY (unbounded sides).  A box unbounded in every dimension
 * is the whole space: -INFINITY everywhere. */
int hj_ls_shape_rectangle_corners(const hj_ls_grid *g, const double *lower, const double *upper, double *out,
                                  hj_error *err);

/* The same by center and full widths (> 0, may be +INFINITY). */
int hj_ls_shape_rectangle_center(const hj_ls_grid *g, const double *center, const double *widths, double *out,
                                 hj_error *err);

/* n . (x - point) / |n|: negative on the side opposite the outward normal. */
int hj_ls_shape_hyperplane(const hj_ls_grid *g, const double *normal, const double *point, double *out, hj_error *err);

void hj_ls_shape_union(const hj_ls_grid *g, const double *a, const double *b, double *out);
void hj_ls_shape_intersection(const hj_ls_grid *g, const double *a, const double *b, double *out);
void hj_ls_shape_difference(const hj_ls_grid *g, const double *a, const double *b, double *out);
void hj_ls_shape_complement(const hj_ls_grid *g, const double *a, double *out);

/* The star of equation (13) (section 2.2.1; reinitDemo, curvatureStarDemo,
 * normalStarDemo, spinStarDemo):
 *     phi(x) = |x| - scale (cos(points theta) + shift),
 * theta the polar angle of (x_1, x_2) (atan2, the toolbox's cart2pol; the
 * printed arctan(x_2 / x_1) changes the shape for odd points).  Not a
 * signed distance function: |grad phi| = sqrt(1 + (r'/r)^2) on the
 * boundary r(theta) = scale (cos(points theta) + shift). */
typedef struct {
    double scale, shift, points;
} hj_ls_star;

/* phi of the star at x (2-D), an hj_ls_field_fn with ctx = hj_ls_star;
 * |x| is hypot(x_1, x_2). */
double hj_ls_star_fn(const double *x, void *ctx);

/* The star on a 2-D grid (HJ_EINVAL for another dimension), with |x| the
 * root of the sum of squares as in the other shapes here (it may differ
 * from hj_ls_star_fn's hypot in the last bit). */
int hj_ls_shape_star(const hj_ls_grid *g, const hj_ls_star *s, double *out, hj_error *err);

/* Area of the star, pi scale^2 (1/2 + shift^2) (shift >= 1: r > 0). */
double hj_ls_star_area(const hj_ls_star *s);

/* n points of the star's boundary at the angles 2 pi k / n, or (star NULL)
 * of the circle of the given centre and radius: *pts (malloc'd, 2 doubles
 * per point, freed by the caller). */
int hj_ls_shape_curve(const hj_ls_star *star, const double *center, double radius, long n, double **pts, hj_error *err);

#ifdef __cplusplus
}
#endif

#endif
