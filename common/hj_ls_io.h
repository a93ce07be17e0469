/* hj_ls_io.h -- writing arrays of the level set kernel as plain data:
 * gnuplot-ready text blocks (1-3 D) and legacy VTK files (3-D fields for
 * ParaView/VisIt; 1-D and 2-D work too), the data behind the figures of
 * Mitchell's toolbox (section 2, e.g. the isosurfaces of Figures 3, 13,
 * 17 as voxel lattices).
 *
 * Text blocks: one line per interior node, the coordinates then one column
 * per field ("%.*g" with 10 significant digits); dimension 0 runs fastest.
 * In 2-D and 3-D a blank line ends every row along dimension 0, which is
 * gnuplot's grid format (splot/contour of 2-D data; voxel grids read the
 * 3-D lines point by point).  Several blocks in one file, separated by two
 * blank lines, are gnuplot's `index` 0, 1, ...  (e.g. the time sequence of
 * a demo).  Nothing here prints to stdout or exits.
 */
#ifndef HJ_LS_IO_H
#define HJ_LS_IO_H

#include <stdio.h>

#include "hj_error.h"
#include "hj_ls_grid.h"

#ifdef __cplusplus
extern "C" {
#endif

/* One block of nfields arrays on g to fp (an open stream, e.g. an hj_out's
 * fp); a header line "# x y ... name1 name2" first when names is given
 * (dimensions 4 to 6 labelled x4 .. x6; a NULL entry is written f1, f2,
 * ... by its field number).  HJ_EIO on a write error; HJ_EINVAL for a
 * NULL stream, grid or field, a negative nfields, or an empty name or one
 * with a blank or a line break (each name is one header column). */
int hj_ls_write_block(FILE *fp, const hj_ls_grid *g, int nfields, const char *const *names,
                      const double *const *fields, hj_error *err);

/* A legacy ASCII VTK file (STRUCTURED_POINTS, one SCALARS section per
 * field), written atomically (hj_out).  title is the one-line header (at
 * most 255 characters, no line break) and every field needs a name, one
 * word (no blank: VTK reads the SCALARS name up to one); anything else,
 * or a NULL path, title, name list or field, is HJ_EINVAL and no file is
 * written.  A NaN or infinite value is HJ_ENONFINITE naming the field and
 * the node, and no file is written: VTK's reader takes "nan" and "inf" in
 * an ASCII file for malformed data (ParaView stops reading there). */
int hj_ls_write_vtk(const char *path, const hj_ls_grid *g, const char *title, int nfields,
                    const char *const *names, const double *const *fields, hj_error *err);

/* One block of nfields arrays on g (with the header line of names) as
 * the whole of a file, written atomically (hj_out). */
int hj_ls_write_dat(const char *path, const hj_ls_grid *g, int nfields, const char *const *names,
                    const double *const *fields, hj_error *err);

/* 3-D fields resampled (trilinearly) on an M x M x M lattice spanning the
 * grid's box, for gnuplot's voxel grids (`set vgrid $v size M` with the
 * axis ranges set to the lattice's box, then `vfill ... using
 * 1:2:3:(0):(column)`): a comment line, then one line "x y z f_1 ... f_n"
 * per lattice point.  With periodic_dim >= 0 the box extends to the period
 * in that dimension (interpolating between the last node and the first).
 * HJ_EINVAL unless g is 3-D and M >= 2; HJ_EIO on a write error. */
int hj_ls_write_voxels(FILE *fp, const hj_ls_grid *g, int nfields, const double *const *fields, int M, int periodic_dim,
                       hj_error *err);

#ifdef __cplusplus
}
#endif

#endif
