/* p2_motion.h -- what the demos of sections 2.3-2.4 share (curvature,
 * normal motion, spin, tripleSine, dumbbell): the square grid, the
 * circle, a switching scalar (the toolbox's switchValue), the run through
 * the output times with the states written as gnuplot index blocks, the
 * area of {phi < 0} at every output time, the check tables against
 * exact radii and heights, and the data of their notes.
 *
 * For programs only: p2_run prints a progress line on a terminal
 * (hj_progress), and p2_check_files and p2_circle_check end the program
 * on a failure; the others return hj_error codes.
 */
#ifndef P2_MOTION_H
#define P2_MOTION_H

#include <stdio.h>

#include "hj_error.h"
#include "hj_ls_grid.h"
#include "hj_ls_shape.h"
#include "hj_ls_ode.h"
#include "hj_ls_term.h"
#include "p2_cli.h"

/* The square [-1, 1]^2 with n nodes per side and extrapolation boundary
 * conditions, the domain of the section 2.3 demos. */
int p2_square_grid(hj_ls_grid *g, long n, hj_error *err);

/* A circle (sphere) of radius r at c[0..2]: |x - c| - r. */
typedef struct {
    double c[3], r;
} p2_circle;
double p2_circle_fn(const double *x, void *ctx);

/* The toolbox's switchValue as an hj_ls_scalar callback: one(x) before the
 * switch, two(x) after.  The switch is made by p2_run when its output at
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
/* The same over a row (hj_ls_scalar's row_fn): one call per row of nodes. */
void p2_switch_row(double t, const hj_ls_row_info *row, const double *phi, double *a, void *ctx);

/* A run's outputs: the state at every output time appended to fp as one
 * gnuplot index block (hj_ls_seq, "# t = " to 6 digits; fp may be NULL:
 * nothing written) and handed to hook. */
typedef struct {
    FILE *fp;
    const hj_ls_grid *grid;
    const char *name;     /* field name in the block header */
    p2_switch *sw;        /* switched at its t_switch, or NULL */
    hj_ls_output_fn hook;
    void *hook_ctx;
    const char *progress; /* label for hj_progress, or NULL */
    hj_ls_post_fn post;   /* called after every step (hj_ls_ode's PostTimestep), or NULL */
    void *post_ctx;
} p2_seq;
/* Integrate y over the output times tspan[0..n-1] (tspan[0] the start),
 * writing tspan[0]'s state first. */
int p2_run(int order, const hj_ls_grid *g, const hj_ls_term *term, const double *tspan, int n, double *y,
           p2_seq *seq, double factor_cfl, hj_error *err);

/* A p2_seq hook recording the measure of {phi < 0} at every output:
 * area[k] for output k (ctx: a p2_areas with room for every output). */
typedef struct {
    const hj_ls_grid *grid;
    double *area;
} p2_areas;
int p2_area_hook(int k, double t, const double *y, void *ctx, hj_error *err);

/* The data of the demos' notes, one layout for all: a TSV file
 * <table>_runs.tsv with a comment line, a header row and one row per run
 * (its accuracy, its parameters, what it measured), numbers to full
 * precision and "-" where a quantity does not apply; the note templates
 * (notes/<demo>_notes.md) present them.  p2_cell writes one number: a tab,
 * then v as %.17g, or "-" when v is NaN. */
void p2_cell(FILE *fp, double v);
/* The numbers that end a row: p2_cell of v[0 .. n - 1], then the line end. */
void p2_cells(FILE *fp, const double *v, int n);

/* A check table: value[n * ncase + c] of case c on the grid of grids[n]
 * nodes per side against exact[c]; case_name in both tables; value_name
 * names the value's column in the runs table, where param_name (may be
 * NULL) adds a column with the cases' parameter param[c]. */
typedef struct {
    const long *grids;
    int ngrids, ncase;
    const char *const *case_name;
    const char *value_name, *param_name;
    const double *param, *value, *exact;
} p2_check;

/* Rows "N case value exact error" (tab-separated; %ld %s %.6f %.6f %.3e). */
void p2_check_rows(FILE *fp, const p2_check *c);

/* The runs table: the header "accuracy N dx case [param_name] value_name
 * value_name_exact error error_dx", then a row per grid and case (dx = 2 /
 * (N - 1) of the square grid, error_dx = error / dx). */
void p2_check_runs(FILE *fp, const char *accuracy, const p2_check *c);

/* Both as files of o->out_dir: tsv (tsv_head, a printf format of the
 * accuracy's name, then the rows) and runs (runs_head, a comment line,
 * then the runs table).  For main(): ends the program on a failure. */
void p2_check_files(const p2_opts *o, const char *tsv, const char *tsv_head, const char *runs, const char *runs_head,
                    const p2_check *c);

/* The figures of curvatureStarDemo, normalStarDemo and spinStarDemo, for
 * main(): on the square grid of o->N nodes per side, for each case k of
 * the two (all but the one with value[k] == only skipped when only >= 0),
 * the star evolved by run(g, value[k], phi, fp, label[k], ctx, err) with
 * its output times written to o->out_dir/file[k] after the line head, a
 * printf format of the accuracy's name, value[k] and o->N. */
typedef int (*p2_figure_fn)(const hj_ls_grid *g, int value, double *phi, FILE *fp, const char *label, void *ctx,
                            hj_error *err);
typedef struct {
    hj_ls_star star;
    int value[2];                   /* the demo's switch per case, e.g. reverseFlow */
    const char *file[2], *label[2]; /* the data file and the progress label per case */
    const char *head;
} p2_star_figure;
void p2_star_figures(const p2_opts *o, const p2_star_figure *f, int only, p2_figure_fn run, void *ctx);

/* The circle checks of normalStarDemo and spinStarDemo, for main(): on
 * the square grids (p2_square_grid) of 51, 101, 201 nodes per side (with
 * o->quick the first two) and for each case k < c->ncase (at most 4), the
 * circle circ evolved by run(g, k, phi, label, ctx, err), label "circle
 * <case_name[k]>, N = <nodes>", and its radius at the end
 * (hj_ls_measure_radius) against c->exact[k]; c's grids and values are set
 * here, then p2_check_files writes the tables. */
typedef int (*p2_case_fn)(const hj_ls_grid *g, int k, double *phi, const char *label, void *ctx, hj_error *err);
void p2_circle_check(const p2_opts *o, const p2_circle *circ, p2_case_fn run, void *ctx, p2_check *c, const char *tsv,
                     const char *tsv_head, const char *runs, const char *runs_head);

#endif
