/* hj_map.c -- slowness maps from grid files and their bilinear interpolation
 * (see hj_map.h). */
#include "hj_map.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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
    FILE *f = fopen(path, "r");
    if (!f) return hj_error_set(err, HJ_EIO, "cannot read %s: %s", path, strerror(errno));
    size_t cap = 1024, n = 0;
    double *v = malloc(cap * sizeof *v);
    int rows = 0, cols = -1, c, lineno = 0, rc = HJ_OK;
    char tok[128];
    int tl = 0, incount = 0;
    if (!v) { fclose(f); return hj_error_set(err, HJ_ENOMEM, "out of memory"); }
    for (;;) {
        c = fgetc(f);
        if (c == EOF || isspace(c)) {
            if (tl > 0) {
                tok[tl] = '\0';
                char *end;
                double x = strtod(tok, &end);
                if (*end) { rc = hj_error_set(err, HJ_EFORMAT, "%s:%d: '%s' is not a number", path, lineno + 1, tok); break; }
                if (!isfinite(x) || x < 0) { rc = hj_error_set(err, HJ_ENONFINITE, "%s:%d: value %s must be finite and >= 0", path, lineno + 1, tok); break; }
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
                    else if (incount != cols) { rc = hj_error_set(err, HJ_EFORMAT, "%s:%d: %d values, previous rows have %d", path, lineno + 1, incount, cols); break; }
                    rows++;
                }
                incount = 0;
                lineno++;
            }
            if (c == EOF) break;
        } else {
            if (tl >= (int)sizeof tok - 1) { rc = hj_error_set(err, HJ_EFORMAT, "%s:%d: token too long", path, lineno + 1); break; }
            tok[tl++] = (char)c;
        }
    }
    fclose(f);
    if (rc == HJ_OK && (rows < 2 || cols < 2)) rc = hj_error_set(err, HJ_EFORMAT, "%s: need at least 2 x 2 values", path);
    if (rc) { free(v); return rc; }
    m->mx = cols;
    m->my = rows;
    m->v = v;
    flip_rows(m);
    default_rectangle(m);
    return HJ_OK;
}

static int pgm_int(FILE *f, long *out)
{
    int c;
    do {
        c = fgetc(f);
        if (c == '#') while (c != '\n' && c != EOF) c = fgetc(f);
    } while (c != EOF && isspace(c));
    if (c == EOF || !isdigit(c)) return -1;
    long v = 0;
    while (c != EOF && isdigit(c)) {
        v = v * 10 + (c - '0');
        if (v > 100000000) return -1;
        c = fgetc(f);
    }
    /* The whole token is a number: "100.200" is not two pixels. */
    if (c != EOF && !isspace(c)) return -1;
    *out = v;
    return 0;
}

/* After the last pixel only white space and comments (P2) or nothing
 * (P5) may follow. */
static int pgm_at_end(FILE *f, int plain)
{
    int c = fgetc(f);
    while (plain && c != EOF && (isspace(c) || c == '#')) {
        if (c == '#') while (c != '\n' && c != EOF) c = fgetc(f);
        c = fgetc(f);
    }
    return c == EOF;
}

int hj_map_read_pgm(hj_map *m, const char *path, double fmin, double fmax, hj_error *err)
{
    FILE *f = fopen(path, "rb");
    if (!f) return hj_error_set(err, HJ_EIO, "cannot read %s: %s", path, strerror(errno));
    char magic[3] = {0};
    long w, h, maxval;
    if (fread(magic, 1, 2, f) != 2 || magic[0] != 'P' || (magic[1] != '2' && magic[1] != '5') || pgm_int(f, &w) ||
        pgm_int(f, &h) || pgm_int(f, &maxval) || w < 2 || h < 2 || maxval < 1 || maxval > 65535) {
        fclose(f);
        return hj_error_set(err, HJ_EFORMAT, "%s: not a PGM (P2/P5) image of at least 2 x 2 pixels", path);
    }
    if ((double)w * h > 1e9) { fclose(f); return hj_error_set(err, HJ_ENOMEM, "%s: image too large", path); }
    double *v = malloc(sizeof *v * (size_t)(w * h));
    if (!v) { fclose(f); return hj_error_set(err, HJ_ENOMEM, "out of memory for %s", path); }
    int rc = HJ_OK;
    for (long k = 0; k < w * h && rc == HJ_OK; k++) {
        long p;
        if (magic[1] == '2') {
            if (pgm_int(f, &p)) rc = HJ_EFORMAT;
        } else {
            int b0 = fgetc(f), b1 = maxval > 255 ? fgetc(f) : 0;
            if (b0 == EOF || b1 == EOF) rc = HJ_EFORMAT;
            p = maxval > 255 ? (b0 << 8 | b1) : b0;
        }
        if (rc == HJ_OK && p > maxval) rc = HJ_EFORMAT;
        if (rc == HJ_OK) v[k] = fmin + (fmax - fmin) * (double)p / (double)maxval;
    }
    const int extra = rc == HJ_OK && !pgm_at_end(f, magic[1] == '2');
    fclose(f);
    if (rc) { free(v); return hj_error_set(err, HJ_EFORMAT, "%s: truncated or malformed pixel data", path); }
    if (extra) {
        free(v);
        return hj_error_set(err, HJ_EFORMAT, "%s: more data than the %ld x %ld pixels of its header", path, w, h);
    }
    m->mx = (int)w;
    m->my = (int)h;
    m->v = v;
    flip_rows(m);
    default_rectangle(m);
    return HJ_OK;
}

int hj_map_read(hj_map *m, const char *path, double fmin, double fmax, hj_error *err)
{
    size_t len = strlen(path);
    int is_pgm = len > 4 && !strcmp(path + len - 4, ".pgm");
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
