/*
# reinitDemo: the reinitialization equation (section 2.2.1, Figures 4-5)

**What it shows.** Solving the reinitialization PDE (4)

    D_t phi + S(phi_0) (|grad phi| - 1) = 0,   phi(x, 0) = phi_0(x),

turns an implicit surface function into (approximately) a signed distance
function, |grad phi| = 1, while keeping its zero level set.  The term is
`termReinit` (`hj_ls_reinit` in `common/hj_ls_term.h`: Godunov upwinding of the
gradient magnitude with the smeared sign S = phi_0 / sqrt(phi_0^2 + dx^2), Osher and
Fedkiw (7.5), no subcell fix), integrated by `odeCFLn` (FactorCFL 0.5) with
the loop of convectionDemo (the document: "the internals of reinitDemo are
virtually identical to convectionDemo").

**Parameters.**
- `--shape circle|star` (the toolbox's `initialType`).  'circle': the
  off-centre circle |x - (-0.4, 0)| - 0.35 (convectionDemo's; the document
  gives no centre or radius), which is a signed distance function near the
  circle but, with periodic boundaries, not across the seam x = +-1 (the
  document's point about this case).  'star': the seven-pointed star (13),
  phi_0 = |x| - s (cos(rho theta) + sigma) with s = 0.25, rho = 7,
  sigma = 2 (r from 0.25 to 0.75) and theta the polar angle; (13) prints
  arctan(x_2 / x_1), which for odd rho changes the shape in the left half
  plane; "the implementation uses polar coordinates", so we use atan2.  The
  document does not give s and sigma ("see the example files"); these are
  our choice.  On the star's boundary |grad phi_0| = sqrt(1 + (r'/r)^2)
  reaches sqrt(1 + 4.04^2) = 4.2 (r'/r = 7 sin / (cos + 2) at cos = -1/2),
  and it grows without bound toward the centre.
- `--accuracy` as in convectionDemo (default `low`); the figures use
  `medium` as in the document.
- Grid [-1, 1 - dx]^2, dx = 0.02 (the document's "relatively coarse grid
  g.dx = 0.02"), periodic boundaries (100 x 100 nodes) for both shapes.
- t in [0, 1] with nine output times (the document gives no t_max; in
  unit time the reinitialization front, which moves at speed |S| <= 1,
  covers a band of width 1 around the interface, everything within the
  star and most of the box).

**Figures.** fig04.png (Figure 4): phi_0 and phi(1) as surfaces for the star,
`medium`.  fig05.png (Figure 5): the zero level sets of phi_0 and phi(1)
(with a zoom on the points and valleys) and |grad phi| before and after.

**Check** (reinit.tsv against published/reinit.tsv).  Near the front, on the
nodes within 5 dx of the exact initial curve (its distance computed from
200000 samples of the exact curve by `hj_ls_unsigned_distance`):
- `grad_before`, `grad_after`: mean of | |grad phi| - 1 | (centered
  differences) before and after: reinitialization must reduce it for the
  star (from about 0.4) and keep it small for the circle;
- `sd_err_after`: max |phi(1) - d| with d the exact signed distance;
- `shift_max`, `shift_mean`: how far the zero level set moved: the
  distance of phi(1)'s zero crossings along the grid edges (linear
  interpolation) from the exact initial curve; `shift_floor` is the same
  for phi_0 (the error of the linear interpolation alone);
- `area_after`: area of {phi(1) < 0} (`hj_ls_measure`) against the exact
  area (pi r^2 = 0.384845; the star pi s^2 (1/2 + sigma^2) = 0.883573),
  kind value; `area_before` likewise for phi_0.
Areas have exact references; the gradient, distance and shift numbers are
held against our own run (regression gate, kind error).  A reinitialization
that moved the front, did not converge toward |grad phi| = 1, or used the
wrong sign would change them by far more than the tolerances.

**Outputs.** reinit.tsv, reinit_runs.tsv (every run to full precision,
which notes/reinit_notes.md presents), reinit_star_medium.dat (x y phi_0
phi(1) |grad phi_0| |grad phi(1)|, gnuplot grid).  With --shape or
--accuracy: one run, reinit_run.tsv and reinit_run.dat (the nine output
times as gnuplot index blocks).
*/
#include <stdio.h>

#include "hj_cli.h"
#include "hj_io.h"
#include "hj_ls_io.h"
#include "hj_ls_ode.h"
#include "hj_ls_accuracy.h"
#include "hj_ls_seq.h"
#include "p2_cli.h"
#include "p2_convection.h"
#include "p2_reinit.h"

static const char *const PROG = "reinit_demo";

/* One run: reinitialize c->phi0 at accuracy acc until t = 1; the result
 * in phi; seq_path (may be NULL) receives the nine output times. */
static long run(const p2_reinit_case *c, int acc, double *phi, const char *seq_path)
{
    hj_error err;
    hj_ls_reinit term;
    hj_ls_reinit_init(&term, &c->g, hj_ls_accuracy_scheme(acc), c->phi0);
    hj_ls_copy(&c->g, phi, c->phi0);
    hj_ls_ode_stats st;
    if (p2_solve(seq_path, acc, &c->g, &term.base, 1, phi, NULL, NULL, &st, &err))
        hj_cli_fail(PROG, HJ_EXIT_RUN, "%s %s: %s", p2_shape_name[c->shape], hj_ls_accuracy_name(acc), err.msg);
    return st.steps;
}

static const char *const SUMMARY =
    "reinitDemo of Mitchell's toolbox (section 2.2.1); see the comment at the top of reinit_demo.c.";
static const char *const EPILOG =
    "With neither --shape nor --accuracy: both shapes at every accuracy, the figures' data and reinit.tsv.\n";

int main(int argc, char **argv)
{
    p2_reinit_opts opt;
    hj_out tab, runs;
    p2_reinit_begin(PROG, SUMMARY, EPILOG, argc, argv, "reinit",
                    "# reinitDemo: near the front (within 5 dx of the exact initial curve) before and after t = 1\n",
                    &opt, &tab);
    const int shape = opt.shape, acc = opt.acc, single = opt.single;
    const char *dir = opt.dir;
    hj_error err;
    char path[4096];
    if (!single) /* every run to full precision, for the notes */
        p2_reinit_begin_runs(PROG, &opt, "reinit",
                             "# reinitDemo: every run, near the front (nodes within 5 dx of the exact initial curve) "
                             "before and after reinitialization to t = 1\n", "", &runs);
    for (int s = 0; s < P2_NSHAPE; s++) {
        if (single && s != shape) continue;
        p2_reinit_case c;
        p2_fail_if(PROG, p2_reinit_setup(&c, s, &err), &err);
        double *phi = hj_ls_alloc(&c.g), *g0 = hj_ls_alloc(&c.g), *g1 = hj_ls_alloc(&c.g);
        if (!phi || !g0 || !g1) hj_cli_fail(PROG, HJ_EXIT_RUN, "out of memory");
        p2_reinit_meas before, after;
        p2_fail_if(PROG, p2_reinit_measure(&c, c.phi0, &before, &err), &err);
        for (int a = 0; a < HJ_LS_NACC; a++) {
            if (single && a != acc) continue;
            snprintf(path, sizeof path, "%s/reinit_run.dat", dir);
            const long steps = run(&c, a, phi, single ? path : NULL);
            p2_fail_if(PROG, p2_reinit_measure(&c, phi, &after, &err), &err);
            p2_reinit_row(tab.fp, &c, a, &before, &after, steps);
            if (single) continue;
            p2_reinit_run_row(runs.fp, &c, a, &before, &after, steps);
            fputc('\n', runs.fp);
            if (s == P2_STAR && a == HJ_LS_ACC_MEDIUM) { /* Figures 4 and 5 */
                p2_fail_if(PROG, hj_ls_gradient_norm(&c.g, c.phi0, c.work, g0, &err), &err);
                p2_fail_if(PROG, hj_ls_gradient_norm(&c.g, phi, c.work, g1, &err), &err);
                const char *names[4] = {"phi0", "phi1", "grad0", "grad1"};
                const double *f[4] = {c.phi0, phi, g0, g1};
                p2_fail_if(PROG, p2_write_dat(dir, "reinit_star_medium.dat", &c.g, 4, names, f, &err), &err);
            }
        }
        hj_ls_free(phi), hj_ls_free(g0), hj_ls_free(g1);
        p2_reinit_free(&c);
    }
    p2_reinit_end(PROG, &opt, &tab, &runs);
    return 0;
}
