/* hj_ub.h -- the UB-HJB scheme of Bokanowski, Cristiani & Zidani 2010:
 * the Ultra-Bee scheme for front propagation with a finite set of controls
 * (section 2.2: averages (7b), fluxes (8)-(9), the min over controls),
 * run on a narrow band kept in any hj_band store (section 3.5).
 *
 * Equation.  theta_t + max_{a in A} ( f(t, x, a) . grad theta ) = 0 with
 * data +-1 (-1 inside Omega_0), on n nodes per direction from lo to hi, end
 * points included: xi_I = lo + I dx, dx = (hi - lo)/(n - 1), and cells
 * xi_I + [-dx/2, dx/2]^d.  The published 2-D results (Tables 6-7) come
 * from N cells of width L/N tiling the domain [a, b]: hj_ub_cell_grid gives
 * the lo, hi of their centres (paper3_ultrabee/overview.md gives the
 * evidence; the 3-D and 4-D examples take the domain's ends as nodes).
 * This is the sign convention under which the paper's examples and its
 * scheme agree: a single control f gives the advection
 * theta_t + f . grad theta = 0 (Example 1), and f = (1, a), a = +-1 gives
 * (13a).  With target = 1 the
 * equation is (4), theta_t + max(0, max_a f . grad theta) = 0.
 *
 * Scheme.  Dimension splitting of the one-dimensional Ultra-Bee fluxes
 * (8)-(9) (with the errata: W_{j-1}, W_{j+1} in the mu = 0 cases), one
 * sweep per direction for each control, then V^{n+1} = min over controls
 * (and min with V^n for the target problem).  Time step from CFL = cfl over
 * the band nodes, truncated to land on the requested final time.  Outside
 * the domain the value is `boundary` (1 in the paper).
 *
 * Band.  The store holds D^n: the nodes with values in ]-1, 1[ and the
 * +-1 nodes with a neighbour (any of the 3^d - 1) of another value.  A node
 * that is not stored has the value of its stored neighbours.  Each step
 * inserts Neigh(D^n) (D^{n+1/2}), updates it, and removes the +-1 nodes
 * equal to all their neighbours.  Values within 1e-12 of +-1 are set to
 * +-1 so that the removal test is exact (the flux arithmetic can leave
 * round-off of that size on constant states).
 *
 * Library code: returns HJ_* codes, never prints.
 */
#ifndef HJ_UB_H
#define HJ_UB_H

#include <stdint.h>

#include "hj_band.h"
#include "hj_front.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A tolerance for the removal test (hj_ub_problem.snap): with the
 * dimension splitting, cells the front has left keep values 1e-12 .. 1e-3
 * away from +-1 (staircase residues of the anti-diffusive limiter) and the
 * band grows without bound (Example 4, N = 50: 4410 nodes after 40 steps
 * with 1e-12, 155 with 1e-3).  A residue below 1e-3 is a covered fraction
 * below 0.05 % of a cell, far below what the sign-based errors see. */
#define HJ_UB_SNAP 1e-3

typedef struct {
    int d;                             /* 2..4 */
    int n;                             /* nodes per direction */
    double lo[HJ_BAND_DMAX], hi[HJ_BAND_DMAX]; /* the domain */
    int ncontrols;                     /* size of the finite control set A */
    /* f(t, x, a) for control a = 0..ncontrols-1 */
    void (*dyn)(double t, const double *x, int a, double *f, void *ctx);
    int target;                        /* 1: equation (4) (max with 0) */
    double cfl;                        /* 0.9 in the paper */
    double boundary;                   /* value outside the domain */
    double dtmax;                      /* optional cap on the time step (0: none) */
    int front_sub;                     /* Hausdorff estimate: the exact front is sampled on the
                                          lattice lines refined front_sub times (0, 1: the lines
                                          through the cell centres); see hj_ub_errors */
    double snap;                       /* values within snap of +-1 become +-1 (0: 1e-12) */
    /* Average of the initial data phi (+-1) over the box [blo, bhi] (7b). */
    double (*avg0)(const double *blo, const double *bhi, void *ctx);
    /* Optional: 1 when phi is surely constant on the box [blo, bhi] (when
     * avg0 is sampled); without it avg0 = +-1 on a box means constant. */
    int (*uniform)(const double *blo, const double *bhi, void *ctx);
    /* A box that contains the closure of Omega_0 (where to look for it). */
    double bbox_lo[HJ_BAND_DMAX], bbox_hi[HJ_BAND_DMAX];
    /* Optional: called once for every cell when its value first becomes -1
     * (at t = 0 for the cells inside Omega_0): the minimal time function
     * of the target problem, streamed without a full grid (hj_mintime.h). */
    void (*reached)(const int *idx, double t, void *ctx);
    void *ctx;
} hj_ub_problem;

typedef struct {
    const hj_ub_problem *pb;
    hj_band *s;
    double t, dx[HJ_BAND_DMAX];
    long steps;
    double band_sum;      /* sum over steps of |D^{n+1/2}| */
    size_t band_max;      /* largest |D^{n+1/2}| */
    /* workspace, grown as needed */
    size_t cap;
    int64_t *lin;
    double **ptr, *v0, *w, *wn, *vmin, *f, *mu;
    double *x;            /* band node centres, d per node (once per step) */
    int32_t *link;
} hj_ub_solver;

/* HJ_EINVAL naming the first parameter of pb that no run can use: a
 * domain bound that is not finite, a boundary value that is not finite, a
 * snap outside [0, 1) or a dtmax that is NaN or negative (each was taken
 * silently: the NaN snap and dtmax as their defaults, a NaN boundary as
 * NaN values).  hj_ub_init and hj_ub_dense_init call it. */
int hj_ub_problem_check_values(const hj_ub_problem *pb, hj_error *err);
/* HJ_EINVAL naming the first of d (2..4), n (>= 3), ncontrols (>= 1),
 * cfl (0 < cfl <= 1) and, with need_data, dyn and avg0 that is out of
 * range or missing.  hj_ub_init (need_data 1) and hj_ub_dense_init (0: it
 * takes a row callback instead of dyn) call it first. */
int hj_ub_problem_check_shape(const hj_ub_problem *pb, int need_data, hj_error *err);

/* Set up the store (kind) with D^0 and the averages (7b).  HJ_EINVAL for a
 * problem hj_ub_problem_check_shape or _values refuses, an empty or
 * non-finite bounding box, and a bounding box that does not contain
 * Omega_0: avg0 must be 1 over the cells two beyond each of its ends that
 * lies inside the domain (the cells beyond the box are never looked at,
 * so the set would be cut there); a box wholly outside the domain is taken
 * only when avg0 is 1 over the whole domain (Omega_0 misses it).  The
 * cells are appended in scan order (lexicographic), O(1) each.  On an
 * error nothing stays allocated (sv as hj_ub_free leaves it; calling
 * hj_ub_free on it is harmless). */
int hj_ub_init(hj_ub_solver *sv, const hj_ub_problem *pb, hj_band_kind kind, hj_error *err);
void hj_ub_free(hj_ub_solver *sv);

/* One step of the scheme, with dt <= tmax - t (none when tmax <= t).
 * HJ_EINVAL for a NaN tmax; HJ_ENONFINITE naming the node, control and
 * time when the dynamics give a NaN or infinite f at a band node. */
int hj_ub_step(hj_ub_solver *sv, double tmax, hj_error *err);
/* Steps until t = T (finite, else HJ_EINVAL); errors as hj_ub_step. */
int hj_ub_run(hj_ub_solver *sv, double T, hj_error *err);

/* Centre of cell idx. */
void hj_ub_centre(const hj_ub_solver *sv, const int *idx, double *x);

/* Errors of section 4 against the exact solution, whose indicator
 * inside(x) is 1 when x is in Omega_t (exact front at the current t): the
 * L1 error and the Hausdorff distance of hj_front.h, with the exact front
 * sampled on the lattice lines refined pb->front_sub times.  Every cell of
 * the grid is visited; the values of the cells that are not stored are
 * recovered from the band as the scheme does (hj_front_band_errors). */
int hj_ub_errors(hj_ub_solver *sv, hj_front_inside_fn inside, void *ctx, double *l1, double *haus, hj_error *err);

/* The value of every cell, recovered from the band as the errors do
 * (stored values; a gap takes its stored neighbour's value; a line without
 * stored cells its neighbour line's): out[l n + i] for line l (the first
 * d - 1 indices, lexicographic) and last index i; n^d doubles.  For figures
 * (hj_front_band_values). */
int hj_ub_values(hj_ub_solver *sv, double *out, hj_error *err);

/* The grid of the paper's examples: n cells of width (b - a)/n tiling
 * [a, b] in each direction; *lo and *hi receive the first and last cell
 * centres, a + dx/2 and b - dx/2 (the lo, hi of hj_ub_problem). */
void hj_ub_cell_grid(double a, double b, int n, double *lo, double *hi);

/* Helpers for avg0: the exact average of +-1 data for a box target, and a
 * sampled one (m^d points per box, exact away from the sphere) for a ball. */
double hj_ub_avg_box(int d, const double *blo, const double *bhi, const double *clo, const double *chi);
double hj_ub_avg_ball(int d, const double *blo, const double *bhi, const double *c, double r, int m);
/* 1 when the box lies entirely inside or entirely outside the ball. */
int hj_ub_ball_uniform(int d, const double *blo, const double *bhi, const double *c, double r);

/* The one-dimensional Ultra-Bee update of W_j (w[0..4] = W_{j-2..j+2},
 * mu[0..2] = mu_{j-1..j+1}): W_j - mu_j (W^L_{j+1/2} - W^R_{j-1/2}). */
double hj_ub_update(const double *w, const double *mu);

/* One control's velocity for the level set kernel's convection term
 * (hj_ls_term.h), so that the level set method runs on the same problem:
 * v = f(t, x, a) from the problem's dynamics; with frozen set, f is
 * evaluated at time tfix instead of t (a flow piecewise constant in time
 * is integrated piece by piece, so that no Runge-Kutta stage sees the
 * switch). */
typedef struct {
    void (*dyn)(double t, const double *x, int a, double *f, void *ctx);
    int a;
    int frozen;
    double tfix;
    void *ctx;
} hj_ub_control;
/* An hj_ls_velocity_fn over an hj_ub_control. */
void hj_ub_control_velocity(double t, const double *x, double dx0, long n, int d, double *v, void *ctx);

#ifdef __cplusplus
}
#endif

#endif
