/* hj_ls_term.c -- the HJ PDE terms, evaluated row by row. */
#include "hj_ls_term.h"
#include "hj_sys.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif

/* AVX-512 and AVX2 clones of the row loops where the CPU has them
 * (-std=c11 contracts no multiply-add: the bits are the SSE2 code's). */
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__SANITIZE_ADDRESS__) && !defined(__clang__)
#define HJ_LS_TERM_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define HJ_LS_TERM_CLONES
#endif

/* ---- row driver ------------------------------------------------------ */

/* Context of one row: its first node k, node index and coordinates (x[0]
 * of node j is x0 + j dx[0]), a per-thread workspace. */
typedef struct {
    size_t k;
    long idx[HJ_LS_MAXDIM];
    double x[HJ_LS_MAXDIM];
    double *ws;
    double *tmax; /* per node of a row: running maximum of the inverse CFL
                   * bound over the rows of this thread (NaN sticks) */
    size_t r;       /* this row's number */
    size_t cache_r; /* row whose differences along dimension 1 the ring holds */
    int head;       /* ring slot of the difference k = -3 */
    double dmax[HJ_LS_MAXDIM]; /* per dimension: running maximum of the
                                * speed over dx_d (the toolbox's rule) */
    int filled; /* the evaluator's per-thread constants are in ws */
    double smax; /* a fused RK stage (hj_ls_stage): running max |dst| */
    int sbad;    /* and whether a value of dst was not finite */
    double imax; /* running maximum of the rows' exact *inv (Lax-Friedrichs) */
    long nrows; /* rows of this call: 1, or a block (for_rows_blocks) */
} row_ctx;

/* The offset of row r's first node and its index in idx: one odometer
 * step from row prev (offset kprev, index in idx) when r follows it, as
 * inside a chunk of rows, else hj_ls_row's divisions. */
static size_t row_next(const hj_ls_grid *g, size_t r, size_t prev, size_t kprev, long *idx)
{
    if (prev != (size_t)-1 && r == prev + 1) {
        size_t k = kprev;
        for (int d = 1; d < g->dim; d++) {
            if (idx[d] + 1 < g->N[d]) {
                idx[d]++;
                return k + (size_t)g->stride[d];
            }
            k -= (size_t)(g->N[d] - 1) * (size_t)g->stride[d];
            idx[d] = 0;
        }
    }
    return hj_ls_row(g, r, idx);
}

/* A row evaluator: writes ydot on the row, *inv = the row's largest inverse
 * CFL bound (NaN if one was NaN); returns 0 or an error code with the node
 * j of the row that failed. */
typedef int (*row_fn)(const void *term, double t, double *y, double *ydot, row_ctx *rc, double *inv, long *bad_j);

/* Run f on every row in parallel.  Returns the largest inverse CFL bound
 * in *maxinv and, when dmax is not NULL, the per-dimension maxima the rows
 * left in rc->dmax (maxima: the result does not depend on the order); on
 * failure the code of the first failing node in row order (deterministic
 * whatever the number of threads), with a message naming `what` and the
 * node. */
static int for_rows_blocks(const hj_ls_grid *g, size_t ws_doubles, row_fn f, long blk, int lines, const void *term,
                           double t, double *y, double *ydot, double *maxinv, double *dmax, hj_ls_stage *st,
                           int layers, const char *what, hj_error *err);
static int for_rows_layers(const hj_ls_grid *g, size_t ws_doubles, row_fn f, const void *term, double t, double *y,
                           double *ydot, double *maxinv, double *dmax, hj_ls_stage *st, int layers, const char *what,
                           hj_error *err)
{
    return for_rows_blocks(g, ws_doubles, f, 1, 0, term, t, y, ydot, maxinv, dmax, st, layers, what, err);
}
static int for_rows(const hj_ls_grid *g, size_t ws_doubles, row_fn f, const void *term, double t, double *y,
                    double *ydot, double *maxinv, double *dmax, const char *what, hj_error *err)
{
    return for_rows_layers(g, ws_doubles, f, term, t, y, ydot, maxinv, dmax, NULL, 0, what, err);
}

/* for_rows_layers with every ghost layer of the face ghosts (faces = 1)
 * or none. */
static int for_rows_run(const hj_ls_grid *g, size_t ws_doubles, row_fn f, const void *term, double t, double *y,
                        double *ydot, double *maxinv, double *dmax, hj_ls_stage *st, int faces, const char *what,
                        hj_error *err)
{
    return for_rows_layers(g, ws_doubles, f, term, t, y, ydot, maxinv, dmax, st, faces ? HJ_LS_GHOST : 0, what, err);
}

/* for_rows, and for a fused RK stage (st not NULL; the rows leave their
 * max |dst| and non-finite flag in rc->smax, rc->sbad) st->amax and
 * st->bad: a maximum and an or, the same for any order of the rows.
 * layers > 0 (a term whose stencils read along one axis at a time, at
 * most layers nodes beyond a face, on a grid that is not distributed):
 * those face ghosts of y are filled here, in the same parallel region
 * (hj_ls_fill_ghost_faces), and each row's dimension-0 ghosts just before
 * the row is evaluated, while the row is in cache, instead of a region and
 * a pass over the grid per dimension (the same bits: no stencil reads
 * another row's dimension-0 ghosts, nor an edge, a corner or a layer
 * beyond layers).
 *
 * blk > 1: f is called on blocks of up to blk consecutive rows of one
 * plane (rows that follow each other along dimension 1, row b at offset
 * rc->k + b stride[1]; rc->nrows of them), their dimension-0 ghosts
 * filled first; f's *bad_j is then b N[0] + j for node j of the block's
 * row b.  The rows' results are those of blk = 1 (each row computed
 * alone; maxima and the first failing row do not depend on the grouping).
 *
 * lines = 1: each thread's workspace starts on a cache line (the
 * Lax-Friedrichs rows; lf_row's buffers lie whole lines apart); 0: where
 * malloc puts it (the other terms, whose row buffers lie n apart). */
static int for_rows_blocks(const hj_ls_grid *g, size_t ws_doubles, row_fn f, long blk, int lines, const void *term,
                           double t, double *y, double *ydot, double *maxinv, double *dmax, hj_ls_stage *st,
                           int layers, const char *what, hj_error *err)
{
    double m = 0, smax = 0;
    int sbad = 0;
    double dm[HJ_LS_MAXDIM] = {0};
    int nan_seen = 0, nomem = 0, ws_fail = 0;
    size_t bad_row = (size_t)-1;
    long bad_j = -1;
    int bad_code = 0;
    /* Guided: a thread takes a share of the rows left, at least chunk of
     * them, so that it runs through long stretches of consecutive rows
     * (neighbours in dimension 1 share differences: a stretch starts by
     * computing all six) and a thread that starts late or is slowed down
     * is still balanced to within a chunk.  chunk: up to 32, at least 8
     * per thread so that a small grid keeps both threads busy to the end. */
    int nth = 1;
#ifdef _OPENMP
    nth = omp_get_max_threads();
#endif
    size_t chunk = g->rows / (8 * (size_t)nth);
    chunk = chunk < 4 ? 4 : chunk > 32 ? 32 : chunk;
#ifdef _OPENMP
#pragma omp parallel reduction(max : m, smax) reduction(| : nan_seen, nomem, sbad)
#endif
    {
        if (layers) hj_ls_fill_ghost_faces(g, y, layers); /* ends in a barrier: the faces are in before any row reads them */
        row_ctx rc;
        rc.smax = 0, rc.sbad = 0, rc.imax = 0;
        const long n = g->N[0];
        /* on a cache line: a row evaluator whose buffers start at multiples
         * of 8 doubles reads and writes them a whole line per vector */
        const size_t bytes = sizeof(double) * (ws_doubles + (size_t)n);
        void *wsp = NULL;
        rc.ws = !lines ? malloc(bytes) : posix_memalign(&wsp, 64, bytes) ? NULL : wsp;
        if (!hj_sys_team_all(rc.ws != NULL, &ws_fail)) nomem = 1;
        else {
            rc.tmax = rc.ws + ws_doubles;
            for (long j = 0; j < n; j++) rc.tmax[j] = 0;
            rc.cache_r = (size_t)-1;
            rc.head = 0;
            rc.filled = 0;
            for (int d = 0; d < HJ_LS_MAXDIM; d++) rc.dmax[d] = 0;
            size_t prev = (size_t)-1;
            rc.k = 0;
            rc.nrows = 1;
            if (blk > 1) {
                /* units of up to blk rows, none across a plane */
                const size_t n1 = g->dim > 1 ? (size_t)g->N[1] : 1, per = (n1 + (size_t)blk - 1) / (size_t)blk;
                const size_t units = g->rows / n1 * per, uchunk = (chunk + (size_t)blk - 1) / (size_t)blk;
                const ptrdiff_t s1 = g->dim > 1 ? g->stride[1] : 0;
#ifdef _OPENMP
#pragma omp for schedule(guided, uchunk)
#endif
                for (size_t u = 0; u < units; u++) {
                    const size_t sub = u % per, r0 = u / per * n1 + sub * (size_t)blk;
                    const size_t cnt = n1 - sub * (size_t)blk < (size_t)blk ? n1 - sub * (size_t)blk : (size_t)blk;
                    rc.k = row_next(g, r0, prev, rc.k, rc.idx);
                    rc.r = r0, rc.nrows = (long)cnt;
                    if (layers)
                        for (size_t b = 0; b < cnt; b++) hj_ls_fill_row_ghosts(g, y, rc.k + b * (size_t)s1, layers);
                    hj_ls_coord(g, rc.idx, rc.x);
                    double inv = 0;
                    long j = -1;
                    int code = f(term, t, y, ydot, &rc, &inv, &j);
                    /* the unit's last row, where row_next steps on from */
                    prev = r0 + cnt - 1;
                    if (cnt > 1) rc.k += (cnt - 1) * (size_t)s1, rc.idx[1] += (long)(cnt - 1);
                    if (code) {
                        const size_t rb = r0 + (size_t)(j / g->N[0]);
#ifdef _OPENMP
#pragma omp critical(hj_ls_term_fail)
#endif
                        if (rb < bad_row) bad_row = rb, bad_j = j % g->N[0], bad_code = code;
                    }
                    if (inv != inv) nan_seen = 1;
                    else m = inv > m ? inv : m;
                }
            } else {
#ifdef _OPENMP
#pragma omp for schedule(guided, chunk)
#endif
            for (size_t r = 0; r < g->rows; r++) {
                rc.k = row_next(g, r, prev, rc.k, rc.idx);
                rc.r = prev = r;
                if (layers) hj_ls_fill_row_ghosts(g, y, rc.k, layers);
                hj_ls_coord(g, rc.idx, rc.x);
                double inv = 0;
                long j = -1;
                int code = f(term, t, y, ydot, &rc, &inv, &j);
                if (code) {
#ifdef _OPENMP
#pragma omp critical(hj_ls_term_fail)
#endif
                    if (r < bad_row) bad_row = r, bad_j = j, bad_code = code;
                }
                if (inv != inv) nan_seen = 1;
                else m = inv > m ? inv : m;
            }
            }
            for (long j = 0; j < n; j++) {
                if (rc.tmax[j] != rc.tmax[j]) nan_seen = 1;
                else m = rc.tmax[j] > m ? rc.tmax[j] : m;
            }
            for (int d = 0; d < g->dim; d++)
                if (rc.dmax[d] != rc.dmax[d]) nan_seen = 1;
#ifdef _OPENMP
#pragma omp critical(hj_ls_term_dmax)
#endif
            for (int d = 0; d < g->dim; d++) dm[d] = rc.dmax[d] > dm[d] ? rc.dmax[d] : dm[d];
            smax = rc.smax > smax ? rc.smax : smax;
            sbad |= rc.sbad;
        }
        free(rc.ws);
    }
    if (st) st->amax = smax, st->bad = sbad;
    if (nomem) return hj_error_set(err, HJ_ENOMEM, "out of memory for the %s workspace", what);
    if (bad_code) {
        char pos[256];
        hj_ls_format_node(g, bad_row, bad_j, pos, sizeof pos);
        return hj_error_set(err, bad_code, "%s returned a non-finite value at x = (%s), t = %g", what, pos, t);
    }
    {
        /* A distributed grid: the largest over all blocks. */
        double v[HJ_LS_MAXDIM + 2] = {m, nan_seen};
        for (int d = 0; d < g->dim; d++) v[2 + d] = dm[d];
        hj_ls_grid_reduce(g, v, g->dim + 2, HJ_LS_REDUCE_MAX);
        m = v[0], nan_seen = v[1] != 0;
        for (int d = 0; d < g->dim; d++) dm[d] = v[2 + d];
    }
    if (nan_seen || m == INFINITY)
        return hj_error_set(err, HJ_ENONFINITE, "%s: non-finite CFL bound at t = %g", what, t);
    *maxinv = m;
    if (dmax) {
        for (int d = 0; d < g->dim; d++)
            if (dm[d] == INFINITY) return hj_error_set(err, HJ_ENONFINITE, "%s: non-finite CFL bound at t = %g", what, t);
        memcpy(dmax, dm, sizeof(double) * (size_t)g->dim);
    }
    return HJ_OK;
}

static inline double scalar_at(const hj_ls_scalar *s, double t, const double *x, double phi, size_t k)
{
    return s->fn ? s->fn(t, x, phi, s->ctx) : s->array ? s->array[k] : s->value;
}

/* The six rows of differences along dimension 1 (offsets -3 .. 2) of the
 * row of rc, kept in a ring of 6 n doubles: rows r - 1 and r are
 * neighbours in dimension 1 (rows are numbered with dimension 1
 * fastest), so five of row r's six rows are row r - 1's, shifted by one,
 * and only the sixth is computed (the same bits as computing all six).
 * D[k]: the row of offset k - 3. */
static void dim1_ring(const hj_ls_grid *g, const double *y, row_ctx *rc, double *ring, const double *D[6])
{
    const long n = g->N[0];
    const double *y0 = y + rc->k;
    if (rc->cache_r != (size_t)-1 && rc->r == rc->cache_r + 1 && rc->idx[1] != 0) {
        rc->head = (rc->head + 1) % 6;
        double *slot = ring + (size_t)((rc->head + 5) % 6) * (size_t)n;
        hj_ls_upwind_difference_row(y0, g->stride[1], n, g->dx[1], 2, slot);
    } else {
        rc->head = 0;
        for (int k = 0; k < 6; k++)
            hj_ls_upwind_difference_row(y0, g->stride[1], n, g->dx[1], k - 3, ring + (size_t)k * (size_t)n);
    }
    rc->cache_r = rc->r;
    for (int k = 0; k < 6; k++) D[k] = ring + (size_t)((rc->head + k) % 6) * (size_t)n;
}

/* The scalar over a row into a[0..n-1] when it has a batched callback;
 * returns 0 (and leaves a alone) otherwise, for scalar_at per node. */
static int scalar_row(const hj_ls_scalar *s, double t, const hj_ls_grid *g, const row_ctx *rc, const double *y,
                      double *a)
{
    if (!s || !s->row_fn) return 0;
    const hj_ls_row_info row = {g->N[0], g->dx[0], rc->x, rc->idx, rc->k};
    s->row_fn(t, &row, y + rc->k, a, s->ctx);
    return 1;
}

static double bound_of(double maxinv) { return maxinv > 0 ? 1 / maxinv : INFINITY; }

/* The CFL bound by the term's rule: 1 / max_x sum_d s_d(x) / dx_d
 * (HJ_LS_CFL_NODE, maxinv) or 1 / sum_d max_x s_d(x) / dx_d
 * (HJ_LS_CFL_TOOLBOX, from the per-dimension maxima; summed in dimension
 * order). */
static double bound_by_rule(int rule, const hj_ls_grid *g, double maxinv, const double *dmax)
{
    if (rule != HJ_LS_CFL_TOOLBOX) return bound_of(maxinv);
    double inv = 0;
    for (int d = 0; d < g->dim; d++) inv += dmax[d];
    return bound_of(inv);
}

/* The WENO5 epsilons of a term evaluation: the grid-wide ones of the
 * toolbox (HJ_LS_WENO_EPS_GRID, WENO5 schemes only) or -1 (local). */
static void weno_eps(const hj_ls_grid *g, int mode, int scheme, const double *y, double *eps)
{
    const int grid = mode == HJ_LS_WENO_EPS_GRID && (scheme == HJ_LS_WENO5A || scheme == HJ_LS_WENO5B);
    for (int d = 0; d < g->dim; d++) eps[d] = grid ? hj_ls_weno_eps_grid(g, y, d) : -1;
    if (grid) hj_ls_grid_reduce(g, eps, g->dim, HJ_LS_REDUCE_MAX);
}

/* ---- convection ------------------------------------------------------ */

/* Vector reductions: "omp simd" lets gcc vectorise them without
 * -ffast-math; the lane order is fixed at compile time, not by threads. */
#ifdef _OPENMP
#define SIMD_REDUCE(...) _Pragma(HJ_LS_STR(omp simd reduction(__VA_ARGS__)))
#define SIMD_CLAUSES(...) _Pragma(HJ_LS_STR(omp simd __VA_ARGS__))
#else
#define SIMD_REDUCE(...)
#define SIMD_CLAUSES(...)
#endif
#define HJ_LS_STR(x) #x

/* A convection evaluation: the term, its WENO5 epsilons (weno_eps) and a
 * fused RK stage (hj_ls_stage) or NULL (G into ydot). */
typedef struct {
    const hj_ls_convection *c;
    double eps[HJ_LS_MAXDIM];
    const hj_ls_stage *stage;
    const double *vcache; /* the steady velocity's rows, or NULL */
} conv_pass;

/* The fused stage on one row: dst = a y0 + b (u + dt G), hj_ls_ode's
 * combination (the same bits), its max |dst| into *smax and whether a
 * value was not finite into *sbad.  The stencils read u, never dst.  In
 * place (dst = y0, the last stage) y0 is read through dst, so that every
 * pointer stays restrict and the loop vectorises. */
static inline __attribute__((always_inline)) void conv_stage_row(long n, const hj_ls_stage *st, size_t k,
                                                                 const double *restrict u,
                                                                 const double *restrict G, double *smax, int *sbad)
{
    const double a = st->a, b = st->b, dt = st->dt;
    double *restrict dst = st->dst + k;
    double m = *smax, nf = 0;
#define CONV_STAGE(Y0)                                            \
    SIMD_CLAUSES(reduction(max : m) reduction(+ : nf))            \
    for (long j = 0; j < n; j++) {                                \
        const double v = a * Y0[j] + b * (u[j] + dt * G[j]);     \
        dst[j] = v;                                               \
        nf += v - v;                                              \
        const double av = v < 0 ? -v : v;                         \
        m = av > m ? av : m;                                      \
    }
    if (st->y0 == st->dst) CONV_STAGE(dst)
    else {
        const double *restrict y0 = st->y0 + k;
        CONV_STAGE(y0)
    }
#undef CONV_STAGE
    *smax = m;
    *sbad |= nf != 0;
}

HJ_LS_TERM_CLONES
static int convection_row(const void *term, double t, double *y, double *ydot, row_ctx *rc, double *inv, long *bad)
{
    const conv_pass *ps = term;
    const hj_ls_convection *c = ps->c;
    const hj_ls_grid *g = c->grid;
    const long n = g->N[0];
    /* acc is the row of ydot itself (no copy at the end), or for a fused
     * stage a row of the workspace (after the ring of dim1_ring) */
    double *cfl = rc->ws, *v = cfl + n, *dl = v + n, *dr = dl + n, *w = dr + n;
    double *acc = ps->stage ? w + (size_t)(HJ_LS_ROW_WORK + 6) * (size_t)n : ydot + rc->k;
    const int weno = c->scheme == HJ_LS_WENO5A || c->scheme == HJ_LS_WENO5B || c->scheme == HJ_LS_WENO3;
    int first = 1; /* no dimension has flow yet: acc and cfl not written */
    for (int d = 0; d < g->dim; d++) {
        const double *vel = v; /* the row of v_d: v, or read in place */
        if (c->velocity_fn || c->velocity_array[d]) {
            if (ps->vcache) vel = ps->vcache + ((size_t)rc->r * (size_t)g->dim + (size_t)d) * (size_t)n;
            else if (c->velocity_fn) c->velocity_fn(t, rc->x, g->dx[0], n, d, v, c->ctx);
            else vel = c->velocity_array[d] + rc->k;
            int flow = 0; /* NaN counts as flow: it reaches the CFL bound */
            SIMD_REDUCE(| : flow)
            for (long j = 0; j < n; j++) flow |= vel[j] != 0;
            if (!flow) continue; /* no flow along d on this row: no derivative */
        } else {
            if (c->velocity[d] == 0) continue;
            for (long j = 0; j < n; j++) v[j] = c->velocity[d];
        }
        if (d == 1 && weno) {
            /* Rows r - 1 and r are neighbours in dimension 1 (rows are
             * numbered with dimension 1 fastest): five of the six rows of
             * differences are the previous row's, shifted by one. */
            const double *D[6];
            dim1_ring(g, y, rc, w + (size_t)HJ_LS_ROW_WORK * (size_t)n, D);
            hj_ls_upwind_select_diffs_eps(c->scheme, D, n, ps->eps[d], vel, dl);
        } else if (weno) /* the upwind side only */
            hj_ls_upwind_row_select_eps(c->scheme, y + rc->k, g->stride[d], n, g->dx[d], ps->eps[d], vel, dl, w);
        else { /* cheap schemes: both sides, selected in the loop below */
            hj_ls_upwind_row_eps(c->scheme, y + rc->k, g->stride[d], n, g->dx[d], ps->eps[d], dl, dr, w);
        }
        const double idx = 1 / g->dx[d];
        /* the side of the upwind direction: WENO's dl holds it already,
         * the cheap schemes' is selected here (unconditional loads, so
         * that the loop vectorises) */
        const double *restrict vv = vel, *restrict L = dl, *restrict R = weno ? dl : dr;
        double *restrict ac = acc, *restrict cf = cfl;
#define CONV_ACC(OP0, OP1, SEL)                      \
    for (long j = 0; j < n; j++) {                   \
        const double l = L[j], r = R[j];             \
        const double D = SEL;                        \
        (void)r;                                     \
        ac[j] = OP0 vv[j] * D;                       \
        cf[j] = OP1 fabs(vv[j]) * idx;               \
    }
        /* first: 0 - x and 0 + x, the bits of accumulating from zero */
        if (weno && first) CONV_ACC(0.0 -, 0.0 +, l)
        else if (weno) CONV_ACC(ac[j] -, cf[j] +, l)
        else if (first) CONV_ACC(0.0 -, 0.0 +, vv[j] > 0 ? l : r)
        else CONV_ACC(ac[j] -, cf[j] +, vv[j] > 0 ? l : r)
#undef CONV_ACC
        first = 0;
    }
    if (first)
        for (long j = 0; j < n; j++) acc[j] = cfl[j] = 0;
    if (ps->stage) conv_stage_row(n, ps->stage, rc->k, y + rc->k, acc, &rc->smax, &rc->sbad);
    /* Elementwise running maximum (no reduction chain in the row loop); a
     * NaN or infinite velocity shows up there as a non-finite bound. */
    double *tm = rc->tmax;
    for (long j = 0; j < n; j++) tm[j] = (cfl[j] > tm[j] || cfl[j] != cfl[j]) ? cfl[j] : tm[j];
    (void)bad;
    *inv = 0;
    return HJ_OK;
}

/* ---- convection in 2-D with a cheap scheme: one loop per row ------- */

/* Row r's entry in the steady velocity's cache (convection_vcache), after
 * the velocity rows: per dimension 1 if v_d has flow on the row (a value
 * not 0, NaN included), then the row's largest inverse CFL bound (NaN if
 * one is NaN). */
static inline const double *convection_vcache_row(const hj_ls_grid *g, const double *cache, size_t r)
{
    const size_t dim = (size_t)g->dim;
    return cache + g->rows * dim * (size_t)g->N[0] + r * (dim + 1);
}

/* The upwind derivative of node j along stride s for velocity v: the left
 * or right one of hj_ls_upwind_row_eps (first order or ENO2, the same
 * expressions), chosen as convection_row chooses it (v > 0: left). */
static inline __attribute__((always_inline)) double conv2_side(int eno2, const double *restrict p, ptrdiff_t s,
                                                               long j, double inv, double v)
{
    double l, r;
    if (!eno2) {
        l = (p[j] - p[j - s]) * inv, r = (p[j + s] - p[j]) * inv;
    } else {
        const double m2 = (p[j - s] - p[j - 2 * s]) * inv, m1 = (p[j] - p[j - s]) * inv,
                     z0 = (p[j + s] - p[j]) * inv, p1 = (p[j + 2 * s] - p[j + s]) * inv;
        const double e2m1 = 0.5 * (m1 - m2), e20 = 0.5 * (z0 - m1), e2p1 = 0.5 * (p1 - z0);
        l = m1 + (fabs(e2m1) < fabs(e20) ? e2m1 : e20);
        r = z0 - (fabs(e20) < fabs(e2p1) ? e20 : e2p1);
    }
    return v > 0 ? l : r;
}

/* The outputs of a 2-D row: G into ydot (mode 0) or the fused stage into
 * dst apart from y0 (1) or in place (2, y0 read through dst). */
typedef struct {
    int mode;
    double *out;       /* ydot or dst, at the row's first node */
    const double *y0;  /* mode 1 */
    double a, b, dt;
} conv2_out;

/* One row: G = -(v_0 D_0 + v_1 D_1) over the dimensions with flow (f0, f1),
 * in the order and with the expressions of convection_row (the same bits:
 * 0 - x and 0 + x start the sums), then the stage's combination and max
 * |dst| as conv_stage_row, and (cfl = 1) the running maximum of the
 * inverse bound per node in tm.  Every value stays in registers: no row of derivatives,
 * velocity products or G goes through memory. */
static inline __attribute__((always_inline)) void conv2_row_k(int eno2, int f0, int f1, int mode, int cfl, long n,
                                                              const double *restrict p, ptrdiff_t s1,
                                                              const double *inv, const double *restrict v0,
                                                              const double *restrict v1, const conv2_out *o,
                                                              double *restrict tm, double *smax, int *sbad)
{
    const double inv0 = inv[0], inv1 = inv[1], idx0 = inv[2], idx1 = inv[3];
    const double a = o->a, b = o->b, dt = o->dt;
    double *restrict out = o->out;
    const double *restrict y0 = mode == 1 ? o->y0 : NULL;
    double m = *smax, nf = 0;
    SIMD_CLAUSES(reduction(max : m) reduction(+ : nf))
    for (long j = 0; j < n; j++) {
        double ac = 0, cf = 0;
        if (f0) {
            const double vj = v0[j], D = conv2_side(eno2, p, 1, j, inv0, vj);
            ac = 0.0 - vj * D, cf = 0.0 + fabs(vj) * idx0;
        }
        if (f1) {
            const double vj = v1[j], D = conv2_side(eno2, p, s1, j, inv1, vj);
            ac = (f0 ? ac : 0.0) - vj * D, cf = (f0 ? cf : 0.0) + fabs(vj) * idx1;
        }
        if (mode == 0)
            out[j] = ac;
        else {
            const double v = a * (mode == 1 ? y0[j] : out[j]) + b * (p[j] + dt * ac);
            out[j] = v;
            nf += v - v;
            const double av = v < 0 ? -v : v;
            m = av > m ? av : m;
        }
        if (cfl) tm[j] = (cf > tm[j] || cf != cf) ? cf : tm[j];
    }
    *smax = m;
    *sbad |= nf != 0;
}

#define CONV2_FLOWS(E, M, C)                                                                               \
    switch (f0 + 2 * f1) {                                                                                 \
    case 0: conv2_row_k(E, 0, 0, M, C, n, p, s1, inv, v0, v1, o, tm, smax, sbad); break;                   \
    case 1: conv2_row_k(E, 1, 0, M, C, n, p, s1, inv, v0, v1, o, tm, smax, sbad); break;                   \
    case 2: conv2_row_k(E, 0, 1, M, C, n, p, s1, inv, v0, v1, o, tm, smax, sbad); break;                   \
    default: conv2_row_k(E, 1, 1, M, C, n, p, s1, inv, v0, v1, o, tm, smax, sbad); break;                  \
    }
#define CONV2_MODES(E, C)                     \
    switch (o->mode) {                        \
    case 0: CONV2_FLOWS(E, 0, C) break;       \
    case 1: CONV2_FLOWS(E, 1, C) break;       \
    default: CONV2_FLOWS(E, 2, C) break;      \
    }

HJ_LS_TERM_CLONES
static void conv2_row(int eno2, int f0, int f1, int cfl, long n, const double *p, ptrdiff_t s1, const double *inv,
                      const double *v0, const double *v1, const conv2_out *o, double *tm, double *smax, int *sbad)
{
    /* cfl = 0: the bound is the cache's (the velocity does not change) */
    if (eno2 && cfl) CONV2_MODES(1, 1)
    else if (eno2) CONV2_MODES(1, 0)
    else if (cfl) CONV2_MODES(0, 1)
    else CONV2_MODES(0, 0)
}
#undef CONV2_MODES
#undef CONV2_FLOWS

/* The velocity rows of a 2-D row and whether each has flow (as
 * convection_row finds them): from the steady velocity's cache, whose
 * entry (convection_vcache_row) is returned, or evaluated into the first
 * two rows of the workspace (NULL returned). */
static const double *conv2_velocity(const conv_pass *ps, double t, const row_ctx *rc, const double **vel, int *flow)
{
    const hj_ls_convection *c = ps->c;
    const hj_ls_grid *g = c->grid;
    const long n = g->N[0];
    const double *row = ps->vcache ? convection_vcache_row(g, ps->vcache, rc->r) : NULL;
    for (int d = 0; d < 2 && row; d++)
        vel[d] = ps->vcache + ((size_t)rc->r * 2 + (size_t)d) * (size_t)n, flow[d] = row[d] != 0;
    for (int d = 0; d < 2 && !row; d++) {
        double *v = rc->ws + (size_t)d * (size_t)n;
        vel[d] = v;
        if (c->velocity_fn || c->velocity_array[d]) {
            if (c->velocity_fn) c->velocity_fn(t, rc->x, g->dx[0], n, d, v, c->ctx);
            else vel[d] = c->velocity_array[d] + rc->k;
            /* NaN counts as flow: it reaches the CFL bound; the first
             * nonzero decides (usually the row's first node) */
            const double *vd = vel[d];
            long j = 0;
            while (j < n && !(vd[j] != 0)) j++;
            flow[d] = j < n;
        } else {
            flow[d] = c->velocity[d] != 0;
            for (long j = 0; j < n; j++) v[j] = c->velocity[d];
        }
    }
    return row;
}

/* The row evaluator of a 2-D convection with a cheap scheme. */
static int convection_row2(const void *term, double t, double *y, double *ydot, row_ctx *rc, double *inv, long *bad)
{
    const conv_pass *ps = term;
    const hj_ls_convection *c = ps->c;
    const hj_ls_grid *g = c->grid;
    const long n = g->N[0];
    const double *vel[2];
    int flow[2];
    const double *row = conv2_velocity(ps, t, rc, vel, flow);
    const hj_ls_stage *st = ps->stage;
    conv2_out o = {0, ydot ? ydot + rc->k : NULL, NULL, 0, 0, 0};
    if (st) {
        o.mode = st->y0 == st->dst ? 2 : 1;
        o.out = st->dst + rc->k, o.y0 = st->y0 + rc->k, o.a = st->a, o.b = st->b, o.dt = st->dt;
    }
    const double invs[4] = {1.0 / g->dx[0], 1.0 / g->dx[1], 1 / g->dx[0], 1 / g->dx[1]};
    conv2_row(c->scheme == HJ_LS_ENO2, flow[0], flow[1], !row, n, y + rc->k, g->stride[1], invs, vel[0], vel[1], &o,
              rc->tmax, &rc->smax, &rc->sbad);
    (void)bad;
    *inv = row ? row[2] : 0; /* the row's maximum, as the cache was filled */
    return HJ_OK;
}

/* The row evaluator of a 2-D convection with WENO5A/B: G of both
 * dimensions in one loop (hj_ls_weno5_transport2_eps, the bits of
 * convection_row's selected derivatives summed in dimension order), from
 * the row's differences along dimension 0 and the ring of dimension 1
 * (dim1_ring); then the fused stage (conv_stage_row) and, unless the
 * cache holds it, the inverse bound per node as convection_row sums it. */
HJ_LS_TERM_CLONES
static int convection_row2w(const void *term, double t, double *y, double *ydot, row_ctx *rc, double *inv, long *bad)
{
    const conv_pass *ps = term;
    const hj_ls_convection *c = ps->c;
    const hj_ls_grid *g = c->grid;
    const long n = g->N[0];
    const double *vel[2];
    int flow[2];
    const double *row = conv2_velocity(ps, t, rc, vel, flow);
    /* workspace: the two velocity rows, the differences along the row
     * (n + 5), the ring (6 n), G of a fused stage */
    double *w = rc->ws + (size_t)2 * (size_t)n, *ring = w + n + 5, *acc = ring + (size_t)6 * (size_t)n;
    if (!ps->stage) acc = ydot + rc->k;
    const double *p = y + rc->k;
    const double *D0[6] = {NULL}, *D1[6] = {NULL};
    if (flow[0]) {
        /* D1_{i+k-3+1/2} along the row is w[i + k]: one row read at six
         * offsets (hj_ls_upwind_row_select_eps's expression) */
        const double inv0 = 1.0 / g->dx[0];
        for (long m = 0; m < n + 5; m++) w[m] = (p[m - 2] - p[m - 3]) * inv0;
        for (int k = 0; k < 6; k++) D0[k] = w + k;
    }
    if (flow[1]) dim1_ring(g, y, rc, ring, D1);
    if (!hj_ls_weno5_transport2_eps(c->scheme, D0, D1, n, ps->eps, flow[0] ? vel[0] : NULL, flow[1] ? vel[1] : NULL,
                                    acc))
        for (long j = 0; j < n; j++) acc[j] = 0; /* no flow on this row */
    if (ps->stage) conv_stage_row(n, ps->stage, rc->k, p, acc, &rc->smax, &rc->sbad);
    if (!row && (flow[0] || flow[1])) {
        const double idx0 = 1 / g->dx[0], idx1 = 1 / g->dx[1];
        const double *restrict v0 = vel[0], *restrict v1 = vel[1];
        double *restrict tm = rc->tmax;
        for (long j = 0; j < n; j++) {
            double cf = 0;
            if (flow[0]) cf = 0.0 + fabs(v0[j]) * idx0;
            if (flow[1]) cf = (flow[0] ? cf : 0.0) + fabs(v1[j]) * idx1;
            tm[j] = (cf > tm[j] || cf != cf) ? cf : tm[j];
        }
    }
    (void)bad;
    *inv = row ? row[2] : 0;
    return HJ_OK;
}

/* The steady velocity's rows, v_d of row r at (r dim + d) n, and per row
 * its flow flags and largest inverse bound (convection_vcache_row, the
 * bound as convection_row sums it: the same bits): evaluated into a new
 * cache on the first call (velocity_fn as convection_row calls it), NULL
 * where there is none (no flag, no callback, over the cap, no memory: the
 * callback per stage then). */
static const double *convection_vcache(hj_ls_convection *c, double t)
{
    const hj_ls_grid *g = c->grid;
    if (!c->velocity_steady || !c->velocity_fn) return NULL;
    if (c->velocity_cache) return c->velocity_cache;
    const size_t len = g->rows * (size_t)g->dim * ((size_t)g->N[0] + 1) + g->rows;
    if (g->rows == 0 || len > c->velocity_cache_max / sizeof(double)) return NULL;
    double *v = malloc(sizeof(double) * len);
    if (!v) return NULL;
    const long n = g->N[0];
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 32)
#endif
    for (size_t r = 0; r < g->rows; r++) {
        long idx[HJ_LS_MAXDIM];
        double x[HJ_LS_MAXDIM];
        hj_ls_row(g, r, idx);
        hj_ls_coord(g, idx, x);
        double *row = (double *)convection_vcache_row(g, v, r), m = 0;
        for (int d = 0; d < g->dim; d++) {
            double *vd = v + (r * (size_t)g->dim + (size_t)d) * (size_t)n;
            c->velocity_fn(t, x, g->dx[0], n, d, vd, c->ctx);
            long j = 0;
            while (j < n && !(vd[j] != 0)) j++;
            row[d] = j < n;
        }
        for (long j = 0; j < n; j++) {
            double cf = 0; /* convection_row's sum over the dimensions with flow */
            int first = 1;
            for (int d = 0; d < g->dim; d++)
                if (row[d] != 0) {
                    const double vj = v[(r * (size_t)g->dim + (size_t)d) * (size_t)n + (size_t)j];
                    cf = (first ? 0.0 : cf) + fabs(vj) * (1 / g->dx[d]);
                    first = 0;
                }
            if (m == m && (cf > m || cf != cf)) m = cf; /* a NaN sticks */
        }
        row[g->dim] = m;
    }
    return c->velocity_cache = v;
}

static void convection_name_bad_velocity(const hj_ls_convection *c, double t, hj_error *err);

/* G into ydot (stage NULL) or the fused stage (ydot NULL). */
static int convection_pass(const hj_ls_convection *c, double t, double *y, double *ydot, hj_ls_stage *stage,
                           double *bound, hj_error *err)
{
    const hj_ls_grid *g = c->grid;
    if (!hj_ls_scheme_name(c->scheme)) return hj_error_set(err, HJ_EINVAL, "convection: unknown scheme %d", c->scheme);
    /* Along one axis at a time: the face ghosts suffice, filled in the
     * row pass's region, unless a distributed grid exchanges halos or the
     * grid-wide WENO epsilons read the ghosts before the pass. */
    const int faces = !g->dist && c->weno_eps != HJ_LS_WENO_EPS_GRID;
    if (!faces) hj_ls_fill_ghosts_width(g, y, hj_ls_scheme_ghost(c->scheme));
    conv_pass ps;
    ps.c = c;
    ps.stage = stage;
    /* the cache is the term's own state, filled once (terms are not const
     * objects; an evaluation has the term to itself) */
    ps.vcache = convection_vcache((hj_ls_convection *)c, t);
    weno_eps(g, c->weno_eps, c->scheme, y, ps.eps);
    double m;
    /* 2-D with a cheap scheme: the one-loop rows of convection_row2;
     * with WENO5: convection_row2w */
    const int cheap = c->scheme == HJ_LS_ENO2 || c->scheme == HJ_LS_UPWIND_FIRST;
    const int weno5 = c->scheme == HJ_LS_WENO5A || c->scheme == HJ_LS_WENO5B;
    const row_fn f = g->dim != 2 ? convection_row : cheap ? convection_row2 : weno5 ? convection_row2w : convection_row;
    int rc = for_rows_run(g, (size_t)(4 + HJ_LS_ROW_WORK + 6 + 1) * (size_t)g->N[0], f, &ps, t, y, ydot, &m, NULL,
                          stage, faces, "convection velocity", err);
    if (rc == HJ_ENONFINITE && !g->dist) convection_name_bad_velocity(c, t, err);
    if (rc) return rc;
    *bound = bound_of(m);
    return HJ_OK;
}

/* After a non-finite CFL bound: the first node (rows in order, then
 * along the row) with a velocity component that is not finite, named in
 * err (the row pass reports only the bound); where every velocity is
 * finite, the first node whose inverse bound sum_d |v_d| / dx_d overflows
 * (a velocity near DBL_MAX), summed with the row pass's roundings (|v_d|
 * times 1 / dx_d), so that a sum just at the overflow threshold is found
 * as it was there.  Only on that error path, so the velocities are asked
 * again. */
static void convection_name_bad_velocity(const hj_ls_convection *c, double t, hj_error *err)
{
    const hj_ls_grid *g = c->grid;
    const long n = g->N[0];
    double *v = malloc((size_t)n * (size_t)g->dim * sizeof *v);
    if (!v) return;
    size_t over_r = 0; /* the first node whose sum overflows, if over_j >= 0 */
    long over_j = -1;
    for (size_t r = 0; r < g->rows; r++) {
        long idx[HJ_LS_MAXDIM];
        double x[HJ_LS_MAXDIM];
        const size_t k = hj_ls_row(g, r, idx);
        hj_ls_coord(g, idx, x);
        for (int d = 0; d < g->dim; d++) {
            double *vd = v + (size_t)d * (size_t)n;
            if (c->velocity_fn) c->velocity_fn(t, x, g->dx[0], n, d, vd, c->ctx);
            else
                for (long j = 0; j < n; j++)
                    vd[j] = c->velocity_array[d] ? c->velocity_array[d][k + (size_t)j] : c->velocity[d];
        }
        for (long j = 0; j < n; j++) {
            double sum = 0;
            for (int d = 0; d < g->dim; d++) {
                const double vd = v[(size_t)d * (size_t)n + (size_t)j];
                sum += fabs(vd) * (1 / g->dx[d]); /* rounded as the row pass rounds it */
                if (!isfinite(vd)) {
                    char pos[256];
                    hj_ls_format_node(g, r, j, pos, sizeof pos);
                    hj_error_set(err, HJ_ENONFINITE, "convection velocity: v_%d = %g at x = (%s), t = %g", d, vd, pos,
                                 t);
                    free(v);
                    return;
                }
            }
            if (over_j < 0 && sum == INFINITY) over_r = r, over_j = j;
        }
    }
    free(v);
    if (over_j >= 0) {
        char pos[256];
        hj_ls_format_node(g, over_r, over_j, pos, sizeof pos);
        hj_error_set(err, HJ_ENONFINITE,
                     "convection velocity: sum_d |v_d| / dx_d overflows at x = (%s), t = %g "
                     "(velocities near the largest double; rescale time or space)",
                     pos, t);
    }
}

static int convection_eval(const hj_ls_term *term, double t, double *y, double *ydot, double *bound, hj_error *err)
{
    return convection_pass((const hj_ls_convection *)term, t, y, ydot, NULL, bound, err);
}

void hj_ls_convection_init(hj_ls_convection *c, const hj_ls_grid *g, int scheme)
{
    memset(c, 0, sizeof *c);
    c->base.eval = convection_eval;
    c->grid = g;
    c->scheme = scheme;
    c->velocity_cache_max = (size_t)1 << 30;
}

void hj_ls_convection_free(hj_ls_convection *c)
{
    free(c->velocity_cache);
    c->velocity_cache = NULL;
}

/* The first j < bad with a non-finite v[j] (v - v is NaN exactly then), or
 * bad.  The common case, all finite, is one vector pass. */
static long first_nonfinite(const double *v, long bad)
{
    int any = 0;
    for (long j = 0; j < bad; j++) any |= !(v[j] - v[j] == 0);
    if (any)
        for (long j = 0; j < bad; j++)
            if (!(v[j] - v[j] == 0)) return j;
    return bad;
}

/* ---- normal motion and reinitialization ------------------------------ */

/* Speed a (normal) or S(phi_0) (reinit) times Godunov |grad phi|. */
typedef struct {
    const hj_ls_grid *grid;
    int scheme;
    const hj_ls_scalar *speed; /* normal motion */
    const double *initial;     /* reinitialization */
    double smear2;             /* max dx^2 */
    int cfl_rule;              /* HJ_LS_CFL_* */
    int subcell_fix;           /* reinitialization: Russo & Smereka near the interface */
    double eps[HJ_LS_MAXDIM];  /* WENO5 epsilon per dimension, < 0: O&F (3.38) */
} godunov_term;


/* sign(v) as MATLAB's sign: -1, 0 or 1. */
static inline double sign0(double v) { return v > 0 ? 1.0 : v < 0 ? -1.0 : 0.0; }

/* The subcell fix of Russo & Smereka (J. Comput. Phys. 163, 2000) as
 * ToolboxLS 1.1's termReinit applies it (subcell_fix_order 1, its robust
 * form (17)): at a node near the interface of phi_0 (on it, or with a
 * neighbour along some dimension on the other side or on it, as
 * isNearInterface), the update is
 *     G = -(sign(phi_0) |phi| - D) / max_d dx_d,
 *     D = phi_0 / sqrt(sum_d max(q_d^2, (1e6 eps)^2)),
 * with q_d the largest in magnitude of the one-sided differences of phi_0
 * along d that stay on the grid (the centred difference is their mean,
 * never larger, so the toolbox's max over all three is this).  Neighbours
 * are taken by index, never across a periodic seam, as the toolbox does.
 * Returns 1 and *G for a node near the interface, 0 elsewhere. */
static int subcell_update(const hj_ls_grid *g, const double *phi0, size_t k, const long *idx, double phi, double h,
                          double *G)
{
    const double s0 = sign0(phi0[k]);
    int near = s0 == 0;
    double den = 0;
    for (int d = 0; d < g->dim; d++) {
        const ptrdiff_t st = g->stride[d];
        double q2 = 0;
        if (idx[d] > 0) {
            const double q = (phi0[k] - phi0[k - (size_t)st]) / g->dx[d];
            q2 = q * q > q2 ? q * q : q2;
            near |= sign0(phi0[k - (size_t)st]) != s0;
        }
        if (idx[d] < g->N[d] - 1) {
            const double q = (phi0[k + (size_t)st] - phi0[k]) / g->dx[d];
            q2 = q * q > q2 ? q * q : q2;
            near |= sign0(phi0[k + (size_t)st]) != s0;
        }
        const double tiny = 1e6 * DBL_EPSILON;
        den += q2 > tiny * tiny ? q2 : tiny * tiny;
    }
    if (!near) return 0;
    *G = -(s0 * fabs(phi) - phi0[k] / sqrt(den)) / h;
    return 1;
}

/* The speed row of a Godunov row: a[j] = the normal speed (normal motion)
 * or S(phi_0) (reinitialization) at node j for j < nb; returns nb, n or
 * the first node whose speed or phi_0 is not finite (the callback is
 * called node by node up to that one, as before). */
static long godunov_speed(const godunov_term *c, double t, const double *y, const row_ctx *rc, double *restrict a)
{
    const hj_ls_grid *g = c->grid;
    const long n = g->N[0];
    if (c->initial) {
        const double *restrict i0 = c->initial + rc->k;
        const long nb = first_nonfinite(i0, n);
        if (c->subcell_fix)
            for (long j = 0; j < nb; j++) a[j] = sign0(i0[j]);
        else {
            const double s2 = c->smear2;
            for (long j = 0; j < nb; j++) a[j] = i0[j] / sqrt(i0[j] * i0[j] + s2);
        }
        return nb;
    }
    if (scalar_row(c->speed, t, g, rc, y, a)) return first_nonfinite(a, n);
    const hj_ls_scalar *s = c->speed;
    if (s->fn) {
        double x[HJ_LS_MAXDIM];
        memcpy(x, rc->x, sizeof(double) * (size_t)g->dim);
        for (long j = 0; j < n; j++) {
            x[0] = g->min[0] + (double)j * g->dx[0];
            a[j] = s->fn(t, x, y[rc->k + (size_t)j], s->ctx);
            if (!isfinite(a[j])) return j;
        }
        return n;
    }
    if (s->array) memcpy(a, s->array + rc->k, sizeof(double) * (size_t)n);
    else
        for (long j = 0; j < n; j++) a[j] = s->value;
    return first_nonfinite(a, n);
}

/* The subcell fix on nodes j < nb of a row: a vector pass marks the nodes
 * near the interface of phi_0 (sign0 of phi_0 zero, or different at a
 * neighbour along some dimension: subcell_update's test), and only those
 * take subcell_update's G (a few nodes near the front). */
static void godunov_subcell(const godunov_term *c, const double *y, double *ydot, const row_ctx *rc, long nb,
                            double *restrict sg, double *restrict near)
{
    const hj_ls_grid *g = c->grid;
    const long n = g->N[0];
    const double *restrict p0 = c->initial + rc->k;
    for (long j = 0; j < n; j++) sg[j] = sign0(p0[j]);
    for (long j = 0; j < nb; j++) near[j] = sg[j] == 0;
    for (long j = 1; j < nb; j++) near[j] = sg[j - 1] != sg[j] ? 1 : near[j];
    for (long j = 0; j < nb && j < n - 1; j++) near[j] = sg[j + 1] != sg[j] ? 1 : near[j];
    for (int d = 1; d < g->dim; d++) {
        const ptrdiff_t st = g->stride[d];
        if (rc->idx[d] > 0) {
            const double *restrict q = p0 - st;
            for (long j = 0; j < nb; j++) near[j] = sign0(q[j]) != sg[j] ? 1 : near[j];
        }
        if (rc->idx[d] < g->N[d] - 1) {
            const double *restrict q = p0 + st;
            for (long j = 0; j < nb; j++) near[j] = sign0(q[j]) != sg[j] ? 1 : near[j];
        }
    }
    long idx[HJ_LS_MAXDIM];
    memcpy(idx, rc->idx, sizeof(long) * (size_t)g->dim);
    const double h = sqrt(c->smear2);
    for (long j = 0; j < nb; j++) {
        if (near[j] == 0) continue;
        const size_t k = rc->k + (size_t)j;
        idx[0] = j;
        double G;
        if (subcell_update(g, c->initial, k, idx, y[k], h, &G)) ydot[k] = G;
    }
}

/* v > m, or v NaN (which then sticks): the toolbox rule's running maximum */
static inline double max_nan(double v, double m) { return v > m || v != v ? v : m; }

/* max_nan over v[0..len-1] (len > 0), folding the upper half onto the
 * lower (overwrites v): vector passes, and the result of the node loop
 * (the largest value, or NaN if one is NaN: the order does not matter). */
static inline double fold_max_nan(double *restrict v, long len)
{
    while (len > 1) {
        const long half = len / 2;
        for (long j = 0; j < half; j++) v[j] = max_nan(v[j + half], v[j]);
        if (len & 1) v[0] = max_nan(v[len - 1], v[0]);
        len = half;
    }
    return v[0];
}

/* One row of normal motion or reinitialization, in passes over the row:
 * the speed a, the Godunov upwind component p_d per dimension (for a >= 0
 * the larger in magnitude of max(D-, 0) and min(D+, 0), the roles swapped
 * for a < 0, by selects) and |p| (the squares summed in dimension order),
 * ydot, the subcell fix, the CFL accumulation.  Per node the same
 * operations in the same order as node by node, so the same bits.
 * The CFL maxima: per node of the row in rc->tmax (HJ_LS_CFL_NODE; a NaN
 * sum is skipped, as by the node loop's s > m) or the row's by halves
 * (HJ_LS_CFL_TOOLBOX; NaN sticks), merged at the end: a maximum does not
 * depend on the order.  A row with a non-finite speed or phi_0 at node
 * nb is computed up to nb (ydot and the toolbox maxima of the nodes
 * before it, as node by node) and reports nb. */
HJ_LS_TERM_CLONES
static int godunov_row(const void *term, double t, double *y, double *ydot, row_ctx *rc, double *inv, long *bad)
{
    const godunov_term *c = term;
    const hj_ls_grid *g = c->grid;
    const long n = g->N[0];
    const int dim = g->dim;
    double *dl = rc->ws, *dr = dl + (size_t)dim * (size_t)n, *w = dr + (size_t)dim * (size_t)n;
    double *restrict a = w + (size_t)HJ_LS_ROW_WORK * (size_t)n;
    for (int d = 0; d < dim; d++)
        hj_ls_upwind_row_eps(c->scheme, y + rc->k, g->stride[d], n, g->dx[d], c->eps[d], dl + d * n, dr + d * n, w);
    const long nb = godunov_speed(c, t, y, rc, a);
    /* w is free again: |p| and the CFL rows */
    double *restrict mag = w, *restrict tmp = w + n, *restrict tmp2 = w + 2 * n;
    for (long j = 0; j < nb; j++) mag[j] = 0;
    for (int d = 0; d < dim; d++) {
        double *restrict pd = dl + d * n; /* the left derivative, then p_d */
        const double *restrict rd = dr + d * n;
        for (long j = 0; j < nb; j++) {
            const double l = pd[j], r = rd[j];
            const int up = a[j] >= 0;
            const double pl = up ? (l > 0 ? l : 0) : (l < 0 ? l : 0);
            const double pr = up ? (r < 0 ? r : 0) : (r > 0 ? r : 0);
            const double p = pl * pl >= pr * pr ? pl : pr;
            pd[j] = p;
            mag[j] += p * p;
        }
    }
    for (long j = 0; j < nb; j++) mag[j] = sqrt(mag[j]);
    double *restrict yd = ydot + rc->k;
    if (c->initial)
        for (long j = 0; j < nb; j++) yd[j] = -a[j] * (mag[j] - 1);
    else
        for (long j = 0; j < nb; j++) yd[j] = -a[j] * mag[j];
    if (c->subcell_fix) godunov_subcell(c, y, ydot, rc, nb, tmp, tmp2);
    if (c->cfl_rule == HJ_LS_CFL_TOOLBOX) {
        /* the toolbox's effective velocity v_d = a p_d / max(|p|, eps) */
        double *restrict mg = tmp;
        for (long j = 0; j < nb; j++) mg[j] = mag[j] > DBL_EPSILON ? mag[j] : DBL_EPSILON;
        for (int d = 0; d < dim; d++) {
            const double *restrict pd = dl + d * n;
            const double dx = g->dx[d];
            for (long j = 0; j < nb; j++) tmp2[j] = fabs(a[j] * pd[j] / mg[j]) / dx;
            if (nb > 0) rc->dmax[d] = max_nan(fold_max_nan(tmp2, nb), rc->dmax[d]);
        }
    } else if (nb == n) {
        double *restrict s = tmp, *restrict tm = rc->tmax;
        for (long j = 0; j < n; j++) s[j] = 0;
        for (int d = 0; d < dim; d++) {
            const double *restrict pd = dl + d * n;
            const double dx = g->dx[d];
            for (long j = 0; j < n; j++) s[j] += (mag[j] > 0 ? fabs(pd[j]) / mag[j] : 1.0) / dx;
        }
        for (long j = 0; j < n; j++) {
            const double v = s[j] * fabs(a[j]);
            tm[j] = v > tm[j] ? v : tm[j];
        }
    }
    *inv = 0;
    if (nb < n) {
        *bad = nb;
        return HJ_ENONFINITE;
    }
    return HJ_OK;
}

static int godunov_eval(const hj_ls_grid *g, godunov_term *gt, int eps_mode, double t, double *y, double *ydot,
                        double *bound, const char *what, hj_error *err)
{
    if (!hj_ls_scheme_name(gt->scheme)) return hj_error_set(err, HJ_EINVAL, "%s: unknown scheme %d", what, gt->scheme);
    hj_ls_fill_ghosts_width(g, y, hj_ls_scheme_ghost(gt->scheme));
    weno_eps(g, eps_mode, gt->scheme, y, gt->eps);
    double m, dm[HJ_LS_MAXDIM];
    int rc = for_rows(g, (size_t)(2 * g->dim + HJ_LS_ROW_WORK + 1) * (size_t)g->N[0], godunov_row, gt, t, y, ydot, &m,
                      dm, what, err);
    if (rc) return rc;
    *bound = bound_by_rule(gt->cfl_rule, g, m, dm);
    return HJ_OK;
}

static int normal_eval(const hj_ls_term *term, double t, double *y, double *ydot, double *bound, hj_error *err)
{
    const hj_ls_normal *c = (const hj_ls_normal *)term;
    godunov_term gt = {c->grid, c->scheme, &c->speed, NULL, 0, c->cfl_rule, 0, {0}};
    return godunov_eval(c->grid, &gt, c->weno_eps, t, y, ydot, bound, "normal speed", err);
}

void hj_ls_normal_init(hj_ls_normal *c, const hj_ls_grid *g, int scheme)
{
    memset(c, 0, sizeof *c);
    c->base.eval = normal_eval;
    c->grid = g;
    c->scheme = scheme;
}

static int reinit_eval(const hj_ls_term *term, double t, double *y, double *ydot, double *bound, hj_error *err)
{
    const hj_ls_reinit *c = (const hj_ls_reinit *)term;
    if (!c->initial) return hj_error_set(err, HJ_EINVAL, "reinitialization needs the initial data");
    /* S(phi_0) must stay that of the data the run started from */
    if (c->initial == y)
        return hj_error_set(err, HJ_EINVAL,
                            "reinitialization: the initial data is the array being integrated; give a copy of phi_0 "
                            "(hj_ls_copy into an array of its own)");
    double h = 0;
    for (int d = 0; d < c->grid->dim; d++) h = c->grid->dx[d] > h ? c->grid->dx[d] : h;
    godunov_term gt = {c->grid, c->scheme, NULL, c->initial, h * h, c->cfl_rule, c->subcell_fix, {0}};
    const int rc = godunov_eval(c->grid, &gt, c->weno_eps, t, y, ydot, bound, "reinitialization", err);
    /* the rows report a NaN or infinite phi_0 (the only value they check
     * here) as a callback's; say what it is */
    const char *at = rc == HJ_ENONFINITE && err ? strstr(err->msg, " returned a non-finite value at x = (") : NULL;
    if (at) {
        char pos[256];
        const char *p0 = strchr(at, '('), *p1 = strchr(p0, ')');
        snprintf(pos, sizeof pos, "%.*s", p1 ? (int)(p1 - p0 - 1) : 0, p0 + 1);
        return hj_error_set(err, HJ_ENONFINITE, "reinitialization: the initial data phi_0 is not finite at x = (%s)",
                            pos);
    }
    return rc;
}

void hj_ls_reinit_init(hj_ls_reinit *c, const hj_ls_grid *g, int scheme, const double *initial)
{
    memset(c, 0, sizeof *c);
    c->base.eval = reinit_eval;
    c->grid = g;
    c->scheme = scheme;
    c->initial = initial;
}

/* ---- Lax-Friedrichs ---------------------------------------------------- */

typedef struct {
    const hj_ls_lax_friedrichs *lf;
    double gmin[HJ_LS_MAXDIM], gmax[HJ_LS_MAXDIM]; /* global gradient range */
    double eps[HJ_LS_MAXDIM];                      /* WENO5 epsilons (weno_eps) */
    double *cache; /* one-sided derivatives of the range pass (lf->work), or NULL */
    int clip;      /* a restriction of this term (hj_ls_restrict): 1 G >= 0, -1 G <= 0, 0 none */
    const hj_ls_stage *stage; /* a fused RK stage, or NULL: G into ydot */
    double hinv[HJ_LS_MAXDIM]; /* 1 / dx_d: divided once per evaluation, not per row */
} lf_pass;

/* Pass 1 (GLF, LLF): the global range of p-, p+ per dimension; *inv
 * carries nothing.  The range is kept in the workspace tail and merged by
 * the caller; here rows only update thread-local ranges. */
HJ_LS_TERM_CLONES
static int lf_range_row(const void *term, double t, double *y, double *ydot, row_ctx *rc, double *inv, long *bad)
{
    (void)t, (void)ydot, (void)bad;
    const lf_pass *ps = term;
    const hj_ls_grid *g = ps->lf->grid;
    const long n = g->N[0];
    double *w = rc->ws + 2 * n, *range = w + (size_t)HJ_LS_ROW_WORK * (size_t)n;
    for (int d = 0; d < g->dim; d++) {
        /* into the cache when there is one (row r, dimension d: dl then dr) */
        double *dl = ps->cache ? ps->cache + (rc->r * (size_t)g->dim + (size_t)d) * 2 * (size_t)n : rc->ws, *dr = dl + n;
        hj_ls_upwind_row_eps(ps->lf->scheme, y + rc->k, g->stride[d], n, g->dx[d], ps->eps[d], dl, dr, w);
        double lo = range[2 * d], hi = range[2 * d + 1];
#ifdef _OPENMP
#pragma omp simd reduction(min : lo) reduction(max : hi)
#endif
        for (long j = 0; j < n; j++) {
            const double a = dl[j] < dr[j] ? dl[j] : dr[j], b = dl[j] < dr[j] ? dr[j] : dl[j];
            lo = a < lo ? a : lo;
            hi = b > hi ? b : hi;
        }
        range[2 * d] = lo, range[2 * d + 1] = hi;
    }
    *inv = 0;
    return HJ_OK;
}

/* Per-node adapters: the batched calls made of per-node callbacks (what
 * the row pipeline runs when the user gave ham or partial only). */
static void lf_ham_nodes(const hj_ls_lax_friedrichs *c, double t, const hj_ls_row_info *row, const double *phi,
                         const double *const *P, double *H)
{
    const int dim = c->grid->dim;
    double x[HJ_LS_MAXDIM], p[HJ_LS_MAXDIM];
    memcpy(x, row->x, sizeof(double) * (size_t)dim);
    for (long j = 0; j < row->n; j++) {
        x[0] = row->x[0] + (double)j * row->dx0;
        for (int d = 0; d < dim; d++) p[d] = P[d][j];
        H[j] = c->ham(t, x, phi[j], p, c->ctx);
    }
}

static void lf_partial_nodes(const hj_ls_lax_friedrichs *c, double t, const hj_ls_row_info *row,
                             const double *const *lo, const double *const *hi, int d, double *alpha)
{
    const int dim = c->grid->dim;
    double x[HJ_LS_MAXDIM], pl[HJ_LS_MAXDIM], ph[HJ_LS_MAXDIM];
    memcpy(x, row->x, sizeof(double) * (size_t)dim);
    for (long j = 0; j < row->n; j++) {
        x[0] = row->x[0] + (double)j * row->dx0;
        for (int e = 0; e < dim; e++) pl[e] = lo[e][j], ph[e] = hi[e][j];
        alpha[j] = c->partial(t, x, pl, ph, d, c->ctx);
    }
}




/* LF_MONO: every alpha but one (dimension LF_MONO_DIM) constant along the
 * row (row_const), as in LF_ROW_CONST's loop: the row's largest CFL sum
 * is that of the largest |alpha| of that dimension, found per node
 * instead of the sum (lf_finish). */
#define LF_MONO(dim, cm) ((dim) == 3 && (cm) == 5)
#define LF_MONO_DIM(cm) 1

/* A fused RK stage on one row (hj_ls_stage): dst = a y0 + b (u + dt G),
 * u the row of the term's input; max |dst| accumulates in smax, and sbad
 * is non-zero once a value of dst is not finite.  In place (dst
 * = y0, the last stage) y0 is read through dst, so that dst stays a
 * restrict pointer, which the row's vector loop needs to be fast.
 *
 * Euler's step (a = 0, b = 1, y0 = u: hj_ls_ode's fused first stage)
 * runs as dst = u + dt G (stage 3 of lf_finish): the same bits where u is
 * finite (0 u + w is w then, -0 included: w = -0 needs u = -0), and a
 * non-finite u makes a non-finite dst either way, which sbad reports. */
typedef struct {
    double a, b, dt;
    const double *y0, *u;
    double smax, sbad;
    int inplace;
    int euler; /* a = 0, b = 1, y0 = u */
} lf_stage_row;

/* The end of a row of G (every partial known): per node, the dissipation
 * sum_d alpha_d (p+_d - p-_d) / 2 and the CFL sum sum_d alpha_d / dx_d
 * accumulated in dimension order from 0.0 (the bits of one loop per
 * dimension), G = -(H - dissipation), clipped as the restriction asks
 * (clip 1: G >= 0, -1: G <= 0), the largest CFL sum in *inv; returns 0,
 * or non-zero when an alpha or H may not be finite: some q = SP + H with
 * q - q not 0, that is NaN where an alpha or H is not finite (SP, a sum
 * of |alpha_d| / dx_d, is then NaN or Inf), and may also be where the sum
 * overflows with every value finite (the caller looks for the node).
 * Both finiteness tests are an or of flags, not a sum of q - q: gcc adds
 * a double sum's vector lanes one after the other at the end of each
 * range, an or's in a tree (air3D low: 10 % of the run's CPU time, the
 * same bits).  With stage set, out receives the stage's combination instead of
 * G (the expression of hj_ls_ode's combine; stage 2: in place, y0 read
 * from out).  One vector loop over the row; dim and stage are constants
 * where inlined (lf_finish_dim), so the loop over dimensions unrolls and
 * the plain G path carries no stage.  Bit d of the constant cm: alpha_d
 * is the same along the row (row_const), its |alpha| the scalar ac[d]
 * (no load per node; the same bits). */
static inline __attribute__((always_inline)) void lf_finish_range(int diffs, int dim, int cm, int stage,
                                                                  size_t astride, long j0, long j1,
                                                                  const double *ac,
                                                                  const double *restrict A,
                                                                  const double *restrict DL,
                                                                  const double *restrict DR, size_t ds_stride,
                                                                  const double *restrict H, const double *hinv,
                                                                  int clip, double *restrict out, double *restrict SP,
                                                                  lf_stage_row *sr, double *mp, double *nfp)
{
    double m = *mp, nf = *nfp;
    double smax = 0, sbad = 0, sa = 0, sb = 0, sdt = 0;
    const double *restrict y0 = NULL, *restrict u = NULL;
    if (stage) smax = sr->smax, sbad = sr->sbad, sa = sr->a, sb = sr->b, sdt = sr->dt, y0 = sr->y0, u = sr->u;
    /* one dimension vd varies along the row (LF_MONO): no CFL sum per node */
    const int mono = LF_MONO(dim, cm), vd = mono ? LF_MONO_DIM(cm) : 0;
    long nfb = 0, sbb = 0;
    SIMD_CLAUSES(reduction(max : m, smax) reduction(| : nfb, sbb))
    for (long j = j0; j < j1; j++) {
        double ds = 0.0, s = 0.0;
        for (int d = 0; d < dim; d++) {
            const double a = cm >> d & 1 ? ac[d] : fabs(A[(size_t)d * astride + (size_t)j]);
            const size_t q = (size_t)d * ds_stride + (size_t)j;
            ds += a * 0.5 * (diffs ? DR[q] : DR[q] - DL[q]);
            if (!mono) s += a * hinv[d];
        }
        const double am = mono ? fabs(A[(size_t)vd * astride + (size_t)j]) : 0;
        const double sh = (mono ? am : s) + H[j];
        nfb |= !(sh - sh == 0);
        double v = -(H[j] - ds);
        v = clip > 0 ? (v > 0 ? v : 0) : clip < 0 ? (v < 0 ? v : 0) : v;
        if (stage) {
            v = stage == 3 ? u[j] + sdt * v : sa * (stage == 2 ? out[j] : y0[j]) + sb * (u[j] + sdt * v);
            sbb |= !(v - v == 0);
            /* fabs: one and; -0 and NaN leave smax >= 0 alone either way */
            const double av = fabs(v);
            smax = av > smax ? av : smax;
        }
        out[j] = v;
        if (mono) m = am > m ? am : m;
        else {
            SP[j] = s;
            m = s > m ? s : m;
        }
    }
    *mp = m, *nfp = nfb ? 1 : nf;
    if (stage) sr->smax = smax, sr->sbad = sbb ? 1 : sbad;
}

/* Whole blocks of 8 nodes, then the last 8 nodes again rather than a
 * scalar remainder (HJ_LS_ROW_BLOCKS8: recomputing a node gives the same
 * bits; max and the finiteness sum do not change).  A fused stage in
 * place must not recompute a node (its y0 is overwritten): there the
 * remainder runs once.
 *
 * The CFL sum s = sum_d |alpha_d| / dx_d is wanted only at the row's
 * largest: the vector loop forms it with multiplications by 1 / dx_d (SP,
 * within (dim + 2) 2^-53 relative of s, all terms being >= 0), and s
 * itself, with its divisions and bits, is computed at the nodes whose SP
 * lies within 1e-12 relative of the row's largest SP, which hold the
 * largest s: three vector divisions per node were a third of the row's
 * end.  Nor is s wanted in a row whose largest SP lies below 1 - 1e-12
 * times floor, an exact s of a row before it (the thread's running
 * maximum): no node of the row can exceed floor, and *inv = 0 leaves
 * the maximum as it is (most rows, once the largest is met). */
static inline __attribute__((always_inline)) int lf_finish(int diffs, int dim, int cm, int stage, long n,
                                                           size_t astride, const double *restrict A, const double *restrict DL,
                                                           const double *restrict DR, size_t ds_stride,
                                                           const double *restrict H, const double *dx,
                                                           const double *inv_dx, int clip, double *restrict out,
                                                           double *restrict SP, lf_stage_row *sr, double floor,
                                                           double *inv)
{
    /* local copies: no store of the row may change them */
    double hinv[HJ_LS_MAXDIM], ac[HJ_LS_MAXDIM];
    for (int d = 0; d < dim; d++) hinv[d] = inv_dx[d], ac[d] = fabs(A[(size_t)d * astride]);
    double mp = 0, nf = 0;
    if (LF_MONO(dim, cm)) /* the constant alphas' finiteness, once */
        for (int d = 0; d < dim; d++)
            if (cm >> d & 1) nf += ac[d] - ac[d];
#define LF_RANGE(j0, j1) \
    lf_finish_range(diffs, dim, cm, stage, astride, (j0), (j1), ac, A, DL, DR, ds_stride, H, hinv, clip, out, SP, sr, &mp, \
                    &nf);
    if (stage == 2) {
        const long n8 = n & ~7L;
        LF_RANGE(0, n8)
        if (n8 < n) LF_RANGE(n8, n)
    } else
        HJ_LS_ROW_BLOCKS8(n, LF_RANGE);
#undef LF_RANGE
    if (LF_MONO(dim, cm)) {
        /* mp: the row's largest |alpha_vd|; s, made of additions and
         * divisions by dx_d > 0, does not decrease as it grows: its
         * largest s is the s of mp, the bits of the largest of the nodes'
         * (a NaN alpha is not in mp, but nf reports it) */
        double s = 0.0;
        for (int d = 0; d < dim; d++) s += (cm >> d & 1 ? ac[d] : mp) / dx[d];
        (void)floor;
        *inv = s;
        return nf != 0;
    }
    /* (far from underflow and overflow, where the bound holds; else every
     * node exactly) */
    if (floor > 1e-290 && floor < 1e290 && mp < floor * (1 - 1e-12)) {
        *inv = 0;
        return nf != 0;
    }
    const double thr = mp > 1e-290 && mp < 1e290 ? mp * (1 - 1e-12) : 0;
    double m = 0;
    /* the candidates found 8 nodes at a time (one vector compare), the
     * few that pass handled one by one */
#define LF_EXACT(j)                                                                                  \
    if (SP[j] >= thr) {                                                                              \
        double s = 0.0;                                                                              \
        for (int d = 0; d < dim; d++)                                                               \
            s += (cm >> d & 1 ? ac[d] : fabs(A[(size_t)d * astride + (size_t)(j)])) / dx[d];      \
        m = s > m ? s : m;                                                                           \
    }
    long j = 0;
    for (; j + 8 <= n; j += 8) {
        int hit = 0;
        for (int q = 0; q < 8; q++) hit |= SP[j + q] >= thr;
        if (hit)
            for (int q = 0; q < 8; q++) LF_EXACT(j + q)
    }
    for (; j < n; j++) LF_EXACT(j)
#undef LF_EXACT
    *inv = m;
    return nf != 0;
}

/* LF_ROW_CONST: the masks of row-constant dimensions (row_const) that
 * have a loop of their own, first order or ENO2 under GLF in 3-D (diffs):
 * dimensions 0 and 2, as air3D's bounds; lf_row_end fills the rows of
 * any other mask and passes cm = 0. */
#define LF_ROW_CONST(diffs, dim, cm) ((diffs) && (dim) == 3 && (cm) == 5)

/* lf_finish on the rows *bp .. nb - 1 of a block (row b: A, DL, DR, H at
 * + b n, dimension d of A at + d astride; out and the stage's y0, u at
 * + b ostride), each row's floor the running maximum *floor of the exact
 * bounds of the rows before it (the order of one row per call), *inv
 * their maximum.  Returns 0 when every row is done; 1 when row *bp may
 * hold a non-finite value, its bound in *mrow (not yet in *floor, *inv),
 * the rows after it not done. */
HJ_LS_TERM_CLONES
static int lf_finish_dim(int diffs, int dim, int cm, long n, long nb, long *bp, size_t astride, const double *A,
                         const double *DL, const double *DR, size_t ds_stride, const double *H, const double *dx,
                         const double *hinv, int clip, double *out, size_t ostride, double *SP, lf_stage_row *sr,
                         double *floor, double *inv, double *mrow)
{
#define LF_FINISH(DIFFS, DIM, CM, STAGE, CLIP)                                                                   \
    for (long b = *bp; b < nb; b++) {                                                                            \
        const size_t o_ = (size_t)b * (size_t)n, q_ = (size_t)b * ostride;                                       \
        lf_stage_row r_;                                                                                         \
        if (STAGE) r_ = *sr, r_.y0 += q_, r_.u += q_;                                                            \
        double m_;                                                                                               \
        const int nf_ = lf_finish(DIFFS, DIM, CM, STAGE, n, astride, A + o_, DL + o_, DR + o_, ds_stride, H + o_, \
                                  dx, hinv, CLIP, out + q_, SP, &r_, *floor, &m_);                               \
        if (STAGE) sr->smax = r_.smax, sr->sbad = r_.sbad;                                                       \
        if (nf_) {                                                                                               \
            *bp = b, *mrow = m_;                                                                                 \
            return 1;                                                                                            \
        }                                                                                                        \
        *floor = m_ > *floor ? m_ : *floor;                                                                      \
        *inv = m_ > *inv ? m_ : *inv;                                                                            \
    }                                                                                                            \
    return 0;
    /* dim and clip constants in 2-D and 3-D (a constant clip is one
     * vector min or max; a variable one, a chain of compares and blends) */
#define LF_FINISH_CLIPS(DIFFS, DIM, CM, STAGE)              \
    if (clip < 0) { LF_FINISH(DIFFS, DIM, CM, STAGE, -1) }  \
    if (clip > 0) { LF_FINISH(DIFFS, DIM, CM, STAGE, 1) }   \
    LF_FINISH(DIFFS, DIM, CM, STAGE, 0)
#define LF_FINISH_DIMS(DIFFS, STAGE)                        \
    switch (dim) {                                          \
    case 2: { LF_FINISH_CLIPS(DIFFS, 2, 0, STAGE) }         \
    case 3: { LF_FINISH_CLIPS(DIFFS, 3, 0, STAGE) }         \
    default: { LF_FINISH(DIFFS, dim, 0, STAGE, clip) }      \
    }
    if (LF_ROW_CONST(diffs, dim, cm)) {
        if (sr && sr->inplace) { LF_FINISH_CLIPS(1, 3, 5, 2) }
        if (sr && sr->euler) { LF_FINISH_CLIPS(1, 3, 5, 3) }
        if (sr) { LF_FINISH_CLIPS(1, 3, 5, 1) }
        LF_FINISH_CLIPS(1, 3, 5, 0)
    }
    if (sr && sr->inplace) {
        if (diffs) { LF_FINISH_DIMS(1, 2) }
        LF_FINISH_DIMS(0, 2)
    }
    if (sr) {
        if (diffs) { LF_FINISH_DIMS(1, 1) }
        LF_FINISH_DIMS(0, 1)
    }
    if (diffs) { LF_FINISH_DIMS(1, 0) }
    LF_FINISH_DIMS(0, 0)
#undef LF_FINISH_DIMS
#undef LF_FINISH_CLIPS
#undef LF_FINISH
}

/* The distance between lf_row's row buffers in its workspace: n rounded
 * up to whole cache lines (8 doubles), so that with the workspace on a
 * cache line (for_rows_blocks) every buffer starts on one and the row
 * kernels' vector loads and stores of them split no line. */
static size_t lf_row_stride(long n) { return ((size_t)n + 7) & ~(size_t)7; }

/* Both one-sided derivatives along dimension 1 of the row of rc by a
 * scheme of six differences (ENO3, WENO5), the differences in registers
 * from the values along stride[1] (as along dimension 2: no rows of
 * differences stored and read back, no ring to keep).  WENO5 also carries
 * the next row's left derivatives, in one of two buffers at ring + 7 rs,
 * ring + 8 rs (rs = lf_row_stride(n)) by the parity of idx[1], read by the
 * next row if this thread evaluates it next (rc->cache_r: the row that
 * left them).  The caller keeps ring + 6 rs for itself. */
/* w: the row's HJ_LS_ROW_WORK rs workspace the ENO kernels may use. */
static void lf_dim1_ring(int scheme, const hj_ls_grid *g, const double *y, row_ctx *rc, double eps, double *ring,
                         double *w, int mean, double *l, double *r)
{
    const size_t n = lf_row_stride(g->N[0]);
    /* dim1_ring's test: this thread's previous row is row r - 1 */
    const int cont = rc->cache_r != (size_t)-1 && rc->r == rc->cache_r + 1 && rc->idx[1] != 0;
    if (scheme == HJ_LS_WENO5A || scheme == HJ_LS_WENO5B) {
        const size_t h = (size_t)(rc->idx[1] & 1);
        double *next = ring + (7 + h) * n, *left = ring + (8 - h) * n;
        hj_ls_weno5_row_next_eps(scheme, y + rc->k, g->stride[1], g->N[0], g->dx[1], eps, mean, cont ? left : NULL,
                                 next, l, r);
        rc->cache_r = rc->r;
        return;
    }
    if (mean) hj_ls_upwind_row_mean_eps(scheme, y + rc->k, g->stride[1], g->N[0], g->dx[1], eps, l, r, w);
    else hj_ls_upwind_row_eps(scheme, y + rc->k, g->stride[1], g->N[0], g->dx[1], eps, l, r, w);
}

/* Whether the row's H and alphas come from ham_partial_row: set, and one
 * box for every dimension (not LLF). */
static int lf_both(const hj_ls_lax_friedrichs *c)
{
    return c->ham_partial_row && c->dissipation != HJ_LS_LLF;
}

/* The end of a Lax-Friedrichs block of nb rows (for_rows_blocks; 1 but
 * for lf_rows_glf) once the gradient's mean is in pp and the ranges the
 * partials read in lo, hi (LL, LH: the local ranges, for LLF; nb = 1):
 * H, the partials into A, and lf_finish_dim's G or fused stage (SP: n
 * doubles of scratch).  Row b of pp[d], of H and of DL, DR and A's
 * dimension d is at + b rs (A's dimension d at A + d nb rs; rs = n when
 * nb > 1, as lf_finish_dim has it), LL's and LH's dimension d at + d rs;
 * lo and hi are the same for every row.  Returns lf_row's code (*bad:
 * b n + j). */
static inline __attribute__((always_inline)) int lf_row_end(const lf_pass *ps, double t, double *y, double *ydot,
                                                            row_ctx *rc, long nb, size_t rs, const double **pp,
                                                            const double **lo, const double **hi, double *LL,
                                                            double *LH, double *A, double *H, int diffs,
                                                            const double *DL, const double *DR, size_t ds_stride,
                                                            double *SP, double *inv, long *bad)
{
    const hj_ls_lax_friedrichs *c = ps->lf;
    const hj_ls_grid *g = c->grid;
    const long n = g->N[0];
    const int dim = g->dim;
    const size_t bn = (size_t)nb * rs;
    const ptrdiff_t s1 = nb > 1 ? g->stride[1] : 0;
    /* row_const: alpha_d read at node 0 only, its row filled where the
     * finish has no loop for the mask */
    const int cm = (int)(c->row_const & ((1u << dim) - 1));
    const int cmloop = LF_ROW_CONST(diffs, dim, cm), cmfill = cmloop ? 0 : cm;
    const int both = lf_both(c);
    const int toolbox = c->cfl_rule == HJ_LS_CFL_TOOLBOX;
    /* the work per dimension after the callback: none for ham_partial_row
     * with every row_const mask in the finish's loop and the node rule */
    const int per_dim = !both || cmfill || toolbox;
    const hj_ls_ham_partial_row_fn hp = c->ham_partial_row;
    void *const ctx = c->ctx;
    long idx[HJ_LS_MAXDIM];
    double x[HJ_LS_MAXDIM];
    if (nb > 1) memcpy(idx, rc->idx, sizeof(long) * (size_t)dim), memcpy(x, rc->x, sizeof(double) * (size_t)dim);
    const double *pb[HJ_LS_MAXDIM];
    double *Ab[HJ_LS_MAXDIM];
    for (int d = 0; d < dim; d++) pb[d] = pp[d], Ab[d] = A + (size_t)d * bn;
    hj_ls_row_info row = {n, g->dx[0], nb > 1 ? x : rc->x, nb > 1 ? idx : rc->idx, rc->k};
    for (long b = 0; b < nb; b++) {
        const size_t o = (size_t)b * rs;
        if (b) { /* hj_ls_coord's expression */
            idx[1] = rc->idx[1] + b, x[1] = g->min[1] + (double)(idx[1] + g->origin[1]) * g->dx[1];
            row.k += (size_t)s1;
            for (int d = 0; d < dim; d++) pb[d] += rs, Ab[d] += rs;
        }
        const double *phi = y + row.k;
        if (both) hp(t, &row, phi, pb, lo, hi, H + o, Ab, ctx);
        else if (c->ham_row) c->ham_row(t, &row, phi, pb, H + o, c->ctx);
        else lf_ham_nodes(c, t, &row, phi, pb, H + o);
        if (!per_dim) continue;
        for (int d = 0; d < dim; d++) {
            double *Ad = A + (size_t)d * bn + o;
            if (!both) {
                const double *sl = lo[d], *sh = hi[d];
                if (c->dissipation == HJ_LS_LLF) /* local range in d only */
                    lo[d] = LL + (size_t)d * rs, hi[d] = LH + (size_t)d * rs;
                if (c->partial_row) c->partial_row(t, &row, lo, hi, d, Ad, c->ctx);
                else lf_partial_nodes(c, t, &row, lo, hi, d, Ad);
                lo[d] = sl, hi[d] = sh;
            }
            if (cmfill >> d & 1)
                for (long j = 1; j < n; j++) Ad[j] = Ad[0];
            if (toolbox) { /* per-dimension maxima only where used */
                const double dx = g->dx[d];
                double dm = rc->dmax[d];
                SIMD_REDUCE(max : dm)
                for (long j = 0; j < (cm >> d & 1 ? 1 : n); j++) {
                    const double a = fabs(Ad[j]) / dx;
                    dm = a > dm ? a : dm;
                }
                rc->dmax[d] = dm;
            }
        }
    }
    double *out;
    lf_stage_row sr, *srp = NULL;
    if (ps->stage) { /* ydot is NULL */
        const hj_ls_stage *st = ps->stage;
        sr = (lf_stage_row){st->a, st->b, st->dt, st->y0 + rc->k, y + rc->k, rc->smax, 0, st->y0 == st->dst,
                            st->a == 0 && st->b == 1 && st->y0 == y};
        srp = &sr, out = st->dst + rc->k;
    } else
        out = ydot + rc->k;
    double imax = rc->imax, m = 0;
    int code = HJ_OK;
    for (long b = 0;; b++) {
        double mrow;
        if (!lf_finish_dim(diffs, dim, cmloop ? cm : 0, n, nb, &b, bn, A, DL, DR, ds_stride, H, g->dx, ps->hinv,
                           ps->clip, out, (size_t)s1, SP, srp, &imax, &m, &mrow))
            break;
        /* the first node of row b with a non-finite alpha or H (none: a
         * sum overflowed, which the CFL bound reports) */
        const size_t o = (size_t)b * rs;
        long badj = n;
        for (int d = 0; d < dim; d++) {
            const double *Ad = A + (size_t)d * bn + o;
            badj = cmloop && cm >> d & 1 ? (Ad[0] - Ad[0] == 0 ? badj : 0) : first_nonfinite(Ad, badj);
        }
        badj = first_nonfinite(H + o, badj);
        if (badj < n) {
            *bad = b * n + badj;
            code = HJ_ENONFINITE;
            break;
        }
        imax = mrow > imax ? mrow : imax;
        m = mrow > m ? mrow : m;
    }
    if (srp) rc->smax = sr.smax, rc->sbad |= sr.sbad != 0;
    rc->imax = imax;
    *inv = m;
    return code;
}

/* Both one-sided derivatives along dimension 2 of the row of rc by WENO5
 * (returns 0 for another scheme or grid, writing nothing): the row's
 * windows give its right derivatives and the left ones of its neighbour in
 * the next plane, row r + N[1], which are kept per slot idx[1] in one of
 * two buffers by the parity of idx[2] (2 N[1] rows lf_row_stride(n)
 * apart at plane), then
 * read there if this thread's last row of that slot was row r - N[1]
 * (the row each slot last held: N[1] doubles after the buffers, < 0 for
 * none).  One window per node instead of two, the same bits. */
static int lf_dim2_plane(int scheme, const hj_ls_grid *g, const double *y, const row_ctx *rc, double eps, double *plane,
                         int mean, double *l, double *r)
{
    if (g->dim < 3) return 0;
    const size_t n = lf_row_stride(g->N[0]), n1 = (size_t)g->N[1], j = (size_t)rc->idx[1], h = (size_t)(rc->idx[2] & 1);
    double *last = plane + 2 * n1 * n;
    const double *left = plane + ((1 - h) * n1 + j) * n;
    const int cont = rc->idx[2] != 0 && last[j] == (double)(rc->r - n1);
    if (!hj_ls_weno5_row_next_eps(scheme, y + rc->k, g->stride[2], g->N[0], g->dx[2], eps, mean, cont ? left : NULL,
                                  plane + (h * n1 + j) * n, l, r))
        return 0;
    last[j] = (double)rc->r;
    return 1;
}

/* lf_dim2_plane's doubles: none on a grid of fewer than three dimensions. */
static size_t lf_plane_doubles(const hj_ls_grid *g)
{
    return g->dim < 3 ? 0 : (2 * lf_row_stride(g->N[0]) + 1) * (size_t)g->N[1];
}

static int lf_row(const void *term, double t, double *y, double *ydot, row_ctx *rc, double *inv, long *bad)
{
    const lf_pass *ps = term;
    const hj_ls_lax_friedrichs *c = ps->lf;
    const hj_ls_grid *g = c->grid;
    const long n = g->N[0];
    const int dim = g->dim;
    /* the workspace's rows rs apart (lf_row_stride), the range pass's
     * cache rows n apart */
    const size_t rs = lf_row_stride(n), dn = (size_t)dim * (size_t)n, dr_ = (size_t)dim * rs;
    double *dl = rc->ws, *dr = dl + dr_, *w = dr + dr_;
    double *P = w + (size_t)HJ_LS_ROW_WORK * rs, *LL = P + dr_, *LH = LL + dr_, *GL = LH + dr_, *GH = GL + dr_;
    double *A = GH + dr_, *H = A + dr_, *ring = H + rs, *plane = ring + 9 * rs;
    const double *pp[HJ_LS_MAXDIM], *lo[HJ_LS_MAXDIM], *hi[HJ_LS_MAXDIM];
    const int six = c->scheme == HJ_LS_ENO3A || c->scheme == HJ_LS_ENO3B || c->scheme == HJ_LS_WENO5A ||
                    c->scheme == HJ_LS_WENO5B;
    const int local = c->dissipation != HJ_LS_GLF;
    /* GLF with no kept derivatives reads only the mean of D- and D+ and
     * their difference (into P and dr): no one-sided derivatives stored */
    const int diffs = !local && !ps->cache;
    /* dimension d's one-sided derivatives at DL + d ds_stride, DR + d
     * ds_stride: the row's own, or those the range pass kept (per row and
     * dimension, dl then dr) */
    const double *DL = dl, *DR = dr;
    size_t ds_stride = rs;
    if (ps->cache) DL = ps->cache + rc->r * 2 * dn, DR = DL + n, ds_stride = 2 * (size_t)n;
    if (!rc->filled && dim >= 3) /* no row kept for lf_dim2_plane yet */
        for (long j = 0; j < g->N[1]; j++) plane[2 * (size_t)g->N[1] * rs + (size_t)j] = -1;
    /* (first order and ENO2 under GLF with no range pass: lf_rows_glf) */
    for (int d = 0; d < dim; d++) {
        double *l = dl + (size_t)d * rs, *r = dr + (size_t)d * rs;
        double *restrict pd = P + (size_t)d * rs, *restrict ll = LL + (size_t)d * rs, *restrict lh = LH + (size_t)d * rs;
        if (diffs) { /* the mean and D+ - D- straight from the kernel */
            if (d == 1 && six) lf_dim1_ring(c->scheme, g, y, rc, ps->eps[1], ring, w, 1, pd, r);
            else if (d == 2 && lf_dim2_plane(c->scheme, g, y, rc, ps->eps[2], plane, 1, pd, r))
                ;
            else hj_ls_upwind_row_mean_eps(c->scheme, y + rc->k, g->stride[d], n, g->dx[d], ps->eps[d], pd, r, w);
            pp[d] = pd;
            double *gl = GL + (size_t)d * rs, *gh = GH + (size_t)d * rs;
            const double a = ps->gmin[d], b = ps->gmax[d];
            if (!rc->filled) /* the global range: the same for every row of this evaluation */
                for (long j = 0; j < n; j++) gl[j] = a, gh[j] = b;
            lo[d] = gl, hi[d] = gh;
            continue;
        }
        if (ps->cache) /* the range pass computed them */
            l = (double *)DL + (size_t)d * ds_stride, r = (double *)DR + (size_t)d * ds_stride;
        else if (d == 1 && six)
            lf_dim1_ring(c->scheme, g, y, rc, ps->eps[1], ring, w, 0, l, r);
        else if (d == 2 && lf_dim2_plane(c->scheme, g, y, rc, ps->eps[2], plane, 0, l, r))
            ;
        else
            hj_ls_upwind_row_eps(c->scheme, y + rc->k, g->stride[d], n, g->dx[d], ps->eps[d], l, r, w);
        /* blocks of 8 nodes and the last 8 again (HJ_LS_ROW_BLOCKS8) */
#define LF_MEAN_RANGE(j0, j1)                                                                                      \
    for (long j = (j0); j < (j1); j++) {                                                                           \
        const double a = l[j], b = r[j];                                                                           \
        pd[j] = 0.5 * (a + b);                                                                                     \
        ll[j] = a < b ? a : b;                                                                                     \
        lh[j] = a < b ? b : a;                                                                                     \
    }
#define LF_MEAN(j0, j1) \
    for (long j = (j0); j < (j1); j++) pd[j] = 0.5 * (l[j] + r[j]);
        if (local) /* the mean and the local ranges in one loop */
            HJ_LS_ROW_BLOCKS8(n, LF_MEAN_RANGE);
        else
            HJ_LS_ROW_BLOCKS8(n, LF_MEAN);
#undef LF_MEAN_RANGE
#undef LF_MEAN
        pp[d] = pd;
        if (c->dissipation == HJ_LS_LLLF) lo[d] = ll, hi[d] = lh;
        else {
            double *gl = GL + (size_t)d * rs, *gh = GH + (size_t)d * rs;
            const double a = ps->gmin[d], b = ps->gmax[d];
            if (!rc->filled) /* the global range: the same for every row of this evaluation */
                for (long j = 0; j < n; j++) gl[j] = a, gh[j] = b;
            lo[d] = gl, hi[d] = gh;
        }
    }
    rc->filled = 1;
    return lf_row_end(ps, t, y, ydot, rc, 1, rs, pp, lo, hi, LL, LH, A, H, diffs, DL, DR, ds_stride, ring + 6 * rs,
                      inv, bad);
}

/* lf_row for global Lax-Friedrichs with no derivatives kept from a range
 * pass (range_free, or the range computed without a work array: the
 * global range comes in gmin, gmax either way) by a scheme whose
 * mean and D+ - D- of every dimension come in one call (first order,
 * ENO2), on a block of rc->nrows rows (for_rows_blocks): no choice per
 * dimension, every buffer a fixed slice of the workspace, one call of the
 * derivative kernel and of the finish per block.  The same calls and
 * expressions per row as lf_row: the same bits. */
static int lf_rows_glf(const void *term, double t, double *y, double *ydot, row_ctx *rc, double *inv, long *bad)
{
    const lf_pass *ps = term;
    const hj_ls_lax_friedrichs *c = ps->lf;
    const hj_ls_grid *g = c->grid;
    const long n = g->N[0], nb = rc->nrows;
    const int dim = g->dim;
    const size_t dn = (size_t)dim * (size_t)n, bn = (size_t)nb * (size_t)n, dbn = (size_t)dim * bn;
    /* the global range first: its place does not depend on the block's rows */
    double *GL = rc->ws, *GH = GL + dn, *P = GH + dn, *DR = P + dbn, *A = DR + dbn, *H = A + dbn, *SP = H + bn;
    const double *pp[HJ_LS_MAXDIM], *lo[HJ_LS_MAXDIM], *hi[HJ_LS_MAXDIM];
    hj_ls_upwind_rows_mean_block(c->scheme, y + rc->k, g->stride, dim, n, nb, g->dx, ps->hinv, P, DR);
    if (!rc->filled) { /* the global range (NaN: unread), once per evaluation */
        for (int d = 0; d < dim; d++)
            for (long j = 0; j < n; j++) GL[(size_t)d * (size_t)n + (size_t)j] = ps->gmin[d],
                                         GH[(size_t)d * (size_t)n + (size_t)j] = ps->gmax[d];
        rc->filled = 1;
    }
    for (int d = 0; d < dim; d++)
        pp[d] = P + (size_t)d * bn, lo[d] = GL + (size_t)d * (size_t)n, hi[d] = GH + (size_t)d * (size_t)n;
    return lf_row_end(ps, t, y, ydot, rc, nb, (size_t)n, pp, lo, hi, NULL, NULL, A, H, 1, DR, DR, bn, SP, inv, bad);
}

/* Rows per block of lf_rows_glf: enough that the per-call costs are
 * shared, few enough that a block's buffers stay in the level-1 cache. */
enum { LF_GLF_BLOCK = 4 };

/* The evaluation, its output clipped as hj_ls_restrict would (clip 1:
 * G >= 0, -1: G <= 0, 0: not), in the same pass. */
static int lf_eval_clip(const hj_ls_term *term, double t, double *y, double *ydot, double *bound, int clip,
                        hj_ls_stage *stage, hj_error *err)
{
    const hj_ls_lax_friedrichs *c = (const hj_ls_lax_friedrichs *)term;
    const hj_ls_grid *g = c->grid;
    if (!hj_ls_scheme_name(c->scheme)) return hj_error_set(err, HJ_EINVAL, "Lax-Friedrichs: unknown scheme");
    if (!lf_both(c) && ((!c->ham && !c->ham_row) || (!c->partial && !c->partial_row)))
        return hj_error_set(err, HJ_EINVAL,
                            c->ham_partial_row ? "Lax-Friedrichs LLF needs ham and partial callbacks (per node or per "
                                                 "row): ham_partial_row has one box for every dimension"
                                               : "Lax-Friedrichs needs ham and partial callbacks (per node or per row)");
    if (c->dissipation < HJ_LS_GLF || c->dissipation > HJ_LS_LLLF)
        return hj_error_set(err, HJ_EINVAL, "Lax-Friedrichs: unknown dissipation %d", c->dissipation);
    const int ranged = c->dissipation != HJ_LS_LLLF && !c->range_free;
    /* Stencils along one axis at a time: the face ghosts suffice, filled
     * in the row pass's region, unless a pass reads the ghosts before it
     * (the gradient range, the grid-wide WENO epsilons) or a distributed
     * grid exchanges halos. */
    const int ghost = hj_ls_scheme_ghost(c->scheme);
    const int faces = !ranged && !g->dist && !(c->weno_eps == HJ_LS_WENO_EPS_GRID &&
                                               (c->scheme == HJ_LS_WENO5A || c->scheme == HJ_LS_WENO5B));
    if (!faces) hj_ls_fill_ghosts_width(g, y, ghost);
    lf_pass ps;
    ps.lf = c;
    ps.clip = clip;
    ps.stage = stage;
    for (int d = 0; d < g->dim; d++) ps.hinv[d] = 1 / g->dx[d];
    ps.cache = ranged ? c->work : NULL;
    weno_eps(g, c->weno_eps, c->scheme, y, ps.eps);
    const long n = g->N[0];
    for (int d = 0; d < g->dim; d++) ps.gmin[d] = ps.gmax[d] = NAN; /* unread when range_free */
    if (ranged) {
        /* Global range: each thread keeps its own in its workspace; min and
         * max are exact, so the merge order does not matter. */
        for (int d = 0; d < g->dim; d++) ps.gmin[d] = INFINITY, ps.gmax[d] = -INFINITY;
        int nomem = 0, ws_fail = 0;
#ifdef _OPENMP
#pragma omp parallel reduction(| : nomem)
#endif
        {
            row_ctx rc;
            const size_t tail = (size_t)(2 + HJ_LS_ROW_WORK) * (size_t)n;
            rc.ws = malloc(sizeof(double) * (tail + 2 * HJ_LS_MAXDIM));
            if (!hj_sys_team_all(rc.ws != NULL, &ws_fail)) nomem = 1;
            else {
                double *range = rc.ws + tail;
                for (int d = 0; d < g->dim; d++) range[2 * d] = INFINITY, range[2 * d + 1] = -INFINITY;
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 32)
#endif
                for (size_t r = 0; r < g->rows; r++) {
                    double inv;
                    long j;
                    rc.k = hj_ls_row(g, r, rc.idx);
                    rc.r = r;
                    lf_range_row(&ps, t, y, ydot, &rc, &inv, &j);
                }
#ifdef _OPENMP
#pragma omp critical(hj_ls_lf_range)
#endif
                for (int d = 0; d < g->dim; d++) {
                    ps.gmin[d] = range[2 * d] < ps.gmin[d] ? range[2 * d] : ps.gmin[d];
                    ps.gmax[d] = range[2 * d + 1] > ps.gmax[d] ? range[2 * d + 1] : ps.gmax[d];
                }
            }
            free(rc.ws);
        }
        if (nomem) return hj_error_set(err, HJ_ENOMEM, "out of memory for the Lax-Friedrichs workspace");
        hj_ls_grid_reduce(g, ps.gmin, g->dim, HJ_LS_REDUCE_MIN);
        hj_ls_grid_reduce(g, ps.gmax, g->dim, HJ_LS_REDUCE_MAX);
    }
    double m, dm[HJ_LS_MAXDIM];
    const int glf = c->dissipation == HJ_LS_GLF && !ps.cache &&
                    (c->scheme == HJ_LS_UPWIND_FIRST || c->scheme == HJ_LS_ENO2);
    const long blk = glf ? LF_GLF_BLOCK : 1;
    const size_t ws = glf ? ((size_t)(2 * g->dim + 1) + (size_t)(3 * g->dim + 1) * (size_t)blk) * (size_t)n
                          : (size_t)(8 * g->dim + HJ_LS_ROW_WORK + 10) * lf_row_stride(n) + lf_plane_doubles(g);
    int rc = for_rows_blocks(g, ws, glf ? lf_rows_glf : lf_row, blk, 1, &ps, t, y, ydot, &m, dm, stage,
                             faces ? ghost : 0, "Hamiltonian or partial callback", err);
    if (rc) return rc;
    *bound = bound_by_rule(c->cfl_rule, g, m, dm);
    return HJ_OK;
}

static int lf_eval(const hj_ls_term *term, double t, double *y, double *ydot, double *bound, hj_error *err)
{
    return lf_eval_clip(term, t, y, ydot, bound, 0, NULL, err);
}

size_t hj_ls_lax_friedrichs_work_size(const hj_ls_grid *g) { return 2 * (size_t)g->dim * g->nodes; }

void hj_ls_lax_friedrichs_init(hj_ls_lax_friedrichs *c, const hj_ls_grid *g, int scheme, int dissipation,
                               hj_ls_ham_fn ham, hj_ls_partial_fn partial, void *ctx)
{
    memset(c, 0, sizeof *c);
    c->base.eval = lf_eval;
    c->grid = g;
    c->scheme = scheme;
    c->dissipation = dissipation;
    c->ham = ham;
    c->partial = partial;
    c->ctx = ctx;
}

/* ---- pointwise terms: curvature, Hessian trace, discount, forcing ----- */

enum { PT_CURV, PT_HESS, PT_DISC, PT_FORC };
typedef struct {
    int kind;
    const hj_ls_grid *grid;
    const hj_ls_scalar *s;
    const double *M;
} point_term;

static int point_row(const void *term, double t, double *y, double *ydot, row_ctx *rc, double *inv, long *bad)
{
    const point_term *c = term;
    const hj_ls_grid *g = c->grid;
    const int dim = g->dim;
    double x[HJ_LS_MAXDIM], m = 0;
    memcpy(x, rc->x, sizeof(double) * (size_t)dim);
    double sdx = 0;
    for (int d = 0; d < dim; d++) sdx += 1 / (g->dx[d] * g->dx[d]);
    const int batched = c->kind != PT_HESS && scalar_row(c->s, t, g, rc, y, rc->ws);
    for (long j = 0; j < g->N[0]; j++) {
        const size_t k = rc->k + (size_t)j;
        x[0] = g->min[0] + (double)j * g->dx[0];
        const double *p = y + k;
        double v = 0, s = 0;
        if (c->kind == PT_HESS) {
            for (int a = 0; a < dim; a++)
                for (int b = 0; b < dim; b++) {
                    const ptrdiff_t sa = g->stride[a], sb = g->stride[b];
                    const double hab = a == b ? (p[sa] - 2 * p[0] + p[-sa]) / (g->dx[a] * g->dx[a])
                                              : (p[sa + sb] - p[sa - sb] - p[-sa + sb] + p[-sa - sb]) *
                                                    (0.25 / (g->dx[a] * g->dx[b]));
                    v -= c->M[a * dim + b] * hab;
                }
        } else {
            const double a = batched ? rc->ws[j] : scalar_at(c->s, t, x, y[k], k);
            if (!isfinite(a)) { *bad = j; return HJ_ENONFINITE; }
            if (c->kind == PT_CURV) {
                double kappa, mag;
                hj_ls_curvature_at(g, p, &kappa, &mag);
                v = a * kappa * mag;
                s = 2 * fabs(a) * sdx;
            } else if (c->kind == PT_DISC) {
                v = -a * y[k];
                s = fabs(a);
            } else
                v = -a;
        }
        ydot[k] = v;
        m = s > m ? s : m;
    }
    *inv = m;
    return HJ_OK;
}

static int point_eval(const point_term *pt, double t, double *y, double *ydot, double *bound, const char *what,
                      hj_error *err)
{
    const hj_ls_grid *g = pt->grid;
    hj_ls_fill_ghosts_width(g, y, 1); /* centered second differences (corners included) or none */
    double m;
    int rc = for_rows(g, (size_t)g->N[0], point_row, pt, t, y, ydot, &m, NULL, what, err);
    if (rc) return rc;
    if (pt->kind == PT_HESS) {
        m = 0;
        for (int a = 0; a < g->dim; a++)
            for (int b = 0; b < g->dim; b++)
                m += fabs(pt->M[a * g->dim + b]) * (a == b ? 2 : 1) / (g->dx[a] * g->dx[b]);
    }
    *bound = bound_of(m);
    return HJ_OK;
}

static int curvature_eval(const hj_ls_term *term, double t, double *y, double *ydot, double *bound, hj_error *err)
{
    const hj_ls_curvature_term *c = (const hj_ls_curvature_term *)term;
    point_term pt = {PT_CURV, c->grid, &c->b, NULL};
    return point_eval(&pt, t, y, ydot, bound, "curvature coefficient b", err);
}

void hj_ls_curvature_term_init(hj_ls_curvature_term *c, const hj_ls_grid *g)
{
    memset(c, 0, sizeof *c);
    c->base.eval = curvature_eval;
    c->grid = g;
}

static int hessian_eval(const hj_ls_term *term, double t, double *y, double *ydot, double *bound, hj_error *err)
{
    const hj_ls_hessian_term *c = (const hj_ls_hessian_term *)term;
    point_term pt = {PT_HESS, c->grid, NULL, c->M};
    return point_eval(&pt, t, y, ydot, bound, "Hessian trace", err);
}

void hj_ls_hessian_term_init(hj_ls_hessian_term *c, const hj_ls_grid *g, const double *L, const double *R)
{
    memset(c, 0, sizeof *c);
    c->base.eval = hessian_eval;
    c->grid = g;
    const int n = g->dim;
    /* trace(L H R) = trace(R L H) = sum_ij (RL)_ij H_ji, and H is symmetric */
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            double s = 0;
            for (int k = 0; k < n; k++) s += R[i * n + k] * L[k * n + j];
            c->M[i * n + j] = s;
        }
}

static int discount_eval(const hj_ls_term *term, double t, double *y, double *ydot, double *bound, hj_error *err)
{
    const hj_ls_discount *c = (const hj_ls_discount *)term;
    point_term pt = {PT_DISC, c->grid, &c->lambda, NULL};
    return point_eval(&pt, t, y, ydot, bound, "discount factor", err);
}

void hj_ls_discount_init(hj_ls_discount *c, const hj_ls_grid *g)
{
    memset(c, 0, sizeof *c);
    c->base.eval = discount_eval;
    c->grid = g;
}

static int forcing_eval(const hj_ls_term *term, double t, double *y, double *ydot, double *bound, hj_error *err)
{
    const hj_ls_forcing *c = (const hj_ls_forcing *)term;
    point_term pt = {PT_FORC, c->grid, &c->F, NULL};
    return point_eval(&pt, t, y, ydot, bound, "forcing", err);
}

void hj_ls_forcing_init(hj_ls_forcing *c, const hj_ls_grid *g)
{
    memset(c, 0, sizeof *c);
    c->base.eval = forcing_eval;
    c->grid = g;
}

/* ---- restrict and sum ------------------------------------------------ */

static int restrict_eval(const hj_ls_term *term, double t, double *y, double *ydot, double *bound, hj_error *err)
{
    const hj_ls_restrict *c = (const hj_ls_restrict *)term;
    const hj_ls_grid *g = c->grid;
    /* A Lax-Friedrichs term (reachability) clips in its own row pass:
     * the same values, one pass over the grid fewer. */
    if (c->inner->eval == lf_eval)
        return lf_eval_clip(c->inner, t, y, ydot, bound, c->positive ? 1 : -1, NULL, err);
    int rc = c->inner->eval(c->inner, t, y, ydot, bound, err);
    if (rc) return rc;
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 32)
#endif
    for (size_t r = 0; r < g->rows; r++) {
        long idx[HJ_LS_MAXDIM];
        double *p = ydot + hj_ls_row(g, r, idx);
        if (c->positive)
            for (long j = 0; j < g->N[0]; j++) p[j] = p[j] > 0 ? p[j] : 0;
        else
            for (long j = 0; j < g->N[0]; j++) p[j] = p[j] < 0 ? p[j] : 0;
    }
    return HJ_OK;
}

int hj_ls_term_stage(const hj_ls_term *term, double t, double *y, hj_ls_stage *st, double *step_bound, int *done,
                     hj_error *err)
{
    *done = 0;
    /* the stencils read y's neighbours after their rows were written */
    if (st->dst == y) return hj_error_set(err, HJ_EINVAL, "fused stage: dst must not be y (y0 or an array apart)");
    if (term->eval == lf_eval) {
        *done = 1;
        return lf_eval_clip(term, t, y, NULL, step_bound, 0, st, err);
    }
    if (term->eval == convection_eval) {
        *done = 1;
        return convection_pass((const hj_ls_convection *)term, t, y, NULL, st, step_bound, err);
    }
    if (term->eval == restrict_eval) {
        const hj_ls_restrict *c = (const hj_ls_restrict *)term;
        if (c->inner->eval != lf_eval) return HJ_OK;
        *done = 1;
        return lf_eval_clip(c->inner, t, y, NULL, step_bound, c->positive ? 1 : -1, st, err);
    }
    return HJ_OK;
}

void hj_ls_restrict_init(hj_ls_restrict *c, const hj_ls_grid *g, const hj_ls_term *inner, int positive)
{
    memset(c, 0, sizeof *c);
    c->base.eval = restrict_eval;
    c->grid = g;
    c->inner = inner;
    c->positive = positive;
}

static int sum_eval(const hj_ls_term *term, double t, double *y, double *ydot, double *bound, hj_error *err)
{
    const hj_ls_sum *c = (const hj_ls_sum *)term;
    const hj_ls_grid *g = c->grid;
    double inv = 0, b;
    int rc = c->terms[0]->eval(c->terms[0], t, y, ydot, &b, err);
    if (rc) return rc;
    inv += 1 / b;
    for (int i = 1; i < c->n; i++) {
        if ((rc = c->terms[i]->eval(c->terms[i], t, y, c->work, &b, err))) return rc;
        inv += 1 / b;
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 32)
#endif
        for (size_t r = 0; r < g->rows; r++) {
            long idx[HJ_LS_MAXDIM];
            const size_t k = hj_ls_row(g, r, idx);
            for (long j = 0; j < g->N[0]; j++) ydot[k + (size_t)j] += c->work[k + (size_t)j];
        }
    }
    *bound = bound_of(inv);
    return HJ_OK;
}

int hj_ls_sum_init(hj_ls_sum *c, const hj_ls_grid *g, const hj_ls_term *const *terms, int n, hj_error *err)
{
    memset(c, 0, sizeof *c);
    if (n < 1 || n > HJ_LS_SUM_MAX) return hj_error_set(err, HJ_EINVAL, "a sum needs 1..%d terms", HJ_LS_SUM_MAX);
    if (!g) return hj_error_set(err, HJ_EINVAL, "a sum: the grid is NULL");
    if (!terms) return hj_error_set(err, HJ_EINVAL, "a sum: the term list is NULL");
    for (int i = 0; i < n; i++)
        if (!terms[i] || !terms[i]->eval) return hj_error_set(err, HJ_EINVAL, "a sum: term %d is NULL or has no eval", i);
    c->base.eval = sum_eval;
    c->grid = g;
    c->n = n;
    for (int i = 0; i < n; i++) c->terms[i] = terms[i];
    if (n > 1 && !(c->work = hj_ls_alloc(g))) return hj_error_set(err, HJ_ENOMEM, "out of memory for a sum of terms");
    return HJ_OK;
}

void hj_ls_sum_free(hj_ls_sum *c)
{
    hj_ls_free(c->work);
    c->work = NULL;
}

/* ---- extremum of terms ---------------------------------------------------- */

static int extremum_eval(const hj_ls_term *term, double t, double *y, double *ydot, double *bound, hj_error *err)
{
    const hj_ls_extremum *c = (const hj_ls_extremum *)term;
    const hj_ls_grid *g = c->grid;
    double b, bmin;
    int rc = c->terms[0]->eval(c->terms[0], t, y, ydot, &bmin, err);
    if (rc) return rc;
    for (int i = 1; i < c->n; i++) {
        if ((rc = c->terms[i]->eval(c->terms[i], t, y, c->work, &b, err))) return rc;
        bmin = b < bmin || isnan(b) ? b : bmin;
        const int take_max = c->take_max;
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 32)
#endif
        for (size_t r = 0; r < g->rows; r++) {
            long idx[HJ_LS_MAXDIM];
            const size_t k = hj_ls_row(g, r, idx);
            for (long j = 0; j < g->N[0]; j++) {
                const double w = c->work[k + (size_t)j], v = ydot[k + (size_t)j];
                ydot[k + (size_t)j] = take_max ? (w > v ? w : v) : (w < v ? w : v);
            }
        }
    }
    *bound = bmin;
    return HJ_OK;
}

int hj_ls_extremum_init(hj_ls_extremum *c, const hj_ls_grid *g, const hj_ls_term *const *terms, int n, int take_max,
                        hj_error *err)
{
    memset(c, 0, sizeof *c);
    if (n < 1 || n > HJ_LS_SUM_MAX) return hj_error_set(err, HJ_EINVAL, "an extremum needs 1..%d terms", HJ_LS_SUM_MAX);
    if (!g) return hj_error_set(err, HJ_EINVAL, "an extremum: the grid is NULL");
    if (!terms) return hj_error_set(err, HJ_EINVAL, "an extremum: the term list is NULL");
    for (int i = 0; i < n; i++)
        if (!terms[i] || !terms[i]->eval) return hj_error_set(err, HJ_EINVAL, "an extremum: term %d is NULL or has no eval", i);
    c->base.eval = extremum_eval;
    c->grid = g;
    c->n = n;
    c->take_max = take_max != 0;
    for (int i = 0; i < n; i++) c->terms[i] = terms[i];
    if (n > 1 && !(c->work = hj_ls_alloc(g))) return hj_error_set(err, HJ_ENOMEM, "out of memory for an extremum of terms");
    return HJ_OK;
}

void hj_ls_extremum_free(hj_ls_extremum *c)
{
    hj_ls_free(c->work);
    c->work = NULL;
}

static const char *const dissipation_name[3] = {"global", "local", "locallocal"};

const char *hj_ls_dissipation_name(int diss)
{
    return diss >= HJ_LS_GLF && diss <= HJ_LS_LLLF ? dissipation_name[diss] : "?";
}

int hj_ls_dissipation_parse(const char *s, int *diss, hj_error *err)
{
    const int v[3] = {HJ_LS_GLF, HJ_LS_LLF, HJ_LS_LLLF};
    for (int k = 0; k < 3; k++)
        if (!strcmp(s, dissipation_name[k])) {
            *diss = v[k];
            return HJ_OK;
        }
    return hj_error_set(err, HJ_EINVAL, "unknown dissipation '%s' (global, local, locallocal)", s);
}

/* ---- the grid a term was made on -------------------------------------- */

/* The grid of a term of this library; *ours = 0 for any other eval. */
static const hj_ls_grid *term_grid(const hj_ls_term *term, int *ours)
{
    *ours = 1;
    const hj_ls_term_fn f = term->eval;
    if (f == convection_eval) return ((const hj_ls_convection *)term)->grid;
    if (f == normal_eval) return ((const hj_ls_normal *)term)->grid;
    if (f == reinit_eval) return ((const hj_ls_reinit *)term)->grid;
    if (f == lf_eval) return ((const hj_ls_lax_friedrichs *)term)->grid;
    if (f == curvature_eval) return ((const hj_ls_curvature_term *)term)->grid;
    if (f == hessian_eval) return ((const hj_ls_hessian_term *)term)->grid;
    if (f == discount_eval) return ((const hj_ls_discount *)term)->grid;
    if (f == forcing_eval) return ((const hj_ls_forcing *)term)->grid;
    if (f == restrict_eval) return ((const hj_ls_restrict *)term)->grid;
    if (f == sum_eval) return ((const hj_ls_sum *)term)->grid;
    if (f == extremum_eval) return ((const hj_ls_extremum *)term)->grid;
    *ours = 0;
    return NULL;
}

const hj_ls_grid *hj_ls_term_grid(const hj_ls_term *term)
{
    int ours;
    return term ? term_grid(term, &ours) : NULL;
}

/* Whether a and b lay out and place their nodes alike: the same
 * dimension, node counts, first node, spacing, boundary conditions and
 * (a block of a distributed grid) global origin.  A condition's lo and hi
 * count only where they are read (Dirichlet, Neumann): a periodic or
 * extrapolating condition's are free; first nodes and spacings are
 * compared to rounding (near).  NULL when alike, else what
 * differs first, into buf. */
/* a and b equal to rounding: within 8 ulps of the larger magnitude (or
 * of scale, the spacing, for a first node near 0).  A periodic grid from
 * hj_ls_grid_init_period and one from hj_ls_grid_init on its max place
 * the same nodes with spacings (max - min) / N and (max' - min) / (N - 1)
 * that differ in the last bit for a third of the N (10 .. 400, period
 * 2 pi); the terms compute with their own grid's values. */
static int near(double a, double b, double scale)
{
    const double m = fmax(fmax(fabs(a), fabs(b)), scale);
    return fabs(a - b) <= 8 * DBL_EPSILON * m;
}

static const char *grid_difference(const hj_ls_grid *a, const hj_ls_grid *b, char *buf, size_t size)
{
    if (a == b) return NULL;
    if (a->dim != b->dim) {
        snprintf(buf, size, "the dimension");
        return buf;
    }
    for (int d = 0; d < a->dim; d++) {
        const int t = a->bc[d].type, values = t == HJ_LS_BC_DIRICHLET || t == HJ_LS_BC_NEUMANN;
        const char *what = a->N[d] != b->N[d]           ? "node count"
                           : !near(a->min[d], b->min[d], a->dx[d]) ? "first node"
                           : !near(a->dx[d], b->dx[d], 0) ? "spacing"
                           : t != b->bc[d].type         ? "boundary condition"
                           : values && (a->bc[d].lo != b->bc[d].lo || a->bc[d].hi != b->bc[d].hi)
                               ? "boundary condition"
                           : a->origin[d] != b->origin[d] ? "block origin"
                                                          : NULL;
        if (what) {
            snprintf(buf, size, "the %s of dimension %d", what, d);
            return buf;
        }
    }
    return NULL;
}

static int check_grid(const hj_ls_term *term, const hj_ls_grid *g, int depth, hj_error *err)
{
    if (!term || !term->eval) return hj_error_set(err, HJ_EINVAL, "a term is NULL or has no eval function");
    if (depth > 64) return hj_error_set(err, HJ_EINVAL, "terms nested more than 64 deep (a term that wraps itself?)");
    int ours;
    const hj_ls_grid *tg = term_grid(term, &ours);
    /* a void *_init given a NULL grid: its eval would dereference it */
    if (ours && !tg) return hj_error_set(err, HJ_EINVAL, "a term was initialised with a NULL grid");
    char why[64];
    const char *diff = tg ? grid_difference(tg, g, why, sizeof why) : NULL;
    if (diff) {
        char a[160] = "", b[160] = "";
        for (int d = 0; d < tg->dim; d++)
            snprintf(a + strlen(a), sizeof a - strlen(a), "%s%ld", d ? " x " : "", tg->N[d]);
        for (int d = 0; d < g->dim; d++)
            snprintf(b + strlen(b), sizeof b - strlen(b), "%s%ld", d ? " x " : "", g->N[d]);
        return hj_error_set(err, HJ_EINVAL,
                            "a term was made on another grid (%d-D, %s nodes) than the one it is evaluated on (%d-D, "
                            "%s nodes; %s differs): init the term with this grid",
                            tg->dim, a, g->dim, b, diff);
    }
    const hj_ls_term_fn f = term->eval;
    if (f == restrict_eval) return check_grid(((const hj_ls_restrict *)term)->inner, g, depth + 1, err);
    if (f == sum_eval || f == extremum_eval) {
        const int n = f == sum_eval ? ((const hj_ls_sum *)term)->n : ((const hj_ls_extremum *)term)->n;
        const hj_ls_term *const *ts = f == sum_eval ? ((const hj_ls_sum *)term)->terms : ((const hj_ls_extremum *)term)->terms;
        for (int i = 0; i < n; i++) {
            int rc = check_grid(ts[i], g, depth + 1, err);
            if (rc) return rc;
        }
    }
    return HJ_OK;
}

int hj_ls_term_check_grid(const hj_ls_term *term, const hj_ls_grid *g, hj_error *err)
{
    if (!g) return hj_error_set(err, HJ_EINVAL, "the grid is NULL");
    return check_grid(term, g, 0, err);
}
