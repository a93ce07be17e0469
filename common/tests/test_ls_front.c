/* Unit tests of common/hj_ls_front: errors near the front, the gradient's
 * deviation from 1, zero crossings and their distance from a curve. */
#include "hj_test.h"

#include <stdlib.h>

#include "hj_ls_front.h"
#include "hj_ls_shape.h"
#include "hj_math.h"

static hj_ls_grid grid2(long n)
{
    hj_ls_grid g;
    const double mn[2] = {-1, -1}, mx[2] = {1, 1};
    const long N[2] = {n, n};
    const hj_ls_bc bc[2] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
    assert_int_equal(hj_ls_grid_init(&g, 2, mn, mx, N, bc, NULL), HJ_OK);
    return g;
}

/* The circle of radius r about c as a signed distance on g (allocated). */
static double *circle(const hj_ls_grid *g, const double *c, double r)
{
    double *phi = hj_ls_alloc(g);
    assert_int_equal(hj_ls_shape_sphere(g, c, r, phi, NULL), HJ_OK);
    return phi;
}

/* |phi - exact| counted only within the band of exact. */
static void error_in_band(void **state)
{
    (void)state;
    const double c[2] = {0, 0};
    hj_ls_grid g = grid2(21);
    double *a = circle(&g, c, 0.5), *b = circle(&g, c, 0.5), mx, mean;
    const long far[2] = {0, 0}, near[2] = {10, 15}; /* corner, and (0, 0.5) on the circle */
    b[hj_ls_index(&g, far)] += 1;
    b[hj_ls_index(&g, near)] += 0.25;
    hj_ls_front_error(&g, b, a, 0.15, &mx, &mean);
    assert_close(mx, 0.25, 1e-15, 0);
    assert_true(mean > 0 && mean < 0.25);
    hj_ls_front_error(&g, b, a, 0, &mx, &mean); /* empty band */
    assert_true(mx == 0 && mean == 0);
    hj_ls_free(a), hj_ls_free(b);
}

/* A cone is a signed distance function away from its tip; twice the cone
 * has gradient 2. */
static void grad_deviation(void **state)
{
    (void)state;
    const double c[2] = {0, 0};
    hj_ls_grid g = grid2(41);
    double *phi = circle(&g, c, 0.5), *dist = circle(&g, c, 0.5), *work = hj_ls_alloc(&g), mean, mx;
    assert_int_equal(hj_ls_front_grad_deviation(&g, phi, phi, 0.2, work, &mean, &mx, NULL), HJ_OK);
    assert_true(mx < 0.02);
    for (size_t k = 0; k < g.total; k++) phi[k] *= 2;
    assert_int_equal(hj_ls_front_grad_deviation(&g, phi, dist, 0.2, work, &mean, &mx, NULL), HJ_OK);
    assert_close(mean, 1, 0.02, 0);
    hj_ls_free(phi), hj_ls_free(work), hj_ls_free(dist);
}

/* The crossings of a circle lie on it (to the interpolation error) and
 * their distance from the sampled circle is as small. */
static void crossings(void **state)
{
    (void)state;
    const double c[2] = {0.1, -0.05};
    hj_ls_grid g = grid2(41);
    double *phi = circle(&g, c, 0.6), *pts, *curve, mx, mean;
    long n;
    assert_int_equal(hj_ls_front_crossings(&g, phi, &pts, &n, NULL), HJ_OK);
    assert_true(n > 60);
    for (long k = 0; k < n; k++) assert_close(hypot(pts[2 * k] - c[0], pts[2 * k + 1] - c[1]), 0.6, 2e-3, 0);
    assert_int_equal(hj_ls_shape_curve(NULL, c, 0.6, 20000, &curve, NULL), HJ_OK);
    hj_ls_front_distance(pts, n, curve, 20000, &mx, &mean);
    assert_true(mx < 2e-3 && mean <= mx);
    const double on[2] = {0.7, -0.05};
    hj_ls_front_distance(on, 1, curve, 20000, &mx, &mean);
    assert_close(mx, 0, 1e-8, 0);
    free(pts), free(curve), hj_ls_free(phi);
    hj_error err;
    hj_ls_grid g1;
    const double mn = 0, mxx = 1;
    const long N = 5;
    const hj_ls_bc bc = {HJ_LS_BC_EXTRAP_AWAY, 0, 0};
    assert_int_equal(hj_ls_grid_init(&g1, 1, &mn, &mxx, &N, &bc, NULL), HJ_OK);
    assert_int_equal(hj_ls_front_crossings(&g1, NULL, &pts, &n, &err), HJ_EINVAL);
}

HJ_TEST_MAIN("hj_ls_front", NULL, NULL, cmocka_unit_test(error_in_band), cmocka_unit_test(grad_deviation),
             cmocka_unit_test(crossings))
