/*
# maskDemo: constraints on phi through PostTimestep (section 2.2.3, Figure 7)

**What it shows.** The constraint (11) phi(x, t) >= psi(x) keeps the evolving
set {phi < 0} out of a forbidden set S, where psi is an implicit surface
function of the complement of S (psi < 0 outside S, > 0 inside).  The
constraint is not a term of the PDE: it is applied after every time step
through the integrator's `PostTimestep` option (`hj_ls_ode_opts.post`),
which here also records min_t phi(x, t), as the toolbox's `maskAndKeepMin`
does (the post-timestep function calls the kernel's `hj_ls_post_mask`,
the toolbox's `postTimestepMask`, then updates the running minimum).  The
motion is convection, D_t phi + v . grad phi = 0, by `termConvection`.

**Parameters** (the document gives none but the small circle at the origin
of Figure 7(b) and a constant flow to the right that cuts the set in half,
Figure 7(a); the rest is our choice).  Grid [-1, 1]^2, dx = 1/50,
extrapolation boundaries; the set: the circle of radius 0.35 centred at
(-0.6, 0); S: the disc of radius 0.2 at the origin, psi = 0.2 - |x|;
v = (2, 0) (convectionDemo's constant field); t in [0, 0.6] with nine
output times, so the circle ends centred at (0.6, 0), clear of S.
`--accuracy` as convectionDemo (default `low`).  The mask is also applied
to phi_0 (a no-op here, the circle being clear of S).

**Exact solution.** A point x is in the set at time t when x - v t is in
the initial disc and the segment from x - v t to x misses S.  At t = 0.6
every point of the final disc with |x_2| < 0.2 has passed through S, so the
set is the disc of radius r = 0.35 at (0.6, 0) minus the strip |x_2| < 0.2:
two pieces of total area pi r^2 - 2 (a sqrt(r^2 - a^2) + r^2 asin(a / r)),
a = 0.2, that is 0.1209337.  The union over time, {min_t phi < 0}, is the
stadium swept by the disc (area 1.2 * 0.7 + pi r^2 = 1.2248451) minus what
lies in the strip |x_2| < 0.2 downstream of S's upstream edge
x_1 = -sqrt(0.04 - x_2^2): 0.24 + 0.1319557 + 0.0628319 = 0.4347876, leaving
0.7900575.

**Figure.** fig07.png: (a) the zero level set at the nine output times over
the masked disc; (b) the masked disc (psi = 0) and min_t phi (colour, with
its zero level set), recorded by the post-timestep function.

**Check** (mask.tsv against published/mask.tsv), for each accuracy:
- `area_final`, `area_min`: areas of {phi(0.6) < 0} and {min_t phi < 0}
  (`hj_ls_measure`) against the exact 0.1209337 and 0.7900575 (kind value;
  the sharp corners that the mask cuts are smeared by the scheme, most by
  `low`);
- `pieces`: connected components of {phi(0.6) < 0} (4-neighbour flood fill
  of the negative nodes): 2, the set cut in half (kind count);
- `in_S`: nodes of S with phi <= 0 after any step (kind error, reference 0:
  a mask applied with the wrong sense, or not applied, breaks it);
- `diff_min`: max |recorded min - independent min| (and of the two final
  states, and infinite if the step counts differ), the independent min
  taken by a second run stepped one CFL step at a time (SingleStep) with
  the kernel's `hj_ls_post_mask` as PostTimestep and the minimum taken in
  the calling loop; reference 0 (kind error: bitwise or round-off).

**Outputs.** mask.tsv, mask_summary.tsv (the same runs in full precision
with the areas' changes, which notes/mask_notes.md presents), mask_seq.dat
(x y phi psi at the nine output times, gnuplot index blocks; `low`, the
default), mask_min.dat (x y psi min_t phi phi(0.6)).  With --accuracy: one
run, mask_run.tsv, mask_run_seq.dat, mask_run_min.dat.
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
#include "hj_ls_accuracy.h"
#include "hj_ls_seq.h"
#include "p2_cli.h"
#include "p2_convection.h"

static const char *const PROG = "mask_demo";
static const double TMAX = 0.6;
static const double AREA_FINAL = 0.1209337, AREA_MIN = 0.7900575; /* exact, see the comment above */
enum { NT = P2_NT };

/* maskAndKeepMin: the constraint phi >= psi, then the running minimum. */
typedef struct {
    hj_ls_mask mask;
    double *min;
    long in_s; /* nodes of S with phi <= 0 after a step, summed over steps */
} keep_min;

static void update_min(const hj_ls_grid *g, const double *y, const double *psi, double *min, long *in_s)
{
    long idx[HJ_LS_MAXDIM];
    for (size_t r = 0; r < g->rows; r++) {
        const size_t k = hj_ls_row(g, r, idx);
        for (long j = 0; j < g->N[0]; j++) {
            const size_t q = k + (size_t)j;
            min[q] = y[q] < min[q] ? y[q] : min[q];
            *in_s += psi[q] > 0 && y[q] <= 0;
        }
    }
}

static int mask_and_keep_min(double t, double *y, void *ctx, hj_error *err)
{
    keep_min *m = ctx;
    int rc = hj_ls_post_mask(t, y, &m->mask, err);
    if (!rc) update_min(m->mask.grid, y, m->mask.mask, m->min, &m->in_s);
    return rc;
}

/* Connected components of {phi < 0} (4 neighbours). */
static long pieces(const hj_ls_grid *g, const double *phi)
{
    const long nx = g->N[0], ny = g->N[1];
    int *lab = calloc((size_t)(nx * ny), sizeof *lab);
    long *stack = malloc(sizeof(long) * (size_t)(nx * ny));
    if (!lab || !stack) hj_cli_fail(PROG, HJ_EXIT_RUN, "out of memory");
    long count = 0;
    for (long s = 0; s < nx * ny; s++) {
        const long si[2] = {s % nx, s / nx};
        if (lab[s] || !(phi[hj_ls_index(g, si)] < 0)) continue;
        count++;
        long top = 0;
        stack[top++] = s, lab[s] = 1;
        while (top) {
            const long p = stack[--top], a = p % nx, b = p / nx;
            const long nb[4][2] = {{a - 1, b}, {a + 1, b}, {a, b - 1}, {a, b + 1}};
            for (int e = 0; e < 4; e++) {
                if (nb[e][0] < 0 || nb[e][0] >= nx || nb[e][1] < 0 || nb[e][1] >= ny) continue;
                const long q = nb[e][1] * nx + nb[e][0];
                if (!lab[q] && phi[hj_ls_index(g, nb[e])] < 0) lab[q] = 1, stack[top++] = q;
            }
        }
    }
    free(lab), free(stack);
    return count;
}

typedef struct {
    double area_final, area_min, diff_min;
    long pieces, in_s, steps;
} result;

static void run(int acc, const char *seq_path, const char *min_path, result *res)
{
    hj_error err;
    hj_ls_grid g;
    const double lo[2] = {-1, -1}, hi[2] = {1, 1}, c0[2] = {-0.6, 0}, o[2] = {0, 0};
    const long n[2] = {101, 101};
    const hj_ls_bc bc[2] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
    p2_fail_if(PROG, hj_ls_grid_init(&g, 2, lo, hi, n, bc, &err), &err);
    double *y = hj_ls_alloc(&g), *psi = hj_ls_alloc(&g), *min = hj_ls_alloc(&g), *y2 = hj_ls_alloc(&g),
           *min2 = hj_ls_alloc(&g);
    if (!y || !psi || !min || !y2 || !min2) hj_cli_fail(PROG, HJ_EXIT_RUN, "out of memory");
    p2_fail_if(PROG, hj_ls_shape_sphere(&g, c0, 0.35, y, &err), &err);
    p2_fail_if(PROG, hj_ls_shape_sphere(&g, o, 0.2, psi, &err), &err);
    hj_ls_shape_complement(&g, psi, psi); /* psi = 0.2 - |x|: the complement of S */
    keep_min km = {{&g, psi, 1}, min, 0};
    p2_fail_if(PROG, hj_ls_post_mask(0, y, &km.mask, &err), &err);
    hj_ls_copy(&g, min, y);
    hj_ls_copy(&g, y2, y);
    hj_ls_copy(&g, min2, y);

    p2_flow flow = {0, 0, 2};
    hj_ls_convection term;
    hj_ls_convection_init(&term, &g, hj_ls_accuracy_scheme(acc));
    term.velocity_fn = p2_flow_velocity;
    term.ctx = &flow;
    hj_ls_seq seq;
    hj_ls_seq_init(&seq, NULL, &g, "phi", 10);
    seq.nextra = 1, seq.extra_name[0] = "psi", seq.extra[0] = psi;
    hj_ls_ode_opts opts;
    hj_ls_ode_defaults(&opts);
    opts.post = mask_and_keep_min, opts.post_ctx = &km;
    hj_ls_ode_stats st;
    if (p2_solve(seq_path, acc, &g, &term.base, TMAX, y, &opts, &seq, &st, &err))
        hj_cli_fail(PROG, HJ_EXIT_RUN, "%s: %s", hj_ls_accuracy_name(acc), err.msg);

    /* The independent minimum: one CFL step per call, the kernel's mask as
     * PostTimestep, the minimum taken here. */
    double tspan[NT];
    hj_ls_seq_times(0, TMAX, NT, tspan);
    hj_ls_mask plain = {&g, psi, 1};
    opts.post = hj_ls_post_mask, opts.post_ctx = &plain, opts.single_step = 1;
    double t = 0;
    long steps2 = 0, dummy = 0;
    for (int k = 1; k < NT; k++)
        while (tspan[k] - t > 1e-12) {
            const double span[2] = {t, tspan[k]};
            hj_ls_ode_stats s2;
            p2_fail_if(PROG,
                       hj_ls_ode(hj_ls_accuracy_order(acc), &g, &term.base, span, 2, y2, &opts, NULL, NULL, &s2, &err),
                       &err);
            t = s2.t, steps2++;
            update_min(&g, y2, psi, min2, &dummy);
        }
    double dmin, dy, avg;
    hj_ls_norms(&g, min, min2, &dmin, &avg, NULL);
    hj_ls_norms(&g, y, y2, &dy, &avg, NULL);
    res->diff_min = dmin > dy ? dmin : dy;
    if (steps2 != st.steps) res->diff_min = INFINITY; /* not the same steps: not independent of the schedule */
    p2_fail_if(PROG, hj_ls_measure(&g, y, &res->area_final, &err), &err);
    p2_fail_if(PROG, hj_ls_measure(&g, min, &res->area_min, &err), &err);
    res->pieces = pieces(&g, y);
    res->in_s = km.in_s;
    res->steps = st.steps;
    if (min_path) {
        const char *names[3] = {"psi", "min_phi", "phi_final"};
        const double *f[3] = {psi, min, y};
        p2_fail_if(PROG, hj_ls_write_dat(min_path, &g, 3, names, f, &err), &err);
    }
    hj_ls_free(y), hj_ls_free(psi), hj_ls_free(min), hj_ls_free(y2), hj_ls_free(min2);
}

static const char *const SUMMARY = "maskDemo of Mitchell's toolbox (section 2.2.3, Figure 7).";
static const char *const EPILOG =
    "Without --accuracy: every accuracy, the figure's data (low), mask.tsv and mask_summary.tsv; with\n"
    "it: one run, mask_run.tsv, mask_run_seq.dat and mask_run_min.dat.  See the comment at the top of\n"
    "mask_demo.c.\n";

int main(int argc, char **argv)
{
    int acc = HJ_LS_ACC_LOW, quick = 0; /* --quick: the same set */
    const char *dir = ".";
    hj_error err;
    hj_cli_opt opts[] = {
        p2_opt_accuracy(&acc),
        p2_opt_out_dir(&dir),
        p2_opt_quick(&quick, "the same set (it takes a second)"),
    };
    const int single =
        p2_parse_runs(PROG, SUMMARY, EPILOG, opts, (int)(sizeof opts / sizeof opts[0]), 1, argc, argv, &dir);
    char path[4096], seq[4096], mn[4096];
    hj_out tab, sum;
    snprintf(path, sizeof path, "%s/%s", dir, single ? "mask_run.tsv" : "mask.tsv");
    p2_fail_if(PROG, hj_out_open(&tab, path, &err), &err);
    fprintf(tab.fp, "# maskDemo: circle convected through the masked disc, t = %g\n"
                    "acc\tarea_final\tarea_min\tpieces\tin_S\tdiff_min\tsteps\n", TMAX);
    if (!single) {
        /* The numbers of the report's note (notes/mask_notes.md), one row per accuracy. */
        p2_fail_if(PROG, p2_open(&sum, dir, "mask_summary.tsv", &err), &err);
        fprintf(sum.fp, "# maskDemo at t = %g: areas of the final set and of {min_t phi < 0} against the exact ones (exact_final,\n"
                        "# exact_min) and their changes in per cent, pieces of the final set, nodes of the masked disc inside the set\n"
                        "# after any step, max difference of the recorded min from an independent single-step run, steps\n"
                        "acc\tarea_final\tchange_final_pct\tarea_min\tchange_min_pct\tpieces\tin_S\tdiff_min\tsteps\t"
                        "exact_final\texact_min\n", TMAX);
    }
    for (int a = 0; a < HJ_LS_NACC; a++) {
        if (single && a != acc) continue;
        snprintf(seq, sizeof seq, "%s/%s", dir, single ? "mask_run_seq.dat" : "mask_seq.dat");
        snprintf(mn, sizeof mn, "%s/%s", dir, single ? "mask_run_min.dat" : "mask_min.dat");
        result r;
        run(a, single || a == HJ_LS_ACC_LOW ? seq : NULL, single || a == HJ_LS_ACC_LOW ? mn : NULL, &r);
        fprintf(tab.fp, "%s\t%.6g\t%.6g\t%ld\t%ld\t%.4e\t%ld\n", hj_ls_accuracy_name(a), r.area_final, r.area_min,
                r.pieces, r.in_s, r.diff_min, r.steps);
        if (!single)
            fprintf(sum.fp, "%s\t%.17g\t%.17g\t%.17g\t%.17g\t%ld\t%ld\t%.17g\t%ld\t%.17g\t%.17g\n",
                    hj_ls_accuracy_name(a), r.area_final, 100 * (r.area_final / AREA_FINAL - 1), r.area_min,
                    100 * (r.area_min / AREA_MIN - 1), r.pieces, r.in_s, r.diff_min, r.steps, AREA_FINAL, AREA_MIN);
    }
    p2_fail_if(PROG, hj_out_commit(&tab, &err), &err);
    if (!single) p2_fail_if(PROG, hj_out_commit(&sum, &err), &err);
    return 0;
}
