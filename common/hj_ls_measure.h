/* hj_ls_measure.h -- the measure (length, area, volume) of the set
 * {phi < 0} of a level set function on a grid of dimension 1, 2 or 3: the
 * areas and volumes that check the examples of Mitchell's toolbox (section
 * 2: convectionDemo's area loss, curvature motion's 2 pi b t, the
 * reachable sets of sections 2.5-2.6); not a toolbox routine itself.
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
 * beyond the outer nodes).  The cell fractions are summed exactly
 * (hj_sum) and rounded once, so the result does not depend on the number
 * of threads, nor, over MPI (hj_mpi_measure), on the number of processes.
 */
#ifndef HJ_LS_MEASURE_H
#define HJ_LS_MEASURE_H

#include "hj_error.h"
#include "hj_ls_grid.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Fraction of the d-simplex (d = 1, 2, 3) with vertex values v[0..d] on
 * which the linear interpolant is negative.  Values beyond +-1e60 (+-inf
 * included) count as +-1e60, so that an infinite vertex gives the limit
 * (the interface at the finite vertex, or half way between -inf and
 * +inf).  NaN vertices count as positive: the measures below check them. */
double hj_ls_simplex_fraction(int d, const double *v);

/* The fractions (in [0, 1]) of {phi < 0} in the cells whose lowest
 * corner i has 0 <= i[d] < ncell[d] <= N[d], added exactly to s.  A cell
 * at i[d] = N[d] - 1 takes its upper corner from the ghost at N[d], which
 * must then hold the neighbouring value (a periodic image, or a
 * neighbouring block's node).  HJ_EINVAL for a dimension above 3 or an
 * ncell out of range; HJ_ENONFINITE, naming the node, for a NaN at a node
 * the cells read (s is then left as it was).  -inf and +inf count as
 * negative and positive. */
int hj_ls_measure_add(const hj_ls_grid *g, const double *phi, const long *ncell, hj_sum *s, hj_error *err);

/* Measure of {phi < 0} over the grid's box; *m receives it.  HJ_EINVAL
 * for a grid of dimension above 3, HJ_ENONFINITE naming the first node
 * where phi is NaN. */
int hj_ls_measure(const hj_ls_grid *g, const double *phi, double *m, hj_error *err);

/* The same on a grid periodic in dimension periodic_dim (>= 0; < 0 is
 * hj_ls_measure): the cells between the last node and the first node's
 * periodic image count too, so the box is a full period, N dx (the grids
 * of the toolbox's periodic examples, e.g. air3D's heading, section
 * 2.6.1).  Needs a copy of phi with one more plane (allocated here). */
int hj_ls_measure_periodic(const hj_ls_grid *g, const double *phi, int periodic_dim, double *m, hj_error *err);

/* Radius of the disc (2-D) or ball (3-D) whose area or volume is the
 * measure of {phi < 0}: the size of a circle or sphere under normal or
 * curvature motion (sections 2.3.1-2.3.2).  HJ_EINVAL for other
 * dimensions. */
int hj_ls_measure_radius(const hj_ls_grid *g, const double *phi, double *r, hj_error *err);

#ifdef __cplusplus
}
#endif

#endif
