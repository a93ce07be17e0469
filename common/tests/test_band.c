/* Unit tests of hj_band: every kind holds the same set after the same
 * random inserts and removes, finds the same neighbours, walks in order. */
#include "hj_test.h"

#include <stdlib.h>
#include <string.h>

#include "hj_band.h"

/* Reference: a plain array over the small grid, NaN = not stored. */
typedef struct {
    int d, n;
    int64_t total;
    double *v;
} ref_grid;

static int64_t lin(int d, int n, const int *idx)
{
    int64_t k = 0;
    for (int i = 0; i < d; i++) k = k * n + idx[i];
    return k;
}

static unsigned rnd(unsigned *state)
{
    *state = *state * 1103515245u + 12345u;
    return (*state >> 16) & 0x7fff;
}

typedef struct {
    int d, n;
    int64_t last;
    size_t seen;
    const ref_grid *ref;
    int ordered;
} walk_ctx;

static int check_visit(const int *idx, double *v, void *vctx)
{
    walk_ctx *w = vctx;
    int64_t k = lin(w->d, w->n, idx);
    if (w->ordered && k <= w->last) return 1;
    w->last = k;
    w->seen++;
    return *v == w->ref->v[k] ? 0 : 2;
}

/* The same random sequence on every kind, checked against the array. */
static void random_sequence_all_kinds(void **state)
{
    (void)state;
    for (int d = 2; d <= 4; d++) {
        const int n = d == 2 ? 40 : d == 3 ? 14 : 7;
        for (int kind = HJ_BAND_FLS; kind < HJ_BAND_NKINDS; kind++) {
            ref_grid ref = {d, n, 1, NULL};
            for (int i = 0; i < d; i++) ref.total *= n;
            ref.v = malloc((size_t)ref.total * sizeof *ref.v);
            assert_non_null(ref.v);
            for (int64_t i = 0; i < ref.total; i++) ref.v[i] = NAN;
            hj_band *s;
            assert_int_equal(hj_band_new(&s, kind, d, n, NULL), HJ_OK);
            unsigned seed = 12345u + (unsigned)d;
            for (int step = 0; step < 20000; step++) {
                int idx[HJ_BAND_DMAX];
                for (int i = 0; i < d; i++) idx[i] = (int)(rnd(&seed) % (unsigned)n);
                int64_t k = lin(d, n, idx);
                unsigned op = rnd(&seed) % 3;
                if (op == 0) {
                    double v = (double)step;
                    assert_int_equal(hj_band_insert(s, idx, v, NULL), HJ_OK);
                    ref.v[k] = v;
                } else if (op == 1) {
                    hj_band_remove(s, idx);
                    ref.v[k] = NAN;
                } else {
                    /* the node and its 2d neighbours */
                    for (int nb = -1; nb < 2 * d; nb++) {
                        int j[HJ_BAND_DMAX];
                        memcpy(j, idx, sizeof j);
                        if (nb >= 0) {
                            j[nb / 2] += nb % 2 ? 1 : -1;
                            if (j[nb / 2] < 0 || j[nb / 2] >= n) continue;
                        }
                        double *p = hj_band_find(s, j), r = ref.v[lin(d, n, j)];
                        if (isnan(r)) assert_null(p);
                        else { assert_non_null(p); assert_true(*p == r); }
                    }
                }
            }
            size_t stored = 0;
            for (int64_t i = 0; i < ref.total; i++) stored += !isnan(ref.v[i]);
            assert_int_equal(hj_band_count(s), stored);
            walk_ctx w = {d, n, -1, 0, &ref, kind != HJ_BAND_FLS};
            assert_int_equal(hj_band_foreach(s, check_visit, &w), 0);
            assert_int_equal(w.seen, stored);
            assert_true(hj_band_bytes(s) > 0);
            hj_band_free(s);
            free(ref.v);
        }
    }
}

static void full_storage_holds_every_node(void **state)
{
    (void)state;
    hj_band *s;
    assert_int_equal(hj_band_new(&s, HJ_BAND_FS, 3, 5, NULL), HJ_OK);
    assert_int_equal(hj_band_count(s), 125);
    int idx[3] = {4, 0, 2};
    double *p = hj_band_find(s, idx);
    assert_non_null(p);
    assert_true(*p == 1.0);
    hj_band_remove(s, idx);
    assert_non_null(hj_band_find(s, idx));
    hj_band_free(s);
}

/* Full kinds beyond the machine fail cleanly; bad shapes are refused. */
static void out_of_memory_and_bad_args(void **state)
{
    (void)state;
    hj_band *s = (hj_band *)&s;
    hj_error err;
    assert_int_equal(hj_band_new(&s, HJ_BAND_FS, 4, 3000, &err), HJ_ENOMEM);
    assert_null(s);
    assert_non_null(strstr(err.msg, "out of memory"));
    assert_int_equal(hj_band_new(&s, HJ_BAND_FLS, 4, 3000, &err), HJ_ENOMEM);
    assert_int_equal(hj_band_new(&s, HJ_BAND_SSD, 5, 10, &err), HJ_EINVAL);
    assert_int_equal(hj_band_new(&s, HJ_BAND_SSD, 3, 0, &err), HJ_EINVAL);
    assert_int_equal(hj_band_kind_from_name("SSD"), HJ_BAND_SSD);
    assert_int_equal(hj_band_kind_from_name("XYZ"), -1);
}

/* hj_band_find_run gives what hj_band_find gives, node by node, for
 * every kind, every start (including -1 and runs leaving the grid), runs
 * of 1 to n + 2 nodes (a whole segment of the scheme and beyond), with
 * searches interleaved with inserts and removes in random order. */
static void find_run_equals_find(void **state)
{
    (void)state;
    for (int d = 2; d <= 4; d++)
        for (int kind = 0; kind < HJ_BAND_NKINDS; kind++) {
            const int n = d == 4 ? 7 : 11;
            hj_band *s;
            assert_int_equal(hj_band_new(&s, (hj_band_kind)kind, d, n, NULL), HJ_OK);
            unsigned seed = 7u + (unsigned)(d * 10 + kind);
            for (int it = 0; it < 4000; it++) {
                int idx[HJ_BAND_DMAX];
                for (int k = 0; k < d; k++) idx[k] = (int)(rnd(&seed) % (unsigned)n);
                const unsigned op = rnd(&seed) % 4;
                if (op == 0) assert_int_equal(hj_band_insert(s, idx, (double)it, NULL), HJ_OK);
                else if (op == 1) hj_band_remove(s, idx);
                else {
                    idx[d - 1] = (int)(rnd(&seed) % (unsigned)(n + 1)) - 1; /* -1 .. n-1 */
                    const int m = 1 + (int)(rnd(&seed) % (unsigned)(n + 2)); /* up to past the line's end */
                    double *run[16];
                    hj_band_find_run(s, idx, m, run);
                    for (int k = 0; k < m; k++) {
                        int j[HJ_BAND_DMAX];
                        memcpy(j, idx, sizeof j);
                        j[d - 1] += k;
                        double *one = j[d - 1] >= 0 && j[d - 1] < n ? hj_band_find(s, j) : NULL;
                        assert_true(run[k] == one);
                    }
                }
            }
            hj_band_free(s);
        }
}

/* Appending nodes in lexicographic order builds the same store as
 * inserting them (same nodes, values, walk order and bytes); an append
 * below the last node of its list is refused and changes nothing. */
static void append_equals_insert(void **state)
{
    (void)state;
    for (int d = 2; d <= 4; d++) {
        const int n = d == 2 ? 30 : d == 3 ? 12 : 6;
        for (int kind = HJ_BAND_FS; kind < HJ_BAND_NKINDS; kind++) {
            hj_band *a, *b;
            assert_int_equal(hj_band_new(&a, kind, d, n, NULL), HJ_OK);
            assert_int_equal(hj_band_new(&b, kind, d, n, NULL), HJ_OK);
            int64_t total = 1;
            for (int i = 0; i < d; i++) total *= n;
            unsigned seed = 777u + (unsigned)d;
            for (int64_t k = 0; k < total; k++) {
                if (rnd(&seed) % 4) continue; /* about a quarter of the grid */
                int idx[HJ_BAND_DMAX];
                int64_t r = k;
                for (int i = d - 1; i >= 0; i--) { idx[i] = (int)(r % n); r /= n; }
                assert_int_equal(hj_band_append(a, idx, (double)k, NULL), HJ_OK);
                assert_int_equal(hj_band_insert(b, idx, (double)k, NULL), HJ_OK);
            }
            assert_int_equal(hj_band_count(a), hj_band_count(b));
            assert_int_equal(hj_band_bytes(a), hj_band_bytes(b));
            for (int64_t k = 0; k < total; k++) {
                int idx[HJ_BAND_DMAX];
                int64_t r = k;
                for (int i = d - 1; i >= 0; i--) { idx[i] = (int)(r % n); r /= n; }
                const double *pa = hj_band_find(a, idx), *pb = hj_band_find(b, idx);
                assert_true((pa == NULL) == (pb == NULL));
                if (pa) assert_true(*pa == *pb);
            }
            if (kind != HJ_BAND_FS && kind != HJ_BAND_FLS) {
                /* the last node of the grid, and one below it in its line
                 * (so in its list for every kind) */
                int top[HJ_BAND_DMAX], low[HJ_BAND_DMAX];
                for (int i = 0; i < d; i++) top[i] = low[i] = n - 1;
                low[d - 1] = 0;
                hj_band_remove(a, top);
                assert_int_equal(hj_band_append(a, top, 5.0, NULL), HJ_OK);
                const size_t before = hj_band_count(a);
                hj_error err;
                assert_int_equal(hj_band_append(a, low, 1.0, &err), HJ_EINVAL);
                assert_int_equal(hj_band_count(a), before);
                /* after a remove the last cell is found again */
                hj_band_remove(a, top);
                assert_int_equal(hj_band_append(a, top, 6.0, NULL), HJ_OK);
                assert_true(*hj_band_find(a, top) == 6.0);
            }
            hj_band_free(a);
            hj_band_free(b);
        }
    }
}

/* hj_band_insert_near and hj_band_remove_near (the search from the
 * list's last position, as hj_band_find_run's) leave the same store as
 * hj_band_insert and hj_band_remove (the search from the head): after
 * the same random inserts, overwrites and removes, interleaved with
 * lookups that move the last position, every kind holds the same nodes
 * and values, walks them in the same order, and allocates the same bytes. */
typedef struct {
    int64_t *k;
    double *v;
    size_t m;
    int d; /* the store's dimension: foreach sets idx[0..d-1] only */
} dump_ctx;

static int dump(const int *idx, double *v, void *vctx)
{
    dump_ctx *c = vctx;
    int64_t k = 0;
    for (int i = 0; i < c->d; i++) k = k * 64 + idx[i];
    c->k[c->m] = k;
    c->v[c->m++] = *v;
    return 0;
}

static void near_equals_head_search(void **state)
{
    (void)state;
    for (int d = 2; d <= 4; d++) {
        const int n = d == 2 ? 40 : d == 3 ? 12 : 6;
        int64_t total = 1;
        for (int i = 0; i < d; i++) total *= n;
        for (int kind = HJ_BAND_FS; kind < HJ_BAND_NKINDS; kind++) {
            hj_band *a, *b;
            assert_int_equal(hj_band_new(&a, kind, d, n, NULL), HJ_OK);
            assert_int_equal(hj_band_new(&b, kind, d, n, NULL), HJ_OK);
            unsigned seed = 4242u + (unsigned)(d * 10 + kind);
            for (int op = 0; op < 6000; op++) {
                int idx[HJ_BAND_DMAX] = {0};
                for (int i = 0; i < d; i++) idx[i] = (int)(rnd(&seed) % (unsigned)n);
                const unsigned r = rnd(&seed) % 8;
                if (r < 4) {
                    assert_int_equal(hj_band_insert(a, idx, op, NULL), HJ_OK);
                    assert_int_equal(hj_band_insert_near(b, idx, op, NULL), HJ_OK);
                } else if (r < 6) {
                    hj_band_remove(a, idx);
                    hj_band_remove_near(b, idx);
                } else {
                    double *pa[3], *pb[3];
                    hj_band_find_run(a, idx, 3, pa);
                    hj_band_find_run(b, idx, 3, pb);
                    for (int k = 0; k < 3; k++) assert_true((pa[k] == NULL) == (pb[k] == NULL));
                }
            }
            assert_int_equal(hj_band_count(a), hj_band_count(b));
            assert_int_equal(hj_band_bytes(a), hj_band_bytes(b));
            dump_ctx ca = {malloc((size_t)total * sizeof(int64_t)), malloc((size_t)total * sizeof(double)), 0, d};
            dump_ctx cb = {malloc((size_t)total * sizeof(int64_t)), malloc((size_t)total * sizeof(double)), 0, d};
            assert_int_equal(hj_band_foreach(a, dump, &ca), 0);
            assert_int_equal(hj_band_foreach(b, dump, &cb), 0);
            assert_int_equal(ca.m, cb.m);
            assert_memory_equal(ca.k, cb.k, ca.m * sizeof *ca.k);
            assert_memory_equal(ca.v, cb.v, ca.m * sizeof *ca.v);
            free(ca.k), free(ca.v), free(cb.k), free(cb.v);
            hj_band_free(a);
            hj_band_free(b);
        }
    }
}

/* hj_band_find_run copied HJ_BAND_DMAX indices from idx, which holds d:
 * an array of two indices for a 2-D store was read past its end (the
 * sanitizer build reports the overflow). */
static void find_run_reads_d_indices(void **state)
{
    (void)state;
    for (int kind = HJ_BAND_FS; kind < HJ_BAND_NKINDS; kind++) {
        hj_band *s;
        assert_int_equal(hj_band_new(&s, kind, 2, 8, NULL), HJ_OK);
        const int at[2] = {3, 4};
        assert_int_equal(hj_band_insert(s, at, -0.5, NULL), HJ_OK);
        double *p[3];
        const int *from = (const int[2]){3, 3}; /* exactly d = 2 ints */
        hj_band_find_run(s, from, 3, p);
        assert_non_null(p[1]);
        assert_true(*p[1] == -0.5);
        if (kind != HJ_BAND_FS) assert_null(p[0]), assert_null(p[2]);
        hj_band_free(s);
    }
}

HJ_TEST_MAIN("hj_band", NULL, NULL, cmocka_unit_test(find_run_reads_d_indices), cmocka_unit_test(random_sequence_all_kinds), cmocka_unit_test(near_equals_head_search),
             cmocka_unit_test(find_run_equals_find), cmocka_unit_test(full_storage_holds_every_node),
             cmocka_unit_test(out_of_memory_and_bad_args), cmocka_unit_test(append_equals_insert))
