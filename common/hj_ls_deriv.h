/* hj_ls_deriv.h -- spatial derivative approximations of the level set
 * kernel (Mitchell's toolbox, section 3.4; Osher & Fedkiw ch. 3).
 *
 * Upwind first derivatives (section 3.4.1).  For dimension d the left
 * approximation D-phi(x_i) serves flow coming from lower indices, the right
 * one D+phi(x_i) flow from higher indices.  With the first divided
 * differences D1_{j+1/2} = (phi_{j+1} - phi_j) / dx:
 *   FIRST   D- = D1_{i-1/2}, D+ = D1_{i+1/2}                       (order 1)
 *   ENO2    adds the smaller (in modulus) neighbouring second divided
 *           difference (O&F (3.22))                                (order 2)
 *   ENO3A   third order ENO from the divided difference table: the stencil
 *           grows one node at a time toward the smaller divided difference
 *           (O&F (3.18)-(3.24))                                    (order 3)
 *   ENO3B   the same scheme in direct form: the three candidates by
 *           O&F (3.25)-(3.27) from v1..v5, the stencil picked by the same
 *           comparisons written in undivided differences of the v's
 *   WENO5A  fifth order WENO: the weights of O&F (3.28)-(3.37) and the
 *           epsilon of (3.38), eps = 1e-6 max v_k^2 + 1e-99, the blend of
 *           the three ENO3 candidates computed in Jiang and Peng's form
 *           (a central part plus a correction in second differences;
 *           algebraically the same blend, hj_ls_deriv.c)          (order 5)
 *   WENO5B  the same weights on the candidates by (3.25)-(3.27)
 *   WENO3   third order WENO (section 4 "future feature"): candidates
 *           -v1/2 + 3 v2/2 and (v2 + v3)/2, ideal weights 1/3, 2/3,
 *           smoothness (v2 - v1)^2, (v3 - v2)^2, eps = 1e-6     (order 3)
 * The A and B forms are the same schemes computed differently; they agree
 * to round-off (tests/test_ls_deriv.c).  Paper ambiguity: the toolbox says
 * ENO3b picks "the smallest smoothness estimate (3.32)-(3.34)", which is a
 * different stencil choice from ENO3a at some nodes and would contradict
 * its own statement that the two are equivalent; we keep ENO's choice.
 *
 * Centered approximations (section 3.4.2), second order: first derivative,
 * Hessian entries, Laplacian, mean curvature with gradient magnitude.
 *
 * All array functions take arrays laid out on the grid (hj_ls_grid.h),
 * write interior nodes only, and fill the ghost layer of their input first
 * (which is why the input is not const).  They never print or exit.
 */
#ifndef HJ_LS_DERIV_H
#define HJ_LS_DERIV_H

#include <stddef.h>

#include "hj_error.h"
#include "hj_ls_grid.h"

#ifdef __cplusplus
extern "C" {
#endif

enum {
    HJ_LS_UPWIND_FIRST,
    HJ_LS_ENO2,
    HJ_LS_ENO3A,
    HJ_LS_ENO3B,
    HJ_LS_WENO5A,
    HJ_LS_WENO5B,
    HJ_LS_WENO3,
    HJ_LS_NSCHEMES
};

/* The ghost layers a scheme's stencil reads on each side: 1 for first
 * order, 2 for ENO2 and WENO3, 3 for ENO3 and WENO5 (HJ_LS_GHOST, also
 * for an unknown scheme).  What a distributed grid exchanges per fill. */
int hj_ls_scheme_ghost(int scheme);

/* The toolbox name of a scheme ("upwindFirstENO3a", ...), or NULL. */
const char *hj_ls_scheme_name(int scheme);
/* Formal order of accuracy on smooth data. */
int hj_ls_scheme_order(int scheme);

/* Doubles of workspace hj_ls_upwind_row needs per node of a row. */
#define HJ_LS_ROW_WORK 16

/* Row kernel: left and right derivatives along the direction of stride s
 * for the n nodes p[0], p[1], ..., p[n-1]; every p[i + k s] with |k| <= 3
 * must be valid.  w holds HJ_LS_ROW_WORK * n doubles.  An unknown scheme
 * leaves dl and dr untouched (the array functions check schemes). */
void hj_ls_upwind_row(int scheme, const double *p, ptrdiff_t s, long n, double dx, double *dl, double *dr, double *w);

/* The same with the WENO5 epsilon given: eps < 0 is O&F (3.38), 1e-6 times
 * the largest squared first difference of the five a node's stencil uses
 * (+1e-99), what hj_ls_upwind_row does; eps >= 0 is used at every node
 * (ToolboxLS's upwindFirstWENO5a takes 1e-6 times the largest over the
 * whole grid, its 'maxOverGrid': hj_ls_weno_eps_grid), but not below
 * 1e-60 times the node's largest squared difference (+1e-153): a smaller
 * one, 0 included, overflowed the weights (NaN at every node).  Other
 * schemes ignore eps. */
void hj_ls_upwind_row_eps(int scheme, const double *p, ptrdiff_t s, long n, double dx, double eps, double *dl,
                          double *dr, double *w);

/* The schemes computed from first differences only (ENO3A/B, WENO5A/B,
 * WENO3), from D[k][i] = D1_{i+k-3+1/2} (k = 0..5; WENO3 reads 1..4) of
 * n nodes: the same bits as hj_ls_upwind_row_eps, for callers that keep
 * the differences from row to row (the rows along a dimension other than
 * 0 share five of their six rows of differences with the previous row).
 * Other schemes leave dl and dr untouched. */
void hj_ls_upwind_diffs_eps(int scheme, const double *const *D, long n, double eps, int mean, double *dl, double *dr);
/* hj_ls_upwind_diffs_eps for WENO5A/B (returns 0 and writes nothing for
 * another scheme) on a row whose neighbour in the direction of the
 * differences comes next: the window D[1..5] gives this row's right
 * derivative and the next row's left one, into next (n doubles); the left
 * derivative is read from left (the previous row's next, not aliasing
 * next) or, left NULL, computed from D[0..4].  One window per node instead
 * of two, the same bits. */
int hj_ls_weno5_diffs_next_eps(int scheme, const double *const *D, long n, double eps, int mean, const double *left,
                               double *next, double *dl, double *dr);
/* hj_ls_weno5_diffs_next_eps with the differences taken from the values
 * p along stride s (spacing dx), as hj_ls_upwind_row_eps takes them (no
 * rows of differences stored and read back): for rows whose neighbour in
 * a dimension other than 0 comes later (the next row along dimension 1,
 * the next plane along dimension 2), whose left derivatives the caller
 * keeps.  The same bits as hj_ls_upwind_row_eps. */
int hj_ls_weno5_row_next_eps(int scheme, const double *p, ptrdiff_t s, long n, double dx, double eps, int mean,
                             const double *left, double *next, double *dl, double *dr);
/* mean = 1 above, and hj_ls_upwind_row_mean_eps: instead of D- and D+,
 * their mean (D- + D+)/2 into dl (mean) and their difference D+ - D- into
 * dr (diff), computed as a caller would from D- and D+ (the same bits):
 * what a Lax-Friedrichs term reads of them. */
void hj_ls_upwind_row_mean_eps(int scheme, const double *p, ptrdiff_t s, long n, double dx, double eps, double *mean,
                               double *diff, double *w);
/* hj_ls_upwind_row_mean_eps along each dimension d < dim (stride s[d],
 * spacing dx[d]) into mean + d n and diff + d n, in one call: the first
 * order and ENO2 schemes only (the same bits; no workspace); returns 0
 * and writes nothing for another scheme.  inv[d] must be 1.0 / dx[d]
 * (a row pass divides once, not once per row). */
int hj_ls_upwind_rows_mean(int scheme, const double *p, const ptrdiff_t *s, int dim, long n, const double *dx,
                           const double *inv, double *mean, double *diff);
/* hj_ls_upwind_rows_mean on nrows rows along x_0 that follow each other
 * along dimension 1 (row b at p + b s[1]; nrows = 1 in 1-D), row b of
 * dimension d into mean + d nrows n + b n and diff + d nrows n + b n: one
 * call for a block of rows (the same bits). */
int hj_ls_upwind_rows_mean_block(int scheme, const double *p, const ptrdiff_t *s, int dim, long n, long nrows,
                                 const double *dx, const double *inv, double *mean, double *diff);

/* ToolboxLS's WENO5 epsilon along dimension d ('maxOverGrid' in
 * upwindFirstWENO5a): 1e-6 max (D1)^2 + 1e-99 over every first difference
 * along d of the interior rows extended by three ghost nodes at each end
 * (filled beforehand, hj_ls_fill_ghosts), as the toolbox's divided
 * difference table holds them. */
double hj_ls_weno_eps_grid(const hj_ls_grid *g, const double *data, int d);

/* The upwind side only: out[i] = D-phi where v[i] > 0, else D+phi, with
 * the same values as hj_ls_upwind_row (bitwise).  For WENO only the needed
 * side is computed (half the work); w as above. */
void hj_ls_upwind_row_select(int scheme, const double *p, ptrdiff_t s, long n, double dx, const double *v,
                             double *out, double *w);
/* The same with the WENO5 epsilon given (as hj_ls_upwind_row_eps). */
void hj_ls_upwind_row_select_eps(int scheme, const double *p, ptrdiff_t s, long n, double dx, double eps,
                                 const double *v, double *out, double *w);

/* The WENO part of hj_ls_upwind_row_select from precomputed first
 * differences: D[k][i] = D1_{i+k-3+1/2} along the direction, k = 0..5
 * (WENO5A, WENO5B, WENO3 only; other schemes leave out untouched).  Lets a
 * caller reuse differences between neighbouring rows. */
void hj_ls_upwind_select_diffs(int scheme, const double *const *D, long n, const double *v, double *out);
/* The same with the WENO5 epsilon given (as hj_ls_upwind_row_eps). */
void hj_ls_upwind_select_diffs_eps(int scheme, const double *const *D, long n, double eps, const double *v,
                                   double *out);

/* The transport term of a 2-D row with WENO5A/B, from the differences D0
 * (along dimension 0) and D1 (along dimension 1) laid out as above:
 * out[i] = (0 - v0[i] W0[i]) - v1[i] W1[i], W_d the upwind side (v_d > 0:
 * left) of hj_ls_upwind_select_diffs_eps with the epsilon eps[d] (the
 * same bits as that function's values summed in dimension order).  A
 * dimension whose velocity row is NULL has no flow and is left out
 * (out = 0 - v W of the other), its D not read.  Returns 0 and writes
 * nothing for other schemes or when both velocity rows are NULL. */
int hj_ls_weno5_transport2_eps(int scheme, const double *const *D0, const double *const *D1, long n,
                               const double *eps, const double *v0, const double *v1, double *out);

/* D[i] = (p[i + (k+1) s] - p[i + k s]) / dx for i < n: one row of the
 * differences above (k = -3..2), computed exactly as the kernels do. */
void hj_ls_upwind_difference_row(const double *p, ptrdiff_t s, long n, double dx, int k, double *D);

/* Left (dl) and right (dr) upwind derivatives in dimension d of data. */
int hj_ls_upwind(const hj_ls_grid *g, int scheme, double *data, int d, double *dl, double *dr, hj_error *err);

/* Centered first derivative in dimension d. */
int hj_ls_centered_first(const hj_ls_grid *g, double *data, int d, double *out, hj_error *err);

/* out = |grad phi| by centered differences (second order); work is an
 * array on g (ghosts are filled in data). */
int hj_ls_gradient_norm(const hj_ls_grid *g, double *data, double *work, double *out, hj_error *err);

/* Hessian entry d^2 phi / dx_i dx_j (i = j: the second derivative). */
int hj_ls_hessian(const hj_ls_grid *g, double *data, int i, int j, double *out, hj_error *err);

/* Laplacian, sum of the second derivatives. */
int hj_ls_laplacian(const hj_ls_grid *g, double *data, double *out, hj_error *err);

/* Mean curvature kappa = div(grad phi / |grad phi|) (toolbox curvatureSecond)
 * and the centered gradient magnitude (grad_mag may be NULL).  Where
 * |grad phi| = 0 the curvature is set to 0. */
int hj_ls_curvature(const hj_ls_grid *g, double *data, double *kappa, double *grad_mag, hj_error *err);

/* Curvature and gradient magnitude at one node from its centered stencil
 * (p is the node, the grid gives strides and spacings). */
void hj_ls_curvature_at(const hj_ls_grid *g, const double *p, double *kappa, double *grad_mag);

#ifdef __cplusplus
}
#endif

#endif
