/* hj_ls_ode.c -- TVD Runge-Kutta integrators of order 1, 2, 3. */
#include "hj_ls_ode.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "hj_sys.h"

void hj_ls_ode_defaults(hj_ls_ode_opts *o)
{
    o->factor_cfl = 0.5;
    o->max_step = DBL_MAX;
    o->post = NULL;
    o->post_ctx = NULL;
    o->single_step = 0;
    o->blowup_factor = 1e6;
    o->always_parallel = 0;
}

static double wall(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* AVX-512 and AVX2 clones of the row loop where the CPU has them
 * (-std=c11 contracts no multiply-add: the bits are the SSE2 code's). */
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__SANITIZE_ADDRESS__) && !defined(__clang__)
#define HJ_LS_ODE_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define HJ_LS_ODE_CLONES
#endif
#ifdef _OPENMP
#define HJ_LS_ODE_SIMD _Pragma("omp simd reduction(| : rb) reduction(max : rm)")
#else
#define HJ_LS_ODE_SIMD
#endif

/* One row of combine: n nodes from q = 0.  dst may alias y or u node for
 * node only (same q), so the lanes carry no dependence: "omp simd" lets
 * gcc vectorise the loop and its reductions without -ffast-math.  Returns
 * 1 if a value is not finite; *amax = max(*amax, max |dst|). */
HJ_LS_ODE_CLONES
static int combine_row(long n, double *dst, double a, const double *y, double b, const double *u, double dt,
                       const double *f, double *amax)
{
    int rb = 0;
    double rm = *amax;
    HJ_LS_ODE_SIMD
    for (long q = 0; q < n; q++) {
        const double v = a * y[q] + b * (u[q] + dt * f[q]);
        dst[q] = v;
        rb |= !(v - v == 0); /* NaN or Inf */
        const double av = v < 0 ? -v : v;
        rm = av > rm ? av : rm;
    }
    *amax = rm;
    return rb;
}

/* dst = a y + b (u + dt f) over the interior; returns 1 if a value of dst
 * is not finite, and *amax = max |dst| (a maximum: the same for any thread
 * count; meaningful only when every value is finite).  dst may alias y or
 * u. */
static int combine(const hj_ls_grid *g, double *dst, double a, const double *y, double b, const double *u, double dt,
                   const double *f, double *amax)
{
    int bad = 0;
    double m = 0;
    const long n = g->N[0];
    /* A small grid on one thread: a streaming pass of microseconds costs
     * less than waking another thread (the same values either way). */
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 32) reduction(| : bad) reduction(max : m) if (g->nodes >= 65536)
#endif
    for (size_t r = 0; r < g->rows; r++) {
        long idx[HJ_LS_MAXDIM];
        const size_t k = hj_ls_row(g, r, idx);
        double rm = 0;
        bad |= combine_row(n, dst + k, a, y + k, b, u + k, dt, f + k, &rm);
        m = rm > m ? rm : m;
    }
    *amax = m;
    return bad;
}

/* A stage after the first: dst = a y0 + b (u + dt G(t, u)), fused into
 * the term's pass where the term has that form (hj_ls_term_stage: one
 * pass over the grid instead of two, the same bits; *fused = 1), else the
 * term into f and combine (*fused = 0).  dst is y0 (the last stage: each
 * node written after its reads) or f (a middle stage: then, unfused, the
 * stage goes into u in place, since f holds G).  *bad and *amax as
 * combine's. */
static int stage(const hj_ls_grid *g, const hj_ls_term *term, double t, double a, double *y0, double b, double *u,
                 double dt, double *dst, double *f, int *fused, double *bound, int *bad, double *amax, hj_error *err)
{
    hj_ls_stage st = {a, b, dt, y0, dst, 0, 0};
    int rc = hj_ls_term_stage(term, t, u, &st, bound, fused, err);
    if (rc) return rc;
    if (*fused) {
        *amax = st.amax, *bad = st.bad;
        return HJ_OK;
    }
    if ((rc = term->eval(term, t, u, f, bound, err))) return rc;
    *bad = combine(g, dst == f ? u : dst, a, y0, b, u, dt, f, amax);
    return HJ_OK;
}

/* The scale against which growth counts as a blow-up: the larger of
 * max |y0| and the domain's diameter (a signed distance never exceeds it). */
static double blowup_scale(const hj_ls_grid *g, const double *y)
{
    double m = 0, diam2 = 0;
    for (int d = 0; d < g->dim; d++) diam2 += (g->max[d] - g->min[d]) * (g->max[d] - g->min[d]);
    for (size_t r = 0; r < g->rows; r++) {
        long idx[HJ_LS_MAXDIM];
        const size_t k = hj_ls_row(g, r, idx);
        for (long j = 0; j < g->N[0]; j++) {
            const double av = fabs(y[k + (size_t)j]);
            m = av > m ? av : m;
        }
    }
    hj_ls_grid_reduce(g, &m, 1, HJ_LS_REDUCE_MAX);
    const double diam = sqrt(diam2);
    return m > diam ? m : diam;
}

/* HJ_ENONFINITE naming the first node of y0 that is NaN or infinite (on
 * a distributed grid every block returns it, the block holding the node
 * names it): the terms would only see it as a blow-up after a step. */
static int check_initial(const hj_ls_grid *g, const double *y, hj_error *err)
{
    size_t bad_r = 0;
    long bad_j = -1;
    for (size_t r = 0; r < g->rows && bad_j < 0; r++) {
        long idx[HJ_LS_MAXDIM];
        const size_t k = hj_ls_row(g, r, idx);
        for (long j = 0; j < g->N[0]; j++)
            if (!isfinite(y[k + (size_t)j])) {
                bad_r = r, bad_j = j;
                break;
            }
    }
    double any = bad_j >= 0;
    hj_ls_grid_reduce(g, &any, 1, HJ_LS_REDUCE_MAX);
    if (!(any > 0)) return HJ_OK;
    if (bad_j < 0) return hj_error_set(err, HJ_ENONFINITE, "non-finite initial state in another block");
    char pos[256];
    hj_ls_format_node(g, bad_r, bad_j, pos, sizeof pos);
    return hj_error_set(err, HJ_ENONFINITE, "non-finite initial state at x = (%s)", pos);
}

/* A callback of the caller's that failed without a message: say which
 * and when (err as the callback left it otherwise: its code may be the
 * caller's own, apart from the return value, as hj_reach's stop codes).
 * Any nonzero value is a failure of the caller's choosing, so a value in
 * the library's range is read as its code only in a parenthesis ("1" may
 * just mean "failed"). */
static void callback_failed(int rc, const char *what, double t, hj_error *err)
{
    if (!err || err->msg[0]) return;
    if (rc != HJ_OK && hj_error_known(rc))
        hj_error_set(err, rc, "%s returned %d at t = %.17g (as a libhj code: %s)", what, rc, t, hj_strerror(rc));
    else
        hj_error_set(err, rc, "%s returned %d at t = %.17g", what, rc, t);
}

/* An infinite bound is checked with the term's values (moves_at). */
static int check_bound(double b, double t, hj_error *err)
{
    if (isnan(b) || b == -INFINITY) return hj_error_set(err, HJ_ENONFINITE, "non-finite CFL bound at t = %g", t);
    if (!(b > 0)) return hj_error_set(err, HJ_EINVAL, "zero CFL bound at t = %g", t);
    return HJ_OK;
}

/* Whether ydot is non-zero at some interior node (of any block): an
 * infinite bound says only that no stencil limits the step (a forcing
 * term, G = -F, has one and moves), not that nothing moves. */
static int moves_at(const hj_ls_grid *g, const double *ydot)
{
    double any = 0;
    for (size_t r = 0; r < g->rows && !(any > 0); r++) {
        long idx[HJ_LS_MAXDIM];
        const size_t k = hj_ls_row(g, r, idx);
        for (long j = 0; j < g->N[0]; j++)
            if (ydot[k + (size_t)j] != 0) {
                any = 1;
                break;
            }
    }
    hj_ls_grid_reduce(g, &any, 1, HJ_LS_REDUCE_MAX);
    return any > 0;
}

/* A step of an infinite bound without MaxStep: only where nothing moves
 * (ydot zero at every node), run to the next output time; it holds only if
 * nothing moves at its end either.  The term is evaluated at t + dt into
 * scratch: motion there (a velocity that starts from zero) would have been
 * stepped over. */
static int still_at_end(const hj_ls_grid *g, const hj_ls_term *term, double t, double dt, double *y, double *scratch,
                        hj_ls_ode_stats *st, hj_error *err)
{
    double b;
    int rc = term->eval(term, t + dt, y, scratch, &b, err);
    st->evals++;
    if (rc) return rc;
    if (!(b == INFINITY) || moves_at(g, scratch))
        return hj_error_set(err, HJ_EINVAL,
                            "no motion at t = %g (infinite CFL bound) but motion at t = %g, the end of the step to "
                            "the next output time: give a MaxStep",
                            t, t + dt);
    return HJ_OK;
}

/* A stage array (hj_ls_alloc's zeros) placed slot KB into its block: the
 * state and the stage arrays, each a large allocation that starts at the
 * same offset within a page, would otherwise put node k of every array at
 * the same address modulo 4 KB, and a load of one then waits on the store
 * to another still in flight (a row's fused stage reads y0 and u and
 * writes dst at the same k).  *base is what to free. */
/* Threads per step (hj_ls_ode_opts.always_parallel): the wall time of
 * each step in its mode, 0 with the threads, 1 on one of them; the first
 * step on one, the second with all, then the mode of the smaller time,
 * the other one timed again TUNE_GAP steps later, the gap doubled (up to
 * TUNE_GAP_MAX) each time the choice stands.  Every term's result is the
 * same bits for any thread count, so only the time changes. */
enum { TUNE_GAP = 8, TUNE_GAP_MAX = 256 };
typedef struct {
    int on, nth, mode;
    double cost[2]; /* wall seconds of a step (0: not yet timed) */
    long it, probe, gap;
    double t0;
} step_tuner;

static void tuner_init(step_tuner *t, const hj_ls_ode_opts *o)
{
    memset(t, 0, sizeof *t);
    t->nth = hj_sys_max_threads();
    t->on = t->nth > 1 && !o->always_parallel && !o->single_step;
    t->gap = TUNE_GAP;
}

static void tuner_begin(step_tuner *t)
{
    if (!t->on) return;
    const int best = t->cost[1] < t->cost[0];
    t->mode = t->cost[1] == 0 ? 1 : t->cost[0] == 0 ? 0 : t->it == t->probe ? !best : best;
#ifdef _OPENMP
    omp_set_num_threads(t->mode ? 1 : t->nth);
#endif
    t->t0 = wall();
}

/* After the step's stages: the caller's thread count back (its callbacks
 * and the rest of the program see it), the step's time recorded. */
static void tuner_end(step_tuner *t)
{
    if (!t->on) return;
#ifdef _OPENMP
    omp_set_num_threads(t->nth);
#endif
    const double dt = wall() - t->t0;
    const int best = t->cost[1] < t->cost[0];
    /* the mode in use smoothed (one step may be preempted), a probe taken as it is */
    if (t->it == t->probe || t->cost[t->mode] == 0) t->cost[t->mode] = dt;
    else t->cost[t->mode] = 0.75 * t->cost[t->mode] + 0.25 * dt;
    if (t->cost[0] > 0 && t->cost[1] > 0 && t->it >= t->probe) {
        const int now = t->cost[1] < t->cost[0];
        if (t->it > 1) t->gap = now == best ? (t->gap * 2 < TUNE_GAP_MAX ? t->gap * 2 : TUNE_GAP_MAX) : TUNE_GAP;
        t->probe = t->it + t->gap;
    }
    t->it++;
}

static double *stage_alloc(const hj_ls_grid *g, int slot, double **base)
{
    const size_t shift = (size_t)slot * 1024 / sizeof(double);
    double *b = calloc(g->total + shift, sizeof(double));
    *base = b;
    return b ? b + shift : NULL;
}

static double step_of(double b, double left, const hj_ls_ode_opts *o, int *last)
{
    double dt = o->factor_cfl * b;
    dt = dt < o->max_step ? dt : o->max_step;
    *last = 0;
    if (dt >= left) dt = left, *last = 1;
    return dt;
}

double hj_ls_ode_span_small(double t0, double tk)
{
    const double roundoff = 100 * DBL_EPSILON * (fabs(tk) > 1 ? fabs(tk) : 1), part = 1e-6 * (tk - t0);
    return part < roundoff ? part : roundoff;
}

int hj_ls_ode(int order, const hj_ls_grid *g, const hj_ls_term *term, const double *tspan, int ntspan, double *y,
              const hj_ls_ode_opts *opts, hj_ls_output_fn out, void *out_ctx, hj_ls_ode_stats *stats, hj_error *err)
{
    hj_ls_ode_opts o;
    if (opts) o = *opts;
    else hj_ls_ode_defaults(&o);
    if (!g || !term || !tspan || !y)
        return hj_error_set(err, HJ_EINVAL, "hj_ls_ode: the %s is NULL",
                            !g ? "grid" : !term ? "term" : !tspan ? "tspan array" : "state y");
    if (order < 1 || order > 3)
        return hj_error_set(err, HJ_EINVAL, "integrator order must be 1, 2 or 3, got %d", order);
    int rcg = hj_ls_term_check_grid(term, g, err);
    if (rcg) return rcg;
    if (ntspan < 2) return hj_error_set(err, HJ_EINVAL, "tspan needs a start and at least one output time");
    for (int k = 0; k < ntspan; k++) {
        if (!isfinite(tspan[k])) return hj_error_set(err, HJ_ENONFINITE, "tspan[%d] is not finite", k);
        if (k && !(tspan[k] > tspan[k - 1]))
            return hj_error_set(err, HJ_EINVAL, "tspan must increase: tspan[%d] = %.17g <= tspan[%d] = %.17g", k,
                                tspan[k], k - 1, tspan[k - 1]);
    }
    /* (0, 1]: each scheme is a convex combination of Euler steps, stable up
     * to the term's bound (hj_ls_ode.h). */
    if (!(o.factor_cfl > 0 && o.factor_cfl <= 1))
        return hj_error_set(err, HJ_EINVAL, "FactorCFL must be in (0, 1], got %g", o.factor_cfl);
    if (!(o.max_step > 0)) return hj_error_set(err, HJ_EINVAL, "MaxStep must be positive, got %g", o.max_step);
    if (!(o.blowup_factor >= 0))
        return hj_error_set(err, HJ_EINVAL, "the blow-up factor must be >= 0 (0: no bound), got %g", o.blowup_factor);
    if (o.always_parallel != 0 && o.always_parallel != 1)
        return hj_error_set(err, HJ_EINVAL, "always_parallel must be 0 or 1, got %d", o.always_parallel);
    /* calloc refuses only a block beyond memory and swap: stage arrays
     * that fit one by one but not with the state would page, or the
     * first step's writes be killed; refuse before reading y */
    const double need = 3.0 * (double)sizeof(double) * (double)g->total;
    const double mem = need > 1e8 ? hj_sys_physical_memory() : 0; /* no system call per call on small grids */
    if (mem > 0 && need > mem)
        return hj_error_set(err, HJ_ENOMEM,
                            "hj_ls_ode: the integration needs %.3g GB (the state and two arrays of %zu doubles), the "
                            "machine has %.3g GB",
                            need / 1e9, g->total, mem / 1e9);
    int rc0 = check_initial(g, y, err);
    if (rc0) return rc0;
    const double limit = o.blowup_factor > 0 ? o.blowup_factor * blowup_scale(g, y) : INFINITY;

    hj_ls_ode_stats st = {0, 0, 0, tspan[0], 0};
    step_tuner tun;
    tuner_init(&tun, &o);
    const double start = wall();
    double *fbase = NULL, *ubase = NULL; /* what to free: u and f trade places */
    double *f = stage_alloc(g, 1, &fbase), *u = order > 1 ? stage_alloc(g, 2, &ubase) : NULL;
    /* The state: y, or at order 1 after a kept guess the array the step
     * went to (y and u then trade places; y receives the state at every
     * output and on return). */
    double *ys = y;
    int rc = HJ_OK;
    if (!f || (order > 1 && !u)) {
        rc = hj_error_set(err, HJ_ENOMEM, "out of memory for the integrator's stage arrays");
        goto done;
    }
    double t = tspan[0];
    double bprev = NAN; /* the previous step's bound */
    int same = 0;  /* steps it repeated for */
    /* 0: the term has no fused form (order 1 with a PostTimestep: the
     * callback sees the caller's array, as unfused) */
    int guess = order > 1 || !o.post;
    int hold = 0;  /* steps without guessing left after a miss */
    for (int k = 1; k < ntspan && rc == HJ_OK; k++) {
        const double tk = tspan[k];
        const double small = hj_ls_ode_span_small(tspan[k - 1], tk);
        while (tk - t > small) {
            double b, dt;
            int last = 0, bad, fused, guessed = 0;
            double amax;
            tuner_begin(&tun);
            if (hold) hold--;
            /* an infinite bound is never guessed: its step needs still_at_end */
            const int try_guess = guess && same >= 2 && !hold && bprev < INFINITY;
            if (try_guess && !u && !(u = stage_alloc(g, 2, &ubase))) guess = 0; /* order 1: no room */
            if (try_guess && guess) {
                /* The bound repeated bit for bit over the last steps (air3D's
                 * does not depend on t or y): the first stage is fused too,
                 * with the step of that bound, and kept only if the bound
                 * the stage returns is the same (then every value is what
                 * the unfused stage gives); a miss is evaluated again,
                 * unfused, and guessing waits many steps.  At order 1 the
                 * stage is the step (its combination is combine's). */
                dt = step_of(bprev, tk - t, &o, &last);
                hj_ls_stage s1 = {0, 1, dt, ys, u, 0, 0};
                if ((rc = hj_ls_term_stage(term, t, ys, &s1, &b, &fused, err))) goto done;
                if (!fused) guess = 0; /* no fused form: never again */
                else {
                    st.evals++;
                    guessed = !memcmp(&b, &bprev, sizeof b);
                    if (!guessed) hold = 16;
                    else if (order == 1) {
                        double *s = ys;
                        ys = u, u = s;
                        bad = s1.bad, amax = s1.amax;
                    }
                }
            }
            if (!guessed) {
                if ((rc = term->eval(term, t, ys, f, &b, err))) goto done;
                st.evals++;
                if ((rc = check_bound(b, t, err))) goto done;
                dt = step_of(b, tk - t, &o, &last);
                /* a step that leaves t as it is never ends the run */
                if (!last && t + dt == t) {
                    rc = hj_error_set(err, HJ_EINVAL, "the step %g (CFL bound %g) does not advance t = %g", dt, b, t);
                    goto done;
                }
                /* more than 2^52 steps to the output time never end (t + dt
                 * rounds to t long before); the guessed steps repeat this dt.
                 * A PostTimestep or a SingleStep caller may end the run
                 * itself (hj_reach stops on convergence within a span of
                 * DBL_MAX / 4, hj_ls_signed_distance steps to a t_max) */
                if (!o.post && !o.single_step && !last && (tk - t) / dt > 0x1p52) {
                    rc = hj_error_set(err, HJ_EINVAL,
                                      "the span from t = %g to %g needs more than 2^52 steps of %g (CFL bound %g)", t,
                                      tk, dt, b);
                    goto done;
                }
                if (b == INFINITY && !(o.max_step < DBL_MAX)) {
                    if (moves_at(g, f)) {
                        rc = hj_error_set(err, HJ_ENONFINITE,
                                          "infinite CFL bound at t = %g and no MaxStep, but the term moves (a "
                                          "forcing term, say): give a MaxStep",
                                          t);
                        goto done;
                    }
                    /* u is free here (order 1: spare, or allocated now) */
                    if (!u && !(u = stage_alloc(g, 2, &ubase))) {
                        rc = hj_error_set(err, HJ_ENOMEM, "out of memory for the integrator's stage arrays");
                        goto done;
                    }
                    if ((rc = still_at_end(g, term, t, dt, ys, u, &st, err))) goto done;
                }
            }
            same = memcmp(&b, &bprev, sizeof b) ? 0 : same + 1;
            bprev = b;
            if (order == 1) {
                if (!guessed) bad = combine(g, ys, 0, ys, 1, ys, dt, f, &amax);
            } else {
                if (!guessed) combine(g, u, 0, y, 1, y, dt, f, &amax);
                if (order == 3) {
                    if ((rc = stage(g, term, t + dt, 0.75, y, 0.25, u, dt, f, f, &fused, &b, &bad, &amax, err)))
                        goto done;
                    if (fused) { /* the stage is in f, which held no G: u and f trade places */
                        double *s = u;
                        u = f, f = s;
                    }
                    st.evals++;
                    st.cfl_violations += b < dt / o.factor_cfl;
                }
                const double tl = order == 2 ? t + dt : t + 0.5 * dt, al = order == 2 ? 0.5 : 1.0 / 3,
                             bl = order == 2 ? 0.5 : 2.0 / 3;
                if ((rc = stage(g, term, tl, al, y, bl, u, dt, y, f, &fused, &b, &bad, &amax, err))) goto done;
                st.evals++;
                st.cfl_violations += b < dt / o.factor_cfl;
            }
            tuner_end(&tun);
            if (g->dist) {
                double v[2] = {amax, bad};
                hj_ls_grid_reduce(g, v, 2, HJ_LS_REDUCE_MAX);
                amax = v[0], bad = v[1] != 0;
            }
            t = last ? tk : t + dt;
            st.steps++;
            st.t = t;
            if (bad) {
                rc = hj_error_set(err, HJ_ENONFINITE, "blow-up: NaN or Inf in the state at t = %.17g after step %ld",
                                  t, st.steps);
                goto done;
            }
            if (amax > limit) {
                rc = hj_error_set(err, HJ_ENONFINITE,
                                  "blow-up: max |phi| = %.3g exceeds %g times the initial scale (%.3g) at t = %.17g after "
                                  "step %ld", amax, o.blowup_factor, limit / o.blowup_factor, t, st.steps);
                goto done;
            }
            if (o.post) {
                hj_error_clear(err);
                if ((rc = o.post(t, y, o.post_ctx, err))) {
                    callback_failed(rc, "the PostTimestep callback", t, err);
                    goto done;
                }
            }
            if (o.single_step) goto done;
        }
        if (ys != y) { /* the state back into the caller's array */
            hj_ls_copy(g, y, ys);
            u = ys, ys = y;
        }
        if (out) {
            hj_error_clear(err);
            if ((rc = out(k, t, y, out_ctx, err))) {
                callback_failed(rc, "the output callback", t, err);
                goto done;
            }
        }
    }
done:
#ifdef _OPENMP
    if (tun.on) omp_set_num_threads(tun.nth); /* the caller's thread count back (a step that failed) */
#endif
    if (ys != y) {
        hj_ls_copy(g, y, ys);
        u = ys;
    }
    free(fbase);
    free(ubase);
    st.seconds = wall() - start;
    if (stats) *stats = st;
    return rc;
}
