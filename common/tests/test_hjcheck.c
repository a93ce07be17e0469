/* The accuracy-regression gate: hjcheck on small synthetic tables.  It must
 * fail when a cell becomes worse than its accepted verdict, skip rows a quick
 * run did not compute, never compare ambiguous cells, reject malformed
 * published tables, and merge a table's paper, exact and regression values
 * (reference/) into one, refusing a cell defined twice and a row that is
 * not the table's. */
#include "hj_test.h"

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#ifndef HJ_BIN_DIR
#error "HJ_BIN_DIR must name the directory of the built programs"
#endif
#define HJCHECK HJ_BIN_DIR "/common/tools/hjcheck"
#define dir hj_test_dir()

static char out_text[8192];

static void write_file(const char *rel, const char *text)
{
    char path[256];
    snprintf(path, sizeof path, "%s/%s", dir, rel);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

static int run_check(const char *flags)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "%s --results %s/res %s p=%s/paper", HJCHECK, dir, flags, dir);
    return hj_test_shell(cmd, 1, out_text, sizeof out_text);
}

/* hjcheck with flags exits with status and prints text. */
static void expect(const char *flags, int status, const char *text)
{
    assert_int_equal(run_check(flags), status);
    if (!strstr(out_text, text)) fail_msg("hjcheck %s: no '%s' in:\n%s", flags, text, out_text);
}

static const char *published =
    "# source: synthetic\n# key: N\n# kind: L1=error L1_order=order iter=count\n"
    "N\tL1\tL1_order\titer\n"
    "40\t1.00E-03\t-\t10\n"
    "80\t1.25E-04\t3.00\t?\n";

static int make_tree(void **state)
{
    if (hj_test_mkdir(state)) return -1;
    char path[256];
    snprintf(path, sizeof path, "%s/paper", dir);
    mkdir(path, 0777);
    snprintf(path, sizeof path, "%s/paper/published", dir);
    mkdir(path, 0777);
    snprintf(path, sizeof path, "%s/res", dir);
    mkdir(path, 0777);
    snprintf(path, sizeof path, "%s/res/p", dir);
    mkdir(path, 0777);
    /* a second paper in the reference layout */
    const char *ref_dirs[] = {"ref", "ref/reference", "ref/reference/paper", "ref/reference/exact",
                              "ref/reference/regression"};
    for (size_t i = 0; i < sizeof ref_dirs / sizeof *ref_dirs; i++) {
        snprintf(path, sizeof path, "%s/%s", dir, ref_dirs[i]);
        mkdir(path, 0777);
    }
    return 0;
}

static void all_match(void **state)
{
    (void)state;
    write_file("paper/published/t.tsv", published);
    write_file("res/p/t.tsv", "N\tL1\tL1_order\titer\textra\n40\t1.02e-3\t-\t10\t7\n80\t1.26e-4\t2.97\t12\t7\n");
    expect("", 0, "p t: 4 match, 0 close, 0 differ, 1 ambiguous");
    assert_non_null(strstr(out_text, "check: 4 passed, 0 failed"));
}

static void regression_fails(void **state)
{
    (void)state;
    write_file("paper/published/t.tsv", published);
    /* L1 at N=80 off by a factor 3: differs, and not accepted */
    write_file("res/p/t.tsv", "N\tL1\tL1_order\titer\n40\t1.0e-3\t-\t10\n80\t3.75e-4\t1.42\t12\n");
    expect("", 1, "check: 2 passed, 2 failed");
    /* --no-fail reports the same but exits 0 (the report uses it) */
    assert_int_equal(run_check("--no-fail"), 0);
    /* accepting the cells with a reason makes the gate pass */
    write_file("paper/reasons.tsv", "id\ttext\nsynthetic\ta synthetic reason\n");
    write_file("paper/accepted.tsv", "table\tkey\tquantity\tverdict\treason\n"
                                     "t\tN=80\tL1\tdiffers\tsynthetic\n"
                                     "t\tN=80\tL1_order\tdiffers\tsynthetic\n");
    assert_int_equal(run_check(""), 0);
    /* an accepted 'close' is exceeded by a 'differs' */
    write_file("paper/accepted.tsv", "table\tkey\tquantity\tverdict\treason\nt\tN=80\tL1\tclose\tsynthetic\n"
                                     "t\tN=80\tL1_order\tdiffers\tsynthetic\n");
    assert_int_equal(run_check(""), 1);
    remove(strcat(strcpy(out_text, dir), "/paper/accepted.tsv"));
}

static void missing_and_quick(void **state)
{
    (void)state;
    write_file("paper/published/t.tsv", published);
    write_file("res/p/t.tsv", "N\tL1\tL1_order\titer\n40\t1.0e-3\t-\t10\n");
    /* full mode: the N=80 row is missing and fails */
    expect("", 1, "2 missing");
    /* quick mode: the uncomputed row is skipped */
    expect("--quick", 0, "skipped (quick)");
    /* a non-finite computed value is never a match */
    write_file("res/p/t.tsv", "N\tL1\tL1_order\titer\n40\tnan\t-\t10\n80\t1.25e-4\t3.0\t10\n");
    assert_int_equal(run_check(""), 1);
}

/* CPU-time ratios are compared but never fail the gate. */
static void ratios_not_gated(void **state)
{
    (void)state;
    write_file("paper/published/t.tsv", "# key: N\n# kind: cpu_ratio=ratio\nN\tcpu_ratio\n80\t8.0\n");
    write_file("res/p/t.tsv", "N\tcpu_ratio\n80\t30\n");
    expect("", 0, "0 match, 0 close, 1 differ");
    assert_non_null(strstr(out_text, "check: 1 passed, 0 failed"));
    /* ... but a ratio that was not computed fails, unless accepted missing. */
    write_file("res/p/t.tsv", "N\tcpu_ratio\n80\t-\n");
    expect("", 1, "check: 0 passed, 1 failed");
    write_file("paper/reasons.tsv", "id\ttext\nslow\ttoo slow here\n");
    write_file("paper/accepted.tsv", "table\tkey\tquantity\tverdict\treason\nt\tN=80\tcpu_ratio\tmissing\tslow\n");
    assert_int_equal(run_check(""), 0);
    remove(strcat(strcpy(out_text, dir), "/paper/accepted.tsv"));
}

static void malformed_published(void **state)
{
    (void)state;
    write_file("paper/published/t.tsv", "# source: x\nN\tL1\n40\t1e-3\n");
    expect("", 2, "needs '# key:' and '# kind:'");
    write_file("paper/published/t.tsv", "# key: N\n# kind: L1=speed\nN\tL1\n40\t1e-3\n");
    assert_int_equal(run_check(""), 2);
    write_file("paper/published/t.tsv", "# key: N\n# kind: L1=error\nN\tL1\n40\t1e-3x\n");
    assert_int_equal(run_check(""), 2);
}

static char file_text[8192];

static const char *read_back(const char *rel)
{
    char path[256];
    snprintf(path, sizeof path, "%s/%s", dir, rel);
    FILE *f = fopen(path, "r");
    if (!f) return "";
    size_t n = fread(file_text, 1, sizeof file_text - 1, f);
    file_text[n] = '\0';
    fclose(f);
    return file_text;
}

static void remove_rel(const char *rel)
{
    char path[256];
    snprintf(path, sizeof path, "%s/%s", dir, rel);
    remove(path);
}

/* Blessing writes the table's current verdicts with one reason id; a cell
 * that matches again is dropped; an unknown id needs its text. */
/* A reason is shown whole in the check's notes, with the prefix of a
 * ratio past its accepted verdict or of a regression (reasons run to 900
 * characters). */
static void long_reason_whole(void **state)
{
    (void)state;
    char reason[1200], text[1400];
    memset(reason, 'r', 900);
    strcpy(reason + 900, " END");
    snprintf(text, sizeof text, "id\ttext\nlong\t%s\n", reason);
    write_file("paper/reasons.tsv", text);
    write_file("paper/published/t.tsv", "# key: N\n# kind: cpu_ratio=ratio L1=error\nN\tcpu_ratio\tL1\n80\t8.0\t1e-3\n");
    write_file("paper/accepted.tsv", "table\tkey\tquantity\tverdict\treason\nt\tN=80\tcpu_ratio\tclose\tlong\n"
                                     "t\tN=80\tL1\tclose\tlong\n");
    write_file("res/p/t.tsv", "N\tcpu_ratio\tL1\n80\t30\t1e-2\n");
    assert_int_equal(run_check(""), 1); /* L1 differs where close was accepted */
    const char *c = read_back("res/p/t.check.tsv");
    snprintf(text, sizeof text, "ratio, not gated (accepted close); %s\t", reason);
    assert_non_null(strstr(c, text));
    snprintf(text, sizeof text, "REGRESSION: accepted close; %s\t", reason);
    assert_non_null(strstr(c, text));
    remove_rel("paper/accepted.tsv");
}

static void accept_blesses(void **state)
{
    (void)state;
    write_file("paper/published/t.tsv", published);
    write_file("res/p/t.tsv", "N\tL1\tL1_order\titer\n40\t1.0e-3\t-\t10\n80\t3.75e-4\t1.42\t12\n");
    remove_rel("paper/reasons.tsv");
    assert_int_equal(run_check(""), 1);
    expect("--accept t --reason coarse", 2, "--reason-text");
    expect("--accept t --reason coarse --reason-text 'too coarse a grid'", 0, "2 cells accepted with reason 'coarse'");
    assert_non_null(strstr(read_back("paper/accepted.tsv"), "t\tN=80\tL1\tdiffers\tcoarse\n"));
    assert_non_null(strstr(read_back("paper/reasons.tsv"), "coarse\ttoo coarse a grid\n"));
    assert_int_equal(run_check(""), 0);
    /* the report's table shows the reason's text, not its id */
    assert_non_null(strstr(read_back("res/p/t.check.tsv"), "too coarse a grid"));
    /* fixed: blessing again drops the rows */
    write_file("res/p/t.tsv", "N\tL1\tL1_order\titer\n40\t1.0e-3\t-\t10\n80\t1.25e-4\t3.0\t10\n");
    assert_int_equal(run_check("--accept t --reason coarse"), 0);
    assert_null(strstr(read_back("paper/accepted.tsv"), "N=80"));
    /* another text for a known id is refused */
    assert_int_equal(run_check("--accept t --reason coarse --reason-text 'other'"), 2);
    remove_rel("paper/accepted.tsv");
    remove_rel("paper/reasons.tsv");
}

/* Blessing a table again keeps the reason of every cell whose verdict did
 * not change; the reason given goes to the cells whose verdict did. */
static void accept_keeps_unchanged_reasons(void **state)
{
    (void)state;
    write_file("paper/published/t.tsv", published);
    write_file("res/p/t.tsv", "N\tL1\tL1_order\titer\n40\t1.0e-3\t-\t10\n80\t3.75e-4\t1.42\t12\n");
    write_file("paper/reasons.tsv", "id\ttext\ncoarse\ttoo coarse a grid\nbetter\tnearer now\n");
    assert_int_equal(run_check("--accept t --reason coarse"), 0);
    /* L1 now close, its order still differs */
    write_file("res/p/t.tsv", "N\tL1\tL1_order\titer\n40\t1.0e-3\t-\t10\n80\t1.35e-4\t1.42\t12\n");
    expect("--accept t --reason better", 0, "1 cell accepted with reason 'better', 1 kept");
    const char *acc = read_back("paper/accepted.tsv");
    assert_non_null(strstr(acc, "t\tN=80\tL1\tclose\tbetter\n"));
    assert_non_null(strstr(acc, "t\tN=80\tL1_order\tdiffers\tcoarse\n"));
    assert_int_equal(run_check(""), 0);
    remove_rel("paper/accepted.tsv");
    remove_rel("paper/reasons.tsv");
}

/* accepted-quick.tsv excuses the quick run only. */
static void quick_only_exceptions(void **state)
{
    (void)state;
    write_file("paper/published/t.tsv", "# key: N\n# kind: cpu_ratio=ratio\nN\tcpu_ratio\n80\t8.0\n");
    write_file("res/p/t.tsv", "N\tcpu_ratio\n80\t-\n");
    write_file("paper/reasons.tsv", "id\ttext\nslow\ttoo slow for the quick run\n");
    write_file("paper/accepted-quick.tsv", "table\tkey\tquantity\tverdict\treason\nt\tN=80\tcpu_ratio\tmissing\tslow\n");
    assert_int_equal(run_check("--quick"), 0);
    assert_int_equal(run_check(""), 1);
    remove_rel("paper/accepted-quick.tsv");
    remove_rel("paper/reasons.tsv");
}

/* Blessing with --quick a cell that now matches where accepted.tsv
 * accepts it at a worse verdict writes it as a match into
 * accepted-quick.tsv: dropped, the full run's exception would apply to the
 * quick run again (a "better than accepted" note in every quick check). */
static void quick_accept_keeps_match_over_full(void **state)
{
    (void)state;
    write_file("paper/published/t.tsv", published);
    write_file("res/p/t.tsv", "N\tL1\tL1_order\titer\n40\t1.0e-3\t-\t10\n80\t1.25e-4\t3.0\t10\n");
    write_file("paper/reasons.tsv", "id\ttext\nfull\tthe full sizes' reason\n");
    write_file("paper/accepted.tsv", "table\tkey\tquantity\tverdict\treason\nt\tN=80\tL1\tclose\tfull\n");
    expect("--quick", 0, "better than accepted close");
    expect("--quick --accept t --reason qs --reason-text 'the quick sizes match'", 0, "1 cell accepted");
    assert_non_null(strstr(read_back("paper/accepted-quick.tsv"), "t\tN=80\tL1\tmatch\tqs\n"));
    assert_int_equal(run_check("--quick"), 0);
    assert_null(strstr(out_text, "better than accepted"));
    /* the full run's list is untouched */
    assert_non_null(strstr(read_back("paper/accepted.tsv"), "t\tN=80\tL1\tclose\tfull\n"));
    remove_rel("paper/accepted-quick.tsv");
    remove_rel("paper/accepted.tsv");
    remove_rel("paper/reasons.tsv");
}

/* Bad accepted lists, names and headers: one message, exit 2, no crash. */
static void bad_inputs(void **state)
{
    (void)state;
    write_file("paper/published/t.tsv", published);
    write_file("res/p/t.tsv", "N\tL1\tL1_order\titer\n40\t1.0e-3\t-\t10\n80\t1.25e-4\t3.0\t10\n");
    /* a reason id that reasons.tsv does not define */
    write_file("paper/accepted.tsv", "table\tkey\tquantity\tverdict\treason\nt\tN=80\tL1\tclose\tnowhere\n");
    expect("", 2, "not an id of reasons.tsv");
    remove_rel("paper/accepted.tsv");
    /* an accepted list that exists but cannot be read is not "absent" */
    char path[256];
    snprintf(path, sizeof path, "%s/paper/accepted.tsv", dir);
    assert_int_equal(mkdir(path, 0777), 0);
    assert_int_equal(run_check(""), 2);
    rmdir(path);
    /* a 300-character paper name is refused, not a crash */
    char cmd[1024], name[301];
    memset(name, 'n', 300), name[300] = '\0';
    snprintf(cmd, sizeof cmd, "%s --results %s/res %s=%s/paper", HJCHECK, dir, name, dir);
    assert_int_equal(hj_test_shell(cmd, 1, out_text, sizeof out_text), 2); /* longer than a file name may be */
    assert_non_null(strstr(out_text, "cannot create directory"));
    char longcmd[2048];
    snprintf(longcmd, sizeof longcmd, "%s --results %s/res %s%s%s%s=x", HJCHECK, dir, name, name, name, name);
    assert_int_equal(hj_test_shell(longcmd, 1, out_text, sizeof out_text), 2);
    /* more kind columns than the checker holds is an error, not a silent cut */
    char big[4096] = "# key: N\n# kind:";
    for (int i = 0; i < 70; i++) snprintf(big + strlen(big), sizeof big - strlen(big), " q%d=error", i);
    strcat(big, "\nN\tq0\n40\t1e-3\n");
    write_file("paper/published/t.tsv", big);
    assert_int_equal(run_check(""), 2);
    /* an unknown option and a missing value: one line each */
    assert_int_equal(run_check("--frobnicate"), 2);
    assert_null(strchr(strchr(out_text, '\n') ? strchr(out_text, '\n') + 1 : "", '\n'));
    snprintf(cmd, sizeof cmd, "%s --results", HJCHECK);
    assert_int_equal(hj_test_shell(cmd, 1, out_text, sizeof out_text), 2);
    assert_non_null(strstr(out_text, "--results needs a value"));
}

/* published/ holds paper values only: the old per-cell '# origin:' and
 * '# commit:' are refused, so no exact or regression value hides there. */
static void published_is_paper(void **state)
{
    (void)state;
    write_file("res/p/t.tsv", "N\tL1\tL1_order\titer\n40\t1.0e-3\t-\t10\n80\t1.25e-4\t3.0\t10\n");
    write_file("paper/published/t.tsv", "# key: N\n# kind: L1=error\nN\tL1\n40\t1.0e-3\n");
    assert_int_equal(run_check(""), 0);
    assert_non_null(strstr(read_back("res/p/t.check.tsv"), "N=40\tL1\terror\t1.0e-3\t0.001\t1\tmatch\tmatch\t\tpaper\n"));
    write_file("paper/published/t.tsv", "# key: N\n# kind: L1=error\n# origin: L1=exact\nN\tL1\n40\t1.0e-3\n");
    expect("", 2, "published/ holds paper values only");
    write_file("paper/published/t.tsv", "# key: N\n# kind: L1=error\n# commit: abc1234\nN\tL1\n40\t1.0e-3\n");
    expect("", 2, "published/ holds paper values only");
}

/* hjcheck on the reference-layout paper ref, as r. */
static int run_ref(const char *flags)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "%s --results %s/res %s r=%s/ref", HJCHECK, dir, flags, dir);
    return hj_test_shell(cmd, 1, out_text, sizeof out_text);
}

static void expect_ref(int status, const char *text)
{
    assert_int_equal(run_ref(""), status);
    if (!strstr(out_text, text)) fail_msg("hjcheck: no '%s' in:\n%s", text, out_text);
}

/* A consistent reference/ tree: the definition (rows 40 and 80), the
 * exact L1 (rows in another order), one paper and one regression count. */
static void write_reference(void)
{
    write_file("ref/reference/t.tsv", "# key: N\n# kind: L1=error iter=count\nN\n40\n80\n");
    write_file("ref/reference/exact/t.tsv", "# source: by hand\nN\tL1\n80\t1.25e-4\n40\t1.0e-3\n");
    write_file("ref/reference/paper/t.tsv", "# source: Table 1\nN\titer\n40\t10\n");
    write_file("ref/reference/regression/t.tsv", "# source: our run\n# commit: abc1234\nN\tL1\titer\n80\t-\t10\n");
    write_file("res/r/t.tsv", "N\tL1\titer\n40\t1.0e-3\t10\n80\t1.25e-4\t10\n");
}

/* Each cell's origin is its directory; rows come in the definition's order. */
static void reference_merged(void **state)
{
    (void)state;
    char path[256];
    snprintf(path, sizeof path, "%s/res/r", dir);
    mkdir(path, 0777);
    write_reference();
    expect_ref(0, "r t: 4 match, 0 close, 0 differ");
    const char *c = read_back("res/r/t.check.tsv");
    assert_non_null(strstr(c, "with "));
    assert_non_null(strstr(c, "/ref/reference/{paper,exact,regression}/t.tsv\n"));
    const char *l40 = strstr(c, "N=40\tL1\terror\t1.0e-3\t0.001\t1\tmatch\tmatch\t\texact\n");
    const char *i40 = strstr(c, "N=40\titer\tcount\t10\t10\t1\tmatch\tmatch\t\tpaper\n");
    const char *l80 = strstr(c, "N=80\tL1\terror\t1.25e-4\t0.000125\t1\tmatch\tmatch\t\texact\n");
    const char *i80 = strstr(c, "N=80\titer\tcount\t10\t10\t1\tmatch\tmatch\t\tregression@abc1234\n");
    assert_true(l40 && i40 && l80 && i80);
    assert_true(l40 < i40 && i40 < l80 && l80 < i80);
    /* blessing works on merged tables too */
    write_file("res/r/t.tsv", "N\tL1\titer\n40\t3.0e-3\t10\n80\t1.25e-4\t10\n");
    expect_ref(1, "check: 3 passed, 1 failed");
    assert_int_equal(run_ref("--accept t --reason coarse --reason-text 'too coarse'"), 0);
    assert_non_null(strstr(read_back("ref/accepted.tsv"), "t\tN=40\tL1\tdiffers\tcoarse\n"));
    expect_ref(0, "check: 4 passed, 0 failed");
    remove_rel("ref/accepted.tsv");
    remove_rel("ref/reasons.tsv");
}

/* A broken reference/ tree: one message naming the file, exit 2. */
static void reference_refused(void **state)
{
    (void)state;
    static const struct {
        const char *file, *text, *message;
    } cases[] = {
        /* a cell with a value in two files */
        {"ref/reference/paper/t.tsv", "# source: Table 1\nN\titer\n40\t10\n80\t12\n", "N=80): iter has a value in paper/ already"},
        /* a row that is not one of the definition's */
        {"ref/reference/exact/t.tsv", "# source: by hand\nN\tL1\n40\t1.0e-3\n160\t3e-5\n", "row 2 (N=160) is not a row of"},
        /* the same row twice in one file */
        {"ref/reference/exact/t.tsv", "# source: by hand\nN\tL1\n40\t1.0e-3\n40\t1.0e-3\n", "a cell is defined once"},
        /* a row of the definition that no file gives a value */
        {"ref/reference/t.tsv", "# key: N\n# kind: L1=error iter=count\nN\n40\n80\n160\n", "row 3 (N=160) has no value"},
        /* a row written twice in the definition */
        {"ref/reference/t.tsv", "# key: N\n# kind: L1=error iter=count\nN\n40\n80\n40\n", "row 3 (N=40) twice"},
        /* values in the definition */
        {"ref/reference/t.tsv", "# key: N\n# kind: L1=error\nN\tL1\n40\t1e-3\n", "are the '# key:' columns"},
        /* a '# kind:' column that no file gives a value */
        {"ref/reference/t.tsv", "# key: N\n# kind: L1=error iter=count L2=error\nN\n40\n80\n", "column 'L2' has no value"},
        /* a row of a values file without a value */
        {"ref/reference/paper/t.tsv", "# source: Table 1\nN\titer\n40\t10\n80\t-\n", "holds no value"},
        /* a column that the definition does not name */
        {"ref/reference/exact/t.tsv", "# source: by hand\nN\tL1\tLinf\n80\t1.25e-4\t1\n40\t1.0e-3\t1\n", "neither a key"},
        /* a values file without its key columns */
        {"ref/reference/exact/t.tsv", "# source: by hand\nL1\n1.0e-3\n", "key column 'N' missing"},
        /* no '# source:' */
        {"ref/reference/exact/t.tsv", "N\tL1\n80\t1.25e-4\n40\t1.0e-3\n", "needs '# source:'"},
        /* regression values without their commit, a commit elsewhere */
        {"ref/reference/regression/t.tsv", "# source: our run\nN\titer\n80\t10\n", "need '# commit:'"},
        {"ref/reference/exact/t.tsv", "# source: by hand\n# commit: abc1234\nN\tL1\n80\t1.25e-4\n40\t1.0e-3\n",
         "stamps regression values only"},
        /* header fields of the definition in a values file */
        {"ref/reference/exact/t.tsv", "# source: by hand\n# kind: L1=error\nN\tL1\n80\t1.25e-4\n40\t1.0e-3\n",
         "belong in"},
        /* unreadable-in-the-source is for paper values; numbers elsewhere */
        {"ref/reference/exact/t.tsv", "# source: by hand\nN\tL1\n80\t?\n40\t1.0e-3\n", "is for paper values only"},
        {"ref/reference/exact/t.tsv", "# source: by hand\nN\tL1\n80\t1.25e-4x\n40\t1.0e-3\n", "is not a number"},
        /* values of a table that has no definition */
        {"ref/reference/exact/u.tsv", "# source: by hand\nN\tL1\n40\t1.0e-3\n", "no table"},
        /* a paper with both layouts */
        {"ref/published/t.tsv", "# key: N\n# kind: L1=error\nN\tL1\n40\t1.0e-3\n", "has both"},
    };
    char path[256];
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        write_reference();
        if (!strncmp(cases[i].file, "ref/published/", 14)) {
            snprintf(path, sizeof path, "%s/ref/published", dir);
            mkdir(path, 0777);
        }
        write_file(cases[i].file, cases[i].text);
        assert_int_equal(run_ref(""), 2);
        if (!strstr(out_text, cases[i].message)) fail_msg("case %zu: no '%s' in:\n%s", i, cases[i].message, out_text);
        remove_rel("ref/reference/exact/u.tsv");
        remove_rel("ref/published/t.tsv");
        snprintf(path, sizeof path, "%s/ref/published", dir);
        rmdir(path);
    }
    /* a table without any values, and a paper with neither layout */
    write_reference();
    remove_rel("ref/reference/exact/t.tsv");
    remove_rel("ref/reference/paper/t.tsv");
    remove_rel("ref/reference/regression/t.tsv");
    expect_ref(2, "no values");
    assert_int_equal(run_check("--results /nonexistent"), 2);
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "%s --results %s/res q=%s/res", HJCHECK, dir, dir);
    assert_int_equal(hj_test_shell(cmd, 1, out_text, sizeof out_text), 2);
    assert_non_null(strstr(out_text, "has neither"));
    write_reference();
}

HJ_TEST_MAIN("hjcheck", make_tree, hj_test_rmdir, cmocka_unit_test(all_match), cmocka_unit_test(regression_fails),
             cmocka_unit_test(missing_and_quick), cmocka_unit_test(ratios_not_gated),
             cmocka_unit_test(malformed_published), cmocka_unit_test(accept_blesses),
             cmocka_unit_test(accept_keeps_unchanged_reasons), cmocka_unit_test(quick_only_exceptions), cmocka_unit_test(quick_accept_keeps_match_over_full), cmocka_unit_test(bad_inputs), cmocka_unit_test(published_is_paper),
             cmocka_unit_test(reference_merged), cmocka_unit_test(reference_refused),
             cmocka_unit_test(long_reason_whole))
