/* Unit tests of common/hj_ls_helper: the post-timestep mask, signed
 * distance by iterated reinitialization, and the k-d tree unsigned distance
 * against brute force. */
#include "hj_test.h"
#include "hj_test_ls.h"

#ifdef _OPENMP
#include <omp.h>
#endif

#include <stdlib.h>

#include "hj_ls_helper.h"
#include "hj_ls_ode.h"

/* dim dimensions of n nodes on [-1, 1], extrapolated away from zero. */
static hj_ls_grid grid(int dim, long n) { return hj_test_grid(dim, n, -1, 1, HJ_LS_BC_EXTRAP_AWAY); }

/* Normal motion outward with a mask phi >= psi (the circle may not grow
 * into the half plane x > 0.2). */
static double circle(const double *x, void *ctx)
{
    (void)ctx;
    return sqrt(x[0] * x[0] + x[1] * x[1]) - 0.3;
}
static double wall(const double *x, void *ctx)
{
    (void)ctx;
    return 0.2 - x[0];
}

static void mask_constrains(void **state)
{
    (void)state;
    hj_ls_grid g = grid(2, 41);
    double *y = hj_ls_alloc(&g), *psi = hj_ls_alloc(&g);
    hj_ls_fill(&g, y, circle, NULL);
    hj_ls_fill(&g, psi, wall, NULL);
    hj_ls_normal nm;
    hj_ls_normal_init(&nm, &g, HJ_LS_ENO2);
    nm.speed.value = 1;
    hj_ls_mask m = {&g, psi, 1};
    hj_ls_ode_opts o;
    hj_ls_ode_defaults(&o);
    o.post = hj_ls_post_mask;
    o.post_ctx = &m;
    double span[2] = {0, 0.3};
    assert_int_equal(hj_ls_ode(2, &g, &nm.base, span, 2, y, &o, NULL, NULL, NULL, NULL), HJ_OK);
    long idx[2];
    int inside_left = 0;
    for (size_t r = 0; r < g.rows; r++) {
        size_t k = hj_ls_row(&g, r, idx);
        for (long j = 0; j < g.N[0]; j++) {
            assert_true(y[k + j] >= psi[k + j]);
            inside_left += y[k + j] < 0;
        }
    }
    assert_true(inside_left > 0);
    hj_ls_free(y), hj_ls_free(psi);
}

/* phi_0 = (|x|^2 - r^2) e^{x} is not a distance; after reinitialization
 * it is |x| - r near the circle.  Reinitialization without a subcell fix
 * moves the front by O(dx) (ENO2 here: 2.7e-3, 1.9e-3, 0.9e-3 at n = 41,
 * 81, 161), so the test asks for first order over two refinements; the
 * iteration stops by its update rule before t_max. */
static double squashed(const double *x, void *ctx)
{
    (void)ctx;
    return (x[0] * x[0] + x[1] * x[1] - 0.25) * exp(x[0]);
}

static void signed_distance_iterative(void **state)
{
    (void)state;
    double err_at[2];
    for (int q = 0; q < 2; q++) {
        hj_ls_grid g = grid(2, q ? 161 : 41);
        double *y = hj_ls_alloc(&g);
        hj_ls_fill(&g, y, squashed, NULL);
        long steps;
        int conv;
        assert_int_equal(hj_ls_signed_distance(&g, y, 0, 0.05, HJ_LS_ENO2, 2, &steps, &conv, NULL), HJ_OK);
        assert_true(steps > 0);
        assert_true(conv);
        double e = 0, x[2];
        long idx[2];
        for (size_t r = 0; r < g.rows; r++) {
            size_t k = hj_ls_row(&g, r, idx);
            for (long j = 0; j < g.N[0]; j++) {
                idx[0] = j;
                hj_ls_coord(&g, idx, x);
                double d = sqrt(x[0] * x[0] + x[1] * x[1]) - 0.5;
                if (fabs(d) < 0.2) e = fabs(y[k + j] - d) > e ? fabs(y[k + j] - d) : e;
            }
        }
        err_at[q] = e;
        hj_ls_free(y);
    }
    if (!(err_at[1] < 0.5 * err_at[0]) || !(err_at[1] < 2e-3)) fail_msg("errors %.3e %.3e", err_at[0], err_at[1]);
}

/* Random clouds in 1-3 dimensions (fixed seed): tree == brute force. */
static void unsigned_distance_matches_brute_force(void **state)
{
    (void)state;
    unsigned s = 12345;
    for (int dim = 1; dim <= 3; dim++)
        for (long np = 1; np <= 200; np *= 7) {
            hj_ls_grid g = grid(dim, dim == 3 ? 17 : 33);
            double *pts = malloc(sizeof(double) * (size_t)(np * dim));
            for (long i = 0; i < np * dim; i++) {
                s = s * 1103515245u + 12345u;
                pts[i] = ((s >> 8) & 0xffff) / 32768.0 - 1.0;
            }
            if (np > 2) pts[dim] = pts[0]; /* a duplicate coordinate */
            double *a = hj_ls_alloc(&g), *b = hj_ls_alloc(&g), e;
            assert_int_equal(hj_ls_unsigned_distance(&g, pts, np, a, NULL), HJ_OK);
            assert_int_equal(hj_ls_unsigned_distance_brute(&g, pts, np, b, NULL), HJ_OK);
            hj_ls_norms(&g, a, b, &e, NULL, NULL);
            assert_close(e, 0, 0, 0);
            hj_ls_free(a), hj_ls_free(b);
            free(pts);
        }
    hj_ls_grid g = grid(2, 5);
    double *a = hj_ls_alloc(&g), p[2] = {0, NAN};
    hj_error err;
    assert_int_equal(hj_ls_unsigned_distance(&g, p, 1, a, &err), HJ_ENONFINITE);
    assert_int_equal(hj_ls_unsigned_distance(&g, p, 0, a, &err), HJ_EINVAL);
    hj_ls_free(a);
}

/* A NaN in the mask is named with its node, not left to pass into the
 * state and be reported as a blow-up; a NULL context or mask array is an
 * error, not a segfault. */
static void mask_errors(void **state)
{
    (void)state;
    hj_ls_grid g = grid(2, 21);
    double *y = hj_ls_alloc(&g), *psi = hj_ls_alloc(&g);
    hj_ls_fill(&g, y, circle, NULL);
    hj_ls_fill(&g, psi, wall, NULL);
    psi[hj_ls_index(&g, (long[]){5, 7})] = NAN;
    hj_error err;
    hj_ls_mask m = {&g, psi, 1};
    assert_int_equal(hj_ls_post_mask(0.25, y, &m, &err), HJ_ENONFINITE);
    assert_has(err.msg, "mask is NaN at x = (-0.5, -0.3)");
    hj_ls_normal nm;
    hj_ls_normal_init(&nm, &g, HJ_LS_ENO2);
    nm.speed.value = 1;
    hj_ls_ode_opts o;
    hj_ls_ode_defaults(&o);
    o.post = hj_ls_post_mask;
    o.post_ctx = &m;
    double span[2] = {0, 0.3};
    assert_int_equal(hj_ls_ode(2, &g, &nm.base, span, 2, y, &o, NULL, NULL, NULL, &err), HJ_ENONFINITE);
    assert_has(err.msg, "mask is NaN");
    assert_int_equal(hj_ls_post_mask(0, y, NULL, &err), HJ_EINVAL);
    hj_ls_mask none = {&g, NULL, 1};
    assert_int_equal(hj_ls_post_mask(0, y, &none, &err), HJ_EINVAL);
    assert_has(err.msg, "NULL");
    hj_ls_free(y), hj_ls_free(psi);
    /* every position of a row: the NaNs are counted in groups of eight
     * and a tail (rows of 5, 8 and 21 nodes, keep_max and keep_min); a
     * row with a NaN is left as it was */
    const long ns[3] = {5, 8, 21};
    for (int q = 0; q < 3; q++)
        for (long j = 0; j < ns[q]; j++)
            for (int keep = 0; keep < 2; keep++) {
                hj_ls_grid h = grid(1, ns[q]);
                double *a = hj_ls_alloc(&h), *b = hj_ls_alloc(&h);
                for (long i = 0; i < ns[q]; i++) a[h.offset + (size_t)i] = (double)i, b[h.offset + (size_t)i] = 2.0;
                b[h.offset + (size_t)j] = NAN;
                hj_ls_mask mh = {&h, b, keep};
                assert_int_equal(hj_ls_post_mask(0, a, &mh, &err), HJ_ENONFINITE);
                for (long i = 0; i < ns[q]; i++) assert_true(a[h.offset + (size_t)i] == (double)i);
                b[h.offset + (size_t)j] = 2.0;
                assert_int_equal(hj_ls_post_mask(0, a, &mh, &err), HJ_OK);
                for (long i = 0; i < ns[q]; i++)
                    assert_true(a[h.offset + (size_t)i] == (keep ? fmax((double)i, 2.0) : fmin((double)i, 2.0)));
                hj_ls_free(a), hj_ls_free(b);
            }
}

/* The distance helpers' bad arguments are errors with a message, not a
 * segfault or a silent default: a NULL grid, array or point list
 * (HJ_EINVAL naming it), and a NaN or infinite t_max or error_max of
 * hj_ls_signed_distance (NaN took the default, an infinite t_max came
 * back as "tspan[1] is not finite", an argument the caller never gave). */
static void distance_errors(void **state)
{
    (void)state;
    hj_ls_grid g = grid(2, 21);
    double *y = hj_ls_alloc(&g), *d = hj_ls_alloc(&g), p[2] = {0, 0};
    hj_ls_fill(&g, y, squashed, NULL);
    hj_error err;
    long steps = -1;
    int conv = -1;
    assert_int_equal(hj_ls_signed_distance(NULL, y, 0, 0, HJ_LS_ENO2, 2, NULL, NULL, &err), HJ_EINVAL);
    assert_has(err.msg, "grid is NULL");
    assert_int_equal(hj_ls_signed_distance(&g, NULL, 0, 0, HJ_LS_ENO2, 2, NULL, NULL, &err), HJ_EINVAL);
    assert_has(err.msg, "data is NULL");
    const double bad[3] = {NAN, INFINITY, -INFINITY};
    for (int i = 0; i < 3; i++) {
        assert_int_equal(hj_ls_signed_distance(&g, y, bad[i], 0, HJ_LS_ENO2, 2, &steps, &conv, &err), HJ_EINVAL);
        assert_has(err.msg, "t_max");
        assert_true(steps == 0 && conv == 0);
        assert_int_equal(hj_ls_signed_distance(&g, y, 0, bad[i], HJ_LS_ENO2, 2, &steps, &conv, &err), HJ_EINVAL);
        assert_has(err.msg, "error_max");
    }
    assert_int_equal(hj_ls_unsigned_distance(&g, NULL, 1, d, &err), HJ_EINVAL);
    assert_has(err.msg, "points are NULL");
    assert_int_equal(hj_ls_unsigned_distance(NULL, p, 1, d, &err), HJ_EINVAL);
    assert_has(err.msg, "grid is NULL");
    assert_int_equal(hj_ls_unsigned_distance_brute(&g, p, 1, NULL, &err), HJ_EINVAL);
    assert_has(err.msg, "output array is NULL");
    hj_ls_free(y), hj_ls_free(d);
}

HJ_TEST_MAIN_ONE_THREAD("hj_ls_helper", NULL, NULL, cmocka_unit_test(mask_constrains), cmocka_unit_test(mask_errors),
                        cmocka_unit_test(signed_distance_iterative),
                        cmocka_unit_test(unsigned_distance_matches_brute_force), cmocka_unit_test(distance_errors))
