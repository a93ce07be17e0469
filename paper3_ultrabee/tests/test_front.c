/* Unit tests of p3_front: the band found from the crossing points equals
 * the band found by visiting every node. */
#include "hj_test.h"

#include <stdlib.h>

#include "p3_front.h"

typedef struct {
    const p3_front *f;
    unsigned char *flag;
    size_t count;
} band_ctx;

static int64_t lin(const p3_front *f, const int *idx)
{
    int64_t k = 0;
    for (int i = 0; i < f->d; i++) k = k * f->n + idx[i];
    return k;
}

static int record(const int *idx, int side, void *vctx)
{
    band_ctx *c = vctx;
    if (side != p3_front_side(c->f, idx)) return 1;
    c->flag[lin(c->f, idx)] = 1;
    c->count++;
    return 0;
}

static void band_equals_brute_force(void **state)
{
    (void)state;
    for (int ex = 1; ex <= 2; ex++)
        for (int d = 2; d <= 4; d++) {
            p3_front f = {ex, d, d == 2 ? 83 : d == 3 ? 41 : 17, 0};
            f.dx = 4.0 / (f.n - 1);
            int64_t total = 1;
            for (int k = 0; k < d; k++) total *= f.n;
            band_ctx c = {&f, calloc((size_t)total, 1), 0};
            assert_non_null(c.flag);
            assert_int_equal(p3_front_band(&f, record, &c, NULL), 0);
            assert_true(c.count > 0);
            size_t brute = 0;
            for (int64_t l = 0; l < total; l++) {
                int idx[HJ_BAND_DMAX];
                int64_t r = l;
                for (int k = d - 1; k >= 0; k--) { idx[k] = (int)(r % f.n); r /= f.n; }
                const int s0 = p3_front_side(&f, idx);
                int border = 0;
                for (int k = 0; k < d; k++)
                    for (int s = -1; s <= 1; s += 2) {
                        if (idx[k] + s < 0 || idx[k] + s >= f.n) continue;
                        idx[k] += s;
                        border |= p3_front_side(&f, idx) != s0;
                        idx[k] -= s;
                    }
                assert_int_equal(border, c.flag[l]);
                brute += (size_t)border;
            }
            assert_int_equal(brute, c.count);
            free(c.flag);
        }
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(band_equals_brute_force)};
    return cmocka_run_group_tests_name("p3_front", tests, NULL, NULL);
}
