/* hj_sum.h -- exact sums of doubles, independent of the order of the terms.
 *
 * An accumulator (a "superaccumulator") holds the exact sum of any number
 * of doubles as a fixed-point integer: HJ_SUM_LIMBS signed 64-bit limbs,
 * limb i of weight 2^(32 i - 1074), so limb 0 is the smallest subnormal and
 * limb 65 reaches beyond the largest double (2^1024); limb 66 is headroom.
 * A double m 2^e (53-bit integer m) is split into three 32-bit pieces that
 * are added to three consecutive limbs: no rounding, ever.  The limbs keep
 * 31 bits of carry room; hj_sum_normalize propagates the carries so that
 * limbs 0..65 lie in [0, 2^32) and limb 66 holds the signed rest: one
 * canonical form per exact sum.  hj_sum_add normalizes by itself before
 * the carry room can run out (every 2^30 additions).
 *
 * The value (hj_sum_value) is the exact sum rounded to nearest, ties to
 * even: the correctly rounded sum, a function of the exact sum alone, so
 * the same bits come out for any order of the terms, any split into
 * partial accumulators and any merge order (threads, processes).  An exact
 * sum of zero gives +0 (as a plain loop from s = 0.0 does); a sum beyond
 * the double range gives +-Inf.  NaN and Inf terms are counted apart and
 * propagate as in a plain sum: any NaN, or +Inf with -Inf, gives NaN;
 * otherwise +Inf (-Inf) gives +Inf (-Inf).
 *
 * Merging (hj_sum_merge) adds limbs and counts: integer additions, exact
 * and associative.  Across MPI processes, normalize each accumulator and
 * add the HJ_SUM_WORDS int64 words w[] with MPI_Allreduce(MPI_INT64_T,
 * MPI_SUM), then set pending to the process count and normalize: limbs
 * 0..65 of P normalized accumulators add to less than P 2^32, exact for
 * P < 2^31 processes (limb 66 holds |sum| / 2^1038: no bound in practice).
 *
 * The struct is the caller's (no allocation): about 560 bytes.
 */
#ifndef HJ_SUM_H
#define HJ_SUM_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define HJ_SUM_LIMBS 67
/* Words after the limbs: counts of NaN, +Inf and -Inf terms. */
enum { HJ_SUM_NAN = HJ_SUM_LIMBS, HJ_SUM_PINF, HJ_SUM_NINF, HJ_SUM_WORDS };

typedef struct {
    int64_t w[HJ_SUM_WORDS]; /* limbs 0..HJ_SUM_LIMBS-1, then the counts */
    int64_t pending;         /* additions (or merged terms) since the last normalization */
} hj_sum;

/* An empty sum (exact value 0). */
void hj_sum_init(hj_sum *s);

/* s += x, exactly. */
void hj_sum_add(hj_sum *s, double x);

/* s += t, exactly (t unchanged). */
void hj_sum_merge(hj_sum *s, const hj_sum *t);

/* Propagate the carries: limbs 0..HJ_SUM_LIMBS-2 in [0, 2^32), the last
 * limb signed; pending = 0.  The exact value is unchanged. */
void hj_sum_normalize(hj_sum *s);

/* The exact sum rounded to nearest (ties to even); see above for zero,
 * overflow, NaN and Inf.  s is not changed. */
double hj_sum_value(const hj_sum *s);

/* The correctly rounded sum of x[0..n-1]. */
double hj_sum_array(const double *x, long n);

#ifdef __cplusplus
}
#endif

#endif
