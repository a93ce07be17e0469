/* Unit tests of common/hj_ls_measure (measure of {phi < 0}) and
 * common/hj_ls_io (gnuplot blocks, legacy VTK). */
#include "hj_test.h"
#include "hj_test_ls.h"

#include <stdlib.h>
#include <string.h>

#include "hj_ls_io.h"
#include "hj_ls_measure.h"
#include "hj_ls_shape.h"
#include "hj_math.h"
#ifdef _OPENMP
#include <omp.h>
#endif


/* dim dimensions of n nodes on [-1, 1], extrapolated away from zero. */
static hj_ls_grid grid(int dim, long n) { return hj_test_grid(dim, n, -1, 1, HJ_LS_BC_EXTRAP_AWAY); }

/* Corner fractions and the complement identity f(v) + f(-v) = 1 (zeros
 * excluded), including the 2-2 split of a tetrahedron and its near-tie
 * branch, which must agree with the divided difference. */
static void simplex_fractions(void **state)
{
    (void)state;
    const double tri[3] = {-1, 1, 1}, tet[4] = {-1, 1, 1, 1}, half[4] = {-1, -1, 1, 1};
    assert_close(hj_ls_simplex_fraction(2, tri), 0.25, 1e-15, 0);
    assert_close(hj_ls_simplex_fraction(3, tet), 0.125, 1e-15, 0);
    assert_close(hj_ls_simplex_fraction(3, half), 0.5, 1e-12, 0);
    srand(7);
    for (int trial = 0; trial < 2000; trial++) {
        const int d = 1 + trial % 3;
        double v[4], w[4];
        for (int k = 0; k <= d; k++) {
            v[k] = (double)rand() / RAND_MAX - 0.5;
            if (v[k] == 0) v[k] = 0.25;
            w[k] = -v[k];
        }
        const double f = hj_ls_simplex_fraction(d, v);
        assert_true(f >= 0 && f <= 1);
        assert_close(f + hj_ls_simplex_fraction(d, w), 1.0, 1e-12, 0);
    }
    /* The near-tie branch (negative values 0.3 and 0.3 (1 + 5e-5)) against
     * its complement, whose two negative values are far apart. */
    const double a[4] = {-0.3, -0.3 * (1 + 5e-5), 0.2, 0.5}, b[4] = {0.3, 0.3 * (1 + 5e-5), -0.2, -0.5};
    assert_close(hj_ls_simplex_fraction(3, a) + hj_ls_simplex_fraction(3, b), 1.0, 1e-9, 0);
}

/* Infinite vertices give the limits of the finite formulas (they gave
 * inf / inf = NaN, and hj_ls_measure a NaN area with HJ_OK). */
static void infinite_vertices(void **state)
{
    (void)state;
    const double e1[2] = {-INFINITY, 1}, e2[2] = {-INFINITY, INFINITY}, e3[2] = {-1, INFINITY};
    assert_close(hj_ls_simplex_fraction(1, e1), 1.0, 1e-15, 0);
    assert_close(hj_ls_simplex_fraction(1, e2), 0.5, 1e-15, 0);
    assert_close(hj_ls_simplex_fraction(1, e3), 0.0, 1e-15, 0);
    const double t1[3] = {-INFINITY, 1, 2}, t2[3] = {-1, INFINITY, INFINITY}, t3[3] = {-INFINITY, INFINITY, 1};
    assert_close(hj_ls_simplex_fraction(2, t1), 1.0, 1e-15, 0);
    assert_close(hj_ls_simplex_fraction(2, t2), 0.0, 1e-15, 0);
    const double f3 = hj_ls_simplex_fraction(2, t3);
    assert_true(f3 >= 0 && f3 <= 1);
    const double q1[4] = {-INFINITY, -1, 1, INFINITY}, q2[4] = {-INFINITY, -INFINITY, INFINITY, INFINITY};
    const double g1 = hj_ls_simplex_fraction(3, q1), g2 = hj_ls_simplex_fraction(3, q2);
    assert_true(g1 >= 0 && g1 <= 1);
    assert_close(g2, 0.5, 1e-12, 0);
    /* A disc whose outside far from the front is +inf: the same area as
     * with the finite values there, well away from the disc's cells. */
    hj_ls_grid g = hj_test_grid(2, 41, -1, 1, HJ_LS_BC_EXTRAP_AWAY);
    double *phi = hj_ls_alloc(&g);
    long idx[2];
    double x[2], m0, m1;
    for (size_t r = 0; r < g.rows; r++) {
        const size_t k = hj_ls_row(&g, r, idx);
        for (long j = 0; j < g.N[0]; j++) {
            idx[0] = j;
            hj_ls_coord(&g, idx, x);
            phi[k + (size_t)j] = sqrt(x[0] * x[0] + x[1] * x[1]) - 0.5;
        }
    }
    assert_int_equal(hj_ls_measure(&g, phi, &m0, NULL), HJ_OK);
    for (size_t r = 0; r < g.rows; r++) {
        const size_t k = hj_ls_row(&g, r, idx);
        for (long j = 0; j < g.N[0]; j++)
            if (phi[k + (size_t)j] > 0.3) phi[k + (size_t)j] = INFINITY;
            else if (phi[k + (size_t)j] < -0.3) phi[k + (size_t)j] = -INFINITY;
    }
    assert_int_equal(hj_ls_measure(&g, phi, &m1, NULL), HJ_OK);
    assert_true(isfinite(m1));
    assert_true(m0 == m1);
    hj_ls_free(phi);
}

/* A half-space is exact (its interpolant is linear); a disc and a ball
 * converge at second order. */
static void measures(void **state)
{
    (void)state;
    for (int dim = 1; dim <= 3; dim++) {
        hj_ls_grid g = grid(dim, 21);
        double *phi = hj_ls_alloc(&g), m;
        const double n[3] = {1, 0.3, -0.2}, p[3] = {0.1, 0, 0};
        assert_int_equal(hj_ls_shape_hyperplane(&g, n, p, phi, NULL), HJ_OK);
        assert_int_equal(hj_ls_measure(&g, phi, &m, NULL), HJ_OK);
        /* {n . (x - p) < 0} in [-1, 1]^dim: x < 0.1 - 0.3 y + 0.2 z, all inside. */
        assert_close(m, 1.1 * (dim >= 2 ? 2 : 1) * (dim == 3 ? 2 : 1), 1e-12, 0);
        hj_ls_free(phi);
    }
    double e_prev = 0, e3_prev = 0;
    for (long n = 21; n <= 81; n = 2 * n - 1) {
        hj_ls_grid g2 = grid(2, n), g3 = grid(3, n);
        double *a = hj_ls_alloc(&g2), *b = hj_ls_alloc(&g3), m2, m3;
        const double c[3] = {0.05, -0.1, 0.02};
        assert_int_equal(hj_ls_shape_sphere(&g2, c, 0.6, a, NULL), HJ_OK);
        assert_int_equal(hj_ls_shape_sphere(&g3, c, 0.6, b, NULL), HJ_OK);
        assert_int_equal(hj_ls_measure(&g2, a, &m2, NULL), HJ_OK);
        assert_int_equal(hj_ls_measure(&g3, b, &m3, NULL), HJ_OK);
        const double e2 = fabs(m2 / (HJ_PI * 0.36) - 1), e3 = fabs(m3 / (4.0 / 3.0 * HJ_PI * 0.216) - 1);
        /* chords of a circle of radius R lose about dx^2 / (6 R) of its radius */
        assert_true(e2 < 0.5 * g2.dx[0] * g2.dx[0] && e3 < 1.5 * g3.dx[0] * g3.dx[0]);
        if (e_prev > 0) assert_true(e2 < 0.35 * e_prev && e3 < 0.35 * e3_prev); /* a quarter per halving */
        e_prev = e2;
        e3_prev = e3;
        hj_ls_free(a), hj_ls_free(b);
    }
    hj_ls_grid g4;
    const double mn[4] = {0, 0, 0, 0}, mx[4] = {1, 1, 1, 1};
    const long N[4] = {3, 3, 3, 3};
    const hj_ls_bc bc[4] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    assert_int_equal(hj_ls_grid_init(&g4, 4, mn, mx, N, bc, NULL), HJ_OK);
    double *z = hj_ls_alloc(&g4), m;
    hj_error err;
    assert_int_equal(hj_ls_measure(&g4, z, &m, &err), HJ_EINVAL);
    hj_ls_free(z);
}

/* Block and VTK layouts: line counts, header, first values. */
static void writers(void **state)
{
    (void)state;
    hj_ls_grid g = grid(2, 3);
    double *a = hj_ls_alloc(&g);
    for (long j = 0; j < 3; j++)
        for (long i = 0; i < 3; i++) {
            const long ij[2] = {i, j};
            a[hj_ls_index(&g, ij)] = (double)(10 * j + i);
        }
    char path[4200], line[256];
    snprintf(path, sizeof path, "%s/block.dat", hj_test_dir());
    FILE *fp = fopen(path, "w");
    assert_non_null(fp);
    const char *names[1] = {"phi"};
    const double *fields[1] = {a};
    assert_int_equal(hj_ls_write_block(fp, &g, 1, names, fields, NULL), HJ_OK);
    fclose(fp);
    fp = fopen(path, "r");
    int lines = 0, blank = 0;
    while (fgets(line, sizeof line, fp)) {
        if (lines == 0) assert_string_equal(line, "# x y phi\n");
        if (lines == 1) assert_string_equal(line, "-1 -1 0\n");
        if (line[0] == '\n') blank++;
        lines++;
    }
    fclose(fp);
    assert_int_equal(lines, 1 + 9 + 3);
    assert_int_equal(blank, 3);
    snprintf(path, sizeof path, "%s/f.vtk", hj_test_dir());
    assert_int_equal(hj_ls_write_vtk(path, &g, "test", 1, names, fields, NULL), HJ_OK);
    fp = fopen(path, "r");
    int n = 0;
    double last = -1;
    while (fgets(line, sizeof line, fp)) {
        n++;
        if (n == 5) assert_string_equal(line, "DIMENSIONS 3 3 1\n");
        if (n > 10) last = atof(line);
    }
    fclose(fp);
    assert_int_equal(n, 10 + 9);
    assert_close(last, 22, 0, 0);
    hj_ls_free(a);
}

/* A periodic dimension adds the cells from the last node to the first
 * node's image: a band across the seam, and a radius from the measure. */
static void periodic_and_radius(void **state)
{
    (void)state;
    hj_ls_grid g;
    const double mn[2] = {0, 0}, mx[2] = {0.9, 1};
    const long N[2] = {10, 11};
    const hj_ls_bc bc[2] = {{HJ_LS_BC_PERIODIC, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
    assert_int_equal(hj_ls_grid_init(&g, 2, mn, mx, N, bc, NULL), HJ_OK);
    double *phi = hj_ls_alloc(&g), m, mp;
    /* {phi < 0}: x < 0.25 or x > 0.85 (the seam), all y */
    for (size_t r = 0; r < g.rows; r++) {
        long i[2] = {0, 0};
        const size_t k = hj_ls_row(&g, r, i);
        for (long j = 0; j < 10; j++) {
            const double x = 0.1 * (double)j;
            phi[k + (size_t)j] = x < 0.55 ? x - 0.25 : 0.85 - x;
        }
    }
    assert_int_equal(hj_ls_measure(&g, phi, &m, NULL), HJ_OK);
    assert_int_equal(hj_ls_measure_periodic(&g, phi, 0, &mp, NULL), HJ_OK);
    assert_close(m, 0.25 + 0.05, 1e-12, 0);
    assert_close(mp, 0.25 + 0.15, 1e-12, 0);
    assert_int_equal(hj_ls_measure_periodic(&g, phi, -1, &mp, NULL), HJ_OK);
    assert_true(mp == m);
    assert_int_equal(hj_ls_measure_periodic(&g, phi, 2, &mp, NULL), HJ_EINVAL);
    hj_ls_free(phi);
    for (int dim = 2; dim <= 3; dim++) {
        hj_ls_grid gs = grid(dim, 41);
        double *s = hj_ls_alloc(&gs), r;
        const double c[3] = {0, 0, 0};
        assert_int_equal(hj_ls_shape_sphere(&gs, c, 0.6, s, NULL), HJ_OK);
        assert_int_equal(hj_ls_measure_radius(&gs, s, &r, NULL), HJ_OK);
        assert_close(r, 0.6, 2e-3, 0);
        hj_ls_free(s);
    }
    hj_ls_grid g1 = grid(1, 5);
    double *s1 = hj_ls_alloc(&g1), r1;
    assert_int_equal(hj_ls_measure_radius(&g1, s1, &r1, NULL), HJ_EINVAL);
    hj_ls_free(s1);
}

/* The cell fractions are summed exactly: the measure is the correctly
 * rounded sum of the fractions that hj_ls_measure_add collects, times the
 * cell, the same bits on 1, 2 and 3 threads; a partial range of cells adds
 * to the whole like disjoint blocks. */
static void measure_exact_threads(void **state)
{
    (void)state;
    hj_ls_grid g = grid(3, 23);
    double *phi = hj_ls_alloc(&g);
    const double c[3] = {0.05, -0.1, 0.02};
    assert_int_equal(hj_ls_shape_sphere(&g, c, 0.55, phi, NULL), HJ_OK);
    double m[3];
    for (int t = 1; t <= 3; t++) {
        hj_test_threads(t);
        assert_int_equal(hj_ls_measure(&g, phi, &m[t - 1], NULL), HJ_OK);
    }
    hj_test_one_thread();
    assert_memory_equal(&m[0], &m[1], sizeof(double));
    assert_memory_equal(&m[0], &m[2], sizeof(double));
    /* The cells with i[2] < 10 and those above, added separately (the
     * upper part through a pointer offset by 10 planes). */
    hj_sum lo, hi;
    hj_sum_init(&lo), hj_sum_init(&hi);
    hj_ls_grid up = g;
    up.N[2] = g.N[2] - 10, up.rows = g.rows / (size_t)g.N[2] * (size_t)up.N[2];
    assert_int_equal(hj_ls_measure_add(&g, phi, (const long[]){22, 22, 10}, &lo, NULL), HJ_OK);
    assert_int_equal(hj_ls_measure_add(&up, phi + 10 * g.stride[2], (const long[]){22, 22, 12}, &hi, NULL), HJ_OK);
    hj_sum_merge(&lo, &hi);
    const double whole = hj_sum_value(&lo) * g.dx[0] * g.dx[1] * g.dx[2];
    assert_memory_equal(&whole, &m[0], sizeof(double));
    assert_int_equal(hj_ls_measure_add(&g, phi, (const long[]){22, 24, 10}, &lo, NULL), HJ_EINVAL);
    hj_ls_free(phi);
}

/* A NaN in phi is HJ_ENONFINITE naming the node, on the front (the
 * measure was NaN) or away from it (it was finite and wrong), in the
 * upper corner nodes and in a ghost the cells read; the lowest node is
 * named whatever the number of threads; the sum is left untouched.
 * Infinite values keep their sign's meaning. */
static void measure_nan(void **state)
{
    (void)state;
    hj_ls_grid g = grid(2, 21); /* dx = 0.1 */
    double *phi = hj_ls_alloc(&g), m;
    const double c[2] = {0, 0};
    hj_error err;
    assert_int_equal(hj_ls_shape_sphere(&g, c, 0.5, phi, NULL), HJ_OK);
    long far[2] = {2, 18}, front[2] = {15, 10}, corner[2] = {20, 20};
    const size_t kf = hj_ls_index(&g, far), kc = hj_ls_index(&g, corner);
    phi[kf] = NAN;
    assert_int_equal(hj_ls_measure(&g, phi, &m, &err), HJ_ENONFINITE);
    assert_non_null(strstr(err.msg, "NaN at x = (-0.8, 0.8)"));
    assert_int_equal(hj_ls_measure_radius(&g, phi, &m, &err), HJ_ENONFINITE);
    assert_int_equal(hj_ls_measure_periodic(&g, phi, 1, &m, &err), HJ_ENONFINITE);
    phi[kf] = 1;
    phi[hj_ls_index(&g, front)] = NAN;
    assert_int_equal(hj_ls_measure(&g, phi, &m, &err), HJ_ENONFINITE);
    assert_non_null(strstr(err.msg, "(0.5, 0)"));
    /* With two NaNs the lower one is named, on 1 to 3 threads. */
    phi[kc] = NAN;
    for (int t = 1; t <= 3; t++) {
        hj_test_threads(t);
        assert_int_equal(hj_ls_measure(&g, phi, &m, &err), HJ_ENONFINITE);
        assert_non_null(strstr(err.msg, "(0.5, 0)"));
    }
    hj_test_one_thread();
    assert_int_equal(hj_ls_shape_sphere(&g, c, 0.5, phi, NULL), HJ_OK);
    phi[kc] = NAN; /* only the last cell's upper corner */
    assert_int_equal(hj_ls_measure(&g, phi, &m, &err), HJ_ENONFINITE);
    assert_non_null(strstr(err.msg, "(1, 1)"));
    /* Cells up to N along dimension 1 read the ghost row above. */
    assert_int_equal(hj_ls_shape_sphere(&g, c, 0.5, phi, NULL), HJ_OK);
    hj_ls_fill_ghosts(&g, phi);
    long ghost[2] = {3, 21};
    phi[hj_ls_index(&g, ghost)] = NAN;
    hj_sum s;
    hj_sum_init(&s);
    assert_int_equal(hj_ls_measure_add(&g, phi, (const long[]){20, 20}, &s, &err), HJ_OK);
    const double before = hj_sum_value(&s);
    assert_int_equal(hj_ls_measure_add(&g, phi, (const long[]){20, 21}, &s, &err), HJ_ENONFINITE);
    assert_non_null(strstr(err.msg, "(-0.7, 1.1)"));
    const double after = hj_sum_value(&s);
    assert_memory_equal(&before, &after, sizeof(double));
    /* -inf and +inf are signs, not errors: the whole box, then nothing. */
    for (size_t k = 0; k < g.total; k++) phi[k] = -INFINITY;
    assert_int_equal(hj_ls_measure(&g, phi, &m, &err), HJ_OK);
    assert_close(m, 4, 1e-15, 0);
    for (size_t k = 0; k < g.total; k++) phi[k] = INFINITY;
    assert_int_equal(hj_ls_measure(&g, phi, &m, &err), HJ_OK);
    assert_true(m == 0);
    hj_ls_free(phi);
}

/* NULL arguments of the measures: an error, not a segfault. */
static void measure_null(void **state)
{
    (void)state;
    hj_ls_grid g = hj_test_grid(2, 5, -1, 1, HJ_LS_BC_EXTRAP_AWAY);
    double *phi = hj_ls_alloc(&g), m, r;
    hj_error err;
    assert_int_equal(hj_ls_measure(&g, NULL, &m, &err), HJ_EINVAL);
    assert_has(err.msg, "NULL");
    assert_int_equal(hj_ls_measure(&g, phi, NULL, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_measure(NULL, phi, &m, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_measure_periodic(&g, NULL, 1, &m, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_measure_radius(&g, phi, NULL, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_measure_radius(&g, NULL, &r, &err), HJ_EINVAL);
    hj_ls_free(phi);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(simplex_fractions),
        cmocka_unit_test(infinite_vertices),
        cmocka_unit_test(measures),
        cmocka_unit_test_setup_teardown(writers, hj_test_mkdir, hj_test_rmdir),
        cmocka_unit_test(periodic_and_radius),
        cmocka_unit_test(measure_exact_threads),
        cmocka_unit_test(measure_nan),
        cmocka_unit_test(measure_null),
    };
    return cmocka_run_group_tests_name("hj_ls_measure", tests, NULL, NULL);
}
