/* p2_acoustic.h -- the acoustic capture game (toolbox section 2.6.2,
 * acoustic) set up on the level set kernel, so that any program can run
 * the computation of acoustic.c at a given accuracy and dx.
 *
 * Relative coordinates z = (x, y), pursuer at the origin:
 *   dz/dt = W_p (0, -1) + (W_p / R) (y, -x) b + 2 W_e min(|z|, S) a   (24),
 * |a| <= 1 (evader, a vector: avoids), |b| <= 1 (pursuer: captures).
 * Backward reachable set of the target [-3.5, 3.5] x [-0.2, 0] written as
 * the toolbox does: termLaxFriedrichs with hamFunc = -H,
 *   H(z, p) = -p2 W_p - (W_p / R) |p1 y - p2 x| + |p| 2 W_e min(|z|, S),
 * partialFunc alpha_1 = (W_p / R) |y| + 2 W_e min(|z|, S), alpha_2 = W_p
 * + (W_p / R) |x| + 2 W_e min(|z|, S) (section 2.6.2), inside
 * termRestrictUpdate (positive = 0: the set never shrinks).
 *
 * The callbacks and the target take x = (i - (N - 1)/2) dx, exactly
 * antisymmetric under i -> N - 1 - i on the grid below (symmetric about
 * x = 0), so that rounding of the coordinates cannot break the game's
 * mirror symmetry x -> -x.  Nothing here prints or exits.
 */
#ifndef P2_ACOUSTIC_H
#define P2_ACOUSTIC_H

#include "hj_error.h"
#include "hj_ls_grid.h"
#include "hj_ls_ode.h"

typedef struct {
    double We, Wp, R, S;
    int cfl_rule; /* HJ_LS_CFL_NODE (ours) or HJ_LS_CFL_TOOLBOX */
    int weno_eps; /* HJ_LS_WENO_EPS_LOCAL (ours) or HJ_LS_WENO_EPS_GRID */
} p2_acoustic_par;

/* W_e = 1.3, W_p = 1.5, R = 0.8, S = 0.5 (section 2.6.2; the released
 * acoustic.m has W_p = 1.0), our CFL rule and WENO5 epsilon. */
void p2_acoustic_defaults(p2_acoustic_par *p);

/* The grid of acoustic.m for spacing dx: [-4, 4] x [-2, 3] (hj_ls_grid_init_dx),
 * extrapolation boundaries; dx = 1/25 gives 201 x 126 nodes. */
int p2_acoustic_grid(double dx, hj_ls_grid *g, hj_error *err);

/* Fill phi with the target [-3.5, 3.5] x [-0.2, 0]: the max of the four
 * half-plane distances (as hj_ls_shape_rectangle_corners) at the
 * mirror-exact x. */
int p2_acoustic_target(const hj_ls_grid *g, double *phi, hj_error *err);

/* Integrate phi (the target on entry) from ts[0] through ts[1..nt-1]
 * (HJ_LS_FACTOR_CFL_REACH, 0.75 as acoustic.m) at the given accuracy
 * (HJ_LS_ACC_*) and dissipation (HJ_LS_GLF ...); out/out_ctx as hj_ls_ode. */
int p2_acoustic_solve(const hj_ls_grid *g, const p2_acoustic_par *p, int acc, int diss, const double *ts, int nt,
                      double *phi, hj_ls_output_fn out, void *out_ctx, hj_ls_ode_stats *stats, hj_error *err);

/* max |phi(x, y) - phi(-x, y)| over the nodes (the game is symmetric
 * under x -> -x, a_x -> -a_x, b -> -b, and so is the target); *flips
 * (may be NULL) receives the number of nodes whose membership of
 * {phi < 0} differs from their mirror node's. */
double p2_acoustic_asymmetry(const hj_ls_grid *g, const double *phi, long *flips);

#endif
