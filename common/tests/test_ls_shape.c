/* Unit tests of common/hj_ls_shape: basic shapes and CSG in one, two and
 * three dimensions (the toolbox's initialConditionsTest1D/2D/3D, with the
 * values checked at chosen nodes instead of plotted). */
#include "hj_test.h"

#include <string.h>

#include "hj_ls_shape.h"

/* Grid on [-1, 1]^dim with 21 nodes (dx = 0.1). */
static hj_ls_grid grid(int dim)
{
    hj_ls_grid g;
    double mn[3] = {-1, -1, -1}, mx[3] = {1, 1, 1};
    long N[3] = {21, 21, 21};
    hj_ls_bc bc[3] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
    assert_int_equal(hj_ls_grid_init(&g, dim, mn, mx, N, bc, NULL), HJ_OK);
    return g;
}

/* Value at the node with coordinates x (multiples of 0.1). */
static double at(const hj_ls_grid *g, const double *a, const double *x)
{
    long i[3];
    for (int d = 0; d < g->dim; d++) i[d] = lround((x[d] + 1) / 0.1);
    return a[hj_ls_index(g, i)];
}

static void shapes_1d(void **state)
{
    (void)state;
    hj_ls_grid g = grid(1);
    double *s = hj_ls_alloc(&g), *r = hj_ls_alloc(&g), *o = hj_ls_alloc(&g);
    double c = 0.2, x;
    assert_int_equal(hj_ls_shape_sphere(&g, &c, 0.5, s, NULL), HJ_OK); /* interval [-0.3, 0.7] */
    x = 0.2; assert_close(at(&g, s, &x), -0.5, 1e-15, 0);
    x = -0.8; assert_close(at(&g, s, &x), 0.5, 1e-15, 0);
    double lo = -INFINITY, hi = 0; /* half line x < 0 */
    assert_int_equal(hj_ls_shape_rectangle_corners(&g, &lo, &hi, r, NULL), HJ_OK);
    x = -1; assert_close(at(&g, r, &x), -1, 1e-15, 0);
    x = 0.5; assert_close(at(&g, r, &x), 0.5, 1e-15, 0);
    hj_ls_shape_intersection(&g, s, r, o); /* [-0.3, 0) */
    x = -0.1; assert_true(at(&g, o, &x) < 0);
    x = 0.1; assert_true(at(&g, o, &x) > 0);
    x = -0.5; assert_true(at(&g, o, &x) > 0);
    hj_ls_shape_union(&g, s, r, o); /* (-inf, 0.7] */
    x = -1; assert_true(at(&g, o, &x) < 0);
    x = 0.6; assert_true(at(&g, o, &x) < 0);
    x = 0.8; assert_true(at(&g, o, &x) > 0);
    hj_ls_shape_difference(&g, s, r, o); /* [0, 0.7] */
    x = -0.1; assert_true(at(&g, o, &x) > 0);
    x = 0.3; assert_true(at(&g, o, &x) < 0);
    hj_ls_shape_complement(&g, s, o);
    x = 0.2; assert_close(at(&g, o, &x), 0.5, 1e-15, 0);
    hj_ls_free(s), hj_ls_free(r), hj_ls_free(o);
}

/* 2-D: a square subtracted from a circle (Figure 21(a)), and a polygon
 * from hyperplanes. */
static void shapes_2d(void **state)
{
    (void)state;
    hj_ls_grid g = grid(2);
    double *c = hj_ls_alloc(&g), *sq = hj_ls_alloc(&g), *o = hj_ls_alloc(&g);
    double cen[2] = {0, 0}, sc[2] = {0.5, 0.5}, w[2] = {1, 1}, x[2];
    hj_ls_shape_sphere(&g, cen, 0.8, c, NULL);
    assert_int_equal(hj_ls_shape_rectangle_center(&g, sc, w, sq, NULL), HJ_OK); /* [0,1]^2 */
    x[0] = 0.5, x[1] = 0.5; assert_close(at(&g, sq, x), -0.5, 1e-15, 0);
    x[0] = -0.3, x[1] = 0.5; assert_close(at(&g, sq, x), 0.3, 1e-15, 0);
    hj_ls_shape_difference(&g, c, sq, o);
    x[0] = 0.3, x[1] = 0.3; assert_true(at(&g, o, x) > 0); /* removed quarter */
    x[0] = -0.3, x[1] = 0.3; assert_true(at(&g, o, x) < 0);
    x[0] = 0.9, x[1] = -0.9; assert_true(at(&g, o, x) > 0); /* outside the circle */
    /* triangle x > 0, y > 0, x + y < 1 as an intersection of hyperplanes */
    double n1[2] = {-1, 0}, n2[2] = {0, -1}, n3[2] = {1, 1}, p0[2] = {0, 0}, p3[2] = {1, 0};
    double *h = hj_ls_alloc(&g);
    hj_ls_shape_hyperplane(&g, n1, p0, o, NULL);
    hj_ls_shape_hyperplane(&g, n2, p0, h, NULL);
    hj_ls_shape_intersection(&g, o, h, o);
    hj_ls_shape_hyperplane(&g, n3, p3, h, NULL);
    x[0] = 0, x[1] = 0; assert_close(at(&g, h, x), -1 / sqrt(2.0), 1e-15, 0); /* signed distance */
    hj_ls_shape_intersection(&g, o, h, o);
    x[0] = 0.2, x[1] = 0.2; assert_true(at(&g, o, x) < 0);
    x[0] = 0.6, x[1] = 0.6; assert_true(at(&g, o, x) > 0);
    x[0] = -0.1, x[1] = 0.5; assert_true(at(&g, o, x) > 0);
    /* cylinder ignoring y: the slab |x - 0.1| < 0.3 */
    int ign = 1;
    double cc[2] = {0.1, 7};
    assert_int_equal(hj_ls_shape_cylinder(&g, &ign, 1, cc, 0.3, o, NULL), HJ_OK);
    x[0] = 0.1, x[1] = -1; assert_close(at(&g, o, x), -0.3, 1e-15, 0);
    x[0] = 0.6, x[1] = 1; assert_close(at(&g, o, x), 0.2, 1e-15, 0);
    hj_ls_free(c), hj_ls_free(sq), hj_ls_free(o), hj_ls_free(h);
}

/* 3-D: union of a sphere and a cube (Figure 21(c)), an octahedron from
 * eight hyperplanes (Figure 21(d)), a vertical cylinder. */
static void shapes_3d(void **state)
{
    (void)state;
    hj_ls_grid g = grid(3);
    double *a = hj_ls_alloc(&g), *b = hj_ls_alloc(&g), *o = hj_ls_alloc(&g);
    double c1[3] = {-0.4, 0, 0}, lo[3] = {0, -0.3, -0.3}, hi[3] = {0.6, 0.3, 0.3}, x[3];
    hj_ls_shape_sphere(&g, c1, 0.4, a, NULL);
    hj_ls_shape_rectangle_corners(&g, lo, hi, b, NULL);
    hj_ls_shape_union(&g, a, b, o);
    x[0] = -0.4, x[1] = 0, x[2] = 0; assert_close(at(&g, o, x), -0.4, 1e-15, 0);
    x[0] = 0.5, x[1] = 0.2, x[2] = -0.2; assert_true(at(&g, o, x) < 0);
    x[0] = 0.5, x[1] = 0.5, x[2] = 0; assert_true(at(&g, o, x) > 0);
    /* octahedron |x| + |y| + |z| < 0.6 */
    double zero[3] = {0, 0, 0};
    for (int s = 0; s < 8; s++) {
        double n[3] = {(s & 1) ? 1 : -1, (s & 2) ? 1 : -1, (s & 4) ? 1 : -1}, p[3] = {0.6 * n[0], 0, 0};
        hj_ls_shape_hyperplane(&g, n, p, b, NULL);
        if (s == 0) memcpy(o, b, sizeof(double) * g.total);
        else hj_ls_shape_intersection(&g, o, b, o);
    }
    assert_close(at(&g, o, zero), -0.6 / sqrt(3.0), 1e-15, 0);
    x[0] = 0.2, x[1] = -0.2, x[2] = 0.1; assert_true(at(&g, o, x) < 0);
    x[0] = 0.3, x[1] = -0.2, x[2] = 0.2; assert_true(at(&g, o, x) > 0);
    int ign = 2;
    hj_ls_shape_cylinder(&g, &ign, 1, zero, 0.5, a, NULL);
    x[0] = 0.3, x[1] = 0.4, x[2] = -1; assert_close(at(&g, a, x), 0, 1e-15, 0);
    hj_ls_free(a), hj_ls_free(b), hj_ls_free(o);
}

static void errors(void **state)
{
    (void)state;
    hj_ls_grid g = grid(2);
    double *a = hj_ls_alloc(&g), c[2] = {0, 0}, lo[2] = {0, 1}, hi[2] = {1, 0}, zero[2] = {0, 0};
    hj_error err;
    assert_int_equal(hj_ls_shape_sphere(&g, c, -1, a, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_shape_rectangle_corners(&g, lo, hi, a, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_shape_hyperplane(&g, zero, c, a, &err), HJ_EINVAL);
    int ign = 2;
    assert_int_equal(hj_ls_shape_cylinder(&g, &ign, 1, c, 1, a, &err), HJ_EINVAL);
    assert_non_null(strstr(err.msg, "dimension mismatch"));
    hj_ls_free(a);
}

/* The star (13): its value at chosen points, its area against the measure
 * of its grid function, its boundary samples. */
static void star(void **state)
{
    (void)state;
    const hj_ls_star s = {0.25, 2, 7};
    const double tip[2] = {0.75, 0}, valley[2] = {-0.25, 0}, centre[2] = {0, 0};
    assert_close(hj_ls_star_fn(tip, (void *)&s), 0, 1e-15, 0);
    assert_close(hj_ls_star_fn(valley, (void *)&s), 0, 1e-15, 0); /* theta = pi: cos(7 pi) = -1 */
    assert_close(hj_ls_star_fn(centre, (void *)&s), -0.75, 1e-15, 0);
    assert_close(hj_ls_star_area(&s), 3.14159265358979323846 * 0.0625 * 4.5, 1e-15, 0);
    hj_ls_grid g = grid(2);
    double *phi = hj_ls_alloc(&g), *pts;
    assert_int_equal(hj_ls_shape_star(&g, &s, phi, NULL), HJ_OK);
    const double x[2] = {0.3, -0.4};
    assert_close(at(&g, phi, x), hj_ls_star_fn(x, (void *)&s), 1e-15, 0);
    assert_int_equal(hj_ls_shape_curve(&s, NULL, 0, 700, &pts, NULL), HJ_OK);
    for (long k = 0; k < 700; k += 37) assert_close(hj_ls_star_fn(pts + 2 * k, (void *)&s), 0, 1e-15, 0);
    free(pts);
    const double c[2] = {1, 2};
    assert_int_equal(hj_ls_shape_curve(NULL, c, 0.5, 4, &pts, NULL), HJ_OK);
    assert_close(pts[2], 1, 1e-15, 0);
    assert_close(pts[3], 2.5, 1e-15, 0);
    free(pts);
    hj_ls_grid g1 = grid(1);
    assert_int_equal(hj_ls_shape_star(&g1, &s, phi, NULL), HJ_EINVAL);
    hj_ls_free(phi);
}

/* A NaN or infinite parameter is HJ_ENONFINITE and leaves the array as
 * it was (a NaN centre used to fill it with NaN and return 0). */
static void nonfinite_parameters(void **state)
{
    (void)state;
    hj_ls_grid g = grid(2);
    double *a = hj_ls_alloc(&g), *pts = NULL;
    hj_error err;
    const double ok[2] = {0, 0}, nan_c[2] = {0, NAN}, inf_c[2] = {INFINITY, 0}, one[2] = {1, 1};
    const double lo[2] = {-0.5, -0.5}, hi[2] = {0.5, 0.5}, nan_lo[2] = {NAN, -0.5}, nan_w[2] = {1, NAN};
    assert_int_equal(hj_ls_shape_sphere(&g, nan_c, 0.5, a, &err), HJ_ENONFINITE);
    assert_non_null(strstr(err.msg, "dimension 1"));
    assert_int_equal(hj_ls_shape_sphere(&g, inf_c, 0.5, a, &err), HJ_ENONFINITE);
    assert_int_equal(hj_ls_shape_sphere(&g, ok, NAN, a, &err), HJ_ENONFINITE);
    assert_int_equal(hj_ls_shape_sphere(&g, ok, INFINITY, a, &err), HJ_ENONFINITE);
    int ign = 1; /* the centre of an ignored dimension is not used */
    assert_int_equal(hj_ls_shape_cylinder(&g, &ign, 1, nan_c, 0.5, a, &err), HJ_OK);
    ign = 0;
    assert_int_equal(hj_ls_shape_cylinder(&g, &ign, 1, nan_c, 0.5, a, &err), HJ_ENONFINITE);
    assert_int_equal(hj_ls_shape_rectangle_corners(&g, nan_lo, hi, a, &err), HJ_ENONFINITE);
    assert_int_equal(hj_ls_shape_rectangle_corners(&g, lo, nan_c, a, &err), HJ_ENONFINITE);
    assert_int_equal(hj_ls_shape_rectangle_center(&g, nan_c, one, a, &err), HJ_ENONFINITE);
    assert_int_equal(hj_ls_shape_rectangle_center(&g, inf_c, one, a, &err), HJ_ENONFINITE);
    assert_int_equal(hj_ls_shape_rectangle_center(&g, ok, nan_w, a, &err), HJ_ENONFINITE);
    assert_int_equal(hj_ls_shape_hyperplane(&g, one, nan_c, a, &err), HJ_ENONFINITE);
    assert_int_equal(hj_ls_shape_hyperplane(&g, inf_c, ok, a, &err), HJ_ENONFINITE);
    const hj_ls_star bad_star = {0.25, NAN, 7};
    assert_int_equal(hj_ls_shape_star(&g, &bad_star, a, &err), HJ_ENONFINITE);
    assert_int_equal(hj_ls_shape_curve(&bad_star, NULL, 0, 10, &pts, &err), HJ_ENONFINITE);
    assert_int_equal(hj_ls_shape_curve(NULL, nan_c, 0.5, 10, &pts, &err), HJ_ENONFINITE);
    assert_int_equal(hj_ls_shape_curve(NULL, ok, INFINITY, 10, &pts, &err), HJ_ENONFINITE);
    assert_int_equal(hj_ls_shape_curve(NULL, ok, 0.5, 0, &pts, &err), HJ_EINVAL);
    assert_null(pts);
    /* Only the cylinder call above wrote (finite values): no NaN anywhere. */
    for (size_t k = 0; k < g.total; k++) assert_false(isnan(a[k]));
    /* Infinite sides of a box stay allowed. */
    const double half_lo[2] = {-INFINITY, -0.5}, inf_w[2] = {INFINITY, 1};
    assert_int_equal(hj_ls_shape_rectangle_corners(&g, half_lo, hi, a, &err), HJ_OK);
    assert_int_equal(hj_ls_shape_rectangle_center(&g, ok, inf_w, a, &err), HJ_OK);
    hj_ls_free(a);
}

/* NULL arguments: an error naming the argument, not a segfault. */
static void null_arguments(void **state)
{
    (void)state;
    hj_ls_grid g;
    const double mn[2] = {-1, -1}, mx[2] = {1, 1}, c[2] = {0, 0}, w[2] = {1, 1};
    const long N[2] = {5, 5};
    const hj_ls_bc bc[2] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
    assert_int_equal(hj_ls_grid_init(&g, 2, mn, mx, N, bc, NULL), HJ_OK);
    double *a = hj_ls_alloc(&g);
    hj_error err;
    assert_int_equal(hj_ls_shape_sphere(&g, c, 0.5, NULL, &err), HJ_EINVAL);
    assert_has(err.msg, "output array");
    assert_int_equal(hj_ls_shape_sphere(NULL, c, 0.5, a, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_shape_sphere(&g, NULL, 0.5, a, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_shape_cylinder(&g, NULL, 1, c, 0.5, a, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_shape_rectangle_corners(&g, NULL, w, a, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_shape_rectangle_center(&g, c, NULL, a, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_shape_hyperplane(&g, w, NULL, a, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_shape_star(&g, NULL, a, &err), HJ_EINVAL);
    hj_ls_free(a);
}

HJ_TEST_MAIN("hj_ls_shape", NULL, NULL, cmocka_unit_test(shapes_1d), cmocka_unit_test(shapes_2d),
             cmocka_unit_test(shapes_3d), cmocka_unit_test(errors), cmocka_unit_test(star),
             cmocka_unit_test(nonfinite_parameters), cmocka_unit_test(null_arguments))
