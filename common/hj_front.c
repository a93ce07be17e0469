/* hj_front.c -- L1 error and Hausdorff distance of section 4 (see hj_front.h). */
#include "hj_front.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* sign(V) = -1 for V <= ZERO: cells cut in half by the front have V = 0 up to
 * the round-off of the fluxes, and must not flip sign with it. */
#define ZERO 1e-12

/* ---- Hausdorff distance between point sets, by bucketing ----------------- */

typedef struct {
    int d;
    const double *p;
    double h, origin[HJ_BAND_DMAX];
    int64_t base;
    int64_t *key; /* bucket key of each point, sorted with order[] */
    size_t *order, n;
} bucket_set;

static int64_t bucket_key(const bucket_set *b, const int64_t *c)
{
    int64_t k = 0;
    for (int i = 0; i < b->d; i++) k = k * b->base + c[i];
    return k;
}

static void bucket_of(const bucket_set *b, const double *x, int64_t *c)
{
    for (int i = 0; i < b->d; i++) c[i] = (int64_t)floor((x[i] - b->origin[i]) / b->h);
}

static const bucket_set *sort_set;
static int by_key(const void *x, const void *y)
{
    const int64_t a = sort_set->key[*(const size_t *)x], c = sort_set->key[*(const size_t *)y];
    return (a > c) - (a < c);
}

static int bucket_build(bucket_set *b, int d, const double *p, size_t n, double h, const double *origin, int64_t base)
{
    b->d = d;
    b->p = p;
    b->n = n;
    b->h = h;
    b->base = base;
    memcpy(b->origin, origin, sizeof b->origin);
    b->key = malloc((n ? n : 1) * sizeof *b->key);
    b->order = malloc((n ? n : 1) * sizeof *b->order);
    if (!b->key || !b->order) return HJ_ENOMEM;
    for (size_t i = 0; i < n; i++) {
        int64_t c[HJ_BAND_DMAX];
        bucket_of(b, &p[i * d], c);
        b->key[i] = bucket_key(b, c);
        b->order[i] = i;
    }
    sort_set = b;
    qsort(b->order, n, sizeof *b->order, by_key);
    /* keys in sorted order, for bisection */
    int64_t *sk = malloc((n ? n : 1) * sizeof *sk);
    if (!sk) return HJ_ENOMEM;
    for (size_t i = 0; i < n; i++) sk[i] = b->key[b->order[i]];
    free(b->key);
    b->key = sk;
    return HJ_OK;
}

static double dist2(int d, const double *x, const double *y)
{
    double s = 0;
    for (int i = 0; i < d; i++) s += (x[i] - y[i]) * (x[i] - y[i]);
    return s;
}

/* Distance from x to the nearest point of b: rings of buckets of growing
 * Chebyshev radius until the ring is farther than the best point found. */
static double nearest(const bucket_set *b, const double *x)
{
    const int d = b->d;
    int64_t c[HJ_BAND_DMAX], q[HJ_BAND_DMAX];
    bucket_of(b, x, c);
    double best = INFINITY;
    for (int r = 0; r <= 64; r++) {
        if ((r - 1) * b->h > 0 && ((double)(r - 1) * b->h) * ((double)(r - 1) * b->h) > best) return sqrt(best);
        long side = 2 * r + 1, total = 1;
        for (int i = 0; i < d; i++) total *= side;
        for (long s = 0; s < total; s++) {
            long t = s;
            int shell = 0;
            for (int i = 0; i < d; i++) {
                const int o = (int)(t % side) - r;
                q[i] = c[i] + o;
                shell |= o == r || o == -r;
                t /= side;
            }
            if (!shell && r > 0) continue;
            const int64_t key = bucket_key(b, q);
            size_t lo = 0, hi = b->n;
            while (lo < hi) {
                size_t mid = lo + (hi - lo) / 2;
                if (b->key[mid] < key) lo = mid + 1; else hi = mid;
            }
            for (; lo < b->n && b->key[lo] == key; lo++) {
                const double e = dist2(d, x, &b->p[b->order[lo] * d]);
                best = e < best ? e : best;
            }
        }
    }
    /* far away: plain search */
    for (size_t i = 0; i < b->n; i++) {
        const double e = dist2(d, x, &b->p[i * d]);
        best = e < best ? e : best;
    }
    return sqrt(best);
}

int hj_front_hausdorff(int d, const double *a, size_t na, const double *b, size_t nb, double h, double *out, hj_error *err)
{
    if (na == 0 || nb == 0) { *out = (na == 0 && nb == 0) ? 0 : INFINITY; return HJ_OK; }
    double origin[HJ_BAND_DMAX] = {0}, top[HJ_BAND_DMAX] = {0};
    for (int i = 0; i < d; i++) origin[i] = top[i] = a[i];
    for (size_t s = 0; s < na + nb; s++) {
        const double *x = s < na ? &a[s * d] : &b[(s - na) * d];
        for (int i = 0; i < d; i++) {
            origin[i] = x[i] < origin[i] ? x[i] : origin[i];
            top[i] = x[i] > top[i] ? x[i] : top[i];
        }
    }
    double span = 0;
    for (int i = 0; i < d; i++) span = top[i] - origin[i] > span ? top[i] - origin[i] : span;
    for (int i = 0; i < d; i++) origin[i] -= 100 * h; /* room for the rings */
    const int64_t base = (int64_t)(span / h) + 300;
    bucket_set A = {0}, B = {0};
    int rc = bucket_build(&A, d, a, na, h, origin, base);
    if (!rc) rc = bucket_build(&B, d, b, nb, h, origin, base);
    if (rc) {
        free(A.key); free(A.order); free(B.key); free(B.order);
        return hj_error_set(err, HJ_ENOMEM, "out of memory (Hausdorff distance)");
    }
    double hd = 0;
    for (size_t i = 0; i < na; i++) { double e = nearest(&B, &a[i * d]); hd = e > hd ? e : hd; }
    for (size_t i = 0; i < nb; i++) { double e = nearest(&A, &b[i * d]); hd = e > hd ? e : hd; }
    free(A.key); free(A.order); free(B.key); free(B.order);
    *out = hd;
    return HJ_OK;
}

/* ---- growing point lists ------------------------------------------------------ */

typedef struct {
    double *p;
    size_t n, cap;
    int d, failed;
} points;

static void push(points *s, const double *x)
{
    if (s->failed) return;
    if (s->n == s->cap) {
        size_t cap = s->cap ? 2 * s->cap : 1024;
        double *np = realloc(s->p, cap * s->d * sizeof *np);
        if (!np) { s->failed = 1; return; }
        s->p = np;
        s->cap = cap;
    }
    memcpy(&s->p[s->n * s->d], x, s->d * sizeof *x);
    s->n++;
}

/* ---- the computed front and the line values ------------------------------------ */

static void centre(int d, const double *lo, const double *dx, const int *idx, double *x)
{
    for (int k = 0; k < d; k++) x[k] = lo[k] + idx[k] * dx[k]; /* as hj_ub_centre */
}

typedef struct {
    hj_band *s;
    int d, n;
    const double *lo, *dx;
    points *front;
    signed char *line; /* per line: 0 empty, +-2 non-empty with stored +-1 nodes of that value,
                          4 non-empty without; empty lines get +-1 from fill_lines */
} front_ctx;

static int visit_front(const int *idx, double *v, void *vctx)
{
    front_ctx *c = vctx;
    const int d = c->d, n = c->n;
    int64_t line = 0;
    for (int k = 0; k < d - 1; k++) line = line * n + idx[k];
    if (*v == 1 || *v == -1) c->line[line] = (signed char)(2 * *v);
    else if (c->line[line] == 0) c->line[line] = 4; /* non-empty, value not known yet */
    if (*v > ZERO || !c->front) return 0;
    /* a cell of the computed set {V <= 0} with a face neighbour outside it */
    int j[HJ_BAND_DMAX];
    memcpy(j, idx, sizeof j);
    for (int k = 0; k < d; k++)
        for (int s = -1; s <= 1; s += 2) {
            j[k] = idx[k] + s;
            if (j[k] >= 0 && j[k] < n) {
                const double *p = hj_band_find(c->s, j);
                if (p && *p > ZERO) {
                    double x[HJ_BAND_DMAX];
                    centre(d, c->lo, c->dx, idx, x);
                    push(c->front, x);
                    return 0;
                }
            }
            j[k] = idx[k];
        }
    return 0;
}

/* Empty lines take the value of a neighbouring line (breadth first). */
static int fill_lines(signed char *line, int64_t nl, int dl, int n, hj_error *err)
{
    int64_t *queue = malloc((size_t)nl * sizeof *queue), head = 0, tail = 0;
    if (!queue) return hj_error_set(err, HJ_ENOMEM, "out of memory (line values)");
    for (int64_t l = 0; l < nl; l++)
        if (line[l] == 2 || line[l] == -2) queue[tail++] = l;
    while (head < tail) {
        const int64_t l = queue[head++];
        const signed char c = line[l] > 0 ? 1 : -1;
        int64_t stride = 1;
        for (int k = dl - 1; k >= 0; k--) {
            const int i = (int)((l / stride) % n);
            if (i > 0 && line[l - stride] == 0) { line[l - stride] = c; queue[tail++] = l - stride; }
            if (i < n - 1 && line[l + stride] == 0) { line[l + stride] = c; queue[tail++] = l + stride; }
            stride *= n;
        }
    }
    for (int64_t l = 0; l < nl; l++)
        if (line[l] == 0) line[l] = 1; /* no front anywhere: outside */
    free(queue);
    return HJ_OK;
}

/* The point where the exact front crosses the segment [x, y] (bisection). */
static void crossing(int d, const double *x, const double *y, int in_x, hj_front_inside_fn inside, void *ctx, double tol,
                     double *out)
{
    double a[HJ_BAND_DMAX], b[HJ_BAND_DMAX], m[HJ_BAND_DMAX];
    memcpy(a, x, d * sizeof *a);
    memcpy(b, y, d * sizeof *b);
    for (int it = 0; it < 60; it++) {
        double len2 = dist2(d, a, b);
        if (len2 <= tol * tol) break;
        for (int i = 0; i < d; i++) m[i] = 0.5 * (a[i] + b[i]);
        if (inside(m, ctx) == in_x) memcpy(a, m, d * sizeof *a); else memcpy(b, m, d * sizeof *b);
    }
    for (int i = 0; i < d; i++) out[i] = 0.5 * (a[i] + b[i]);
}

/* The crossings of the exact front with the sub^(d-1) segments parallel to
 * [x, y] (direction k) through the points x + o, o_j = (s_j / sub - 1/2)
 * dx_j (j != k, s_j = 0 .. sub - 1): the lattice lines refined sub times in
 * the strip of cells around the segment.  A sub-segment whose ends are on
 * the same side gives no point. */
static void sub_crossings(int d, int k, const double *x, const double *y, const double *dx, int sub,
                          hj_front_inside_fn inside, void *ctx, double tol, points *exact)
{
    int64_t count = 1;
    for (int j = 0; j < d - 1; j++) count *= sub;
    for (int64_t t = 0; t < count; t++) {
        double xs[HJ_BAND_DMAX], ys[HJ_BAND_DMAX], c[HJ_BAND_DMAX];
        int64_t r = t;
        for (int j = 0; j < d; j++) {
            double o = 0;
            if (j != k) {
                o = ((double)(r % sub) / sub - 0.5) * dx[j];
                r /= sub;
            }
            xs[j] = x[j] + o;
            ys[j] = y[j] + o;
        }
        const int in_x = inside(xs, ctx) != 0;
        if (in_x == (inside(ys, ctx) != 0)) continue;
        crossing(d, xs, ys, in_x, inside, ctx, tol, c);
        push(exact, c);
    }
}

/* The exact signs of the lines already visited: lines are visited in
 * order, and the -e_k neighbour line of line l is l - n^(d-2-k), so the
 * last n^(d-2) + 1 lines are kept (n^(d-1) bytes). */
typedef struct {
    signed char *in;
    int64_t slots;
} sign_ring;

static int ring_init(sign_ring *r, int d, int n)
{
    r->slots = 1;
    for (int k = 0; k < d - 2; k++) r->slots *= n;
    r->slots += 1;
    r->in = malloc((size_t)r->slots * (size_t)n);
    return r->in ? HJ_OK : HJ_ENOMEM;
}

/* One line along the last index (line number l, idx[0..d-2] set, vals its
 * n values): the cells whose sign is wrong, and the crossings of the exact
 * front between each cell and its -e_k neighbours (the lower cell first,
 * as a sweep towards +e_k would find them), with the signs of the lower
 * lines taken from the ring: inside() once per cell.  Shared by the band
 * (UB) and the full grid (LS). */
static int64_t line_errors(int d, int n, const double *lo, const double *dx, int64_t l, int *idx, const double *vals,
                           sign_ring *ring, hj_front_inside_fn inside, void *ctx, double hmin, int sub, points *exact)
{
    int64_t wrong = 0;
    signed char *in = &ring->in[(size_t)(l % ring->slots) * (size_t)n];
    for (int i = 0; i < n; i++) {
        double x[HJ_BAND_DMAX];
        idx[d - 1] = i;
        centre(d, lo, dx, idx, x);
        in[i] = (signed char)(inside(x, ctx) != 0);
        wrong += (vals[i] <= ZERO) != (in[i] != 0);
    }
    int64_t stride = 1;
    for (int k = d - 1; k >= 0; k--) {
        if (k < d - 1 && idx[k] == 0) { stride *= k == d - 1 ? 1 : n; continue; }
        const signed char *below = k == d - 1 ? in : &ring->in[(size_t)((l - stride) % ring->slots) * (size_t)n];
        for (int i = k == d - 1 ? 1 : 0; i < n; i++) {
            const int i_lo = k == d - 1 ? i - 1 : i;
            if (below[i_lo] == in[i]) continue;
            double x[HJ_BAND_DMAX], y[HJ_BAND_DMAX], c[HJ_BAND_DMAX];
            idx[d - 1] = i;
            centre(d, lo, dx, idx, y);
            idx[k]--; /* the lower cell's own centre */
            centre(d, lo, dx, idx, x);
            idx[k]++;
            if (sub <= 1) {
                crossing(d, x, y, below[i_lo], inside, ctx, 1e-6 * hmin, c);
                push(exact, c);
            } else {
                sub_crossings(d, k, x, y, dx, sub, inside, ctx, 1e-6 * hmin, exact);
            }
        }
        if (k < d - 1) stride *= n;
    }
    return wrong;
}

/* The values of line idx[0..d-2] (line state ls, from fill_lines): stored
 * ones, gaps from the stored neighbour. */
static void line_values(hj_band *s, signed char ls, int *idx, double *vals)
{
    const int d = hj_band_dim(s), n = hj_band_size(s);
    for (int i = 0; i < n; i++) {
        idx[d - 1] = i;
        const double *p = (ls == 1 || ls == -1) ? NULL : hj_band_find(s, idx);
        vals[i] = p ? *p : (ls == 1 || ls == -1) ? ls : NAN;
    }
    double last = NAN;
    for (int i = 0; i < n; i++) if (isnan(vals[i])) vals[i] = last; else last = vals[i];
    last = NAN;
    for (int i = n - 1; i >= 0; i--) if (isnan(vals[i])) vals[i] = last; else last = vals[i];
}

int hj_front_band_values(hj_band *s, double *out, hj_error *err)
{
    const int d = hj_band_dim(s), n = hj_band_size(s);
    int64_t nl = 1;
    for (int k = 0; k < d - 1; k++) nl *= n;
    signed char *line = calloc((size_t)nl, 1);
    if (!line) return hj_error_set(err, HJ_ENOMEM, "out of memory (line values)");
    front_ctx fc = {s, d, n, NULL, NULL, NULL, line};
    hj_band_foreach(s, visit_front, &fc);
    int rc = fill_lines(line, nl, d - 1, n, err);
    for (int64_t l = 0; l < nl && !rc; l++) {
        int idx[HJ_BAND_DMAX];
        int64_t r = l;
        for (int k = d - 2; k >= 0; k--) { idx[k] = (int)(r % n); r /= n; }
        line_values(s, line[l], idx, out + l * n);
    }
    free(line);
    return rc;
}

int hj_front_band_errors(hj_band *s, const double *lo, const double *dx, int sub, hj_front_inside_fn inside,
                         void *ctx, double *l1, double *haus, hj_error *err)
{
    const int d = hj_band_dim(s), n = hj_band_size(s);
    int64_t nl = 1;
    for (int k = 0; k < d - 1; k++) nl *= n;
    signed char *line = calloc((size_t)nl, 1);
    double *vals = malloc((size_t)n * sizeof *vals);
    sign_ring ring;
    const int ring_rc = ring_init(&ring, d, n);
    points front = {NULL, 0, 0, d, 0}, exact = {NULL, 0, 0, d, 0};
    int rc = HJ_OK;
    if (!line || !vals || ring_rc) { rc = hj_error_set(err, HJ_ENOMEM, "out of memory (errors)"); goto done; }
    front_ctx fc = {s, d, n, lo, dx, &front, line};
    hj_band_foreach(s, visit_front, &fc);
    if ((rc = fill_lines(line, nl, d - 1, n, err))) goto done;
    double cellvol = 1, hmin = dx[0];
    for (int k = 0; k < d; k++) {
        cellvol *= dx[k];
        hmin = dx[k] < hmin ? dx[k] : hmin;
    }
    int64_t wrong = 0;
    for (int64_t l = 0; l < nl; l++) {
        int idx[HJ_BAND_DMAX];
        int64_t r = l;
        for (int k = d - 2; k >= 0; k--) { idx[k] = (int)(r % n); r /= n; }
        line_values(s, line[l], idx, vals);
        wrong += line_errors(d, n, lo, dx, l, idx, vals, &ring, inside, ctx, hmin, sub, &exact);
    }
    if (front.failed || exact.failed) { rc = hj_error_set(err, HJ_ENOMEM, "out of memory (front points)"); goto done; }
    *l1 = cellvol * (double)wrong;
    rc = hj_front_hausdorff(d, front.p, front.n, exact.p, exact.n, hmin, haus, err);
done:
    free(line);
    free(vals);
    free(ring.in);
    free(front.p);
    free(exact.p);
    return rc;
}

int hj_front_grid_errors(int d, int n, const double *lo, const double *dx, hj_front_value_fn value, void *vctx,
                    hj_front_inside_fn inside, void *ctx, int sub, double *l1, double *haus, int64_t *ncells,
                    hj_error *err)
{
    double *vals = malloc((size_t)n * sizeof *vals);
    sign_ring ring;
    const int ring_rc = ring_init(&ring, d, n);
    points front = {NULL, 0, 0, d, 0}, exact = {NULL, 0, 0, d, 0};
    int rc = HJ_OK;
    if (!vals || ring_rc) { rc = hj_error_set(err, HJ_ENOMEM, "out of memory (errors)"); goto done; }
    int64_t nl = 1, wrong = 0, neg = 0;
    for (int k = 0; k < d - 1; k++) nl *= n;
    double cellvol = 1, hmin = dx[0];
    for (int k = 0; k < d; k++) {
        cellvol *= dx[k];
        hmin = dx[k] < hmin ? dx[k] : hmin;
    }
    for (int64_t l = 0; l < nl; l++) {
        int idx[HJ_BAND_DMAX], j[HJ_BAND_DMAX];
        int64_t r = l;
        for (int k = d - 2; k >= 0; k--) { idx[k] = (int)(r % n); r /= n; }
        for (int i = 0; i < n; i++) {
            idx[d - 1] = i;
            vals[i] = value(idx, vctx);
            if (vals[i] > ZERO) continue;
            neg++;
            /* the computed front: {V <= 0} cells with a face neighbour V > 0 */
            memcpy(j, idx, sizeof j);
            int edge = 0;
            for (int k = 0; k < d && !edge; k++)
                for (int s = -1; s <= 1 && !edge; s += 2) {
                    j[k] = idx[k] + s;
                    edge = j[k] >= 0 && j[k] < n && value(j, vctx) > ZERO;
                    j[k] = idx[k];
                }
            if (edge) {
                double x[HJ_BAND_DMAX];
                centre(d, lo, dx, idx, x);
                push(&front, x);
            }
        }
        wrong += line_errors(d, n, lo, dx, l, idx, vals, &ring, inside, ctx, hmin, sub, &exact);
    }
    if (front.failed || exact.failed) { rc = hj_error_set(err, HJ_ENOMEM, "out of memory (front points)"); goto done; }
    *l1 = cellvol * (double)wrong;
    if (ncells) *ncells = neg;
    rc = hj_front_hausdorff(d, front.p, front.n, exact.p, exact.n, hmin, haus, err);
done:
    free(vals);
    free(ring.in);
    free(front.p);
    free(exact.p);
    return rc;
}

typedef struct {
    const hj_ls_grid *g;
    const double *y;
} ls_field;

static double ls_value(const int *idx, void *vctx)
{
    const ls_field *f = vctx;
    long i[HJ_LS_MAXDIM];
    for (int k = 0; k < f->g->dim; k++) i[k] = idx[k];
    return f->y[hj_ls_index(f->g, i)];
}

int hj_front_ls_errors(const hj_ls_grid *g, const double *y, hj_front_inside_fn inside, void *ctx, int sub,
                       double *l1, double *haus, int64_t *ncells, hj_error *err)
{
    ls_field f = {g, y};
    return hj_front_grid_errors(g->dim, (int)g->N[0], g->min, g->dx, ls_value, &f, inside, ctx, sub, l1, haus, ncells,
                                err);
}
