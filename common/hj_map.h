/* hj_map.h -- the right-hand side f(x, y) of the Eikonal equation for the
 * solver of paper 1 (hj_fsm.h: |grad phi| = f of Huang, Shu & Zhang 2008,
 * section 2) read from a grid file, and its bilinear interpolation.  f is
 * the slowness, 1 / speed, so that phi is a travel time: a file of speeds
 * is read and then turned into slownesses with hj_map_invert.
 *
 * Files: plain text (one row of decimal numbers per line, whitespace
 * separated, every value finite and >= 0; hj_vol.h) or a PGM image (P2 or P5, 8 or 16 bits; a
 * pixel value v maps to f = fmin + (fmax - fmin) v / maxval).  In both the
 * first row of the file is the top of the domain (largest y), as in an
 * image; in memory row 0 is the bottom.  At least 2 x 2 values.
 *
 * The map covers the rectangle [xmin, xmax] x [ymin, ymax] (the caller may
 * set it before or after reading; a reader given none, xmax <= xmin or
 * ymax <= ymin, sets pixel units, [0, mx - 1] x [0, my - 1]: one unit per
 * pixel, the bottom-left pixel at the origin): node (i, j) sits at
 * xmin + i (xmax - xmin) / (mx - 1), ymin + j (ymax - ymin) / (my - 1).  Between nodes f is
 * bilinear; outside the rectangle it is clamped to the nearest edge.
 *
 * Library code: returns HJ_* codes with a message naming the file, the
 * line and column of the bad token (in P5 pixel data its byte offset),
 * never prints.  What a message quotes from the file is escaped (\xHH
 * for a control or non-ASCII byte).  A header is checked against the
 * file's size before the pixels are allocated.
 */
#ifndef HJ_MAP_H
#define HJ_MAP_H

#include "hj_error.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    int mx, my;      /* map nodes per row, rows */
    double *v;       /* row-major, row 0 = bottom; NULL: the constant speed */
    double xmin, xmax, ymin, ymax;
    double constant; /* used when v == NULL */
} hj_map;

/* f at (x, y); ctx is an hj_map (the signature of hj_speed.f). */
double hj_map_eval(double x, double y, void *ctx);

/* Read a text grid or a PGM image into m->mx, m->my, m->v (the other
 * fields are left alone).  HJ_EIO when the file cannot be read,
 * HJ_EFORMAT when it is malformed, HJ_ENONFINITE for a negative or
 * non-finite text value, HJ_ENOMEM. */
int hj_map_read_text(hj_map *m, const char *path, hj_error *err);
int hj_map_read_pgm(hj_map *m, const char *path, double fmin, double fmax, hj_error *err);
/* The format told by the content, not the name (hj_vol_is_pgm):
 * hj_map_read_pgm for a file starting with "P2" or "P5" and white space,
 * else hj_map_read_text. */
int hj_map_read(hj_map *m, const char *path, double fmin, double fmax, hj_error *err);

/* Speeds to slownesses: every value v becomes 1 / v.  HJ_EINVAL naming
 * the row (counted from the top, as in the file) and column of the first
 * value that is not positive; m is then unchanged. */
int hj_map_invert(hj_map *m, hj_error *err);

/* Free m->v (m itself is the caller's). */
void hj_map_free(hj_map *m);

#ifdef __cplusplus
}
#endif

#endif
