/* Unit tests of common/hj_vol: text volumes (slices split by blank
 * lines), raw float32/float64 volumes, the format told by content, the
 * errors for malformed, truncated, negative, non-finite and all-zero
 * grids, and the VTK writer. */
#include "hj_test.h"

#include <stdlib.h>
#include <string.h>

#include "hj_map.h"
#include "hj_vol.h"

#define dir hj_test_dir()

#define WRITE(name, lit) hj_test_write_file(name, lit, sizeof lit - 1)

/* Two slices of 3 x 2; each slice's first line is its top row. */
static void text_volume(void **state)
{
    (void)state;
    hj_vol v = {0};
    hj_error err;
    assert_int_equal(hj_vol_read_text(&v, WRITE("v.txt", "1 2 3\n4 5 6\n\n\n7 8 9\n10 11 12\n\n"), 1, &err), HJ_OK);
    assert_int_equal(v.dim, 3);
    assert_int_equal(v.n[0], 3);
    assert_int_equal(v.n[1], 2);
    assert_int_equal(v.n[2], 2);
    const double want[12] = {4, 5, 6, 1, 2, 3, 10, 11, 12, 7, 8, 9};
    for (int k = 0; k < 12; k++) assert_true(v.v[k] == want[k]);
    hj_vol_free(&v);
    assert_null(v.v);
    /* one block: a 2-D map; slices = 0 ignores blank lines */
    assert_int_equal(hj_vol_read_text(&v, WRITE("m.txt", "1 2\n3 4"), 1, &err), HJ_OK);
    assert_int_equal(v.dim, 2);
    assert_int_equal(v.n[2], 1);
    assert_true(v.v[0] == 3 && v.v[3] == 2);
    hj_vol_free(&v);
    assert_int_equal(hj_vol_read_text(&v, WRITE("f.txt", "1 2\n\n3 4\n"), 0, &err), HJ_OK);
    assert_int_equal(v.dim, 2);
    assert_int_equal(v.n[1], 2);
    hj_vol_free(&v);
}

static void text_volume_errors(void **state)
{
    (void)state;
    hj_vol v = {0};
    hj_error err;
    assert_int_equal(hj_vol_read_text(&v, WRITE("s.txt", "1 2\n3 4\n\n5 6\n"), 1, &err), HJ_EFORMAT);
    assert_has(err.msg, "slice 2 has 1 row, the first has 2");
    assert_int_equal(hj_vol_read_text(&v, WRITE("c.txt", "1 2\n3 4\n\n5 6 7\n8 9 1\n"), 1, &err), HJ_EFORMAT);
    assert_has(err.msg, "c.txt:4: 3 values, previous rows have 2");
    assert_int_equal(hj_vol_read_text(&v, WRITE("n.txt", "1 2\n3 nan\n"), 1, &err), HJ_ENONFINITE);
    assert_has(err.msg, "n.txt:2:3: value nan must be finite and >= 0");
    assert_int_equal(hj_vol_read_text(&v, WRITE("e.txt", "\n\n"), 1, &err), HJ_EFORMAT);
    assert_has(err.msg, "need at least 2 x 2 values (the file holds none)");
    assert_int_equal(hj_vol_read_text(&v, WRITE("d.txt", "1 2\n3 4.5.6\n"), 1, &err), HJ_EFORMAT);
    assert_has(err.msg, "d.txt:2:3: '4.5.6' is not a number");
    assert_null(strstr(err.msg, "binary"));
    /* float32 1.0 (00 00 80 3f): a raw volume read as text says so */
    assert_int_equal(hj_vol_read_text(&v, WRITE("r.f32", "\x01\x02\x80\x3f\x01\x02\x80\x3f"), 1, &err), HJ_EFORMAT);
    assert_has(err.msg, "binary data: a raw volume is read with its dimensions given");
    /* hexadecimal, which strtod takes, is refused with its place */
    assert_int_equal(hj_vol_read_text(&v, WRITE("h.txt", "1 2\n3 0x1p3\n"), 1, &err), HJ_EFORMAT);
    assert_has(err.msg, "h.txt:2:3: '0x1p3' is not a decimal number");
    assert_int_equal(hj_vol_read_text(&v, WRITE("x.txt", "1 0X10\n3 4\n"), 1, &err), HJ_EFORMAT);
    assert_has(err.msg, "x.txt:1:3: '0X10' is not a decimal number");
    assert_int_equal(hj_vol_read_text(&v, WRITE("i.txt", "1 2\n3 -INF\n"), 1, &err), HJ_ENONFINITE);
    assert_has(err.msg, "i.txt:2:3: value -INF must be finite and >= 0");
    /* every decimal form is kept: signs, a point on either side, exponents */
    assert_int_equal(hj_vol_read_text(&v, WRITE("ok.txt", "+1 .5 2.\n1e2 2.5E-1 0e+0\n"), 1, &err), HJ_OK);
    assert_true(v.v[0] == 100 && v.v[1] == 0.25 && v.v[2] == 0 && v.v[3] == 1 && v.v[4] == 0.5 && v.v[5] == 2);
    hj_vol_free(&v);
    /* a directory, by every reader: "Is a directory" (it was a bare
     * "error reading") */
    const long n[3] = {2, 2, 1};
    assert_int_equal(hj_vol_read_text(&v, hj_test_dir(), 1, &err), HJ_EIO);
    assert_has(err.msg, ": Is a directory");
    assert_int_equal(hj_vol_read_raw(&v, hj_test_dir(), n, 8, &err), HJ_EIO);
    assert_has(err.msg, ": Is a directory");
    assert_int_equal(hj_vol_read(&v, hj_test_dir(), 0, 1, &err), HJ_EIO);
    assert_has(err.msg, ": Is a directory");
    assert_null(v.v);
}

static void put_le(unsigned char *b, double x, int bytes)
{
    uint64_t u;
    if (bytes == 8) memcpy(&u, &x, 8);
    else {
        float s = (float)x;
        uint32_t w;
        memcpy(&w, &s, 4);
        u = w;
    }
    for (int k = 0; k < bytes; k++) b[k] = (unsigned char)(u >> (8 * k));
}

/* A 2 x 3 x 2 volume in both value sizes, x fastest, bottom first. */
static void raw_volume(void **state)
{
    (void)state;
    for (int bytes = 4; bytes <= 8; bytes += 4) {
        unsigned char buf[12 * 8];
        for (int k = 0; k < 12; k++) put_le(buf + k * bytes, 0.5 * k, bytes);
        const long n[3] = {2, 3, 2};
        hj_vol v = {0};
        hj_error err;
        const char *p = hj_test_write_file("r.raw", buf, (size_t)(12 * bytes));
        assert_int_equal(hj_vol_read_raw(&v, p, n, bytes, &err), HJ_OK);
        assert_int_equal(v.dim, 3);
        for (int k = 0; k < 12; k++) assert_true(v.v[k] == 0.5 * k);
        hj_vol_free(&v);
        /* one value short, one too many, other dimensions */
        p = hj_test_write_file("t.raw", buf, (size_t)(11 * bytes));
        assert_int_equal(hj_vol_read_raw(&v, p, n, bytes, &err), HJ_EFORMAT);
        assert_has(err.msg, "t.raw: ");
        assert_has(err.msg, "truncated");
        const long n2[3] = {2, 2, 2};
        assert_int_equal(hj_vol_read_raw(&v, hj_test_write_file("l.raw", buf, (size_t)(12 * bytes)), n2, bytes, &err),
                         HJ_EFORMAT);
        put_le(buf + 7 * bytes, -1, bytes);
        assert_int_equal(hj_vol_read_raw(&v, hj_test_write_file("g.raw", buf, (size_t)(12 * bytes)), n, bytes, &err),
                         HJ_ENONFINITE);
        assert_has(err.msg, "value -1 at (i, j, k) = (1, 0, 1)");
        put_le(buf + 7 * bytes, NAN, bytes);
        assert_int_equal(hj_vol_read_raw(&v, hj_test_write_file("g.raw", buf, (size_t)(12 * bytes)), n, bytes, &err),
                         HJ_ENONFINITE);
        assert_null(v.v);
    }
    const long n[3] = {2, 2, 1};
    hj_error err;
    hj_vol v = {0};
    assert_int_equal(hj_vol_read_raw(&v, WRITE("x.raw", "12345678"), n, 3, &err), HJ_EINVAL);
}

/* PGM by its magic whatever the name; text otherwise, even named .pgm;
 * strict P2 numbers; 16-bit P5. */
static void format_by_content(void **state)
{
    (void)state;
    hj_vol v = {0};
    hj_error err;
    assert_int_equal(hj_vol_read(&v, WRITE("IMAGE.PGM", "P2\n2 2\n4\n0 4\n2 1\n"), 1, 3, &err), HJ_OK);
    assert_int_equal(v.dim, 2);
    assert_true(v.v[0] == 2 && v.v[1] == 1.5 && v.v[2] == 1 && v.v[3] == 3);
    hj_vol_free(&v);
    assert_int_equal(hj_vol_read(&v, WRITE("speed", "P2 2 2 4 0 4 2 1"), 1, 3, &err), HJ_OK);
    hj_vol_free(&v);
    assert_int_equal(hj_vol_read(&v, WRITE("text.pgm", "1 2\n3 4\n"), 1, 3, &err), HJ_OK);
    assert_true(v.v[0] == 3);
    hj_vol_free(&v);
    assert_int_equal(hj_vol_read(&v, WRITE("dot.pgm", "P2\n2 2\n255\n100.200 3\n4 5\n"), 0, 1, &err), HJ_EFORMAT);
    assert_has(err.msg, "is '100.200', not a whole number");
    const unsigned char p5[] = {'P', '5', ' ', '2', ' ', '2', ' ', '1', '0', '0', '0', '\n', 0, 0, 0x03, 0xe8, 0x01, 0xf4, 0, 1};
    assert_int_equal(hj_vol_read(&v, hj_test_write_file("wide", p5, sizeof p5), 0, 1, &err), HJ_OK);
    assert_close(v.v[0], 0.5, 0, 1e-15); /* bottom row first: 500 / 1000 */
    assert_close(v.v[3], 1.0, 0, 1e-15);
    hj_vol_free(&v);
    assert_int_equal(hj_vol_read(&v, "/nonexistent/x", 0, 1, &err), HJ_EIO);
    /* other Netpbm kinds are named, not read as text ("'P6' is not a number") */
    assert_int_equal(hj_vol_read(&v, WRITE("colour.ppm", "P6\n2 2\n255\n012345678901"), 0, 1, &err), HJ_EFORMAT);
    assert_has(err.msg, "a PPM colour image (P6), not a PGM grey image");
    assert_int_equal(hj_vol_read(&v, WRITE("bits.pbm", "P1\n2 2\n0 1\n1 0\n"), 0, 1, &err), HJ_EFORMAT);
    assert_has(err.msg, "a PBM bitmap (P1)");
    hj_map m = {0};
    assert_int_equal(hj_map_read(&m, WRITE("colour2.ppm", "P3\n2 2\n255\n"), 0, 1, &err), HJ_EFORMAT);
    assert_has(err.msg, "a PPM colour image (P3)");
}

static void all_zero(void **state)
{
    (void)state;
    hj_vol v = {0};
    hj_error err;
    assert_int_equal(hj_vol_read(&v, WRITE("z.txt", "0 0\n0 0\n"), 0, 1, &err), HJ_OK);
    assert_int_equal(hj_vol_check_nonzero(&v, "z.txt", &err), HJ_EINVAL);
    assert_has(err.msg, "z.txt: every value is 0");
    v.v[2] = 1;
    assert_int_equal(hj_vol_check_nonzero(&v, "z.txt", &err), HJ_OK);
    hj_vol_free(&v);
}

/* The header, the point count, values x-fastest, inf written as fill. */
static void vtk_writer(void **state)
{
    (void)state;
    char path[128];
    snprintf(path, sizeof path, "%s/t.vtk", dir);
    const long n[3] = {2, 1, 2};
    const double x0[3] = {0, 1, 2}, dx[3] = {0.5, 1, 0.25}, val[4] = {0, 1.5, INFINITY, 3};
    hj_error err;
    assert_int_equal(hj_vol_write_vtk(path, n, x0, dx, "T\nx", "T", val, -1, &err), HJ_OK);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    char buf[1024];
    const size_t got = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[got] = '\0';
    assert_string_equal(buf, "# vtk DataFile Version 3.0\nT x\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 2 1 2\n"
                             "ORIGIN 0 1 2\nSPACING 0.5 1 0.25\nPOINT_DATA 4\nSCALARS T double 1\nLOOKUP_TABLE "
                             "default\n0\n1.5\n-1\n3\n");
    snprintf(path, sizeof path, "%s/missing/t.vtk", dir);
    assert_int_equal(hj_vol_write_vtk(path, n, x0, dx, "T", "T", val, -1, &err), HJ_EIO);
}

/* Arguments that would make a file VTK refuses or misreads: HJ_EINVAL
 * and no file at all (they were written: DIMENSIONS 0, "nan" as the fill
 * or in the header, a field name of two words or none). */
static void vtk_writer_bad_arguments(void **state)
{
    (void)state;
    char path[128];
    snprintf(path, sizeof path, "%s/bad.vtk", dir);
    const long n[3] = {2, 1, 2}, n0[3] = {2, 0, 2}, nneg[3] = {-2, -1, 2};
    const double x0[3] = {0, 1, 2}, dx[3] = {0.5, 1, 0.25}, val[4] = {0, 1.5, INFINITY, 3};
    const double x0nan[3] = {0, NAN, 2}, dx0[3] = {0.5, 0, 0.25}, dxinf[3] = {INFINITY, 1, 1};
    hj_error err;
    assert_int_equal(hj_vol_write_vtk(path, n0, x0, dx, "T", "T", val, -1, &err), HJ_EINVAL);
    assert_has(err.msg, "0 nodes along dimension 2");
    assert_int_equal(hj_vol_write_vtk(path, nneg, x0, dx, "T", "T", val, -1, &err), HJ_EINVAL);
    assert_int_equal(hj_vol_write_vtk(path, n, x0nan, dx, "T", "T", val, -1, &err), HJ_EINVAL);
    assert_int_equal(hj_vol_write_vtk(path, n, x0, dx0, "T", "T", val, -1, &err), HJ_EINVAL);
    assert_int_equal(hj_vol_write_vtk(path, n, x0, dxinf, "T", "T", val, -1, &err), HJ_EINVAL);
    assert_int_equal(hj_vol_write_vtk(path, n, x0, dx, "T", "T", val, NAN, &err), HJ_EINVAL);
    assert_has(err.msg, "fill");
    assert_int_equal(hj_vol_write_vtk(path, n, x0, dx, "T", "T", val, INFINITY, &err), HJ_EINVAL);
    assert_int_equal(hj_vol_write_vtk(path, n, x0, dx, "T", "travel time", val, -1, &err), HJ_EINVAL);
    assert_has(err.msg, "one word");
    assert_int_equal(hj_vol_write_vtk(path, n, x0, dx, "T", "T\n", val, -1, &err), HJ_EINVAL);
    assert_int_equal(hj_vol_write_vtk(path, n, x0, dx, "T", "", val, -1, &err), HJ_EINVAL);
    /* NULL arguments: an error, not a crash */
    assert_int_equal(hj_vol_write_vtk(path, n, x0, dx, "T", "T", NULL, -1, &err), HJ_EINVAL);
    assert_int_equal(hj_vol_write_vtk(NULL, n, x0, dx, "T", "T", val, -1, &err), HJ_EINVAL);
    assert_int_equal(hj_vol_write_vtk(path, n, x0, dx, NULL, "T", val, -1, &err), HJ_EINVAL);
    assert_int_equal(hj_vol_write_vtk(path, n, x0, dx, "T", NULL, val, -1, &err), HJ_EINVAL);
    FILE *f = fopen(path, "r");
    assert_null(f);
    if (f) fclose(f);
    /* a DEL byte in the title is a control byte too */
    assert_int_equal(hj_vol_write_vtk(path, n, x0, dx, "a\x7f" "b", "T", val, -1, &err), HJ_OK);
    f = fopen(path, "r");
    assert_non_null(f);
    char buf[64];
    assert_non_null(fgets(buf, sizeof buf, f));
    assert_non_null(fgets(buf, sizeof buf, f));
    fclose(f);
    assert_string_equal(buf, "a b\n");
}

HJ_TEST_MAIN("hj_vol", hj_test_mkdir, hj_test_rmdir, cmocka_unit_test(text_volume), cmocka_unit_test(text_volume_errors),
             cmocka_unit_test(raw_volume), cmocka_unit_test(format_by_content), cmocka_unit_test(all_zero),
             cmocka_unit_test(vtk_writer), cmocka_unit_test(vtk_writer_bad_arguments))
