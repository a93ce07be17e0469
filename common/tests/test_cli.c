/* hj_cli: the declarative option table.  Every value type, its range, the
 * messages for unknown, repeated and incomplete options, the one option
 * type that may be repeated, and --help built from the table with the
 * defaults. */
#include "hj_test.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "hj_cli.h"
#include "hj_io.h"

static long N;
static double cfl, eps;
static const char *out;
static long sizes[4];
static int nsizes, quick, scheme;
static const char *points[3];
static int npoints;
static const char *const schemes[] = {"eno2", "weno5", NULL};
static hj_cli_opt opts[] = {
    {.name = "--N", .type = HJ_OPT_LONG, .value = &N, .min = 2, .max = 1000, .metavar = "N", .help = "nodes per dimension"},
    {.name = "--cfl", .type = HJ_OPT_DOUBLE, .value = &cfl, .min = 0.01, .max = 1, .metavar = "C", .help = "CFL factor"},
    {.name = "--out", .type = HJ_OPT_STRING, .value = &out, .metavar = "FILE", .help = "output file"},
    {.name = "--sizes", .type = HJ_OPT_LONG_LIST, .value = sizes, .min = 8, .max = 100, .metavar = "N,N,...",
     .help = "grid sizes", .count = &nsizes, .maxn = 4},
    {.name = "--quick", .type = HJ_OPT_FLAG, .value = &quick, .help = "coarse rows only"},
    {.name = "--scheme", .type = HJ_OPT_CHOICE, .value = &scheme, .metavar = "S", .help = "upwind scheme", .choices = schemes},
    {.name = "--eps", .type = HJ_OPT_DOUBLE, .value = &eps, .min = 0, .max = 1, .metavar = "X", .help = "epsilon",
     .dflt = "the paper's"},
    {.name = "--point", .type = HJ_OPT_STRING_LIST, .value = points, .metavar = "X,Y", .help = "a point",
     .count = &npoints, .maxn = 3},
};
static hj_cli_spec spec = {.prog = "prog", .summary = "A test program.", .opts = opts,
                           .nopts = (int)(sizeof opts / sizeof opts[0]), .epilog = "Tables: see the source.\n"};

static void defaults(void)
{
    N = 101, cfl = 0.5, out = "phi.tsv", nsizes = 2, sizes[0] = 10, sizes[1] = 20, quick = 0, scheme = 1;
    npoints = 1, points[0] = "0,0";
}

static hj_error err;
static int help;

/* Parse line, a space-separated string of at most 16 words, from the
 * defaults into the variables, help and err. */
static int parse(const char *line)
{
    static char buf[512];
    char *argv[17] = {"prog"};
    int argc = 1;
    snprintf(buf, sizeof buf, "%s", line);
    for (char *w = strtok(buf, " "); w && argc < 16; w = strtok(NULL, " ")) argv[argc++] = w;
    defaults();
    return hj_cli_parse(&spec, argc, argv, &help, &err);
}

static void values_and_defaults(void **state)
{
    (void)state;
    assert_int_equal(parse(""), HJ_OK);
    assert_int_equal(N, 101);
    assert_int_equal(help, 0);
    assert_int_equal(parse("--N 40 --cfl 0.9 --out x.tsv --sizes 8,16,32 --quick --scheme eno2"), HJ_OK);
    assert_int_equal(N, 40);
    assert_close(cfl, 0.9, 0, 1e-15);
    assert_string_equal(out, "x.tsv");
    assert_int_equal(nsizes, 3);
    assert_int_equal(sizes[2], 32);
    assert_int_equal(quick, 1);
    assert_int_equal(scheme, 0);
    assert_int_equal(opts[0].seen, 1);
}

static void bad_values(void **state)
{
    (void)state;
    const char *bad[] = {"--N 1", "--N 1001", "--N 12abc", "--N ''", "--cfl nan", "--cfl inf", "--cfl 0",
                         "--sizes 8,,16", "--sizes 8,16,32,64,100", "--sizes 4", "--scheme weno7", "--N"};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        assert_int_not_equal(parse(bad[k]), HJ_OK);
        assert_true(strlen(err.msg) > 0);
    }
    assert_int_equal(parse("--frob 3"), HJ_EINVAL);
    assert_non_null(strstr(err.msg, "unknown option '--frob'"));
    assert_int_equal(parse("stray"), HJ_EINVAL);
    assert_non_null(strstr(err.msg, "unexpected argument"));
    assert_int_equal(parse("--N 5 --N 6"), HJ_EINVAL);
    assert_non_null(strstr(err.msg, "given twice"));
    assert_int_equal(parse("--scheme weno7"), HJ_EINVAL);
    assert_non_null(strstr(err.msg, "eno2, weno5"));
    assert_int_equal(parse("--out"), HJ_EINVAL);
    assert_non_null(strstr(err.msg, "--out needs a value"));
}

/* A STRING_LIST collects one value per occurrence, in order; the first
 * occurrence replaces the defaults; empty values and more than maxn
 * occurrences are refused. */
static void repeated_list(void **state)
{
    (void)state;
    assert_int_equal(parse("--N 40"), HJ_OK);
    assert_int_equal(npoints, 1);
    assert_string_equal(points[0], "0,0");
    assert_int_equal(opts[7].seen, 0);
    assert_int_equal(parse("--point 1,2 --N 40 --point 3,4,5"), HJ_OK);
    assert_int_equal(npoints, 2);
    assert_string_equal(points[0], "1,2");
    assert_string_equal(points[1], "3,4,5");
    assert_int_equal(opts[7].seen, 1);
    assert_int_equal(parse("--point a --point b --point c"), HJ_OK);
    assert_int_equal(npoints, 3);
    assert_string_equal(points[2], "c");
    assert_int_equal(parse("--point a --point b --point c --point d"), HJ_EINVAL);
    assert_string_equal(err.msg, "--point is given more than 3 times");
    assert_int_equal(parse("--point a --point"), HJ_EINVAL);
    assert_string_equal(err.msg, "--point needs a value");
    char *argv[] = {"prog", "--point", "1,2", "--point", ""};
    defaults();
    assert_int_equal(hj_cli_parse(&spec, 5, argv, &help, &err), HJ_EINVAL);
    assert_string_equal(err.msg, "--point needs a non-empty value");
    /* the other types stay single */
    assert_int_equal(parse("--point a --out x --point b --out y"), HJ_EINVAL);
    assert_string_equal(err.msg, "--out is given twice");
}

static void help_lists_every_option(void **state)
{
    (void)state;
    assert_int_equal(parse("--N 7 --help --frob"), HJ_OK);
    assert_int_equal(help, 1);
    char text[4096] = "";
    FILE *f = fmemopen(text, sizeof text - 1, "w");
    assert_non_null(f);
    hj_cli_help(&spec, f);
    fclose(f);
    assert_non_null(strstr(text, "usage: prog [options]"));
    assert_non_null(strstr(text, "--N N"));
    assert_non_null(strstr(text, "[2..1000] (default 7)"));
    assert_non_null(strstr(text, "(default 0.5)"));
    assert_non_null(strstr(text, "(default 10,20)"));
    assert_non_null(strstr(text, "{eno2|weno5} (default weno5)"));
    assert_non_null(strstr(text, "--help"));
    assert_non_null(strstr(text, "epsilon [0..1] (default the paper's)"));
    assert_non_null(strstr(text, "Tables: see the source."));
    assert_non_null(strstr(text, "--point X,Y"));
    assert_non_null(strstr(text, "a point [repeatable, at most 3] (default 0,0)"));
}

/* --list-options: the table as TSV for the bad-input drivers, bounds
 * exact, one line per option in table order. */
static void list_options_as_tsv(void **state)
{
    (void)state;
    assert_int_equal(parse("--N 7 --list-options --frob"), HJ_OK);
    assert_int_equal(help, HJ_CLI_LIST);
    assert_int_equal(parse("--help"), HJ_OK);
    assert_int_equal(help, HJ_CLI_HELP);
    char text[4096] = "";
    FILE *f = fmemopen(text, sizeof text - 1, "w");
    assert_non_null(f);
    hj_cli_list(&spec, f);
    fclose(f);
    assert_string_equal(text, "name\ttype\tmin\tmax\tchoices\tmaxn\n"
                              "--N\tlong\t2\t1000\t-\t-\n"
                              "--cfl\tdouble\t0.01\t1\t-\t-\n"
                              "--out\tstring\t-\t-\t-\t-\n"
                              "--sizes\tlong-list\t8\t100\t-\t4\n"
                              "--quick\tflag\t-\t-\t-\t-\n"
                              "--scheme\tchoice\t-\t-\teno2,weno5\t-\n"
                              "--eps\tdouble\t0\t1\t-\t-\n"
                              "--point\tstring-list\t-\t-\t-\t3\n");
}

/* hj_cli_fail: one line whatever the message quotes (it used to print a
 * newline or an escape sequence typed on the command line as it was). */
static void fail_prints_one_line(void **state)
{
    (void)state;
    char path[] = "/tmp/hj_test_cli.XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    fflush(stderr);
    pid_t child = fork();
    assert_true(child >= 0);
    if (child == 0) {
        dup2(fd, STDERR_FILENO);
        hj_cli_fail("prog", HJ_EXIT_USAGE, "--N: '%s' is not an integer", "1\n2\033[0m\t\x7f");
    }
    int status = 0;
    waitpid(child, &status, 0);
    assert_true(WIFEXITED(status) && WEXITSTATUS(status) == HJ_EXIT_USAGE);
    char text[256] = "";
    ssize_t n = pread(fd, text, sizeof text - 1, 0);
    close(fd);
    unlink(path);
    assert_true(n > 0);
    assert_string_equal(text, "prog: --N: '1\\n2\\x1b[0m\\x09\\x7f' is not an integer\n");
}

/* hj_cli_fail removes the temporaries of outputs still open: a program
 * that committed one output and failed on the next left the others. */
static void fail_removes_open_temporaries(void **state)
{
    (void)state;
    char dir[] = "/tmp/hj_test_cli.XXXXXX", path[64], path2[64];
    assert_non_null(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/out.tsv", dir);
    snprintf(path2, sizeof path2, "%s/out2.tsv", dir);
    fflush(stderr);
    pid_t child = fork();
    assert_true(child >= 0);
    if (child == 0) {
        hj_out a, b;
        if (hj_out_open(&a, path, NULL) || hj_out_open(&b, path2, NULL)) _exit(3);
        fputs("x\n", a.fp);
        if (!freopen("/dev/null", "w", stderr)) _exit(4);
        hj_cli_fail("prog", HJ_EXIT_RUN, "error writing %s", path);
    }
    int status = 0;
    waitpid(child, &status, 0);
    assert_true(WIFEXITED(status) && WEXITSTATUS(status) == HJ_EXIT_RUN);
    assert_int_equal(rmdir(dir), 0); /* no temporary left in it */
}

/* --help into stdout that cannot be written (/dev/full): one message and
 * HJ_EXIT_RUN; it used to exit 0 with the text lost. */
static int run_help_into(const char *path, char *text, size_t n)
{
    char errpath[] = "/tmp/hj_test_cli.XXXXXX";
    int efd = mkstemp(errpath);
    assert_true(efd >= 0);
    unlink(errpath);
    fflush(stdout), fflush(stderr);
    pid_t child = fork();
    assert_true(child >= 0);
    if (child == 0) {
        int ofd = open(path, O_WRONLY);
        if (ofd < 0) _exit(5);
        dup2(ofd, STDOUT_FILENO), dup2(efd, STDERR_FILENO);
        char *argv[] = {"prog", "--help", NULL};
        hj_cli_parse_or_exit(&spec, 2, argv);
        _exit(6);
    }
    int status = 0;
    waitpid(child, &status, 0);
    ssize_t got = pread(efd, text, n - 1, 0);
    text[got > 0 ? got : 0] = '\0';
    close(efd);
    assert_true(WIFEXITED(status));
    return WEXITSTATUS(status);
}

static void help_write_error_fails(void **state)
{
    (void)state;
    char text[256];
    if (access("/dev/full", W_OK)) skip();
    assert_int_equal(run_help_into("/dev/full", text, sizeof text), HJ_EXIT_RUN);
    assert_string_equal(text, "prog: error writing stdout: No space left on device\n");
    assert_int_equal(run_help_into("/dev/null", text, sizeof text), 0);
    assert_string_equal(text, "");
}

HJ_TEST_MAIN("cli", NULL, NULL, cmocka_unit_test(values_and_defaults), cmocka_unit_test(bad_values),
             cmocka_unit_test(repeated_list), cmocka_unit_test(help_lists_every_option),
             cmocka_unit_test(list_options_as_tsv), cmocka_unit_test(fail_prints_one_line),
             cmocka_unit_test(fail_removes_open_temporaries),
             cmocka_unit_test(help_write_error_fails))
