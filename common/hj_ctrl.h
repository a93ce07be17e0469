/* hj_ctrl.h -- optimal control from a value function on a grid, and
 * closed-loop trajectories of control-affine systems (hj_reach.h).
 *
 * The value phi (an array on the grid, e.g. a BRT from hj_reach_solve or
 * its time-to-reach) is interpolated multilinearly; periodic dimensions
 * wrap, others clamp to the grid's box.  Its gradient at a state x is the
 * central difference of the interpolant with step dx_d in each dimension
 * (the interpolant is only piecewise linear: one cell's width averages
 * its kinks).  A time-to-reach is INFINITY where nothing arrives (and
 * inside an obstacle): in a cell with such nodes the gradient differences
 * the interpolant of the cell's other nodes (hj_ctrl_value stays
 * INFINITY there), so a time-optimal path along an obstacle keeps its
 * control; where one side has no finite node it is the one-sided
 * difference on the finite side, and NaN where neither side has one.
 * The optimal inputs are the arguments of the players' optima in the
 * Hamiltonian for that gradient (hj_reach_dyn_optimal);
 * hj_ctrl_optimal gives NaN inputs for a gradient that is not finite.
 *
 * Simulation: classical RK4 with the control (and disturbance) held over
 * each step of length dt, both recomputed from the value at the start of
 * the step (a sampled-data feedback, as a controller would run it); the
 * value at the state is recorded at every step.  The run stops when the
 * target (if given) holds a state (target <= 0), or at t_max.  Touching
 * the obstacle (obstacle <= 0 at a step's end) is recorded, not stopped;
 * so is leaving the grid's box (t_left).  An initial state outside the
 * box (a non-periodic dimension) is refused: the value is not known
 * there (before, the run went on from the clamped edge's values).
 */
#ifndef HJ_CTRL_H
#define HJ_CTRL_H

#include "hj_error.h"
#include "hj_ls_grid.h"
#include "hj_reach.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The interpolated value and gradient of phi at x. */
double hj_ctrl_value(const hj_ls_grid *g, const double *phi, const double *x);
void hj_ctrl_gradient(const hj_ls_grid *g, const double *phi, const double *x, double *p);

/* The optimal control u and disturbance d (either may be NULL) at forward
 * time t and state x for the value phi. */
void hj_ctrl_optimal(const hj_reach_dyn *s, const hj_ls_grid *g, const double *phi, double t, const double *x,
                     double *u, double *d);

/* The disturbance in a simulation. */
enum { HJ_CTRL_D_ZERO, HJ_CTRL_D_OPTIMAL, HJ_CTRL_D_FN };
typedef void (*hj_ctrl_input_fn)(double t, const double *x, double *d, void *ctx);

typedef struct {
    double dt;          /* step, > 0 */
    double t_max;       /* the run's length, > 0 */
    int disturbance;    /* HJ_CTRL_D_* (default zero) */
    hj_ctrl_input_fn d_fn;
    void *d_ctx;
    hj_reach_set target;   /* stop when target(t, x) <= 0 (optional) */
    hj_reach_set obstacle; /* record obstacle(t, x) <= 0 (optional) */
} hj_ctrl_sim_opts;

/* A trajectory: up to cap + 1 points (cap steps). */
typedef struct {
    int nx, nu, nd;
    long cap;
    long n;        /* points stored, >= 1 */
    double *t;     /* n times */
    double *x;     /* n x nx states, row major */
    double *u;     /* n x nu controls applied from each point (last: 0) */
    double *value; /* n values phi(x) */
    int reached;   /* the target held the last point */
    int collided;  /* the obstacle held some point */
    double min_obstacle; /* the least obstacle value met (INFINITY: none) */
    double t_left; /* the first time a point lay outside the grid's box in
                    * a non-periodic dimension (INFINITY: never); from there
                    * on the value and control come from the box's edge
                    * (the interpolant is clamped), not from the problem */
} hj_ctrl_traj;

/* Arrays for cap steps; HJ_ENOMEM.  Free with hj_ctrl_traj_free. */
int hj_ctrl_traj_alloc(hj_ctrl_traj *tr, int nx, int nu, int nd, long cap, hj_error *err);
void hj_ctrl_traj_free(hj_ctrl_traj *tr);

void hj_ctrl_sim_defaults(hj_ctrl_sim_opts *o);

/* Simulate from x0 at t = 0 under the optimal control of phi; tr must have
 * room for ceil(t_max / dt) steps (HJ_EINVAL otherwise); x0 must lie in
 * the grid's box (HJ_EINVAL otherwise, naming the coordinate).  The target and
 * obstacle are given as functions (fn): a trajectory leaves the nodes, so
 * an array alone is refused.  HJ_ENONFINITE if the state leaves the
 * finite numbers, or if the value has no finite gradient at a state (no
 * finite value around it: e.g. outside the reached set of a
 * time-to-reach); tr then holds the run up to that state. */
int hj_ctrl_simulate(const hj_reach_dyn *s, const hj_ls_grid *g, const double *phi, const double *x0,
                     const hj_ctrl_sim_opts *o, hj_ctrl_traj *tr, hj_error *err);

#ifdef __cplusplus
}
#endif

#endif
