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

#endif
