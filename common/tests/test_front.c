/* Unit tests of common/hj_front, the errors of a computed front: the
 * Hausdorff distance of point sets, and the same L1 error and Hausdorff
 * distance from a full grid, a level set grid and a band store. */
#include "hj_test.h"

#include <stdlib.h>

#include "hj_front.h"

/* The grid: 21 x 21 cell centres -1 + i dx, dx = 0.1; the exact set
 * x0 <= 0.13, the computed set x0 <= 0.1 (its sign at every centre is
 * right: L1 = 0; the fronts are 0.03 apart). */
enum { N = 21 };
static const double LO[2] = {-1, -1}, DX[2] = {0.1, 0.1};

static int left_of(const double *x, void *ctx)
{
    (void)ctx;
    return x[0] <= 0.13;
}

static double grid_value(const int *idx, void *ctx)
{
    (void)ctx;
    return idx[0] <= 11 ? -1 : 1;
}

static double level_set(const double *x, void *ctx)
{
    (void)ctx;
    return x[0] - 0.15;
}

static void hausdorff_of_point_sets(void **state)
{
    (void)state;
    const double a[] = {0, 0, 1, 0, 2, 0}, b[] = {0, 0.5, 2, 0, 7, 0};
    double h;
    assert_int_equal(hj_front_hausdorff(2, a, 3, b, 3, 0.5, &h, NULL), HJ_OK);
    assert_close(h, 5.0, 1e-15, 0);
    assert_int_equal(hj_front_hausdorff(2, a, 2, b, 1, 0.1, &h, NULL), HJ_OK);
    assert_close(h, sqrt(1.25), 1e-15, 0);
    assert_int_equal(hj_front_hausdorff(2, a, 0, b, 1, 0.1, &h, NULL), HJ_OK);
    assert_true(isinf(h));
}

/* Full grid, level set grid and band store give the same errors. */
static void grid_ls_and_band_agree(void **state)
{
    (void)state;
    double l1 = -1, haus = -1;
    int64_t cells = -1;
    assert_int_equal(hj_front_grid_errors(2, N, LO, DX, grid_value, NULL, left_of, NULL, 1, &l1, &haus, &cells, NULL),
                     HJ_OK);
    assert_true(l1 == 0);
    assert_close(haus, 0.03, 1e-6 * DX[0], 0); /* bisection to 1e-6 dx */
    assert_int_equal(cells, 12 * N);

    /* the same signs from a level set function on an hj_ls grid */
    hj_ls_grid g;
    const double hi[2] = {1, 1};
    const long n2[2] = {N, N};
    const hj_ls_bc bc[2] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
    assert_int_equal(hj_ls_grid_init(&g, 2, LO, hi, n2, bc, NULL), HJ_OK);
    double *y = hj_ls_alloc(&g);
    assert_non_null(y);
    hj_ls_fill(&g, y, level_set, NULL);
    double l1s = -1, hauss = -1;
    int64_t cells_s = -1;
    assert_int_equal(hj_front_ls_errors(&g, y, left_of, NULL, 1, &l1s, &hauss, &cells_s, NULL), HJ_OK);
    assert_true(l1s == l1 && hauss == haus && cells_s == cells);
    hj_ls_free(y);

    /* the band of the same front: the columns i = 11, 12 only; the other
     * lines (along the last index) are recovered from their neighbours */
    hj_band *s;
    assert_int_equal(hj_band_new(&s, HJ_BAND_SSD, 2, N, NULL), HJ_OK);
    for (int i = 11; i <= 12; i++)
        for (int j = 0; j < N; j++) assert_int_equal(hj_band_insert(s, (int[2]){i, j}, i == 11 ? -1 : 1, NULL), HJ_OK);
    double *v = malloc(N * N * sizeof *v);
    assert_non_null(v);
    assert_int_equal(hj_front_band_values(s, v, NULL), HJ_OK);
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++) assert_true(v[i * N + j] == grid_value((int[2]){i, j}, NULL));
    free(v);
    double l1b = -1, hausb = -1;
    assert_int_equal(hj_front_band_errors(s, LO, DX, 1, left_of, NULL, &l1b, &hausb, NULL), HJ_OK);
    assert_true(l1b == l1 && hausb == haus);
    hj_band_free(s);
}

/* A wrong sign costs one cell's area; the exact front sampled on lines
 * refined 4 times. */
static double shifted_value(const int *idx, void *ctx)
{
    (void)ctx;
    return idx[0] <= 12 ? -1 : 1;
}

static void l1_counts_wrong_cells(void **state)
{
    (void)state;
    double l1, haus;
    assert_int_equal(hj_front_grid_errors(2, N, LO, DX, shifted_value, NULL, left_of, NULL, 4, &l1, &haus, NULL, NULL),
                     HJ_OK);
    assert_close(l1, N * DX[0] * DX[1], 1e-15, 1e-12); /* the column x0 = 0.2 */
    /* the lattice lines refined 4 times reach half a cell past the
     * bottom row of centres: 0.07 across, 0.05 along the front */
    assert_close(haus, sqrt(0.07 * 0.07 + 0.05 * 0.05), 1e-6 * DX[0], 0);
}

HJ_TEST_MAIN("hj_front", NULL, NULL, cmocka_unit_test(hausdorff_of_point_sets),
             cmocka_unit_test(grid_ls_and_band_agree), cmocka_unit_test(l1_counts_wrong_cells))
