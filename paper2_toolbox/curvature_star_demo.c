/*
# curvatureStarDemo: motion by mean curvature of a star (section 2.3.1, Figure 9)

**Problem.** The toolbox's `curvatureStarDemo(accuracy, splitFlow)`: the
seven-pointed star (13) moves by mean curvature,

    D_t phi = b(x, t) kappa |grad phi|      on [-1, 1]^2,

the term `termCurvature` (6) of the kernel (`hj_ls_curvature_term`:
kappa and |grad phi| by centered second order differences, so the spatial
order is 2 whatever the accuracy).  With `--split-flow 1` the multiplier is
the section's time and space varying b(x, t) = b0 (1 - x_1 / |x|) for
t <= t_s and b0 (1 + x_1 / |x|) after, t_s = tMax / 2 (the toolbox's
`switchValue` as a `scalarGridFunc`): the left side moves first, then the
right; the result at tMax should look much like the constant b0 case.

**Parameters.** The text gives none; these are those of the released
toolbox file ("chosen to try to match [Osher & Fedkiw, figure 4.2]"):
rho = 7, sigma = 2, s = 0.25 in (13); b0 = 0.02; output times 0, 0.25,
0.5, 1 (tMax = 1, t_s = 0.5); FactorCFL 0.9; dx = 1/50 (`--N 101`);
extrapolation boundary conditions.  `--accuracy` picks the Runge-Kutta
order as in the toolbox: low = RK1, medium (default) = RK2, high = RK3;
veryHigh (not offered by the toolbox for this demo) is RK3 too, since
the curvature term has no upwind scheme to raise.

- Switch timing (decision): the switch is made between steps, exactly at
  t_s (an output time), not by testing each stage's time (`p2_switch`).
- At x = 0 the toolbox's cart2pol gives theta = 0; we use the same.

**Figure 9.** Top row (a) constant b0, bottom row (b) `splitFlow`: the
zero contour at the four output times, one subplot each as in the
toolbox, the initial star in grey behind.

**Check.** For any simple closed curve moving by curvature with a
constant b in the plane, dA/dt = -b times the integral of kappa along the
curve = -2 pi b (the total curvature of a simple closed curve is 2 pi):
the area enclosed decreases linearly, A(0) - A(t) = 2 pi b t, whatever the
shape, and for a circle this is r(t)^2 = r0^2 - 2 b t.  We check both:
the star of the demo itself (b0 = 0.02: area loss 0.125664 at t = 1) and a
circle of radius r0 = 0.4 under the same term (r(1) = sqrt(0.12) =
0.346410), on grids of 51, 101 and 201 nodes per side with the chosen
accuracy; areas by `hj_ls_measure` (second order), the loss taken from
the measured A(0) so that the initial area's discretization error
cancels.  The star's sharp notches are where the centered curvature is
least accurate, so its loss converges more slowly than the circle's.  The
`splitFlow` star's loss is shown (not compared): for the varying b it is
the integral of b kappa along the curve, not 2 pi b0 t.  `--quick` runs
the grids 51 and 101.

**Output.** curvature_star_a.dat (constant b), curvature_star_b.dat
(splitFlow): phi at the output times as gnuplot index blocks;
curvature_star.tsv (the check, against the exact values in
published/curvature_star.tsv); curvature_star_runs.tsv (every check run to
full precision, which notes/curvature_star_notes.md presents).
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
#include "p2_cli.h"
#include "p2_motion.h"
#include "hj_math.h"

static const char *prog = "curvature_star_demo";
static const char *usage =
    "Without --split-flow both cases of Figure 9 are run; --N is the figure grid (default 101).\n"
    "See the comment at the top of curvature_star_demo.c.\n";


/* Curvature motion of phi over tspan; b0 constant or split; areas at the
 * output times into area[] (may be NULL). */
static int run_curv(const hj_ls_grid *g, int order, double b0, int split, const double *tspan, int nt, double *phi,
                    FILE *fp, double *area, const char *label, hj_error *err)
{
    p2_switch sw = {0.5 * tspan[nt - 1], {b0, b0}, {split ? -1 : 0, split ? 1 : 0}, 0};
    hj_ls_curvature_term term;
    hj_ls_curvature_term_init(&term, g);
    term.b.row_fn = p2_switch_row;
    term.b.ctx = &sw;
    p2_areas areas = {g, area};
    p2_seq seq = {fp, g, "phi", &sw, area ? p2_area_hook : NULL, &areas, label, NULL, NULL};
    return p2_run(order, g, &term.base, tspan, nt, phi, &seq, HJ_LS_FACTOR_CFL_CURVATURE, err);
}

/* The speed b0 and the output times of the figure and the check. */
static const double b0 = 0.02, tspan[4] = {0, 0.25, 0.5, 1.0};

/* Figure 9's case (ctx: the options): the star under curvature motion,
 * b split if split. */
static int figure_run(const hj_ls_grid *g, int split, double *phi, FILE *fp, const char *label, void *ctx,
                      hj_error *err)
{
    const p2_opts *o = ctx;
    return run_curv(g, hj_ls_accuracy_order(o->acc), b0, split, tspan, 4, phi, fp, NULL, label, err);
}

int main(int argc, char **argv)
{
    p2_opts o = {prog, usage, HJ_LS_ACC_MEDIUM, 101, ".", 0};
    int only = -1; /* -1: both cases */
    p2_parse_demo(&o, argc, argv, "--split-flow", &only, NULL, 0);
    hj_error err;
    const hj_ls_star star = {0.25, 2, 7};

    /* Figure 9. */
    const p2_star_figure fig = {star, {0, 1}, {"curvature_star_a.dat", "curvature_star_b.dat"},
                                {"star", "star, split"},
                                "# curvatureStarDemo(%s, splitFlow = %d) on %ld^2 nodes: phi at t = 0, 0.25, 0.5, 1\n"};
    p2_star_figures(&o, &fig, only, figure_run, &o);
    hj_ls_grid g;
    double *phi;

    /* The check: area loss 2 pi b t of the star and of a circle. */
    const long grids[3] = {51, 101, 201};
    const int ngrids = o.quick ? 2 : 3;
    const char *shape[3] = {"circle", "star", "star_split"};
    const double r0 = 0.4, t1 = 1.0, loss_exact = 2 * HJ_PI * b0 * t1, r_exact = sqrt(r0 * r0 - 2 * b0 * t1);
    double loss[3][3], rc[3];
    for (int n = 0; n < ngrids; n++) {
        p2_fail_if(prog, p2_square_grid(&g, grids[n], &err), &err);
        phi = hj_ls_alloc(&g);
        if (!phi) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory");
        for (int s = 0; s < 3; s++) {
            p2_circle circ = {{0, 0, 0}, r0};
            if (s == 0) hj_ls_fill(&g, phi, p2_circle_fn, &circ);
            else hj_ls_fill(&g, phi, hj_ls_star_fn, (void *)&star);
            double area[4];
            char label[64];
            snprintf(label, sizeof label, "%s, N = %ld", shape[s], grids[n]);
            p2_fail_if(prog,
                       run_curv(&g, hj_ls_accuracy_order(o.acc), b0, s == 2, tspan, 4, phi, NULL, area, label, &err),
                       &err);
            loss[n][s] = area[0] - area[3];
            if (s == 0) rc[n] = sqrt(area[3] / HJ_PI);
        }
        hj_ls_free(phi);
    }
    hj_out out;
    p2_fail_if(prog, p2_open(&out, o.out_dir, "curvature_star.tsv", &err), &err);
    fprintf(out.fp, "# curvatureStarDemo check: area loss A(0) - A(1) under curvature motion, b0 = 0.02, accuracy %s "
                    "(exact 2 pi b0 t for a simple closed curve and constant b); r(1) of the circle r0 = 0.4\n"
                    "N\tshape\tarea_loss\tr\tarea_loss_exact\n", hj_ls_accuracy_name(o.acc));
    for (int n = 0; n < ngrids; n++)
        for (int s = 0; s < 3; s++) {
            fprintf(out.fp, "%ld\t%s\t%.6f\t", grids[n], shape[s], loss[n][s]);
            if (s == 0) fprintf(out.fp, "%.6f\t%.6f\n", rc[n], loss_exact);
            else fprintf(out.fp, "-\t%s\n", s == 1 ? "0.125664" : "-");
        }
    /* Every check run; the splitFlow star has no exact loss. */
    p2_next_file(prog, &out, o.out_dir, "curvature_star_runs.tsv");
    fprintf(out.fp, "# curvatureStarDemo: every check run, area loss A(0) - A(1) under curvature motion with b0 = 0.02 "
                    "(exact 2 pi b0 t for constant b) and r(1) of the circle r0 = 0.4 (exact sqrt(r0^2 - 2 b0 t))\n"
                    "accuracy\tN\tshape\tarea_loss\tarea_loss_exact\tloss_ratio\tr\tr_exact\n");
    for (int n = 0; n < ngrids; n++)
        for (int s = 0; s < 3; s++) {
            const double exact = s < 2 ? loss_exact : NAN;
            fprintf(out.fp, "%s\t%ld\t%s", hj_ls_accuracy_name(o.acc), grids[n], shape[s]);
            const double cells[5] = {loss[n][s], exact, loss[n][s] / exact, s == 0 ? rc[n] : NAN,
                                     s == 0 ? r_exact : NAN};
            p2_cells(out.fp, cells, 5);
        }
    p2_fail_if(prog, hj_out_commit(&out, &err), &err);
    return 0;
}
