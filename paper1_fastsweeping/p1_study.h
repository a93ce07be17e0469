/* p1_study.h -- the convergence study shared by the paper 1 examples.
 *
 * An example program describes its problem (domain, speed, exact solution,
 * inflow pieces, boxes excluded from the error) as p1_case values and
 * hands them to p1_main(), which parses the command line, solves on every
 * N, measures the errors exactly as the paper says, and writes
 *
 *   <out>/<table>.tsv      one row per case and N: errors, pairwise
 *                          orders, iterations, seconds (the checked table)
 *   <out>/<table>.fit.tsv  fitted orders e = C h^p (Ceres, see hj_fit.h)
 *   <out>/<table>.fit.gp   the same as gnuplot variables, for the figure
 *   <out>/<table>.<case>.grid.tsv  solution and error on the grid of the
 *                          --grid-N run, in gnuplot's grid format
 *
 * All files are written under temporary names and renamed when complete.
 */
#ifndef P1_STUDY_H
#define P1_STUDY_H

#include "hj_fsm.h"

/* A box of the plane.  For an excluded box, around_point marks the box
 * the paper gives around a singular point (its centre, half-width w): the
 * default measurement (--exclude distance) leaves out the nodes closer
 * than w to the point, the disc inscribed in the box; see excluded() in
 * p1_study.c. */
typedef struct {
    double xmin, xmax, ymin, ymax;
    int around_point;
} p1_box;

typedef struct {
    const char *name;       /* case key in the table ("a", "b", or "-") */
    p1_box domain;          /* square computational domain */
    hj_speed speed;
    double (*exact)(double x, double y);
    const hj_inflow *inflow;
    int ninflow;
    const p1_box *exclude;  /* regions not measured (see p1_box) */
    int nexclude;
    double eps;             /* WENO epsilon ... */
    int eps_times_h2;       /* ... times h^2 when set (Example 2) */
} p1_case;

typedef struct {
    const char *program;
    const char *table;      /* e.g. "table3.1" */
    hj_bc_strategy strategy;
    const p1_case *cases;
    int ncases;
    const long *sizes;      /* the published N */
    int nsizes;
    int nquick;             /* --quick runs the first nquick sizes */
    hj_fsm_guess guess;     /* initial guess (default: HJ_GUESS_WITH_III) */
} p1_study;

/* Run the study from the command line; returns the process exit status. */
int p1_main(int argc, char **argv, const p1_study *study, const char *usage_extra);

/* f = 1 and its (zero) gradient: Examples 3 and 4. */
double p1_unit_speed(double x, double y, void *ctx);
void p1_unit_speed_grad(double x, double y, double grad[2], void *ctx);

#endif
