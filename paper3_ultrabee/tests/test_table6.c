/* Unit tests of the paper's reading of Table 6 (examples2d.c): which grid
 * and which data give the published zeros and Hausdorff distances. */
#include "hj_test.h"

#include <stdlib.h>
#include <string.h>

#include "hj_ub.h"
#include "p3_prog.h"

/* Table 6's published L1 = 0.000 at N = 50 ... 400 against the grid.  Since
 * the scheme reproduces the exact averages of the moved square
 * (common/tests/test_ub.c), the L1 count at T = 1 is that of the exact averages: a cell
 * counts when its sign (V <= 1e-12 is -1) differs from the closed moved
 * square [-1.5, -0.5]^2 at its centre (with P3_CLOSED_SLACK, so a centre
 * on an edge is inside).  Three grids of [-2, 2]:
 *   A  N nodes with both ends, dx = 4/(N-1) (used before): 1 corner cell at
 *      N >= 100, covered 0.625^2 < 1/2 with its centre inside;
 *   B  N cells, centres -2 + (i + 1/2) dx, dx = 4/N: at N = 100 the edges
 *      pass through centres and the 4 corner cells, a quarter covered,
 *      differ;
 *   C  nodes at multiples of dx = 4/N (the paper's xi_ij = (i dx, j dx)):
 *      the same at N = 200 and 400.
 * So with the exact averages no grid gives 0 at every N.  The examples
 * therefore take (7b) by the midpoint rule on grid B, where the published
 * zeros and Hausdorff distances come out (table6_paper_reading). */
static int table6_sign_errors(int grid, int N)
{
    const double dx = grid == 0 ? 4.0 / (N - 1) : 4.0 / N, slack = P3_CLOSED_SLACK * dx;
    const int m = grid == 0 ? N : grid == 1 ? N : N + 1;
    const double off = grid == 1 ? 0.5 : 0;
    const double lo[2] = {-1.5, -1.5}, hi[2] = {-0.5, -0.5};
    int wrong = 0;
    for (int i = 0; i < m; i++)
        for (int j = 0; j < m; j++) {
            const double x[2] = {-2 + (i + off) * dx, -2 + (j + off) * dx};
            const double blo[2] = {x[0] - dx / 2, x[1] - dx / 2}, bhi[2] = {x[0] + dx / 2, x[1] + dx / 2};
            const int comp = hj_ub_avg_box(2, blo, bhi, lo, hi) <= 1e-12;
            const int in = x[0] >= lo[0] - slack && x[0] <= hi[0] + slack && x[1] >= lo[1] - slack && x[1] <= hi[1] + slack;
            wrong += comp != in;
        }
    return wrong;
}

static void table6_zero_on_no_grid(void **state)
{
    (void)state;
    static const int sizes[4] = {50, 100, 200, 400};
    static const int expect[3][4] = {{0, 1, 1, 1}, {0, 4, 0, 0}, {0, 0, 4, 4}};
    for (int g = 0; g < 3; g++)
        for (int s = 0; s < 4; s++) assert_int_equal(table6_sign_errors(g, sizes[s]), expect[g][s]);
}

/* Table 6 as the examples run it: grid B above (N cells of width 4/N,
 * hj_ub_cell_grid), the data sampled at the cell centres (the midpoint rule
 * for (7b)), the exact front sampled on lattice lines refined 8 times.
 * The scheme moves the sampled square exactly (whole cells in x, whole or
 * half cells in y), so L1 = 0 at every N, and the Hausdorff distance is
 * the distance from the exact front to the centres of the boundary cells:
 * the edges lie 1/4 cell from them at N = 50 (sqrt(1/4^2 + 1/2^2) dx with
 * the point between two centres), on them at N = 100 (1/2 dx between two
 * centres) and half a cell from them at N = 200, 400 (sqrt(1/2) dx).  The
 * published values, 0.044 / 0.55, 0.020 / 0.50, 0.014 / 0.70, 0.007 /
 * 0.70, are these truncated to three digits. */
static double sq_lo[2] = {0.5, -0.5}, sq_hi[2] = {1.5, 0.5};

static void sq_dyn(double t, const double *x, int a, double *f, void *vctx)
{
    (void)t, (void)x, (void)a, (void)vctx;
    f[0] = -2;
    f[1] = -1;
}

static int sq_in(const double *x, double shift_x, double shift_y, double dx)
{
    const double s = P3_CLOSED_SLACK * dx, y[2] = {x[0] - shift_x, x[1] - shift_y};
    return y[0] >= sq_lo[0] - s && y[0] <= sq_hi[0] + s && y[1] >= sq_lo[1] - s && y[1] <= sq_hi[1] + s;
}

static double sq_midpoint(const double *blo, const double *bhi, void *vctx)
{
    const double c[2] = {0.5 * (blo[0] + bhi[0]), 0.5 * (blo[1] + bhi[1])};
    return sq_in(c, 0, 0, *(const double *)vctx) ? -1 : 1;
}

static int sq_never(const double *blo, const double *bhi, void *vctx)
{
    (void)blo, (void)bhi, (void)vctx;
    return 0;
}

static int sq_moved(const double *x, void *vctx)
{
    return sq_in(x, -2, -1, *(const double *)vctx);
}

static void table6_paper_reading(void **state)
{
    (void)state;
    static const int sizes[4] = {50, 100, 200, 400};
    const double expect[4] = {sqrt(1.0 / 16 + 1.0 / 4), 0.5, sqrt(0.5), sqrt(0.5)};
    for (int s = 0; s < 4; s++) {
        double dx = 4.0 / sizes[s];
        hj_ub_problem pb = {.d = 2, .n = sizes[s], .ncontrols = 1, .dyn = sq_dyn, .cfl = 0.9, .boundary = 1,
                         .avg0 = sq_midpoint, .uniform = sq_never, .front_sub = 8, .ctx = &dx,
                         .bbox_lo = {0.5, -0.5}, .bbox_hi = {1.5, 0.5}};
        for (int k = 0; k < 2; k++) hj_ub_cell_grid(-2, 2, sizes[s], &pb.lo[k], &pb.hi[k]);
        hj_ub_solver sv;
        assert_int_equal(hj_ub_init(&sv, &pb, HJ_BAND_SSD, NULL), HJ_OK);
        assert_close(sv.dx[0], dx, 1e-14, 0);
        assert_int_equal(hj_ub_run(&sv, 1.0, NULL), HJ_OK);
        double l1 = -1, haus = -1;
        assert_int_equal(hj_ub_errors(&sv, sq_moved, &dx, &l1, &haus, NULL), HJ_OK);
        assert_true(l1 == 0);
        assert_close(haus / dx, expect[s], 1e-5, 0);
        hj_ub_free(&sv);
    }
}

HJ_TEST_MAIN("p3_table6", NULL, NULL, cmocka_unit_test(table6_zero_on_no_grid), cmocka_unit_test(table6_paper_reading))
