/* p3_front.h -- the fixed fronts of section 3.3 (Examples 1 and 2 of the
 * storage comparison) and their narrow band F+ u F-.
 *
 * Grid: n nodes per direction on [-2, 2]^d, end points included.  A node's
 * side depends only on rho^2 (squared distance to the x_d axis) and x_d:
 *   Example 1: six nested spheres of radii 0.3 k, k = 1..6 (the paper does
 *              not give them; these reproduce its N_nb exactly in d = 2, 3
 *              and within 0.1 % in d = 4), the
 *              inside being the odd layers;
 *   Example 2: the cylinder rho <= 0.5, |x_d| <= 1.6 (longest side along
 *              the last axis, as in the paper; sizes not given either,
 *              these give N_nb within 5 %).
 * F+ (F-) are the outside (inside) nodes with a face neighbour inside
 * (outside).  The band is found line by line from the analytic crossing
 * points, in O(N_nb + N^(d-1)) work, without visiting every node. */
#ifndef P3_FRONT_H
#define P3_FRONT_H

#include <stddef.h>
#include <stdint.h>

#include "hj_band.h"
#include "hj_error.h"

typedef struct {
    int example; /* 1 spheres, 2 cylinder */
    int d, n;
    double dx;
} p3_front;

/* -1 inside, +1 outside, for node idx. */
int p3_front_side(const p3_front *f, const int *idx);

/* Call fn(idx, side, ctx) for every node of F+ u F-, line by line in
 * lexicographic order.  A non-zero return of fn stops and is returned. */
typedef int (*p3_front_fn)(const int *idx, int side, void *ctx);
int p3_front_band(const p3_front *f, p3_front_fn fn, void *ctx, hj_error *err);

#endif
