/* hj_curve.h -- two inflow curves for the fast sweeping solver (hj_fsm.h),
 * with the level and local descriptions of an HJ_INFLOW_CURVE piece: a
 * circle (Examples 3 and 4 of Huang, Shu & Zhang 2008, section 3) and an
 * axis-parallel line (the edges of the box of Example 2).  The data on
 * both is phi = 0.
 */
#ifndef HJ_CURVE_H
#define HJ_CURVE_H

#include "hj_fsm.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The circle of radius r centred at (cx, cy); level is the signed
 * distance, negative inside. */
typedef struct {
    double cx, cy, r;
} hj_curve_circle;
double hj_curve_circle_level(double x, double y, void *circle);
/* -1 at the centre, where every point of the circle is nearest. */
int hj_curve_circle_local(double x, double y, hj_curve_local *out, void *circle);

/* The line x = at (axis 0) or y = at (axis 1); level is the distance,
 * positive on the side inward points to. */
typedef struct {
    int axis;      /* 0: the line x = at; 1: the line y = at */
    double at;
    double inward; /* +1 or -1: the side of the domain */
} hj_curve_line;
double hj_curve_line_level(double x, double y, void *line);
int hj_curve_line_local(double x, double y, hj_curve_local *out, void *line);

#ifdef __cplusplus
}
#endif

#endif
