/* hj_fsm.h -- fast sweeping for the Eikonal equation |grad phi| = f in 2-D.
 *
 * Third order WENO fast sweeping (Zhang, Zhao & Qian 2006) with the two
 * inflow boundary treatments of Huang, Shu & Zhang (2008):
 *
 *   HJ_BC_RICHARDSON    Category III values from first order Godunov
 *                       sweeps (Zhao 2005) on h, h/2 and h/4 in a small box
 *                       around each inflow piece, combined by (2.9):
 *                       I = I_h/3 - 2 I_{h/2} + 8/3 I_{h/4}.
 *   HJ_BC_LAX_WENDROFF  Category III values from the Taylor expansion
 *                       phi = g + s phi_s + s^2/2 phi_ss in the normal
 *                       distance s to the inflow curve, with phi_s and
 *                       phi_ss from the PDE (section 2.3).
 *   HJ_BC_FIRST_ORDER   Category III values frozen at the first order
 *                       solution (the treatment of refs. [7,16] that the
 *                       paper improves on; kept for comparison).
 *
 * Grid: nodes (x0 + i h, y0 + j h), 0 <= i <= nx, 0 <= j <= ny; arrays are
 * row-major, phi[j * (nx + 1) + i].
 *
 * Categories of nodes (section 2.1):
 *   I   on the inflow boundary: fixed at the boundary data;
 *   II  the two ghost layers outside the box: third order extrapolation
 *       of the grid values before every sweep;
 *   III not in I and at horizontal or vertical distance < 3h (option band) from an
 *       inflow curve, or within [-2h, 2h]^2 of a point source that asks for
 *       Richardson: fixed by the boundary treatment;
 *   IV  every other node, box boundary included: WENO Gauss-Seidel
 *       updates (2.2)-(2.7) in four alternating sweep directions (2.1).
 * The first order Godunov solution (with I and III fixed) is the initial
 * guess.  Iteration stops when ||phi_new - phi_old|| <= delta (2.8) after a
 * full iteration of four sweeps, in the norm chosen in the options.
 */
#ifndef HJ_FSM_H
#define HJ_FSM_H

#include "hj_error.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    int nx, ny;    /* intervals; nodes 0..nx, 0..ny */
    double x0, y0; /* coordinates of node (0, 0) */
    double h;      /* mesh size, dx = dy = h */
} hj_grid2;

typedef struct {
    double (*f)(double x, double y, void *ctx);
    /* Gradient of f, used by the Lax-Wendroff procedure only.  NULL means
     * centred differences of f with step 1e-4 h (error ~1e-8 h^2 f''':
     * fine for third order, not for round-off). */
    void (*grad_f)(double x, double y, double grad[2], void *ctx);
    void *ctx;
} hj_speed;

/* Local description of a smooth inflow curve near a point (x, y). */
typedef struct {
    double dist;    /* distance from (x, y) to the curve, >= 0 */
    double foot[2]; /* nearest point of the curve */
    double n[2];    /* unit normal at foot, pointing towards (x, y) */
    double kappa;   /* curvature w.r.t. n: in x = foot(t) + s n(t) the
                     * metric is ds^2 + (1 + kappa s)^2 dt^2 */
    double g, g_t, g_tt; /* data phi = g on the curve and its arclength
                          * derivatives along tau = (-n[1], n[0]) */
} hj_curve_local;

typedef enum { HJ_INFLOW_POINT, HJ_INFLOW_CURVE } hj_inflow_type;

typedef struct {
    hj_inflow_type type;
    /* HJ_INFLOW_POINT: phi(x, y) = value at a grid node. With richardson
     * set, the nodes of [-2h, 2h]^2 around it are Category III (strategy
     * Richardson only); otherwise the node alone is fixed. */
    double x, y, value;
    int richardson;
    /* HJ_INFLOW_CURVE: level(x, y) is a signed distance to the curve,
     * zero on it; local() describes the curve near a point. */
    double (*level)(double x, double y, void *ctx);
    int (*local)(double x, double y, hj_curve_local *out, void *ctx);
    void *ctx;
} hj_inflow;

typedef enum { HJ_BC_RICHARDSON, HJ_BC_LAX_WENDROFF, HJ_BC_FIRST_ORDER } hj_bc_strategy;
/* Where the local first order sweeps of Richardson extrapolation run for
 * an inflow curve (point sources always use [-2h, 2h]^2 around the source,
 * on all three grids):
 *   HJ_RICH_BOX_NODE   a box [-2h, 2h]^2 around each Category III node
 *                      (the paper's "small box"), on each of the grids h,
 *                      h/2, h/4 widened by one node of that grid (third
 *                      order accurate: reproduces Table 3.2);
 *   HJ_RICH_BOX_TIGHT  the same boxes without the extra node (the box
 *                      [-2h, 2h]^2 alone on every grid);
 *   HJ_RICH_BOX_PIECE  one box around all the piece's Category III nodes,
 *                      reaching the neighbouring pieces (more accurate:
 *                      exact wherever first order sweeps are). */
typedef enum { HJ_RICH_BOX_NODE, HJ_RICH_BOX_PIECE, HJ_RICH_BOX_TIGHT } hj_rich_box;
/* Initial guess of the Category IV nodes (section 2.1: "the solution from
 * the first-order Godunov fast sweeping method [19] is used as the initial
 * guess"):
 *   HJ_GUESS_WITH_III  first order sweeps that hold Category I and the
 *                      strategy's Category III values fixed (the default:
 *                      an inflow curve that misses the grid nodes enters
 *                      the first order method through the nodes near it);
 *   HJ_GUESS_PHYSICAL  first order sweeps from the boundary condition on
 *                      the grid nodes (Category I) alone, Zhao's method as
 *                      it stands, for boundaries that run along grid lines
 *                      (Example 2); the Category III values of the strategy
 *                      are kept.  A piece with no Category I node still
 *                      enters through its Category III values.  A curve
 *                      that only touches a few nodes gives a poor guess
 *                      (Example 3 then does not converge at N = 320). */
typedef enum { HJ_GUESS_WITH_III, HJ_GUESS_PHYSICAL } hj_fsm_guess;
/* Norms of (2.8): mean |change| over the nodes, h^2 sum |change| (the L1
 * integral, as the paper's L1 errors), max |change|. */
typedef enum { HJ_STOP_L1_MEAN, HJ_STOP_L1_INTEGRAL, HJ_STOP_LINF } hj_stop_norm;

typedef struct {
    hj_bc_strategy strategy;
    double eps;             /* epsilon of the WENO weights (2.6)-(2.7) */
    double delta;           /* stopping threshold of (2.8) */
    hj_stop_norm stop_norm; /* norm of (2.8) */
    int max_iter;           /* at most this many iterations (4 sweeps each) */
    int first_order_only;   /* stop after the first order initial guess */
    double band;            /* Category III: distance to a curve < band h,
                             * horizontally or vertically (paper: 3) */
    hj_rich_box richardson_box; /* local boxes of Richardson for curves */
    hj_fsm_guess guess;         /* initial guess of Category IV */
    /* Round-off sensitivity studies: each Category IV value of the initial
     * guess is multiplied by 1 + guess_noise u, u uniform in [-1, 1) from
     * a fixed generator seeded by guess_seed.  0 (the default) leaves the
     * guess alone.  Where the discrete problem has several fixed points
     * (near a zero of f, Example 2 (b)) the one reached can change with
     * perturbations of round-off size; this option measures that. */
    double guess_noise;         /* 0 <= guess_noise < 1 */
    unsigned long guess_seed;
    /* Called after every iteration when not NULL (progress display). */
    void (*progress)(int iter, double change, void *ctx);
    void *progress_ctx;
} hj_fsm_options;

typedef struct {
    int iterations;    /* WENO iterations, four sweeps each */
    int fo_iterations; /* first order iterations of the initial guess */
    double change;     /* ||phi_new - phi_old|| of the last iteration */
    long ncat[4];      /* number of nodes in Categories I, II, III, IV */
} hj_fsm_stats;

/* Default options: Lax-Wendroff, eps = 1e-6, delta = 1e-11 in the L1
 * integral norm, band = 3, Richardson boxes around each node, max_iter = 10000 (the reading of paper 1's
 * illegible delta that reproduces its iteration counts). */
hj_fsm_options hj_fsm_default_options(void);

/* Bytes of work memory hj_fsm_solve() needs for grid g. */
double hj_fsm_memory(const hj_grid2 *g);

/* Solve on grid g.  phi must hold (nx+1)(ny+1) doubles.  Returns HJ_OK,
 * HJ_ENOCONV (phi then holds the last iterate), or an error. */
int hj_fsm_solve(const hj_grid2 *g, const hj_speed *speed, const hj_inflow *inflow, int ninflow,
                 const hj_fsm_options *opt, double *phi, hj_fsm_stats *stats, hj_error *err);

/* Category III value of node (x, y) from the Lax-Wendroff procedure for a
 * curve piece (exposed for tests). */
int hj_fsm_lax_wendroff_value(const hj_speed *speed, const hj_inflow *piece, double x, double y, double h,
                              double *value, hj_error *err);

#ifdef __cplusplus
}
#endif

#endif
