/* hj_map.c -- slowness maps from grid files and their bilinear interpolation
 * (see hj_map.h). */
#include "hj_map.h"
#include "hj_io.h"
#include "hj_vol.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

double hj_map_eval(double x, double y, void *ctx)
{
    const hj_map *m = ctx;
    if (!m->v) return m->constant;
    double u = (x - m->xmin) / (m->xmax - m->xmin) * (m->mx - 1);
    double w = (y - m->ymin) / (m->ymax - m->ymin) * (m->my - 1);
    /* clamp: the Richardson boxes may reach half a cell outside */
    u = u < 0 ? 0 : u > m->mx - 1 ? m->mx - 1 : u;
    w = w < 0 ? 0 : w > m->my - 1 ? m->my - 1 : w;
    int i = (int)u, j = (int)w;
    if (i > m->mx - 2) i = m->mx - 2;
    if (j > m->my - 2) j = m->my - 2;
    const double a = u - i, b = w - j;
    const double *r0 = m->v + (long)j * m->mx, *r1 = r0 + m->mx;
    return (1 - b) * ((1 - a) * r0[i] + a * r0[i + 1]) + b * ((1 - a) * r1[i] + a * r1[i + 1]);
}

/* Pixel units when the caller gave no rectangle. */
static void default_rectangle(hj_map *m)
{
    if (!(m->xmax > m->xmin)) m->xmin = 0, m->xmax = m->mx - 1;
    if (!(m->ymax > m->ymin)) m->ymin = 0, m->ymax = m->my - 1;
}

/* Files list the top row first; row 0 in memory is the bottom. */
static void flip_rows(hj_map *m)
{
    for (int j = 0; j < m->my / 2; j++)
        for (int i = 0; i < m->mx; i++) {
            double *a = &m->v[(long)j * m->mx + i], *b = &m->v[(long)(m->my - 1 - j) * m->mx + i];
            double t = *a;
            *a = *b;
            *b = t;
        }
}

int hj_map_read_text(hj_map *m, const char *path, hj_error *err)
{
    hj_vol vol;
    const int rc = hj_vol_read_text(&vol, path, 0, err);
    if (rc) return rc;
    m->mx = (int)vol.n[0];
    m->my = (int)vol.n[1];
    m->v = vol.v; /* rows already bottom first */
    default_rectangle(m);
    return HJ_OK;
}

/* A PGM file being read, with the position of the last byte read for the
 * messages: line and column (from 1) in the header and in P2 pixel data,
 * the byte offset (from 0) in P5 pixel data. */
typedef struct {
    FILE *f;
    const char *path;
    long line, col, offset;
    int newline; /* the last byte read ended a line */
} pgm_in;

static int pgm_getc(pgm_in *in)
{
    const int c = fgetc(in->f);
    if (c == EOF) return c;
    if (in->newline) in->line++, in->col = 0;
    in->newline = c == '\n';
    in->col++;
    in->offset++;
    return c;
}

/* Where the next byte would be: the position of a missing token. */
static void pgm_next_pos(const pgm_in *in, long *line, long *col)
{
    *line = in->newline ? in->line + 1 : in->line;
    *col = in->newline ? 1 : in->col + 1;
}

/* The next token, after white space and comments ('#' to the end of the
 * line), as a whole number in [lo, hi]; what names it in the messages.
 * The white space byte that ends the token is consumed (P5 pixel data
 * starts right after the one that follows maxval). */
static int pgm_number(pgm_in *in, const char *what, long lo, long hi, long *out, hj_error *err)
{
    int c;
    do {
        c = pgm_getc(in);
        if (c == '#') while (c != '\n' && c != EOF) c = pgm_getc(in);
    } while (c != EOF && isspace(c));
    if (c == EOF) {
        long l, k;
        pgm_next_pos(in, &l, &k);
        return hj_error_set(err, HJ_EFORMAT, "%s:%ld:%ld: truncated or malformed: the file ends before the %s", in->path,
                            l, k, what);
    }
    const long line = in->line, col = in->col;
    char tok[24], q[4 * sizeof tok + 1]; /* the messages quote at most tok */
    size_t n = 0;
    int digits = 1, longer = 0;
    long v = 0;
    for (; c != EOF && !isspace(c); c = pgm_getc(in)) {
        if (n < sizeof tok) tok[n++] = (char)c;
        else longer = 1;
        if (!isdigit(c)) digits = 0;
        else if (v <= hi) v = v * 10 + (c - '0'); /* past hi it only needs to stay past it */
    }
    if (!digits)
        return hj_error_set(err, HJ_EFORMAT, "%s:%ld:%ld: the %s is '%s%s', not a whole number", in->path, line, col,
                            what, hj_error_quote(tok, n, q, sizeof q), longer ? "..." : "");
    if (v < lo || v > hi)
        return hj_error_set(err, HJ_EFORMAT, "%s:%ld:%ld: the %s is %s%s, outside %ld..%ld", in->path, line, col, what,
                            hj_error_quote(tok, n, q, sizeof q), longer ? "..." : "", lo, hi);
    *out = v;
    return HJ_OK;
}

int hj_map_read_pgm(hj_map *m, const char *path, double fmin, double fmax, hj_error *err)
{
    FILE *f = hj_in_open(path, "rb", err);
    if (!f) return HJ_EIO;
    pgm_in in = {f, path, 1, 0, 0, 0};
    char magic[2], q[32];
    int nm = 0, c = 0;
    while (nm < 2 && (c = pgm_getc(&in)) != EOF) magic[nm++] = (char)c;
    if (nm == 2) c = pgm_getc(&in);
    /* "P2" or "P5", then white space or a comment */
    if (nm < 2 || magic[0] != 'P' || (magic[1] != '2' && magic[1] != '5') || (c != '#' && !isspace(c))) {
        fclose(f);
        /* the other Netpbm kinds are named: a colour or bitmap image is a
         * likely mistake, and converting it to grey is the remedy */
        static const char *const kind[8] = {"", "a PBM bitmap", "", "a PPM colour image", "a PBM bitmap", "",
                                            "a PPM colour image", "a PAM image"};
        if (nm == 2 && magic[0] == 'P' && magic[1] >= '1' && magic[1] <= '7' && (c == '#' || isspace(c)))
            return hj_error_set(err, HJ_EFORMAT, "%s:1:1: %s (%c%c), not a PGM grey image (P2 or P5): convert it "
                                                 "to grey levels first", path, kind[magic[1] - '0'], magic[0],
                                magic[1]);
        return hj_error_set(err, HJ_EFORMAT, "%s:1:1: not a PGM image: it starts with '%s', not P2 or P5", path,
                            hj_error_quote(magic, (size_t)nm, q, sizeof q));
    }
    if (c == '#') while (c != '\n' && c != EOF) c = pgm_getc(&in);
    const int plain = magic[1] == '2';
    long w, h, maxval;
    int rc = pgm_number(&in, "width", 2, 100000000, &w, err);
    if (!rc) rc = pgm_number(&in, "height", 2, 100000000, &h, err);
    if (!rc) rc = pgm_number(&in, "maxval", 1, 65535, &maxval, err);
    if (rc) { fclose(f); return rc; }
    if ((double)w * h > 1e9) { fclose(f); return hj_error_set(err, HJ_ENOMEM, "%s: image too large", path); }
    /* A header must not make us allocate what the file cannot fill: P5
     * holds 1 or 2 bytes per pixel, P2 at least a digit and a separator. */
    const int wide = maxval > 255;
    const double need = plain ? 2.0 * w * h - 1 : (double)w * h * (wide ? 2 : 1);
    struct stat st;
    if (fstat(fileno(f), &st) == 0 && S_ISREG(st.st_mode) && (double)(st.st_size - in.offset) < need) {
        fclose(f);
        return hj_error_set(err, HJ_EFORMAT,
                            "%s: truncated or malformed: the %ld x %ld pixels of its header need %s%.0f bytes, %ld follow it",
                            path, w, h, plain ? "at least " : "", need, (long)(st.st_size - in.offset));
    }
    double *v = malloc(sizeof *v * (size_t)(w * h));
    if (!v) { fclose(f); return hj_error_set(err, HJ_ENOMEM, "out of memory for %s", path); }
    for (long k = 0; k < w * h && rc == HJ_OK; k++) {
        long p = 0;
        char what[64];
        snprintf(what, sizeof what, "pixel at row %ld, column %ld", k / w + 1, k % w + 1);
        if (plain) {
            rc = pgm_number(&in, what, 0, maxval, &p, err);
        } else {
            const int b0 = pgm_getc(&in), b1 = wide && b0 != EOF ? pgm_getc(&in) : 0;
            if (b0 == EOF || b1 == EOF)
                rc = hj_error_set(err, HJ_EFORMAT, "%s: offset %ld: truncated or malformed: the file ends before the %s",
                                  path, in.offset, what);
            else if ((p = wide ? (long)b0 * 256 + b1 : b0) > maxval)
                rc = hj_error_set(err, HJ_EFORMAT, "%s: offset %ld: the %s is %ld, above maxval %ld", path,
                                  in.offset - (wide ? 2 : 1), what, p, maxval);
        }
        if (rc == HJ_OK) v[k] = fmin + (fmax - fmin) * (double)p / (double)maxval;
    }
    /* After the last pixel only white space and comments (P2) or nothing
     * (P5) may follow. */
    if (rc == HJ_OK) {
        c = pgm_getc(&in);
        while (plain && c != EOF && (isspace(c) || c == '#')) {
            if (c == '#') while (c != '\n' && c != EOF) c = pgm_getc(&in);
            c = pgm_getc(&in);
        }
        if (c != EOF && plain)
            rc = hj_error_set(err, HJ_EFORMAT, "%s:%ld:%ld: more data than the %ld x %ld pixels of its header", path,
                              in.line, in.col, w, h);
        else if (c != EOF)
            rc = hj_error_set(err, HJ_EFORMAT, "%s: offset %ld: more data than the %ld x %ld pixels of its header", path,
                              in.offset - 1, w, h);
    }
    if (rc == HJ_OK && ferror(f)) rc = hj_error_set(err, HJ_EIO, "error reading %s", path);
    fclose(f);
    if (rc) { free(v); return rc; }
    m->mx = (int)w;
    m->my = (int)h;
    m->v = v;
    flip_rows(m);
    default_rectangle(m);
    return HJ_OK;
}

int hj_map_read(hj_map *m, const char *path, double fmin, double fmax, hj_error *err)
{
    int is_pgm = 0;
    const int rc = hj_vol_is_pgm(path, &is_pgm, err);
    if (rc) return rc;
    return is_pgm ? hj_map_read_pgm(m, path, fmin, fmax, err) : hj_map_read_text(m, path, err);
}

int hj_map_invert(hj_map *m, hj_error *err)
{
    const long n = (long)m->mx * m->my;
    for (long k = 0; k < n; k++)
        if (!(m->v[k] > 0))
            return hj_error_set(err, HJ_EINVAL, "speed %g at row %ld, column %ld: every speed must be > 0", m->v[k],
                                (long)m->my - k / m->mx, k % m->mx + 1);
    for (long k = 0; k < n; k++) m->v[k] = 1 / m->v[k];
    return HJ_OK;
}

void hj_map_free(hj_map *m)
{
    free(m->v);
    m->v = NULL;
}
