/* p2_reach.h -- the log of a reachable set computation (sections 2.5 and
 * 2.6 of the toolbox: air3d, acoustic, air_mode): at the initial time and
 * at every output time of hj_ls_ode, the measure of {phi < 0} (periodic in
 * one dimension if asked, hj_ls_measure_periodic) and the number of nodes
 * at which phi increased since the previous output (0 for a set that only
 * grows, termRestrictUpdate).  Nothing here prints or exits.
 */
#ifndef P2_REACH_H
#define P2_REACH_H

#include "hj_error.h"
#include "hj_ls_grid.h"
#include "hj_ls_ode.h"
#include "hj_ls_term.h"

/* Pass p2_reach_output as hj_ls_ode's output callback with the log as
 * context; it calls user(k, t, y, user_ctx, err) too when set (to write
 * blocks). */
#define P2_MAXT 64
typedef struct {
    const hj_ls_grid *g;
    int periodic_dim;
    double *prev;
    int n;
    double t[P2_MAXT], measure[P2_MAXT];
    long increased[P2_MAXT];
    hj_ls_output_fn user;
    void *user_ctx;
} p2_reach_log;
int p2_reach_log_init(p2_reach_log *log, const hj_ls_grid *g, int periodic_dim, double t0, const double *y0,
                      hj_ls_output_fn user, void *user_ctx, hj_error *err);
int p2_reach_output(int k, double t, const double *y, void *ctx, hj_error *err);
void p2_reach_log_free(p2_reach_log *log);

/* Integrate phi (the target on entry) from ts[0] through ts[1 .. nt - 1]
 * with the TVD RK scheme of the given order by term inside
 * termRestrictUpdate (the set only grows), at the CFL factor of air3D.m
 * and acoustic.m (HJ_LS_FACTOR_CFL_REACH); arguments as hj_ls_ode. */
int p2_reach_solve(int order, const hj_ls_grid *g, const hj_ls_term *term, const double *ts, int nt, double *phi,
                   hj_ls_output_fn out, void *out_ctx, hj_ls_ode_stats *stats, hj_error *err);

#endif
