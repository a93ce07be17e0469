/* Unit tests of common/hj_ls_deriv: orders of accuracy of every upwind
 * scheme and of the centered approximations on smooth data, agreement of
 * the two forms of ENO3 and WENO5 to round-off, WENO5 against O&F's
 * formulas node by node, and argument errors. */
#include "hj_test.h"

#ifdef _OPENMP
#include <omp.h>
#endif

#include <stdlib.h>
#include <string.h>

#include "hj_ls_deriv.h"
#include "hj_math.h"


/* Smooth periodic test function along dimension `dir` and its derivative. */
static double f_smooth(double x) { return sin(2 * HJ_PI * x) + 0.3 * cos(4 * HJ_PI * x + 1); }
static double df_smooth(double x) { return 2 * HJ_PI * cos(2 * HJ_PI * x) - 1.2 * HJ_PI * sin(4 * HJ_PI * x + 1); }

typedef struct {
    int dir;
} dirctx;

static double field(const double *x, void *ctx) { return f_smooth(x[((dirctx *)ctx)->dir]); }

/* Periodic grid on [0, 1)^dim with n nodes per dimension. */
static void periodic_grid(hj_ls_grid *g, int dim, long n)
{
    double mn[3] = {0, 0, 0}, mx[3];
    long N[3] = {n, n, n};
    hj_ls_bc bc[3] = {{HJ_LS_BC_PERIODIC, 0, 0}, {HJ_LS_BC_PERIODIC, 0, 0}, {HJ_LS_BC_PERIODIC, 0, 0}};
    for (int d = 0; d < 3; d++) mx[d] = 1 - 1.0 / (double)n;
    assert_int_equal(hj_ls_grid_init(g, dim, mn, mx, N, bc, NULL), HJ_OK);
}

/* Max error of left and right derivatives in dimension dir. */
static double upwind_error(int scheme, int dim, int dir, long n)
{
    hj_ls_grid g;
    periodic_grid(&g, dim, n);
    double *a = hj_ls_alloc(&g), *l = hj_ls_alloc(&g), *r = hj_ls_alloc(&g), *ex = hj_ls_alloc(&g);
    dirctx c = {dir};
    hj_ls_fill(&g, a, field, &c);
    assert_int_equal(hj_ls_upwind(&g, scheme, a, dir, l, r, NULL), HJ_OK);
    double e = 0;
    long i[3];
    for (size_t row = 0; row < g.rows; row++) {
        size_t k = hj_ls_row(&g, row, i);
        for (long j = 0; j < n; j++) {
            i[0] = j;
            double x = (double)i[dir] * g.dx[dir];
            double el = fabs(l[k + j] - df_smooth(x)), er = fabs(r[k + j] - df_smooth(x));
            e = el > e ? el : e;
            e = er > e ? er : e;
        }
    }
    hj_ls_free(a), hj_ls_free(l), hj_ls_free(r), hj_ls_free(ex);
    return e;
}

/* Observed order at least the formal order minus 0.2 on smooth data.  The
 * WENO schemes are measured where they are asymptotic: WENO5 over n = 256
 * to 1024 (at n = 64..256 it shows 4.6-4.8, the known loss of the
 * Jiang-Shu weights near critical points of phi', and at n >= 4096 it hits
 * round-off); WENO3 over n = 1024 to 4096 (below it is second order, for
 * the same reason, until eps = 1e-6 dominates the smoothness indicators). */
static void smooth_orders(void **state)
{
    (void)state;
    for (int s = 0; s < HJ_LS_NSCHEMES; s++) {
        long n1 = 64, n2 = 128;
        if (s == HJ_LS_WENO5A || s == HJ_LS_WENO5B) n1 = 256, n2 = 1024;
        if (s == HJ_LS_WENO3) n1 = 1024, n2 = 4096;
        double e1 = upwind_error(s, 1, 0, n1), e2 = upwind_error(s, 1, 0, n2);
        double p = log(e1 / e2) / log((double)n2 / (double)n1);
        if (!(p > hj_ls_scheme_order(s) - 0.2))
            fail_msg("%s: observed order %.3f, formal %d (errors %.3e %.3e)", hj_ls_scheme_name(s), p,
                     hj_ls_scheme_order(s), e1, e2);
    }
}

/* The same derivative along dimension 1 of a 2-D grid (strided kernel path)
 * and dimension 2 of a 3-D grid gives exactly the 1-D errors. */
static void strided_equals_contiguous(void **state)
{
    (void)state;
    for (int s = 0; s < HJ_LS_NSCHEMES; s++) {
        double e1 = upwind_error(s, 1, 0, 32);
        assert_close(upwind_error(s, 2, 1, 32), e1, 0, 0);
        assert_close(upwind_error(s, 3, 2, 32), e1, 0, 0);
    }
}

/* Six dimensions: the derivative along the last one (3 nodes in the
 * others, 32 along it) equals the 1-D result to round-off, and the ghost layer
 * of a corner node is periodic in every dimension. */
static double last_coord(const double *x, void *ctx)
{
    (void)ctx;
    return f_smooth(x[5]) + 0.25 * x[0] * x[0] - x[2]; /* the other dims do not matter for d/dx_5 */
}

static void six_dimensions(void **state)
{
    (void)state;
    hj_ls_grid g, g1;
    double mn[6] = {0, 0, 0, 0, 0, 0}, mx[6] = {2.0 / 3, 2.0 / 3, 2.0 / 3, 2.0 / 3, 2.0 / 3, 1 - 1.0 / 32};
    long N[6] = {3, 3, 3, 3, 3, 32};
    hj_ls_bc bc[6];
    for (int d = 0; d < 6; d++) bc[d] = (hj_ls_bc){HJ_LS_BC_PERIODIC, 0, 0};
    assert_int_equal(hj_ls_grid_init(&g, 6, mn, mx, N, bc, NULL), HJ_OK);
    assert_int_equal(hj_ls_grid_init(&g1, 1, mn + 5, mx + 5, N + 5, bc, NULL), HJ_OK);
    double *a = hj_ls_alloc(&g), *l = hj_ls_alloc(&g), *r = hj_ls_alloc(&g);
    double *a1 = hj_ls_alloc(&g1), *l1 = hj_ls_alloc(&g1), *r1 = hj_ls_alloc(&g1);
    dirctx c = {0};
    hj_ls_fill(&g, a, last_coord, NULL);
    hj_ls_fill(&g1, a1, field, &c);
    assert_int_equal(hj_ls_upwind(&g, HJ_LS_WENO5A, a, 5, l, r, NULL), HJ_OK);
    assert_int_equal(hj_ls_upwind(&g1, HJ_LS_WENO5A, a1, 0, l1, r1, NULL), HJ_OK);
    long i[6] = {2, 1, 0, 2, 1, 0};
    for (long j = 0; j < 32; j++) {
        i[5] = j;
        assert_close(l[hj_ls_index(&g, i)], l1[g1.offset + (size_t)j], 1e-12, 0);
        assert_close(r[hj_ls_index(&g, i)], r1[g1.offset + (size_t)j], 1e-12, 0);
    }
    long gi[6] = {-1, 3, -2, 0, 4, 33}, wi[6] = {2, 0, 1, 0, 1, 1};
    assert_close(a[hj_ls_index(&g, gi)], a[hj_ls_index(&g, wi)], 0, 0);
    hj_ls_free(a), hj_ls_free(l), hj_ls_free(r), hj_ls_free(a1), hj_ls_free(l1), hj_ls_free(r1);
}

/* Kinked test function of firstDerivSpatialTest1 (section 2.7.2). */
static double kinked(const double *x, void *ctx)
{
    (void)ctx;
    double t = x[0];
    if (t < 0.25) return sin(2 * HJ_PI * t + HJ_PI / 2);
    if (t < 0.5) return sin(2 * HJ_PI * t - HJ_PI / 2);
    return sin(2 * HJ_PI * t) + 1;
}

static double noisy(const double *x, void *ctx)
{
    (void)ctx;
    return sin(37 * x[0]) + 0.01 * cos(1e4 * x[0] * x[0]);
}

static double max_diff(const hj_ls_grid *g, const double *a, const double *b)
{
    double m;
    hj_ls_norms(g, a, b, &m, NULL, NULL);
    return m;
}

/* ENO3a == ENO3b and WENO5a == WENO5b to round-off, on smooth, kinked and
 * rough data. */
static void forms_agree(void **state)
{
    (void)state;
    hj_ls_field_fn fs[3] = {field, kinked, noisy};
    dirctx c = {0};
    for (int k = 0; k < 3; k++) {
        hj_ls_grid g;
        periodic_grid(&g, 1, 80);
        double *a = hj_ls_alloc(&g), *l1 = hj_ls_alloc(&g), *r1 = hj_ls_alloc(&g), *l2 = hj_ls_alloc(&g),
               *r2 = hj_ls_alloc(&g);
        hj_ls_fill(&g, a, fs[k], &c);
        const int pairs[2][2] = {{HJ_LS_ENO3A, HJ_LS_ENO3B}, {HJ_LS_WENO5A, HJ_LS_WENO5B}};
        for (int q = 0; q < 2; q++) {
            hj_ls_upwind(&g, pairs[q][0], a, 0, l1, r1, NULL);
            hj_ls_upwind(&g, pairs[q][1], a, 0, l2, r2, NULL);
            double scale;
            hj_ls_norms(&g, l1, NULL, &scale, NULL, NULL);
            assert_close(max_diff(&g, l1, l2), 0, 1e-13 * scale, 0);
            assert_close(max_diff(&g, r1, r2), 0, 1e-13 * scale, 0);
        }
        hj_ls_free(a), hj_ls_free(l1), hj_ls_free(r1), hj_ls_free(l2), hj_ls_free(r2);
    }
}

/* WENO5 node by node as O&F print it, (3.28)-(3.38): v1..v5 with v1
 * farthest upwind, alpha_k = d_k / (S_k + eps)^2; eps < 0 is (3.38). */
static double weno5_reference(const double v[5], double epsg)
{
    const double c1 = v[0] / 3 - 7 * v[1] / 6 + 11 * v[2] / 6, c2 = -v[1] / 6 + 5 * v[2] / 6 + v[3] / 3,
                 c3 = v[2] / 3 + 5 * v[3] / 6 - v[4] / 6;
    const double s1 = 13.0 / 12 * pow(v[0] - 2 * v[1] + v[2], 2) + 0.25 * pow(v[0] - 4 * v[1] + 3 * v[2], 2);
    const double s2 = 13.0 / 12 * pow(v[1] - 2 * v[2] + v[3], 2) + 0.25 * pow(v[1] - v[3], 2);
    const double s3 = 13.0 / 12 * pow(v[2] - 2 * v[3] + v[4], 2) + 0.25 * pow(3 * v[2] - 4 * v[3] + v[4], 2);
    double m = 0;
    for (int k = 0; k < 5; k++) m = fmax(m, v[k] * v[k]);
    const double eps = epsg >= 0 ? epsg : 1e-6 * m + 1e-99;
    const double a1 = 0.1 / pow(s1 + eps, 2), a2 = 0.6 / pow(s2 + eps, 2), a3 = 0.3 / pow(s3 + eps, 2);
    return (a1 * c1 + a2 * c2 + a3 * c3) / (a1 + a2 + a3);
}

/* The kernels' WENO5 (both schemes; each window's weights shared by the
 * left derivative of one node and the right one of its neighbour) against
 * weno5_reference at every node, along the row and across rows, both
 * sides and the upwind side only, with the local and a given epsilon: to
 * round-off on smooth, kinked, rough and partly flat data. */
static double rough_flat(const double *x, void *ctx)
{
    (void)ctx;
    return x[0] < 0.3 ? 0.25 : noisy(x, NULL) + (x[0] > 0.7 ? 3 : 0);
}

static void weno5_against_reference(void **state)
{
    (void)state;
    hj_ls_field_fn fs[4] = {field, kinked, noisy, rough_flat};
    dirctx c = {0};
    const long sizes[3] = {7, 16, 53};
    for (int f = 0; f < 4; f++)
        for (int si = 0; si < 3; si++) {
            const long n = sizes[si], S = n + 1;
            const double dx = 1.0 / (double)n;
            double *p = malloc(sizeof(double) * (size_t)(n + 6)), *q = malloc(sizeof(double) * (size_t)(7 * S));
            double *w = malloc(sizeof(double) * HJ_LS_ROW_WORK * (size_t)n), *v = malloc(sizeof(double) * (size_t)n);
            double *dl = malloc(sizeof(double) * (size_t)n), *dr = malloc(sizeof(double) * (size_t)n),
                   *out = malloc(sizeof(double) * (size_t)n);
            double big = 0;
            for (long i = -3; i < n + 3; i++) {
                const double x = (double)i * dx;
                p[i + 3] = fs[f](&x, &c);
            }
            for (int k = -3; k <= 3; k++) /* the same values across rows: q[(k + 3) S + i] = p at i + k */
                for (long i = 0; i < n; i++) q[(k + 3) * S + i] = p[i + k + 3];
            for (long i = 0; i < n + 5; i++) big = fmax(big, fabs((p[i + 1] - p[i]) / dx));
            for (long i = 0; i < n; i++) v[i] = i % 2 ? 1 : -1;
            for (int e = 0; e < 2; e++) {
                const double epsg = e ? 1e-6 * big * big + 1e-99 : -1;
                for (int sch = HJ_LS_WENO5A; sch <= HJ_LS_WENO5B; sch++)
                    for (int across = 0; across < 2; across++) {
                        const double *row = across ? q + 3 * S : p + 3;
                        const ptrdiff_t st = across ? S : 1;
                        hj_ls_upwind_row_eps(sch, row, st, n, dx, epsg, dl, dr, w);
                        hj_ls_upwind_row_select_eps(sch, row, st, n, dx, epsg, v, out, w);
                        for (long i = 0; i < n; i++) {
                            double vl[5], vr[5]; /* D1_{i-5/2}..D1_{i+3/2}, D1_{i+5/2}..D1_{i-3/2} */
                            for (int k = 0; k < 5; k++) {
                                vl[k] = (p[i + k + 1] - p[i + k]) / dx;
                                vr[k] = (p[i + 6 - k] - p[i + 5 - k]) / dx;
                            }
                            const double L = weno5_reference(vl, epsg), R = weno5_reference(vr, epsg);
                            assert_close(dl[i], L, 1e-13 * big, 0);
                            assert_close(dr[i], R, 1e-13 * big, 0);
                            assert_close(out[i], v[i] > 0 ? L : R, 1e-13 * big, 0);
                        }
                    }
            }
            free(p), free(q), free(w), free(v), free(dl), free(dr), free(out);
        }
}

/* hj_ls_upwind_row_select (the upwind side only, as convection uses it)
 * gives bitwise the values of the two-sided kernel, for every scheme, along
 * the row (stride 1) and across rows, with velocities of both signs. */
static double mixed(const double *x, void *ctx)
{
    (void)ctx;
    return kinked(x, NULL) * cos(3 * x[1]) + noisy(x, NULL) * x[1];
}

static void select_equals_two_sided(void **state)
{
    (void)state;
    hj_ls_grid g;
    periodic_grid(&g, 2, 24);
    double *a = hj_ls_alloc(&g);
    hj_ls_fill(&g, a, mixed, NULL);
    hj_ls_fill_ghosts(&g, a);
    const long n = g.N[0];
    double *w = malloc(sizeof(double) * HJ_LS_ROW_WORK * (size_t)n), *dl = malloc(sizeof(double) * (size_t)n),
           *dr = malloc(sizeof(double) * (size_t)n), *out = malloc(sizeof(double) * (size_t)n),
           *v = malloc(sizeof(double) * (size_t)n);
    for (long j = 0; j < n; j++) v[j] = (j % 3 == 0) ? -1.5 : (j % 3 == 1 ? 2.0 : 0.0);
    long idx[2];
    for (int s = 0; s < HJ_LS_NSCHEMES; s++)
        for (int d = 0; d < 2; d++)
            for (size_t r = 0; r < g.rows; r++) {
                const double *p = a + hj_ls_row(&g, r, idx);
                hj_ls_upwind_row(s, p, g.stride[d], n, g.dx[d], dl, dr, w);
                hj_ls_upwind_row_select(s, p, g.stride[d], n, g.dx[d], v, out, w);
                for (long j = 0; j < n; j++) {
                    const double want = v[j] > 0 ? dl[j] : dr[j];
                    if (memcmp(&want, &out[j], sizeof want))
                        fail_msg("%s, dim %d, row %zu, node %ld: %.17g != %.17g", hj_ls_scheme_name(s), d, r, j,
                                 out[j], want);
                }
            }
    free(w), free(dl), free(dr), free(out), free(v);
    hj_ls_free(a);
}

/* WENO5 over consecutive rows (hj_ls_weno5_diffs_next_eps): a row's
 * right derivative and the next row's left one from one window, the same
 * bits as hj_ls_upwind_diffs_eps row by row; other schemes decline. */
static void weno5_next_rows_bitwise(void **state)
{
    (void)state;
    const long n = 13;
    double *E[7], *out[6];
    for (int k = 0; k < 7; k++) {
        E[k] = malloc(sizeof(double) * (size_t)n);
        for (long i = 0; i < n; i++) {
            const double x = 0.07 * (double)(i + 3 * k);
            E[k][i] = noisy(&x, NULL) + (k == 3 && i == 5 ? 2.0 : 0.0); /* a kink */
        }
    }
    for (int k = 0; k < 6; k++) out[k] = malloc(sizeof(double) * (size_t)n);
    double *next0 = malloc(sizeof(double) * (size_t)n), *next1 = malloc(sizeof(double) * (size_t)n);
    for (int s = 0; s < HJ_LS_NSCHEMES; s++)
        for (int mean = 0; mean < 2; mean++)
            for (int e = 0; e < 2; e++) {
                const double eps = e ? 3e-4 : -1;
                const double *A[6] = {E[0], E[1], E[2], E[3], E[4], E[5]};
                const double *B[6] = {E[1], E[2], E[3], E[4], E[5], E[6]};
                const int done = hj_ls_weno5_diffs_next_eps(s, A, n, eps, mean, NULL, next0, out[0], out[1]);
                assert_int_equal(done, s == HJ_LS_WENO5A || s == HJ_LS_WENO5B);
                if (!done) continue;
                hj_ls_weno5_diffs_next_eps(s, B, n, eps, mean, next0, next1, out[2], out[3]);
                hj_ls_upwind_diffs_eps(s, A, n, eps, mean, out[4], out[5]);
                assert_memory_equal(out[0], out[4], sizeof(double) * (size_t)n);
                assert_memory_equal(out[1], out[5], sizeof(double) * (size_t)n);
                hj_ls_upwind_diffs_eps(s, B, n, eps, mean, out[4], out[5]);
                assert_memory_equal(out[2], out[4], sizeof(double) * (size_t)n);
                assert_memory_equal(out[3], out[5], sizeof(double) * (size_t)n);
            }
    for (int k = 0; k < 7; k++) free(E[k]);
    for (int k = 0; k < 6; k++) free(out[k]);
    free(next0), free(next1);
}

/* The 2-D WENO5 transport (hj_ls_weno5_transport2_eps) gives the bits of
 * (0 - v0 W0) - v1 W1 with W_d from hj_ls_upwind_select_diffs_eps, for
 * velocities of both signs and zeros node by node, of one sign over the
 * whole row (left; right with zeros), of one sign over the first block
 * only, local and given epsilons, one dimension without flow, on rows
 * shorter than, not a multiple of and a multiple of a vector block; it
 * declines other schemes and no flow. */
static void weno5_transport2_bitwise(void **state)
{
    (void)state;
    const long sizes[3] = {5, 13, 16}, nmax = 16;
    double *E[12], *v[2], *W[2], *out = malloc(sizeof(double) * (size_t)nmax);
    for (int k = 0; k < 12; k++) {
        E[k] = malloc(sizeof(double) * (size_t)nmax);
        for (long i = 0; i < nmax; i++) {
            const double x = 0.09 * (double)(i + 2 * k) - 0.4;
            E[k][i] = noisy(&x, NULL) + (k == 8 && i == 6 ? -1.5 : 0.0); /* a kink */
        }
    }
    for (int d = 0; d < 2; d++)
        v[d] = malloc(sizeof(double) * (size_t)nmax), W[d] = malloc(sizeof(double) * (size_t)nmax);
    const double *D[2][6] = {{E[0], E[1], E[2], E[3], E[4], E[5]}, {E[6], E[7], E[8], E[9], E[10], E[11]}};
    for (int pat = 0; pat < 3; pat++) {
        for (int d = 0; d < 2; d++)
            for (long i = 0; i < nmax; i++) {
                const double mixed = (i + d) % 4 == 0 ? -0.8 : (i + d) % 4 == 1 ? 0.0 : 1.1 + 0.1 * (double)i;
                const double one = d == 0 ? 0.3 + 0.1 * (double)i : (i % 3 ? -0.6 : 0.0);
                v[d][i] = pat == 0 ? mixed : pat == 1 ? one : i < 8 ? one : -mixed;
            }
        for (int s = 0; s < HJ_LS_NSCHEMES; s++)
            for (int z = 0; z < 3; z++)
                for (int e = 0; e < 3; e++)
                    for (int q = 0; q < 4; q++) {
                        const long n = sizes[z];
                        const double eps[2] = {e == 1 ? 2e-4 : -1, e == 2 ? 5e-3 : -1};
                        const double *u0 = q & 1 ? NULL : v[0], *u1 = q & 2 ? NULL : v[1];
                        const int done = hj_ls_weno5_transport2_eps(s, D[0], D[1], n, eps, u0, u1, out);
                        assert_int_equal(done, (s == HJ_LS_WENO5A || s == HJ_LS_WENO5B) && q != 3);
                        if (!done) continue;
                        for (int d = 0; d < 2; d++) hj_ls_upwind_select_diffs_eps(s, D[d], n, eps[d], v[d], W[d]);
                        for (long i = 0; i < n; i++) {
                            double want = 0;
                            if (u0) want = 0.0 - v[0][i] * W[0][i];
                            if (u1) want = (u0 ? want : 0.0) - v[1][i] * W[1][i];
                            if (memcmp(&want, &out[i], sizeof want))
                                fail_msg("%s, velocities %d, n %ld, eps %d, flows %d, node %ld: %.17g != %.17g",
                                         hj_ls_scheme_name(s), pat, n, e, q, i, out[i], want);
                        }
                    }
    }
    for (int k = 0; k < 12; k++) free(E[k]);
    for (int d = 0; d < 2; d++) free(v[d]), free(W[d]);
    free(out);
}

/* The row kernel's forms give the same bits: along the row (stride 1,
 * where the six rows of differences are one row read at six offsets) and
 * across rows (the same values laid out with a stride), the mean and
 * difference form against (D- + D+)/2 and D+ - D-, that form for every
 * dimension in one call, and the form from given rows of differences; rows
 * of 2 nodes, shorter than, not a multiple of, and a multiple of a vector
 * block; O&F's WENO5 epsilon and a given one. */
static void kernel_forms_bitwise(void **state)
{
    (void)state;
    const long sizes[4] = {2, 5, 13, 16};
    for (int si = 0; si < 8; si++) {
        const double eps = si % 2 ? 3e-4 : -1; /* O&F's WENO5 epsilon, or one given */
        const long n = sizes[si / 2], S = n + 6;
        const double dx = 0.03;
        double *c = malloc(sizeof(double) * (size_t)(n + 6)), *q = malloc(sizeof(double) * (size_t)(7 * S));
        double *w = malloc(sizeof(double) * HJ_LS_ROW_WORK * (size_t)n), *out[8], *D[6];
        for (int k = 0; k < 8; k++) out[k] = malloc(sizeof(double) * (size_t)n);
        for (int k = 0; k < 6; k++) D[k] = malloc(sizeof(double) * (size_t)n);
        for (long i = -3; i < n + 3; i++) {
            const double x = (double)i * dx;
            c[i + 3] = noisy(&x, NULL) + kinked(&(double){x + 0.2}, NULL);
        }
        /* q: row k + 3 holds node i's neighbour at offset k (i + k) */
        for (int k = -3; k <= 3; k++)
            for (long i = 0; i < n; i++) q[(k + 3) * S + i] = c[i + k + 3];
        /* and row 3 with its three neighbours each side along stride 1 (in
         * the gaps between the rows) */
        for (long i = -3; i < n + 3; i++) q[3 * S + i] = c[i + 3];
        for (int s = 0; s < HJ_LS_NSCHEMES; s++) {
            double *l1 = out[0], *r1 = out[1], *l2 = out[2], *r2 = out[3], *m = out[4], *df = out[5];
            hj_ls_upwind_row_eps(s, c + 3, 1, n, dx, eps, l1, r1, w);
            hj_ls_upwind_row_eps(s, q + 3 * S, S, n, dx, eps, l2, r2, w);
            assert_memory_equal(l1, l2, sizeof(double) * (size_t)n);
            assert_memory_equal(r1, r2, sizeof(double) * (size_t)n);
            for (int stride = 0; stride < 2; stride++) {
                if (stride) hj_ls_upwind_row_mean_eps(s, q + 3 * S, S, n, dx, eps, m, df, w);
                else hj_ls_upwind_row_mean_eps(s, c + 3, 1, n, dx, eps, m, df, w);
                for (long i = 0; i < n; i++) {
                    const double want_m = 0.5 * (l1[i] + r1[i]), want_d = r1[i] - l1[i];
                    assert_memory_equal(&m[i], &want_m, sizeof want_m);
                    assert_memory_equal(&df[i], &want_d, sizeof want_d);
                }
            }
            /* every dimension in one call (first order, ENO2): 2 and 3
             * dimensions of stride S, or the first of stride 1 (along the
             * row), each the single call's */
            for (int dim = 2; dim <= 3; dim++)
                for (int along = 0; along < 2; along++) {
                    const ptrdiff_t st[3] = {along ? 1 : S, S, S};
                    const double h[3] = {dx, dx, dx}, hinv[3] = {1.0 / dx, 1.0 / dx, 1.0 / dx};
                    double *ms = malloc(sizeof(double) * 3 * (size_t)n), *ds = malloc(sizeof(double) * 3 * (size_t)n);
                    const int done = hj_ls_upwind_rows_mean(s, q + 3 * S, st, dim, n, h, hinv, ms, ds);
                    assert_int_equal(done, s == HJ_LS_UPWIND_FIRST || s == HJ_LS_ENO2);
                    for (int d = 0; done && d < dim; d++) {
                        assert_memory_equal(ms + d * n, m, sizeof(double) * (size_t)n);
                        assert_memory_equal(ds + d * n, df, sizeof(double) * (size_t)n);
                    }
                    free(ms), free(ds);
                }
            if (s == HJ_LS_UPWIND_FIRST || s == HJ_LS_ENO2) continue;
            for (int k = 0; k < 6; k++) hj_ls_upwind_difference_row(q + 3 * S, S, n, dx, k - 3, D[k]);
            hj_ls_upwind_diffs_eps(s, (const double *const *)D, n, eps, 0, l2, r2);
            assert_memory_equal(l1, l2, sizeof(double) * (size_t)n);
            assert_memory_equal(r1, r2, sizeof(double) * (size_t)n);
            hj_ls_upwind_diffs_eps(s, (const double *const *)D, n, eps, 1, m, df);
            for (long i = 0; i < n; i++) {
                const double want_m = 0.5 * (l1[i] + r1[i]), want_d = r1[i] - l1[i];
                assert_memory_equal(&m[i], &want_m, sizeof want_m);
                assert_memory_equal(&df[i], &want_d, sizeof want_d);
            }
        }
        for (int k = 0; k < 8; k++) free(out[k]);
        for (int k = 0; k < 6; k++) free(D[k]);
        free(c), free(q), free(w);
    }
}

/* hj_ls_upwind_rows_mean_block: a block of rows that follow each other
 * along dimension 1 gives, row by row, the bits of one
 * hj_ls_upwind_rows_mean call per row, at the block's offsets (row b of
 * dimension d at d nrows n + b n); 0 and nothing written for the other
 * schemes. */
static void rows_mean_block_bitwise(void **state)
{
    (void)state;
    const long n = 13, nrows = 5;
    const ptrdiff_t s1 = n + 8, s2 = s1 * (nrows + 8);
    const size_t len = (size_t)s2 * 9;
    double *v = malloc(sizeof(double) * len);
    unsigned seed = 7;
    for (size_t k = 0; k < len; k++) seed = seed * 1103515245u + 12345u, v[k] = (double)(seed >> 8) / 16777216.0 - 0.5;
    const double *p = v + 4 * s2 + 4 * s1 + 4; /* room for the stencils on every side */
    const ptrdiff_t st[3] = {1, s1, s2};
    const double h[3] = {0.3, 0.7, 0.11}, hinv[3] = {1 / 0.3, 1 / 0.7, 1 / 0.11};
    const size_t bn = (size_t)nrows * (size_t)n;
    double *mb = malloc(sizeof(double) * 3 * bn), *db = malloc(sizeof(double) * 3 * bn);
    double m1[3 * 13], d1[3 * 13];
    for (int dim = 2; dim <= 3; dim++)
        for (int sc = 0; sc < HJ_LS_NSCHEMES; sc++) {
            for (size_t k = 0; k < 3 * bn; k++) mb[k] = db[k] = -7;
            const int done = hj_ls_upwind_rows_mean_block(sc, p, st, dim, n, nrows, h, hinv, mb, db);
            assert_int_equal(done, sc == HJ_LS_UPWIND_FIRST || sc == HJ_LS_ENO2);
            if (!done) {
                for (size_t k = 0; k < 3 * bn; k++) assert_true(mb[k] == -7 && db[k] == -7);
                continue;
            }
            for (long b = 0; b < nrows; b++) {
                assert_int_equal(hj_ls_upwind_rows_mean(sc, p + b * s1, st, dim, n, h, hinv, m1, d1), 1);
                for (int d = 0; d < dim; d++) {
                    assert_memory_equal(mb + (size_t)d * bn + (size_t)b * (size_t)n, m1 + d * n, sizeof(double) * (size_t)n);
                    assert_memory_equal(db + (size_t)d * bn + (size_t)b * (size_t)n, d1 + d * n, sizeof(double) * (size_t)n);
                }
            }
        }
    free(mb), free(db), free(v);
}

/* Centered derivatives of phi = sin(2 pi x) cos(2 pi y) + x y^2 on a 2-D
 * periodic grid: second order for the first derivative, the Hessian and the
 * Laplacian. */
static double f2(const double *x, void *ctx)
{
    (void)ctx;
    return sin(2 * HJ_PI * x[0]) * cos(2 * HJ_PI * x[1]);
}

static void centered_orders(void **state)
{
    (void)state;
    double err[2][4];
    for (int m = 0; m < 2; m++) {
        hj_ls_grid g;
        periodic_grid(&g, 2, 32 << m);
        double *a = hj_ls_alloc(&g), *o = hj_ls_alloc(&g), *ex = hj_ls_alloc(&g);
        hj_ls_fill(&g, a, f2, NULL);
        long i[2];
        double x[2];
        /* exact values, one kind at a time */
        for (int kind = 0; kind < 4; kind++) {
            for (size_t r = 0; r < g.rows; r++) {
                size_t k = hj_ls_row(&g, r, i);
                for (long j = 0; j < g.N[0]; j++) {
                    i[0] = j;
                    hj_ls_coord(&g, i, x);
                    double sx = sin(2 * HJ_PI * x[0]), cx = cos(2 * HJ_PI * x[0]);
                    double sy = sin(2 * HJ_PI * x[1]), cy = cos(2 * HJ_PI * x[1]), w = 2 * HJ_PI;
                    ex[k + j] = kind == 0 ? w * cx * cy : kind == 1 ? -w * w * sx * cy
                              : kind == 2 ? -w * w * cx * sy : -2 * w * w * sx * cy;
                }
            }
            if (kind == 0) hj_ls_centered_first(&g, a, 0, o, NULL);
            if (kind == 1) hj_ls_hessian(&g, a, 0, 0, o, NULL);
            if (kind == 2) hj_ls_hessian(&g, a, 1, 0, o, NULL);
            if (kind == 3) hj_ls_laplacian(&g, a, o, NULL);
            err[m][kind] = max_diff(&g, o, ex);
        }
        hj_ls_free(a), hj_ls_free(o), hj_ls_free(ex);
    }
    for (int kind = 0; kind < 4; kind++) {
        double p = log(err[0][kind] / err[1][kind]) / log(2.0);
        if (!(p > 1.9 && p < 2.1)) fail_msg("centered kind %d: order %.3f", kind, p);
    }
}

/* Curvature of phi = |x| - 0.5 (signed distance to a circle / sphere):
 * kappa = (dim - 1) / |x| and |grad phi| = 1, second order away from 0. */
static double sphere(const double *x, void *ctx)
{
    int dim = *(int *)ctx;
    double s = 0;
    for (int d = 0; d < dim; d++) s += x[d] * x[d];
    return sqrt(s) - 0.5;
}

static double curvature_error(int dim, long n, double *gerr)
{
    hj_ls_grid g;
    double mn[3] = {-1, -1, -1}, mx[3] = {1, 1, 1};
    long N[3] = {n, n, n};
    hj_ls_bc bc[3] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
    hj_ls_grid_init(&g, dim, mn, mx, N, bc, NULL);
    double *a = hj_ls_alloc(&g), *k = hj_ls_alloc(&g), *m = hj_ls_alloc(&g);
    hj_ls_fill(&g, a, sphere, &dim);
    hj_ls_curvature(&g, a, k, m, NULL);
    double e = 0, ge = 0;
    long i[3];
    double x[3];
    for (size_t r = 0; r < g.rows; r++) {
        size_t b = hj_ls_row(&g, r, i);
        for (long j = 0; j < n; j++) {
            i[0] = j;
            hj_ls_coord(&g, i, x);
            double rad = 0;
            for (int d = 0; d < dim; d++) rad += x[d] * x[d];
            rad = sqrt(rad);
            if (rad < 0.4 || rad > 0.6) continue; /* a band around the circle */
            double ek = fabs(k[b + j] - (dim - 1) / rad), eg = fabs(m[b + j] - 1);
            e = ek > e ? ek : e;
            ge = eg > ge ? eg : ge;
        }
    }
    hj_ls_free(a), hj_ls_free(k), hj_ls_free(m);
    *gerr = ge;
    return e;
}

static void curvature_order(void **state)
{
    (void)state;
    for (int dim = 2; dim <= 3; dim++) {
        double g1, g2;
        double e1 = curvature_error(dim, 41, &g1), e2 = curvature_error(dim, 81, &g2);
        double p = log(e1 / e2) / log(80.0 / 40.0), pg = log(g1 / g2) / log(2.0);
        if (!(p > 1.8) || !(pg > 1.8)) fail_msg("dim %d: curvature order %.3f, |grad| order %.3f", dim, p, pg);
    }
}

static void bad_arguments(void **state)
{
    (void)state;
    hj_ls_grid g;
    periodic_grid(&g, 2, 8);
    double *a = hj_ls_alloc(&g);
    hj_error err;
    assert_int_equal(hj_ls_upwind(&g, HJ_LS_WENO5A, a, 2, a, a, &err), HJ_EINVAL);
    assert_non_null(strstr(err.msg, "dimension mismatch"));
    assert_int_equal(hj_ls_upwind(&g, 99, a, 0, a, a, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_hessian(&g, a, 0, -1, a, &err), HJ_EINVAL);
    assert_null(hj_ls_scheme_name(HJ_LS_NSCHEMES));
    hj_ls_free(a);
}

/* |grad phi| of a linear function is exact at the nodes off the boundary. */
static void gradient_norm(void **state)
{
    (void)state;
    hj_ls_grid g;
    const double mn[2] = {-1, -1}, mx[2] = {1, 1};
    const long N[2] = {11, 11};
    const hj_ls_bc bc[2] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
    assert_int_equal(hj_ls_grid_init(&g, 2, mn, mx, N, bc, NULL), HJ_OK);
    double *phi = hj_ls_alloc(&g), *work = hj_ls_alloc(&g), *out = hj_ls_alloc(&g);
    for (size_t r = 0; r < g.rows; r++) {
        long i[2] = {0, 0};
        const size_t k = hj_ls_row(&g, r, i);
        for (long j = 0; j < 11; j++)
            phi[k + (size_t)j] = 3 * (-1 + 0.2 * (double)j) - 4 * (-1 + 0.2 * (double)i[1]) + 10;
    }
    assert_int_equal(hj_ls_gradient_norm(&g, phi, work, out, NULL), HJ_OK);
    for (size_t r = 0; r < g.rows; r++) {
        long i[2] = {0, 0};
        const size_t k = hj_ls_row(&g, r, i);
        for (long j = 1; j < 10 && i[1] > 0 && i[1] < 10; j++) assert_close(out[k + (size_t)j], 5, 1e-12, 0);
    }
    hj_ls_free(phi), hj_ls_free(work), hj_ls_free(out);
}

/* A caller's WENO5 epsilon far below the data's scale, 0 included: the
 * weights' products overflowed (NaN at every node); now the floor of
 * 1e-60 times the window's largest square holds them, and the values
 * are those of eps = 1e-40 to round-off. */
static void weno5_tiny_eps(void **state)
{
    (void)state;
    enum { N = 34 };
    double buf[N + 6], ref[2][N], dl[N], dr[N], w[4 * N + 64];
    for (int i = 0; i < N + 6; i++) buf[i] = sin(0.3 * (i - 3)) + (i > 20 ? 1 : 0);
    const double eps[3] = {0, 1e-80, 1e-200};
    for (int sch = HJ_LS_WENO5A; sch <= HJ_LS_WENO5B; sch++) {
        hj_ls_upwind_row_eps(sch, buf + 3, 1, N, 0.1, 1e-40, ref[0], ref[1], w);
        for (int e = 0; e < 3; e++) {
            hj_ls_upwind_row_eps(sch, buf + 3, 1, N, 0.1, eps[e], dl, dr, w);
            for (int i = 0; i < N; i++) {
                if (!(fabs(dl[i] - ref[0][i]) <= 1e-13 && fabs(dr[i] - ref[1][i]) <= 1e-13))
                    fail_msg("scheme %d eps %g node %d: %g %g against %g %g", sch, eps[e], i, dl[i], dr[i],
                             ref[0][i], ref[1][i]);
            }
        }
    }
}

HJ_TEST_MAIN_ONE_THREAD("hj_ls_deriv", NULL, NULL, cmocka_unit_test(smooth_orders),
                        cmocka_unit_test(strided_equals_contiguous), cmocka_unit_test(six_dimensions),
                        cmocka_unit_test(forms_agree), cmocka_unit_test(weno5_against_reference),
                        cmocka_unit_test(select_equals_two_sided),
                        cmocka_unit_test(kernel_forms_bitwise),
                        cmocka_unit_test(weno5_next_rows_bitwise), cmocka_unit_test(weno5_transport2_bitwise),
                        cmocka_unit_test(centered_orders), cmocka_unit_test(curvature_order),
                        cmocka_unit_test(rows_mean_block_bitwise),
                        cmocka_unit_test(bad_arguments), cmocka_unit_test(gradient_norm),
                        cmocka_unit_test(weno5_tiny_eps))
