/*
# tripleSine: regularization and the viscous limit (section 2.4.1, Figure 12)

**Problem.** The toolbox's `tripleSine(b, accuracy)`: a sine-shaped
interface moves in its normal direction with speed a(x) = 1 - b kappa(x),

    D_t phi + |grad phi| - b kappa |grad phi| = 0,

the sum (`hj_ls_sum`, `termSum`) of `termNormal` (3) with speed 1
(`hj_ls_normal`, the upwind scheme of the accuracy) and `termCurvature` (6)
with multiplier b (`hj_ls_curvature_term`, centered); for b = 0 the normal
term alone, as in the toolbox.  For b > 0 the front stays smooth; for
b = 0 its valleys form corners, the viscosity solution, which is the limit
b -> 0 of the smooth ones (Sethian's figures 2.6 and 2.7).

**Parameters.** The text names neither the grid nor the values of b; from
the released toolbox file: phi(x, 0) = sin(3 pi (x_1 + 0.5)) + 2 x_2 - 1.5
(the front is x_2 = 0.75 - 0.5 sin(3 pi (x_1 + 0.5)), moving up),
[0, 2)^2 with dx = 1/100 (200^2 nodes, `--N 200`), periodic in x_1 and
extrapolation in x_2, tMax = 0.5 with 12 equally spaced output times,
FactorCFL 0.5, `--accuracy` as in the toolbox (low = first order + RK1,
medium = ENO2 + RK2 (default), high = ENO3 + RK3, veryHigh = WENO5 + RK3).
Decision: the three values of b of Figure 12 are 0.1, 0.025 and 0 (the
text names only 0.025 and 0); `--b VALUE` (>= 0) runs one.  In `--quick`
mode the figure is drawn on 100^2 nodes.

**Figure 12.** One panel per b, all 12 output times overlaid (the toolbox
plots them in one axes, the initial curve lowest).

**Check.** For b = 0 the exact viscosity solution is Huygens' principle:
the region {phi < 0} at time t is the set of points within distance t of
the initial region, so along the vertical line through x_1 = x0 the front
is at height y(x0, t) = max over |s - x0| <= t of f(s) + sqrt(t^2 -
(s - x0)^2), f the initial curve.  At t = 0.5 this is 1.710286 on the
flank x0 = 0.2 (maximum at s = 0.0093: the front there is the arc grown
from the crest) and 1.630852 at the valley bottom x0 = 1, where the
corner forms (maximum at s = 0.6850: the front there comes from near the
neighbouring crest, which is what makes the corner); both computed by a
fine search refined by golden section (paper2_toolbox/tests/test_huygens.c
recomputes them, to 7 digits).  The crest x0 = 0 itself is not a test: by symmetry the
upwind x-derivatives vanish there, phi stays 2 x_2 - 2.5 - 2t on that
column and any upwind scheme gets 1.25 + t to round-off (we saw 1.750000
on every grid).  The front height is found on the grid
column by linear interpolation of phi between the two nodes that bracket
its sign change, on grids of 50, 100, 200 nodes per side (`--quick`: 50,
100).  The valley value tests the upwinding where characteristics
collide: a scheme that is not the viscosity solution (or too diffusive)
puts the corner at the wrong height.  The heights for b > 0 are in the
notes (no closed form).

**Output.** triple_sine_b0.1.dat, triple_sine_b0.025.dat,
triple_sine_b0.dat (phi at the output times as gnuplot index blocks; with
`--b`, triple_sine_b<value>.dat), triple_sine.tsv (the check, against the
values in published/triple_sine.tsv), triple_sine_runs.tsv (every run's
front heights to full precision, which notes/triple_sine_notes.md
presents).
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hj_cli.h"
#include "hj_io.h"
#include "hj_ls_grid.h"
#include "hj_ls_term.h"
#include "hj_ls_accuracy.h"
#include "hj_ls_seq.h"
#include "p2_cli.h"
#include "p2_motion.h"
#include "hj_math.h"

static const char *prog = "triple_sine";
static const char *usage =
    "Without --b the three cases b = 0.1, 0.025, 0 of Figure 12 are run; --N is the figure grid\n"
    "(default 200, 100 with --quick).  See the comment at the top of triple_sine.c.\n";


static double sine_fn(const double *x, void *ctx)
{
    (void)ctx;
    return sin(3 * HJ_PI * (x[0] + 0.5)) + 2 * x[1] - 1.5;
}

static void grid_sine(hj_ls_grid *g, long n)
{
    const hj_ls_bc bc[2] = {{HJ_LS_BC_PERIODIC, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
    const double dx = 2.0 / (double)n;
    const double lo[2] = {0, 0}, hi[2] = {2 - dx, 2 - dx};
    const long N[2] = {n, n};
    hj_error err;
    p2_fail_if(prog, hj_ls_grid_init(g, 2, lo, hi, N, bc, &err), &err);
}

/* Height of the front (phi = 0, phi increasing upward) on column i. */
static double front_height(const hj_ls_grid *g, const double *phi, long i)
{
    for (long j = 0; j + 1 < g->N[1]; j++) {
        const long a[2] = {i, j}, c[2] = {i, j + 1};
        const double p0 = phi[hj_ls_index(g, a)], p1 = phi[hj_ls_index(g, c)];
        if (p0 < 0 && p1 >= 0) return g->min[1] + g->dx[1] * ((double)j + p0 / (p0 - p1));
    }
    return NAN;
}

static int run_sine(const hj_ls_grid *g, const p2_opts *o, double b, const double *tspan, int nt, double *phi,
                    FILE *fp, const char *label, hj_error *err)
{
    hj_ls_normal normal;
    hj_ls_normal_init(&normal, g, hj_ls_accuracy_scheme(o->acc));
    normal.speed.value = 1;
    hj_ls_curvature_term curv;
    hj_ls_curvature_term_init(&curv, g);
    curv.b.value = b;
    p2_seq seq = {fp, g, "phi", NULL, NULL, NULL, label, NULL, NULL};
    if (b == 0)
        return p2_run(hj_ls_accuracy_order(o->acc), g, &normal.base, tspan, nt, phi, &seq, HJ_LS_FACTOR_CFL, err);
    const hj_ls_term *terms[2] = {&normal.base, &curv.base};
    hj_ls_sum sum;
    int rc = hj_ls_sum_init(&sum, g, terms, 2, err);
    if (rc) return rc;
    rc = p2_run(hj_ls_accuracy_order(o->acc), g, &sum.base, tspan, nt, phi, &seq, HJ_LS_FACTOR_CFL, err);
    hj_ls_sum_free(&sum);
    return rc;
}

int main(int argc, char **argv)
{
    p2_opts o = {prog, usage, HJ_LS_ACC_MEDIUM, 0, ".", 0};
    double bs[3] = {0.1, 0.025, 0};
    int nb = 3;
    hj_error err;
    hj_cli_opt extra[] = {{.name = "--b", .type = HJ_OPT_DOUBLE, .value = &bs[0], .min = 0, .max = 10, .metavar = "VALUE",
                           .help = "run only this b", .dflt = "the three of Figure 12"}};
    p2_parse_demo(&o, argc, argv, NULL, NULL, extra, 1);
    if (extra[0].seen) nb = 1;
    if (!o.N) o.N = o.quick ? 100 : 200;
    if (o.N % 2) hj_cli_fail(prog, HJ_EXIT_USAGE, "--N must be even (x_1 = 1 must be a node)");
    double tspan[12];
    hj_ls_seq_times(0, 0.5, 12, tspan);

    /* Figure 12 (and the front heights of each b on the figure grid). */
    hj_ls_grid g;
    grid_sine(&g, o.N);
    double *phi = hj_ls_alloc(&g);
    if (!phi) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory");
    double hfig[3][2];
    for (int k = 0; k < nb; k++) {
        hj_ls_fill(&g, phi, sine_fn, NULL);
        char name[64], label[64];
        snprintf(name, sizeof name, "triple_sine_b%g.dat", bs[k]);
        snprintf(label, sizeof label, "tripleSine b = %g", bs[k]);
        hj_out out;
        p2_fail_if(prog, p2_open(&out, o.out_dir, name, &err), &err);
        fprintf(out.fp, "# tripleSine(%g, %s) on %ld^2 nodes: phi at t = 0.5 k / 11, k = 0..11\n", bs[k],
                hj_ls_accuracy_name(o.acc), o.N);
        p2_commit_run(prog, &out, run_sine(&g, &o, bs[k], tspan, 12, phi, out.fp, label, &err), &err);
        hfig[k][0] = front_height(&g, phi, 0);
        hfig[k][1] = front_height(&g, phi, o.N / 2);
    }
    hj_ls_free(phi);

    /* The check: b = 0 front heights on the flank and at the valley, t = 0.5. */
    const long grids[3] = {50, 100, 200};
    const int ngrids = o.quick ? 2 : 3;
    const double exact[2] = {1.710286, 1.630852};
    const char *point[2] = {"flank", "valley"};
    double h[3][2];
    const double tc[2] = {0, 0.5};
    for (int n = 0; n < ngrids; n++) {
        grid_sine(&g, grids[n]);
        phi = hj_ls_alloc(&g);
        if (!phi) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory");
        hj_ls_fill(&g, phi, sine_fn, NULL);
        char label[64];
        snprintf(label, sizeof label, "tripleSine b = 0, N = %ld", grids[n]);
        p2_fail_if(prog, run_sine(&g, &o, 0, tc, 2, phi, NULL, label, &err), &err);
        h[n][0] = front_height(&g, phi, grids[n] / 10); /* x_1 = 0.2 */
        h[n][1] = front_height(&g, phi, grids[n] / 2);  /* x_1 = 1 */
        hj_ls_free(phi);
    }
    hj_out out;
    p2_fail_if(prog, p2_open(&out, o.out_dir, "triple_sine.tsv", &err), &err);
    fprintf(out.fp, "# tripleSine check: b = 0, accuracy %s, front height at t = 0.5 on the column x_1 = 0.2 (flank) "
                    "and x_1 = 1 (valley)\nN\tpoint\theight\texact\terror\n", hj_ls_accuracy_name(o.acc));
    const p2_check check = {grids, ngrids, 2, point, NULL, NULL, NULL, h[0], exact};
    p2_check_rows(out.fp, &check);
    /* Every run: the check's (flank and valley) and the figure's (crest
     * and valley), t = 0.5. */
    p2_next_file(prog, &out, o.out_dir, "triple_sine_runs.tsv");
    fprintf(out.fp, "# tripleSine: every run, front height at t = 0.5 on the columns x_1 = 0 (crest), 0.2 (flank) "
                    "and 1 (valley); exact: Huygens' principle (b = 0)\n"
                    "accuracy\trun\tN\tb\tcrest\tflank\tflank_exact\tflank_error\tvalley\tvalley_exact\t"
                    "valley_error\n");
    for (int n = 0; n < ngrids; n++) {
        fprintf(out.fp, "%s\tcheck\t%ld", hj_ls_accuracy_name(o.acc), grids[n]);
        p2_cell(out.fp, 0);
        p2_cell(out.fp, NAN);
        for (int k = 0; k < 2; k++) {
            p2_cell(out.fp, h[n][k]);
            p2_cell(out.fp, exact[k]);
            p2_cell(out.fp, fabs(h[n][k] - exact[k]));
        }
        fputc('\n', out.fp);
    }
    for (int k = 0; k < nb; k++) {
        fprintf(out.fp, "%s\tfigure\t%ld", hj_ls_accuracy_name(o.acc), o.N);
        const double cells[8] = {bs[k], hfig[k][0], NAN, NAN, NAN, hfig[k][1], NAN, NAN};
        p2_cells(out.fp, cells, 8);
    }
    p2_fail_if(prog, hj_out_commit(&out, &err), &err);
    return 0;
}
