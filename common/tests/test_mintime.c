/* Unit tests of common/hj_mintime: records written and read back onto the
 * grid, malformed streams refused, and the minimal time of a target
 * problem run by hj_ub. */
#include "hj_test.h"

#include <stdlib.h>
#include <string.h>

#include "hj_mintime.h"
#include "hj_ub.h"

#define dir hj_test_dir()

static void write_and_read_back(void **state)
{
    (void)state;
    char path[128];
    snprintf(path, sizeof path, "%s/t.bin", dir);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    hj_mintime_stream s = {f, 2, 0};
    assert_int_equal(hj_mintime_put(&s, (int[2]){1, 2}, 0.0), HJ_OK);
    assert_int_equal(hj_mintime_put(&s, (int[2]){0, 0}, 0.25), HJ_OK);
    assert_int_equal(hj_mintime_put(&s, (int[2]){1, 2}, 0.5), HJ_OK); /* a later time: the first stays */
    assert_int_equal(fclose(f), 0);
    double T[9];
    assert_int_equal(hj_mintime_read(path, 2, 3, T, NULL), HJ_OK);
    for (int q = 0; q < 9; q++) {
        if (q == 1 * 3 + 2) assert_true(T[q] == 0.0);
        else if (q == 0) assert_true(T[q] == 0.25);
        else assert_true(isinf(T[q]));
    }
}

static void malformed_streams(void **state)
{
    (void)state;
    char path[128];
    hj_error err;
    double T[4];
    snprintf(path, sizeof path, "%s/none.bin", dir);
    assert_int_equal(hj_mintime_read(path, 2, 2, T, &err), HJ_EIO);
    snprintf(path, sizeof path, "%s/bad.bin", dir);
    FILE *f = fopen(path, "wb");
    hj_mintime_stream s = {f, 2, 0};
    assert_int_equal(hj_mintime_put(&s, (int[2]){0, 2}, 1.0), HJ_OK); /* outside a 2 x 2 grid */
    fclose(f);
    assert_int_equal(hj_mintime_read(path, 2, 2, T, &err), HJ_EFORMAT);
    assert_non_null(strstr(err.msg, "outside"));
    f = fopen(path, "wb");
    const int32_t half[2] = {0, 1};
    fwrite(half, sizeof half, 1, f); /* indices without the time */
    fclose(f);
    assert_int_equal(hj_mintime_read(path, 2, 2, T, &err), HJ_EFORMAT);
    assert_non_null(strstr(err.msg, "truncated"));
}

/* The target problem (4) with f = (1, 0) from the box [-0.2, 0.2]^2: a
 * cell is reached when the set that grows to the right covers it.  Every
 * cell with V = -1 at T has a recorded time <= T, the others none, and the
 * target's own cells have time 0. */
static void dyn(double t, const double *x, int a, double *f, void *ctx)
{
    (void)t, (void)x, (void)a, (void)ctx;
    f[0] = 1;
    f[1] = 0;
}

static double avg0(const double *blo, const double *bhi, void *ctx)
{
    (void)ctx;
    const double lo[2] = {-0.2, -0.2}, hi[2] = {0.2, 0.2};
    return hj_ub_avg_box(2, blo, bhi, lo, hi);
}

static void reached(const int *idx, double t, void *ctx) { hj_mintime_put(ctx, idx, t); }

static void target_problem(void **state)
{
    (void)state;
    enum { n = 41 };
    char path[128];
    snprintf(path, sizeof path, "%s/ub.bin", dir);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    hj_mintime_stream s = {f, 2, 0};
    hj_ub_problem pb = {.d = 2, .n = n, .lo = {-1, -1}, .hi = {1, 1}, .ncontrols = 1, .dyn = dyn, .target = 1,
                        .cfl = 0.9, .boundary = 1, .snap = HJ_UB_SNAP, .avg0 = avg0, .bbox_lo = {-0.2, -0.2},
                        .bbox_hi = {0.2, 0.2}, .reached = reached, .ctx = &s};
    hj_ub_solver sv;
    assert_int_equal(hj_ub_init(&sv, &pb, HJ_BAND_SSD, NULL), HJ_OK);
    assert_int_equal(hj_ub_run(&sv, 0.5, NULL), HJ_OK);
    assert_int_equal(fclose(f), 0);
    assert_false(s.failed);
    double *T = malloc(n * n * sizeof *T), *V = malloc(n * n * sizeof *V);
    assert_non_null(T);
    assert_non_null(V);
    assert_int_equal(hj_mintime_read(path, 2, n, T, NULL), HJ_OK);
    assert_int_equal(hj_ub_values(&sv, V, NULL), HJ_OK);
    int zero = 0, later = 0;
    for (int q = 0; q < n * n; q++) {
        assert_true((V[q] == -1) == !isinf(T[q]));
        if (!isinf(T[q])) assert_true(T[q] >= 0 && T[q] <= 0.5);
        zero += T[q] == 0;
        later += T[q] > 0 && !isinf(T[q]);
    }
    assert_true(zero > 0 && later > 0);
    free(T);
    free(V);
    hj_ub_free(&sv);
}

HJ_TEST_MAIN("hj_mintime", hj_test_mkdir, hj_test_rmdir, cmocka_unit_test(write_and_read_back),
             cmocka_unit_test(malformed_streams), cmocka_unit_test(target_problem))
