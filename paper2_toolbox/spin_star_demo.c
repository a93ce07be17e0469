/*
# spinStarDemo: normal motion plus rotation of a star (section 2.3.3, Figure 11)

**Problem.** The toolbox's `spinStarDemo(accuracy, rigid)`: the star (13)
moves in its normal direction at speed a and is carried by a rotation,

    D_t phi + v(x) . grad phi + a |grad phi| = 0      on [-1, 1]^2,

the sum (`hj_ls_sum`, the toolbox's `termSum`) of `termNormal` (3)
(`hj_ls_normal`) and `termConvection` (2) (`hj_ls_convection`), both with
the upwind scheme of the chosen accuracy.  The velocity is the rigid
rotation v = omega (-x_2, x_1) (`--rigid 1`), or, by default, the same
multiplied by |x|^2 (`--rigid 0`), which the text says recreates
[Osher & Fedkiw, figure 6.2], whose tips turn faster than its body
although its caption says rigid.

**Parameters.** The text gives the grid (201^2 nodes on [-1, 1]^2, as
Figure 11 states, `--N 201`; `--quick` draws the figure on 101^2) and `accuracy = 'medium'` (the default);
the rest are those of the released toolbox file: rho = 7, sigma = 2.5,
s = 0.20 in (13); a = 0.20; omega = 0.75 pi (counter-clockwise: the
toolbox's rotation = -0.75 pi in its matrix [0 1; -1 0]); tMax = 1 with
9 output times; FactorCFL 0.5; extrapolation boundary conditions.

**Figure 11.** Top row (a) rigid rotation, bottom row (b) rotation speed
times |x|^2 (the default): the zero contour at t = 0, 0.25, 0.5, 0.75, 1
(every other of the 9 output times; the toolbox draws all 9 as subplots),
the initial star in grey behind each.

**Check.** A circle that is not centred at the origin, centre (0.4, 0)
and radius r0 = 0.3, under the rigid rotation plus normal motion at speed
a stays a circle: its centre turns with the flow and its radius is
exactly r0 + a t.  With a = +0.1 and a = -0.1 the radius at t = 1 is 0.4
and 0.2 (the centre is then at angle 0.75 pi); it is measured from the
area of {phi < 0} (`hj_ls_measure`) on 51, 101 and 201 nodes per side.
The rotation moves the circle about 0.94 in 1 unit of time, so an error
in the convection term's upwinding or in how the sum combines the CFL
bounds shows up as a smeared, shrunken disc, i.e. as a radius error.
`--quick` runs 51 and 101 only.

**Output.** spin_star_a.dat (rigid), spin_star_b.dat (|x|^2 rotation):
phi at the output times as gnuplot index blocks; spin_circle.tsv (the
check, against the exact radii in published/spin_circle.tsv);
spin_circle_runs.tsv (every circle run to full precision with its error
per dx, which notes/spin_star_notes.md presents).
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
#include "hj_math.h"

static const char *prog = "spin_star_demo";
static const char *usage =
    "Without --rigid both cases of Figure 11 are run; --N is the figure grid (default 201, 101 with --quick).\n"
    "See the comment at the top of spin_star_demo.c.\n";


typedef struct {
    double omega;
    int rigid;
} rotation;

/* v = omega (-y, x), times |x|^2 unless rigid; one row along x. */
static void rotation_velocity(double t, const double *x, double dx0, long n, int d, double *v, void *ctx)
{
    (void)t;
    const rotation *rot = ctx;
    for (long j = 0; j < n; j++) {
        const double xj = x[0] + (double)j * dx0, y = x[1];
        const double s = rot->rigid ? rot->omega : rot->omega * (xj * xj + y * y);
        v[j] = d == 0 ? -s * y : s * xj;
    }
}

static int run_spin(const hj_ls_grid *g, const p2_opts *o, double a, int rigid, const double *tspan, int nt,
                    double *phi, FILE *fp, const char *label, hj_error *err)
{
    rotation rot = {0.75 * HJ_PI, rigid};
    hj_ls_normal normal;
    hj_ls_normal_init(&normal, g, hj_ls_accuracy_scheme(o->acc));
    normal.speed.value = a;
    hj_ls_convection conv;
    hj_ls_convection_init(&conv, g, hj_ls_accuracy_scheme(o->acc));
    conv.velocity_fn = rotation_velocity;
    conv.ctx = &rot;
    const hj_ls_term *terms[2] = {&normal.base, &conv.base};
    hj_ls_sum sum;
    int rc = hj_ls_sum_init(&sum, g, terms, 2, err);
    if (rc) return rc;
    p2_seq seq = {fp, g, "phi", NULL, NULL, NULL, label, NULL, NULL};
    rc = p2_run(hj_ls_accuracy_order(o->acc), g, &sum.base, tspan, nt, phi, &seq, HJ_LS_FACTOR_CFL, err);
    hj_ls_sum_free(&sum);
    return rc;
}

/* The check's cases: normal speed +0.1 (grow) and -0.1 (shrink). */
static const double CIRCLE_SPEED[2] = {0.1, -0.1};

/* The check's case c (ctx: the options): rigid rotation plus normal
 * speed CIRCLE_SPEED[c] to t = 1. */
static int circle_run(const hj_ls_grid *g, int c, double *phi, const char *label, void *ctx, hj_error *err)
{
    const double tc[2] = {0, 1};
    return run_spin(g, ctx, CIRCLE_SPEED[c], 1, tc, 2, phi, NULL, label, err);
}

/* Figure 11's case (ctx: the options): the star under rigid rotation (or
 * rotation times |x|^2) plus normal speed 0.20 to t = 1, 9 output times. */
static int figure_run(const hj_ls_grid *g, int rigid, double *phi, FILE *fp, const char *label, void *ctx,
                      hj_error *err)
{
    double tspan[9];
    hj_ls_seq_times(0, 1, 9, tspan);
    return run_spin(g, ctx, 0.20, rigid, tspan, 9, phi, fp, label, err);
}

int main(int argc, char **argv)
{
    p2_opts o = {prog, usage, HJ_LS_ACC_MEDIUM, 0, ".", 0};
    int only = -1; /* -1: both cases */
    p2_parse_demo(&o, argc, argv, "--rigid", &only, NULL, 0);
    if (!o.N) o.N = o.quick ? 101 : 201; /* the figure grid: 201^2 as in the text, 101^2 in quick mode */

    /* Figure 11: (a) rigid, (b) rotation times |x|^2. */
    const p2_star_figure fig = {{0.20, 2.5, 7}, {1, 0}, {"spin_star_a.dat", "spin_star_b.dat"},
                                {"star, rigid", "star, |x|^2"},
                                "# spinStarDemo(%s, rigid = %d) on %ld^2 nodes: phi at t = k/8, k = 0..8\n"};
    p2_star_figures(&o, &fig, only, figure_run, &o);

    /* The check: an off-centre circle, rigid rotation plus normal motion. */
    const char *case_name[2] = {"grow", "shrink"};
    const double exact[2] = {0.4, 0.2};
    const p2_circle circ = {{0.4, 0, 0}, 0.3};
    p2_check check = {NULL, 0, 2, case_name, "r", "a", CIRCLE_SPEED, NULL, exact};
    p2_circle_check(&o, &circ, circle_run, &o, &check, "spin_circle.tsv",
                    "# spinStarDemo check: circle r0 = 0.3 at (0.4, 0), rigid rotation 0.75 pi plus normal speed a, "
                    "accuracy %s, radius at t = 1 from the area of {phi < 0}\nN\tcase\tr\tr_exact\terror\n",
                    "spin_circle_runs.tsv",
                    "# spinStarDemo: every circle run (r0 = 0.3 at (0.4, 0), rigid rotation 0.75 pi plus normal "
                    "speed a), radius at t = 1 from the area of {phi < 0} against r0 + a t\n");
    return 0;
}
