/*
# normalStarDemo: motion in the normal direction of a star (section 2.3.2, Figure 10)

**Problem.** The toolbox's `normalStarDemo(accuracy, reverseFlow)`: the
seven-pointed star (13), phi(x, 0) = |x| - s (cos(rho theta) + sigma), moves
in its normal direction at constant speed a,

    D_t phi + a(t) |grad phi| = 0      on [-1, 1]^2,

the term `termNormal` (3) of the kernel (`hj_ls_normal`: Godunov upwinding
of the upwind derivatives of the chosen scheme).  With `--reverse-flow 1`
the speed is the toolbox's `switchValue`: a = +a0 until t = tMax / 2 and
-a0 after it.  The star grows outward; its concave notches form corners
(the viscosity solution) which the reversed motion cannot undo, so the
star is not recovered at tMax (the text's remark).

**Parameters.** The text gives none; these are those of the released
toolbox file, whose choice the text describes ("chosen to try to match
[Osher & Fedkiw, figure 6.1]"): rho = 7 points, sigma = 2.5, s = 0.20;
a0 = 0.25; tMax = 1 with the state shown at 9 equally spaced times;
FactorCFL 0.5; dx = 1/50 (`--N 101` nodes per side), extrapolation
boundary conditions (`HJ_LS_BC_EXTRAP_AWAY`).  `--accuracy` as in the
toolbox: low = first order upwind + RK1, medium (default) = ENO2 + RK2,
high = ENO3 + RK3, veryHigh = WENO5 + RK3.

- Switch timing (decision): the toolbox tests the stage time against
  t_s, so the one step that straddles t_s mixes the two speeds; here the
  switch is made between steps, exactly at t_s (an output time), see
  `p2_switch` in p2_motion.h.

**Figure 10.** (a) constant speed, (b) reversed at t = 0.5: the zero
contours of the 9 output times, overlaid in one panel per case (the
toolbox draws 9 subplots per case; overlaid, the growth and the loss of
the notches read at one glance).

**Check.** A circle of radius r0 = 0.5 at the origin under the same term
moves exactly as r(t) = r0 + a t while r > 0: the radius at t = 1 is
0.75 for a = +0.25, 0.25 for a = -0.25, and 0.5 again for the reversed
speed (a circle has no concave part, so here the motion is reversible).
The radius is measured from the area of {phi < 0} (`hj_ls_measure`, exact
for the piecewise linear interpolant, second order) as sqrt(A / pi), on
grids of 51, 101 and 201 nodes per side with the chosen accuracy; it
tests the normal term, the upwinding of both signs of a and the
integrator at once, since any error in the speed shows as a wrong
radius.  `--quick` runs the grids 51 and 101 only.

**Output.** normal_star_a.dat, normal_star_b.dat (phi, one gnuplot index
block per output time), normal_circle.tsv (the check, against the exact
radii in published/normal_circle.tsv), normal_circle_runs.tsv (every
circle run to full precision with its error per dx, which
notes/normal_star_notes.md presents).
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "hj_cli.h"
#include "hj_io.h"
#include "hj_ls_grid.h"
#include "hj_ls_measure.h"
#include "hj_ls_shape.h"
#include "hj_ls_term.h"
#include "hj_ls_accuracy.h"
#include "hj_ls_seq.h"
#include "p2_cli.h"
#include "p2_motion.h"

static const char *prog = "normal_star_demo";
static const char *usage =
    "Without --reverse-flow both cases of Figure 10 are run; --N is the figure grid (default 101).\n"
    "See the comment at the top of normal_star_demo.c.\n";

/* One run of the normal term: speed a0, reversed at t_switch if reverse. */
static int run_normal(const hj_ls_grid *g, const p2_opts *o, double a0, int reverse, const double *tspan, int nt,
                      double *phi, FILE *fp, const char *label, hj_error *err)
{
    p2_switch sw = {0.5 * tspan[nt - 1], {a0, reverse ? -a0 : a0}, {0, 0}, 0};
    hj_ls_normal term;
    hj_ls_normal_init(&term, g, hj_ls_accuracy_scheme(o->acc));
    term.speed.row_fn = p2_switch_row;
    term.speed.ctx = &sw;
    p2_seq seq = {fp, g, "phi", &sw, NULL, NULL, label, NULL, NULL};
    return p2_run(hj_ls_accuracy_order(o->acc), g, &term.base, tspan, nt, phi, &seq, HJ_LS_FACTOR_CFL, err);
}

/* The check's case c (ctx: the options): speed +-0.25, reversed at
 * t_switch = 0.5 for the third (an output time, as it must be). */
static int circle_run(const hj_ls_grid *g, int c, double *phi, const char *label, void *ctx, hj_error *err)
{
    const double speed[3] = {0.25, -0.25, 0.25}, tc[3] = {0, 0.5, 1};
    return run_normal(g, ctx, speed[c], c == 2, tc, 3, phi, NULL, label, err);
}

/* Figure 10's case (ctx: the options): the star at speed a0 = 0.25 to
 * tMax = 1, reversed at t = 0.5 if reverse, at 9 output times. */
static int figure_run(const hj_ls_grid *g, int reverse, double *phi, FILE *fp, const char *label, void *ctx,
                      hj_error *err)
{
    double tspan[9];
    hj_ls_seq_times(0, 1, 9, tspan);
    return run_normal(g, ctx, 0.25, reverse, tspan, 9, phi, fp, label, err);
}

int main(int argc, char **argv)
{
    p2_opts o = {prog, usage, HJ_LS_ACC_MEDIUM, 101, ".", 0};
    int only = -1; /* -1: both cases */
    p2_parse_demo(&o, argc, argv, "--reverse-flow", &only, NULL, 0);

    /* Figure 10: the star, constant and reversed speed. */
    const p2_star_figure fig = {{0.20, 2.5, 7}, {0, 1}, {"normal_star_a.dat", "normal_star_b.dat"},
                                {"star", "star, reversed"},
                                "# normalStarDemo(%s, reverseFlow = %d) on %ld^2 nodes: phi at t = k/8, k = 0..8\n"};
    p2_star_figures(&o, &fig, only, figure_run, &o);

    /* The check: a circle under the same term. */
    const char *case_name[3] = {"grow", "shrink", "reverse"};
    const double exact[3] = {0.75, 0.25, 0.5};
    const p2_circle circ = {{0, 0, 0}, 0.5};
    p2_check check = {NULL, 0, 3, case_name, "r", NULL, NULL, NULL, exact};
    p2_circle_check(&o, &circ, circle_run, &o, &check, "normal_circle.tsv",
                    "# normalStarDemo check: circle r0 = 0.5 under normal motion, accuracy %s, radius at t = 1 "
                    "from the area of {phi < 0}\nN\tcase\tr\tr_exact\terror\n",
                    "normal_circle_runs.tsv",
                    "# normalStarDemo: every circle run (r0 = 0.5, speed +-0.25, reverse: reversed at t = 0.5), "
                    "radius at t = 1 from the area of {phi < 0} against r0 + a t\n");
    return 0;
}
