/*
# curvatureSpiralDemo: motion by mean curvature of a wound spiral (section 2.3.1, Figure 8)

**Problem.** The toolbox's `curvatureSpiralDemo(accuracy, initial)`: the
classic wound spiral of Osher & Sethian (1988) moves by mean curvature,

    D_t phi = b kappa |grad phi|      on [-1, 1]^2,

the term `termCurvature` (6) (`hj_ls_curvature_term`, centered second
order in space).  A simple closed curve under this motion unwinds, turns
convex and shrinks to a point without ever touching itself (Grayson's
theorem), which is what the figure shows.

**Initial data** (`--initial`):

- `ellipse` (the default, the toolbox's `spiralFromEllipse`): an ellipse in
  the polar plane (r, theta), sqrt(y^T M y) - d with y = (r - r_c, theta -
  theta_c), M = R diag(0.06^-2, (2 pi)^-2) R^T, R the rotation by pi/100
  (without it the ellipse would close into a torus), d = 1, r_c = 0.5,
  theta_c = -pi/3; theta runs over five copies theta + 2 pi k, k = -2..2,
  and the minimum over them is taken, which winds the ellipse into a
  spiral.  The parameters are those of the released file (the text only
  says they "were chosen to try to match the shape of the original").
- `points` (beyond the toolbox, which left `spiralFromPoints`
  unimplemented): the original point cloud of Osher & Sethian, the curve
  gamma(s) = (0.1 e^(-10 y(s)) - 0.05 (0.1 - x(s))) (cos a(s), sin a(s)),
  a = 25 atan(10 y), x = 0.1 cos(2 pi s) + 0.1, y = 0.05 sin(2 pi s) + 0.1,
  s in [0, 1).  phi is the distance to the points by the kernel's k-d tree
  (`hj_ls_unsigned_distance`), made negative inside the closed polygon
  through the points (even-odd crossing rule).  Decisions: the original
  curve spans radii 0.022 to 0.066, so it is scaled by 12 to fill the
  domain as the ellipse spiral does (the scale of the original figure is
  not given); and it is sampled at 4000 points (`--samples`) rather than
  O&S's delta s = 0.005 (200 points), whose gaps of about 3 cells at
  dx = 1/50 make phi jump by up to half a gap across the curve (where the
  sign flips away from a sample); at 4000 the jump is under dx/10.

**Parameters** (released toolbox file; the text gives none): b = 0.075,
tMax = 1 with 9 equally spaced output times, FactorCFL 0.5, dx = 1/50
(`--N 101`), extrapolation boundary conditions.  `--accuracy` picks the
Runge-Kutta order: low = RK1, medium (default) = RK2, high and veryHigh =
RK3 (the toolbox offers low/medium/high; the curvature term has no upwind
scheme to raise).

**Figure 8.** The zero contour at the 9 output times, one subplot each as
in the toolbox: (a) the `--initial` data (`ellipse` by default, as in the
toolbox), (b) the point cloud of Osher & Sethian, which the toolbox could
not draw.

**Check.** Whatever its shape, a simple closed curve moving by curvature
with constant b loses area at the rate 2 pi b (the total curvature of a
simple closed curve is 2 pi), so A(0) - A(t) = 2 pi b t until it vanishes.
This is a sharp test for the spiral: most of its boundary has small
curvature, and the area law needs the ends of the thin arm (radius about
0.06, 3 cells at dx = 1/50) and the narrow gaps between the turns to be
right too; a numerical merging of two turns across a gap would change the
topology and break the law.  We compare A(0) - A(t) at t = 0.25 (loss
2 pi 0.075 0.25 = 0.117810) for both initial data on 101, 201 and 401
nodes per side (`--quick`: 101 and 201), areas by `hj_ls_measure`; the
notes also give the loss at t = 0.125 and, for the figure's run, at every
output time.  Finding: for `ellipse` the loss is 1.18, 1.06, 0.99 times the
exact one on 101, 201, 401 nodes, converging: the arm ends are nearly
pointed (half-width 0.06, 3 cells at dx = 1/50) and phi, a minimum over
the theta-copies, has kinks in the gaps between turns, 2 to 3 cells from
the front at dx = 1/50, where the centered curvature is not consistent.
For `points` it is 1.06, 0.95, 0.96: within 6 % but not monotone in dx;
the distance to the point cloud has kinks on the arm's medial axis and at
its tips, close to the front; we did not investigate further.

**Output.** curvature_spiral.dat (phi at the output times as gnuplot index
blocks; `ellipse`, or the `--initial` given), curvature_spiral_points.dat
(the same for the point cloud), curvature_spiral.tsv (the
check, against the exact loss in published/curvature_spiral.tsv),
curvature_spiral_runs.tsv (every run's area loss at its output times to
full precision, which notes/curvature_spiral_notes.md presents).
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hj_cli.h"
#include "hj_io.h"
#include "hj_ls_grid.h"
#include "hj_ls_helper.h"
#include "hj_ls_term.h"
#include "hj_ls_accuracy.h"
#include "hj_ls_seq.h"
#include "p2_cli.h"
#include "p2_motion.h"
#include "hj_math.h"

static const char *prog = "curvature_spiral_demo";
/* After the options in --help (the source's comment says the rest). */
static const char *usage = "--N is the figure grid; see the comment at the top of curvature_spiral_demo.c.\n";


/* spiralFromEllipse: min over five theta copies of sqrt(y^T M y) - d. */
typedef struct {
    double M[4], d, r_c, th_c;
} spiral_ellipse;

static double spiral_ellipse_fn(const double *x, void *ctx)
{
    const spiral_ellipse *e = ctx;
    const double r = hypot(x[0], x[1]), th = atan2(x[1], x[0]);
    double best = INFINITY;
    for (int k = -2; k <= 2; k++) {
        const double y0 = r - e->r_c, y1 = th + 2 * HJ_PI * k - e->th_c;
        const double q = y0 * (e->M[0] * y0 + e->M[1] * y1) + y1 * (e->M[2] * y0 + e->M[3] * y1);
        const double v = sqrt(q) - e->d;
        if (v < best) best = v;
    }
    return best;
}

static void make_ellipse(const hj_ls_grid *g, double *phi)
{
    const double rot = HJ_PI / 100, c = cos(rot), s = sin(rot);
    const double D0 = 1 / (0.06 * 0.06), D1 = 1 / (4 * HJ_PI * HJ_PI);
    /* M = R diag(D0, D1) R^T */
    spiral_ellipse e = {{c * c * D0 + s * s * D1, c * s * (D0 - D1), c * s * (D0 - D1), s * s * D0 + c * c * D1},
                        1.0, 0.5, -HJ_PI / 3};
    hj_ls_fill(g, phi, spiral_ellipse_fn, &e);
}

/* The Osher-Sethian spiral: samples points of gamma(s), scaled. */
static void spiral_points(long n, double scale, double *p)
{
    for (long k = 0; k < n; k++) {
        const double s = (double)k / (double)n;
        const double x = 0.1 * cos(2 * HJ_PI * s) + 0.1, y = 0.05 * sin(2 * HJ_PI * s) + 0.1;
        const double a = 25 * atan(10 * y), m = scale * (0.1 * exp(-10 * y) - 0.05 * (0.1 - x));
        p[2 * k] = m * cos(a);
        p[2 * k + 1] = m * sin(a);
    }
}

typedef struct {
    const double *p;
    long n;
} polygon;

/* Even-odd rule: is x inside the closed polygon p[0], ..., p[n-1]? */
static double inside_sign(const double *x, void *ctx)
{
    const polygon *P = ctx;
    int in = 0;
    for (long k = 0, j = P->n - 1; k < P->n; j = k++) {
        const double xk = P->p[2 * k], yk = P->p[2 * k + 1], xj = P->p[2 * j], yj = P->p[2 * j + 1];
        if ((yk > x[1]) != (yj > x[1]) && x[0] < xk + (x[1] - yk) * (xj - xk) / (yj - yk)) in = !in;
    }
    return in ? -1.0 : 1.0;
}

static int make_points(const hj_ls_grid *g, long samples, double *phi, hj_error *err)
{
    double *p = malloc(2 * (size_t)samples * sizeof *p), *sign = hj_ls_alloc(g);
    if (!p || !sign) {
        free(p);
        hj_ls_free(sign);
        return hj_error_set(err, HJ_ENOMEM, "out of memory");
    }
    spiral_points(samples, 12.0, p);
    int rc = hj_ls_unsigned_distance(g, p, samples, phi, err);
    if (!rc) {
        polygon P = {p, samples};
        hj_ls_fill(g, sign, inside_sign, &P);
        for (size_t r = 0; r < g->rows; r++) {
            long i[HJ_LS_MAXDIM];
            const size_t k0 = hj_ls_row(g, r, i);
            for (long a = 0; a < g->N[0]; a++) phi[k0 + (size_t)a] *= sign[k0 + (size_t)a];
        }
    }
    free(p);
    hj_ls_free(sign);
    return rc;
}

/* Initial data, the run over tspan, the areas at the output times. */
static int run_spiral(const hj_ls_grid *g, int order, int points, long samples, const double *tspan, int nt,
                      FILE *fp, double *area, const char *label, hj_error *err)
{
    double *phi = hj_ls_alloc(g);
    if (!phi) return hj_error_set(err, HJ_ENOMEM, "out of memory");
    int rc = HJ_OK;
    if (points) rc = make_points(g, samples, phi, err);
    else make_ellipse(g, phi);
    if (!rc) {
        hj_ls_curvature_term term;
        hj_ls_curvature_term_init(&term, g);
        term.b.value = 0.075;
        p2_areas areas = {g, area};
        p2_seq seq = {fp, g, "phi", NULL, p2_area_hook, &areas, label, NULL, NULL};
        rc = p2_run(order, g, &term.base, tspan, nt, phi, &seq, HJ_LS_FACTOR_CFL, err);
    }
    hj_ls_free(phi);
    return rc;
}

/* Rows of curvature_spiral_runs.tsv: the run's area loss at the output
 * times tspan[1 .. nt - 1] against 2 pi b t. */
static void loss_rows(FILE *fp, const char *accuracy, const char *run, const char *initial, long n, double b,
                      const double *tspan, const double *area, int nt)
{
    for (int k = 1; k < nt; k++) {
        const double exact = 2 * HJ_PI * b * tspan[k];
        fprintf(fp, "%s\t%s\t%s\t%ld", accuracy, run, initial, n);
        const double cells[6] = {tspan[k], area[0], area[k], area[0] - area[k], exact, (area[0] - area[k]) / exact};
        p2_cells(fp, cells, 6);
    }
}

int main(int argc, char **argv)
{
    p2_opts o = {prog, usage, HJ_LS_ACC_MEDIUM, 101, ".", 0};
    int initial = 0; /* 0 ellipse, 1 points */
    long samples = 4000;
    hj_error err;
    static const char *const initials[] = {"ellipse", "points", NULL};
    hj_cli_opt extra[] = {
        {.name = "--initial", .type = HJ_OPT_CHOICE, .value = &initial, .choices = initials, .metavar = "I",
         .help = "initial spiral: from the ellipse construction, or the distance to sampled points"},
        {.name = "--samples", .type = HJ_OPT_LONG, .value = &samples, .min = 3, .max = 10000000, .metavar = "P",
         .help = "size of the point cloud"},
    };
    p2_parse_demo(&o, argc, argv, NULL, NULL, extra, 2);
    double tspan[9], area[9];
    hj_ls_seq_times(0, 1, 9, tspan);
    const double b = 0.075;

    /* Figure 8. */
    hj_ls_grid g;
    p2_fail_if(prog, p2_square_grid(&g, o.N, &err), &err);
    hj_out out;
    p2_fail_if(prog, p2_open(&out, o.out_dir, "curvature_spiral.dat", &err), &err);
    fprintf(out.fp, "# curvatureSpiralDemo(%s, '%s') on %ld^2 nodes: phi at t = k/8, k = 0..8\n",
            hj_ls_accuracy_name(o.acc), initial ? "points" : "ellipse", o.N);
    p2_commit_run(prog, &out,
                  run_spiral(&g, hj_ls_accuracy_order(o.acc), initial, samples, tspan, 9, out.fp, area, "spiral", &err),
                  &err);
    /* Figure 8 (b): the point cloud, whatever --initial chose for (a). */
    double area_points[9];
    p2_fail_if(prog, p2_open(&out, o.out_dir, "curvature_spiral_points.dat", &err), &err);
    fprintf(out.fp, "# curvatureSpiralDemo(%s, 'points') on %ld^2 nodes, %ld points: phi at t = k/8, k = 0..8\n",
            hj_ls_accuracy_name(o.acc), o.N, samples);
    p2_commit_run(
        prog, &out,
        run_spiral(&g, hj_ls_accuracy_order(o.acc), 1, samples, tspan, 9, out.fp, area_points, "spiral points", &err),
        &err);

    /* The check: area loss 2 pi b t for both initial data on three grids,
     * up to t = 0.25. */
    const long grids[3] = {101, 201, 401};
    const int ngrids = o.quick ? 2 : 3;
    const char *init_name[2] = {"ellipse", "points"};
    double areas[3][2][3];
    for (int n = 0; n < ngrids; n++) {
        p2_fail_if(prog, p2_square_grid(&g, grids[n], &err), &err);
        for (int ini = 0; ini < 2; ini++) {
            char label[64];
            snprintf(label, sizeof label, "spiral %s, N = %ld", init_name[ini], grids[n]);
            p2_fail_if(
                prog,
                run_spiral(&g, hj_ls_accuracy_order(o.acc), ini, samples, tspan, 3, NULL, areas[n][ini], label, &err),
                &err);
        }
    }
    p2_fail_if(prog, p2_open(&out, o.out_dir, "curvature_spiral.tsv", &err), &err);
    fprintf(out.fp, "# curvatureSpiralDemo check: area loss A(0) - A(0.25) under curvature motion, b = 0.075, "
                    "accuracy %s, %ld points for the point cloud (exact 2 pi b t = 0.117810)\n"
                    "N\tinitial\tarea_loss\tarea0\n", hj_ls_accuracy_name(o.acc), samples);
    for (int n = 0; n < ngrids; n++)
        for (int ini = 0; ini < 2; ini++)
            fprintf(out.fp, "%ld\t%s\t%.6f\t%.6f\n", grids[n], init_name[ini], areas[n][ini][0] - areas[n][ini][2],
                    areas[n][ini][0]);
    /* Every run's area loss at its output times, against 2 pi b t: the
     * check's (t = 0.125, 0.25), then the figure's (every output time). */
    p2_next_file(prog, &out, o.out_dir, "curvature_spiral_runs.tsv");
    fprintf(out.fp, "# curvatureSpiralDemo: every run, area loss A(0) - A(t) under curvature motion, b = 0.075, "
                    "against the exact 2 pi b t; %ld points for the point cloud\n"
                    "accuracy\trun\tinitial\tN\tt\tarea0\tarea\tarea_loss\tarea_loss_exact\tloss_ratio\n",
            samples);
    const char *acc = hj_ls_accuracy_name(o.acc);
    for (int ini = 0; ini < 2; ini++)
        for (int n = 0; n < ngrids; n++)
            loss_rows(out.fp, acc, "check", init_name[ini], grids[n], b, tspan, areas[n][ini], 3);
    loss_rows(out.fp, acc, "figure", init_name[initial], o.N, b, tspan, area, 9);
    p2_fail_if(prog, hj_out_commit(&out, &err), &err);
    return 0;
}
