/*
# Two-dimensional examples of the UB-HJB scheme (Tables 6-10)

**Problems.** Section 4, Examples 1-3 of Bokanowski, Cristiani & Zidani
(2010), all with data -1 inside Omega_0 and 1 outside, solved with the
UB-HJB scheme on the SSD narrow band (CFL = 0.9 over the band nodes,
value 1 outside the domain):

* Table 6 -- Example 1, advection of the square [0.5, 1.5] x [-0.5, 0.5]
  by f = (-2, -1) up to T = 1 on [-2, 2]^2 (exact: the moved square).
* Table 7 -- the same square rotated by f = (-x2, x1) up to T = 2 pi
  (exact: the initial square).
* Tables 8 and 9 -- Example 2, the rendez-vous problem (13),
  theta_t + theta_x1 + |theta_x2| = 0 (f = (1, a), a = +-1), T = 1, on
  [-1, 2]^2, target the box |x|_inf <= r with r = 0.1 (Table 8) and
  r = dx (Table 9).  Exact: [T - r, T + r] x [-T - r, T + r].  In
  Table 9 the L1 error is taken against the thin target r = 0 itself,
  whose exact set is the segment {T} x [-T, T] of measure zero, so that
  the L1 error is the area of the computed set {V <= 0}: this is what the
  published values are (0.166 = about 1.3 dx x 2.1 at N = 51).  Its
  Hausdorff distance is taken against the r = dx set (the segment
  thickened by dx), since no grid segment crosses the segment itself.
* Table 10 -- Example 3, deformation of the half plane x2 <= 0 by
  f(t, x) = -s(t) max(1 - |x|, 0) (-2 pi x2, 2 pi x1), s = +1 before T/2
  and -1 after, T = 6, on [-1, 1]^2 (the paper does not give the domain;
  the flow vanishes outside the unit disc), errors at t = 3 and t = 6.
  Exact by characteristics: theta(t, x) = phi(R(2 pi a(x) t1) x),
  t1 = min(t, T - t), with the rotation R of the flow as written (the
  paper's formula has the opposite angle, see the overview).

**Method.** common/hj_ub.h: dimension-split Ultra-Bee fluxes with the errata,
band maintenance of section 3.5.  Three readings, fixed by the published
numbers of Tables 6 and 7 (overview, "Grid, data and Hausdorff estimate
of the 2-D examples"):

* the grid is N cells of width dx = L/N tiling the domain, values at the
  cell centres (hj_ub_cell_grid);
* (7b) is taken by the midpoint rule: V^0 is phi at the cell centre;
* the exact front is sampled on the lattice lines refined 8 times.

With them Table 6 comes out as published, L1 = 0 at every N and
Haus./dx = 0.559, 0.5, 0.707, 0.707 (printed, truncated: 0.55, 0.50,
0.70, 0.70), and so do Table 7's Hausdorff distances at N = 50 and 100
(0.1166 and 0.0566 against 0.116 and 0.056).  The exact averages give 4
wrong corner cells at N = 100 on this grid, and no grid gives 0 at every
N with them (unit test table6_zero_on_no_grid).

**Level set comparison.** The paper's "very simple RK2-ENO2 solver
(without reinitialization), following Osher and Shu", on the common level
set kernel (p3_ls.h): the same grid (level set values at the UB cell
centres), ENO2 upwind derivatives, Heun's TVD RK2, the kernel's unsplit
CFL bound with factor 0.5 (the paper's CFL 0.9 makes this scheme blow up,
see the overview), ghost nodes by linear extrapolation.  Data: (12)
min(max(|x1 - 1|, |x2|) - 0.5, 0.5) for the square, the same form
min(|x|_inf - r, 0.5) for the rendez-vous target (r = dx for Table 9),
(15) min(max(x2, -1), 1) for the half plane.  The rendez-vous Hamiltonian
max_a f(x, a) . p is the node-by-node maximum of the two controls' upwind
convection terms (hj_ls_extremum); Example 3's flow, which changes sign
at T / 2, is integrated in two pieces, each with its sign frozen.  The
errors are those of the UB runs (same L1 by signs at the cell centres,
same Hausdorff estimate on the level set's sign set).  A front is lost
when no node has V <= 0: then no error is given ('-', as in the paper),
and ls_lost_t is the first time after a step at which it happened.

**Measured.** L1 error = dx^2 #{cells whose sign differs from the exact
sign at the centre}, Hausdorff distance between the computed front (the
centres of the boundary cells of {V <= 0}) and the exact front sampled
where it crosses the lattice lines refined 8 times, Haus/dx, total CPU
time (initialisation and steps) and its ratio between successive N (the
published "Order" column).  CPU seconds themselves are not compared (2008
laptop).  The same errors for
the level set runs (ls_*), with their CPU time, steps, the number of
nodes with V <= 0 at T and the time the front was lost.

**Parameters.** N = 50, 100, 200, 400 (Tables 6, 7), 51, 101, 201, 401
(Tables 8, 9), 50, 100, 200 (Table 10); `--quick` runs the two smallest
sizes of each table.

**Output.** table6.tsv ... table10.tsv (Table 10: ls_L1_t3, ls_haus_t3,
ls_L1_t6, ls_haus_t6 beside the UB columns).  Figure data, taken from the
table runs outside the timed parts (quick and full runs both make these
sizes): fig06_rendezvous.dat (Table 8, N = 101: x y V_ub V_ls at T = 1),
fig07_deformation.dat and fig08_deformation.dat (Table 10, N = 100 and
50: x y V_ub V_ls at t = 3 and t = 6, then the exact front as the zero
set of g = sin(th) x1 + cos(th) x2 on a 201^2 grid), drawn as Figures 6-8
(fig06.png ... fig08.png by plot/fig06.gp ... fig08.gp): the 0 contours
of V_ub and V_ls beside the exact front.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hj_cli.h"
#include "hj_math.h"
#include "hj_sys.h"
#include "hj_ub.h"
#include "p3_ls.h"
#include "p3_prog.h"


typedef struct {
    int example;           /* 1 translation, 2 rotation, 3 rendez-vous, 4 deformation */
    double lo[2], hi[2];   /* the initial box (Examples 1, 2) */
    double r;              /* rendez-vous target half width */
    double T, t;           /* final time; time of the exact solution */
    double dx;             /* the grid step, set by run() */
} ex2d;

static void dyn(double t, const double *x, int a, double *f, void *vctx)
{
    const ex2d *e = vctx;
    switch (e->example) {
    case 1: f[0] = -2; f[1] = -1; break;
    case 2: f[0] = -x[1]; f[1] = x[0]; break;
    case 3: f[0] = 1; f[1] = a ? 1 : -1; break;
    default: {
        const double r = sqrt(x[0] * x[0] + x[1] * x[1]), amp = r < 1 ? 1 - r : 0;
        const double s = t < e->T / 2 ? 1 : -1;
        f[0] = -s * amp * (-2 * HJ_PI * x[1]);
        f[1] = -s * amp * (2 * HJ_PI * x[0]);
    }
    }
}

/* Whether y lies in the closed box [lo, hi], with tol of slack. */
static int in_box(const double *y, const double *lo, const double *hi, double tol)
{
    return y[0] >= lo[0] - tol && y[0] <= hi[0] + tol && y[1] >= lo[1] - tol && y[1] <= hi[1] + tol;
}

/* The initial value of the cell [blo, bhi]: (7b) by the midpoint rule,
 * phi at the cell centre (closed sets, P3_CLOSED_SLACK).  The exact
 * averages would put 1 - 2 (1/4) = 0.5 in the corner cells of Table 6's
 * square at N = 100, whose centres lie on the corners: 4 wrong signs,
 * L1 = 0.0064 against the published 0.000 (overview, "Grid, data and
 * Hausdorff estimate of the 2-D examples"). */
static double avg0(const double *blo, const double *bhi, void *vctx)
{
    const ex2d *e = vctx;
    const double c[2] = {0.5 * (blo[0] + bhi[0]), 0.5 * (blo[1] + bhi[1])}, tol = P3_CLOSED_SLACK * e->dx;
    if (e->example == 4) return c[1] <= tol ? -1 : 1; /* half plane x2 <= 0 */
    return in_box(c, e->lo, e->hi, tol) ? -1 : 1;
}

/* Sampled data: a block of cells is uniform only if every centre says so
 * (hj_ub_init then checks them one by one). */
static int never_uniform(const double *blo, const double *bhi, void *vctx)
{
    (void)blo, (void)bhi, (void)vctx;
    return 0;
}

/* Hausdorff estimate: the exact front sampled on the lattice lines refined
 * eight times (hj_ub_errors), so that its points between the cell
 * centre lines count: Table 6's fronts lie 1/4 or 1/2 cell from the centre
 * lines, and the distance the paper prints (0.55, 0.50, 0.70 dx) is that of
 * the continuous front, which the centre lines alone miss (0.25, 0, 0.5). */
#define FRONT_SUB 8

/* The domain [a, b]^2 of each example. */
static void domain(int example, double *a, double *b)
{
    *a = example == 1 || example == 2 ? -2 : -1;
    *b = example == 4 ? 1 : 2;
}

/* Closed sets, P3_CLOSED_SLACK (on the cell grid the faces of Table 6's
 * square pass through cell centres at N = 100, and the data's at N = 50). */
static int inside(const double *x, void *vctx)
{
    const ex2d *e = vctx;
    const double tol = P3_CLOSED_SLACK * e->dx;
    double y[2] = {x[0], x[1]};
    switch (e->example) {
    case 1: y[0] = x[0] + 2 * e->t; y[1] = x[1] + e->t; break;
    case 2: { /* back along the rotation by -t */
        const double c = cos(e->t), s = sin(e->t);
        y[0] = c * x[0] + s * x[1];
        y[1] = -s * x[0] + c * x[1];
        break;
    }
    case 3:
        if (e->r == 0) return fabs(x[0] - e->T) <= tol && fabs(x[1]) <= e->T + tol; /* the thin target's segment */
        return x[0] >= e->T - e->r - tol && x[0] <= e->T + e->r + tol && fabs(x[1]) <= e->T + e->r + tol;
    default: {
        const double r = sqrt(x[0] * x[0] + x[1] * x[1]), amp = r < 1 ? 1 - r : 0;
        const double t1 = e->t < e->T - e->t ? e->t : e->T - e->t, th = 2 * HJ_PI * amp * t1;
        return sin(th) * x[0] + cos(th) * x[1] <= 0;
    }
    }
    return in_box(y, e->lo, e->hi, tol);
}

typedef struct {
    double cpu, l1, haus, dx, steps, band;
    double l1b, hausb; /* Table 10: at t = 6 */
} run_result;

/* Figure data of one run (Figs. 6-8): the UB and level set values on the
 * n^2 grid at the output times (k = 0: T, or t = 3 for Example 3; k = 1:
 * t = 6), taken outside the timed parts. */
typedef struct {
    double *ub[2], *ls[2];
} fig2d;

/* ---- the level set comparison (RK2-ENO2 on the common kernel, p3_ls.h) ---- */

/* The Lipschitz data of the level set runs: (12) for the square, the same
 * form min(|x|_inf - r, 0.5) for the rendez-vous target (the paper does not
 * give it), (15) for the half plane. */
static double phi_ls(const double *x, void *vctx)
{
    const ex2d *e = vctx;
    if (e->example == 4) return x[1] < -1 ? -1 : x[1] > 1 ? 1 : x[1];
    double r;
    if (e->example == 3) r = fmax(fabs(x[0]), fabs(x[1])) - fabs(e->r);
    else r = fmax(fabs(x[0] - 1), fabs(x[1])) - 0.5; /* (12): the square [0.5, 1.5] x [-0.5, 0.5] */
    return r < 0.5 ? r : 0.5;
}

typedef struct {
    double cpu, l1, haus, l1b, hausb, steps, lost_t;
    int64_t cells, cellsb; /* #{V <= 0} at the end (Table 10: at t = 3 and t = 6) */
} ls_result;

/* Errors of the level set run; a lost front (no V <= 0) gives no error. */
static int ls_errors(p3_ls *ls, ex2d *e, double *l1, double *haus, int64_t *cells, hj_error *err)
{
    const double rs = e->r; /* < 0: the thin target r = -rs = dx */
    e->r = fabs(rs);
    int rc = hj_front_ls_errors(&ls->g, ls->y, inside, e, FRONT_SUB, l1, haus, cells, err);
    if (!rc && rs < 0) { /* thin target: L1 against r = 0, as for UB */
        double h0;
        e->r = 0;
        rc = hj_front_ls_errors(&ls->g, ls->y, inside, e, FRONT_SUB, l1, &h0, NULL, err);
    }
    e->r = rs;
    if (!rc && *cells == 0) *l1 = *haus = NAN;
    return rc;
}

/* The same problem as run() (e as run() left it) by the level set method. */
static int run_ls(ex2d *e, int n, ls_result *res, fig2d *fig, hj_error *err)
{
    double da, db, lo[2], hi[2];
    domain(e->example, &da, &db);
    hj_ub_cell_grid(da, db, n, &lo[0], &hi[0]);
    lo[1] = lo[0];
    hi[1] = hi[0];
    const int ncontrols = e->example == 3 ? 2 : 1;
    const double rr = e->r;
    if (e->example == 3 && e->r < 0) e->r = e->dx; /* thin target r = dx for the data */
    p3_ls ls;
    const double c0 = hj_sys_cpu_seconds();
    int rc = p3_ls_init(&ls, 2, n, lo, hi, phi_ls, e, err);
    e->r = rr;
    hj_ls_convection conv[2];
    hj_ub_control ctl[2];
    const hj_ls_term *terms[2];
    hj_ls_extremum hjb = {0};
    for (int a = 0; a < ncontrols && !rc; a++) {
        ctl[a] = (hj_ub_control){dyn, a, 0, 0, e};
        hj_ls_convection_init(&conv[a], &ls.g, HJ_LS_ENO2);
        conv[a].velocity_fn = hj_ub_control_velocity;
        conv[a].ctx = &ctl[a];
        terms[a] = &conv[a].base;
    }
    /* theta_t + max_a f(x, a) . grad theta = 0: G = min over the controls */
    if (!rc) rc = hj_ls_extremum_init(&hjb, &ls.g, terms, ncontrols, 0, err);
    const double tstop = e->example == 4 ? e->T / 2 : e->T;
    if (e->example == 4) ctl[0].frozen = 1, ctl[0].tfix = 0; /* s = +1 up to T / 2 */
    if (!rc) rc = p3_ls_run(&ls, &hjb.base, tstop, P3_LS_CFL, err);
    res->cpu = hj_sys_cpu_seconds() - c0;
    if (!rc && fig) p3_ls_values(&ls, fig->ls[0]);
    e->t = tstop;
    if (!rc) rc = ls_errors(&ls, e, &res->l1, &res->haus, &res->cells, err);
    if (!rc && e->example == 4) {
        const double c1 = hj_sys_cpu_seconds();
        ctl[0].tfix = e->T; /* s = -1 after */
        rc = p3_ls_run(&ls, &hjb.base, e->T, P3_LS_CFL, err);
        res->cpu += hj_sys_cpu_seconds() - c1;
        if (!rc && fig) p3_ls_values(&ls, fig->ls[1]);
        e->t = e->T;
        if (!rc) rc = ls_errors(&ls, e, &res->l1b, &res->hausb, &res->cellsb, err);
    }
    res->steps = (double)ls.steps;
    res->lost_t = ls.lost_t;
    hj_ls_extremum_free(&hjb);
    p3_ls_free(&ls);
    return rc;
}

static int run(ex2d *e, int n, run_result *res, fig2d *fig, hj_error *err)
{
    hj_ub_problem pb = {.d = 2, .n = n, .ncontrols = e->example == 3 ? 2 : 1, .dyn = dyn, .cfl = 0.9, .boundary = 1, .snap = HJ_UB_SNAP,
                     .avg0 = avg0, .uniform = never_uniform, .front_sub = FRONT_SUB, .ctx = e};
    double dom, domhi;
    domain(e->example, &dom, &domhi);
    e->dx = (domhi - dom) / n;
    for (int k = 0; k < 2; k++) {
        hj_ub_cell_grid(dom, domhi, n, &pb.lo[k], &pb.hi[k]);
        pb.bbox_lo[k] = e->example == 4 ? dom : e->lo[k];
        pb.bbox_hi[k] = e->example == 4 ? (k ? 0 : domhi) : e->hi[k];
    }
    if (e->example == 3 && e->r == 0) { /* thin target: r = dx */
        const double dx = e->dx;
        e->lo[0] = e->lo[1] = -dx;
        e->hi[0] = e->hi[1] = dx;
        pb.bbox_lo[0] = pb.bbox_lo[1] = -dx;
        pb.bbox_hi[0] = pb.bbox_hi[1] = dx;
        e->r = -dx; /* marks the thin case for the exact solution */
    }
    const double rr = fabs(e->r);
    hj_ub_solver sv;
    const double c0 = hj_sys_cpu_seconds();
    int rc = hj_ub_init(&sv, &pb, HJ_BAND_SSD, err);
    const double tstop = e->example == 4 ? e->T / 2 : e->T;
    if (!rc) rc = hj_ub_run(&sv, tstop, err);
    res->cpu = hj_sys_cpu_seconds() - c0;
    if (!rc && fig) rc = hj_ub_values(&sv, fig->ub[0], err);
    if (rc) { hj_ub_free(&sv); return rc; }
    const double r_saved = e->r;
    e->r = rr;
    e->t = tstop;
    rc = hj_ub_errors(&sv, inside, e, &res->l1, &res->haus, err);
    if (!rc && r_saved < 0) { /* thin target: L1 against r = 0 (see above) */
        double haus0;
        e->r = 0;
        rc = hj_ub_errors(&sv, inside, e, &res->l1, &haus0, err);
    }
    res->dx = sv.dx[0];
    if (!rc && e->example == 4) {
        const double c1 = hj_sys_cpu_seconds();
        rc = hj_ub_run(&sv, e->T, err);
        res->cpu += hj_sys_cpu_seconds() - c1;
        if (!rc && fig) rc = hj_ub_values(&sv, fig->ub[1], err);
        e->t = e->T;
        if (!rc) rc = hj_ub_errors(&sv, inside, e, &res->l1b, &res->hausb, err);
    }
    e->r = r_saved;
    res->steps = (double)sv.steps;
    res->band = sv.steps ? sv.band_sum / (double)sv.steps : 0;
    hj_ub_free(&sv);
    return rc;
}

typedef struct {
    const char *table;
    ex2d e;
    long sizes[4];
    int nsizes;
} table_spec;

/* The figure drawn from the run of table t at size n, or NULL: Fig. 6
 * (Table 8, N = 101), Figs. 7 and 8 (Table 10, N = 100 and 50). */
static const char *fig_name(long t, long n)
{
    if (t == 8 && n == 101) return "fig06_rendezvous.dat";
    if (t == 10 && n == 100) return "fig07_deformation.dat";
    if (t == 10 && n == 50) return "fig08_deformation.dat";
    return NULL;
}

/* Example 3's exact solution as a continuous function whose zero set is
 * the exact front: g(x) = sin(th) x1 + cos(th) x2, th = 2 pi a(x) t1 (the
 * second coordinate of the point the flow came from; inside is g <= 0). */
static double deform_g(const double *x, double t, double T)
{
    const double r = sqrt(x[0] * x[0] + x[1] * x[1]), amp = r < 1 ? 1 - r : 0;
    const double t1 = t < T - t ? t : T - t, th = 2 * HJ_PI * amp * t1;
    return sin(th) * x[0] + cos(th) * x[1];
}

/* Write the figure data of one run (fig_name): index 0 (and 1 for Example
 * 3, t = 6) "x y V_ub V_ls" on the n^2 grid; for Example 3 also index 2
 * (t = 3) and 3 (t = 6): "x y g" of deform_g on a 201^2 grid of the
 * domain, whose zero contour is the exact front. */
static int write_fig(const p3_args *a, const char *name, const ex2d *e, int n, const fig2d *fig, hj_error *err)
{
    double lo, hi, c0, c1;
    domain(e->example, &lo, &hi);
    hj_ub_cell_grid(lo, hi, n, &c0, &c1);
    const double dx = (hi - lo) / n;
    hj_out out;
    int rc = p3_open(&out, a->out_dir, name, err);
    if (rc) return rc;
    fprintf(out.fp, "# %s: examples2d, %s N = %d: x y V_ub V_ls (%s)\n", name,
            e->example == 3 ? "rendez-vous (Table 8)" : "deformation (Table 10)", n,
            e->example == 3 ? "T = 1" : "index 0: t = 3, 1: t = 6; 2, 3: exact g at t = 3, 6 on 201^2");
    const int i0[2] = {0, 0}, m[2] = {n, n};
    for (int k = 0; k < (e->example == 4 ? 2 : 1) && !rc; k++) {
        const double *f[2] = {fig->ub[k], fig->ls[k]};
        rc = p3_fig_block(out.fp, 2, n, c0, dx, i0, m, 2, f, err);
    }
    if (!rc && e->example == 4) {
        const int nf = 201, mf[2] = {nf, nf};
        double *g = malloc((size_t)nf * nf * sizeof *g);
        if (!g) rc = hj_error_set(err, HJ_ENOMEM, "out of memory (figure)");
        for (int k = 0; k < 2 && !rc; k++) {
            for (int i = 0; i < nf; i++)
                for (int j = 0; j < nf; j++) {
                    const double x[2] = {lo + i * (hi - lo) / (nf - 1), lo + j * (hi - lo) / (nf - 1)};
                    g[i * nf + j] = deform_g(x, k ? e->T : e->T / 2, e->T);
                }
            const double *f[1] = {g};
            rc = p3_fig_block(out.fp, 2, nf, lo, (hi - lo) / (nf - 1), i0, mf, 1, f, err);
        }
        free(g);
    }
    if (rc) { hj_out_abort(&out); return rc; }
    return hj_out_commit(&out, err);
}

int main(int argc, char **argv)
{
    p3_args a = {.prog = "examples2d"};
    p3_args_parse(&a, argc, argv, "Tables 6-10: UB-HJB on the 2-D examples 1-3 of section 4.", NULL, 6, 10);
    const table_spec specs[] = {
        {"table6", {1, {0.5, -0.5}, {1.5, 0.5}, 0, 1, 0, 0}, {50, 100, 200, 400}, 4},
        {"table7", {2, {0.5, -0.5}, {1.5, 0.5}, 0, 2 * HJ_PI, 0, 0}, {50, 100, 200, 400}, 4},
        {"table8", {3, {-0.1, -0.1}, {0.1, 0.1}, 0.1, 1, 0, 0}, {51, 101, 201, 401}, 4},
        {"table9", {3, {0, 0}, {0, 0}, 0, 1, 0, 0}, {51, 101, 201, 401}, 4},
        {"table10", {4, {0, 0}, {0, 0}, 0, 6, 0, 0}, {50, 100, 200}, 3},
    };
    hj_error err;
    for (size_t s = 0; s < sizeof specs / sizeof *specs; s++) {
        const table_spec *sp = &specs[s];
        if (!p3_want(&a, atol(sp->table + 5))) continue;
        long sizes[P3_MAX_SIZES];
        int ns = a.nsizes ? a.nsizes : a.quick ? 2 : sp->nsizes;
        memcpy(sizes, a.nsizes ? a.sizes : sp->sizes, sizeof(long) * (size_t)ns);
        hj_out out;
        char name[64];
        snprintf(name, sizeof name, "%s.tsv", sp->table);
        if (p3_open(&out, a.out_dir, name, &err)) p3_die(a.prog, &err);
        FILE *fp = out.fp;
        fprintf(fp, "# %s: UB-HJB on the SSD band, computed by examples2d%s\n", sp->table, a.quick ? " --quick" : "");
        if (sp->e.example == 4)
            fprintf(fp, "N\tcpu\tcpu_ratio\tL1_t3\thaus_t3\tL1_t6\thaus_t6\tsteps\tband"
                        "\tls_L1_t3\tls_haus_t3\tls_L1_t6\tls_haus_t6\tls_cpu\tls_steps\n");
        else
            fprintf(fp, "N\tcpu\tcpu_ratio\tL1\thaus\thaus_dx\tsteps\tband\tls_L1\tls_haus\tls_haus_dx"
                        "\tls_cpu\tls_steps\tls_cells\tls_lost_t\n");
        double prev = NAN;
        for (int i = 0; i < ns; i++) {
            if (a.max_n && sizes[i] > a.max_n) continue;
            ex2d e = sp->e;
            run_result r;
            const char *fname = fig_name(atol(sp->table + 5), sizes[i]);
            fig2d fig = {{NULL, NULL}, {NULL, NULL}}, *figp = NULL;
            if (fname) {
                const size_t nn = (size_t)sizes[i] * (size_t)sizes[i];
                for (int k = 0; k < 2; k++) {
                    fig.ub[k] = malloc(nn * sizeof(double));
                    fig.ls[k] = malloc(nn * sizeof(double));
                    if (!fig.ub[k] || !fig.ls[k]) {
                        hj_error_set(&err, HJ_ENOMEM, "out of memory (figure)");
                        hj_out_abort(&out);
                        p3_die(a.prog, &err);
                    }
                }
                figp = &fig;
            }
            hj_progress("%s N=%ld ...\n", sp->table, sizes[i]);
            if (run(&e, (int)sizes[i], &r, figp, &err)) { hj_out_abort(&out); p3_die(a.prog, &err); }
            ls_result q;
            hj_progress("%s N=%ld level set ...\n", sp->table, sizes[i]);
            if (run_ls(&e, (int)sizes[i], &q, figp, &err)) { hj_out_abort(&out); p3_die(a.prog, &err); }
            if (fname && write_fig(&a, fname, &sp->e, (int)sizes[i], &fig, &err)) {
                hj_out_abort(&out);
                p3_die(a.prog, &err);
            }
            for (int k = 0; k < 2; k++) { free(fig.ub[k]); free(fig.ls[k]); }
            char b[12][32];
            if (sp->e.example == 4)
                fprintf(fp, "%ld\t%.3g\t%s\t%s\t%s\t%s\t%s\t%.0f\t%.0f\t%s\t%s\t%s\t%s\t%.3g\t%.0f\n", sizes[i], r.cpu,
                        p3_num(b[0], r.cpu / prev), p3_num(b[1], r.l1), p3_num(b[2], r.haus), p3_num(b[3], r.l1b),
                        p3_num(b[4], r.hausb), r.steps, r.band, p3_num(b[5], q.l1), p3_num(b[6], q.haus),
                        p3_num(b[7], q.l1b), p3_num(b[8], q.hausb), q.cpu, q.steps);
            else
                fprintf(fp, "%ld\t%.3g\t%s\t%s\t%s\t%s\t%.0f\t%.0f\t%s\t%s\t%s\t%.3g\t%.0f\t%lld\t%s\n", sizes[i],
                        r.cpu, p3_num(b[0], r.cpu / prev), p3_num(b[1], r.l1), p3_num(b[2], r.haus),
                        p3_num(b[3], r.haus / r.dx), r.steps, r.band, p3_num(b[4], q.l1), p3_num(b[5], q.haus),
                        p3_num(b[6], q.haus / r.dx), q.cpu, q.steps, (long long)q.cells, p3_num(b[7], q.lost_t));
            prev = r.cpu;
        }
        if (hj_out_commit(&out, &err)) p3_die(a.prog, &err);
    }
    return 0;
}
