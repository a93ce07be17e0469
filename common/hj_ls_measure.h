/* hj_ls_measure.h -- the measure (length, area, volume) of the set
 * {phi < 0} of a level set function on a grid of dimension 1, 2 or 3.
 *
 * phi is interpolated linearly on the Kuhn simplices of every grid cell
 * (a cell of 2^d nodes is cut into d! simplices along its main diagonal),
 * and the measure of {phi < 0} in each simplex is computed exactly for
 * that linear interpolant.  The result is second order accurate in dx for
 * a smooth interface, whatever the slope of phi (node counting is only
 * first order and depends on |grad phi|), and it is exact for a set whose
 * boundary is piecewise linear on the simplices (a half-space, say).
 *
 * Only the interior cells count: the domain is [min, max] (no half cells
 * beyond the outer nodes).  Sums are taken row by row and added in row
 * order, so the result does not depend on the number of threads.
 */
#ifndef HJ_LS_MEASURE_H
#define HJ_LS_MEASURE_H

#include "hj_error.h"
#include "hj_ls_grid.h"

/* Fraction of the d-simplex (d = 1, 2, 3) with vertex values v[0..d] on
 * which the linear interpolant is negative. */
double hj_ls_simplex_fraction(int d, const double *v);

/* Measure of {phi < 0} over the grid's box; *m receives it.  HJ_EINVAL
 * for a grid of dimension above 3. */
int hj_ls_measure(const hj_ls_grid *g, const double *phi, double *m, hj_error *err);

#endif
