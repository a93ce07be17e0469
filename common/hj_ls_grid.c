/* hj_ls_grid.c -- grids, ghosted arrays and boundary conditions. */
#include "hj_ls_grid.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "hj_sys.h"

/* The pointer arguments of the grid constructors (sizes: N or dx). */
static int check_pointers(const hj_ls_grid *g, const double *min, const double *max, const void *sizes,
                          const char *sizes_name, const hj_ls_bc *bc, hj_error *err)
{
    if (!g) return hj_error_set(err, HJ_EINVAL, "grid: the hj_ls_grid to fill is NULL");
    const char *which = !min ? "min" : !max ? "max" : !sizes ? sizes_name : !bc ? "boundary condition" : NULL;
    if (which) return hj_error_set(err, HJ_EINVAL, "grid: the %s array is NULL", which);
    return HJ_OK;
}

int hj_ls_grid_layout(hj_ls_grid *g, int dim, const double *min, const double *max, const long *N, const hj_ls_bc *bc,
                      hj_error *err)
{
    int rc = check_pointers(g, min, max, N, "N", bc, err);
    if (rc) return rc;
    if (dim < 1 || dim > HJ_LS_MAXDIM)
        return hj_error_set(err, HJ_EINVAL, "grid dimension must be 1..%d, got %d", HJ_LS_MAXDIM, dim);
    g->dim = dim;
    g->total = 1;
    g->nodes = 1;
    for (int d = 0; d < dim; d++) {
        if (!isfinite(min[d]) || !isfinite(max[d]))
            return hj_error_set(err, HJ_ENONFINITE, "grid bounds in dimension %d are not finite", d);
        if (!(max[d] > min[d]))
            return hj_error_set(err, HJ_EINVAL, "grid max must exceed min in dimension %d", d);
        if (N[d] < 2) return hj_error_set(err, HJ_EINVAL, "grid needs N >= 2 in dimension %d, got %ld", d, N[d]);
        if (bc[d].type < HJ_LS_BC_PERIODIC || bc[d].type > HJ_LS_BC_EXTRAP_TOWARD)
            return hj_error_set(err, HJ_EINVAL, "unknown boundary condition %d in dimension %d", bc[d].type, d);
        if (!isfinite(bc[d].lo) || !isfinite(bc[d].hi))
            return hj_error_set(err, HJ_ENONFINITE, "boundary data in dimension %d are not finite", d);
        g->N[d] = N[d];
        g->min[d] = min[d];
        g->max[d] = max[d];
        g->dx[d] = (max[d] - min[d]) / (double)(N[d] - 1);
        /* max - min overflows beyond +-DBL_MAX / 2 and dx is 0 or subnormal
         * on a tiny box: the stencils divide by dx (1 / 1e-321 is inf) */
        if (!isfinite(g->dx[d]) || !(g->dx[d] >= DBL_MIN))
            return hj_error_set(err, HJ_EINVAL, "grid spacing (max - min) / (N - 1) = %g in dimension %d: must be "
                                "finite and at least %g", g->dx[d], d, DBL_MIN);
        g->bc[d] = bc[d];
        g->ext[d] = N[d] + 2 * HJ_LS_GHOST;
        /* Overflow-safe product: "grid too large" before any allocation. */
        if ((size_t)g->ext[d] > SIZE_MAX / sizeof(double) / g->total)
            return hj_error_set(err, HJ_ENOMEM, "grid too large: the array size overflows");
        g->stride[d] = (ptrdiff_t)g->total;
        g->total *= (size_t)g->ext[d];
        g->nodes *= (size_t)N[d];
    }
    for (int d = 0; d < HJ_LS_MAXDIM; d++) g->origin[d] = 0;
    g->dist = NULL;
    g->offset = 0;
    for (int d = 0; d < dim; d++) g->offset += (size_t)HJ_LS_GHOST * (size_t)g->stride[d];
    g->rows = g->nodes / (size_t)N[0];
    return HJ_OK;
}

int hj_ls_grid_init(hj_ls_grid *g, int dim, const double *min, const double *max, const long *N, const hj_ls_bc *bc,
                    hj_error *err)
{
    const int rc = hj_ls_grid_layout(g, dim, min, max, N, bc, err);
    if (rc) return rc;
    const double mem = hj_sys_physical_memory();
    if (mem > 0 && (double)g->total * sizeof(double) > mem)
        return hj_error_set(err, HJ_ENOMEM, "grid too large: one array needs %.3g GB, the machine has %.3g GB",
                            (double)g->total * sizeof(double) / 1e9, mem / 1e9);
    return HJ_OK;
}

int hj_ls_grid_init_period(hj_ls_grid *g, int dim, const double *min, const double *max, const long *N,
                           const hj_ls_bc *bc, hj_error *err)
{
    int rc = check_pointers(g, min, max, N, "N", bc, err);
    if (rc) return rc;
    if (dim < 1 || dim > HJ_LS_MAXDIM)
        return hj_error_set(err, HJ_EINVAL, "grid dimension must be 1..%d, got %d", HJ_LS_MAXDIM, dim);
    double mx[HJ_LS_MAXDIM];
    for (int d = 0; d < dim; d++) {
        mx[d] = max[d];
        if (bc[d].type != HJ_LS_BC_PERIODIC) continue;
        if (!isfinite(min[d]) || !isfinite(max[d]))
            return hj_error_set(err, HJ_ENONFINITE, "grid bounds in dimension %d are not finite", d);
        if (!(max[d] > min[d])) return hj_error_set(err, HJ_EINVAL, "the period must be positive in dimension %d", d);
        if (N[d] < 2) return hj_error_set(err, HJ_EINVAL, "grid needs N >= 2 in dimension %d, got %ld", d, N[d]);
        /* N nodes per period: the last node sits one spacing before the
         * first node's image min + period. */
        mx[d] = min[d] + (max[d] - min[d]) * (double)(N[d] - 1) / (double)N[d];
    }
    rc = hj_ls_grid_init(g, dim, min, mx, N, bc, err);
    if (rc) return rc;
    for (int d = 0; d < dim; d++)
        if (bc[d].type == HJ_LS_BC_PERIODIC) g->dx[d] = (max[d] - min[d]) / (double)N[d];
    return HJ_OK;
}

double hj_ls_grid_period(const hj_ls_grid *g, int d)
{
    return g->bc[d].type == HJ_LS_BC_PERIODIC ? (double)g->N[d] * g->dx[d] : 0.0;
}

int hj_ls_grid_init_dx(hj_ls_grid *g, int dim, const double *min, const double *max, const double *dx,
                       const hj_ls_bc *bc, hj_error *err)
{
    int rc = check_pointers(g, min, max, dx, "dx", bc, err);
    if (rc) return rc;
    if (dim < 1 || dim > HJ_LS_MAXDIM)
        return hj_error_set(err, HJ_EINVAL, "grid dimension must be 1..%d, got %d", HJ_LS_MAXDIM, dim);
    long N[HJ_LS_MAXDIM];
    double mx[HJ_LS_MAXDIM];
    for (int d = 0; d < dim; d++) {
        if (!(dx[d] > 0) || !isfinite(dx[d]))
            return hj_error_set(err, HJ_EINVAL, "grid spacing must be positive and finite in dimension %d", d);
        const double n = floor((max[d] - min[d]) / dx[d] + 0.5) + 1;
        if (!(n >= 2) || n > 1e15)
            return hj_error_set(err, HJ_EINVAL, "grid spacing gives %g nodes in dimension %d", n, d);
        N[d] = (long)n;
        mx[d] = min[d] + (double)(N[d] - 1) * dx[d];
    }
    rc = hj_ls_grid_init(g, dim, min, mx, N, bc, err);
    if (rc) return rc;
    for (int d = 0; d < dim; d++) g->dx[d] = dx[d];
    return HJ_OK;
}

double *hj_ls_alloc(const hj_ls_grid *g) { return g ? calloc(g->total, sizeof(double)) : NULL; }

void hj_ls_free(double *a) { free(a); }

size_t hj_ls_index(const hj_ls_grid *g, const long *i)
{
    ptrdiff_t k = (ptrdiff_t)g->offset;
    for (int d = 0; d < g->dim; d++) k += i[d] * g->stride[d];
    return (size_t)k;
}

void hj_ls_coord(const hj_ls_grid *g, const long *i, double *x)
{
    for (int d = 0; d < g->dim; d++) x[d] = g->min[d] + (double)(i[d] + g->origin[d]) * g->dx[d];
}

void hj_ls_format_node(const hj_ls_grid *g, size_t r, long j, char *buf, size_t n)
{
    long idx[HJ_LS_MAXDIM];
    double x[HJ_LS_MAXDIM];
    hj_ls_row(g, r, idx);
    idx[0] = j;
    hj_ls_coord(g, idx, x);
    size_t len = 0;
    if (n) buf[0] = 0;
    for (int d = 0; d < g->dim && len < n; d++) {
        const int w = snprintf(buf + len, n - len, "%s%g", d ? ", " : "", x[d]);
        if (w < 0) break;
        len += (size_t)w;
    }
}

size_t hj_ls_row(const hj_ls_grid *g, size_t r, long *i)
{
    size_t k = g->offset;
    i[0] = 0;
    for (int d = 1; d < g->dim; d++) {
        i[d] = (long)(r % (size_t)g->N[d]);
        r /= (size_t)g->N[d];
        k += (size_t)i[d] * (size_t)g->stride[d];
    }
    return k;
}

/* Fill the 2 width ghosts of one line nearest its ends (width <=
 * HJ_LS_GHOST; layer k's value does not depend on width): p points at
 * interior node 0, s is the stride along the line, n its number of
 * interior nodes. */
static void fill_line(double *p, ptrdiff_t s, long n, double dx, const hj_ls_bc *bc, int width)
{
    double *lo = p, *hi = p + (n - 1) * s;
    for (long k = 1; k <= width; k++) {
        double *gl = lo - k * s, *gh = hi + k * s;
        switch (bc->type) {
        case HJ_LS_BC_PERIODIC:
            /* k <= HJ_LS_GHOST may exceed n on tiny grids: wrap fully. */
            *gl = p[((n - k % n) % n) * s];
            *gh = p[((k - 1) % n) * s];
            break;
        case HJ_LS_BC_DIRICHLET:
            *gl = bc->lo;
            *gh = bc->hi;
            break;
        case HJ_LS_BC_NEUMANN:
            *gl = *lo + (double)k * dx * bc->lo;
            *gh = *hi + (double)k * dx * bc->hi;
            break;
        default: { /* extrapolation away from / toward zero */
            const double dir = bc->type == HJ_LS_BC_EXTRAP_AWAY ? 1.0 : -1.0;
            const double sl = *lo > 0 ? 1.0 : (*lo < 0 ? -1.0 : 0.0);
            const double sh = *hi > 0 ? 1.0 : (*hi < 0 ? -1.0 : 0.0);
            *gl = *lo + (double)k * dir * sl * fabs(*lo - lo[s]);
            *gh = *hi + (double)k * dir * sh * fabs(*hi - hi[-s]);
        }
        }
    }
}

/* fill_line for the m neighbouring lines p[i], p[i + s], ... (i < m):
 * the same expression per ghost node, in a loop over i that vectorises
 * (the lines along d > 0 lie side by side in memory). */
static void fill_lines(double *p, ptrdiff_t s, long n, long m, double dx, const hj_ls_bc *bc, int width)
{
    double *lo = p, *hi = p + (n - 1) * s;
    const double *lo1 = lo + s, *hi1 = hi - s;
    for (long k = 1; k <= width; k++) {
        double *gl = lo - k * s, *gh = hi + k * s;
        switch (bc->type) {
        case HJ_LS_BC_PERIODIC: {
            const double *sl = p + ((n - k % n) % n) * s, *sh = p + ((k - 1) % n) * s;
            for (long i = 0; i < m; i++) gl[i] = sl[i], gh[i] = sh[i];
            break;
        }
        case HJ_LS_BC_DIRICHLET:
            for (long i = 0; i < m; i++) gl[i] = bc->lo, gh[i] = bc->hi;
            break;
        case HJ_LS_BC_NEUMANN:
            for (long i = 0; i < m; i++) {
                gl[i] = lo[i] + (double)k * dx * bc->lo;
                gh[i] = hi[i] + (double)k * dx * bc->hi;
            }
            break;
        default: { /* extrapolation away from / toward zero */
            const double dir = bc->type == HJ_LS_BC_EXTRAP_AWAY ? 1.0 : -1.0;
            for (long i = 0; i < m; i++) {
                const double sl = lo[i] > 0 ? 1.0 : (lo[i] < 0 ? -1.0 : 0.0);
                const double sh = hi[i] > 0 ? 1.0 : (hi[i] < 0 ? -1.0 : 0.0);
                gl[i] = lo[i] + (double)k * dir * sl * fabs(lo[i] - lo1[i]);
                gh[i] = hi[i] + (double)k * dir * sh * fabs(hi[i] - hi1[i]);
            }
        }
        }
    }
}

void hj_ls_fill_ghosts(const hj_ls_grid *g, double *a) { hj_ls_fill_ghosts_width(g, a, HJ_LS_GHOST); }

/* Ghost nodes of one dimension below which its fill runs on one thread:
 * a few tens of microseconds of work, about what waking a second thread
 * costs on a loaded machine (each node is set independently: the same
 * values either way). */
#define HJ_LS_FILL_PARALLEL 32768

/* Offset of the q-th combination (dimension d + 1 fastest) of interior
 * indices of the dimensions above d, the indices of d and below being 0
 * in the ghosted numbering (the first ghost). */
static size_t above_offset(const hj_ls_grid *g, int d, size_t q)
{
    size_t k = 0;
    for (int e = d + 1; e < g->dim; e++) {
        k += (q % (size_t)g->N[e] + (size_t)HJ_LS_GHOST) * (size_t)g->stride[e];
        q /= (size_t)g->N[e];
    }
    return k;
}

/* A width outside 1..HJ_LS_GHOST as the nearest of them: the arrays have
 * HJ_LS_GHOST layers, and a wider fill would write beyond them. */
static int clamp_width(int width)
{
    return width < 1 ? 1 : width > HJ_LS_GHOST ? HJ_LS_GHOST : width;
}

void hj_ls_fill_ghosts_width(const hj_ls_grid *g, double *a, int width)
{
    width = clamp_width(width);
    /* Lines along d over the full (ghosted) extent of the dimensions below
     * d, so that corners take the ghosts already filled there, and over
     * the interior of the dimensions above d only: the ghosts of those
     * are filled later from their interior planes, which overwrites
     * whatever a line through them would have written (the same values
     * as filling every line, with fewer lines). */
    for (int d = 0; d < g->dim; d++) {
        size_t above = 1;
        for (int e = d + 1; e < g->dim; e++) above *= (size_t)g->N[e];
        if (d == 0) {
            /* planes of the dimensions above 1, each n1 lines apart by stride 1 */
            const size_t n1 = g->dim > 1 ? (size_t)g->N[1] : 1, s1 = g->dim > 1 ? (size_t)g->stride[1] : 0;
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 1) if (above * 2 * HJ_LS_GHOST >= HJ_LS_FILL_PARALLEL)
#endif
            for (size_t q = 0; q < above / n1; q++) {
                double *p = a + above_offset(g, 1, q) + (size_t)HJ_LS_GHOST * (s1 + 1);
                for (size_t l = 0; l < n1; l++) fill_line(p + l * s1, 1, g->N[0], g->dx[0], &g->bc[0], HJ_LS_GHOST);
            }
        } else {
            /* Along d > 0 the lines through one plane of the dimensions
             * below d are contiguous: planes (one per combination of the
             * interior indices above d) cut into pieces of `piece` lines. */
            const size_t inner = (size_t)g->stride[d];
            const size_t piece = 512, pieces = (inner + piece - 1) / piece;
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 4) if (above * inner * 2 * HJ_LS_GHOST >= HJ_LS_FILL_PARALLEL)
#endif
            for (size_t q = 0; q < above * pieces; q++) {
                const size_t o = q / pieces, i0 = (q % pieces) * piece;
                const size_t m = inner - i0 < piece ? inner - i0 : piece;
                double *p = a + above_offset(g, d, o) + (size_t)HJ_LS_GHOST * inner + i0;
                fill_lines(p, g->stride[d], g->N[d], (long)m, g->dx[d], &g->bc[d], HJ_LS_GHOST);
            }
        }
        if (g->dist) g->dist->halo(g, a, d, width, g->dist->ctx);
    }
}

/* Run q (0 <= q < prod_{e != 0, d} N[e]) of the lines along d at interior
 * indices: its N[0] lines side by side, first at interior node 0 of d. */
static double *face_run(const hj_ls_grid *g, double *a, int d, size_t q)
{
    size_t k = g->offset;
    for (int e = 1; e < g->dim; e++) {
        if (e == d) continue;
        k += (q % (size_t)g->N[e]) * (size_t)g->stride[e];
        q /= (size_t)g->N[e];
    }
    return a + k;
}

void hj_ls_fill_ghost_faces(const hj_ls_grid *g, double *a, int width)
{
    width = clamp_width(width);
    /* runs of dimension 1, then of 2, ...: one loop over all of them */
    size_t runs[HJ_LS_MAXDIM] = {0}, total = 0;
    for (int d = 1; d < g->dim; d++) {
        runs[d] = g->nodes / ((size_t)g->N[0] * (size_t)g->N[d]);
        total += runs[d];
    }
#ifdef _OPENMP
#pragma omp for schedule(static)
#endif
    for (size_t q = 0; q < total; q++) {
        int d = 1;
        size_t r = q;
        while (r >= runs[d]) r -= runs[d++];
        fill_lines(face_run(g, a, d, r), g->stride[d], g->N[d], g->N[0], g->dx[d], &g->bc[d], width);
    }
}

void hj_ls_fill_row_ghosts(const hj_ls_grid *g, double *a, size_t k, int width)
{
    fill_line(a + k, 1, g->N[0], g->dx[0], &g->bc[0], clamp_width(width));
}

void hj_ls_grid_reduce(const hj_ls_grid *g, double *v, int n, int op)
{
    if (g->dist) g->dist->reduce(v, n, op, g->dist->ctx);
}

void hj_ls_fill(const hj_ls_grid *g, double *a, hj_ls_field_fn f, void *ctx)
{
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 16)
#endif
    for (size_t r = 0; r < g->rows; r++) {
        long i[HJ_LS_MAXDIM];
        double x[HJ_LS_MAXDIM];
        double *p = a + hj_ls_row(g, r, i);
        hj_ls_coord(g, i, x);
        for (long j = 0; j < g->N[0]; j++) {
            x[0] = g->min[0] + (double)j * g->dx[0];
            p[j] = f(x, ctx);
        }
    }
}

void hj_ls_copy(const hj_ls_grid *g, double *dst, const double *src)
{
    long i[HJ_LS_MAXDIM];
    for (size_t r = 0; r < g->rows; r++) {
        const size_t k = hj_ls_row(g, r, i);
        for (long j = 0; j < g->N[0]; j++) dst[k + (size_t)j] = src[k + (size_t)j];
    }
}

void hj_ls_pack(const hj_ls_grid *g, double *packed, const double *a)
{
    long i[HJ_LS_MAXDIM];
    const size_t n0 = (size_t)g->N[0];
    for (size_t r = 0; r < g->rows; r++) memcpy(packed + r * n0, a + hj_ls_row(g, r, i), n0 * sizeof(double));
}

void hj_ls_unpack(const hj_ls_grid *g, double *a, const double *packed)
{
    long i[HJ_LS_MAXDIM];
    const size_t n0 = (size_t)g->N[0];
    for (size_t r = 0; r < g->rows; r++) memcpy(a + hj_ls_row(g, r, i), packed + r * n0, n0 * sizeof(double));
}

void hj_ls_norms_add(const hj_ls_grid *g, const double *a, const double *b, double *max, hj_sum *s1, hj_sum *s2)
{
    double m = *max;
    /* One accumulator pair per thread, merged: exact, so the merge order
     * does not matter. */
#pragma omp parallel
    {
        hj_sum t1, t2;
        hj_sum_init(&t1), hj_sum_init(&t2);
        double tm = 0;
        long i[HJ_LS_MAXDIM];
#pragma omp for schedule(static) nowait
        for (size_t r = 0; r < g->rows; r++) {
            const size_t k = hj_ls_row(g, r, i);
            for (long j = 0; j < g->N[0]; j++) {
                const double e = fabs(a[k + (size_t)j] - (b ? b[k + (size_t)j] : 0.0));
                tm = e > tm ? e : tm;
                if (s1) hj_sum_add(&t1, e);
                if (s2) hj_sum_add(&t2, e * e);
            }
        }
#pragma omp critical(hj_ls_norms_merge)
        {
            m = tm > m ? tm : m;
            if (s1) hj_sum_merge(s1, &t1);
            if (s2) hj_sum_merge(s2, &t2);
        }
    }
    *max = m;
}

void hj_ls_norms(const hj_ls_grid *g, const double *a, const double *b, double *max, double *avg, double *rms)
{
    double m = 0;
    hj_sum s1, s2;
    hj_sum_init(&s1), hj_sum_init(&s2);
    hj_ls_norms_add(g, a, b, &m, avg ? &s1 : NULL, rms ? &s2 : NULL);
    if (max) *max = m;
    if (avg) *avg = hj_sum_value(&s1) / (double)g->nodes;
    if (rms) *rms = sqrt(hj_sum_value(&s2) / (double)g->nodes);
}

static long count_rows(const hj_ls_grid *g, const double *a, const double *b, int differ)
{
    long c = 0;
    for (size_t r = 0; r < g->rows; r++) {
        long i[HJ_LS_MAXDIM] = {0};
        const size_t k = hj_ls_row(g, r, i);
        for (long j = 0; j < g->N[0]; j++) {
            const double x = a[k + (size_t)j], y = b[k + (size_t)j];
            c += differ ? memcmp(&x, &y, sizeof x) != 0 : y > x;
        }
    }
    return c;
}

long hj_ls_count_increase(const hj_ls_grid *g, const double *a, const double *b) { return count_rows(g, a, b, 0); }
long hj_ls_count_differ(const hj_ls_grid *g, const double *a, const double *b) { return count_rows(g, a, b, 1); }
