/* hj_test_ls.h -- a grid for the level set kernel's tests: n nodes from lo
 * to hi in each of dim dimensions, one boundary condition for all. */
#ifndef HJ_TEST_LS_H
#define HJ_TEST_LS_H

#include "hj_ls_grid.h"
#include "hj_test.h"

static inline hj_ls_grid hj_test_grid(int dim, long n, double lo, double hi, int bc)
{
    hj_ls_grid g;
    double mn[HJ_LS_MAXDIM], mx[HJ_LS_MAXDIM];
    long N[HJ_LS_MAXDIM];
    hj_ls_bc b[HJ_LS_MAXDIM];
    for (int d = 0; d < HJ_LS_MAXDIM; d++) {
        mn[d] = lo, mx[d] = hi, N[d] = n;
        b[d] = (hj_ls_bc){bc, 0, 0};
    }
    assert_int_equal(hj_ls_grid_init(&g, dim, mn, mx, N, b, NULL), HJ_OK);
    return g;
}

#endif
