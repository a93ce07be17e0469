/* Unit tests of common/hj_ls_accuracy: the toolbox's accuracy levels. */
#include "hj_test.h"

#include "hj_ls_accuracy.h"
#include "hj_ls_deriv.h"

static void levels(void **state)
{
    (void)state;
    static const char *const name[HJ_LS_NACC] = {"low", "medium", "high", "veryHigh"};
    static const int scheme[HJ_LS_NACC] = {HJ_LS_UPWIND_FIRST, HJ_LS_ENO2, HJ_LS_ENO3A, HJ_LS_WENO5A};
    static const int order[HJ_LS_NACC] = {1, 2, 3, 3};
    for (int a = 0; a < HJ_LS_NACC; a++) {
        int parsed = -1;
        assert_string_equal(hj_ls_accuracy_name(a), name[a]);
        assert_int_equal(hj_ls_accuracy_scheme(a), scheme[a]);
        assert_int_equal(hj_ls_accuracy_order(a), order[a]);
        assert_int_equal(hj_ls_accuracy_parse(name[a], &parsed, NULL), HJ_OK);
        assert_int_equal(parsed, a);
    }
    assert_string_equal(hj_ls_accuracy_name(-1), "?");
    assert_string_equal(hj_ls_accuracy_name(HJ_LS_NACC), "?");
    assert_true(HJ_LS_FACTOR_CFL < HJ_LS_FACTOR_CFL_REACH && HJ_LS_FACTOR_CFL_REACH < HJ_LS_FACTOR_CFL_CURVATURE);
}

static void unknown(void **state)
{
    (void)state;
    hj_error err;
    int acc = 7;
    assert_int_equal(hj_ls_accuracy_parse("veryhigh", &acc, &err), HJ_EINVAL);
    assert_int_equal(acc, 7);
    assert_non_null(strstr(err.msg, "'veryhigh'"));
    assert_non_null(strstr(err.msg, "veryHigh"));
}

HJ_TEST_MAIN("hj_ls_accuracy", NULL, NULL, cmocka_unit_test(levels), cmocka_unit_test(unknown))
