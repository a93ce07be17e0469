/* Unit tests of common/hj_io (atomic output, TSV tables) and hj_cli parsing. */
#define _XOPEN_SOURCE 700 /* mknod, S_IFCHR */
#include "hj_test.h"

#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "hj_cli.h"
#include "hj_io.h"

#define dir hj_test_dir()

static void atomic_write_and_read_back(void **state)
{
    (void)state;
    char path[128];
    snprintf(path, sizeof path, "%s/t.tsv", dir);
    hj_out out;
    hj_error err;
    assert_int_equal(hj_out_open(&out, path, &err), HJ_OK);
    fprintf(out.fp, "# source: test\n# key: N\nN\tL1\n40\t1e-3\n80\t2.5e-4\n");
    assert_int_not_equal(access(path, F_OK), 0); /* not visible before commit */
    assert_int_equal(hj_out_commit(&out, &err), HJ_OK);
    hj_table t;
    assert_int_equal(hj_table_read(&t, path, &err), HJ_OK);
    assert_int_equal(t.ncols, 2);
    assert_int_equal(t.nrows, 2);
    assert_string_equal(t.cells[1][1], "2.5e-4");
    assert_int_equal(hj_table_col(&t, "L1"), 1);
    assert_int_equal(hj_table_col(&t, "Linf"), -1);
    assert_string_equal(hj_table_meta(&t, "source"), "test");
    assert_string_equal(hj_table_meta(&t, "key"), "N");
    hj_table_free(&t);
}

static void abort_leaves_nothing(void **state)
{
    (void)state;
    char path[128];
    snprintf(path, sizeof path, "%s/aborted.tsv", dir);
    hj_out out;
    assert_int_equal(hj_out_open(&out, path, NULL), HJ_OK);
    fprintf(out.fp, "half a table");
    hj_out_abort(&out);
    assert_int_not_equal(access(path, F_OK), 0);
}

static void malformed_tables(void **state)
{
    (void)state;
    char path[128];
    hj_error err;
    hj_table t;
    snprintf(path, sizeof path, "%s/bad.tsv", dir);
    FILE *f = fopen(path, "w");
    fprintf(f, "a\tb\n1\t2\n3\n");
    fclose(f);
    assert_int_equal(hj_table_read(&t, path, &err), HJ_EFORMAT);
    assert_non_null(strstr(err.msg, ":3:"));
    f = fopen(path, "w");
    fprintf(f, "# only comments\n");
    fclose(f);
    assert_int_equal(hj_table_read(&t, path, &err), HJ_EFORMAT);
    /* A NUL byte (a binary file) is refused; it used to end the line
     * there, and "1<NUL>9<TAB>2" was read as the one cell "1". */
    f = fopen(path, "w");
    fwrite("a\n1\0009\t2\n", 1, 9, f);
    fclose(f);
    assert_int_equal(hj_table_read(&t, path, &err), HJ_EFORMAT);
    assert_non_null(strstr(err.msg, ":2: a NUL byte"));
    snprintf(path, sizeof path, "%s/none.tsv", dir);
    assert_int_equal(hj_table_read(&t, path, &err), HJ_EIO);
    /* a directory says so (it was a bare "error reading") */
    assert_int_equal(hj_table_read(&t, dir, &err), HJ_EIO);
    assert_non_null(strstr(err.msg, "cannot read"));
    assert_non_null(strstr(err.msg, ": Is a directory"));
}

static void unwritable_output(void **state)
{
    (void)state;
    hj_out out;
    hj_error err;
    assert_int_equal(hj_out_open(&out, "/nonexistent-dir/x.tsv", &err), HJ_EIO);
    assert_non_null(strstr(err.msg, "/nonexistent-dir/x.tsv"));
}

/* Only regular files are ever replaced: a FIFO, a symbolic link, a device
 * node and a directory under the output name are refused, before anything
 * is written, and left as they were. */
static void only_regular_files_replaced(void **state)
{
    (void)state;
    hj_out out;
    hj_error err;
    char path[256], target[256];
    snprintf(path, sizeof path, "%s/fifo.tsv", hj_test_dir());
    assert_int_equal(mkfifo(path, 0666), 0);
    assert_int_equal(hj_out_open(&out, path, &err), HJ_EIO);
    assert_non_null(strstr(err.msg, "not a regular file"));
    struct stat st;
    assert_int_equal(lstat(path, &st), 0);
    assert_true(S_ISFIFO(st.st_mode));

    snprintf(target, sizeof target, "%s/target.tsv", hj_test_dir());
    FILE *f = fopen(target, "w");
    assert_non_null(f);
    fputs("kept\n", f);
    fclose(f);
    snprintf(path, sizeof path, "%s/link.tsv", hj_test_dir());
    assert_int_equal(symlink(target, path), 0);
    assert_int_equal(hj_out_check(path, &err), HJ_EIO);
    assert_int_equal(hj_out_open(&out, path, &err), HJ_EIO);
    assert_int_equal(lstat(path, &st), 0);
    assert_true(S_ISLNK(st.st_mode));

    snprintf(path, sizeof path, "%s/adir", hj_test_dir());
    assert_int_equal(mkdir(path, 0777), 0);
    assert_int_equal(hj_out_open(&out, path, &err), HJ_EIO);

    /* a copy of the null device (needs root to make; skipped otherwise) */
    snprintf(path, sizeof path, "%s/null", hj_test_dir());
    if (stat("/dev/null", &st) == 0 && mknod(path, S_IFCHR | 0666, st.st_rdev) == 0) {
        assert_int_equal(hj_out_open(&out, path, &err), HJ_EIO);
        assert_int_equal(lstat(path, &st), 0);
        assert_true(S_ISCHR(st.st_mode));
    }

    /* a regular file is replaced, and nothing else is left */
    assert_int_equal(hj_out_open(&out, target, &err), HJ_OK);
    fputs("new\n", out.fp);
    assert_int_equal(hj_out_commit(&out, &err), HJ_OK);
    f = fopen(target, "r");
    char line[16] = "";
    assert_non_null(fgets(line, sizeof line, f));
    fclose(f);
    assert_string_equal(line, "new\n");
}

/* path = the test directory / name. */
static void test_path(char *path, size_t n, const char *name) { snprintf(path, n, "%s/%s", hj_test_dir(), name); }

/* A killed run's "<path>.tmp.<pid>" is removed by the next open of path;
 * a signal removes the temporary files of the process it stops. */
static void temporaries_removed(void **state)
{
    (void)state;
    hj_out out;
    hj_error err;
    char path[256], stale[300];
    test_path(path, sizeof path, "interrupted.tsv");
    pid_t child = fork();
    assert_true(child >= 0);
    if (child == 0) _exit(0);
    waitpid(child, NULL, 0); /* a pid that no longer exists */
    snprintf(stale, sizeof stale, "%s.tmp.%ld", path, (long)child);
    FILE *f = fopen(stale, "w");
    assert_non_null(f);
    fclose(f);
    assert_int_equal(hj_out_open(&out, path, &err), HJ_OK);
    assert_int_not_equal(access(stale, F_OK), 0);
    hj_out_abort(&out);

    child = fork();
    assert_true(child >= 0);
    if (child == 0) {
        hj_out_remove_on_signal();
        if (hj_out_open(&out, path, NULL)) _exit(3);
        raise(SIGTERM);
        _exit(4);
    }
    int status = 0;
    waitpid(child, &status, 0);
    assert_true(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
    snprintf(stale, sizeof stale, "%s.tmp.%ld", path, (long)child);
    assert_int_not_equal(access(stale, F_OK), 0);
    assert_int_not_equal(access(path, F_OK), 0);
    /* A signal ignored before (nohup) stays ignored. */
    child = fork();
    assert_true(child >= 0);
    if (child == 0) {
        signal(SIGHUP, SIG_IGN);
        hj_out_remove_on_signal();
        if (hj_out_open(&out, path, NULL)) _exit(3);
        raise(SIGHUP);
        hj_out_abort(&out);
        _exit(5);
    }
    waitpid(child, &status, 0);
    assert_true(WIFEXITED(status) && WEXITSTATUS(status) == 5);
}

/* An empty name is an error (it used to read past the buffer); a file in
 * the way of a directory is named. */
static void mkdirs_edges(void **state)
{
    (void)state;
    hj_error err;
    char path[256];
    assert_int_equal(hj_mkdirs("", &err), HJ_EINVAL);
    snprintf(path, sizeof path, "%s/a/b/c", hj_test_dir());
    assert_int_equal(hj_mkdirs(path, &err), HJ_OK);
    assert_int_equal(hj_mkdirs(path, &err), HJ_OK);
    snprintf(path, sizeof path, "%s/plain", hj_test_dir());
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fclose(f);
    snprintf(path, sizeof path, "%s/plain/sub", hj_test_dir());
    assert_int_equal(hj_mkdirs(path, &err), HJ_EIO);
    assert_non_null(strstr(err.msg, "plain"));
}

static void cli_parsing(void **state)
{
    (void)state;
    long v, list[4];
    double d;
    int n;
    hj_error err;
    assert_int_equal(hj_parse_long("640", "N", 8, 20000, &v, &err), HJ_OK);
    assert_int_equal(v, 640);
    assert_int_equal(hj_parse_long("0", "N", 8, 20000, &v, &err), HJ_EINVAL);
    assert_int_equal(hj_parse_long("-5", "N", 8, 20000, &v, &err), HJ_EINVAL);
    assert_int_equal(hj_parse_long("12x", "N", 8, 20000, &v, &err), HJ_EINVAL);
    assert_int_equal(hj_parse_long("99999999999999999999", "N", 8, 20000, &v, &err), HJ_EINVAL);
    assert_int_equal(hj_parse_double("1e-11", "delta", 0, 1, &d, &err), HJ_OK);
    assert_int_equal(hj_parse_double("nan", "delta", 0, 1, &d, &err), HJ_ENONFINITE);
    assert_int_equal(hj_parse_double("inf", "delta", 0, 1, &d, &err), HJ_ENONFINITE);
    assert_int_equal(hj_parse_long_list("40,80,160", "sizes", 8, 20000, list, 4, &n, &err), HJ_OK);
    assert_int_equal(n, 3);
    assert_int_equal(list[2], 160);
    assert_int_equal(hj_parse_long_list("40,,80", "sizes", 8, 20000, list, 4, &n, &err), HJ_EINVAL);
    assert_int_equal(hj_parse_long_list("8,8,8,8,8", "sizes", 8, 20000, list, 4, &n, &err), HJ_EINVAL);
}

HJ_TEST_MAIN("hj_io", hj_test_mkdir, hj_test_rmdir, cmocka_unit_test(atomic_write_and_read_back),
             cmocka_unit_test(abort_leaves_nothing), cmocka_unit_test(malformed_tables),
             cmocka_unit_test(unwritable_output), cmocka_unit_test(cli_parsing),
             cmocka_unit_test(only_regular_files_replaced), cmocka_unit_test(temporaries_removed),
             cmocka_unit_test(mkdirs_edges))
