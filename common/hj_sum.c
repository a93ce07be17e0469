/* hj_sum.c -- exact, order-independent sums of doubles; see hj_sum.h. */
#include "hj_sum.h"

#include <math.h>
#include <string.h>

#define TOP (HJ_SUM_LIMBS - 1)
#define MASK32 0xffffffffu
/* Normalize before pending reaches this: a limb then stays below
 * (pending + 1) 2^32 <= 2^62 in magnitude, even after merging two
 * accumulators just under the bound. */
#define PENDING_MAX ((int64_t)1 << 29)

void hj_sum_init(hj_sum *s) { memset(s, 0, sizeof *s); }

void hj_sum_normalize(hj_sum *s)
{
    for (int i = 0; i < TOP; i++) {
        /* lo = limb mod 2^32 in [0, 2^32); the rest is an exact multiple. */
        const int64_t lo = (int64_t)((uint64_t)s->w[i] & MASK32);
        s->w[i + 1] += (s->w[i] - lo) / ((int64_t)1 << 32);
        s->w[i] = lo;
    }
    s->pending = 0;
}

void hj_sum_add(hj_sum *s, double x)
{
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    const int E = (int)((bits >> 52) & 0x7ff);
    const uint64_t frac = bits & (((uint64_t)1 << 52) - 1);
    if (E == 0x7ff) {
        s->w[frac ? HJ_SUM_NAN : bits >> 63 ? HJ_SUM_NINF : HJ_SUM_PINF]++;
        return;
    }
    /* x = +-m 2^(p - 1074), m < 2^53: m 2^(p mod 32) in three 32-bit
     * pieces at limb p / 32 (+-0 adds zeros).  The sign without a branch:
     * (v ^ neg) - neg is v or -v. */
    const uint64_t m = E ? frac | (uint64_t)1 << 52 : frac;
    const int p = E ? E - 1 : 0, i = p >> 5, sh = p & 31;
    const uint64_t rest = m >> (32 - sh);
    const int64_t neg = -(int64_t)(bits >> 63);
    const int64_t p0 = (int64_t)((m << sh) & MASK32), p1 = (int64_t)(rest & MASK32), p2 = (int64_t)(rest >> 32);
    s->w[i] += (p0 ^ neg) - neg;
    s->w[i + 1] += (p1 ^ neg) - neg;
    s->w[i + 2] += (p2 ^ neg) - neg;
    if (++s->pending >= PENDING_MAX) hj_sum_normalize(s);
}

void hj_sum_merge(hj_sum *s, const hj_sum *t)
{
    for (int k = 0; k < HJ_SUM_WORDS; k++) s->w[k] += t->w[k];
    s->pending += t->pending + 1;
    if (s->pending >= PENDING_MAX) hj_sum_normalize(s);
}

/* Number of significant bits of v > 0. */
static int bit_length(uint64_t v)
{
    int b = 0;
    while (v) b++, v >>= 1;
    return b;
}

double hj_sum_value(const hj_sum *s)
{
    if (s->w[HJ_SUM_NAN] || (s->w[HJ_SUM_PINF] && s->w[HJ_SUM_NINF])) return NAN;
    if (s->w[HJ_SUM_PINF]) return INFINITY;
    if (s->w[HJ_SUM_NINF]) return -INFINITY;
    hj_sum a = *s;
    hj_sum_normalize(&a);
    /* Canonical form: negative exactly when the top limb is; then the
     * magnitude is the canonical form of the negated limbs. */
    const int neg = a.w[TOP] < 0;
    if (neg) {
        for (int k = 0; k < HJ_SUM_LIMBS; k++) a.w[k] = -a.w[k];
        hj_sum_normalize(&a);
    }
    if (a.w[TOP]) return neg ? -INFINITY : INFINITY; /* >= 2^1038 */
    int h = TOP - 1;
    while (h >= 0 && !a.w[h]) h--;
    if (h < 0) return 0.0; /* an exact zero is +0 */
    /* The 64 bits below the leading one (at bit P, in units of 2^-1074),
     * left-aligned in mant; sticky records any lower nonzero bit. */
    const uint64_t L2 = (uint64_t)a.w[h], L1 = h >= 1 ? (uint64_t)a.w[h - 1] : 0, L0 = h >= 2 ? (uint64_t)a.w[h - 2] : 0;
    const int b = bit_length(L2), P = 32 * h + b - 1;
    const uint64_t mant = L2 << (64 - b) | L1 << (32 - b) | L0 >> b;
    int sticky = (L0 & (((uint64_t)1 << b) - 1)) != 0;
    for (int k = 0; k < h - 2 && !sticky; k++) sticky = a.w[k] != 0;
    /* Keep 53 bits, fewer for a subnormal result (lsb at 2^-1074). */
    int lsb = P >= 52 ? P - 52 : 0;
    const int drop = 64 - (P - lsb + 1); /* 11..63 */
    uint64_t q = mant >> drop;
    const uint64_t rem = mant & (((uint64_t)1 << drop) - 1), half = (uint64_t)1 << (drop - 1);
    q += rem > half || (rem == half && (sticky || (q & 1)));
    if (q >> 53) q >>= 1, lsb++; /* rounded up to 2^53: still exact */
    if (lsb - 1074 > 1023 - 52) return neg ? -INFINITY : INFINITY;
    const double v = ldexp((double)q, lsb - 1074); /* exact */
    return neg ? -v : v;
}

double hj_sum_array(const double *x, long n)
{
    hj_sum s;
    hj_sum_init(&s);
    for (long k = 0; k < n; k++) hj_sum_add(&s, x[k]);
    return hj_sum_value(&s);
}
