/* Unit tests of common/hj_error (codes, names, messages). */
#include "hj_test.h"

#include <string.h>

#include "hj_error.h"

/* Every code of the enum has its own name and is known; any other int,
 * as a caller's callback may return, is unknown and named so. */
static void codes_and_names(void **state)
{
    (void)state;
    const int codes[] = {HJ_OK, HJ_EINVAL, HJ_ENOMEM, HJ_EIO, HJ_EFORMAT, HJ_ENONFINITE, HJ_ENOCONV, HJ_EFIT};
    const int n = (int)(sizeof codes / sizeof codes[0]);
    for (int i = 0; i < n; i++) {
        assert_int_equal(hj_error_known(codes[i]), 1);
        assert_string_not_equal(hj_strerror(codes[i]), "unknown error");
        for (int j = 0; j < i; j++) assert_string_not_equal(hj_strerror(codes[i]), hj_strerror(codes[j]));
    }
    const int others[] = {-1, HJ_EFIT + 1, 42, -2147483647 - 1};
    for (int i = 0; i < 4; i++) {
        assert_int_equal(hj_error_known(others[i]), 0);
        assert_string_equal(hj_strerror(others[i]), "unknown error");
    }
}

/* hj_error_set returns its code, fills the message (cut to the buffer,
 * terminated), and accepts NULL; hj_error_clear empties it. */
static void set_and_clear(void **state)
{
    (void)state;
    hj_error err;
    assert_int_equal(hj_error_set(&err, HJ_EIO, "cannot open %s", "x.tsv"), HJ_EIO);
    assert_int_equal(err.code, HJ_EIO);
    assert_string_equal(err.msg, "cannot open x.tsv");
    assert_int_equal(hj_error_set(NULL, HJ_EINVAL, "ignored"), HJ_EINVAL);
    char big[2 * sizeof err.msg];
    memset(big, 'a', sizeof big - 1);
    big[sizeof big - 1] = '\0';
    hj_error_set(&err, HJ_EFORMAT, "%s", big);
    assert_int_equal((int)strlen(err.msg), (int)sizeof err.msg - 1);
    hj_error_clear(&err);
    assert_int_equal(err.code, HJ_OK);
    assert_string_equal(err.msg, "");
    hj_error_clear(NULL);
    assert_string_equal(hj_plural(1), "");
    assert_string_equal(hj_plural(0), "s");
    assert_string_equal(hj_plural(2), "s");
}

/* hj_error_quote: printable bytes as they are, others as \xHH, the
 * backslash doubled, cut with "..." to fit the buffer. */
static void quote(void **state)
{
    (void)state;
    char buf[64];
    assert_string_equal(hj_error_quote("a b\\c", 5, buf, sizeof buf), "a b\\\\c");
    assert_string_equal(hj_error_quote("x\n\xff", 3, buf, sizeof buf), "x\\x0a\\xff");
    char small[12];
    const char *q = hj_error_quote("0123456789abcdef", 16, small, sizeof small);
    assert_true(strlen(q) < sizeof small);
    assert_non_null(strstr(q, "..."));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(codes_and_names),
        cmocka_unit_test(set_and_clear),
        cmocka_unit_test(quote),
    };
    return cmocka_run_group_tests_name("hj_error", tests, NULL, NULL);
}
