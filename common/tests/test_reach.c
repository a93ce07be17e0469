/* Unit tests of common/hj_reach: the Hamiltonian and partial bounds of
 * control-affine dynamics against brute force over the input sets, the
 * optimal inputs, and reachability problems with closed-form answers in
 * 1-D (a tube, the time-to-reach, the convergence stop, time-varying
 * targets, discounting), bitwise independence of the thread count, and
 * the measure of a set on a grid periodic by its period. */
#include "hj_test.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "hj_ls_shape.h"
#include "hj_math.h"
#include "hj_reach.h"
#include "hj_sys.h"

#ifdef _OPENMP
#include <omp.h>
#endif

/* A 2-D test system with state-dependent matrices: f = (x1, -x0),
 * G = [[1, x0], [0, 2]], H = [[0.5], [x1]]. */
static void f2(double t, const double *x, double *o, void *c)
{
    (void)t, (void)c;
    o[0] = x[1], o[1] = -x[0];
}
static void G2(double t, const double *x, double *o, void *c)
{
    (void)t, (void)c;
    o[0] = 1, o[1] = x[0], o[2] = 0, o[3] = 2;
}
static void H2(double t, const double *x, double *o, void *c)
{
    (void)t, (void)c;
    o[0] = 0.5, o[1] = x[1];
}

/* Brute force: opt over a grid of inputs of p . xdot (u on a fine grid of
 * the box or circle, d on the segment's ends and middle). */
static double brute(const hj_reach_dyn *s, const double *x, const double *p)
{
    const int n = 200;
    double best_u = s->u.mode == HJ_REACH_MIN ? INFINITY : -INFINITY;
    for (int a = 0; a <= n; a++)
        for (int b = 0; b <= (s->u.shape == HJ_REACH_BOX ? n : 0); b++) {
            double u[2];
            if (s->u.shape == HJ_REACH_BOX) {
                u[0] = s->u.lo[0] + (s->u.hi[0] - s->u.lo[0]) * a / n;
                u[1] = s->u.lo[1] + (s->u.hi[1] - s->u.lo[1]) * b / n;
            } else {
                const double th = 2 * HJ_PI * a / n;
                u[0] = s->u.c[0] + s->u.r * cos(th), u[1] = s->u.c[1] + s->u.r * sin(th);
            }
            double best_d = s->d.mode == HJ_REACH_MIN ? INFINITY : -INFINITY;
            for (int e = 0; e <= 2; e++) {
                const double d = s->d.lo[0] + (s->d.hi[0] - s->d.lo[0]) * e / 2;
                double xd[2];
                hj_reach_dyn_eval(s, 0, x, u, &d, xd);
                const double v = p[0] * xd[0] + p[1] * xd[1];
                best_d = s->d.mode == HJ_REACH_MIN ? fmin(best_d, v) : fmax(best_d, v);
            }
            best_u = s->u.mode == HJ_REACH_MIN ? fmin(best_u, best_d) : fmax(best_u, best_d);
        }
    return best_u;
}

static void hamiltonian_brute_force(void **state)
{
    (void)state;
    hj_reach_dyn s;
    hj_reach_dyn_init(&s, 2, f2, NULL);
    hj_reach_dyn_control_box(&s, G2, 2, (double[]){-1, 0}, (double[]){1, 0.5});
    hj_reach_dyn_disturbance_box(&s, H2, 1, (double[]){-0.3}, (double[]){0.3});
    assert_int_equal(hj_reach_dyn_check(&s, NULL), HJ_OK);
    const double xs[3][2] = {{0.3, -0.7}, {-1.2, 0.4}, {0, 0}};
    const double ps[3][2] = {{1, 2}, {-0.5, 0.25}, {0.7, -1.1}};
    for (int goal = 0; goal < 2; goal++) {
        hj_reach_dyn_goal(&s, goal);
        for (int shape = 0; shape < 2; shape++) {
            if (shape) hj_reach_dyn_control_ball(&s, G2, 2, (double[]){0.1, -0.2}, 0.8);
            else hj_reach_dyn_control_box(&s, G2, 2, (double[]){-1, 0}, (double[]){1, 0.5});
            for (int a = 0; a < 3; a++)
                for (int b = 0; b < 3; b++) {
                    const double h = hj_reach_hamiltonian(&s, 0, xs[a], ps[b]);
                    /* The box's vertices are on the brute-force grid;
                     * the circle is sampled at 200 points. */
                    assert_close(h, brute(&s, xs[a], ps[b]), shape ? 1e-3 : 1e-12, 1e-12);
                    /* The optimal inputs attain it. */
                    double u[2], d[1], xd[2];
                    hj_reach_dyn_optimal(&s, 0, xs[a], ps[b], u, d);
                    hj_reach_dyn_eval(&s, 0, xs[a], u, d, xd);
                    assert_close(ps[b][0] * xd[0] + ps[b][1] * xd[1], h, 1e-12, 1e-12);
                    /* The kernel's form is -H at the forward time. */
                    assert_close(hj_reach_ls_ham(0, xs[a], 0, ps[b], &s), -h, 0, 0);
                }
        }
    }
}

/* The partial bound alpha_i is max over the inputs of |dx_i/dt|: check it
 * is attained on the box's vertices and bounds every sampled input. */
static void partial_bounds_exact(void **state)
{
    (void)state;
    hj_reach_dyn s;
    hj_reach_dyn_init(&s, 2, f2, NULL);
    hj_reach_dyn_control_box(&s, G2, 2, (double[]){-1, 0}, (double[]){1, 0.5});
    hj_reach_dyn_disturbance_box(&s, H2, 1, (double[]){-0.3}, (double[]){0.3});
    const double x[2] = {0.3, -0.7};
    for (int i = 0; i < 2; i++) {
        double m = 0;
        for (int v = 0; v < 8; v++) {
            const double u[2] = {v & 1 ? 1 : -1, v & 2 ? 0.5 : 0}, d = v & 4 ? 0.3 : -0.3;
            double xd[2];
            hj_reach_dyn_eval(&s, 0, x, u, &d, xd);
            m = fmax(m, fabs(xd[i]));
        }
        assert_close(hj_reach_ls_partial(0, x, NULL, NULL, i, &s), m, 1e-15, 1e-15);
    }
    /* A ball: alpha_i = |f_i + (G c)_i| + r |G_i.|. */
    hj_reach_dyn_control_ball(&s, G2, 2, (double[]){0, 0}, 2.0);
    s.d.n = 0;
    assert_close(hj_reach_ls_partial(0, x, NULL, NULL, 0, &s), fabs(-0.7) + 2 * sqrt(1 + 0.09), 1e-15, 1e-15);
}

static void invalid_systems(void **state)
{
    (void)state;
    hj_reach_dyn s;
    hj_error err;
    hj_reach_dyn_init(&s, 2, f2, NULL);
    hj_reach_dyn_control_box(&s, NULL, 1, (double[]){-1}, (double[]){1});
    assert_int_equal(hj_reach_dyn_check(&s, &err), HJ_EINVAL);
    assert_string_equal(err.msg, "control: 1 input but no input matrix");
    hj_reach_dyn_control_box(&s, G2, 2, (double[]){1, 0}, (double[]){-1, 1});
    assert_int_equal(hj_reach_dyn_check(&s, &err), HJ_EINVAL);
    assert_non_null(strstr(err.msg, "empty"));
    hj_reach_dyn_control_ball(&s, G2, 2, (double[]){0, 0}, -1);
    assert_int_equal(hj_reach_dyn_check(&s, &err), HJ_EINVAL);
}

/* 1-D: x' = a x + u, |u| <= 1, on [-2, 2] with N nodes. */
static void f1(double t, const double *x, double *o, void *c)
{
    (void)t;
    o[0] = *(const double *)c * x[0];
}
static void G1(double t, const double *x, double *o, void *c)
{
    (void)t, (void)x, (void)c;
    o[0] = 1;
}

static hj_ls_grid grid1(long n)
{
    hj_ls_grid g;
    const double lo = -2, hi = 2;
    const hj_ls_bc bc = {HJ_LS_BC_EXTRAP_AWAY, 0, 0};
    assert_int_equal(hj_ls_grid_init(&g, 1, &lo, &hi, &n, &bc, NULL), HJ_OK);
    return g;
}

static double interval(double t, const double *x, void *c)
{
    (void)t;
    return fabs(x[0]) - *(const double *)c;
}

/* The 1-D problem most tests share: x' = a x + u, u in [-umax, umax], on
 * grid1(n), target |x| <= 0.5; the problem points at the struct's own
 * dynamics, grid and radius. */
typedef struct {
    double a, r;
    hj_reach_dyn s;
    hj_ls_grid g;
    hj_reach_problem pb;
} line1;

static void line1_init(line1 *L, double a, double umax, long n)
{
    L->a = a, L->r = 0.5;
    hj_reach_dyn_init(&L->s, 1, f1, &L->a);
    hj_reach_dyn_control_box(&L->s, G1, 1, (double[]){-umax}, (double[]){umax});
    L->g = grid1(n);
    hj_reach_problem_init(&L->pb, &L->g, &L->s);
    L->pb.target.fn = interval, L->pb.target.ctx = &L->r;
}

/* Zero crossing of phi on x > 0 (the set's right end). */
static double right_end(const hj_ls_grid *g, const double *phi)
{
    for (long i = g->N[0] / 2; i + 1 < g->N[0]; i++) {
        const double a = phi[g->offset + (size_t)i], b = phi[g->offset + (size_t)i + 1];
        if (a <= 0 && b > 0) return g->min[0] + g->dx[0] * ((double)i + a / (a - b));
    }
    return NAN;
}

static void tube_and_time_to_reach(void **state)
{
    (void)state;
    line1 L;
    line1_init(&L, 0, 1, 81);
    hj_reach_dyn_goal(&L.s, HJ_REACH_REACH);
    L.pb.horizon = 1;
    double *phi = hj_ls_alloc(&L.g), *ttr = hj_ls_alloc(&L.g);
    hj_reach_stats st;
    hj_error err;
    assert_int_equal(hj_reach_solve(&L.pb, phi, ttr, &st, &err), HJ_OK);
    /* The set is |x| <= 0.5 + T; time-to-reach |x| - 0.5 (exact for the
     * linear value: the scheme is exact on linear data away from the kink). */
    assert_close(right_end(&L.g, phi), 1.5, 1e-4, 0);
    for (long i = 0; i < L.g.N[0]; i++) {
        const double x = -2 + L.g.dx[0] * (double)i, t = ttr[L.g.offset + (size_t)i];
        if (fabs(x) <= 0.5) assert_close(t, 0, 0, 0);
        else if (fabs(x) < 1.5 - 1e-9) assert_close(t, fabs(x) - 0.5, 1e-4, 0);
        else if (fabs(x) > 1.5 + 1e-9) assert_true(isinf(t));
    }
    assert_close(st.tau, 1, 0, 0);
    assert_false(st.converged);
    /* An avoiding control against the same set: the set does not grow. */
    hj_reach_dyn_goal(&L.s, HJ_REACH_AVOID);
    assert_int_equal(hj_reach_solve(&L.pb, phi, NULL, NULL, &err), HJ_OK);
    assert_close(right_end(&L.g, phi), 0.5, 1e-12, 0); /* an avoider leaves whenever it can */
    hj_ls_free(phi), hj_ls_free(ttr);
}

/* x' = 1 - t: at rest at the horizon T = 1 (tau = 0) only. */
static void f_rest_at_end(double t, const double *x, double *o, void *c)
{
    (void)x, (void)c;
    o[0] = 1 - t;
}

/* Nothing moves (x' = 0, the control's box a point): one step to the
 * horizon, the value is the target and ttr 0 inside, inf outside, on the
 * fused and the general path; it was an error ("infinite CFL bound ... no
 * MaxStep").  Under an infinite horizon: converged at the first step, at
 * tau = 0.  Dynamics at rest at tau = 0 only: an error naming both
 * times, not a step over the motion. */
static void no_motion(void **state)
{
    (void)state;
    line1 L;
    line1_init(&L, 0, 0, 41);
    hj_reach_dyn_goal(&L.s, HJ_REACH_REACH);
    L.pb.horizon = 1;
    double *phi = hj_ls_alloc(&L.g), *ttr = hj_ls_alloc(&L.g);
    hj_reach_stats st;
    hj_error err;
    for (int general = 0; general <= 1; general++)
        for (int inf = 0; inf <= 1; inf++) { /* an infinite horizon converges at once */
            L.pb.general = general;
            L.pb.horizon = inf ? INFINITY : 1, L.pb.conv_tol = inf ? 1e-6 : 0;
            assert_int_equal(hj_reach_solve(&L.pb, phi, ttr, &st, &err), HJ_OK);
            assert_int_equal(st.steps, 1);
            assert_int_equal(st.converged, inf);
            /* infinite: the value is the limit from tau = 0 (it reported
             * tau = DBL_MAX / 4, the integrator's span) */
            assert_close(st.tau, inf ? 0 : 1, 0, 0);
            for (long i = 0; i < L.g.N[0]; i++) {
                const double x = -2 + L.g.dx[0] * (double)i;
                assert_close(phi[L.g.offset + (size_t)i], fabs(x) - L.r, 1e-15, 0);
                const double t = ttr[L.g.offset + (size_t)i];
                if (fabs(x) <= L.r) assert_close(t, 0, 0, 0);
                else assert_true(isinf(t));
            }
        }
    L.pb.horizon = 1, L.pb.conv_tol = 0;
    hj_reach_dyn_init(&L.s, 1, f_rest_at_end, NULL);
    hj_reach_dyn_control_box(&L.s, G1, 1, (double[]){0}, (double[]){0});
    for (int general = 0; general <= 1; general++) {
        L.pb.general = general;
        assert_int_equal(hj_reach_solve(&L.pb, phi, ttr, &st, &err), HJ_EINVAL);
        assert_has(err.msg, "no motion at");
        assert_has(err.msg, "but motion at");
    }
    hj_ls_free(phi), hj_ls_free(ttr);
}

/* x' = x + u, |u| <= 1, target |x| <= 0.5: the infinite horizon tube is
 * |x| < 1, reached after ln(0.5 / (1 - |x|)). */
static void convergence_stop(void **state)
{
    (void)state;
    line1 L;
    line1_init(&L, 1, 1, 201);
    L.pb.horizon = INFINITY;
    L.pb.conv_tol = 1e-6;
    double *phi = hj_ls_alloc(&L.g), *ttr = hj_ls_alloc(&L.g);
    hj_reach_stats st;
    hj_error err;
    if (hj_reach_solve(&L.pb, phi, ttr, &st, &err)) fail_msg("%s", err.msg);
    assert_true(st.converged);
    assert_true(st.tau > 3 && st.tau < 100);
    assert_close(right_end(&L.g, phi), 1.0, 2 * L.g.dx[0], 0);
    for (long i = 0; i < L.g.N[0]; i++) {
        const double x = -2 + L.g.dx[0] * (double)i;
        if (fabs(x) > 0.55 && fabs(x) < 0.9) assert_close(ttr[L.g.offset + (size_t)i], log(0.5 / (1 - fabs(x))), 0.03, 0);
    }
    /* Without a tolerance an infinite horizon is refused. */
    L.pb.conv_tol = 0;
    assert_int_equal(hj_reach_solve(&L.pb, phi, ttr, &st, &err), HJ_EINVAL);
    hj_ls_free(phi), hj_ls_free(ttr);
}

/* A target given as a function constant in time and as an array: the same
 * bits.  A target that shrinks in time: a BRS (the set at tau = T only)
 * reaches the target as it is at the end, T - tau = 0 ... */
static double moving(double t, const double *x, void *c)
{
    (void)c;
    return fabs(x[0] - t) - 0.25; /* the interval [t - 0.25, t + 0.25] */
}

static void time_varying_target(void **state)
{
    (void)state;
    double a = 0, r = 0.5;
    hj_reach_dyn s;
    hj_reach_dyn_init(&s, 1, f1, &a);
    hj_reach_dyn_control_box(&s, G1, 1, (double[]){-0.5}, (double[]){0.5});
    hj_ls_grid g = grid1(81);
    double *phi = hj_ls_alloc(&g), *phi2 = hj_ls_alloc(&g), *target = hj_ls_alloc(&g);
    for (long i = 0; i < g.N[0]; i++) target[g.offset + (size_t)i] = fabs(-2 + g.dx[0] * (double)i) - r;
    hj_reach_problem pb;
    hj_reach_problem_init(&pb, &g, &s);
    pb.horizon = 1;
    pb.target.fn = interval, pb.target.ctx = &r;
    hj_error err;
    assert_int_equal(hj_reach_solve(&pb, phi, NULL, NULL, &err), HJ_OK);
    pb.target.fn = NULL, pb.target.array = target;
    assert_int_equal(hj_reach_solve(&pb, phi2, NULL, NULL, &err), HJ_OK);
    assert_int_equal(hj_ls_count_differ(&g, phi, phi2), 0);
    /* The moving interval: at forward time t it is [t - 0.25, t + 0.25];
     * from x at time 0, speed 0.5, T = 1: a BRS (reach it at t = 1, the
     * interval [0.75, 1.25]) is [0.25, 1.75]; the tube reaches it at
     * some t in [0, 1]: x + 0.5 t >= t - 0.25 and x - 0.5 t <= t + 0.25,
     * i.e. x in [-0.25, 1.75]. */
    pb.target.fn = moving, pb.target.array = NULL;
    pb.kind = HJ_REACH_BRS;
    assert_int_equal(hj_reach_solve(&pb, phi, NULL, NULL, &err), HJ_OK);
    for (long i = 0; i < g.N[0]; i++) {
        const double x = -2 + g.dx[0] * (double)i, v = phi[g.offset + (size_t)i];
        if (x < 0.25 - 0.06 || x > 1.75 + 0.06) assert_true(v > 0);
        if (x > 0.25 + 0.06 && x < 1.75 - 0.06) assert_true(v < 0);
    }
    pb.kind = HJ_REACH_BRT;
    assert_int_equal(hj_reach_solve(&pb, phi, NULL, NULL, &err), HJ_OK);
    for (long i = 0; i < g.N[0]; i++) {
        const double x = -2 + g.dx[0] * (double)i, v = phi[g.offset + (size_t)i];
        if (x < -0.25 - 0.06 || x > 1.75 + 0.06) assert_true(v > 0);
        if (x > -0.25 + 0.06 && x < 1.75 - 0.06) assert_true(v < 0);
    }
    hj_ls_free(phi), hj_ls_free(phi2), hj_ls_free(target);
}

/* Discounting phi_tau + ... + lambda phi = 0 with no motion: phi decays
 * as exp(-lambda tau) where the target does not bind (BRS). */
static void discount(void **state)
{
    (void)state;
    double a = 0, r = 0.5;
    hj_reach_dyn s;
    hj_reach_dyn_init(&s, 1, f1, &a);
    hj_ls_grid g = grid1(41);
    hj_reach_problem pb;
    hj_reach_problem_init(&pb, &g, &s);
    pb.kind = HJ_REACH_BRS;
    pb.horizon = 1;
    pb.discount = 0.5;
    pb.order = 3;
    pb.factor_cfl = 0.05; /* the decay's own limit is the only one: dt = 0.1 */
    pb.target.fn = interval, pb.target.ctx = &r;
    double *phi = hj_ls_alloc(&g);
    hj_error err;
    assert_int_equal(hj_reach_solve(&pb, phi, NULL, NULL, &err), HJ_OK);
    assert_close(phi[g.offset], 1.5 * exp(-0.5), 1e-4, 0);
    pb.discount = -1;
    assert_int_equal(hj_reach_solve(&pb, phi, NULL, NULL, &err), HJ_EINVAL);
    hj_ls_free(phi);
}

/* Dubins car reach-avoid on a period-given grid: one thread and two give
 * the same bits; the measure counts the full period. */
static void dub_f(double t, const double *x, double *o, void *c)
{
    (void)t, (void)c;
    o[0] = cos(x[2]), o[1] = sin(x[2]), o[2] = 0;
}
static void dub_G(double t, const double *x, double *o, void *c)
{
    (void)t, (void)x, (void)c;
    o[0] = 0, o[1] = 0, o[2] = 1;
}
static double disc(double t, const double *x, void *c)
{
    (void)t, (void)c;
    return hypot(x[0], x[1]) - 0.5;
}
static double box(double t, const double *x, void *c)
{
    (void)t, (void)c;
    return fmax(fabs(x[0] + 1) - 0.4, fabs(x[1] - 0.8) - 0.6);
}

static void dubins_threads_and_period(void **state)
{
    (void)state;
    hj_ls_grid g;
    const hj_ls_bc bc[3] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_PERIODIC, 0, 0}};
    assert_int_equal(hj_ls_grid_init_period(&g, 3, (double[]){-2, -2, 0}, (double[]){2, 2, 2 * HJ_PI},
                                            (long[]){21, 21, 16}, bc, NULL),
                     HJ_OK);
    hj_reach_dyn s;
    hj_reach_dyn_init(&s, 3, dub_f, NULL);
    hj_reach_dyn_control_box(&s, dub_G, 1, (double[]){-1}, (double[]){1});
    hj_reach_problem pb;
    hj_reach_problem_init(&pb, &g, &s);
    pb.target.fn = disc, pb.obstacle.fn = box, pb.horizon = 0.5;
    double *phi[2] = {hj_ls_alloc(&g), hj_ls_alloc(&g)}, *ttr[2] = {hj_ls_alloc(&g), hj_ls_alloc(&g)};
    hj_error err;
    for (int k = 0; k < 2; k++) {
#ifdef _OPENMP
        omp_set_num_threads(k + 1);
#endif
        assert_int_equal(hj_reach_solve(&pb, phi[k], ttr[k], NULL, &err), HJ_OK);
    }
    hj_test_one_thread();
    assert_int_equal(hj_ls_count_differ(&g, phi[0], phi[1]), 0);
    assert_int_equal(hj_ls_count_differ(&g, ttr[0], ttr[1]), 0);
    /* The target's cylinder over a full period: pi 0.5^2 2 pi, to the
     * accuracy of the piecewise linear interface on this grid. */
    double *cyl = hj_ls_alloc(&g), m;
    for (size_t r = 0; r < g.rows; r++) {
        long i[3];
        double x[3];
        const size_t k = hj_ls_row(&g, r, i);
        for (long j = 0; j < g.N[0]; j++) {
            i[0] = j;
            hj_ls_coord(&g, i, x);
            cyl[k + (size_t)j] = disc(0, x, NULL);
        }
    }
    assert_int_equal(hj_reach_measure(&g, cyl, &m, &err), HJ_OK);
    assert_close(m, HJ_PI * 0.25 * 2 * HJ_PI, 0, 0.03);
    for (int k = 0; k < 2; k++) hj_ls_free(phi[k]), hj_ls_free(ttr[k]);
    hj_ls_free(cyl);
}

/* The batched row callbacks and the kept derivatives give the bits of the
 * per-node callbacks: a 4-D system with a drift, a state-dependent control
 * matrix (box) and a disturbance (ball), an obstacle, the time-to-reach,
 * each dissipation, and a 3-D Dubins car with a discount (a sum of terms),
 * on 1 and 2 threads. */
static void f4(double t, const double *x, double *o, void *c)
{
    (void)c;
    o[0] = x[1], o[1] = -0.3 * x[0] + 0.1 * t, o[2] = x[3], o[3] = 0.2 * x[1] * x[2];
}
static void G4(double t, const double *x, double *o, void *c)
{
    (void)t, (void)c;
    const double m[8] = {0, 0, 1, 0.5 * x[0], 0, 0, x[2], 1};
    memcpy(o, m, sizeof m);
}
static void H4(double t, const double *x, double *o, void *c)
{
    (void)t, (void)c;
    const double m[8] = {0.1, 0, 0, 0.2, x[3], 0, 0, 0.3};
    memcpy(o, m, sizeof m);
}
static double ball4(double t, const double *x, void *c)
{
    (void)t, (void)c;
    return sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3]) - 0.6;
}
static double slab4(double t, const double *x, void *c)
{
    (void)c;
    return fabs(x[0] - 0.8 + 0.2 * t) - 0.15;
}

/* Solve pb with every (per_node, keep_derivs) and thread count; all must
 * give the bits of the per-node run without kept derivatives on one thread. */
static void same_bits_all_paths(hj_reach_problem *pb)
{
    const hj_ls_grid *g = pb->grid;
    double *ref = hj_ls_alloc(g), *rttr = hj_ls_alloc(g), *phi = hj_ls_alloc(g), *ttr = hj_ls_alloc(g);
    assert_non_null(ref), assert_non_null(rttr), assert_non_null(phi), assert_non_null(ttr);
    hj_error err;
    hj_reach_stats st, rst;
    pb->per_node = 1, pb->keep_derivs = 0, pb->general = 1; /* the kernel's paths (fused: below) */
    assert_int_equal(hj_reach_solve(pb, ref, rttr, &rst, &err), HJ_OK);
    assert_true(rst.steps > 2);
    for (int threads = 1; threads <= 2; threads++)
        for (int v = 0; v < 4; v++) {
            hj_test_threads(threads);
            pb->per_node = v & 1, pb->keep_derivs = v >> 1;
            assert_int_equal(hj_reach_solve(pb, phi, ttr, &st, &err), HJ_OK);
            assert_int_equal(st.steps, rst.steps);
            assert_int_equal(hj_ls_count_differ(g, ref, phi), 0);
            assert_int_equal(hj_ls_count_differ(g, rttr, ttr), 0);
        }
    hj_test_one_thread();
    hj_ls_free(ref), hj_ls_free(rttr), hj_ls_free(phi), hj_ls_free(ttr);
}

static void batched_rows_same_bits(void **state)
{
    (void)state;
    hj_ls_grid g;
    hj_ls_bc bc[4];
    for (int d = 0; d < 4; d++) bc[d] = (hj_ls_bc){HJ_LS_BC_EXTRAP_AWAY, 0, 0};
    assert_int_equal(hj_ls_grid_init(&g, 4, (double[]){-1, -1, -1, -1}, (double[]){1, 1, 1, 1},
                                     (long[]){11, 9, 8, 7}, bc, NULL),
                     HJ_OK);
    hj_reach_dyn s;
    hj_reach_dyn_init(&s, 4, f4, NULL);
    hj_reach_dyn_control_box(&s, G4, 2, (double[]){-1, -0.5}, (double[]){1, 0.7});
    hj_reach_dyn_disturbance_ball(&s, H4, 2, (double[]){0.05, 0}, 0.2);
    hj_reach_problem pb;
    hj_reach_problem_init(&pb, &g, &s);
    pb.target.fn = ball4, pb.obstacle.fn = slab4, pb.horizon = 0.3;
    const int diss[3] = {HJ_LS_LLF, HJ_LS_GLF, HJ_LS_LLLF};
    for (int k = 0; k < 3; k++) {
        pb.dissipation = diss[k];
        same_bits_all_paths(&pb);
    }
    pb.dissipation = HJ_LS_LLF, pb.scheme = HJ_LS_WENO5A, pb.order = 3;
    same_bits_all_paths(&pb);
    /* 3-D, periodic heading, a discount: the kernel's sum of terms. */
    hj_ls_grid g3;
    const hj_ls_bc bc3[3] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_PERIODIC, 0, 0}};
    assert_int_equal(hj_ls_grid_init_period(&g3, 3, (double[]){-2, -2, 0}, (double[]){2, 2, 2 * HJ_PI},
                                            (long[]){17, 15, 12}, bc3, NULL),
                     HJ_OK);
    hj_reach_dyn s3;
    hj_reach_dyn_init(&s3, 3, dub_f, NULL);
    hj_reach_dyn_control_box(&s3, dub_G, 1, (double[]){-1}, (double[]){1});
    hj_reach_problem p3;
    hj_reach_problem_init(&p3, &g3, &s3);
    p3.target.fn = disc, p3.obstacle.fn = box, p3.horizon = 0.5, p3.discount = 0.3;
    same_bits_all_paths(&p3);
}

/* The fused path (hj_reach_solve_fused) against the general path
 * (pb->general = 1) on one thread: the same steps and bits of the value
 * and the time-to-reach on 1 and 2 threads, and again with compact
 * (interior-only) arrays, for the problem pb as given with each of first
 * order upwinding and forward Euler, ENO2 and RK2, WENO5 and RK3.  tgt:
 * when not NULL, the target as an array on the grid, also given compact. */
static void fused_same_bits_one(hj_reach_problem *pb, const double *tgt);
static void fused_same_bits_n(hj_reach_problem *pb, const double *tgt, int nschemes)
{
    const int scheme[3] = {HJ_LS_UPWIND_FIRST, HJ_LS_ENO2, HJ_LS_WENO5A};
    for (int k = 0; k < nschemes; k++) {
        pb->scheme = scheme[k], pb->order = k + 1;
        fused_same_bits_one(pb, tgt);
    }
}
static void fused_same_bits(hj_reach_problem *pb, const double *tgt) { fused_same_bits_n(pb, tgt, 3); }
static void fused_same_bits_one(hj_reach_problem *pb, const double *tgt)
{
    const hj_ls_grid *g = pb->grid;
    double *ref = hj_ls_alloc(g), *rttr = hj_ls_alloc(g), *phi = hj_ls_alloc(g), *ttr = hj_ls_alloc(g);
    double *cphi = malloc(sizeof(double) * g->nodes), *cttr = malloc(sizeof(double) * g->nodes);
    double *ctgt = malloc(sizeof(double) * g->nodes);
    assert_non_null(ref), assert_non_null(rttr), assert_non_null(phi), assert_non_null(ttr);
    assert_non_null(cphi), assert_non_null(cttr), assert_non_null(ctgt);
    hj_error err;
    hj_reach_stats st, rst;
    pb->compact = 0;
    assert_true(hj_reach_fused_applies(pb));
    pb->general = 1;
    assert_false(hj_reach_fused_applies(pb));
    if (tgt) pb->target.array = tgt;
    assert_int_equal(hj_reach_solve(pb, ref, rttr, &rst, &err), HJ_OK);
    assert_true(rst.steps > 2);
    pb->general = 0;
    for (int run = 0; run < 3; run++) { /* one thread, then two; compact on the last */
        const int threads = run ? 2 : 1, compact = run == 2;
        hj_test_threads(threads);
            pb->compact = compact;
            if (tgt && compact)
                for (size_t r = 0; r < g->rows; r++) {
                    long i[HJ_LS_MAXDIM];
                    const size_t k = hj_ls_row(g, r, i);
                    memcpy(ctgt + r * (size_t)g->N[0], tgt + k, sizeof(double) * (size_t)g->N[0]);
                }
            if (tgt) pb->target.array = compact ? ctgt : tgt;
            assert_int_equal(hj_reach_solve(pb, compact ? cphi : phi, compact ? cttr : ttr, &st, &err), HJ_OK);
            assert_int_equal(st.steps, rst.steps);
            assert_true(st.tau == rst.tau);
            if (g->dim >= 4) assert_true(st.bytes < rst.bytes); /* row buffers dominate below */
            if (compact) /* back to the grid's layout for the comparison */
                for (size_t r = 0; r < g->rows; r++) {
                    long i[HJ_LS_MAXDIM];
                    const size_t k = hj_ls_row(g, r, i), kc = r * (size_t)g->N[0];
                    memcpy(phi + k, cphi + kc, sizeof(double) * (size_t)g->N[0]);
                    memcpy(ttr + k, cttr + kc, sizeof(double) * (size_t)g->N[0]);
                }
            assert_int_equal(hj_ls_count_differ(g, ref, phi), 0);
            assert_int_equal(hj_ls_count_differ(g, rttr, ttr), 0);
            if (!compact) assert_int_equal(memcmp(ref, phi, sizeof(double) * g->total), 0); /* ghosts too */
        }
    hj_test_one_thread();
    pb->compact = 0;
    hj_ls_free(ref), hj_ls_free(rttr), hj_ls_free(phi), hj_ls_free(ttr);
    free(cphi), free(cttr), free(ctgt);
}

/* Three double integrators: f = (v0, 0, v1, 0, v2, 0), G constant. */
static void f6(double t, const double *x, double *o, void *c)
{
    (void)t, (void)c;
    for (int k = 0; k < 6; k += 2) o[k] = x[k + 1], o[k + 1] = 0;
}
static void G6(double t, const double *x, double *o, void *c)
{
    (void)t, (void)x, (void)c;
    for (int q = 0; q < 18; q++) o[q] = q == 3 || q == 10 || q == 17;
}

/* A double integrator: f = (v, 0), G = (0, 1). */
static void f2d(double t, const double *x, double *o, void *c)
{
    (void)t, (void)c;
    o[0] = x[1], o[1] = 0;
}
static void G2d(double t, const double *x, double *o, void *c)
{
    (void)t, (void)x, (void)c;
    o[0] = 0, o[1] = 1;
}

static double box2d(double t, const double *x, void *c)
{
    (void)t, (void)c;
    return fmax(fabs(x[0]), fabs(x[1])) - 0.5;
}

/* The measure of a compact solve (interior-only arrays) equals that of
 * the same solve on grid arrays; a 4-D grid is refused. */
static void measure_compact(void **state)
{
    (void)state;
    hj_ls_grid g;
    const hj_ls_bc bc[2] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
    assert_int_equal(hj_ls_grid_init(&g, 2, (double[]){-2, -2}, (double[]){2, 2}, (long[]){41, 33}, bc, NULL), HJ_OK);
    hj_reach_dyn s;
    hj_reach_dyn_init(&s, 2, f2d, NULL);
    hj_reach_dyn_control_box(&s, G2d, 1, (double[]){-1}, (double[]){1});
    hj_reach_dyn_goal(&s, HJ_REACH_REACH);
    hj_reach_problem pb;
    hj_reach_problem_init(&pb, &g, &s);
    pb.target.fn = box2d, pb.horizon = 0.5;
    double *c = calloc(g.nodes, sizeof *c), *a = hj_ls_alloc(&g);
    assert_non_null(c), assert_non_null(a);
    pb.compact = 1;
    assert_int_equal(hj_reach_solve(&pb, c, NULL, NULL, NULL), HJ_OK);
    pb.compact = 0;
    assert_int_equal(hj_reach_solve(&pb, a, NULL, NULL, NULL), HJ_OK);
    double mc, ma;
    assert_int_equal(hj_reach_measure_compact(&g, c, &mc, NULL), HJ_OK);
    assert_int_equal(hj_reach_measure(&g, a, &ma, NULL), HJ_OK);
    assert_true(mc > 1.0);
    assert_memory_equal(&mc, &ma, sizeof mc);
    free(c), hj_ls_free(a);
    hj_ls_grid g4;
    hj_ls_bc bc4[4];
    for (int d = 0; d < 4; d++) bc4[d] = bc[0];
    assert_int_equal(hj_ls_grid_init(&g4, 4, (double[]){-1, -1, -1, -1}, (double[]){1, 1, 1, 1}, (long[]){5, 5, 5, 5},
                                     bc4, NULL),
                     HJ_OK);
    double z[625] = {0}, m4;
    hj_error err;
    assert_int_equal(hj_reach_measure_compact(&g4, z, &m4, &err), HJ_EINVAL);
    assert_non_null(strstr(err.msg, "1 to 3 only"));
}

static void fused_path_same_bits(void **state)
{
    (void)state;
    /* 4-D: drift, state-dependent control (box) and disturbance (ball)
     * matrices, a moving obstacle, a tube, each dissipation. */
    hj_ls_grid g;
    hj_ls_bc bc[6];
    for (int d = 0; d < 6; d++) bc[d] = (hj_ls_bc){HJ_LS_BC_EXTRAP_AWAY, 0, 0};
    assert_int_equal(hj_ls_grid_init(&g, 4, (double[]){-1, -1, -1, -1}, (double[]){1, 1, 1, 1},
                                     (long[]){11, 9, 8, 7}, bc, NULL),
                     HJ_OK);
    hj_reach_dyn s;
    hj_reach_dyn_init(&s, 4, f4, NULL);
    hj_reach_dyn_control_box(&s, G4, 2, (double[]){-1, -0.5}, (double[]){1, 0.7});
    hj_reach_dyn_disturbance_ball(&s, H4, 2, (double[]){0.05, 0}, 0.2);
    hj_reach_problem pb;
    hj_reach_problem_init(&pb, &g, &s);
    pb.target.fn = ball4, pb.obstacle.fn = slab4, pb.horizon = 0.3;
    fused_same_bits(&pb, NULL);
    pb.dissipation = HJ_LS_GLF; /* the bounds do not depend on the gradient */
    assert_true(hj_reach_fused_applies(&pb));
    pb.dissipation = HJ_LS_LLLF;
    assert_true(hj_reach_fused_applies(&pb));
    /* 3-D Dubins car, constant G, every boundary condition on some face,
     * a set (BRS) and a tube with a convergence stop. */
    const hj_ls_bc bcs[2][3] = {
        {{HJ_LS_BC_EXTRAP_TOWARD, 0, 0}, {HJ_LS_BC_NEUMANN, 0.3, -0.2}, {HJ_LS_BC_PERIODIC, 0, 0}},
        {{HJ_LS_BC_PERIODIC, 0, 0}, {HJ_LS_BC_DIRICHLET, 1, 2}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}}};
    for (int b = 0; b < 2; b++) {
        hj_ls_grid g3;
        assert_int_equal(hj_ls_grid_init_period(&g3, 3, (double[]){-2, -2, 0}, (double[]){2, 2, 2 * HJ_PI},
                                                (long[]){17, 15, 12}, bcs[b], NULL),
                         HJ_OK);
        hj_reach_dyn s3;
        hj_reach_dyn_init(&s3, 3, dub_f, NULL);
        hj_reach_dyn_control_box(&s3, dub_G, 1, (double[]){-1}, (double[]){1});
        s3.G_const = 1;
        hj_reach_problem p3;
        hj_reach_problem_init(&p3, &g3, &s3);
        p3.target.fn = disc, p3.obstacle.fn = box, p3.horizon = 0.5;
        p3.kind = b ? HJ_REACH_BRT : HJ_REACH_BRS;
        fused_same_bits(&p3, NULL);
        if (b) {
            p3.horizon = INFINITY, p3.conv_tol = 0.5;
            fused_same_bits_n(&p3, NULL, 1);
        }
    }
    /* 6-D: three double integrators, the target as an array. */
    hj_ls_grid g6;
    double lo[6], hi[6];
    long N[6];
    for (int d = 0; d < 6; d++) lo[d] = -1.5, hi[d] = 1.5, N[d] = 4 + d % 2;
    assert_int_equal(hj_ls_grid_init(&g6, 6, lo, hi, N, bc, NULL), HJ_OK);
    double *tgt = hj_ls_alloc(&g6);
    assert_non_null(tgt);
    for (size_t r = 0; r < g6.rows; r++) {
        long i[6];
        double x[6];
        const size_t k = hj_ls_row(&g6, r, i);
        for (long j = 0; j < g6.N[0]; j++) {
            i[0] = j;
            hj_ls_coord(&g6, i, x);
            double m = -INFINITY;
            for (int d = 0; d < 6; d++) m = fmax(m, fabs(x[d]) - 0.5);
            tgt[k + (size_t)j] = m;
        }
    }
    hj_reach_dyn s6;
    hj_reach_dyn_init(&s6, 6, f6, NULL);
    hj_reach_dyn_control_box(&s6, G6, 3, (double[]){-1, -1, -1}, (double[]){1, 1, 1});
    s6.G_const = 1;
    hj_reach_problem p6;
    hj_reach_problem_init(&p6, &g6, &s6);
    p6.kind = HJ_REACH_BRS, p6.horizon = 0.4;
    fused_same_bits_n(&p6, tgt, 1);
    p6.scheme = HJ_LS_WENO5A, p6.order = 3;
    fused_same_bits_one(&p6, tgt);
    hj_ls_free(tgt);
    /* 2-D double integrator with 40 nodes a row: a plane of 31 rows is cut
     * into blocks of 12, 12 and 7 rows; each boundary condition along
     * dimension 1 and along 0; and 1-D (one row). */
    const int bc2d[3][2] = {{HJ_LS_BC_PERIODIC, HJ_LS_BC_DIRICHLET},
                            {HJ_LS_BC_NEUMANN, HJ_LS_BC_EXTRAP_TOWARD},
                            {HJ_LS_BC_EXTRAP_AWAY, HJ_LS_BC_PERIODIC}};
    for (int b = 0; b < 3; b++) {
        hj_ls_grid g2;
        const hj_ls_bc bc2[2] = {{bc2d[b][0], -0.3, 0.2}, {bc2d[b][1], 0.5, -0.4}};
        assert_int_equal(hj_ls_grid_init(&g2, 2, (double[]){-1.5, -1.5}, (double[]){1.5, 1.5}, (long[]){40, 31}, bc2,
                                         NULL),
                         HJ_OK);
        hj_reach_dyn s2;
        hj_reach_dyn_init(&s2, 2, f2d, NULL);
        hj_reach_dyn_control_box(&s2, G2d, 1, (double[]){-1}, (double[]){1});
        s2.G_const = b & 1;
        hj_reach_problem p2;
        hj_reach_problem_init(&p2, &g2, &s2);
        p2.target.fn = disc, p2.obstacle.fn = box, p2.horizon = 0.3;
        fused_same_bits_n(&p2, NULL, b == 0 ? 3 : 1);
    }
    double a1 = -0.5, r1 = 0.5;
    hj_ls_grid g1 = grid1(41);
    hj_reach_dyn s1;
    hj_reach_dyn_init(&s1, 1, f1, &a1);
    hj_reach_dyn_control_box(&s1, G1, 1, (double[]){-1}, (double[]){1});
    hj_reach_problem p1;
    hj_reach_problem_init(&p1, &g1, &s1);
    p1.target.fn = interval, p1.target.ctx = &r1, p1.horizon = 0.5;
    fused_same_bits_n(&p1, NULL, 3);
    /* Compact arrays need the fused path. */
    double *phi = malloc(sizeof(double) * g.nodes);
    hj_error err;
    pb.compact = 1, pb.discount = 0.1;
    assert_false(hj_reach_fused_applies(&pb));
    assert_int_equal(hj_reach_solve(&pb, phi, NULL, NULL, &err), HJ_EINVAL);
    assert_int_equal(hj_reach_solve_fused(&pb, phi, NULL, NULL, &err), HJ_EINVAL);
    pb.discount = 0, pb.target.fn = NULL; /* checked as hj_reach_solve checks */
    assert_int_equal(hj_reach_solve_fused(&pb, phi, NULL, NULL, &err), HJ_EINVAL);
    assert_non_null(strstr(err.msg, "no target"));
    free(phi);
}

/* Problems refused before any work: no target, a zero horizon, a grid of
 * another dimension, a measure with two periodic dimensions. */
static void invalid_problems(void **state)
{
    (void)state;
    double a = 0, r = 0.5;
    hj_reach_dyn s;
    hj_reach_dyn_init(&s, 1, f1, &a);
    hj_ls_grid g = grid1(11);
    hj_reach_problem pb;
    hj_reach_problem_init(&pb, &g, &s);
    double *phi = hj_ls_alloc(&g);
    hj_error err;
    pb.horizon = 1;
    assert_int_equal(hj_reach_solve(&pb, phi, NULL, NULL, &err), HJ_EINVAL); /* no target */
    pb.target.fn = interval, pb.target.ctx = &r, pb.horizon = 0;
    assert_int_equal(hj_reach_solve(&pb, phi, NULL, NULL, &err), HJ_EINVAL);
    pb.horizon = 1;
    /* A CFL factor beyond the integrators' stable range (0, 1], on both
     * paths (the fused one took it as given). */
    pb.factor_cfl = 5;
    assert_int_equal(hj_reach_solve(&pb, phi, NULL, NULL, &err), HJ_EINVAL);
    assert_non_null(strstr(err.msg, "(0, 1]"));
    assert_int_equal(hj_reach_solve_fused(&pb, phi, NULL, NULL, &err), HJ_EINVAL);
    pb.factor_cfl = 0.5;
    /* An unknown dissipation on both paths (the fused one never reads it
     * and returned HJ_OK), an unknown scheme or RK order, a NULL value
     * array (it crashed), a NULL problem. */
    for (int general = 0; general < 2; general++) {
        pb.general = general;
        pb.dissipation = 77;
        assert_int_equal(hj_reach_solve(&pb, phi, NULL, NULL, &err), HJ_EINVAL);
        assert_non_null(strstr(err.msg, "unknown dissipation 77"));
        pb.dissipation = HJ_LS_LLF, pb.scheme = HJ_LS_NSCHEMES;
        assert_int_equal(hj_reach_solve(&pb, phi, NULL, NULL, &err), HJ_EINVAL);
        pb.scheme = HJ_LS_ENO2, pb.order = 4;
        assert_int_equal(hj_reach_solve(&pb, phi, NULL, NULL, &err), HJ_EINVAL);
        pb.order = 2;
        assert_int_equal(hj_reach_solve(&pb, NULL, NULL, NULL, &err), HJ_EINVAL);
    }
    pb.general = 0;
    assert_int_equal(hj_reach_solve_fused(&pb, NULL, NULL, NULL, &err), HJ_EINVAL);
    assert_int_equal(hj_reach_solve(NULL, phi, NULL, NULL, &err), HJ_EINVAL);
    double m0;
    assert_int_equal(hj_reach_measure(&g, NULL, &m0, &err), HJ_EINVAL);
    assert_int_equal(hj_reach_measure_compact(&g, NULL, &m0, &err), HJ_EINVAL);
    /* A finite horizon beyond 2^52 steps: tau + dt stops changing before
     * it is reached, and the run never ended. */
    hj_reach_dyn_control_box(&s, G1, 1, (double[]){-1}, (double[]){1});
    pb.horizon = 1e300;
    for (int general = 0; general < 2; general++) {
        pb.general = general;
        assert_int_equal(hj_reach_solve(&pb, phi, NULL, NULL, &err), HJ_EINVAL);
        assert_non_null(strstr(err.msg, "2^52 steps"));
    }
    /* Also with a convergence tolerance, which could end the run sooner
     * (then at the infinite horizon's limit): refused at the first step's
     * bound, the message saying what to give instead. */
    pb.conv_tol = 1e-6;
    for (int general = 0; general < 2; general++) {
        hj_reach_stats st;
        pb.general = general;
        assert_int_equal(hj_reach_solve(&pb, phi, NULL, &st, &err), HJ_EINVAL);
        assert_has(err.msg, "2^52 steps");
        assert_has(err.msg, "conv_tol could stop it sooner, but only at the infinite horizon's limit: give horizon = "
                            "INFINITY");
        assert_int_equal(st.steps, 0);
    }
    pb.conv_tol = 0;
    pb.general = 0;
    pb.horizon = 1;
    s.nx = 2;
    assert_int_equal(hj_reach_solve(&pb, phi, NULL, NULL, &err), HJ_EINVAL);
    assert_non_null(strstr(err.msg, "2-D dynamics on a 1-D grid"));
    hj_ls_free(phi);
    hj_ls_grid g2;
    const hj_ls_bc bc[2] = {{HJ_LS_BC_PERIODIC, 0, 0}, {HJ_LS_BC_PERIODIC, 0, 0}};
    assert_int_equal(hj_ls_grid_init(&g2, 2, (double[]){0, 0}, (double[]){1, 1}, (long[]){5, 5}, bc, NULL), HJ_OK);
    double *b = hj_ls_alloc(&g2), m;
    assert_int_equal(hj_reach_measure(&g2, b, &m, &err), HJ_EINVAL);
    hj_ls_free(b);
}

/* NaN beyond x = 0.7 (nodes at -2 + 0.4 i: the first is 0.8). */
static double nan_right(double t, const double *x, void *c)
{
    (void)t, (void)c;
    return x[0] > 0.7 ? NAN : fabs(x[0]) - 0.5;
}

/* A NaN target names its first node on both paths (the message said "at
 * a node"), as the API guide promises for every NaN input. */
static void nan_target_names_node(void **state)
{
    (void)state;
    double a = 0;
    hj_reach_dyn s;
    hj_reach_dyn_init(&s, 1, f1, &a);
    hj_reach_dyn_control_box(&s, G1, 1, (double[]){-1}, (double[]){1});
    hj_ls_grid g = grid1(11);
    hj_reach_problem pb;
    hj_reach_problem_init(&pb, &g, &s);
    pb.target.fn = nan_right, pb.horizon = 1;
    double *phi = hj_ls_alloc(&g);
    for (int general = 0; general < 2; general++) {
        hj_error err;
        pb.general = general;
        assert_int_equal(hj_reach_solve(&pb, phi, NULL, NULL, &err), HJ_ENONFINITE);
        assert_string_equal(err.msg, "reach: the target is NaN at x = (0.8)");
    }
    hj_ls_free(phi);
}

/* x' = a(t): a speed so small at t > 1e19 that the first step of the
 * horizon T = 1e20 ends 1e9 short of it (more than the round-off that
 * ends a run, 100 eps T), then 1: a step of 0.05 that tau ~ 1e20 (ulp
 * 16384) cannot take, with 2e10 steps left (the 2^52 check passes). */
static void f_slow_then_fast(double t, const double *x, double *o, void *c)
{
    (void)x, (void)c;
    o[0] = t > 1e19 ? 0.05 / (1e20 - 1e9) : 1;
}

/* A step that leaves tau as it is: an error on both paths (the fused one
 * ran for ever; the alarm ends the test there). */
static void step_does_not_advance(void **state)
{
    (void)state;
    double r = 0.5;
    hj_reach_dyn s;
    hj_reach_dyn_init(&s, 1, f_slow_then_fast, NULL);
    hj_ls_grid g = grid1(41);
    hj_reach_problem pb;
    hj_reach_problem_init(&pb, &g, &s);
    pb.target.fn = interval, pb.target.ctx = &r;
    pb.horizon = 1e20, pb.scheme = HJ_LS_UPWIND_FIRST, pb.order = 1;
    double *phi = hj_ls_alloc(&g);
    alarm(60);
    for (int general = 0; general <= 1; general++) {
        hj_error err;
        hj_reach_stats st;
        pb.general = general;
        assert_int_equal(hj_reach_solve(&pb, phi, NULL, &st, &err), HJ_EINVAL);
        assert_has(err.msg, "does not advance");
        assert_int_equal(st.steps, 1);
    }
    alarm(0);
    hj_ls_free(phi);
}

/* A horizon on a small time scale is integrated: T = 1e-20 takes one step
 * of 1e-20 on both paths (the end-of-span rule was 100 eps absolute below
 * |T| = 1, so such a run took no step and reported tau = 0). */
static void tiny_horizon_steps(void **state)
{
    (void)state;
    line1 L;
    line1_init(&L, 1, 1, 41);
    L.pb.horizon = 1e-20;
    double *phi = hj_ls_alloc(&L.g);
    for (int general = 0; general <= 1; general++) {
        hj_error err;
        hj_reach_stats st;
        L.pb.general = general;
        assert_int_equal(hj_reach_solve(&L.pb, phi, NULL, &st, &err), HJ_OK);
        assert_int_equal(st.steps, 1);
        assert_true(st.tau == 1e-20);
    }
    hj_ls_free(phi);
}

typedef struct {
    long calls, last_steps, stop_at;
    double last_tau, horizon;
    int order_ok;
} progress_log;

static int log_progress(double tau, double horizon, long steps, void *ctx)
{
    progress_log *l = ctx;
    l->order_ok &= steps > l->last_steps && tau >= l->last_tau;
    l->calls++, l->last_steps = steps, l->last_tau = tau, l->horizon = horizon;
    return steps == l->stop_at ? 42 : 0;
}

/* The progress callback on both paths: every k-th step, with tau, the
 * horizon as given and the step count; a nonzero return stops the solve
 * with that code, the value then that of the step (the same bits on
 * both paths). */
static void progress_callback(void **state)
{
    (void)state;
    line1 L;
    line1_init(&L, 1, 1, 41);
    double *phi[2] = {hj_ls_alloc(&L.g), hj_ls_alloc(&L.g)}, *ttr = hj_ls_alloc(&L.g);
    for (int inf = 0; inf <= 1; inf++)
        for (long every = 1; every <= 7; every = 2 * every + 1) /* 1, 3, 7 */
            for (int general = 0; general <= 1; general++) {
                hj_reach_stats st;
                hj_error err;
                progress_log l = {0, 0, -1, 0, 0, 1};
                L.pb.general = general, L.pb.progress = log_progress, L.pb.progress_ctx = &l, L.pb.progress_every = every;
                L.pb.horizon = inf ? INFINITY : 1, L.pb.conv_tol = inf ? 1e-6 : 0;
                assert_int_equal(hj_reach_solve(&L.pb, phi[general], ttr, &st, &err), HJ_OK);
                assert_true(st.steps > 6);
                /* every k-th step and the step that ends the run */
                assert_int_equal(l.calls, st.steps / every + (st.steps % every != 0));
                assert_true(l.order_ok);
                assert_int_equal(l.last_steps, st.steps);
                assert_close(l.last_tau, st.tau, 0, 0);
                assert_true(l.horizon == L.pb.horizon);
                /* stopped at the first call from step 6 on */
                const long stop = every * ((6 + every - 1) / every);
                char after[32];
                snprintf(after, sizeof after, "after %ld steps", stop);
                l = (progress_log){0, 0, stop, 0, 0, 1};
                assert_int_equal(hj_reach_solve(&L.pb, phi[general], ttr, &st, &err), 42);
                assert_int_equal(err.code, 42);
                assert_has(err.msg, "stopped by the progress callback");
                assert_has(err.msg, after);
                assert_int_equal(st.steps, stop);
                assert_false(st.converged);
                assert_close(l.last_tau, st.tau, 0, 0);
                assert_true(st.tau > 0 && st.tau < 1);
            }
    for (size_t k = 0; k < L.g.total; k++) assert_memory_equal(&phi[0][k], &phi[1][k], sizeof(double));
    hj_ls_free(phi[0]), hj_ls_free(phi[1]), hj_ls_free(ttr);
}

/* x' = inf beyond x = 1 (nodes at -2 + 0.1 i). */
static void f_inf_right(double t, const double *x, double *o, void *c)
{
    (void)t, (void)c;
    o[0] = x[0] > 1 ? INFINITY : 0;
}

/* The fused path's messages name the backward time tau as such (they said
 * t = for it, the forward time's name elsewhere in the module). */
static void fused_messages_say_tau(void **state)
{
    (void)state;
    double r = 0.5;
    hj_reach_dyn s;
    hj_reach_dyn_init(&s, 1, f_inf_right, NULL);
    hj_ls_grid g = grid1(41);
    hj_reach_problem pb;
    hj_reach_problem_init(&pb, &g, &s);
    pb.target.fn = interval, pb.target.ctx = &r, pb.horizon = 1;
    double *phi = hj_ls_alloc(&g);
    hj_error err;
    assert_int_equal(hj_reach_solve_fused(&pb, phi, NULL, NULL, &err), HJ_ENONFINITE);
    assert_has(err.msg, "non-finite value at x = (1.1), tau = 0");
    hj_ls_free(phi);
}

/* A problem whose arrays do not fit in the machine's memory is refused
 * before any allocation, with what it needs and what there is: malloc
 * alone said "out of memory" only when one block was larger than memory
 * and swap, and a solve whose own arrays fit but not with the caller's was
 * started.  6-D, compact, a grid laid out only (no array on it), with the
 * solver's own two arrays (RK2) over twice the physical memory. */
static double ball6_big(double t, const double *x, void *c)
{
    (void)t, (void)c;
    return sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) - 0.5;
}
static void f6_big(double t, const double *x, double *o, void *c)
{
    (void)t, (void)c;
    for (int i = 0; i < 3; i++) o[i] = x[3 + i], o[3 + i] = 0;
}
static void G6_big(double t, const double *x, double *o, void *c)
{
    (void)t, (void)x, (void)c;
    memset(o, 0, 18 * sizeof *o);
    for (int i = 0; i < 3; i++) o[(3 + i) * 3 + i] = 1;
}

static void too_large_refused(void **state)
{
    (void)state;
    const double mem = hj_sys_physical_memory();
    if (!(mem > 0)) skip();
    long n = 8;
    while (16 * pow((double)n, 6) <= 2 * mem) n++;
    hj_ls_grid g;
    hj_ls_bc bc[6];
    double lo[6], hi[6];
    long N[6];
    for (int d = 0; d < 6; d++) bc[d] = (hj_ls_bc){HJ_LS_BC_EXTRAP_AWAY, 0, 0}, lo[d] = -1, hi[d] = 1, N[d] = n;
    assert_int_equal(hj_ls_grid_layout(&g, 6, lo, hi, N, bc, NULL), HJ_OK);
    hj_reach_dyn s;
    hj_reach_dyn_init(&s, 6, f6_big, NULL);
    hj_reach_dyn_control_ball(&s, G6_big, 3, (double[]){0, 0, 0}, 1);
    hj_reach_problem pb;
    hj_reach_problem_init(&pb, &g, &s);
    pb.target.fn = ball6_big, pb.horizon = 0.5, pb.compact = 1;
    double phi[1], ttr[1]; /* never reached: the refusal comes first */
    hj_error err;
    assert_int_equal(hj_reach_solve(&pb, phi, NULL, NULL, &err), HJ_ENOMEM);
    assert_has(err.msg, "the machine has");
    /* Its own arrays fit (two values per node, compact, RK2), not with the
     * caller's value and time-to-reach (two more): n^6 between mem / 32
     * and mem / 16 (a 6-D grid's n^6 grows by less than 2 per step in n
     * from n = 9 on). */
    n = 8;
    while (32 * pow((double)n, 6) <= 1.1 * mem) n++;
    if (!(16 * pow((double)n, 6) < 0.9 * mem)) skip();
    for (int d = 0; d < 6; d++) N[d] = n;
    assert_int_equal(hj_ls_grid_layout(&g, 6, lo, hi, N, bc, NULL), HJ_OK);
    assert_true((double)hj_reach_fused_bytes(&pb, 1) < 0.95 * mem);
    assert_int_equal(hj_reach_solve(&pb, phi, ttr, NULL, &err), HJ_ENOMEM);
    assert_has(err.msg, "its own arrays and the caller's");
}

/* The general path (the kernel's term and integrator) holds the whole
 * solve against the machine's memory as the fused path does: it checked
 * one array (hj_ls_grid_init) and started a solve whose own arrays, or
 * its own with the caller's value and time-to-reach, exceed it.  1-D,
 * a grid laid out only, the node count set from the memory; the target is
 * NaN, so a solve that is not refused before it reads the target fails
 * with HJ_ENONFINITE instead (and the caller's one-double arrays are
 * never written). */
static double nan_target(double t, const double *x, void *c)
{
    (void)t, (void)x, (void)c;
    return NAN;
}
static void general_too_large_refused(void **state)
{
    (void)state;
    const double mem = hj_sys_physical_memory();
    if (!(mem > 0)) skip();
    double a = 0;
    hj_reach_dyn s;
    hj_reach_dyn_init(&s, 1, f1, &a);
    hj_reach_dyn_control_box(&s, G1, 1, (double[]){-1}, (double[]){1});
    const double lo = -2, hi = 2;
    const hj_ls_bc bc = {HJ_LS_BC_EXTRAP_AWAY, 0, 0};
    /* One array on the grid of half the memory: RK2's three, the kept
     * derivatives and the row buffer are beyond it on their own. */
    long n = (long)(mem / 2 / sizeof(double));
    hj_ls_grid g;
    assert_int_equal(hj_ls_grid_layout(&g, 1, &lo, &hi, &n, &bc, NULL), HJ_OK);
    hj_reach_problem pb;
    hj_reach_problem_init(&pb, &g, &s);
    pb.target.fn = nan_target, pb.horizon = 0.5, pb.general = 1;
    assert_true((double)hj_reach_general_bytes(&pb, 1) > 2 * mem);
    double phi[1], ttr[1];
    hj_error err;
    assert_int_equal(hj_reach_solve(&pb, phi, NULL, NULL, &err), HJ_ENOMEM);
    assert_has(err.msg, "the machine has");
    /* Per node, first order, no kept derivatives: its own two arrays (0.8
     * of the memory) fit, not with the caller's value and time-to-reach
     * (two more). */
    n = (long)(0.4 * mem / sizeof(double)) - 2 * HJ_LS_GHOST;
    assert_int_equal(hj_ls_grid_layout(&g, 1, &lo, &hi, &n, &bc, NULL), HJ_OK);
    pb.per_node = 1, pb.keep_derivs = 0, pb.order = 1;
    assert_false(hj_reach_fused_applies(&pb));
    assert_true((double)hj_reach_general_bytes(&pb, 1) < 0.95 * mem);
    assert_int_equal(hj_reach_solve(&pb, phi, ttr, NULL, &err), HJ_ENOMEM);
    assert_has(err.msg, "its own arrays and the caller's");
    /* The same problem on the fused path is refused by the same check. */
    pb.per_node = 0, pb.general = 0;
    assert_true(hj_reach_fused_applies(&pb));
    assert_int_equal(hj_reach_solve(&pb, phi, ttr, NULL, &err), HJ_ENOMEM);
    assert_has(err.msg, "its own arrays and the caller's");
}

HJ_TEST_MAIN_ONE_THREAD("reach", NULL, NULL, cmocka_unit_test(hamiltonian_brute_force), cmocka_unit_test(partial_bounds_exact),
             cmocka_unit_test(invalid_systems), cmocka_unit_test(no_motion), cmocka_unit_test(tube_and_time_to_reach),
             cmocka_unit_test(convergence_stop), cmocka_unit_test(time_varying_target), cmocka_unit_test(discount),
             cmocka_unit_test(dubins_threads_and_period), cmocka_unit_test(batched_rows_same_bits),
             cmocka_unit_test(fused_path_same_bits), cmocka_unit_test(measure_compact),
             cmocka_unit_test(invalid_problems), cmocka_unit_test(nan_target_names_node),
             cmocka_unit_test(step_does_not_advance), cmocka_unit_test(progress_callback),
             cmocka_unit_test(fused_messages_say_tau), cmocka_unit_test(too_large_refused),
             cmocka_unit_test(general_too_large_refused), cmocka_unit_test(tiny_horizon_steps))
