/* hj_ls_helper.h -- helper routines of the level set kernel (Mitchell's
 * toolbox, section 3.7): masking after each time step, signed distance by
 * iterated reinitialization, unsigned distance from a point cloud.
 */
#ifndef HJ_LS_HELPER_H
#define HJ_LS_HELPER_H

#include "hj_error.h"
#include "hj_ls_deriv.h"
#include "hj_ls_grid.h"

#ifdef __cplusplus
extern "C" {
#endif

/* postTimestepMask: pass hj_ls_post_mask as the integrator's PostTimestep
 * with a pointer to this struct; after every step
 *     y = max(y, mask)  (keep_max, the constraint phi >= psi), or
 *     y = min(y, mask)  (phi <= psi).
 * A NaN in the mask is HJ_ENONFINITE naming the node (the rows before it
 * are masked already); a NULL context, grid or mask is HJ_EINVAL.  The
 * mask must be an array on the integrator's grid. */
typedef struct {
    const hj_ls_grid *grid;
    const double *mask;
    int keep_max;
} hj_ls_mask;
int hj_ls_post_mask(double t, double *y, void *ctx, hj_error *err);

/* signedDistanceIterative: solve the reinitialization PDE from data (an
 * implicit surface function, replaced by the result) with the given upwind
 * scheme and RK order, one CFL step at a time, until time t_max (<= 0: the
 * diagonal of the domain, enough for the front to cross the grid) or until
 * the average absolute update of a step drops below error_max * max dx
 * (<= 0: the toolbox's default 1e-3).  *steps (may be NULL) receives the
 * number of steps and *converged (may be NULL) whether the update rule
 * stopped the iteration.  A NULL grid or data, or a NaN or infinite t_max
 * or error_max, is HJ_EINVAL before any step. */
int hj_ls_signed_distance(const hj_ls_grid *g, double *data, double t_max, double error_max, int scheme, int order,
                          long *steps, int *converged, hj_error *err);

/* unsignedDistanceFromPoints: out = distance from every node to the
 * nearest of npoints points (row-major, g->dim coordinates each), by a k-d
 * tree: O(P log P) to build and about O(log P) per node, instead of the
 * toolbox's brute force O(P) per node.  Exact (the tree is searched with
 * exact pruning).  npoints >= 1; a NULL grid, point list or out is
 * HJ_EINVAL. */
int hj_ls_unsigned_distance(const hj_ls_grid *g, const double *points, long npoints, double *out, hj_error *err);

/* The brute force method, for testing. */
int hj_ls_unsigned_distance_brute(const hj_ls_grid *g, const double *points, long npoints, double *out, hj_error *err);

#ifdef __cplusplus
}
#endif

#endif
