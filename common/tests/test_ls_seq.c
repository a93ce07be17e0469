/* Unit tests of common/hj_ls_seq: output times, the time sequence writer
 * (block layout, the switch flag, the hook) and integration through it. */
#include "hj_test.h"

#include <stdlib.h>
#include <string.h>

#include "hj_ls_seq.h"
#include "hj_ls_term.h"

static hj_ls_grid grid1(long n)
{
    hj_ls_grid g;
    const double mn = 0, mx = 1;
    const hj_ls_bc bc = {HJ_LS_BC_EXTRAP_AWAY, 0, 0};
    assert_int_equal(hj_ls_grid_init(&g, 1, &mn, &mx, &n, &bc, NULL), HJ_OK);
    return g;
}

static void times(void **state)
{
    (void)state;
    double t[12];
    hj_ls_seq_times(0, 0.5, 12, t);
    for (int k = 0; k < 12; k++) assert_true(t[k] == 0.5 * k / 11.0);
    hj_ls_seq_times(0.1, 0.7, 4, t);
    assert_true(t[0] == 0.1);
    assert_true(t[3] == 0.7); /* the last exactly t1 */
    assert_close(t[1], 0.3, 1e-15, 0);
}

/* Read the whole file at path into buf. */
static void slurp(const char *path, char *buf, size_t cap)
{
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    const size_t n = fread(buf, 1, cap - 1, f);
    buf[n] = '\0';
    fclose(f);
}

static int calls;
static int count_hook(int k, double t, const double *y, void *ctx, hj_error *err)
{
    (void)t, (void)y, (void)err;
    assert_int_equal(k, calls);
    ++*(int *)ctx;
    calls++;
    return HJ_OK;
}

static void writer(void **state)
{
    (void)state;
    hj_ls_grid g = grid1(2);
    double *y = hj_ls_alloc(&g), *e = hj_ls_alloc(&g);
    y[g.offset] = 1, y[g.offset + 1] = 2, e[g.offset] = 3, e[g.offset + 1] = 4;
    char path[256], text[1024];
    snprintf(path, sizeof path, "%s/seq.dat", hj_test_dir());
    FILE *fp = fopen(path, "w");
    hj_ls_seq s;
    int flag = 0, seen = 0;
    hj_ls_seq_init(&s, fp, &g, "phi", 6);
    s.nextra = 1, s.extra_name[0] = "psi", s.extra[0] = e;
    s.flag = &flag, s.t_switch = 0.5;
    s.hook = count_hook, s.hook_ctx = &seen;
    calls = 0;
    assert_int_equal(hj_ls_seq_output(0, 0, y, &s, NULL), HJ_OK);
    assert_int_equal(flag, 0);
    assert_int_equal(hj_ls_seq_output(1, 0.5, y, &s, NULL), HJ_OK);
    assert_int_equal(flag, 1);
    assert_int_equal(seen, 2);
    fclose(fp);
    slurp(path, text, sizeof text);
    assert_string_equal(text, "# t = 0\n# x phi psi\n0 1 3\n1 2 4\n\n\n# t = 0.5\n# x phi psi\n0 1 3\n1 2 4\n");
    /* digits 0: the time in the column name, no comment line */
    fp = fopen(path, "w");
    hj_ls_seq_init(&s, fp, &g, "phi", 0);
    assert_int_equal(hj_ls_seq_write(&s, 0.25, y, NULL), HJ_OK);
    assert_int_equal(hj_ls_seq_write(&s, 1.0 / 3, y, NULL), HJ_OK);
    fclose(fp);
    slurp(path, text, sizeof text);
    assert_string_equal(text, "# x phi(t=0.25)\n0 1\n1 2\n\n\n# x phi(t=0.333333)\n0 1\n1 2\n");
    /* no stream: nothing written, the flag still switches */
    hj_ls_seq_init(&s, NULL, &g, "phi", 6);
    flag = 0, s.flag = &flag, s.t_switch = 0;
    assert_int_equal(hj_ls_seq_output(0, 0, y, &s, NULL), HJ_OK);
    assert_int_equal(flag, 1);
    assert_int_equal(s.blocks, 0);
    hj_ls_free(y), hj_ls_free(e);
}

/* Convection at unit speed through three output times: the hook sees the
 * initial state and each output time once, and the result is hj_ls_ode's. */
static void solve(void **state)
{
    (void)state;
    hj_ls_grid g = grid1(41);
    double *y = hj_ls_alloc(&g), *z = hj_ls_alloc(&g);
    for (long i = 0; i < 41; i++) y[g.offset + (size_t)i] = z[g.offset + (size_t)i] = 0.025 * (double)i - 0.3;
    hj_ls_convection c;
    hj_ls_convection_init(&c, &g, HJ_LS_UPWIND_FIRST);
    c.velocity[0] = 1;
    double t[3];
    hj_ls_seq_times(0, 0.2, 3, t);
    hj_ls_seq s;
    int seen = 0;
    hj_ls_seq_init(&s, NULL, &g, "phi", 6);
    s.hook = count_hook, s.hook_ctx = &seen;
    calls = 0;
    assert_int_equal(hj_ls_seq_solve(1, &g, &c.base, t, 3, y, NULL, &s, NULL, NULL), HJ_OK);
    assert_int_equal(seen, 3);
    assert_int_equal(hj_ls_ode(1, &g, &c.base, t, 3, z, NULL, NULL, NULL, NULL, NULL), HJ_OK);
    assert_int_equal(hj_ls_count_differ(&g, y, z), 0);
    hj_ls_free(y), hj_ls_free(z);
}

int main(void)
{
    hj_test_one_thread();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(times),
        cmocka_unit_test_setup_teardown(writer, hj_test_mkdir, hj_test_rmdir),
        cmocka_unit_test(solve),
    };
    return cmocka_run_group_tests_name("hj_ls_seq", tests, NULL, NULL);
}
