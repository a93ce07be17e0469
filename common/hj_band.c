/* hj_band.c -- the storage kinds of hj_band.h. */
#include "hj_band.h"

#include <stdlib.h>
#include <string.h>

#include "hj_sys.h"

/* One cell of a sorted list: key is the last index (SSD) or the compressed
 * remaining indices (LS, CRS); next/prev are indices in the list's pool. */
typedef struct {
    int64_t key;
    double v;
    int32_t next, prev;
} band_cell;

/* A sorted list whose cells live in a pool of its own. */
typedef struct {
    band_cell *pool;
    int32_t head, cur, free, used, cap, n;
} band_list;

/* A line of SSDA: sorted contiguous cells. */
typedef struct {
    int64_t key;
    double v;
} band_acell;

typedef struct {
    band_acell *c;
    int32_t n, cap;
} band_aline;

/* A non-empty line of the Remark 3.1 variant. */
typedef struct {
    int64_t line;
    band_list list;
} band_line;

struct hj_band {
    hj_band_kind kind;
    int d, n;
    int64_t total; /* n^d */
    int split;     /* number of leading indices that select the list */
    size_t count;
    /* FS, FLS */
    double *val;
    unsigned char *state; /* FLS: 0 out, 1 in band, 2 removed but still listed */
    int64_t *band;
    size_t nband, capband;
    /* LS, CRS, SSD */
    band_list *lists;
    int64_t nlists;
    /* SSDA */
    band_aline *alines;
    /* SSDC */
    band_line *lines;
    size_t nlines, caplines;
};

static const char *const kind_names[HJ_BAND_NKINDS] = {"FS", "FLS", "LS", "CRS", "SSD", "SSDC", "SSDA"};

const char *hj_band_kind_name(hj_band_kind k) { return (k >= 0 && k < HJ_BAND_NKINDS) ? kind_names[k] : "?"; }

int hj_band_kind_from_name(const char *name)
{
    for (int k = 0; k < HJ_BAND_NKINDS; k++)
        if (!strcmp(name, kind_names[k])) return k;
    return -1;
}

hj_band_kind hj_band_kind_of(const hj_band *s) { return s->kind; }
int hj_band_dim(const hj_band *s) { return s->d; }
int hj_band_size(const hj_band *s) { return s->n; }
size_t hj_band_count(const hj_band *s) { return s->count; }

/* Compressed index of idx[from..to-1] (row-major). */
static int64_t compress(const hj_band *s, const int *idx, int from, int to)
{
    int64_t k = 0;
    for (int i = from; i < to; i++) k = k * s->n + idx[i];
    return k;
}

static void expand(const hj_band *s, int64_t k, int *idx, int from, int to)
{
    for (int i = to - 1; i >= from; i--) {
        idx[i] = (int)(k % s->n);
        k /= s->n;
    }
}

/* ---- sorted lists with pooled cells -------------------------------------- */

static void list_init(band_list *l)
{
    memset(l, 0, sizeof *l);
    l->head = l->cur = l->free = -1;
}

/* The cell with key k, or -1; *pred is the last cell with key < k (or -1).
 * LS (bidir) walks forward or backward from the last cell found, as the
 * paper describes; CRS and SSD walk their row / line list from its head,
 * as a singly linked list is searched. */
static int32_t list_search(band_list *l, int64_t k, int bidir, int32_t *pred)
{
    const band_cell *c = l->pool;
    int32_t q = l->head;
    if (bidir && l->cur >= 0 && c[l->cur].key <= k) {
        q = l->cur;
    } else if (bidir && l->cur >= 0) {
        q = l->cur;
        while (q >= 0 && c[q].key > k) q = c[q].prev;
        if (q < 0) q = l->head;
    }
    int32_t p = q >= 0 ? c[q].prev : -1;
    while (q >= 0 && c[q].key < k) { p = q; q = c[q].next; }
    *pred = p;
    if (q >= 0 && c[q].key == k) { l->cur = q; return q; }
    if (p >= 0) l->cur = p;
    return -1;
}

static int list_insert(band_list *l, int64_t k, double v, int bidir, double **slot)
{
    int32_t pred, q = list_search(l, k, bidir, &pred);
    if (q >= 0) { l->pool[q].v = v; *slot = &l->pool[q].v; return HJ_OK; }
    if (l->free < 0 && l->used == l->cap) {
        int64_t cap = l->cap ? 2 * (int64_t)l->cap : 4;
        if (cap > INT32_MAX) return HJ_ENOMEM;
        band_cell *np = realloc(l->pool, (size_t)cap * sizeof *np);
        if (!np) return HJ_ENOMEM;
        l->pool = np;
        l->cap = (int32_t)cap;
    }
    if (l->free >= 0) { q = l->free; l->free = l->pool[q].next; }
    else q = l->used++;
    band_cell *c = l->pool;
    c[q].key = k;
    c[q].v = v;
    c[q].prev = pred;
    c[q].next = pred >= 0 ? c[pred].next : l->head;
    if (c[q].next >= 0) c[c[q].next].prev = q;
    if (pred >= 0) c[pred].next = q; else l->head = q;
    l->n++;
    l->cur = q;
    *slot = &c[q].v;
    return HJ_OK;
}

static int list_remove(band_list *l, int64_t k, int bidir)
{
    int32_t pred, q = list_search(l, k, bidir, &pred);
    if (q < 0) return 0;
    band_cell *c = l->pool;
    if (pred >= 0) c[pred].next = c[q].next; else l->head = c[q].next;
    if (c[q].next >= 0) c[c[q].next].prev = pred;
    l->cur = pred >= 0 ? pred : l->head;
    c[q].next = l->free;
    l->free = q;
    l->n--;
    if (l->n == 0) { free(l->pool); list_init(l); }
    return 1;
}

/* ---- Remark 3.1: the non-empty lines, sorted, found by bisection --------- */

static size_t line_search(const hj_band *s, int64_t line, int *found)
{
    size_t lo = 0, hi = s->nlines;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (s->lines[mid].line < line) lo = mid + 1; else hi = mid;
    }
    *found = lo < s->nlines && s->lines[lo].line == line;
    return lo;
}

static band_list *list_of(hj_band *s, const int *idx, int create, int *rc)
{
    int64_t line = compress(s, idx, 0, s->split);
    if (s->kind != HJ_BAND_SSDC) return &s->lists[line];
    int found;
    size_t at = line_search(s, line, &found);
    if (found) return &s->lines[at].list;
    if (!create) return NULL;
    if (s->nlines == s->caplines) {
        size_t cap = s->caplines ? 2 * s->caplines : 64;
        band_line *nl = realloc(s->lines, cap * sizeof *nl);
        if (!nl) { *rc = HJ_ENOMEM; return NULL; }
        s->lines = nl;
        s->caplines = cap;
    }
    memmove(&s->lines[at + 1], &s->lines[at], (s->nlines - at) * sizeof *s->lines);
    s->nlines++;
    s->lines[at].line = line;
    list_init(&s->lines[at].list);
    return &s->lines[at].list;
}

/* ---- SSDA: sorted arrays per line ----------------------------------------- */

/* First position with key >= k. */
static int32_t aline_search(const band_aline *l, int64_t k)
{
    int32_t lo = 0, hi = l->n;
    while (lo < hi) {
        const int32_t mid = lo + (hi - lo) / 2;
        if (l->c[mid].key < k) lo = mid + 1; else hi = mid;
    }
    return lo;
}

static double *aline_find(band_aline *l, int64_t k)
{
    const int32_t at = aline_search(l, k);
    return at < l->n && l->c[at].key == k ? &l->c[at].v : NULL;
}

/* Returns 1 if a cell was added, 0 if overwritten, -1 out of memory. */
static int aline_insert(band_aline *l, int64_t k, double v)
{
    const int32_t at = aline_search(l, k);
    if (at < l->n && l->c[at].key == k) { l->c[at].v = v; return 0; }
    if (l->n == l->cap) {
        const int64_t cap = l->cap ? 2 * (int64_t)l->cap : 4;
        if (cap > INT32_MAX) return -1;
        band_acell *nc = realloc(l->c, (size_t)cap * sizeof *nc);
        if (!nc) return -1;
        l->c = nc;
        l->cap = (int32_t)cap;
    }
    memmove(&l->c[at + 1], &l->c[at], (size_t)(l->n - at) * sizeof *l->c);
    l->c[at].key = k;
    l->c[at].v = v;
    l->n++;
    return 1;
}

static int aline_remove(band_aline *l, int64_t k)
{
    const int32_t at = aline_search(l, k);
    if (at >= l->n || l->c[at].key != k) return 0;
    memmove(&l->c[at], &l->c[at + 1], (size_t)(l->n - at - 1) * sizeof *l->c);
    if (--l->n == 0) { free(l->c); l->c = NULL; l->cap = 0; }
    return 1;
}

/* ---- the interface --------------------------------------------------------- */

int hj_band_new(hj_band **out, hj_band_kind kind, int d, int n, hj_error *err)
{
    *out = NULL;
    if (d < 2 || d > HJ_BAND_DMAX || n < 1 || kind < 0 || kind >= HJ_BAND_NKINDS)
        return hj_error_set(err, HJ_EINVAL, "store: need 2 <= d <= %d, n >= 1 and a known kind", HJ_BAND_DMAX);
    double total = 1;
    for (int i = 0; i < d; i++) total *= n;
    if (total > 9e15) return hj_error_set(err, HJ_EINVAL, "store: %d^%d nodes cannot be indexed", n, d);
    hj_band *s = calloc(1, sizeof *s);
    if (!s) return hj_error_set(err, HJ_ENOMEM, "out of memory");
    s->kind = kind;
    s->d = d;
    s->n = n;
    s->total = (int64_t)total;
    s->split = kind == HJ_BAND_LS ? 0 : kind == HJ_BAND_CRS ? 1 : d - 1;
    const double phys = hj_sys_physical_memory();
    if (kind == HJ_BAND_FS || kind == HJ_BAND_FLS) {
        const double need = total * (kind == HJ_BAND_FS ? 8.0 : 9.0);
        /* A request beyond the machine's memory is refused up front: the
         * kernel would grant it lazily and kill the process later. */
        if ((phys > 0 && need > phys) || need > (double)SIZE_MAX / 2) {
            free(s);
            return hj_error_set(err, HJ_ENOMEM, "out of memory: %s needs %.3g GB", hj_band_kind_name(kind), need / 1e9);
        }
        s->val = malloc((size_t)s->total * sizeof *s->val);
        if (kind == HJ_BAND_FLS) s->state = calloc((size_t)s->total, 1);
        if (!s->val || (kind == HJ_BAND_FLS && !s->state)) {
            hj_band_free(s);
            return hj_error_set(err, HJ_ENOMEM, "out of memory: %s needs %.3g GB", hj_band_kind_name(kind), need / 1e9);
        }
        for (int64_t i = 0; i < s->total; i++) s->val[i] = 1.0;
        if (kind == HJ_BAND_FS) s->count = (size_t)s->total;
    } else if (kind == HJ_BAND_SSDA) {
        int64_t nl = 1;
        for (int i = 0; i < d - 1; i++) nl *= n;
        if (phys > 0 && (double)nl * sizeof(band_aline) > phys) {
            free(s);
            return hj_error_set(err, HJ_ENOMEM, "out of memory: SSDA heads need %.3g GB", (double)nl * sizeof(band_aline) / 1e9);
        }
        s->alines = calloc((size_t)nl, sizeof *s->alines);
        if (!s->alines) { free(s); return hj_error_set(err, HJ_ENOMEM, "out of memory"); }
        s->nlists = nl; /* number of lines; lists stays NULL */
    } else if (kind != HJ_BAND_SSDC) {
        s->nlists = 1;
        for (int i = 0; i < s->split; i++) s->nlists *= n;
        const double need = (double)s->nlists * sizeof(band_list);
        if (phys > 0 && need > phys) {
            free(s);
            return hj_error_set(err, HJ_ENOMEM, "out of memory: %s heads need %.3g GB", hj_band_kind_name(kind), need / 1e9);
        }
        s->lists = malloc((size_t)s->nlists * sizeof *s->lists);
        if (!s->lists) { free(s); return hj_error_set(err, HJ_ENOMEM, "out of memory"); }
        for (int64_t i = 0; i < s->nlists; i++) list_init(&s->lists[i]);
    }
    *out = s;
    return HJ_OK;
}

void hj_band_free(hj_band *s)
{
    if (!s) return;
    free(s->val);
    free(s->state);
    free(s->band);
    if (s->lists)
        for (int64_t i = 0; i < s->nlists; i++) free(s->lists[i].pool);
    free(s->lists);
    if (s->alines)
        for (int64_t i = 0; i < s->nlists; i++) free(s->alines[i].c);
    free(s->alines);
    for (size_t i = 0; i < s->nlines; i++) free(s->lines[i].list.pool);
    free(s->lines);
    free(s);
}

static int bidir(const hj_band *s) { return s->kind == HJ_BAND_LS; }

double *hj_band_find(hj_band *s, const int *idx)
{
    switch (s->kind) {
    case HJ_BAND_FS: return &s->val[compress(s, idx, 0, s->d)];
    case HJ_BAND_FLS: {
        int64_t k = compress(s, idx, 0, s->d);
        return s->state[k] == 1 ? &s->val[k] : NULL;
    }
    case HJ_BAND_SSDA: {
        band_aline *l = &s->alines[compress(s, idx, 0, s->d - 1)];
        return l->n ? aline_find(l, idx[s->d - 1]) : NULL;
    }
    default: {
        band_list *l = list_of(s, idx, 0, NULL);
        if (!l || l->n == 0) return NULL;
        int32_t pred, q = list_search(l, compress(s, idx, s->split, s->d), bidir(s), &pred);
        return q >= 0 ? &l->pool[q].v : NULL;
    }
    }
}

void hj_band_find_run(hj_band *s, const int *idx, int m, double **out)
{
    const int last = s->d - 1;
    int j[HJ_BAND_DMAX], k0 = 0;
    memcpy(j, idx, sizeof j);
    while (k0 < m && idx[last] + k0 < 0) out[k0++] = NULL; /* below the grid */
    if (k0 < m && idx[last] + k0 < s->n && s->kind != HJ_BAND_FS && s->kind != HJ_BAND_FLS && s->kind != HJ_BAND_SSDA) {
        j[last] = idx[last] + k0;
        band_list *l = list_of(s, j, 0, NULL);
        int32_t q = -1, pred;
        int64_t key = 0;
        if (l && l->n) {
            key = compress(s, j, s->split, s->d);
            q = list_search(l, key, 1, &pred); /* from the list's last position */
            if (q < 0) q = pred >= 0 ? l->pool[pred].next : l->head; /* the first key above */
        }
        for (int k = k0; k < m; k++, key++) {
            while (q >= 0 && l->pool[q].key < key) q = l->pool[q].next;
            out[k] = idx[last] + k < s->n && q >= 0 && l->pool[q].key == key ? &l->pool[q].v : NULL;
        }
        return;
    }
    for (int k = k0; k < m; k++) {
        j[last] = idx[last] + k;
        out[k] = j[last] < s->n ? hj_band_find(s, j) : NULL;
    }
}

int hj_band_insert(hj_band *s, const int *idx, double v, hj_error *err)
{
    if (s->kind == HJ_BAND_FS || s->kind == HJ_BAND_FLS) {
        int64_t k = compress(s, idx, 0, s->d);
        s->val[k] = v;
        if (s->kind == HJ_BAND_FS || s->state[k] == 1) return HJ_OK;
        if (s->state[k] == 0) {
            if (s->nband == s->capband) {
                size_t cap = s->capband ? 2 * s->capband : 1024;
                int64_t *nb = realloc(s->band, cap * sizeof *nb);
                if (!nb) return hj_error_set(err, HJ_ENOMEM, "out of memory (FLS band list)");
                s->band = nb;
                s->capband = cap;
            }
            s->band[s->nband++] = k;
        }
        s->state[k] = 1;
        s->count++;
        return HJ_OK;
    }
    if (s->kind == HJ_BAND_SSDA) {
        const int added = aline_insert(&s->alines[compress(s, idx, 0, s->d - 1)], idx[s->d - 1], v);
        if (added < 0) return hj_error_set(err, HJ_ENOMEM, "out of memory (SSDA line)");
        s->count += (size_t)added;
        return HJ_OK;
    }
    int rc = HJ_OK;
    band_list *l = list_of(s, idx, 1, &rc);
    if (!l) return hj_error_set(err, HJ_ENOMEM, "out of memory (%s lines)", hj_band_kind_name(s->kind));
    const int32_t n0 = l->n;
    double *slot;
    if (list_insert(l, compress(s, idx, s->split, s->d), v, bidir(s), &slot))
        return hj_error_set(err, HJ_ENOMEM, "out of memory (%s list cells)", hj_band_kind_name(s->kind));
    s->count += (size_t)(l->n - n0);
    return HJ_OK;
}

void hj_band_remove(hj_band *s, const int *idx)
{
    if (s->kind == HJ_BAND_FS) return;
    if (s->kind == HJ_BAND_FLS) {
        int64_t k = compress(s, idx, 0, s->d);
        if (s->state[k] == 1) { s->state[k] = 2; s->count--; }
        return;
    }
    if (s->kind == HJ_BAND_SSDA) {
        s->count -= (size_t)aline_remove(&s->alines[compress(s, idx, 0, s->d - 1)], idx[s->d - 1]);
        return;
    }
    band_list *l = list_of(s, idx, 0, NULL);
    if (!l || l->n == 0) return;
    if (list_remove(l, compress(s, idx, s->split, s->d), bidir(s))) s->count--;
    if (s->kind == HJ_BAND_SSDC && l->n == 0) {
        int found;
        size_t at = line_search(s, compress(s, idx, 0, s->split), &found);
        memmove(&s->lines[at], &s->lines[at + 1], (s->nlines - at - 1) * sizeof *s->lines);
        s->nlines--;
    }
}

size_t hj_band_bytes(const hj_band *s)
{
    size_t b = sizeof *s;
    if (s->val) b += (size_t)s->total * sizeof *s->val;
    if (s->state) b += (size_t)s->total;
    b += s->capband * sizeof *s->band;
    if (s->lists) {
        b += (size_t)s->nlists * sizeof *s->lists;
        for (int64_t i = 0; i < s->nlists; i++) b += (size_t)s->lists[i].cap * sizeof(band_cell);
    }
    if (s->alines) {
        b += (size_t)s->nlists * sizeof *s->alines;
        for (int64_t i = 0; i < s->nlists; i++) b += (size_t)s->alines[i].cap * sizeof(band_acell);
    }
    b += s->caplines * sizeof *s->lines;
    for (size_t i = 0; i < s->nlines; i++) b += (size_t)s->lines[i].list.cap * sizeof(band_cell);
    return b;
}

static int visit_list(hj_band *s, int64_t line, band_list *l, hj_band_visit_fn fn, void *ctx)
{
    int idx[HJ_BAND_DMAX];
    expand(s, line, idx, 0, s->split);
    for (int32_t q = l->head; q >= 0; q = l->pool[q].next) {
        expand(s, l->pool[q].key, idx, s->split, s->d);
        int rc = fn(idx, &l->pool[q].v, ctx);
        if (rc) return rc;
    }
    return 0;
}

int hj_band_foreach(hj_band *s, hj_band_visit_fn fn, void *ctx)
{
    int idx[HJ_BAND_DMAX], rc;
    switch (s->kind) {
    case HJ_BAND_FS:
        for (int64_t k = 0; k < s->total; k++) {
            expand(s, k, idx, 0, s->d);
            if ((rc = fn(idx, &s->val[k], ctx))) return rc;
        }
        return 0;
    case HJ_BAND_FLS: {
        size_t m = 0; /* drop the removed nodes first */
        for (size_t i = 0; i < s->nband; i++) {
            int64_t k = s->band[i];
            if (s->state[k] == 1) s->band[m++] = k; else s->state[k] = 0;
        }
        s->nband = m;
        for (size_t i = 0; i < s->nband; i++) {
            expand(s, s->band[i], idx, 0, s->d);
            if ((rc = fn(idx, &s->val[s->band[i]], ctx))) return rc;
        }
        return 0;
    }
    case HJ_BAND_SSDA:
        for (int64_t i = 0; i < s->nlists; i++) {
            band_aline *l = &s->alines[i];
            if (!l->n) continue;
            expand(s, i, idx, 0, s->d - 1);
            for (int32_t q = 0; q < l->n; q++) {
                idx[s->d - 1] = (int)l->c[q].key;
                if ((rc = fn(idx, &l->c[q].v, ctx))) return rc;
            }
        }
        return 0;
    case HJ_BAND_SSDC:
        for (size_t i = 0; i < s->nlines; i++)
            if ((rc = visit_list(s, s->lines[i].line, &s->lines[i].list, fn, ctx))) return rc;
        return 0;
    default:
        for (int64_t i = 0; i < s->nlists; i++)
            if (s->lists[i].n && (rc = visit_list(s, i, &s->lists[i], fn, ctx))) return rc;
        return 0;
    }
}
