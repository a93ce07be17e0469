/* Unit tests of common/hj_ls_grid: grid set-up, indexing, and the ghost
 * values of every boundary condition in one and two dimensions (the
 * toolbox's ghostCell script, with the values checked instead of looked at). */
#include "hj_test.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

#include "hj_ls_grid.h"
#include "hj_test_ls.h"
#ifdef _OPENMP
#include <omp.h>
#endif

static hj_ls_grid grid1(int type, double lo, double hi, long n)
{
    hj_ls_grid g;
    double mn = 0, mx = 1;
    hj_ls_bc bc = {type, lo, hi};
    assert_int_equal(hj_ls_grid_init(&g, 1, &mn, &mx, &n, &bc, NULL), HJ_OK);
    return g;
}

/* phi_i = values[i] on a 1-D grid of n nodes; returns the array. */
static double *line(const hj_ls_grid *g, const double *v)
{
    double *a = hj_ls_alloc(g);
    assert_non_null(a);
    for (long i = 0; i < g->N[0]; i++) a[g->offset + (size_t)i] = v[i];
    hj_ls_fill_ghosts(g, a);
    return a;
}

#define AT(a, g, i) ((a)[(size_t)((ptrdiff_t)(g).offset + (i))])

static void ghosts_1d(void **state)
{
    (void)state;
    const double v[5] = {-2, -1, 0.5, 2, 4};
    hj_ls_grid g = grid1(HJ_LS_BC_PERIODIC, 0, 0, 5);
    double *a = line(&g, v);
    assert_close(AT(a, g, -1), 4, 0, 0);
    assert_close(AT(a, g, -3), 0.5, 0, 0);
    assert_close(AT(a, g, 5), -2, 0, 0);
    assert_close(AT(a, g, 7), 0.5, 0, 0);
    hj_ls_free(a);

    g = grid1(HJ_LS_BC_DIRICHLET, 7, -7, 5);
    a = line(&g, v);
    for (int k = 1; k <= 3; k++) {
        assert_close(AT(a, g, -k), 7, 0, 0);
        assert_close(AT(a, g, 4 + k), -7, 0, 0);
    }
    hj_ls_free(a);

    /* Neumann: outward normal derivative 1 below, 2 above; dx = 0.25. */
    g = grid1(HJ_LS_BC_NEUMANN, 1, 2, 5);
    a = line(&g, v);
    assert_close(AT(a, g, -2), -2 + 2 * 0.25 * 1, 1e-15, 0);
    assert_close(AT(a, g, 7), 4 + 3 * 0.25 * 2, 1e-15, 0);
    hj_ls_free(a);

    /* Extrapolation away from zero: lower end -2 (slope 1 away = down). */
    g = grid1(HJ_LS_BC_EXTRAP_AWAY, 0, 0, 5);
    a = line(&g, v);
    assert_close(AT(a, g, -1), -3, 0, 0);
    assert_close(AT(a, g, -3), -5, 0, 0);
    assert_close(AT(a, g, 5), 6, 0, 0);
    assert_close(AT(a, g, 6), 8, 0, 0);
    hj_ls_free(a);
    g = grid1(HJ_LS_BC_EXTRAP_TOWARD, 0, 0, 5);
    a = line(&g, v);
    assert_close(AT(a, g, -1), -1, 0, 0);
    assert_close(AT(a, g, 5), 2, 0, 0);
    hj_ls_free(a);
}

/* 2-D: periodic in x, Dirichlet in y; corners follow both. */
static void ghosts_2d(void **state)
{
    (void)state;
    hj_ls_grid g;
    double mn[2] = {0, 0}, mx[2] = {1, 1};
    long N[2] = {4, 3};
    hj_ls_bc bc[2] = {{HJ_LS_BC_PERIODIC, 0, 0}, {HJ_LS_BC_DIRICHLET, -1, 9}};
    assert_int_equal(hj_ls_grid_init(&g, 2, mn, mx, N, bc, NULL), HJ_OK);
    assert_int_equal(g.total, (size_t)(10 * 9));
    double *a = hj_ls_alloc(&g);
    for (long j = 0; j < 3; j++)
        for (long i = 0; i < 4; i++) {
            long ix[2] = {i, j};
            a[hj_ls_index(&g, ix)] = 10 * j + i;
        }
    hj_ls_fill_ghosts(&g, a);
    long p[2];
    p[0] = -1, p[1] = 1;
    assert_close(a[hj_ls_index(&g, p)], 13, 0, 0);
    p[0] = 5, p[1] = 2;
    assert_close(a[hj_ls_index(&g, p)], 21, 0, 0);
    p[0] = 2, p[1] = -2;
    assert_close(a[hj_ls_index(&g, p)], -1, 0, 0);
    p[0] = -3, p[1] = 4; /* corner: x first (periodic), then y overwrites */
    assert_close(a[hj_ls_index(&g, p)], 9, 0, 0);
    hj_ls_free(a);
}

/* The ghost value of every boundary condition at distance k from the
 * boundary node b (neighbour b1 inward), as fill_line has it. */
static double ghost_ref(const hj_ls_bc *bc, const double *p, ptrdiff_t s, long n, double dx, long k, int upper)
{
    const double *b = upper ? p + (n - 1) * s : p, *b1 = upper ? b - s : b + s;
    switch (bc->type) {
    case HJ_LS_BC_PERIODIC: return upper ? p[((k - 1) % n) * s] : p[((n - k % n) % n) * s];
    case HJ_LS_BC_DIRICHLET: return upper ? bc->hi : bc->lo;
    case HJ_LS_BC_NEUMANN: return *b + (double)k * dx * (upper ? bc->hi : bc->lo);
    default: {
        const double dir = bc->type == HJ_LS_BC_EXTRAP_AWAY ? 1.0 : -1.0;
        const double sg = *b > 0 ? 1.0 : (*b < 0 ? -1.0 : 0.0);
        return *b + (double)k * dir * sg * fabs(*b - *b1);
    }
    }
}

/* 3-D, a different condition per dimension: every node, ghosts and
 * corners included, holds the bits of the plain definition (every line
 * along d through the full ghosted extent of all other dimensions, d in
 * order), which the fill reaches with fewer lines; 1 and 2 threads. */
static void ghosts_3d_reference(void **state)
{
    (void)state;
    hj_ls_grid g;
    double mn[3] = {0, -1, 2}, mx[3] = {1, 1, 3};
    long N[3] = {7, 5, 6};
    hj_ls_bc bc[3] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_NEUMANN, 0.5, -2}, {HJ_LS_BC_PERIODIC, 0, 0}};
    for (int variant = 0; variant < 2; variant++) {
        if (variant) bc[0].type = HJ_LS_BC_DIRICHLET, bc[0].lo = 3, bc[0].hi = -4, bc[2].type = HJ_LS_BC_EXTRAP_TOWARD;
        assert_int_equal(hj_ls_grid_init(&g, 3, mn, mx, N, bc, NULL), HJ_OK);
        double *ref = hj_ls_alloc(&g), *a = hj_ls_alloc(&g);
        assert_non_null(ref), assert_non_null(a);
        for (size_t q = 0; q < g.total; q++) ref[q] = sin(0.37 * (double)q) + (q % 3 == 0 ? 0.0 : 0.5);
        memcpy(a, ref, sizeof(double) * g.total); /* the same stale ghosts */
        for (int d = 0; d < 3; d++) {
            const int e1 = (d + 1) % 3, e2 = (d + 2) % 3;
            for (long i1 = -HJ_LS_GHOST; i1 < g.N[e1] + HJ_LS_GHOST; i1++)
                for (long i2 = -HJ_LS_GHOST; i2 < g.N[e2] + HJ_LS_GHOST; i2++) {
                    long ix[3];
                    ix[d] = 0, ix[e1] = i1, ix[e2] = i2;
                    double *p = ref + hj_ls_index(&g, ix);
                    const ptrdiff_t s = g.stride[d];
                    for (long k = 1; k <= HJ_LS_GHOST; k++) {
                        p[-k * s] = ghost_ref(&g.bc[d], p, s, g.N[d], g.dx[d], k, 0);
                        p[(g.N[d] - 1 + k) * s] = ghost_ref(&g.bc[d], p, s, g.N[d], g.dx[d], k, 1);
                    }
                }
        }
        for (int th = 1; th <= 2; th++) {
            hj_test_threads(th);
            double *b = hj_ls_alloc(&g);
            memcpy(b, a, sizeof(double) * g.total);
            hj_ls_fill_ghosts(&g, b);
            assert_memory_equal(b, ref, sizeof(double) * g.total);
            hj_ls_free(b);
        }
        hj_test_one_thread();
        hj_ls_free(ref), hj_ls_free(a);
    }
}

/* Which ghost kind node i is: 0 interior, 1 face (one index outside), 2
 * edge or corner. */
/* 0: interior; 1: a face ghost, its distance from the face in *depth;
 * 2: an edge or corner ghost. */
static int ghost_kind(const hj_ls_grid *g, const long *i, long *depth)
{
    int out = 0;
    *depth = 0;
    for (int d = 0; d < g->dim; d++)
        if (i[d] < 0 || i[d] >= g->N[d]) out++, *depth = i[d] < 0 ? -i[d] : i[d] - g->N[d] + 1;
    return out > 1 ? 2 : out;
}

/* hj_ls_fill_ghost_faces (inside a team of 1 and 2 threads, and outside
 * a parallel region) with hj_ls_fill_row_ghosts on every row, both of
 * width w, give every face ghost within w of its face the bits of
 * hj_ls_fill_ghosts and leave the deeper layers, edges and corners alone,
 * in 3-D and 4-D, for every boundary condition and width. */
static void ghost_faces(void **state)
{
    (void)state;
    for (int dim = 3; dim <= 4; dim++)
        for (int type = HJ_LS_BC_PERIODIC; type <= HJ_LS_BC_EXTRAP_TOWARD; type++)
            for (int w = 1; w <= HJ_LS_GHOST; w++) {
                hj_ls_grid g;
                double mn[4] = {0, -1, 2, 0}, mx[4] = {1, 1, 3, 0.5};
                long N[4] = {7, 5, 6, 4};
                hj_ls_bc bc[4];
                for (int d = 0; d < 4; d++) bc[d] = (hj_ls_bc){(type + d) % (HJ_LS_BC_EXTRAP_TOWARD + 1), 0.5, -2};
                assert_int_equal(hj_ls_grid_init(&g, dim, mn, mx, N, bc, NULL), HJ_OK);
                double *ref = hj_ls_alloc(&g), *a = hj_ls_alloc(&g);
                assert_non_null(ref), assert_non_null(a);
                for (size_t q = 0; q < g.total; q++) ref[q] = sin(0.37 * (double)q) + (q % 3 == 0 ? 0.0 : 0.5);
                for (int mode = 0; mode < 3; mode++) { /* 1 thread, 2 threads, no parallel region */
                    for (size_t q = 0; q < g.total; q++) a[q] = NAN;
                    long idx[HJ_LS_MAXDIM];
                    for (size_t r = 0; r < g.rows; r++) {
                        const size_t k = hj_ls_row(&g, r, idx);
                        memcpy(a + k, ref + k, sizeof(double) * (size_t)g.N[0]);
                    }
                    if (mode == 2) hj_ls_fill_ghost_faces(&g, a, w);
                    else {
#ifdef _OPENMP
#pragma omp parallel num_threads(mode + 1)
#endif
                        hj_ls_fill_ghost_faces(&g, a, w);
                    }
                    for (size_t r = 0; r < g.rows; r++) hj_ls_fill_row_ghosts(&g, a, hj_ls_row(&g, r, idx), w);
                    if (mode == 0) hj_ls_fill_ghosts(&g, ref);
                    /* every node of the ghosted array, an odometer over -GHOST .. N + GHOST - 1 */
                    long i[HJ_LS_MAXDIM];
                    for (int d = 0; d < dim; d++) i[d] = -HJ_LS_GHOST;
                    for (size_t q = 0; q < g.total; q++) {
                        const size_t k = hj_ls_index(&g, i);
                        long depth;
                        const int kind = ghost_kind(&g, i, &depth);
                        if (kind == 0 || (kind == 1 && depth <= w)) assert_memory_equal(a + k, ref + k, sizeof(double));
                        else assert_true(isnan(a[k]));
                        for (int d = 0; d < dim; d++) {
                            if (++i[d] < g.N[d] + HJ_LS_GHOST) break;
                            i[d] = -HJ_LS_GHOST;
                        }
                    }
                }
                hj_ls_free(ref), hj_ls_free(a);
            }
}

static void coords_and_rows(void **state)
{
    (void)state;
    hj_ls_grid g;
    double mn[3] = {-1, 0, 2}, mx[3] = {1, 1, 3};
    long N[3] = {5, 3, 2};
    hj_ls_bc bc[3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    assert_int_equal(hj_ls_grid_init(&g, 3, mn, mx, N, bc, NULL), HJ_OK);
    assert_int_equal(g.rows, 6);
    long i[3];
    size_t k = hj_ls_row(&g, 4, i);
    assert_int_equal(i[1], 1);
    assert_int_equal(i[2], 1);
    assert_int_equal(k, hj_ls_index(&g, i));
    double x[3];
    hj_ls_coord(&g, i, x);
    assert_close(x[0], -1, 0, 0);
    assert_close(x[1], 0.5, 1e-15, 0);
    assert_close(x[2], 3, 1e-15, 0);
    /* init by dx moves max to the last node */
    double dx[1] = {0.3}, a = 0, b = 1;
    hj_ls_bc p = {0, 0, 0};
    assert_int_equal(hj_ls_grid_init_dx(&g, 1, &a, &b, dx, &p, NULL), HJ_OK);
    assert_int_equal(g.N[0], 4);
    assert_close(g.max[0], 0.9, 1e-15, 0);
}

static void errors(void **state)
{
    (void)state;
    hj_ls_grid g;
    hj_error err;
    double mn[8] = {0}, mx[8] = {1, 1, 1, 1, 1, 1, 1, 1};
    long N[8] = {100000, 100000, 100000, 100000, 100000, 100000, 100000, 100000};
    hj_ls_bc bc[8] = {{0, 0, 0}};
    assert_int_equal(hj_ls_grid_init(&g, 8, mn, mx, N, bc, &err), HJ_ENOMEM);
    assert_non_null(strstr(err.msg, "too large"));
    assert_int_equal(hj_ls_grid_init(&g, 0, mn, mx, N, bc, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_grid_init(&g, 9, mn, mx, N, bc, &err), HJ_EINVAL);
    long n1 = 1;
    assert_int_equal(hj_ls_grid_init(&g, 1, mn, mx, &n1, bc, &err), HJ_EINVAL);
    double bad = NAN;
    long n5 = 5;
    assert_int_equal(hj_ls_grid_init(&g, 1, &bad, mx, &n5, bc, &err), HJ_ENONFINITE);
    hj_ls_bc ub = {42, 0, 0};
    assert_int_equal(hj_ls_grid_init(&g, 1, mn, mx, &n5, &ub, &err), HJ_EINVAL);
    /* finite bounds whose spacing is not: max - min overflows, or dx
     * underflows to 0 (both were accepted, dx = inf or 0) */
    const double huge_lo = -1e308, huge_hi = 1e308, tiny = 5e-324;
    assert_int_equal(hj_ls_grid_init(&g, 1, &huge_lo, &huge_hi, &n5, bc, &err), HJ_EINVAL);
    assert_non_null(strstr(err.msg, "grid spacing"));
    assert_int_equal(hj_ls_grid_init(&g, 1, mn, &tiny, &n5, bc, &err), HJ_EINVAL);
    assert_non_null(strstr(err.msg, "grid spacing"));
    /* a subnormal spacing (1e-321 > 0) whose reciprocal is inf */
    const double sub = 1e-320;
    long n11 = 11;
    assert_int_equal(hj_ls_grid_init(&g, 1, mn, &sub, &n11, bc, &err), HJ_EINVAL);
    assert_non_null(strstr(err.msg, "grid spacing"));
    /* the smallest normal spacing is a grid */
    const double lo0 = 0, normal = 4 * DBL_MIN;
    assert_int_equal(hj_ls_grid_init(&g, 1, &lo0, &normal, &n5, bc, &err), HJ_OK);
    /* NULL arguments: an error naming the argument, not a segfault */
    assert_int_equal(hj_ls_grid_init(NULL, 1, mn, mx, &n5, bc, &err), HJ_EINVAL);
    assert_has(err.msg, "NULL");
    assert_int_equal(hj_ls_grid_init(&g, 1, NULL, mx, &n5, bc, &err), HJ_EINVAL);
    assert_has(err.msg, "min");
    assert_int_equal(hj_ls_grid_init(&g, 1, mn, NULL, &n5, bc, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_grid_init(&g, 1, mn, mx, NULL, bc, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_grid_init(&g, 1, mn, mx, &n5, NULL, &err), HJ_EINVAL);
    assert_has(err.msg, "boundary");
    assert_int_equal(hj_ls_grid_layout(&g, 1, mn, mx, NULL, bc, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_grid_init_period(&g, 1, mn, mx, NULL, bc, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_grid_init_period(&g, 1, mn, mx, &n5, NULL, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_grid_init_dx(&g, 1, mn, mx, NULL, bc, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_grid_init_dx(NULL, 1, mn, mx, mx, bc, &err), HJ_EINVAL);
    assert_null(hj_ls_alloc(NULL));
}

/* Norms of a known field: |x| on [-1, 1]. */
static double absx(const double *x, void *ctx)
{
    (void)ctx;
    return fabs(x[0]);
}

static void norms(void **state)
{
    (void)state;
    hj_ls_grid g = grid1(HJ_LS_BC_PERIODIC, 0, 0, 5);
    double *a = hj_ls_alloc(&g);
    hj_ls_fill(&g, a, absx, NULL);
    double mx, avg, rms;
    hj_ls_norms(&g, a, NULL, &mx, &avg, &rms);
    assert_close(mx, 1, 0, 0);
    assert_close(avg, 2.5 / 5, 1e-15, 0);
    assert_close(rms, sqrt((0 + 0.0625 + 0.25 + 0.5625 + 1) / 5), 1e-15, 0);
    hj_ls_free(a);
}

/* The sums of the norms are exact and rounded once: the average is the
 * correctly rounded sum of |a - b| (hj_sum_array) over the node count, the
 * same bits on 1, 2 and 3 threads, on a field whose plain row sums do
 * depend on the order (terms from 1e-300 to 1e8). */
static void norms_exact_threads(void **state)
{
    (void)state;
    hj_ls_grid g = hj_test_grid(2, 37, -1, 1, HJ_LS_BC_EXTRAP_AWAY);
    double *a = hj_ls_alloc(&g), *e = malloc(sizeof(double) * g.nodes), *e2 = malloc(sizeof(double) * g.nodes);
    long i[HJ_LS_MAXDIM];
    size_t n = 0;
    for (size_t r = 0; r < g.rows; r++) {
        const size_t k = hj_ls_row(&g, r, i);
        for (long j = 0; j < g.N[0]; j++, n++) {
            const double v = ((j * 7 + (long)r * 3) % 5 - 2) * pow(10.0, (double)((j * 13 + (long)r) % 16) - 8) +
                             (j == 3 ? 1e8 : 0) + (r == 5 ? 1e-300 : 0);
            a[k + (size_t)j] = v, e[n] = fabs(v), e2[n] = v * v;
        }
    }
    double m[3], avg[3], rms[3];
    for (int t = 1; t <= 3; t++) {
        hj_test_threads(t);
        hj_ls_norms(&g, a, NULL, &m[t - 1], &avg[t - 1], &rms[t - 1]);
    }
    hj_test_one_thread();
    double want_max = 0;
    for (size_t k = 0; k < n; k++) want_max = e[k] > want_max ? e[k] : want_max;
    const double want_avg = hj_sum_array(e, (long)n) / (double)g.nodes;
    const double want_rms = sqrt(hj_sum_array(e2, (long)n) / (double)g.nodes);
    for (int t = 0; t < 3; t++) {
        assert_memory_equal(&avg[t], &want_avg, sizeof(double));
        assert_memory_equal(&rms[t], &want_rms, sizeof(double));
        assert_true(m[t] == want_max);
    }
    free(e), free(e2), hj_ls_free(a);
}

/* Nodes where b > a, and nodes that differ in any bit (-0 from 0 too);
 * ghost nodes do not count. */
static void counts(void **state)
{
    (void)state;
    hj_ls_grid g;
    const hj_ls_bc bc = {HJ_LS_BC_PERIODIC, 0, 0};
    assert_int_equal(hj_ls_grid_init(&g, 1, (const double[]){0}, (const double[]){1}, (const long[]){6}, &bc, NULL), 0);
    double *a = hj_ls_alloc(&g), *b = hj_ls_alloc(&g);
    b[g.offset + 1] = 1, b[g.offset + 3] = -1, b[g.offset + 5] = -0.0;
    a[0] = 5;
    assert_int_equal(hj_ls_count_increase(&g, a, b), 1);
    assert_int_equal(hj_ls_count_increase(&g, b, a), 1);
    assert_int_equal(hj_ls_count_differ(&g, a, b), 3);
    assert_int_equal(hj_ls_count_differ(&g, a, a), 0);
    hj_ls_free(a), hj_ls_free(b);
}

/* The hooks of a distributed block: origin shifts the coordinates (the
 * global grid's bits), halo runs after each dimension's boundary
 * condition (it sees dimension d's ghosts filled), reduce goes through
 * hj_ls_grid_reduce, which is a no-op on an undivided grid. */
typedef struct {
    int calls[2];
    double seen_ghost; /* a ghost of dimension d when halo(d) ran */
    int width;         /* the width asked for */
} fake_dist;

static void fake_halo(const hj_ls_grid *g, double *a, int d, int width, void *ctx)
{
    fake_dist *f = ctx;
    f->calls[d]++;
    f->width = width;
    const long i[2] = {d == 0 ? -1 : 0, d == 1 ? -1 : 0};
    f->seen_ghost = a[hj_ls_index(g, i)];
    a[hj_ls_index(g, i)] = 100 + d; /* the exchange overrides the boundary condition */
}

static void fake_reduce(double *v, int n, int op, void *ctx)
{
    (void)ctx;
    for (int k = 0; k < n; k++) v[k] = op == HJ_LS_REDUCE_MAX ? 7 : -7;
}

static void dist_hooks(void **state)
{
    (void)state;
    hj_ls_grid g, w;
    const hj_ls_bc bc[2] = {{HJ_LS_BC_DIRICHLET, 5, 5}, {HJ_LS_BC_DIRICHLET, 6, 6}};
    const double lo[2] = {-1, 0.1}, hi[2] = {1, 0.7};
    assert_int_equal(hj_ls_grid_init(&g, 2, lo, hi, (const long[]){5, 7}, bc, NULL), 0);
    assert_int_equal(hj_ls_grid_init(&w, 2, lo, hi, (const long[]){5, 13}, bc, NULL), 0);
    assert_null(g.dist);
    assert_true(g.origin[0] == 0 && g.origin[1] == 0);
    double v[2] = {1, 2};
    hj_ls_grid_reduce(&g, v, 2, HJ_LS_REDUCE_MAX);
    assert_true(v[0] == 1 && v[1] == 2);
    /* g as the block of w holding w's nodes 6..12 along dimension 1: the
     * same coordinate bits as w's. */
    g.dx[1] = w.dx[1];
    g.origin[1] = 6;
    for (long j = 0; j < 7; j++) {
        double x[2], y[2];
        hj_ls_coord(&g, (const long[]){2, j}, x);
        hj_ls_coord(&w, (const long[]){2, j + 6}, y);
        assert_memory_equal(x, y, sizeof x);
    }
    fake_dist f = {{0, 0}, 0, 0};
    const hj_ls_dist dist = {fake_halo, fake_reduce, &f};
    g.dist = &dist;
    double *a = hj_ls_alloc(&g);
    assert_non_null(a);
    hj_ls_fill_ghosts(&g, a);
    assert_int_equal(f.calls[0], 1);
    assert_int_equal(f.calls[1], 1);
    assert_true(f.seen_ghost == 6); /* dimension 1's Dirichlet value was in place */
    assert_true(a[hj_ls_index(&g, (const long[]){-1, 0})] == 100);
    assert_true(a[hj_ls_index(&g, (const long[]){0, -1})] == 101);
    assert_int_equal(f.width, HJ_LS_GHOST);
    /* The width passes to the hook, clamped to 1..HJ_LS_GHOST. */
    hj_ls_fill_ghosts_width(&g, a, 2);
    assert_int_equal(f.width, 2);
    hj_ls_fill_ghosts_width(&g, a, 0);
    assert_int_equal(f.width, 1);
    hj_ls_fill_ghosts_width(&g, a, 9);
    assert_int_equal(f.width, HJ_LS_GHOST);
    hj_ls_grid_reduce(&g, v, 2, HJ_LS_REDUCE_MIN);
    assert_true(v[0] == -7 && v[1] == -7);
    hj_ls_free(a);
}

/* 64-bit sizes: a 2000 x 2000 x 1000 grid (4e9 nodes, above 2^31 and
 * 2^32) is laid out without overflow and not allocated. */
static void layout_64bit(void **state)
{
    (void)state;
    hj_ls_grid g;
    const hj_ls_bc bc[3] = {{HJ_LS_BC_DIRICHLET, 0, 0}, {HJ_LS_BC_DIRICHLET, 0, 0}, {HJ_LS_BC_DIRICHLET, 0, 0}};
    const long N[3] = {2000, 2000, 1000};
    assert_int_equal(hj_ls_grid_layout(&g, 3, (double[]){0, 0, 0}, (double[]){1, 1, 1}, N, bc, NULL), HJ_OK);
    assert_true(g.nodes == (size_t)4000000000ULL);
    assert_true(g.total == (size_t)2006 * (size_t)2006 * (size_t)1006);
    assert_true(g.rows == (size_t)2000 * 1000);
    const size_t last = hj_ls_index(&g, (long[]){1999, 1999, 999});
    const size_t e = 2006;
    assert_true(last == e * e * 1006 - 1 - (3 + 3 * e + 3 * e * e));
    long i[3];
    assert_true(hj_ls_row(&g, g.rows - 1, i) == last - 1999);
    assert_int_equal(i[1], 1999);
    assert_int_equal(i[2], 999);
}

/* A periodic dimension given by its period: N nodes per period, no node
 * at min + period; the other dimensions as hj_ls_grid_init; bad periods. */
static void period_grid(void **state)
{
    (void)state;
    hj_ls_grid g;
    hj_error err;
    const hj_ls_bc bc[2] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_PERIODIC, 0, 0}};
    const double pi2 = 6.283185307179586;
    assert_int_equal(hj_ls_grid_init_period(&g, 2, (double[]){-1, 0}, (double[]){1, pi2}, (long[]){21, 16}, bc, &err),
                     HJ_OK);
    assert_close(g.dx[0], 0.1, 1e-15, 0);
    assert_close(g.dx[1], pi2 / 16, 0, 0);
    assert_close(g.max[1], pi2 - pi2 / 16, 1e-15, 0);
    assert_close(hj_ls_grid_period(&g, 1), pi2, 1e-15, 0);
    assert_close(hj_ls_grid_period(&g, 0), 0, 0, 0);
    /* The last node's coordinate is one spacing short of the period. */
    double x[2];
    hj_ls_coord(&g, (long[]){0, 15}, x);
    assert_close(x[1], pi2 - g.dx[1], 1e-14, 0);
    assert_int_equal(hj_ls_grid_init_period(&g, 2, (double[]){-1, 1}, (double[]){1, 1}, (long[]){21, 16}, bc, &err),
                     HJ_EINVAL);
    assert_int_equal(hj_ls_grid_init_period(&g, 2, (double[]){-1, 0}, (double[]){1, NAN}, (long[]){21, 16}, bc, &err),
                     HJ_ENONFINITE);
    assert_int_equal(hj_ls_grid_init_period(&g, 9, (double[]){-1, 0}, (double[]){1, 1}, (long[]){21, 16}, bc, &err),
                     HJ_EINVAL);
}

/* A width outside 1..HJ_LS_GHOST is taken as the nearest of them by the
 * face and row fills, as by hj_ls_fill_ghosts_width: a row's fill of
 * width 6 wrote three values beyond its ghost layers, into the previous
 * row's ghosts (and a face fill beyond the array). */
static void ghost_widths_clamped(void **state)
{
    (void)state;
    hj_ls_grid g;
    double mn[2] = {0, 0}, mx[2] = {1, 1};
    long N[2] = {9, 7};
    hj_ls_bc bc[2] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_NEUMANN, 0.5, -2}};
    assert_int_equal(hj_ls_grid_init(&g, 2, mn, mx, N, bc, NULL), HJ_OK);
    double *a = hj_ls_alloc(&g), *ref = hj_ls_alloc(&g);
    assert_non_null(a), assert_non_null(ref);
    const int widths[4] = {-2, 0, 4, 6};
    for (int q = 0; q < 4; q++) {
        const int w = widths[q], wc = w < 1 ? 1 : HJ_LS_GHOST;
        for (size_t k = 0; k < g.total; k++) a[k] = ref[k] = 7;
        long idx[HJ_LS_MAXDIM];
        for (size_t r = 0; r < g.rows; r++) {
            const size_t k = hj_ls_row(&g, r, idx);
            for (long j = 0; j < g.N[0]; j++) a[k + (size_t)j] = ref[k + (size_t)j] = sin((double)(k + (size_t)j));
        }
        const size_t k2 = hj_ls_row(&g, 2, idx);
        hj_ls_fill_row_ghosts(&g, a, k2, w);
        hj_ls_fill_row_ghosts(&g, ref, k2, wc);
        assert_memory_equal(a, ref, sizeof(double) * g.total);
        hj_ls_fill_ghost_faces(&g, a, w);
        hj_ls_fill_ghost_faces(&g, ref, wc);
        assert_memory_equal(a, ref, sizeof(double) * g.total);
    }
    hj_ls_free(a), hj_ls_free(ref);
}

/* hj_ls_unpack puts an array without ghosts (dimension 0 fastest) into the
 * interior, node by node, ghosts untouched; hj_ls_pack takes it back. */
static void pack_unpack(void **state)
{
    (void)state;
    hj_ls_grid g;
    double mn[3] = {0, 0, 0}, mx[3] = {1, 1, 1};
    long N[3] = {5, 4, 3};
    hj_ls_bc bc[3] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_PERIODIC, 0, 0}, {HJ_LS_BC_DIRICHLET, 1, 2}};
    assert_int_equal(hj_ls_grid_init(&g, 3, mn, mx, N, bc, NULL), HJ_OK);
    double *a = hj_ls_alloc(&g), packed[60], back[60];
    for (size_t k = 0; k < g.total; k++) a[k] = -7;
    for (int q = 0; q < 60; q++) packed[q] = q + 0.5;
    hj_ls_unpack(&g, a, packed);
    long i[3];
    for (i[2] = 0; i[2] < 3; i[2]++)
        for (i[1] = 0; i[1] < 4; i[1]++)
            for (i[0] = 0; i[0] < 5; i[0]++)
                assert_true(a[hj_ls_index(&g, i)] == (double)(i[0] + 5 * (i[1] + 4 * i[2])) + 0.5);
    long ghost[3] = {-1, 0, 0};
    assert_true(a[hj_ls_index(&g, ghost)] == -7);
    hj_ls_pack(&g, back, a);
    assert_memory_equal(back, packed, sizeof packed);
    hj_ls_free(a);
}

HJ_TEST_MAIN("hj_ls_grid", NULL, NULL, cmocka_unit_test(dist_hooks), cmocka_unit_test(ghosts_1d), cmocka_unit_test(ghosts_2d), cmocka_unit_test(ghosts_3d_reference), cmocka_unit_test(ghost_faces), cmocka_unit_test(ghost_widths_clamped), cmocka_unit_test(pack_unpack),
             cmocka_unit_test(coords_and_rows), cmocka_unit_test(errors), cmocka_unit_test(norms), cmocka_unit_test(norms_exact_threads),
             cmocka_unit_test(counts), cmocka_unit_test(layout_64bit), cmocka_unit_test(period_grid))
