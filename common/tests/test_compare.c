/* Unit tests of common/hj_compare: the verdict rules. */
#include "hj_test.h"

#include "hj_compare.h"

static void error_rules(void **state)
{
    (void)state;
    int ro;
    assert_int_equal(hj_compare(HJ_KIND_ERROR, 1e-4, 1.04e-4, &ro), HJ_MATCH);
    assert_int_equal(hj_compare(HJ_KIND_ERROR, 1e-4, 0.96e-4, &ro), HJ_MATCH);
    assert_int_equal(hj_compare(HJ_KIND_ERROR, 1e-4, 1.06e-4, &ro), HJ_CLOSE);
    assert_int_equal(hj_compare(HJ_KIND_ERROR, 1e-4, 1.99e-4, &ro), HJ_CLOSE);
    assert_int_equal(hj_compare(HJ_KIND_ERROR, 1e-4, 0.51e-4, &ro), HJ_CLOSE);
    assert_int_equal(hj_compare(HJ_KIND_ERROR, 1e-4, 2.01e-4, &ro), HJ_DIFFERS);
    assert_int_equal(hj_compare(HJ_KIND_ERROR, 1e-4, 0.49e-4, &ro), HJ_DIFFERS);
    assert_int_equal(ro, 0);
}

static void roundoff_rule(void **state)
{
    (void)state;
    int ro = 0;
    assert_int_equal(hj_compare(HJ_KIND_ERROR, 1e-14, 7e-15, &ro), HJ_MATCH);
    assert_int_equal(ro, 1);
    /* one side above the floor: the ratio rule applies and fails */
    assert_int_equal(hj_compare(HJ_KIND_ERROR, 4.4e-15, 3.4e-9, &ro), HJ_DIFFERS);
    assert_int_equal(ro, 0);
}

static void order_count_ratio_rules(void **state)
{
    (void)state;
    assert_int_equal(hj_compare(HJ_KIND_ORDER, 3.0, 3.1, NULL), HJ_MATCH);
    assert_int_equal(hj_compare(HJ_KIND_ORDER, 3.0, 3.3, NULL), HJ_CLOSE);
    assert_int_equal(hj_compare(HJ_KIND_ORDER, 3.0, 2.4, NULL), HJ_DIFFERS);
    assert_int_equal(hj_compare(HJ_KIND_COUNT, 40, 44, NULL), HJ_MATCH);
    assert_int_equal(hj_compare(HJ_KIND_COUNT, 40, 45, NULL), HJ_CLOSE);
    assert_int_equal(hj_compare(HJ_KIND_COUNT, 40, 61, NULL), HJ_DIFFERS);
    assert_int_equal(hj_compare(HJ_KIND_RATIO, 8, 9.9, NULL), HJ_MATCH);
    assert_int_equal(hj_compare(HJ_KIND_RATIO, 8, 15, NULL), HJ_CLOSE);
}

static void bound_exact_rules(void **state)
{
    (void)state;
    assert_int_equal(hj_compare(HJ_KIND_BOUND, 5e-11, 4.6e-11, NULL), HJ_MATCH);
    assert_int_equal(hj_compare(HJ_KIND_BOUND, 5e-11, 5e-11, NULL), HJ_MATCH);
    assert_int_equal(hj_compare(HJ_KIND_BOUND, 5e-11, 4e-10, NULL), HJ_CLOSE);
    assert_int_equal(hj_compare(HJ_KIND_BOUND, 5e-11, 1.5e-3, NULL), HJ_DIFFERS);
    assert_int_equal(hj_compare(HJ_KIND_BOUND, 0, 0, NULL), HJ_MATCH);
    assert_int_equal(hj_compare(HJ_KIND_BOUND, 0, 2, NULL), HJ_DIFFERS);
    assert_true(hj_difference(HJ_KIND_BOUND, 0, 2) == 2);
    assert_true(hj_difference(HJ_KIND_BOUND, 5e-11, 2.5e-11) == 0.5);
    assert_int_equal(hj_compare(HJ_KIND_EXACT, 392, 392, NULL), HJ_MATCH);
    assert_int_equal(hj_compare(HJ_KIND_EXACT, 392, 393, NULL), HJ_CLOSE);
    assert_int_equal(hj_compare(HJ_KIND_EXACT, 392, 368, NULL), HJ_DIFFERS);
}

static void nonfinite_differs(void **state)
{
    (void)state;
    assert_int_equal(hj_compare(HJ_KIND_ERROR, 1e-4, NAN, NULL), HJ_DIFFERS);
    assert_int_equal(hj_compare(HJ_KIND_ORDER, 3, INFINITY, NULL), HJ_DIFFERS);
}

static void names_round_trip(void **state)
{
    (void)state;
    for (int v = HJ_MATCH; v <= HJ_AMBIGUOUS; v++) assert_int_equal(hj_verdict_from_name(hj_verdict_name(v)), v);
    assert_int_equal(hj_verdict_from_name("better"), -1);
    assert_int_equal(hj_kind_from_name("order"), HJ_KIND_ORDER);
    for (int k = HJ_KIND_ERROR; k < HJ_KIND_UNKNOWN; k++) assert_int_equal(hj_kind_from_name(hj_kind_name(k)), k);
    assert_int_equal(hj_kind_from_name("speed"), HJ_KIND_UNKNOWN);
}

HJ_TEST_MAIN("hj_compare", NULL, NULL, cmocka_unit_test(error_rules), cmocka_unit_test(roundoff_rule),
             cmocka_unit_test(order_count_ratio_rules), cmocka_unit_test(bound_exact_rules),
             cmocka_unit_test(nonfinite_differs),
             cmocka_unit_test(names_round_trip))
