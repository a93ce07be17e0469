/* Unit tests of common/hj_io (atomic output, TSV tables) and hj_cli parsing. */
#include "hj_test.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "hj_cli.h"
#include "hj_io.h"

#define dir hj_test_dir()

static void atomic_write_and_read_back(void **state)
{
    (void)state;
    char path[128];
    snprintf(path, sizeof path, "%s/t.tsv", dir);
    hj_out out;
    hj_error err;
    assert_int_equal(hj_out_open(&out, path, &err), HJ_OK);
    fprintf(out.fp, "# source: test\n# key: N\nN\tL1\n40\t1e-3\n80\t2.5e-4\n");
    assert_int_not_equal(access(path, F_OK), 0); /* not visible before commit */
    assert_int_equal(hj_out_commit(&out, &err), HJ_OK);
    hj_table t;
    assert_int_equal(hj_table_read(&t, path, &err), HJ_OK);
    assert_int_equal(t.ncols, 2);
    assert_int_equal(t.nrows, 2);
    assert_string_equal(t.cells[1][1], "2.5e-4");
    assert_int_equal(hj_table_col(&t, "L1"), 1);
    assert_int_equal(hj_table_col(&t, "Linf"), -1);
    assert_string_equal(hj_table_meta(&t, "source"), "test");
    assert_string_equal(hj_table_meta(&t, "key"), "N");
    hj_table_free(&t);
}

static void abort_leaves_nothing(void **state)
{
    (void)state;
    char path[128];
    snprintf(path, sizeof path, "%s/aborted.tsv", dir);
    hj_out out;
    assert_int_equal(hj_out_open(&out, path, NULL), HJ_OK);
    fprintf(out.fp, "half a table");
    hj_out_abort(&out);
    assert_int_not_equal(access(path, F_OK), 0);
}

static void malformed_tables(void **state)
{
    (void)state;
    char path[128];
    hj_error err;
    hj_table t;
    snprintf(path, sizeof path, "%s/bad.tsv", dir);
    FILE *f = fopen(path, "w");
    fprintf(f, "a\tb\n1\t2\n3\n");
    fclose(f);
    assert_int_equal(hj_table_read(&t, path, &err), HJ_EFORMAT);
    assert_non_null(strstr(err.msg, ":3:"));
    f = fopen(path, "w");
    fprintf(f, "# only comments\n");
    fclose(f);
    assert_int_equal(hj_table_read(&t, path, &err), HJ_EFORMAT);
    snprintf(path, sizeof path, "%s/none.tsv", dir);
    assert_int_equal(hj_table_read(&t, path, &err), HJ_EIO);
}

static void unwritable_output(void **state)
{
    (void)state;
    hj_out out;
    hj_error err;
    assert_int_equal(hj_out_open(&out, "/nonexistent-dir/x.tsv", &err), HJ_EIO);
    assert_non_null(strstr(err.msg, "/nonexistent-dir/x.tsv"));
}

static void cli_parsing(void **state)
{
    (void)state;
    long v, list[4];
    double d;
    int n;
    hj_error err;
    assert_int_equal(hj_parse_long("640", "N", 8, 20000, &v, &err), HJ_OK);
    assert_int_equal(v, 640);
    assert_int_equal(hj_parse_long("0", "N", 8, 20000, &v, &err), HJ_EINVAL);
    assert_int_equal(hj_parse_long("-5", "N", 8, 20000, &v, &err), HJ_EINVAL);
    assert_int_equal(hj_parse_long("12x", "N", 8, 20000, &v, &err), HJ_EINVAL);
    assert_int_equal(hj_parse_long("99999999999999999999", "N", 8, 20000, &v, &err), HJ_EINVAL);
    assert_int_equal(hj_parse_double("1e-11", "delta", 0, 1, &d, &err), HJ_OK);
    assert_int_equal(hj_parse_double("nan", "delta", 0, 1, &d, &err), HJ_ENONFINITE);
    assert_int_equal(hj_parse_double("inf", "delta", 0, 1, &d, &err), HJ_ENONFINITE);
    assert_int_equal(hj_parse_long_list("40,80,160", "sizes", 8, 20000, list, 4, &n, &err), HJ_OK);
    assert_int_equal(n, 3);
    assert_int_equal(list[2], 160);
    assert_int_equal(hj_parse_long_list("40,,80", "sizes", 8, 20000, list, 4, &n, &err), HJ_EINVAL);
    assert_int_equal(hj_parse_long_list("8,8,8,8,8", "sizes", 8, 20000, list, 4, &n, &err), HJ_EINVAL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(atomic_write_and_read_back), cmocka_unit_test(abort_leaves_nothing),
        cmocka_unit_test(malformed_tables), cmocka_unit_test(unwritable_output), cmocka_unit_test(cli_parsing),
    };
    return cmocka_run_group_tests_name("hj_io", tests, hj_test_mkdir, hj_test_rmdir);
}
