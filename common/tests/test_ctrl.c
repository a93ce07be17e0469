/* Unit tests of common/hj_ctrl: multilinear interpolation and its
 * gradient (exact on multilinear data, periodic wrap), the optimal inputs
 * from a grid value, and closed-loop RK4 runs with known arrival times. */
#include "hj_test.h"

#include <stdlib.h>
#include <string.h>

#include "hj_ctrl.h"
#include "hj_math.h"

static double bilinear(const double *x) { return 1 + 2 * x[0] - x[1] + 0.5 * x[0] * x[1]; }

static void fill(const hj_ls_grid *g, double *a, double (*f)(const double *))
{
    for (size_t r = 0; r < g->rows; r++) {
        long i[HJ_LS_MAXDIM];
        double x[HJ_LS_MAXDIM];
        const size_t k = hj_ls_row(g, r, i);
        for (long j = 0; j < g->N[0]; j++) {
            i[0] = j;
            hj_ls_coord(g, i, x);
            a[k + (size_t)j] = f(x);
        }
    }
}

static void interpolation_exact(void **state)
{
    (void)state;
    hj_ls_grid g;
    const hj_ls_bc bc[2] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
    assert_int_equal(hj_ls_grid_init(&g, 2, (double[]){-1, -2}, (double[]){1, 2}, (long[]){11, 21}, bc, NULL), HJ_OK);
    double *a = hj_ls_alloc(&g);
    fill(&g, a, bilinear);
    const double xs[4][2] = {{0.13, -0.77}, {-0.99, 1.999}, {1, 2}, {0.5, 0.5}};
    for (int k = 0; k < 4; k++) {
        assert_close(hj_ctrl_value(&g, a, xs[k]), bilinear(xs[k]), 1e-13, 0);
        double p[2];
        hj_ctrl_gradient(&g, a, (double[]){0.31, 0.47}, p);
        /* The central difference of a bilinear function is its derivative. */
        assert_close(p[0], 2 + 0.5 * 0.47, 1e-13, 0);
        assert_close(p[1], -1 + 0.5 * 0.31, 1e-13, 0);
    }
    /* Outside the box the value is clamped to the nearest boundary point. */
    assert_close(hj_ctrl_value(&g, a, (double[]){3, 0}), bilinear((double[]){1, 0}), 1e-13, 0);
    hj_ls_free(a);
}

static double wave(const double *x) { return cos(x[0]); }

static void interpolation_periodic(void **state)
{
    (void)state;
    hj_ls_grid g;
    const hj_ls_bc bc = {HJ_LS_BC_PERIODIC, 0, 0};
    assert_int_equal(hj_ls_grid_init_period(&g, 1, (double[]){0}, (double[]){2 * HJ_PI}, (long[]){64}, &bc, NULL),
                     HJ_OK);
    double *a = hj_ls_alloc(&g);
    fill(&g, a, wave);
    /* Between the last node and the period's end, and one period away. */
    const double th = 2 * HJ_PI - 0.5 * g.dx[0];
    assert_close(hj_ctrl_value(&g, a, &th), cos(th), 2e-3, 0);
    const double th2 = th - 4 * HJ_PI;
    assert_close(hj_ctrl_value(&g, a, &th2), hj_ctrl_value(&g, a, &th), 1e-12, 0);
    hj_ls_free(a);
}

/* x' = u, |u| <= 1, value |x| - 0.5: from 1.2 the target is reached at
 * t = 0.7 (first step end at or after it). */
static void one_g(double t, const double *x, double *o, void *c)
{
    (void)t, (void)x, (void)c;
    o[0] = 1;
}
static double absx(const double *x) { return fabs(x[0]) - 0.5; }
static double target_fn(double t, const double *x, void *c)
{
    (void)t, (void)c;
    return fabs(x[0]) - 0.5;
}
static double obstacle_fn(double t, const double *x, void *c)
{
    (void)t, (void)c;
    return fabs(x[0] - 1.0) - 0.05; /* around 1.0 */
}

/* x' = u, |u| <= 1 on [-2, 2] (41 nodes), the value |x| - 0.5 (an array
 * the caller frees). */
static double *setup_1d(hj_ls_grid *g, hj_reach_dyn *s)
{
    const hj_ls_bc bc = {HJ_LS_BC_EXTRAP_AWAY, 0, 0};
    assert_int_equal(hj_ls_grid_init(g, 1, (double[]){-2}, (double[]){2}, (long[]){41}, &bc, NULL), HJ_OK);
    double *a = hj_ls_alloc(g);
    assert_non_null(a);
    fill(g, a, absx);
    hj_reach_dyn_init(s, 1, NULL, NULL);
    hj_reach_dyn_control_box(s, one_g, 1, (double[]){-1}, (double[]){1});
    return a;
}

static void simulate_reaches(void **state)
{
    (void)state;
    hj_ls_grid g;
    hj_reach_dyn s;
    double *a = setup_1d(&g, &s);
    double u;
    hj_ctrl_optimal(&s, &g, a, 0, (double[]){1.2}, &u, NULL);
    assert_close(u, -1, 0, 0);
    hj_ctrl_sim_opts o;
    hj_ctrl_sim_defaults(&o);
    o.dt = 0.01, o.t_max = 2;
    o.target.fn = target_fn, o.obstacle.fn = obstacle_fn;
    hj_ctrl_traj tr;
    hj_error err;
    assert_int_equal(hj_ctrl_traj_alloc(&tr, 1, 1, 0, 200, &err), HJ_OK);
    assert_int_equal(hj_ctrl_simulate(&s, &g, a, (double[]){1.2}, &o, &tr, &err), HJ_OK);
    assert_true(tr.reached);
    assert_close(tr.t[tr.n - 1], 0.7, 1e-9, 0);
    assert_close(tr.x[tr.n - 1], 0.5, 1e-9, 0);
    assert_close(tr.value[0], 0.7, 1e-12, 0);
    assert_true(tr.collided); /* it crossed 1.0 */
    assert_close(tr.min_obstacle, -0.05, 1e-9, 0);
    /* An avoiding controller (max) from inside stays away: never reaches. */
    hj_reach_dyn_goal(&s, HJ_REACH_AVOID);
    assert_int_equal(hj_ctrl_simulate(&s, &g, a, (double[]){0.6}, &o, &tr, &err), HJ_OK);
    assert_false(tr.reached);
    assert_close(tr.t[tr.n - 1], 2, 1e-12, 0);
    assert_int_equal(tr.n, 201);
    /* Too short a trajectory for the run: refused. */
    o.t_max = 3;
    assert_int_equal(hj_ctrl_simulate(&s, &g, a, (double[]){0.6}, &o, &tr, &err), HJ_EINVAL);
    hj_ctrl_traj_free(&tr);
    hj_ls_free(a);
}

/* Sizes and arguments no run can use are refused with a message: a cap
 * whose byte count wrapped around size_t gave tiny arrays and HJ_OK, an
 * input count beyond HJ_REACH_MAXIN and an unknown disturbance mode were
 * taken, NULL arguments crashed. */
static void bad_trajectories_and_options(void **state)
{
    (void)state;
    hj_ctrl_traj tr;
    hj_error err;
    assert_int_equal(hj_ctrl_traj_alloc(&tr, 2, 2, 0, (1L << 61) - 1, &err), HJ_ENOMEM);
    assert_null(tr.t);
    assert_int_equal(hj_ctrl_traj_alloc(&tr, 2, HJ_REACH_MAXIN + 1, 0, 10, &err), HJ_EINVAL);
    assert_int_equal(hj_ctrl_traj_alloc(&tr, 2, 1, HJ_REACH_MAXIN + 1, 10, &err), HJ_EINVAL);
    assert_int_equal(hj_ctrl_traj_alloc(&tr, HJ_LS_MAXDIM + 1, 1, 0, 10, &err), HJ_EINVAL);
    hj_ls_grid g;
    hj_reach_dyn s;
    double *a = setup_1d(&g, &s);
    hj_ctrl_sim_opts o;
    hj_ctrl_sim_defaults(&o);
    assert_int_equal(hj_ctrl_traj_alloc(&tr, 1, 1, 0, 200, &err), HJ_OK);
    const double x0 = 1.2;
    o.disturbance = 17;
    assert_int_equal(hj_ctrl_simulate(&s, &g, a, &x0, &o, &tr, &err), HJ_EINVAL);
    assert_non_null(strstr(err.msg, "disturbance mode 17"));
    o.disturbance = HJ_CTRL_D_ZERO;
    assert_int_equal(hj_ctrl_simulate(NULL, &g, a, &x0, &o, &tr, &err), HJ_EINVAL);
    assert_int_equal(hj_ctrl_simulate(&s, NULL, a, &x0, &o, &tr, &err), HJ_EINVAL);
    assert_int_equal(hj_ctrl_simulate(&s, &g, NULL, &x0, &o, &tr, &err), HJ_EINVAL);
    assert_int_equal(hj_ctrl_simulate(&s, &g, a, NULL, &o, &tr, &err), HJ_EINVAL);
    assert_int_equal(hj_ctrl_simulate(&s, &g, a, &x0, NULL, &tr, &err), HJ_EINVAL);
    assert_int_equal(hj_ctrl_simulate(&s, &g, a, &x0, &o, NULL, &err), HJ_EINVAL);
    assert_int_equal(hj_ctrl_simulate(&s, &g, a, &x0, &o, &tr, &err), HJ_OK);
    hj_ctrl_traj_free(&tr);
    hj_ls_free(a);
}

/* The value is known on the grid's box only (the interpolant is clamped
 * to it).  An initial state outside the box is refused, naming the
 * coordinate (before, x0 = 3 on [-2, 2] ran from the edge's values and
 * recorded the value at 2 as its own); a run that leaves the box says
 * when (t_left), one that stays in it has t_left = INFINITY. */
static void simulate_outside_grid(void **state)
{
    (void)state;
    hj_ls_grid g;
    hj_reach_dyn s;
    double *a = setup_1d(&g, &s);
    hj_ctrl_sim_opts o;
    hj_ctrl_sim_defaults(&o);
    o.dt = 0.01, o.t_max = 2;
    o.target.fn = target_fn;
    hj_ctrl_traj tr;
    hj_error err;
    assert_int_equal(hj_ctrl_traj_alloc(&tr, 1, 1, 0, 200, &err), HJ_OK);
    assert_int_equal(hj_ctrl_simulate(&s, &g, a, (double[]){3}, &o, &tr, &err), HJ_EINVAL);
    assert_non_null(strstr(err.msg, "outside the grid (coordinate 0 = 3, the grid spans [-2, 2]"));
    assert_int_equal(hj_ctrl_simulate(&s, &g, a, (double[]){-2.001}, &o, &tr, &err), HJ_EINVAL);
    /* On the box's edge: taken; reaching from 1.2 stays inside. */
    assert_int_equal(hj_ctrl_simulate(&s, &g, a, (double[]){2}, &o, &tr, &err), HJ_OK);
    assert_true(tr.reached);
    assert_true(tr.t_left == INFINITY);
    assert_int_equal(hj_ctrl_simulate(&s, &g, a, (double[]){1.2}, &o, &tr, &err), HJ_OK);
    assert_true(tr.t_left == INFINITY);
    /* Avoiding from 0.6 at speed 1: past x = 2 after 1.4, first seen at the
     * step ending there (the run goes on to t_max, as before). */
    hj_reach_dyn_goal(&s, HJ_REACH_AVOID);
    o.target.fn = NULL;
    assert_int_equal(hj_ctrl_simulate(&s, &g, a, (double[]){0.6}, &o, &tr, &err), HJ_OK);
    assert_true(tr.t_left >= 1.4 - 1e-9 && tr.t_left <= 1.41 + 1e-9);
    assert_close(tr.t[tr.n - 1], 2, 1e-12, 0);
    hj_ctrl_traj_free(&tr);
    hj_ls_free(a);
}

/* A time-to-reach is INFINITY where the target is not reached within the
 * horizon.  Next to such a node the central difference was infinite, G^T p
 * then took 0 * inf = NaN and the control came out arbitrary (u = +1 where
 * -1 is optimal); a state whose value is not finite got a control all the
 * same and its run returned HJ_OK. */
static void v_g(double t, const double *x, double *o, void *c)
{
    (void)t, (void)x, (void)c;
    o[0] = 0, o[1] = 1;
}
static double far_x(double t, const double *x, void *c)
{
    (void)t, (void)c;
    return fabs(x[1]) - 0.05;
}

static void infinite_neighbours(void **state)
{
    (void)state;
    hj_ls_grid g;
    const hj_ls_bc bc[2] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
    assert_int_equal(hj_ls_grid_init(&g, 2, (double[]){-2, -2}, (double[]){2, 2}, (long[]){41, 41}, bc, NULL), HJ_OK);
    double *a = hj_ls_alloc(&g);
    assert_non_null(a);
    /* 10 + x_1 where x_0 < 1.55, not reached (INFINITY) beyond. */
    for (long j = 0; j < 41; j++)
        for (long i = 0; i < 41; i++) {
            double x[2];
            hj_ls_coord(&g, (long[]){i, j}, x);
            a[hj_ls_index(&g, (long[]){i, j})] = x[0] < 1.55 ? 10 + x[1] : INFINITY;
        }
    double p[2], u;
    const double x0[2] = {1.5, 0.3};
    hj_ctrl_gradient(&g, a, x0, p);
    assert_close(p[0], 0, 1e-12, 0); /* one-sided, from the finite side */
    assert_close(p[1], 1, 1e-12, 0);
    hj_reach_dyn s;
    hj_reach_dyn_init(&s, 2, NULL, NULL);
    hj_reach_dyn_control_box(&s, v_g, 1, (double[]){-1}, (double[]){1});
    hj_ctrl_optimal(&s, &g, a, 0, x0, &u, NULL);
    assert_close(u, -1, 0, 0);
    /* No finite value on either side: no gradient, no control. */
    hj_ctrl_gradient(&g, a, (double[]){1.7, 0.3}, p);
    assert_true(isnan(p[0]));
    hj_ctrl_optimal(&s, &g, a, 0, (double[]){1.7, 0.3}, &u, NULL);
    assert_true(isnan(u));
    hj_ctrl_sim_opts o;
    hj_ctrl_sim_defaults(&o);
    o.target.fn = far_x;
    hj_ctrl_traj tr;
    hj_error err;
    assert_int_equal(hj_ctrl_traj_alloc(&tr, 2, 1, 0, 100, &err), HJ_OK);
    assert_int_equal(hj_ctrl_simulate(&s, &g, a, (double[]){1.7, 0.3}, &o, &tr, &err), HJ_ENONFINITE);
    assert_non_null(strstr(err.msg, "no finite gradient"));
    assert_int_equal(tr.n, 1);
    /* From a state with finite values around it the run goes on. */
    assert_int_equal(hj_ctrl_simulate(&s, &g, a, x0, &o, &tr, &err), HJ_OK);
    assert_true(tr.reached);
    hj_ctrl_traj_free(&tr);
    hj_ls_free(a);
}

/* A reach-avoid time-to-reach is INFINITY inside the obstacle, and the
 * time-optimal path runs along the obstacle's edge.  The gradient was NaN
 * wherever a node of the state's cell was not finite, so a run steered by
 * the time-to-reach stopped (HJ_ENONFINITE) at its first corner.  Here the
 * exact time-to-reach of a unit-speed point to the disc |x| <= 0.2 around
 * the wall [0.4, 0.6] x [-0.5, 0.5], from behind the wall. */
static double wall_box(double t, const double *x, void *c)
{
    (void)t, (void)c;
    return fmax(fabs(x[0] - 0.5) - 0.1, fabs(x[1]) - 0.5);
}
static double small_disc(double t, const double *x, void *c)
{
    (void)t, (void)c;
    return hypot(x[0], x[1]) - 0.2;
}
static int sees(const double *a, const double *b)
{
    for (int k = 1; k < 1000; k++) {
        const double s = k / 1000.0, x = a[0] + (b[0] - a[0]) * s, y = a[1] + (b[1] - a[1]) * s;
        if (fabs(x - 0.5) < 0.1 && fabs(y) < 0.5) return 0;
    }
    return 1;
}
static double around_wall(const double *p)
{
    const double q[2] = {p[0], fabs(p[1])}, o[2] = {0, 0}, c1[2] = {0.6, 0.5}, c2[2] = {0.4, 0.5};
    const double last = hypot(0.4, 0.5) - 0.2;
    if (sees(q, o)) return fmax(hypot(p[0], p[1]) - 0.2, 0);
    if (sees(q, c2)) return hypot(q[0] - c2[0], q[1] - c2[1]) + last;
    return hypot(q[0] - c1[0], q[1] - c1[1]) + 0.2 + last;
}
static void identity2(double t, const double *x, double *o, void *c)
{
    (void)t, (void)x, (void)c;
    o[0] = 1, o[1] = 0, o[2] = 0, o[3] = 1;
}

static void steer_along_obstacle(void **state)
{
    (void)state;
    hj_ls_grid g;
    const hj_ls_bc bc[2] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
    assert_int_equal(hj_ls_grid_init(&g, 2, (double[]){-1.5, -1.5}, (double[]){1.5, 1.5}, (long[]){61, 61}, bc, NULL),
                     HJ_OK);
    double *a = hj_ls_alloc(&g);
    assert_non_null(a);
    for (long j = 0; j < 61; j++)
        for (long i = 0; i < 61; i++) {
            double x[2];
            hj_ls_coord(&g, (long[]){i, j}, x);
            a[hj_ls_index(&g, (long[]){i, j})] = wall_box(0, x, NULL) <= 0 ? INFINITY : around_wall(x);
        }
    hj_reach_dyn s;
    hj_reach_dyn_init(&s, 2, NULL, NULL);
    hj_reach_dyn_control_ball(&s, identity2, 2, (double[]){0, 0}, 1);
    hj_ctrl_sim_opts o;
    hj_ctrl_sim_defaults(&o);
    o.dt = 0.01, o.t_max = 3, o.target.fn = small_disc, o.obstacle.fn = wall_box;
    hj_ctrl_traj tr;
    hj_error err;
    assert_int_equal(hj_ctrl_traj_alloc(&tr, 2, 2, 0, 300, &err), HJ_OK);
    const double x0[2] = {1.0, 0.1};
    assert_int_equal(hj_ctrl_simulate(&s, &g, a, x0, &o, &tr, &err), HJ_OK);
    assert_true(tr.reached);
    /* The exact time is 1.338; the path's corners cost a few steps. */
    assert_close(tr.t[tr.n - 1], around_wall(x0), 0, 0.05);
    assert_true(tr.min_obstacle > -g.dx[0]);
    /* Inside a block of nodes that are all INFINITY there is still no gradient. */
    double p[2];
    hj_ctrl_gradient(&g, a, (double[]){0.5, 0}, p);
    assert_true(isnan(p[0]) && isnan(p[1]));
    hj_ctrl_traj_free(&tr);
    hj_ls_free(a);
}

HJ_TEST_MAIN_ONE_THREAD("ctrl", NULL, NULL, cmocka_unit_test(interpolation_exact),
                        cmocka_unit_test(interpolation_periodic), cmocka_unit_test(simulate_reaches),
                        cmocka_unit_test(simulate_outside_grid),
                        cmocka_unit_test(bad_trajectories_and_options), cmocka_unit_test(infinite_neighbours),
                        cmocka_unit_test(steer_along_obstacle))
