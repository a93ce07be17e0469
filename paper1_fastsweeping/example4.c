/*
# Example 4: two circles, Lax-Wendroff (Table 3.5)

**Problem.** |grad phi| = 1 on [-3, 3]^2 with phi = 0 on two circles of
radius 0.5 centred at (-1, 0) and (sqrt(1.5), 0).  The exact solution is
the distance to the nearer circle.  It is singular at the two centres and
on the bisector x = (sqrt(1.5) - 1)/2 where the characteristics of the two
circles meet.  The paper measures the errors outside the boxes
[-1.15, -0.85] x [-0.15, 0.15], [sqrt(1.5) - 0.15, sqrt(1.5) + 0.15] x
[-0.15, 0.15] and [sqrt(0.375) - 0.65, sqrt(0.375) - 0.35] x [-3, 3]
(sqrt(0.375) - 0.5 = (sqrt(1.5) - 1)/2 is the bisector).  As in Example 3
we leave out the nodes closer than 0.15 to a centre (the discs inscribed in
the first two boxes) and the band, closed, as written: the L-infinity
errors then agree within 1.3 % at N = 160, 320, 640 (7.567e-4, 2.940e-5,
3.363e-6 against 0.766E-03, 0.294E-04, 0.336E-05); the boxes as written
(`--exclude literal`) give 0.26-0.58 of them.  The study "Where the errors
of Examples 3 and 4 are measured", under Example 3, shows both.

**Method.** As Example 3, with two inflow curves; a Category III node takes
its Lax-Wendroff value from the nearer circle.

**Parameters.** N = 80, 160, 320, 640 (h = 6/N), WENO eps = 1e-6,
delta and norms as in Example 1.  `--quick` runs N = 80, 160.

**Output.** Table 3.5, its convergence figure, a contour plot.
*/
#include <math.h>

#include "hj_curve.h"
#include "p1_study.h"

static hj_curve_circle circles[2] = {{-1, 0, 0.5}, {0, 0, 0.5}};

static double exact(double x, double y)
{
    return fmin(fabs(hj_curve_circle_level(x, y, &circles[0])), fabs(hj_curve_circle_level(x, y, &circles[1])));
}

int main(int argc, char **argv)
{
    circles[1].cx = sqrt(1.5);
    static const hj_inflow gamma[] = {
        {.type = HJ_INFLOW_CURVE, .level = hj_curve_circle_level, .local = hj_curve_circle_local, .ctx = &circles[0]},
        {.type = HJ_INFLOW_CURVE, .level = hj_curve_circle_level, .local = hj_curve_circle_local, .ctx = &circles[1]}};
    const double s15 = sqrt(1.5), s0375 = sqrt(0.375);
    const p1_box excl[] = {
        {-1.15, -0.85, -0.15, 0.15, .around_point = 1},
        {s15 - 0.15, s15 + 0.15, -0.15, 0.15, .around_point = 1},
        {s0375 - 0.65, s0375 - 0.35, -3, 3, .around_point = 0}};
    static const long sizes[] = {80, 160, 320, 640};
    const p1_case cases[] = {{.name = "-", .domain = {-3, 3, -3, 3}, .speed = {p1_unit_speed, p1_unit_speed_grad, NULL},
                              .exact = exact, .inflow = gamma, .ninflow = 2, .exclude = excl, .nexclude = 3,
                              .eps = 1e-6}};
    const p1_study study = {.program = "example4", .table = "table3.5", .strategy = HJ_BC_LAX_WENDROFF,
                            .cases = cases, .ncases = 1, .sizes = sizes, .nsizes = 4, .nquick = 2};
    return p1_main(argc, argv, &study, NULL);
}
