/* hjreach -- reachable sets from the command line: a system from a small
 * catalogue, a grid, a target, an obstacle and a horizon; writes the value
 * and the time-to-reach (common/hj_reach).
 *
 *   hjreach --system dubins --N 41,41,40 --target-radius 0.5 \
 *           --obstacle -1.4,0.2:-0.6,1.4 --horizon 1 --out-dir out
 *
 * Systems (state order; the control reaches the target unless the system
 * says otherwise):
 *   double_integrator  (x, v): x' = v, v' = u, |u| <= --u-max
 *   dubins             (x, y, th): speed --speed, |th'| <= --u-max, th
 *                      periodic (its grid is given by the period)
 *   planar_di          (x, y, vx, vy): acceleration in a disc of radius --u-max
 *   air3d              (x, y, psi): the toolbox's game (section 2.6.1),
 *                      evader speed and turn rate --speed, --u-max avoid
 *                      the capture cylinder, the pursuer (same speed and
 *                      rate) disturbs; psi periodic
 * The target is the ball (a cylinder in the other dimensions) of radius
 * --target-radius about --target-centre over the first two state
 * dimensions (the first for the double integrator: |x - c| <= r); the
 * obstacle (optional) a box lo:hi over the same dimensions.
 *
 * Outputs in --out-dir: value.dat and ttr.dat (gnuplot blocks: 1-D to
 * 3-D; for 4-D the slice through the middle of the velocities) and, for
 * 3-D, reach.vtk with both fields.  Dimensions are numbered from 1 in
 * every message, in the order of --N, --min and --max.  The box is held
 * to coordinates within +-1e100 and spacings of at least 1e-100 before the
 * run (beyond, the target's distance or the dynamics' bounds overflow and
 * the run failed once started).  ttr is inf where the set is not
 * reached by the horizon, -1 in reach.vtk (VTK's text reader, C++ stream
 * extraction, stops at "inf").  Every output name is checked before the
 * run, so a name that cannot be written fails at once, not after it.  The number of time steps (the horizon over the
 * CFL step, estimated before the run) is checked against --max-steps
 * first: a long horizon, or a tiny period or spacing, is refused with the
 * count instead of running for ever; with --horizon 0 the run stops
 * unconverged after that many steps.  A target with no node of the grid
 * (outside it, or between its nodes), an obstacle over every node of the
 * grid or of the target, and for air3d a capture set over every node are
 * refused before the run: the answer would be a set of measure 0 (or the
 * whole grid) that says nothing.  So are a periodic angle whose period is
 * not 2 pi (or a multiple) and, before any pass over the nodes, a grid
 * whose solve does not fit in memory (hj_reach_check_memory).  Progress
 * on stderr, at most about once a second and a final line, by default only when stderr is a terminal
 * (--progress: always, one line each; --quiet: never); one line of
 * results on stdout: the steps, the final tau and the measure of the set
 * (dimensions 1 to 3).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "hj.h"

static const char *prog = "hjreach";

typedef struct {
    double speed, umax;
} params;

static void di_f(double t, const double *x, double *o, void *c)
{
    (void)t, (void)c;
    o[0] = x[1], o[1] = 0;
}
static void di_G(double t, const double *x, double *o, void *c)
{
    (void)t, (void)x, (void)c;
    o[0] = 0, o[1] = 1;
}
static void dub_f(double t, const double *x, double *o, void *c)
{
    (void)t;
    const params *p = c;
    o[0] = p->speed * cos(x[2]), o[1] = p->speed * sin(x[2]), o[2] = 0;
}
static void dub_G(double t, const double *x, double *o, void *c)
{
    (void)t, (void)x, (void)c;
    o[0] = 0, o[1] = 0, o[2] = 1;
}
static void pdi_f(double t, const double *x, double *o, void *c)
{
    (void)t, (void)c;
    o[0] = x[2], o[1] = x[3], o[2] = 0, o[3] = 0;
}
static void pdi_G(double t, const double *x, double *o, void *c)
{
    (void)t, (void)x, (void)c;
    for (int q = 0; q < 8; q++) o[q] = q == 4 || q == 7;
}
/* air3D: relative position (x, y) of the pursuer in the evader's frame
 * and relative heading psi; evader turn a (control), pursuer turn b. */
static void air_f(double t, const double *x, double *o, void *c)
{
    (void)t;
    const params *p = c;
    o[0] = -p->speed + p->speed * cos(x[2]), o[1] = p->speed * sin(x[2]), o[2] = 0;
}
static void air_G(double t, const double *x, double *o, void *c)
{
    (void)t, (void)c;
    o[0] = x[1], o[1] = -x[0], o[2] = -1;
}
static void air_H(double t, const double *x, double *o, void *c)
{
    (void)t, (void)x, (void)c;
    o[0] = 0, o[1] = 0, o[2] = 1;
}

typedef struct {
    int dims; /* target/obstacle dimensions: 1 or 2 */
    double c[2], r;
    double lo[2], hi[2];
} sets;

static double target_fn(double t, const double *x, void *ctx)
{
    (void)t;
    const sets *s = ctx;
    double d2 = 0;
    for (int k = 0; k < s->dims; k++) d2 += (x[k] - s->c[k]) * (x[k] - s->c[k]);
    return sqrt(d2) - s->r;
}
static double obstacle_fn(double t, const double *x, void *ctx)
{
    (void)t;
    const sets *s = ctx;
    double m = -INFINITY;
    for (int k = 0; k < s->dims; k++) m = fmax(m, fmax(s->lo[k] - x[k], x[k] - s->hi[k]));
    return m;
}

/* Comma-separated doubles, exactly n of them. */
static void parse_list(const char *s, const char *what, double *out, int n)
{
    hj_error err;
    char buf[512], *save = NULL;
    if (strlen(s) >= sizeof buf) hj_cli_fail(prog, HJ_EXIT_USAGE, "%s: too long", what);
    strcpy(buf, s);
    int k = 0;
    for (char *tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save), k++) {
        if (k >= n) hj_cli_fail(prog, HJ_EXIT_USAGE, "%s: expected %d number%s, got more", what, n, n == 1 ? "" : "s");
        if (hj_parse_double(tok, what, -1e300, 1e300, &out[k], &err)) hj_cli_fail(prog, HJ_EXIT_USAGE, "%s", err.msg);
    }
    if (k != n) hj_cli_fail(prog, HJ_EXIT_USAGE, "%s: expected %d number%s, got %d", what, n, n == 1 ? "" : "s", k);
}

/* The CFL step the solver will take, estimated before the run: factor_cfl
 * / max over the nodes of sum_d alpha_d / dx_d, with alpha_d the partial
 * bounds of the dynamics (they do not depend on the gradient, and these
 * systems not on time), plus the discount's rate lambda (the kernel's sum
 * of terms adds the inverse bounds).  *dim_most: the dimension with the
 * largest term at that node, the one that limits the step, or -1 when the
 * discount's rate exceeds the dynamics'.  INFINITY when nothing moves. */
static double cfl_step(const hj_ls_grid *g, const hj_reach_dyn *s, double factor_cfl, double discount, int *dim_most)
{
    long idx[HJ_LS_MAXDIM] = {0};
    double worst = 0;
    *dim_most = 0;
    for (size_t n = 0; n < g->nodes; n++) {
        double x[HJ_LS_MAXDIM], sum = 0, top = -1;
        int dtop = 0;
        for (int d = 0; d < g->dim; d++) x[d] = g->min[d] + (double)idx[d] * g->dx[d];
        for (int d = 0; d < g->dim; d++) {
            const double a = hj_reach_ls_partial(0, x, NULL, NULL, d, (void *)s) / g->dx[d];
            sum += a;
            if (a > top) top = a, dtop = d;
        }
        if (sum > worst) worst = sum, *dim_most = dtop;
        for (int d = 0; d < g->dim && ++idx[d] == g->N[d]; d++) idx[d] = 0;
    }
    if (discount > worst) *dim_most = -1;
    return worst + discount > 0 ? factor_cfl / (worst + discount) : INFINITY;
}

/* Dimensions are numbered from 1 in every message of hjreach: dimension k
 * is the k-th number of --N, --min and --max (the state order of the
 * system's line above).  The library numbers them from 0 (an array
 * index), so the grid's conditions it would report with a dimension
 * (bounds in order, a positive period, a spacing it can divide by) are
 * checked here first, with the option named, and hj_ls_grid_init_period's
 * own messages, relayed as they are, then name none. */

/* The box the tool takes: every coordinate of --min and --max within
 * COORD_MAX, every spacing at least SPACING_MIN.  Within it the values
 * and bounds at the grid's nodes stay finite: the target's distance
 * ((x - c)^2 below 1e201 for a centre in the box; a centre far outside
 * it is refused by check_sets), the partial bounds of the catalogue's dynamics
 * (at most |x| + 2 --speed + --u-max |x|, below 1e107 with speed and
 * --u-max at most 1e6) over a spacing, summed over 4 dimensions (below
 * 1e208: the CFL bound), and the measure's cells (below 1e301 in 3-D).
 * Beyond it the run failed after it started, on a non-finite Hamiltonian
 * (a target 1e155 away squares to inf). */
#define COORD_MAX 1e100
#define SPACING_MIN 1e-100

/* Refuse (exit 2) a box outside that range or empty in a dimension, naming
 * the option and the dimension (from 1). */
static void check_box(int dim, const double *lo, const double *hi, const long *N, const hj_ls_bc *bc)
{
    for (int side = 0; side < 2; side++)
        for (int d = 0; d < dim; d++) {
            const double v = side ? hi[d] : lo[d];
            if (!(fabs(v) <= COORD_MAX))
                hj_cli_fail(prog, HJ_EXIT_USAGE,
                            "%s: %g in dimension %d is out of range: hjreach takes coordinates within +-%g (beyond, "
                            "the target's distance and the dynamics overflow)",
                            side ? "--max" : "--min", v, d + 1, COORD_MAX);
        }
    for (int d = 0; d < dim; d++) {
        const int periodic = bc[d].type == HJ_LS_BC_PERIODIC;
        if (!(hi[d] > lo[d]))
            hj_cli_fail(prog, HJ_EXIT_USAGE, "--max %g must exceed --min %g in dimension %d%s", hi[d], lo[d], d + 1,
                        periodic ? " (periodic: --max - --min is the period)" : "");
        const double dx = (hi[d] - lo[d]) / (double)(periodic ? N[d] : N[d] - 1);
        if (!(dx >= SPACING_MIN))
            hj_cli_fail(prog, HJ_EXIT_USAGE,
                        "--min, --max and --N give a spacing of %g in dimension %d, below %g: widen the box or "
                        "lower --N there",
                        dx, d + 1, SPACING_MIN);
    }
}

/* Refuse (exit 2) a periodic dimension whose period is not 2 pi or a
 * multiple of it, within a relative 1e-5 (6.2832 and 2 x 3.14159 pass):
 * the catalogue's periodic dimensions are angles, read through their cosine
 * and sine, and on another period the dynamics jump where the grid wraps.
 * Before, a Dubins car on [0, pi) ran and gave a set of measure 8.49 where
 * [-pi, pi) gives 16.27. */
static void check_period(int dim, const double *lo, const double *hi, const hj_ls_bc *bc, const char *system)
{
    for (int d = 0; d < dim; d++) {
        if (bc[d].type != HJ_LS_BC_PERIODIC) continue;
        const double period = hi[d] - lo[d], turns = nearbyint(period / (2 * HJ_PI));
        if (!(turns >= 1 && fabs(period - turns * 2 * HJ_PI) <= 1e-5 * period))
            hj_cli_fail(prog, HJ_EXIT_USAGE,
                        "--max - --min in dimension %d is %.10g, the period of %s's angle: give 2 pi (--min 0 --max "
                        "6.283185307179586 there) or a multiple of it, within a relative 1e-5",
                        d + 1, period, system);
    }
}

/* Whether the target's ball (over its dimensions) meets the grid's box. */
static int target_meets_grid(const sets *s, const hj_ls_grid *g)
{
    double d2 = 0;
    for (int k = 0; k < s->dims; k++) {
        const double c = s->c[k], e = c < g->min[k] ? g->min[k] - c : c > g->max[k] ? c - g->max[k] : 0;
        d2 += e * e;
    }
    return sqrt(d2) <= s->r;
}

/* Refuse (exit 2) a problem whose value at tau = 0 says nothing: a target
 * with no node of the grid, an obstacle over every node of the grid or of
 * the target, and for a target to avoid (air3d's capture set) one over
 * every node.  Every node is visited once, as cfl_step does. */
static void check_sets(const hj_ls_grid *g, const sets *s, int obstacle, int avoid)
{
    long idx[HJ_LS_MAXDIM] = {0};
    size_t in_target = 0, free_of_obstacle = 0, start = 0;
    for (size_t n = 0; n < g->nodes; n++) {
        double x[HJ_LS_MAXDIM];
        for (int d = 0; d < g->dim; d++) x[d] = g->min[d] + (double)idx[d] * g->dx[d];
        const int t = target_fn(0, x, (void *)s) <= 0, o = !obstacle || obstacle_fn(0, x, (void *)s) > 0;
        in_target += t, free_of_obstacle += o, start += t && o;
        for (int d = 0; d < g->dim && ++idx[d] == g->N[d]; d++) idx[d] = 0;
    }
    char c[64], sp[96];
    if (s->dims == 1) snprintf(c, sizeof c, "%g", s->c[0]), snprintf(sp, sizeof sp, "spacing %g", g->dx[0]);
    else
        snprintf(c, sizeof c, "(%g, %g)", s->c[0], s->c[1]),
            snprintf(sp, sizeof sp, "spacing %g in dimension 1, %g in dimension 2", g->dx[0], g->dx[1]);
    if (in_target == 0 && !target_meets_grid(s, g))
        hj_cli_fail(prog, HJ_EXIT_USAGE,
                    "the target (centre %s, radius %g) lies wholly outside the grid: move --target-centre into it "
                    "(--min, --max) or enlarge --target-radius",
                    c, s->r);
    if (in_target == 0)
        hj_cli_fail(prog, HJ_EXIT_USAGE,
                    "the target (centre %s, radius %g) holds no node of the grid (%s): enlarge "
                    "--target-radius or refine --N",
                    c, s->r, sp);
    if (free_of_obstacle == 0)
        hj_cli_fail(prog, HJ_EXIT_USAGE, "--obstacle covers every node of the grid: nothing is left to reach");
    if (start == 0)
        hj_cli_fail(prog, HJ_EXIT_USAGE, "--obstacle covers every node of the target: the set would be empty");
    if (avoid && in_target == g->nodes)
        hj_cli_fail(prog, HJ_EXIT_USAGE,
                    "the capture set (centre %s, radius %g) covers every node of the grid: every state is captured; "
                    "shrink --target-radius or widen the grid",
                    c, s->r);
}

/* Progress on stderr at most once a second, from the solver's callback. */
typedef struct {
    int tty;        /* a terminal: one line rewritten in place */
    int until_conv; /* --horizon 0: the solver's horizon is the step limit's
                     * (INFINITY where nothing moves) */
    double start, last;
    long max_steps;
} progress;

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void progress_line(const progress *p, double tau, double horizon, long steps, int final)
{
    char where[96];
    if (p->until_conv && !isfinite(horizon)) snprintf(where, sizeof where, "until converged");
    else if (p->until_conv) snprintf(where, sizeof where, "until converged, at most %ld steps", p->max_steps);
    else snprintf(where, sizeof where, "of %g, %.0f%%", horizon, 100 * tau / horizon);
    fprintf(stderr, "%s%s: step %ld, tau = %g (%s), %.0f s%s%s", p->tty ? "\r" : "", prog, steps, tau, where,
            now() - p->start, p->tty ? "   " : "", p->tty && !final ? "" : "\n");
    fflush(stderr);
}

static int show_progress(double tau, double horizon, long steps, void *ctx)
{
    progress *p = ctx;
    const double t = now();
    if (t - p->last >= 1) {
        p->last = t;
        progress_line(p, tau, horizon, steps, 0);
    }
    return 0;
}

static void write_fields(const char *dir, const hj_ls_grid *g, const double *phi, const double *ttr)
{
    hj_error err;
    char path[1024];
    const char *names[2] = {"value", "ttr"};
    const double *f[2] = {phi, ttr};
    if (g->dim <= 3) {
        snprintf(path, sizeof path, "%s/value.dat", dir);
        if (hj_ls_write_dat(path, g, 1, names, f, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
        snprintf(path, sizeof path, "%s/ttr.dat", dir);
        if (hj_ls_write_dat(path, g, 1, names + 1, f + 1, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
        if (g->dim == 3) {
            /* The time-to-reach with -1 for "not reached": VTK readers take no inf. */
            double *t = hj_ls_alloc(g);
            if (!t) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory");
            for (size_t k = 0; k < g->total; k++) t[k] = isinf(ttr[k]) ? -1 : ttr[k];
            const double *fv[2] = {phi, t};
            snprintf(path, sizeof path, "%s/reach.vtk", dir);
            if (hj_ls_write_vtk(path, g, "hjreach value and time-to-reach (-1: not reached)", 2, names, fv, &err))
                hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
            hj_ls_free(t);
        }
        return;
    }
    /* 4-D: the (x, y) slice through the middle nodes of the velocities. */
    hj_ls_grid s;
    const hj_ls_bc bc[2] = {g->bc[0], g->bc[1]};
    if (hj_ls_grid_init(&s, 2, g->min, g->max, g->N, bc, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    double *a = hj_ls_alloc(&s), *b = hj_ls_alloc(&s);
    if (!a || !b) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory");
    for (long j = 0; j < g->N[1]; j++)
        for (long i = 0; i < g->N[0]; i++) {
            const size_t k = hj_ls_index(g, (long[]){i, j, g->N[2] / 2, g->N[3] / 2}), q = hj_ls_index(&s, (long[]){i, j});
            a[q] = phi[k], b[q] = ttr[k];
        }
    const double *sf[2] = {a, b};
    snprintf(path, sizeof path, "%s/value.dat", dir);
    if (hj_ls_write_dat(path, &s, 1, names, sf, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    snprintf(path, sizeof path, "%s/ttr.dat", dir);
    if (hj_ls_write_dat(path, &s, 1, names + 1, sf + 1, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    hj_ls_free(a), hj_ls_free(b);
}

int main(int argc, char **argv)
{
    static const char *const systems[] = {"double_integrator", "dubins", "planar_di", "air3d", NULL};
    static const char *const kinds[] = {"brt", "brs", NULL};
    static const char *const boundaries[] = {"away", "toward", NULL};
    static const char *const schemes[] = {"upwind1", "eno2", "eno3", "weno5", NULL};
    static const int scheme_ids[] = {HJ_LS_UPWIND_FIRST, HJ_LS_ENO2, HJ_LS_ENO3A, HJ_LS_WENO5A};
    int sys = 1, kind = 0, scheme = 1, boundary = 0, ncount = 0;
    long N[4] = {0};
    const char *lo_s = NULL, *hi_s = NULL, *centre_s = NULL, *obstacle_s = NULL, *out_dir = ".";
    double horizon = 1, radius = 0.5, tol = 0, speed = 1, umax = 1, discount = 0;
    long max_steps = 100000;
    int quiet = 0, force_progress = 0;
    hj_cli_opt opts[] = {
        {.name = "--system", .type = HJ_OPT_CHOICE, .value = &sys, .choices = systems, .metavar = "NAME",
         .help = "the system from the catalogue"},
        {.name = "--N", .type = HJ_OPT_LONG_LIST, .value = N, .min = 3, .max = 100000, .count = &ncount, .maxn = 4,
         .metavar = "N1,N2,..",
         .help = "nodes in each dimension (per period for a periodic one); dimensions are numbered from 1 in this "
                 "order, that of --min and --max, in every message",
         .dflt = "41 (21 in 4-D)"},
        {.name = "--min", .type = HJ_OPT_STRING, .value = &lo_s, .metavar = "A,B,..",
         .help = "lower corner of the grid (coordinates within +-1e100, spacing at least 1e-100)",
         .dflt = "the system's"},
        {.name = "--max", .type = HJ_OPT_STRING, .value = &hi_s, .metavar = "A,B,..",
         .help = "upper corner (a periodic dimension, an angle: min + its period, 2 pi or a multiple)",
         .dflt = "the system's"},
        {.name = "--target-centre", .type = HJ_OPT_STRING, .value = &centre_s, .metavar = "X,Y",
         .help = "centre of the target ball over the first two dimensions (the first only for double_integrator: |x - c| <= r)", .dflt = "0"},
        {.name = "--target-radius", .type = HJ_OPT_DOUBLE, .value = &radius, .min = 1e-12, .max = 1e12,
         .metavar = "R", .help = "radius of the target ball"},
        {.name = "--obstacle", .type = HJ_OPT_STRING, .value = &obstacle_s, .metavar = "LO:HI",
         .help = "obstacle box lo1,lo2:hi1,hi2 over the first two dimensions (lo:hi over the first only for double_integrator)", .dflt = "none"},
        {.name = "--horizon", .type = HJ_OPT_DOUBLE, .value = &horizon, .min = 0, .max = 1e12, .metavar = "T",
         .help = "time horizon (0: until converged, needs --tol)"},
        {.name = "--max-steps", .type = HJ_OPT_LONG, .value = &max_steps, .min = 1, .max = 1000000000, .metavar = "N",
         .help = "refuse a run of more time steps (the horizon over the CFL step, estimated before the run; with "
                 "--horizon 0 the run stops there, unconverged)"},
        {.name = "--tol", .type = HJ_OPT_DOUBLE, .value = &tol, .min = 0, .max = 1e12, .metavar = "RATE",
         .help = "stop when max |dphi/dtau| falls below RATE (0: never)"},
        {.name = "--discount", .type = HJ_OPT_DOUBLE, .value = &discount, .min = 0, .max = 1e12, .metavar = "L",
         .help = "discount rate lambda of the term lambda phi"},
        {.name = "--kind", .type = HJ_OPT_CHOICE, .value = &kind, .choices = kinds, .metavar = "KIND",
         .help = "reachable tube or set"},
        {.name = "--scheme", .type = HJ_OPT_CHOICE, .value = &scheme, .choices = schemes, .metavar = "S",
         .help = "spatial scheme (RK order 1 for upwind1, 2 for eno2, 3 otherwise)"},
        {.name = "--boundary", .type = HJ_OPT_CHOICE, .value = &boundary, .choices = boundaries, .metavar = "B",
         .help = "ghost values at the non-periodic faces: extrapolated linearly away from zero (ToolboxLS's "
                 "addGhostExtrapolate) or toward it; over a long horizon 'away' lets a negative value at a face the "
                 "dynamics leave sink below the target's minimum (docs/API.md, Boundaries), 'toward' does not"},
        {.name = "--speed", .type = HJ_OPT_DOUBLE, .value = &speed, .min = 0, .max = 1e6, .metavar = "V",
         .help = "speed (dubins, air3d)"},
        {.name = "--u-max", .type = HJ_OPT_DOUBLE, .value = &umax, .min = 0, .max = 1e6, .metavar = "U",
         .help = "control bound (turn rate, acceleration)"},
        {.name = "--out-dir", .type = HJ_OPT_STRING, .value = &out_dir, .metavar = "DIR",
         .help = "where to write value.dat, ttr.dat (and reach.vtk in 3-D; its ttr is -1 where not reached)"},
        {.name = "--progress", .type = HJ_OPT_FLAG, .value = &force_progress,
         .help = "progress on stderr (about once a second, and a final line) even when stderr is not a terminal, "
                 "one line each; without it only a terminal gets it, so that logs and scripts reading stderr see "
                 "errors alone"},
        {.name = "--quiet", .type = HJ_OPT_FLAG, .value = &quiet, .help = "no progress on stderr, even on a terminal"},
    };
    hj_cli_spec spec = {prog, "reachable sets of a catalogue system: the value and the time-to-reach", opts,
                        (int)(sizeof opts / sizeof opts[0]), NULL};
    hj_cli_parse_or_exit(&spec, argc, argv);

    static const int dims[] = {2, 3, 4, 3};
    static const double dlo[4][4] = {{-2, -2}, {-2, -2, 0}, {-1.6, -1.6, -1.2, -1.2}, {-6, -10, 0}};
    static const double dhi[4][4] = {{2, 2}, {2, 2, 2 * HJ_PI}, {1.6, 1.6, 1.2, 1.2}, {20, 10, 2 * HJ_PI}};
    const int dim = dims[sys];
    double lo[4], hi[4];
    for (int d = 0; d < dim; d++) lo[d] = dlo[sys][d], hi[d] = dhi[sys][d];
    if (lo_s) parse_list(lo_s, "--min", lo, dim);
    if (hi_s) parse_list(hi_s, "--max", hi, dim);
    if (ncount == 0)
        for (int d = 0; d < dim; d++) N[d] = dim == 4 ? 21 : 41;
    else if (ncount == 1)
        for (int d = 1; d < dim; d++) N[d] = N[0];
    else if (ncount != dim)
        hj_cli_fail(prog, HJ_EXIT_USAGE, "--N: %s is %d-D, got %d counts", systems[sys], dim, ncount);
    if (horizon == 0 && !(tol > 0)) hj_cli_fail(prog, HJ_EXIT_USAGE, "--horizon 0 (until converged) needs --tol > 0");
    if (quiet && force_progress) hj_cli_fail(prog, HJ_EXIT_USAGE, "--quiet and --progress contradict each other");
    sets st = {sys == 0 ? 1 : 2, {0, 0}, radius, {0, 0}, {0, 0}};
    if (centre_s) parse_list(centre_s, "--target-centre", st.c, st.dims);
    if (obstacle_s) {
        const char *colon = strchr(obstacle_s, ':');
        if (!colon) hj_cli_fail(prog, HJ_EXIT_USAGE, "--obstacle: expected lo1,lo2:hi1,hi2");
        char lo_part[256];
        const size_t n = (size_t)(colon - obstacle_s);
        if (n >= sizeof lo_part) hj_cli_fail(prog, HJ_EXIT_USAGE, "--obstacle: too long");
        memcpy(lo_part, obstacle_s, n), lo_part[n] = '\0';
        parse_list(lo_part, "--obstacle (lower corner)", st.lo, st.dims);
        parse_list(colon + 1, "--obstacle (upper corner)", st.hi, st.dims);
        for (int k = 0; k < st.dims; k++)
            if (!(st.lo[k] < st.hi[k])) hj_cli_fail(prog, HJ_EXIT_USAGE, "--obstacle: the box is empty");
    }
    hj_ls_bc bc[4];
    for (int d = 0; d < dim; d++) bc[d] = (hj_ls_bc){boundary ? HJ_LS_BC_EXTRAP_TOWARD : HJ_LS_BC_EXTRAP_AWAY, 0, 0};
    if (sys == 1 || sys == 3) bc[2].type = HJ_LS_BC_PERIODIC;
    check_box(dim, lo, hi, N, bc);
    check_period(dim, lo, hi, bc, systems[sys]);
    hj_error err;
    char probe[1024];
    static const char *const outputs[] = {"value.dat", "ttr.dat", "reach.vtk"};
    for (int k = 0; k < (dim == 3 ? 3 : 2); k++) {
        snprintf(probe, sizeof probe, "%s/%s", out_dir, outputs[k]);
        if (hj_out_check(probe, &err)) hj_cli_fail(prog, HJ_EXIT_USAGE, "%s", err.msg);
    }

    hj_ls_grid g;
    if (hj_ls_grid_init_period(&g, dim, lo, hi, N, bc, &err)) hj_cli_fail(prog, HJ_EXIT_USAGE, "%s", err.msg);

    params p = {speed, umax};
    hj_reach_dyn s;
    const hj_reach_vec_fn fs[4] = {di_f, dub_f, pdi_f, air_f};
    const hj_reach_vec_fn Gs[4] = {di_G, dub_G, pdi_G, air_G};
    hj_reach_dyn_init(&s, dim, fs[sys], &p);
    if (sys == 2) hj_reach_dyn_control_ball(&s, Gs[sys], 2, (double[]){0, 0}, umax);
    else hj_reach_dyn_control_box(&s, Gs[sys], 1, (double[]){-umax}, (double[]){umax});
    if (sys == 3) {
        /* The evader (control) avoids capture, the pursuer (disturbance)
         * seeks it: modes named, not signs. */
        hj_reach_dyn_disturbance_box(&s, air_H, 1, (double[]){-umax}, (double[]){umax});
        hj_reach_dyn_goal(&s, HJ_REACH_AVOID);
    }
    hj_reach_problem pb;
    hj_reach_problem_init(&pb, &g, &s);
    pb.kind = kind == 0 ? HJ_REACH_BRT : HJ_REACH_BRS;
    pb.target.fn = target_fn, pb.target.ctx = &st;
    if (obstacle_s) pb.obstacle.fn = obstacle_fn, pb.obstacle.ctx = &st;
    pb.horizon = horizon > 0 ? horizon : INFINITY, pb.conv_tol = tol, pb.discount = discount;
    pb.scheme = scheme_ids[scheme], pb.order = scheme == 0 ? 1 : scheme == 1 ? 2 : 3;
    /* Memory first: the checks below visit every node, minutes on a grid
     * whose solve cannot fit (200^4 nodes) before the solver refused it. */
    if (hj_reach_check_memory(&pb, 1, &err)) hj_cli_fail(prog, HJ_EXIT_USAGE, "%s: coarsen --N", err.msg);
    check_sets(&g, &st, obstacle_s != NULL, sys == 3);
    /* The run's length before it starts: a horizon far beyond the CFL step
     * (a long horizon, or a tiny period or spacing) would run for ever. */
    int dlim;
    const double dt = cfl_step(&g, &s, pb.factor_cfl, discount, &dlim);
    if (horizon > 0 && isfinite(dt) && horizon / dt > (double)max_steps && dlim < 0)
        hj_cli_fail(prog, HJ_EXIT_USAGE,
                    "--horizon %g needs about %.3g time steps (CFL step %.3g, limited by --discount %g), more than "
                    "--max-steps %ld: shorten the horizon, lower the discount or raise --max-steps",
                    horizon, ceil(horizon / dt), dt, discount, max_steps);
    if (horizon > 0 && isfinite(dt) && horizon / dt > (double)max_steps)
        hj_cli_fail(prog, HJ_EXIT_USAGE,
                    "--horizon %g needs about %.3g time steps (CFL step %.3g, limited by dimension %d of spacing %.3g), "
                    "more than --max-steps %ld: shorten the horizon, coarsen dimension %d or raise --max-steps",
                    horizon, ceil(horizon / dt), dt, dlim + 1, g.dx[dlim], max_steps, dlim + 1);
    /* Until converged: at most max_steps steps of that size. */
    if (horizon == 0 && isfinite(dt)) pb.horizon = (double)max_steps * dt;
    double *phi = hj_ls_alloc(&g), *ttr = hj_ls_alloc(&g);
    if (!phi || !ttr) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory for a %zu-node grid", g.nodes);
    const int tty = isatty(STDERR_FILENO), show = !quiet && (tty || force_progress);
    progress pr = {tty, horizon == 0, now(), now(), max_steps};
    if (show) {
        fprintf(stderr, "%s: %s on %zu nodes, horizon %g\n", prog, systems[sys], g.nodes, horizon);
        pb.progress = show_progress, pb.progress_ctx = &pr;
    }
    hj_reach_stats stats = {0}; /* read for the last progress line even when the solve failed early */
    const int rc = hj_reach_solve(&pb, phi, ttr, &stats, &err);
    if (show) progress_line(&pr, stats.tau, pb.horizon, stats.steps, 1);
    if (rc) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    if (horizon == 0 && !stats.converged)
        hj_cli_fail(prog, HJ_EXIT_RUN, "not converged (--tol %g) after %ld step%s, tau = %g: --max-steps %ld reached",
                    tol, stats.steps, hj_plural(stats.steps), stats.tau, max_steps);
    write_fields(out_dir, &g, phi, ttr);
    double m = NAN;
    if (dim <= 3 && hj_reach_measure(&g, phi, &m, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    printf("%s: %s, %ld step%s, tau = %g%s", prog, systems[sys], stats.steps, hj_plural(stats.steps), stats.tau,
           stats.converged ? " (converged)" : "");
    if (dim <= 3) printf(", measure of the set %.6g\n", m);
    else printf(", measure of the set not computed (%d-D; hj_reach_measure covers 1 to 3)\n", dim);
    hj_ls_free(phi), hj_ls_free(ttr);
    return 0;
}
