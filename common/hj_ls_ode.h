/* hj_ls_ode.h -- explicit TVD Runge-Kutta integration with CFL-limited
 * steps (Mitchell's toolbox, section 3.5: odeCFL1, odeCFL2, odeCFL3).
 *
 * Solves D_t y = G(t, y), G given by a term (hj_ls_term.h), by the method
 * of lines.  Order 1 is forward Euler; order 2 Heun's TVD scheme
 *     u1 = y + dt G(y),  y' = (y + u1 + dt G(u1)) / 2;
 * order 3 Shu and Osher's TVD scheme
 *     u1 = y + dt G(y),  u2 = 3/4 y + 1/4 (u1 + dt G(u1)),
 *     y' = 1/3 y + 2/3 (u2 + dt G(u2)).
 * The step is dt = min(FactorCFL * bound, MaxStep, time to the next output
 * time), with bound the CFL bound returned by the term at the start of the
 * step (as in the toolbox, later stages are not re-limited; a stage whose
 * bound is below dt / FactorCFL is counted in the statistics).
 *
 * No motion: a term whose bound is infinite and whose values are zero at
 * every node (a velocity, speed or Hamiltonian that is zero everywhere) is
 * stepped to the next output time in one step (or by MaxStep when one is
 * given).  Without MaxStep the term is evaluated once more at the end of
 * that step: if it moves there (a velocity starting from zero), the step
 * would have skipped the motion, and HJ_EINVAL asks for a MaxStep.  Motion
 * that starts and stops within one such step is not seen: give a MaxStep
 * for such a term.  An infinite bound with non-zero values (a forcing
 * term, whose step no stencil limits) needs a MaxStep (HJ_ENONFINITE).
 *
 * FactorCFL must lie in (0, 1] (HJ_EINVAL otherwise): a term's bound is
 * the largest step for which one forward Euler step is stable (CFL number
 * 1 for its monotone scheme), and the TVD schemes above are convex
 * combinations of forward Euler steps of size dt (SSP coefficient 1), so
 * they keep that stability exactly up to dt = bound and lose it beyond.
 *
 * Memory: the state y plus two arrays (one stage, one time derivative),
 * whatever the order; when the three exceed the machine's physical memory
 * the call fails with HJ_ENOMEM (both sizes in the message) before it
 * reads y or allocates (the terms' own work arrays are not counted).
 *
 * Stages after the first are fused into the term's pass where the term
 * has that form (hj_ls_term_stage: convection, and Lax-Friedrichs alone
 * or restricted):
 * one pass over the grid per stage instead of two, the same bits.  When
 * the bound has repeated bit for bit over two steps (one independent of t
 * and y), the first stage is fused too, with the step of that bound, and
 * kept only if the bound it returns is the same again; a miss costs one
 * evaluation more (counted in evals) and guessing then pauses 16 steps.
 * At order 1 that stage is the whole step: it goes into the second array,
 * which then holds the state (y receives it at every output time and on
 * return); not with a PostTimestep, which sees y itself.
 *
 * Errors (returned, never printed): a step that does not advance t, a span
 * of more than 2^52 steps without a PostTimestep or SingleStep (which may
 * end the run), a NaN bound, a zero bound, motion at
 * the end of a step taken without it (above), the term's own errors, and
 * a blow-up: NaN or Inf in the state after a step, or finite growth
 * beyond blowup_factor
 * times the initial scale (max |y0| or the domain's diameter, the larger:
 * a level set function changes by at most t max |G|, so growth by 10^6 is
 * instability, not motion), reported with the time and the step number
 * (HJ_ENONFINITE).
 */
#ifndef HJ_LS_ODE_H
#define HJ_LS_ODE_H

#include "hj_error.h"
#include "hj_ls_grid.h"
#include "hj_ls_term.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Called after every full step; may change y (e.g. a mask, section 3.7.2).
 * A nonzero return (from this or the output callback below) ends the run
 * and is hj_ls_ode's return value; the callback's message in err is kept,
 * and where it set none hj_ls_ode says which callback failed and when. */
typedef int (*hj_ls_post_fn)(double t, double *y, void *ctx, hj_error *err);

typedef struct {
    double factor_cfl;   /* FactorCFL in (0, 1], default 0.5 */
    double max_step;     /* MaxStep, default DBL_MAX */
    hj_ls_post_fn post;  /* PostTimestep, default NULL */
    void *post_ctx;
    int single_step;     /* SingleStep: return after one step */
    double blowup_factor; /* a step that leaves max |y| above this many times
                           * max(max |y0|, the domain's diameter) is a
                           * blow-up (default 1e6; 0: no bound) */
    int always_parallel;  /* 0 (default): with more than one OpenMP thread
                           * (and without single_step) each step runs with
                           * the threads or on one of them, whichever the
                           * steps before measured faster (the first on
                           * one, the second with all, then the faster,
                           * the other timed again after 8, 16, .. 256
                           * steps): on a small grid every stage's
                           * parallel region costs a wake-up of the
                           * threads, and on cores busy with other work a
                           * thread waits for the scheduler at every
                           * barrier; 1: always with the threads.  The
                           * result is the same bits either way. */
} hj_ls_ode_opts;

/* Stats (the library does not print them; the caller may). */
typedef struct {
    long steps;          /* time steps taken */
    long evals;          /* term evaluations */
    long cfl_violations; /* later stages whose bound was below dt / FactorCFL */
    double t;            /* time reached */
    double seconds;      /* wall-clock time spent */
} hj_ls_ode_stats;

/* Receives the solution at output time tspan[k], k = 1 .. ntspan - 1. */
typedef int (*hj_ls_output_fn)(int k, double t, const double *y, void *ctx, hj_error *err);

void hj_ls_ode_defaults(hj_ls_ode_opts *o);

/* What is left of the span from t0 to tk below which it counts as done:
 * 100 eps max(|tk|, 1), the round-off that t accumulates over many steps
 * (the last step lands on tk exactly; after 3000 steps to t = 0.125 the
 * sum of the steps fell 5.5e-15 short, and a step of that size would only
 * add rounding), but at most 1e-6 of the span, so that a span on any time
 * scale is integrated (a horizon of 1e-20 s takes its step; with the
 * absolute bound alone it took none). */
double hj_ls_ode_span_small(double t0, double tk);

/* Integrate y from tspan[0] through the increasing times tspan[1..ntspan-1]
 * with the TVD RK scheme of the given order (1, 2, 3).  y is updated in
 * place and holds the solution at the last time reached; out (may be NULL)
 * is called at every output time.  opts and stats may be NULL. */
int hj_ls_ode(int order, const hj_ls_grid *g, const hj_ls_term *term, const double *tspan, int ntspan, double *y,
              const hj_ls_ode_opts *opts, hj_ls_output_fn out, void *out_ctx, hj_ls_ode_stats *stats, hj_error *err);

#ifdef __cplusplus
}
#endif

#endif
