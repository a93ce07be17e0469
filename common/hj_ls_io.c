/* hj_ls_io.c -- gnuplot blocks and legacy VTK; see hj_ls_io.h. */
#include "hj_ls_io.h"

#include <math.h>
#include <string.h>

#include "hj_io.h"

static const char *axis_name[3] = {"x", "y", "z"};

/* The fields (nfields >= 0, none NULL) and, when names is given (needed:
 * VTK), one name per field, a non-empty word: VTK's SCALARS line reads
 * the name up to a blank, and a gnuplot header's columns are its words
 * (a blank in a name would shift every later column's label). */
static int check_fields(const char *what, const hj_ls_grid *g, int nfields, const char *const *names,
                        const double *const *fields, int need_names, hj_error *err)
{
    if (!g) return hj_error_set(err, HJ_EINVAL, "%s: the grid is NULL", what);
    if (nfields < 0) return hj_error_set(err, HJ_EINVAL, "%s: %d fields", what, nfields);
    if (nfields > 0 && !fields) return hj_error_set(err, HJ_EINVAL, "%s: the field list is NULL", what);
    if (need_names && nfields > 0 && !names) return hj_error_set(err, HJ_EINVAL, "%s: every field needs a name", what);
    for (int f = 0; f < nfields; f++) {
        if (!fields[f]) return hj_error_set(err, HJ_EINVAL, "%s: field %d is NULL", what, f);
        if (!names) continue;
        const char *nm = names[f];
        if (!need_names && !nm) continue; /* a gnuplot header names it by its column */
        if (!nm || !nm[0]) return hj_error_set(err, HJ_EINVAL, "%s: field %d has no name", what, f);
        for (const char *c = nm; *c; c++)
            if (*c == '\n' || *c == '\r' || *c == ' ' || *c == '\t') {
                char q[80];
                return hj_error_set(err, HJ_EINVAL, "%s: field name \"%s\" must be one word without blanks",
                                    what, hj_error_quote(nm, strlen(nm), q, sizeof q));
            }
    }
    return HJ_OK;
}

int hj_ls_write_block(FILE *fp, const hj_ls_grid *g, int nfields, const char *const *names,
                      const double *const *fields, hj_error *err)
{
    if (!fp) return hj_error_set(err, HJ_EINVAL, "gnuplot block: the stream is NULL");
    int rc = check_fields("gnuplot block", g, nfields, names, fields, 0, err);
    if (rc) return rc;
    if (names) {
        fputc('#', fp);
        for (int d = 0; d < g->dim; d++) {
            if (d < 3) fprintf(fp, " %s", axis_name[d]);
            else fprintf(fp, " x%d", d + 1); /* x4, x5, x6: the dimension's number */
        }
        for (int f = 0; f < nfields; f++) {
            if (names[f]) fprintf(fp, " %s", names[f]);
            else fprintf(fp, " f%d", f + 1);
        }
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
    if (!path) return hj_error_set(err, HJ_EINVAL, "VTK: the path is NULL");
    int rc = check_fields(path, g, nfields, names, fields, 1, err);
    if (rc) return rc;
    if (g->dim > 3) return hj_error_set(err, HJ_EINVAL, "%s: VTK structured points hold 1 to 3 dimensions", path);
    /* the header's second line, at most 256 characters (VTK's limit) */
    if (!title || strlen(title) > 255 || strpbrk(title, "\n\r"))
        return hj_error_set(err, HJ_EINVAL, "%s: the VTK title must be one line of at most 255 characters", path);
    /* "nan" and "inf" in an ASCII legacy file are not numbers to VTK's
     * reader (ParaView stops reading there): name the value, write nothing */
    for (int f = 0; f < nfields; f++)
        for (size_t r = 0; r < g->rows; r++) {
            long i[HJ_LS_MAXDIM] = {0};
            const double *row = fields[f] + hj_ls_row(g, r, i);
            for (long a = 0; a < g->N[0]; a++)
                if (!isfinite(row[a])) {
                    char pos[256];
                    hj_ls_format_node(g, r, a, pos, sizeof pos);
                    return hj_error_set(err, HJ_ENONFINITE,
                                        "%s: field %s is %g at x = (%s); VTK readers take only finite values in "
                                        "ASCII (replace it, e.g. by a sentinel value)",
                                        path, names[f], row[a], pos);
                }
        }
    hj_out out;
    rc = hj_out_open(&out, path, err);
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

int hj_ls_write_dat(const char *path, const hj_ls_grid *g, int nfields, const char *const *names,
                    const double *const *fields, hj_error *err)
{
    if (!path) return hj_error_set(err, HJ_EINVAL, "data file: the path is NULL");
    int rc = check_fields(path, g, nfields, names, fields, 0, err);
    if (rc) return rc;
    hj_out out;
    rc = hj_out_open(&out, path, err);
    if (rc) return rc;
    rc = hj_ls_write_block(out.fp, g, nfields, names, fields, err);
    if (rc) {
        hj_out_abort(&out);
        return rc;
    }
    return hj_out_commit(&out, err);
}

int hj_ls_write_voxels(FILE *fp, const hj_ls_grid *g, int nfields, const double *const *fields, int M, int periodic_dim,
                       hj_error *err)
{
    if (g->dim != 3 || M < 2) return hj_error_set(err, HJ_EINVAL, "voxels: a 3-D grid and M >= 2 are needed");
    double hi[3];
    for (int d = 0; d < 3; d++) hi[d] = d == periodic_dim ? g->min[d] + (double)g->N[d] * g->dx[d] : g->max[d];
    fprintf(fp, "# %d^3 lattice on [%.10g, %.10g] x [%.10g, %.10g] x [%.10g, %.10g]: x y z fields\n", M, g->min[0],
            hi[0], g->min[1], hi[1], g->min[2], hi[2]);
    for (int c = 0; c < M; c++)
        for (int b = 0; b < M; b++)
            for (int a = 0; a < M; a++) {
                const int l[3] = {a, b, c};
                double x[3], w[3];
                long i0[3], i1[3];
                for (int d = 0; d < 3; d++) {
                    x[d] = g->min[d] + (hi[d] - g->min[d]) * l[d] / (M - 1);
                    double s = (x[d] - g->min[d]) / g->dx[d];
                    long i = (long)floor(s);
                    const long last = d == periodic_dim ? g->N[d] - 1 : g->N[d] - 2;
                    i = i < 0 ? 0 : i > last ? last : i;
                    w[d] = s - (double)i;
                    w[d] = w[d] < 0 ? 0 : w[d] > 1 ? 1 : w[d];
                    i0[d] = i;
                    i1[d] = d == periodic_dim ? (i + 1) % g->N[d] : i + 1;
                }
                fprintf(fp, "%.9g %.9g %.9g", x[0], x[1], x[2]);
                for (int f = 0; f < nfields; f++) {
                    double v = 0;
                    for (int corner = 0; corner < 8; corner++) {
                        long i[3];
                        double wt = 1;
                        for (int d = 0; d < 3; d++) {
                            const int up = corner >> d & 1;
                            i[d] = up ? i1[d] : i0[d];
                            wt *= up ? w[d] : 1 - w[d];
                        }
                        v += wt * fields[f][hj_ls_index(g, i)];
                    }
                    fprintf(fp, " %.6g", v);
                }
                fputc('\n', fp);
            }
    return ferror(fp) ? hj_error_set(err, HJ_EIO, "voxels: write error") : HJ_OK;
}
