/* hj_ub_dense.c -- the UB-HJB step on the full grid, row by row (see
 * hj_ub_dense.h).  The arithmetic is hj_ub.c's, operation for operation,
 * so that the values are bitwise those of hj_ub_step on the FS store. */
#include "hj_ub_dense.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif

/* Row segments of the strided sweeps: long enough to vectorise, short
 * enough that the rolling rows stay in L1/L2, many enough to share among
 * threads on a 2-D grid. */
enum { SEG = 256 };

/* The row kernels are built for AVX-512 and AVX2 as well as the baseline
 * x86-64 and chosen at run time (-std=c11 contracts no a b + c into an
 * FMA: the same IEEE operations, the same bits). */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__SANITIZE_ADDRESS__)
#define HJ_UB_CLONES __attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
#else
#define HJ_UB_CLONES
#endif

/* The planes' faces of a group of controls that share a pass of the d = 3
 * step (sweep_planes), per thread: in the last level cache with the rows
 * they read. */
#define GROUP_BYTES 4e6

static size_t seg_max(int n) { return (size_t)n > SEG ? (size_t)n : SEG; }

/* Per-thread buffer, in doubles from its start (s = seg_max(n)):
 * strided sweeps: mu, A, P of two parities, the boundary row, Q (6 s);
 * the dynamics of two rows (2 d (n + 2));
 * the last direction's padded row: W_{-3 .. n+2} (n + 6), then mu, A, P, Q
 * of nodes -1 .. n (4 (n + 2)). */
static size_t buf_size(int d, int n)
{
    return 6 * seg_max(n) + 2 * (size_t)d * (size_t)(n + 2) + (size_t)(n + 6) + 4 * (size_t)(n + 2);
}

static int thread_id(void)
{
#ifdef _OPENMP
    return omp_get_thread_num();
#else
    return 0;
#endif
}

int hj_ub_dense_init(hj_ub_dense *ws, const hj_ub_problem *pb, hj_ub_row_fn dyn_row, hj_error *err)
{
    memset(ws, 0, sizeof *ws);
    int rc = hj_ub_problem_check_shape(pb, 0, err);
    if (rc) return rc;
    if (!pb->dyn && !dyn_row) return hj_error_set(err, HJ_EINVAL, "problem: no dynamics (neither pb->dyn nor dyn_row)");
    rc = hj_ub_problem_check_values(pb, err);
    if (rc) return rc;
    const int d = pb->d, n = pb->n;
    double total = 1;
    for (int k = 0; k < d; k++) {
        if (!(pb->hi[k] > pb->lo[k])) return hj_error_set(err, HJ_EINVAL, "problem: empty domain");
        ws->dx[k] = (pb->hi[k] - pb->lo[k]) / (n - 1);
        total *= n;
    }
    if (total * 8 * 3 > (double)SIZE_MAX / 2) return hj_error_set(err, HJ_ENOMEM, "out of memory: %d^%d grid", n, d);
    ws->pb = pb;
    ws->dyn_row = dyn_row;
    ws->total = (size_t)total;
#ifdef _OPENMP
    ws->nthreads = omp_get_max_threads();
#else
    ws->nthreads = 1;
#endif
    ws->bufper = buf_size(d, n);
    /* d = 3: controls in groups whose planes' faces take about
     * GROUP_BYTES per thread; d = 4: one (each has its own w1) */
    const double face_bytes = 4.0 * n * n * sizeof(double);
    ws->group = d == 3 && GROUP_BYTES / face_bytes > 1 ? (int)(GROUP_BYTES / face_bytes) : 1;
    if (ws->group > pb->ncontrols) ws->group = pb->ncontrols;
    /* per thread, d >= 3: the intermediate plane, mu, A, two P for each
     * control of a group (n^2 each), Q, the boundary row and the dynamics
     * of a row */
    ws->planeper = d >= 3 ? (1 + 4 * (size_t)ws->group) * (size_t)n * (size_t)n + (size_t)(2 + d) * (size_t)n : 0;
    ws->w1 = d != 3 ? malloc(ws->total * sizeof *ws->w1) : NULL; /* d = 3: no intermediate grid */
    ws->vmin = malloc(ws->total * sizeof *ws->vmin);
    ws->xlast = malloc((size_t)(n + 2) * sizeof *ws->xlast);
    ws->buf = malloc((size_t)ws->nthreads * ws->bufper * sizeof *ws->buf);
    ws->planes = d >= 3 ? malloc((size_t)ws->nthreads * ws->planeper * sizeof *ws->planes) : NULL;
    if ((d != 3 && !ws->w1) || !ws->vmin || !ws->xlast || !ws->buf || (d >= 3 && !ws->planes)) {
        hj_ub_dense_free(ws);
        return hj_error_set(err, HJ_ENOMEM, "out of memory: UB workspace of %.3g GB", total * 16 / 1e9);
    }
    /* as hj_ub_centre, and the cells beside the ends as mu_beside: x -+ dx */
    const int l = d - 1;
    for (int j = 0; j < n; j++) ws->xlast[j + 1] = pb->lo[l] + j * ws->dx[l];
    ws->xlast[0] = ws->xlast[1] - ws->dx[l];
    ws->xlast[n + 1] = ws->xlast[n] + ws->dx[l];
    return HJ_OK;
}

void hj_ub_dense_free(hj_ub_dense *ws)
{
    free(ws->w1);
    free(ws->planes);
    free(ws->vmin);
    free(ws->xlast);
    free(ws->buf);
    memset(ws, 0, sizeof *ws);
}

/* The first d - 1 coordinates of row r (row-major over the first d - 1
 * indices); position `at` (-1 or n) in direction k replaces idx[k] by the
 * cell beside the grid, x -+ dx as hj_ub.c's mu_beside. */
static void row_coords(const hj_ub_dense *ws, size_t r, int k, int at, double *x)
{
    const hj_ub_problem *pb = ws->pb;
    const int n = pb->n;
    for (int q = pb->d - 2; q >= 0; q--) {
        const int i = (int)(r % (size_t)n);
        r /= (size_t)n;
        x[q] = pb->lo[q] + i * ws->dx[q];
    }
    if (at < 0) x[k] = (pb->lo[k] + 0 * ws->dx[k]) - ws->dx[k];
    else if (at >= n) x[k] = (pb->lo[k] + (n - 1) * ws->dx[k]) + ws->dx[k];
}

/* f over a row: the batched callback, or the per-node one. */
static void row_dyn(const hj_ub_dense *ws, double t, const double *x, const double *xl, long len, int a, double *f)
{
    const hj_ub_problem *pb = ws->pb;
    if (ws->dyn_row) {
        ws->dyn_row(t, x, xl, len, a, f, pb->ctx);
        return;
    }
    const int d = pb->d;
    double y[HJ_BAND_DMAX], g[HJ_BAND_DMAX];
    memcpy(y, x, sizeof y);
    for (long j = 0; j < len; j++) {
        y[d - 1] = xl[j];
        pb->dyn(t, y, a, g, pb->ctx);
        for (int k = 0; k < d; k++) f[(long)k * len + j] = g[k];
    }
}

/* max_j |f[j]|: a max reduction gcc vectorises, the same maximum in any
 * order (|f| >= 0 has no signed zero; a NaN is skipped here as by q > m). */
HJ_UB_CLONES
static double row_absmax(long len, const double *restrict f)
{
    double m = 0;
#pragma omp simd reduction(max : m)
    for (long j = 0; j < len; j++) {
        const double q = fabs(f[j]);
        m = q > m ? q : m;
    }
    return m;
}

/* 1 when f[0..m-1] are all finite (f * 0 is 0 for a finite f, NaN else). */
HJ_UB_CLONES
static int row_finite(size_t m, const double *restrict f)
{
    double z = 0;
#pragma omp simd reduction(+ : z)
    for (size_t j = 0; j < m; j++) z += f[j] * 0.0;
    return z == 0;
}

/* max over nodes, controls and directions of |f_k| / dx_k at time t */
static double max_rate(hj_ub_dense *ws, double t)
{
    const hj_ub_problem *pb = ws->pb;
    const int d = pb->d, n = pb->n;
    const size_t rows = ws->total / (size_t)n;
    double rate = 0;
    size_t bad = SIZE_MAX; /* the first row with a non-finite f */
#pragma omp parallel for num_threads(ws->nthreads) schedule(static) reduction(max : rate) reduction(min : bad)
    for (size_t r = 0; r < rows; r++) {
        double x[HJ_BAND_DMAX] = {0}, *f = ws->buf + (size_t)thread_id() * ws->bufper;
        row_coords(ws, r, 0, 0, x);
        for (int a = 0; a < pb->ncontrols; a++) {
            row_dyn(ws, t, x, ws->xlast + 1, n, a, f);
            /* max |f_k| / dx_k = max (|f_k| / dx_k): division is monotone */
            for (int k = 0; k < d; k++) {
                const double q = row_absmax(n, f + (size_t)k * (size_t)n) / ws->dx[k];
                rate = q > rate ? q : rate;
            }
            if (!row_finite((size_t)d * (size_t)n, f) && r < bad) bad = r;
        }
    }
    ws->bad = 0;
    if (bad == SIZE_MAX) return rate;
    /* the row again, alone, to name the first node */
    double x[HJ_BAND_DMAX] = {0}, *f = ws->buf;
    row_coords(ws, bad, 0, 0, x);
    for (int a = 0; a < pb->ncontrols && !ws->bad; a++) {
        row_dyn(ws, t, x, ws->xlast + 1, n, a, f);
        for (long j = 0; j < n && !ws->bad; j++)
            for (int k = 0; k < d && !ws->bad; k++)
                if (!isfinite(f[(size_t)k * (size_t)n + (size_t)j])) {
                    ws->bad = 1, ws->bad_a = a, ws->bad_k = k, ws->bad_f = f[(size_t)k * (size_t)n + (size_t)j], ws->bad_t = t;
                    memcpy(ws->bad_x, x, sizeof x);
                    ws->bad_x[d - 1] = ws->xlast[1 + j];
                }
    }
    return NAN;
}


double hj_ub_dense_dt(hj_ub_dense *ws, double t, double tmax)
{
    const hj_ub_problem *pb = ws->pb;
    if (isnan(tmax)) return NAN; /* hj_ub_step refuses it; was a CFL step */
    if (!ws->autonomous || !ws->rate_known) {
        ws->rate = max_rate(ws, t);
        ws->rate_known = 1;
        ws->rate_t = t;
    }
    if (ws->bad) return NAN;
    const double rate = ws->rate, left = tmax - t;
    const double dt = rate * left <= pb->cfl ? left : pb->cfl / rate;
    return pb->dtmax > 0 && dt > pb->dtmax ? pb->dtmax : dt;
}

/* ---- the Ultra-Bee faces over rows (hj_ub.c's flux_left, flux_right) ------ */

/* What node j gives the faces of the update in one direction, from W_{j-2..j+2}
 * and mu_j = dt/dx_k f_k:
 *  A_j, the flux node j hands to the face it feeds when mu_j != 0: W^L_{j+1/2}
 *    (mu_j > 0) or W^R_{j-1/2} (mu_j < 0).  hj_ub.c clips to
 *    [mx + (c - mx)/mu, mn + (c - mn)/mu] with mx, mn the max and min of
 *    c = W_j and its upwind neighbour e: one of the two bounds is
 *    c + (+0)/mu = c + 0.0, so one division gives both, bit for bit (c + 0.0
 *    keeps the sign-of-zero rule of the original);
 *  P_j, the face j+1/2 as node j+1 uses it when mu_{j+1} > 0: A_j when node j
 *    flows right, else the mu = 0 value or (8) of hj_ub_update;
 *  Q_j, the face j-1/2 as node j-1 uses it when mu_{j-1} < 0, symmetrically.
 * With P and Q each node's update reads 5 values instead of 11. */
static inline void node_faces(double wmm, double wm, double w0, double wp, double wpp, double m, double *A, double *P,
                              double *Q)
{
    const int right = m > 0;
    const double e = right ? wm : wp, down = right ? wp : wm;
    /* |mu| (hj_ub.c's -mu when mu < 0); 1 for mu = 0, where A is not used
     * (nor for a NaN mu, whose update is NaN whatever A) */
    const double den = m == 0 ? 1 : fabs(m);
    const double g = e + (w0 - e) / den, c0 = w0 + 0.0;
    const double lo = w0 > e ? c0 : g, hi = w0 < e ? c0 : g;
    const double x = down < lo ? lo : down, a = x > hi ? hi : x;
    /* two-way selects one after the other: gcc if-converts these (not
     * one nested select of five arms) */
    const double pz = w0 != wm ? wp : w0, pn = wp == wpp ? wp : w0, p0 = m == 0 ? pz : pn;
    const double qz = w0 != wp ? wm : w0, qp = wm == wmm ? wm : w0, q0 = m == 0 ? qz : qp;
    *A = a;
    *P = m > 0 ? a : p0;
    *Q = m < 0 ? a : q0;
}

/* The update W_j - mu_j (W^L_{j+1/2} - W^R_{j-1/2}) of hj_ub_update from node
 * j's own mu_j, A_j and its neighbours' P_{j-1}, Q_{j+1}. */
static inline double node_step(double w0, double m, double a, double pl, double qr)
{
    const double df = m > 0 ? a - pl : qr - a;
    return m == 0 ? w0 : w0 - m * df;
}

/* A strided sweep's step from row i to row i+1, in one pass: the faces of
 * row i+1 from rows r0..r4 = W_{i-1..i+3} and its f_k, and the update of row
 * i = r1 into out.  mu, A hold row i's on entry and row i+1's on return; P
 * holds P_{i-1} on entry and P_{i+1} on return (Q_{i+1} is used at once). */
HJ_UB_CLONES
static void row_pipe(long len, const double *restrict r0, const double *restrict r1, const double *restrict r2,
                     const double *restrict r3, const double *restrict r4, const double *restrict fk, double c,
                     double *restrict mu, double *restrict A, double *restrict P, double *restrict out)
{
    for (long j = 0; j < len; j++) {
        const double m = c * fk[j];
        double a, p, q;
        node_faces(r0[j], r1[j], r2[j], r3[j], r4[j], m, &a, &p, &q);
        out[j] = node_step(r1[j], mu[j], A[j], P[j], q);
        mu[j] = m;
        A[j] = a;
        P[j] = p;
    }
}

/* The faces of the row r2 (rows r0..r4 around it) without an update: those
 * of the first rows of a strided sweep, or with stride 1 the faces of a
 * whole padded row. */
HJ_UB_CLONES
static void row_faces(long len, const double *restrict r0, const double *restrict r1, const double *restrict r2,
                      const double *restrict r3, const double *restrict r4, const double *restrict fk, double c,
                      double *restrict mu, double *restrict A, double *restrict P, double *restrict Q)
{
    for (long j = 0; j < len; j++) {
        const double m = c * fk[j];
        double a, p, q;
        node_faces(r0[j], r1[j], r2[j], r3[j], r4[j], m, &a, &p, &q);
        mu[j] = m;
        A[j] = a;
        P[j] = p;
        Q[j] = q;
    }
}

/* The last direction's update of a padded row (w[j] = W_j, mu[j], A[j],
 * P[j], Q[j] for j = -1 .. n, n = len): mode 0 stores it into vmin, mode 1
 * the minimum with vmin; mode 2 is the last control's: the minimum over the
 * controls (vmin NULL: a single control), the min with V^n = vn for the
 * target problem, and the snap to +-1, into out.  out may be vmin or vn
 * itself (each node reads its own entries before writing: ivdep). */
HJ_UB_CLONES
static void row_last(long len, const double *restrict w, const double *restrict mu, const double *restrict A,
                     const double *restrict P, const double *restrict Q, int mode, double *vmin, int target,
                     double snap, const double *vn, double *out)
{
    if (mode == 0)
#pragma GCC ivdep
        for (long j = 0; j < len; j++) vmin[j] = node_step(w[j], mu[j], A[j], P[j - 1], Q[j + 1]);
    else if (mode == 1)
#pragma GCC ivdep
        for (long j = 0; j < len; j++) {
            const double u = node_step(w[j], mu[j], A[j], P[j - 1], Q[j + 1]);
            vmin[j] = u < vmin[j] ? u : vmin[j];
        }
    else
#pragma GCC ivdep
        for (long j = 0; j < len; j++) {
            double u = node_step(w[j], mu[j], A[j], P[j - 1], Q[j + 1]);
            u = !vmin || u < vmin[j] ? u : vmin[j];
            u = target && vn[j] < u ? vn[j] : u;
            out[j] = u > 1 - snap ? 1 : u < -1 + snap ? -1 : u;
        }
}

static double *buf_f(const hj_ub_dense *ws, double *b, int slot)
{
    return b + 6 * seg_max(ws->pb->n) + (size_t)slot * (size_t)ws->pb->d * (size_t)(ws->pb->n + 2);
}
/* W_0 of the padded row */
static double *last_row_in(const hj_ub_dense *ws, double *b) { return buf_f(ws, b, 2) + 3; }

/* What the last direction's sweep does with its rows: mode 0 / 1 / 2 of
 * row_last (first: no minimum over the controls yet); V^n is v, the last
 * control's values go to out (v, or vmin when V^n is still to be read). */
typedef struct {
    double *v, *out;
    int mode, first;
    double snap;
} fused;

/* The last direction's sweep of row r from the padded row of buffer b
 * (W_0 .. W_{n-1} filled by the caller) with the dynamics of the row f
 * (d (n + 2) values: nodes -1 .. n): pads with the boundary value, faces,
 * update (row_last's modes). */
static void last_row(hj_ub_dense *ws, double *b, const double *f, size_t r, const fused *fz, double dt)
{
    const hj_ub_problem *pb = ws->pb;
    const int d = pb->d, n = pb->n, k = d - 1;
    double *w = last_row_in(ws, b), *mu = w + n + 3, *A = mu + n + 2, *P = A + n + 2, *Q = P + n + 2;
    w[-3] = w[-2] = w[-1] = w[n] = w[n + 1] = w[n + 2] = pb->boundary;
    /* node j = -1 .. n at index j + 1 */
    row_faces(n + 2, w - 3, w - 2, w - 1, w, w + 1, f + (size_t)k * (size_t)(n + 2), dt / ws->dx[k], mu, A, P, Q);
    const size_t o = r * (size_t)n;
    row_last(n, w, mu + 1, A + 1, P + 1, Q + 1, fz->mode, fz->mode == 2 && fz->first ? NULL : ws->vmin + o, pb->target,
             fz->snap, fz->v + o, fz->out + o);
}

/* Sweep in the last direction alone (d = 2): every row on its own. */
static void sweep_last(hj_ub_dense *ws, const double *src, const fused *fz, int a, double t, double dt)
{
    const int n = ws->pb->n;
    const size_t rows = ws->total / (size_t)n;
#pragma omp parallel for num_threads(ws->nthreads) schedule(static)
    for (size_t r = 0; r < rows; r++) {
        double *b = ws->buf + (size_t)thread_id() * ws->bufper, *f = buf_f(ws, b, 0);
        double x[HJ_BAND_DMAX] = {0};
        row_coords(ws, r, 0, 0, x);
        row_dyn(ws, t, x, ws->xlast, n + 2, a, f);
        memcpy(last_row_in(ws, b), src + r * (size_t)n, (size_t)n * sizeof *src);
        last_row(ws, b, f, r, fz, dt);
    }
}

/* One line of a sweep in direction k < d - 1: the rows i = 0 .. n-1 along
 * k, row i at src0 + i sstride (columns j0 .. j0 + len - 1), grid row base
 * + i stride, walked with row_pipe into dst (or, last != NULL, each row
 * straight to the last direction's sweep, without a grid between the two,
 * with the dynamics evaluated here for it: whole rows, j0 = 0). */
static void sweep_line(hj_ub_dense *ws, double *b, int k, const double *src0, size_t sstride, size_t base, size_t stride,
                       size_t j0, long len, size_t SEGL, double *dst, int a, double t, double dt, const fused *last)
{
    const int n = ws->pb->n;
    const double c = dt / ws->dx[k];
    double *mu = b, *A = b + SEGL, *P[2] = {b + 2 * SEGL, b + 3 * SEGL}, *brow = b + 4 * SEGL, *Q = b + 5 * SEGL;
    /* fused: the dynamics of the whole row (nodes -1 .. n) are kept for
     * the last direction's sweep of that row */
    const long fn = last ? n + 2 : len, fo = last ? 1 : 0;
    for (long j = 0; j < len; j++) brow[j] = ws->pb->boundary;
#define ROW(i) ((i) < 0 || (i) >= n ? brow : src0 + (size_t)(i) * sstride)
    /* the dynamics of row i (-1 .. n) into slot i & 1; its f_k */
#define FILL(i, fk)                                                                                     \
    do {                                                                                                \
        double x_[HJ_BAND_DMAX] = {0}, *f_ = buf_f(ws, b, (i) & 1);                                     \
        row_coords(ws, base + (size_t)((i) < 0 ? 0 : (i) >= n ? n - 1 : (i)) * stride, k, (i), x_);    \
        row_dyn(ws, t, x_, ws->xlast + 1 - fo + j0, fn, a, f_);                                        \
        fk = f_ + (long)k * fn + fo;                                                                    \
    } while (0)
    const double *fk;
    /* P_{-1}; mu_0, A_0, P_0 */
    FILL(-1, fk);
    row_faces(len, ROW(-3), ROW(-2), ROW(-1), ROW(0), ROW(1), fk, c, mu, A, P[1], Q);
    FILL(0, fk);
    row_faces(len, ROW(-2), ROW(-1), ROW(0), ROW(1), ROW(2), fk, c, mu, A, P[0], Q);
    for (int i = 0; i < n; i++) {
        /* the row the next iteration brings in, one grid plane away
         * for k = 0: ask for it now (the hardware does not follow) */
        if (i + 4 < n) {
            const char *nx = (const char *)ROW(i + 4);
            for (long j = 0; j < len * (long)sizeof(double); j += 64) __builtin_prefetch(nx + j);
        }
        /* and the row of the grid written two steps on: the
         * intermediate grid, or the running minimum (and V for the
         * last control) of the fused last sweep */
        if (i + 2 < n) {
            const size_t o = (base + (size_t)(i + 2) * stride) * (size_t)n + j0;
            const char *wr = (const char *)(last ? (last->mode == 2 ? last->out : ws->vmin) + o : dst + o);
            for (long j = 0; j < len * (long)sizeof(double); j += 64) __builtin_prefetch(wr + j, 1);
            if (last && last->mode == 2 && !last->first && last->out != ws->vmin)
                for (long j = 0; j < len * (long)sizeof(double); j += 64)
                    __builtin_prefetch((const char *)(ws->vmin + o) + j);
        }
        FILL(i + 1, fk);
        const size_t row = base + (size_t)i * stride;
        double *out = last ? last_row_in(ws, b) : dst + row * (size_t)n + j0;
        row_pipe(len, ROW(i - 1), ROW(i), ROW(i + 1), ROW(i + 2), ROW(i + 3), fk, c, mu, A, P[(i + 1) & 1], out);
        if (last) last_row(ws, b, buf_f(ws, b, i & 1), row, last, dt);
    }
#undef FILL
#undef ROW
}

/* Sweep in direction k < d - 1 over the grid into dst: lines of rows
 * along k, in segments of SEG columns. */
static void sweep_rows(hj_ub_dense *ws, int k, const double *src, double *dst, int a, double t, double dt)
{
    const hj_ub_problem *pb = ws->pb;
    const int d = pb->d, n = pb->n;
    size_t stride = 1; /* rows between neighbours in direction k */
    for (int q = k + 1; q < d - 1; q++) stride *= (size_t)n;
    const size_t lines = ws->total / ((size_t)n * (size_t)n), nseg = ((size_t)n + SEG - 1) / SEG;
#pragma omp parallel for num_threads(ws->nthreads) schedule(static)
    for (size_t item = 0; item < lines * nseg; item++) {
        const size_t line = item / nseg, j0 = (item % nseg) * SEG;
        const long len = (long)((size_t)n - j0 < SEG ? (size_t)n - j0 : SEG);
        const size_t base = (line / stride) * (size_t)n * stride + line % stride;
        sweep_line(ws, ws->buf + (size_t)thread_id() * ws->bufper, k, src + base * (size_t)n + j0, stride * (size_t)n,
                   base, stride, j0, len, SEG, dst, a, t, dt, NULL);
    }
}

/* The last three directions K = d - 3, d - 2, d - 1 of the controls a0 ..
 * a1-1, plane by plane: a plane is the n^2 nodes of one index i along K
 * (and of one index along direction 0 for d = 4).  For each control, the
 * sweep in K steps from plane i to plane i + 1 as sweep_line does from row
 * to row, with the faces of a plane kept (per thread and control: mu, A,
 * two P), and writes plane i of the intermediate grid into a buffer of
 * one plane; the plane's line along d - 2 then runs at once, each row to
 * the last direction.  No intermediate grid, and the controls of a group
 * share the pass: the running minimum and src are read from memory once
 * per group, and the other controls find them in cache.
 *
 * The planes along K are cut into one range per thread (each starts with
 * the faces of its first two planes), so that d = 3 shares work among
 * threads.  For d = 3, src is V^n itself: the last control's values go to
 * vmin first (read there, then written), and back into v once no thread
 * reads V^n there: a plane q of the range [p0, p1) after step q + 1
 * unless the neighbouring ranges read it (q < p0 + 3 or q >= p1 - 3:
 * after a barrier). */
static void sweep_planes(hj_ub_dense *ws, const double *src, int a0, int a1, double t, double dt, double snap)
{
    const hj_ub_problem *pb = ws->pb;
    const int d = pb->d, n = pb->n, K = d - 3, na = pb->ncontrols;
    const size_t nn = (size_t)n * (size_t)n, nouter = ws->total / (nn * (size_t)n);
    const int inplace = d == 3 && a1 == na;
    const double c = dt / ws->dx[K];
#pragma omp parallel num_threads(ws->nthreads)
    {
#ifdef _OPENMP
        const int nt = omp_get_num_threads();
#else
        const int nt = 1;
#endif
        const int tid = thread_id();
        double *b = ws->buf + (size_t)tid * ws->bufper, *pl = ws->planes + (size_t)tid * ws->planeper;
        double *w = pl, *Q = pl + (1 + 4 * (size_t)ws->group) * nn, *brow = Q + n, *fr = brow + n;
        for (int j = 0; j < n; j++) brow[j] = pb->boundary;
        /* ranges: nouter x nt, cyclic over the threads */
        const size_t items = nouter * (size_t)nt;
        for (size_t item = (size_t)tid; item < items; item += (size_t)nt) {
            const size_t o = item / (size_t)nt;
            const int ch = (int)(item % (size_t)nt), p0 = (int)((long)n * ch / nt), p1 = (int)((long)n * (ch + 1) / nt);
            const double *so = src + o * nn * (size_t)n;
            /* the rows of plane i, row i1; the absolute row index */
#define PROW(i, i1) ((i) < 0 || (i) >= n ? brow : so + ((size_t)(i) * nn + (size_t)(i1) * (size_t)n))
#define GROW(i, i1) ((o * (size_t)n + (size_t)(i)) * (size_t)n + (size_t)(i1))
#define FILL(i, i1, fk)                                                                                        \
    do {                                                                                                       \
        double x_[HJ_BAND_DMAX] = {0};                                                                         \
        row_coords(ws, GROW((i) < 0 ? 0 : (i) >= n ? n - 1 : (i), i1), K, (i), x_);                           \
        row_dyn(ws, t, x_, ws->xlast + 1, n, a, fr);                                                           \
        fk = fr + (long)K * n;                                                                                 \
    } while (0)
            if (p0 >= p1) continue;
            const double *fk;
            /* P_{p0-1}; mu, A, P of p0 */
            for (int a = a0; a < a1; a++) {
                double *mu = pl + (1 + 4 * (size_t)(a - a0)) * nn, *A = mu + nn, *P[2] = {A + nn, A + 2 * nn};
                for (int i1 = 0; i1 < n; i1++) {
                    const size_t r = (size_t)i1 * (size_t)n;
                    FILL(p0 - 1, i1, fk);
                    row_faces(n, PROW(p0 - 3, i1), PROW(p0 - 2, i1), PROW(p0 - 1, i1), PROW(p0, i1), PROW(p0 + 1, i1), fk,
                              c, mu + r, A + r, P[(p0 + 1) & 1] + r, Q);
                    FILL(p0, i1, fk);
                    row_faces(n, PROW(p0 - 2, i1), PROW(p0 - 1, i1), PROW(p0, i1), PROW(p0 + 1, i1), PROW(p0 + 2, i1), fk,
                              c, mu + r, A + r, P[p0 & 1] + r, Q);
                }
            }
            for (int i = p0; i < p1; i++) {
                for (int a = a0; a < a1; a++) {
                    double *mu = pl + (1 + 4 * (size_t)(a - a0)) * nn, *A = mu + nn, *P[2] = {A + nn, A + 2 * nn};
                    for (int i1 = 0; i1 < n; i1++) {
                        const size_t r = (size_t)i1 * (size_t)n;
                        FILL(i + 1, i1, fk);
                        row_pipe(n, PROW(i - 1, i1), PROW(i, i1), PROW(i + 1, i1), PROW(i + 2, i1), PROW(i + 3, i1), fk,
                                 c, mu + r, A + r, P[(i + 1) & 1] + r, w + r);
                    }
                    /* d = 3: the last control's values wait in vmin */
                    const fused fz = {.v = ws->v, .out = d == 3 ? ws->vmin : ws->v, .mode = a == na - 1 ? 2 : a == 0 ? 0 : 1,
                                      .first = a == 0, .snap = snap};
                    sweep_line(ws, b, d - 2, w, (size_t)n, GROW(i, 0), 1, 0, n, seg_max(n), NULL, a, t, dt, &fz);
                }
                const int q = i - 1;
                if (inplace && q >= p0 + 3 && q < p1 - 3)
                    memcpy(ws->v + GROW(q, 0) * (size_t)n, ws->vmin + GROW(q, 0) * (size_t)n, nn * sizeof(double));
            }
        }
        if (inplace) {
#pragma omp barrier
            for (size_t item = (size_t)tid; item < items; item += (size_t)nt) {
                const size_t o = item / (size_t)nt;
                const int ch = (int)(item % (size_t)nt), p0 = (int)((long)n * ch / nt), p1 = (int)((long)n * (ch + 1) / nt);
                for (int q = p0; q < p1; q++)
                    if (q < p0 + 3 || q >= p1 - 3)
                        memcpy(ws->v + GROW(q, 0) * (size_t)n, ws->vmin + GROW(q, 0) * (size_t)n, nn * sizeof(double));
            }
        }
#undef FILL
#undef GROW
#undef PROW
    }
}

int hj_ub_dense_step(hj_ub_dense *ws, double *v, double t, double dt, hj_error *err)
{
    const hj_ub_problem *pb = ws->pb;
    if (ws->bad) {
        char xs[128];
        int at = 0;
        for (int k = 0; k < pb->d && at < (int)sizeof xs; k++)
            at += snprintf(xs + at, sizeof xs - (size_t)at, "%s%g", k ? ", " : "", ws->bad_x[k]);
        return hj_error_set(err, HJ_ENONFINITE, "dynamics: f_%d = %g at x = (%s), control %d, t = %g (must be finite)",
                            ws->bad_k, ws->bad_f, xs, ws->bad_a, ws->bad_t);
    }
    if (!(dt > 0)) return hj_error_set(err, HJ_EINVAL, "UB step: dt must be > 0, got %g", dt);
    /* the scheme's limit, where the rate at this t is known */
    if (ws->rate_known && (ws->autonomous || ws->rate_t == t) && dt * ws->rate > 1 + 1e-12)
        return hj_error_set(err, HJ_EINVAL,
                            "UB step: dt = %g is above the scheme's limit 1 / max |f_k| / dx_k = %g (Courant number %g > 1)",
                            dt, 1 / ws->rate, dt * ws->rate);
    const int d = pb->d, na = pb->ncontrols;
    const double snap = pb->snap > 0 ? pb->snap : 1e-12;
    ws->v = v;
    if (d == 3)
        for (int a = 0; a < na; a += ws->group) sweep_planes(ws, v, a, a + ws->group < na ? a + ws->group : na, t, dt, snap);
    else
        for (int a = 0; a < na; a++) {
            /* d = 2, 4: direction 0 into w1, then the last direction row by
             * row (d = 2) or the last three plane by plane (d = 4) */
            sweep_rows(ws, 0, v, ws->w1, a, t, dt);
            if (d == 4) sweep_planes(ws, ws->w1, a, a + 1, t, dt, snap);
            else {
                const fused fz = {.v = v, .out = v, .mode = a == na - 1 ? 2 : a == 0 ? 0 : 1, .first = a == 0, .snap = snap};
                sweep_last(ws, ws->w1, &fz, a, t, dt);
            }
        }
    ws->v = NULL;
    return HJ_OK;
}
