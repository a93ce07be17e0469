/*
# airMode: three-mode collision avoidance, a hybrid reach-avoid set (Figure 20)

**Problem.** Section 2.6.3, the toolbox's `airMode`: a hybrid system.
Two aircraft fly a three-mode protocol: mode 1 straight, mode 2 a
synchronised turn, mode 3 straight again; the only input is the time at
which mode 1 switches to mode 2 (Figure 19 of the text is the hybrid
automaton, a diagram; it is not reproduced).  The relative heading psi is
fixed, so the state is z = (x_r, y_r) and the dynamics are

    straight: dz/dt = f_s = (-v_a + v_b cos psi, v_b sin psi),
    curved:   dz/dt = f_c(z) = (-v_a + v_b cos psi + omega y_r, v_b sin psi - omega x_r),

with v_a = 3, v_b = 4, psi = -4 pi/3, omega = 1 (text).  The text prints
"v_a sin psi_r" in the second components; the relative velocity of two
aircraft is v_b (cos psi, sin psi) - (v_a, 0), as in (23) of air3D and in
the released `airMode.m`, so we use v_b (with v_a the figure would be a
different one).

**Method.** No inputs in each mode: `termConvection` with the flow
reversed (velocity -f, the toolbox's terminal-to-initial trick), in
`termRestrictUpdate` where the text asks for it; FactorCFL 0.75.  The four
reach computations of the text: (1) mode 3, straight, 5 time units, from
the target disc of radius 5; (2) mode 2, curved, pi / omega; (3) from
mode 3's set, curved, pi / omega, *not* restricted (states that pass
through mode 3's unsafe set while still in mode 2 are not unsafe); (4)
mode 1: straight, 5 units, reach-avoid: the escape set's complement
avoid = min(mode 2's set, set (3)) masks the evolution after every step
by phi = max(phi, avoid) (`hj_ls_post_mask`, the toolbox's
`postTimestepMask`), so the set never enters the escape set.  Where the
text is silent we follow `airMode.m`: the reset maps between modes are
MATLAB's rot90(., -1) of the arrays (out(x, y) = in(-y, x)), applied to
mode 3's set before (3) and to both sets forming avoid; the grid [-25,
25]^2 with N = 101 nodes, extrapolation boundaries, tMax 5 (straight) and
pi / omega (curved), default accuracy medium.

**Options.** `--accuracy`, `--N`; either: one run written to
`air_mode_run.dat` (x y reach avoid mode3 mode2 switch2), areas on stdout.

**Figure 20.** On N = 201 (the toolbox grid is 101), axes clipped by 5 as
`airMode.m`: filled, the set where collision is inevitable (reach < 0);
red, the boundary of avoid (outside it the protocol can be initiated
safely); dashed, mode 3's set (the unsafe set if no protocol is
initiated).

**Check** (`air_mode.tsv` against `published/air_mode.tsv`), accuracy
medium, on N = 101, 201, 401 (quick: 101, 201):
- exact areas: the flows are rigid motions, so the set of (1) is the
  union of the disc's translates, the points within 5 of the segment from
  0 to -5 f_s, and that of (2) the points within 5 of the half circle
  traced by the disc's centre about the flow's fixed point (f_c = 0 at
  (v_b sin psi, v_a - v_b cos psi) / omega); their areas inside the box
  (both sets leave it) by the midpoint rule on 4000^2 points (2000^2
  agrees to 0.01), kind value (1 %);
- the areas of (3), (4) and avoid: no exact value; reference our own run,
  with the grid sequence in the note (`notes/air_mode_notes.md`, from
  `air_mode_summary.tsv`);
- `increased` = 0 for the restricted computations (1), (2), (4);
- `violations`: nodes in the final reach set that lie in the escape set
  (reach < 0 < avoid), 0 if the mask acts after every step.

**Result** (full run, the note): mode 3's set has area 341.84,
342.09, 342.27 on N = 101, 201, 401 against the exact 342.32 (error 0.14 %,
0.07 %, 0.016 %), mode 2's 268.92, 269.50, 269.62 against 269.63; the
reach-avoid set 197.4, 193.2, 191.5 (changes -4.3, -1.7: ratio 2.5 per
halving of dx, an observed order of about 1.3), set (3)
233.9, 234.6, 234.7, avoid 422.1, 422.5, 422.4.  No node increased in the
restricted computations and no node of the reach-avoid set lies in the
escape set.

**Outputs.** `air_mode.tsv`, `air_mode_2d.dat` (x y reach avoid mode3 mode2
switch2, N = 201), `air_mode_summary.tsv` (per set: the exact area and
the areas on every grid, which `notes/air_mode_notes.md` presents);
plotted by `plot/fig20.gp`.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hj_cli.h"
#include "hj_io.h"
#include "hj_ls_helper.h"
#include "hj_ls_io.h"
#include "hj_ls_measure.h"
#include "hj_ls_ode.h"
#include "hj_ls_shape.h"
#include "hj_ls_term.h"
#include "hj_ls_accuracy.h"
#include "p2_cli.h"
#include "p2_reach.h"
#include "hj_math.h"

static const char *prog = "air_mode";

typedef struct {
    double r, va, vb, psi, omega;
    double c1, c2; /* f_s = (c1, c2) = (-va + vb cos psi, vb sin psi) */
} par;

/* The curved mode's PDE velocity -f_c(x) = -(c1 + omega y, c2 - omega x), one row at a time. */
static void curved(double t, const double *x, double dx0, long n, int d, double *v, void *ctx)
{
    (void)t;
    const par *q = ctx;
    for (long j = 0; j < n; j++) v[j] = d == 0 ? -(q->c1 + q->omega * x[1]) : -(q->c2 - q->omega * (x[0] + (double)j * dx0));
}

/* One reach computation of findReachSet: convection by -f_s (straight) or
 * -f_c (curved) for time tmax from data (updated in place), inside
 * termRestrictUpdate when grow, masked by max(., avoid) after every step
 * when avoid is set.  The log (may be NULL) records areas and increases. */
static void find_reach(const hj_ls_grid *g, const par *q, int acc, int is_curved, double tmax, int grow,
                       const double *avoid, double *data, p2_reach_log *log, long *steps)
{
    hj_error err;
    hj_ls_convection cv;
    hj_ls_convection_init(&cv, g, hj_ls_accuracy_scheme(acc));
    if (is_curved) cv.velocity_fn = curved, cv.ctx = (void *)q;
    else cv.velocity[0] = -q->c1, cv.velocity[1] = -q->c2;
    hj_ls_restrict rs;
    hj_ls_restrict_init(&rs, g, &cv.base, 0);
    hj_ls_ode_opts o;
    hj_ls_ode_defaults(&o);
    o.factor_cfl = HJ_LS_FACTOR_CFL_REACH;
    hj_ls_mask mask = {g, avoid, 1};
    if (avoid) {
        for (size_t r = 0; r < g->rows; r++) {
            long i[2] = {0, 0};
            const size_t k = hj_ls_row(g, r, i);
            for (long j = 0; j < g->N[0]; j++)
                data[k + (size_t)j] = data[k + (size_t)j] > avoid[k + (size_t)j] ? data[k + (size_t)j] : avoid[k + (size_t)j];
        }
        o.post = hj_ls_post_mask, o.post_ctx = &mask;
    }
    /* output every time unit (tPlot = 1), and at tmax */
    double ts[P2_MAXT];
    int nt = 0;
    for (double t = 0; t < tmax - 1e-12 && nt < P2_MAXT - 1; t += 1) ts[nt++] = t;
    ts[nt++] = tmax;
    if (log) p2_fail_if(prog, p2_reach_log_init(log, g, -1, 0, data, NULL, NULL, &err), &err);
    hj_ls_ode_stats st;
    p2_fail_if(prog, hj_ls_ode(hj_ls_accuracy_order(acc), g, grow ? &rs.base : &cv.base, ts, nt, data, &o,
                  log ? p2_reach_output : NULL, log, &st, &err), &err);
    if (log) p2_reach_log_free(log);
    *steps += st.steps;
}

/* rot90(a, -1) of MATLAB on the square grid (x index first): out(x, y) = a(-y, x). */
static void rot90m(const hj_ls_grid *g, const double *a, double *out)
{
    const long n = g->N[0];
    for (long j = 0; j < n; j++)
        for (long i = 0; i < n; i++)
            out[hj_ls_index(g, (long[2]){i, j})] = a[hj_ls_index(g, (long[2]){n - 1 - j, i})];
}

enum { S_MODE3, S_MODE2, S_SWITCH2, S_REACH, S_AVOID, NSETS };
static const char *const set_name[NSETS] = {"mode3", "mode2", "switch2", "reach", "avoid"};

typedef struct {
    long N;
    double area[NSETS];
    long increased[NSETS]; /* summed over output times; -1: not restricted */
    long violations;       /* nodes in the reach set and in the escape set */
    long steps;
} result;

/* The four reach computations of airMode on an N x N grid; fields (5
 * arrays, may be NULL) receive reach, avoid, mode3, mode2, switch2. */
static void air_mode(const par *q, int acc, long N, result *res, double **fields, hj_ls_grid *g)
{
    hj_error err;
    const double lo[2] = {-25, -25}, hi[2] = {25, 25};
    const long n[2] = {N, N};
    const hj_ls_bc bc[2] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
    p2_fail_if(prog, hj_ls_grid_init(g, 2, lo, hi, n, bc, &err), &err);
    double *a[7];
    for (int k = 0; k < 7; k++)
        if (!(a[k] = hj_ls_alloc(g))) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory");
    double *data0 = a[0], *mode3 = a[1], *mode2 = a[2], *switch2 = a[3], *reach = a[4], *avoid = a[5], *tmp = a[6];
    const double c[2] = {0, 0};
    p2_fail_if(prog, hj_ls_shape_sphere(g, c, q->r, data0, &err), &err);
    memset(res, 0, sizeof *res);
    res->N = N;
    p2_reach_log log;
    hj_progress("air_mode: accuracy %s, N = %ld ...\n", hj_ls_accuracy_name(acc), N);
    /* mode 3: straight motion, 5 time units */
    hj_ls_copy(g, mode3, data0);
    find_reach(g, q, acc, 0, 5, 1, NULL, mode3, &log, &res->steps);
    for (int k = 0; k < log.n; k++) res->increased[S_MODE3] += log.increased[k];
    /* mode 2: curved motion, pi / omega */
    hj_ls_copy(g, mode2, data0);
    find_reach(g, q, acc, 1, HJ_PI / q->omega, 1, NULL, mode2, &log, &res->steps);
    for (int k = 0; k < log.n; k++) res->increased[S_MODE2] += log.increased[k];
    /* states taken by mode 2 into mode 3's unsafe set: not restricted */
    rot90m(g, mode3, switch2);
    find_reach(g, q, acc, 1, HJ_PI / q->omega, 0, NULL, switch2, NULL, &res->steps);
    res->increased[S_SWITCH2] = -1;
    /* mode 1: reach-avoid against the escape set */
    rot90m(g, mode2, avoid);
    rot90m(g, switch2, tmp);
    hj_ls_shape_union(g, avoid, tmp, avoid);
    hj_ls_copy(g, reach, data0);
    find_reach(g, q, acc, 0, 5, 1, avoid, reach, &log, &res->steps);
    for (int k = 0; k < log.n; k++) res->increased[S_REACH] += log.increased[k];
    res->increased[S_AVOID] = -1;
    const double *sets[NSETS] = {mode3, mode2, switch2, reach, avoid};
    for (int s = 0; s < NSETS; s++) p2_fail_if(prog, hj_ls_measure(g, sets[s], &res->area[s], &err), &err);
    for (size_t r = 0; r < g->rows; r++) {
        long i[2] = {0, 0};
        const size_t k = hj_ls_row(g, r, i);
        for (long j = 0; j < g->N[0]; j++) res->violations += reach[k + (size_t)j] < 0 && avoid[k + (size_t)j] > 0;
    }
    if (fields) {
        fields[0] = reach, fields[1] = avoid, fields[2] = mode3, fields[3] = mode2, fields[4] = switch2;
        hj_ls_free(data0);
        hj_ls_free(tmp);
    } else
        for (int k = 0; k < 7; k++) hj_ls_free(a[k]);
}

/* Exact areas in the box [-25, 25]^2 of the mode 3 and mode 2 reach sets:
 * the points within r of the path of the target's centre, a segment
 * (straight) or an arc of the rotation about the flow's fixed point
 * (curved), by the midpoint rule on an M x M lattice. */
static double dist_segment(const double *p, const double *b)
{
    const double bb = b[0] * b[0] + b[1] * b[1];
    double s = (p[0] * b[0] + p[1] * b[1]) / bb;
    s = s < 0 ? 0 : s > 1 ? 1 : s;
    return hypot(p[0] - s * b[0], p[1] - s * b[1]);
}

static void exact_areas(const par *q, int M, double *a3, double *a2)
{
    /* mode 3: the centre moves with -f_s for 5 time units */
    const double b[2] = {-5 * q->c1, -5 * q->c2};
    /* mode 2: dz/dt = -f_c(z) = A z - c, A the rotation at rate omega;
     * fixed point zc = (c2, -c1) / omega; from 0 the centre turns
     * counterclockwise by omega t = pi about zc */
    const double zc[2] = {q->c2 / q->omega, -q->c1 / q->omega}, rho = hypot(zc[0], zc[1]);
    const double th0 = atan2(-zc[1], -zc[0]), sweep = HJ_PI;
    const double e1[2] = {zc[0] + rho * cos(th0 + sweep), zc[1] + rho * sin(th0 + sweep)};
    long n3 = 0, n2 = 0;
    for (int j = 0; j < M; j++)
        for (int i = 0; i < M; i++) {
            const double p[2] = {-25 + 50 * (i + 0.5) / M, -25 + 50 * (j + 0.5) / M};
            n3 += dist_segment(p, b) <= q->r;
            double d;
            const double rel = fmod(atan2(p[1] - zc[1], p[0] - zc[0]) - th0 + 4 * HJ_PI, 2 * HJ_PI);
            if (rel <= sweep) d = fabs(hypot(p[0] - zc[0], p[1] - zc[1]) - rho);
            else {
                const double d0 = hypot(p[0], p[1]), d1 = hypot(p[0] - e1[0], p[1] - e1[1]);
                d = d0 < d1 ? d0 : d1;
            }
            n2 += d <= q->r;
        }
    *a3 = 2500.0 * (double)n3 / ((double)M * M);
    *a2 = 2500.0 * (double)n2 / ((double)M * M);
}

static const char *summary = "Three-mode collision avoidance of Mitchell's toolbox (section 2.6.3, Figure 20).";
static const char *epilog =
    "With neither --accuracy nor --N: Figure 20's data and the checks (air_mode.tsv,\n"
    "air_mode_2d.dat, air_mode_summary.tsv).  With one of them: one run written to air_mode_run.dat\n"
    "(x y reach avoid mode3 mode2 switch2), its areas on stdout.  See the comment at the top of\n"
    "air_mode.c.\n";

int main(int argc, char **argv)
{
    const char *out_dir = ".";
    int quick = 0, acc = HJ_LS_ACC_MEDIUM;
    long N = 101;
    hj_error err;
    /* the run options first: either makes one run */
    hj_cli_opt opts[] = {
        p2_opt_accuracy(&acc),
        {.name = "--N", .type = HJ_OPT_LONG, .value = &N, .min = 11, .max = 4001, .metavar = "N",
         .help = "nodes per side of [-25, 25]^2 (airMode.m's grid)"},
        p2_opt_out_dir(&out_dir),
        p2_opt_quick(&quick, "the checks on N = 101, 201 only"),
    };
    const int single =
        p2_parse_runs(prog, summary, epilog, opts, (int)(sizeof opts / sizeof opts[0]), 2, argc, argv, &out_dir);
    p2_one_thread(); /* 2-D grids */
    par q = {5, 3, 4, -4 * HJ_PI / 3, 1, 0, 0};
    q.c1 = -q.va + q.vb * cos(q.psi), q.c2 = q.vb * sin(q.psi);
    hj_ls_grid g;
    static result R[4];
    double *f[5];
    const char *names[5] = {"reach", "avoid", "mode3", "mode2", "switch2"};
    hj_out out;
    if (single) {
        air_mode(&q, acc, N, &R[0], f, &g);
        p2_fail_if(prog, p2_write_dat(out_dir, "air_mode_run.dat", &g, 5, names, (const double *const *)f, &err), &err);
        printf("# airMode accuracy=%s N=%ld: areas in [-25, 25]^2\n", hj_ls_accuracy_name(acc), N);
        double e3, e2;
        exact_areas(&q, 2000, &e3, &e2);
        for (int s = 0; s < NSETS; s++) printf("%s\t%.6g\n", set_name[s], R[0].area[s]);
        printf("# exact: mode3 %.6g, mode2 %.6g; violations %ld; increases mode3 %ld mode2 %ld reach %ld; %ld steps\n", e3,
               e2, R[0].violations, R[0].increased[S_MODE3], R[0].increased[S_MODE2], R[0].increased[S_REACH], R[0].steps);
        for (int k = 0; k < 5; k++) hj_ls_free(f[k]);
        return 0;
    }
    /* The grid sequence N = 101 (airMode.m), 201, 401 (quick: 101, 201);
     * Figure 20 from N = 201. */
    static const long ns[] = {101, 201, 401};
    const int nn = quick ? 2 : 3;
    for (int k = 0; k < nn; k++) {
        air_mode(&q, acc, ns[k], &R[k], k == 1 ? f : NULL, &g);
        if (k == 1) {
            p2_fail_if(prog, p2_write_dat(out_dir, "air_mode_2d.dat", &g, 5, names, (const double *const *)f, &err),
                       &err);
            for (int m = 0; m < 5; m++) hj_ls_free(f[m]);
        }
    }
    double e3, e2, e3c, e2c;
    exact_areas(&q, 4000, &e3, &e2);
    exact_areas(&q, 2000, &e3c, &e2c);
    p2_fail_if(prog, p2_open(&out, out_dir, "air_mode.tsv", &err), &err);
    fprintf(out.fp, "# airMode, accuracy %s: area in [-25, 25]^2 of each set at the end of its computation, nodes where phi\n"
                    "# increased between output times (summed; - where the update is not restricted), and nodes of the reach\n"
                    "# set inside the escape set (violations; reach row only); exact = area of the exact set (mode3, mode2)\n"
                    "set\tN\tarea\texact\tincreased\tviolations\tsteps\n", hj_ls_accuracy_name(acc));
    for (int s = 0; s < NSETS; s++)
        for (int k = 0; k < nn; k++) {
            fprintf(out.fp, "%s\t%ld\t%.6g\t", set_name[s], ns[k], R[k].area[s]);
            if (s == S_MODE3 || s == S_MODE2) fprintf(out.fp, "%.6g\t", s == S_MODE3 ? e3 : e2); else fputs("-\t", out.fp);
            if (R[k].increased[s] >= 0) fprintf(out.fp, "%ld\t", R[k].increased[s]); else fputs("-\t", out.fp);
            if (s == S_REACH) fprintf(out.fp, "%ld\t", R[k].violations); else fputs("-\t", out.fp);
            fprintf(out.fp, "%ld\n", R[k].steps);
        }
    /* The numbers of the report's note (notes/air_mode_notes.md), one row per set. */
    p2_next_file(prog, &out, out_dir, "air_mode_summary.tsv");
    fprintf(out.fp, "# airMode, accuracy %s: area in [-25, 25]^2 of each set at the end of its computation on the N x N grids\n"
                    "# (- where the grid is not run: --quick); exact (mode3, mode2): the exact set's area by the midpoint rule\n"
                    "# on 4000^2 points, exact_2000 on 2000^2\nset\texact\texact_2000", hj_ls_accuracy_name(acc));
    for (int k = 0; k < 3; k++) fprintf(out.fp, "\tarea_N%ld", ns[k]);
    fputc('\n', out.fp);
    for (int s = 0; s < NSETS; s++) {
        fprintf(out.fp, "%s", set_name[s]);
        if (s == S_MODE3 || s == S_MODE2)
            fprintf(out.fp, "\t%.17g\t%.17g", s == S_MODE3 ? e3 : e2, s == S_MODE3 ? e3c : e2c);
        else
            fputs("\t-\t-", out.fp);
        for (int k = 0; k < 3; k++)
            if (k < nn) fprintf(out.fp, "\t%.17g", R[k].area[s]); else fputs("\t-", out.fp);
        fputc('\n', out.fp);
    }
    p2_fail_if(prog, hj_out_commit(&out, &err), &err);
    return 0;
}
