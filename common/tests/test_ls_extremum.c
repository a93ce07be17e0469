/* Unit tests of hj_ls_extremum (common/hj_ls_term): the node-by-node
 * minimum / maximum of terms and its CFL bound, and the HJB equation
 * u_t + |u_x| = 0 (controls a = +-1, u_t + max_a a u_x = 0) solved as the
 * minimum of two convection terms against its exact solution. */
#include "hj_test.h"

#include "hj_ls_ode.h"
#include "hj_ls_term.h"

static hj_ls_grid grid1(long n, double lo, double hi)
{
    hj_ls_grid g;
    const double mn[1] = {lo}, mx[1] = {hi};
    const long N[1] = {n};
    const hj_ls_bc b[1] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
    assert_int_equal(hj_ls_grid_init(&g, 1, mn, mx, N, b, NULL), HJ_OK);
    return g;
}

static double bowl(const double *x, void *ctx)
{
    (void)ctx;
    return (x[0] - 0.5) * (x[0] - 0.5) - 0.01;
}

/* Node by node: min (max) of the two convections' G, bound the smaller. */
static void pointwise(void **state)
{
    (void)state;
    for (int take_max = 0; take_max <= 1; take_max++) {
        hj_ls_grid g = grid1(41, 0, 1);
        double *y = hj_ls_alloc(&g), *f = hj_ls_alloc(&g), *f1 = hj_ls_alloc(&g), *f2 = hj_ls_alloc(&g);
        hj_ls_fill(&g, y, bowl, NULL);
        hj_ls_convection c1, c2;
        hj_ls_convection_init(&c1, &g, HJ_LS_ENO2);
        hj_ls_convection_init(&c2, &g, HJ_LS_ENO2);
        c1.velocity[0] = 1;
        c2.velocity[0] = -2;
        double b1, b2, b;
        assert_int_equal(c1.base.eval(&c1.base, 0, y, f1, &b1, NULL), HJ_OK);
        assert_int_equal(c2.base.eval(&c2.base, 0, y, f2, &b2, NULL), HJ_OK);
        const hj_ls_term *terms[2] = {&c1.base, &c2.base};
        hj_ls_extremum e;
        assert_int_equal(hj_ls_extremum_init(&e, &g, terms, 2, take_max, NULL), HJ_OK);
        assert_int_equal(e.base.eval(&e.base, 0, y, f, &b, NULL), HJ_OK);
        assert_close(b, b1 < b2 ? b1 : b2, 0, 0);
        int both_sides = 0;
        for (long j = 0; j < g.N[0]; j++) {
            const size_t k = g.offset + (size_t)j;
            const double want = take_max ? fmax(f1[k], f2[k]) : fmin(f1[k], f2[k]);
            assert_true(f[k] == want);
            both_sides |= f[k] == f1[k] && f[k] != f2[k] ? 1 : f[k] == f2[k] && f[k] != f1[k] ? 2 : 0;
        }
        assert_true(both_sides != 0);
        hj_ls_extremum_free(&e);
        hj_ls_free(y), hj_ls_free(f), hj_ls_free(f1), hj_ls_free(f2);
    }
}

/* u_t + |u_x| = 0, u(0) = (x - 1/2)^2 - 0.01: u(t, x) = min over |y - x| <= t
 * of u(0, y) = max(|x - 1/2| - t, 0)^2 - 0.01.  RK2-ENO2 max error at t =
 * 0.2, n nodes on [0, 1]. */
static double hjb_error(long n)
{
    hj_ls_grid g = grid1(n, 0, 1);
    double *y = hj_ls_alloc(&g);
    hj_ls_fill(&g, y, bowl, NULL);
    hj_ls_convection c[2];
    const hj_ls_term *terms[2];
    for (int a = 0; a < 2; a++) {
        hj_ls_convection_init(&c[a], &g, HJ_LS_ENO2);
        c[a].velocity[0] = a ? -1 : 1;
        terms[a] = &c[a].base;
    }
    hj_ls_extremum e;
    assert_int_equal(hj_ls_extremum_init(&e, &g, terms, 2, 0, NULL), HJ_OK);
    const double span[2] = {0, 0.2};
    assert_int_equal(hj_ls_ode(2, &g, &e.base, span, 2, y, NULL, NULL, NULL, NULL, NULL), HJ_OK);
    double emax = 0;
    for (long j = 0; j < g.N[0]; j++) {
        const double x = (double)j * g.dx[0], r = fabs(x - 0.5) - 0.2, u = (r > 0 ? r * r : 0) - 0.01;
        const double d = fabs(y[g.offset + (size_t)j] - u);
        emax = d > emax ? d : emax;
    }
    hj_ls_extremum_free(&e);
    hj_ls_free(y);
    return emax;
}

static void hjb_converges(void **state)
{
    (void)state;
    const double e1 = hjb_error(51), e2 = hjb_error(101), e3 = hjb_error(201);
    assert_true(e1 < 2e-3);
    assert_true(e2 < e1 / 1.8);
    assert_true(e3 < e2 / 1.8);
}

static void bad_count(void **state)
{
    (void)state;
    hj_ls_grid g = grid1(11, 0, 1);
    hj_ls_extremum e;
    hj_error err;
    assert_int_equal(hj_ls_extremum_init(&e, &g, NULL, 0, 0, &err), HJ_EINVAL);
    hj_ls_extremum_free(&e);
}

/* A NULL entry in the term list of a sum or an extremum: an error at init,
 * not a segfault at the first evaluation. */
static void null_terms(void **state)
{
    (void)state;
    hj_ls_grid g = grid1(11, 0, 1);
    hj_ls_convection c;
    hj_ls_convection_init(&c, &g, HJ_LS_ENO2);
    const hj_ls_term *terms[2] = {&c.base, NULL};
    hj_error err;
    hj_ls_extremum e;
    assert_int_equal(hj_ls_extremum_init(&e, &g, terms, 2, 0, &err), HJ_EINVAL);
    assert_has(err.msg, "term 1");
    hj_ls_extremum_free(&e);
    assert_int_equal(hj_ls_extremum_init(&e, &g, NULL, 1, 0, &err), HJ_EINVAL);
    hj_ls_extremum_free(&e);
    hj_ls_sum s;
    assert_int_equal(hj_ls_sum_init(&s, &g, terms, 2, &err), HJ_EINVAL);
    assert_has(err.msg, "term 1");
    hj_ls_sum_free(&s);
}

HJ_TEST_MAIN_ONE_THREAD("hj_ls_extremum", NULL, NULL, cmocka_unit_test(pointwise), cmocka_unit_test(hjb_converges),
                        cmocka_unit_test(bad_count), cmocka_unit_test(null_terms))
