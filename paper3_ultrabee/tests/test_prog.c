/* Unit tests of p3_prog's rule for the timing tables (p3_pub_has,
 * p3_rule_decide, p3_rule_listed): the published files say which cells
 * the paper has a value for, as the tables storage.c restated before; the
 * rule decides as storage's affordable() and hjbstep's inline test did,
 * for the same recorded times.  The two former rules are kept here, as
 * they were, to be compared with. */
#include "hj_test.h"

#include <stdlib.h>

#include "p3_prog.h"

static const char *const PUBDIR = "paper3_ultrabee/published";

/* ---- which cells are published ------------------------------------------ */

static const hj_band_kind SEARCH_KINDS[7] = {HJ_BAND_FS, HJ_BAND_FLS, HJ_BAND_LS, HJ_BAND_CRS, HJ_BAND_SSD, HJ_BAND_SSDC, HJ_BAND_SSDA};
static const hj_band_kind UPDATE_KINDS[6] = {HJ_BAND_FLS, HJ_BAND_LS, HJ_BAND_CRS, HJ_BAND_SSD, HJ_BAND_SSDC, HJ_BAND_SSDA};

/* The largest size index with a published value, as storage.c held them:
 * Tables 1-2 by example, d = 2, 3, 4 and SEARCH_KINDS; Table 3 by example
 * and UPDATE_KINDS; Table 4 by SEARCH_KINDS (-1: none). */
static const signed char OLD_SEARCH[2][3][7] = {
    {{2, 2, 2, 2, 2, -1, -1}, {2, 2, 2, 2, 3, -1, -1}, {2, 2, 1, 1, 3, -1, -1}},
    {{-1, -1, -1, -1, -1, -1, -1}, {-1, 2, -1, -1, 3, -1, -1}, {-1, 2, -1, -1, 3, -1, -1}},
};
static const signed char OLD_UPDATE[2][6] = {{3, 4, 3, 4, -1, -1}, {3, 4, 4, 4, -1, -1}};
static const signed char OLD_MEMORY[7] = {2, 2, 3, 3, 3, -1, -1};

static void read_table(p3_pub *p, const char *name)
{
    hj_error err;
    if (p3_pub_read(p, PUBDIR, name, &err)) fail_msg("%s", err.msg);
}

static void published_cells_as_before(void **state)
{
    (void)state;
    static const long s2[] = {400, 800, 1600}, s3[] = {100, 200, 400, 800}, s4[] = {25, 50, 100, 200};
    p3_pub p[5];
    read_table(&p[0], "table1");
    read_table(&p[1], "table2");
    read_table(&p[2], "table3");
    read_table(&p[3], "table4");
    read_table(&p[4], "table5");
    int cells = 0, published = 0;
    for (int ex = 1; ex <= 2; ex++)
        for (int d = ex == 1 ? 2 : 3; d <= 4; d++)
            for (int i = 0; i < (d == 2 ? 3 : 4); i++)
                for (int k = 0; k < 7; k++) {
                    const long key[2] = {d, d == 2 ? s2[i] : d == 3 ? s3[i] : s4[i]};
                    const int has = p3_pub_has(&p[ex - 1], key, hj_band_kind_name(SEARCH_KINDS[k]));
                    if (has != (i <= OLD_SEARCH[ex - 1][d - 2][k]))
                        fail_msg("table%d d=%d N=%ld %s: file %d", ex, d, key[1], hj_band_kind_name(SEARCH_KINDS[k]), has);
                    cells++;
                    published += has;
                }
    for (int ex = 1; ex <= 2; ex++)
        for (int i = 0; i < 5; i++)
            for (int k = 0; k < 6; k++) {
                const long key[2] = {ex, 50L << i};
                const int has = p3_pub_has(&p[2], key, hj_band_kind_name(UPDATE_KINDS[k]));
                if (has != (i <= OLD_UPDATE[ex - 1][k])) fail_msg("table3 ex=%d N=%ld %s: file %d", ex, key[1], hj_band_kind_name(UPDATE_KINDS[k]), has);
                cells++;
                published += has;
            }
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 7; k++) {
            const long key[2] = {3, 100L << i};
            const int has = p3_pub_has(&p[3], key, hj_band_kind_name(SEARCH_KINDS[k]));
            if (has != (i <= OLD_MEMORY[k])) fail_msg("table4 N=%ld %s: file %d", key[1], hj_band_kind_name(SEARCH_KINDS[k]), has);
            cells++;
            published += has;
        }
    /* hjbstep's: FLS to N = 400, SSD at every size, SSDA none */
    for (int i = 0; i < 6; i++) {
        const long n = 50L << i;
        assert_int_equal(p3_pub_has(&p[4], &n, "FLS"), n <= 400);
        assert_int_equal(p3_pub_has(&p[4], &n, "SSD"), 1);
        assert_int_equal(p3_pub_has(&p[4], &n, "SSDA"), 0);
        published += 1 + (n <= 400);
    }
    assert_int_equal(cells, 77 + 56 + 60 + 28); /* the test walked every cell */
    assert_true(published > 100);
    /* a size the paper does not have, a key of the wrong width */
    assert_int_equal(p3_pub_has(&p[4], (const long[]){64}, "SSD"), 0);
    assert_int_equal(p3_pub_has(&p[0], (const long[]){3, 64}, "SSD"), 0);
    for (int t = 0; t < 5; t++) p3_pub_free(&p[t]);
}

static void unreadable_tables_are_errors(void **state)
{
    (void)state;
    p3_pub p;
    hj_error err;
    assert_int_equal(p3_pub_read(&p, "/nonexistent", "table1", &err), HJ_EIO);
    char path[128];
    snprintf(path, sizeof path, "%s/nokey.tsv", hj_test_dir());
    FILE *fp = fopen(path, "w");
    assert_non_null(fp);
    fputs("# source: x\nN\tSSD\n50\t1\n", fp);
    fclose(fp);
    assert_int_equal(p3_pub_read(&p, hj_test_dir(), "nokey", &err), HJ_EFORMAT);
    fp = fopen(path, "w");
    assert_non_null(fp);
    fputs("# key: d N\nN\tSSD\n50\t1\n", fp);
    fclose(fp);
    assert_int_equal(p3_pub_read(&p, hj_test_dir(), "nokey", &err), HJ_EFORMAT);
    remove(path);
}

/* ---- the rule against the two former ones ------------------------------- */

/* storage.c's former rule: prev[] the times of the column's smaller sizes
 * (NaN: not run or out of memory). */
static int old_within(const double *prev, int i, int d, double budget)
{
    if (i == 0 || isnan(prev[i - 1])) return i == 0;
    const double growth = i >= 2 && !isnan(prev[i - 2]) && prev[i - 2] > 0 ? prev[i - 1] / prev[i - 2] : (double)(1 << d);
    return prev[i - 1] * (growth > 2 ? growth : 2) <= budget;
}

static int old_affordable(const double *prev, int i, int d, int published, int big, int extra_all, double budget)
{
    if (published || extra_all) return old_within(prev, i, d, budget);
    return !big && old_within(prev, i, d, 2.0 < budget ? 2.0 : budget);
}

/* A random time: a few exact values the comparisons meet at their edges,
 * else log-uniform over 1e-5 .. 1e3 s; NaN with probability oom (out of
 * memory). */
static double random_time(double oom)
{
    const double u = rand() / (RAND_MAX + 1.0);
    if (u < oom) return NAN;
    switch (rand() % 8) {
    case 0: return 0.0;
    case 1: return 2.0 / 8; /* on the 2 s budget with growth 8 (storage) */
    case 2: return 2.0 / 24; /* the same for hjbstep's 3 steps */
    case 3: return 100.0 / 4;
    default: return pow(10, -5 + 8 * (rand() / (RAND_MAX + 1.0)));
    }
}

static void rule_decides_as_storage_did(void **state)
{
    (void)state;
    srand(12345);
    int runs = 0, skips = 0, listed = 0;
    for (int trial = 0; trial < 20000; trial++) {
        const int d = 2 + rand() % 3, ns = 1 + rand() % 6, extra = rand() % 4 == 0;
        const double budget = rand() % 2 ? 100.0 : 5.0;
        const p3_rule rule = {budget, extra, 1.0};
        p3_col col = P3_COL_INIT;
        double prev[6];
        for (int i = 0; i < ns; i++) {
            const int pub = rand() % 2, big = rand() % 3 == 0;
            const int old = old_affordable(prev, i, d, pub, big, extra, budget);
            const int old_listed = !old && !pub && (i == 0 || !isnan(prev[i - 1]));
            const p3_decision dec = p3_rule_decide(&rule, &col, d, pub, big);
            assert_int_equal(dec == P3_RUN, old);
            assert_int_equal(p3_rule_listed(dec, pub), old_listed);
            prev[i] = old ? random_time(0.1) : NAN;
            p3_col_record(&col, prev[i]);
            runs += old;
            skips += !old;
            listed += old_listed;
        }
    }
    assert_true(runs > 1000 && skips > 1000 && listed > 1000); /* every branch met often */
}

/* hjbstep stopped a store for good at its first skipped size, even past
 * a later published one; the rule stops at a size after a skipped one.
 * The two agree where the published sizes of a store come first, as in
 * every table (published_cells_as_before), so the columns here are so. */
static void rule_decides_as_hjbstep_did(void **state)
{
    (void)state;
    srand(54321);
    enum { STEPS = 3 };
    int runs = 0, skips = 0, listed = 0;
    for (int trial = 0; trial < 20000; trial++) {
        const int ns = 1 + rand() % 6, extra = rand() % 4 == 0, npub = rand() % (ns + 1);
        const p3_rule rule = {INFINITY, extra, STEPS};
        p3_col col = P3_COL_INIT;
        double last[2] = {NAN, NAN};
        int stopped = 0;
        for (int i = 0; i < ns; i++) {
            const int paper = i < npub, big = rand() % 3 == 0;
            /* hjbstep's former test, for one store */
            const int pub = extra || paper;
            int old_listed = 0;
            if (!pub && !stopped) {
                const double growth = last[0] > 0 ? last[1] / last[0] : 8;
                stopped = big || (!isnan(last[1]) && STEPS * last[1] * (growth > 2 ? growth : 2) > 2.0);
                old_listed = stopped;
            }
            const int old = !(!pub && stopped);
            const p3_decision dec = p3_rule_decide(&rule, &col, 3, paper, big);
            assert_int_equal(dec == P3_RUN, old);
            assert_int_equal(p3_rule_listed(dec, paper), old_listed);
            if (old) {
                const double t = random_time(0.1);
                if (!isnan(t)) { /* out of memory leaves the times as they were */
                    last[0] = last[1];
                    last[1] = t;
                    p3_col_record(&col, t);
                }
            } else
                p3_col_record(&col, NAN);
            runs += old;
            skips += !old;
            listed += old_listed;
        }
    }
    assert_true(runs > 1000 && skips > 1000 && listed > 1000);
}

static void decision_texts(void **state)
{
    (void)state;
    const p3_rule rule = {5.0, 0, 1.0};
    char buf[96];
    assert_string_equal(p3_decision_text(buf, sizeof buf, &rule, P3_RUN, 1), "run");
    assert_string_equal(p3_decision_text(buf, sizeof buf, &rule, P3_SKIP_COST, 1), "skip: predicted above 5 s");
    assert_string_equal(p3_decision_text(buf, sizeof buf, &rule, P3_SKIP_COST, 0), "skip: predicted above 2 s");
    assert_string_equal(p3_decision_text(buf, sizeof buf, &rule, P3_SKIP_BIG, 0), "skip: full store above 1 GB");
    assert_int_equal(p3_store_big(HJ_BAND_FLS, 3, 480), 0); /* 9 x 480^3 = 0.995e9 */
    assert_int_equal(p3_store_big(HJ_BAND_FLS, 3, 482), 1);
    assert_int_equal(p3_store_big(HJ_BAND_SSD, 4, 200), 0);
}

/* ---- --plan's two walks -------------------------------------------------- */

static void plan_merges_the_walks(void **state)
{
    (void)state;
    p3_plan p = {0};
    hj_error err;
    for (p.world = 0; p.world < 2; p.world++) {
        assert_int_equal(p3_plan_note(&p, "a\tpublished", "run", &err), HJ_OK);
        assert_int_equal(p3_plan_note(&p, "b\tpublished", p.world ? "skip: x" : "run", &err), HJ_OK);
    }
    char path[128];
    snprintf(path, sizeof path, "%s/plan.txt", hj_test_dir());
    FILE *fp = fopen(path, "w+");
    assert_non_null(fp);
    assert_int_equal(p3_plan_print(&p, fp, &err), HJ_OK);
    rewind(fp);
    char text[256] = "";
    const size_t n = fread(text, 1, sizeof text - 1, fp);
    text[n] = 0;
    fclose(fp);
    remove(path);
    assert_string_equal(text, "a\tpublished\trun\nb\tpublished\tdepends on measured time (if cheap: run; if dear: skip: x)\n");
    p.world = 1;
    assert_int_equal(p3_plan_note(&p, "c", "run", &err), HJ_OK); /* the walks now differ in length */
    assert_int_equal(p3_plan_print(&p, stdout, &err), HJ_EFORMAT);
    p3_plan_free(&p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(published_cells_as_before), cmocka_unit_test(unreadable_tables_are_errors),
        cmocka_unit_test(rule_decides_as_storage_did), cmocka_unit_test(rule_decides_as_hjbstep_did),
        cmocka_unit_test(decision_texts), cmocka_unit_test(plan_merges_the_walks),
    };
    return cmocka_run_group_tests_name("p3_prog", tests, hj_test_mkdir, hj_test_rmdir);
}
