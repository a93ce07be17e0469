/* Unit tests of common/hj_sum (exact, order-independent sums). */
#include "hj_test.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

#include "hj_sum.h"

static int same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

#define assert_bits(a, b)                                                                                      \
    do {                                                                                                       \
        const double x_ = (a), y_ = (b);                                                                       \
        if (!same_bits(x_, y_)) fail_msg("%s = %a, expected %s = %a", #a, x_, #b, y_);                         \
    } while (0)

/* A small deterministic generator (tests must not depend on rand()). */
static uint64_t rng_state = 88172645463325252u;
static uint64_t rng(void)
{
    rng_state ^= rng_state << 13, rng_state ^= rng_state >> 7, rng_state ^= rng_state << 17;
    return rng_state;
}
static void shuffle(double *x, long n)
{
    for (long k = n - 1; k > 0; k--) {
        const long j = (long)(rng() % (uint64_t)(k + 1));
        const double t = x[k];
        x[k] = x[j], x[j] = t;
    }
}

/* Sums whose exact value is known and representable, or whose correct
 * rounding is known, including where a plain loop is wrong. */
static void exact_values(void **state)
{
    (void)state;
    assert_bits(hj_sum_array((double[]){1e16, 1, -1e16}, 3), 1.0);
    assert_bits(hj_sum_array((double[]){1e308, 1e308, -1e308}, 3), 1e308);
    assert_bits(hj_sum_array((double[]){DBL_MAX, DBL_MAX, -DBL_MAX}, 3), DBL_MAX);
    assert_bits(hj_sum_array((double[]){0.1, 0.2, 0.3, -0.6}, 4), 0x1p-55); /* exact (a plain loop: 0x1p-53) */
    assert_bits(hj_sum_array((double[]){1, 0x1p-60, -1}, 3), 0x1p-60);
    /* Ties to even, and a lower bit that breaks the tie. */
    assert_bits(hj_sum_array((double[]){0x1p53, 1}, 2), 0x1p53);
    assert_bits(hj_sum_array((double[]){0x1p53, 3}, 2), 0x1p53 + 4);
    assert_bits(hj_sum_array((double[]){0x1p53, 1, 0x1p-1000}, 3), 0x1p53 + 2);
    assert_bits(hj_sum_array((double[]){-0x1p53, -1, -0x1p-1074}, 3), -0x1p53 - 2);
    /* Subnormals: exact multiples of the smallest one; and the boundary to
     * the normal range. */
    const double tiny = 0x1p-1074;
    assert_bits(hj_sum_array((double[]){tiny, tiny, tiny}, 3), 3 * tiny);
    assert_bits(hj_sum_array((double[]){DBL_MIN, -tiny}, 2), DBL_MIN - tiny);
    assert_bits(hj_sum_array((double[]){DBL_MIN - tiny, tiny}, 2), DBL_MIN);
    assert_bits(hj_sum_array((double[]){1, tiny, -1}, 3), tiny);
    /* Zeros: an exact zero is +0 whatever the signs of the terms. */
    assert_bits(hj_sum_array((double[]){-0.0, -0.0}, 2), 0.0);
    assert_bits(hj_sum_array((double[]){1.5, -1.5}, 2), 0.0);
    assert_bits(hj_sum_array(NULL, 0), 0.0);
    /* Overflow of the exact sum rounds to Inf; just below it does not. */
    assert_bits(hj_sum_array((double[]){DBL_MAX, DBL_MAX}, 2), INFINITY);
    assert_bits(hj_sum_array((double[]){-DBL_MAX, -DBL_MAX}, 2), -INFINITY);
    assert_bits(hj_sum_array((double[]){DBL_MAX, 0x1p969}, 2), DBL_MAX);   /* below half an ulp */
    assert_bits(hj_sum_array((double[]){DBL_MAX, 0x1p970}, 2), INFINITY); /* the tie rounds to 2^1024 */
}

/* The correctly rounded sum against an exact integer reference: terms
 * m 2^e with |m| < 2^53 and e in [-40, 20] are integers times 2^-40,
 * summed exactly in 128 bits and rounded once by the conversion. */
static void random_exact(void **state)
{
    (void)state;
    enum { N = 300 };
    double x[N + 1];
    for (int trial = 0; trial < 2000; trial++) {
        __int128 ref = 0;
        int n = 1 + (int)(rng() % N);
        for (int k = 0; k < n; k++) {
            const int64_t m = (int64_t)((rng() >> 11) >> (rng() % 50)) * ((rng() & 1) ? 1 : -1);
            const int e = -40 + (int)(rng() % 61);
            x[k] = ldexp((double)m, e);
            ref += (__int128)m * ((__int128)1 << (e + 40));
        }
        /* Near-cancellation: one more term, minus the sum rounded (an
         * integer in units of 2^-40, so converted back exactly). */
        if (trial % 3 == 0) {
            const double c = -(double)ref;
            x[n++] = ldexp(c, -40);
            ref += (__int128)c;
        }
        const double want = ldexp((double)ref, -40); /* one rounding (gcc's __floattidf), exact scaling */
        assert_bits(hj_sum_array(x, n), want);
    }
}

/* Every order of adversarial terms (huge, tiny, subnormal, cancelling,
 * signed zeros) gives the same bits, and merging partial sums in any
 * grouping gives them too. */
static void permutations_and_merge(void **state)
{
    (void)state;
    double x[] = {1e308,  -1e308, 1e16,     1,        -1e16,  0x1p-1074, -0x1p-1074, 0x1p-1060, 0.0,
                  -0.0,   3.5e-300, 1e-310, -2.5e-320, 1e200,  -1e200,   0.1,        0.2,       -0.3,
                  1e-16,  7e307,  7e307,    -7e307,   123.456, 0x1p52, 0.5,        -0x1p-53,  1e-5};
    const long n = (long)(sizeof x / sizeof x[0]);
    const double ref = hj_sum_array(x, n);
    hj_sum s0;
    hj_sum_init(&s0);
    for (long k = 0; k < n; k++) hj_sum_add(&s0, x[k]);
    hj_sum_normalize(&s0);
    for (int trial = 0; trial < 500; trial++) {
        shuffle(x, n);
        assert_bits(hj_sum_array(x, n), ref);
        /* Split into up to 5 parts, merged in reverse order. */
        hj_sum part[5], all;
        const int np = 1 + trial % 5;
        for (int p = 0; p < np; p++) hj_sum_init(&part[p]);
        for (long k = 0; k < n; k++) hj_sum_add(&part[rng() % (uint64_t)np], x[k]);
        hj_sum_init(&all);
        for (int p = np - 1; p >= 0; p--) hj_sum_merge(&all, &part[p]);
        assert_bits(hj_sum_value(&all), ref);
        /* The canonical form is unique: normalized limbs match word for word. */
        hj_sum_normalize(&all);
        assert_memory_equal(all.w, s0.w, sizeof all.w);
    }
}

/* Carry room: doubling an accumulator 80 times (2^80 copies of a term
 * whose pieces are all 32-bit maxima) stays exact; and 2^20 additions of
 * the same term equal the product. */
static void carries(void **state)
{
    (void)state;
    const double x = -(0x1p53 - 1) * 0x1p-30; /* 53 one bits across three limbs */
    hj_sum s;
    hj_sum_init(&s);
    hj_sum_add(&s, x);
    for (int k = 0; k < 80; k++) {
        const hj_sum t = s;
        hj_sum_merge(&s, &t);
    }
    assert_bits(hj_sum_value(&s), ldexp(x, 80));
    hj_sum_init(&s);
    for (long k = 0; k < (1L << 20); k++) hj_sum_add(&s, 0x1.fffffffffffffp-3);
    assert_bits(hj_sum_value(&s), 0x1.fffffffffffffp-3 * 0x1p20);
}

/* NaN and Inf propagate as in a plain sum. */
static void specials(void **state)
{
    (void)state;
    assert_bits(hj_sum_array((double[]){1, INFINITY, 1e308}, 3), INFINITY);
    assert_bits(hj_sum_array((double[]){1, -INFINITY, -1e308, -1e308}, 4), -INFINITY);
    assert_true(isnan(hj_sum_array((double[]){INFINITY, 1, -INFINITY}, 3)));
    assert_true(isnan(hj_sum_array((double[]){1, NAN, 2}, 3)));
    assert_true(isnan(hj_sum_array((double[]){INFINITY, NAN}, 2)));
    /* A merge carries them too. */
    hj_sum a, b;
    hj_sum_init(&a), hj_sum_init(&b);
    hj_sum_add(&a, 1), hj_sum_add(&b, -INFINITY);
    hj_sum_merge(&a, &b);
    assert_bits(hj_sum_value(&a), -INFINITY);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(exact_values), cmocka_unit_test(random_exact), cmocka_unit_test(permutations_and_merge),
        cmocka_unit_test(carries),      cmocka_unit_test(specials),
    };
    return cmocka_run_group_tests_name("hj_sum", tests, NULL, NULL);
}
