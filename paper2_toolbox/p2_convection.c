/* p2_convection.c -- see p2_convection.h. */
#include "p2_convection.h"

#include <limits.h>

#include "hj_ls_accuracy.h"
#include "hj_math.h"

const char *const p2_flow_name[P2_NFLOW] = {"constant", "linear", "constantRev", "linearRev"};

void p2_flow_velocity(double t, const double *x, double dx0, long n, int d, double *v, void *ctx)
{
    (void)t;
    const p2_flow *f = ctx;
    const double s = f->reversed ? -1.0 : 1.0;
    /* x read once into locals: v might alias x for the compiler, which
     * would otherwise reload it per node and not vectorise the loops */
    if (!f->linear) {
        const double c = d == 0 ? 2 * s : 0;
        for (long j = 0; j < n; j++) v[j] = c;
    } else if (f->dim < 2) {
        for (long j = 0; j < n; j++) v[j] = 0;
    } else if (d == 0) {
        const double c = s * 2 * HJ_PI * x[1];
        for (long j = 0; j < n; j++) v[j] = c;
    } else if (d == 1) {
        /* an int counter: its conversion to double vectorises (a long's
         * does not before AVX-512), with the same values */
        const double c = -s * 2 * HJ_PI, x0 = x[0];
        const int ni = n < INT_MAX ? (int)n : INT_MAX;
        for (int j = 0; j < ni; j++) v[j] = c * (x0 + (double)j * dx0);
        for (long j = ni; j < n; j++) v[j] = c * (x0 + (double)j * dx0);
    } else {
        for (long j = 0; j < n; j++) v[j] = 0;
    }
}

int p2_solve(const char *path, int acc, const hj_ls_grid *g, const hj_ls_term *term, double tmax, double *y,
             const hj_ls_ode_opts *opts, hj_ls_seq *seq, hj_ls_ode_stats *stats, hj_error *err)
{
    double tspan[P2_NT];
    hj_ls_seq_times(0, tmax, P2_NT, tspan);
    hj_ls_seq plain;
    if (!seq) {
        hj_ls_seq_init(&plain, NULL, g, "phi", 10);
        seq = &plain;
    }
    return hj_ls_seq_solve_file(path, hj_ls_accuracy_order(acc), g, term, tspan, P2_NT, y, opts, seq, stats, err);
}
