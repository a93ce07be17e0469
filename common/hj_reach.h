/* hj_reach.h -- reachability on the level set kernel: control-affine
 * dynamics as data, and backward reachable sets and tubes (BRS, BRT),
 * reach-avoid problems and time-to-reach functions solved with the
 * kernel's Lax-Friedrichs term (hj_ls_term.h) and TVD Runge-Kutta
 * integrator (hj_ls_ode.h).
 *
 * Dynamics.  dx/dt = f(t, x) + G(t, x) u + H(t, x) d, with u in a box
 * [lo, hi] or a ball |u - c| <= r of R^nu, and d likewise in R^nd.  Each
 * player is named as minimising or maximising the value phi: with the set
 * {phi <= 0}, a control that reaches it minimises, a control that avoids
 * it maximises, and a disturbance plays against the control (or with it:
 * the user says).  With p = grad phi and the optimal inputs,
 *     H(t, x, p) = p . f + opt_u (G^T p) . u + opt_d (H^T p) . d,
 * where, for a box with centre c and half widths w, min_u q . u =
 * q . c - sum_j |q_j| w_j (max: +), and for a ball min_u q . u = q . c -
 * r |q| (max: +).  phi evolves in backward time tau = T - t (the time
 * remaining to the horizon T) by
 *     D_tau phi - H(T - tau, x, grad phi) = 0,
 * i.e. the kernel's Hamiltonian is -H.  Its partial bounds are exact over
 * the input sets, independent of p:
 *     alpha_i = |f_i + (G c_u)_i + (H c_d)_i| + sum_j |G_ij| w_j
 *               + sum_j |H_ij| w'_j     (boxes; r |G_i.| for a ball),
 * the largest |dx_i/dt| over the inputs (section 2.6's air3D bounds).
 * The general form stays: hj_ls_lax_friedrichs with any H and partial.
 *
 * Problems.  The target and the obstacle are level set functions
 * (negative inside), static arrays on the grid or functions of the
 * forward time t and the state.  The value at tau = 0 is
 * max(target(T), -obstacle(T)); after every step of the kernel
 *     BRT (tube):  phi = max(min(phi, target(t)), -obstacle(t)),
 *     BRS (set):   phi = max(phi, -obstacle(t)),
 * t = T - tau: the discrete form of the reach-avoid variational
 * inequality (Fisac et al., 2015), which treats time-varying targets and
 * obstacles at the time they hold.  Optional: a discount term lambda phi
 * (hj_ls_discount), a convergence stop (max |phi_new - phi_old| / dt below
 * a tolerance: the infinite horizon value, for static sets), and the
 * time-to-reach function: the first tau at which each node's phi becomes
 * <= 0, interpolated linearly in the step (INFINITY for nodes never
 * reached); for a time-invariant system and target under a BRT it is the
 * minimum time to reach the target while avoiding the obstacle.
 *
 * Every evaluation is node by node and parallel over rows, so results do
 * not depend on the number of OpenMP threads; callbacks must be
 * thread-safe.  Errors are returned (hj_error.h), never printed.
 */
#ifndef HJ_REACH_H
#define HJ_REACH_H

#include "hj_error.h"
#include "hj_ls_grid.h"
#include "hj_ls_ode.h"
#include "hj_ls_term.h"

#ifdef __cplusplus
extern "C" {
#endif

#define HJ_REACH_MAXIN 8

enum { HJ_REACH_BOX, HJ_REACH_BALL };
/* What a player does with the value phi. */
enum { HJ_REACH_MIN, HJ_REACH_MAX };
/* Shorthands for the control's goal: REACH the set {phi <= 0} (control
 * minimises, disturbance maximises) or AVOID it (the reverse). */
enum { HJ_REACH_REACH, HJ_REACH_AVOID };

/* An input set in R^n: a box [lo, hi] or a ball of centre c and radius r. */
typedef struct {
    int n;     /* number of inputs, 0..HJ_REACH_MAXIN */
    int shape; /* HJ_REACH_BOX or HJ_REACH_BALL */
    double lo[HJ_REACH_MAXIN], hi[HJ_REACH_MAXIN]; /* box */
    double c[HJ_REACH_MAXIN], r;                   /* ball */
    int mode;  /* HJ_REACH_MIN or HJ_REACH_MAX */
} hj_reach_input;

/* f: fx[0..nx-1]; G, H: nx x n matrices, row major (g[i * n + j]). */
typedef void (*hj_reach_vec_fn)(double t, const double *x, double *out, void *ctx);
/* f over a row of n nodes along dimension 0 (node j at x with x[0] + j dx0
 * in place of x[0]): out[i * n + j] = f_i at node j. */
typedef void (*hj_reach_row_fn)(double t, const double *x, double dx0, long n, double *out, void *ctx);

typedef struct {
    int nx;                 /* state dimension, that of the grid */
    hj_reach_vec_fn f;      /* drift, NULL for 0 */
    hj_reach_vec_fn G;      /* control matrix (needed when u.n > 0) */
    hj_reach_vec_fn H;      /* disturbance matrix (needed when d.n > 0) */
    hj_reach_input u, d;
    void *ctx;
    hj_reach_row_fn f_row; /* optional: f batched over a row, used by the
                            * fused path; must give the bits of f, which
                            * stays needed (the general path, the
                            * per-node functions) */
    int G_const, H_const; /* 1: G (H) depends on neither t nor x, so the
                           * fused path (below) evaluates it once per solve
                           * and skips its zero entries (same bits) */
} hj_reach_dyn;

/* Zero inputs, no callbacks. */
void hj_reach_dyn_init(hj_reach_dyn *s, int nx, hj_reach_vec_fn f, void *ctx);
/* A box [lo, hi] (ball: hj_reach_input_ball) of n inputs as control (G)
 * or disturbance (H). */
void hj_reach_dyn_control_box(hj_reach_dyn *s, hj_reach_vec_fn G, int n, const double *lo, const double *hi);
void hj_reach_dyn_control_ball(hj_reach_dyn *s, hj_reach_vec_fn G, int n, const double *c, double r);
void hj_reach_dyn_disturbance_box(hj_reach_dyn *s, hj_reach_vec_fn H, int n, const double *lo, const double *hi);
void hj_reach_dyn_disturbance_ball(hj_reach_dyn *s, hj_reach_vec_fn H, int n, const double *c, double r);
/* Set the players' modes from the control's goal (HJ_REACH_REACH or
 * HJ_REACH_AVOID); the disturbance opposes the control. */
void hj_reach_dyn_goal(hj_reach_dyn *s, int goal);
/* HJ_EINVAL for an inconsistent system (dimensions, empty box, missing
 * matrix, unknown mode). */
int hj_reach_dyn_check(const hj_reach_dyn *s, hj_error *err);

/* The Hamiltonian H(t, x, p) above (the players' optima), and the
 * kernel's form (hj_ls_ham_fn, hj_ls_partial_fn, ctx = the hj_reach_dyn,
 * t the forward time): -H and the partial bounds alpha_d. */
double hj_reach_hamiltonian(const hj_reach_dyn *s, double t, const double *x, const double *p);
double hj_reach_ls_ham(double t, const double *x, double phi, const double *p, void *ctx);
double hj_reach_ls_partial(double t, const double *x, const double *pmin, const double *pmax, int d, void *ctx);

/* The optimal control u[0..nu-1] and disturbance d[0..nd-1] (either may
 * be NULL) for the gradient p at (t, x): the argument of the optima in H.
 * Where a component of G^T p vanishes the box's centre is taken. */
void hj_reach_dyn_optimal(const hj_reach_dyn *s, double t, const double *x, const double *p, double *u, double *d);
/* dx/dt = f + G u + H d (u, d may be NULL for zero inputs). */
void hj_reach_dyn_eval(const hj_reach_dyn *s, double t, const double *x, const double *u, const double *d,
                       double *xdot);

/* A level set function of the forward time and the state. */
typedef double (*hj_reach_set_fn)(double t, const double *x, void *ctx);
/* A set: an array on the grid, or fn (overrides the array), or neither
 * (no set). */
typedef struct {
    const double *array;
    hj_reach_set_fn fn;
    void *ctx;
} hj_reach_set;

/* Whether s holds a set. */
static inline int hj_reach_set_given(const hj_reach_set *s) { return s->fn || s->array; }
/* The value of s at time t and node k (coordinates x). */
static inline double hj_reach_set_at(const hj_reach_set *s, double t, const double *x, size_t k)
{
    return s->fn ? s->fn(t, x, s->ctx) : s->array[k];
}
/* v projected on the problem's constraints at node k: the minimum with the
 * target's value (a tube, when tube != 0) and the maximum with minus the
 * obstacle's (when obst != 0); *nan is set when either value is NaN. */
static inline double hj_reach_set_constrain(const hj_reach_set *target, const hj_reach_set *obstacle, int tube,
                                            int obst, double t, const double *x, size_t k, double v, int *nan)
{
    if (tube) {
        const double l = hj_reach_set_at(target, t, x, k);
        *nan |= l != l;
        v = l < v ? l : v;
    }
    if (obst) {
        const double o = -hj_reach_set_at(obstacle, t, x, k);
        *nan |= o != o;
        v = o > v ? o : v;
    }
    return v;
}

/* HJ_EINVAL when the time left to the horizon, horizon - tau, is more than
 * 2^52 steps of dt: tau + dt stops changing before the horizon, and the
 * run would never end.  Both solver paths check every step.  Refused even
 * when conv_tol > 0 could stop the run sooner: such a run reaches the
 * horizon only if it does not converge, which it then cannot; if it
 * converges, its value is the infinite horizon's limit, computed with the
 * forward time t = T - tau rounded to more than a quarter of a step (the
 * whole run sees t = T for a horizon far beyond), so the infinite horizon
 * is the problem to state.  conv_tol is the caller's tolerance (only the
 * message depends on it). */
static inline int hj_reach_check_steps_left(double horizon, double tau, double dt, double conv_tol, hj_error *err)
{
    if ((horizon - tau) / dt > 4503599627370496.0) /* 2^52, written in decimal for C++11 */
        return hj_error_set(err, HJ_EINVAL,
                            "reach: the horizon %g needs more than 2^52 steps of dt = %g (the CFL bound); %s",
                            horizon, dt,
                            conv_tol > 0 ? "conv_tol could stop it sooner, but only at the infinite horizon's limit: "
                                           "give horizon = INFINITY"
                                         : "for the limit value use an infinite horizon with conv_tol");
    return HJ_OK;
}

/* Progress of a solve (hj_reach_problem.progress): tau the backward time
 * reached, horizon the problem's (INFINITY for an infinite one), steps the
 * steps taken.  Nonzero ends the solve with that value as its code. */
typedef int (*hj_reach_progress_fn)(double tau, double horizon, long steps, void *ctx);

enum { HJ_REACH_BRS, HJ_REACH_BRT };

typedef struct {
    const hj_ls_grid *grid;
    const hj_reach_dyn *dyn;
    int kind;             /* HJ_REACH_BRS or HJ_REACH_BRT (default) */
    hj_reach_set target;  /* needed */
    hj_reach_set obstacle; /* optional */
    double horizon;       /* T > 0 (the largest tau); INFINITY needs conv_tol
                           * and static sets (functions then see t = -tau) */
    double conv_tol;      /* > 0: stop when max |dphi| / dt <= conv_tol */
    double discount;      /* lambda >= 0: the term lambda phi (0: none) */
    int scheme;           /* HJ_LS_* upwind scheme, default HJ_LS_ENO2 */
    int order;            /* RK order 1..3, default 2 */
    int dissipation;      /* default HJ_LS_LLF */
    double factor_cfl;    /* in (0, 1] (hj_ls_ode.h), default 0.5 */
    int per_node;         /* 1: the kernel's per-node callbacks; 0 (default):
                           * batched rows, f and G evaluated once per node
                           * for H and every alpha_d (same bits) */
    int keep_derivs;      /* 1 (default): GLF and LLF keep the one-sided
                           * derivatives of their range pass for the update
                           * (hj_ls_lax_friedrichs_work_size doubles, 2 nx
                           * per node; same bits); 0 computes them twice */
    int general;          /* 1: always the general path (the kernel's
                           * hj_ls_lax_friedrichs and hj_ls_ode), for
                           * comparison; 0 (default): the fused path where
                           * it applies (hj_reach_fused_applies) */
    int compact;          /* 1: phi, ttr and the target and obstacle arrays
                           * hold the interior nodes only (g->nodes doubles,
                           * dimension 0 fastest, no ghost layers); needs
                           * the fused path; its measure is
                           * hj_reach_measure_compact.  0 (default): arrays
                           * on the grid (hj_ls_alloc) */
    hj_reach_progress_fn progress; /* optional, both paths: called on the
                           * calling thread after every progress_every-th
                           * step (every step when progress_every <= 1),
                           * that ending the run included, after the
                           * target, obstacle and time-to-reach; nonzero
                           * stops the solve: hj_reach_solve returns that
                           * value, err names the step, phi (and ttr)
                           * hold the value at stats.tau */
    void *progress_ctx;
    long progress_every;
} hj_reach_problem;

/* The progress callback after step `steps` at tau, when one is due
 * (both solver paths): its nonzero return, with err naming the step. */
static inline int hj_reach_progress_call(const hj_reach_problem *pb, double horizon, double tau, long steps,
                                         int last, hj_error *err)
{
    if (!pb->progress || (!last && pb->progress_every > 1 && steps % pb->progress_every)) return HJ_OK;
    const int code = pb->progress(tau, horizon, steps, pb->progress_ctx);
    if (code)
        hj_error_set(err, code, "reach: stopped by the progress callback at tau = %g after %ld step%s (code %d)", tau,
                     steps, hj_plural(steps), code);
    return code;
}

/* Defaults above for grid g and system s (target and horizon to set). */
void hj_reach_problem_init(hj_reach_problem *pb, const hj_ls_grid *g, const hj_reach_dyn *s);

typedef struct {
    long steps;
    double tau;    /* backward time reached (T, or less when converged;
                    * where nothing moves under an infinite horizon, the
                    * tau of the step that found it: the value is the
                    * limit from there) */
    int converged; /* the convergence stop ended the run */
    double seconds;
    double step_seconds; /* of which in the time steps (no setup) */
    size_t bytes;  /* the solver's own arrays and row buffers (the
                    * caller's phi and ttr not counted) */
} hj_reach_stats;

/* HJ_EINVAL naming what makes pb unsolvable (no target, zero horizon,
 * dimensions that do not match, ...); hj_reach_solve checks this first. */
int hj_reach_problem_check(const hj_reach_problem *pb, hj_error *err);

/* Solve: phi (an array on the grid, written) receives the value at tau
 * (forward time T - tau); ttr (may be NULL) the time-to-reach; stats may
 * be NULL.  HJ_EINVAL for a problem that cannot be solved (checked before
 * any step: no target, zero horizon, dimensions that do not match, an
 * unknown scheme, order or dissipation, a NULL phi, ...; from the first
 * step's bound: a finite horizon more than 2^52 steps away, whatever
 * conv_tol), HJ_ENOMEM, HJ_ENONFINITE when the value stops being finite,
 * HJ_EINVAL for a step too short to advance tau (tau + dt == tau), the
 * progress callback's nonzero value when it stops the solve.  HJ_ENOMEM
 * before any allocation when the solve's arrays and the caller's exceed
 * the machine's memory (hj_reach_check_memory, either path). */
int hj_reach_solve(const hj_reach_problem *pb, double *phi, double *ttr, hj_reach_stats *stats, hj_error *err);

/* The fused path, which hj_reach_solve takes by itself when it applies:
 * any upwind scheme (first order to WENO5), RK order 1..3, no discount,
 * per_node and general 0, an undivided grid (any dissipation: the partial
 * bounds of a control-affine system do not depend on the gradient, so
 * GLF, LLF and LLLF coincide).  Per block of consecutive rows one pass
 * computes the one-sided derivatives, f and G (H) at each node, the
 * Hamiltonian, the bounds, the dissipation and the time derivative;
 * streaming passes combine the Runge-Kutta stages, the last one with the
 * target, the obstacle, the convergence measure and the time-to-reach.
 * Its state is interior-sized: the value, the time derivative and, for
 * RK2/3, one stage (the caller's phi is the value when compact); the
 * ghost values a stencil reads along each dimension, face ghosts only,
 * are made per block from the boundary conditions.  Same arithmetic, in
 * the same order, as the general path: the same bits, for any number of
 * OpenMP threads.  hj_reach_solve_fused: HJ_EINVAL where the path does
 * not apply, else as hj_reach_solve (which it is called by).
 * hj_reach_fused_bytes: the bytes it allocates for pb with `threads`
 * threads. */
int hj_reach_fused_applies(const hj_reach_problem *pb);
int hj_reach_solve_fused(const hj_reach_problem *pb, double *phi, double *ttr, hj_reach_stats *stats, hj_error *err);
size_t hj_reach_fused_bytes(const hj_reach_problem *pb, int threads);

/* The bytes the general path (the kernel's hj_ls_lax_friedrichs and
 * hj_ls_ode) allocates for pb with `threads` threads: the previous value,
 * the integrator's time derivative and (RK2/3) stage, on the grid with its
 * ghost layers; the kept derivatives (keep_derivs); the row buffers
 * (per_node 0); the sum of terms' array (discount > 0).  stats.bytes of a
 * general solve. */
size_t hj_reach_general_bytes(const hj_reach_problem *pb, int threads);
/* HJ_ENOMEM, with both sizes in the message, when the solve of pb does not
 * fit in the machine's physical memory: the arrays of the path
 * hj_reach_solve takes (hj_reach_fused_bytes or hj_reach_general_bytes,
 * omp_get_max_threads() threads) plus the caller's phi and, when with_ttr,
 * ttr (interior-sized when compact); HJ_OK otherwise or when the memory is
 * unknown.  Both paths check this before they allocate or read the target:
 * malloc alone refuses only a block beyond memory and swap. */
int hj_reach_check_memory(const hj_reach_problem *pb, int with_ttr, hj_error *err);

/* The measure of {phi < 0} on a grid of dimension 1..3 with at most one
 * periodic dimension, which counts a full period (hj_ls_measure_periodic). */
int hj_reach_measure(const hj_ls_grid *g, const double *phi, double *m, hj_error *err);
/* The same for an interior-only array (the layout of pb.compact = 1):
 * hj_reach_measure reads arrays on the grid (hj_ls_alloc), and an
 * interior-only array given to it is read at the wrong nodes. */
int hj_reach_measure_compact(const hj_ls_grid *g, const double *phi, double *m, hj_error *err);

#ifdef __cplusplus
}
#endif

#endif
