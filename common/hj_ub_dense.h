/* hj_ub_dense.h -- one step of the UB-HJB scheme (hj_ub.h) on the full grid
 * held as one array, row by row.
 *
 * The same scheme and the same numbers as hj_ub_step on the FS store
 * (bitwise: unit test), without the store: V is n^d doubles, row-major
 * (the last index runs fastest), and every direction is swept over whole
 * rows of the last index, so that the Ultra-Bee flux evaluation is one
 * branch-free loop the compiler vectorises.  Each node's flux, and the
 * values its two faces take in its neighbours' updates, are computed once
 * per sweep, so that a node's update reads 5 values; a sweep along a
 * strided direction steps from one row to the next in one pass (the faces
 * of row i + 1 and the update of row i).  The dynamics may be given over a
 * row of nodes per call (hj_ub_row_fn), so that the user's code vectorises
 * too; without it the problem's per-node dyn is called.
 *
 * The controls and the memory: with dimension splitting a control's
 * second sweep needs its first sweep on the neighbouring rows, so the
 * controls cannot run inside the row loop without one intermediate grid
 * each.  For d >= 3 the last three directions run plane by plane instead
 * (a plane: the last two indices): the sweep in direction d - 3 steps from
 * plane to plane keeping a plane's faces, and hands each plane, in cache,
 * to the sweep in d - 2, whose rows go straight to the last direction;
 * the minimum over the controls (and the final min with V^n, the snap)
 * is taken in the same pass.  For d = 3 the controls run in groups (as
 * many as keep their planes' faces in about 4 MB per thread), every
 * control of a group on each plane in turn, so that the running minimum
 * and V^n are read from memory once per group: about 24 B per node per
 * group, against 40-48 B per node and control with a grid between the
 * sweeps.  d = 4 sweeps direction 0 into one intermediate grid per
 * control first; d = 2 sweeps each row of it.  The row kernels are built
 * for AVX-512 and AVX2 besides the baseline, chosen at run time.
 *
 * OpenMP: the rows (or row segments) of a sweep, and for d >= 3 the planes
 * (one range of planes per thread), are shared among the threads; each
 * node's value depends on its stencil only, so results are bitwise the
 * same for any thread count (unit test).
 *
 * Library code: returns HJ_* codes, never prints.
 */
#ifndef HJ_UB_DENSE_H
#define HJ_UB_DENSE_H

#include <stddef.h>

#include "hj_error.h"
#include "hj_ub.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The dynamics of control a over a row of len nodes: the row's first d - 1
 * coordinates in x[0..d-2], the last coordinate of node j in xlast[j];
 * writes f[k len + j], component k of f(t, x_j, a). */
typedef void (*hj_ub_row_fn)(double t, const double *x, const double *xlast, long len, int a, double *f, void *ctx);

typedef struct {
    const hj_ub_problem *pb; /* d, n, lo, hi, ncontrols, dyn, target, cfl, boundary, dtmax, snap, ctx */
    hj_ub_row_fn dyn_row;    /* NULL: pb->dyn node by node */
    int nthreads;            /* OpenMP threads of the sweeps (the maximum when set up) */
    size_t total;            /* n^d */
    double dx[HJ_BAND_DMAX];
    double *w1, *vmin;       /* the sweep in direction 0 (d = 2, 4), minimum over controls */
    double *xlast;           /* last coordinate of nodes -1 .. n */
    double *buf;             /* per-thread row buffers */
    size_t bufper;
    double *planes;          /* per-thread plane buffers (d >= 3) */
    size_t planeper;
    int group;               /* controls sharing a pass (d = 3; may be lowered after init) */
    double *v;               /* V during a step */
    int autonomous;          /* set by the caller: 1 when f does not depend on t */
    int rate_known;          /* the CFL rate max |f_k| / dx_k is ws->rate (autonomous f) */
    double rate;
    double rate_t;           /* the time at which ws->rate was computed */
    /* Set by hj_ub_dense_dt when the dynamics gave a NaN or infinite f
     * there (the first such node in row order: its centre, control,
     * component and value); dt is then NaN and hj_ub_dense_step refuses. */
    int bad, bad_a, bad_k;
    double bad_f, bad_t, bad_x[HJ_BAND_DMAX];
} hj_ub_dense;

/* Set up the workspace for problem pb (pb->avg0, uniform, reached, bbox and
 * front_sub are not used).  Holds n^d doubles besides the caller's V
 * (2 n^d for d = 2, 4), and per thread for d >= 3 the planes' faces (4 n^2
 * doubles per control of a group) and a plane. */
int hj_ub_dense_init(hj_ub_dense *ws, const hj_ub_problem *pb, hj_ub_row_fn dyn_row, hj_error *err);
void hj_ub_dense_free(hj_ub_dense *ws);

/* The time step at time t towards tmax: CFL pb->cfl over every node and
 * control, truncated to land on tmax, capped by pb->dtmax (hj_ub_step's).
 * The rate max |f_k| / dx_k costs one evaluation of the dynamics over the
 * grid; with ws->autonomous set (f independent of t) it is computed once.
 * tmax <= t gives tmax - t (<= 0: no step to take), a NaN tmax NaN.  A NaN or infinite f at
 * some node gives NaN, with the node in ws->bad_* (before, a NaN f was
 * skipped by the maximum and the step filled V with NaN without an error;
 * an infinite one gave dt = 0). */
double hj_ub_dense_dt(hj_ub_dense *ws, double t, double tmax);

/* V^{n+1} from V^n = v at time t, in place, with the step dt (from
 * hj_ub_dense_dt; dt > 0).  HJ_EINVAL for dt <= 0 or NaN, and for a dt
 * above the scheme's limit, dt max |f_k| / dx_k > 1, when that rate is
 * known (computed by hj_ub_dense_dt at this t, or once for autonomous f):
 * the fluxes stay within [-1, 1] there, so the result looked plausible.
 * HJ_ENONFINITE naming the node, control and time when the last
 * hj_ub_dense_dt met a NaN or infinite f.  V itself is not checked. */
int hj_ub_dense_step(hj_ub_dense *ws, double *v, double t, double dt, hj_error *err);

#ifdef __cplusplus
}
#endif

#endif
