/* Unit tests of common/hj_curve: the signed distance, foot point, normal
 * (towards the point) and curvature of a circle and of a line. */
#include "hj_test.h"

#include "hj_curve.h"

static void circle_both_sides(void **state)
{
    (void)state;
    hj_curve_circle c = {1, 2, 0.5};
    hj_curve_local L;
    assert_close(hj_curve_circle_level(1, 3, &c), 0.5, 1e-15, 0);
    assert_int_equal(hj_curve_circle_local(1, 3, &L, &c), 0); /* outside, above */
    assert_close(L.dist, 0.5, 1e-15, 0);
    assert_close(L.foot[0], 1, 1e-15, 0);
    assert_close(L.foot[1], 2.5, 1e-15, 0);
    assert_close(L.n[1], 1, 1e-15, 0);
    assert_close(L.kappa, 2, 1e-15, 0);
    assert_close(hj_curve_circle_level(1.2, 2, &c), -0.3, 1e-15, 0);
    assert_int_equal(hj_curve_circle_local(1.2, 2, &L, &c), 0); /* inside, right */
    assert_close(L.dist, 0.3, 1e-15, 0);
    assert_close(L.foot[0], 1.5, 1e-15, 0);
    assert_close(L.n[0], -1, 1e-15, 0); /* towards the point: to the centre */
    assert_close(L.kappa, -2, 1e-15, 0);
    assert_int_equal(hj_curve_circle_local(1, 2, &L, &c), -1); /* the centre */
}

static void line_both_sides(void **state)
{
    (void)state;
    hj_curve_line e = {1, -1, 1}; /* y = -1, the domain above */
    hj_curve_local L;
    assert_close(hj_curve_line_level(0.3, -0.5, &e), 0.5, 1e-15, 0);
    assert_int_equal(hj_curve_line_local(0.3, -0.5, &L, &e), 0);
    assert_close(L.dist, 0.5, 1e-15, 0);
    assert_true(L.foot[0] == 0.3 && L.foot[1] == -1);
    assert_true(L.n[0] == 0 && L.n[1] == 1 && L.kappa == 0);
    assert_int_equal(hj_curve_line_local(0.3, -1.25, &L, &e), 0); /* outside */
    assert_close(L.dist, 0.25, 1e-15, 0);
    assert_true(L.n[1] == -1);
}

HJ_TEST_MAIN("hj_curve", NULL, NULL, cmocka_unit_test(circle_both_sides), cmocka_unit_test(line_both_sides))
