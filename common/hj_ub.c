/* hj_ub.c -- the UB-HJB scheme on a narrow band (see hj_ub.h). */
#include "hj_ub.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hj_ls_grid.h"

/* ---- the one-dimensional Ultra-Bee fluxes (8)-(9) ------------------------ */

static inline double clip(double x, double lo, double hi)
{
    x = x < lo ? lo : x;
    return x > hi ? hi : x;
}

/* W^L_{i+1/2} from node i when mu_i >= 0 (wm, wi, wp = W_{i-1}, W_i, W_{i+1}). */
static inline double flux_left(double wm, double wi, double wp, double mu)
{
    if (mu > 0) {
        const double mx = wi > wm ? wi : wm, mn = wi < wm ? wi : wm;
        return clip(wp, mx + (wi - mx) / mu, mn + (wi - mn) / mu);
    }
    return wi != wm ? wp : wi;
}

/* W^R_{i-1/2} from node i when mu_i <= 0. */
static inline double flux_right(double wm, double wi, double wp, double mu)
{
    if (mu < 0) {
        const double mx = wi > wp ? wi : wp, mn = wi < wp ? wi : wp;
        return clip(wm, mx + (wi - mx) / -mu, mn + (wi - mn) / -mu);
    }
    return wi != wp ? wm : wi;
}

static inline double ub_update(const double *w, const double *mu)
{
    const double m = mu[1];
    if (m > 0) {
        const double fl = flux_left(w[1], w[2], w[3], m);
        /* left face: from node j-1 if it also flows right, else (8) */
        const double fr = mu[0] >= 0 ? flux_left(w[0], w[1], w[2], mu[0]) : (w[2] == w[3] ? w[2] : w[1]);
        return w[2] - m * (fl - fr);
    }
    if (m < 0) {
        const double fr = flux_right(w[1], w[2], w[3], m);
        const double fl = mu[2] <= 0 ? flux_right(w[2], w[3], w[4], mu[2]) : (w[2] == w[1] ? w[2] : w[3]);
        return w[2] - m * (fl - fr);
    }
    return w[2];
}

double hj_ub_update(const double *w, const double *mu) { return ub_update(w, mu); }

/* ---- geometry ------------------------------------------------------------ */

void hj_ub_centre(const hj_ub_solver *sv, const int *idx, double *x)
{
    for (int k = 0; k < sv->pb->d; k++) x[k] = sv->pb->lo[k] + idx[k] * sv->dx[k];
}

static void unlin(int d, int n, int64_t k, int *idx)
{
    for (int i = d - 1; i >= 0; i--) {
        idx[i] = (int)(k % n);
        k /= n;
    }
}

static int64_t linear(int d, int n, const int *idx)
{
    int64_t k = 0;
    for (int i = 0; i < d; i++) k = k * n + idx[i];
    return k;
}

/* The 3^d - 1 offsets of Neigh(I). */
static int offsets(int d, int off[][HJ_BAND_DMAX])
{
    int m = 0, total = 1;
    for (int i = 0; i < d; i++) total *= 3;
    for (int c = 0; c < total; c++) {
        int r = c, zero = 1;
        for (int i = 0; i < d; i++) {
            off[m][i] = r % 3 - 1;
            zero &= off[m][i] == 0;
            r /= 3;
        }
        if (!zero) m++;
    }
    return m;
}

void hj_ub_cell_grid(double a, double b, int n, double *lo, double *hi)
{
    const double dx = (b - a) / n;
    *lo = a + 0.5 * dx;
    *hi = b - 0.5 * dx;
}

/* ---- averages of the initial data (7b) ----------------------------------- */

double hj_ub_avg_box(int d, const double *blo, const double *bhi, const double *clo, const double *chi)
{
    double frac = 1;
    for (int k = 0; k < d; k++) {
        const double a = blo[k] > clo[k] ? blo[k] : clo[k], b = bhi[k] < chi[k] ? bhi[k] : chi[k];
        double f = b > a ? (b - a) / (bhi[k] - blo[k]) : 0;
        /* faces that coincide up to round-off of the grid coordinates */
        f = f < 1e-9 ? 0 : f > 1 - 1e-9 ? 1 : f;
        frac *= f;
    }
    return 1 - 2 * frac;
}

int hj_ub_ball_uniform(int d, const double *blo, const double *bhi, const double *c, double r)
{
    double near = 0, far = 0;
    for (int k = 0; k < d; k++) {
        const double q = c[k] < blo[k] ? blo[k] - c[k] : c[k] > bhi[k] ? c[k] - bhi[k] : 0;
        const double f = fabs(c[k] - blo[k]) > fabs(c[k] - bhi[k]) ? fabs(c[k] - blo[k]) : fabs(c[k] - bhi[k]);
        near += q * q;
        far += f * f;
    }
    return near >= r * r || far <= r * r;
}

double hj_ub_avg_ball(int d, const double *blo, const double *bhi, const double *c, double r, int m)
{
    double near = 0, far = 0; /* squared distances from c to the box */
    for (int k = 0; k < d; k++) {
        const double q = c[k] < blo[k] ? blo[k] - c[k] : c[k] > bhi[k] ? c[k] - bhi[k] : 0;
        const double f = fabs(c[k] - blo[k]) > fabs(c[k] - bhi[k]) ? fabs(c[k] - blo[k]) : fabs(c[k] - bhi[k]);
        near += q * q;
        far += f * f;
    }
    if (near >= r * r) return 1;
    if (far <= r * r) return -1;
    long total = 1, in = 0;
    for (int k = 0; k < d; k++) total *= m;
    for (long s = 0; s < total; s++) {
        long q = s;
        double r2 = 0;
        for (int k = 0; k < d; k++) {
            const double x = blo[k] + ((double)(q % m) + 0.5) / m * (bhi[k] - blo[k]) - c[k];
            r2 += x * x;
            q /= m;
        }
        in += r2 <= r * r;
    }
    return 1 - 2.0 * (double)in / (double)total;
}

/* ---- workspace ------------------------------------------------------------ */

static int reserve(hj_ub_solver *sv, size_t m, hj_error *err)
{
    if (m <= sv->cap) return HJ_OK;
    size_t cap = sv->cap ? sv->cap : 1024;
    while (cap < m) cap *= 2;
    const int d = sv->pb->d;
#define GROW(p, count)                                                            \
    do {                                                                          \
        void *np = realloc(sv->p, (count) * sizeof *sv->p);                       \
        if (!np) return hj_error_set(err, HJ_ENOMEM, "out of memory (band workspace)"); \
        sv->p = np;                                                               \
    } while (0)
    GROW(lin, cap);
    GROW(ptr, cap);
    GROW(v0, cap);
    GROW(w, cap);
    GROW(wn, cap);
    GROW(vmin, cap);
    GROW(f, cap * (size_t)d);
    GROW(x, cap * (size_t)d);
    GROW(mu, cap * (size_t)d);
    GROW(link, cap * 2 * (size_t)d);
#undef GROW
    sv->cap = cap;
    return HJ_OK;
}

void hj_ub_free(hj_ub_solver *sv)
{
    hj_band_free(sv->s);
    free(sv->lin);
    free(sv->ptr);
    free(sv->v0);
    free(sv->w);
    free(sv->wn);
    free(sv->vmin);
    free(sv->f);
    free(sv->x);
    free(sv->mu);
    free(sv->link);
    memset(sv, 0, sizeof *sv);
}

/* ---- initialisation -------------------------------------------------------- */

/* Whether the cells around idx all have the value v of cell idx (outside
 * the grid: the boundary value): sure when the data average over the whole
 * block is +-1, else checked cell by cell (sampled averages may call a cell
 * uniform that the block test would not). */
static int uniform_block(const hj_ub_solver *sv, const int *idx, double v, const double *blo, const double *bhi)
{
    const hj_ub_problem *pb = sv->pb;
    for (int k = 0; k < pb->d; k++) /* a neighbour outside has the boundary value */
        if ((idx[k] == 0 || idx[k] == pb->n - 1) && v != pb->boundary) return 0;
    if (pb->uniform) {
        if (pb->uniform(blo, bhi, pb->ctx)) return 1;
    } else {
        const double b = pb->avg0(blo, bhi, pb->ctx);
        if (b == 1 || b == -1) return b == v;
    }
    int off[81][HJ_BAND_DMAX], j[HJ_BAND_DMAX];
    const int noff = offsets(pb->d, off);
    for (int o = 0; o < noff; o++) {
        double clo[HJ_BAND_DMAX], chi[HJ_BAND_DMAX];
        for (int k = 0; k < pb->d; k++) {
            j[k] = idx[k] + off[o][k];
            clo[k] = pb->lo[k] + (j[k] - 0.5) * sv->dx[k];
            chi[k] = clo[k] + sv->dx[k];
        }
        if (pb->avg0(clo, chi, pb->ctx) != v) return 0;
    }
    return 1;
}

/* Cells idx[0..d-2], j of D^0 (FS: every cell), in the scan's order. */
static int init_cell(hj_ub_solver *sv, hj_band_kind kind, int *idx, int j, int near, hj_error *err)
{
    const hj_ub_problem *pb = sv->pb;
    const int d = pb->d;
    idx[d - 1] = j;
    double clo[HJ_BAND_DMAX], chi[HJ_BAND_DMAX], blo[HJ_BAND_DMAX], bhi[HJ_BAND_DMAX];
    for (int k = 0; k < d; k++) {
        clo[k] = pb->lo[k] + (idx[k] - 0.5) * sv->dx[k];
        chi[k] = clo[k] + sv->dx[k];
        blo[k] = clo[k] - sv->dx[k];
        bhi[k] = chi[k] + sv->dx[k];
    }
    const double v = pb->avg0(clo, chi, pb->ctx);
    if (v == -1 && pb->reached) pb->reached(idx, 0.0, pb->ctx);
    /* D^0: the cells whose 3^d block is not uniform (FS: every cell).  The
     * scan visits the cells in lexicographic order, so each is appended
     * after the last cell of its list (O(1)): hj_band_insert searched the
     * list lines of SSD and CRS from their heads, O(m^2) for a line of m
     * band cells (a face of a square lying along a line: 1.6 s at n = 1e5,
     * more than 60 s at n = 1e6).  The store is the same, cell for cell. */
    if (kind == HJ_BAND_FS || !uniform_block(sv, idx, v, blo, bhi))
        return near ? hj_band_insert_near(sv->s, idx, v, err) : hj_band_append(sv->s, idx, v, err);
    return HJ_OK;
}

/* With a boundary value other than +1, a +1 cell on the domain's edge
 * differs from its neighbour outside, so it belongs to D^0 (uniform_block
 * says so) wherever it lies, and the scan of the bounding box sees only
 * those inside the box (widened: lo..hi; none when !scanned).  This pass
 * adds the others, after the scan (inserted from the list's last
 * position).  Before, every store but FS stopped at the first step with
 * "band invariant violated" when the set flowed in through the edge
 * (boundary -1). */
static int init_edges(hj_ub_solver *sv, hj_band_kind kind, const int *lo, const int *hi, int scanned, hj_error *err)
{
    const hj_ub_problem *pb = sv->pb;
    const int d = pb->d, n = pb->n;
    if (kind == HJ_BAND_FS || pb->boundary == 1) return HJ_OK;
    long lines = 1;
    for (int k = 0; k < d - 1; k++) lines *= n;
    int idx[HJ_BAND_DMAX];
    for (long c = 0; c < lines; c++) {
        long r = c;
        int edge = 0, inbox = scanned;
        for (int k = d - 2; k >= 0; k--) {
            idx[k] = (int)(r % n);
            r /= n;
            edge |= idx[k] == 0 || idx[k] == n - 1;
            inbox &= idx[k] >= lo[k] && idx[k] <= hi[k];
        }
        /* every cell of an edge line, else its two end cells */
        for (int j = 0; j < n; j = edge || j == n - 1 ? j + 1 : n - 1) {
            if (inbox && j >= lo[d - 1] && j <= hi[d - 1]) continue;
            const int rc = init_cell(sv, kind, idx, j, 1, err);
            if (rc) return rc;
        }
    }
    return HJ_OK;
}

/* Cells j0..j1 of a line, in order.  A run whose cells' 3^d blocks all lie
 * in one box where the data are constant (pb->uniform, else avg0 = +-1 on
 * the box, as uniform_block decides) holds no node of D^0: its cells are
 * only reported to pb->reached; other runs are halved, down to single
 * cells.  So the scan costs about the number of cells near the front,
 * not the volume of the box (the unit ball of Table 5 at N = 1600: 5e8
 * cells).  The box is widened by 1e-9 dx so that it holds every cell's
 * block despite round-off.  The grid's edge cells are always tested one
 * by one (there a uniform block may still be in D^0). */
static int init_cells(hj_ub_solver *sv, hj_band_kind kind, int *idx, int j0, int j1, hj_error *err)
{
    const hj_ub_problem *pb = sv->pb;
    const int d = pb->d, n = pb->n;
    int edge = kind == HJ_BAND_FS || j0 == 0 || j1 == n - 1 || j1 - j0 < 7;
    for (int k = 0; k < d - 1; k++) edge |= idx[k] == 0 || idx[k] == n - 1;
    if (edge && j1 - j0 >= 7 && kind != HJ_BAND_FS) { /* peel the edge cells off a long run */
        int rc;
        if (j0 == 0) {
            if ((rc = init_cell(sv, kind, idx, 0, 0, err))) return rc;
            return init_cells(sv, kind, idx, 1, j1, err);
        }
        if (j1 == n - 1) {
            if ((rc = init_cells(sv, kind, idx, j0, n - 2, err))) return rc;
            return init_cell(sv, kind, idx, n - 1, 0, err);
        }
    }
    if (edge) {
        for (int j = j0; j <= j1; j++) {
            const int rc = init_cell(sv, kind, idx, j, 0, err);
            if (rc) return rc;
        }
        return HJ_OK;
    }
    double blo[HJ_BAND_DMAX], bhi[HJ_BAND_DMAX];
    for (int k = 0; k < d; k++) {
        const int a = k < d - 1 ? idx[k] : j0, b = k < d - 1 ? idx[k] : j1;
        blo[k] = pb->lo[k] + (a - 1.5) * sv->dx[k] - 1e-9 * sv->dx[k];
        bhi[k] = pb->lo[k] + (b + 1.5) * sv->dx[k] + 1e-9 * sv->dx[k];
    }
    double b = 0;
    if (pb->uniform ? pb->uniform(blo, bhi, pb->ctx) : (b = pb->avg0(blo, bhi, pb->ctx)) == 1 || b == -1) {
        if (!pb->reached) return HJ_OK;
        double clo[HJ_BAND_DMAX], chi[HJ_BAND_DMAX];
        for (int k = 0; k < d; k++) {
            clo[k] = pb->lo[k] + ((k < d - 1 ? idx[k] : j0) - 0.5) * sv->dx[k];
            chi[k] = clo[k] + sv->dx[k];
        }
        if (pb->avg0(clo, chi, pb->ctx) == -1)
            for (int j = j0; j <= j1; j++) {
                idx[d - 1] = j;
                pb->reached(idx, 0.0, pb->ctx);
            }
        return HJ_OK;
    }
    const int mid = j0 + (j1 - j0) / 2;
    const int rc = init_cells(sv, kind, idx, j0, mid, err);
    return rc ? rc : init_cells(sv, kind, idx, mid + 1, j1, err);
}

int hj_ub_problem_check_shape(const hj_ub_problem *pb, int need_data, hj_error *err)
{
    if (pb->d < 2 || pb->d > HJ_BAND_DMAX)
        return hj_error_set(err, HJ_EINVAL, "problem: d = %d, need 2 <= d <= %d", pb->d, HJ_BAND_DMAX);
    if (pb->n < 3) return hj_error_set(err, HJ_EINVAL, "problem: n = %d nodes per direction, need n >= 3", pb->n);
    if (pb->ncontrols < 1)
        return hj_error_set(err, HJ_EINVAL, "problem: ncontrols = %d, need at least one control", pb->ncontrols);
    if (!(pb->cfl > 0) || pb->cfl > 1) return hj_error_set(err, HJ_EINVAL, "problem: cfl = %g, need 0 < cfl <= 1", pb->cfl);
    if (need_data && !pb->dyn) return hj_error_set(err, HJ_EINVAL, "problem: no dynamics (dyn is NULL)");
    if (need_data && !pb->avg0) return hj_error_set(err, HJ_EINVAL, "problem: no initial data (avg0 is NULL)");
    return HJ_OK;
}

int hj_ub_problem_check_values(const hj_ub_problem *pb, hj_error *err)
{
    for (int k = 0; k < pb->d && k < HJ_BAND_DMAX; k++)
        if (!isfinite(pb->lo[k]) || !isfinite(pb->hi[k]))
            return hj_error_set(err, HJ_EINVAL, "problem: domain [%g, %g] of direction %d is not finite", pb->lo[k],
                                pb->hi[k], k + 1);
    if (!isfinite(pb->boundary))
        return hj_error_set(err, HJ_EINVAL, "problem: the boundary value %g must be finite", pb->boundary);
    if (!(pb->snap >= 0 && pb->snap < 1))
        return hj_error_set(err, HJ_EINVAL, "problem: snap %g must be in [0, 1) (0: 1e-12)", pb->snap);
    if (!(pb->dtmax >= 0))
        return hj_error_set(err, HJ_EINVAL, "problem: dtmax %g must be >= 0 (0: no cap)", pb->dtmax);
    return HJ_OK;
}

static int ub_init(hj_ub_solver *sv, const hj_ub_problem *pb, hj_band_kind kind, hj_error *err)
{
    memset(sv, 0, sizeof *sv);
    sv->pb = pb;
    int rc = hj_ub_problem_check_shape(pb, 1, err);
    if (rc) return rc;
    rc = hj_ub_problem_check_values(pb, err);
    if (rc) return rc;
    /* the box is converted to cell indices (int) below */
    for (int k = 0; k < pb->d; k++) {
        if (!isfinite(pb->bbox_lo[k]) || !isfinite(pb->bbox_hi[k]))
            return hj_error_set(err, HJ_EINVAL, "problem: bounding box [%g, %g] of direction %d is not finite",
                                pb->bbox_lo[k], pb->bbox_hi[k], k + 1);
        if (pb->bbox_lo[k] > pb->bbox_hi[k])
            return hj_error_set(err, HJ_EINVAL, "problem: bounding box [%g, %g] of direction %d is empty (bbox_lo > bbox_hi)",
                                pb->bbox_lo[k], pb->bbox_hi[k], k + 1);
    }
    const int d = pb->d, n = pb->n;
    for (int k = 0; k < d; k++) {
        if (!(pb->hi[k] > pb->lo[k])) return hj_error_set(err, HJ_EINVAL, "problem: empty domain");
        sv->dx[k] = (pb->hi[k] - pb->lo[k]) / (n - 1);
    }
    rc = hj_band_new(&sv->s, kind, d, n, err);
    if (rc) return rc;
    /* scan the cells of the bounding box, widened by two cells */
    int lo[HJ_BAND_DMAX] = {0}, hi[HJ_BAND_DMAX] = {0}, idx[HJ_BAND_DMAX];
    long cells = 1;
    for (int k = 0; k < d; k++) {
        /* clamped to [-1, n] as doubles first: a box far beyond the domain
         * would overflow the conversion to int */
        double qlo = floor((pb->bbox_lo[k] - pb->lo[k]) / sv->dx[k]) - 2,
               qhi = ceil((pb->bbox_hi[k] - pb->lo[k]) / sv->dx[k]) + 2;
        qlo = qlo < 0 ? 0 : qlo > n ? n : qlo;
        qhi = qhi > n - 1 ? n - 1 : qhi < -1 ? -1 : qhi;
        lo[k] = (int)qlo, hi[k] = (int)qhi;
        cells *= hi[k] - lo[k] + 1;
    }
    for (int k = 0; k < d; k++)
        if (hi[k] < lo[k]) {
            /* The box lies beyond the domain: Omega_0 must then miss the
             * domain, which holds no cell of the set (before, a box placed
             * there by mistake started an empty band and the run went on). */
            double dlo[HJ_BAND_DMAX], dhi[HJ_BAND_DMAX];
            for (int j = 0; j < d; j++) {
                dlo[j] = pb->lo[j] - 0.5 * sv->dx[j];
                dhi[j] = pb->hi[j] + 0.5 * sv->dx[j];
            }
            const double v = pb->avg0(dlo, dhi, pb->ctx);
            if (!(v == 1))
                return hj_error_set(err, HJ_EINVAL,
                                    "problem: the bounding box [%g, %g] of direction %d lies outside the domain [%g, %g], "
                                    "but the data average %g, not 1, over the domain: Omega_0 is not inside the box",
                                    pb->bbox_lo[k], pb->bbox_hi[k], k + 1, pb->lo[k], pb->hi[k], v);
            return init_edges(sv, kind, lo, hi, 0, err); /* Omega_0 outside the domain */
        }
    /* the lines of the box (its first d - 1 indices), each along the last index */
    const long lines = cells / (hi[d - 1] - lo[d - 1] + 1);
    for (long c = 0; c < lines; c++) {
        long r = c;
        for (int k = d - 2; k >= 0; k--) {
            idx[k] = lo[k] + (int)(r % (hi[k] - lo[k] + 1));
            r /= hi[k] - lo[k] + 1;
        }
        if ((rc = init_cells(sv, kind, idx, lo[d - 1], hi[d - 1], err))) return rc;
    }
    /* The cells of the scanned box's faces lie at least 1.5 cells outside
     * the bounding box, so the data are +1 on each face that is not on the
     * domain's edge.  A box that does not contain Omega_0 (left at zero,
     * say) cut the set silently: the cells beyond it were never stored. */
    for (int k = 0; k < d; k++)
        for (int side = 0; side < 2; side++) {
            const int at = side ? hi[k] : lo[k];
            if (at == 0 || at == n - 1) continue;
            double flo[HJ_BAND_DMAX], fhi[HJ_BAND_DMAX];
            for (int j = 0; j < d; j++) {
                const int a = j == k ? at : lo[j], b = j == k ? at : hi[j];
                flo[j] = pb->lo[j] + (a - 0.5) * sv->dx[j];
                fhi[j] = pb->lo[j] + (b + 0.5) * sv->dx[j];
            }
            const double v = pb->avg0(flo, fhi, pb->ctx);
            if (!(v == 1))
                return hj_error_set(err, HJ_EINVAL,
                                    "problem: the bounding box [%g, %g] of direction %d does not contain Omega_0: the data "
                                    "average %g, not 1, over the cells two beyond its %s end",
                                    pb->bbox_lo[k], pb->bbox_hi[k], k + 1, v, side ? "upper" : "lower");
        }
    return init_edges(sv, kind, lo, hi, 1, err);
}

/* A refusal after the store was made (the bounding box's checks, out of
 * memory in the scan) frees it: sv is left as hj_ub_free leaves it. */
int hj_ub_init(hj_ub_solver *sv, const hj_ub_problem *pb, hj_band_kind kind, hj_error *err)
{
    const int rc = ub_init(sv, pb, kind, err);
    if (rc) hj_ub_free(sv);
    return rc;
}

/* ---- one step ---------------------------------------------------------------- */

typedef struct {
    hj_ub_solver *sv;
    size_t m;
} collect_ctx;

static int collect(const int *idx, double *v, void *vctx)
{
    collect_ctx *c = vctx;
    hj_ub_solver *sv = c->sv;
    sv->lin[c->m] = linear(sv->pb->d, sv->pb->n, idx);
    sv->ptr[c->m] = v;
    sv->v0[c->m] = *v;
    c->m++;
    return 0;
}

/* The 3^(d-1) offsets of the first d - 1 indices (the last index left 0):
 * Neigh(I) is walked as 3^(d-1) runs of nodes along the last index, each
 * run one search of the store (hj_band_find_run). */
static int line_offsets(int d, int off[][HJ_BAND_DMAX])
{
    int m = 0, total = 1;
    for (int i = 0; i < d - 1; i++) total *= 3;
    for (int c = 0; c < total; c++, m++) {
        int r = c;
        for (int i = 0; i < d - 1; i++) {
            off[m][i] = r % 3 - 1;
            r /= 3;
        }
        off[m][d - 1] = -1; /* the run starts one below */
    }
    return m;
}

/* The end of the segment that starts at snapshot node i0: the following
 * nodes of the same line with consecutive last indices. */
static size_t segment_end(const hj_ub_solver *sv, size_t i0, size_t m)
{
    const int64_t n = sv->pb->n;
    size_t i1 = i0 + 1;
    while (i1 < m && sv->lin[i1] == sv->lin[i1 - 1] + 1 && sv->lin[i1] % n != 0) i1++;
    return i1;
}

/* The store's pointers to nodes lo..hi (-1 <= lo, hi <= n - 1) of the line
 * of j (its first d - 1 indices): out[0 .. hi - lo], one run of the
 * store's search (hj_band_find_run): one list and one walk per segment
 * and neighbouring line instead of one per 3 nodes. */
static void line_run(hj_ub_solver *sv, const int *j, int lo, int hi, double **out)
{
    const int d = sv->pb->d;
    int q[HJ_BAND_DMAX];
    memcpy(q, j, (size_t)d * sizeof *q);
    q[d - 1] = lo;
    hj_band_find_run(sv->s, q, hi - lo + 1, out);
}

/* D^{n+1/2} = D^n + Neigh(D^n); a new node takes the value of the first
 * node of D^n (in the store's order) it neighbours.
 *
 * The band is walked in segments: nodes of one line with consecutive last
 * indices a..b.  Their neighbours on each of the 3^(d-1) lines are asked
 * of the store once per segment, as one run covering a-1..b+1 (one search
 * per segment and line instead of one per node).  A node absent then may have been
 * inserted since by an earlier node: it is looked up again before its
 * insert, so that the inserts, their order and their values are those of
 * the node-by-node walk. */
static int expand_band(hj_ub_solver *sv, hj_error *err)
{
    const int d = sv->pb->d, n = sv->pb->n;
    int rc = reserve(sv, hj_band_count(sv->s), err);
    if (rc) return rc;
    int loff[27][HJ_BAND_DMAX];
    const int nl = line_offsets(d, loff);
    const size_t span = (size_t)n + 2; /* last indices -1 .. n of one line */
    char *pres = malloc((size_t)nl * span);
    double **pp = malloc(span * sizeof *pp);
    if (!pres || !pp) {
        free(pres);
        free(pp);
        return hj_error_set(err, HJ_ENOMEM, "out of memory (band workspace)");
    }
    collect_ctx c = {sv, 0};
    hj_band_foreach(sv->s, collect, &c);
    for (size_t i0 = 0, i1; i0 < c.m && !rc; i0 = i1) {
        i1 = segment_end(sv, i0, c.m);
        int idx[HJ_BAND_DMAX], line_ok[27];
        unlin(d, n, sv->lin[i0], idx);
        const int a = idx[d - 1], b = a + (int)(i1 - i0) - 1, top = b + 1 < n - 1 ? b + 1 : n - 1;
        /* presence in D^n of the nodes a-1 .. top of each neighbouring line: pres[r span + 1 + j] */
        for (int r = 0; r < nl; r++) {
            int j[HJ_BAND_DMAX];
            line_ok[r] = 1;
            for (int q = 0; q < d - 1; q++) {
                j[q] = idx[q] + loff[r][q];
                line_ok[r] &= j[q] >= 0 && j[q] < n;
            }
            if (!line_ok[r]) continue;
            line_run(sv, j, a - 1, top, pp);
            for (int k = 0; k <= top - a + 1; k++) pres[(size_t)r * span + (size_t)(a + k)] = pp[k] != NULL;
        }
        for (size_t i = i0; i < i1 && !rc; i++) {
            const int jl = a + (int)(i - i0);
            for (int r = 0; r < nl && !rc; r++) {
                if (!line_ok[r]) continue;
                for (int k = 0; k < 3; k++) {
                    const int jk = jl - 1 + k;
                    char *pr = &pres[(size_t)r * span + (size_t)(jk + 1)];
                    if (jk < 0 || jk >= n || *pr) continue; /* outside, or stored (I itself too) */
                    int j[HJ_BAND_DMAX];
                    double *p;
                    for (int q = 0; q < d - 1; q++) j[q] = idx[q] + loff[r][q];
                    j[d - 1] = jk;
                    hj_band_find_run(sv->s, j, 1, &p); /* inserted by an earlier segment? */
                    *pr = 1;
                    if (p) continue;
                    if (sv->v0[i] != 1 && sv->v0[i] != -1) {
                        rc = hj_error_set(err, HJ_EINVAL, "band invariant violated: a value in ]-1,1[ next to an unstored node");
                        break;
                    }
                    if ((rc = hj_band_insert_near(sv->s, j, sv->v0[i], err))) break;
                }
            }
        }
    }
    free(pres);
    free(pp);
    return rc;
}

/* Value slots temporarily hold the node's position in the snapshot, so that
 * the store's own neighbour search gives the links. */
static int snapshot(hj_ub_solver *sv, size_t *m, hj_error *err)
{
    const int d = sv->pb->d, n = sv->pb->n;
    int rc = reserve(sv, hj_band_count(sv->s), err);
    if (rc) return rc;
    double **pp = malloc((size_t)n * sizeof *pp);
    if (!pp) return hj_error_set(err, HJ_ENOMEM, "out of memory (band workspace)");
    collect_ctx c = {sv, 0};
    hj_band_foreach(sv->s, collect, &c);
    *m = c.m;
    for (size_t i = 0; i < c.m; i++) *sv->ptr[i] = (double)i;
    const size_t L = 2 * (size_t)d;
    for (size_t i0 = 0, i1; i0 < c.m; i0 = i1) {
        i1 = segment_end(sv, i0, c.m);
        int idx[HJ_BAND_DMAX];
        unlin(d, n, sv->lin[i0], idx);
        const int a = idx[d - 1], b = a + (int)(i1 - i0) - 1;
        for (size_t i = i0; i < i1; i++) { /* centres once per step, for every control */
            idx[d - 1] = a + (int)(i - i0);
            hj_ub_centre(sv, idx, &sv->x[i * (size_t)d]);
        }
        idx[d - 1] = a;
        /* the segment's neighbouring lines, one run of searches each */
        for (int k = 0; k < d - 1; k++)
            for (int s = 0; s < 2; s++) {
                idx[k] += s ? 1 : -1;
                const int out = idx[k] < 0 || idx[k] >= n;
                if (!out) line_run(sv, idx, a, b, pp);
                for (size_t i = i0; i < i1; i++)
                    sv->link[i * L + 2 * (size_t)k + (size_t)s] = out ? -2 : pp[i - i0] ? (int32_t)*pp[i - i0] : -1;
                idx[k] -= s ? 1 : -1;
            }
        /* along the last index: the segment's own nodes, and its two ends */
        for (size_t i = i0; i < i1; i++) {
            const int j = a + (int)(i - i0);
            int32_t *l = &sv->link[i * L + L - 2];
            for (int s = 0; s < 2; s++) {
                const int jn = j + (s ? 1 : -1);
                if (jn < 0 || jn >= n) l[s] = -2;
                else if (s ? i + 1 < i1 : i > i0) l[s] = (int32_t)(s ? i + 1 : i - 1);
                else {
                    double *p;
                    idx[d - 1] = jn;
                    hj_band_find_run(sv->s, idx, 1, &p);
                    l[s] = p ? (int32_t)*p : -1;
                }
            }
        }
    }
    free(pp);
    return HJ_OK;
}

static int time_step(hj_ub_solver *sv, size_t m, double tmax, double *dt, hj_error *err)
{
    const hj_ub_problem *pb = sv->pb;
    double rate = 0, f[HJ_BAND_DMAX], x[HJ_BAND_DMAX];
    for (int a = 0; a < pb->ncontrols; a++)
        for (size_t i = 0; i < m; i++) {
            memcpy(x, &sv->x[i * pb->d], (size_t)pb->d * sizeof *x);
            pb->dyn(sv->t, x, a, f, pb->ctx);
            for (int k = 0; k < pb->d; k++) {
                /* a NaN would drop out of the max and an infinity give
                 * dt = 0: steps that never reach tmax */
                if (!isfinite(f[k])) {
                    char at[128];
                    int len = 0;
                    for (int q = 0; q < pb->d; q++)
                        len += snprintf(at + len, sizeof at - (size_t)len, "%s%g", q ? ", " : "", x[q]);
                    return hj_error_set(err, HJ_ENONFINITE,
                                        "dynamics: f_%d = %g at x = (%s), control %d, t = %g (must be finite)", k,
                                        f[k], at, a, sv->t);
                }
                const double r = fabs(f[k]) / sv->dx[k];
                rate = r > rate ? r : rate;
            }
        }
    const double left = tmax - sv->t;
    *dt = rate * left <= pb->cfl ? left : pb->cfl / rate;
    if (pb->dtmax > 0 && *dt > pb->dtmax) *dt = pb->dtmax;
    return HJ_OK;
}

/* mu of direction k at the cell next to node i (s = 0: left, 1: right). */
static double mu_beside(hj_ub_solver *sv, size_t i, int k, int s, int a, double dt)
{
    double x[HJ_BAND_DMAX], f[HJ_BAND_DMAX];
    memcpy(x, &sv->x[i * sv->pb->d], (size_t)sv->pb->d * sizeof *x);
    x[k] += s ? sv->dx[k] : -sv->dx[k];
    sv->pb->dyn(sv->t, x, a, f, sv->pb->ctx);
    return dt / sv->dx[k] * f[k];
}

/* One sweep in direction k for control a: wn = UB update of w. */
static void sweep(hj_ub_solver *sv, size_t m, int k, int a, double dt, const double *restrict w, double *restrict wn)
{
    const int d = sv->pb->d;
    const double bnd = sv->pb->boundary;
    for (size_t i = 0; i < m; i++) {
        double w5[5], mu3[3];
        w5[2] = w[i];
        mu3[1] = sv->mu[i * d + k];
        for (int s = 0; s < 2; s++) {
            const int32_t n1 = sv->link[i * 2 * d + 2 * k + s];
            double w1, w2, m1;
            if (n1 >= 0) {
                const int32_t n2 = sv->link[(size_t)n1 * 2 * d + 2 * k + s];
                w1 = w[n1];
                m1 = sv->mu[(size_t)n1 * d + k];
                w2 = n2 >= 0 ? w[n2] : n2 == -1 ? sv->v0[n1] : bnd;
            } else {
                /* not stored: the value of this node at t_n; outside: boundary */
                w1 = w2 = n1 == -1 ? sv->v0[i] : bnd;
                m1 = mu_beside(sv, i, k, s, a, dt);
            }
            w5[s ? 3 : 1] = w1;
            w5[s ? 4 : 0] = w2;
            mu3[s ? 2 : 0] = m1;
        }
        wn[i] = ub_update(w5, mu3);
    }
}

/* D^{n+1} = D^{n+1/2} minus the +-1 nodes equal to every node of Neigh(I)
 * (an unstored node: I's value at t_n; outside: the boundary value).
 * Segment by segment: the 2d axis neighbours come first, from the links,
 * without a search (most nodes that stay differ there); a neighbouring
 * line's nodes a-1..b+1 are asked of the store once per segment, when a
 * node first needs them; a node's test stops at the first value that
 * differs.  No store change until every node is tested. */
static int reduce_band(hj_ub_solver *sv, size_t m, hj_error *err)
{
    const int d = sv->pb->d, n = sv->pb->n;
    const double bnd = sv->pb->boundary;
    int loff[27][HJ_BAND_DMAX];
    const int nl = line_offsets(d, loff);
    const size_t span = (size_t)n + 2, L = 2 * (size_t)d;
    double **pp = malloc((size_t)nl * span * sizeof *pp);
    int64_t *gone = malloc((m ? m : 1) * sizeof *gone);
    if (!pp || !gone) {
        free(pp);
        free(gone);
        return hj_error_set(err, HJ_ENOMEM, "out of memory (band workspace)");
    }
    size_t ngone = 0;
    for (size_t i0 = 0, i1; i0 < m; i0 = i1) {
        i1 = segment_end(sv, i0, m);
        int idx[HJ_BAND_DMAX], got[27] = {0};
        unlin(d, n, sv->lin[i0], idx);
        const int a = idx[d - 1], b = a + (int)(i1 - i0) - 1, top = b + 1 < n - 1 ? b + 1 : n - 1;
        for (size_t i = i0; i < i1; i++) {
            const double v = sv->vmin[i];
            int keep = v != 1 && v != -1;
            for (size_t q = 0; q < L && !keep; q++) {
                const int32_t l = sv->link[i * L + q];
                keep = (l >= 0 ? sv->vmin[l] : l == -1 ? sv->v0[i] : bnd) != v;
            }
            const int jl = a + (int)(i - i0);
            for (int r = 0; r < nl && !keep; r++) {
                int j[HJ_BAND_DMAX], ok = 1;
                for (int q = 0; q < d - 1; q++) {
                    j[q] = idx[q] + loff[r][q];
                    ok &= j[q] >= 0 && j[q] < n;
                }
                if (!ok) {
                    keep = bnd != v;
                    continue;
                }
                double **p = pp + (size_t)r * span;
                if (!got[r]) {
                    line_run(sv, j, a - 1, top, p);
                    got[r] = 1;
                }
                for (int k = 0; k < 3 && !keep; k++) {
                    const int jk = jl - 1 + k;
                    keep = (jk < 0 || jk >= n ? bnd : p[jk - a + 1] ? *p[jk - a + 1] : sv->v0[i]) != v;
                }
            }
            if (!keep) gone[ngone++] = sv->lin[i];
        }
    }
    for (size_t i = 0; i < ngone; i++) {
        int idx[HJ_BAND_DMAX];
        unlin(d, n, gone[i], idx);
        hj_band_remove_near(sv->s, idx); /* in order: from the last removal */
    }
    free(pp);
    free(gone);
    return HJ_OK;
}

int hj_ub_step(hj_ub_solver *sv, double tmax, hj_error *err)
{
    const hj_ub_problem *pb = sv->pb;
    const int d = pb->d;
    int rc;
    if (isnan(tmax)) return hj_error_set(err, HJ_EINVAL, "step: the final time is NaN");
    if (!(tmax > sv->t)) return HJ_OK;
    if (hj_band_kind_of(sv->s) != HJ_BAND_FS && (rc = expand_band(sv, err))) return rc;
    size_t m = 0;
    if ((rc = snapshot(sv, &m, err))) return rc;
    sv->band_sum += (double)m;
    sv->band_max = m > sv->band_max ? m : sv->band_max;
    double dt = 0;
    if ((rc = time_step(sv, m, tmax, &dt, err))) return rc;
    const double snap = pb->snap > 0 ? pb->snap : 1e-12;
    for (int a = 0; a < pb->ncontrols; a++) {
        for (size_t i = 0; i < m; i++) {
            double x[HJ_BAND_DMAX];
            memcpy(x, &sv->x[i * d], (size_t)d * sizeof *x);
            pb->dyn(sv->t, x, a, &sv->f[i * d], pb->ctx);
            for (int k = 0; k < d; k++) sv->mu[i * d + k] = dt / sv->dx[k] * sv->f[i * d + k];
        }
        for (int k = 0; k < d; k++) { /* the first sweep reads V^n itself */
            sweep(sv, m, k, a, dt, k ? sv->w : sv->v0, sv->wn);
            double *tmp = sv->w;
            sv->w = sv->wn;
            sv->wn = tmp;
        }
        for (size_t i = 0; i < m; i++)
            if (a == 0 || sv->w[i] < sv->vmin[i]) sv->vmin[i] = sv->w[i];
    }
    for (size_t i = 0; i < m; i++) {
        double v = sv->vmin[i];
        if (pb->target && sv->v0[i] < v) v = sv->v0[i];
        v = v > 1 - snap ? 1 : v < -1 + snap ? -1 : v;
        sv->vmin[i] = v;
        *sv->ptr[i] = v;
        if (pb->reached && v == -1 && sv->v0[i] != -1) {
            int idx[HJ_BAND_DMAX];
            unlin(d, pb->n, sv->lin[i], idx);
            pb->reached(idx, sv->t + dt, pb->ctx);
        }
    }
    /* D^{n+1} = D^{n+1/2} minus the +-1 nodes equal to all their neighbours */
    if (hj_band_kind_of(sv->s) != HJ_BAND_FS && (rc = reduce_band(sv, m, err))) return rc;
    sv->t = dt == tmax - sv->t ? tmax : sv->t + dt;
    sv->steps++;
    return HJ_OK;
}

int hj_ub_run(hj_ub_solver *sv, double T, hj_error *err)
{
    if (!isfinite(T)) return hj_error_set(err, HJ_EINVAL, "run: the final time must be finite, got %g", T);
    while (sv->t < T) {
        int rc = hj_ub_step(sv, T, err);
        if (rc) return rc;
    }
    return HJ_OK;
}

/* ---- errors and values (hj_front) --------------------------------------- */

int hj_ub_errors(hj_ub_solver *sv, hj_front_inside_fn inside, void *ctx, double *l1, double *haus, hj_error *err)
{
    return hj_front_band_errors(sv->s, sv->pb->lo, sv->dx, sv->pb->front_sub, inside, ctx, l1, haus, err);
}

int hj_ub_values(hj_ub_solver *sv, double *out, hj_error *err) { return hj_front_band_values(sv->s, out, err); }

/* ---- the same problem for the level set kernel -------------------------- */

void hj_ub_control_velocity(double t, const double *x, double dx0, long n, int d, double *v, void *ctx)
{
    const hj_ub_control *c = ctx;
    double y[HJ_LS_MAXDIM], f[HJ_LS_MAXDIM];
    memcpy(y, x, sizeof y);
    for (long j = 0; j < n; j++) {
        y[0] = x[0] + (double)j * dx0;
        c->dyn(c->frozen ? c->tfix : t, y, c->a, f, c->ctx);
        v[j] = f[d];
    }
}
