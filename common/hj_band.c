/* hj_band.c -- the storage kinds of hj_band.h. */
#include "hj_band.h"

#include <stdlib.h>
#include <string.h>

#include "hj_sys.h"

/* The links of one cell of a sorted list: key is the last index (SSD) or
 * the compressed remaining indices (LS, CRS); next/prev are indices in the
 * list's pool.  The values sit in an array of their own beside the links,
 * so that a walk, which reads keys and links only, moves 16 bytes per step
 * instead of 24 (the bytes per cell are the same). */
typedef struct {
    int64_t key;
    int32_t next, prev;
} band_link;

/* A sorted list whose cells live in a pool of its own: one block of cap
 * links followed by cap values (one allocation, so that a list head stays
 * 32 bytes: Table 4 of the paper counts the heads). */
typedef struct {
    band_link *link;
    int32_t head, cur, free, used, cap, n;
} band_list;

/* The values of the pool, after its cap links. */
static double *list_val(const band_list *l) { return (double *)(l->link + l->cap); }

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

static void list_free(band_list *l) { free(l->link); }

/* The cell with key k, or -1; *pred is the last cell with key < k (or -1).
 * LS (bidir) walks forward or backward from the last cell found, as the
 * paper describes; CRS and SSD walk their row / line list from its head,
 * as a singly linked list is searched. */
static int32_t list_search(band_list *l, int64_t k, int bidir, int32_t *pred)
{
    const band_link *c = l->link;
    int32_t q = l->head;
    if (bidir && l->cur >= 0) {
        q = l->cur;
        if (c[q].key > k) {
            while (q >= 0 && c[q].key > k) q = c[q].prev;
            if (q < 0) q = l->head;
        }
    }
    int32_t p = q >= 0 ? c[q].prev : -1;
    while (q >= 0 && c[q].key < k) { p = q; q = c[q].next; }
    *pred = p;
    if (q >= 0 && c[q].key == k) { l->cur = q; return q; }
    if (p >= 0) l->cur = p;
    return -1;
}

/* Room for one more cell: 0, or HJ_ENOMEM (the list unchanged). */
static int list_reserve(band_list *l)
{
    if (l->free >= 0 || l->used < l->cap) return HJ_OK;
    const int64_t cap = l->cap ? 2 * (int64_t)l->cap : 4;
    if (cap > INT32_MAX) return HJ_ENOMEM;
    band_link *np = realloc(l->link, (size_t)cap * (sizeof *np + sizeof(double)));
    if (!np) return HJ_ENOMEM;
    /* the values move up behind the grown links */
    memmove(np + cap, np + l->cap, (size_t)l->cap * sizeof(double));
    l->link = np;
    l->cap = (int32_t)cap;
    return HJ_OK;
}

/* A new cell (key k, value v) linked after pred (-1: at the head). */
static int32_t list_link(band_list *l, int32_t pred, int64_t k, double v)
{
    int32_t q;
    if (l->free >= 0) { q = l->free; l->free = l->link[q].next; }
    else q = l->used++;
    band_link *c = l->link;
    c[q].key = k;
    list_val(l)[q] = v;
    c[q].prev = pred;
    c[q].next = pred >= 0 ? c[pred].next : l->head;
    if (c[q].next >= 0) c[c[q].next].prev = q;
    if (pred >= 0) c[pred].next = q; else l->head = q;
    l->n++;
    l->cur = q;
    return q;
}

static int list_insert(band_list *l, int64_t k, double v, int bidir, double **slot)
{
    int32_t pred, q = list_search(l, k, bidir, &pred);
    if (q >= 0) { list_val(l)[q] = v; *slot = &list_val(l)[q]; return HJ_OK; }
    if (list_reserve(l)) return HJ_ENOMEM;
    q = list_link(l, pred, k, v);
    *slot = &list_val(l)[q];
    return HJ_OK;
}

/* Insert a key above every stored one: the last cell is found from the
 * list's last position (where the previous append left it), so that a
 * list built in order costs O(1) per cell.  Returns 1 if k is not above
 * the last key (nothing done), 0 or HJ_ENOMEM otherwise. */
static int list_append(band_list *l, int64_t k, double v)
{
    int32_t last = l->cur >= 0 ? l->cur : l->head;
    if (last >= 0)
        while (l->link[last].next >= 0) last = l->link[last].next;
    if (last >= 0 && l->link[last].key >= k) return 1;
    if (list_reserve(l)) return HJ_ENOMEM;
    list_link(l, last, k, v);
    return 0;
}

static int list_remove(band_list *l, int64_t k, int bidir)
{
    int32_t pred, q = list_search(l, k, bidir, &pred);
    if (q < 0) return 0;
    band_link *c = l->link;
    if (pred >= 0) c[pred].next = c[q].next; else l->head = c[q].next;
    if (c[q].next >= 0) c[c[q].next].prev = pred;
    l->cur = pred >= 0 ? pred : l->head;
    c[q].next = l->free;
    l->free = q;
    l->n--;
    if (l->n == 0) { list_free(l); list_init(l); }
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
        s->val = hj_sys_alloc_large((size_t)s->total * sizeof *s->val);
        if (kind == HJ_BAND_FLS) s->state = hj_sys_alloc_large((size_t)s->total);
        if (!s->val || (kind == HJ_BAND_FLS && !s->state)) {
            hj_band_free(s);
            return hj_error_set(err, HJ_ENOMEM, "out of memory: %s needs %.3g GB", hj_band_kind_name(kind), need / 1e9);
        }
        if (kind == HJ_BAND_FS) { /* FLS reads a value only where state says it was stored */
            for (int64_t i = 0; i < s->total; i++) s->val[i] = 1.0;
            s->count = (size_t)s->total;
        } else {
            memset(s->state, 0, (size_t)s->total);
        }
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
        for (int64_t i = 0; i < s->nlists; i++) list_free(&s->lists[i]);
    free(s->lists);
    if (s->alines)
        for (int64_t i = 0; i < s->nlists; i++) free(s->alines[i].c);
    free(s->alines);
    for (size_t i = 0; i < s->nlines; i++) list_free(&s->lines[i].list);
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
        return q >= 0 ? &list_val(l)[q] : NULL;
    }
    }
}

void hj_band_find_run(hj_band *s, const int *idx, int m, double **out)
{
    const int last = s->d - 1;
    int j[HJ_BAND_DMAX] = {0}, k0 = 0;
    memcpy(j, idx, (size_t)s->d * sizeof *j); /* idx holds d indices (sizeof j read past a shorter array) */
    while (k0 < m && idx[last] + k0 < 0) out[k0++] = NULL; /* below the grid */
    if (k0 < m && idx[last] + k0 < s->n && s->kind != HJ_BAND_FS && s->kind != HJ_BAND_FLS && s->kind != HJ_BAND_SSDA) {
        j[last] = idx[last] + k0;
        band_list *l = list_of(s, j, 0, NULL);
        int32_t q = -1, pred;
        int64_t key = 0;
        if (l && l->n) {
            key = compress(s, j, s->split, s->d);
            q = list_search(l, key, 1, &pred); /* from the list's last position */
            if (q < 0) q = pred >= 0 ? l->link[pred].next : l->head; /* the first key above */
        }
        for (int k = k0; k < m; k++, key++) {
            while (q >= 0 && l->link[q].key < key) q = l->link[q].next;
            out[k] = idx[last] + k < s->n && q >= 0 && l->link[q].key == key ? &list_val(l)[q] : NULL;
        }
        return;
    }
    for (int k = k0; k < m; k++) {
        j[last] = idx[last] + k;
        out[k] = j[last] < s->n ? hj_band_find(s, j) : NULL;
    }
}

static int band_insert(hj_band *s, const int *idx, double v, int near, hj_error *err);
static void band_remove(hj_band *s, const int *idx, int near);

int hj_band_insert(hj_band *s, const int *idx, double v, hj_error *err) { return band_insert(s, idx, v, 0, err); }
int hj_band_insert_near(hj_band *s, const int *idx, double v, hj_error *err) { return band_insert(s, idx, v, 1, err); }
void hj_band_remove(hj_band *s, const int *idx) { band_remove(s, idx, 0); }
void hj_band_remove_near(hj_band *s, const int *idx) { band_remove(s, idx, 1); }

/* near: the list kinds search from the list's last position (bidir) */
static int band_insert(hj_band *s, const int *idx, double v, int near, hj_error *err)
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
    if (list_insert(l, compress(s, idx, s->split, s->d), v, near || bidir(s), &slot))
        return hj_error_set(err, HJ_ENOMEM, "out of memory (%s list cells)", hj_band_kind_name(s->kind));
    s->count += (size_t)(l->n - n0);
    return HJ_OK;
}

int hj_band_append(hj_band *s, const int *idx, double v, hj_error *err)
{
    if (s->kind == HJ_BAND_FS || s->kind == HJ_BAND_FLS) return hj_band_insert(s, idx, v, err);
    if (s->kind == HJ_BAND_SSDA) {
        const band_aline *l = &s->alines[compress(s, idx, 0, s->d - 1)];
        if (l->n && l->c[l->n - 1].key >= idx[s->d - 1])
            return hj_error_set(err, HJ_EINVAL, "store: append below the last node of its line");
        return hj_band_insert(s, idx, v, err);
    }
    int rc = HJ_OK;
    band_list *l = list_of(s, idx, 1, &rc);
    if (!l) return hj_error_set(err, HJ_ENOMEM, "out of memory (%s lines)", hj_band_kind_name(s->kind));
    rc = list_append(l, compress(s, idx, s->split, s->d), v);
    if (rc == 1) return hj_error_set(err, HJ_EINVAL, "store: append below the last node of its list");
    if (rc) return hj_error_set(err, HJ_ENOMEM, "out of memory (%s list cells)", hj_band_kind_name(s->kind));
    s->count++;
    return HJ_OK;
}

static void band_remove(hj_band *s, const int *idx, int near)
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
    if (list_remove(l, compress(s, idx, s->split, s->d), near || bidir(s))) s->count--;
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
        for (int64_t i = 0; i < s->nlists; i++) b += (size_t)s->lists[i].cap * (sizeof(band_link) + sizeof(double));
    }
    if (s->alines) {
        b += (size_t)s->nlists * sizeof *s->alines;
        for (int64_t i = 0; i < s->nlists; i++) b += (size_t)s->alines[i].cap * sizeof(band_acell);
    }
    b += s->caplines * sizeof *s->lines;
    for (size_t i = 0; i < s->nlines; i++) b += (size_t)s->lines[i].list.cap * (sizeof(band_link) + sizeof(double));
    return b;
}

static int visit_list(hj_band *s, int64_t line, band_list *l, hj_band_visit_fn fn, void *ctx)
{
    int idx[HJ_BAND_DMAX];
    expand(s, line, idx, 0, s->split);
    for (int32_t q = l->head; q >= 0; q = l->link[q].next) {
        expand(s, l->link[q].key, idx, s->split, s->d);
        int rc = fn(idx, &list_val(l)[q], ctx);
        if (rc) return rc;
    }
    return 0;
}

int hj_band_foreach(hj_band *s, hj_band_visit_fn fn, void *ctx)
{
    int idx[HJ_BAND_DMAX], rc;
    switch (s->kind) {
    case HJ_BAND_FS: /* the indices counted up, not divided out of k */
        expand(s, 0, idx, 0, s->d);
        for (int64_t k = 0; k < s->total; k++) {
            if ((rc = fn(idx, &s->val[k], ctx))) return rc;
            for (int i = s->d - 1; i >= 0 && ++idx[i] == s->n; i--) idx[i] = 0;
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
