/* Unit tests of common/hj_fit: pairwise orders and the Ceres order fit. */
#include "hj_test.h"

#include <stdlib.h>

#include "hj_fit.h"

static void pair_order(void **state)
{
    (void)state;
    assert_close(hj_pair_order(0.1, 1e-3, 0.05, 1.25e-4), 3.0, 1e-12, 0);
    assert_true(isnan(hj_pair_order(0.1, 0, 0.05, 1e-4)));
    assert_true(isnan(hj_pair_order(0.1, 1e-3, 0.1, 1e-4)));
}

/* Exact power law: the fit returns p and C exactly and a zero error. */
static void exact_power_law(void **state)
{
    (void)state;
    double h[5], e[5];
    for (int k = 0; k < 5; k++) {
        h[k] = 0.1 / (1 << k);
        e[k] = 7.0 * pow(h[k], 2.5);
    }
    hj_order_fit f;
    hj_error err;
    assert_int_equal(hj_fit_order(h, e, 5, &f, &err), HJ_OK);
    assert_close(f.p, 2.5, 1e-6, 0);
    assert_close(f.C, 7.0, 0, 1e-5);
    assert_close(f.p_se, 0.0, 1e-6, 0);
    assert_int_equal(f.n, 5);
}

/* One pre-asymptotic point far off the line pulls the least-squares slope
 * much more than the robust one. */
static void robust_to_one_outlier(void **state)
{
    (void)state;
    double h[6], e[6];
    for (int k = 0; k < 6; k++) {
        h[k] = 0.1 / (1 << k);
        e[k] = pow(h[k], 3.0) * (1 + 0.01 * ((k % 2) ? 1 : -1));
    }
    e[0] *= 20; /* coarsest point: pre-asymptotic */
    hj_order_fit f;
    assert_int_equal(hj_fit_order(h, e, 6, &f, NULL), HJ_OK);
    assert_true(fabs(f.p - 3.0) < 0.5 * fabs(f.p_ls - 3.0));
    assert_true(fabs(f.p - 3.0) < 0.2);
    assert_true(f.p_se > 0);
}

static void two_points_no_error_bar(void **state)
{
    (void)state;
    double h[2] = {0.1, 0.05}, e[2] = {1e-3, 1.25e-4};
    hj_order_fit f;
    assert_int_equal(hj_fit_order(h, e, 2, &f, NULL), HJ_OK);
    assert_close(f.p, 3.0, 1e-6, 0);
    assert_true(isnan(f.p_se));
}

/* Points that scatter about every line by more than the Huber scale
 * (paper 1's Table 3.5 L1 errors, pairwise orders 4.05, 3.75, 2.35): the
 * robust fit does not converge, and the least-squares slope is still
 * given. */
static void no_robust_fit_keeps_least_squares(void **state)
{
    (void)state;
    double h[4] = {0.075, 0.0375, 0.01875, 0.009375}, e[4] = {5.214e-03, 3.147e-04, 2.343e-05, 4.608e-06};
    hj_order_fit f;
    hj_error err;
    f.p_ls = NAN, f.n = 0;
    assert_int_equal(hj_fit_order(h, e, 4, &f, &err), HJ_ENOCONV);
    assert_close(f.p_ls, 3.41797, 1e-5, 0);
    assert_int_equal(f.n, 4);
}

static void bad_input(void **state)
{
    (void)state;
    double h[3] = {0.1, 0.05, 0.025}, e[3] = {1e-3, -1, 1e-5};
    hj_order_fit f;
    hj_error err;
    assert_int_equal(hj_fit_order(h, e, 3, &f, &err), HJ_EFIT);
    e[1] = NAN;
    assert_int_equal(hj_fit_order(h, e, 3, &f, &err), HJ_ENONFINITE);
    assert_int_equal(hj_fit_order(h, e, 1, &f, &err), HJ_EFIT);
    double hs[3] = {0.1, 0.1, 0.1}, es[3] = {1, 2, 3};
    assert_int_equal(hj_fit_order(hs, es, 3, &f, &err), HJ_EFIT);
}

HJ_TEST_MAIN("hj_fit", NULL, NULL, cmocka_unit_test(pair_order), cmocka_unit_test(exact_power_law),
             cmocka_unit_test(robust_to_one_outlier), cmocka_unit_test(two_points_no_error_bar),
             cmocka_unit_test(no_robust_fit_keeps_least_squares), cmocka_unit_test(bad_input))
