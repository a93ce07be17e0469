/*
# air3D: the game of two identical vehicles (Figure 17)

**Problem.** Section 2.6.1, the toolbox's `air3D`: the game of two
identical vehicles (Figure 16 of the text is a diagram of the relative
coordinates, not a computed result; it is not reproduced).  In relative
coordinates x = (x, y, psi), the evader at the origin facing +x,

    dx/dt = -v_a + v_b cos psi + a y,   dy/dt = v_b sin psi - a x,   dpsi/dt = b - a   (23)

with the evader's turn rate |a| <= A (control, avoids collision) and the
pursuer's |b| <= B (disturbance).  The target (collision) set is the
cylinder x^2 + y^2 <= r^2; the backward reachable set solves (17)-(18),
written as an initial value problem: the Hamiltonian of section 2.6.1,

    H(x, p) = -v_a p1 + v_b (p1 cos psi + p2 sin psi) + A |y p1 - x p2 - p3| - B |p3|,

multiplied by -1, in `termLaxFriedrichs` with the partial bounds of the
text (from (22)): alpha_1 = |-v_a + v_b cos psi| + A |y|, alpha_2 = |v_b
sin psi| + A |x|, alpha_3 = A + B; wrapped in `termRestrictUpdate`
(positive = 0: phi never increases, so the set never shrinks).
Parameters as the text: r = 5, v_a = v_b = 5, A = B = 1, t = 2.8.

**Where the text is silent** we follow the released `air3D.m`: the grid
[-6, 20] x [-10, 10] x [0, 2 pi) with N = (NX, ceil(NX 20/26), NX - 1) =
51 x 40 x 50 nodes for NX = 51, linear extrapolation in x and y, periodic
in psi; FactorCFL 0.75; global Lax-Friedrichs dissipation; output every
2.8 / 8.  The set-up is shared with the benchmark (`p2_air3d.c`).  The
callbacks read cos psi, sin psi and y from tables that are exactly
mirror-symmetric, and the target's y coordinates are taken as (j - (N_y -
1)/2) dy, so that rounding of the coordinates does not break the game's
symmetry (see the check).

**Options.** `--accuracy` (default medium, as `air3D(accuracy)`),
`--diss`, `--N` (NX), `--tmax`; any of them: one run written to
`air3d_run.vtk` with its volumes on stdout.

**Figure 17.** (a) the target cylinder, (b) the reachable set at t = 2.8
computed with accuracy medium on the toolbox grid, as isosurfaces phi = 0
on gnuplot voxel grids (the fields resampled trilinearly on a 51^3
lattice, `air3d_vox.dat`); both fields also as legacy VTK (`air3d.vtk`).

**Check** (`air3d.tsv` against `published/air3d.tsv`), for accuracies
medium and low on NX = 26, 38, 51, 76 (quick: 26), at the 9 output times:
- the volume of {phi < 0} in the (x, y, psi) box (second order measure,
  `hj_ls_measure`, the periodic psi direction closed): it must converge
  under refinement; there is no exact value, so the reference is our own
  run and the note (`notes/air3d_notes.md`, from `air3d_summary.tsv`)
  shows the sequence and its differences;
- `increased`: nodes where phi grew since the previous output time; the
  restricted update makes every RK stage non-increasing, so this must be
  0 (exact);
- the game is symmetric under (y, psi, a, b) -> (-y, -psi, -a, -b), so
  the reachable set must be too: `flips`, the nodes whose membership of
  the set differs from their mirror node's, must be 0; `asym`, max
  |phi(x, y, psi) - phi(x, -y, -psi)|, is shown: exactly 0 for low (the
  first order scheme is mirror-exact), round-off growing to about 1e-10
  for medium (ENO2's stencil arithmetic is not mirror-exact).

**Result** (full run, the note): at t = 2.8 the volume is 873.6,
880.1, 882.5, 884.3 for medium on NX = 26, 38, 51, 76 (changes 6.5, 2.4,
1.8) and 760.9, 805.3, 828.8, 850.0 for low (changes 44, 24, 21: first
order and slow: the low scheme's larger dissipation gives a smaller set,
13 % below medium at NX = 26, 4 % at NX = 76); the
target's volume is 25 pi * 2 pi = 493.5.  No node increased; no node
changed membership under the reflection (largest |phi - mirror| 1.3e-10
medium, 0 low).

**Outputs.** `air3d.tsv`, `air3d_summary.tsv` (per grid: the final
volumes, their changes and the mirror check, which `notes/air3d_notes.md`
presents), `air3d.vtk` (target and reachable set, medium, NX = 51; quick:
26), `air3d_vox.dat`; plotted by `plot/fig17.gp`.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hj_cli.h"
#include "hj_io.h"
#include "hj_ls_io.h"
#include "hj_ls_term.h"
#include "p2_air3d.h"
#include "hj_ls_accuracy.h"
#include "hj_ls_seq.h"
#include "p2_cli.h"
#include "p2_reach.h"
#include "hj_math.h"

static const char *prog = "air3d";

/* Asymmetry at every output time (snapshot callback of the reach log). */
typedef struct {
    const hj_ls_grid *g;
    double asym[P2_MAXT];
    long flips[P2_MAXT];
} snap;

static int on_snapshot(int k, double t, const double *y, void *ctx, hj_error *err)
{
    (void)t, (void)err;
    snap *s = ctx;
    if (k < P2_MAXT) s->asym[k] = p2_air3d_asymmetry(s->g, y, &s->flips[k]);
    return HJ_OK;
}

typedef struct {
    int acc;
    long Nx;
    int nint;
    double tmax;
    p2_reach_log log;
    snap sn;
    hj_ls_ode_stats st;
    double seconds;
} result;

/* One run; *phi0 and *phi (may be NULL) receive the target and the final set. */
static void run(const p2_air3d_par *p, int acc, int diss, long Nx, double tmax, int nint, hj_ls_grid *g, result *r,
                double **phi0, double **phi)
{
    hj_error err;
    p2_fail_if(prog, p2_air3d_grid(Nx, g, &err), &err);
    double *y = hj_ls_alloc(g), *y0 = hj_ls_alloc(g);
    if (!y || !y0) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory for NX = %ld", Nx);
    p2_fail_if(prog, p2_air3d_target(g, p, y, &err), &err);
    hj_ls_copy(g, y0, y);
    r->acc = acc, r->Nx = Nx, r->nint = nint, r->tmax = tmax;
    r->sn.g = g;
    p2_fail_if(prog, p2_reach_log_init(&r->log, g, 2, 0, y, on_snapshot, &r->sn, &err), &err);
    double ts[P2_MAXT];
    hj_ls_seq_times(0, tmax, nint + 1, ts);
    hj_progress("air3d: accuracy %s, NX = %ld ...\n", hj_ls_accuracy_name(acc), Nx);
    p2_fail_if(prog, p2_air3d_solve(g, p, acc, diss, ts, nint + 1, y, p2_reach_output, &r->log, &r->st, &err), &err);
    p2_reach_log_free(&r->log);
    if (phi0) *phi0 = y0; else hj_ls_free(y0);
    if (phi) *phi = y; else hj_ls_free(y);
}

static const char *summary = "The game of two identical vehicles of Mitchell's toolbox (section 2.6.1, Figure 17).";
static const char *epilog =
    "With none of the run options (--accuracy .. --tmax): Figure 17's data and the checks\n"
    "(air3d.tsv, air3d.vtk, air3d_vox.dat, air3d_summary.tsv).  With any of them: one run written to\n"
    "air3d_run.vtk, its volumes on stdout.  See the comment at the top of air3d.c.\n";

int main(int argc, char **argv)
{
    const char *out_dir = ".";
    int quick = 0, acc = HJ_LS_ACC_MEDIUM, diss = HJ_LS_GLF;
    long Nx = 51;
    double tmax = 2.8;
    hj_error err;
    /* the run options first: any of them makes one run */
    hj_cli_opt opts[] = {
        p2_opt_accuracy(&acc),
        p2_opt_dissipation("--diss", &diss),
        {.name = "--N", .type = HJ_OPT_LONG, .value = &Nx, .min = 8, .max = 2000, .metavar = "NX",
         .help = "nodes in x (air3D.m's grid)"},
        {.name = "--tmax", .type = HJ_OPT_DOUBLE, .value = &tmax, .min = 1e-9, .max = 1000, .metavar = "T",
         .help = "final time, 8 output intervals"},
        p2_opt_out_dir(&out_dir),
        p2_opt_quick(&quick, "the checks on NX = 26 only"),
    };
    const int single =
        p2_parse_runs(prog, summary, epilog, opts, (int)(sizeof opts / sizeof opts[0]), 4, argc, argv, &out_dir);
    p2_air3d_par par;
    p2_air3d_defaults(&par);
    char path[4096];
    hj_ls_grid g;
    static result fr;
    double *phi0, *phi;
    if (single) {
        run(&par, acc, diss, Nx, tmax, 8, &g, &fr, &phi0, &phi);
        snprintf(path, sizeof path, "%s/air3d_run.vtk", out_dir);
        const char *names[2] = {"target", "reach"};
        const double *f[2] = {phi0, phi};
        p2_fail_if(prog, hj_ls_write_vtk(path, &g, "air3D reachable set", 2, names, f, &err), &err);
        printf("# air3D accuracy=%s diss=%s NX=%ld: %ld steps\n# t\tvolume\tincreased\tasymmetry\tflips\n",
               hj_ls_accuracy_name(acc), hj_ls_dissipation_name(diss), Nx, fr.st.steps);
        for (int k = 0; k < fr.log.n; k++)
            printf("%.4g\t%.6g\t%ld\t%.3g\t%ld\n", fr.log.t[k], fr.log.measure[k], fr.log.increased[k], fr.sn.asym[k],
                   fr.sn.flips[k]);
        hj_ls_free(phi0);
        hj_ls_free(phi);
        return 0;
    }
    /* The grid sequence at the two cheapest accuracies; the figure from
     * medium on the toolbox grid (NX = 51; the quick run: NX = 26). */
    static const long seq[] = {26, 38, 51, 76};
    const int nseq = quick ? 1 : 4, accs[2] = {HJ_LS_ACC_MEDIUM, HJ_LS_ACC_LOW};
    static result R[2][4];
    const long fig_nx = quick ? 26 : 51;
    hj_ls_grid gf;
    double *fig0 = NULL, *fig1 = NULL;
    for (int a = 0; a < 2; a++)
        for (int k = 0; k < nseq; k++) {
            const int keep = accs[a] == HJ_LS_ACC_MEDIUM && seq[k] == fig_nx;
            run(&par, accs[a], diss, seq[k], 2.8, 8, keep ? &gf : &g, &R[a][k], keep ? &fig0 : NULL, keep ? &fig1 : NULL);
        }
    snprintf(path, sizeof path, "%s/air3d.vtk", out_dir);
    const char *names[2] = {"target", "reach"};
    const double *f[2] = {fig0, fig1};
    p2_fail_if(
        prog,
        hj_ls_write_vtk(path, &gf, "air3D: target cylinder and reachable set at t = 2.8 (medium)", 2, names, f, &err),
        &err);
    hj_out out;
    p2_fail_if(prog, p2_open(&out, out_dir, "air3d_vox.dat", &err), &err);
    p2_fail_if(prog, hj_ls_write_voxels(out.fp, &gf, 2, f, 51, 2, &err), &err);
    p2_fail_if(prog, hj_out_commit(&out, &err), &err);
    hj_ls_free(fig0);
    hj_ls_free(fig1);

    p2_fail_if(prog, p2_open(&out, out_dir, "air3d.tsv", &err), &err);
    fprintf(out.fp, "# air3D: volume of the reachable set (x, y, psi; second order measure), nodes where phi increased\n"
                    "# since the previous output time, max |phi(x,y,psi) - phi(x,-y,-psi)|, nodes whose membership of the set\n"
                    "# differs from their mirror image's (flips); N = NX, the nodes in x\n"
                    "acc\tN\tt\tvolume\tincreased\tasym\tflips\tsteps\n");
    for (int a = 0; a < 2; a++)
        for (int k = 0; k < nseq; k++) {
            const result *r = &R[a][k];
            for (int q = 0; q < r->log.n; q++)
                fprintf(out.fp, "%s\t%ld\t%.2f\t%.6g\t%ld\t%.3e\t%ld\t%ld\n", hj_ls_accuracy_name(r->acc), r->Nx,
                        r->log.t[q], r->log.measure[q], r->log.increased[q], r->sn.asym[q], r->sn.flips[q], r->st.steps);
        }
    /* The numbers of the report's note (notes/air3d_notes.md), one row per grid. */
    p2_next_file(prog, &out, out_dir, "air3d_summary.tsv");
    fprintf(out.fp, "# air3D: volume of the reachable set at t = 2.8 on each grid of the sequence for medium and low, its change\n"
                    "# from the previous grid (- on the first), the largest |phi(x,y,psi) - phi(x,-y,-psi)| over the output times\n"
                    "# of each run, and target = the target cylinder's volume in the box, pi r^2 * 2 pi\n"
                    "NX\tgrid\tmedium\tmedium_change\tlow\tlow_change\tasym_medium\tasym_low\ttarget\n");
    for (int k = 0; k < nseq; k++) {
        hj_ls_grid gs;
        p2_fail_if(prog, p2_air3d_grid(seq[k], &gs, &err), &err);
        fprintf(out.fp, "%ld\t%ldx%ldx%ld", seq[k], gs.N[0], gs.N[1], gs.N[2]);
        for (int a = 0; a < 2; a++) {
            const double v = R[a][k].log.measure[R[a][k].log.n - 1];
            fprintf(out.fp, "\t%.17g", v);
            if (k) fprintf(out.fp, "\t%.17g", v - R[a][k - 1].log.measure[R[a][k - 1].log.n - 1]);
            else fputs("\t-", out.fp);
        }
        for (int a = 0; a < 2; a++) {
            double asym = 0;
            for (int q = 0; q < R[a][k].log.n; q++) asym = R[a][k].sn.asym[q] > asym ? R[a][k].sn.asym[q] : asym;
            fprintf(out.fp, "\t%.17g", asym);
        }
        fprintf(out.fp, "\t%.17g\n", HJ_PI * par.r * par.r * 2 * HJ_PI);
    }
    p2_fail_if(prog, hj_out_commit(&out, &err), &err);
    return 0;
}
