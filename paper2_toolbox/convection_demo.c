/*
# convectionDemo: motion by an external velocity field (section 2.1, Figures 1-3)

**What it shows.** The toolbox's annotated first example: a circle (sphere
in 3-D) moved by a given velocity field, the PDE (2)

    D_t phi + v(x, t) . grad phi = 0,

with `termConvection` (upwinded per dimension) and the CFL-limited TVD
Runge-Kutta integrators `odeCFL1/2/3` (FactorCFL 0.5), here
`common/hj_ls_term.h`'s convection term and `common/hj_ls_ode.h`.

**Parameters** (those of the document's listing, section 2.1):

- grid [-1, 1]^dim with dx = 1/50 (101 nodes per dimension); with periodic
  boundary conditions the upper bound is 1 - dx (100 nodes, period 2),
  otherwise extrapolation (away from zero) boundaries, the toolbox's
  default `periodic = 0`;
- initial data the signed distance to the sphere of radius 0.35 centred at
  (-0.4, 0, 0, 0);
- t in [0, 1], nine output times 0, 1/8, ..., 1 (`plotSteps = 9`);
- flows: `constant` v = (2, 0, ...) (the default), `linear` v = A x with
  A = 2 pi [0 1; -1 0] in (x_1, x_2) (one clockwise turn per unit time;
  zero in 1-D, where the integrator then steps by MaxStep = 1/8),
  `constantRev` and `linearRev` (the same, negated at
  t_max / 2 = 0.5);
- accuracy `low` (first order upwind + RK1, the default), `medium` (ENO2 +
  RK2), `high` (ENO3 + RK3), `veryHigh` (WENO5 + RK3).

**Decisions where the text is silent or ambiguous.**
- *Switch time of the 'Rev' flows.* The toolbox's `switchValue` returns the
  forward field for t <= tSwitch, tested at each Runge-Kutta stage time; the
  step that starts at tSwitch = 0.5 then evaluates its first stage with the
  forward field.  Here the field is negated when the integration reaches the
  output time 0.5 (an output time, so a step ends there exactly): every stage
  before 0.5 uses the forward field and every stage after it the reversed
  one, so the exact solution returns to the initial data at t = 1.
- *The 'constant' flow* carries the circle 2 units to the right in t = 1,
  out of [-1, 1] with the default extrapolation boundaries.  The checked
  'constant' runs use periodic boundaries (the toolbox's `periodic = 1`),
  where the circle returns to its start after one period; the initial data
  are then discontinuous across the seam x = +-1 (the listing's comment says
  so and ignores it), away from the front.
- *Dimensions.* Figure 3 comes from changing `g.dim`; the program takes
  `--dim 1..4` (the listing works up to 4).  The default run makes 1-D
  'constantRev' at every accuracy (Figure 3(a) is `veryHigh`) and 3-D
  'linear' `medium` (Figure 3(b), 101^3 nodes, the full run only).

**Figures.** fig01.png: `convectionDemo('linear', 'medium')`, the nine
output times as 3 x 3 subplots of the zero contour (Figure 1).  fig02.png:
`convectionDemo('linearRev', 'low')` with `useSubplots = 0`, all nine zero
contours in one axis (Figure 2; the forward and backward circles do not
overlap, the area loss of the first order scheme).  fig03.png: (a) phi of
the 1-D `constantRev`, `veryHigh` run at the nine times; (b) the zero
isosurface of the 3-D `linear`, `medium` run at the nine times (the
voxel data are every second node, 51^3).

**Check** (convection.tsv against published/convection.tsv).  Every checked
run has an exact solution at t = 1 equal to the initial data: one full turn
('linear'), out and back ('linearRev', 'constantRev'), one period
('constant', periodic).  For each flow, dimension and accuracy:
- `measure`: length / area / volume of {phi < 0} at t = 1 (second order,
  `hj_ls_measure.h`) against the exact 2 r = 0.7, pi r^2 = 0.384845,
  4/3 pi r^3 = 0.179594 (kind value: 1 % match, 10 % close).  This is the
  document's "low visibly loses area, the rest are indistinguishable" in
  numbers;
- `front_max`, `front_mean`: maximum and mean of |phi(x, 1) - phi_0(x)| over
  the nodes within 2 dx of the initial front, against the values of our own
  run (regression gate, kind error).
These checks can fail: a wrong upwind direction, a wrong switch of the
reversed flows, a boundary condition that leaks, or a loss of order would
move the area or the front error by far more than the tolerances.

**Outputs** (in --out-dir): convection.tsv; convection_summary.tsv (the
same runs in full precision with the relative change of the measure, which
notes/convection_notes.md presents); convection_2d_linear_medium.dat,
convection_2d_linearRev_low.dat, convection_1d_constantRev_veryHigh.dat
(gnuplot index blocks, one per output time: x [y] phi);
convection_3d_linear_medium.dat (x y z phi on every second node, one
block per output time, for gnuplot voxel grids) and
convection_3d_linear_medium.vtk (phi_0 and phi(1) on all nodes).
With any of --flow, --accuracy, --dim, --N, --periodic the program makes one
run and writes convection_run.tsv and convection_run.dat instead (in 4-D
the measure is not computed: `hj_ls_measure` handles 1-3 dimensions, and
the time sequence file holds x_1 ... x_4 phi per node).
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hj_cli.h"
#include "hj_io.h"
#include "hj_ls_io.h"
#include "hj_ls_measure.h"
#include "hj_ls_ode.h"
#include "hj_ls_seq.h"
#include "hj_ls_shape.h"
#include "hj_ls_accuracy.h"
#include "hj_ls_front.h"
#include "p2_cli.h"
#include "p2_convection.h"
#include "hj_math.h"

static const char *const PROG = "convection_demo";
static const double RADIUS = 0.35;

typedef struct {
    int flow, acc, dim, periodic;
    long N; /* nodes per dimension of the extrapolated grid; periodic: N - 1 */
} cfg;

typedef struct {
    double measure, exact, front_max, front_mean;
    long steps;
} result;

/* 3-D time sequence for gnuplot voxels: every second node. */
typedef struct {
    hj_out out;
    const hj_ls_grid *g;
} voxel_seq;

static int voxel_block(int k, double t, const double *y, void *ctx, hj_error *err)
{
    (void)k;
    voxel_seq *v = ctx;
    const hj_ls_grid *g = v->g;
    fprintf(v->out.fp, "%s# t = %.10g\n", ftell(v->out.fp) > 0 ? "\n\n" : "", t);
    for (long c = 0; c < g->N[2]; c += 2)
        for (long b = 0; b < g->N[1]; b += 2)
            for (long a = 0; a < g->N[0]; a += 2) {
                const long i[3] = {a, b, c};
                double x[3];
                hj_ls_coord(g, i, x);
                fprintf(v->out.fp, "%.4g %.4g %.4g %.5g\n", x[0], x[1], x[2], y[hj_ls_index(g, i)]);
            }
    return ferror(v->out.fp) ? hj_error_set(err, HJ_EIO, "write error") : HJ_OK;
}

/* One run of convectionDemo(flow, accuracy) in c->dim dimensions; seq_path
 * (may be NULL): the time sequence; voxel_path / vtk_path (3-D, may be
 * NULL). */
static void run(const cfg *c, const char *seq_path, const char *voxel_path, const char *vtk_path, result *res)
{
    hj_error err;
    hj_ls_grid g;
    const double dx = 2.0 / (double)(c->N - 1);
    double lo[HJ_LS_MAXDIM], hi[HJ_LS_MAXDIM];
    long n[HJ_LS_MAXDIM];
    hj_ls_bc bc[HJ_LS_MAXDIM];
    for (int d = 0; d < c->dim; d++) {
        n[d] = c->periodic ? c->N - 1 : c->N;
        lo[d] = -1;
        hi[d] = -1 + (double)(n[d] - 1) * dx;
        bc[d] = (hj_ls_bc){c->periodic ? HJ_LS_BC_PERIODIC : HJ_LS_BC_EXTRAP_AWAY, 0, 0};
    }
    p2_fail_if(PROG, hj_ls_grid_init(&g, c->dim, lo, hi, n, bc, &err), &err);
    double *y0 = hj_ls_alloc(&g), *y = hj_ls_alloc(&g);
    if (!y0 || !y) hj_cli_fail(PROG, HJ_EXIT_RUN, "out of memory");
    const double center[HJ_LS_MAXDIM] = {-0.4, 0, 0, 0, 0, 0, 0, 0};
    p2_fail_if(PROG, hj_ls_shape_sphere(&g, center, RADIUS, y0, &err), &err);
    hj_ls_copy(&g, y, y0);

    p2_flow flow = {c->flow == P2_LINEAR || c->flow == P2_LINEAR_REV, 0, c->dim};
    hj_ls_convection term;
    hj_ls_convection_init(&term, &g, hj_ls_accuracy_scheme(c->acc));
    term.velocity_fn = p2_flow_velocity;
    term.ctx = &flow;
    /* the forward flows do not depend on t: their rows are evaluated once */
    term.velocity_steady = c->flow == P2_CONSTANT || c->flow == P2_LINEAR;

    hj_ls_seq seq;
    hj_ls_seq_init(&seq, NULL, &g, "phi", 10);
    if (c->flow == P2_CONSTANT_REV || c->flow == P2_LINEAR_REV) seq.flag = &flow.reversed, seq.t_switch = 0.5;
    voxel_seq vox = {.g = &g};
    if (voxel_path) {
        p2_fail_if(PROG, hj_out_open(&vox.out, voxel_path, &err), &err);
        seq.hook = voxel_block, seq.hook_ctx = &vox;
    }
    hj_ls_ode_stats st;
    hj_ls_ode_opts opts;
    hj_ls_ode_defaults(&opts);
    opts.max_step = 1.0 / (P2_NT - 1); /* a zero field (1-D 'linear') has no CFL bound */
    if (p2_solve(seq_path, c->acc, &g, &term.base, 1, y, &opts, &seq, &st, &err))
        hj_cli_fail(PROG, HJ_EXIT_RUN, "%s %s: %s", p2_flow_name[c->flow], hj_ls_accuracy_name(c->acc), err.msg);
    hj_ls_convection_free(&term);
    if (voxel_path) p2_fail_if(PROG, hj_out_commit(&vox.out, &err), &err);
    if (vtk_path) {
        const char *names[2] = {"phi0", "phi1"};
        const double *f[2] = {y0, y};
        p2_fail_if(PROG, hj_ls_write_vtk(vtk_path, &g, "convectionDemo: phi at t = 0 and t = 1", 2, names, f, &err),
                   &err);
    }
    res->steps = st.steps;
    res->exact = c->dim == 1 ? 2 * RADIUS : c->dim == 2 ? HJ_PI * RADIUS * RADIUS
               : c->dim == 3 ? 4.0 / 3.0 * HJ_PI * RADIUS * RADIUS * RADIUS : NAN;
    res->measure = NAN;
    if (c->dim <= 3) p2_fail_if(PROG, hj_ls_measure(&g, y, &res->measure, &err), &err);
    hj_ls_front_error(&g, y, y0, 2 * dx, &res->front_max, &res->front_mean);
    hj_ls_free(y0), hj_ls_free(y);
}

static void table_header(FILE *fp)
{
    fprintf(fp, "flow\tdim\tN\tbc\tacc\tmeasure\tfront_max\tfront_mean\texact_measure\tsteps\n");
}

static void table_row(FILE *fp, const cfg *c, const result *r)
{
    fprintf(fp, "%s\t%d\t%ld\t%s\t%s\t%.6g\t%.4e\t%.4e\t%.6g\t%ld\n", p2_flow_name[c->flow], c->dim,
            c->periodic ? c->N - 1 : c->N, c->periodic ? "periodic" : "extrap", hj_ls_accuracy_name(c->acc), r->measure,
            r->front_max, r->front_mean, r->exact, r->steps);
}

static const char *const SUMMARY = "convectionDemo of Mitchell's toolbox (section 2.1, Figures 1-3).";
static const char *const EPILOG =
    "With none of --flow, --accuracy, --dim, --N, --periodic: the figures and checked table.\n"
    "See the comment at the top of convection_demo.c.\n";

int main(int argc, char **argv)
{
    cfg one = {P2_CONSTANT, HJ_LS_ACC_LOW, 2, 0, 101};
    int quick = 0;
    long dim = one.dim;
    const char *dir = ".";
    hj_error err;
    const char *flows[P2_NFLOW + 1] = {NULL};
    for (int k = 0; k < P2_NFLOW; k++) flows[k] = p2_flow_name[k];
    /* the run options first: any of them makes one run */
    hj_cli_opt opts[] = {
        {.name = "--flow", .type = HJ_OPT_CHOICE, .value = &one.flow, .choices = flows, .metavar = "F",
         .help = "velocity field (section 2.1)"},
        p2_opt_accuracy(&one.acc),
        {.name = "--dim", .type = HJ_OPT_LONG, .value = &dim, .min = 1, .max = 4, .metavar = "D", .help = "dimension"},
        {.name = "--N", .type = HJ_OPT_LONG, .value = &one.N, .min = 5, .max = 100000, .metavar = "N",
         .help = "nodes per dimension on [-1, 1], dx = 2 / (N - 1); periodic: N - 1 nodes"},
        {.name = "--periodic", .type = HJ_OPT_FLAG, .value = &one.periodic,
         .help = "periodic boundaries (default: extrapolation)"},
        p2_opt_out_dir(&dir),
        p2_opt_quick(&quick, "the default set without the 3-D run (make check QUICK=1)"),
    };
    const int single =
        p2_parse_runs(PROG, SUMMARY, EPILOG, opts, (int)(sizeof opts / sizeof opts[0]), 5, argc, argv, &dir);
    one.dim = (int)dim;
    char path[4096], path2[4096];
    hj_out tab;
    if (single) {
        result r;
        snprintf(path, sizeof path, "%s/convection_run.dat", dir);
        run(&one, path, NULL, NULL, &r);
        p2_fail_if(PROG, p2_open(&tab, dir, "convection_run.tsv", &err), &err);
        fprintf(tab.fp, "# convectionDemo, one run: the error against the exact solution at t = 1 is meaningful only\n"
                        "# when it returns to the initial data (linear, the Rev flows, constant with --periodic)\n");
        table_header(tab.fp);
        table_row(tab.fp, &one, &r);
        p2_fail_if(PROG, hj_out_commit(&tab, &err), &err);
        return 0;
    }

    /* The default set: 2-D (four flows), 1-D constantRev, 3-D linear medium. */
    enum { MAXRUN = 24 };
    cfg runs[MAXRUN];
    result res[MAXRUN];
    int nr = 0;
    const int flows2[4] = {P2_CONSTANT, P2_LINEAR, P2_CONSTANT_REV, P2_LINEAR_REV};
    for (int f = 0; f < 4; f++)
        for (int a = 0; a < HJ_LS_NACC; a++) runs[nr++] = (cfg){flows2[f], a, 2, flows2[f] == P2_CONSTANT, 101};
    for (int a = 0; a < HJ_LS_NACC; a++) runs[nr++] = (cfg){P2_CONSTANT_REV, a, 1, 0, 101};
    if (!quick) runs[nr++] = (cfg){P2_LINEAR, HJ_LS_ACC_MEDIUM, 3, 0, 101};
    for (int k = 0; k < nr; k++) {
        const cfg *c = &runs[k];
        const char *seq = NULL, *vox = NULL, *vtk = NULL;
        const int fig1 = c->dim == 2 && c->flow == P2_LINEAR && c->acc == HJ_LS_ACC_MEDIUM;
        const int fig2 = c->dim == 2 && c->flow == P2_LINEAR_REV && c->acc == HJ_LS_ACC_LOW;
        if (fig1 || fig2 || (c->dim == 1 && c->acc == HJ_LS_ACC_VERYHIGH) || c->dim == 3) {
            snprintf(path, sizeof path, "%s/convection_%dd_%s_%s.dat", dir, c->dim, p2_flow_name[c->flow],
                     hj_ls_accuracy_name(c->acc));
            seq = c->dim == 3 ? NULL : path;
            vox = c->dim == 3 ? path : NULL;
        }
        if (c->dim == 3) {
            snprintf(path2, sizeof path2, "%s/convection_3d_linear_medium.vtk", dir);
            vtk = path2;
        }
        hj_progress("\rconvection_demo: %dd %s %s (%d of %d)   ", c->dim, p2_flow_name[c->flow],
                    hj_ls_accuracy_name(c->acc), k + 1, nr);
        run(c, seq, vox, vtk, &res[k]);
    }
    hj_progress("\n");

    p2_fail_if(PROG, p2_open(&tab, dir, "convection.tsv", &err), &err);
    fprintf(tab.fp, "# convectionDemo: measure of {phi < 0} and |phi - phi_0| within 2 dx of the front at t = 1\n");
    table_header(tab.fp);
    for (int k = 0; k < nr; k++) table_row(tab.fp, &runs[k], &res[k]);
    p2_fail_if(PROG, hj_out_commit(&tab, &err), &err);

    /* The numbers of the report's note (notes/convection_notes.md), one row per run. */
    p2_fail_if(PROG, p2_open(&tab, dir, "convection_summary.tsv", &err), &err);
    fprintf(tab.fp, "# convectionDemo at t = 1: measure of {phi < 0} against the exact one, its relative change in per cent,\n"
                    "# max and mean |phi - phi_0| within 2 dx of the initial front, steps\n"
                    "flow\tdim\tboundary\tacc\tmeasure\texact\tchange_pct\tfront_max\tfront_mean\tsteps\n");
    for (int k = 0; k < nr; k++) {
        const cfg *c = &runs[k];
        const result *r = &res[k];
        fprintf(tab.fp, "%s\t%d\t%s\t%s\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%ld\n", p2_flow_name[c->flow], c->dim,
                c->periodic ? "periodic" : "extrapolate", hj_ls_accuracy_name(c->acc), r->measure, r->exact,
                100 * (r->measure / r->exact - 1), r->front_max, r->front_mean, r->steps);
    }
    p2_fail_if(PROG, hj_out_commit(&tab, &err), &err);
    return 0;
}
