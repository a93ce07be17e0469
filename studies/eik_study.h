/* What the Eikonal studies (defect_correction, nested_eik, anderson_eik)
 * share: the `linear` case of paper 1's convergence study (speed
 * v = V0 + G . x, a point source at S; hj_eik_linear_time its travel time)
 * and whole-argument number parsing. */
#ifndef EIK_STUDY_H
#define EIK_STUDY_H

#include <limits.h>
#include <math.h>

#include "hj_cli.h"

#define EIK_STUDY_V0 2.0
#define EIK_STUDY_S {0.1234, -0.0567, 0.0311}
#define EIK_STUDY_G {0.5, -0.3, 0.2}

/* v(x) = V0 + G . x, summed in dimension order. */
static inline double eik_study_vel(int dim, double v0, const double *g, const double *x)
{
    double v = v0;
    for (int d = 0; d < dim; d++) v += g[d] * x[d];
    return v;
}

/* A whole argument as a number (hj_cli's parsers: the whole string, a
 * finite double); 0 when it is not one. */
static inline int eik_study_long(const char *s, long *v)
{
    return hj_parse_long(s, "", LONG_MIN, LONG_MAX, v, NULL) == HJ_OK;
}
static inline int eik_study_double(const char *s, double *v)
{
    return hj_parse_double(s, "", -HUGE_VAL, HUGE_VAL, v, NULL) == HJ_OK;
}

#endif
