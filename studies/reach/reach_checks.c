/* reach_checks -- the accuracy checks of the reachability layer
 * (common/hj_reach, common/hj_ctrl), each against an exact answer or a
 * fine-grid reference, as tables that make check holds
 * (studies/reach/reference/, README.md there):
 *
 *   di_mintime.tsv      double integrator x' = v, v' = u, |u| <= 1: the
 *                       time-to-reach of the target {T0 <= 1} (T0 the
 *                       minimum time to the origin, in closed form) is
 *                       T0 - 1 exactly; mean and max errors on a
 *                       sequence of grids and the order fitted by Ceres;
 *   product6d.tsv       three decoupled double integrators with a box
 *                       target: the 6-D BRS against the product of the
 *                       three 2-D BRS on the same grid (nodes whose sign
 *                       differs, in all and away from the 2-D boundaries);
 *   trajectories.tsv    Dubins car with a wind disturbance, reach-avoid:
 *                       closed-loop runs from sample states inside the set
 *                       (they must reach the target without touching the
 *                       obstacle under the worst disturbance) and outside
 *                       it (under the optimal disturbance they must not),
 *                       failures counted away from and near the boundary;
 *   moving_obstacle.tsv a bar sweeping across the plane: the set with the
 *                       obstacle as a function of time, and with the
 *                       obstacle frozen at its initial place (the static
 *                       treatment), against a fine-grid reference.
 *
 * Figure data: di_mintime.dat, trajectories.dat, moving_obstacle.dat.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hj.h"

static const char *prog = "reach_checks";
static const char *out_dir = ".";
static int quick = 0;

#define CHECK(call)                                                                                       \
    do {                                                                                                  \
        if (call) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);                                          \
    } while (0)

static double *alloc_or_fail(const hj_ls_grid *g)
{
    double *a = hj_ls_alloc(g);
    if (!a) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory for a %zu-node grid", g->nodes);
    return a;
}

static void open_out(hj_out *o, const char *name)
{
    char path[1024];
    hj_error err;
    snprintf(path, sizeof path, "%s/%s", out_dir, name);
    CHECK(hj_out_open(o, path, &err));
}

static void commit(hj_out *o)
{
    hj_error err;
    CHECK(hj_out_commit(o, &err));
}

/* ---- double integrator ------------------------------------------------ */

static void di_G(double t, const double *x, double *o, void *c)
{
    (void)t, (void)x, (void)c;
    o[0] = 0, o[1] = 1;
}
static void di_f(double t, const double *x, double *o, void *c)
{
    (void)t, (void)c;
    o[0] = x[1], o[1] = 0;
}

/* Minimum time from (x, v) to the origin under |u| <= 1 (bang-bang with
 * one switch on the curve x = -v |v| / 2). */
static double di_time(double x, double v)
{
    if (x + 0.5 * v * fabs(v) > 0) return v + 2 * sqrt(x + 0.5 * v * v);
    return -v + 2 * sqrt(-x + 0.5 * v * v);
}

/* The target {T0 <= DI_T0}: its time-to-reach is T0 - DI_T0. */
#define DI_T0 1.0

static double di_target(double t, const double *x, void *c)
{
    (void)t, (void)c;
    return di_time(x[0], x[1]) - DI_T0;
}

static void di_system(hj_reach_dyn *s)
{
    hj_reach_dyn_init(s, 2, di_f, NULL);
    hj_reach_dyn_control_box(s, di_G, 1, (double[]){-1}, (double[]){1});
    hj_reach_dyn_goal(s, HJ_REACH_REACH);
}

static void check_mintime(void)
{
    const long Ns[4] = {41, 81, 161, 321};
    const int n = quick ? 3 : 4;
    const double horizon = 0.8;
    double h[4], emean[4], emax[4];
    hj_out o;
    open_out(&o, "di_mintime.tsv");
    fprintf(o.fp, "# Double integrator, target {T0 <= %g}, BRT to tau = %g, ENO2/LLF/RK2, CFL 0.5: time-to-reach "
                  "against T0 - %g at the nodes where 0 < T0 - %g <= %g\n",
            DI_T0, horizon, DI_T0, DI_T0, horizon - 0.1);
    fprintf(o.fp, "N\th\tnodes\tmean_err\tmax_err\torder\tseconds\n");
    hj_reach_dyn s;
    di_system(&s);
    for (int k = 0; k < n; k++) {
        hj_error err;
        hj_ls_grid g;
        const hj_ls_bc bc[2] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
        CHECK(hj_ls_grid_init(&g, 2, (double[]){-2, -2}, (double[]){2, 2}, (long[]){Ns[k], Ns[k]}, bc, &err));
        double *phi = alloc_or_fail(&g), *ttr = alloc_or_fail(&g), *exact = alloc_or_fail(&g);
        hj_reach_problem pb;
        hj_reach_problem_init(&pb, &g, &s);
        pb.target.fn = di_target;
        pb.horizon = horizon;
        hj_reach_stats st;
        hj_progress("%s: double integrator N = %ld\n", prog, Ns[k]);
        CHECK(hj_reach_solve(&pb, phi, ttr, &st, &err));
        double sum = 0, m = 0;
        long cnt = 0;
        for (size_t r = 0; r < g.rows; r++) {
            long i[2];
            double x[2];
            const size_t k0 = hj_ls_row(&g, r, i);
            for (long j = 0; j < g.N[0]; j++) {
                i[0] = j;
                hj_ls_coord(&g, i, x);
                const double te = di_time(x[0], x[1]) - DI_T0;
                exact[k0 + (size_t)j] = te > 0 ? te : 0;
                if (!(te > 0 && te <= horizon - 0.1)) continue;
                /* A node not reached by the horizon counts as reached at it. */
                const double tn = ttr[k0 + (size_t)j] < horizon ? ttr[k0 + (size_t)j] : horizon;
                const double e = fabs(tn - te);
                sum += e, m = e > m ? e : m, cnt++;
            }
        }
        h[k] = g.dx[0], emean[k] = sum / (double)cnt, emax[k] = m;
        fprintf(o.fp, "%ld\t%.6g\t%ld\t%.4e\t%.4e\t-\t%.2f\n", Ns[k], h[k], cnt, emean[k], emax[k], st.seconds);
        if (k == n - 1) {
            hj_out d;
            open_out(&d, "di_mintime.dat");
            for (size_t q = 0; q < g.total; q++)
                if (isinf(ttr[q])) ttr[q] = NAN;
            const char *names[3] = {"ttr", "exact", "phi"};
            const double *f[3] = {ttr, exact, phi};
            CHECK(hj_ls_write_block(d.fp, &g, 3, names, f, &err));
            commit(&d);
        }
        hj_ls_free(phi), hj_ls_free(ttr), hj_ls_free(exact);
    }
    /* Orders fitted over the first three grids (both runs) and over all
     * four (the full run). */
    for (int m = 3; m <= n; m++) {
        hj_order_fit fm, fx;
        hj_error err;
        CHECK(hj_fit_order(h, emean, m, &fm, &err));
        CHECK(hj_fit_order(h, emax, m, &fx, &err));
        fprintf(o.fp, "fit%ld-%ld\t-\t-\t-\t-\t%.3f\t-\n", Ns[0], Ns[m - 1], fm.p);
        fprintf(o.fp, "fitmax%ld-%ld\t-\t-\t-\t-\t%.3f\t-\n", Ns[0], Ns[m - 1], fx.p);
    }
    commit(&o);
}

/* ---- three decoupled double integrators ------------------------------- */

static void di3_f(double t, const double *x, double *o, void *c)
{
    (void)t, (void)c;
    for (int k = 0; k < 3; k++) o[2 * k] = x[2 * k + 1], o[2 * k + 1] = 0;
}
static void di3_G(double t, const double *x, double *o, void *c)
{
    (void)t, (void)x, (void)c;
    for (int q = 0; q < 18; q++) o[q] = 0;
    for (int k = 0; k < 3; k++) o[(2 * k + 1) * 3 + k] = 1;
}
static double box2(double t, const double *x, void *c)
{
    (void)t, (void)c;
    return fmax(fabs(x[0]) - 0.5, fabs(x[1]) - 0.5);
}
static double box6(double t, const double *x, void *c)
{
    (void)t, (void)c;
    return fmax(fmax(box2(t, x, c), box2(t, x + 2, c)), box2(t, x + 4, c));
}

/* One row of product6d.tsv: N nodes a dimension, the scheme and RK order. */
static void product_row(hj_out *o, long N, int scheme, int order)
{
    const double T = 0.5, lo = -1.5, hi = 1.5;
    hj_error err;
    hj_ls_grid g2, g6;
    hj_ls_bc bc[6];
    double mn[6], mx[6];
    long n6[6];
    for (int d = 0; d < 6; d++) bc[d] = (hj_ls_bc){HJ_LS_BC_EXTRAP_AWAY, 0, 0}, mn[d] = lo, mx[d] = hi, n6[d] = N;
    CHECK(hj_ls_grid_init(&g2, 2, mn, mx, n6, bc, &err));
    CHECK(hj_ls_grid_init(&g6, 6, mn, mx, n6, bc, &err));
    /* 2-D: one computation serves the three identical factors. */
    hj_reach_dyn s2, s6;
    di_system(&s2);
    hj_reach_problem pb;
    hj_reach_problem_init(&pb, &g2, &s2);
    pb.kind = HJ_REACH_BRS, pb.target.fn = box2, pb.horizon = T, pb.scheme = scheme, pb.order = order;
    double *v2 = alloc_or_fail(&g2);
    CHECK(hj_reach_solve(&pb, v2, NULL, NULL, &err));
    /* A 2-D node is at the boundary when a neighbour (8-neighbourhood)
     * has the other sign. */
    char *in2 = calloc((size_t)(N * N), 1), *bd2 = calloc((size_t)(N * N), 1);
    if (!in2 || !bd2) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory");
    for (long b = 0; b < N; b++)
        for (long a = 0; a < N; a++) in2[b * N + a] = v2[hj_ls_index(&g2, (long[]){a, b})] <= 0;
    for (long b = 0; b < N; b++)
        for (long a = 0; a < N; a++)
            for (long db = -1; db <= 1; db++)
                for (long da = -1; da <= 1; da++) {
                    const long aa = a + da, bb = b + db;
                    if (aa >= 0 && aa < N && bb >= 0 && bb < N && in2[bb * N + aa] != in2[b * N + a]) bd2[b * N + a] = 1;
                }
    /* 6-D */
    hj_reach_dyn_init(&s6, 6, di3_f, NULL);
    hj_reach_dyn_control_box(&s6, di3_G, 3, (double[]){-1, -1, -1}, (double[]){1, 1, 1});
    hj_reach_problem_init(&pb, &g6, &s6);
    pb.kind = HJ_REACH_BRS, pb.target.fn = box6, pb.horizon = T, pb.scheme = scheme, pb.order = order;
    double *v6 = alloc_or_fail(&g6);
    hj_reach_stats st;
    hj_progress("%s: 6-D product, N = %ld\n", prog, N);
    CHECK(hj_reach_solve(&pb, v6, NULL, &st, &err));
    long differ = 0, differ_away = 0, inside = 0, inside2 = 0;
    for (size_t r = 0; r < g6.rows; r++) {
        long i[6];
        const size_t k0 = hj_ls_row(&g6, r, i);
        for (long j = 0; j < N; j++) {
            i[0] = j;
            int prod = 1, near = 0;
            for (int f = 0; f < 3; f++) {
                const long q = i[2 * f + 1] * N + i[2 * f];
                prod &= in2[q];
                near |= bd2[q];
            }
            const int in6 = v6[k0 + (size_t)j] <= 0;
            inside += in6, inside2 += prod;
            if (in6 != prod) differ++, differ_away += !near;
        }
    }
    fprintf(o->fp, "%ld\t%s-rk%d\t%zu\t%ld\t%ld\t%ld\t%ld\t%ld\t%.2f\t%.1f\n", N, hj_ls_scheme_name(scheme), order, g6.nodes, inside, inside2, differ, differ_away,
            st.steps, st.seconds, ((double)g6.total * sizeof(double) + (double)st.bytes) / (double)g6.nodes);
    free(in2), free(bd2);
    hj_ls_free(v2), hj_ls_free(v6);
}

/* Quick: 9^6 nodes, first order upwind with forward Euler (a third of the
 * work of ENO2/RK2 per step); full: that and ENO2/RK2 on 11^6 nodes. */
static void check_product(void)
{
    hj_out o;
    open_out(&o, "product6d.tsv");
    fprintf(o.fp, "# Three double integrators, box target |x_k|, |v_k| <= 0.5, BRS at T = 0.5 on [-1.5, 1.5]^6, "
                  "LLF: nodes of the 6-D set against the product of the 2-D sets on the same nodes; bytes_per_node: "
                  "the value (with its ghost layers) and what hj_reach_solve allocates (first order: the fused "
                  "path's interior array and row buffers; ENO2/RK2: the previous value and two RK stages with "
                  "ghost layers, the one-sided derivatives the Lax-Friedrichs term keeps)\n");
    fprintf(o.fp, "N\tscheme\tnodes\tinside_6d\tinside_product\tdiffer\tdiffer_away\tsteps\tseconds\tbytes_per_node\n");
    product_row(&o, 9, HJ_LS_UPWIND_FIRST, 1);
    if (!quick) product_row(&o, 11, HJ_LS_ENO2, 2);
    commit(&o);
}

/* ---- Dubins car with wind: trajectories ------------------------------- */

static void car_f(double t, const double *x, double *o, void *c)
{
    (void)t, (void)c;
    o[0] = cos(x[2]), o[1] = sin(x[2]), o[2] = 0;
}
static void car_G(double t, const double *x, double *o, void *c)
{
    (void)t, (void)x, (void)c;
    o[0] = 0, o[1] = 0, o[2] = 1;
}
static void car_H(double t, const double *x, double *o, void *c)
{
    (void)t, (void)x, (void)c;
    o[0] = 1, o[1] = 0, o[2] = 0, o[3] = 1, o[4] = 0, o[5] = 0;
}
static double car_target(double t, const double *x, void *c)
{
    (void)t, (void)c;
    return hypot(x[0], x[1]) - 0.5;
}
static double car_obstacle(double t, const double *x, void *c)
{
    (void)t, (void)c;
    return fmax(fabs(x[0] + 1) - 0.4, fabs(x[1] - 0.8) - 0.6);
}

static void check_trajectories(void)
{
    const long N = quick ? 41 : 61;
    const int samples = quick ? 400 : 1000;
    const double T = 1.5;
    hj_error err;
    hj_ls_grid g;
    const hj_ls_bc bc[3] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_PERIODIC, 0, 0}};
    CHECK(hj_ls_grid_init_period(&g, 3, (double[]){-2, -2, 0}, (double[]){2, 2, 2 * HJ_PI}, (long[]){N, N, N - 1}, bc,
                                 &err));
    hj_reach_dyn s;
    hj_reach_dyn_init(&s, 3, car_f, NULL);
    hj_reach_dyn_control_box(&s, car_G, 1, (double[]){-1}, (double[]){1});
    hj_reach_dyn_disturbance_ball(&s, car_H, 2, (double[]){0, 0}, 0.2);
    hj_reach_dyn_goal(&s, HJ_REACH_REACH);
    hj_reach_problem pb;
    hj_reach_problem_init(&pb, &g, &s);
    pb.target.fn = car_target, pb.obstacle.fn = car_obstacle, pb.horizon = T;
    double *phi = alloc_or_fail(&g);
    hj_progress("%s: Dubins car reach-avoid, N = %ld\n", prog, N);
    CHECK(hj_reach_solve(&pb, phi, NULL, NULL, &err));
    hj_ctrl_sim_opts so;
    hj_ctrl_sim_defaults(&so);
    so.dt = 0.005, so.t_max = T;
    so.disturbance = HJ_CTRL_D_OPTIMAL;
    so.target.fn = car_target, so.obstacle.fn = car_obstacle;
    hj_ctrl_traj tr;
    CHECK(hj_ctrl_traj_alloc(&tr, 3, 1, 2, (long)ceil(T / so.dt) + 1, &err));
    /* Away from the boundary: |phi| above two cells of the plane. */
    const double margin = 2 * g.dx[0];
    long n_in = 0, n_out = 0, fail_in = 0, fail_out = 0, near_in = 0, near_out = 0, fail_near_in = 0,
         fail_near_out = 0;
    unsigned long long seed = 12345;
    hj_out d;
    open_out(&d, "trajectories.dat");
    fprintf(d.fp, "# closed-loop trajectories (x y th value), one block per sample state drawn; index 0: inside, "
                  "then outside\n");
    int drawn_in = 0, drawn_out = 0;
    for (int k = 0; k < samples; k++) {
        double x0[3];
        for (int q = 0; q < 3; q++) {
            seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
            const double u01 = (double)(seed >> 11) / 9007199254740992.0;
            x0[q] = q < 2 ? -1.9 + 3.8 * u01 : 2 * HJ_PI * u01;
        }
        const double v = hj_ctrl_value(&g, phi, x0);
        if (car_obstacle(0, x0, NULL) <= 0 || car_target(0, x0, NULL) <= 0) continue;
        CHECK(hj_ctrl_simulate(&s, &g, phi, x0, &so, &tr, &err));
        const int success = tr.reached && !tr.collided;
        const int near = fabs(v) <= margin;
        if (v < 0) {
            if (near) near_in++, fail_near_in += !success;
            else n_in++, fail_in += !success;
        } else {
            if (near) near_out++, fail_near_out += success;
            else n_out++, fail_out += success;
        }
        if (!near && ((v < 0 && drawn_in < 12) || (v > 0 && drawn_out < 12))) {
            v < 0 ? drawn_in++ : drawn_out++;
            for (long p = 0; p < tr.n; p++)
                fprintf(d.fp, "%.5g %.5g %.5g %.5g %d\n", tr.x[3 * p], tr.x[3 * p + 1], tr.x[3 * p + 2], tr.value[p],
                        v < 0);
            fprintf(d.fp, "\n\n");
        }
    }
    commit(&d);
    hj_out o;
    open_out(&o, "trajectories.tsv");
    fprintf(o.fp, "# Dubins car (speed 1, |turn| <= 1) with wind |d| <= 0.2, target disc 0.5, box obstacle, "
                  "BRT T = %g on %ld x %ld x %ld (period 2 pi), ENO2/LLF/RK2; RK4 closed loop dt = %g, optimal "
                  "disturbance; away: |phi| > %.3g\n",
            T, N, N, N - 1, so.dt, margin);
    fprintf(o.fp, "start\tsamples\tfailures\tsamples_near\tfailures_near\n");
    fprintf(o.fp, "inside\t%ld\t%ld\t%ld\t%ld\n", n_in, fail_in, near_in, fail_near_in);
    fprintf(o.fp, "outside\t%ld\t%ld\t%ld\t%ld\n", n_out, fail_out, near_out, fail_near_out);
    commit(&o);
    hj_ctrl_traj_free(&tr);
    hj_ls_free(phi);
}

/* ---- moving obstacle --------------------------------------------------- */

static void hol_G(double t, const double *x, double *o, void *c)
{
    (void)t, (void)x, (void)c;
    o[0] = 1, o[1] = 0, o[2] = 0, o[3] = 1;
}
static double hol_target(double t, const double *x, void *c)
{
    (void)t, (void)c;
    return hypot(x[0], x[1]) - 0.3;
}
/* A bar 0.3 wide and 2 high sweeping from x = -1.2 at t = 0 to x = 0.8 at
 * t = 1: it blocks the way from the left early and from the right late. */
static double bar(double t, const double *x, void *c)
{
    (void)c;
    const double cx = -1.2 + 2.0 * t;
    return fmax(fabs(x[0] - cx) - 0.15, fabs(x[1]) - 1.0);
}
static double bar_static(double t, const double *x, void *c)
{
    (void)t;
    return bar(0, x, c);
}

static double moving_run(long N, hj_reach_set_fn obstacle, double **phi_out, hj_ls_grid *g)
{
    hj_error err;
    const hj_ls_bc bc[2] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
    CHECK(hj_ls_grid_init(g, 2, (double[]){-2, -2}, (double[]){2, 2}, (long[]){N, N}, bc, &err));
    hj_reach_dyn s;
    hj_reach_dyn_init(&s, 2, NULL, NULL);
    hj_reach_dyn_control_ball(&s, hol_G, 2, (double[]){0, 0}, 1.0);
    hj_reach_problem pb;
    hj_reach_problem_init(&pb, g, &s);
    pb.target.fn = hol_target, pb.obstacle.fn = obstacle, pb.horizon = 1.0;
    double *phi = alloc_or_fail(g);
    CHECK(hj_reach_solve(&pb, phi, NULL, NULL, &err));
    double area;
    CHECK(hj_ls_measure(g, phi, &area, &err));
    *phi_out = phi;
    return area;
}

/* Each grid N against the time-varying run on 4 (N - 1) + 1 nodes a side
 * (its nodes include the coarse ones): quick 41, full 41 and 81. */
static void check_moving(void)
{
    hj_out o;
    open_out(&o, "moving_obstacle.tsv");
    fprintf(o.fp, "# x' = u, |u| <= 1, target disc 0.3, bar obstacle sweeping from x = -1.2 (t = 0) to 0.8 (t = 1), "
                  "BRT T = 1 on [-2, 2]^2, ENO2/LLF/RK2; reference: the time-varying run on 4 (N - 1) + 1 nodes a "
                  "side (area_ref); cells: nodes whose sign differs from the reference's\n");
    fprintf(o.fp, "treatment\tN\tarea\tarea_ref\tarea_rel_err\tcells_differ\tvisibly_worse\n");
    for (long N = 41; N <= (quick ? 41 : 81); N = 2 * N - 1) {
    const long Nf = 4 * (N - 1) + 1, step = 4;
    hj_ls_grid g, gs, gf;
    double *phi, *phis, *phif;
    hj_progress("%s: moving obstacle, N = %ld and %ld\n", prog, N, Nf);
    const double af = moving_run(Nf, bar, &phif, &gf);
    const double a = moving_run(N, bar, &phi, &g);
    const double as = moving_run(N, bar_static, &phis, &gs);
    long dm = 0, ds = 0;
    for (long b = 0; b < N; b++)
        for (long c = 0; c < N; c++) {
            const int ref = phif[hj_ls_index(&gf, (long[]){step * c, step * b})] < 0;
            const size_t k = hj_ls_index(&g, (long[]){c, b});
            dm += (phi[k] < 0) != ref;
            ds += (phis[k] < 0) != ref;
        }
    const double em = fabs(a / af - 1), es = fabs(as / af - 1);
    fprintf(o.fp, "moving\t%ld\t%.5f\t%.5f\t%.4f\t%ld\t-\n", N, a, af, em, dm);
    fprintf(o.fp, "static\t%ld\t%.5f\t%.5f\t%.4f\t%ld\t%d\n", N, as, af, es, ds, es > 5 * em && ds > 5 * dm);
    if (N == 41) {
        hj_out d;
        hj_error err;
        open_out(&d, "moving_obstacle.dat");
        const char *names[2] = {"phi_moving", "phi_static"};
        const double *f[2] = {phi, phis};
        CHECK(hj_ls_write_block(d.fp, &g, 2, names, f, &err));
        commit(&d);
    }
    hj_ls_free(phi), hj_ls_free(phis), hj_ls_free(phif);
    }
    commit(&o);
}

int main(int argc, char **argv)
{
    static const char *const which_names[] = {"all", "mintime", "product", "trajectories", "moving", NULL};
    int which = 0;
    hj_cli_opt opts[] = {
        {"--out-dir", HJ_OPT_STRING, &out_dir, 0, 0, "DIR", "directory of the tables and figure data", NULL, NULL, 0,
         NULL, 0},
        {"--quick", HJ_OPT_FLAG, &quick, 0, 0, NULL, "coarser grids and fewer samples (seconds)", NULL, NULL, 0, NULL,
         0},
        {"--only", HJ_OPT_CHOICE, &which, 0, 0, "CHECK", "run one check", which_names, NULL, 0, NULL, 0},
    };
    hj_cli_spec spec = {prog, "the reachability checks: minimum time, 6-D product set, trajectories, moving obstacle",
                        opts, (int)(sizeof opts / sizeof opts[0]), NULL};
    hj_cli_parse_or_exit(&spec, argc, argv);
    hj_error err;
    char probe[1024];
    snprintf(probe, sizeof probe, "%s/di_mintime.tsv", out_dir);
    CHECK(hj_out_check(probe, &err));
    if (which == 0 || which == 1) check_mintime();
    if (which == 0 || which == 2) check_product();
    if (which == 0 || which == 3) check_trajectories();
    if (which == 0 || which == 4) check_moving();
    return 0;
}
