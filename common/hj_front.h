/* hj_front.h -- the errors of a computed front against the exact one, as
 * section 4 of Bokanowski, Cristiani & Zidani 2010 measures them (Tables
 * 6-13): the L1 error of the computed set and the Hausdorff distance
 * between the computed and the exact fronts.
 *
 * The computed set is {V <= 0} on a grid of n cells per direction with
 * centres lo + i dx (d = 2..4); the exact set is given by its indicator
 * inside(x).
 *   l1   = prod dx * #{ I : sign(V_I) != sign(phi(xi_I)) }, sign(0) = -1,
 *          V_I within 1e-12 of 0 counting as 0 (half-cut cells)
 *   haus = Hausdorff distance between the computed front, the centres of
 *          the boundary cells of {V <= 0} (V <= 0 with a face neighbour
 *          V > 0), and the exact front: the points where it crosses the
 *          segments joining neighbouring cell centres (bisection on inside,
 *          to 1e-6 dx); with sub = m > 1, where it crosses the m^(d-1)
 *          parallel segments shifted by (s / m - 1/2) dx (s = 0 .. m - 1)
 *          in the other directions, i.e. the lattice lines refined m times,
 *          in the strip of cells around each crossing.  The exact front's
 *          points farthest from the cell centres lie between the centre
 *          lines, so m = 1 underestimates the distance (a straight front
 *          half a cell from the centres: 0.5 dx against sqrt(0.5) dx with m
 *          even).
 * The values come from a full grid (hj_front_grid_errors, hj_front_ls_errors)
 * or from the band of a +-1 front held in an hj_band store
 * (hj_front_band_errors), whose unstored cells are recovered line by line
 * without a full array.
 *
 * Library code: returns HJ_* codes, never prints.
 */
#ifndef HJ_FRONT_H
#define HJ_FRONT_H

#include <stddef.h>
#include <stdint.h>

#include "hj_band.h"
#include "hj_error.h"
#include "hj_ls_grid.h"

#ifdef __cplusplus
extern "C" {
#endif

/* 1 when x is in the exact set. */
typedef int (*hj_front_inside_fn)(const double *x, void *ctx);
/* V at cell idx. */
typedef double (*hj_front_value_fn)(const int *idx, void *ctx);

/* The errors for values on the full grid of n^d cell centres lo + i dx:
 * value(idx) is V at cell idx.  *ncells (may be NULL) receives
 * #{V <= 0}; an empty computed set gives haus = +inf. */
int hj_front_grid_errors(int d, int n, const double *lo, const double *dx, hj_front_value_fn value, void *vctx,
                         hj_front_inside_fn inside, void *ctx, int sub, double *l1, double *haus, int64_t *ncells,
                         hj_error *err);

/* The same for a level set function y on an hj_ls grid with n nodes in
 * every direction (the nodes are the cell centres). */
int hj_front_ls_errors(const hj_ls_grid *g, const double *y, hj_front_inside_fn inside, void *ctx, int sub,
                       double *l1, double *haus, int64_t *ncells, hj_error *err);

/* The errors for the band of a +-1 front in store s (values in [-1, 1],
 * the band rule of hj_ub.h: a node that is not stored has the value of its
 * stored neighbours, a line without stored nodes its neighbour line's),
 * cell centres lo + i dx.  The computed front is taken from the stored
 * cells and their stored face neighbours. */
int hj_front_band_errors(hj_band *s, const double *lo, const double *dx, int sub, hj_front_inside_fn inside,
                         void *ctx, double *l1, double *haus, hj_error *err);

/* The value of every cell of that band, recovered as the errors do:
 * out[l n + i] for line l (the first d - 1 indices, lexicographic) and
 * last index i; n^d doubles. */
int hj_front_band_values(hj_band *s, double *out, hj_error *err);

/* Hausdorff distance between two finite point sets in R^d (rows of d
 * doubles); h is a typical spacing used to bucket the points.  +inf when
 * exactly one set is empty, 0 when both are. */
int hj_front_hausdorff(int d, const double *a, size_t na, const double *b, size_t nb, double h, double *out,
                       hj_error *err);

#ifdef __cplusplus
}
#endif

#endif
