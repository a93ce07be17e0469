/* hj_vol.h -- grids of values in 2-D and 3-D read from files (speed or
 * slowness maps of the Eikonal tool), and a legacy VTK writer for 3-D
 * results.
 *
 * In memory a volume is x-fastest: value (i, j, k) at
 * v[i + n[0] (j + n[1] k)], j = 0 the bottom row, k = 0 the bottom slice
 * (the layout of hj_eik.h's grids).
 *
 * Text: one row of numbers per line, whitespace separated, every value
 * finite and >= 0, written in decimal (1, 0.5, -2e-3, .5; not
 * hexadecimal, which strtod would take).  A slice is a block of rows laid out as a 2-D map
 * (hj_map.h): its first line is its top row (largest y).  Slices are
 * separated by one or more blank lines, the first slice is k = 0.  A file
 * of one block is a 2-D map.
 *
 * Raw: n[0] n[1] n[2] little-endian IEEE floats (4 or 8 bytes), x fastest,
 * then y upwards, then z (numpy's C order of an array indexed [k][j][i],
 * written with tofile() on a little-endian machine); the dimensions come
 * from the caller, and the file must hold exactly that many bytes.
 *
 * Library code: HJ_* codes with a message naming the file and the place
 * of the bad value, never prints.
 */
#ifndef HJ_VOL_H
#define HJ_VOL_H

#include "hj_error.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    int dim;      /* 2 or 3 */
    long n[3];    /* values per dimension (n[2] = 1 when dim = 2) */
    double *v;    /* x-fastest, row 0 and slice 0 at the bottom */
} hj_vol;

/* A text grid (see above).  slices = 1: blank lines separate slices (a
 * file of one block gives dim 2); slices = 0: blank lines are ignored and
 * every row belongs to one 2-D map.  At least 2 values per dimension.
 * HJ_EIO, HJ_EFORMAT (with file:line:column; a token that is not a decimal
 * number too), HJ_ENONFINITE (a negative or non-finite value), HJ_ENOMEM. */
int hj_vol_read_text(hj_vol *vol, const char *path, int slices, hj_error *err);

/* A raw volume of n[0] x n[1] x n[2] values of `bytes` (4 or 8) bytes
 * each (n[2] = 1: a 2-D map, row 0 at the bottom).  HJ_EFORMAT when the
 * file's size is not exactly that, HJ_ENONFINITE naming the index (i, j,
 * k) of the first negative or non-finite value. */
int hj_vol_read_raw(hj_vol *vol, const char *path, const long n[3], int bytes, hj_error *err);

/* *is_pgm = whether the file starts as a Netpbm image does: "P1" .. "P7"
 * ("P2" and "P5" are PGM), then white space or a comment; such a file is
 * for the PGM reader, which refuses the other kinds by name.  HJ_EIO when
 * it cannot be read. */
int hj_vol_is_pgm(const char *path, int *is_pgm, hj_error *err);

/* A grid file whose format is told by its content: a PGM image (it starts
 * with "P2" or "P5" and white space; pixel v maps to a + (b - a) v /
 * maxval, see hj_map_read_pgm) or else a text grid (slices = 1).  The
 * name's suffix plays no part. */
int hj_vol_read(hj_vol *vol, const char *path, double a, double b, hj_error *err);

/* HJ_EINVAL when every value is 0 (a map that cannot carry a front),
 * naming what (e.g. the file). */
int hj_vol_check_nonzero(const hj_vol *vol, const char *what, hj_error *err);

/* Free vol->v (vol itself is the caller's). */
void hj_vol_free(hj_vol *vol);

/* A legacy ASCII VTK file (STRUCTURED_POINTS, one SCALARS field named
 * name, "%.10g"), written atomically (hj_out): n[3] nodes, origin x0[3],
 * spacing dx[3], values x-fastest.  A non-finite value (VTK's ASCII
 * reader takes none) is written as `fill`; title is the header line
 * (control bytes replaced by spaces).  HJ_EINVAL, before any file is
 * made, for n[d] < 1, a non-finite origin or spacing, a spacing <= 0, a
 * non-finite fill, a name that is not one word of printable ASCII or a
 * NULL argument. */
int hj_vol_write_vtk(const char *path, const long n[3], const double x0[3], const double dx[3],
                     const char *title, const char *name, const double *values, double fill, hj_error *err);

#ifdef __cplusplus
}
#endif

#endif
