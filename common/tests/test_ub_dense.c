/* Unit tests of common/hj_ub_dense: the row-by-row UB-HJB step gives
 * bitwise the values of hj_ub_step on the FS store (every flux branch:
 * both signs of mu, mu = 0, inflow through the grid's edge, several
 * controls, the target problem, flows that change sign between
 * neighbours, random data from a few levels), the batched dynamics the
 * same as the per-node ones, the same bits for 1, 2 and 3 OpenMP threads
 * and for controls in groups of any size, and the rate of autonomous
 * dynamics computed once with the same time steps. */
#include "hj_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hj_ub_dense.h"

typedef struct {
    int d;
    int kind;              /* 0 constant (f_1 = 0: mu = 0), 1 rotation, 2 three controls, 3 inflow,
                              4 diverging along x1 (mu changes sign between neighbours) */
    double blo[4], bhi[4]; /* the initial box */
} dcase;

static void dyn(double t, const double *x, int a, double *f, void *vctx)
{
    const dcase *c = vctx;
    switch (c->kind) {
    case 0: f[0] = -1.3; f[1] = 0; f[2] = 0.7; f[3] = 0.2; break;
    case 1: f[0] = -x[1]; f[1] = x[0]; f[2] = 0.3 + 0.1 * t; f[3] = 0.5; break;
    case 2: f[0] = a - 1.0; f[1] = 1; f[2] = a == 1 ? -0.5 : 0.5; f[3] = 0; break;
    case 3: f[0] = 0.9; f[1] = 0.3 * x[0]; f[2] = 0.2; f[3] = 0.1; break;
    default: f[0] = x[0] - 0.35; f[1] = 0.4; f[2] = -0.3; f[3] = 0.2; break;
    }
}

static long row_calls; /* calls of dyn_row (one thread) */

/* The batched form of dyn: the row's coordinates, the last one per node. */
static void dyn_row(double t, const double *x, const double *xl, long len, int a, double *f, void *vctx)
{
    const dcase *c = vctx;
#pragma omp atomic
    row_calls++;
    for (long j = 0; j < len; j++) {
        double z[4] = {0, 0, 0, 0}, h[4];
        for (int k = 0; k < c->d - 1; k++) z[k] = x[k];
        z[c->d - 1] = xl[j];
        dyn(t, z, a, h, vctx);
        for (int k = 0; k < c->d; k++) f[(long)k * len + j] = h[k];
    }
}

static double avg(const double *blo, const double *bhi, void *vctx)
{
    const dcase *c = vctx;
    return hj_ub_avg_box(c->d, blo, bhi, c->blo, c->bhi);
}

static hj_ub_problem problem(dcase *c, int n)
{
    hj_ub_problem pb = {.d = c->d, .n = n, .ncontrols = c->kind == 2 ? 3 : 1, .dyn = dyn, .target = c->kind == 2,
                        .cfl = 0.9, .boundary = 1, .avg0 = avg, .ctx = c};
    for (int k = 0; k < c->d; k++) {
        pb.lo[k] = -2;
        pb.hi[k] = 2;
        pb.bbox_lo[k] = c->blo[k];
        pb.bbox_hi[k] = c->bhi[k];
    }
    return pb;
}

static int collect(const int *idx, double *v, void *vctx)
{
    (void)idx;
    double **p = vctx;
    *(*p)++ = *v;
    return 0;
}

/* The FS store's values in row-major order. */
static void fs_values(hj_ub_solver *sv, double *out) { hj_band_foreach(sv->s, collect, &out); }

static void cases(dcase *cs, int *m)
{
    *m = 0;
    for (int d = 2; d <= 4; d++)
        for (int kind = 0; kind < 5; kind++) {
            dcase c = {d, kind, {0.3, -0.5, -0.4, -0.3}, {1.1, 0.5, 0.2, 0.6}};
            if (kind == 3) { c.blo[0] = -3; c.bhi[0] = 0.1; } /* the box crosses the edge x1 = -2: inflow of 1 */
            cs[(*m)++] = c;
        }
}

/* Up to nsteps steps towards T of the dense step (ws) and of hj_ub_step
 * on the FS store (sv), from the store's values: the same bits after
 * every step; with `moved`, some node off +-1 (the front on the grid).
 * `what` names the case in a failure. */
static void steps_match_fs(hj_ub_dense *ws, hj_ub_solver *sv, double T, int nsteps, int moved, const char *what)
{
    double *v = malloc(ws->total * sizeof *v), *ref = malloc(ws->total * sizeof *ref);
    fs_values(sv, v);
    double t = 0;
    for (int st = 0; st < nsteps && t < T; st++) {
        const double dt = hj_ub_dense_dt(ws, t, T);
        assert_int_equal(hj_ub_dense_step(ws, v, t, dt, NULL), HJ_OK);
        t = dt == T - t ? T : t + dt;
        assert_int_equal(hj_ub_step(sv, T, NULL), HJ_OK);
        assert_true(sv->t == t);
        fs_values(sv, ref);
        size_t off = 0;
        for (size_t k = 0; k < ws->total; k++) {
            if (memcmp(&v[k], &ref[k], sizeof v[k]))
                fail_msg("%s step %d node %zu: %.17g, FS %.17g", what, st, k, v[k], ref[k]);
            off += v[k] != 1 && v[k] != -1;
        }
        if (moved) assert_true(off > 0);
    }
    free(v);
    free(ref);
}

/* Steps of hj_ub_step on FS and of the dense step, compared bit for bit. */
static void equals_fs_store(void **state)
{
    (void)state;
    hj_test_one_thread();
    dcase cs[15];
    int m;
    cases(cs, &m);
    for (int i = 0; i < m; i++)
        for (int batched = 0; batched < 2; batched++) {
            hj_ub_problem pb = problem(&cs[i], cs[i].d == 2 ? 37 : cs[i].d == 3 ? 15 : 11);
            hj_ub_solver sv;
            hj_ub_dense ws;
            assert_int_equal(hj_ub_init(&sv, &pb, HJ_BAND_FS, NULL), HJ_OK);
            assert_int_equal(hj_ub_dense_init(&ws, &pb, batched ? dyn_row : NULL, NULL), HJ_OK);
            char what[64];
            snprintf(what, sizeof what, "d %d kind %d batched %d", cs[i].d, cs[i].kind, batched);
            steps_match_fs(&ws, &sv, 0.6, 10, 1, what);
            hj_ub_dense_free(&ws);
            hj_ub_free(&sv);
        }
}

/* 1, 2 and 3 threads: the same bits (the rows, or the planes of d >= 3,
 * are shared among threads, each node's value depends on its stencil
 * only; three uneven ranges of planes for d = 3). */
static void threads_bitwise(void **state)
{
    (void)state;
#ifdef _OPENMP
    dcase cs[15];
    int m;
    cases(cs, &m);
    for (int i = 0; i < m; i++) {
        double *v[3] = {NULL, NULL, NULL};
        size_t total = 0;
        for (int th = 1; th <= 3; th++) {
            omp_set_num_threads(th);
            /* 2-D: rows longer than one segment, so that segments are shared */
            hj_ub_problem pb = problem(&cs[i], cs[i].d == 2 ? 300 : cs[i].d == 3 ? 40 : 14);
            hj_ub_solver sv;
            hj_ub_dense ws;
            assert_int_equal(hj_ub_init(&sv, &pb, HJ_BAND_FS, NULL), HJ_OK);
            assert_int_equal(hj_ub_dense_init(&ws, &pb, dyn_row, NULL), HJ_OK);
            assert_int_equal(ws.nthreads, th);
            total = ws.total;
            v[th - 1] = malloc(total * sizeof *v[0]);
            fs_values(&sv, v[th - 1]);
            hj_ub_free(&sv);
            double t = 0;
            for (int st = 0; st < 4; st++) {
                const double dt = hj_ub_dense_dt(&ws, t, 1.0);
                assert_int_equal(hj_ub_dense_step(&ws, v[th - 1], t, dt, NULL), HJ_OK);
                t += dt;
            }
            hj_ub_dense_free(&ws);
        }
        assert_memory_equal(v[0], v[1], total * sizeof *v[0]);
        assert_memory_equal(v[0], v[2], total * sizeof *v[0]);
        for (int th = 0; th < 3; th++) free(v[th]);
    }
    omp_set_num_threads(1);
#endif
}

/* d = 3 with the controls in groups smaller than all (a group's planes
 * share a pass): groups of 1 and 2 of the 3 controls give the FS store's
 * bits, at 1 and 2 threads. */
static void control_groups(void **state)
{
    (void)state;
    dcase c = {3, 2, {0.3, -0.5, -0.4, 0}, {1.1, 0.5, 0.2, 0}};
    for (int th = 1; th <= 2; th++)
        for (int g = 1; g <= 2; g++) {
#ifdef _OPENMP
            omp_set_num_threads(th);
#else
            if (th > 1) continue;
#endif
            hj_ub_problem pb = problem(&c, 17);
            hj_ub_solver sv;
            hj_ub_dense ws;
            assert_int_equal(hj_ub_init(&sv, &pb, HJ_BAND_FS, NULL), HJ_OK);
            assert_int_equal(hj_ub_dense_init(&ws, &pb, dyn_row, NULL), HJ_OK);
            assert_int_equal(ws.group, 3); /* a small grid: every control in one group */
            ws.group = g;
            char what[64];
            snprintf(what, sizeof what, "threads %d group %d", th, g);
            steps_match_fs(&ws, &sv, 0.6, 6, 0, what);
            hj_ub_dense_free(&ws);
            hj_ub_free(&sv);
        }
    hj_test_one_thread();
}

/* Values from a few levels (-1, -1/2, 0, 1/2, 1), drawn at random, into
 * the FS store: many equal neighbours, so that the flux's equality tests
 * take both ways, and values that move everywhere. */
static int quantize(const int *idx, double *v, void *vctx)
{
    (void)idx;
    unsigned *seed = vctx;
    *seed = *seed * 1103515245u + 12345u;
    *v = (double)((*seed >> 16) % 5) / 2 - 1;
    return 0;
}

/* Quantized random data, diverging and converging flows and three
 * controls in groups of 1, 2 and 3, at 1 and 2 threads: the FS store's
 * bits after every step (every node reads its stencil's V^n, also where
 * the last control's values are written back plane by plane). */
static void random_levels(void **state)
{
    (void)state;
    const int kinds[2] = {2, 4};
    for (int d = 2; d <= 4; d++)
        for (int ki = 0; ki < 2; ki++)
            for (int th = 1; th <= 2; th++)
                for (int g = 1; g <= 3; g++) {
                    if ((kinds[ki] != 2 || d != 3) && g > 1) continue; /* groups: d = 3, several controls */
#ifdef _OPENMP
                    omp_set_num_threads(th);
#else
                    if (th > 1) continue;
#endif
                    dcase c = {d, kinds[ki], {0.3, -0.5, -0.4, -0.3}, {1.1, 0.5, 0.2, 0.6}};
                    hj_ub_problem pb = problem(&c, d == 2 ? 31 : d == 3 ? 19 : 9);
                    hj_ub_solver sv;
                    hj_ub_dense ws;
                    assert_int_equal(hj_ub_init(&sv, &pb, HJ_BAND_FS, NULL), HJ_OK);
                    assert_int_equal(hj_ub_dense_init(&ws, &pb, dyn_row, NULL), HJ_OK);
                    ws.group = g < ws.group ? g : ws.group;
                    unsigned seed = 12345u + (unsigned)(d * 10 + ki);
                    assert_int_equal(hj_band_foreach(sv.s, quantize, &seed), 0);
                    char what[64];
                    snprintf(what, sizeof what, "d %d kind %d threads %d group %d", d, kinds[ki], th, g);
                    steps_match_fs(&ws, &sv, 0.5, 3, 0, what);
                    hj_ub_dense_free(&ws);
                    hj_ub_free(&sv);
                }
    hj_test_one_thread();
}

/* f independent of t (kinds 0, 2, 3): with ws.autonomous the rate is
 * computed once, and every step's dt is the same as without. */
static void autonomous_rate(void **state)
{
    (void)state;
    hj_test_one_thread();
    for (int kind = 0; kind < 4; kind++) {
        if (kind == 1) continue; /* f_3 depends on t */
        dcase c = {3, kind, {0.3, -0.5, -0.4, 0}, {1.1, 0.5, 0.2, 0}};
        hj_ub_problem pb = problem(&c, 13);
        hj_ub_dense ws[2];
        double *v[2];
        for (int i = 0; i < 2; i++) {
            assert_int_equal(hj_ub_dense_init(&ws[i], &pb, dyn_row, NULL), HJ_OK);
            ws[i].autonomous = i;
            v[i] = malloc(ws[i].total * sizeof *v[i]);
            for (size_t l = 0; l < ws[i].total; l++) v[i][l] = l % 7 < 3 ? -1 : 1;
        }
        double t = 0;
        for (int st = 0; st < 4; st++) {
            const double dt0 = hj_ub_dense_dt(&ws[0], t, 10);
            const long calls = row_calls;
            const double dt1 = hj_ub_dense_dt(&ws[1], t, 10);
            if (st > 0) assert_int_equal(row_calls, calls); /* the rate of step 0 */
            assert_memory_equal(&dt0, &dt1, sizeof dt0);
            assert_true(dt0 > 0);
            for (int i = 0; i < 2; i++) assert_int_equal(hj_ub_dense_step(&ws[i], v[i], t, dt0, NULL), HJ_OK);
            t += dt0;
        }
        assert_memory_equal(v[0], v[1], ws[0].total * sizeof *v[0]);
        for (int i = 0; i < 2; i++) {
            free(v[i]);
            hj_ub_dense_free(&ws[i]);
        }
    }
}

static void bad_input(void **state)
{
    (void)state;
    dcase c = {2, 0, {0.3, -0.5, 0, 0}, {1.1, 0.5, 0, 0}};
    hj_ub_problem pb = problem(&c, 21);
    hj_ub_dense ws;
    hj_error err;
    pb.cfl = 1.5;
    assert_int_equal(hj_ub_dense_init(&ws, &pb, NULL, &err), HJ_EINVAL);
    pb.cfl = 0.9;
    pb.d = 5;
    assert_int_equal(hj_ub_dense_init(&ws, &pb, NULL, &err), HJ_EINVAL);
    pb.d = 2;
    pb.hi[1] = -3;
    assert_int_equal(hj_ub_dense_init(&ws, &pb, NULL, &err), HJ_EINVAL);
    pb.hi[1] = 2;
    assert_int_equal(hj_ub_dense_init(&ws, &pb, NULL, &err), HJ_OK);
    double v[21 * 21];
    assert_int_equal(hj_ub_dense_step(&ws, v, 0, 0, &err), HJ_EINVAL);
    hj_ub_dense_free(&ws);
}

/* A NaN or infinite f somewhere: the maximum of |f| skipped a NaN, so
 * hj_ub_dense_dt gave an ordinary step and hj_ub_dense_step filled V with
 * NaN without an error (an infinite f gave dt = 0 and "dt must be > 0").
 * Now dt is NaN and the step refuses, HJ_ENONFINITE naming f's component,
 * the node, the control and the time, with V untouched. */
static int bad_f; /* 1: f_0 NaN where x_0 > 0.5; 2: f_1 infinite everywhere */
static void dyn_bad(double t, const double *x, int a, double *f, void *vctx)
{
    dyn(t, x, a, f, vctx);
    if (bad_f == 1 && x[0] > 0.5) f[0] = NAN;
    if (bad_f == 2) f[1] = INFINITY;
}

static void nonfinite_dynamics(void **state)
{
    (void)state;
    dcase c = {2, 3, {0.3, -0.5, 0, 0}, {1.1, 0.5, 0, 0}};
    for (bad_f = 1; bad_f <= 2; bad_f++)
        for (int autonomous = 0; autonomous <= 1; autonomous++) {
            hj_ub_problem pb = problem(&c, 21);
            pb.dyn = dyn_bad;
            hj_ub_dense ws;
            hj_error err = {0};
            assert_int_equal(hj_ub_dense_init(&ws, &pb, NULL, &err), HJ_OK);
            ws.autonomous = autonomous;
            double v[21 * 21];
            for (size_t l = 0; l < ws.total; l++) v[l] = l % 5 < 2 ? -1 : 1;
            const double dt = hj_ub_dense_dt(&ws, 0, 1);
            assert_true(isnan(dt));
            assert_int_equal(hj_ub_dense_step(&ws, v, 0, dt, &err), HJ_ENONFINITE);
            assert_non_null(strstr(err.msg, bad_f == 1 ? "f_0 = nan" : "f_1 = inf"));
            assert_non_null(strstr(err.msg, bad_f == 1 ? "x = (0.6, -2)" : "x = (-2, -2)"));
            /* a step of one's own is refused as well, and V is untouched */
            assert_int_equal(hj_ub_dense_step(&ws, v, 0, 0.01, &err), HJ_ENONFINITE);
            for (size_t l = 0; l < ws.total; l++) assert_true(v[l] == (l % 5 < 2 ? -1 : 1));
            hj_ub_dense_free(&ws);
        }
    bad_f = 0;
}

/* A step above the scheme's limit (Courant number max |f_k| dt / dx_k > 1)
 * was taken without a word, and its values stayed within [-1, 1] (the
 * limiter clips the fluxes), so nothing showed it.  Where the rate is
 * known (autonomous f, or hj_ub_dense_dt at the same t) it is refused;
 * the step at the limit itself (cfl = 1) is taken. */
static void step_above_the_limit(void **state)
{
    (void)state;
    dcase c = {2, 1, {0.3, -0.5, 0, 0}, {1.1, 0.5, 0, 0}};
    for (int autonomous = 0; autonomous <= 1; autonomous++) {
        hj_ub_problem pb = problem(&c, 21);
        pb.cfl = 1;
        hj_ub_dense ws;
        hj_error err = {0};
        assert_int_equal(hj_ub_dense_init(&ws, &pb, NULL, &err), HJ_OK);
        ws.autonomous = autonomous;
        double v[21 * 21];
        for (size_t l = 0; l < ws.total; l++) v[l] = l % 5 < 2 ? -1 : 1;
        const double dt = hj_ub_dense_dt(&ws, 0, 10);
        assert_true(dt > 0 && dt < 10);
        assert_int_equal(hj_ub_dense_step(&ws, v, 0, 1.5 * dt, &err), HJ_EINVAL);
        assert_non_null(strstr(err.msg, "above the scheme's limit"));
        assert_int_equal(hj_ub_dense_step(&ws, v, 0, dt, &err), HJ_OK);
        assert_true(isnan(hj_ub_dense_dt(&ws, 0, NAN)));
        hj_ub_dense_free(&ws);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(equals_fs_store),
        cmocka_unit_test(threads_bitwise),
        cmocka_unit_test(control_groups),
        cmocka_unit_test(random_levels),
        cmocka_unit_test(autonomous_rate),
        cmocka_unit_test(bad_input),
        cmocka_unit_test(nonfinite_dynamics),
        cmocka_unit_test(step_above_the_limit),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
