/* Command-line behaviour of the paper 1 programs: bad input gives one clear
 * message and a non-zero exit, and never a half-written result file. */
#include "hj_test.h"
#include "hj_sys.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#ifndef HJ_BIN_DIR
#error "HJ_BIN_DIR must name the directory of the built programs"
#endif
#define P1 HJ_BIN_DIR "/paper1_fastsweeping/"

#define dir hj_test_dir()
static char err_text[4096];

/* Run a shell command with its stderr captured in err_text. */
static int run(const char *cmd) { return hj_test_shell(cmd, 0, err_text, sizeof err_text); }

static int lines(const char *s)
{
    int n = 0;
    for (; *s; s++) n += *s == '\n';
    return n;
}

/* exit status, one line on stderr, containing what */
static void expect_failure(const char *cmd, int status, const char *what)
{
    int st = run(cmd);
    if (st != status || lines(err_text) != 1 || !strstr(err_text, what))
        fail_msg("'%s': status %d (expected %d), stderr:\n%s(expected one line containing '%s')", cmd, st, status,
                 err_text, what);
}

static void bad_options(void **state)
{
    (void)state;
    expect_failure(P1 "example1 --bogus", 2, "unknown option '--bogus'");
    expect_failure(P1 "example1 --sizes 0", 2, "between 8 and 10000");
    expect_failure(P1 "example1 --sizes -40", 2, "between 8 and 10000");
    expect_failure(P1 "example1 --sizes 40,nan", 2, "not an integer");
    expect_failure(P1 "example1 --sizes 1000000", 2, "between 8 and 10000");
    expect_failure(P1 "example1 --delta nan", 2, "must be finite");
    expect_failure(P1 "example3 --eps inf", 2, "must be finite");
    expect_failure(P1 "example2 --strategy magic", 2, "--strategy: 'magic' is not one of richardson, lax-wendroff, first-order");
    expect_failure(P1 "example2 --guess exact", 2, "--guess: 'exact' is not one of physical, category-iii");
    expect_failure(P1 "example3 --exclude box", 2, "--exclude: 'box' is not one of distance, literal, closed, open");
    expect_failure(P1 "example2 --richardson-box wide", 2, "--richardson-box: 'wide' is not one of node, tight, piece");
    expect_failure(P1 "example1 --delta 0", 2, "--delta must be between");
    expect_failure(P1 "example1 --quick --sizes 40", 2, "--quick or --sizes, not both");
    expect_failure(P1 "example2 --eps 1e-6 --eps-h2 1", 2, "--eps or --eps-h2, not both");
    expect_failure(P1 "example1 --band 3 --band 4", 2, "--band is given twice");
    expect_failure(P1 "example2 --guess-noise 1", 2, "--guess-noise must be between 0 and 0.5");
    expect_failure(P1 "example2 --guess-noise nan", 2, "--guess-noise must be finite");
    expect_failure(P1 "example2 --seed -1", 2, "--seed must be between");
    expect_failure(P1 "example4 --sizes", 2, "needs a value");
    expect_failure(P1 "example1 stray", 2, "unexpected argument");
}

static void help_works(void **state)
{
    (void)state;
    assert_int_equal(run(P1 "example1 --help"), 0);
    assert_int_equal(run(P1 "eikonal --help"), 0);
}

static void unwritable_output_leaves_nothing(void **state)
{
    (void)state;
    char cmd[512], path[256];
    snprintf(path, sizeof path, "%s/ro", dir);
    mkdir(path, 0555);
    snprintf(cmd, sizeof cmd, P1 "example3 --sizes 16 --grid-N 16 --out-dir %s", path);
    if (geteuid() != 0) { /* root writes anywhere: the check only means something otherwise */
        expect_failure(cmd, 1, "cannot write");
    }
    snprintf(cmd, sizeof cmd, P1 "example3 --sizes 16 --out-dir /proc/hj-no-such-dir");
    expect_failure(cmd, 1, "cannot create directory");
    /* the result onto stdout that cannot take it: the reason is named */
    if (access("/dev/full", W_OK) == 0)
        expect_failure("(" P1 "eikonal --speed-const 1 --domain -1,1,-1,1 --N 8 --source 0,0 --out - >/dev/full)", 1,
                       "eikonal: error writing stdout: No space left on device");
}

static void results_complete(void **state)
{
    (void)state;
    char cmd[512], path[256];
    snprintf(cmd, sizeof cmd, P1 "example3 --sizes 16,32 --grid-N 16 --out-dir %s/ok", dir);
    assert_int_equal(run(cmd), 0);
    snprintf(path, sizeof path, "%s/ok/table3.4.tsv", dir);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    char line[1024];
    int n = 0;
    while (fgets(line, sizeof line, f)) n++;
    fclose(f);
    assert_int_equal(n, 4); /* comment, header, two rows */
    /* no temporary files left behind */
    snprintf(cmd, sizeof cmd, "ls %s/ok | grep -c tmp", dir);
    assert_int_not_equal(run(cmd), 0);
}

/* The last row of a table3.4.tsv: L1, L-infinity and the number of
 * measured nodes (columns 4, 6 and 13). */
static void read_row(const char *path, double *l1, double *linf, long *measured)
{
    *l1 = *linf = NAN;
    *measured = -1;
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    char line[1024], last[1024] = "";
    while (fgets(line, sizeof line, f))
        if (line[0] != '#') strcpy(last, line);
    fclose(f);
    char *tok = strtok(last, "\t");
    for (int col = 1; tok; col++, tok = strtok(NULL, "\t")) {
        if (col == 4) *l1 = strtod(tok, NULL);
        if (col == 6) *linf = strtod(tok, NULL);
        if (col == 13) *measured = strtol(tok, NULL, 10);
    }
    if (!(*l1 >= 0) || !(*linf >= 0) || *measured < 0) fail_msg("%s: no complete table row", path);
}

/* Example 3's excluded region: the default leaves out the nodes closer than
 * 0.15 to the centre (the disc inside the paper's box), so it measures the
 * nodes that the literal box test measures and the box's corners too.  At
 * N = 40 (h = 0.05) the closed box holds 7 x 7 nodes, of which the rows on
 * +0.15 round to outside (36 excluded); the open disc holds the 25 nodes
 * with i^2 + j^2 < 9, and the two on -0.15 that round to inside: 9 more
 * nodes are measured. */
static void exclusion_distance_measures_more(void **state)
{
    (void)state;
    char cmd[512], path[256];
    double l1[2], linf[2];
    long n[2];
    const char *mode[2] = {"distance", "literal"};
    for (int m = 0; m < 2; m++) {
        snprintf(cmd, sizeof cmd, P1 "example3 --sizes 40 --exclude %s --out-dir %s/ex%s", mode[m], dir, mode[m]);
        assert_int_equal(run(cmd), 0);
        snprintf(path, sizeof path, "%s/ex%s/table3.4.tsv", dir, mode[m]);
        read_row(path, &l1[m], &linf[m], &n[m]);
    }
    assert_int_equal(n[0] - n[1], 9);
    assert_true(l1[0] > l1[1]);      /* the extra nodes carry error */
    assert_true(linf[0] >= linf[1]); /* a superset of the nodes */
}

/* path = the test directory / name, holding text. */
static void write_text(char *path, size_t n, const char *name, const char *text)
{
    snprintf(path, n, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

static void eikonal_bad_files(void **state)
{
    (void)state;
    char cmd[512], path[256];
    expect_failure(P1 "eikonal --speed /nonexistent.txt --source 0,0", 1, "cannot read /nonexistent.txt");
    write_text(path, sizeof path, "ragged.txt", "1 1 1\n1 1\n1 1 1\n");
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed %s --source 0,0", path);
    expect_failure(cmd, 1, "2 values, previous rows have 3");
    write_text(path, sizeof path, "ragged.txt", "1 1 1\n1 nan 1\n1 1 1\n");
    expect_failure(cmd, 1, "must be finite");
    write_text(path, sizeof path, "ragged.txt", "1 1 -1\n1 1 1\n");
    expect_failure(cmd, 1, "value -1 must be finite and >= 0");
    write_text(path, sizeof path, "ragged.txt", "1 1 x\n1 1 1\n");
    expect_failure(cmd, 1, "not a number");
    write_text(path, sizeof path, "ragged.txt", "1 1\n1 1\n\n1 1\n");
    expect_failure(cmd, 1, "slice 2 has 1 row, the first has 2");
    /* hexadecimal is not a value of a map, with its line and column */
    write_text(path, sizeof path, "ragged.txt", "1 1 1\n1 0x1p3 1\n1 1 1\n");
    expect_failure(cmd, 1, "ragged.txt:2:3: '0x1p3' is not a decimal number");
    write_text(path, sizeof path, "ragged.txt", "0 0 0\n0 0 0\n");
    expect_failure(cmd, 1, "every value is 0");
    /* a raw float32 volume given without --raw: the tool names the option */
    write_text(path, sizeof path, "ragged.txt", "\x01\x02\x80\x3f\x01\x02\x80\x3f");
    expect_failure(cmd, 1, "binary data: a raw volume is read with --raw NX,NY[,NZ]");
    /* PGM told by content, whatever the name; P2 numbers strict */
    write_text(path, sizeof path, "bad.txt", "P2\n3 3\n255\n1 2 3\n4 5\n");
    snprintf(cmd, sizeof cmd, P1 "eikonal --slowness %s --source 0,0", path);
    expect_failure(cmd, 1, "truncated or malformed");
    write_text(path, sizeof path, "dot.PGM", "P2\n2 2\n255\n100.200 3\n4 5\n");
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed %s --source 0,0", path);
    expect_failure(cmd, 1, "is '100.200', not a whole number");
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed %s --source 0,0 --N 8", path);
    expect_failure(cmd, 2, "--N is for a constant medium");
    expect_failure(P1 "eikonal --speed-const 1 --source 1.5,0 --N 10", 2, "source 1 is outside the domain");
    expect_failure(P1 "eikonal --speed-const 1 --N 10", 2, "give a source");
    expect_failure(P1 "eikonal --speed-const 0 --source 0,0", 2, "--speed-const must be between");
    expect_failure(P1 "eikonal --speed-const 1 --N 10 --N 12 --source 0,0", 2, "--N is given twice");
    expect_failure(P1 "eikonal --speed-const 1 --source 0,0 --source ''", 2, "--source needs a non-empty value");
    expect_failure(P1 "eikonal --speed-const 1 --source 0,0 --order 2", 2, "--order: '2' is not one of 1, 3, 5");
    expect_failure(P1 "eikonal --speed-const 1 --domain 0,1,0,1,0,1 --N 8 --source 0,0", 2,
                   "--source wants X,Y,Z or X,Y,Z,T0");
    expect_failure(P1 "eikonal --speed-const 1 --source 0,0 --format vtk --out -", 2, "--format vtk needs --out FILE");
    /* 1e308 is finite: the message gives the bound it is beyond */
    expect_failure(P1 "eikonal --speed-const 1 --source 1e308,0", 2, "(numbers within +-1e300)");
    /* a directory as a map or point file is named as one */
    expect_failure(P1 "eikonal --speed examples --source 0,0", 1, "cannot read examples: Is a directory");
    expect_failure(P1 "eikonal --speed-const 1 --sources examples", 1, "cannot read examples: Is a directory");
    expect_failure(P1 "eikonal --speed examples/data/volume.txt --source 2,2,2 --out -", 2, "a 3-D result is written as VTK");
    /* a speed of 0 is an obstacle: a source on it, and walled-off nodes */
    write_text(path, sizeof path, "zero.txt", "1 1 1\n1 0 1\n1 1 1\n");
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed %s --source 1,1", path);
    expect_failure(cmd, 1, "source 1 at (1, 1) is inside an obstacle");
    snprintf(cmd, sizeof cmd, P1 "eikonal --slowness %s --source 0,0", path);
    expect_failure(cmd, 1, "slowness 0 at node (1, 1, 0): every slowness must be > 0");
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed %s --speed-const 1 --source 0,0", path);
    expect_failure(cmd, 2, "give only one of");
    write_text(path, sizeof path, "walled.txt", "1 1 1 1\n0 0 0 0\n1 1 1 1\n");
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed %s --source 0,0 --out %s/w.tsv", path, dir);
    expect_failure(cmd, 4, "4 of 12 nodes outside the obstacles cannot be reached from any source");
    expect_failure(P1 "eikonal --speed-const 1 --source 0,0 --source 0,0,1 --N 10", 2,
                   "sources 1 and 2 are at the same point with different times");
    expect_failure(P1 "eikonal --speed-const 1 --domain 0,1e-200,0,1e-200 --N 10 --source 0,0", 2,
                   "the domain is too small");
    write_text(path, sizeof path, "src.txt", "0.5 0.5\n0.2 x\n");
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed-const 1 --sources %s", path);
    expect_failure(cmd, 1, "src.txt:2: 'x' is not a finite number");
    write_text(path, sizeof path, "src.txt", "0.5 0.5\n2 0.5\n");
    expect_failure(cmd, 1, "source 2 is outside the domain: its x coordinate is 2");
    write_text(path, sizeof path, "line.txt", "0 0.5\n");
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed-const 1 --polyline %s", path);
    expect_failure(cmd, 1, "line.txt:1: a polyline vertex needs 3 numbers, this line has 2");
    write_text(path, sizeof path, "line.txt", "0 0.5 0\n1 0.5 0\n");
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed-const 1 --N 10 --polyline %s --source 0.5,0.5,1", path);
    expect_failure(cmd, 1, "source 1 sits on a node the polyline fixes at 0, with a different time 1");
    write_text(path, sizeof path, "mask.txt", "0 0\n0 0\n");
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed-const 1 --N 10 --obstacle %s --source 0,0", path);
    expect_failure(cmd, 1, "the mask");
    /* raw volumes: the size must match the dimensions */
    write_text(path, sizeof path, "v.raw", "0123456789abcdef");
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed %s --raw 2,2,2 --source 0,0,0", path);
    expect_failure(cmd, 1, "16 bytes, but 2 x 2 x 2 values of 4 bytes need 32");
    /* a list longer than the reader's buffer is refused, not cut */
    char longsrc[400] = P1 "eikonal --speed-const 1 --N 10 --source 0,0,";
    for (size_t k = strlen(longsrc); k < 330; k++) longsrc[k] = '0';
    expect_failure(longsrc, 2, "--source wants X,Y or X,Y,T0");
    /* options that would be ignored are refused, not dropped */
    expect_failure(P1 "eikonal --speed-const 1 --raw-type float64 --source 0,0", 2,
                   "--raw-type is the value type of --raw files: give --raw NX,NY[,NZ] too");
    expect_failure(P1 "eikonal --speed-const 1 --pgm-range 0,2 --source 0,0", 2,
                   "--pgm-range maps the pixels of a --speed or --slowness PGM: none is given");
    write_text(path, sizeof path, "two.txt", "1 1 1\n1 2 1\n1 1 1\n");
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed %s --pgm-range 0,2 --source 0,0", path);
    expect_failure(cmd, 2, "two.txt is not one (a text grid's values are used as they are)");
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed %s --raw 3,3 --pgm-range 0,2 --source 0,0", path);
    expect_failure(cmd, 2, "--pgm-range maps the pixels of a PGM, but --raw reads the map as a raw volume");
    /* a speed whose inverse overflows is named by its own value, not by 1 / inf */
    write_text(path, sizeof path, "tiny.txt", "1 1 1\n1 1e-320 1\n1 1 1\n");
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed %s --source 0,0", path);
    expect_failure(cmd, 1, "tiny.txt: speed 9.99989e-321 at node (1, 1, 0) is too small (1 / speed overflows)");
    /* too few nodes for the order: the axis by name (the library numbers from 0) */
    write_text(path, sizeof path, "flat.txt", "1 1 1\n1 1 1\n");
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed %s --source 0,0", path);
    expect_failure(cmd, 1, "the grid has 2 nodes along y; order 3 needs at least 3: give --order 1");
    expect_failure(P1 "eikonal --speed-const 1 --N 100 --domain 0,1,0,0.01 --order 5 --source 0,0", 1,
                   "the grid has 2 nodes along y; order 5 needs at least 5: give --order 1 or a larger --domain along it");
    write_text(path, sizeof path, "cube.txt", "1 1 1 1\n1 1 1 1\n1 1 1 1\n\n1 1 1 1\n1 1 1 1\n1 1 1 1\n\n"
                                              "1 1 1 1\n1 1 1 1\n1 1 1 1\n");
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed %s --source 0,0,0 --order 5 --out %s/c.vtk", path, dir);
    expect_failure(cmd, 1, "the grid has 4 nodes along x; order 5 needs at least 5: give --order 3");
    /* a map on a pipe: refused by name, not read as a malformed file */
    expect_failure("cat examples/data/speed.pgm | " P1 "eikonal --speed /dev/stdin --pgm-range 0,2 --source 1,1", 1,
                   "/dev/stdin is a pipe or a device, not a regular file");
    expect_failure("cat examples/data/wall.txt | " P1 "eikonal --speed-const 1 --obstacle /dev/stdin --source 1,1", 1,
                   "/dev/stdin is a pipe or a device, not a regular file");
    /* a polyline's two vertices at one point with different times */
    write_text(path, sizeof path, "line.txt", "0.2 0.5 0\n0.5 0.5 0.3\n0.5 0.5 1\n");
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed-const 1 --N 10 --polyline %s", path);
    expect_failure(cmd, 1, "line.txt: vertices 2 and 3 are at the same point with different times 0.3 and 1");
}

/* A run that succeeds says, on a terminal, what it wrote and where (with
 * its progress); off a terminal stderr stays empty.  The terminal is
 * script(1)'s pseudo-terminal (util-linux); without it that half is
 * skipped. */
static void eikonal_says_what_it_wrote(void **state)
{
    (void)state;
    char cmd[1024], path[256];
    snprintf(path, sizeof path, "%s/said.tsv", dir);
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed-const 1 --N 20 --domain 0,2,0,1 --source 0.5,0.5 --out %s", path);
    assert_int_equal(run(cmd), 0);
    assert_int_equal(lines(err_text), 0);
    if (run("command -v script >/dev/null") != 0) return;
    snprintf(cmd, sizeof cmd,
             "script -qec '" P1 "eikonal --speed-const 1 --N 20 --domain 0,2,0,1 --source 0.5,0.5 --out %s' /dev/null "
             "| tr '\\r' '\\n'", path);
    assert_int_equal(hj_test_shell(cmd, 1, err_text, sizeof err_text), 0);
    char want[512];
    snprintf(want, sizeof want, "eikonal: wrote T on 21 x 11 nodes (TSV) to %s", path);
    if (!strstr(err_text, want)) fail_msg("on a terminal: no '%s' in\n%s", want, err_text);
}

/* The output (x y T per line) of eikonal with the medium given by
 * `medium` on [-1, 1]^2, from a source at the origin: N intervals for a
 * constant medium, the map's nodes for a map. */
static FILE *run_eikonal(const char *medium, int N)
{
    char cmd[512], path[256];
    snprintf(path, sizeof path, "%s/phi.tsv", dir);
    char n_opt[32] = "";
    if (strstr(medium, "-const")) snprintf(n_opt, sizeof n_opt, "--N %d", N); /* a map's grid is its nodes */
    snprintf(cmd, sizeof cmd, P1 "eikonal %s --domain -1,1,-1,1 %s --source 0,0 --out %s", medium, n_opt, path);
    assert_int_equal(run(cmd), 0);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    return f;
}

/* phi at (1, 0) of a run with N = 40. */
static double time_at_edge(const char *medium)
{
    FILE *f = run_eikonal(medium, 40);
    char line[256];
    double x, y, p, at = NAN;
    while (fgets(line, sizeof line, f))
        if (sscanf(line, "%lf %lf %lf", &x, &y, &p) == 3 && fabs(x - 1) < 1e-12 && fabs(y) < 1e-12) at = p;
    fclose(f);
    return at;
}

/* A speed map means speed: a medium of speed 2 takes time 0.5 to the edge
 * at distance 1, of slowness 2 time 2 (once read as a slowness, the speed
 * file gave 2).  The maps are 3 x 3 nodes on [-1, 1]^2. */
static void speed_means_speed(void **state)
{
    (void)state;
    char path[256], medium[300];
    write_text(path, sizeof path, "two.txt", "2 2 2\n2 2 2\n2 2 2\n");
    snprintf(medium, sizeof medium, "--speed %s", path);
    assert_close(time_at_edge(medium), 0.5, 1e-9, 0);
    snprintf(medium, sizeof medium, "--slowness %s", path);
    assert_close(time_at_edge(medium), 2.0, 1e-9, 0);
    assert_close(time_at_edge("--speed-const 2"), 0.5, 0.01, 0);
    assert_close(time_at_edge("--slowness-const 2"), 2.0, 0.04, 0);
}

/* A map in pixel units (121 x 81 pixels, speed 2 everywhere) converges with
 * the default stopping rule, which scales with the problem; a run stopped
 * early (one iteration through a two-speed image) writes its last iterate,
 * says so, and exits 3. */
static void pixel_units_and_no_convergence(void **state)
{
    (void)state;
    char path[256], out[300], cmd[1024];
    static char text[121 * 81 * 4 + 64];
    int n = snprintf(text, sizeof text, "P2\n121 81\n255\n");
    for (int k = 0; k < 121 * 81; k++) n += snprintf(text + n, sizeof text - (size_t)n, "255%c", k % 121 == 120 ? '\n' : ' ');
    static char text2[121 * 81 * 4 + 64]; /* the same with a slow band (pixel 100) at x < 30 */
    memcpy(text2, text, sizeof text2);
    for (char *p = text2 + strlen("P2\n121 81\n255\n"), *row = p; *p; p++)
        if (*p == '\n') row = p + 1;
        else if (p - row < 4 * 30 && p[0] == '2' && p[1] == '5') p[0] = '1', p[1] = '0', p[2] = '0';
    write_text(path, sizeof path, "px.pgm", text);
    snprintf(out, sizeof out, "%s/px.tsv", dir);
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed %s --pgm-range 1,2 --source 10,20 --out %s", path, out);
    assert_int_equal(run(cmd), 0);
    FILE *f = fopen(out, "r");
    assert_non_null(f);
    char line[256];
    double x, y, p, at = NAN;
    while (fgets(line, sizeof line, f))
        if (sscanf(line, "%lf %lf %lf", &x, &y, &p) == 3 && x == 100 && y == 20) at = p;
    fclose(f);
    assert_close(at, 45, 1e-6, 0); /* distance 90 at speed 2 */
    write_text(path, sizeof path, "px2.pgm", text2);
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed %s --pgm-range 1,2 --source 10,20 --max-iter 1 --out %s", path, out);
    assert_int_equal(run(cmd), 3);
    assert_non_null(strstr(err_text, "the last iterate is written"));
    f = fopen(out, "r");
    assert_non_null(f);
    assert_non_null(fgets(line, sizeof line, f));
    fclose(f);
    assert_non_null(strstr(line, "not converged"));
}

/* Not converged: the warning gives the solver's reason, since the remedy
 * depends on it (a tol below the rounding level is not helped by more
 * iterations, a --max-iter too small is). */
static void no_convergence_says_why(void **state)
{
    (void)state;
    char path[256], out[300], cmd[1024];
    static char text[48 * 40 * 8 + 64];
    int n = 0;
    for (int j = 0; j < 40; j++)
        for (int i = 0; i < 48; i++)
            n += snprintf(text + n, sizeof text - (size_t)n, "%.4f%c", 1 + 0.5 * i / 47.0 + 0.3 * j / 39.0,
                          i == 47 ? '\n' : ' ');
    write_text(path, sizeof path, "lin.txt", text);
    snprintf(out, sizeof out, "%s/lin.tsv", dir);
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed %s --source 10.3,20.6 --tol 1e-17 --out %s", path, out);
    expect_failure(cmd, 3, "below the rounding level");
    assert_non_null(strstr(err_text, "the last iterate is written"));
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed %s --source 10.3,20.6 --max-iter 2 --out %s", path, out);
    expect_failure(cmd, 3, "no convergence in 2 iterations (last change");
    assert_null(strstr(err_text, "last iterate is kept")); /* said once, as "written" */
}

/* Max |T - r| over every node of an eikonal run with f = 1 and a source at
 * the origin on N intervals. */
static double distance_error(int N)
{
    FILE *f = run_eikonal("--speed-const 1", N);
    char line[256];
    double x, y, p, emax = 0;
    int n = 0;
    while (fgets(line, sizeof line, f))
        if (sscanf(line, "%lf %lf %lf", &x, &y, &p) == 3) {
            n++;
            if (fabs(p - hypot(x, y)) > emax) emax = fabs(p - hypot(x, y));
        }
    fclose(f);
    assert_int_equal(n, (N + 1) * (N + 1));
    return emax;
}

/* Uniform speed from a point: T is the distance.  The solver factors T =
 * r tau near a point source, and tau = 1 here, so T is exact to the 12
 * digits written at every order (an unfactored first order start left
 * 0.0055 at N = 40, 0.0027 at N = 80). */
static void eikonal_distance(void **state)
{
    (void)state;
    assert_true(distance_error(40) < 1e-9);
    assert_true(distance_error(80) < 1e-9);
}

/* The file's own coordinates are as precise as its T: the distance from
 * an off-node source recomputed from the x and y columns agrees with T
 * within the 12 digits of T, x and y (half a unit in the 12th digit of
 * each: 1e-11 at most here; 8.6e-12 measured) on a grid whose spacings
 * 2/37 and 1/19 do not print short (with 10-digit coordinates the
 * difference was 4.9e-10), and the
 * header's spacings are the grid's to 12 digits. */
static void eikonal_coordinates_precise(void **state)
{
    (void)state;
    char cmd[512], path[256], line[256];
    snprintf(path, sizeof path, "%s/dist.tsv", dir);
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed-const 1 --domain 0,2,0,1 --N 37 --source 0.713,0.291 --out %s", path);
    assert_int_equal(run(cmd), 0);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    double x, y, t, emax = 0, dx = 0, dy = 0;
    int n = 0;
    while (fgets(line, sizeof line, f)) {
        if (sscanf(line, "# grid %*d x %*d x %*d nodes, dx %lf %lf", &dx, &dy) == 2) continue;
        if (sscanf(line, "%lf %lf %lf", &x, &y, &t) == 3) {
            n++;
            emax = fmax(emax, fabs(t - hypot(x - 0.713, y - 0.291)));
        }
    }
    fclose(f);
    assert_int_equal(n, 38 * 20);
    if (!(emax < 2e-11)) fail_msg("max |T - |x - s|| from the file's columns %g", emax);
    if (!(fabs(dx - 2.0 / 37) < 1e-13 && fabs(dy - 1.0 / 19) < 1e-13)) fail_msg("header spacings %.17g %.17g", dx, dy);
}

/* T at the node nearest (x, y[, z]) in a TSV output of eikonal (x y [z] T
 * per line), NAN when no line matches. */
static double tsv_value(const char *path, int dim, double x, double y, double z)
{
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    char line[256];
    double v[4], at = NAN;
    while (fgets(line, sizeof line, f)) {
        if (line[0] == '#') continue;
        const int n = sscanf(line, "%lf %lf %lf %lf", &v[0], &v[1], &v[2], &v[3]);
        if (n == dim + 1 && fabs(v[0] - x) < 1e-9 && fabs(v[1] - y) < 1e-9 && (dim == 2 || fabs(v[2] - z) < 1e-9))
            at = v[dim];
    }
    fclose(f);
    return at;
}

/* What the tool offers beyond one source on a square grid: a wall that
 * the front goes around, dx != dy, a file of sources, a polyline, a 3-D
 * grid written as VTK. */
static void eikonal_features(void **state)
{
    (void)state;
    char path[256], out[300], cmd[1024];
    static char mask[41 * 41 * 2 + 64];
    size_t n = 0;
    for (int r = 0; r < 41; r++) /* first line = top row, y = 40 */
        for (int x = 0; x < 41; x++) {
            const int y = 40 - r;
            mask[n++] = x == 20 && !(y >= 30 && y <= 34) ? '1' : '0';
            mask[n++] = x == 40 ? '\n' : ' ';
        }
    mask[n] = '\0';
    write_text(path, sizeof path, "wall.txt", mask);
    snprintf(out, sizeof out, "%s/o.tsv", dir);
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed-const 1 --domain 0,40,0,40 --N 40 --obstacle %s --source 5,20 --out %s",
             path, out);
    assert_int_equal(run(cmd), 0);
    /* around the end of the wall: 2 hypot(15, 10) = 36.06, not the 30 straight through */
    const double around = 2 * hypot(15, 10), t = tsv_value(out, 2, 35, 20, 0);
    if (!(t > around - 0.5 && t < around + 1)) fail_msg("T(35, 20) = %g behind the wall, expected about %g", t, around);
    /* the README's wall example converges at every order (order 5 used to
     * stop after 1000 iterations, exit status 3) */
    for (int order = 1; order <= 5; order += 2) {
        snprintf(cmd, sizeof cmd, P1 "eikonal --speed-const 1 --domain 0,40,0,40 --N 40 --obstacle "
                 "examples/data/wall.txt --source 5,20 --order %d --out %s", order, out);
        if (run(cmd) != 0) fail_msg("README wall example, order %d: %s", order, err_text);
    }
    /* a late source is overtaken: the first front reaches (0.8, 0.8) at
     * 0.6 sqrt 2 < 2 */
    write_text(path, sizeof path, "late.txt", "0.2 0.2 0\n0.8 0.8 2\n");
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed-const 1 --N 20 --sources %s --out %s", path, out);
    assert_int_equal(run(cmd), 0);
    assert_close(tsv_value(out, 2, 0.8, 0.8, 0), 0.6 * sqrt(2), 1e-9, 0);
    /* dx = 1, dy = 0.25: a 3 x 5 map of slowness 1 on [0, 2] x [0, 1] */
    write_text(path, sizeof path, "rect.txt", "1 1 1\n1 1 1\n1 1 1\n1 1 1\n1 1 1\n");
    snprintf(cmd, sizeof cmd, P1 "eikonal --slowness %s --domain 0,2,0,1 --source 0,0 --out %s", path, out);
    assert_int_equal(run(cmd), 0);
    assert_close(tsv_value(out, 2, 2, 0, 0), 2, 1e-6, 0);
    assert_close(tsv_value(out, 2, 0, 1, 0), 1, 1e-6, 0);
    assert_close(tsv_value(out, 2, 0, 0.25, 0), 0.25, 1e-6, 0);
    /* two sources from a file, the second starting at time 0.5 */
    write_text(path, sizeof path, "src.txt", "# x y t0\n0.2 0.2\n0.8, 0.8, 0.5\n");
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed-const 1 --N 10 --sources %s --out %s", path, out);
    assert_int_equal(run(cmd), 0);
    assert_close(tsv_value(out, 2, 0.2, 0.2, 0), 0, 1e-9, 0);
    assert_close(tsv_value(out, 2, 0.8, 0.8, 0), 0.5, 1e-9, 0);
    assert_close(tsv_value(out, 2, 0.5, 0.5, 0), hypot(0.3, 0.3), 0.01, 0); /* from the first, sooner */
    /* a polyline at y = 0.5 with T = 0: a plane wave, T = |y - 0.5| */
    write_text(path, sizeof path, "line.txt", "0 0.5 0\n1 0.5 0\n");
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed-const 1 --N 10 --polyline %s --out %s", path, out);
    assert_int_equal(run(cmd), 0);
    assert_close(tsv_value(out, 2, 0.3, 0, 0), 0.5, 1e-6, 0);
    assert_close(tsv_value(out, 2, 0.7, 1, 0), 0.5, 1e-6, 0);
    /* 3-D: VTK by default, TSV on request */
    snprintf(out, sizeof out, "%s/o.vtk", dir);
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed-const 2 --domain 0,1,0,1,0,1 --N 8 --source 0,0,0 --out %s", out);
    assert_int_equal(run(cmd), 0);
    FILE *f = fopen(out, "r");
    assert_non_null(f);
    char text[512];
    const size_t got = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[got] = '\0';
    assert_non_null(strstr(text, "# vtk DataFile Version 3.0\n"));
    assert_non_null(strstr(text, "DIMENSIONS 9 9 9\nORIGIN 0 0 0\nSPACING 0.125 0.125 0.125\nPOINT_DATA 729\n"));
    snprintf(out, sizeof out, "%s/o3.tsv", dir);
    snprintf(cmd, sizeof cmd, P1 "eikonal --speed-const 2 --domain 0,1,0,1,0,1 --N 8 --source 0,0,0 --format tsv --out %s", out);
    assert_int_equal(run(cmd), 0);
    assert_close(tsv_value(out, 3, 1, 0, 0), 0.5, 1e-6, 0);
    assert_close(tsv_value(out, 3, 1, 1, 1), sqrt(3) / 2, 0.05, 0);
}

#if !defined(__SANITIZE_ADDRESS__)
/* Too little memory: one message, exit 1 (the address space is limited
 * with ulimit -v; AddressSanitizer cannot run under such a limit). */
static void out_of_memory(void **state)
{
    (void)state;
    expect_failure("ulimit -v 150000; exec " P1 "example1 --sizes 3000 --out-dir /tmp", 1, "out of memory");
    /* eikonal refuses, before it allocates, a grid whose solve needs more
     * than 0.8 of the machine's memory: a constant medium needs about 64
     * bytes a node (56 in the solver, 8 for T); a grid of 0.8 / 60 of the
     * memory in nodes is refused (the old estimate, 48 bytes, let it
     * start; the ulimit turns that into a quick "out of memory") */
    const double have = hj_sys_physical_memory();
    const double nodes = 0.8 * have / 60, N = floor(sqrt(nodes)) - 1;
    if (have <= 0 || N > 100000) return;
    char cmd[512];
    snprintf(cmd, sizeof cmd, "ulimit -v 2000000; exec " P1 "eikonal --speed-const 1 --N %.0f --source 0.5,0.5", N);
    expect_failure(cmd, 1, "more than this machine has");
}
#endif

/* Head waves (a source in a slow layer over a fast one, README): the
 * orthant passes stall and the header says after which iteration the
 * full sweeps took over, also with --separate-sources (it said nothing
 * there, though each source's solve had switched). */
static void eikonal_names_the_stall(void **state)
{
    (void)state;
    char path[256], out[256], cmd[1024], head[512] = "";
    snprintf(path, sizeof path, "%s/layers.txt", dir);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    for (int j = 199; j >= 0; j--) /* the first row is the top, y = 199 */
        for (int i = 0; i < 300; i++) fprintf(f, "%s%c", j > 99.5 ? "1" : "2", i == 299 ? '\n' : ' ');
    fclose(f);
    snprintf(out, sizeof out, "%s/layers.tsv", dir);
    for (int sep = 0; sep < 2; sep++) {
        snprintf(cmd, sizeof cmd,
                 "OMP_NUM_THREADS=1 " P1 "eikonal --speed %s --source 50.3,150.6 %s --order 3 --out %s", path,
                 sep ? "--source 200.3,150.6 --separate-sources" : "", out);
        assert_int_equal(run(cmd), 0);
        FILE *t = fopen(out, "r");
        assert_non_null(t);
        assert_non_null(fgets(head, sizeof head, t));
        fclose(t);
        if (!strstr(head, "full sweeps after iteration 72 (the orthant passes stalled)"))
            fail_msg("%s: header %s", sep ? "separate solves" : "one source", head);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(bad_options),      cmocka_unit_test(help_works),        cmocka_unit_test(unwritable_output_leaves_nothing),
        cmocka_unit_test(results_complete), cmocka_unit_test(eikonal_bad_files), cmocka_unit_test(eikonal_distance), cmocka_unit_test(speed_means_speed),
        cmocka_unit_test(pixel_units_and_no_convergence), cmocka_unit_test(no_convergence_says_why), cmocka_unit_test(eikonal_features),
        cmocka_unit_test(exclusion_distance_measures_more),
        cmocka_unit_test(eikonal_says_what_it_wrote),
        cmocka_unit_test(eikonal_coordinates_precise),
        cmocka_unit_test(eikonal_names_the_stall),
#if !defined(__SANITIZE_ADDRESS__)
        cmocka_unit_test(out_of_memory),
#endif
    };
    return cmocka_run_group_tests_name("paper1 command line", tests, hj_test_mkdir, hj_test_rmdir);
}
