/* p2_convection.h -- the flow fields of convectionDemo (section 2.1,
 * equation (2)), shared by that demo, laxFriedrichsDemo and maskDemo
 * (section 2.2) and the Table 1 benchmark:
 *   constant  v = (2, 0, ..., 0);
 *   linear    v = A x with A = 2 pi [0 1; -1 0] in (x_1, x_2) and 0
 *             elsewhere (one clockwise turn per unit time; zero in 1-D,
 *             where A is 1 x 1);
 *   constantRev, linearRev: the same, negated once `reversed` is set (at
 *             t_max / 2, through hj_ls_seq's flag).
 */
#ifndef P2_CONVECTION_H
#define P2_CONVECTION_H

enum { P2_CONSTANT, P2_LINEAR, P2_CONSTANT_REV, P2_LINEAR_REV, P2_NFLOW };
extern const char *const p2_flow_name[P2_NFLOW];

typedef struct {
    int linear;   /* 0: constant field, 1: rotation */
    int reversed; /* 1: the field is negated */
    int dim;      /* grid dimension */
} p2_flow;

/* hj_ls_velocity_fn with ctx = p2_flow. */
void p2_flow_velocity(double t, const double *x, double dx0, long n, int d, double *v, void *ctx);

#endif
