/* hj_eik.c -- fast sweeping for |grad T| = f in 2-D and 3-D; see hj_eik.h.
 *
 * The unknown.  With point sources and opt->factored, every node belongs
 * to the source whose estimated arrival t0 + f(s) |x - s| is smallest and
 * the solver works on tau in
 *
 *     T = t0 + T0 tau,   T0 = f(s) |x - s|          (Fomel, Luo & Zhao 2009)
 *
 * in the whole domain.  Near a source T is a cone plus a smooth function,
 * so any finite difference of T is first order there whatever the scheme;
 * tau is smooth through the source (tau -> 1), so the schemes keep their
 * order.  Using the factor everywhere (rather than in a ball around the
 * source, Luo & Qian 2012) avoids a switch whose radius would have to be
 * tuned and whose seam is itself a source of error; far from the source
 * the factor is a smooth positive weight and costs nothing in accuracy.
 * The factor first comes from the earliest estimated source; after the
 * first order phase each node takes the factor of the source whose front
 * reached it there (a late source can be overtaken: its time is a bound).
 * Taking the factor from the earliest source keeps T0 a good model of T
 * on each source's side of the meeting line; where two owners meet, the
 * neighbour values are converted into the node's own factorisation (T is
 * continuous there, tau is not).  Without sources, or with factored = 0,
 * T0 = 1 and t0 = 0: the plain Godunov scheme on T.  T has a kink where
 * two owners meet, and the stencils that straddle it make this joint
 * solve first order in Linf there; with separate_sources each source is
 * solved alone and the node-wise minimum taken (solve_separate).
 *
 * The discretisation.  Along dimension d the derivative of T is
 * p_d tau + T0 D_d tau (p = grad T0), with D_d tau one-sided: first order
 * differences, or the WENO3 (Zhang, Zhao & Qian 2006) or WENO5 (Xiong,
 * Zhang, Zhang & Shu 2010) approximations written as an extrapolated
 * neighbour value tau -/+ h D^-/+ tau, as in hj_fsm.  The upwind side is
 * the one whose adjacent node has the smaller T (decided on the nodes, not
 * on the WENO values: deciding on the WENO values made the side flip back
 * and forth where fronts meet, and the third order iteration then needed
 * 60-70 iterations instead of 11-15 on a 3-D test); the Godunov update
 * then solves sum_d (a_d tau - b_d)_+^2 = f^2 over the upwind sides.
 * The high order update keeps that side except where both neighbours
 * along d are earlier than the node (a valley of T along d): there it
 * takes the side whose term is larger at the root (the Godunov max,
 * godunov_max), so that the update does not jump when the neighbours'
 * order flips.
 *
 * Downwind relaxation.  The WENO stencil of D^- tau at node i reaches
 * the downwind nodes i+1 (WENO3) and i+1, i+2 (WENO5).  A Gauss-Seidel
 * update that moves the node alone against a held stencil only half
 * corrects a smooth error (the node's own weight in h D^- is 1/2 for
 * WENO3 with its linear weights); such errors were carried out of the
 * grid a few nodes per sweep and the iteration count grew with N (2-D,
 * point source, order 3: 24, 30, 40, 56, 94 iterations for N = 40 ...
 * 640; order 5: 32 ... 114).  Where the sweep runs along dimension d in
 * the direction of the side's flow, the downwind nodes come after the
 * node in that sweep and will move with it.  The term is linearised
 * with the change of tau extrapolated linearly along d from the upwind
 * neighbour's change du in this sweep: the node moves by D, the
 * downwind node j nodes away by (j + 1) D - j du.  The slope is then
 * T0 (c + e) / h + p instead of T0 / h + p, with c the own plus downwind
 * coefficient of h D^- and e = sum_j j a_j over its downwind
 * coefficients a_j, the weights held (WENO3: c = 0.5 + w, e = (1 - w) / 2;
 * 5/6 and 1/3 with the linear weights; WENO5 47/60 and 2/5), and the
 * right-hand side holds -e du and leaves the term unchanged at the
 * current tau when du = 0, so the converged solution is the same.  In
 * 1-D with the linear weights a sweep along the flow then damps a
 * smooth error by O(h k) (k its wave number) and every wave number by
 * at least 2 (WENO3; 1.6 for WENO5).  Moving the downwind nodes by D
 * alone (e = 0, the first form of this relaxation) damped every wave
 * number by 2 (WENO3) and 3/2 (WENO5) but reversed smooth errors
 * instead of removing them (amplification -1/2 as k -> 0): the error
 * then alternated in sign from one iteration to the next along the
 * characteristics into the outflow corner, decaying by only 0.24 to 0.33
 * per iteration, and the 3-D counts still grew (order 3 13, 16, 21, 23
 * iterations for N = 20 ... 160; 14 ... 31 with no relaxation at all).
 * Now the counts are about flat in N (linear speed, tol 1e-12, first
 * order start included: order 3 12, 12, 14, 16 iterations of 2^dim full
 * sweeps in 3-D for N = 20 ... 160, 17, 17, 19, 20 in 2-D for N = 40
 * ... 320; see paper1_fastsweeping/eik/notes).  With one point source
 * and no obstacle or fixed node an iteration is now one orthant pass
 * (source_cut): 3-D order 3 27, 27, 29, 31 passes, a third fewer local
 * solves and 1.4 to 2.3 times less CPU time, but a count that grows.
 * Where the upwind neighbour did not change in this sweep (a fixed node,
 * a locked one) du = 0 is its true change.  The relaxation stays on after demote_cycling (with the first
 * form and c held at the linear weights' value there, the 40 x 40 map
 * below took 105 iterations at order 5, with the quicker cycle test;
 * 64 instead of 33 now).  In the
 * sweeps against the flow the downwind nodes are already new and the
 * relaxed slope there amplifies short waves (1-D WENO5: by 3.6 per
 * sweep; the WENO5 iteration cycled); the plain slope T0 / h + p, on
 * the other hand, lets these sweeps undo part of what the sweeps along
 * the flow did: in a 1-D model of the iteration (linear weights, the
 * four sweeps of a 2-D iteration, two along the flow and two against)
 * the error falls by only 0.58 per iteration with WENO5 and 0.20 with
 * WENO3, its largest part next to the outflow end, whatever the
 * boundary closure.  Against the flow the slope is T0 AGAINST_SLOPE /
 * h + p, the right-hand side keeping the term's value at the current
 * tau (the same fixed point): 0.37 and 0.18 in the model (slope 1.5:
 * 0.33 and 0.17, but 3-D order 3 then took one iteration more; below
 * 1 the model diverges).  Stencils reaching the ghost layers take the
 * ghost values from the current values of their line (current_ghosts,
 * the quadratic extrapolation of fill_ghosts), not from those filled
 * before the sweep, and the ghosts' coefficients in h D^-/+ count as
 * the coefficients of the nodes they extrapolate (fold_ghosts): the
 * relaxation then holds there too, with c and e over the in-grid nodes,
 * and against the flow the slope is at least the node's own coefficient
 * (1.5 at the last node with WENO3, whose stencil then is the one-sided
 * second order difference).  With the ghosts held for the sweep the
 * relaxation had to be off there (relaxed, the order 3 iteration slowed
 * to a factor 0.66 per iteration at the outflow boundary), and current
 * ghosts with the plain slope overshot (the node enters its stencil
 * through the ghosts with weight 3).  The weights' c, not the linear weights' constant,
 * is what keeps order 3 converging on maps whose speed varies by a
 * large factor over a few cells (with the constant the 40 x 40 map below
 * did not converge in 1000 iterations): where a stencil is not smooth
 * the weights lean upwind and c > 1 damps the update.  An order 3 iteration that stops converging by the same test drops the
 * relaxation (the wall of eik_convergence at N = 40 stalled at changes
 * of 3.5e-12 of the scale with it).
 *
 * The sweeps.  Each of the 2^dim sweeps visits the nodes in blocks taken
 * by hyperplanes I + J (+ K) = const of block indices in the sweep's
 * orientation (Detrixhe, Gibou & Min 2013, with blocks for nodes), the
 * nodes of a block in lexicographic order: every axis-aligned stencil of
 * a node lies in blocks of other hyperplanes, so the blocks of one
 * hyperplane are updated in parallel, and along every axis line the
 * order is that of the plain lexicographic sweep, so the result does not
 * depend on the number of threads or the block size (bit for bit).  One
 * thread sweeps the whole grid as one block, along the rows in memory.
 * The higher order iterations start from the converged first order
 * solution.  A node whose stencil did not change since its last update
 * is skipped (locking, Bak, McLaughlin & Renzi 2010): in the first order
 * phase when no neighbour changed by more than 1e-14 of tau after the
 * node's last computation, in the higher order phase when the changes
 * were below a tenth of the stopping threshold.
 *
 * Causal sweeps (opt->causal_sweeps, where the orthant pass does not
 * apply).  Each free node gets an orientation, along each axis the side
 * of its earlier neighbour (causal_sides, from the iterate at the start
 * of the iteration), and of the 2^dim sweeps only the one of its
 * orientation solves it: every node is solved in a sweep that runs along
 * its flow on every axis (the relaxation always applies) and once per
 * iteration.  Locking compares with the node's sweep of the last
 * iteration, 2^dim sweeps back, and a node whose orientation changed is
 * solved; the relaxation's du is the upwind neighbour's change in this
 * iteration (its sweep precedes the node's or is the same).  Where an
 * axis line crosses a surface on which another axis' orientation flips
 * (T's minimum along that axis), its nodes lie in two sweeps, and half of
 * such links run against the order of the sweeps whatever it is: with
 * one point source the count is higher than the orthant pass's, so the
 * pass stays there (see paper1_fastsweeping/eik/notes).
 *
 * Kinks.  WENO5 is replaced by WENO3 within 3 nodes of obstacles and of
 * the lines where two sources' fronts meet, and nodes that their source
 * cannot see in a straight line are not factored, in either phase (mark_low,
 * sees, hide_shadows): without these the WENO5 iteration settled into a cycle
 * there (changes of 2e-5 to 4e-5 of the solution's scale for 1000
 * iterations) on a wall with a gap and on two meeting fronts.  Where the
 * speed varies by a large factor over a few cells WENO5's weights can
 * still swing from sweep to sweep and the iteration cycle; when the
 * largest change falls by less than half over 4 iterations, the nodes
 * that still move switch to WENO3 (demote_cycling).  An iteration that
 * converges never does.
 *
 * Under-resolved data.  On slowness maps with noise at the grid scale
 * no scheme has its order and the high order iterations cycled or ran
 * away (T = -1e153 at a grid corner of a 200 x 150 map of random
 * pixels).  Three safeguards degrade the order locally instead, each
 * node to the first order Godunov update, which is upwind and monotone:
 * nodes where f is rough at the grid scale, or that lie between such
 * nodes, from the start (mark_rough); a node whose high order value
 * comes before its earliest neighbour (safeguard_ok); and, if the
 * iteration still stops converging, the nodes that still move
 * (demote_first, every node in its last round).  None of them acts on
 * the convergence study's cases; hj_eik_stats.first_order counts the
 * nodes they touched.  Their first order update averages the slowness
 * along its upwind links (godunov_links): along a speed step the node's
 * own slowness over the cell behind it left an O(h) error past the step
 * that the higher orders carried along the rays. */
#include "hj_eik.h"
#include "hj_eik_guard.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif

enum { GH = 3 };                                  /* ghost layers: WENO5 reaches i +- 3 */
/* ST_SRC: a node near a point source during the first order phase; its
 * source's time there is a bound, not a value (a later source can be
 * overtaken by an earlier one). */
/* First order phase: relative change of tau that unlocks the neighbours
 * (see visit).  1e-13 saved a third more local solves but let the errors
 * of the exact constant-speed case grow to 4e-12 (N = 320, 2-D); 1e-14
 * keeps them at rounding level (5e-13 there, 8e-13 with exact locking). */
#define FIRST_LOCK 1e-14
/* Stall test (an order 3 iteration dropping the relaxation, demote_first):
 * the largest change of a block of STALL_SPAN iterations at least
 * STALL_RATIO times that of the block before.  WENO5 cycles
 * (demote_cycling): at most STALL_ROUNDS demotions, each of the nodes
 * whose change in the last iteration was at least STALL_FRAC of the
 * largest.  With
 * 0.1 instead of 0.01 the cycle moved on to the next nodes after each
 * demotion (3-D 40^3, speed 1 + 0.5 sin(x/7) cos(y/5): 154 iterations
 * instead of 108). */
enum { STALL_SPAN = 8, STALL_ROUNDS = 8 };
/* The WENO5 cycle test itself (demote_cycling) looks at blocks of
 * CYCLE_SPAN iterations and fires when a block's largest change is at
 * least CYCLE_RATIO times the last block's (the change falls by less than
 * 0.84 per iteration): on the 40 x 40 map of speed 1 + 0.5 sin(x/7)
 * cos(y/5) one node next to the boundary moved up and down by 0.1 in
 * alternate sweeps while the largest change fell by only 2.5 % per
 * iteration, which the stall test above (blocks of 8, 0.9) took 100
 * iterations to see.  Converging WENO5 iterations fall by a factor
 * 1.7 or more per iteration (the convergence study, up to N = 640 in
 * 2-D), 0.12 or less over a block, and never reach it. */
enum { CYCLE_SPAN = 4 };
#define CYCLE_RATIO 0.5
/* The rounding level of the largest change, relative to max |T|: the
 * change levels off there, whatever tol asks (the one source of the
 * linear speed 1 + 0.5 x + 0.3 y on [0, 1]^2, its maximum over 150
 * iterations in the plateau: 1.4e-13, 3.0e-13, 8.9e-13, 2.6e-12 at N =
 * 40, 80, 160, 320, orders 3 and 5; 3-D 1.0e-13 and 2.0e-13 at N = 20 and
 * 40), about 2 to 5 eps n^1.5 with n the most nodes along a dimension.
 * ROUND_LEVEL eps n^1.5, at least 1e-12, keeps a margin of 3 over those;
 * a plateau below it is no stall or cycle to demote nodes for (with the
 * 1e-12 alone the 2-D N = 320 order 5 case demoted 30591 nodes to first
 * order at tol = 1e-12, L1 2.3e-6 instead of 3e-12), and it ends the
 * iteration: tol is below what round-off lets it reach. */
#define ROUND_LEVEL 16
/* ORTHANT_STALL: the orthant pass sweeps every axis line away from the
 * source, so first arrivals that come back toward the source along an
 * axis move one node per pass in it: head waves, in a slow layer above
 * a fast one (speed 1 above y = 99.5, 2 below, on [0, 299] x [0, 199],
 * source (50.3, 150.6), order 3: 137, 546 and 670 passes at 1, 3 and 5
 * nodes per unit, and the stall and cycle tests below then demoted
 * nearly every node to the first order update: a mean error 1.77e-2 at 5
 * nodes per unit against 1.31e-2 at order 1).  When a block of
 * STALL_SPAN << dim passes has a largest change not below ORTHANT_RATIO
 * times the block before's (on blocks of their own, which the WENO5
 * demotions do not restart), the iteration goes on with the 2^dim full
 * sweeps, which carry arrivals in every direction, and the other tests
 * start afresh: 85 and 86 iterations then at 1 and 5 nodes per unit
 * (order 3; order 5 95 and 129), the result of full sweeps from the
 * start within 1.5e-4 of max T at spacing 1 (the two stop at other
 * points near the kinks where head and direct waves meet; 3.7e-5 at
 * 0.75, 7.6e-9 at 1/3).  It needs two whole blocks, 64 passes in
 * 2-D and 128 in 3-D: the convergence study's passes (at most 36) never
 * get there, nor do the varying-speed maps of the tests (same bits).
 * Tried: STALL_RATIO (0.9) instead let order 5 go on (221 and 291
 * passes at spacings 1 and 0.75, the demotions' drops passing the
 * test); the WENO5 cycle test's blocks (CYCLE_SPAN << dim, CYCLE_RATIO)
 * fired on a smooth varying slowness in 3-D at order 5 (40 x 36 x 30),
 * where the demotion had converged with less work (173 grid sweeps
 * against 256). */
#define ORTHANT_RATIO 0.1

/* Rounds of demote_first, the last one demoting every node. */
enum { FALL_ROUNDS = 4 };
#define STALL_RATIO 0.9
#define STALL_FRAC 0.01
/* Slope of a higher order term in a sweep against its side's flow, in
 * units of the plain T0 / h (see the head of this file). */
#define AGAINST_SLOPE 1.25
enum { ST_GHOST = 0, ST_FREE, ST_FIXED, ST_OBST, ST_UNREACH, ST_SRC };

hj_eik_options hj_eik_default_options(void)
{
    hj_eik_options o;
    memset(&o, 0, sizeof o);
    o.order = 3;
    o.factored = 1;
    o.tol = 1e-10;
    o.max_iter = 1000;
    return o;
}

typedef struct {
    double x[3];
    double s0, t0;     /* slowness and time at the source */
    double g[3], H[3][3]; /* gradient and Hessian of the slowness there */
    double fmin, fmax;    /* slowness range over the start region's box */
} src_info;

typedef struct {
    int dim;
    long n[3], P[3], st[3], G[3]; /* nodes, padded sizes, strides, ghost layers */
    size_t npad;
    double x0[3], h[3];
    double *tau, *T0, *fs; /* unknown, factor, slowness (padded) */
    int *own;              /* owning source, -1: none */
    unsigned char *low;    /* 1: WENO3 instead of WENO5 (near obstacles and
                            * where fronts of two sources meet) */
    int *lab;              /* first order phase: the source whose front
                            * reached the node first (-1: none, fixed data) */
    unsigned char *fo;     /* 1: the first order update from now on (the
                            * high order one was found untrustworthy
                            * there; see safeguard); NULL at order 1 */
    unsigned char *state;
    unsigned char *ufix;   /* 1: a node of the caller's fixed data (NULL:
                            * none); settled source nodes are ST_FIXED too */
    int *stamp;            /* last sweep that changed the node (locking) */
    float *chg;            /* order 5: largest change of T per node in the
                            * current iteration (NULL otherwise) */
    int *calc;             /* first order phase: last sweep that computed
                            * the node (-1: none yet); higher order phase:
                            * last sweep that changed it */
    float *dl;             /* higher order phase: tau's change in sweep
                            * calc (downwind relaxation) */
    int *odist;            /* with obstacles and factoring: each grid node's
                            * index distance (max over the axes) to the
                            * nearest obstacle node, for visible(); NULL
                            * otherwise */
    src_info *src;
    int nsrc;
    double eps3, eps5[3];
    double lock_tol; /* a change below this (in T) does not unlock neighbours */
    int relax;       /* downwind relaxation: 1 with the downwind change
                      * extrapolated, 0 none (an order 3 iteration that
                      * stalled) */
    unsigned char *sig; /* causal sweeps (NULL: none): bits 0 .. dim-1 the
                         * orientation of the sweep that solves the node
                         * (causal_sides), bit 7 set when it changed */
    int q0;          /* first sweep whose changes dl the relaxation reads */
} eik_work;

static void work_free(eik_work *w)
{
    free(w->ufix);
    free(w->tau);
    free(w->T0);
    free(w->fs);
    free(w->own);
    free(w->lab);
    free(w->low);
    free(w->fo);
    free(w->state);
    free(w->stamp);
    free(w->calc);
    free(w->odist);
    free(w->chg);
    free(w->dl);
    free(w->sig);
    free(w->src);
}

static inline double src_T0(const eik_work *w, int o, const double *x)
{
    if (o < 0) return 1.0;
    const src_info *s = &w->src[o];
    double r2 = 0;
    for (int d = 0; d < w->dim; d++) r2 += (x[d] - s->x[d]) * (x[d] - s->x[d]);
    return s->s0 * sqrt(r2);
}

static inline double src_tb(const eik_work *w, int o) { return o < 0 ? 0.0 : w->src[o].t0; }

/* Coordinates of padded node (i, j, k). */
static inline void node_x(const eik_work *w, const long ip[3], double x[3])
{
    for (int d = 0; d < 3; d++) x[d] = w->x0[d] + (double)(ip[d] - w->G[d]) * w->h[d];
}

/* tau of node nb expressed in the factorisation of owner o (x: nb's
 * coordinates). */
static inline double tau_in(const eik_work *w, int o, long nb, const double *x)
{
    const double t = w->tau[nb];
    if (w->own[nb] == o || !(t < INFINITY)) return t;
    const double T = src_tb(w, w->own[nb]) + w->T0[nb] * t;
    const double t0 = src_T0(w, o, x);
    return t0 > 0 ? (T - src_tb(w, o)) / t0 : INFINITY;
}

/* ---- one-sided WENO derivatives, as extrapolated neighbour values ----- */

/* WENO3's weights of the one-sided second order formulas for h D^- (*wm)
 * and h D^+ (*wp) on v[0..4] = tau at i-2..i+2 (Zhang, Zhao & Qian 2006). */
static inline void weno3_weights(const double *v, double eps, double *wm, double *wp)
{
    const double dc = v[3] - 2 * v[2] + v[1], dm = v[2] - 2 * v[1] + v[0], dp = v[2] - 2 * v[3] + v[4];
    const double den = eps + dc * dc;
    const double rm = (eps + dm * dm) / den, rp = (eps + dp * dp) / den;
    *wm = 1.0 / (1.0 + 2.0 * rm * rm), *wp = 1.0 / (1.0 + 2.0 * rp * rp);
}

/* WENO3 (Zhang, Zhao & Qian 2006): v[0..4] = tau at i-2..i+2; *hm = h D^-,
 * *hp = h D^+ (undivided).  *cm, *cp: how much hm and -hp grow when the
 * node and its downwind neighbours (i..i+2 for hm, i-2..i for hp) all
 * move by 1, the weights held; *em, *ep: how much they grow when the
 * downwind neighbour j nodes away moves by j (see local_update). */
static inline void weno3(const double *v, double eps, double *hm, double *hp, double *cm, double *cp, double *em,
                         double *ep)
{
    double wm, wp;
    weno3_weights(v, eps, &wm, &wp);
    const double cen = 0.5 * (v[3] - v[1]);
    *hm = (1 - wm) * cen + wm * 0.5 * (3 * v[2] - 4 * v[1] + v[0]);
    *hp = (1 - wp) * cen + wp * 0.5 * (-3 * v[2] + 4 * v[3] - v[4]);
    *cm = 0.5 + wm;
    *cp = 0.5 + wp;
    *em = 0.5 * (1 - wm);
    *ep = 0.5 * (1 - wp);
}

/* Jiang & Peng's unnormalised WENO5 weights a[0..2] of the three
 * candidate stencils on the undivided differences d1..d5. */
static inline void weno5_alphas(double d1, double d2, double d3, double d4, double d5, double eps, double *a)
{
    const double q = d1 - 2 * d2 + d3, b = d1 - 4 * d2 + 3 * d3;
    const double cc = d2 - 2 * d3 + d4, e = d2 - d4;
    const double f = d3 - 2 * d4 + d5, g = 3 * d3 - 4 * d4 + d5;
    const double s1 = 13.0 / 12 * q * q + 0.25 * b * b;
    const double s2 = 13.0 / 12 * cc * cc + 0.25 * e * e;
    const double s3 = 13.0 / 12 * f * f + 0.25 * g * g;
    a[0] = 0.1 / ((eps + s1) * (eps + s1));
    a[1] = 0.6 / ((eps + s2) * (eps + s2));
    a[2] = 0.3 / ((eps + s3) * (eps + s3));
}

/* WENO5 of Jiang & Peng on the undivided differences d1..d5; *c: the
 * derivative of the result in d3 with the weights held, *c45: in d4 and
 * d5 together. */
static inline double weno5_one(double d1, double d2, double d3, double d4, double d5, double eps, double *c,
                               double *c45)
{
    const double p1 = d1 / 3 - 7 * d2 / 6 + 11 * d3 / 6;
    const double p2 = -d2 / 6 + 5 * d3 / 6 + d4 / 3;
    const double p3 = d3 / 3 + 5 * d4 / 6 - d5 / 6;
    double al[3];
    weno5_alphas(d1, d2, d3, d4, d5, eps, al);
    const double a1 = al[0], a2 = al[1], a3 = al[2];
    const double as = a1 + a2 + a3;
    *c = (11.0 / 6 * a1 + 5.0 / 6 * a2 + a3 / 3) / as;
    *c45 = (a2 / 3 + 2 * a3 / 3) / as;
    return (a1 * p1 + a2 * p2 + a3 * p3) / as;
}

/* v[0..6] = tau at i-3..i+3 (Jiang & Peng 2000, as in Xiong et al. 2010);
 * *cm, *cp, *em, *ep as in weno3: moving the node and its downwind
 * neighbours by 1 moves only the difference v[3] - v[2] (hp: v[4] - v[3]),
 * the third argument of weno5_one; moving the downwind neighbour j nodes
 * away by j moves the fourth and fifth by 1. */
static inline void weno5(const double *v, double eps, double *hm, double *hp, double *cm, double *cp, double *em,
                         double *ep)
{
    const double d0 = v[1] - v[0], d1 = v[2] - v[1], d2 = v[3] - v[2];
    const double d3 = v[4] - v[3], d4 = v[5] - v[4], d5 = v[6] - v[5];
    *hm = weno5_one(d0, d1, d2, d3, d4, eps, cm, em);
    *hp = weno5_one(d5, d4, d3, d2, d1, eps, cp, ep);
}

/* Held-weight coefficients of h D^- (km) and h D^+ (kp) on the stencil
 * v[0..2r] (r = 2: WENO3, 3: WENO5), with the weights of weno3 and
 * weno5_one on the same values. */
static void weno_coef(const double *v, int r, double eps, double *km, double *kp)
{
    if (r == 2) {
        double wm, wp;
        weno3_weights(v, eps, &wm, &wp);
        km[0] = 0.5 * wm, km[1] = -0.5 * (1 - wm) - 2 * wm, km[2] = 1.5 * wm, km[3] = 0.5 * (1 - wm), km[4] = 0;
        kp[0] = 0, kp[1] = -0.5 * (1 - wp), kp[2] = -1.5 * wp, kp[3] = 0.5 * (1 - wp) + 2 * wp, kp[4] = -0.5 * wp;
        return;
    }
    double dd[6];
    for (int j = 0; j < 6; j++) dd[j] = v[j + 1] - v[j];
    for (int side = 0; side < 2; side++) {
        /* weno5_one's arguments: d0..d4 for hm, d5..d1 for hp */
        double e[5];
        for (int j = 0; j < 5; j++) e[j] = side ? dd[5 - j] : dd[j];
        double al[3];
        weno5_alphas(e[0], e[1], e[2], e[3], e[4], eps, al);
        const double a1 = al[0], a2 = al[1], a3 = al[2];
        const double as = a1 + a2 + a3, o1 = a1 / as, o2 = a2 / as, o3 = a3 / as;
        const double g[5] = {o1 / 3, -7 * o1 / 6 - o2 / 6, 11 * o1 / 6 + 5 * o2 / 6 + o3 / 3, o2 / 3 + 5 * o3 / 6,
                             -o3 / 6};
        double cd[6] = {0, 0, 0, 0, 0, 0}; /* coefficient of dd[j] = v[j+1] - v[j] */
        for (int j = 0; j < 5; j++) cd[side ? 5 - j : j] += g[j];
        double *k = side ? kp : km;
        for (int j = 0; j <= 6; j++) k[j] = (j > 0 ? cd[j - 1] : 0) - (j < 6 ? cd[j] : 0);
    }
}

/* Weights of the quadratic extrapolation to the g-th ghost past a
 * boundary from the boundary node and the two before it (fill_ghosts
 * with degree 2). */
static const double ghost_w[4][3] = {{0, 0, 0}, {3, -3, 1}, {6, -8, 3}, {10, -15, 6}};

/* Stencil v[0..2r] of node id on a line of n >= 3 nodes: the entries past
 * the line's ends become the extrapolations of the current in-grid
 * entries (the three boundary nodes lie in the stencil whenever a ghost
 * does). */
static void current_ghosts(double *v, int r, long id, long n)
{
    for (int q = -r; q <= r; q++) {
        const long pos = id + q;
        if (pos > n - 1) {
            const long g = pos - (n - 1), b = n - 1 - id + r;
            v[q + r] = ghost_w[g][0] * v[b] + ghost_w[g][1] * v[b - 1] + ghost_w[g][2] * v[b - 2];
        }
    }
    for (int q = r; q >= -r; q--) {
        const long pos = id + q;
        if (pos < 0) {
            const long g = -pos, b = r - id;
            v[q + r] = ghost_w[g][0] * v[b] + ghost_w[g][1] * v[b + 1] + ghost_w[g][2] * v[b + 2];
        }
    }
}

/* The coefficients k[0..2r] of a stencil whose ghost entries are
 * extrapolations (current_ghosts), moved onto the in-grid entries. */
static void fold_ghosts(double *k, int r, long id, long n)
{
    for (int q = -r; q <= r; q++) {
        const long pos = id + q;
        if (pos >= 0 && pos <= n - 1) continue;
        const long g = pos > n - 1 ? pos - (n - 1) : -pos, b = pos > n - 1 ? n - 1 - id + r : r - id;
        const int dir = pos > n - 1 ? -1 : 1;
        for (int m = 0; m < 3; m++) k[b + m * dir] += k[q + r] * ghost_w[g][m];
        k[q + r] = 0;
    }
}

/* ---- the local Godunov solve ------------------------------------------- */

/* Smallest tau with sum_d (a_d tau - b_d)_+^2 = f^2 (a_d > 0). */
static inline double godunov_solve(int m, double *a, double *b, double f)
{
    double t[3];
    for (int d = 0; d < m; d++) t[d] = b[d] / a[d];
    /* insertion sort by threshold (m <= 3) */
    for (int i = 1; i < m; i++)
        for (int j = i; j > 0 && t[j] < t[j - 1]; j--) {
            double s = t[j]; t[j] = t[j - 1]; t[j - 1] = s;
            s = a[j]; a[j] = a[j - 1]; a[j - 1] = s;
            s = b[j]; b[j] = b[j - 1]; b[j - 1] = s;
        }
    double A = 0, B = 0, C = -f * f, tau = INFINITY;
    for (int k = 0; k < m; k++) {
        A += a[k] * a[k];
        B += a[k] * b[k];
        C += b[k] * b[k];
        const double disc = B * B - A * C;
        if (disc < 0) break;
        tau = (B + sqrt(disc)) / A;
        if (k + 1 == m || tau <= t[k + 1]) break;
    }
    return tau;
}

/* The Godunov update with the upwind side of each dimension d taken where
 * it gives the larger term: the smallest tau with
 *     sum_d max(al_d tau - bl_d, ar_d tau - br_d, 0)^2 + sum_j (a_j tau - b_j)_+^2 = f^2
 * (a side with al_d = 0 or ar_d = 0 is absent; (a, b, m): terms with a
 * fixed side).  The left side is a maximum over the side choices S of
 * increasing functions F_S, so the root is the smallest of the roots of
 * the F_S: starting from the sides sd, each pass takes the sides that are
 * largest at the last root, which can only lower it, until no side
 * changes.  The result is a continuous function of the data.  Choosing
 * the side from the neighbours' times instead (as the first order scheme
 * does) made the high order update jump where the two neighbours along
 * a dimension have nearly the same time (a valley of T along that axis):
 * the side flipped from sweep to sweep and the iteration cycled. */
static double godunov_max(int dim, const double *a, const double *b, int m, const double *al, const double *bl,
                          const double *ar, const double *br, int *sd, double f)
{
    double tau = INFINITY;
    for (int pass = 0; pass <= 2 * dim; pass++) {
        double A[3], B[3];
        int n = 0;
        for (int j = 0; j < m; j++, n++) {
            A[n] = a[j];
            B[n] = b[j];
        }
        for (int d = 0; d < dim; d++) {
            if (sd[d] < 0) continue;
            if (sd[d] == 0 ? !(al[d] > 0) : !(ar[d] > 0)) sd[d] = 1 - sd[d];
            if (sd[d] == 0 ? !(al[d] > 0) : !(ar[d] > 0)) continue;
            A[n] = sd[d] ? ar[d] : al[d];
            B[n] = sd[d] ? br[d] : bl[d];
            n++;
        }
        tau = n > 0 ? godunov_solve(n, A, B, f) : INFINITY;
        if (!(tau < INFINITY)) return tau;
        int changed = 0;
        for (int d = 0; d < dim; d++) {
            if (sd[d] < 0 || !(al[d] > 0) || !(ar[d] > 0)) continue;
            const double tl = al[d] * tau - bl[d], tr = ar[d] * tau - br[d];
            const double cur = sd[d] ? tr : tl, oth = sd[d] ? tl : tr;
            if (oth > cur && oth > 0) {
                sd[d] = 1 - sd[d];
                changed = 1;
            }
        }
        if (!changed) break;
    }
    return tau;
}

/* Neighbour nb (coordinates x with x[d] moved by dxd) of a node owned by
 * o: *t its tau in o's factorisation, *Tr its T - t0(o) (+INFINITY when
 * it has no value).  With the same owner Tr = T0[nb] tau[nb], the time
 * the neighbour holds, with no square root. */
static inline void neighbour(const eik_work *w, int o, long nb, const double *x, int d, double dxd, double *t,
                             double *Tr)
{
    *t = INFINITY;
    *Tr = INFINITY;
    if (w->state[nb] == ST_GHOST) return;
    const double v = w->tau[nb];
    if (w->own[nb] == o || !(v < INFINITY)) {
        *t = v;
        if (v < INFINITY) *Tr = w->T0[nb] * v;
        return;
    }
    double xn[3] = {x[0], x[1], x[2]};
    xn[d] = x[d] + dxd;
    const double T = src_tb(w, w->own[nb]) + w->T0[nb] * v;
    const double t0 = src_T0(w, o, xn);
    *t = t0 > 0 ? (T - src_tb(w, o)) / t0 : INFINITY;
    if (*t < INFINITY) *Tr = t0 * *t;
}

/* Adds dimension d's upwind term to (a, b, m) from the neighbour values
 * nl, nr (tau at x -/+ h, or their WENO extrapolations) whose times
 * (T - t0) are Tl, Tr: the upwind side is the given one if its value is
 * finite, else (side < 0 too) the one with the smaller time. */
static inline int add_term(const eik_work *w, int o, double T0, const double *x, int d, double nl, double nr,
                           double Tl, double Tr, int side, double *a, double *b, int *m)
{
    const double h = w->h[d];
    if (!(Tl < INFINITY) && !(Tr < INFINITY)) return -1;
    const double p = o >= 0 ? w->src[o].s0 * w->src[o].s0 * (x[d] - w->src[o].x[d]) / T0 : 0;
    if (side < 0 || !((side ? Tr : Tl) < INFINITY)) side = Tl <= Tr ? 0 : 1;
    if (side == 0) {
        a[*m] = T0 / h + p;
        b[*m] = T0 * nl / h;
    } else {
        a[*m] = T0 / h - p;
        b[*m] = T0 * nr / h;
    }
    if (a[*m] > 0) (*m)++;
    return side;
}

/* Is the high order value v (tau) of a node causal?  v1: the first order
 * Godunov value of the same neighbours, Tmin: the earliest of those
 * neighbours' times (T - t0), T0: the node's factor.  The front reaches
 * a node after the neighbour it comes from, so T0 v must be later than
 * Tmin, unless the first order value is not either: next to a point
 * source between nodes the node nearest to it is earlier than its
 * neighbours (the test fired there once on the tests' sin map, 2-D,
 * order 5, before this exception).  Where the slowness jumps from cell
 * to cell the WENO extrapolations follow the noise and can break this:
 * the clamp of local_update (within f h of v1) alone did not stop the
 * iteration from running away on such maps (T = -1e153 at a grid corner
 * of a 200 x 150 map of random pixels): v1 - f h is up to 0.3 f h before
 * the earliest neighbour, so nodes that feed each other's WENO stencils
 * could sink by that much at every sweep, and the factored first order
 * value amplifies a negative time outwards (by T0(x) / T0(neighbour)
 * per node).  A node that fails is switched to the first order update
 * for good (visit): upwind and monotone there, while the rest of the
 * grid keeps its order. */
static inline int safeguard_ok(double v, double v1, double Tmin, double T0)
{
    return T0 * v > Tmin || !(T0 * v1 > Tmin);
}

/* The first order update of a node that orders 3 and 5 leave at first
 * order (fo: along a speed step, on rough maps), with the slowness
 * averaged along its upwind links.  The plain update takes the node's own
 * slowness f_k over the whole cell behind it; where the slowness steps
 * between the node and its upwind neighbour that is an O(h) error at the
 * step (the map does not say where between the two nodes the step lies:
 * the plain update puts it at the upwind node), about -0.3 h in T on the
 * first nodes past a step from slowness 1 to 1/2, which the higher
 * orders then carry along the rays unchanged.  Here the term of
 * dimension d stands for a share s_d = (a_d tau - b_d)_+^2 / f^2 of the
 * squared gradient (the shares sum to 1 at the root), and the slowness is
 * f_k + sum_d s_d (f_d - f_k) / 2, f_d the slowness of that term's
 * neighbour: the trapezoid rule along the link, exact for a step halfway
 * between the nodes (or the map interpolated linearly) along an axis, and
 * a convex combination of the slownesses around, so the update stays
 * within their range.  Three passes (the shares from the last root).  On
 * the two-medium square (slowness 1 | 1/2 at x = 0.5, halfway between two
 * nodes, a source at (0.25, 0.5)) order 3's mean error went from 1.93e-3
 * to 4.7e-4 at N = 51 and from 3.4e-4 to 5.3e-5 at N = 401 (order 1:
 * 8.0e-4 and 1.05e-4); paper1_fastsweeping/eik/notes/eikonal-tool.md.
 * Smooth maps have no such nodes.  (a, b, m): the terms in the order
 * local_update built them (godunov_solve sorts its own copies), fn their
 * neighbours' slownesses, v the root with f_k. */
static double godunov_links(int m, const double *a, const double *b, const double *fn, double fk, double v)
{
    double f = fk;
    for (int pass = 0; pass < 3 && v < INFINITY; pass++) {
        double fe = fk, aa[3], bb[3];
        for (int j = 0; j < m; j++) {
            const double t = a[j] * v - b[j];
            if (t > 0) fe += t * t / (f * f) * 0.5 * (fn[j] - fk);
            aa[j] = a[j], bb[j] = b[j];
        }
        f = fe;
        v = godunov_solve(m, aa, bb, f);
    }
    return v;
}

/* New tau at padded node k (padded index ip, coordinates x) with the
 * scheme of `order` in sweep orientation sw.  A higher order term
 * relaxed downwind (see the head of this file) keeps at least half the
 * plain slope: near a source p can cancel most of T0 c / h.
 * The downwind relaxation uses an upwind neighbour's change (dl) only if
 * a sweep numbered q0 or later made it: the current sweep, or with causal
 * sweeps the current iteration's (the neighbour's sweep then precedes the
 * node's or is the same).
 * A higher order value that fails safeguard_ok is replaced by the first
 * order one and *fell is set.  Else it is clamped to within f h (in T)
 * of the first order update of the same stencil: on smooth data the two
 * differ by O(h^2), so the clamp only acts where WENO's extrapolations go
 * wild (kinks, corners next to obstacles, fronts crossing in a smooth
 * but strongly varying medium); a clamp rather than a switch keeps the
 * update continuous there (a switch made 11 nodes of a smooth 8-bit
 * speed image first order at order 5). */
static double local_update(const eik_work *w, long k, const long ip[3], const double *x, int order, int sw, int q0,
                           int *fell)
{
    const int o = w->own[k];
    const double T0 = w->T0[k];
    double a[3], b[3], a1[3], b1[3], fn1[3];
    /* high order: both sides' terms per dimension (a = 0: none) */
    double al[3] = {0, 0, 0}, bl[3] = {0, 0, 0}, ar[3] = {0, 0, 0}, br[3] = {0, 0, 0};
    int sd[3] = {-1, -1, -1};
    int m = 0, m1 = 0, high = 0;
    double Tmin = INFINITY; /* earliest neighbour (safeguard_ok) */
    for (int d = 0; d < w->dim; d++) {
        const long st = w->st[d];
        const double h = w->h[d];
        double nl1, nr1, Tl1, Tr1; /* first order neighbour values and times */
        neighbour(w, o, k - st, x, d, -h, &nl1, &Tl1);
        neighbour(w, o, k + st, x, d, h, &nr1, &Tr1);
        Tmin = Tl1 < Tmin ? Tl1 : Tmin;
        Tmin = Tr1 < Tmin ? Tr1 : Tmin;
        const int m1o = m1;
        const int side = add_term(w, o, T0, x, d, nl1, nr1, Tl1, Tr1, -1, a1, b1, &m1);
        if (m1 > m1o) fn1[m1 - 1] = w->fs[k + (side ? st : -st)];
        if (order == 1) continue;
        double xn[3] = {x[0], x[1], x[2]};
        const int R = order == 5 && !w->low[k] ? 3 : 2;
        double v[7];
        int ok = 1;
        for (int q = -R; q <= R; q++) {
            xn[d] = x[d] + q * h;
            v[q + R] = q == 0 ? w->tau[k] : tau_in(w, o, k + q * st, xn);
            /* a stencil reaching into another source's nodes straddles
             * the kink where the two fronts meet: lower order there */
            if (q != 0 && w->own[k + q * st] != o) v[q + R] = NAN;
            /* nor across the caller's fixed data into free nodes beyond:
             * T grows away from a fixed line on both sides (a kink), and
             * WENO3's weight of a stencil across it (eps3 not scaled with
             * h) left an error growing as h^-3 */
            if (w->ufix && (q < -1 || q > 1) && w->state[k + q * st] == ST_FREE)
                for (int j = q < 0 ? -1 : 1; j != q; j += q < 0 ? -1 : 1)
                    if (w->ufix[k + j * st]) v[q + R] = NAN;
            ok = ok && isfinite(v[q + R]);
        }
        int ord = R == 3 ? 5 : 3;
        if (!ok && R == 3) { /* WENO5 stencil cut: try WENO3 */
            ok = 1;
            for (int q = 1; q <= 5; q++) ok = ok && isfinite(v[q]);
            if (ok) memmove(v, v + 1, 5 * sizeof v[0]);
            ord = 3;
        }
        if (ok) {
            const long id = ip[d] - w->G[d], nd = w->n[d];
            const int rs = ord == 5 ? 3 : 2;
            /* a stencil reaching the ghosts takes them from the current
             * values (see the head of this file) */
            const int edge = !(id >= R && id <= nd - 1 - R) && nd >= 3;
            if (edge) current_ghosts(v, rs, id, nd);
            double hm, hp, cm, cp, em, ep;
            if (ord == 5) weno5(v, w->eps5[d], &hm, &hp, &cm, &cp, &em, &ep);
            else weno3(v, w->eps3, &hm, &hp, &cm, &cp, &em, &ep);
            double gm = 0, gp = 0; /* the node's own coefficient in hm and -hp, ghosts included */
            if (edge) {
                /* cm, em, cp, ep as in weno3 over the in-grid nodes, the
                 * ghosts moving with the nodes they extrapolate */
                double km[7], kp[7];
                weno_coef(v, rs, ord == 5 ? w->eps5[d] : w->eps3, km, kp);
                fold_ghosts(km, rs, id, nd);
                fold_ghosts(kp, rs, id, nd);
                gm = cm = km[rs];
                gp = cp = -kp[rs];
                em = ep = 0;
                for (int j = 1; j <= rs; j++) {
                    cm += km[rs + j], em += j * km[rs + j];
                    cp -= kp[rs - j], ep -= j * kp[rs - j];
                }
            }
            const double p = o >= 0 ? w->src[o].s0 * w->src[o].s0 * (x[d] - w->src[o].x[d]) / T0 : 0;
            const double tk = w->tau[k], nl = tk - hm, nr = tk + hp, Tk = T0 * tk;
            /* downwind moving along: this sweep runs along d in the
             * direction of the side's flow (left side: forwards), so the
             * downwind neighbours still hold the previous sweep's values */
            const int inner = w->relax && ((id >= R && id <= nd - 1 - R) || edge), fwd = !((sw >> d) & 1);
            /* against the flow: the slope AGAINST_SLOPE (relaxation on),
             * and at least the node's own coefficient where the ghosts
             * move with it */
            const double base = w->relax ? AGAINST_SLOPE : 1.0;
            const double sl = gm > base ? gm : base, sr = gp > base ? gp : base;
            /* a side is a candidate if it is the first order one or its
             * neighbour is earlier than the node (both: a valley of T
             * along d); a later neighbour's side has a small a near a
             * source, and taking it let values run away there */
            if (T0 / h + p > 0 && (side == 0 || Tl1 < Tk)) {
                const double A = T0 / h + p;
                if (inner && fwd) {
                    /* downwind changes extrapolated linearly from the
                     * upwind neighbour's change du in this sweep */
                    const double du = w->calc[k - st] >= q0 ? w->dl[k - st] : 0, Ac = T0 * (cm + em) / h + p;
                    al[d] = Ac > 0.5 * A ? Ac : 0.5 * A;
                    bl[d] = al[d] * tk - (p * tk + T0 * (hm - em * du) / h);
                } else if (sl != 1.0) {
                    al[d] = T0 * sl / h + p;
                    bl[d] = al[d] * tk - (p * tk + T0 * hm / h);
                } else {
                    al[d] = A;
                    bl[d] = T0 * nl / h;
                }
            }
            if (T0 / h - p > 0 && (side == 1 || Tr1 < Tk)) {
                const double A = T0 / h - p;
                if (inner && !fwd) {
                    const double du = w->calc[k + st] >= q0 ? w->dl[k + st] : 0, Ac = T0 * (cp + ep) / h - p;
                    ar[d] = Ac > 0.5 * A ? Ac : 0.5 * A;
                    br[d] = ar[d] * tk + (p * tk + T0 * (hp + ep * du) / h);
                } else if (sr != 1.0) {
                    ar[d] = T0 * sr / h - p;
                    br[d] = ar[d] * tk + (p * tk + T0 * hp / h);
                } else {
                    ar[d] = A;
                    br[d] = T0 * nr / h;
                }
            }
            sd[d] = side;
            high = 1;
        } else {
            add_term(w, o, T0, x, d, nl1, nr1, Tl1, Tr1, -1, a, b, &m);
        }
    }
    /* godunov_solve sorts its arguments: the links' update needs them as
     * they came (fo nodes only) */
    const int links = order == 1 && w->fo && w->fo[k] && m1 > 0;
    double ca[3], cb[3];
    for (int j = 0; links && j < m1; j++) ca[j] = a1[j], cb[j] = b1[j];
    double v1 = m1 > 0 ? godunov_solve(m1, a1, b1, w->fs[k]) : INFINITY;
    if (links) v1 = godunov_links(m1, ca, cb, fn1, w->fs[k], v1);
    if (order == 1 || !high) return v1;
    const double v = godunov_max(w->dim, a, b, m, al, bl, ar, br, sd, w->fs[k]);
    if (!safeguard_ok(v, v1, Tmin, T0)) {
        *fell = 1;
        return v1;
    }
    double hmin = w->h[0];
    for (int d = 1; d < w->dim; d++) hmin = w->h[d] < hmin ? w->h[d] : hmin;
    const double lim = w->fs[k] * hmin / T0;
    if (!(v >= v1 - lim)) return v < INFINITY || v1 == INFINITY ? v1 - lim : v1;
    return v > v1 + lim ? v1 + lim : v;
}

/* ---- sweeps ------------------------------------------------------------ */

/* Is node k's stencil (radius R along the axes) changed since sweep q-1? */
static inline int active(const eik_work *w, long k, int R, int q)
{
    if (w->stamp[k] >= q - 1) return 1;
    for (int d = 0; d < w->dim; d++)
        for (int r = 1; r <= R; r++)
            if (w->stamp[k - r * w->st[d]] >= q - 1 || w->stamp[k + r * w->st[d]] >= q - 1) return 1;
    return 0;
}

/* First order phase (order 1: the update reads the neighbours, not the
 * node itself): must node k be computed again in sweep q?  Only if a
 * neighbour changed after k's last computation: in a later sweep, or in
 * the same sweep but visited after k (downstream in that sweep's
 * orientation, sweep r being orientation (r - 1) mod 2^dim).  Any other
 * computation gives the value k already has, so skipping it keeps the
 * bits of the rule of active() while computing each change about once. */
static inline int active_first(const eik_work *w, long k, int q)
{
    const int c = w->calc[k];
    const int back = (c - 1) & ((1 << w->dim) - 1); /* bit d: dimension d swept backwards in sweep c */
    (void)q;
    for (int d = 0; d < w->dim; d++) {
        const int sl = w->stamp[k - w->st[d]], sr = w->stamp[k + w->st[d]];
        if (sl > c || sr > c) return 1;
        if (c > 0 && (((back >> d) & 1) ? sl == c : sr == c)) return 1;
    }
    return 0;
}

/* The source label of the neighbour with the smallest T: the front that
 * reached node k (first order phase; neighbours lie on other hyperplanes,
 * so this does not depend on the thread count). */
static inline int arrival_label(const eik_work *w, long k)
{
    double best = INFINITY;
    int lab = -1;
    for (int d = 0; d < w->dim; d++)
        for (int sgn = -1; sgn <= 1; sgn += 2) {
            const long nb = k + sgn * w->st[d];
            const unsigned char sn = w->state[nb];
            if (sn != ST_FREE && sn != ST_FIXED && sn != ST_SRC) continue;
            const double t = w->tau[nb];
            if (!(t < INFINITY)) continue;
            const double T = src_tb(w, w->own[nb]) + w->T0[nb] * t;
            if (T < best) {
                best = T;
                lab = w->lab[nb];
            }
        }
    return lab;
}

/* One node of a sweep; returns |change of T|. */
static inline double visit(eik_work *w, const long ip[3], int sw, int order, int q, int first, size_t *nup)
{
    const long k = ip[0] * w->st[0] + ip[1] * w->st[1] + ip[2] * w->st[2];
    if (w->state[k] != ST_FREE && !(first && w->state[k] == ST_SRC)) return 0;
    if (!first && w->sig) {
        /* causal sweeps: only the nodes of this orientation, each active
         * if its stencil changed since its sweep of the last iteration
         * (nsw sweeps ago) or its orientation changed */
        const unsigned char sg = w->sig[k];
        if ((sg & 0x7f) != sw) return 0;
        if (!(sg & 0x80) && !active(w, k, (order + 1) / 2, q - (1 << w->dim) + 1)) return 0;
        w->sig[k] = (unsigned char)sw;
    } else if (first ? !active_first(w, k, q) : !active(w, k, (order + 1) / 2, q)) {
        return 0;
    }
    double x[3];
    node_x(w, ip, x);
    const double old = w->tau[k];
    int fell = 0;
    double v = local_update(w, k, ip, x, w->fo && w->fo[k] ? 1 : order, sw, w->q0, &fell);
    if (fell) w->fo[k] = 1; /* the node's own flag: the same for any thread count */
    (*nup)++;
    if (first) {
        w->calc[k] = q;
        /* a source-region node gives up its source's time only to a
         * clearly earlier arrival, not to rounding */
        if (!(v < (w->state[k] == ST_SRC ? old - 1e-12 * fabs(old) : old))) return 0;
        w->lab[k] = arrival_label(w, k);
    } else if (!isfinite(v) || v == old) {
        return 0;
    }
    w->tau[k] = v;
    if (!first) {
        w->dl[k] = old < INFINITY ? (float)(v - old) : 0;
        w->calc[k] = q;
    }
    const double dT = old < INFINITY ? fabs(w->T0[k] * (old - v)) : INFINITY;
    /* First order phase: a change at rounding level (below FIRST_LOCK of
     * tau) does not unlock the neighbours.  Exact locking let values
     * creep down by a few ulps sweep after sweep: in the 3-D distance
     * (N = 100) 300 000 to 400 000 such changes per sweep of the second
     * iteration, half the work of the solve. */
    if (first ? fabs(old - v) > FIRST_LOCK * fabs(v) : dT > w->lock_tol) w->stamp[k] = q;
    if (w->chg && dT > w->chg[k]) w->chg[k] = (float)dT;
    return dT;
}

/* The nodes of one block in sweep coordinates (u: block index per
 * dimension within the box [lo, hi) of nodes), in the sweep's
 * lexicographic order; returns the largest change of T. */
static double sweep_block(eik_work *w, int s, const long lo[3], const long hi[3], const long u[3], const long B[3],
                          int order, int q, int first, size_t *nu)
{
    const long m0 = hi[0] - lo[0], m1 = hi[1] - lo[1], m2 = hi[2] - lo[2];
    const int s0 = s & 1, s1 = (s >> 1) & 1, s2 = (s >> 2) & 1;
    const long i0 = u[0] * B[0], j0 = u[1] * B[1], k0 = u[2] * B[2];
    const long i1 = i0 + B[0] < m0 ? i0 + B[0] : m0, j1 = j0 + B[1] < m1 ? j0 + B[1] : m1,
               k1 = k0 + B[2] < m2 ? k0 + B[2] : m2;
    double change = 0;
    for (long kk = k0; kk < k1; kk++)
        for (long jj = j0; jj < j1; jj++)
            for (long ii = i0; ii < i1; ii++) {
                const long ip[3] = {(s0 ? hi[0] - 1 - ii : lo[0] + ii) + w->G[0],
                                    (s1 ? hi[1] - 1 - jj : lo[1] + jj) + w->G[1],
                                    (s2 ? hi[2] - 1 - kk : lo[2] + kk) + w->G[2]};
                const double c = visit(w, ip, s, order, q, first, nu);
                if (c > change) change = c;
            }
    return change;
}

/* Sweep q in orientation s (bit d set: dimension d backwards); returns the
 * largest change of T.  The grid is cut into blocks of B[d] nodes and the
 * blocks are taken by hyperplanes I + J (+ K) = const of block indices in
 * the sweep's orientation, the nodes of a block in the sweep's
 * lexicographic order.  A node's update reads only nodes on its own axis
 * lines, and along every axis line this order visits the nodes in the
 * same order as the plain lexicographic sweep or the node hyperplanes of
 * Detrixhe, Gibou & Min (2013) (the block size 1): all give the same bits.
 * Two blocks of one hyperplane share no axis line, so they are swept in
 * parallel (a hyperplane of at least par_min nodes); one block (the whole
 * grid) is the serial sweep, whose memory access runs along the rows:
 * node hyperplanes touch a new cache line at every node, which made the
 * serial 3-D sweep several times slower. */
static double sweep(eik_work *w, int s, const long lo[3], const long hi[3], int order, int q, int first, long par_min,
                    const long B[3], size_t *nup)
{
    long nb[3], Lmax = 0;
    for (int d = 0; d < 3; d++) {
        nb[d] = (hi[d] - lo[d] + B[d] - 1) / B[d];
        Lmax += nb[d] - 1;
    }
    double change = 0;
    size_t nu = 0;
    for (long L = 0; L <= Lmax; L++) {
        /* blocks (I, J, K) with I + J + K = L, numbered by (K, J) */
        const long klo = L - (nb[0] - 1) - (nb[1] - 1) > 0 ? L - (nb[0] - 1) - (nb[1] - 1) : 0;
        const long khi = L < nb[2] - 1 ? L : nb[2] - 1;
        long count = 0;
        for (long K = klo; K <= khi; K++) {
            const long M = L - K;
            count += (M < nb[1] - 1 ? M : nb[1] - 1) - (M - (nb[0] - 1) > 0 ? M - (nb[0] - 1) : 0) + 1;
        }
        const int par = count > 1 && count * B[0] * B[1] * B[2] >= par_min;
#pragma omp parallel for if (par) schedule(static) reduction(max : change) reduction(+ : nu)
        for (long c = 0; c < count; c++) {
            /* the c-th block of the hyperplane */
            long K = klo, rest = c;
            for (;; K++) {
                const long M = L - K;
                const long jlo = M - (nb[0] - 1) > 0 ? M - (nb[0] - 1) : 0, jhi = M < nb[1] - 1 ? M : nb[1] - 1;
                if (rest <= jhi - jlo) {
                    const long J = jlo + rest, u[3] = {M - J, J, K};
                    const double ch = sweep_block(w, s, lo, hi, u, B, order, q, first, &nu);
                    if (ch > change) change = ch;
                    break;
                }
                rest -= jhi - jlo + 1;
            }
        }
    }
    *nup += nu;
    return change;
}

/* The orthants around source s: along dimension d the nodes below
 * cut[d] lie at or before the source (x <= s), the others after it. */
static void source_cut(const eik_work *w, const src_info *s, long cut[3])
{
    for (int d = 0; d < w->dim; d++) {
        const double u = floor((s->x[d] - w->x0[d]) / w->h[d]) + 1;
        cut[d] = u < 0 ? 0 : u > (double)w->n[d] ? w->n[d] : (long)u;
    }
}

/* T of node k for causal_sides: +INFINITY where no front arrives (ghost,
 * obstacle and unreachable nodes too). */
static inline double node_T(const eik_work *w, long k)
{
    const unsigned char sk = w->state[k];
    if (sk != ST_FREE && sk != ST_FIXED) return INFINITY;
    const double t = w->tau[k];
    return t < INFINITY ? src_tb(w, w->own[k]) + w->T0[k] * t : INFINITY;
}

/* Causal sweep orientations.  Bit d of sig[k] is set where the node's
 * earlier neighbour along d is k + st[d], the side the first order update
 * takes its term from (where both neighbours have the same time, or
 * neither has one, the bit stays); the sweep of that orientation runs
 * along the node's flow on every axis.  Bit 7 marks a node whose
 * orientation changed (it is solved in its new sweep whatever the
 * locking says).  box[s]: the nodes of orientation s lie in [lo, hi)
 * (box[s][0], box[s][1]; empty: lo >= hi). */
static void causal_sides(eik_work *w, long box[8][2][3])
{
    const int nsw = 1 << w->dim;
    for (int s = 0; s < nsw; s++)
        for (int d = 0; d < 3; d++) {
            box[s][0][d] = d < w->dim ? w->n[d] : 0;
            box[s][1][d] = d < w->dim ? 0 : 1;
        }
    for (long c = 0; c < w->n[2]; c++)
        for (long b = 0; b < w->n[1]; b++)
            for (long a = 0; a < w->n[0]; a++) {
                const long ip[3] = {a, b, c};
                const long k = (a + w->G[0]) * w->st[0] + (b + w->G[1]) * w->st[1] + (c + w->G[2]) * w->st[2];
                if (w->state[k] != ST_FREE) continue;
                const unsigned char old = w->sig[k];
                unsigned char sg = old & 0x7f;
                for (int d = 0; d < w->dim; d++) {
                    const double Tl = node_T(w, k - w->st[d]), Tr = node_T(w, k + w->st[d]);
                    if (Tr < Tl) sg = (unsigned char)(sg | 1 << d);
                    else if (Tl < Tr) sg = (unsigned char)(sg & ~(1 << d));
                }
                w->sig[k] = sg != (old & 0x7f) ? (unsigned char)(sg | 0x80) : (unsigned char)(sg | (old & 0x80));
                for (int d = 0; d < w->dim; d++) {
                    if (ip[d] < box[sg][0][d]) box[sg][0][d] = ip[d];
                    if (ip[d] + 1 > box[sg][1][d]) box[sg][1][d] = ip[d] + 1;
                }
            }
}

/* Block edges for the sweeps: the whole grid with one thread or on a grid
 * of fewer than 16 par_min nodes (a barrier per block hyperplane costs
 * more than it brings there: on a loaded 2-core machine the quick
 * convergence study ran 3.5 times slower with 2 threads than with 1);
 * else about four blocks per thread along each dimension (at least 8
 * nodes), so that the block hyperplanes keep the threads busy.  `block`
 * > 0 forces it. */
static void sweep_blocks(const eik_work *w, long block, long par_min, long B[3])
{
    int nth = 1;
#ifdef _OPENMP
    nth = omp_get_max_threads();
#endif
    double nodes = 1;
    for (int d = 0; d < w->dim; d++) nodes *= (double)w->n[d];
    if (nodes < 16.0 * (double)par_min) nth = 1;
    for (int d = 0; d < 3; d++) {
        long b = w->n[d];
        if (block > 0) b = block;
        else if (nth > 1) b = (w->n[d] + 4 * nth - 1) / (4 * nth);
        if (block <= 0 && b < 8) b = 8;
        B[d] = d < w->dim ? (b < w->n[d] ? b : w->n[d]) : 1;
    }
}

/* Parallel or serial sweeps, whichever runs faster where the solve runs.
 * The hyperplane blocks need a barrier per hyperplane, and a thread that
 * waits for one whose core is busy with other work waits for the
 * scheduler: beside other busy processes on the 2 cores, the 2-thread
 * solve of an 81^3 volume took 2.2 to 7 s of wall time at order 1 where
 * one thread took 1.2 s, the waiting threads spinning (libgomp's default
 * policy); idle, two threads took 0.92 s and one 1.19 s.  With the
 * choice below: 1.36-1.44 s beside one busy process, 0.89-0.96 s idle
 * (161^3, order 3, idle: 9.2-9.6 s against 9.0 s always parallel).  So each iteration times itself (wall clock per unit of
 * work: a local solve, or 1/16 for a node only checked for activity),
 * the first of a phase serially (the whole grid as one block: a slow
 * parallel probe costs more than a slow serial one), the second in
 * parallel, then the cheaper of the two, the other one measured
 * again every TUNE_PROBE iterations (the machine's load changes); the
 * higher order phase starts from the first order phase's ratio.  Every
 * block layout gives the same bits (see sweep), so the choice changes
 * the time, never the result.  Off (always the blocks of sweep_blocks)
 * with one thread, a block size given by the caller, always_parallel, or
 * without OpenMP. */
enum { TUNE_PROBE = 8 };
typedef struct {
    long Bp[3], Bs[3]; /* the parallel blocks (sweep_blocks) and the whole grid */
    int on, mode;      /* mode of this iteration: 0 parallel, 1 serial */
    double cost[2];    /* seconds per unit of work, last measured (0: none yet) */
    long it;           /* iterations of this phase */
    double t0, u0;     /* the iteration's start */
    double ratio;      /* cost[0] / cost[1] of the phase before (0: none) */
} sweep_tuner;

static double tune_clock(void)
{
#ifdef _OPENMP
    return omp_get_wtime();
#else
    return 0;
#endif
}

static void tuner_init(sweep_tuner *t, const eik_work *w, long block, int always, const long Bp[3])
{
    int nb = 1;
    for (int d = 0; d < 3; d++) {
        t->Bp[d] = Bp[d];
        t->Bs[d] = d < w->dim ? w->n[d] : 1;
        nb = nb && Bp[d] == t->Bs[d];
    }
    t->on = !always && block <= 0 && !nb; /* sweep_blocks cut the grid: more than one thread */
#ifndef _OPENMP
    t->on = 0;
#endif
    t->mode = 0, t->it = 0, t->cost[0] = t->cost[1] = 0, t->t0 = t->u0 = 0, t->ratio = 0;
}

/* A new phase: other costs per unit of work, but the ratio of the two
 * (the machine's) carries over; the first iteration runs in the faster
 * mode and the other one's cost is taken from the ratio until it is
 * measured again (every TUNE_PROBE iterations). */
static void tuner_reset(sweep_tuner *t)
{
    t->ratio = t->cost[0] > 0 && t->cost[1] > 0 ? t->cost[0] / t->cost[1] : 0;
    t->it = 0, t->cost[0] = t->cost[1] = 0;
}

/* The blocks of the next iteration; work: the units done so far. */
static const long *tuner_begin(sweep_tuner *t, double work)
{
    if (!t->on) return t->Bp;
    const int better = t->cost[1] < t->cost[0];
    if (t->cost[0] == 0 && t->cost[1] == 0 && t->ratio > 0) t->mode = t->ratio > 1;
    else t->mode = t->cost[1] == 0 ? 1 : t->cost[0] == 0 ? 0 : t->it % TUNE_PROBE == 0 ? !better : better;
    t->t0 = tune_clock(), t->u0 = work;
    return t->mode ? t->Bs : t->Bp;
}

static void tuner_end(sweep_tuner *t, double work)
{
    if (!t->on) return;
    const double dt = tune_clock() - t->t0, du = work - t->u0;
    if (du > 0 && dt > 0) {
        t->cost[t->mode] = dt / du;
        /* the other mode's from the phase before's ratio */
        if (t->ratio > 0 && t->cost[!t->mode] == 0)
            t->cost[!t->mode] = t->mode ? t->cost[1] * t->ratio : t->cost[0] / t->ratio;
    }
    t->it++;
}

/* The units of work done: local solves, and 1/16 for each node visited. */
static double tune_work(const hj_eik_stats *st, size_t np)
{
    return (double)st->updates + (double)st->sweeps * (double)np / 16;
}

/* Polynomial extrapolation of tau (degree deg, from deg+1 interior nodes)
 * into the ghost layers along each dimension, so that the WENO stencils
 * at the boundary keep their order (hj_fsm does the same with degree 2).
 * A ghost whose value changes is stamped with sweep q. */
static void fill_ghosts(eik_work *w, int deg, int q)
{
    static const double c[5][5] = {{1}, {2, -1}, {3, -3, 1}, {4, -6, 4, -1}, {5, -10, 10, -5, 1}};
    for (int d = 0; d < w->dim; d++) {
        const long st = w->st[d], n = w->n[d];
        const int e1 = d == 0 ? 1 : 0, e2 = d == 2 ? 1 : 2; /* the other dimensions */
        const long m1 = w->n[e1], m2 = e2 < w->dim ? w->n[e2] : 1;
        for (long b = 0; b < m2; b++)
            for (long a = 0; a < m1; a++) {
                long base = (a + w->G[e1]) * w->st[e1] + (b + w->G[e2]) * w->st[e2];
                for (int side = 0; side < 2; side++) {
                    /* k0: the boundary node, dir: outward step */
                    const long k0 = base + (side ? n - 1 + GH : GH) * st, dir = side ? st : -st;
                    for (int g = 1; g <= GH; g++) {
                        const long kg = k0 + g * dir;
                        double v = 0;
                        for (int j = 0; j <= deg; j++) v += c[deg][j] * w->tau[kg - (j + 1) * dir];
                        if (!(v == w->tau[kg])) { /* NaN-safe */
                            if (!(isnan(v) && isnan(w->tau[kg]))) w->stamp[kg] = q;
                            w->tau[kg] = v;
                        }
                    }
                }
            }
    }
}

/* ---- set-up and checks ------------------------------------------------- */

/* Slowness at x by multilinear interpolation over the non-obstacle corners
 * of the cell holding x. */
static double slowness_at(const eik_work *w, const double *x)
{
    long i0[3] = {0, 0, 0};
    double t[3] = {0, 0, 0};
    for (int d = 0; d < w->dim; d++) {
        double u = (x[d] - w->x0[d]) / w->h[d];
        long i = (long)floor(u);
        if (i > w->n[d] - 2) i = w->n[d] - 2;
        if (i < 0) i = 0;
        i0[d] = i;
        t[d] = u - (double)i;
        if (t[d] < 0) t[d] = 0;
        if (t[d] > 1) t[d] = 1;
    }
    double sum = 0, wsum = 0;
    for (int c = 0; c < (1 << w->dim); c++) {
        double wt = 1;
        long k = 0;
        for (int d = 0; d < w->dim; d++) {
            const int bit = (c >> d) & 1;
            wt *= bit ? t[d] : 1 - t[d];
            k += (i0[d] + bit + w->G[d]) * w->st[d];
        }
        if (w->state[k] == ST_OBST || wt == 0) continue;
        sum += wt * w->fs[k];
        wsum += wt;
    }
    return wsum > 0 ? sum / wsum : NAN;
}

/* Slowness at padded node k offset by `off` nodes along dimensions d, e
 * (NAN outside the grid or in an obstacle). */
static double f_off(const eik_work *w, const long ip[3], int d, int od, int e, int oe)
{
    long q[3] = {ip[0], ip[1], ip[2]};
    q[d] += od;
    q[e] += oe;
    for (int c = 0; c < w->dim; c++)
        if (q[c] < w->G[c] || q[c] >= w->n[c] + w->G[c]) return NAN;
    const long k = q[0] * w->st[0] + q[1] * w->st[1] + q[2] * w->st[2];
    return w->state[k] == ST_OBST ? NAN : w->fs[k];
}

/* Slowness, gradient and Hessian at source s by Taylor expansion from the
 * nearest node c (central differences, O(h^2) for f and its gradient,
 * which the r^2 term needs; a difference that would reach outside the
 * grid or into an obstacle is left out).  ip: c's padded index. */
static void source_taylor(const eik_work *w, src_info *s, const long ip[3])
{
    double fc = f_off(w, ip, 0, 0, 0, 0), g[3] = {0, 0, 0}, H[3][3] = {{0}};
    for (int d = 0; d < w->dim; d++) {
        const double h = w->h[d], fm = f_off(w, ip, d, -1, d, 0), fp = f_off(w, ip, d, 1, d, 0);
        if (isfinite(fm) && isfinite(fp)) {
            g[d] = (fp - fm) / (2 * h);
            H[d][d] = (fp - 2 * fc + fm) / (h * h);
        }
        for (int e = 0; e < d; e++) {
            const double a = f_off(w, ip, d, 1, e, 1), b = f_off(w, ip, d, 1, e, -1), c = f_off(w, ip, d, -1, e, 1),
                         q = f_off(w, ip, d, -1, e, -1);
            if (isfinite(a) && isfinite(b) && isfinite(c) && isfinite(q))
                H[d][e] = H[e][d] = (a - b - c + q) / (4 * h * w->h[e]);
        }
    }
    double dx[3] = {0, 0, 0};
    for (int d = 0; d < w->dim; d++) dx[d] = s->x[d] - (w->x0[d] + (double)(ip[d] - w->G[d]) * w->h[d]);
    double f = fc;
    for (int d = 0; d < w->dim; d++) {
        f += g[d] * dx[d];
        double hd = 0;
        for (int e = 0; e < w->dim; e++) {
            f += 0.5 * dx[d] * H[d][e] * dx[e];
            hd += H[d][e] * dx[e];
        }
        s->g[d] = g[d] + hd;
        for (int e = 0; e < 3; e++) s->H[d][e] = H[d][e];
    }
    if (f > 0 && isfinite(f)) s->s0 = f;
}

/* Smallest and largest slowness over the nodes (obstacles aside) within
 * hmax of source s along every dimension: the box that holds its start
 * region (see source_time's caller). */
static void source_range(const eik_work *w, src_info *s, double hmax)
{
    long lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    for (int d = 0; d < w->dim; d++) {
        const double u = (s->x[d] - w->x0[d]) / w->h[d], du = hmax / w->h[d] * (1 + 1e-12);
        lo[d] = (long)ceil(u - du);
        hi[d] = (long)floor(u + du);
        lo[d] = lo[d] < 0 ? 0 : lo[d];
        hi[d] = hi[d] > w->n[d] - 1 ? w->n[d] - 1 : hi[d];
    }
    s->fmin = INFINITY;
    s->fmax = 0;
    for (long c = lo[2]; c <= hi[2]; c++)
        for (long b = lo[1]; b <= hi[1]; b++)
            for (long a = lo[0]; a <= hi[0]; a++) {
                const long k = (a + w->G[0]) * w->st[0] + (b + w->G[1]) * w->st[1] + (c + w->G[2]) * w->st[2];
                if (w->state[k] == ST_OBST) continue;
                if (w->fs[k] < s->fmin) s->fmin = w->fs[k];
                if (w->fs[k] > s->fmax) s->fmax = w->fs[k];
            }
}

/* Travel time from source s to x by the expansion of T in r = |x - s|
 * along e = (x - s) / r: T = t0 + f r + (g.e) r^2 / 2
 * + (e.H e / 6 - (|g|^2 - (g.e)^2) / (24 f)) r^3 + O(r^4), from
 * |grad T|^2 = f^2 order by order (the r^3 term holds the ray's bending). */
static double source_time(const eik_work *w, const src_info *s, const double *x)
{
    double e[3] = {0, 0, 0}, r2 = 0;
    for (int d = 0; d < w->dim; d++) {
        e[d] = x[d] - s->x[d];
        r2 += e[d] * e[d];
    }
    const double r = sqrt(r2);
    if (r == 0) return s->t0;
    double ge = 0, g2 = 0, eHe = 0;
    for (int d = 0; d < w->dim; d++) {
        e[d] /= r;
        ge += s->g[d] * e[d];
        g2 += s->g[d] * s->g[d];
    }
    for (int d = 0; d < w->dim; d++)
        for (int c = 0; c < w->dim; c++) eHe += e[d] * s->H[d][c] * e[c];
    const double f = s->s0;
    return s->t0 + r * (f + r * (0.5 * ge + r * (eHe / 6 - (g2 - ge * ge) / (24 * f))));
}

/* Is the straight segment from x to y free of obstacle nodes?  Sampled
 * at a quarter of the smallest spacing; a sample counts its nearest node
 * (a ray grazing an obstacle corner counts as blocked). */
static int visible(const eik_work *w, const double *x, const double *y)
{
    double len = 0, hmin = w->h[0];
    for (int d = 0; d < w->dim; d++) {
        len += (y[d] - x[d]) * (y[d] - x[d]);
        if (w->h[d] < hmin) hmin = w->h[d];
    }
    const long ns = (long)ceil(4 * sqrt(len) / hmin);
    for (long i = 1; i < ns;) {
        const double t = (double)i / (double)ns;
        long k = 0;
        int inside = 1;
        for (int d = 0; d < w->dim; d++) {
            long j = lround((x[d] + t * (y[d] - x[d]) - w->x0[d]) / w->h[d]);
            if (j < 0 || j > w->n[d] - 1) inside = 0;
            j = j < 0 ? 0 : j > w->n[d] - 1 ? w->n[d] - 1 : j;
            k += (j + w->G[d]) * w->st[d];
        }
        if (w->state[k] == ST_OBST) return 0;
        /* Skip the samples that cannot reach an obstacle node: a sample
         * moves at most 1/4 of a spacing per step along every axis, so m
         * steps on its nearest node index is at most m / 4 + 1 away; with
         * the nearest obstacle D >= 3 away, the next 4 (D - 2) samples
         * are clear (3/4 of a spacing to spare for rounding).  The
         * samples tested are the same as without skipping. */
        const long D = w->odist && inside ? w->odist[k] : 0;
        i += D > 2 ? 4 * (D - 2) + 1 : 1;
    }
    return 1;
}

/* odist: the index distance max_d |i_d - j_d| from every grid node to the
 * nearest obstacle node, by the two raster passes of the chessboard
 * distance transform (exact for this metric with the 3^dim neighbours).
 * Returns nonzero when out of memory. */
static int obstacle_distance(eik_work *w)
{
    w->odist = malloc(w->npad * sizeof(int));
    if (!w->odist) return 1;
    const int far = (int)(w->n[0] + w->n[1] + w->n[2]);
    for (size_t k = 0; k < w->npad; k++) w->odist[k] = w->state[k] == ST_OBST ? 0 : far;
    for (int pass = 0; pass < 2; pass++) {
        const long s = pass == 0 ? 1 : -1; /* forward: the neighbours before the node; backward: after */
        for (long c0 = 0; c0 < w->n[2]; c0++)
            for (long b0 = 0; b0 < w->n[1]; b0++)
                for (long a0 = 0; a0 < w->n[0]; a0++) {
                    const long a = pass == 0 ? a0 : w->n[0] - 1 - a0, b = pass == 0 ? b0 : w->n[1] - 1 - b0,
                               c = pass == 0 ? c0 : w->n[2] - 1 - c0;
                    const long k = (a + w->G[0]) * w->st[0] + (b + w->G[1]) * w->st[1] + (c + w->G[2]) * w->st[2];
                    int best = w->odist[k];
                    for (long dc = -1; dc <= 1; dc++)
                        for (long db = -1; db <= 1; db++)
                            for (long da = -1; da <= 1; da++) {
                                /* lexicographically before (0, 0, 0) in the pass's order */
                                const long lex = dc != 0 ? dc : db != 0 ? db : da;
                                if (lex * s >= 0) continue;
                                const long an = a + da, bn = b + db, cn = c + dc;
                                if (an < 0 || an >= w->n[0] || bn < 0 || bn >= w->n[1] || cn < 0 || cn >= w->n[2])
                                    continue;
                                const int v = w->odist[k + da * w->st[0] + db * w->st[1] + dc * w->st[2]] + 1;
                                if (v < best) best = v;
                            }
                    w->odist[k] = best;
                }
    }
    return 0;
}

/* Can source o see grid node k, or for a ghost node the nearest grid node? */
static int sees(const eik_work *w, const long ip[3], int o)
{
    long q[3];
    for (int d = 0; d < 3; d++) {
        const long lo = w->G[d], hi = w->n[d] - 1 + w->G[d];
        q[d] = ip[d] < lo ? lo : ip[d] > hi ? hi : ip[d];
    }
    double x[3];
    node_x(w, q, x);
    return visible(w, x, w->src[o].x);
}

/* Nodes that their source cannot see in a straight line (behind an
 * obstacle, reached by rays bent around its corners) get label -2: no
 * factor.  There grad T is not along x - s, the factored update's
 * coefficients T0 / h -/+ p_d become small or change sign, and the
 * higher order iteration settled into a cycle (the wall example: changes
 * of 4e-5 of the scale for 1000 iterations at order 5); T itself is
 * smooth there away from the corners, so the plain scheme keeps the order. */
static void hide_shadows(eik_work *w)
{
    for (long c = w->G[2]; c < w->n[2] + w->G[2]; c++)
        for (long b = w->G[1]; b < w->n[1] + w->G[1]; b++)
            for (long a = w->G[0]; a < w->n[0] + w->G[0]; a++) {
                const long ip[3] = {a, b, c}, k = a + w->st[1] * b + w->st[2] * c;
                const int o = w->lab[k];
                if (o < 0 || w->state[k] == ST_FIXED) continue;
                /* the first order phase's owner is a source the node sees;
                 * none (-1) means it sees no source */
                if (o == w->own[k]) continue;
                double x[3];
                node_x(w, ip, x);
                if (w->own[k] < 0 || !visible(w, x, w->src[o].x)) w->lab[k] = -2;
            }
}

/* After the first order phase: a source-region node that kept its
 * source's time holds it from now on; one reached earlier from elsewhere
 * (an overtaken late source) becomes free.  With factoring, every node
 * then takes the factor of the source whose front actually reached it
 * (its label; a ghost node the label of the nearest grid node), not the
 * one estimated from the straight-line times, and tau is converted. */
static void settle_sources(eik_work *w, int factored, int has_obst)
{
    const size_t np = w->npad;
    for (size_t k = 0; k < np; k++)
        if (w->state[k] == ST_SRC) w->state[k] = w->stamp[k] ? ST_FREE : ST_FIXED;
    if (!factored) return;
    if (has_obst) hide_shadows(w);
    for (long c = 0; c < w->P[2]; c++)
        for (long b = 0; b < w->P[1]; b++)
            for (long a = 0; a < w->P[0]; a++) {
                const long ip[3] = {a, b, c}, k = a + w->st[1] * b + w->st[2] * c;
                long q[3];
                for (int d = 0; d < 3; d++) {
                    const long lo = w->G[d], hi = w->n[d] - 1 + w->G[d];
                    q[d] = ip[d] < lo ? lo : ip[d] > hi ? hi : ip[d];
                }
                const int lo = w->lab[q[0] + w->st[1] * q[1] + w->st[2] * q[2]];
                const int o = lo == -2 ? -1 : lo; /* -2: in a shadow, not factored */
                if (lo == -1 || o == w->own[k]) continue;
                double x[3];
                node_x(w, ip, x);
                const double T0 = src_T0(w, o, x), t = w->tau[k];
                if (t < INFINITY) {
                    const double T = src_tb(w, w->own[k]) + w->T0[k] * t;
                    w->tau[k] = T0 > 0 ? (T - src_tb(w, o)) / T0 : 1.0;
                }
                w->own[k] = o;
                w->T0[k] = T0;
            }
}

/* Marks bit 1 of m also on every node within 3 nodes of a marked one (a
 * 7^dim box, the reach of the WENO5 stencil), dimension by dimension;
 * other bits (4: a mark kept from before) are left as they are.  A
 * wrap-around at the padded row ends only marks ghost or extra nodes. */
static void dilate_box3(const eik_work *w, unsigned char *m)
{
    const size_t np = w->npad;
    for (int d = 0; d < w->dim; d++) {
        const long st = w->st[d];
        for (size_t k = 0; k < np; k++)
            if (m[k] & 1)
                for (int r = -3; r <= 3; r++) {
                    const long kk = (long)k + r * st;
                    if (kk >= 0 && (size_t)kk < np && !(m[kk] & 1)) m[kk] |= 2;
                }
        for (size_t k = 0; k < np; k++)
            if (m[k] & 2) m[k] = (unsigned char)((m[k] & 4) | 1);
    }
}

/* WENO5 is kept away from obstacles and from the lines where two sources'
 * fronts meet: a node within 3 nodes (a box, the reach of the WENO5
 * stencil) of an obstacle or of a node of another owner uses WENO3.  At
 * these kinks and corners the solution is not smooth, WENO5's weights
 * kept switching from one iteration to the next and the iteration settled
 * into a cycle (changes about 1e-5 of the solution's scale, no
 * convergence) while WENO3 converges; away from them the order stays 5. */
static void mark_low(eik_work *w)
{
    for (long c = w->G[2]; c < w->n[2] + w->G[2]; c++)
        for (long b = w->G[1]; b < w->n[1] + w->G[1]; b++)
            for (long a = w->G[0]; a < w->n[0] + w->G[0]; a++) {
                const long k = a + w->st[1] * b + w->st[2] * c;
                int mark = w->state[k] == ST_OBST;
                for (int d = 0; d < w->dim && !mark; d++) {
                    const unsigned char sn = w->state[k + w->st[d]];
                    mark = sn != ST_GHOST && sn != ST_OBST && w->own[k + w->st[d]] != w->own[k];
                }
                w->low[k] = (unsigned char)mark;
            }
    dilate_box3(w, w->low);
}

/* WENO5 can settle into a cycle instead of converging where the speed
 * varies by a large factor over a few cells: the smoothness indicators
 * of data resolved by only a few nodes per wavelength are of one size,
 * their ratios swing with each sweep's small changes, and so do the
 * weights (from (0.9, 0.1, 0) to (0.2, 0.7, 0.1) on one node in
 * consecutive sweeps; changes of 0.2-0.3 % of max T for ever on a 40 x 40
 * map, speed 1 + 0.5 sin(x/7) cos(y/5)).  WENO3's weights stay put there.
 * The nodes whose last change was at least STALL_FRAC of the
 * iteration's largest (change), and those within 3 nodes of them, use
 * WENO3 from now on and all nodes are made active (sweep q).  A converging iteration
 * never gets here, so its result does not change. */
static void demote_cycling(eik_work *w, double change, int q)
{
    const size_t np = w->npad;
    const float lim = (float)(STALL_FRAC * change);
    unsigned char *m = w->low;
    for (size_t k = 0; k < np; k++) {
        if (m[k]) m[k] = 4; /* kept: already WENO3 */
        if (w->chg[k] >= lim) m[k] |= 1;
        w->stamp[k] = q;
    }
    dilate_box3(w, m);
    for (size_t k = 0; k < np; k++) m[k] = m[k] ? 1 : 0;
}

/* Slowness maps with noise at the grid scale (independent random pixels,
 * layers a cell apart) are not resolved: T's gradient jumps from cell to
 * cell, no scheme has its order there, and the WENO extrapolations follow
 * the jumps (the iterations cycled, or ran away at a grid corner).  Such
 * nodes take the first order update from the start.  Along each axis,
 * with D1 the largest |first difference| of f over i-3..i+3 (WENO5's
 * reach) and D2 the largest |second difference| centred on i-1..i+1
 * (neighbours in obstacles or outside the grid left out), node i is
 * rough where
 *     D2 > ROUGH_RATIO D1   and   D2 > ROUGH_FLOOR f(i).
 * Resolved data has D2 / D1 of about k h (k the wave number) and at most
 * about 0.4 next to an extremum of f (D2 = f'' h^2 there, D1 = 2.5 f''
 * h^2): 0 on the tests' 1 + 0.5 sin(x / 7) cos(y / 5), where 0.5 over
 * i-2..i+2 caught 8 % of the nodes at the extrema; zero for linear and
 * constant fields.  Independent pixels give D2 / D1 of 1 to 2 (D2 <= 2 D1
 * always): 97.4-99.6 % of the nodes of the 200 x 150 random maps.  The
 * floor leaves alone noise too small to matter, in particular the 8-bit
 * steps of a smooth image (a step of 2 / 255 in speed is 1.6 % of f at
 * speed 0.5, and D2 reaches two steps: a floor of 1 % marked 10 % of
 * the nodes of 1 + 0.5 sin(x / 15) cos(y / 11) stored as an 8-bit PGM,
 * 5 % none; maps whose noise stays below it converged at both orders
 * before these safeguards).
 * A node with rough nodes within 3 on both sides along an axis is marked
 * too: every WENO stencil along that axis reads noise on both sides, and
 * the node can sit at a dip of tau between them whose WENO extrapolation
 * of the upwind side lies below the node itself, so that it sinks sweep
 * after sweep.  Such nodes, within a few cells of a source whose start
 * nodes (clamped expansions, see source_range) lie among rough nodes,
 * came out below the exact solution's bound T >= t0 + r min f on
 * random 12 x 10 maps of the tests (slowness 0.5-10): 3 of 400 maps with
 * the source at (3, 3), by up to 10 % at order 3 and 20 % at order 5; 5
 * of 300 with the source at (6, 5), up to 11 %; 1 of 100 40 x 30 maps, 2
 * % (safeguard_ok, the clamp and the result check passed them all).  With
 * the mark none is below it.  Along a speed step between regions of
 * constant speed the rough nodes lie on one side of the free ones and
 * nothing changes (examples/data/speed.pgm: the same bits). */
#define ROUGH_RATIO 0.6
#define ROUGH_FLOOR 0.05
static void mark_rough(eik_work *w)
{
    for (size_t k = 0; k < w->npad; k++) {
        if (w->state[k] != ST_FREE) continue;
        int rough = 0;
        for (int d = 0; d < w->dim && !rough; d++) {
            const long st = w->st[d];
            double fv[7];
            for (int r = -3; r <= 3; r++) {
                const long kk = (long)k + r * st;
                const unsigned char sk = w->state[kk];
                fv[r + 3] = sk == ST_GHOST || sk == ST_OBST ? NAN : w->fs[kk];
            }
            double D1 = 0, D2 = 0;
            for (int j = 0; j < 6; j++) {
                const double e = fabs(fv[j + 1] - fv[j]);
                if (e > D1) D1 = e; /* NaN compares false: left out */
            }
            for (int j = 2; j <= 4; j++) {
                const double e = fabs(fv[j + 1] - 2 * fv[j] + fv[j - 1]);
                if (e > D2) D2 = e;
            }
            rough = D2 > ROUGH_RATIO * D1 && D2 > ROUGH_FLOOR * w->fs[k];
        }
        w->fo[k] = (unsigned char)rough;
    }
    /* between rough nodes (bit 2 while marking, so that the new marks do
     * not propagate) */
    for (size_t k = 0; k < w->npad; k++) {
        if (w->state[k] != ST_FREE || w->fo[k]) continue;
        for (int d = 0; d < w->dim; d++) {
            int lo = 0, hi = 0;
            for (long r = 1; r <= 3; r++) {
                lo |= w->fo[k - (size_t)(r * w->st[d])] & 1;
                hi |= w->fo[k + (size_t)(r * w->st[d])] & 1;
            }
            if (lo && hi) w->fo[k] = 2;
        }
    }
    for (size_t k = 0; k < w->npad; k++) w->fo[k] = w->fo[k] != 0;
}

/* The last resort against a cycle (after demote_cycling's rounds at
 * order 5, after the relaxation is dropped at order 3): the nodes whose
 * last change was at least STALL_FRAC of the iteration's largest
 * (change), and those within 3 nodes of them, use the first order update
 * from now on (all of them when `all`), and all nodes are made active
 * (sweep q).  The first order update is monotone, so with every node
 * demoted the iteration is the first order one and converges; each round
 * leaves the nodes that stopped moving at their order.  A converging
 * iteration never gets here. */
static void demote_first(eik_work *w, double change, int q, int all)
{
    const size_t np = w->npad;
    const float lim = (float)(STALL_FRAC * change);
    for (size_t k = 0; k < np; k++) {
        w->fo[k] = all || w->fo[k] || w->chg[k] >= lim;
        w->stamp[k] = q;
    }
    dilate_box3(w, w->fo); /* leaves 0 / 1 */
}

/* Units.  The local solve squares products of f, T0 / h and tau (f^4 N^4
 * in its discriminant) and keeps changes of T in floats: a slowness of
 * 1e99 overflowed them (every node outside the source region came out
 * unreachable, with HJ_OK), 1e-100 underflowed them (T = 0).  |grad T| = f
 * is homogeneous: with f = 2^ef f' and x = 2^eh x', T = 2^(ef + eh) T'.
 * A largest slowness or spacing outside [2^-32, 2^32] is solved in the
 * units that bring it to [1, 2) (powers of two: exact); data inside is
 * solved as given, to the bit as before.  Returns the exponent e of
 * v = 2^e v' (0: as given). */
static int unit_exp(double v) { return v > 0x1p32 || v < 0x1p-32 ? ilogb(v) : 0; }

/* The exponent for the slowness: of its largest value outside obstacles;
 * 0 if a value is not finite and > 0 (the set-up reports it as given). */
static int slowness_exp(const hj_eik_grid *g, const double *f, double f_const, const unsigned char *obstacle)
{
    if (!f) return unit_exp(f_const);
    const size_t n = (size_t)g->n[0] * (size_t)g->n[1] * (size_t)(g->dim == 3 ? g->n[2] : 1);
    double fmax = 0;
    for (size_t u = 0; u < n; u++) {
        if (obstacle && obstacle[u]) continue;
        if (!(f[u] > 0) || !isfinite(f[u])) return 0;
        fmax = f[u] > fmax ? f[u] : fmax;
    }
    return fmax > 0 ? unit_exp(fmax) : 0;
}

static int check_input(const hj_eik_grid *g, const hj_eik_source *src, int nsrc, const hj_eik_options *opt,
                       double f_const, const double *f, hj_error *err)
{
    if (!g || !opt) return hj_error_set(err, HJ_EINVAL, "hj_eik_solve: NULL grid or options");
    if (g->dim != 2 && g->dim != 3) return hj_error_set(err, HJ_EINVAL, "grid dimension %d: must be 2 or 3", g->dim);
    const long nmin = opt->order == 1 ? 2 : opt->order;
    for (int d = 0; d < g->dim; d++) {
        if (g->n[d] < nmin)
            return hj_error_set(err, HJ_EINVAL, "grid: %ld node%s along dimension %d, order %d needs at least %ld",
                                g->n[d], hj_plural(g->n[d]), d, opt->order, nmin);
        if (!(g->dx[d] > 0) || !isfinite(g->dx[d]) || !isfinite(g->x0[d]))
            return hj_error_set(err, HJ_EINVAL, "grid: spacing %g and origin %g along dimension %d must be finite, "
                                                "spacing > 0", g->dx[d], g->x0[d], d);
    }
    if (g->dim == 2 && g->n[2] != 1) return hj_error_set(err, HJ_EINVAL, "2-D grid: n[2] must be 1, got %ld", g->n[2]);
    if (opt->order != 1 && opt->order != 3 && opt->order != 5)
        return hj_error_set(err, HJ_EINVAL, "order %d: must be 1, 3 or 5", opt->order);
    if (!(opt->tol >= 0) || !isfinite(opt->tol)) return hj_error_set(err, HJ_EINVAL, "tolerance %g: must be finite and >= 0", opt->tol);
    if (opt->max_iter < 1) return hj_error_set(err, HJ_EINVAL, "max_iter %ld: must be >= 1", opt->max_iter);
    if (opt->block < 0) return hj_error_set(err, HJ_EINVAL, "block %ld: must be >= 0 (0: chosen by the solver)", opt->block);
    if (opt->always_parallel != 0 && opt->always_parallel != 1)
        return hj_error_set(err, HJ_EINVAL, "always_parallel %d: must be 0 or 1", opt->always_parallel);
    if (opt->parallel_min < 0)
        return hj_error_set(err, HJ_EINVAL, "parallel_min %ld: must be >= 0 (0: the default)", opt->parallel_min);
    if (nsrc < 0) return hj_error_set(err, HJ_EINVAL, "sources: count %d: must be >= 0", nsrc);
    if (nsrc > 0 && !src) return hj_error_set(err, HJ_EINVAL, "sources: %d given with a NULL array", nsrc);
    if (opt->factored != 0 && opt->factored != 1)
        return hj_error_set(err, HJ_EINVAL, "factored %d: must be 0 or 1", opt->factored);
    if (opt->separate_sources != 0 && opt->separate_sources != 1)
        return hj_error_set(err, HJ_EINVAL, "separate_sources %d: must be 0 or 1", opt->separate_sources);
    if (!f && (!(f_const > 0) || !isfinite(f_const)))
        return hj_error_set(err, HJ_EINVAL, "constant slowness %g: must be finite and > 0", f_const);
    double npad = 1;
    for (int d = 0; d < g->dim; d++) npad *= (double)(g->n[d] + 2 * GH);
    if (npad > 4e9) return hj_error_set(err, HJ_ENOMEM, "grid of %.3g nodes (with ghost layers) is too large", npad);
    return HJ_OK;
}

/* The largest start time (fixed value, source time) in the solver's
 * units: the local solves square times, and beyond about 1.3e154 those
 * squares overflow, which would leave every node at +INFINITY, counted as
 * walled off. */
#define EIK_T_RANGE 1e150

/* One solve with every source and the fixed data together (the joint
 * solve).  fo_out (NULL: none): per node 1 where the result took the first
 * order update.  check_only: return after the input checks, before any
 * sweep. */
static int solve_joint(const hj_eik_grid *g, const double *f, double f_const, const unsigned char *obstacle,
                       const hj_eik_source *src, int nsrc, const double *fixed, const hj_eik_options *opt, double *T,
                       hj_eik_stats *st, unsigned char *fo_out, int check_only, hj_error *err)
{
    hj_eik_stats dummy;
    if (!st) st = &dummy;
    memset(st, 0, sizeof *st);
    if (!T) return hj_error_set(err, HJ_EINVAL, "hj_eik_solve: NULL output array");
    int rc = check_input(g, src, nsrc, opt, f_const, f, err);
    if (rc != HJ_OK) return rc;

    /* solver units (unit_exp): f = 2^ef f', x = 2^eh x', T = 2^et T' */
    double hmax_in = 0;
    for (int d = 0; d < g->dim; d++) hmax_in = g->dx[d] > hmax_in ? g->dx[d] : hmax_in;
    const int ef = slowness_exp(g, f, f_const, obstacle), eh = unit_exp(hmax_in), et = ef + eh;

    eik_work w;
    memset(&w, 0, sizeof w);
    w.dim = g->dim;
    for (int d = 0; d < 3; d++) {
        w.n[d] = d < g->dim ? g->n[d] : 1;
        w.G[d] = d < g->dim ? GH : 0;
        w.P[d] = w.n[d] + 2 * w.G[d];
        w.x0[d] = d < g->dim ? ldexp(g->x0[d], -eh) : 0;
        w.h[d] = d < g->dim ? ldexp(g->dx[d], -eh) : 1;
    }
    w.st[0] = 1;
    w.st[1] = w.P[0];
    w.st[2] = w.P[0] * w.P[1];
    w.npad = (size_t)(w.P[0] * w.P[1] * w.P[2]);
    const size_t np = w.npad;
    w.tau = malloc(np * sizeof(double));
    w.T0 = malloc(np * sizeof(double));
    w.fs = malloc(np * sizeof(double));
    w.own = malloc(np * sizeof(int));
    w.lab = malloc(np * sizeof(int));
    w.low = calloc(np, 1);
    w.state = calloc(np, 1);
    w.stamp = malloc(np * sizeof(int));
    w.calc = malloc(np * sizeof(int));
    w.src = malloc((size_t)(nsrc > 0 ? nsrc : 1) * sizeof(src_info));
    w.nsrc = nsrc;
    if (!w.tau || !w.T0 || !w.fs || !w.own || !w.lab || !w.low || !w.state || !w.stamp || !w.calc || !w.src) {
        work_free(&w);
        return hj_error_set(err, HJ_ENOMEM, "out of memory: the solver needs %.3g MB",
                            (double)np * (3 * sizeof(double) + 4 * sizeof(int) + 2) / 1e6);
    }
    for (size_t k = 0; k < np; k++) {
        w.tau[k] = INFINITY;
        w.T0[k] = 1;
        w.fs[k] = 0;
        w.own[k] = -1;
        w.lab[k] = -1;
        w.stamp[k] = 0;
        w.calc[k] = -1;
    }

    /* Nodes: state and slowness; bad values before anything else. */
    const long n0 = w.n[0], n1 = w.n[1], n2 = w.n[2];
    size_t nfixed = 0, nobst = 0;
    for (long c = 0; c < n2 && rc == HJ_OK; c++)
        for (long b = 0; b < n1 && rc == HJ_OK; b++)
            for (long a = 0; a < n0; a++) {
                const long u = a + n0 * (b + n1 * c);
                const long k = (a + w.G[0]) * w.st[0] + (b + w.G[1]) * w.st[1] + (c + w.G[2]) * w.st[2];
                if (obstacle && obstacle[u]) {
                    w.state[k] = ST_OBST;
                    nobst++;
                    if (fixed && !isnan(fixed[u])) {
                        rc = hj_error_set(err, HJ_EINVAL, "node (%ld, %ld, %ld) is both an obstacle and a fixed value",
                                          a, b, c);
                        break;
                    }
                    continue;
                }
                const double fv = f ? f[u] : f_const;
                if (!(fv > 0) || !isfinite(fv)) {
                    rc = hj_error_set(err, HJ_EINVAL, "slowness %g at node (%ld, %ld, %ld): must be finite and > 0 "
                                                      "outside obstacles", fv, a, b, c);
                    break;
                }
                w.fs[k] = ldexp(fv, -ef);
                w.state[k] = ST_FREE;
                if (opt->start && isfinite(opt->start[u]) && !(fabs(ldexp(opt->start[u], -et)) <= EIK_T_RANGE)) {
                    rc = hj_error_set(err, HJ_EINVAL, "start value %g at node (%ld, %ld, %ld) is out of range in the "
                                      "solver's units (times divided by 2^%d: |T| <= %g)", opt->start[u], a, b, c, et,
                                      EIK_T_RANGE);
                    break;
                }
                if (fixed && !isnan(fixed[u])) {
                    if (!isfinite(fixed[u])) {
                        rc = hj_error_set(err, HJ_EINVAL, "fixed value %g at node (%ld, %ld, %ld): must be finite or NaN",
                                          fixed[u], a, b, c);
                        break;
                    }
                    if (!(fabs(ldexp(fixed[u], -et)) <= EIK_T_RANGE)) {
                        rc = hj_error_set(err, HJ_EINVAL, "fixed value %g at node (%ld, %ld, %ld) is out of range in the "
                                          "solver's units (times divided by 2^%d: |T| <= %g)", fixed[u], a, b, c, et,
                                          EIK_T_RANGE);
                        break;
                    }
                    if (!w.ufix && !(w.ufix = calloc(np, 1))) {
                        rc = hj_error_set(err, HJ_ENOMEM, "out of memory: the fixed data's mask (%.3g MB)", np / 1e6);
                        break;
                    }
                    w.ufix[k] = 1;
                    w.state[k] = ST_FIXED;
                    nfixed++;
                }
            }
    /* Sources: inside the grid, not in an obstacle. */
    for (int s = 0; s < nsrc && rc == HJ_OK; s++) {
        long ip[3] = {0, 0, 0};
        for (int d = 0; d < 3; d++) {
            const double x = d < w.dim ? ldexp(src[s].x[d], -eh) : 0;
            w.src[s].x[d] = x;
            if (d >= w.dim) continue;
            const double u = (x - w.x0[d]) / w.h[d], tol = 1e-9;
            if (!isfinite(u) || u < -tol || u > (double)(w.n[d] - 1) + tol) {
                rc = hj_error_set(err, HJ_EINVAL, "source %d: coordinate %g along dimension %d is outside the grid "
                                                  "[%g, %g]", s + 1, src[s].x[d], d, g->x0[d], g->x0[d] + (double)(w.n[d] - 1) * g->dx[d]);
                break;
            }
            long i = lround(u);
            ip[d] = (i < 0 ? 0 : i > w.n[d] - 1 ? w.n[d] - 1 : i) + w.G[d];
        }
        if (rc != HJ_OK) break;
        if (!isfinite(src[s].t0)) {
            rc = hj_error_set(err, HJ_EINVAL, "source %d: time %g must be finite", s + 1, src[s].t0);
            break;
        }
        if (w.state[ip[0] * w.st[0] + ip[1] * w.st[1] + ip[2] * w.st[2]] == ST_OBST) {
            if (w.dim == 2)
                rc = hj_error_set(err, HJ_EINVAL, "source %d at (%g, %g) lies in an obstacle", s + 1,
                                  ldexp(w.src[s].x[0], eh), ldexp(w.src[s].x[1], eh));
            else
                rc = hj_error_set(err, HJ_EINVAL, "source %d at (%g, %g, %g) lies in an obstacle", s + 1,
                                  ldexp(w.src[s].x[0], eh), ldexp(w.src[s].x[1], eh), ldexp(w.src[s].x[2], eh));
            break;
        }
        w.src[s].t0 = ldexp(src[s].t0, -et);
        if (!(fabs(w.src[s].t0) <= EIK_T_RANGE)) {
            rc = hj_error_set(err, HJ_EINVAL, "source %d: time %g is out of range in the solver's units (times "
                                              "divided by 2^%d: |T| <= %g)", s + 1, src[s].t0, et, EIK_T_RANGE);
            break;
        }
        w.src[s].s0 = slowness_at(&w, w.src[s].x);
        if (!(w.src[s].s0 > 0)) {
            rc = hj_error_set(err, HJ_EINVAL, "source %d: no slowness around it (obstacles)", s + 1);
            break;
        }
        source_taylor(&w, &w.src[s], ip);
    }
    if (rc == HJ_OK && nsrc == 0 && nfixed == 0)
        rc = hj_error_set(err, HJ_EINVAL, "no source and no fixed node: nothing to propagate from");
    if (rc != HJ_OK || check_only) {
        work_free(&w);
        return rc;
    }

    /* Owners and factors (ghost nodes too: the WENO stencils reach them). */
    const int factored = opt->factored && nsrc > 0;
    double hmax = 0, Lmax = 0;
    for (int d = 0; d < w.dim; d++) {
        if (w.h[d] > hmax) hmax = w.h[d];
        const double L = (double)(w.n[d] - 1) * w.h[d];
        if (L > Lmax) Lmax = L;
    }
    for (int s = 0; s < nsrc; s++) source_range(&w, &w.src[s], hmax);
    /* Factoring is only for nodes their source sees in a straight line
     * (hide_shadows): in the first order phase too, where a factored
     * update behind a thin wall next to the source took T = |x - s| tau
     * through the wall (a one-node wall 1 node from the source: T 10.5
     * behind it where the way around is over 140). */
    const int shadows = factored && nobst > 0;
    if (shadows && obstacle_distance(&w)) {
        work_free(&w);
        return hj_error_set(err, HJ_ENOMEM, "out of memory: the obstacles' distance map needs %.3g MB",
                            (double)np * sizeof(int) / 1e6);
    }
    for (long c = 0; c < w.P[2]; c++)
        for (long b = 0; b < w.P[1]; b++)
            for (long a = 0; a < w.P[0]; a++) {
                const long ip[3] = {a, b, c}, k = a + w.st[1] * b + w.st[2] * c;
                double x[3];
                node_x(&w, ip, x);
                /* Source-region nodes: within one cell of a source, or
                 * closer than the largest spacing.  Their value is the
                 * expansion of T to r^3 (source_time), error O(h^4) in a
                 * smooth slowness; the straight-ray time r (f(s) + f(x)) / 2
                 * misses the ray's bending, O(h^3), which bounded every
                 * order at 3.  A user's fixed value there is kept. */
                if (w.state[k] == ST_FREE) {
                    double Tbest = INFINITY;
                    int sbest = -1;
                    for (int s = 0; s < nsrc; s++) {
                        double r2 = 0;
                        int box = 1;
                        for (int d = 0; d < w.dim; d++) {
                            const double e = x[d] - w.src[s].x[d];
                            r2 += e * e;
                            if (fabs(e) > w.h[d] * (1 + 1e-12)) box = 0;
                        }
                        const double r = sqrt(r2);
                        if (!box && r > hmax * (1 + 1e-12)) continue;
                        if (shadows && !visible(&w, x, w.src[s].x)) continue;
                        /* The exact T lies in [r fmin, r fmax] (after t0)
                         * when the slowness there stays in the box's range;
                         * where f jumps between pixels the expansion's
                         * differenced derivatives leave it (T < 0 was seen).
                         * Clamping moves such a value only to the nearest
                         * admissible one and leaves every value inside the
                         * range as it was (smooth data: it never acted in the
                         * convergence study), where falling back to f0 r
                         * would drop the expansion's terms whenever it is
                         * barely outside. */
                        const double Te = source_time(&w, &w.src[s], x), lo = w.src[s].t0 + r * w.src[s].fmin,
                                     hi = w.src[s].t0 + r * w.src[s].fmax;
                        const double Tv = Te < lo ? lo : Te > hi ? hi : Te;
                        if (Tv < Tbest) {
                            Tbest = Tv;
                            sbest = s;
                        }
                    }
                    if (Tbest < INFINITY) {
                        w.state[k] = ST_SRC;
                        w.lab[k] = sbest;
                        w.tau[k] = Tbest; /* T for now; tau below */
                    }
                } else if (w.state[k] == ST_FIXED) {
                    w.tau[k] = ldexp(fixed[(a - w.G[0]) + n0 * ((b - w.G[1]) + n1 * (c - w.G[2]))], -et);
                }
                if (!factored) continue;
                /* The owner: the source of the earliest straight-line
                 * time; with obstacles the earliest the node can see (none:
                 * -1, unfactored).  A ghost node keeps the straight-line
                 * owner: settle_sources re-derives it from its grid node. */
                double best = INFINITY;
                for (int s = 0; s < nsrc; s++) {
                    const double e = w.src[s].t0 + src_T0(&w, s, x);
                    if (e < best) {
                        best = e;
                        w.own[k] = s;
                    }
                }
                if (shadows && w.state[k] != ST_OBST && w.state[k] != ST_GHOST && !sees(&w, ip, w.own[k])) {
                    const int hidden = w.own[k];
                    w.own[k] = -1;
                    best = INFINITY;
                    for (int s = 0; s < nsrc; s++) {
                        const double e = w.src[s].t0 + src_T0(&w, s, x);
                        if (s != hidden && e < best && sees(&w, ip, s)) {
                            best = e;
                            w.own[k] = s;
                        }
                    }
                }
                w.T0[k] = src_T0(&w, w.own[k], x);
                if ((w.state[k] == ST_FIXED || w.state[k] == ST_SRC) && isfinite(w.tau[k]))
                    w.tau[k] = w.T0[k] > 0 ? (w.tau[k] - src_tb(&w, w.own[k])) / w.T0[k] : 1.0;
            }
    w.relax = 1;
    w.eps3 = 1e-6;
    for (int d = 0; d < w.dim; d++) w.eps5[d] = 1e-6 * (w.h[d] / Lmax) * (w.h[d] / Lmax);
    w.lock_tol = 0; /* exact locking for the first order phase */

    const long par_min = opt->parallel_min > 0 ? opt->parallel_min : 4096;
    long B[3];
    sweep_blocks(&w, opt->block, par_min, B);
    const long all_lo[3] = {0, 0, 0}, all_hi[3] = {w.n[0], w.n[1], w.n[2]};
    sweep_tuner tun;
    tuner_init(&tun, &w, opt->block, opt->always_parallel, B);

    /* First order sweeps to convergence. */
    int q = 1;
    const int nsw = 1 << w.dim;
    int conv = 0, at_round = 0;
    double scale = 0;
    for (long it = 1; it <= opt->max_iter; it++) {
        double change = 0;
        const long *Bi = tuner_begin(&tun, tune_work(st, np));
        for (int s = 0; s < nsw; s++, q++) {
            const double c = sweep(&w, s, all_lo, all_hi, 1, q, 1, par_min, Bi, &st->updates);
            if (c > change) change = c;
        }
        scale = 0;
        for (size_t k = 0; k < np; k++)
            if (w.state[k] == ST_FREE || w.state[k] == ST_FIXED || w.state[k] == ST_SRC) {
                const double v = fabs(src_tb(&w, w.own[k]) + w.T0[k] * w.tau[k]);
                if (v < INFINITY && v > scale) scale = v;
            }
        st->iterations = st->fo_iterations = it;
        st->sweeps += nsw;
        tuner_end(&tun, tune_work(st, np));
        st->change = scale > 0 ? change / scale : change;
        if (opt->progress) opt->progress(it, st->change, opt->progress_ctx);
        if (change <= opt->tol * scale) {
            conv = 1;
            break;
        }
    }
    const double fo_scale = scale; /* the guard's scale: the first order iteration cannot blow up */
    for (size_t k = 0; k < np; k++)
        if (w.state[k] == ST_FREE && !(w.tau[k] < INFINITY)) {
            w.state[k] = ST_UNREACH;
            st->unreachable++;
        }
    settle_sources(&w, factored, nobst > 0);
    if (opt->order == 5) mark_low(&w);

    /* Higher order sweeps from the first order solution. */
    if (conv && opt->order > 1) {
        double uscale = 0;
        for (size_t k = 0; k < np; k++)
            if ((w.state[k] == ST_FREE || w.state[k] == ST_FIXED) && fabs(w.tau[k]) > uscale) uscale = fabs(w.tau[k]);
        if (uscale > 0) {
            w.eps3 *= uscale * uscale;
            for (int d = 0; d < w.dim; d++) w.eps5[d] *= uscale * uscale;
        }
        for (size_t k = 0; k < np; k++) w.stamp[k] = q; /* everything active at first */
        /* A change below a tenth of the stopping threshold does not
         * unlock the neighbours: a third fewer local solves (2-D, N = 160,
         * orders 3 and 5), errors equal to 3 digits.  The first order
         * phase locks exactly (lock_tol = 0). */
        w.lock_tol = 0.1 * opt->tol * scale;
        conv = 0;
        const int deg = 2; /* degrees 3 and 4 made the WENO5 iteration oscillate at the boundary */
        /* dl and chg: a float per node, fo: a byte */
        if (!(w.dl = malloc(np * sizeof(float))) || !(w.chg = calloc(np, sizeof(float))) || !(w.fo = calloc(np, 1))) {
            work_free(&w);
            return hj_error_set(err, HJ_ENOMEM, "out of memory: the solver needs %.3g MB more",
                                (double)np * (2 * sizeof(float) + 1) / 1e6);
        }
        mark_rough(&w);
        /* The caller's start (opt->start): the free nodes take it in
         * place of the first order solution, refactored by this solve's
         * own T0 and owner; everything set up from the first order
         * solution (states, eps, scale, locking, the rough and WENO3
         * marks) stays as it is without it. */
        if (opt->start)
            for (long c = 0; c < n2; c++)
                for (long b = 0; b < n1; b++)
                    for (long a = 0; a < n0; a++) {
                        const long u = a + n0 * (b + n1 * c);
                        const long k = (a + w.G[0]) * w.st[0] + (b + w.G[1]) * w.st[1] + (c + w.G[2]) * w.st[2];
                        if (w.state[k] != ST_FREE || !isfinite(opt->start[u]) || !(w.T0[k] > 0)) continue;
                        w.tau[k] = (ldexp(opt->start[u], -et) - src_tb(&w, w.own[k])) / w.T0[k];
                    }
        /* One point source, no obstacle, no fixed data: the higher order
         * iterations sweep the 2^dim orthants around the source, each away
         * from it, so that every axis line is visited away from the
         * source (source_cut); else the 2^dim full sweeps. */
        int octants = nsrc == 1 && nobst == 0 && nfixed == 0;
        /* Else, with opt->causal_sweeps, each iteration solves every node
         * once, in the sweep of its causal orientation (causal_sides). */
        const int causal = opt->causal_sweeps && !octants;
        long cbox[8][2][3];
        if (causal) {
            if (!(w.sig = calloc(np, 1))) {
                work_free(&w);
                return hj_error_set(err, HJ_ENOMEM, "out of memory: the solver needs %.3g MB more", (double)np / 1e6);
            }
            causal_sides(&w, cbox);
        }
        long cut[3] = {0, 0, 0};
        if (octants) source_cut(&w, &w.src[0], cut);
        long nmax = 0;
        for (int d = 0; d < w.dim; d++) nmax = w.n[d] > nmax ? w.n[d] : nmax;
        const double round_level = fmax(1e-12, ROUND_LEVEL * DBL_EPSILON * pow((double)nmax, 1.5));
        double rnd[2] = {0, 0}; /* the rounding test's blocks, like blk */
        int nrnd = 0;
        double blk[2] = {0, 0}; /* largest change of the last full block and of the current one */
        double cyc[2] = {0, 0}; /* the same for the WENO5 cycle test */
        int demoted = 0, fell = 0, nblk = 0, ncyc = 0;
        /* the cycle and stall tests' blocks in units of work: a pass
         * visits each node once, an iteration of full sweeps 2^dim times */
        int cyc_span = octants || causal ? CYCLE_SPAN << w.dim : CYCLE_SPAN;
        int stall_span = octants || causal ? STALL_SPAN << w.dim : STALL_SPAN;
        double orth[2] = {0, 0}; /* the orthant passes' own stall blocks, like blk */
        int north = 0;
        /* max_iter bounds the total, the first order start included */
        tuner_reset(&tun);
        for (long it = 1; it <= opt->max_iter - st->fo_iterations; it++) {
            double change = 0;
            const long *Bi = tuner_begin(&tun, tune_work(st, np));
            if (w.chg) memset(w.chg, 0, np * sizeof(float));
            if (causal) {
                /* each node in the sweep of its orientation (causal_sides),
                 * within the box of that orientation's nodes */
                w.q0 = q;
                for (int s = 0; s < nsw; s++, q++) {
                    int empty = 0;
                    for (int d = 0; d < w.dim; d++) empty = empty || cbox[s][0][d] >= cbox[s][1][d];
                    if (empty) continue;
                    fill_ghosts(&w, deg, q);
                    const double c = sweep(&w, s, cbox[s][0], cbox[s][1], opt->order, q, 0, par_min, Bi, &st->updates);
                    if (c > change) change = c;
                }
                st->sweeps++;
            } else if (octants) {
                /* one pass: each orthant swept away from the source, all
                 * with the pass's number q (each node is visited once) */
                w.q0 = q;
                for (int s = 0; s < nsw; s++) {
                    long lo[3], hi[3];
                    int empty = 0;
                    for (int d = 0; d < 3; d++) {
                        const int back = d < w.dim && ((s >> d) & 1);
                        lo[d] = d < w.dim && !back ? cut[d] : 0;
                        hi[d] = back ? cut[d] : w.n[d];
                        empty = empty || lo[d] >= hi[d];
                    }
                    if (empty) continue;
                    fill_ghosts(&w, deg, q);
                    const double c = sweep(&w, s, lo, hi, opt->order, q, 0, par_min, Bi, &st->updates);
                    if (c > change) change = c;
                }
                q++;
                st->sweeps++;
            } else {
                for (int s = 0; s < nsw; s++, q++) {
                    fill_ghosts(&w, deg, q);
                    w.q0 = q;
                    const double c = sweep(&w, s, all_lo, all_hi, opt->order, q, 0, par_min, Bi, &st->updates);
                    if (c > change) change = c;
                }
                st->sweeps += nsw;
            }
            tuner_end(&tun, tune_work(st, np));
            scale = 0;
            for (size_t k = 0; k < np; k++)
                if (w.state[k] == ST_FREE || w.state[k] == ST_FIXED) {
                    const double v = fabs(src_tb(&w, w.own[k]) + w.T0[k] * w.tau[k]);
                    if (v < INFINITY && v > scale) scale = v;
                }
            st->iterations = st->fo_iterations + it;
            st->change = scale > 0 ? change / scale : change;
            if (opt->progress) opt->progress(st->iterations, st->change, opt->progress_ctx);
            if (!isfinite(change)) break;
            if (change <= opt->tol * scale) {
                conv = 1;
                break;
            }
            if (causal) causal_sides(&w, cbox);
            /* Orthant passes that stall (ORTHANT_STALL; the stall test
             * below on blocks of their own, which the other tests do not
             * restart): the full sweeps from here on, the tests afresh. */
            if (octants) {
                if (change > orth[1]) orth[1] = change;
                if (++north == stall_span) {
                    if (orth[0] > 0 && orth[1] >= ORTHANT_RATIO * orth[0] && orth[1] > round_level * scale) {
                        octants = 0;
                        cyc_span = CYCLE_SPAN, stall_span = STALL_SPAN;
                        rnd[0] = rnd[1] = blk[0] = blk[1] = cyc[0] = cyc[1] = 0;
                        nrnd = nblk = ncyc = 0;
                        st->orthant_stalled = st->iterations;
                        tuner_reset(&tun);
                        continue;
                    }
                    orth[0] = orth[1];
                    orth[1] = 0;
                    north = 0;
                }
            }
            /* A block of stall_span iterations whose largest change is
             * below the rounding level and not below STALL_RATIO times
             * the last block's: round-off, tol cannot be reached; but
             * order 3 first drops the downwind relaxation, whose own
             * plateau can lie there (the obstacle case of eik_convergence
             * at N = 40: 2.8e-12 of the scale with it; it converges
             * without). */
            if (change > rnd[1]) rnd[1] = change;
            if (++nrnd == stall_span) {
                if (rnd[0] > 0 && rnd[1] >= STALL_RATIO * rnd[0] && rnd[1] <= round_level * scale) {
                    if (!(opt->order == 3 && w.relax)) {
                        at_round = 1;
                        break;
                    }
                    w.relax = 0;
                    rnd[1] = 0;
                    blk[0] = blk[1] = 0;
                    nblk = 0;
                }
                rnd[0] = rnd[1];
                rnd[1] = 0;
                nrnd = 0;
            }
            /* WENO5 cycling (the largest change of a block of
             * CYCLE_SPAN iterations not below CYCLE_RATIO times that of
             * the block before): the nodes that still move use WENO3.
             * A plateau at rounding level (below round_level of the
             * scale: a tolerance too small to reach) is no cycle. */
            if (opt->order == 5 && demoted < STALL_ROUNDS) {
                if (change > cyc[1]) cyc[1] = change;
                if (++ncyc == cyc_span) {
                    if (cyc[0] > 0 && cyc[1] >= CYCLE_RATIO * cyc[0] && cyc[1] > round_level * scale) {
                        demote_cycling(&w, change, q);
                        demoted++;
                        cyc[1] = 0; /* the next block starts afresh */
                        blk[0] = blk[1] = 0;
                        nblk = 0;
                    }
                    cyc[0] = cyc[1];
                    cyc[1] = 0;
                    ncyc = 0;
                }
                continue; /* the stall test below waits for the last round */
            }
            if (change > blk[1]) blk[1] = change;
            if (++nblk == stall_span) {
                /* a plateau at rounding level is no stall either */
                const int stall = blk[0] > 0 && blk[1] >= STALL_RATIO * blk[0] && blk[1] > round_level * scale;
                if (stall && opt->order == 3 && w.relax) {
                    /* order 3: the plain update from here on (the wall
                     * of eik_convergence at N = 40: changes of 3.5e-12
                     * of the scale for 1000 iterations with it) */
                    w.relax = 0;
                    blk[1] = 0;
                } else if (stall && fell < FALL_ROUNDS) {
                    /* still cycling: the nodes that still move use the
                     * first order update (demote_first) */
                    demote_first(&w, change, q, ++fell == FALL_ROUNDS);
                    blk[1] = 0;
                }
                blk[0] = blk[1];
                blk[1] = 0;
                nblk = 0;
            }
        }
    }
    st->converged = conv;
    if (w.fo)
        for (size_t k = 0; k < np; k++) st->first_order += w.fo[k] && w.state[k] == ST_FREE;
    if (fo_out)
        for (long c = 0; c < n2; c++)
            for (long b = 0; b < n1; b++)
                for (long a = 0; a < n0; a++) {
                    const long k = (a + w.G[0]) * w.st[0] + (b + w.G[1]) * w.st[1] + (c + w.G[2]) * w.st[2];
                    fo_out[a + n0 * (b + n1 * c)] = w.fo && w.fo[k] && w.state[k] == ST_FREE;
                }

    for (long c = 0; c < n2; c++)
        for (long b = 0; b < n1; b++)
            for (long a = 0; a < n0; a++) {
                const long k = (a + w.G[0]) * w.st[0] + (b + w.G[1]) * w.st[1] + (c + w.G[2]) * w.st[2];
                const double v = w.tau[k];
                T[a + n0 * (b + n1 * c)] =
                    (w.state[k] == ST_OBST || !(v < INFINITY)) ? INFINITY : ldexp(src_tb(&w, w.own[k]) + w.T0[k] * v, et);
            }
    /* The stopping rule is relative to max |T|, which a blown-up iterate
     * inflates: check the result (hj_eik_guard.h).  low's first n bytes
     * are free now; they hold which nodes a front reached. */
    double t_min = INFINITY;
    for (int s = 0; s < nsrc; s++) t_min = src[s].t0 < t_min ? src[s].t0 : t_min;
    for (size_t u = 0; fixed && u < (size_t)(n0 * n1 * n2); u++)
        if (fixed[u] < t_min) t_min = fixed[u]; /* NaN (free) compares false */
    for (long c = 0; c < n2; c++)
        for (long b = 0; b < n1; b++)
            for (long a = 0; a < n0; a++) {
                const unsigned char sk =
                    w.state[(a + w.G[0]) * w.st[0] + (b + w.G[1]) * w.st[1] + (c + w.G[2]) * w.st[2]];
                w.low[a + n0 * (b + n1 * c)] = sk == ST_FREE || sk == ST_FIXED || sk == ST_SRC;
            }
    const long nn[3] = {n0, n1, n2};
    rc = hj_eik_guard(T, w.low, nn, t_min, ldexp(fo_scale, et), err);
    work_free(&w);
    if (rc != HJ_OK) {
        st->converged = 0;
        return rc;
    }
    /* The first order start can use up max_iter: then no higher order
     * iteration ran and the last change (the start's) is within tol. */
    if (!conv && opt->order > 1 && st->iterations == st->fo_iterations && st->change <= opt->tol)
        return hj_error_set(err, HJ_ENOCONV, "no convergence in %ld iteration%s: the first order start took all "
                                             "of max_iter %ld, no order %d iteration ran; the first order result is "
                                             "kept", st->iterations, hj_plural(st->iterations), opt->max_iter, opt->order);
    if (at_round)
        return hj_error_set(err, HJ_ENOCONV, "no convergence in %ld iteration%s: tol %.3g is below the rounding level "
                                             "reached (the change levels off at %.3g of the solution's scale); the "
                                             "last iterate is kept", st->iterations, hj_plural(st->iterations), opt->tol,
                            st->change);
    if (!conv)
        return hj_error_set(err, HJ_ENOCONV, "no convergence in %ld iteration%s (last change %.3g of the solution's "
                                             "scale > tol %.3g); the last iterate is kept", st->iterations,
                            hj_plural(st->iterations), st->change,
                            opt->tol);
    return HJ_OK;
}

/* Progress of the separate solves: iterations counted from the first
 * solve's first. */
typedef struct {
    const hj_eik_options *opt;
    long offset;
} sep_progress;

static void sep_progress_cb(long iter, double change, void *ctx)
{
    const sep_progress *p = ctx;
    p->opt->progress(p->offset + iter, change, p->opt->progress_ctx);
}

/* Several sources (the fixed data one more): T = min_k T_k, each T_k solved
 * alone.  Each T_k is smooth away from its own source, so the minimum has
 * the scheme's order up to the kink where two fronts meet, where the joint
 * solve's stencils straddle the kink and fall to first order. */
static int solve_separate(const hj_eik_grid *g, const double *f, double f_const, const unsigned char *obstacle,
                          const hj_eik_source *src, int nsrc, const double *fixed, size_t n, int nfix,
                          const hj_eik_options *opt, double *T, hj_eik_stats *st, hj_error *err)
{
    hj_eik_options o = *opt;
    o.separate_sources = 0;
    o.start = NULL; /* a start of the minimum is none of the single solves' */
    sep_progress pctx = {opt, 0};
    if (opt->progress) {
        o.progress = sep_progress_cb;
        o.progress_ctx = &pctx;
    }
    /* Tc: the current solve; fw, fc: the first order flags of the running
     * minimum's solve and of the current one. */
    double *Tc = malloc(n * sizeof *Tc);
    unsigned char *fw = opt->order > 1 ? calloc(n, 2) : NULL, *fc = fw ? fw + n : NULL;
    if (!Tc || (opt->order > 1 && !fw)) {
        free(Tc);
        free(fw);
        return hj_error_set(err, HJ_ENOMEM, "out of memory: the separate solves need %.3g MB besides the solver's",
                            (double)n * (sizeof(double) + 2) / 1e6);
    }
    int rc = HJ_OK;
    hj_error first;
    hj_error_clear(&first);
    st->converged = 1;
    const int ncomp = nsrc + nfix;
    for (int c = 0; c < ncomp; c++) {
        hj_eik_stats sc;
        hj_error e;
        hj_error_clear(&e);
        double *Tk = c == 0 ? T : Tc;
        unsigned char *fk = c == 0 ? fw : fc;
        const int r = c < nsrc ? solve_joint(g, f, f_const, obstacle, src + c, 1, NULL, &o, Tk, &sc, fk, 0, &e)
                               : solve_joint(g, f, f_const, obstacle, NULL, 0, fixed, &o, Tk, &sc, fk, 0, &e);
        st->iterations += sc.iterations;
        st->fo_iterations += sc.fo_iterations;
        st->updates += sc.updates;
        st->sweeps += sc.sweeps;
        /* the first solve whose orthant passes stalled, in the summed count */
        if (sc.orthant_stalled > 0 && st->orthant_stalled == 0)
            st->orthant_stalled = st->iterations - sc.iterations + sc.orthant_stalled;
        st->change = sc.change > st->change ? sc.change : st->change;
        st->converged = st->converged && sc.converged;
        pctx.offset = st->iterations;
        if (r != HJ_OK && r != HJ_ENOCONV) { /* out of memory: nothing to keep */
            free(Tc);
            free(fw);
            if (c < nsrc) return hj_error_set(err, r, "source %d solved alone: %s", c + 1, e.msg);
            return hj_error_set(err, r, "the fixed data solved alone: %s", e.msg);
        }
        if (r != HJ_OK && rc == HJ_OK) {
            /* the first failure is reported; the others are still solved
             * and the minimum of the last iterates kept, as the joint
             * solve keeps its last iterate */
            rc = r;
            if (c < nsrc) hj_error_set(&first, r, "source %d solved alone: %s", c + 1, e.msg);
            else hj_error_set(&first, r, "the fixed data solved alone: %s", e.msg);
        }
        if (c == 0) continue;
        for (size_t u = 0; u < n; u++)
            if (Tc[u] < T[u] || isnan(T[u])) {
                T[u] = Tc[u];
                if (fw) fw[u] = fc[u];
            }
    }
    /* The fixed nodes hold their values, as in the joint solve (a source
     * may reach one before its value). */
    for (size_t u = 0; fixed && u < n; u++)
        if (!isnan(fixed[u])) T[u] = fixed[u];
    for (size_t u = 0; u < n; u++) {
        if (obstacle && obstacle[u]) continue;
        st->unreachable += !(T[u] < INFINITY);
        if (fw) st->first_order += fw[u] && (!fixed || isnan(fixed[u]));
    }
    free(Tc);
    free(fw);
    if (rc != HJ_OK) return hj_error_set(err, rc, "%s", first.msg);
    return HJ_OK;
}

int hj_eik_solve(const hj_eik_grid *g, const double *f, double f_const, const unsigned char *obstacle,
                 const hj_eik_source *src, int nsrc, const double *fixed, const hj_eik_options *opt, double *T,
                 hj_eik_stats *st, hj_error *err)
{
    if (!opt || !opt->separate_sources || nsrc < 1)
        return solve_joint(g, f, f_const, obstacle, src, nsrc, fixed, opt, T, st, NULL, 0, err);
    /* every check of the joint solve, on all the sources, before any sweep */
    hj_eik_stats dummy;
    if (!st) st = &dummy;
    int rc = solve_joint(g, f, f_const, obstacle, src, nsrc, fixed, opt, T, st, NULL, 1, err);
    if (rc != HJ_OK) return rc;
    const size_t n = (size_t)g->n[0] * (size_t)g->n[1] * (size_t)(g->dim == 3 ? g->n[2] : 1);
    int nfix = 0;
    for (size_t u = 0; fixed && u < n && !nfix; u++) nfix = !isnan(fixed[u]);
    if (nsrc + nfix < 2) return solve_joint(g, f, f_const, obstacle, src, nsrc, fixed, opt, T, st, NULL, 0, err);
    return solve_separate(g, f, f_const, obstacle, src, nsrc, fixed, n, nfix, opt, T, st, err);
}

/* v0 + g . y, summed in the order of the dimensions */
static double linear_speed(int dim, double v0, const double *g, const double *y)
{
    double v = v0;
    for (int d = 0; d < dim; d++) v += g[d] * y[d];
    return v;
}

double hj_eik_linear_time(int dim, double v0, const double *g, const double *s, const double *x)
{
    if (dim < 1 || dim > 3 || !g || !s || !x) return NAN;
    double r2 = 0, g2 = 0;
    for (int d = 0; d < dim; d++) {
        r2 += (x[d] - s[d]) * (x[d] - s[d]);
        g2 += g[d] * g[d];
    }
    const double vs = linear_speed(dim, v0, g, s), vx = linear_speed(dim, v0, g, x);
    if (!(vs > 0 && vx > 0)) return NAN;
    if (g2 == 0) return sqrt(r2) / v0;
    /* acosh(1 + 2 z^2) = 2 asinh(z), z = |g| |x - s| / (2 sqrt(v(s) v(x))):
     * acosh(1 + e) lost e's digits in 1 + e where |g| |x - s| / v is small
     * (T = 0 at distance 1 for |g| = 1e-9, 4e-5 relative error at
     * |x - s| = 1e-6 for |g| = 0.5, near every source). */
    const double gn = sqrt(g2);
    return 2 * asinh(gn * sqrt(r2) / (2 * sqrt(vs) * sqrt(vx))) / gn;
}
