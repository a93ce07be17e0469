/* hj_ls_io.c -- gnuplot blocks and legacy VTK; see hj_ls_io.h. */
#include "hj_ls_io.h"

#include "hj_io.h"

static const char *axis_name[3] = {"x", "y", "z"};

int hj_ls_write_block(FILE *fp, const hj_ls_grid *g, int nfields, const char *const *names,
                      const double *const *fields, hj_error *err)
{
    if (names) {
        fputc('#', fp);
        for (int d = 0; d < g->dim; d++) fprintf(fp, " %s", d < 3 ? axis_name[d] : "x_d");
        for (int f = 0; f < nfields; f++) fprintf(fp, " %s", names[f]);
        fputc('\n', fp);
    }
    for (size_t r = 0; r < g->rows; r++) {
        long i[HJ_LS_MAXDIM] = {0};
        const size_t k0 = hj_ls_row(g, r, i);
        for (long a = 0; a < g->N[0]; a++) {
            double x[HJ_LS_MAXDIM];
            i[0] = a;
            hj_ls_coord(g, i, x);
            for (int d = 0; d < g->dim; d++) fprintf(fp, "%s%.10g", d ? " " : "", x[d]);
            for (int f = 0; f < nfields; f++) fprintf(fp, " %.10g", fields[f][k0 + (size_t)a]);
            fputc('\n', fp);
        }
        if (g->dim > 1) fputc('\n', fp);
    }
    if (ferror(fp)) return hj_error_set(err, HJ_EIO, "write error");
    return HJ_OK;
}

int hj_ls_write_vtk(const char *path, const hj_ls_grid *g, const char *title, int nfields,
                    const char *const *names, const double *const *fields, hj_error *err)
{
    if (g->dim > 3) return hj_error_set(err, HJ_EINVAL, "%s: VTK structured points hold 1 to 3 dimensions", path);
    hj_out out;
    int rc = hj_out_open(&out, path, err);
    if (rc) return rc;
    long n[3] = {1, 1, 1};
    double o[3] = {0, 0, 0}, s[3] = {1, 1, 1};
    for (int d = 0; d < g->dim; d++) { n[d] = g->N[d]; o[d] = g->min[d]; s[d] = g->dx[d]; }
    fprintf(out.fp, "# vtk DataFile Version 3.0\n%s\nASCII\nDATASET STRUCTURED_POINTS\n", title);
    fprintf(out.fp, "DIMENSIONS %ld %ld %ld\nORIGIN %.10g %.10g %.10g\nSPACING %.10g %.10g %.10g\nPOINT_DATA %zu\n", n[0],
            n[1], n[2], o[0], o[1], o[2], s[0], s[1], s[2], g->nodes);
    for (int f = 0; f < nfields; f++) {
        fprintf(out.fp, "SCALARS %s double 1\nLOOKUP_TABLE default\n", names[f]);
        for (size_t r = 0; r < g->rows; r++) {
            long i[HJ_LS_MAXDIM] = {0};
            const size_t k0 = hj_ls_row(g, r, i);
            for (long a = 0; a < g->N[0]; a++) fprintf(out.fp, "%.9g\n", fields[f][k0 + (size_t)a]);
        }
    }
    if (ferror(out.fp)) {
        hj_out_abort(&out);
        return hj_error_set(err, HJ_EIO, "%s: write error", path);
    }
    return hj_out_commit(&out, err);
}
