/* hj_ub_dense.c -- the UB-HJB step on the full grid, row by row (see
 * hj_ub_dense.h).  The arithmetic is hj_ub.c's, operation for operation,
 * so that the values are bitwise those of hj_ub_step on the FS store. */
#include "hj_ub_dense.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif

/* Row segments of the strided sweeps: long enough to vectorise, short
 * enough that the rolling rows stay in L1/L2, many enough to share among
 * threads on a 2-D grid. */
enum { SEG = 256 };

/* The row kernels are built for AVX2 as well as the baseline x86-64 and
 * chosen at run time (no FMA: the same IEEE operations, the same bits). */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__SANITIZE_ADDRESS__)
#define HJ_UB_CLONES __attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
#else
#define HJ_UB_CLONES
#endif

/* Per-thread buffer: 7 rolling rows of sweep_rows (at most seg_max
 * columns), the dynamics of a row, and the padded row of the last sweep
 * (values, mu, fluxes). */
static size_t seg_max(int n) { return (size_t)n > SEG ? (size_t)n : SEG; }

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
    if (pb->d < 2 || pb->d > HJ_BAND_DMAX || pb->n < 3 || pb->ncontrols < 1 || (!pb->dyn && !dyn_row) || !(pb->cfl > 0) ||
        pb->cfl > 1)
        return hj_error_set(err, HJ_EINVAL, "problem: need 2 <= d <= 4, n >= 3, controls, dynamics, 0 < cfl <= 1");
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
    ws->bufper = 7 * seg_max(n) + (size_t)d * (size_t)(n + 2) + 3 * (size_t)(n + 4);
    ws->w1 = malloc(ws->total * sizeof *ws->w1);
    ws->w2 = d >= 4 ? malloc(ws->total * sizeof *ws->w2) : NULL; /* d = 2, 3: one intermediate grid at most */
    ws->vmin = malloc(ws->total * sizeof *ws->vmin);
    ws->xlast = malloc((size_t)(n + 2) * sizeof *ws->xlast);
    ws->buf = malloc((size_t)ws->nthreads * ws->bufper * sizeof *ws->buf);
    if (!ws->w1 || (d >= 4 && !ws->w2) || !ws->vmin || !ws->xlast || !ws->buf) {
        hj_ub_dense_free(ws);
        return hj_error_set(err, HJ_ENOMEM, "out of memory: UB workspace of %.3g GB", total * 24 / 1e9);
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
    free(ws->w2);
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

double hj_ub_dense_dt(hj_ub_dense *ws, double t, double tmax)
{
    const hj_ub_problem *pb = ws->pb;
    const int d = pb->d, n = pb->n;
    const size_t rows = ws->total / (size_t)n;
    double rate = 0;
#pragma omp parallel for num_threads(ws->nthreads) schedule(static) reduction(max : rate)
    for (size_t r = 0; r < rows; r++) {
        double x[HJ_BAND_DMAX] = {0}, *f = ws->buf + (size_t)thread_id() * ws->bufper;
        row_coords(ws, r, 0, 0, x);
        for (int a = 0; a < pb->ncontrols; a++) {
            row_dyn(ws, t, x, ws->xlast + 1, n, a, f);
            /* max |f_k| / dx_k = max (|f_k| / dx_k): division is monotone */
            for (int k = 0; k < d; k++) {
                double fk = 0;
                const double *fr = f + (size_t)k * (size_t)n;
                /* a max reduction gcc vectorises: the same maximum (|f| >= 0
                 * has no signed zero; a NaN is skipped here as by q > fk) */
#pragma omp simd reduction(max : fk)
                for (int j = 0; j < n; j++) {
                    const double q = fabs(fr[j]);
                    fk = q > fk ? q : fk;
                }
                const double q = fk / ws->dx[k];
                rate = q > rate ? q : rate;
            }
        }
    }
    const double left = tmax - t;
    const double dt = rate * left <= pb->cfl ? left : pb->cfl / rate;
    return pb->dtmax > 0 && dt > pb->dtmax ? pb->dtmax : dt;
}

/* ---- the Ultra-Bee fluxes over rows (hj_ub.c's flux_left, flux_right) ----- */

/* The flux node j hands to the face it feeds when mu_j != 0: W^L_{j+1/2}
 * (mu_j > 0) or W^R_{j-1/2} (mu_j < 0), from W_{j-1}, W_j, W_{j+1}.
 * hj_ub.c clips to [mx + (c - mx)/mu, mn + (c - mn)/mu] with mx, mn the
 * max and min of c = W_j and its upwind neighbour e: one of the two bounds
 * is c + (+0)/mu = c + 0.0, so one division gives both, bit for bit
 * (c + 0.0 keeps the sign-of-zero rule of the original). */
HJ_UB_CLONES
static void row_flux(long len, const double *restrict wm, const double *restrict wi, const double *restrict wp,
                     double cfl_k, const double *restrict fk, double *restrict mu, double *restrict out)
{
    for (long j = 0; j < len; j++) {
        /* mu_j = dt/dx_k f_k, stored for the update, in the same pass */
        const double m = cfl_k * fk[j], c = wi[j];
        mu[j] = m;
        const int right = m > 0;
        const double e = right ? wm[j] : wp[j], down = right ? wp[j] : wm[j];
        const double den = right ? m : m < 0 ? -m : 1;
        const double g = e + (c - e) / den, c0 = c + 0.0;
        const double lo = c > e ? c0 : g, hi = c < e ? c0 : g;
        const double x = down < lo ? lo : down;
        out[j] = x > hi ? hi : x;
    }
}

/* The update W_j - mu_j (W^L_{j+1/2} - W^R_{j-1/2}) of hj_ub_update, from
 * W_{j-2..j+2}, mu_{j-1..j+1} and the fluxes A_{j-1..j+1} of row_flux. */
static inline double node_update(double wmm, double wm, double w0, double wp, double wpp, double mL, double m0, double mR,
                                 double aL, double a0, double aR)
{
    /* left face when mu_j > 0: node j-1's flux if it flows right; its
     * mu = 0 value; else (8) */
    const double frp = mL > 0 ? aL : mL == 0 ? (wm != wmm ? w0 : wm) : (w0 == wp ? w0 : wm);
    /* right face when mu_j < 0, symmetrically */
    const double fln = mR < 0 ? aR : mR == 0 ? (wp != wpp ? w0 : wp) : (w0 == wm ? w0 : wp);
    const double fl = m0 > 0 ? a0 : fln, fr = m0 > 0 ? frp : a0;
    return m0 == 0 ? w0 : w0 - m0 * (fl - fr);
}

/* node_update over a row. */
HJ_UB_CLONES
static void row_update(long len, const double *restrict wmm, const double *restrict wm, const double *restrict w0,
                       const double *restrict wp, const double *restrict wpp, const double *restrict mL,
                       const double *restrict m0, const double *restrict mR, const double *restrict aL,
                       const double *restrict a0, const double *restrict aR, double *restrict out)
{
    for (long j = 0; j < len; j++)
        out[j] = node_update(wmm[j], wm[j], w0[j], wp[j], wpp[j], mL[j], m0[j], mR[j], aL[j], a0[j], aR[j]);
}

/* node_update over a row of the last sweep of a control, with the minimum
 * over the controls in the same pass: vmin = min(vmin, update). */
HJ_UB_CLONES
static void row_update_min(long len, const double *restrict w, const double *restrict mu, const double *restrict A,
                           double *restrict vmin)
{
    for (long j = 0; j < len; j++) {
        const double u = node_update(w[j], w[j + 1], w[j + 2], w[j + 3], w[j + 4], mu[j], mu[j + 1], mu[j + 2], A[j],
                                     A[j + 1], A[j + 2]);
        vmin[j] = u < vmin[j] ? u : vmin[j];
    }
}

/* The last control's last sweep: the minimum over the controls (vmin
 * NULL: a single control), the min with V^n for the target problem, and
 * the snap to +-1, into v (V^n on entry). */
HJ_UB_CLONES
static void row_update_final(long len, const double *restrict w, const double *restrict mu, const double *restrict A,
                             const double *restrict vmin, int target, double snap, double *restrict v)
{
    for (long j = 0; j < len; j++) {
        double u = node_update(w[j], w[j + 1], w[j + 2], w[j + 3], w[j + 4], mu[j], mu[j + 1], mu[j + 2], A[j], A[j + 1],
                               A[j + 2]);
        u = !vmin || u < vmin[j] ? u : vmin[j];
        u = target && v[j] < u ? v[j] : u;
        v[j] = u > 1 - snap ? 1 : u < -1 + snap ? -1 : u;
    }
}

/* The last direction's sweep of row r, from w[2 .. n + 1] (the buffer's
 * padded row, filled by the caller): pads with the boundary value and the
 * mu of the cells beside the ends, fluxes, update.  mode 0: the first
 * control's result into vmin; 1: the minimum with vmin; 2: the final value
 * of the step into v (first: a single control). */
static void last_row(hj_ub_dense *ws, double *b, size_t r, double *v, int mode, int first, double snap, int a, double t,
                     double dt)
{
    const hj_ub_problem *pb = ws->pb;
    const int d = pb->d, n = pb->n, k = d - 1;
    double *f = b + 7 * seg_max(n), *w = f + (size_t)d * (size_t)(n + 2), *mu = w + n + 4, *A = mu + n + 4;
    double x[HJ_BAND_DMAX] = {0};
    row_coords(ws, r, 0, 0, x);
    row_dyn(ws, t, x, ws->xlast, n + 2, a, f);
    w[0] = w[1] = w[n + 2] = w[n + 3] = pb->boundary; /* w[j + 2] = W_j */
    /* mu[j + 1] = mu_j, A[j + 1] = A_j, j = -1..n */
    row_flux(n + 2, w, w + 1, w + 2, dt / ws->dx[k], f + (size_t)k * (size_t)(n + 2), mu, A);
    const size_t o = r * (size_t)n;
    if (mode == 0)
        row_update(n, w, w + 1, w + 2, w + 3, w + 4, mu, mu + 1, mu + 2, A, A + 1, A + 2, ws->vmin + o);
    else if (mode == 1)
        row_update_min(n, w, mu, A, ws->vmin + o);
    else
        row_update_final(n, w, mu, A, first ? NULL : ws->vmin + o, pb->target, snap, v + o);
}

/* The padded row of last_row in thread buffer b. */
static double *last_row_in(const hj_ub_dense *ws, double *b)
{
    return b + 7 * seg_max(ws->pb->n) + (size_t)ws->pb->d * (size_t)(ws->pb->n + 2) + 2;
}

/* Sweep in the last direction alone (d = 2): every row on its own. */
static void sweep_last(hj_ub_dense *ws, const double *src, double *v, int mode, int first, double snap, int a, double t,
                       double dt)
{
    const int n = ws->pb->n;
    const size_t rows = ws->total / (size_t)n;
#pragma omp parallel for num_threads(ws->nthreads) schedule(static)
    for (size_t r = 0; r < rows; r++) {
        double *b = ws->buf + (size_t)thread_id() * ws->bufper;
        memcpy(last_row_in(ws, b), src + r * (size_t)n, (size_t)n * sizeof *src);
        last_row(ws, b, r, v, mode, first, snap, a, t, dt);
    }
}

/* The last sweep fused into sweep_rows (last != NULL): each row of the
 * sweep in direction d - 2 goes straight to last_row, without a grid
 * between the two. */
typedef struct {
    double *v;
    int mode, first;
    double snap;
} fused;

/* Sweep in direction k < d - 1: lines of rows along k, each walked with
 * three rolling rows of mu and fluxes, in segments of SEG columns (whole
 * rows when the last sweep is fused). */
static void sweep_rows(hj_ub_dense *ws, int k, const double *src, double *dst, int a, double t, double dt, const fused *last)
{
    const hj_ub_problem *pb = ws->pb;
    const int d = pb->d, n = pb->n;
    size_t stride = 1; /* rows between neighbours in direction k */
    for (int q = k + 1; q < d - 1; q++) stride *= (size_t)n;
    const size_t SEGL = last ? (size_t)n : SEG; /* whole rows when the last sweep follows */
    const size_t lines = ws->total / ((size_t)n * (size_t)n), nseg = ((size_t)n + SEGL - 1) / SEGL;
    const double bnd = pb->boundary, c = dt / ws->dx[k];
#pragma omp parallel for num_threads(ws->nthreads) schedule(static)
    for (size_t item = 0; item < lines * nseg; item++) {
        const size_t line = item / nseg, j0 = (item % nseg) * SEGL;
        const long len = (long)((size_t)n - j0 < SEGL ? (size_t)n - j0 : SEGL);
        const size_t base = (line / stride) * (size_t)n * stride + line % stride;
        double *b = ws->buf + (size_t)thread_id() * ws->bufper;
        double *mu[3] = {b, b + SEGL, b + 2 * SEGL}, *A[3] = {b + 3 * SEGL, b + 4 * SEGL, b + 5 * SEGL}, *brow = b + 6 * SEGL;
        double *f = b + 7 * seg_max(n);
        for (long j = 0; j < len; j++) brow[j] = bnd;
#define ROW(i) ((i) < 0 || (i) >= n ? brow : src + (base + (size_t)(i) * stride) * (size_t)n + j0)
        /* mu and flux of row i (-1 .. n) into slot s */
#define FILL(i, s)                                                                                     \
    do {                                                                                               \
        double x_[HJ_BAND_DMAX] = {0};                                                                 \
        row_coords(ws, base + (size_t)((i) < 0 ? 0 : (i) >= n ? n - 1 : (i)) * stride, k, (i), x_);   \
        row_dyn(ws, t, x_, ws->xlast + 1 + j0, len, a, f);                                            \
        row_flux(len, ROW((i) - 1), ROW(i), ROW((i) + 1), c, f + (long)k * len, mu[s], A[s]);          \
    } while (0)
        FILL(-1, 0);
        FILL(0, 1);
        for (int i = 0; i < n; i++) {
            const int sl = i % 3, s0 = (i + 1) % 3, sr = (i + 2) % 3; /* slots of rows i-1, i, i+1 */
            /* the row the next iteration brings in, one grid plane away
             * for k = 0: ask for it now (the hardware does not follow) */
            if (i + 3 < n) {
                const char *nx = (const char *)ROW(i + 3);
                for (long j = 0; j < len * (long)sizeof(double); j += 64) __builtin_prefetch(nx + j);
            }
            FILL(i + 1, sr);
            const double *wmm = ROW(i - 2), *wm = ROW(i - 1), *w0 = ROW(i), *wp = ROW(i + 1), *wpp = ROW(i + 2);
            const double *mL = mu[sl], *m0 = mu[s0], *mR = mu[sr], *aL = A[sl], *a0 = A[s0], *aR = A[sr];
            const size_t row = base + (size_t)i * stride;
            double *out = last ? last_row_in(ws, b) : dst + row * (size_t)n + j0;
            row_update(len, wmm, wm, w0, wp, wpp, mL, m0, mR, aL, a0, aR, out);
            if (last) last_row(ws, b, row, last->v, last->mode, last->first, last->snap, a, t, dt);
        }
#undef FILL
#undef ROW
    }
}

int hj_ub_dense_step(hj_ub_dense *ws, double *v, double t, double dt, hj_error *err)
{
    const hj_ub_problem *pb = ws->pb;
    if (!(dt > 0)) return hj_error_set(err, HJ_EINVAL, "UB step: dt must be > 0");
    const int d = pb->d;
    const double snap = pb->snap > 0 ? pb->snap : 1e-12;
    for (int a = 0; a < pb->ncontrols; a++) {
        const double *src = v;
        double *tmp[2] = {ws->w1, ws->w2};
        const int last = a == pb->ncontrols - 1;
        const fused fz = {.v = v, .mode = last ? 2 : a == 0 ? 0 : 1, .first = a == 0, .snap = snap};
        /* d >= 3: the last sweep inside the sweep in direction d - 2 (its
         * lines are many enough to share among threads); d = 2: apart */
        for (int k = 0; k < d - 1; k++) {
            const int fuse = d >= 3 && k == d - 2;
            sweep_rows(ws, k, src, tmp[k % 2], a, t, dt, fuse ? &fz : NULL);
            src = tmp[k % 2];
        }
        if (d == 2) sweep_last(ws, src, v, fz.mode, fz.first, snap, a, t, dt);
    }
    return HJ_OK;
}
