/* Unit tests of common/hj_ls_ode: order of accuracy of the three TVD RK
 * integrators, output times, options (MaxStep, PostTimestep, SingleStep,
 * stats), error reports (zero / NaN / infinite CFL bound, blow-up), and
 * bitwise identical results for 1 and 2 OpenMP threads. */
#include "hj_test.h"

#include <float.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "hj_ls_ode.h"
#include "hj_math.h"
#include "hj_ls_term.h"
#include "hj_sys.h"

static hj_ls_grid grid1(long n)
{
    hj_ls_grid g;
    double mn = 0, mx = 1;
    hj_ls_bc bc = {HJ_LS_BC_PERIODIC, 0, 0};
    assert_int_equal(hj_ls_grid_init(&g, 1, &mn, &mx, &n, &bc, NULL), HJ_OK);
    return g;
}

static double minus_cos(double t, const double *x, double phi, void *ctx)
{
    (void)x, (void)phi, (void)ctx;
    return -cos(t);
}

/* y' = -y + cos t (discount 1 plus forcing -cos t, as a sum of terms),
 * y(0) = 2: y(1) = 1.5 e^-1 + (cos 1 + sin 1) / 2.  Steps fixed by
 * MaxStep. */
static double ode_error(int order, double h)
{
    hj_ls_grid g = grid1(4);
    hj_ls_discount dc;
    hj_ls_forcing fc;
    hj_ls_discount_init(&dc, &g);
    dc.lambda.value = 1;
    hj_ls_forcing_init(&fc, &g);
    fc.F.fn = minus_cos;
    const hj_ls_term *terms[2] = {&dc.base, &fc.base};
    hj_ls_sum sum;
    assert_int_equal(hj_ls_sum_init(&sum, &g, terms, 2, NULL), HJ_OK);
    double *y = hj_ls_alloc(&g);
    for (int j = 0; j < 4; j++) y[g.offset + (size_t)j] = 2;
    hj_ls_ode_opts o;
    hj_ls_ode_defaults(&o);
    o.max_step = h;
    double span[2] = {0, 1};
    hj_error err;
    int rc = hj_ls_ode(order, &g, &sum.base, span, 2, y, &o, NULL, NULL, NULL, &err);
    if (rc) fail_msg("%s", err.msg);
    const double exact = 1.5 * exp(-1.0) + 0.5 * (cos(1.0) + sin(1.0));
    double e = fabs(y[g.offset] - exact);
    hj_ls_free(y);
    hj_ls_sum_free(&sum);
    return e;
}

static void integrator_orders(void **state)
{
    (void)state;
    for (int order = 1; order <= 3; order++) {
        double e1 = ode_error(order, 0.02), e2 = ode_error(order, 0.01);
        double p = log(e1 / e2) / log(2.0);
        if (!(fabs(p - order) < 0.1)) fail_msg("RK%d: observed order %.3f (errors %.3e %.3e)", order, p, e1, e2);
    }
}

/* A constant G = 1 term with a configurable CFL bound. */
typedef struct {
    hj_ls_term base;
    const hj_ls_grid *g;
    double bound, rate;
} const_term;

static int const_eval(const hj_ls_term *term, double t, double *y, double *ydot, double *bound, hj_error *err)
{
    (void)t, (void)err;
    const const_term *c = (const const_term *)term;
    for (long j = 0; j < c->g->N[0]; j++) ydot[c->g->offset + (size_t)j] = c->rate * (1 + y[c->g->offset + (size_t)j]);
    *bound = c->bound;
    return HJ_OK;
}

typedef struct {
    int calls;
    double times[8];
} record;

static int on_output(int k, double t, const double *y, void *ctx, hj_error *err)
{
    (void)k, (void)y, (void)err;
    record *r = ctx;
    r->times[r->calls++] = t;
    return HJ_OK;
}

static int post_clamp(double t, double *y, void *ctx, hj_error *err)
{
    (void)t, (void)err;
    record *r = ctx;
    r->calls++;
    y[HJ_LS_GHOST] = 0; /* node 0 of the 1-D grid */
    return HJ_OK;
}

static void outputs_and_options(void **state)
{
    (void)state;
    hj_ls_grid g = grid1(4);
    const_term c = {{const_eval}, &g, 0.3, 0};
    double *y = hj_ls_alloc(&g);
    double span[4] = {0, 0.25, 0.5, 1};
    record r = {0, {0}};
    hj_ls_ode_stats st;
    assert_int_equal(hj_ls_ode(3, &g, &c.base, span, 4, y, NULL, on_output, &r, &st, NULL), HJ_OK);
    assert_int_equal(r.calls, 3);
    assert_close(r.times[0], 0.25, 0, 0);
    assert_close(r.times[2], 1, 0, 0);
    /* dt = 0.15: 2 steps to 0.25, 2 to 0.5, 4 to 1 */
    assert_int_equal(st.steps, 8);
    assert_int_equal(st.evals, 24);
    /* FactorCFL and SingleStep */
    hj_ls_ode_opts o;
    hj_ls_ode_defaults(&o);
    o.factor_cfl = 0.9;
    o.single_step = 1;
    double span1[2] = {0, 1};
    assert_int_equal(hj_ls_ode(1, &g, &c.base, span1, 2, y, &o, NULL, NULL, &st, NULL), HJ_OK);
    assert_int_equal(st.steps, 1);
    assert_close(st.t, 0.27, 1e-15, 0);
    /* PostTimestep called after every step and may change y */
    o.single_step = 0;
    o.post = post_clamp;
    o.post_ctx = &r;
    r.calls = 0;
    c.rate = 1;
    for (int j = 0; j < 4; j++) y[g.offset + (size_t)j] = 0;
    assert_int_equal(hj_ls_ode(1, &g, &c.base, span, 2, y, &o, NULL, NULL, &st, NULL), HJ_OK);
    assert_int_equal(r.calls, st.steps);
    assert_close(y[g.offset], 0, 0, 0);
    assert_true(y[g.offset + 1] > 0);
    hj_ls_free(y);
}

/* y' = t with the bound 1 / t: no motion at t = 0 only (a velocity that
 * starts from zero). */
static int ramp_eval(const hj_ls_term *term, double t, double *y, double *ydot, double *bound, hj_error *err)
{
    (void)y, (void)err;
    const const_term *c = (const const_term *)term;
    for (long j = 0; j < c->g->N[0]; j++) ydot[c->g->offset + (size_t)j] = t;
    *bound = t > 0 ? 1 / t : INFINITY;
    return HJ_OK;
}

/* A term with no motion (zero velocity everywhere: an infinite CFL bound)
 * steps to each output time and leaves the state as it is; it was an
 * error asking for a MaxStep.  A velocity that starts from zero within
 * such a step is an error naming both times, for every order; with a
 * MaxStep it runs. */
static void no_motion(void **state)
{
    (void)state;
    hj_ls_grid g = grid1(16);
    hj_ls_convection still;
    hj_ls_convection_init(&still, &g, HJ_LS_WENO5A);
    double *y = hj_ls_alloc(&g), *y0 = hj_ls_alloc(&g), span[3] = {0, 0.25, 1};
    for (long j = 0; j < 16; j++) y[g.offset + (size_t)j] = y0[g.offset + (size_t)j] = sin(0.3 * (double)j) - 0.2;
    hj_error err;
    hj_ls_ode_stats st;
    for (int order = 1; order <= 3; order++) {
        assert_int_equal(hj_ls_ode(order, &g, &still.base, span, 3, y, NULL, NULL, NULL, &st, &err), HJ_OK);
        assert_int_equal(st.steps, 2);
        assert_close(st.t, 1, 0, 0);
        /* orders 1 and 2 add dt 0 and average equal values: the same bits;
         * RK3's weights 3/4, 1/4 and 1/3, 2/3 round */
        if (order < 3) assert_memory_equal(y + g.offset, y0 + g.offset, 16 * sizeof *y);
        for (long j = 0; j < 16; j++) assert_close(y[g.offset + (size_t)j], y0[g.offset + (size_t)j], 0, 4e-16);
    }
    const_term ramp = {{ramp_eval}, &g, 0, 0};
    for (int order = 1; order <= 3; order++) {
        assert_int_equal(hj_ls_ode(order, &g, &ramp.base, span, 3, y, NULL, NULL, NULL, NULL, &err), HJ_EINVAL);
        assert_has(err.msg, "no motion at t = 0 (infinite CFL bound) but motion at t = 0.25");
        assert_has(err.msg, "give a MaxStep");
    }
    hj_ls_ode_opts o;
    hj_ls_ode_defaults(&o);
    o.max_step = 0.01;
    for (long j = 0; j < 16; j++) y[g.offset + (size_t)j] = 0;
    assert_int_equal(hj_ls_ode(2, &g, &ramp.base, span, 3, y, &o, NULL, NULL, NULL, &err), HJ_OK);
    assert_close(y[g.offset], 0.5, 1e-12, 0); /* Heun is exact for y' = t */
    hj_ls_free(y), hj_ls_free(y0);
}

/* A span of more than 2^52 steps of the CFL bound is refused at its first
 * step (it ran for ever: t + dt rounds to t long before the end). */
static void endless_span(void **state)
{
    (void)state;
    hj_ls_grid g = grid1(4);
    const_term c = {{const_eval}, &g, 1, 0};
    double *y = hj_ls_alloc(&g), span[2] = {0, 1e300};
    hj_error err;
    hj_ls_ode_stats st;
    for (int order = 1; order <= 3; order++) {
        assert_int_equal(hj_ls_ode(order, &g, &c.base, span, 2, y, NULL, NULL, NULL, &st, &err), HJ_EINVAL);
        assert_has(err.msg, "needs more than 2^52 steps");
    }
    /* a short span of the same term runs */
    span[1] = 4;
    assert_int_equal(hj_ls_ode(1, &g, &c.base, span, 2, y, NULL, NULL, NULL, &st, &err), HJ_OK);
    hj_ls_free(y);
}

/* A span on a small time scale is integrated: y' = 1 + y from y = 0 over
 * [0, 1e-20] is one step of 1e-20 at every order (y = e^dt - 1 within the
 * step's truncation error, relative dt, or round-off);
 * the end-of-span rule was 100 eps absolute below |t| = 1, and such a span
 * took no step.  A span near t = 1e6 of 1e-3 runs too. */
static void tiny_span_steps(void **state)
{
    (void)state;
    hj_ls_grid g = grid1(4);
    const_term c = {{const_eval}, &g, 1, 1};
    double *y = hj_ls_alloc(&g);
    hj_error err;
    hj_ls_ode_stats st;
    const double spans[2][2] = {{0, 1e-20}, {1e6, 1e6 + 1e-3}};
    for (int k = 0; k < 2; k++)
        for (int order = 1; order <= 3; order++) {
            for (long j = 0; j < 4; j++) y[g.offset + (size_t)j] = 0;
            assert_int_equal(hj_ls_ode(order, &g, &c.base, spans[k], 2, y, NULL, NULL, NULL, &st, &err), HJ_OK);
            assert_int_equal(st.steps, 1);
            assert_true(st.t == spans[k][1]);
            const double dt = spans[k][1] - spans[k][0];
            assert_close(y[g.offset], expm1(dt), 0, dt > 1e-15 ? dt : 1e-15);
        }
    /* The steps' round-off is not a span: 3000 steps of 0.125 / 3000 sum to
     * 5.5e-15 short of 0.125 (above 100 eps of 0.125), and no tiny 3001st
     * step follows (it changed paper 2's spiral areas at round-off, then
     * by 3.4e-6 after a pinch). */
    hj_ls_ode_opts o;
    hj_ls_ode_defaults(&o);
    o.max_step = 0.125 / 3000;
    c.bound = 1e9;
    const double span3[2] = {0, 0.125};
    for (int order = 1; order <= 3; order++) {
        assert_int_equal(hj_ls_ode(order, &g, &c.base, span3, 2, y, &o, NULL, NULL, &st, &err), HJ_OK);
        assert_int_equal(st.steps, 3000);
    }
    hj_ls_free(y);
}

static void error_reports(void **state)
{
    (void)state;
    hj_ls_grid g = grid1(4);
    const_term c = {{const_eval}, &g, 0, 1};
    double *y = hj_ls_alloc(&g), span[2] = {0, 1};
    hj_error err;
    assert_int_equal(hj_ls_ode(1, &g, &c.base, span, 2, y, NULL, NULL, NULL, NULL, &err), HJ_EINVAL);
    assert_non_null(strstr(err.msg, "zero CFL bound"));
    /* times out of order: the message says which and their values (it
     * said only "tspan must increase") */
    const double back[3] = {0, 1, 0.5};
    assert_int_equal(hj_ls_ode(1, &g, &c.base, back, 3, y, NULL, NULL, NULL, NULL, &err), HJ_EINVAL);
    assert_has(err.msg, "tspan[2] = 0.5 <= tspan[1] = 1");
    c.bound = NAN;
    assert_int_equal(hj_ls_ode(2, &g, &c.base, span, 2, y, NULL, NULL, NULL, NULL, &err), HJ_ENONFINITE);
    assert_non_null(strstr(err.msg, "non-finite CFL bound"));
    /* an infinite bound, no MaxStep and a term that moves (y' = 1 + y, a
     * forcing term's kind): an error, not one step over the whole span */
    c.bound = INFINITY;
    for (int order = 1; order <= 3; order++) {
        assert_int_equal(hj_ls_ode(order, &g, &c.base, span, 2, y, NULL, NULL, NULL, NULL, &err), HJ_ENONFINITE);
        assert_has(err.msg, "but the term moves");
    }
    /* with MaxStep an infinite bound is fine */
    hj_ls_ode_opts o;
    hj_ls_ode_defaults(&o);
    o.always_parallel = -1;
    assert_int_equal(hj_ls_ode(1, &g, &c.base, span, 2, y, &o, NULL, NULL, NULL, &err), HJ_EINVAL);
    assert_has(err.msg, "always_parallel must be 0 or 1, got -1");
    o.always_parallel = 0;
    o.max_step = 0.25;
    for (int j = 0; j < 4; j++) y[g.offset + (size_t)j] = 0;
    assert_int_equal(hj_ls_ode(1, &g, &c.base, span, 2, y, &o, NULL, NULL, NULL, &err), HJ_OK);
    assert_close(y[g.offset], pow(1.25, 4) - 1, 1e-14, 0);
    /* blow-up: y' = 1e300 (1 + y) overflows at the second step (the bound
     * on finite growth off, so that the overflow itself is detected) */
    c.bound = 1, c.rate = 1e300;
    hj_ls_ode_stats st;
    hj_ls_ode_defaults(&o);
    o.blowup_factor = 0;
    assert_int_equal(hj_ls_ode(1, &g, &c.base, span, 2, y, &o, NULL, NULL, &st, &err), HJ_ENONFINITE);
    assert_non_null(strstr(err.msg, "blow-up"));
    assert_non_null(strstr(err.msg, "after step 2"));
    /* finite growth: y' = 10 (1 + y) from 0 with dt = 0.5 multiplies 1 + y
     * by 6 per step; the scale is the diameter 1 of [0, 1], so the default
     * factor 1e6 is passed at step 8 (6^8 - 1 = 1.7e6), long before any
     * overflow */
    for (int j = 0; j < 4; j++) y[g.offset + (size_t)j] = 0;
    c.rate = 10;
    double long_span[2] = {0, 100};
    assert_int_equal(hj_ls_ode(1, &g, &c.base, long_span, 2, y, NULL, NULL, NULL, &st, &err), HJ_ENONFINITE);
    assert_non_null(strstr(err.msg, "exceeds 1e+06 times the initial scale"));
    assert_int_equal(st.steps, 8);
    o.blowup_factor = -1;
    assert_int_equal(hj_ls_ode(1, &g, &c.base, span, 2, y, &o, NULL, NULL, NULL, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_ode(4, &g, &c.base, span, 2, y, NULL, NULL, NULL, NULL, &err), HJ_EINVAL);
    double bad[2] = {1, 0};
    assert_int_equal(hj_ls_ode(1, &g, &c.base, bad, 2, y, NULL, NULL, NULL, NULL, &err), HJ_EINVAL);
    /* FactorCFL outside (0, 1], where the schemes are stable: refused
     * before any step, y untouched; 1 itself is allowed. */
    c.rate = 1;
    const double factors[] = {5, 1.0000001, 0, -0.5, NAN, INFINITY};
    for (int q = 0; q < 6; q++) {
        for (int j = 0; j < 4; j++) y[g.offset + (size_t)j] = 0;
        hj_ls_ode_defaults(&o);
        o.factor_cfl = factors[q];
        assert_int_equal(hj_ls_ode(3, &g, &c.base, span, 2, y, &o, NULL, NULL, NULL, &err), HJ_EINVAL);
        assert_non_null(strstr(err.msg, "FactorCFL must be in (0, 1]"));
        assert_true(y[g.offset] == 0);
    }
    o.factor_cfl = 1;
    assert_int_equal(hj_ls_ode(3, &g, &c.base, span, 2, y, &o, NULL, NULL, NULL, &err), HJ_OK);
    /* a NaN or infinity in the initial state is named before any step */
    const double nonfinite[2] = {NAN, -INFINITY};
    for (int q = 0; q < 2; q++) {
        for (int j = 0; j < 4; j++) y[g.offset + (size_t)j] = 0;
        y[g.offset + 2] = nonfinite[q];
        assert_int_equal(hj_ls_ode(3, &g, &c.base, span, 2, y, NULL, NULL, NULL, NULL, &err), HJ_ENONFINITE);
        assert_non_null(strstr(err.msg, "non-finite initial state at x = ("));
        assert_true(y[g.offset] == 0);
    }
    hj_ls_free(y);
}

static double bump(const double *x, void *ctx)
{
    (void)ctx;
    return sqrt((x[0] - 0.1) * (x[0] - 0.1) + (x[1] + 0.2) * (x[1] + 0.2)) - 0.4;
}

static void swirl(double t, const double *x, double dx0, long n, int d, double *v, void *ctx)
{
    (void)ctx;
    for (long j = 0; j < n; j++) {
        const double x0 = x[0] + (double)j * dx0;
        v[j] = d == 0 ? -x[1] * (1 + t) : x0 * x0 - 0.3;
    }
}

static int fail_at_step3(double t, double *y, void *ctx, hj_error *err)
{
    (void)t, (void)y;
    return ++*(int *)ctx == 3 ? hj_error_set(err, HJ_EINVAL, "stop") : HJ_OK;
}

/* swirl with NaN: the integration fails inside its first step (run on one thread) */
static void swirl_nan(double t, const double *x, double dx0, long n, int d, double *v, void *ctx)
{
    swirl(t, x, dx0, n, d, v, ctx);
    for (long j = 0; j < n; j++) v[j] = NAN;
}

/* WENO5 + RK3 convection and normal motion on 2-D with 1 and 2 threads:
 * bitwise the same state, with the threads chosen per step by their
 * measured time (the first step on one thread, the second on both) and
 * with always_parallel; the caller's thread count is back after the
 * run, also after one that fails. */
static void threads_bitwise(void **state)
{
    (void)state;
#ifdef _OPENMP
    hj_ls_grid g;
    double mn[2] = {-1, -1}, mx[2] = {1, 1};
    long N[2] = {41, 37};
    hj_ls_bc bc[2] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_PERIODIC, 0, 0}};
    assert_int_equal(hj_ls_grid_init(&g, 2, mn, mx, N, bc, NULL), HJ_OK);
    double *a = hj_ls_alloc(&g), *b = hj_ls_alloc(&g), span[2] = {0, 0.05};
    hj_ls_convection c;
    hj_ls_convection_init(&c, &g, HJ_LS_WENO5A);
    c.velocity_fn = swirl;
    hj_ls_normal nm;
    hj_ls_normal_init(&nm, &g, HJ_LS_WENO5B);
    nm.speed.value = 0.5;
    const hj_ls_term *terms[2] = {&c.base, &nm.base};
    hj_ls_sum sum;
    assert_int_equal(hj_ls_sum_init(&sum, &g, terms, 2, NULL), HJ_OK);
    for (int run = 0; run < 3; run++) {
        const int th = run ? 2 : 1;
        omp_set_num_threads(th);
        assert_int_equal(omp_get_max_threads(), th);
        double *y = th == 1 ? a : b;
        hj_ls_fill(&g, y, bump, NULL);
        hj_ls_ode_opts o;
        hj_ls_ode_defaults(&o);
        o.always_parallel = run == 2;
        hj_ls_ode_stats st;
        assert_int_equal(hj_ls_ode(3, &g, &sum.base, span, 2, y, &o, NULL, NULL, &st, NULL), HJ_OK);
        assert_true(st.steps > 2);
        assert_int_equal(omp_get_max_threads(), th);
        long idx[2];
        for (size_t r = 0; run && r < g.rows; r++) {
            size_t k = hj_ls_row(&g, r, idx);
            assert_memory_equal(a + k, b + k, sizeof(double) * (size_t)g.N[0]);
        }
    }
    hj_ls_ode_opts o;
    hj_ls_ode_defaults(&o);
    int calls = 0;
    o.post = fail_at_step3, o.post_ctx = &calls;
    hj_error e;
    hj_ls_fill(&g, b, bump, NULL);
    assert_int_equal(hj_ls_ode(3, &g, &sum.base, span, 2, b, &o, NULL, NULL, NULL, &e), HJ_EINVAL);
    assert_int_equal(omp_get_max_threads(), 2);
    c.velocity_fn = swirl_nan;
    hj_ls_fill(&g, b, bump, NULL);
    assert_int_not_equal(hj_ls_ode(3, &g, &c.base, span, 2, b, NULL, NULL, NULL, NULL, &e), HJ_OK);
    assert_int_equal(omp_get_max_threads(), 2);
    omp_set_num_threads(1);
    hj_ls_sum_free(&sum);
    hj_ls_free(a), hj_ls_free(b);
#else
    skip();
#endif
}

/* A 2-D Hamiltonian H = v(x) . p - |p_1| / 2 with partials |v_d| + c
 * (c = 0.5 for d = 1): bounds of x only (constant, as air3D's), or, with
 * ctx set, 1.5 times larger from t = 0.1 on (an output time: the first
 * step after it changes the bound). */
static double lf_ham(double t, const double *x, double phi, const double *p, void *ctx)
{
    (void)t, (void)phi, (void)ctx;
    return -x[1] * p[0] + (x[0] * x[0] - 0.3) * p[1] - 0.5 * fabs(p[1]);
}
static double lf_partial(double t, const double *x, const double *pmin, const double *pmax, int d, void *ctx)
{
    (void)pmin, (void)pmax;
    const double s = ctx && t >= 0.1 ? 1.5 : 1;
    return s * (d == 0 ? fabs(x[1]) : fabs(x[0] * x[0] - 0.3) + 0.5);
}

/* The term it wraps, without the fused form (eval only). */
typedef struct {
    hj_ls_term base;
    const hj_ls_term *inner;
} plain_term;
static int plain_eval(const hj_ls_term *term, double t, double *y, double *ydot, double *bound, hj_error *err)
{
    const plain_term *c = (const plain_term *)term;
    return c->inner->eval(c->inner, t, y, ydot, bound, err);
}

/* The fused-stage runs' grid: 37 x 29 nodes on [-1, 1]^2 (unequal sides,
 * rows not a multiple of the blocks of 8), extrapolated away. */
static hj_ls_grid fused_grid(void)
{
    hj_ls_grid g;
    double mn[2] = {-1, -1}, mx[2] = {1, 1};
    long N[2] = {37, 29};
    hj_ls_bc bc[2] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
    assert_int_equal(hj_ls_grid_init(&g, 2, mn, mx, N, bc, NULL), HJ_OK);
    return g;
}

/* Integrates from `bump` over span with `term` evaluated and combined in
 * separate passes (through plain_term) into a, and fused into b: the same
 * steps, CFL violations and bits at every interior node; *s0, *s1 the
 * two runs' statistics. */
static void run_plain_and_fused(const hj_ls_grid *g, int order, const hj_ls_term *term, const double *span, double *a,
                                double *b, hj_ls_ode_stats *s0, hj_ls_ode_stats *s1)
{
    plain_term pt = {{plain_eval}, term};
    hj_ls_fill(g, a, bump, NULL);
    hj_ls_fill(g, b, bump, NULL);
    assert_int_equal(hj_ls_ode(order, g, &pt.base, span, 3, a, NULL, NULL, NULL, s0, NULL), HJ_OK);
    assert_int_equal(hj_ls_ode(order, g, term, span, 3, b, NULL, NULL, NULL, s1, NULL), HJ_OK);
    assert_true(s0->steps > 10);
    assert_int_equal(s0->steps, s1->steps);
    assert_int_equal(s0->cfl_violations, s1->cfl_violations);
    long idx[2];
    for (size_t r = 0; r < g->rows; r++) {
        const size_t k = hj_ls_row(g, r, idx);
        assert_memory_equal(a + k, b + k, sizeof(double) * (size_t)g->N[0]);
    }
}

/* RK1, RK2 and RK3 with a restricted Lax-Friedrichs term (stages fused
 * into its pass; with a constant bound the first stage too, guessed from
 * the last steps' bound: at order 1 the whole step, into a second array) give the bits and steps of the same term evaluated and
 * combined in separate passes, with 1 and 2 threads; where the bound
 * changes the guess misses and costs one evaluation, not bits. */
static void fused_stages_bitwise(void **state)
{
    (void)state;
    hj_ls_grid g = fused_grid();
    double *a = hj_ls_alloc(&g), *b = hj_ls_alloc(&g), span[3] = {0, 0.1, 0.23};
    const int threads = hj_test_max_threads();
    static int grows = 1;
    for (int varying = 0; varying < 2; varying++)
        for (int order = 1; order <= 3; order++)
            for (int th = 1; th <= threads; th++) {
                hj_test_threads(th);
                hj_ls_lax_friedrichs lf;
                hj_ls_lax_friedrichs_init(&lf, &g, HJ_LS_ENO2, HJ_LS_GLF, lf_ham, lf_partial, varying ? &grows : NULL);
                lf.range_free = 1;
                hj_ls_restrict rs;
                hj_ls_restrict_init(&rs, &g, &lf.base, 0);
                hj_ls_ode_stats s0, s1;
                run_plain_and_fused(&g, order, &rs.base, span, a, b, &s0, &s1);
                assert_int_equal(s1.evals, s0.evals + varying); /* the guess that missed */
            }
    hj_test_one_thread();
    hj_ls_free(a), hj_ls_free(b);
}

static void rotation(double t, const double *x, double dx0, long n, int d, double *v, void *ctx)
{
    (void)t, (void)ctx;
    for (long j = 0; j < n; j++) v[j] = d == 0 ? 2 * x[1] : -2 * (x[0] + (double)j * dx0) + 0.3;
}

/* RK1, RK2 and RK3 with a convection term (stages fused into its pass; a
 * velocity independent of t, called per stage or cached by
 * velocity_steady, fuses the first stage too) give the bits and steps of
 * the term evaluated and combined in separate passes, 1 and 2 threads; a
 * velocity that changes with t (swirl) changes the bound, and the fused
 * run costs no more evaluations than the guesses that missed. */
static void convection_fused_bitwise(void **state)
{
    (void)state;
    hj_ls_grid g = fused_grid();
    double *a = hj_ls_alloc(&g), *b = hj_ls_alloc(&g), span[3] = {0, 0.1, 0.23};
    const int threads = hj_test_max_threads();
    for (int flow = 0; flow < 3; flow++) /* swirl; rotation; rotation, steady */
        for (int order = 1; order <= 3; order++)
            for (int th = 1; th <= threads; th++) {
                hj_test_threads(th);
                hj_ls_convection c;
                hj_ls_convection_init(&c, &g, order == 3 ? HJ_LS_WENO5A : HJ_LS_ENO2);
                c.velocity_fn = flow ? rotation : swirl;
                c.velocity_steady = flow == 2;
                hj_ls_ode_stats s0, s1;
                run_plain_and_fused(&g, order, &c.base, span, a, b, &s0, &s1);
                hj_ls_convection_free(&c);
                if (flow) assert_int_equal(s1.evals, s0.evals); /* every guess kept */
                else assert_true(s1.evals <= s0.evals + 1);
            }
    hj_test_one_thread();
    hj_ls_free(a), hj_ls_free(b);
}

/* A failing output or PostTimestep callback: its code is returned, with
 * its own message, or one that says which callback failed and when (an
 * empty message before). */
static int failing_output(int k, double t, const double *y, void *ctx, hj_error *err)
{
    (void)k, (void)t, (void)y, (void)ctx, (void)err;
    return HJ_EIO;
}
static int failing_post(double t, double *y, void *ctx, hj_error *err)
{
    (void)t, (void)y;
    return ctx ? hj_error_set(err, 42, "my post failed") : 42;
}
static void callback_errors(void **state)
{
    (void)state;
    hj_ls_grid g = grid1(8);
    const_term c = {{const_eval}, &g, 0.01, 0};
    double *y = hj_ls_alloc(&g), span[3] = {0, 0.1, 0.2};
    hj_error err;
    assert_int_equal(hj_ls_ode(1, &g, &c.base, span, 3, y, NULL, failing_output, NULL, NULL, &err), HJ_EIO);
    assert_int_equal(err.code, HJ_EIO);
    assert_has(err.msg, "the output callback returned 3 at t = 0.1");
    assert_has(err.msg, "(as a libhj code: input/output error)");
    hj_ls_ode_opts o;
    hj_ls_ode_defaults(&o);
    o.post = failing_post;
    assert_int_equal(hj_ls_ode(1, &g, &c.base, span, 3, y, &o, NULL, NULL, NULL, &err), 42);
    assert_has(err.msg, "the PostTimestep callback returned 42 at t = ");
    assert_null(strchr(err.msg, '(')); /* 42 is no library code */
    o.post_ctx = &o;
    assert_int_equal(hj_ls_ode(1, &g, &c.base, span, 3, y, &o, NULL, NULL, NULL, &err), 42);
    assert_string_equal(err.msg, "my post failed");
    hj_ls_free(y);
}

/* A term made on one grid and integrated on another: the term's stencils
 * would index the integrator's arrays with the other grid's strides (out
 * of bounds on a larger grid, silently wrong on a smaller one), so it is
 * refused before any step, as is one wrapped in a restriction, a sum or
 * an extremum; a copy of the same grid is the same grid.  NULL
 * arguments are refused too. */
static void term_on_another_grid(void **state)
{
    (void)state;
    hj_ls_grid g = fused_grid(), small, big;
    double mn[2] = {-1, -1}, mx[2] = {1, 1};
    long Ns[2] = {21, 21}, Nb[2] = {81, 81};
    hj_ls_bc bc[2] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
    assert_int_equal(hj_ls_grid_init(&small, 2, mn, mx, Ns, bc, NULL), HJ_OK);
    assert_int_equal(hj_ls_grid_init(&big, 2, mn, mx, Nb, bc, NULL), HJ_OK);
    double *y = hj_ls_alloc(&g), span[2] = {0, 0.1};
    assert_non_null(y);
    hj_error err;
    const hj_ls_grid *others[2] = {&small, &big};
    for (int q = 0; q < 2; q++) {
        hj_ls_convection c;
        hj_ls_convection_init(&c, others[q], HJ_LS_ENO2);
        c.velocity[0] = 1;
        assert_int_equal(hj_ls_ode(2, &g, &c.base, span, 2, y, NULL, NULL, NULL, NULL, &err), HJ_EINVAL);
        assert_has(err.msg, "another grid");
        hj_ls_restrict r;
        hj_ls_restrict_init(&r, &g, &c.base, 0);
        assert_int_equal(hj_ls_ode(2, &g, &r.base, span, 2, y, NULL, NULL, NULL, NULL, &err), HJ_EINVAL);
        assert_has(err.msg, "another grid");
        hj_ls_curvature_term k;
        hj_ls_curvature_term_init(&k, &g);
        const hj_ls_term *terms[2] = {&k.base, &c.base};
        hj_ls_sum s;
        assert_int_equal(hj_ls_sum_init(&s, &g, terms, 2, &err), HJ_OK);
        assert_int_equal(hj_ls_ode(2, &g, &s.base, span, 2, y, NULL, NULL, NULL, NULL, &err), HJ_EINVAL);
        assert_has(err.msg, "another grid");
        hj_ls_sum_free(&s);
        hj_ls_extremum x;
        assert_int_equal(hj_ls_extremum_init(&x, &g, terms, 2, 0, &err), HJ_OK);
        assert_int_equal(hj_ls_ode(2, &g, &x.base, span, 2, y, NULL, NULL, NULL, NULL, &err), HJ_EINVAL);
        assert_has(err.msg, "another grid");
        hj_ls_extremum_free(&x);
        assert_true(y[g.offset] == 0);
    }
    /* the same layout in another struct (a copy): accepted */
    hj_ls_grid copy = g;
    hj_ls_convection c;
    hj_ls_convection_init(&c, &copy, HJ_LS_ENO2);
    c.velocity[0] = 1;
    assert_int_equal(hj_ls_ode(2, &g, &c.base, span, 2, y, NULL, NULL, NULL, NULL, &err), HJ_OK);
    /* NULL arguments */
    assert_int_equal(hj_ls_ode(2, NULL, &c.base, span, 2, y, NULL, NULL, NULL, NULL, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_ode(2, &g, NULL, span, 2, y, NULL, NULL, NULL, NULL, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_ode(2, &g, &c.base, NULL, 2, y, NULL, NULL, NULL, NULL, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_ode(2, &g, &c.base, span, 2, NULL, NULL, NULL, NULL, NULL, &err), HJ_EINVAL);
    assert_has(err.msg, "NULL");
    hj_ls_free(y);
}

/* Grids that place their nodes alike are the same grid, whatever their
 * boundary conditions' unused values: lo and hi are read only for
 * Dirichlet and Neumann conditions, so a periodic or extrapolating
 * condition's lo and hi (left uninitialised by a caller, or set in
 * another way) do not make another grid.  A different Dirichlet value or
 * spacing does, and the message names what differs. */
static void term_grid_unused_bc_values(void **state)
{
    (void)state;
    double mn[2] = {-1, -1}, mx[2] = {1, 1};
    long N[2] = {21, 21};
    const int types[3] = {HJ_LS_BC_PERIODIC, HJ_LS_BC_EXTRAP_AWAY, HJ_LS_BC_EXTRAP_TOWARD};
    hj_error err;
    for (int q = 0; q < 3; q++) {
        hj_ls_bc bc0[2] = {{types[q], 0, 0}, {types[q], 0, 0}}, bc1[2] = {{types[q], 7, -3}, {types[q], 0.5, 2}};
        hj_ls_grid g0, g1;
        assert_int_equal(hj_ls_grid_init(&g0, 2, mn, mx, N, bc0, NULL), HJ_OK);
        assert_int_equal(hj_ls_grid_init(&g1, 2, mn, mx, N, bc1, NULL), HJ_OK);
        hj_ls_convection c;
        hj_ls_convection_init(&c, &g1, HJ_LS_ENO2);
        assert_int_equal(hj_ls_term_check_grid(&c.base, &g0, &err), HJ_OK);
    }
    hj_ls_bc d0[2] = {{HJ_LS_BC_DIRICHLET, 0, 0}, {HJ_LS_BC_DIRICHLET, 0, 0}};
    hj_ls_bc d1[2] = {{HJ_LS_BC_DIRICHLET, 0, 0}, {HJ_LS_BC_DIRICHLET, 0, 1}};
    hj_ls_grid g0, g1, g2;
    assert_int_equal(hj_ls_grid_init(&g0, 2, mn, mx, N, d0, NULL), HJ_OK);
    assert_int_equal(hj_ls_grid_init(&g1, 2, mn, mx, N, d1, NULL), HJ_OK);
    assert_int_equal(hj_ls_grid_init(&g2, 2, mn, (double[]){1, 1.5}, N, d0, NULL), HJ_OK);
    hj_ls_convection c;
    hj_ls_convection_init(&c, &g1, HJ_LS_ENO2);
    assert_int_equal(hj_ls_term_check_grid(&c.base, &g0, &err), HJ_EINVAL);
    assert_has(err.msg, "boundary condition of dimension 1");
    hj_ls_convection_init(&c, &g2, HJ_LS_ENO2);
    assert_int_equal(hj_ls_term_check_grid(&c.base, &g0, &err), HJ_EINVAL);
    assert_has(err.msg, "spacing of dimension 1");
    /* a periodic grid from hj_ls_grid_init_period and the same nodes from
     * hj_ls_grid_init on its max: spacings (max - min) / N and
     * (max' - min) / (N - 1), apart by an ulp for a third of the N */
    hj_ls_bc per[1] = {{HJ_LS_BC_PERIODIC, 0, 0}};
    int differ = 0;
    for (long n = 10; n <= 400; n++) {
        hj_ls_grid a, b;
        assert_int_equal(hj_ls_grid_init_period(&a, 1, (double[]){0}, (double[]){2 * HJ_PI}, &n, per, NULL), HJ_OK);
        assert_int_equal(hj_ls_grid_init(&b, 1, (double[]){0}, a.max, &n, per, NULL), HJ_OK);
        differ += a.dx[0] != b.dx[0];
        hj_ls_convection_init(&c, &a, HJ_LS_ENO2);
        if (hj_ls_term_check_grid(&c.base, &b, &err)) fail_msg("N = %ld: %s", n, err.msg);
        /* a spacing apart by more than rounding is another grid */
        b.dx[0] *= 1 + 1e-12;
        assert_int_equal(hj_ls_term_check_grid(&c.base, &b, &err), HJ_EINVAL);
    }
    assert_true(differ > 100);
}

/* A term whose (void) init was given a NULL grid is refused by hj_ls_ode
 * before any step (its eval dereferenced the grid: a segfault), as is a
 * sum or an extremum on a NULL grid by its init. */
static void term_on_null_grid(void **state)
{
    (void)state;
    hj_ls_grid g = grid1(8);
    double *y = hj_ls_alloc(&g), span[2] = {0, 0.1};
    hj_error err;
    hj_ls_convection c;
    hj_ls_convection_init(&c, NULL, HJ_LS_ENO2);
    c.velocity[0] = 1;
    assert_int_equal(hj_ls_ode(1, &g, &c.base, span, 2, y, NULL, NULL, NULL, NULL, &err), HJ_EINVAL);
    assert_has(err.msg, "NULL grid");
    hj_ls_restrict r;
    hj_ls_restrict_init(&r, &g, &c.base, 0);
    assert_int_equal(hj_ls_ode(1, &g, &r.base, span, 2, y, NULL, NULL, NULL, NULL, &err), HJ_EINVAL);
    hj_ls_convection_init(&c, &g, HJ_LS_ENO2);
    const hj_ls_term *terms[1] = {&c.base};
    hj_ls_sum s;
    assert_int_equal(hj_ls_sum_init(&s, NULL, terms, 1, &err), HJ_EINVAL);
    assert_has(err.msg, "grid is NULL");
    hj_ls_extremum x;
    assert_int_equal(hj_ls_extremum_init(&x, NULL, terms, 1, 0, &err), HJ_EINVAL);
    hj_ls_free(y);
}

/* A grid whose one array fits in memory but whose integration does not
 * (the state and the two stage arrays: 3 arrays of 0.45 of the machine's
 * memory) is refused with HJ_ENOMEM before the state is read or an array
 * allocated: before, the stage arrays' calloc succeeded (overcommit) and
 * the first step's writes would page or be killed by the kernel's OOM
 * killer.  The state passed here is a small dummy, never read. */
static void integration_beyond_memory(void **state)
{
    (void)state;
    const double mem = hj_sys_physical_memory();
    if (!(mem > 0)) skip();
    const long n0 = 1 << 15, n1 = (long)(0.45 * mem / 8.0 / (double)n0);
    const double lo[2] = {0, 0}, hi[2] = {1, 1};
    const hj_ls_bc bc[2] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
    hj_ls_grid g;
    hj_error err;
    assert_int_equal(hj_ls_grid_init(&g, 2, lo, hi, (long[]){n0, n1}, bc, &err), HJ_OK);
    hj_ls_normal nm;
    hj_ls_normal_init(&nm, &g, HJ_LS_UPWIND_FIRST);
    nm.speed.value = 1;
    double dummy[1] = {0};
    const double span[2] = {0, 1};
    for (int order = 1; order <= 3; order++) {
        assert_int_equal(hj_ls_ode(order, &g, &nm.base, span, 2, dummy, NULL, NULL, NULL, NULL, &err), HJ_ENOMEM);
        assert_has(err.msg, "GB");
    }
}

HJ_TEST_MAIN_ONE_THREAD("hj_ls_ode", NULL, NULL, cmocka_unit_test(integrator_orders),
                        cmocka_unit_test(outputs_and_options), cmocka_unit_test(no_motion), cmocka_unit_test(endless_span), cmocka_unit_test(tiny_span_steps), cmocka_unit_test(error_reports),
                        cmocka_unit_test(threads_bitwise), cmocka_unit_test(fused_stages_bitwise),
                        cmocka_unit_test(convection_fused_bitwise), cmocka_unit_test(term_on_another_grid), cmocka_unit_test(term_grid_unused_bc_values), cmocka_unit_test(term_on_null_grid), cmocka_unit_test(callback_errors), cmocka_unit_test(integration_beyond_memory))
