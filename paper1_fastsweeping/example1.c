/*
# Example 1: a point source, Richardson extrapolation (Table 3.1)

**Problem.** The Eikonal equation |grad phi| = f on [-1, 1]^2 with

    f(x, y) = (pi/2) sqrt( sin^2(pi x / 2) + sin^2(pi y / 2) ),

and the single inflow point (0, 0), where phi = -2.  The exact solution is
phi(x, y) = -cos(pi x / 2) - cos(pi y / 2).  The speed vanishes at the
source, so phi is smooth there (phi ~ -2 + pi^2 r^2 / 8).

**Method.** Third order WENO fast sweeping (section 2.1).  The source is
Category I; the other 24 nodes of the box [-2h, 2h]^2 around it are
Category III and are fixed by Richardson extrapolation (2.9) of first
order Godunov sweeps run on that box alone with mesh sizes h, h/2 and h/4.
The box boundary [-1, 1]^2 is outflow: two ghost layers are filled by third
order extrapolation before every sweep.  The first order solution is the
initial guess.

**Parameters.** N = 40, 80, 160, 320, 640 intervals per direction
(h = 2/N, so that the source is a node), WENO eps = 1e-6, stopping rule
(2.8) with delta = 1e-11 on h^2 sum |phi_new - phi_old| over a full
iteration of four sweeps.  L1 error = h^2 sum |phi - exact| over the nodes
(the integral; the mean over nodes is 4x smaller here), L-infinity the
maximum.  These readings of the paper are justified in the overview.
`--quick` runs N = 40, 80, 160.

**Output.** Table 3.1 (L1, L-infinity errors, orders, iteration counts),
its convergence figure with the fitted orders, and a contour plot.
*/
#include <math.h>

#include "p1_study.h"
#include "hj_math.h"


static double speed(double x, double y, void *ctx)
{
    (void)ctx;
    const double sx = sin(HJ_PI * x / 2), sy = sin(HJ_PI * y / 2);
    return HJ_PI / 2 * sqrt(sx * sx + sy * sy);
}

static void speed_grad(double x, double y, double g[2], void *ctx)
{
    const double f = speed(x, y, ctx);
    /* f f_x = (pi/2)^2 sin(pi x/2) cos(pi x/2) (pi/2) */
    const double c = HJ_PI * HJ_PI * HJ_PI / 8;
    g[0] = f > 0 ? c * sin(HJ_PI * x / 2) * cos(HJ_PI * x / 2) / f : 0;
    g[1] = f > 0 ? c * sin(HJ_PI * y / 2) * cos(HJ_PI * y / 2) / f : 0;
}

static double exact(double x, double y) { return -cos(HJ_PI * x / 2) - cos(HJ_PI * y / 2); }

int main(int argc, char **argv)
{
    static const hj_inflow source[] = {{.type = HJ_INFLOW_POINT, .x = 0, .y = 0, .value = -2, .richardson = 1}};
    static const long sizes[] = {40, 80, 160, 320, 640};
    const p1_case cases[] = {{.name = "-", .domain = {-1, 1, -1, 1}, .speed = {speed, speed_grad, NULL}, .exact = exact,
                              .inflow = source, .ninflow = 1, .eps = 1e-6}};
    const p1_study study = {.program = "example1", .table = "table3.1", .strategy = HJ_BC_RICHARDSON, .cases = cases,
                            .ncases = 1, .sizes = sizes, .nsizes = 5, .nquick = 3};
    return p1_main(argc, argv, &study, NULL);
}
