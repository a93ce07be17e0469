/* p2_motion.h -- shared pieces of the section 2.3-2.4 demos (curvature,
 * normal motion, spin, tripleSine, dumbbell): the toolbox's accuracy
 * levels, the common options and the 0|1 switches, the square grid, the
 * star (13), a switching scalar (the toolbox's switchValue), time
 * sequences written as gnuplot index blocks, and the radius of {phi < 0}
 * from its measure.  Nothing here prints or exits but p2_common_option
 * (--help, bad options), p2_binary_option, p2_fail_if and p2_commit_run,
 * which are for main() only.
 */
#ifndef P2_MOTION_H
#define P2_MOTION_H

#include <stdio.h>

#include "hj_error.h"
#include "hj_io.h"
#include "hj_ls_grid.h"
#include "hj_ls_ode.h"
#include "hj_ls_term.h"

/* Toolbox accuracy: low = first order upwind + RK1, medium = ENO2 + RK2,
 * high = ENO3 + RK3, veryHigh = WENO5 + RK3.  Returns 0, or -1 for an
 * unknown name. */
int p2_accuracy(const char *name, int *scheme, int *order);

/* Options every demo takes: --accuracy, --N, --out-dir, --quick, --help.
 * p2_common_option consumes argv[*i] (and its value) when it is one of
 * them and returns 1; 0 when the option is not a common one.  Bad values
 * end the program through hj_cli_fail (main() only). */
typedef struct {
    const char *prog, *usage;
    const char *accuracy; /* name */
    int scheme, order;
    long N;               /* nodes per unit dimension of the figure grid */
    const char *out_dir;
    int quick;
} p2_opts;
int p2_common_option(p2_opts *o, int argc, char **argv, int *i);

/* End the program with the error's message when rc != 0 (main() only). */
void p2_fail_if(const char *prog, int rc, const hj_error *err);

/* A demo's 0|1 switch (--reverse-flow, --rigid, --split-flow): when
 * argv[*i] is name, *value = its 0 or 1 (anything else ends the program,
 * main() only) and 1 is returned; 0 when argv[*i] is another option. */
int p2_binary_option(const char *prog, const char *name, int argc, char **argv, int *i, int *value);

/* Finish a figure file after the run that wrote it returned rc: commit it,
 * or, when the run failed, remove it and end the program (main() only). */
void p2_commit_run(const char *prog, hj_out *out, int rc, const hj_error *err);

/* The square [-1, 1]^2 with n nodes per side and extrapolation boundary
 * conditions, the domain of the section 2.3 demos. */
int p2_square_grid(hj_ls_grid *g, long n, hj_error *err);

/* The star (13): phi = |x| - scale (cos(points theta) + shift). */
typedef struct {
    double points, shift, scale;
} p2_star;
double p2_star_fn(const double *x, void *ctx);

/* A circle (sphere) of radius r at c[0..2]: |x - c| - r. */
typedef struct {
    double c[3], r;
} p2_circle;
double p2_circle_fn(const double *x, void *ctx);

/* The toolbox's switchValue as an hj_ls_scalar callback: one(x) before the
 * switch, two(x) after.  The switch is made by p2_seq when its output at
 * time t_switch has been written (t_switch must be an output time), so
 * every stage of every step before t_switch uses one and every stage
 * after it uses two (a test on the stage time would mix the two within
 * the step that straddles t_switch).  one/two are value_k * (1 + c_k
 * cos theta), theta the polar angle: constants with c_k = 0. */
typedef struct {
    double t_switch;
    double value[2], cos_coef[2];
    int after;
} p2_switch;
double p2_switch_fn(double t, const double *x, double phi, void *ctx);

/* A time sequence: the state at every output time appended as one gnuplot
 * index block (fp may be NULL: nothing written) and handed to hook. */
typedef struct {
    FILE *fp;
    const hj_ls_grid *grid;
    const char *name;     /* field name in the block header */
    p2_switch *sw;        /* switched at its t_switch, or NULL */
    int (*hook)(int k, double t, const double *y, void *ctx, hj_error *err);
    void *hook_ctx;
    const char *progress; /* label for hj_progress, or NULL */
    hj_ls_post_fn post;   /* called after every step (hj_ls_ode's PostTimestep), or NULL */
    void *post_ctx;
} p2_seq;
/* Integrate y over the output times tspan[0..n-1] (tspan[0] the start),
 * writing tspan[0]'s state first. */
int p2_run(int order, const hj_ls_grid *g, const hj_ls_term *term, const double *tspan, int n, double *y,
           p2_seq *seq, double factor_cfl, hj_error *err);

/* Radius of the disc (2-D) or ball (3-D) with the measure of {phi < 0}
 * (hj_ls_measure, second order). */
int p2_radius(const hj_ls_grid *g, const double *phi, double *r, hj_error *err);

/* A p2_seq hook recording the measure of {phi < 0} at every output:
 * area[k] for output k (ctx: a p2_areas with room for every output). */
typedef struct {
    const hj_ls_grid *grid;
    double *area;
} p2_areas;
int p2_area_hook(int k, double t, const double *y, void *ctx, hj_error *err);

/* path = dir/name, then hj_out_open. */
int p2_open(hj_out *out, const char *dir, const char *name, hj_error *err);

#endif
