/* hj_eik.h -- fast sweeping for the Eikonal equation |grad T| = f in 2-D
 * and 3-D, for users' problems: orders 1, 3 and 5, point sources factored
 * (T = T0 tau near them, so the source does not spoil the order: order 3
 * keeps 3, order 5 measures about 4 in L1 and 3 in Linf, held by the
 * boundary closure), obstacles, several sources (T has a kink where
 * their fronts meet: one joint solve is first order in Linf there,
 * separate_sources keeps the order), dx != dy, a scale-free stopping
 * rule.  (Paper 1's own solver, with its inflow
 * treatments, stays in hj_fsm.h.)
 *
 * f is the slowness (1 / speed), f > 0 where the front may pass; nodes
 * with obstacle[i] != 0 are never crossed (T = +INFINITY there).
 *
 * Grid: g->n[d] nodes along dimension d (d < dim), node i_d at
 * x0[d] + i_d dx[d]; arrays are x-fastest: idx = i0 + n0 (i1 + n1 i2).
 *
 * THIS FILE IS THE CONTRACT BETWEEN THE SOLVER AND ITS CLIENTS: fields may
 * be added; the names below are not renamed.
 */
#ifndef HJ_EIK_H
#define HJ_EIK_H

#include <stddef.h>
#include "hj_error.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    int dim;        /* 2 or 3 */
    long n[3];      /* nodes per dimension (n[2] = 1 when dim = 2) */
    double x0[3];   /* coordinates of node 0 */
    double dx[3];   /* spacing per dimension, > 0 */
} hj_eik_grid;

/* A point source anywhere in the domain (not only at nodes). */
typedef struct {
    double x[3];
    double t0;      /* travel time at the source, usually 0 */
} hj_eik_source;

typedef struct {
    int order;          /* 1, 3 or 5 (default 3) */
    int factored;       /* 1 (default): T = T0 tau near point sources */
    double tol;         /* stop when max |T_new - T_old| <= tol * scale,
                         * scale = max finite |T|; default 1e-10 */
    long max_iter;      /* bound on stats.iterations (convergence tests),
                         * the first order start included; default 1000;
                         * an iteration is 2^dim sweeps, or one grid's
                         * worth of solves for the orthant pass and
                         * causal_sweeps */
    /* Called after each iteration, with its count and change (NULL:
     * none). */
    void (*progress)(long iter, double change, void *ctx);
    void *progress_ctx;
    long parallel_min;  /* hyperplanes of blocks holding at least this
                         * many nodes are swept by all OpenMP threads
                         * (0: 4096); the result is the same for any
                         * thread count */
    long block;         /* block edge (nodes) of the sweeps' order (0:
                         * automatic: the whole grid with one thread;
                         * 1: node hyperplanes); the result does not
                         * depend on it */
    int always_parallel; /* 0 (default): where the solver cuts the grid
                          * into blocks for the threads (block 0, more
                          * than one thread, 16 parallel_min nodes or
                          * more), each iteration sweeps with the
                          * threads or on one of them, whichever it
                          * measured faster in the iterations before
                          * (both are timed at the start of the first
                          * order phase; a later phase starts in the
                          * faster one by the ratio measured before; the
                          * slower one is timed again every 8
                          * iterations): a thread that waits at a
                          * block hyperplane for one whose core is busy
                          * with other work waits for the scheduler
                          * (an 81^3 order 1 solve on 2 cores beside one
                          * busy process: 2.2-2.5 s with the threads
                          * always, 1.4 s with the choice, 1.2-1.3 s on
                          * one thread; idle the choice costs 0 to 6 %);
                          * 1: always with the threads.  The result is
                          * the same bits either way */
    int separate_sources; /* 1: with two or more sources (the fixed data
                           * counting as one more), solve each alone and
                           * take the node-wise minimum (see
                           * hj_eik_solve); 0 (default): one joint solve */
    int causal_sweeps;    /* 1: where the orthant pass does not apply
                           * (several sources, obstacles, fixed data), a
                           * higher order iteration solves each node once,
                           * in the one of the 2^dim sweeps that runs along
                           * its upwind sides (taken from the iterate at
                           * the iteration's start); 0 (default): each node
                           * in each of the 2^dim sweeps (locking skips
                           * it where its stencil did not change).  The
                           * same fixed point, but the iteration stops
                           * elsewhere: within a few times tol * scale
                           * (8.4e-9 against 5e-9 on a wall map), and
                           * where order 5 demotes cycling nodes to
                           * order 3 (its cycle test counts blocks of
                           * 2^dim causal iterations) other nodes at other
                           * times: up to 1e-3 relative on a rough map
                           * with fixed data.  2.8 to 3.2 times the
                           * iterations (each a grid's worth of solves,
                           * against 2^dim for full sweeps: max_iter
                           * allows a quarter (2-D) to an eighth (3-D)
                           * of the work), 0.75 to 0.9
                           * times the instructions on a wall, a maze and
                           * two sources, but 1.14 on one case
                           * (paper1_fastsweeping/eik/notes/eik-convergence.md);
                           * memory: a byte per node more; with one
                           * source and no obstacle or fixed data the
                           * orthant pass runs whatever it says */
    const double *start;  /* NULL (default): the higher order phase
                           * (orders 3 and 5) starts from the first order
                           * solution.  Else one value per node, in T's
                           * units and layout: that phase starts from it,
                           * e.g. a coarser grid's solution interpolated
                           * (nested iteration).  The solver still makes
                           * its first order start and takes from it
                           * everything but the iterate (which nodes are
                           * reached, the stopping rule's scale and
                           * locking threshold, the WENO eps, the nodes
                           * kept at WENO3 or first order); the start
                           * replaces the free nodes' values where it is
                           * finite, not the source neighbourhood's
                           * nodes that the solver holds, nor fixed
                           * data or obstacles.  With factoring the
                           * solver divides it by its own factor T0 =
                           * f(s) |x - s|: interpolate T / |x - s| (smooth
                           * near the source), not T (a cone there), and
                           * multiply back.  Ignored at order 1 and by
                           * separate_sources' single solves.  The
                           * fixed point is the same, so the result
                           * differs from the plain solve's within the
                           * stopping rule's reach. */
} hj_eik_options;

/* An iteration ends with a convergence test.  In the first order start,
 * and in the higher order phase in general, it is 2^dim sweeps of the
 * whole grid.  With one point source and neither obstacles nor fixed
 * data, a higher order iteration is one pass instead: the 2^dim orthants
 * around the source, each swept away from it, a grid's worth of work.
 * With causal_sweeps (elsewhere) it is the 2^dim sweeps, each solving
 * only the nodes of its orientation, also a grid's worth of solves.
 * sweeps counts the work in whole-grid sweeps (a pass or a causal
 * iteration counts one).
 * With separate_sources the counts (iterations, fo_iterations, updates,
 * sweeps) are the sums over the solves, change is the largest of their
 * last changes, converged says that every solve converged; unreachable
 * and first_order count the nodes of the result (first_order: where the
 * solve that gives the node its minimum left it at first order). */
typedef struct {
    long iterations;    /* iterations (convergence tests) made */
    double change;      /* last max change / scale */
    int converged;
    size_t unreachable; /* nodes left at +INFINITY outside obstacles */
    long fo_iterations; /* iterations of the first order start (included
                         * in iterations) */
    size_t updates;     /* local solves done (active nodes only) */
    size_t first_order; /* orders 3 and 5: nodes left at the first order
                         * update, where the high order one failed its
                         * safeguard or kept the iteration from
                         * converging (under-resolved data) */
    long sweeps;        /* whole-grid sweeps done, first order start
                         * included (an orthant pass or a causal
                         * iteration counts one) */
    long orthant_stalled; /* the iteration after which the orthant
                           * passes stalled and full sweeps took over
                           * (arrivals coming back toward the source
                           * along an axis, as head waves do); 0: never.
                           * With separate_sources: the first solve's
                           * that stalled, counted in the summed
                           * iterations */
} hj_eik_stats;

hj_eik_options hj_eik_default_options(void);

/* Solve.  f: slowness per node (NULL: constant f_const); obstacle: NULL or
 * a mask; src/nsrc: point sources; fixed: NULL or per node a value to hold
 * (NaN: free), e.g. boundary data along a curve.  T (caller-owned, one
 * double per node) receives the solution.  On HJ_ENOCONV T holds the last
 * iterate and st says how far it got: the iteration did not converge, or
 * its result failed the check of hj_eik_guard.h (a blow-up: T below the
 * earliest start, NaN, or not finite where a front arrives).  Bad input (f <= 0 or non-finite
 * outside obstacles, a source in an obstacle or outside the grid, no
 * source and no fixed node, a fixed value or source time beyond 1e150 in
 * the solver's units, ...) gives HJ_EINVAL with a message before any
 * sweep.  Messages number the sources from 1.
 *
 * Several sources.  The viscosity solution is T = min_k T_k, T_k the
 * solution from source k alone (with the obstacles; the fixed data, when
 * some node is fixed, count as one more source).  One joint solve (the
 * default) is first order in Linf and second in L1 where two fronts meet,
 * at every order: T has a kink there and the WENO stencils straddle it.
 * With opt->separate_sources = 1 and two or more sources (the fixed data
 * counting), each is solved alone, as a single-source problem (the
 * orthant pass when there is no obstacle), and T is their node-wise
 * minimum: each T_k is smooth away from its own source, so the minimum
 * has the scheme's order everywhere, the kink included; the fixed nodes
 * hold their values.  Cost: one solve per source (two sources: 0.96 to
 * 1.5 times the joint solve's instructions at orders 3 and 5, twice at
 * order 1; paper1_fastsweeping/eik/notes/eik-convergence.md); memory:
 * n more doubles (the solve under way beside the running minimum in T)
 * and 2 n bytes at orders 3 and 5 (which solve left a node at first
 * order), one solve's work arrays at a time.  max_iter bounds each solve;
 * progress is called with the iterations counted on across the solves.
 * The input is checked for all the sources before the first solve.  On
 * HJ_ENOCONV from a solve the others still run, T is the minimum of the
 * last iterates and the message names the first solve that failed; on
 * another error (out of memory) T holds no result.  One
 * source and no fixed data (or fixed data alone) is the joint solve, to
 * the bit.  The result does not depend on the thread count. */
int hj_eik_solve(const hj_eik_grid *g, const double *f, double f_const,
                 const unsigned char *obstacle, const hj_eik_source *src, int nsrc,
                 const double *fixed, const hj_eik_options *opt, double *T,
                 hj_eik_stats *st, hj_error *err);

/* The closed-form travel time from s to x in the linear velocity field
 * v(y) = v0 + g . y (|grad T| = 1 / v), dim 1 to 3: T = acosh(1 + |g|^2
 * |x - s|^2 / (2 v(s) v(x))) / |g| (Fomel, Luo & Zhao 2009), |x - s| / v0
 * for g = 0; evaluated as 2 asinh(|g| |x - s| / (2 sqrt(v(s) v(x)))) / |g|,
 * the same value without the loss of digits in 1 + e where |g| |x - s| / v
 * is small.  The reference solution of the convergence studies and a check
 * for a user's own solver.  NaN where v(s) or v(x) is not positive (the
 * field has no travel time there) or dim is out of range. */
double hj_eik_linear_time(int dim, double v0, const double *g, const double *s, const double *x);

#ifdef __cplusplus
}
#endif

#endif
