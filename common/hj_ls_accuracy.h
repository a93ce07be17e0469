/* hj_ls_accuracy.h -- the accuracy levels of Mitchell's toolbox (section
 * 2.1, the `accuracy` argument of convectionDemo and of every later
 * example) and the CFL factors its examples integrate with.
 *
 * A level names a pair of a spatial upwind scheme (section 3.3.1, Table 2)
 * and an order of the TVD Runge-Kutta integrator (section 3.5, odeCFLn):
 *
 *   level     scheme                          order
 *   low       upwindFirstFirst  (HJ_LS_UPWIND_FIRST)  1
 *   medium    upwindFirstENO2   (HJ_LS_ENO2)          2
 *   high      upwindFirstENO3   (HJ_LS_ENO3A)         3
 *   veryHigh  upwindFirstWENO5  (HJ_LS_WENO5A)        3
 *
 * Nothing here prints or exits.
 */
#ifndef HJ_LS_ACCURACY_H
#define HJ_LS_ACCURACY_H

#include "hj_error.h"

#ifdef __cplusplus
extern "C" {
#endif

enum { HJ_LS_ACC_LOW, HJ_LS_ACC_MEDIUM, HJ_LS_ACC_HIGH, HJ_LS_ACC_VERYHIGH, HJ_LS_NACC };

/* FactorCFL of the toolbox's examples (odeCFLset): 0.5 in most of them
 * (section 2.1, also hj_ls_ode_defaults), 0.75 in the reachability
 * examples of section 2.6 (air3D, acoustic, airMode), 0.9 in
 * curvatureStarDemo (section 2.3.1). */
#define HJ_LS_FACTOR_CFL 0.5
#define HJ_LS_FACTOR_CFL_REACH 0.75
#define HJ_LS_FACTOR_CFL_CURVATURE 0.9

/* "low", "medium", "high", "veryHigh"; "?" for a level out of range. */
const char *hj_ls_accuracy_name(int acc);

/* The level's upwind scheme (HJ_LS_* of hj_ls_deriv.h) and Runge-Kutta
 * order; acc must be a level (0 .. HJ_LS_NACC - 1). */
int hj_ls_accuracy_scheme(int acc);
int hj_ls_accuracy_order(int acc);

/* *acc = the level named s; HJ_EINVAL naming the choices otherwise. */
int hj_ls_accuracy_parse(const char *s, int *acc, hj_error *err);

#ifdef __cplusplus
}
#endif

#endif
