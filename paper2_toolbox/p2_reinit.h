/* p2_reinit.h -- the cases, measurements, table rows and options of
 * reinitDemo and reinitTest (sections 2.2.1 and 2.7.3).
 *
 * Grid [-1, 1 - dx]^2, dx = 0.02, periodic (100 x 100 nodes).  'circle':
 * |x - (-0.4, 0)| - 0.35, a signed distance function near the circle but
 * not across the periodic seam; 'star': (13) with scale 0.25, 7 points,
 * shift 2 (r from 0.25 to 0.75), whose gradient is far from unit.  dist is
 * the exact signed distance to the initial zero level set (the distance to
 * P2_CURVE_SAMPLES samples of the exact curve, hj_ls_unsigned_distance,
 * signed by phi0), accurate to about 1e-4 near the curve.
 *
 * p2_reinit_setup and _measure return hj_error codes.
 */
#ifndef P2_REINIT_H
#define P2_REINIT_H

#include <stdio.h>

#include "hj_error.h"
#include "hj_io.h"
#include "hj_ls_grid.h"
#include "hj_ls_shape.h"

enum { P2_CIRCLE, P2_STAR, P2_NSHAPE };
extern const char *const p2_shape_name[P2_NSHAPE];
#define P2_CURVE_SAMPLES 200000
/* The zero crossings' distances use every 10th sample and the chords
 * between them (within about 1e-6 of the exact curve). */
#define P2_CURVE_STRIDE 10
typedef struct {
    hj_ls_grid g;
    int shape;
    hj_ls_star star;
    double center[2], radius;
    double *phi0, *dist, *curve, *coarse, *work;
    double exact_area;
} p2_reinit_case;
int p2_reinit_setup(p2_reinit_case *c, int shape, hj_error *err);
void p2_reinit_free(p2_reinit_case *c);

/* Measurements of phi (its ghosts are filled) against the case: mean and
 * maximum of | |grad phi| - 1 | and maximum of |phi - dist| over the nodes
 * with |dist| < 5 dx; the maximum and mean distance of phi's zero
 * crossings from the exact initial curve; the area of {phi < 0}. */
typedef struct {
    double grad_mean, grad_max, sd_err, shift_max, shift_mean, area;
} p2_reinit_meas;
int p2_reinit_measure(const p2_reinit_case *c, double *phi, p2_reinit_meas *m, hj_error *err);

/* The columns of reinit.tsv / reinit_test.tsv, and one row. */
void p2_reinit_header(FILE *fp);
void p2_reinit_row(FILE *fp, const p2_reinit_case *c, int acc, const p2_reinit_meas *before,
                   const p2_reinit_meas *after, long steps);
/* The columns of reinit_runs.tsv / reinit_test_runs.tsv, the data of
 * their notes, and one row, to full precision, before and after, with the
 * change of area in percent; both without the line end (reinitTest adds
 * a column). */
void p2_reinit_run_header(FILE *fp);
void p2_reinit_run_row(FILE *fp, const p2_reinit_case *c, int acc, const p2_reinit_meas *before,
                       const p2_reinit_meas *after, long steps);

/* The options reinitDemo and reinitTest share: --shape, --accuracy (either
 * sets single: one run), --out-dir, --quick (accepted: the default set is
 * already quick). */
typedef struct {
    int shape, acc, single, quick;
    const char *dir;
} p2_reinit_opts;

/* For main() (ends the program on bad usage or a failure): the options,
 * read through hj_cli's option table (--help prints summary, the options
 * and epilog), the output directory, and the table o->dir/<base>.tsv (one
 * run: <base>_run.tsv) opened in *tab with the comment line(s) and the
 * columns. */
void p2_reinit_begin(const char *prog, const char *summary, const char *epilog, int argc, char **argv,
                     const char *base, const char *comment, p2_reinit_opts *o, hj_out *tab);

/* For main(), for the default set (not o->single): the table of every
 * run, o->dir/<base>_runs.tsv, opened in *runs with the comment line(s),
 * the run columns, the further columns extra ("" for none) and the line
 * end. */
void p2_reinit_begin_runs(const char *prog, const p2_reinit_opts *o, const char *base, const char *comment,
                          const char *extra, hj_out *runs);

/* For main(): commit the table and, for the default set, the runs table. */
void p2_reinit_end(const char *prog, const p2_reinit_opts *o, hj_out *tab, hj_out *runs);

#endif
