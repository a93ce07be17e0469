/* hj_fsm.c -- fast sweeping WENO for the Eikonal equation; see hj_fsm.h.
 * Equation numbers refer to Huang, Shu & Zhang (2008) as restored in
 * shared/papers/ERRATA.md. */
#include "hj_fsm.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

enum { CAT_I = 0, CAT_II = 1, CAT_III = 2, CAT_IV = 3 };
enum { GHOST = 2 };            /* ghost layers: the WENO stencil is i-2..i+2 */
#define FAR 1e100              /* "not reached yet" in the first order sweeps */

hj_fsm_options hj_fsm_default_options(void)
{
    hj_fsm_options o;
    memset(&o, 0, sizeof o);
    o.strategy = HJ_BC_LAX_WENDROFF;
    o.eps = 1e-6;
    o.delta = 1e-11;
    o.band = 3;
    o.stop_norm = HJ_STOP_L1_INTEGRAL;
    o.max_iter = 10000;
    return o;
}

double hj_fsm_memory(const hj_grid2 *g)
{
    double n = ((double)g->nx + 1 + 2 * GHOST) * ((double)g->ny + 1 + 2 * GHOST);
    /* phi with ghosts, its copy, f h, categories (1 byte), owners (4 bytes) */
    return n * (3 * sizeof(double) + 1 + sizeof(int));
}

/* ---- the local solvers ------------------------------------------------- */

/* Godunov update (2.2) from the upwind neighbour values a (x) and b (y). */
static inline double godunov(double a, double b, double fh)
{
    double d = a - b;
    if (d >= fh || -d >= fh) return (a < b ? a : b) + fh;
    return 0.5 * (a + b + sqrt(2.0 * fh * fh - d * d));
}

/* First order Godunov fast sweeping (Zhao 2005) on an (nx+1) x (ny+1)
 * array without ghosts.  Nodes with fixed[k] keep u[k]; the others start at
 * FAR and keep min(old, new).  Neighbours outside the array are absent
 * (outflow).  Stops when a full iteration changes no value by more than
 * 1e-14 (1 + max |u|). */
static int first_order_solve(int nx, int ny, const double *fh, const unsigned char *fixed, double *u, int max_iter,
                             int *iters)
{
    const int W = nx + 1;
    double umax = 1.0;
    for (long k = 0; k < (long)W * (ny + 1); k++) {
        if (!fixed[k]) u[k] = FAR;
        else if (fabs(u[k]) + 1 > umax) umax = fabs(u[k]) + 1;
    }
    const double tol = 1e-14 * umax;
    for (int it = 1; it <= max_iter; it++) {
        double change = 0;
        for (int s = 0; s < 4; s++) {
            const int ix = (s == 0 || s == 3) ? 1 : -1, iy = (s < 2) ? 1 : -1;
            for (int jj = 0; jj <= ny; jj++) {
                const int j = iy > 0 ? jj : ny - jj;
                for (int ii = 0; ii <= nx; ii++) {
                    const int i = ix > 0 ? ii : nx - ii;
                    const long k = (long)j * W + i;
                    if (fixed[k]) continue;
                    double a = FAR, b = FAR;
                    if (i > 0) a = u[k - 1];
                    if (i < nx && u[k + 1] < a) a = u[k + 1];
                    if (j > 0) b = u[k - W];
                    if (j < ny && u[k + W] < b) b = u[k + W];
                    if (a >= FAR && b >= FAR) continue;
                    double v = godunov(a, b, fh[k]);
                    if (v < u[k]) {
                        double d = u[k] >= FAR ? FAR : u[k] - v;
                        if (d > change) change = d;
                        u[k] = v;
                    }
                }
            }
        }
        if (change <= tol) {
            *iters = it;
            return HJ_OK;
        }
    }
    *iters = max_iter;
    return HJ_ENOCONV;
}

/* phi_xmin of (2.3)-(2.7) along a line with stride st: the smaller of the
 * two WENO-extrapolated neighbour values phi -/+ h phi_x^-/+. */
static inline double weno_min(const double *p, long st, double eps)
{
    const double pm2 = p[-2 * st], pm1 = p[-st], p0 = p[0], pp1 = p[st], pp2 = p[2 * st];
    const double dc = pp1 - 2 * p0 + pm1, dm = p0 - 2 * pm1 + pm2, dp = p0 - 2 * pp1 + pp2;
    const double den = eps + dc * dc;
    const double rm = (eps + dm * dm) / den, rp = (eps + dp * dp) / den;
    const double wm = 1.0 / (1.0 + 2.0 * rm * rm), wp = 1.0 / (1.0 + 2.0 * rp * rp);
    const double cen = 0.5 * (pp1 - pm1);
    const double hdm = (1 - wm) * cen + wm * 0.5 * (3 * p0 - 4 * pm1 + pm2);  /* h (phi_x)^- (2.4) */
    const double hdp = (1 - wp) * cen + wp * 0.5 * (-3 * p0 + 4 * pp1 - pp2); /* h (phi_x)^+ (2.5) */
    const double a1 = p0 - hdm, a2 = p0 + hdp;
    return a1 < a2 ? a1 : a2;
}

/* Third order extrapolation into the two ghost layers (Category II). */
static void extrapolate_ghosts(double *p, int nx, int ny)
{
    const long W = nx + 1 + 2 * GHOST;
#define P(i, j) p[((long)(j) + GHOST) * W + (i) + GHOST]
    for (int j = 0; j <= ny; j++) {
        P(-1, j) = 3 * P(0, j) - 3 * P(1, j) + P(2, j);
        P(-2, j) = 3 * P(-1, j) - 3 * P(0, j) + P(1, j);
        P(nx + 1, j) = 3 * P(nx, j) - 3 * P(nx - 1, j) + P(nx - 2, j);
        P(nx + 2, j) = 3 * P(nx + 1, j) - 3 * P(nx, j) + P(nx - 1, j);
    }
    for (int i = -GHOST; i <= nx + GHOST; i++) {
        P(i, -1) = 3 * P(i, 0) - 3 * P(i, 1) + P(i, 2);
        P(i, -2) = 3 * P(i, -1) - 3 * P(i, 0) + P(i, 1);
        P(i, ny + 1) = 3 * P(i, ny) - 3 * P(i, ny - 1) + P(i, ny - 2);
        P(i, ny + 2) = 3 * P(i, ny + 1) - 3 * P(i, ny) + P(i, ny - 1);
    }
#undef P
}

/* ---- boundary description ---------------------------------------------- */

static double speed_at(const hj_speed *sp, double x, double y) { return sp->f(x, y, sp->ctx); }

static void speed_grad(const hj_speed *sp, double x, double y, double h, double g[2])
{
    if (sp->grad_f) {
        sp->grad_f(x, y, g, sp->ctx);
        return;
    }
    const double d = 1e-4 * h;
    g[0] = (sp->f(x + d, y, sp->ctx) - sp->f(x - d, y, sp->ctx)) / (2 * d);
    g[1] = (sp->f(x, y + d, sp->ctx) - sp->f(x, y - d, sp->ctx)) / (2 * d);
}

int hj_fsm_lax_wendroff_value(const hj_speed *sp, const hj_inflow *c, double x, double y, double h, double *value,
                              hj_error *err)
{
    hj_curve_local L;
    if (c->type != HJ_INFLOW_CURVE)
        return hj_error_set(err, HJ_EINVAL, "Lax-Wendroff needs an inflow curve, not a point source");
    if (c->local(x, y, &L, c->ctx) != 0)
        return hj_error_set(err, HJ_EINVAL, "inflow curve: no local description near (%g, %g)", x, y);
    const double f = speed_at(sp, L.foot[0], L.foot[1]);
    double gf[2];
    speed_grad(sp, L.foot[0], L.foot[1], h, gf);
    const double tau[2] = {-L.n[1], L.n[0]};
    const double f_s = gf[0] * L.n[0] + gf[1] * L.n[1];
    const double f_t = gf[0] * tau[0] + gf[1] * tau[1];
    const double disc = f * f - L.g_t * L.g_t;
    if (!isfinite(disc) || !isfinite(f_s) || !isfinite(f_t))
        return hj_error_set(err, HJ_ENONFINITE, "Lax-Wendroff: non-finite speed or data at (%g, %g)", L.foot[0], L.foot[1]);
    if (disc < -1e-12 * (f * f + 1))
        return hj_error_set(err, HJ_EINVAL,
                            "Lax-Wendroff: |g_t| > f at (%g, %g): the boundary data is not compatible with inflow",
                            L.foot[0], L.foot[1]);
    /* The root of H(phi_s, g_t) = f with d_u H > 0 (2.12): flow into the
     * side of the curve that (x, y) is on. */
    const double phi_s = sqrt(disc > 0 ? disc : 0);
    double phi_st = 0, phi_ss = 0;
    /* phi_s = 0: characteristics tangent to the curve; the expansion stops
     * at first order there (phi_st, phi_ss undetermined by the PDE). */
    if (phi_s > 1e-12 * (fabs(f) + 1e-300)) {
        phi_st = (f * f_t - L.g_t * L.g_tt) / phi_s;                         /* (2.13) */
        phi_ss = (f * f_s - L.g_t * phi_st + L.kappa * L.g_t * L.g_t) / phi_s; /* normal derivative of the PDE */
    }
    const double s = L.dist;
    *value = L.g + s * phi_s + 0.5 * s * s * phi_ss;
    return HJ_OK;
}

/* Is (x, y) on a piece: returns 1 and the data value if so. */
static int on_piece(const hj_inflow *c, double x, double y, double h, double *value)
{
    if (c->type == HJ_INFLOW_POINT) {
        if (fabs(x - c->x) <= 1e-9 * h && fabs(y - c->y) <= 1e-9 * h) {
            *value = c->value;
            return 1;
        }
        return 0;
    }
    if (fabs(c->level(x, y, c->ctx)) > 1e-10 * h) return 0;
    hj_curve_local L;
    if (c->local(x, y, &L, c->ctx) != 0) return 0;
    *value = L.g;
    return 1;
}

/* Does the open horizontal or vertical segment of half-length band h
 * around (x, y) cross the curve?  The signed distance is sampled every
 * h/16; the node's distance to the curve is then < band h in that
 * direction. */
static int curve_within(const hj_inflow *c, double x, double y, double h, double band)
{
    const int nk = (int)ceil(16 * band);
    const double l0 = c->level(x, y, c->ctx);
    static const double dir[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (int d = 0; d < 4; d++)
        for (int k = 1; k <= nk; k++) {
            double t = (k < nk ? k / 16.0 : band * (1 - 1e-12)) * h;
            double l = c->level(x + t * dir[d][0], y + t * dir[d][1], c->ctx);
            if (l == 0 || (l > 0) != (l0 > 0)) return 1;
        }
    return 0;
}

/* Distance used to give a Category III node to its nearest piece. */
static double piece_distance(const hj_inflow *c, double x, double y)
{
    if (c->type == HJ_INFLOW_POINT) return fmax(fabs(x - c->x), fabs(y - c->y));
    return fabs(c->level(x, y, c->ctx));
}

/* ---- the solver -------------------------------------------------------- */

typedef struct {
    int nx, ny;
    long W;               /* row length with ghosts */
    double *p, *old, *fh; /* with ghosts */
    unsigned char *cat;   /* with ghosts */
    int *owner;           /* inflow piece of Category I/III nodes, or -1 */
} work;

static long widx(const work *w, int i, int j) { return ((long)j + GHOST) * w->W + i + GHOST; }

static void work_free(work *w)
{
    free(w->p);
    free(w->old);
    free(w->fh);
    free(w->cat);
    free(w->owner);
}

/* Categories I-IV of every node; Category I values are stored in p. */
static int classify(work *w, const hj_grid2 *g, const hj_inflow *in, int nin, hj_bc_strategy strat, double band,
                    hj_error *err)
{
    for (long k = 0; k < w->W * (long)(w->ny + 1 + 2 * GHOST); k++) {
        w->cat[k] = CAT_II;
        w->owner[k] = -1;
    }
    for (int j = 0; j <= w->ny; j++)
        for (int i = 0; i <= w->nx; i++) {
            const double x = g->x0 + i * g->h, y = g->y0 + j * g->h;
            const long k = widx(w, i, j);
            double v;
            w->cat[k] = CAT_IV;
            for (int c = 0; c < nin; c++)
                if (on_piece(&in[c], x, y, g->h, &v)) {
                    w->cat[k] = CAT_I;
                    w->owner[k] = c;
                    w->p[k] = v;
                    break;
                }
            if (w->cat[k] == CAT_I) continue;
            double best = INFINITY;
            for (int c = 0; c < nin; c++) {
                int near;
                if (in[c].type == HJ_INFLOW_POINT)
                    near = in[c].richardson && fabs(x - in[c].x) < 2.5 * g->h && fabs(y - in[c].y) < 2.5 * g->h;
                else
                    near = curve_within(&in[c], x, y, g->h, band);
                if (!near) continue;
                double d = piece_distance(&in[c], x, y);
                if (d < best) {
                    best = d;
                    w->cat[k] = CAT_III;
                    w->owner[k] = c;
                }
            }
        }
    for (int c = 0; c < nin; c++) {
        if (in[c].type == HJ_INFLOW_POINT && in[c].richardson && strat == HJ_BC_LAX_WENDROFF)
            return hj_error_set(err, HJ_EINVAL,
                                "inflow piece %d is a point source: the Lax-Wendroff procedure needs a curve "
                                "(use Richardson extrapolation)", c);
        if (in[c].type == HJ_INFLOW_POINT) {
            double v;
            int found = 0;
            for (int j = 0; j <= w->ny && !found; j++)
                for (int i = 0; i <= w->nx && !found; i++)
                    found = on_piece(&in[c], g->x0 + i * g->h, g->y0 + j * g->h, g->h, &v);
            if (!found)
                return hj_error_set(err, HJ_EINVAL, "point source %d at (%g, %g) is not a grid node", c, in[c].x, in[c].y);
        }
    }
    return HJ_OK;
}

/* A rectangle of grid nodes, ilo..ihi x jlo..jhi. */
typedef struct {
    int ilo, ihi, jlo, jhi;
} node_box;

/* The box ilo..ihi x jlo..jhi clipped to the nodes 0..nx x 0..ny. */
static node_box clip_box(int nx, int ny, int ilo, int ihi, int jlo, int jhi)
{
    node_box b = {ilo < 0 ? 0 : ilo, ihi > nx ? nx : ihi, jlo < 0 ? 0 : jlo, jhi > ny ? ny : jhi};
    return b;
}

/* Richardson extrapolation (2.9) in one box: first order solutions on h,
 * h/2, h/4 in the box, every fine node on an inflow piece fixed at its
 * data, nodes outside the box absent.  On each grid the box is widened by
 * `margin` nodes of that grid (clipped to the domain): HJ_RICH_BOX_NODE
 * uses one, see richardson().  Writes the Category III nodes of piece c
 * inside the box, or only node (ti, tj) when ti >= 0. */
static int richardson_box(work *w, const hj_grid2 *g, const hj_speed *sp, const hj_inflow *in, int nin, int c,
                          node_box bx, int margin, int ti, int tj, int max_iter, hj_error *err)
{
    const int ratios[3] = {1, 2, 4};
    double *sol[3] = {NULL, NULL, NULL};
    node_box fb[3]; /* each grid's box, in that grid's node indices */
    int rc = HJ_OK;
    for (int r = 0; r < 3 && rc == HJ_OK; r++) {
        const int m = ratios[r];
        fb[r] = clip_box(w->nx * m, w->ny * m, bx.ilo * m - margin, bx.ihi * m + margin, bx.jlo * m - margin,
                         bx.jhi * m + margin);
        const int fnx = fb[r].ihi - fb[r].ilo, fny = fb[r].jhi - fb[r].jlo;
        const double hf = g->h / m;
        const long n = (long)(fnx + 1) * (fny + 1);
        double *fh = malloc(sizeof(double) * (size_t)n);
        unsigned char *fixed = malloc((size_t)n);
        sol[r] = malloc(sizeof(double) * (size_t)n);
        if (!fh || !fixed || !sol[r]) {
            free(fh);
            free(fixed);
            rc = hj_error_set(err, HJ_ENOMEM, "out of memory in the Richardson boxes");
            break;
        }
        int nfixed = 0;
        for (int b = 0; b <= fny; b++)
            for (int a = 0; a <= fnx; a++) {
                const long k = (long)b * (fnx + 1) + a;
                const double x = g->x0 + (fb[r].ilo + a) * hf, y = g->y0 + (fb[r].jlo + b) * hf;
                fh[k] = speed_at(sp, x, y) * hf;
                fixed[k] = 0;
                for (int q = 0; q < nin; q++)
                    if (on_piece(&in[q], x, y, hf, &sol[r][k])) {
                        fixed[k] = 1;
                        nfixed++;
                        break;
                    }
            }
        int iters;
        if (nfixed == 0)
            rc = hj_error_set(err, HJ_EINVAL,
                              "Richardson extrapolation: inflow piece %d has no grid node in its box "
                              "(a curve that misses the grid nodes needs the Lax-Wendroff procedure)", c);
        else if (first_order_solve(fnx, fny, fh, fixed, sol[r], max_iter, &iters) != HJ_OK)
            rc = hj_error_set(err, HJ_ENOCONV, "first order sweeps in the Richardson box did not converge");
        free(fh);
        free(fixed);
    }
    for (int j = bx.jlo; j <= bx.jhi && rc == HJ_OK; j++)
        for (int i = bx.ilo; i <= bx.ihi; i++) {
            long k = widx(w, i, j);
            if (w->cat[k] != CAT_III || w->owner[k] != c || (ti >= 0 && (i != ti || j != tj))) continue;
            double I[3];
            for (int r = 0; r < 3; r++) {
                const int m = ratios[r];
                I[r] = sol[r][(long)(j * m - fb[r].jlo) * (fb[r].ihi - fb[r].ilo + 1) + (i * m - fb[r].ilo)];
            }
            if (I[0] >= FAR || I[1] >= FAR || I[2] >= FAR) {
                rc = hj_error_set(err, HJ_EINVAL, "Richardson box of inflow piece %d: node (%d, %d) not reached", c, i, j);
                break;
            }
            w->p[k] = I[0] / 3.0 - 2.0 * I[1] + 8.0 / 3.0 * I[2]; /* (2.9) */
        }
    for (int r = 0; r < 3; r++) free(sol[r]);
    return rc;
}

/* Richardson extrapolation for the Category III nodes of piece c.
 *
 * A point source: one box, exactly [-2h, 2h]^2 around it on every grid
 * (Example 1; no margin, see below).
 *
 * A curve, HJ_RICH_BOX_NODE (the default): each node gets its own box
 * [-Rh, Rh]^2 (R = 2, more when the band is wider so that the box reaches
 * the curve), the "small box [-2h, 2h]^2" in which Example 1 applies the
 * local sweeps.  The box cuts off part of the node's domain of dependence
 * along the curve, so the values are only third order accurate even where
 * first order sweeps are exact, as the paper says of Table 3.2 ("only
 * high order accurate but not exact to round-off").
 *
 * The margin.  On each of the grids h, h/2, h/4 the box is widened by one
 * node of that grid: [-3h, 3h], [-2.5h, 2.5h], [-2.25h, 2.25h] (a local
 * array with one layer of free nodes around the box).  The text does not
 * say this; Table 3.2 decides it.  With the margin, Example 2 gives
 * 3.63e-6 ... 1.89e-9 (a) and 4.47e-5 ... 9.68e-9 (b) against the paper's
 * 3.45e-6 ... 2.14e-9 and 3.38e-5 ... 9.25e-9, within 0.88-1.32 at all
 * eight sizes; without it (HJ_RICH_BOX_TIGHT) 0.54-0.72 and 0.22-0.45.
 * What tells them apart is case (b) against case (a): the paper's (b) is
 * 9.8, 11.3, 8.6, 4.3 times its (a), the margin gives 12.3, 12.0, 9.9, 5.1
 * and the tight box 3.0, 3.5, 3.2, 3.6.  A point source keeps the box the
 * paper names: there the margin leaves Example 1 unchanged (Table 3.1
 * identical with and without), but with a general speed map it could let
 * a path around a slow region into the box.
 *
 * A curve, HJ_RICH_BOX_PIECE: one box, the bounding box of the piece's
 * nodes widened by two nodes.  Why two: near a corner of the box domain a
 * Category III node belongs to the nearer edge, so an edge's nodes start
 * one node in from the corner; widened by one, the box's end column then
 * lies off the neighbouring edge, has no inflow data, and its outflow value
 * spoils the corner nodes (Example 2 (a): 3.6e-7 instead of exact).
 * Widened by two, the box reaches the neighbouring edge and the local
 * solution equals the global first order one (exact for Example 2 (a)). */
static int richardson(work *w, const hj_grid2 *g, const hj_speed *sp, const hj_inflow *in, int nin, int c,
                      const hj_fsm_options *opt, hj_error *err)
{
    int ilo = w->nx, ihi = 0, jlo = w->ny, jhi = 0;
    for (int j = 0; j <= w->ny; j++)
        for (int i = 0; i <= w->nx; i++) {
            long k = widx(w, i, j);
            if (w->cat[k] != CAT_III || w->owner[k] != c) continue;
            if (i < ilo) ilo = i;
            if (i > ihi) ihi = i;
            if (j < jlo) jlo = j;
            if (j > jhi) jhi = j;
        }
    if (ilo > ihi) return HJ_OK; /* no Category III nodes for this piece */
    if (in[c].type == HJ_INFLOW_POINT)
        return richardson_box(w, g, sp, in, nin, c, clip_box(w->nx, w->ny, ilo, ihi, jlo, jhi), 0, -1, -1,
                              opt->max_iter, err);
    if (opt->richardson_box == HJ_RICH_BOX_PIECE)
        return richardson_box(w, g, sp, in, nin, c, clip_box(w->nx, w->ny, ilo - 2, ihi + 2, jlo - 2, jhi + 2), 0,
                              -1, -1, opt->max_iter, err);
    const int R = opt->band > 3 ? (int)ceil(opt->band) - 1 : 2;
    const int margin = opt->richardson_box == HJ_RICH_BOX_NODE;
    for (int j = jlo; j <= jhi; j++)
        for (int i = ilo; i <= ihi; i++) {
            long k = widx(w, i, j);
            if (w->cat[k] != CAT_III || w->owner[k] != c) continue;
            int rc = richardson_box(w, g, sp, in, nin, c, clip_box(w->nx, w->ny, i - R, i + R, j - R, j + R), margin,
                                    i, j, opt->max_iter, err);
            if (rc != HJ_OK) return rc;
        }
    return HJ_OK;
}

/* hj_fsm_options.guess_noise: multiply each Category IV value by
 * 1 + noise u, u uniform in [-1, 1).  The generator is splitmix64, written
 * out so that a seed gives the same perturbation on every platform. */
static void perturb_guess(work *w, double noise, unsigned long seed)
{
    uint64_t x = seed;
    for (int j = 0; j <= w->ny; j++)
        for (int i = 0; i <= w->nx; i++) {
            const long k = widx(w, i, j);
            if (w->cat[k] != CAT_IV) continue;
            uint64_t z = (x += 0x9E3779B97F4A7C15ull);
            z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
            z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
            z ^= z >> 31;
            const double u = (double)(z >> 11) * 0x1.0p-52 - 1.0; /* [-1, 1) */
            w->p[k] *= 1 + noise * u;
        }
}

/* First order solution on the whole grid, written into w->p.  The sweeps
 * hold Category I fixed, and the Category III nodes of a piece when fix_iii
 * or when the piece has no Category I node (a curve that misses every node
 * enters the first order method only through its Category III values).
 * With keep_iii the Category III values already set are kept. */
static int first_order_guess(work *w, int nin, int fix_iii, int keep_iii, int max_iter, int *iters, hj_error *err)
{
    const int W = w->nx + 1;
    const long n = (long)W * (w->ny + 1);
    double *u = malloc(sizeof(double) * (size_t)n), *fh = malloc(sizeof(double) * (size_t)n);
    unsigned char *fixed = malloc((size_t)n), *has_i = calloc((size_t)nin, 1);
    if (!u || !fh || !fixed || !has_i) {
        free(u); free(fh); free(fixed); free(has_i);
        return hj_error_set(err, HJ_ENOMEM, "out of memory for the first order sweeps");
    }
    for (int j = 0; j <= w->ny; j++)
        for (int i = 0; i <= w->nx; i++) {
            const long k = widx(w, i, j);
            if (w->cat[k] == CAT_I && w->owner[k] >= 0) has_i[w->owner[k]] = 1;
        }
    for (int j = 0; j <= w->ny; j++)
        for (int i = 0; i <= w->nx; i++) {
            const long k = widx(w, i, j), q = (long)j * W + i;
            fixed[q] = w->cat[k] == CAT_I ||
                       (keep_iii && w->cat[k] == CAT_III && (fix_iii || !has_i[w->owner[k]]));
            u[q] = w->p[k];
            fh[q] = w->fh[k];
        }
    int rc = first_order_solve(w->nx, w->ny, fh, fixed, u, max_iter, iters);
    if (rc != HJ_OK) rc = hj_error_set(err, HJ_ENOCONV, "first order sweeps did not converge in %d iteration%s", max_iter,
                                     hj_plural(max_iter));
    for (int j = 0; j <= w->ny && rc == HJ_OK; j++)
        for (int i = 0; i <= w->nx; i++) {
            const long q = (long)j * W + i;
            if (u[q] >= FAR) {
                rc = hj_error_set(err, HJ_EINVAL, "node (%d, %d) is not reached from any inflow boundary", i, j);
                break;
            }
            if (!(keep_iii && w->cat[widx(w, i, j)] == CAT_III)) w->p[widx(w, i, j)] = u[q];
        }
    free(u); free(fh); free(fixed); free(has_i);
    return rc;
}

/* One Gauss-Seidel sweep over the Category IV nodes in direction s. */
static void weno_sweep(work *w, int s, double eps)
{
    const int nx = w->nx, ny = w->ny;
    const int ix = (s == 0 || s == 3) ? 1 : -1, iy = (s < 2) ? 1 : -1;
    for (int jj = 0; jj <= ny; jj++) {
        const int j = iy > 0 ? jj : ny - jj;
        for (int ii = 0; ii <= nx; ii++) {
            const int i = ix > 0 ? ii : nx - ii;
            const long k = widx(w, i, j);
            if (w->cat[k] != CAT_IV) continue;
            const double a = weno_min(&w->p[k], 1, eps), b = weno_min(&w->p[k], w->W, eps);
            w->p[k] = godunov(a, b, w->fh[k]);
        }
    }
}

int hj_fsm_solve(const hj_grid2 *g, const hj_speed *sp, const hj_inflow *in, int nin, const hj_fsm_options *opt,
                 double *phi, hj_fsm_stats *stats, hj_error *err)
{
    memset(stats, 0, sizeof *stats);
    if (!g || !sp || !sp->f || !opt || !phi || (nin > 0 && !in))
        return hj_error_set(err, HJ_EINVAL, "hj_fsm_solve: NULL argument");
    if (g->nx < 4 || g->ny < 4) return hj_error_set(err, HJ_EINVAL, "grid needs at least 4 intervals per direction");
    if (!(g->h > 0) || !isfinite(g->h) || !isfinite(g->x0) || !isfinite(g->y0))
        return hj_error_set(err, HJ_EINVAL, "grid spacing and origin must be finite, h > 0");
    if (!(opt->eps > 0) || !isfinite(opt->eps) || !(opt->delta >= 0) || !isfinite(opt->delta) || opt->max_iter < 1 ||
        !(opt->band >= 1 && opt->band <= 10) ||
        (opt->richardson_box != HJ_RICH_BOX_NODE && opt->richardson_box != HJ_RICH_BOX_PIECE &&
         opt->richardson_box != HJ_RICH_BOX_TIGHT) ||
        (opt->guess != HJ_GUESS_PHYSICAL && opt->guess != HJ_GUESS_WITH_III) ||
        !(opt->guess_noise >= 0 && opt->guess_noise < 1))
        return hj_error_set(err, HJ_EINVAL, "options: need eps > 0, delta >= 0 finite, 1 <= band <= 10, max_iter >= 1, "
                                            "a valid Richardson box and initial guess, 0 <= guess_noise < 1");
    if (nin < 1) return hj_error_set(err, HJ_EINVAL, "no inflow boundary given");
    for (int c = 0; c < nin; c++)
        if (in[c].type == HJ_INFLOW_CURVE && (!in[c].level || !in[c].local))
            return hj_error_set(err, HJ_EINVAL, "inflow curve %d: level and local functions are required", c);

    work w;
    memset(&w, 0, sizeof w);
    w.nx = g->nx;
    w.ny = g->ny;
    w.W = g->nx + 1 + 2 * GHOST;
    const double ntot = (double)w.W * (g->ny + 1 + 2 * GHOST);
    if (ntot > 4e9) return hj_error_set(err, HJ_ENOMEM, "grid of %.3g nodes is too large", ntot);
    const size_t n = (size_t)ntot;
    w.p = calloc(n, sizeof(double));
    w.old = malloc(n * sizeof(double));
    w.fh = calloc(n, sizeof(double));
    w.cat = malloc(n);
    w.owner = malloc(n * sizeof(int));
    if (!w.p || !w.old || !w.fh || !w.cat || !w.owner) {
        work_free(&w);
        return hj_error_set(err, HJ_ENOMEM, "out of memory: the solver needs %.3g MB", hj_fsm_memory(g) / 1e6);
    }
    int rc = HJ_OK;
    for (int j = 0; j <= g->ny && rc == HJ_OK; j++)
        for (int i = 0; i <= g->nx; i++) {
            const double x = g->x0 + i * g->h, y = g->y0 + j * g->h, f = speed_at(sp, x, y);
            if (!isfinite(f) || f < 0) {
                rc = hj_error_set(err, HJ_ENONFINITE, "speed f(%g, %g) = %g: must be finite and >= 0", x, y, f);
                break;
            }
            w.fh[widx(&w, i, j)] = f * g->h;
        }
    if (rc == HJ_OK) rc = classify(&w, g, in, nin, opt->strategy, opt->band, err);
    if (rc == HJ_OK)
        for (long k = 0; k < (long)n; k++) stats->ncat[w.cat[k]]++;

    /* Category III values, then the first order initial guess. */
    if (rc == HJ_OK && opt->strategy == HJ_BC_RICHARDSON)
        for (int c = 0; c < nin && rc == HJ_OK; c++) rc = richardson(&w, g, sp, in, nin, c, opt, err);
    if (rc == HJ_OK && opt->strategy == HJ_BC_LAX_WENDROFF)
        for (int j = 0; j <= g->ny && rc == HJ_OK; j++)
            for (int i = 0; i <= g->nx && rc == HJ_OK; i++) {
                const long k = widx(&w, i, j);
                if (w.cat[k] == CAT_III)
                    rc = hj_fsm_lax_wendroff_value(sp, &in[w.owner[k]], g->x0 + i * g->h, g->y0 + j * g->h, g->h, &w.p[k],
                                                   err);
            }
    /* The initial guess (hj_fsm_guess): with HJ_GUESS_PHYSICAL our
     * iteration counts of Table 3.3 (b) are 34 47 against the paper's
     * 35 47; holding Category III fixed too gives 38 54. */
    if (rc == HJ_OK) {
        const int set_iii = opt->strategy != HJ_BC_FIRST_ORDER;
        rc = first_order_guess(&w, nin, set_iii && opt->guess == HJ_GUESS_WITH_III, set_iii, opt->max_iter,
                               &stats->fo_iterations, err);
    }

    if (rc == HJ_OK && opt->guess_noise > 0) perturb_guess(&w, opt->guess_noise, opt->guess_seed);

    /* WENO Gauss-Seidel iterations on Category IV. */
    if (rc == HJ_OK && !opt->first_order_only) {
        const long nodes = (long)(g->nx + 1) * (g->ny + 1);
        rc = HJ_ENOCONV;
        for (int it = 1; it <= opt->max_iter; it++) {
            memcpy(w.old, w.p, n * sizeof(double));
            for (int s = 0; s < 4; s++) {
                extrapolate_ghosts(w.p, g->nx, g->ny);
                weno_sweep(&w, s, opt->eps);
            }
            double sum = 0, mx = 0;
            for (int j = 0; j <= g->ny; j++)
                for (int i = 0; i <= g->nx; i++) {
                    const long k = widx(&w, i, j);
                    const double d = fabs(w.p[k] - w.old[k]);
                    sum += d;
                    if (d > mx) mx = d;
                }
            const double change = opt->stop_norm == HJ_STOP_LINF          ? mx
                                  : opt->stop_norm == HJ_STOP_L1_INTEGRAL ? sum * g->h * g->h
                                                                          : sum / nodes;
            stats->iterations = it;
            stats->change = change;
            if (opt->progress) opt->progress(it, change, opt->progress_ctx);
            if (!isfinite(change)) {
                rc = hj_error_set(err, HJ_ENONFINITE, "WENO iteration %d produced non-finite values", it);
                break;
            }
            if (change <= opt->delta) {
                rc = HJ_OK;
                break;
            }
        }
        if (rc == HJ_ENOCONV)
            hj_error_set(err, HJ_ENOCONV, "no convergence in %d iteration%s (last change %.3g > delta %.3g)", opt->max_iter,
                         hj_plural(opt->max_iter), stats->change, opt->delta);
    }
    if (rc == HJ_OK || rc == HJ_ENOCONV)
        for (int j = 0; j <= g->ny; j++)
            for (int i = 0; i <= g->nx; i++) phi[(long)j * (g->nx + 1) + i] = w.p[widx(&w, i, j)];
    work_free(&w);
    return rc;
}
