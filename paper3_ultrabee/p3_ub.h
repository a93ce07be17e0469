/* p3_ub.h -- the UB-HJB scheme (section 2.2 of Bokanowski, Cristiani &
 * Zidani 2010) on a narrow band kept in any p3_store (section 3.5).
 *
 * Equation.  theta_t + max_{a in A} ( f(t, x, a) . grad theta ) = 0 with
 * data +-1 (-1 inside Omega_0), on n nodes per direction from lo to hi, end
 * points included: xi_I = lo + I dx, dx = (hi - lo)/(n - 1), and cells
 * xi_I + [-dx/2, dx/2]^d.  The published 2-D results (Tables 6-7) come
 * from N cells of width L/N tiling the domain [a, b]: p3_cell_grid gives
 * the lo, hi of their centres (the overview gives the evidence; the 3-D
 * and 4-D examples still take the domain's ends as nodes).  This is the sign
 * convention under which the paper's examples and its scheme agree: a
 * single control f gives the advection theta_t + f . grad theta = 0
 * (Example 1), and f = (1, a), a = +-1 gives (13a).  With target = 1 the
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
#ifndef P3_UB_H
#define P3_UB_H

#include <stdint.h>

#include "p3_store.h"

/* The tolerance the example programs use for the removal test: with the
 * dimension splitting, cells the front has left keep values 1e-12 .. 1e-3
 * away from +-1 (staircase residues of the anti-diffusive limiter) and the
 * band grows without bound (Example 4, N = 50: 4410 nodes after 40 steps
 * with 1e-12, 155 with 1e-3).  A residue below 1e-3 is a covered fraction
 * below 0.05 % of a cell, far below what the sign-based errors see. */
#define P3_SNAP 1e-3

/* The exact sets of the examples are closed: a cell centre on a face is
 * inside.  Their tests allow P3_CLOSED_SLACK dx, so that the round-off of
 * the coordinates (-2 + i dx is ~1e-17 off a face through a centre) does
 * not decide it. */
#define P3_CLOSED_SLACK 1e-9

typedef struct {
    int d;                             /* 2..4 */
    int n;                             /* nodes per direction */
    double lo[P3_DMAX], hi[P3_DMAX];   /* the domain */
    int ncontrols;                     /* size of the finite control set A */
    /* f(t, x, a) for control a = 0..ncontrols-1 */
    void (*dyn)(double t, const double *x, int a, double *f, void *ctx);
    int target;                        /* 1: equation (4) (max with 0) */
    double cfl;                        /* 0.9 in the paper */
    double boundary;                   /* value outside the domain */
    double dtmax;                      /* optional cap on the time step (0: none) */
    int front_sub;                     /* Hausdorff estimate: the exact front is sampled on the
                                          lattice lines refined front_sub times (0, 1: the lines
                                          through the cell centres); see p3_solver_errors */
    double snap;                       /* values within snap of +-1 become +-1 (0: 1e-12) */
    /* Average of the initial data phi (+-1) over the box [blo, bhi] (7b). */
    double (*avg0)(const double *blo, const double *bhi, void *ctx);
    /* Optional: 1 when phi is surely constant on the box [blo, bhi] (when
     * avg0 is sampled); without it avg0 = +-1 on a box means constant. */
    int (*uniform)(const double *blo, const double *bhi, void *ctx);
    /* A box that contains the closure of Omega_0 (where to look for it). */
    double bbox_lo[P3_DMAX], bbox_hi[P3_DMAX];
    /* Optional: called once for every cell when its value first becomes -1
     * (at t = 0 for the cells inside Omega_0): the minimal time function
     * of the target problem, streamed without a full grid. */
    void (*reached)(const int *idx, double t, void *ctx);
    void *ctx;
} p3_problem;

typedef struct {
    const p3_problem *pb;
    p3_store *s;
    double t, dx[P3_DMAX];
    long steps;
    double band_sum;      /* sum over steps of |D^{n+1/2}| */
    size_t band_max;      /* largest |D^{n+1/2}| */
    /* workspace, grown as needed */
    size_t cap;
    int64_t *lin;
    double **ptr, *v0, *w, *wn, *vmin, *f, *mu;
    int32_t *link;
} p3_solver;

/* Set up the store (kind) with D^0 and the averages (7b). */
int p3_solver_init(p3_solver *sv, const p3_problem *pb, p3_kind kind, hj_error *err);
void p3_solver_free(p3_solver *sv);

/* One step of the scheme, with dt <= tmax - t. */
int p3_solver_step(p3_solver *sv, double tmax, hj_error *err);
/* Steps until t = T. */
int p3_solver_run(p3_solver *sv, double T, hj_error *err);

/* Centre of cell idx. */
void p3_centre(const p3_solver *sv, const int *idx, double *x);

/* Errors of section 4 against the exact solution, whose indicator
 * inside(x) is 1 when x is in Omega_t (exact front at the current t).
 *   l1   = prod dx * #{ I : sign(V_I) != sign(phi(xi_I)) }, sign(0) = -1,
 *          V_I within 1e-12 of 0 counting as 0 (half-cut cells)
 *   haus = Hausdorff distance between the computed front and the exact
 *          one.  Computed front: the centres of the boundary cells of the
 *          computed set {V <= 0} (V <= 0 with a face neighbour V > 0), the
 *          set whose signs the L1 error counts.  Exact front: the points
 *          where it crosses the segments joining neighbouring cell centres
 *          (bisection on inside, to 1e-6 dx); with pb->front_sub = m > 1,
 *          where it crosses the m^(d-1) parallel segments shifted by
 *          (s / m - 1/2) dx (s = 0 .. m - 1) in the other directions, i.e.
 *          the lattice lines refined m times, in the strip of cells around
 *          each crossing.  The exact front's points farthest from the cell
 *          centres lie between the centre lines, so m = 1 underestimates the
 *          distance (a straight front half a cell from the centres: 0.5 dx
 *          against sqrt(0.5) dx with m even).
 * Every cell of the grid is visited; the values of the cells that are not
 * stored are recovered from the band as the scheme does. */
typedef int (*p3_inside_fn)(const double *x, void *ctx);
int p3_solver_errors(p3_solver *sv, p3_inside_fn inside, void *ctx, double *l1, double *haus, hj_error *err);

/* The value of every cell, recovered from the band as the errors do
 * (stored values; a gap takes its stored neighbour's value; a line without
 * stored cells its neighbour line's): out[l n + i] for line l (the first
 * d - 1 indices, lexicographic) and last index i; n^d doubles.  For figures. */
int p3_solver_values(p3_solver *sv, double *out, hj_error *err);

/* The same errors for values on the full grid of n^d cell centres lo + i dx
 * (the level set runs): value(idx) is V at cell idx; sub as front_sub.  *ncells (may be
 * NULL) receives #{V <= 0}; an empty computed set gives haus = +inf. */
typedef double (*p3_value_fn)(const int *idx, void *ctx);
int p3_field_errors(int d, int n, const double *lo, const double *dx, p3_value_fn value, void *vctx,
                    p3_inside_fn inside, void *ctx, int sub, double *l1, double *haus, int64_t *ncells,
                    hj_error *err);

/* The grid of the paper's examples: n cells of width (b - a)/n tiling
 * [a, b] in each direction; *lo and *hi receive the first and last cell
 * centres, a + dx/2 and b - dx/2 (the lo, hi of p3_problem). */
void p3_cell_grid(double a, double b, int n, double *lo, double *hi);

/* Helpers for avg0: the exact average of +-1 data for a box target, and a
 * sampled one (m^d points per box, exact away from the sphere) for a ball. */
double p3_avg_box(int d, const double *blo, const double *bhi, const double *clo, const double *chi);
double p3_avg_ball(int d, const double *blo, const double *bhi, const double *c, double r, int m);
/* 1 when the box lies entirely inside or entirely outside the ball. */
int p3_ball_uniform(int d, const double *blo, const double *bhi, const double *c, double r);

/* Hausdorff distance between two finite point sets in R^d (rows of d
 * doubles); h is a typical spacing used to bucket the points.  +inf when
 * exactly one set is empty, 0 when both are. */
int p3_hausdorff(int d, const double *a, size_t na, const double *b, size_t nb, double h, double *out, hj_error *err);

/* The one-dimensional Ultra-Bee update of W_j (w[0..4] = W_{j-2..j+2},
 * mu[0..2] = mu_{j-1..j+1}): W_j - mu_j (W^L_{j+1/2} - W^R_{j-1/2}). */
double p3_ub_update(const double *w, const double *mu);

#endif
