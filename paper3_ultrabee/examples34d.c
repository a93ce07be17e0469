/*
# Three- and four-dimensional examples of the UB-HJB scheme (Tables 11-13)

**Problems.** Section 4, Examples 4-6 of Bokanowski, Cristiani & Zidani
(2010), data -1 inside Omega_0 and 1 outside, UB-HJB scheme on the SSD
narrow band, CFL = 0.9 over the band nodes, value 1 outside the domain:

* Table 11 -- Example 4 on [-2, 2]^3 with f = (-2 pi x2, 2 pi x1, -1) and
  the ball of radius 0.1 centred at (-1, 0, 1): advection (single control)
  up to T = 2, and the target problem (4) up to T = 0.5.  The text says
  the centre is (-1, 0, 1) and the formula (1, 0, 1); both lie on the
  unit circle of the rotation, so the two choices are mirror images with
  the same errors and cost.  We take (-1, 0, 1).  Exact advection: the
  ball moved by the flow; exact target set: the points whose backward
  trajectory meets the ball within T (minimum over the time by sampling
  and golden-section refinement).  The target run streams the minimal
  time function T(x) (first time the cell value is -1) to
  table11_mintime_N<N>.bin (int32 indices and float64 time per cell;
  common/hj_mintime.h writes it and reads it back onto the grid).
* Table 12 -- Example 5 on [-1, 1]^4, f = (-2 pi x2, 2 pi x1, -2 pi x4,
  2 pi x3), the box (0.5, 0, 0.5, 0) + [-0.1, 0.1]^4, T = 1 (exact: the
  initial box).
* Table 13 -- Example 6 on [-2, 2]^4, target problem (18) with the four
  controls (1,0,0,0), (1,1,0,0), (1,0,1,0), (1,0,0,1), the target the
  origin (its cell: N is odd so that the origin is a node), T = 1.
  Exact: x >= 0, x2 + x3 + x4 <= x1 <= t.

**Method.** common/hj_ub.h on the SSD store; errors as in common/hj_ub.h (L1 by the
signs at the cell centres, Hausdorff between the boundary cells of
{V <= 0} and the exact front sampled on the grid segments).

**Measured.** CPU time (initialisation and steps, not the error
evaluation), its ratio between successive N (the published "Order"),
L1 error, Hausdorff distance, Haus/dx, steps, mean band size, peak
resident memory.

**Parameters.** Table 11: N = 50, 100, 200, 400, 800; Table 12: N = 25,
50, 100, 200; Table 13: N = 25, 51, 101, 201.  `--quick`: the two
smallest of each.  `--max-n` skips larger sizes, `--tables 11,13`
selects tables.

**Output.** table11.tsv, table12.tsv, table13.tsv.  Figure 9
(fig09.png by plot/fig09.gp, voxel isosurfaces): the Table 11 runs at
N = 50 (quick and full) write fig09_advection.dat (T = 2) and
fig09_target.dat (T = 0.5), "x y z V g" on a cube of the grid around
the sets, V the UB values and g a continuous function whose zero set is
the exact front; after the timed steps.
*/
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "hj_cli.h"
#include "hj_math.h"
#include "hj_mintime.h"
#include "hj_sys.h"
#include "hj_ub.h"
#include "p3_prog.h"


typedef struct {
    int example; /* 4 advection, 5 target of Example 4, 6 Example 5, 7 Example 6 */
    double T, t, dx;
    double c[4], r;
    double cs, sn; /* cos, sin of the back rotation at time t */
    hj_mintime_stream mintime; /* fp NULL: not recorded */
} exnd;

static void dyn(double t, const double *x, int a, double *f, void *vctx)
{
    (void)t;
    const exnd *e = vctx;
    if (e->example <= 5) {
        f[0] = -2 * HJ_PI * x[1];
        f[1] = 2 * HJ_PI * x[0];
        f[2] = -1;
    } else if (e->example == 6) {
        f[0] = -2 * HJ_PI * x[1];
        f[1] = 2 * HJ_PI * x[0];
        f[2] = -2 * HJ_PI * x[3];
        f[3] = 2 * HJ_PI * x[2];
    } else {
        f[0] = 1;
        f[1] = a == 1;
        f[2] = a == 2;
        f[3] = a == 3;
    }
}

static double avg0(const double *blo, const double *bhi, void *vctx)
{
    const exnd *e = vctx;
    if (e->example <= 5) return hj_ub_avg_ball(3, blo, bhi, e->c, e->r, 6);
    double lo[4], hi[4];
    const double half = e->example == 6 ? 0.1 : e->dx / 2;
    for (int k = 0; k < 4; k++) { lo[k] = e->c[k] - half; hi[k] = e->c[k] + half; }
    return hj_ub_avg_box(4, blo, bhi, lo, hi);
}

static int uniform(const double *blo, const double *bhi, void *vctx)
{
    const exnd *e = vctx;
    if (e->example <= 5) return hj_ub_ball_uniform(3, blo, bhi, e->c, e->r);
    const double b = avg0(blo, bhi, vctx);
    return b == 1 || b == -1;
}

static void reached(const int *idx, double t, void *vctx)
{
    exnd *e = vctx;
    if (e->mintime.fp) hj_mintime_put(&e->mintime, idx, t);
}

/* |X(-tau; x) - c|^2 for Example 4's flow. */
static double back_dist2(const exnd *e, const double *x, double tau)
{
    const double cs = cos(2 * HJ_PI * tau), sn = sin(2 * HJ_PI * tau);
    const double y0 = cs * x[0] + sn * x[1] - e->c[0], y1 = -sn * x[0] + cs * x[1] - e->c[1], y2 = x[2] + tau - e->c[2];
    return y0 * y0 + y1 * y1 + y2 * y2;
}

/* Example 4's target problem: min over tau in [0, t] of |X(-tau; x) - c|^2,
 * or +inf when x is surely farther than r from every X(tau; c) (outside
 * the annulus |rho - rho_c| <= r or the height range). */
static double target_dist2(const exnd *e, const double *x)
{
    const double rho = sqrt(x[0] * x[0] + x[1] * x[1]), rc = sqrt(e->c[0] * e->c[0] + e->c[1] * e->c[1]);
    if (fabs(rho - rc) > e->r || x[2] < e->c[2] - e->r - e->t || x[2] > e->c[2] + e->r) return INFINITY;
    /* minimum over tau in [0, t]: samples, then golden section */
    const int m = 200;
    int best = 0;
    double dbest = INFINITY;
    for (int i = 0; i <= m; i++) {
        const double dd = back_dist2(e, x, e->t * i / m);
        if (dd < dbest) { dbest = dd; best = i; }
    }
    double a = e->t * (best > 0 ? best - 1 : 0) / m, b = e->t * (best < m ? best + 1 : m) / m;
    const double g = 0.5 * (sqrt(5.0) - 1);
    for (int it = 0; it < 40; it++) {
        const double p = b - g * (b - a), q = a + g * (b - a);
        if (back_dist2(e, x, p) < back_dist2(e, x, q)) b = q; else a = p;
    }
    const double dm = back_dist2(e, x, 0.5 * (a + b));
    return dm < dbest ? dm : dbest;
}

static int inside(const double *x, void *vctx)
{
    const exnd *e = vctx;
    if (e->example == 4) {
        const double y0 = e->cs * x[0] + e->sn * x[1] - e->c[0], y1 = -e->sn * x[0] + e->cs * x[1] - e->c[1];
        const double y2 = x[2] + e->t - e->c[2];
        return y0 * y0 + y1 * y1 + y2 * y2 <= e->r * e->r;
    }
    if (e->example == 5) return target_dist2(e, x) <= e->r * e->r;
    /* Examples 5 and 6: closed polytopes, P3_CLOSED_SLACK (Table 13's odd
     * N put x_k = 0, x1 = t and x2 + x3 + x4 = x1 through cell centres). */
    const double tol = P3_CLOSED_SLACK * e->dx;
    if (e->example == 6) {
        const double y[4] = {e->cs * x[0] + e->sn * x[1], -e->sn * x[0] + e->cs * x[1], e->cs * x[2] + e->sn * x[3],
                             -e->sn * x[2] + e->cs * x[3]};
        for (int k = 0; k < 4; k++)
            if (fabs(y[k] - e->c[k]) > 0.1 + tol) return 0;
        return 1;
    }
    return x[0] >= -tol && x[1] >= -tol && x[2] >= -tol && x[3] >= -tol && x[1] + x[2] + x[3] <= x[0] + tol &&
           x[0] <= e->t + tol;
}

typedef struct {
    double cpu, l1, haus, dx, steps, band, peak;
} run_result;

/* Figure 9 (Example 4 at N = 50): the UB values V and the exact g, a
 * continuous function with the exact set {g <= 0} (|y - c| - r for the
 * advected ball, y the point the flow came from; for the target problem
 * the distance from x's backward trajectory over [0, T] to c, minus r),
 * clipped at 0.3, at the nodes of the smallest cube of the grid that holds
 * both sets with two nodes to spare (at least 12 nodes a side): "x y z V g", for a voxel isosurface
 * (the cube side, m, is the cube root of the line count).  Written after
 * the timed steps. */
static int write_fig09(exnd *e, hj_ub_solver *sv, const char *out_dir, hj_error *err)
{
    const int n = sv->pb->n;
    const size_t nn = (size_t)n * n * n;
    double *v = malloc(nn * sizeof *v), *g = malloc(nn * sizeof *g);
    int rc = v && g ? hj_ub_values(sv, v, err) : hj_error_set(err, HJ_ENOMEM, "out of memory (figure)");
    int blo[3] = {n, n, n}, bhi[3] = {-1, -1, -1};
    for (size_t q = 0; q < nn && !rc; q++) {
        const int idx[3] = {(int)(q / ((size_t)n * n)), (int)(q / (size_t)n % (size_t)n), (int)(q % (size_t)n)};
        double x[3];
        hj_ub_centre(sv, idx, x);
        double gq;
        if (e->example == 4) {
            const double y[3] = {e->cs * x[0] + e->sn * x[1] - e->c[0], -e->sn * x[0] + e->cs * x[1] - e->c[1], x[2] + e->t - e->c[2]};
            gq = sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2]) - e->r;
        } else {
            gq = sqrt(target_dist2(e, x)) - e->r;
        }
        g[q] = gq < 0.3 ? gq : 0.3;
        if (v[q] <= 0 || g[q] <= 0)
            for (int k = 0; k < 3; k++) {
                blo[k] = idx[k] < blo[k] ? idx[k] : blo[k];
                bhi[k] = idx[k] > bhi[k] ? idx[k] : bhi[k];
            }
    }
    hj_out out;
    if (!rc && bhi[0] < 0) rc = hj_error_set(err, HJ_EINVAL, "figure 9: empty sets");
    if (!rc) rc = p3_open(&out, out_dir, e->example == 4 ? "fig09_advection.dat" : "fig09_target.dat", err);
    if (!rc) {
        int m = 0, i0[3], ms[3];
        for (int k = 0; k < 3; k++) m = bhi[k] - blo[k] + 5 > m ? bhi[k] - blo[k] + 5 : m;
        m = m < 12 ? 12 : m; /* gnuplot's voxel grids have at least 10^3 nodes */
        m = m < n ? m : n;
        for (int k = 0; k < 3; k++) {
            i0[k] = (blo[k] + bhi[k]) / 2 - m / 2;
            i0[k] = i0[k] < 0 ? 0 : i0[k] + m > n ? n - m : i0[k];
            ms[k] = m;
        }
        fprintf(out.fp, "# %s: examples34d, Example 4 (%s), N = %d, t = %g: x y z V g on a %d^3 cube of the grid\n",
                e->example == 4 ? "fig09_advection.dat" : "fig09_target.dat", e->example == 4 ? "advection" : "target problem",
                n, e->t, m);
        const double *f[2] = {v, g};
        rc = p3_fig_block(out.fp, 3, n, sv->pb->lo[0], sv->dx[0], i0, ms, 2, f, err);
        if (rc) hj_out_abort(&out);
        else rc = hj_out_commit(&out, err);
    }
    free(v);
    free(g);
    return rc;
}

static int run(exnd *e, int n, const char *out_dir, int fig, run_result *res, hj_error *err)
{
    const int d = e->example <= 5 ? 3 : 4;
    const double L = e->example == 6 ? 1 : 2;
    hj_ub_problem pb = {.d = d, .n = n, .ncontrols = e->example == 7 ? 4 : 1, .dyn = dyn, .target = e->example == 5 || e->example == 7,
                     .cfl = 0.9, .boundary = 1, .snap = HJ_UB_SNAP, .avg0 = avg0, .uniform = uniform, .reached = e->example == 5 ? reached : NULL, .ctx = e};
    e->dx = 2 * L / (n - 1);
    for (int k = 0; k < d; k++) {
        pb.lo[k] = -L;
        pb.hi[k] = L;
        const double half = e->example <= 5 ? e->r : e->example == 6 ? 0.1 : e->dx;
        pb.bbox_lo[k] = e->c[k] - half;
        pb.bbox_hi[k] = e->c[k] + half;
    }
    hj_out mt;
    int have_mt = 0;
    if (e->example == 5) {
        char name[64];
        snprintf(name, sizeof name, "table11_mintime_N%d.bin", n);
        int rc = p3_open(&mt, out_dir, name, err);
        if (rc) return rc;
        e->mintime = (hj_mintime_stream){mt.fp, 3, 0};
        have_mt = 1;
    }
    hj_ub_solver sv;
    const double c0 = hj_sys_cpu_seconds();
    int rc = hj_ub_init(&sv, &pb, HJ_BAND_SSD, err);
    if (!rc) {
        while (!rc && sv.t < e->T) {
            rc = hj_ub_step(&sv, e->T, err);
            hj_progress("\r  N=%d t=%.4f/%g band=%zu   ", n, sv.t, e->T, hj_band_count(sv.s));
        }
        hj_progress("\n");
    }
    res->cpu = hj_sys_cpu_seconds() - c0;
    res->peak = hj_sys_peak_rss_mb();
    if (have_mt) {
        if (!rc && e->mintime.failed) rc = hj_error_set(err, HJ_EIO, "write error (minimal time)");
        e->mintime.fp = NULL;
        if (rc) hj_out_abort(&mt);
        else rc = hj_out_commit(&mt, err);
    }
    if (rc) { hj_ub_free(&sv); return rc; }
    e->t = e->T;
    const double back = e->example == 6 ? 2 * HJ_PI * e->t : 2 * HJ_PI * e->t;
    e->cs = cos(back);
    e->sn = sin(back);
    if (fig) rc = write_fig09(e, &sv, out_dir, err);
    if (!rc) rc = hj_ub_errors(&sv, inside, e, &res->l1, &res->haus, err);
    res->dx = sv.dx[0];
    res->steps = (double)sv.steps;
    res->band = sv.steps ? sv.band_sum / (double)sv.steps : 0;
    hj_ub_free(&sv);
    return rc;
}

int main(int argc, char **argv)
{
    p3_args a = {.prog = "examples34d"};
    p3_args_parse(&a, argc, argv, "Tables 11-13: UB-HJB on the 3-D and 4-D examples 4-6 of section 4.", NULL, 11, 13);
    hj_error err;
    static const long s11[] = {50, 100, 200, 400, 800}, s12[] = {25, 50, 100, 200}, s13[] = {25, 51, 101, 201};
    for (int table = 11; table <= 13; table++) {
        if (!p3_want(&a, table)) continue;
        const long *sizes = table == 11 ? s11 : table == 12 ? s12 : s13;
        int ns = a.quick ? 2 : table == 11 ? 5 : 4;
        if (a.nsizes) { sizes = a.sizes; ns = a.nsizes; }
        hj_out out;
        char name[64];
        snprintf(name, sizeof name, "table%d.tsv", table);
        if (p3_open(&out, a.out_dir, name, &err)) p3_die(a.prog, &err);
        FILE *fp = out.fp;
        fprintf(fp, "# table%d: UB-HJB on the SSD band, computed by examples34d%s\n", table, a.quick ? " --quick" : "");
        fprintf(fp, "%sN\tcpu\tcpu_ratio\tL1\thaus\thaus_dx\tsteps\tband\tpeak_MB\n", table == 11 ? "problem\t" : "");
        for (int p = 0; p < (table == 11 ? 2 : 1); p++) {
            double prev = NAN;
            for (int i = 0; i < ns; i++) {
                if (a.max_n && sizes[i] > a.max_n) continue;
                exnd e = {0};
                if (table == 11) {
                    e.example = 4 + p;
                    e.T = p ? 0.5 : 2;
                    e.c[0] = -1; e.c[2] = 1;
                    e.r = 0.1;
                } else if (table == 12) {
                    e.example = 6;
                    e.T = 1;
                    e.c[0] = 0.5; e.c[2] = 0.5;
                } else {
                    e.example = 7;
                    e.T = 1;
                }
                run_result r;
                hj_progress("table%d N=%ld\n", table, sizes[i]);
                if (run(&e, (int)sizes[i], a.out_dir, table == 11 && sizes[i] == 50, &r, &err)) { hj_out_abort(&out); p3_die(a.prog, &err); }
                char b[6][32];
                fprintf(fp, "%s%ld\t%.4g\t%s\t%s\t%s\t%s\t%.0f\t%.0f\t%.0f\n",
                        table == 11 ? (p ? "target\t" : "advection\t") : "", sizes[i], r.cpu, p3_num(b[0], r.cpu / prev),
                        p3_num(b[1], r.l1), p3_num(b[2], r.haus), p3_num(b[3], r.haus / r.dx), r.steps, r.band, r.peak);
                fflush(fp);
                prev = r.cpu;
            }
        }
        if (hj_out_commit(&out, &err)) p3_die(a.prog, &err);
    }
    return 0;
}
