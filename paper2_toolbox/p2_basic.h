/* p2_basic.h -- what the section 2.1-2.2 demos of Mitchell's toolbox
 * (convection_demo, reinit_demo, reinit_test, lax_friedrichs_demo,
 * mask_demo) and the Table 1 benchmark (bench_convection) share: the
 * accuracy levels, the flow fields of convectionDemo, a time sequence
 * writer, the star of (13), measurements against exact solutions
 * (error near a front, gradient deviation, zero crossings and their
 * distance from an exact curve), and the cases, options and table rows
 * of reinitDemo and reinitTest.
 *
 * Library code: it returns hj_error codes, never prints or exits.
 */
#ifndef P2_BASIC_H
#define P2_BASIC_H

#include <stdio.h>

#include "hj_error.h"
#include "hj_io.h"
#include "hj_ls_grid.h"

/* ---- accuracy levels (toolbox meaning) ---------------------------------
 *   low      upwindFirstFirst + odeCFL1
 *   medium   upwindFirstENO2  + odeCFL2
 *   high     upwindFirstENO3  + odeCFL3
 *   veryHigh upwindFirstWENO5 + odeCFL3 */
enum { P2B_LOW, P2B_MEDIUM, P2B_HIGH, P2B_VERYHIGH, P2B_NACC };
extern const char *const p2b_acc_name[P2B_NACC];
extern const int p2b_acc_scheme[P2B_NACC];
extern const int p2b_acc_order[P2B_NACC];

/* *out = index of s in names[0..n-1]; HJ_EINVAL naming `what` and the
 * choices otherwise. */
int p2b_parse_choice(const char *s, const char *what, const char *const *names, int n, int *out, hj_error *err);

/* ---- flow fields of convectionDemo -------------------------------------
 * constant: v = (2, 0, ..., 0);  linear: v = A x with A = 2 pi [0 1; -1 0]
 * in (x_1, x_2) and 0 elsewhere (one clockwise turn per unit time).  sign
 * multiplies the field (the 'Rev' flows negate it at t_max / 2). */
enum { P2B_CONSTANT, P2B_LINEAR, P2B_CONSTANT_REV, P2B_LINEAR_REV, P2B_NFLOW };
extern const char *const p2b_flow_name[P2B_NFLOW];
typedef struct {
    int linear; /* 0: constant field, 1: rotation */
    double sign;
    int dim;    /* grid dimension: the rotation is zero in 1-D (A is 1 x 1 there) */
} p2b_flow;
/* hj_ls_velocity_fn with ctx = p2b_flow. */
void p2b_flow_velocity(double t, const double *x, double dx0, long n, int d, double *v, void *ctx);

/* ---- time sequence of a demo --------------------------------------------
 * A gnuplot file of index blocks ("# t = ..." then hj_ls_write_block of the
 * state and the extra fields), one per output time.  p2b_seq_out is an
 * hj_ls_output_fn with ctx = p2b_seq; when flip is set, flip->sign is
 * negated once the block of the output time t_switch has been written (so
 * every stage of every step after t_switch sees the reversed field).
 * path NULL: nothing is written (only the flip and the hook). hook (may be
 * NULL) is called after each block. */
typedef struct {
    hj_out out;
    int open;
    const hj_ls_grid *g;
    const char *name;
    int nextra;
    const char *extra_name[3];
    const double *extra[3];
    p2b_flow *flip;
    double t_switch;
    int (*hook)(int k, double t, const double *y, void *ctx, hj_error *err);
    void *hook_ctx;
} p2b_seq;
int p2b_seq_open(p2b_seq *s, const char *path, const hj_ls_grid *g, const char *name, hj_error *err);
int p2b_seq_block(p2b_seq *s, double t, const double *y, hj_error *err);
int p2b_seq_out(int k, double t, const double *y, void *ctx, hj_error *err);
int p2b_seq_commit(p2b_seq *s, hj_error *err);
void p2b_seq_abort(p2b_seq *s);

/* tspan[k] = t0 + k (t1 - t0) / (n - 1), k = 0..n-1, the last exactly t1. */
void p2b_times(double t0, double t1, int n, double *tspan);

/* ---- measurements ---------------------------------------------------------- */

/* Maximum and mean of |phi - exact| over the interior nodes where
 * |exact| < band (0 if there is none). */
void p2b_front_error(const hj_ls_grid *g, const double *phi, const double *exact, double band, double *max,
                     double *mean);

/* out = |grad phi| by centered differences (second order); work is an
 * array on g; phi's ghost layer is filled. */
int p2b_grad_magnitude(const hj_ls_grid *g, double *phi, double *work, double *out, hj_error *err);

/* Mean and maximum of | |grad phi| - 1 | (centered differences, second
 * order) over the interior nodes where |dist| < band; work is an array on
 * g.  phi's ghost layer is filled. */
int p2b_grad_deviation(const hj_ls_grid *g, double *phi, const double *dist, double band, double *work,
                       double *mean, double *max, hj_error *err);

/* Zero crossings of phi along the grid edges of a 2-D grid, linearly
 * interpolated (a node exactly zero counts once): *pts (malloc'd, 2
 * doubles per point, freed by the caller) and *n. */
int p2b_crossings(const hj_ls_grid *g, const double *phi, double **pts, long *n, hj_error *err);

/* The star (13): r(theta) = scale (cos(points theta) + shift), theta the
 * polar angle (atan2, the toolbox's cart2pol); phi = |x| - r(theta). */
typedef struct {
    double scale, shift;
    int points;
} p2b_star;
double p2b_star_phi(const double *x, void *ctx); /* hj_ls_field_fn, ctx = p2b_star */
double p2b_star_area(const p2b_star *s);          /* pi scale^2 (1/2 + shift^2) */

/* n samples of a closed plane curve, equally spaced in angle: the star
 * (star != NULL) or the circle of the given centre and radius; *pts
 * (malloc'd, 2 doubles each). */
int p2b_curve_sample(const p2b_star *star, const double *center, double radius, long n, double **pts, hj_error *err);

/* Distance from each of the np points p to the closed polygon through the
 * nc curve samples c (nearest sample by brute force, then its two chords;
 * serial): maximum and mean.  With samples spaced h on a curve of
 * curvature kappa the polygon is within kappa h^2 / 8 of the curve. */
void p2b_point_curve_distance(const double *p, long np, const double *c, long nc, double *max, double *mean);

/* ---- the cases of reinitDemo and reinitTest (section 2.2.1) -------------
 * Grid [-1, 1 - dx]^2, dx = 0.02, periodic (100 x 100 nodes).  'circle':
 * |x - (-0.4, 0)| - 0.35, a signed distance function near the circle but
 * not across the periodic seam; 'star': (13) with scale 0.25, 7 points,
 * shift 2 (r from 0.25 to 0.75), whose gradient is far from unit.  dist is
 * the exact signed distance to the initial zero level set (the distance to
 * P2B_CURVE_SAMPLES samples of the exact curve, hj_ls_unsigned_distance,
 * signed by phi0), accurate to about 1e-4 near the curve. */
enum { P2B_CIRCLE, P2B_STAR, P2B_NSHAPE };
extern const char *const p2b_shape_name[P2B_NSHAPE];
#define P2B_CURVE_SAMPLES 200000
/* The zero crossings' distances use every 10th sample and the chords
 * between them (within about 1e-6 of the exact curve). */
#define P2B_CURVE_STRIDE 10
typedef struct {
    hj_ls_grid g;
    int shape;
    p2b_star star;
    double center[2], radius;
    double *phi0, *dist, *curve, *coarse, *work;
    double exact_area;
} p2b_reinit_case;
int p2b_reinit_setup(p2b_reinit_case *c, int shape, hj_error *err);
void p2b_reinit_free(p2b_reinit_case *c);

/* Measurements of phi (its ghosts are filled) against the case: mean and
 * maximum of | |grad phi| - 1 | and maximum of |phi - dist| over the nodes
 * with |dist| < 5 dx; the maximum and mean distance of phi's zero
 * crossings from the exact initial curve; the area of {phi < 0}. */
typedef struct {
    double grad_mean, grad_max, sd_err, shift_max, shift_mean, area;
} p2b_reinit_meas;
int p2b_reinit_measure(const p2b_reinit_case *c, double *phi, p2b_reinit_meas *m, hj_error *err);

/* The columns of reinit.tsv / reinit_test.tsv, and one row. */
void p2b_reinit_header(FILE *fp);
void p2b_reinit_row(FILE *fp, const p2b_reinit_case *c, int acc, const p2b_reinit_meas *before,
                    const p2b_reinit_meas *after, long steps);
/* One row of reinit_notes.md / reinit_test_notes.md, before -> after,
 * without its line end (reinitTest adds a column). */
void p2b_reinit_note_row(FILE *fp, const p2b_reinit_case *c, int acc, const p2b_reinit_meas *before,
                         const p2b_reinit_meas *after, long steps);

/* The options reinitDemo and reinitTest share: --shape, --accuracy (either
 * sets single: one run), --out-dir, --quick (accepted: the default set is
 * already quick) and --help, which ends the scan with help set so that
 * the program prints its usage as soon as it is seen.  HJ_EINVAL with the
 * message for an unknown option or a missing or bad value. */
typedef struct {
    int shape, acc, single, help;
    const char *dir;
} p2b_reinit_opts;
int p2b_reinit_options(int argc, char **argv, p2b_reinit_opts *o, hj_error *err);

#endif
