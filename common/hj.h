/* hj.h -- libhj, Hamilton-Jacobi numerics: one include for the whole library.
 *
 *   #include <hj/hj.h>
 *   cc prog.c $(pkg-config --cflags --libs hj)
 *
 * Every function that can fail returns an HJ_* code (hj_error.h) and fills
 * in an hj_error message; library code never prints or exits.  The API
 * guide (docs/API.md) lists the modules and maps each paper's equations,
 * algorithms and tables to the functions that implement them.
 */
#ifndef HJ_H
#define HJ_H

#define HJ_VERSION_STRING "0.1.0"

/* Foundations */
#include "hj_error.h"
#include "hj_math.h"
#include "hj_sys.h"
#include "hj_io.h"
#include "hj_cli.h"
#include "hj_sum.h"

/* Fast sweeping for the Eikonal equation: paper 1's solver, the general
 * solver (hj_eik: 2-D/3-D, orders 1/3/5, factored point sources), speed
 * maps read from files, inflow curves */
#include "hj_fsm.h"
#include "hj_eik.h"
#include "hj_eik_guard.h"
#include "hj_map.h"
#include "hj_vol.h"
#include "hj_curve.h"

/* The level set kernel (paper 2) */
#include "hj_ls_grid.h"
#include "hj_ls_deriv.h"
#include "hj_ls_term.h"
#include "hj_ls_ode.h"
#include "hj_ls_shape.h"
#include "hj_ls_helper.h"
#include "hj_ls_measure.h"
#include "hj_ls_io.h"
#include "hj_ls_accuracy.h"
#include "hj_ls_seq.h"
#include "hj_ls_front.h"

/* Reachability on the kernel: control-affine dynamics, reach-avoid sets
 * and tubes, time-to-reach, optimal control and trajectories */
#include "hj_reach.h"
#include "hj_ctrl.h"

/* Ultra-Bee on sparse narrow bands (paper 3): the band stores, the UB-HJB
 * scheme, front errors, the minimal time function */
#include "hj_band.h"
#include "hj_ub.h"
#include "hj_ub_dense.h"
#include "hj_front.h"
#include "hj_mintime.h"

/* Convergence orders and published-versus-computed comparison */
#include "hj_fit.h"
#include "hj_compare.h"

#endif
