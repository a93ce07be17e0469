/* hj_curve.c -- circles and lines as inflow curves (see hj_curve.h). */
#include "hj_curve.h"

#include <math.h>

double hj_curve_circle_level(double x, double y, void *vc)
{
    const hj_curve_circle *c = vc;
    return hypot(x - c->cx, y - c->cy) - c->r;
}

int hj_curve_circle_local(double x, double y, hj_curve_local *L, void *vc)
{
    const hj_curve_circle *c = vc;
    const double dx = x - c->cx, dy = y - c->cy, rho = hypot(dx, dy);
    if (rho == 0) return -1; /* the centre: every point of the circle is nearest */
    const double ux = dx / rho, uy = dy / rho;
    L->foot[0] = c->cx + c->r * ux;
    L->foot[1] = c->cy + c->r * uy;
    L->dist = fabs(rho - c->r);
    /* Outside: n points away from the centre and x = foot + s n has metric
     * factor (1 + s/r): kappa = 1/r.  Inside: n points to the centre,
     * factor (1 - s/r): kappa = -1/r. */
    const double side = rho >= c->r ? 1.0 : -1.0;
    L->n[0] = side * ux;
    L->n[1] = side * uy;
    L->kappa = side / c->r;
    L->g = L->g_t = L->g_tt = 0;
    return 0;
}

double hj_curve_line_level(double x, double y, void *ve)
{
    const hj_curve_line *e = ve;
    return e->inward * ((e->axis == 0 ? x : y) - e->at);
}

int hj_curve_line_local(double x, double y, hj_curve_local *L, void *ve)
{
    const hj_curve_line *e = ve;
    const double s = e->inward * ((e->axis == 0 ? x : y) - e->at);
    L->dist = fabs(s);
    L->foot[0] = e->axis == 0 ? e->at : x;
    L->foot[1] = e->axis == 0 ? y : e->at;
    const double sgn = s >= 0 ? e->inward : -e->inward;
    L->n[0] = e->axis == 0 ? sgn : 0;
    L->n[1] = e->axis == 0 ? 0 : sgn;
    L->kappa = 0;
    L->g = L->g_t = L->g_tt = 0;
    return 0;
}
