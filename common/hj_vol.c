/* hj_vol.c -- 2-D and 3-D value grids from text, raw and PGM files, and a
 * legacy VTK writer (see hj_vol.h). */
#include "hj_vol.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "hj_io.h"
#include "hj_map.h"

/* Files list the top row of a slice first; row 0 in memory is the bottom. */
static void flip_rows(double *v, long nx, long ny, long nz)
{
    for (long k = 0; k < nz; k++)
        for (long j = 0; j < ny / 2; j++) {
            double *a = v + (k * ny + j) * nx, *b = v + (k * ny + ny - 1 - j) * nx;
            for (long i = 0; i < nx; i++) {
                const double t = a[i];
                a[i] = b[i];
                b[i] = t;
            }
        }
}

/* Whether s is a decimal number: [+-] digits [. digits] [e [+-] digits],
 * with digits on at least one side of the point.  strtod alone also takes
 * hexadecimal ("0x1p3"), which a map written as decimal text never
 * holds, so such a token is a mistake to report, not a value. */
static int is_decimal(const char *s)
{
    int digits = 0;
    if (*s == '+' || *s == '-') s++;
    while (isdigit((unsigned char)*s)) s++, digits++;
    if (*s == '.') {
        s++;
        while (isdigit((unsigned char)*s)) s++, digits++;
    }
    if (!digits) return 0;
    if (*s == 'e' || *s == 'E') {
        s++;
        if (*s == '+' || *s == '-') s++;
        if (!isdigit((unsigned char)*s)) return 0;
        while (isdigit((unsigned char)*s)) s++;
    }
    return *s == '\0';
}

int hj_vol_read_text(hj_vol *vol, const char *path, int slices, hj_error *err)
{
    FILE *f = hj_in_open(path, "r", err);
    if (!f) return HJ_EIO;
    size_t cap = 1024, n = 0;
    double *v = malloc(cap * sizeof *v);
    long rows = 0, cols = -1, nz = 0, slice_rows = 0, rows0 = -1; /* rows0: rows of the first slice */
    int c, rc = HJ_OK;
    char tok[128], q[64];
    int tl = 0, incount = 0;
    long line = 1, col = 0, tcol = 0; /* tcol: column of the token's first byte */
    if (!v) { fclose(f); return hj_error_set(err, HJ_ENOMEM, "out of memory"); }
    for (;;) {
        c = fgetc(f);
        if (c != EOF) col++;
        if (c == EOF || isspace(c)) {
            if (tl > 0) {
                tok[tl] = '\0';
                char *end;
                double x = strtod(tok, &end);
                /* end short of the token: a letter, or a NUL byte in it */
                if (end != tok + tl) {
                    /* Control bytes or bytes above 0x7e: a binary file,
                     * most likely a raw volume, which has no header to
                     * tell its dimensions by. */
                    int binary = 0;
                    for (int b = 0; b < tl; b++) binary |= (unsigned char)tok[b] < 0x20 || (unsigned char)tok[b] > 0x7e;
                    rc = hj_error_set(err, HJ_EFORMAT, "%s:%ld:%ld: '%s' is not a number%s", path, line, tcol,
                                      hj_error_quote(tok, (size_t)tl, q, sizeof q),
                                      binary ? " (binary data: a raw volume is read with its dimensions given, "
                                               "hj_vol_read_raw)"
                                             : "");
                    break;
                }
                /* inf and nan (a letter first) are named as non-finite
                 * below; anything else must be plain decimal */
                const char *lead = tok + (tok[0] == '+' || tok[0] == '-');
                if (!is_decimal(tok) && !isalpha((unsigned char)*lead)) {
                    rc = hj_error_set(err, HJ_EFORMAT, "%s:%ld:%ld: '%s' is not a decimal number", path, line, tcol,
                                      hj_error_quote(tok, (size_t)tl, q, sizeof q));
                    break;
                }
                if (!isfinite(x) || x < 0) {
                    rc = hj_error_set(err, HJ_ENONFINITE, "%s:%ld:%ld: value %s must be finite and >= 0", path, line,
                                      tcol, hj_error_quote(tok, (size_t)tl, q, sizeof q));
                    break;
                }
                if (n == cap) {
                    double *nv = realloc(v, 2 * cap * sizeof *v);
                    if (!nv) { rc = hj_error_set(err, HJ_ENOMEM, "out of memory reading %s", path); break; }
                    v = nv;
                    cap *= 2;
                }
                v[n++] = x;
                incount++;
                tl = 0;
            }
            if (c == '\n' || c == EOF) {
                if (incount > 0) {
                    if (cols < 0) cols = incount;
                    else if (incount != cols) {
                        rc = hj_error_set(err, HJ_EFORMAT, "%s:%ld: %d value%s, previous rows have %ld", path,
                                          line, incount, hj_plural(incount), cols);
                        break;
                    }
                    rows++;
                    slice_rows++;
                }
                /* a blank line, or the end, closes a slice */
                if (slices && (incount == 0 || c == EOF) && slice_rows > 0) {
                    if (rows0 < 0) rows0 = slice_rows;
                    else if (slice_rows != rows0) {
                        rc = hj_error_set(err, HJ_EFORMAT, "%s:%ld: slice %ld has %ld row%s, the first has %ld",
                                          path, line - (c == EOF ? 0 : 1), nz + 1, slice_rows,
                                          hj_plural(slice_rows), rows0);
                        break;
                    }
                    nz++;
                    slice_rows = 0;
                }
                incount = 0;
                line++;
                col = 0;
            }
            if (c == EOF) break;
        } else {
            if (tl == 0) tcol = col;
            if (tl >= (int)sizeof tok - 1) {
                rc = hj_error_set(err, HJ_EFORMAT, "%s:%ld:%ld: a token longer than %d bytes: '%s'", path, line, tcol,
                                  (int)sizeof tok - 1, hj_error_quote(tok, (size_t)tl, q, sizeof q));
                break;
            }
            tok[tl++] = (char)c;
        }
    }
    if (rc == HJ_OK && ferror(f)) rc = hj_error_set(err, HJ_EIO, "error reading %s", path);
    fclose(f);
    if (!slices || nz < 1) nz = 1, rows0 = rows;
    if (rc == HJ_OK && (rows0 < 2 || cols < 2))
        rc = hj_error_set(err, HJ_EFORMAT, "%s: need at least 2 x 2 values%s", path, n == 0 ? " (the file holds none)" : "");
    if (rc) { free(v); return rc; }
    vol->dim = nz > 1 ? 3 : 2;
    vol->n[0] = cols;
    vol->n[1] = rows0;
    vol->n[2] = nz;
    vol->v = v;
    flip_rows(v, cols, rows0, nz);
    return HJ_OK;
}

/* A little-endian IEEE value of 4 or 8 bytes, whatever the host's order. */
static double le_value(const unsigned char *b, int bytes)
{
    uint64_t u = 0;
    for (int k = bytes - 1; k >= 0; k--) u = u << 8 | b[k];
    if (bytes == 8) {
        double d;
        memcpy(&d, &u, sizeof d);
        return d;
    }
    const uint32_t w = (uint32_t)u;
    float s;
    memcpy(&s, &w, sizeof s);
    return s;
}

int hj_vol_read_raw(hj_vol *vol, const char *path, const long n[3], int bytes, hj_error *err)
{
    if (bytes != 4 && bytes != 8) return hj_error_set(err, HJ_EINVAL, "raw values have 4 or 8 bytes, not %d", bytes);
    for (int d = 0; d < 3; d++)
        if (n[d] < (d < 2 ? 2 : 1) || n[d] > 100000000)
            return hj_error_set(err, HJ_EINVAL, "raw volume %s: %ld values along dimension %d", path, n[d], d + 1);
    const double count = (double)n[0] * n[1] * n[2];
    if (count > 2e9) return hj_error_set(err, HJ_ENOMEM, "raw volume %s: %.3g values, too many", path, count);
    FILE *f = hj_in_open(path, "rb", err);
    if (!f) return HJ_EIO;
    struct stat st;
    const long total = n[0] * n[1] * n[2];
    if (fstat(fileno(f), &st) == 0 && S_ISREG(st.st_mode) && (double)st.st_size != count * bytes) {
        fclose(f);
        return hj_error_set(err, HJ_EFORMAT,
                            "%s: %lld bytes, but %ld x %ld x %ld values of %d bytes need %.0f (truncated, or other "
                            "dimensions or value size)",
                            path, (long long)st.st_size, n[0], n[1], n[2], bytes, count * bytes);
    }
    double *v = malloc(sizeof *v * (size_t)total);
    if (!v) { fclose(f); return hj_error_set(err, HJ_ENOMEM, "out of memory for %s", path); }
    unsigned char buf[8 * 4096];
    int rc = HJ_OK;
    for (long k = 0; k < total && rc == HJ_OK;) {
        const long want = total - k < 4096 ? total - k : 4096;
        const size_t got = fread(buf, (size_t)bytes, (size_t)want, f);
        if (got != (size_t)want) {
            rc = ferror(f) ? hj_error_set(err, HJ_EIO, "error reading %s", path)
                           : hj_error_set(err, HJ_EFORMAT, "%s: truncated: the file ends after %ld of %ld values", path,
                                          k + (long)got, total);
            break;
        }
        for (long m = 0; m < want; m++, k++) {
            const double x = le_value(buf + m * bytes, bytes);
            if (!isfinite(x) || x < 0) {
                rc = hj_error_set(err, HJ_ENONFINITE, "%s: value %g at (i, j, k) = (%ld, %ld, %ld) must be finite and >= 0",
                                  path, x, k % n[0], k / n[0] % n[1], k / (n[0] * n[1]));
                break;
            }
            v[k] = x;
        }
    }
    if (rc == HJ_OK && fgetc(f) != EOF)
        rc = hj_error_set(err, HJ_EFORMAT, "%s: more data than %ld values of %d bytes", path, total, bytes);
    fclose(f);
    if (rc) { free(v); return rc; }
    vol->dim = n[2] > 1 ? 3 : 2;
    for (int d = 0; d < 3; d++) vol->n[d] = n[d];
    vol->v = v;
    return HJ_OK;
}

int hj_vol_is_pgm(const char *path, int *is_pgm, hj_error *err)
{
    FILE *f = hj_in_open(path, "rb", err);
    if (!f) return HJ_EIO;
    unsigned char b[3] = {0, 0, 0};
    const size_t got = fread(b, 1, 3, f);
    fclose(f);
    /* any Netpbm magic (P1 .. P7) goes to the PGM reader, which reads P2
     * and P5 and names the other kinds, rather than to the text reader,
     * whose message would be that 'P6' is not a number */
    *is_pgm = got == 3 && b[0] == 'P' && b[1] >= '1' && b[1] <= '7' && (b[2] == '#' || isspace(b[2]));
    return HJ_OK;
}

int hj_vol_read(hj_vol *vol, const char *path, double a, double b, hj_error *err)
{
    int is_pgm = 0;
    int rc = hj_vol_is_pgm(path, &is_pgm, err);
    if (rc) return rc;
    if (!is_pgm) return hj_vol_read_text(vol, path, 1, err);
    hj_map m = {0};
    rc = hj_map_read_pgm(&m, path, a, b, err);
    if (rc) return rc;
    vol->dim = 2;
    vol->n[0] = m.mx;
    vol->n[1] = m.my;
    vol->n[2] = 1;
    vol->v = m.v; /* the same layout: x fastest, row 0 at the bottom */
    return HJ_OK;
}

int hj_vol_check_nonzero(const hj_vol *vol, const char *what, hj_error *err)
{
    const long total = vol->n[0] * vol->n[1] * vol->n[2];
    for (long k = 0; k < total; k++)
        if (vol->v[k] != 0) return HJ_OK;
    return hj_error_set(err, HJ_EINVAL, "%s: every value is 0", what);
}

void hj_vol_free(hj_vol *vol)
{
    free(vol->v);
    vol->v = NULL;
}

int hj_vol_write_vtk(const char *path, const long n[3], const double x0[3], const double dx[3],
                     const char *title, const char *name, const double *values, double fill, hj_error *err)
{
    /* Checked before the file is opened: each of these made a file that
     * VTK's ASCII reader refuses or misreads (no points, "nan" in the
     * header or the values, a field name split into two tokens). */
    if (!path || !n || !x0 || !dx || !title || !name || !values)
        return hj_error_set(err, HJ_EINVAL, "VTK: NULL path, size, origin, spacing, title, name or values");
    double count = 1;
    for (int d = 0; d < 3; d++) {
        if (n[d] < 1) return hj_error_set(err, HJ_EINVAL, "VTK %s: %ld nodes along dimension %d", path, n[d], d + 1);
        if (!isfinite(x0[d]) || !isfinite(dx[d]) || !(dx[d] > 0))
            return hj_error_set(err, HJ_EINVAL, "VTK %s: origin %g and spacing %g along dimension %d must be finite, "
                                "the spacing > 0", path, x0[d], dx[d], d + 1);
        count *= (double)n[d];
    }
    if (count > 2e9) return hj_error_set(err, HJ_EINVAL, "VTK %s: %.3g nodes, too many", path, count);
    if (!isfinite(fill)) return hj_error_set(err, HJ_EINVAL, "VTK %s: the fill value %g must be finite", path, fill);
    if (!name[0]) return hj_error_set(err, HJ_EINVAL, "VTK %s: empty field name", path);
    for (const char *c = name; *c; c++)
        if ((unsigned char)*c <= 0x20 || (unsigned char)*c >= 0x7f)
            return hj_error_set(err, HJ_EINVAL, "VTK %s: the field name must be one word of printable ASCII", path);
    char head[256];
    size_t k = 0;
    for (; title[k] && k < sizeof head - 1; k++)
        head[k] = (unsigned char)title[k] < 0x20 || (unsigned char)title[k] == 0x7f ? ' ' : title[k];
    head[k] = '\0';
    hj_out out;
    int rc = hj_out_open(&out, path, err);
    if (rc) return rc;
    FILE *fp = out.fp;
    const long total = n[0] * n[1] * n[2];
    fprintf(fp, "# vtk DataFile Version 3.0\n%s\nASCII\nDATASET STRUCTURED_POINTS\n", head);
    fprintf(fp, "DIMENSIONS %ld %ld %ld\nORIGIN %.17g %.17g %.17g\nSPACING %.17g %.17g %.17g\n", n[0], n[1], n[2],
            x0[0], x0[1], x0[2], dx[0], dx[1], dx[2]);
    fprintf(fp, "POINT_DATA %ld\nSCALARS %s double 1\nLOOKUP_TABLE default\n", total, name);
    for (long m = 0; m < total; m++) fprintf(fp, "%.10g\n", isfinite(values[m]) ? values[m] : fill);
    return hj_out_commit(&out, err);
}
