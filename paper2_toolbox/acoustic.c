/*
# acoustic: the acoustic capture game (Figure 18)

**Problem.** Section 2.6.2, the toolbox's `acoustic`: the acoustic
capture game (a homicidal chauffeur variant), in relative coordinates z =
(x, y) with the pursuer at the origin,

    dz/dt = W_p (0, -1) + (W_p / R) (y, -x) b + 2 W_e min(|z|, S) a   (24),

|a| <= 1 (evader, a vector: avoids), |b| <= 1 (pursuer: captures).  The
Hamiltonian of the text, H = -p2 W_p - (W_p / R) |p1 y - p2 x| + |p| 2 W_e
min(|z|, S), times -1, in `termLaxFriedrichs` with the text's partial
bounds alpha_1 = (W_p / R) |y| + 2 W_e min(|z|, S), alpha_2 = W_p + (W_p /
R) |x| + 2 W_e min(|z|, S), inside `termRestrictUpdate` (the set never
shrinks).  Parameters as the text: W_e = 1.3, W_p = 1.5, R = 0.8, S = 0.5.
The released `acoustic.m` uses W_p = 1.0 (its thesis values); we follow
the text, and `--Wp` changes it.

**Where the text is silent** (it only calls the target "a wide but
shallow horizontal rectangle near the origin") we follow `acoustic.m`: the
target [-3.5, 3.5] x [-0.2, 0], the grid [-4, 4] x [-2, 3] with dx = 1/25
(201 x 126 nodes), extrapolation boundaries, t = 4 with output every 0.5
(the toolbox's 3 x 3 subplots), global dissipation, FactorCFL 0.75,
default accuracy medium.  The set-up (parameters, grid, target,
Hamiltonian, partial bounds, the solve) is shared in `p2_acoustic.c`; this
program adds the checks.

**Options.** `--accuracy`, `--diss`, `--dx`, `--Wp`, `--tmax`; any of them:
one run (`acoustic_run.dat`, areas on stdout).

**Figure 18.** The evolution: the zero level set at t = 0, 0.5, ..., 4 on
the toolbox grid, the target in grey.  The hole of the text appears at t
= 1: a closed curve above the target at x = 0, y from about 0.8 to 1.8,
which nowhere touches the target; by t = 1.5 the set has swallowed it.

**Check** (`acoustic.tsv` against `published/acoustic.tsv`), accuracy
medium, on dx = 0.08, 0.04, 0.02 (quick: the first two), at every output
time:
- the area of the set (second order measure): no exact value; reference
  our own run, and the note (`notes/acoustic_notes.md`, from
  `acoustic_summary.tsv`) shows the convergence;
- `increased` must be 0 (restricted update);
- holes: the components of {phi >= 0} that are enclosed by the set (do
  not reach the box boundary) and lie more than 1.5 dx from the target
  (an enclosed pocket against the target, as below it at late times, is
  not a hole in the text's sense): their number, area and distance
  (min phi_0) to the target.  The text's claim is checked as: at t = 1
  there is exactly one hole and its distance to the target is positive
  (about 0.8, many cells) on every grid;
- the game is symmetric under x -> -x (with a_x -> -a_x, b -> -b) and so
  is the target: `flips`, the nodes whose membership of the set differs
  from their mirror node's, must be 0; `asym` = max |phi(x, y) - phi(-x,
  y)| is shown (round-off).  The callbacks and the target use x = (i -
  (N - 1)/2) dx, exactly antisymmetric; with the grid's min + i dx the
  rounding seeded an asymmetry that grew to 3e-8 by t = 4 on dx = 0.02.

**Result** (full run, the note): the area at t = 4 is 35.77,
35.63, 35.70 on dx = 0.08, 0.04, 0.02 (at t = 1: 21.70, 22.65, 23.11, still
moving by 2 %: the fronts are not yet resolved there).  At t = 1 each grid
has exactly one hole, 0.84 from the target (0.80 on dx = 0.08); its area
shrinks under refinement, 0.35, 0.20, 0.15 (differences 0.15, 0.06: a thin
sliver whose area converges to about 0.1 if the ratio of the differences
holds), so the hole is a feature of the solution, not of one grid.  No node
increased; no node changed membership under the mirror (largest |phi -
mirror| 3e-12).

**Outputs.** `acoustic.tsv`, `acoustic_2d.dat` (9 index blocks, dx =
1/25), `acoustic_summary.tsv` (per output time: the areas and holes on
every grid and the mirror check, which `notes/acoustic_notes.md`
presents); plotted by `plot/fig18.gp`.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hj_cli.h"
#include "hj_io.h"
#include "hj_ls_io.h"
#include "hj_ls_ode.h"
#include "hj_ls_accuracy.h"
#include "hj_ls_seq.h"
#include "p2_acoustic.h"
#include "p2_cli.h"
#include "p2_reach.h"

static const char *prog = "acoustic";

/* Holes: connected components (4-neighbours) of {phi >= 0} that do not
 * reach the grid's boundary.  A component with a node within 1.5 dx of the
 * target ({phi0 < 1.5 dx}) is a pocket against the target, not a hole in
 * the sense of section 2.6.2; the others are counted: their number, total
 * area and the smallest phi0 (distance to the target) over their nodes. */
typedef struct {
    long n;
    double area, gap;
} hole_stat;

static hole_stat holes(const hj_ls_grid *g, const double *phi, const double *phi0)
{
    const long nx = g->N[0], ny = g->N[1];
    long *label = calloc((size_t)(nx * ny), sizeof(long)), *stack = malloc(sizeof(long) * (size_t)(nx * ny));
    if (!label || !stack) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory");
    hole_stat h = {0, 0, INFINITY};
    long next = 1;
    for (long s = 0; s < nx * ny; s++) {
        if (label[s] || phi[hj_ls_index(g, (long[2]){s % nx, s / nx})] < 0) continue;
        long top = 0, count = 0;
        int boundary = 0;
        double gap = INFINITY;
        label[s] = next;
        stack[top++] = s;
        while (top) {
            const long c = stack[--top], i = c % nx, j = c / nx;
            count++;
            boundary |= i == 0 || j == 0 || i == nx - 1 || j == ny - 1;
            const double v = phi0[hj_ls_index(g, (long[2]){i, j})];
            gap = v < gap ? v : gap;
            const long ni[4] = {i - 1, i + 1, i, i}, nj[4] = {j, j, j - 1, j + 1};
            for (int k = 0; k < 4; k++) {
                if (ni[k] < 0 || ni[k] >= nx || nj[k] < 0 || nj[k] >= ny) continue;
                const long q = nj[k] * nx + ni[k];
                if (!label[q] && phi[hj_ls_index(g, (long[2]){ni[k], nj[k]})] >= 0) {
                    label[q] = next;
                    stack[top++] = q;
                }
            }
        }
        next++;
        if (!boundary && gap > 1.5 * g->dx[0]) {
            h.n++;
            h.area += (double)count * g->dx[0] * g->dx[1];
            h.gap = gap < h.gap ? gap : h.gap;
        }
    }
    free(label);
    free(stack);
    if (!h.n) h.gap = NAN;
    return h;
}

typedef struct {
    const hj_ls_grid *g;
    const double *phi0;
    hole_stat hole[P2_MAXT];
    double asym[P2_MAXT];
    long flips[P2_MAXT];
    hj_ls_seq *blocks;
} snap;

static int on_snapshot(int k, double t, const double *y, void *ctx, hj_error *err)
{
    snap *s = ctx;
    if (k < P2_MAXT) {
        s->hole[k] = holes(s->g, y, s->phi0);
        s->asym[k] = p2_acoustic_asymmetry(s->g, y, &s->flips[k]);
    }
    return s->blocks ? hj_ls_seq_output(k, t, y, s->blocks, err) : HJ_OK;
}

typedef struct {
    double dx;
    p2_reach_log log;
    snap sn;
    hj_ls_ode_stats st;
} result;

static void run(const p2_acoustic_par *q, int acc, int diss, double dx, double tmax, const char *path, result *r)
{
    hj_error err;
    hj_ls_grid g;
    p2_fail_if(prog, p2_acoustic_grid(dx, &g, &err), &err);
    double *y = hj_ls_alloc(&g), *y0 = hj_ls_alloc(&g);
    if (!y || !y0) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory");
    p2_fail_if(prog, p2_acoustic_target(&g, y, &err), &err);
    hj_ls_copy(&g, y0, y);
    hj_out out;
    hj_ls_seq b;
    hj_ls_seq_init(&b, NULL, &g, "phi", 0);
    if (path) {
        p2_fail_if(prog, hj_out_open(&out, path, &err), &err);
        b.fp = out.fp;
    }
    r->dx = dx;
    r->sn.g = &g, r->sn.phi0 = y0, r->sn.blocks = path ? &b : NULL;
    p2_fail_if(prog, p2_reach_log_init(&r->log, &g, -1, 0, y, on_snapshot, &r->sn, &err), &err);
    double ts[9];
    hj_ls_seq_times(0, tmax, 9, ts);
    hj_progress("acoustic: accuracy %s, dx = %g ...\n", hj_ls_accuracy_name(acc), dx);
    p2_fail_if(prog, p2_acoustic_solve(&g, q, acc, diss, ts, 9, y, p2_reach_output, &r->log, &r->st, &err), &err);
    if (path) p2_fail_if(prog, hj_out_commit(&out, &err), &err);
    p2_reach_log_free(&r->log);
    r->sn.g = NULL, r->sn.phi0 = NULL, r->sn.blocks = NULL;
    hj_ls_free(y);
    hj_ls_free(y0);
}

static const char *summary = "The acoustic capture game of Mitchell's toolbox (section 2.6.2, Figure 18).";
static const char *epilog =
    "With none of the run options (--accuracy .. --tmax): Figure 18's data and the checks\n"
    "(acoustic.tsv, acoustic_2d.dat, acoustic_summary.tsv).  With any of them: one run, its time\n"
    "sequence in acoustic_run.dat and its areas on stdout.  See the comment at the top of acoustic.c.\n";

int main(int argc, char **argv)
{
    const char *out_dir = ".";
    int quick = 0, acc = HJ_LS_ACC_MEDIUM, diss = HJ_LS_GLF;
    double dx = 0.04, tmax = 4;
    p2_acoustic_par q;
    p2_acoustic_defaults(&q);
    hj_error err;
    /* the run options first: any of them makes one run */
    hj_cli_opt opts[] = {
        p2_opt_accuracy(&acc),
        p2_opt_dissipation("--diss", &diss),
        {.name = "--dx", .type = HJ_OPT_DOUBLE, .value = &dx, .min = 0.002, .max = 0.5, .metavar = "DX",
         .help = "grid spacing (toolbox: 1/25)"},
        {.name = "--Wp", .type = HJ_OPT_DOUBLE, .value = &q.Wp, .min = 0.01, .max = 100, .metavar = "WP",
         .help = "pursuer speed W_p (the text's; acoustic.m: 1)"},
        {.name = "--tmax", .type = HJ_OPT_DOUBLE, .value = &tmax, .min = 1e-9, .max = 100, .metavar = "T",
         .help = "final time, 8 output intervals"},
        p2_opt_out_dir(&out_dir),
        p2_opt_quick(&quick, "the checks on dx = 0.08, 0.04 only"),
    };
    const int single =
        p2_parse_runs(prog, summary, epilog, opts, (int)(sizeof opts / sizeof opts[0]), 5, argc, argv, &out_dir);
    p2_one_thread(); /* 2-D grids of 10^4-10^5 nodes */
    char path[4096];
    static result R[8];
    if (single) {
        snprintf(path, sizeof path, "%s/acoustic_run.dat", out_dir);
        run(&q, acc, diss, dx, tmax, path, &R[0]);
        printf("# acoustic accuracy=%s diss=%s dx=%g Wp=%g: %ld steps\n# t\tarea\tincreased\tholes\thole_area\thole_gap\tasym\tflips\n",
               hj_ls_accuracy_name(acc), hj_ls_dissipation_name(diss), dx, q.Wp, R[0].st.steps);
        for (int k = 0; k < R[0].log.n; k++)
            printf("%.4g\t%.6g\t%ld\t%ld\t%.4g\t%.3g\t%.3g\t%ld\n", R[0].log.t[k], R[0].log.measure[k],
                   R[0].log.increased[k], R[0].sn.hole[k].n, R[0].sn.hole[k].area, R[0].sn.hole[k].gap, R[0].sn.asym[k],
                   R[0].sn.flips[k]);
        return 0;
    }
    /* Figure 18: the time sequence on the toolbox grid (dx = 1/25); the
     * grid sequence dx = 0.08, 0.04, 0.02 (quick: 0.08, 0.04). */
    static const double dxs[] = {0.08, 0.04, 0.02};
    const int nd = quick ? 2 : 3;
    for (int k = 0; k < nd; k++) {
        snprintf(path, sizeof path, "%s/acoustic_2d.dat", out_dir);
        run(&q, acc, diss, dxs[k], tmax, k == 1 ? path : NULL, &R[k]);
    }
    hj_out out;
    p2_fail_if(prog, p2_open(&out, out_dir, "acoustic.tsv", &err), &err);
    fprintf(out.fp, "# acoustic capture, accuracy medium: area of the reachable set, nodes where phi increased since the\n"
                    "# previous output, holes = enclosed components of the complement not touching the target (their\n"
                    "# number, area, distance to the target), asym = max |phi(x,y) - phi(-x,y)|, flips = nodes whose\n"
                    "# membership of the set differs from their mirror node's\n"
                    "dx\tt\tarea\tincreased\tholes\thole_area\thole_gap\tasym\tflips\n");
    for (int k = 0; k < nd; k++)
        for (int m = 0; m < R[k].log.n; m++) {
            const hole_stat *h = &R[k].sn.hole[m];
            fprintf(out.fp, "%.2f\t%.1f\t%.6g\t%ld\t%ld\t%.4g\t", dxs[k], R[k].log.t[m], R[k].log.measure[m],
                    R[k].log.increased[m], h->n, h->area);
            if (h->n) fprintf(out.fp, "%.3g\t", h->gap); else fputs("-\t", out.fp);
            fprintf(out.fp, "%.3e\t%ld\n", R[k].sn.asym[m], R[k].sn.flips[m]);
        }
    /* The numbers of the report's note (notes/acoustic_notes.md), one row per output time. */
    p2_next_file(prog, &out, out_dir, "acoustic_summary.tsv");
    fprintf(out.fp, "# acoustic capture, accuracy %s, per output time: area of the reachable set and of its holes on each grid\n"
                    "# (- where the grid is not run: --quick); hole_gap = the holes' distance to the target on the finest grid\n"
                    "# run (- without a hole); over all grids: nodes where phi increased since the previous output and nodes\n"
                    "# whose membership of the set differs from their mirror node's (summed), the largest |phi(x,y) - phi(-x,y)|\n"
                    "t", hj_ls_accuracy_name(acc));
    for (int k = 0; k < 3; k++) fprintf(out.fp, "\tarea_%g", dxs[k]);
    for (int k = 0; k < 3; k++) fprintf(out.fp, "\thole_area_%g", dxs[k]);
    fputs("\thole_gap\tincreased\tflips\tasym\n", out.fp);
    for (int m = 0; m < R[0].log.n; m++) {
        fprintf(out.fp, "%.17g", R[0].log.t[m]);
        for (int k = 0; k < 3; k++)
            if (k < nd) fprintf(out.fp, "\t%.17g", R[k].log.measure[m]); else fputs("\t-", out.fp);
        for (int k = 0; k < 3; k++)
            if (k < nd) fprintf(out.fp, "\t%.17g", R[k].sn.hole[m].area); else fputs("\t-", out.fp);
        const hole_stat *h = &R[nd - 1].sn.hole[m];
        if (h->n) fprintf(out.fp, "\t%.17g", h->gap); else fputs("\t-", out.fp);
        long inc = 0, flips = 0;
        double asym = 0;
        for (int k = 0; k < nd; k++) {
            inc += R[k].log.increased[m];
            flips += R[k].sn.flips[m];
            asym = R[k].sn.asym[m] > asym ? R[k].sn.asym[m] : asym;
        }
        fprintf(out.fp, "\t%ld\t%ld\t%.17g\n", inc, flips, asym);
    }
    p2_fail_if(prog, hj_out_commit(&out, &err), &err);
    return 0;
}
