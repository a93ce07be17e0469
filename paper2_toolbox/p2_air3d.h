/* p2_air3d.h -- the game of two identical vehicles (toolbox section 2.6.1,
 * air3D) set up on the level set kernel, shared by the demo (air3d.c) and
 * its benchmark (bench_air3d.c).
 *
 * Relative coordinates x = (x, y, psi), evader at the origin facing +x:
 *   dx/dt = -va + vb cos psi + a y,  dy/dt = vb sin psi - a x,  dpsi/dt = b - a,
 * |a| <= A (evader, avoids), |b| <= B (pursuer, captures).  Backward
 * reachable set of the target cylinder x^2 + y^2 <= r^2 by
 *   D_t phi + min(0, -H(x, grad phi)) = 0 ... written as the toolbox does:
 * termLaxFriedrichs with hamFunc = -H,
 *   H(x, p) = -va p1 + vb (cos psi p1 + sin psi p2) + A |y p1 - x p2 - p3| - B |p3|,
 * partialFunc alpha_1 = |-va + vb cos psi| + A |y|, alpha_2 = |vb sin psi|
 * + A |x|, alpha_3 = A + B (section 2.6.1), inside termRestrictUpdate
 * (positive = 0: phi never increases, the set never shrinks).
 */
#ifndef P2_AIR3D_H
#define P2_AIR3D_H

#include "hj_error.h"
#include "hj_ls_grid.h"
#include "hj_ls_ode.h"

typedef struct {
    double r, va, vb, A, B;
    int cfl_rule; /* HJ_LS_CFL_NODE (ours) or HJ_LS_CFL_TOOLBOX */
    int weno_eps; /* HJ_LS_WENO_EPS_LOCAL (ours) or HJ_LS_WENO_EPS_GRID */
} p2_air3d_par;

/* r = 5, va = vb = 5, A = B = 1 (section 2.6.1), our CFL rule and WENO5
 * epsilon. */
void p2_air3d_defaults(p2_air3d_par *p);

/* The grid of air3D.m for Nx nodes in x: [-6, 20] x [-10, 10] x [0, 2 pi)
 * with N = (Nx, ceil(Nx 20 / 26), Nx - 1), extrapolation in x and y,
 * periodic in psi. */
int p2_air3d_grid(long Nx, hj_ls_grid *g, hj_error *err);

/* Fill phi with the target cylinder of radius r (signed distance in x, y,
 * with y exactly antisymmetric about the grid centre). */
int p2_air3d_target(const hj_ls_grid *g, const p2_air3d_par *p, double *phi, hj_error *err);

/* Integrate phi (the target on entry) from 0 through ts[1..nt-1]
 * (HJ_LS_FACTOR_CFL_REACH, 0.75 as air3D.m) at the given accuracy (HJ_LS_ACC_*) and
 * dissipation (HJ_LS_GLF ...); out/out_ctx as hj_ls_ode. */
int p2_air3d_solve(const hj_ls_grid *g, const p2_air3d_par *p, int acc, int diss, const double *ts, int nt,
                   double *phi, hj_ls_output_fn out, void *out_ctx, hj_ls_ode_stats *stats, hj_error *err);

/* The same on a block g of the global grid (hj_mpi.h: g->origin is the
 * global index of the block's first node); g = global for the whole. */
int p2_air3d_target_block(const hj_ls_grid *global, const hj_ls_grid *g, const p2_air3d_par *p, double *phi,
                          hj_error *err);
int p2_air3d_solve_block(const hj_ls_grid *global, const hj_ls_grid *g, const p2_air3d_par *p, int acc, int diss,
                         const double *ts, int nt, double *phi, hj_ls_output_fn out, void *out_ctx,
                         hj_ls_ode_stats *stats, hj_error *err);

/* max |phi(x, y, psi) - phi(x, -y, -psi)| over the nodes (0 for an exactly
 * symmetric result: the game is symmetric under y -> -y, psi -> -psi,
 * a -> -a, b -> -b); *flips (may be NULL) receives the number of nodes
 * whose membership of {phi < 0} differs from their mirror image's. */
double p2_air3d_asymmetry(const hj_ls_grid *g, const double *phi, long *flips);

#endif
