/* hj_ls_front.h -- how well a computed level set function holds its front
 * (the zero level set), the measurements of the toolbox's demos against
 * exact solutions: convectionDemo and laxFriedrichsDemo (sections 2.1,
 * 2.2.2: phi after a full turn against phi_0 near the front), reinitDemo
 * and reinitTest (sections 2.2.1, 2.7.3: |grad phi| = 1, equation (4),
 * and how far reinitialization shifted the front).
 *
 * Means over grid nodes are exact sums (hj_sum.h), rounded once; the mean
 * distance of crossings is summed in crossing order.  Nothing here prints
 * or exits.
 */
#ifndef HJ_LS_FRONT_H
#define HJ_LS_FRONT_H

#include "hj_error.h"
#include "hj_ls_grid.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Maximum and mean of |phi - exact| over the interior nodes where
 * |exact| < band (0 if there is none). */
void hj_ls_front_error(const hj_ls_grid *g, const double *phi, const double *exact, double band, double *max,
                       double *mean);

/* Mean and maximum of | |grad phi| - 1 | (hj_ls_gradient_norm) over the
 * interior nodes where |dist| < band; work is an array on g; phi's ghost
 * layer is filled. */
int hj_ls_front_grad_deviation(const hj_ls_grid *g, double *phi, const double *dist, double band, double *work,
                               double *mean, double *max, hj_error *err);

/* Zero crossings of phi along the grid edges of a 2-D grid, linearly
 * interpolated (a node exactly zero counts once): *pts (malloc'd, 2
 * doubles per point, freed by the caller) and *n. */
int hj_ls_front_crossings(const hj_ls_grid *g, const double *phi, double **pts, long *n, hj_error *err);

/* Distance from each of the np points p to the closed polygon through the
 * nc curve samples c (2 doubles each; nearest sample by brute force, then
 * its two chords): maximum and mean.  With samples spaced h on a curve of
 * curvature kappa the polygon is within kappa h^2 / 8 of the curve. */
void hj_ls_front_distance(const double *p, long np, const double *c, long nc, double *max, double *mean);

#ifdef __cplusplus
}
#endif

#endif
