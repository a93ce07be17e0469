/* Unit tests of common/hj_map: text and PGM speed maps (the first row of
 * the file at the top), malformed files refused with a message, and the
 * bilinear interpolation. */
#include "hj_test.h"

#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "hj_map.h"

#define dir hj_test_dir()


/* The text map txt, written to name and read (which must succeed). */
static hj_map read_text_map(const char *name, const char *txt)
{
    hj_map m = {0};
    hj_error err;
    assert_int_equal(hj_map_read(&m, hj_test_write_file(name, txt, strlen(txt)), 0, 1, &err), HJ_OK);
    return m;
}

static void text_map_rows_flipped(void **state)
{
    (void)state;
    hj_map m = read_text_map("m.txt", "1 2 3\n\n4 5 6\n");
    assert_int_equal(m.mx, 3);
    assert_int_equal(m.my, 2);
    const double bottom_first[6] = {4, 5, 6, 1, 2, 3};
    for (int k = 0; k < 6; k++) assert_true(m.v[k] == bottom_first[k]);
    hj_map_free(&m);
    assert_null(m.v);
}

static void pgm_maps(void **state)
{
    (void)state;
    hj_map m = {0};
    const char p2[] = "P2\n# a comment\n2 2\n4\n0 4\n2 1\n";
    assert_int_equal(hj_map_read(&m, hj_test_write_file("a.pgm", p2, strlen(p2)), 1, 3, NULL), HJ_OK);
    assert_int_equal(m.mx, 2);
    const double p2v[4] = {2, 1.5, 1, 3}; /* f = 1 + 2 v / 4, bottom row first */
    for (int k = 0; k < 4; k++) assert_true(m.v[k] == p2v[k]);
    hj_map_free(&m);
    /* the format by content: an upper-case suffix, no suffix, text named .pgm */
    assert_int_equal(hj_map_read(&m, hj_test_write_file("A.PGM", p2, strlen(p2)), 1, 3, NULL), HJ_OK);
    assert_true(m.v[0] == 2);
    hj_map_free(&m);
    assert_int_equal(hj_map_read(&m, hj_test_write_file("image", p2, strlen(p2)), 1, 3, NULL), HJ_OK);
    hj_map_free(&m);
    assert_int_equal(hj_map_read(&m, hj_test_write_file("t.pgm", "7 8\n9 6\n", 8), 1, 3, NULL), HJ_OK);
    assert_true(m.v[0] == 9);
    hj_map_free(&m);
    const unsigned char p5[] = {'P', '5', '\n', '2', ' ', '2', '\n', '2', '5', '5', '\n', 0, 255, 51, 102};
    assert_int_equal(hj_map_read_pgm(&m, hj_test_write_file("b.pgm", p5, sizeof p5), 0, 1, NULL), HJ_OK);
    assert_close(m.v[0], 0.2, 1e-15, 0);
    assert_close(m.v[3], 1.0, 1e-15, 0);
    hj_map_free(&m);
}

static void malformed_maps(void **state)
{
    (void)state;
    hj_map m = {0};
    hj_error err;
    assert_int_equal(hj_map_read(&m, "/nonexistent.txt", 0, 1, &err), HJ_EIO);
    assert_non_null(strstr(err.msg, "cannot read /nonexistent.txt"));
    const char word[] = "1 2\n3 x\n", ragged[] = "1 2\n3\n", negative[] = "1 -2\n3 4\n", small[] = "1 2\n";
    assert_int_equal(hj_map_read(&m, hj_test_write_file("w.txt", word, strlen(word)), 0, 1, &err), HJ_EFORMAT);
    assert_non_null(strstr(err.msg, ":2:3: 'x' is not a number"));
    assert_int_equal(hj_map_read(&m, hj_test_write_file("r.txt", ragged, strlen(ragged)), 0, 1, &err), HJ_EFORMAT);
    assert_non_null(strstr(err.msg, "previous rows have 2"));
    assert_int_equal(hj_map_read(&m, hj_test_write_file("n.txt", negative, strlen(negative)), 0, 1, &err), HJ_ENONFINITE);
    assert_int_equal(hj_map_read(&m, hj_test_write_file("s.txt", small, strlen(small)), 0, 1, &err), HJ_EFORMAT);
    const char cut[] = "P2\n2 2\n4\n0 4\n2\n";
    assert_int_equal(hj_map_read(&m, hj_test_write_file("c.pgm", cut, strlen(cut)), 0, 1, &err), HJ_EFORMAT);
    assert_non_null(strstr(err.msg, "truncated"));
    /* a token is a number as a whole, and nothing follows the last pixel */
    const char dotted[] = "P2\n2 2\n255\n100.200 4\n2 3\n", extra[] = "P2\n2 2\n4\n0 4\n2 3 # ok\n1\n";
    assert_int_equal(hj_map_read(&m, hj_test_write_file("d.pgm", dotted, strlen(dotted)), 0, 1, &err), HJ_EFORMAT);
    assert_int_equal(hj_map_read(&m, hj_test_write_file("e.pgm", extra, strlen(extra)), 0, 1, &err), HJ_EFORMAT);
    assert_non_null(strstr(err.msg, "more data than the 2 x 2 pixels"));
    const unsigned char raw[] = {'P', '5', '\n', '2', ' ', '2', '\n', '9', '\n', 1, 2, 3, 4, 5};
    assert_int_equal(hj_map_read(&m, hj_test_write_file("e5.pgm", raw, sizeof raw), 0, 1, &err), HJ_EFORMAT);
    assert_int_equal(hj_map_read(&m, hj_test_write_file("ok5.pgm", raw, sizeof raw - 1), 0, 1, &err), HJ_OK);
    hj_map_free(&m);
    assert_null(m.v);
}

static void bilinear_and_clamped(void **state)
{
    (void)state;
    double v[6] = {0, 1, 2, 10, 11, 12}; /* rows y = 0 and y = 1, x = 0, 1, 2 */
    hj_map m = {.mx = 3, .my = 2, .v = v, .xmin = 0, .xmax = 2, .ymin = 0, .ymax = 1};
    assert_close(hj_map_eval(1, 0, &m), 1, 1e-15, 0);
    assert_close(hj_map_eval(0.5, 0.5, &m), 5.5, 1e-15, 0);
    assert_close(hj_map_eval(2, 1, &m), 12, 1e-15, 0);
    assert_close(hj_map_eval(-1, 2, &m), 10, 1e-15, 0); /* outside: the nearest edge */
    hj_map c = {.constant = 0.7};
    assert_true(hj_map_eval(3, 4, &c) == 0.7);
}

/* A map read without a rectangle is in pixel units; speeds invert to
 * slownesses, and a zero speed is named by its row and column in the file. */
static void pixel_units_and_speeds(void **state)
{
    (void)state;
    hj_map m = read_text_map("s.txt", "1 2 4\n2 0 1\n");
    hj_error err;
    assert_close(m.xmax, 2, 0, 0);
    assert_close(m.ymax, 1, 0, 0);
    assert_close(hj_map_eval(2, 1, &m), 4, 0, 0); /* top right pixel */
    assert_int_equal(hj_map_invert(&m, &err), HJ_EINVAL);
    assert_non_null(strstr(err.msg, "speed 0 at row 2, column 2"));
    assert_close(hj_map_eval(2, 1, &m), 4, 0, 0); /* unchanged */
    m.v[1] = 8;                                   /* the zero (bottom row in memory) */
    assert_int_equal(hj_map_invert(&m, &err), HJ_OK);
    assert_close(hj_map_eval(2, 1, &m), 0.25, 0, 1e-15);
    assert_close(hj_map_eval(1, 0, &m), 0.125, 0, 1e-15);
    hj_map_free(&m);
}

/* err.msg after reading the n bytes of data as a PGM (which must fail
 * with code); the message must be one line without control bytes. */
static const char *pgm_error(const char *name, const char *data, size_t n, int code)
{
    static hj_error err;
    hj_map m = {0};
    assert_int_equal(hj_map_read_pgm(&m, hj_test_write_file(name, data, n), 0, 1, &err), code);
    for (const unsigned char *p = (const unsigned char *)err.msg; *p; p++)
        if (*p < 0x20 || *p == 0x7f) fail_msg("control byte 0x%02x in '%s'", *p, err.msg);
    return err.msg;
}
#define PGM_ERROR(name, lit, code) pgm_error(name, lit, sizeof lit - 1, code)

/* A bad PGM token is named by file, line and column, quoted with its
 * control bytes escaped. */
static void pgm_messages_name_line_and_column(void **state)
{
    (void)state;
    assert_has(PGM_ERROR("x.pgm", "P2\n# c\n3 2\n255\n1 2 3\n4 x5 6\n", HJ_EFORMAT),
               "x.pgm:6:3: the pixel at row 2, column 2 is 'x5', not a whole number");
    assert_has(PGM_ERROR("esc.pgm", "P2\n2 2\n255\n1 \033[31m\n1 1\n", HJ_EFORMAT),
               "esc.pgm:4:3: the pixel at row 1, column 2 is '\\x1b[31m', not a whole number");
    assert_has(PGM_ERROR("w.pgm", "P2\n1 2\n255\n1 2\n", HJ_EFORMAT), "w.pgm:2:1: the width is 1, outside 2..100000000");
    assert_has(PGM_ERROR("mv.pgm", "P5 2 2\n\t70000\n", HJ_EFORMAT), "mv.pgm:2:2: the maxval is 70000, outside 1..65535");
    assert_has(PGM_ERROR("big.pgm", "P2\n2 2\n4\n0 5\n1 1\n", HJ_EFORMAT),
               "big.pgm:4:3: the pixel at row 1, column 2 is 5, outside 0..4");
    assert_has(PGM_ERROR("m.pgm", "P7\n2 2\n", HJ_EFORMAT), "m.pgm:1:1: a PAM image (P7), not a PGM grey image (P2 or P5)");
    assert_has(PGM_ERROR("b.pgm", "\001\377", HJ_EFORMAT), "it starts with '\\x01\\xff'");
    assert_has(PGM_ERROR("j.pgm", "P22 2 255\n1 2\n3 4\n", HJ_EFORMAT), "not a PGM image");
    assert_has(PGM_ERROR("h.pgm", "P2\n2 2\n", HJ_EFORMAT), "h.pgm:3:1: truncated or malformed: the file ends before the maxval");
    assert_has(PGM_ERROR("e.pgm", "P2\n2 2\n4\n0 4\n2 3 x\n", HJ_EFORMAT),
               "e.pgm:5:5: more data than the 2 x 2 pixels of its header");
    assert_has(PGM_ERROR("o5.pgm", "P5\n2 2\n9\n\001\002\012\004", HJ_EFORMAT),
               "o5.pgm: offset 11: the pixel at row 2, column 1 is 10, above maxval 9");
    const char long_word[] = "P2\n2 2\n255\n1 1234567890123456789012345x 3 4\n";
    assert_has(PGM_ERROR("l.pgm", long_word, HJ_EFORMAT),
               ":4:3: the pixel at row 1, column 2 is '123456789012345678901234...', not a whole number");
    const char long_number[] = "P2\n2 2\n255\n1 123456789012345678901234567890 3 4\n";
    assert_has(PGM_ERROR("n.pgm", long_number, HJ_EFORMAT),
               ":4:3: the pixel at row 1, column 2 is 123456789012345678901234..., outside 0..255");
    /* leading zeros make a long token, not a large number */
    hj_map m = {0};
    const char zeros[] = "P2\n2 2\n255\n1 0000000000000000000000000000007 3 4\n";
    assert_int_equal(hj_map_read_pgm(&m, hj_test_write_file("z.pgm", zeros, sizeof zeros - 1), 0, 255, NULL), HJ_OK);
    assert_true(m.v[3] == 7); /* top row, second pixel */
    hj_map_free(&m);
}

/* A header is checked against the data that follows it: a 24-byte file
 * claiming 30000 x 30000 pixels is refused before 7 GB are allocated, and
 * a 16-bit P5 cut inside its data is refused (reading it shifted EOF, -1,
 * left: undefined behaviour, found by the fuzzer). */
static void pgm_header_against_file_size(void **state)
{
    (void)state;
    assert_has(PGM_ERROR("huge.pgm", "P5\n30000 30000\n255\n\001\002", HJ_EFORMAT),
               "the 30000 x 30000 pixels of its header need 900000000 bytes, 2 follow it");
    assert_has(PGM_ERROR("huge2.pgm", "P2 30000 30000 255 1 2 3", HJ_EFORMAT), "need at least 1799999999 bytes");
    assert_has(PGM_ERROR("cut16.pgm", "P5\n2 2\n65535\n\000\001\000\002\000", HJ_EFORMAT), "need 8 bytes, 5 follow it");
    /* Through a FIFO (no size to check) the pixel loop sees the end. */
    char fifo[160];
    snprintf(fifo, sizeof fifo, "%s/cut.pgm", dir);
    assert_int_equal(mkfifo(fifo, 0600), 0);
    pid_t child = fork();
    assert_true(child >= 0);
    if (child == 0) {
        FILE *f = fopen(fifo, "wb");
        static const char cut[] = "P5\n2 2\n65535\n\000\001\000\002\000";
        if (f) fwrite(cut, 1, sizeof cut - 1, f), fclose(f);
        _exit(0);
    }
    hj_map m = {0};
    hj_error err;
    assert_int_equal(hj_map_read_pgm(&m, fifo, 0, 1, &err), HJ_EFORMAT);
    waitpid(child, NULL, 0);
    assert_has(err.msg, "cut.pgm: offset 18: truncated or malformed: the file ends before the pixel at row 2, column 1");
}

/* Text maps: the column of a bad token, its control bytes escaped, and a
 * NUL byte inside a token refused (strtod stopped at it: "4\0005" was
 * read as 4). */
static void text_map_messages(void **state)
{
    (void)state;
    hj_map m = {0};
    hj_error err;
    const char ctl[] = "1 2\n3 \001x\n", nul[] = "1 2\n3 4\0005\n";
    assert_int_equal(hj_map_read_text(&m, hj_test_write_file("c.txt", ctl, sizeof ctl - 1), &err), HJ_EFORMAT);
    assert_has(err.msg, "c.txt:2:3: '\\x01x' is not a number");
    assert_int_equal(hj_map_read_text(&m, hj_test_write_file("z.txt", nul, sizeof nul - 1), &err), HJ_EFORMAT);
    assert_has(err.msg, "z.txt:2:3: '4\\x005' is not a number");
    const char neg[] = "1 2\n3   -4\n";
    assert_int_equal(hj_map_read_text(&m, hj_test_write_file("n.txt", neg, sizeof neg - 1), &err), HJ_ENONFINITE);
    assert_has(err.msg, "n.txt:2:5: value -4 must be finite and >= 0");
}

HJ_TEST_MAIN("hj_map", hj_test_mkdir, hj_test_rmdir, cmocka_unit_test(text_map_rows_flipped), cmocka_unit_test(pixel_units_and_speeds),
             cmocka_unit_test(pgm_maps), cmocka_unit_test(malformed_maps), cmocka_unit_test(bilinear_and_clamped),
             cmocka_unit_test(pgm_messages_name_line_and_column), cmocka_unit_test(pgm_header_against_file_size),
             cmocka_unit_test(text_map_messages))
