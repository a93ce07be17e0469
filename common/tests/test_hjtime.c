/* hjtime, the run-time recorder of make reproduce: it passes the command's
 * exit status through, writes its one-row table only when the command
 * succeeded (removing an older one otherwise), and rejects bad usage. */
#include "hj_test.h"

#include <sys/stat.h>
#include <unistd.h>

#ifndef HJ_BIN_DIR
#error "HJ_BIN_DIR must name the directory of the built programs"
#endif
#define HJTIME HJ_BIN_DIR "/common/tools/hjtime"
#define dir hj_test_dir()

static char out_text[4096];

static int run(const char *args)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "%s %s", HJTIME, args);
    return hj_test_shell(cmd, 1, out_text, sizeof out_text);
}

static int exists(const char *rel)
{
    char path[256];
    snprintf(path, sizeof path, "%s/%s", dir, rel);
    return access(path, F_OK) == 0;
}

static void success_writes_row(void **state)
{
    (void)state;
    char args[512], path[256];
    snprintf(args, sizeof args, "%s/sub/time/t.tsv demo -- sh -c 'echo hello'", dir);
    assert_int_equal(run(args), 0);
    assert_non_null(strstr(out_text, "hello")); /* output passes through */
    snprintf(path, sizeof path, "%s/sub/time/t.tsv", dir);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    char head[128], label[64];
    double wall, cpu, mb;
    assert_non_null(fgets(head, sizeof head, f));
    assert_string_equal(head, "label\twall_s\tcpu_s\tpeak_mb\n");
    assert_int_equal(fscanf(f, "%63s %lf %lf %lf", label, &wall, &cpu, &mb), 4);
    fclose(f);
    assert_string_equal(label, "demo");
    assert_true(wall >= 0 && wall < 60 && cpu >= 0 && mb > 0);
}

static void failure_leaves_no_table(void **state)
{
    (void)state;
    char args[512];
    snprintf(args, sizeof args, "%s/sub/time/t.tsv demo -- sh -c 'exit 3'", dir);
    assert_int_equal(run(args), 3); /* the command's status */
    assert_false(exists("sub/time/t.tsv")); /* the older table is gone */
    snprintf(args, sizeof args, "%s/x.tsv demo -- /nonexistent/program", dir);
    assert_int_equal(run(args), 127);
    assert_false(exists("x.tsv"));
}

static void bad_usage(void **state)
{
    (void)state;
    assert_int_equal(run("only-two args"), 2);
    assert_int_equal(run("out.tsv label true"), 2); /* no "--" */
    assert_non_null(strstr(out_text, "usage"));
}

/* A FIFO (or link, device, directory) under OUT.tsv is refused before the
 * command runs, and left as it was (it used to be removed and replaced). */
static void special_file_kept(void **state)
{
    (void)state;
    char args[512], fifo[256];
    snprintf(fifo, sizeof fifo, "%s/fifo.tsv", dir);
    assert_int_equal(mkfifo(fifo, 0600), 0);
    snprintf(args, sizeof args, "%s demo -- touch %s/ran", fifo, dir);
    assert_int_equal(run(args), 2);
    assert_non_null(strstr(out_text, "not a regular file"));
    struct stat st;
    assert_int_equal(lstat(fifo, &st), 0);
    assert_true(S_ISFIFO(st.st_mode));
    assert_false(exists("ran"));
}

HJ_TEST_MAIN("hjtime", hj_test_mkdir, hj_test_rmdir, cmocka_unit_test(success_writes_row),
             cmocka_unit_test(failure_leaves_no_table), cmocka_unit_test(bad_usage), cmocka_unit_test(special_file_kept))
