/* hj_eik_guard.c -- plausibility check of an Eikonal solution (see
 * hj_eik_guard.h). */
#include "hj_eik_guard.h"

#include <math.h>

int hj_eik_guard(const double *T, const unsigned char *reached, const long n[3], double t_min, double scale,
                 hj_error *err)
{
    /* far above rounding in T (1e-16 of its size), far below any
     * discretisation error: a blow-up is many orders beyond it */
    const double lo = t_min - HJ_EIK_GUARD_TOL * (fabs(t_min) + fabs(scale));
    const size_t total = (size_t)n[0] * (size_t)n[1] * (size_t)n[2];
    for (size_t k = 0; k < total; k++) {
        const double v = T[k];
        const int must = reached ? reached[k] : v != INFINITY;
        if (!must && !isnan(v) && v != -INFINITY) continue;
        if (isfinite(v) && v >= lo) continue;
        const long a = (long)(k % (size_t)n[0]), b = (long)(k / (size_t)n[0] % (size_t)n[1]),
                   c = (long)(k / ((size_t)n[0] * (size_t)n[1]));
        return hj_error_set(err, HJ_ENOCONV,
                            "the iteration blew up: T = %g at node (%ld, %ld, %ld), %s the earliest start %g; the "
                            "last iterate is kept (try order 1)",
                            v, a, b, c, isfinite(v) ? "below" : "not finite, reached from", t_min);
    }
    return HJ_OK;
}
