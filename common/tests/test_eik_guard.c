/* Unit tests of common/hj_eik_guard: the plausibility check that keeps
 * hj_eik_solve from reporting a blown-up iterate as converged.  The
 * solver's safeguards stop every blow-up that was seen, so the check is
 * tested on crafted arrays: a distance field (passes), the same field with
 * one of the failures seen before the safeguards (|T| ~ 1e151 below the
 * source time at a grid corner, NaN) or with a non-finite value where a
 * front arrives (fails), rounding below the source time (passes). */
#include "hj_test.h"

#include <stdlib.h>
#include <string.h>

#include "hj_eik.h"
#include "hj_eik_guard.h"

enum { NX = 12, NY = 9 };

/* T = t0 + distance to node (4, 3) on a unit grid; obstacle column x = 8
 * for y < 5 (+INFINITY, not reached); its max is the scale */
static double field(double *T, unsigned char *reached, double t0)
{
    double mx = 0;
    for (int j = 0; j < NY; j++)
        for (int i = 0; i < NX; i++) {
            const int k = i + NX * j, wall = i == 8 && j < 5;
            T[k] = wall ? INFINITY : t0 + hypot(i - 4.0, j - 3.0);
            reached[k] = !wall;
            if (!wall && T[k] > mx) mx = T[k];
        }
    return mx;
}

static const long n[3] = {NX, NY, 1};

static void plausible_passes(void **state)
{
    (void)state;
    double T[NX * NY];
    unsigned char r[NX * NY];
    for (int s = 0; s < 2; s++) {
        const double t0 = s ? -3.5 : 0, scale = field(T, r, t0);
        hj_error e;
        assert_int_equal(hj_eik_guard(T, r, n, t0, scale, &e), HJ_OK);
        assert_int_equal(hj_eik_guard(T, NULL, n, t0, scale, &e), HJ_OK);
        /* rounding below the earliest start is not a blow-up */
        T[4 + NX * 3] = t0 - 1e-13 * (fabs(t0) + scale);
        assert_int_equal(hj_eik_guard(T, r, n, t0, scale, &e), HJ_OK);
    }
}

static void blowup_below_start_fails(void **state)
{
    (void)state;
    double T[NX * NY];
    unsigned char r[NX * NY];
    const double scale = field(T, r, 0);
    hj_error e;
    T[0] = -9.67e151; /* the corner (0, 0) of a noisy map before the safeguards */
    assert_int_equal(hj_eik_guard(T, r, n, 0, scale, &e), HJ_ENOCONV);
    assert_non_null(strstr(e.msg, "blew up"));
    assert_non_null(strstr(e.msg, "(0, 0, 0)"));
    /* just beyond the round-off margin, at another node */
    field(T, r, 0);
    T[5 + NX * 7] = -2 * HJ_EIK_GUARD_TOL * scale;
    assert_int_equal(hj_eik_guard(T, r, n, 0, scale, &e), HJ_ENOCONV);
    assert_non_null(strstr(e.msg, "(5, 7, 0)"));
    /* a later source time moves the floor with it */
    field(T, r, 2);
    T[3] = 1.9;
    assert_int_equal(hj_eik_guard(T, NULL, n, 2, scale + 2, &e), HJ_ENOCONV);
}

static void nonfinite_fails(void **state)
{
    (void)state;
    double T[NX * NY];
    unsigned char r[NX * NY];
    const double scale = field(T, r, 0);
    hj_error e;
    T[NX * NY - 1] = NAN;
    assert_int_equal(hj_eik_guard(T, r, n, 0, scale, &e), HJ_ENOCONV);
    assert_int_equal(hj_eik_guard(T, NULL, n, 0, scale, &e), HJ_ENOCONV);
    field(T, r, 0);
    T[2] = -INFINITY;
    assert_int_equal(hj_eik_guard(T, NULL, n, 0, scale, &e), HJ_ENOCONV);
    /* +INFINITY where a front arrives: an overflow, not a wall */
    field(T, r, 0);
    T[1 + NX * 8] = INFINITY;
    assert_int_equal(hj_eik_guard(T, r, n, 0, scale, &e), HJ_ENOCONV);
    assert_non_null(strstr(e.msg, "(1, 8, 0)"));
    /* ... but fine where none does, or when nothing says where */
    r[1 + NX * 8] = 0;
    assert_int_equal(hj_eik_guard(T, r, n, 0, scale, &e), HJ_OK);
    assert_int_equal(hj_eik_guard(T, NULL, n, 0, scale, &e), HJ_OK);
    /* a NaN is wrong even at a node no front reaches */
    T[1 + NX * 8] = NAN;
    assert_int_equal(hj_eik_guard(T, r, n, 0, scale, &e), HJ_ENOCONV);
}

/* The solver runs the check on every result: a closed wall leaves nodes
 * at +INFINITY (unreachable, not an error), and the solution near a
 * source with t0 < 0 stays above t0. */
static void solver_results_pass(void **state)
{
    (void)state;
    hj_eik_grid g = {2, {NX, NY, 1}, {0, 0, 0}, {1, 1, 1}};
    unsigned char ob[NX * NY] = {0};
    for (int j = 0; j < NY; j++) ob[6 + NX * j] = 1;
    hj_eik_source s = {{2.3, 4.1, 0}, -1.5};
    double T[NX * NY];
    for (int order = 1; order <= 5; order += 2) {
        hj_eik_options o = hj_eik_default_options();
        o.order = order;
        hj_eik_stats st;
        hj_error e;
        assert_int_equal(hj_eik_solve(&g, NULL, 1.0, ob, &s, 1, NULL, &o, T, &st, &e), HJ_OK);
        assert_true(st.converged);
        assert_true(st.unreachable > 0);
        for (int k = 0; k < NX * NY; k++) assert_true(T[k] >= -1.5);
    }
}

HJ_TEST_MAIN("hj_eik_guard", NULL, NULL, cmocka_unit_test(plausible_passes), cmocka_unit_test(blowup_below_start_fails),
             cmocka_unit_test(nonfinite_fails), cmocka_unit_test(solver_results_pass))
