/* p2_convection.h -- the flow fields of convectionDemo (section 2.1,
 * equation (2)), shared by that demo, laxFriedrichsDemo and maskDemo
 * (section 2.2) and the Table 1 benchmark:
 *   constant  v = (2, 0, ..., 0);
 *   linear    v = A x with A = 2 pi [0 1; -1 0] in (x_1, x_2) and 0
 *             elsewhere (one clockwise turn per unit time; zero in 1-D,
 *             where A is 1 x 1);
 *   constantRev, linearRev: the same, negated once `reversed` is set (at
 *             t_max / 2, through hj_ls_seq's flag).
 */
#ifndef P2_CONVECTION_H
#define P2_CONVECTION_H

#include "hj_error.h"
#include "hj_ls_grid.h"
#include "hj_ls_ode.h"
#include "hj_ls_seq.h"
#include "hj_ls_term.h"

enum { P2_CONSTANT, P2_LINEAR, P2_CONSTANT_REV, P2_LINEAR_REV, P2_NFLOW };
extern const char *const p2_flow_name[P2_NFLOW];

typedef struct {
    int linear;   /* 0: constant field, 1: rotation */
    int reversed; /* 1: the field is negated */
    int dim;      /* grid dimension */
} p2_flow;

/* hj_ls_velocity_fn with ctx = p2_flow. */
void p2_flow_velocity(double t, const double *x, double dx0, long n, int d, double *v, void *ctx);

/* The run of convectionDemo and of the section 2.2 demos built like it
 * (reinitDemo, laxFriedrichsDemo, maskDemo): y integrated at accuracy acc
 * through the P2_NT output times 0, tmax / 8, ..., tmax (plotSteps = 9),
 * every state written to path (NULL: no file) as a gnuplot block headed
 * "# t = " (10 digits).  seq (may be NULL: the state alone, named "phi")
 * adds extra fields, a switch flag or a hook (hj_ls_seq_init(seq, NULL,
 * g, "phi", 10), then set them); opts and stats may be NULL. */
enum { P2_NT = 9 };
int p2_solve(const char *path, int acc, const hj_ls_grid *g, const hj_ls_term *term, double tmax, double *y,
             const hj_ls_ode_opts *opts, hj_ls_seq *seq, hj_ls_ode_stats *stats, hj_error *err);

#endif
