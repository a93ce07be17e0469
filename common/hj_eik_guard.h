/* hj_eik_guard.h -- is an Eikonal solution plausible?
 *
 * The stopping rule of hj_eik_solve is relative to max |T|, a scale that
 * grows with the iterate itself: an iteration that blows up (|T| ~ 1e151
 * at a grid corner, seen with orders 3 and 5 on noisy speed maps before
 * their safeguards) makes its changes look small against that scale and
 * stops as "converged".  hj_eik_solve therefore checks its result with
 * this function and reports a failure instead of HJ_OK.
 *
 * A solution of |grad T| = f with f > 0 is never earlier than the earliest
 * start (source times t0 and held values), and is finite wherever a front
 * reaches.  The check is one pass over T; no allocation.
 */
#ifndef HJ_EIK_GUARD_H
#define HJ_EIK_GUARD_H

#include <stddef.h>

#include "hj_error.h"

#ifdef __cplusplus
extern "C" {
#endif

/* T: n0 x n1 x n2 values (x fastest); reached: per node 1 where a front
 * arrives (so T must be finite there), 0 elsewhere (obstacles, nodes
 * walled off from every source: +INFINITY is right there); NULL: every
 * node whose T is not +INFINITY.  t_min: the earliest source time or held
 * value; scale: a magnitude of T that the iteration cannot inflate (the
 * first order solution's max |T|).  A value below t_min - HJ_EIK_GUARD_TOL
 * (|t_min| + scale), NaN, -INFINITY or a non-finite value at a reached
 * node gives HJ_ENOCONV, with a message naming the first such node;
 * otherwise HJ_OK. */
#define HJ_EIK_GUARD_TOL 1e-9

int hj_eik_guard(const double *T, const unsigned char *reached, const long n[3], double t_min, double scale,
                 hj_error *err);

#ifdef __cplusplus
}
#endif

#endif
