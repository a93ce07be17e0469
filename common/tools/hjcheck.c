/* hjcheck -- compare every published cell with the computed one.
 *
 * Usage: hjcheck --results DIR [--quick] [--no-fail] [--rules] NAME=PAPERDIR ...
 *
 * For each NAME=PAPERDIR (e.g. paper1=paper1_fastsweeping) and each
 * published table PAPERDIR/published/<table>.tsv it reads the computed
 * table DIR/NAME/<table>.tsv, gives every published cell a verdict (rules in
 * common/hj_compare.h), writes DIR/NAME/<table>.check.tsv and prints
 *     NAME <table>: a match, b close, c differ[, ...]
 * then, last,
 *     check: N passed, M failed
 * A cell passes when its verdict is no worse than the accepted verdict in
 * PAPERDIR/accepted.tsv (cells not listed there must match).  Cells of
 * kind 'ratio' (CPU-time and memory ratios) are compared and shown but
 * never fail on their value: they measure the machine and its load as much
 * as the code; a ratio that is missing fails like any other cell.  With --quick,
 * rows the quick run did not compute are skipped rather than missing.
 * Exit status 1 if any cell failed (unless --no-fail), 2 on bad usage or
 * unreadable input.
 *
 * Published table format: TSV with header fields
 *     # source: <paper, table, page>
 *     # key: <key columns, space separated>
 *     # kind: <column>=<error|order|count|ratio|value> ...
 * A cell "-" or empty is not a published value; "?" is ambiguous.
 * The computed table has the same key and quantity columns (more columns
 * are allowed and ignored).
 */
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hj_compare.h"
#include "hj_io.h"

typedef struct {
    char *table, *key, *quantity, *reason;
    int verdict;
    int used;
} accepted_cell;

typedef struct {
    accepted_cell *cells;
    int n;
} accepted_list;

static const char *prog = "hjcheck";

static int load_accepted(const char *path, accepted_list *acc, hj_error *err)
{
    hj_table t;
    acc->cells = NULL;
    acc->n = 0;
    FILE *probe = fopen(path, "r");
    if (!probe) return HJ_OK; /* no accepted deviations: everything must match */
    fclose(probe);
    int rc = hj_table_read(&t, path, err);
    if (rc) return rc;
    int ct = hj_table_col(&t, "table"), ck = hj_table_col(&t, "key"), cq = hj_table_col(&t, "quantity"),
        cv = hj_table_col(&t, "verdict"), cr = hj_table_col(&t, "reason");
    if (ct < 0 || ck < 0 || cq < 0 || cv < 0 || cr < 0) {
        hj_table_free(&t);
        return hj_error_set(err, HJ_EFORMAT, "%s: needs columns table key quantity verdict reason", path);
    }
    acc->cells = calloc((size_t)t.nrows + 1, sizeof *acc->cells);
    if (!acc->cells) { hj_table_free(&t); return hj_error_set(err, HJ_ENOMEM, "out of memory"); }
    for (int r = 0; r < t.nrows; r++) {
        accepted_cell *a = &acc->cells[acc->n];
        a->verdict = hj_verdict_from_name(t.cells[r][cv]);
        if (a->verdict < 0 || a->verdict == HJ_AMBIGUOUS) {
            int line_rc = hj_error_set(err, HJ_EFORMAT, "%s: row %d: unknown verdict '%s'", path, r + 1, t.cells[r][cv]);
            hj_table_free(&t);
            return line_rc;
        }
        if (t.cells[r][cr][0] == '\0') {
            int line_rc = hj_error_set(err, HJ_EFORMAT, "%s: row %d: a reason is required", path, r + 1);
            hj_table_free(&t);
            return line_rc;
        }
        a->table = strdup(t.cells[r][ct]);
        a->key = strdup(t.cells[r][ck]);
        a->quantity = strdup(t.cells[r][cq]);
        a->reason = strdup(t.cells[r][cr]);
        acc->n++;
    }
    hj_table_free(&t);
    return HJ_OK;
}

static void free_accepted(accepted_list *acc)
{
    for (int i = 0; i < acc->n; i++) {
        free(acc->cells[i].table);
        free(acc->cells[i].key);
        free(acc->cells[i].quantity);
        free(acc->cells[i].reason);
    }
    free(acc->cells);
}

static accepted_cell *find_accepted(accepted_list *acc, const char *table, const char *key, const char *q)
{
    for (int i = 0; i < acc->n; i++)
        if (!strcmp(acc->cells[i].table, table) && !strcmp(acc->cells[i].key, key) && !strcmp(acc->cells[i].quantity, q))
            return &acc->cells[i];
    return NULL;
}

static int parse_cell(const char *s, double *v)
{
    char *end;
    if (s[0] == '\0' || !strcmp(s, "-")) return 0;
    *v = strtod(s, &end);
    return *end == '\0' ? 1 : -1;
}

typedef struct {
    int count[5];
    int skipped, passed, failed;
} tally;

/* Split "a b c" into words (in place); returns count. */
static int split_words(char *s, char **w, int max)
{
    int n = 0;
    for (char *tok = strtok(s, " \t"); tok && n < max; tok = strtok(NULL, " \t")) w[n++] = tok;
    return n;
}

enum { MAXCOLS = 64 };

static int check_table(const char *name, const char *paperdir, const char *table, const char *resdir, int quick,
                       accepted_list *acc, tally *total)
{
    char path[4096], cpath[4096], opath[4096];
    hj_error err;
    hj_table pub, com;
    snprintf(path, sizeof path, "%s/published/%s.tsv", paperdir, table);
    snprintf(cpath, sizeof cpath, "%s/%s/%s.tsv", resdir, name, table);
    snprintf(opath, sizeof opath, "%s/%s/%s.check.tsv", resdir, name, table);
    if (hj_table_read(&pub, path, &err)) {
        fprintf(stderr, "%s: %s\n", prog, err.msg);
        return -1;
    }
    const char *keymeta = hj_table_meta(&pub, "key"), *kindmeta = hj_table_meta(&pub, "kind");
    if (!keymeta || !kindmeta) {
        fprintf(stderr, "%s: %s: needs '# key:' and '# kind:' header lines\n", prog, path);
        hj_table_free(&pub);
        return -1;
    }
    char keybuf[1024], kindbuf[2048];
    char *keys[MAXCOLS], *kinds[MAXCOLS];
    snprintf(keybuf, sizeof keybuf, "%s", keymeta);
    snprintf(kindbuf, sizeof kindbuf, "%s", kindmeta);
    int nkey = split_words(keybuf, keys, MAXCOLS), nkind = split_words(kindbuf, kinds, MAXCOLS);
    int have_com = hj_table_read(&com, cpath, &err) == HJ_OK;
    if (!have_com && !quick) fprintf(stderr, "%s: warning: %s\n", prog, err.msg);

    hj_out out;
    char dir[4096];
    snprintf(dir, sizeof dir, "%s/%s", resdir, name);
    if (hj_mkdirs(dir, &err) || hj_out_open(&out, opath, &err)) {
        fprintf(stderr, "%s: %s\n", prog, err.msg);
        hj_table_free(&pub);
        if (have_com) hj_table_free(&com);
        return -1;
    }
    fprintf(out.fp, "# comparison of %s/%s with %s\n", name, table, path);
    fprintf(out.fp, "table\tkey\tquantity\tkind\tpublished\tcomputed\tdifference\tverdict\taccepted\treason\n");
    tally t = {{0}, 0, 0, 0};
    int bad = 0;
    for (int r = 0; r < pub.nrows && !bad; r++) {
        /* key string and matching computed row */
        char key[1024] = "";
        int crow = -1;
        for (int k = 0; k < nkey; k++) {
            int c = hj_table_col(&pub, keys[k]);
            if (c < 0) { fprintf(stderr, "%s: %s: key column '%s' missing\n", prog, path, keys[k]); bad = 1; break; }
            size_t len = strlen(key);
            snprintf(key + len, sizeof key - len, "%s%s=%s", k ? "," : "", keys[k], pub.cells[r][c]);
        }
        if (bad) break;
        if (have_com) {
            for (int cr = 0; cr < com.nrows && crow < 0; cr++) {
                int same = 1;
                for (int k = 0; k < nkey && same; k++) {
                    int pc = hj_table_col(&pub, keys[k]), cc = hj_table_col(&com, keys[k]);
                    same = cc >= 0 && !strcmp(pub.cells[r][pc], com.cells[cr][cc]);
                }
                if (same) crow = cr;
            }
        }
        for (int q = 0; q < nkind; q++) {
            char qname[128];
            snprintf(qname, sizeof qname, "%s", kinds[q]);
            char *eq = strchr(qname, '=');
            if (!eq) { fprintf(stderr, "%s: %s: malformed kind '%s'\n", prog, path, kinds[q]); bad = 1; break; }
            *eq = '\0';
            hj_kind kind = hj_kind_from_name(eq + 1);
            int pc = hj_table_col(&pub, qname);
            if (kind == HJ_KIND_UNKNOWN || pc < 0) {
                fprintf(stderr, "%s: %s: unknown kind or column in '%s'\n", prog, path, kinds[q]);
                bad = 1;
                break;
            }
            const char *ps = pub.cells[r][pc];
            double pv = NAN, cv = NAN;
            int ambiguous = !strcmp(ps, "?");
            int pok = ambiguous ? 0 : parse_cell(ps, &pv);
            if (pok < 0) { fprintf(stderr, "%s: %s: row %d: '%s' is not a number\n", prog, path, r + 1, ps); bad = 1; break; }
            if (!ambiguous && pok == 0) continue; /* no published cell here */
            if (quick && crow < 0) { t.skipped++; continue; }
            int cc = have_com ? hj_table_col(&com, qname) : -1;
            int cok = (crow >= 0 && cc >= 0) ? parse_cell(com.cells[crow][cc], &cv) : 0;
            int roundoff = 0;
            hj_verdict v;
            if (ambiguous) v = HJ_AMBIGUOUS;
            else if (cok != 1) v = HJ_MISSING;
            else v = hj_compare(kind, pv, cv, &roundoff);
            accepted_cell *a = find_accepted(acc, table, key, qname);
            if (a) a->used = 1;
            int accepted = a ? a->verdict : HJ_MATCH;
            const char *reason = a ? a->reason : roundoff ? "both at round-off level" : "";
            char why[256] = "";
            t.count[v]++;
            if (v == HJ_AMBIGUOUS) {
                reason = "published cell unreadable in the source";
            } else if ((int)v > accepted && kind == HJ_KIND_RATIO && v != HJ_MISSING) {
                /* CPU-time and memory ratios depend on the machine and its
                 * load: shown, never gated (timings are not tests).  A ratio
                 * that was not computed at all is a regression like any
                 * other missing cell. */
                t.passed++;
                snprintf(why, sizeof why, "ratio, not gated (accepted %s)%s%s", hj_verdict_name((hj_verdict)accepted),
                         a ? "; " : "", a ? a->reason : "");
                reason = why;
            } else if ((int)v > accepted) {
                t.failed++;
                snprintf(why, sizeof why, "REGRESSION: accepted %s%s%s", hj_verdict_name((hj_verdict)accepted),
                         a ? "; " : "", a ? a->reason : "");
                reason = why;
                fprintf(stderr, "%s: %s %s %s %s: %s, computed %s, published %s (accepted: %s)\n", prog, name, table, key,
                        qname, hj_verdict_name(v), cok == 1 ? com.cells[crow][cc] : "none", ps,
                        hj_verdict_name((hj_verdict)accepted));
            } else {
                t.passed++;
                if ((int)v < accepted && kind != HJ_KIND_RATIO) /* ratios vary from run to run */
                    fprintf(stderr, "%s: note: %s %s %s %s is now %s, better than accepted %s: update %s/accepted.tsv\n", prog,
                            name, table, key, qname, hj_verdict_name(v), hj_verdict_name((hj_verdict)accepted), paperdir);
            }
            fprintf(out.fp, "%s\t%s\t%s\t%s\t%s\t", table, key, qname, hj_kind_name(kind), ps);
            if (cok == 1) fprintf(out.fp, "%.6g\t", cv); else fputs("-\t", out.fp);
            if (cok == 1 && !ambiguous) fprintf(out.fp, "%.4g\t", hj_difference(kind, pv, cv)); else fputs("-\t", out.fp);
            fprintf(out.fp, "%s%s\t%s\t%s\n", hj_verdict_name(v), roundoff ? " (round-off)" : "",
                    hj_verdict_name((hj_verdict)accepted), reason);
        }
    }
    hj_table_free(&pub);
    if (have_com) hj_table_free(&com);
    if (bad) {
        hj_out_abort(&out);
        return -1;
    }
    if (hj_out_commit(&out, &err)) {
        fprintf(stderr, "%s: %s\n", prog, err.msg);
        return -1;
    }
    printf("%s %s: %d match, %d close, %d differ", name, table, t.count[HJ_MATCH], t.count[HJ_CLOSE], t.count[HJ_DIFFERS]);
    if (t.count[HJ_MISSING]) printf(", %d missing", t.count[HJ_MISSING]);
    if (t.count[HJ_AMBIGUOUS]) printf(", %d ambiguous", t.count[HJ_AMBIGUOUS]);
    if (t.skipped) printf(", %d skipped (quick)", t.skipped);
    if (t.failed) printf("  [%d worse than accepted]", t.failed);
    printf("\n");
    for (int v = 0; v < 5; v++) total->count[v] += t.count[v];
    total->skipped += t.skipped;
    total->passed += t.passed;
    total->failed += t.failed;
    return 0;
}

static int cmp_str(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

static int check_paper(const char *name, const char *paperdir, const char *resdir, int quick, tally *total)
{
    char dir[4096], accpath[4096];
    hj_error err;
    snprintf(dir, sizeof dir, "%s/published", paperdir);
    snprintf(accpath, sizeof accpath, "%s/accepted.tsv", paperdir);
    accepted_list acc;
    if (load_accepted(accpath, &acc, &err)) {
        fprintf(stderr, "%s: %s\n", prog, err.msg);
        return -1;
    }
    DIR *d = opendir(dir);
    if (!d) {
        fprintf(stderr, "%s: cannot open %s\n", prog, dir);
        free_accepted(&acc);
        return -1;
    }
    char *names[512];
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL && n < 512) {
        size_t len = strlen(e->d_name);
        if (len > 4 && !strcmp(e->d_name + len - 4, ".tsv")) {
            names[n] = strdup(e->d_name);
            names[n][len - 4] = '\0';
            n++;
        }
    }
    closedir(d);
    qsort(names, (size_t)n, sizeof *names, cmp_str);
    int rc = 0;
    for (int i = 0; i < n; i++) {
        if (check_table(name, paperdir, names[i], resdir, quick, &acc, total) < 0) rc = -1;
        free(names[i]);
    }
    for (int i = 0; i < acc.n; i++)
        if (!acc.cells[i].used && !quick)
            fprintf(stderr, "%s: note: %s/accepted.tsv names %s %s %s, which no published table has\n", prog, paperdir,
                    acc.cells[i].table, acc.cells[i].key, acc.cells[i].quantity);
    free_accepted(&acc);
    return rc;
}

static void usage(FILE *f)
{
    fprintf(f, "usage: %s --results DIR [--quick] [--no-fail] NAME=PAPERDIR ...\n"
               "       %s --rules   (print the comparison rules as Markdown)\n"
               "Compares published with computed tables; see the header of common/tools/hjcheck.c.\n",
            prog, prog);
}

int main(int argc, char **argv)
{
    const char *resdir = NULL;
    int quick = 0, nofail = 0, npapers = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help")) { usage(stdout); return 0; }
        if (!strcmp(argv[i], "--rules")) { hj_compare_rules(stdout); return 0; }
        if (!strcmp(argv[i], "--quick")) quick = 1;
        else if (!strcmp(argv[i], "--no-fail")) nofail = 1;
        else if (!strcmp(argv[i], "--results") && i + 1 < argc) resdir = argv[++i];
        else if (argv[i][0] == '-') { fprintf(stderr, "%s: unknown option '%s'\n", prog, argv[i]); usage(stderr); return 2; }
        else if (!strchr(argv[i], '=')) { fprintf(stderr, "%s: expected NAME=PAPERDIR, got '%s'\n", prog, argv[i]); return 2; }
        else npapers++;
    }
    if (!resdir || npapers == 0) { usage(stderr); return 2; }
    tally total = {{0}, 0, 0, 0};
    int rc = 0;
    for (int i = 1; i < argc; i++) {
        if (argv[i][0] == '-' || !strchr(argv[i], '=')) {
            if (!strcmp(argv[i], "--results")) i++;
            continue;
        }
        char name[256];
        snprintf(name, sizeof name, "%s", argv[i]);
        char *eq = strchr(name, '=');
        *eq = '\0';
        if (check_paper(name, eq + 1, resdir, quick, &total) < 0) rc = 2;
    }
    printf("check: %d passed, %d failed\n", total.passed, total.failed);
    if (rc) return rc;
    return (total.failed && !nofail) ? 1 : 0;
}
