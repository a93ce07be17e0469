/* p2_convection.c -- see p2_convection.h. */
#include "p2_convection.h"

#include "hj_math.h"

const char *const p2_flow_name[P2_NFLOW] = {"constant", "linear", "constantRev", "linearRev"};

void p2_flow_velocity(double t, const double *x, double dx0, long n, int d, double *v, void *ctx)
{
    (void)t;
    const p2_flow *f = ctx;
    const double s = f->reversed ? -1.0 : 1.0;
    if (!f->linear) {
        for (long j = 0; j < n; j++) v[j] = d == 0 ? 2 * s : 0;
    } else if (f->dim < 2) {
        for (long j = 0; j < n; j++) v[j] = 0;
    } else if (d == 0) {
        for (long j = 0; j < n; j++) v[j] = s * 2 * HJ_PI * x[1];
    } else if (d == 1) {
        for (long j = 0; j < n; j++) v[j] = -s * 2 * HJ_PI * (x[0] + (double)j * dx0);
    } else {
        for (long j = 0; j < n; j++) v[j] = 0;
    }
}
