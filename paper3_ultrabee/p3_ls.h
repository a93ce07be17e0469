/* p3_ls.h -- the level set comparison of section 4: "a very simple
 * RK2-ENO2 solver (without reinitialization), following Osher and Shu",
 * run on the common level set kernel (hj_ls_grid, hj_ls_convection /
 * hj_ls_extremum, hj_ls_ode with order 2 = Heun and HJ_LS_ENO2): nothing
 * here differentiates or integrates in time by itself.
 *
 * Grid: the UB grid (n nodes per direction including both ends, dx = L /
 * (n - 1)), so that the level set values sit at the UB cell centres and the
 * errors of hj_front_ls_errors are the UB ones.  Ghost nodes by linear
 * extrapolation away from zero (the toolbox's usual level set boundary).
 * Time step: the kernel's CFL bound for the unsplit scheme, dt max_x
 * sum_d |f_d(x)| / dx_d = P3_LS_CFL (for several controls the largest
 * over them), the last step shortened to land on the end time.  The
 * paper's CFL = 0.9 is unusable for this scheme (overview.md): with its
 * condition (10) (max over d) RK2-ENO2 blows up on the diagonal flow of
 * Table 6 at N = 50; with the sum, at N = 400.  P3_LS_CFL is the kernel's
 * (and Mitchell's toolbox's) default FactorCFL, 0.5. */
#define P3_LS_CFL 0.5
#ifndef P3_LS_H
#define P3_LS_H

#include <stdint.h>

#include "hj_ls_grid.h"
#include "hj_ls_term.h"
#include "hj_ub.h"

typedef struct {
    hj_ls_grid g;
    double *y;     /* the level set function, on g */
    int d, n;
    double t;      /* time reached */
    long steps;    /* steps taken */
    double lost_t; /* first time after a step at which {V <= 0} was empty (NAN: never) */
} p3_ls;

/* Grid on [lo, hi]^d with n nodes per direction, y = phi0 at the nodes. */
int p3_ls_init(p3_ls *ls, int d, int n, const double *lo, const double *hi, hj_ls_field_fn phi0, void *ctx,
               hj_error *err);
void p3_ls_free(p3_ls *ls);

/* Advance from ls->t to t1 with the term (TVD RK2, FactorCFL = cfl). */
int p3_ls_run(p3_ls *ls, const hj_ls_term *term, double t1, double cfl, hj_error *err);

/* The values at the n^d nodes, in the layout of hj_ub_values (last
 * index fastest).  For figures.  The errors of section 4 are
 * hj_front_ls_errors(&ls->g, ls->y, ...), measured as the UB runs are. */
void p3_ls_values(const p3_ls *ls, double *out);

#endif
