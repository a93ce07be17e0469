/* hj_ls_term.h -- approximations of the terms of the HJ PDE (Mitchell's
 * toolbox, section 3.6):
 *
 *   0 = D_t phi + v.grad phi + a |grad phi| + S(phi_0)(|grad phi| - 1)
 *       + H(x, grad phi) - b kappa |grad phi| + trace[L D^2 phi R]
 *       + lambda phi + F.
 *
 * One calling convention for every term (the toolbox's schemeFunc):
 *     term->eval(term, t, y, ydot, &step_bound, err)
 * takes the state y (an array on the grid; its ghost layer is filled by the
 * term, hence not const), writes G(t, y) = the negated sum of the terms into
 * the interior of ydot, and returns the CFL bound on the time step
 * (INFINITY if the term imposes none).  A term is a struct whose first
 * member is an hj_ls_term; fill it with the matching *_init function, set
 * the parameters, and pass &term.base to the integrator (hj_ls_ode.h).
 *
 * Evaluation is parallel over rows (OpenMP, dynamic chunks of rows so
 * that a thread delayed by other processes does not hold up the others)
 * and every node is computed independently; the CFL bound is a maximum,
 * which does not depend on the order of evaluation, so results are bitwise
 * identical for any number of threads and any schedule.  Callbacks must therefore be thread-safe.  Failures (a
 * callback returning NaN, a NaN CFL bound, out of memory) are returned as
 * error codes; terms never print or exit.
 */
#ifndef HJ_LS_TERM_H
#define HJ_LS_TERM_H

#include "hj_error.h"
#include "hj_ls_deriv.h"
#include "hj_ls_grid.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct hj_ls_term hj_ls_term;

/* How a term turns its per-node speeds s_d(x) (|v_d| for convection, the
 * effective velocity of normal motion and reinitialization, alpha_d for
 * Lax-Friedrichs) into its CFL bound:
 *   HJ_LS_CFL_NODE     1 / max_x sum_d s_d(x) / dx_d, the linear stability
 *                      limit at the worst node (the default);
 *   HJ_LS_CFL_TOOLBOX  1 / sum_d max_x s_d(x) / dx_d, as ToolboxLS's
 *                      artificialDissipationGLF/LLF and termNormal/
 *                      termReinit compute it: never larger, smaller where
 *                      the maxima of the dimensions lie at different nodes
 *                      (air3D: 392 steps instead of 368).
 * Both are stable; the first takes the longest step the scheme allows, the
 * second reproduces the toolbox's step sequence.  Convection has only the
 * first: it equals the second when the maxima meet at one node (the
 * rotations of the demos). */
enum { HJ_LS_CFL_NODE, HJ_LS_CFL_TOOLBOX };

/* The epsilon of the WENO5 weights (upwind schemes HJ_LS_WENO5A/B):
 *   HJ_LS_WENO_EPS_LOCAL  O&F (3.38), 1e-6 times the largest squared first
 *                         difference of the node's own stencil (default);
 *   HJ_LS_WENO_EPS_GRID   1e-6 times the largest over the whole grid, per
 *                         dimension, at every node: ToolboxLS 1.1's
 *                         upwindFirstWENO5a ('maxOverGrid').
 * Where the solution is steep somewhere, the second makes the weights
 * smoother (closer to the linear ones) everywhere else.  Convection,
 * normal motion, reinitialization and Lax-Friedrichs offer both. */
enum { HJ_LS_WENO_EPS_LOCAL, HJ_LS_WENO_EPS_GRID };
typedef int (*hj_ls_term_fn)(const hj_ls_term *term, double t, double *y, double *ydot, double *step_bound,
                             hj_error *err);
struct hj_ls_term {
    hj_ls_term_fn eval;
};

/* A row of n nodes along dimension 0 as batched callbacks see it: node j
 * has the coordinates (x[0] + j dx0, x[1], ..., x[dim-1]) (x[0] is the
 * grid's min[0], so x[0] + j dx0 has the bits of hj_ls_coord's) and the
 * grid index (j, idx[1], ..., idx[dim-1]); k is its offset in arrays on
 * the grid, so tables of time-independent coefficients can be read by
 * index instead of recomputed from coordinates. */
typedef struct {
    long n;
    double dx0;
    const double *x;
    const long *idx;
    size_t k;
} hj_ls_row_info;
/* F(j0, j1), a loop over the nodes [j0, j1) of a row of n nodes, run on
 * whole blocks of 8 nodes and then on the last 8 again instead of a
 * scalar remainder (n < 8: the n nodes once): a scalar node costs about
 * what a vector of them does, and a loop whose outputs do not alias its
 * inputs gives the same bits when it recomputes a node.  The kernel's row
 * loops use it; batched callbacks may too. */
#define HJ_LS_ROW_BLOCKS8(n, F)                    \
    do {                                           \
        const long n8_ = (n) & ~7L;                \
        F(0, n8_)                                  \
        if (n8_ < (n) && (n) >= 8) F((n) - 8, (n)) \
        else if (n8_ < (n)) F(n8_, (n))            \
    } while (0)
/* A scalar parameter a(t, x, phi): row_fn if set, else fn, else array (on
 * the grid) if set, else the constant value (the toolbox's scalar / array
 * / scalarGridFunc choices).  row_fn is fn batched over a row (one call,
 * a vectorisable loop): a[j] = a(t, x_j, phi[j]) for j < row->n. */
typedef double (*hj_ls_scalar_fn)(double t, const double *x, double phi, void *ctx);
typedef void (*hj_ls_scalar_row_fn)(double t, const hj_ls_row_info *row, const double *phi, double *a, void *ctx);
typedef struct {
    double value;
    const double *array;
    hj_ls_scalar_fn fn;
    void *ctx;
    hj_ls_scalar_row_fn row_fn; /* ctx is passed to it too */
} hj_ls_scalar;

/* ---- convection (2): G = -v(x, t) . grad phi, upwinded per dimension. */
/* Velocity callback, one call per row and dimension (vectorise it, as the
 * toolbox asks of its callbacks): v[j] = v_d(t, x + j dx0 e_0) for
 * j = 0 .. n-1, where x is the first node of the row. */
typedef void (*hj_ls_velocity_fn)(double t, const double *x, double dx0, long n, int d, double *v, void *ctx);
typedef struct {
    hj_ls_term base;
    const hj_ls_grid *grid;
    int scheme;                  /* HJ_LS_* upwind scheme */
    double velocity[HJ_LS_MAXDIM]; /* constant velocity (default 0) */
    const double *velocity_array[HJ_LS_MAXDIM]; /* v_d on the grid, or NULL */
    hj_ls_velocity_fn velocity_fn; /* v_d(t, x), overrides the above */
    void *ctx;
    int weno_eps; /* HJ_LS_WENO_EPS_LOCAL (default) or HJ_LS_WENO_EPS_GRID */
    int velocity_steady; /* 1: velocity_fn does not depend on t (below) */
    size_t velocity_cache_max; /* bytes the cache may take (default 1 GiB) */
    double *velocity_cache;    /* the term's own, set by its evaluation */
} hj_ls_convection;
/* CFL bound: 1 / max_x sum_d |v_d| / dx_d.  Rows on which v_d vanishes
 * skip the derivative in d; only the upwind side is computed, and WENO
 * differences along dimension 1 are reused from the neighbouring row (same
 * bits as hj_ls_upwind).  A NaN or infinite velocity is HJ_ENONFINITE
 * naming its component, node and time (found after the pass, on the
 * error path; a distributed grid reports the non-finite CFL bound). */
void hj_ls_convection_init(hj_ls_convection *c, const hj_ls_grid *g, int scheme);
/* velocity_steady = 1 (default 0) declares that velocity_fn returns the
 * same values at every t: the first evaluation then calls it once per row
 * and dimension into a cache of dim nodes doubles (and (dim + 1) rows
 * more: per row its flow flags and CFL maximum) that later evaluations
 * read instead (the same bits, no callback per stage).  When the cache
 * would exceed velocity_cache_max bytes or cannot be allocated, the term
 * calls velocity_fn per stage as without the flag.  The cache belongs to
 * the term: hj_ls_convection_free releases it (harmless without one).
 * It pays where the callback costs more than reading dim doubles per node
 * each stage: a closed form as cheap as a rotation on a grid whose cache
 * outgrows the last level cache runs faster without it (convectionDemo's
 * on 101^3, 24 MB: 4-13 % less CPU time). */
void hj_ls_convection_free(hj_ls_convection *c);

/* ---- normal motion (3): G = -a |grad phi|, Godunov upwinding
 * (|grad phi|^2 = sum_d max(max(D-,0)^2, min(D+,0)^2) for a > 0, with the
 * roles swapped for a < 0).  CFL bound 1 / max_x sum_d |a| |p_d| / (|grad
 * phi| dx_d), p the upwind gradient (|a| / dx_d where grad phi = 0). */
typedef struct {
    hj_ls_term base;
    const hj_ls_grid *grid;
    int scheme;
    hj_ls_scalar speed;
    int cfl_rule; /* HJ_LS_CFL_NODE (default) or HJ_LS_CFL_TOOLBOX */
    int weno_eps; /* HJ_LS_WENO_EPS_LOCAL (default) or HJ_LS_WENO_EPS_GRID */
} hj_ls_normal;
void hj_ls_normal_init(hj_ls_normal *c, const hj_ls_grid *g, int scheme);

/* ---- reinitialization (4): G = -S(phi_0)(|grad phi| - 1) with the
 * smeared sign S = phi_0 / sqrt(phi_0^2 + max dx^2) of the initial data
 * (Osher & Fedkiw (7.5)) and Godunov upwinding as for normal motion with
 * speed S.  initial is an array on the grid, a copy of the data the run
 * starts from: the array being integrated itself is HJ_EINVAL (S would
 * follow the iterate; ToolboxLS's schemeData.initial is a copy).
 *
 * subcell_fix = 1 applies the subcell fix of Russo & Smereka (2000) as
 * ToolboxLS 1.1's termReinit does by default (subcell_fix_order 1): S is
 * the plain sign of phi_0, and at the nodes next to the interface of phi_0
 * the update is -(sign(phi_0)|phi| - D) / max dx with D phi_0's distance
 * estimate from its one-sided differences, which keeps the interface where
 * phi_0 puts it (the CFL bound is not changed).  The default (0) is the
 * scheme of the toolbox's 2004 text, without the fix. */
typedef struct {
    hj_ls_term base;
    const hj_ls_grid *grid;
    int scheme;
    const double *initial;
    int subcell_fix;
    int cfl_rule; /* HJ_LS_CFL_NODE (default) or HJ_LS_CFL_TOOLBOX */
    int weno_eps; /* HJ_LS_WENO_EPS_LOCAL (default) or HJ_LS_WENO_EPS_GRID */
} hj_ls_reinit;
void hj_ls_reinit_init(hj_ls_reinit *c, const hj_ls_grid *g, int scheme, const double *initial);

/* ---- general Hamiltonian (5) by Lax-Friedrichs, toolbox (25)-(26):
 * G = -(H(x, (p+ + p-)/2) - sum_d alpha_d (p+_d - p-_d) / 2), with alpha_d
 * = partial(t, x, pmin, pmax, d) bounding |dH/dp_d| over the box
 * [pmin, pmax] of gradients (>= 0; a negative value is not an error, its
 * magnitude is taken):
 *   GLF   the box is the global range of p-, p+ over the grid,
 *   LLF   local range in dimension d, global in the others,
 *   LLLF  local range in every dimension.
 * CFL bound 1 / max_x sum_d alpha_d / dx_d.  A NaN from either callback is
 * an HJ_ENONFINITE error naming the node.  The callbacks come per node
 * (ham, partial: simplest to write) or per row (ham_row, partial_row below:
 * no call per node, vectorisable); either of each pair is enough, and both
 * forms give the same bits when they compute the same expression. */
enum { HJ_LS_GLF, HJ_LS_LLF, HJ_LS_LLLF };
/* The toolbox's names of the dissipations (artificialDissipationGLF, LLF,
 * LLLF as its examples' arguments): "global", "local", "locallocal"; "?"
 * for another value.  hj_ls_dissipation_parse: HJ_EINVAL naming the
 * choices for an unknown name. */
const char *hj_ls_dissipation_name(int diss);
int hj_ls_dissipation_parse(const char *s, int *diss, hj_error *err);
typedef double (*hj_ls_ham_fn)(double t, const double *x, double phi, const double *p, void *ctx);
typedef double (*hj_ls_partial_fn)(double t, const double *x, const double *pmin, const double *pmax, int d,
                                   void *ctx);
/* Batched forms of ham and partial, one call per row (and dimension d)
 * so that the compiler can vectorise the user's loop: H[j] = ham(t, x_j,
 * phi[j], (p[0][j], ..., p[dim-1][j])) and alpha[j] = partial(t, x_j,
 * (pmin[e][j])_e, (pmax[e][j])_e, d).  A non-finite value is reported as
 * the per-node callbacks' are. */
typedef void (*hj_ls_ham_row_fn)(double t, const hj_ls_row_info *row, const double *phi, const double *const *p,
                                 double *H, void *ctx);
typedef void (*hj_ls_partial_row_fn)(double t, const hj_ls_row_info *row, const double *const *pmin,
                                     const double *const *pmax, int d, double *alpha, void *ctx);
/* Both in one call (one loop over the row in the user's code instead of
 * one for H and one per dimension for alpha): H[j] as ham_row's and
 * alpha[d][j] as partial_row's for every d < dim, the boxes pmin, pmax
 * those of every dimension's partial.  Used under GLF and LLLF, whose box
 * is the same for every d; LLF (a box per d) calls ham_row and
 * partial_row (or ham and partial), which it then needs. */
typedef void (*hj_ls_ham_partial_row_fn)(double t, const hj_ls_row_info *row, const double *phi,
                                         const double *const *p, const double *const *pmin,
                                         const double *const *pmax, double *H, double *const *alpha, void *ctx);
typedef struct {
    hj_ls_term base;
    const hj_ls_grid *grid;
    int scheme;
    int dissipation; /* HJ_LS_GLF, HJ_LS_LLF or HJ_LS_LLLF */
    hj_ls_ham_fn ham;
    hj_ls_partial_fn partial;
    hj_ls_ham_row_fn ham_row;         /* if set, used instead of ham */
    hj_ls_partial_row_fn partial_row; /* if set, used instead of partial */
    hj_ls_ham_partial_row_fn ham_partial_row; /* if set, used instead of both under GLF and LLLF */
    double *work; /* optional, hj_ls_lax_friedrichs_work_size doubles (below) */
    void *ctx;
    int cfl_rule; /* HJ_LS_CFL_NODE (default) or HJ_LS_CFL_TOOLBOX */
    int weno_eps; /* HJ_LS_WENO_EPS_LOCAL (default) or HJ_LS_WENO_EPS_GRID */
    int range_free; /* 1: the partials never read pmin, pmax (below) */
    unsigned row_const; /* bit d: alpha_d is the same at every node of a row (below) */
} hj_ls_lax_friedrichs;
void hj_ls_lax_friedrichs_init(hj_ls_lax_friedrichs *c, const hj_ls_grid *g, int scheme, int dissipation,
                               hj_ls_ham_fn ham, hj_ls_partial_fn partial, void *ctx);
/* The doubles of the optional caller-owned work array (2 dim nodes): with
 * it, GLF and LLF keep the one-sided derivatives of their gradient-range
 * pass and the update pass reads them instead of computing them again
 * (same bits; worth it where the derivatives cost more than the memory
 * traffic, as WENO5's do).  LLLF has no range pass and does not use it. */
size_t hj_ls_lax_friedrichs_work_size(const hj_ls_grid *g);
/* range_free = 1 declares that alpha_d depends on t and x only (air3D's
 * bounds): GLF and LLF then skip the pass over the grid that finds the
 * global gradient range, and each derivative is computed once, in the
 * update pass (same bits as range_free = 0 for such callbacks; no work
 * array is used).  The boxes handed to the partials are then NaN where
 * the range pass would have filled them, so a partial that reads them
 * after all returns NaN (an HJ_ENONFINITE error) rather than a silently
 * wrong bound.  Default 0.
 *
 * Bit d of row_const declares that alpha_d is the same at every node of a
 * row of x_0 (it may depend on t and the row's other coordinates: air3D's
 * alpha_1 and alpha_3): only alpha[0] of that dimension is read, so
 * partial_row (or ham_partial_row, alpha[d][0]) may write alpha[0] alone
 * (the same bits as writing the whole row; the per-node partial is still
 * called at every node).  Default 0. */

/* ---- an explicit Runge-Kutta stage fused into a term's pass over the
 * grid (what hj_ls_ode runs where it can, stages after the first): instead
 * of G = G(t, y) into an array and a second pass that combines,
 *     dst = a y0 + b (y + dt G)
 * at every interior node, the expression of hj_ls_ode's combination (the
 * same bits), with st->amax = max |dst| and st->bad = 1 if a value of dst
 * is not finite.  dst is either y0 itself (in place) or an array apart
 * from y0, and never y (the stencils read y's neighbours).  Convection
 * terms and Lax-Friedrichs terms, alone or restricted (hj_ls_restrict),
 * have the fused form; for any other term *done = 0, nothing is written,
 * and the caller evaluates and combines.  *step_bound is the term's bound
 * at y, as eval returns it. */
typedef struct {
    double a, b, dt;
    const double *y0;
    double *dst;
    double amax; /* out */
    int bad;     /* out */
} hj_ls_stage;
int hj_ls_term_stage(const hj_ls_term *term, double t, double *y, hj_ls_stage *st, double *step_bound, int *done,
                     hj_error *err);

/* ---- mean curvature (6): G = b kappa |grad phi|, centered second order
 * (hj_ls_curvature_at).  CFL bound 1 / max_x 2 b sum_d 1/dx_d^2. */
typedef struct {
    hj_ls_term base;
    const hj_ls_grid *grid;
    hj_ls_scalar b;
} hj_ls_curvature_term;
void hj_ls_curvature_term_init(hj_ls_curvature_term *c, const hj_ls_grid *g);

/* ---- trace of the Hessian (7), a section 4 extra: G = -trace(L D^2phi R)
 * = -sum_ij M_ij phi_{x_j x_i} with M = R L (constant, dim x dim, row
 * major).  CFL bound 1 / (sum_i 2 |M_ii| / dx_i^2 + sum_{i != j} |M_ij| /
 * (dx_i dx_j)), the explicit diffusion limit.  Stable (diffusive) only if
 * -(M + M^T)/2 is positive semidefinite: the term does not check. */
typedef struct {
    hj_ls_term base;
    const hj_ls_grid *grid;
    double M[HJ_LS_MAXDIM * HJ_LS_MAXDIM];
} hj_ls_hessian_term;
void hj_ls_hessian_term_init(hj_ls_hessian_term *c, const hj_ls_grid *g, const double *L, const double *R);

/* ---- discount (8): G = -lambda phi, bound 1 / max |lambda| (explicit
 * decay limit); forcing (9): G = -F, no bound (INFINITY).  Section 4
 * extras. */
typedef struct {
    hj_ls_term base;
    const hj_ls_grid *grid;
    hj_ls_scalar lambda;
} hj_ls_discount;
void hj_ls_discount_init(hj_ls_discount *c, const hj_ls_grid *g);
typedef struct {
    hj_ls_term base;
    const hj_ls_grid *grid;
    hj_ls_scalar F;
} hj_ls_forcing;
void hj_ls_forcing_init(hj_ls_forcing *c, const hj_ls_grid *g);

/* ---- restrict update (10): the inner term's G clipped to >= 0 (positive)
 * or <= 0; its CFL bound unchanged (toolbox termRestrictUpdate).  A
 * Lax-Friedrichs inner term (reachability) clips in its own row pass
 * instead of a pass of its own (same values). */
typedef struct {
    hj_ls_term base;
    const hj_ls_grid *grid;
    const hj_ls_term *inner;
    int positive;
} hj_ls_restrict;
void hj_ls_restrict_init(hj_ls_restrict *c, const hj_ls_grid *g, const hj_ls_term *inner, int positive);

/* ---- sum of terms: G = sum_i G_i, bound (sum_i 1 / bound_i)^-1 (toolbox
 * section 3.6.5).  Holds one work array, allocated by init (HJ_ENOMEM) and
 * released by hj_ls_sum_free. */
#define HJ_LS_SUM_MAX 16
typedef struct {
    hj_ls_term base;
    const hj_ls_grid *grid;
    int n;
    const hj_ls_term *terms[HJ_LS_SUM_MAX];
    double *work;
} hj_ls_sum;
int hj_ls_sum_init(hj_ls_sum *c, const hj_ls_grid *g, const hj_ls_term *const *terms, int n, hj_error *err);
void hj_ls_sum_free(hj_ls_sum *c);

/* ---- extremum of terms (for paper 3's HJB equations over a finite control
 * set): G = min_i G_i (take_max = 0) or max_i G_i, node by node; bound
 * min_i bound_i (the most restrictive term).  With one convection term
 * per control a, each upwinded for its own velocity f(x, a), min_i G_i =
 * -max_a f(x, a) . grad phi: the Hamiltonian of theta_t + max_a f . grad
 * theta = 0, by the upwinding of each control (a monotone scheme when each
 * term is).  Holds one work array, allocated by init (HJ_ENOMEM) and
 * released by hj_ls_extremum_free. */
typedef struct {
    hj_ls_term base;
    const hj_ls_grid *grid;
    int n;
    int take_max;
    const hj_ls_term *terms[HJ_LS_SUM_MAX];
    double *work;
} hj_ls_extremum;
int hj_ls_extremum_init(hj_ls_extremum *c, const hj_ls_grid *g, const hj_ls_term *const *terms, int n, int take_max,
                        hj_error *err);
void hj_ls_extremum_free(hj_ls_extremum *c);

/* The grid a term of this library was made on (the g of its *_init), or
 * NULL for a term of the caller's own (any other eval function). */
const hj_ls_grid *hj_ls_term_grid(const hj_ls_term *term);
/* HJ_EINVAL, naming both grids' sizes, when term, or a term it wraps (a
 * restricted update's inner term, the terms of a sum or an extremum), was
 * made on a grid whose layout or placement differs from g's (dimension,
 * node counts, first node, spacing, boundary conditions; the message
 * names the first that differs): its stencils would index arrays on g
 * with the other grid's strides.  A copy of the same grid is the same
 * grid, and so is one whose periodic or extrapolating conditions carry
 * other lo and hi values (read for Dirichlet and Neumann only) or whose
 * first node and spacing differ by rounding (8 ulps: a periodic grid of
 * hj_ls_grid_init_period and the same nodes by hj_ls_grid_init).  A NULL
 * term or eval, or a NULL g, is HJ_EINVAL too, and so is a term of this
 * library whose (void) init was given a NULL grid.  hj_ls_ode runs this
 * check before any step. */
int hj_ls_term_check_grid(const hj_ls_term *term, const hj_ls_grid *g, hj_error *err);

#ifdef __cplusplus
}
#endif

#endif
