/* hjcheck -- compare every reference cell with the computed one.
 *
 * Usage: hjcheck --results DIR [--quick] [--no-fail] [--rules] NAME=PAPERDIR ...
 *
 * For each NAME=PAPERDIR (e.g. paper1=paper1_fastsweeping) and each of its
 * reference tables (below) it reads the computed table
 * DIR/NAME/<table>.tsv, gives every reference cell a verdict (rules in
 * common/hj_compare.h), writes DIR/NAME/<table>.check.tsv and prints
 *     NAME <table>: a match, b close, c differ[, ...]
 * then, last,
 *     check: N passed, M failed
 * A cell passes when its verdict is no worse than the accepted verdict in
 * PAPERDIR/accepted.tsv (cells not listed there must match).  Each accepted
 * cell names a reason by its id; PAPERDIR/reasons.tsv (columns id, text)
 * states each reason once for the group of cells it covers.  With --quick,
 * PAPERDIR/accepted-quick.tsv is read too and takes precedence: exceptions
 * that only the quick run needs (a row it skips) live there, so a full run
 * is never excused by them.
 *
 * Blessing is explicit:
 *     hjcheck --results DIR [--quick] --accept TABLE --reason ID
 *             [--reason-text TEXT] NAME=PAPERDIR
 * compares TABLE and writes its current verdicts into accepted.tsv
 * (accepted-quick.tsv with --quick): every cell that is not a match is
 * accepted at its verdict with reason ID (one this list already accepts
 * at that verdict keeps its own reason), cells that now match are
 * dropped (with --quick, written as a match where accepted.tsv accepts
 * them at a worse verdict, which would otherwise apply to the quick run
 * again); other tables' rows are kept.  --reason-text adds ID to
 * reasons.tsv (or must equal its text there).  Cells of
 * kind 'ratio' (CPU-time and memory ratios) are compared and shown but
 * never fail on their value: they measure the machine and its load as much
 * as the code; a ratio that is missing fails like any other cell.  With --quick,
 * rows the quick run did not compute are skipped rather than missing.
 * Exit status 1 if any cell failed (unless --no-fail), 2 on bad usage or
 * unreadable input.
 *
 * References say what they are, and where they live says it.  A reference
 * value is transcribed from the paper ("paper"), an exact value from a
 * formula or a hand computation that its file's '# source:' names
 * ("exact"), or a regression value, the accepted result of one of our own
 * runs ("regression", stamped with the run's '# commit:'), or a value of
 * another implementation's run on the same problem ("peer": ToolboxLS's
 * own outputs, its '# source:' naming the run).  The check table gives
 * each cell's reference: paper, exact, regression@<commit> or peer.  A
 * paper keeps its references in one of two layouts:
 *
 *   PAPERDIR/published/<table>.tsv   paper values only, one file a table:
 *       # source: <paper, table, page>
 *       # key: <key columns, space separated>
 *       # kind: <column>=<error|order|count|ratio|value> ...
 *     then the key and value columns.
 *
 *   PAPERDIR/reference/<table>.tsv   the table's definition: '# key:' and
 *     '# kind:' as above, and its rows, key columns only, in the order
 *     of the check table (the files of one kind each hold some rows and
 *     cannot say how these interleave); every row has a value somewhere
 *     below, every '# kind:' column too.
 *   PAPERDIR/reference/paper/<table>.tsv       (each optional, at least one)
 *   PAPERDIR/reference/exact/<table>.tsv
 *   PAPERDIR/reference/regression/<table>.tsv
 *   PAPERDIR/reference/peer/<table>.tsv
 *     the values of that kind: '# source:' for them ('# commit:' too in
 *     regression/), the key columns and the '# kind:' columns that have
 *     values of this kind, and only the rows that have one.  The merge
 *     refuses a row that is not one of the definition's, and a cell with
 *     a value in two files (or twice in one).
 *
 * In both, a cell "-" or empty has no value (in reference/, the cells of
 * a row that are of another kind); "?" is a paper value unreadable in the
 * source (shown, never compared).  Papers 1 and 3 keep published/: every
 * value they check is transcribed, so one self-contained file a table
 * (the form their own scripts read) says all there is, and a definition
 * beside a single paper/ file would only double the files.  Paper 2
 * publishes almost no numbers and mixes all three kinds, hence reference/.
 *
 * The computed table has the same key and quantity columns (more columns
 * are allowed and ignored).
 */
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hj_compare.h"
#include "hj_cli.h"
#include "hj_io.h"

typedef struct {
    char *table, *key, *quantity, *reason; /* reason: the id in reasons.tsv */
    const char *text;                      /* its text */
    int verdict;
    int used;
} accepted_cell;

typedef struct {
    accepted_cell *cells;
    int n;
} accepted_list;

typedef struct {
    char **id, **text;
    int n;
} reason_list;

static const char *prog = "hjcheck";

/* Open path for reading: 0 if it does not exist (nothing to load), 1 if it
 * does, -1 (with err) if it exists but cannot be read. */
static int probe(const char *path, hj_error *err)
{
    FILE *f = fopen(path, "r");
    if (f) { fclose(f); return 1; }
    if (errno == ENOENT) return 0;
    hj_error_set(err, HJ_EIO, "%s: %s", path, strerror(errno));
    return -1;
}

static void free_reasons(reason_list *r)
{
    for (int i = 0; i < r->n; i++) free(r->id[i]), free(r->text[i]);
    free(r->id), free(r->text);
    r->id = r->text = NULL, r->n = 0;
}

static const char *reason_text(const reason_list *r, const char *id)
{
    for (int i = 0; i < r->n; i++)
        if (!strcmp(r->id[i], id)) return r->text[i];
    return NULL;
}

static int load_reasons(const char *path, reason_list *r, hj_error *err)
{
    r->id = r->text = NULL, r->n = 0;
    int p = probe(path, err);
    if (p <= 0) return p < 0 ? err->code : HJ_OK;
    hj_table t;
    int rc = hj_table_read(&t, path, err);
    if (rc) return rc;
    int ci = hj_table_col(&t, "id"), cx = hj_table_col(&t, "text");
    if (ci < 0 || cx < 0) { hj_table_free(&t); return hj_error_set(err, HJ_EFORMAT, "%s: needs columns id text", path); }
    r->id = calloc((size_t)t.nrows + 1, sizeof *r->id);
    r->text = calloc((size_t)t.nrows + 1, sizeof *r->text);
    if (!r->id || !r->text) { hj_table_free(&t); free_reasons(r); return hj_error_set(err, HJ_ENOMEM, "out of memory"); }
    for (int i = 0; i < t.nrows; i++) {
        if (!t.cells[i][ci][0] || !t.cells[i][cx][0] || reason_text(r, t.cells[i][ci])) {
            rc = hj_error_set(err, HJ_EFORMAT, "%s: row %d: an id must be non-empty and unique, with a text", path, i + 1);
            hj_table_free(&t);
            free_reasons(r);
            return rc;
        }
        r->id[r->n] = strdup(t.cells[i][ci]);
        r->text[r->n++] = strdup(t.cells[i][cx]);
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
    acc->cells = NULL, acc->n = 0;
}

/* Append the rows of path (absent: none) to acc; every reason id must be in
 * reasons. */
static int load_accepted(const char *path, const reason_list *reasons, accepted_list *acc, hj_error *err)
{
    int p = probe(path, err);
    if (p <= 0) return p < 0 ? err->code : HJ_OK;
    hj_table t;
    int rc = hj_table_read(&t, path, err);
    if (rc) return rc;
    int ct = hj_table_col(&t, "table"), ck = hj_table_col(&t, "key"), cq = hj_table_col(&t, "quantity"),
        cv = hj_table_col(&t, "verdict"), cr = hj_table_col(&t, "reason");
    if (ct < 0 || ck < 0 || cq < 0 || cv < 0 || cr < 0) {
        hj_table_free(&t);
        return hj_error_set(err, HJ_EFORMAT, "%s: needs columns table key quantity verdict reason", path);
    }
    accepted_cell *grown = realloc(acc->cells, ((size_t)acc->n + (size_t)t.nrows + 1) * sizeof *grown);
    if (!grown) { hj_table_free(&t); return hj_error_set(err, HJ_ENOMEM, "out of memory"); }
    acc->cells = grown;
    for (int r = 0; r < t.nrows; r++) {
        accepted_cell *a = &acc->cells[acc->n];
        memset(a, 0, sizeof *a);
        a->verdict = hj_verdict_from_name(t.cells[r][cv]);
        a->text = reason_text(reasons, t.cells[r][cr]);
        if (a->verdict < 0 || a->verdict == HJ_AMBIGUOUS || !a->text) {
            int line_rc = a->text ? hj_error_set(err, HJ_EFORMAT, "%s: row %d: unknown verdict '%s'", path, r + 1, t.cells[r][cv])
                                  : hj_error_set(err, HJ_EFORMAT, "%s: row %d: reason '%s' is not an id of reasons.tsv",
                                                 path, r + 1, t.cells[r][cr]);
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

static accepted_cell *find_accepted(accepted_list *acc, const char *table, const char *key, const char *q)
{
    for (int i = 0; i < acc->n; i++)
        if (!strcmp(acc->cells[i].table, table) && !strcmp(acc->cells[i].key, key) && !strcmp(acc->cells[i].quantity, q))
            return &acc->cells[i];
    return NULL;
}

/* A cell's verdict as computed, kept for --accept. */
typedef struct {
    char key[1024], quantity[128];
    int verdict;
} computed_cell;

typedef struct {
    computed_cell *cells;
    int n, cap;
} computed_list;

static int add_computed(computed_list *c, const char *key, const char *q, int verdict)
{
    if (c->n == c->cap) {
        int cap = c->cap ? 2 * c->cap : 64;
        computed_cell *grown = realloc(c->cells, (size_t)cap * sizeof *grown);
        if (!grown) return -1;
        c->cells = grown, c->cap = cap;
    }
    snprintf(c->cells[c->n].key, sizeof c->cells[c->n].key, "%s", key);
    snprintf(c->cells[c->n].quantity, sizeof c->cells[c->n].quantity, "%s", q);
    c->cells[c->n++].verdict = verdict;
    return 0;
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

/* Split "a b c" into words (in place); returns the count, or -1 if there
 * are more than max. */
static int split_words(char *s, char **w, int max)
{
    int n = 0;
    for (char *tok = strtok(s, " \t"); tok; tok = strtok(NULL, " \t")) {
        if (n == max) return -1;
        w[n++] = tok;
    }
    return n;
}

enum { MAXCOLS = 64 };

/* What a reference value is; in the reference layout, also the name of
 * the directory that holds it. */
enum { ORIGIN_PAPER, ORIGIN_EXACT, ORIGIN_REGRESSION, ORIGIN_PEER, NORIGIN };
static const char *const origin_names[NORIGIN] = {"paper", "exact", "regression", "peer"};

/* The reference values of one table, merged from its files. */
typedef struct {
    hj_table t;          /* key columns, then the compared ones; the header fields of the table's definition */
    signed char *origin; /* ORIGIN_* of cell (r, c) at r * t.ncols + c; -1 where there is no value */
    char *commit;        /* the commit of the regression values, or NULL */
    char path[4096];     /* the definition (or published table), for messages */
    char files[4096];    /* the files the values come from */
} reference;

static void free_reference(reference *ref)
{
    hj_table_free(&ref->t);
    free(ref->origin);
    free(ref->commit);
    ref->origin = NULL, ref->commit = NULL;
}

/* Whether path is a directory. */
static int is_dir(const char *path)
{
    DIR *d = opendir(path);
    if (d) closedir(d);
    return d != NULL;
}

/* The layout of a paper's references: 1 for PAPERDIR/reference/, 0 for
 * PAPERDIR/published/, -1 (with err) for both or neither. */
static int reference_layout(const char *paperdir, hj_error *err)
{
    char pub[4096], ref[4096];
    snprintf(pub, sizeof pub, "%s/published", paperdir);
    snprintf(ref, sizeof ref, "%s/reference", paperdir);
    int p = is_dir(pub), r = is_dir(ref);
    if (p != r) return r;
    hj_error_set(err, HJ_EFORMAT, "%s: needs one of published/ and reference/, has %s", paperdir,
                 p ? "both" : "neither");
    return -1;
}

/* Append column name to t, every cell "-" (no value).  On failure t stays
 * consistent for hj_table_free. */
static int add_column(hj_table *t, const char *name)
{
    char **cols = realloc(t->cols, ((size_t)t->ncols + 1) * sizeof *cols);
    if (!cols) return -1;
    t->cols = cols;
    for (int r = 0; r < t->nrows; r++) {
        char **row = realloc(t->cells[r], ((size_t)t->ncols + 1) * sizeof *row);
        if (!row) return -1;
        t->cells[r] = row;
        row[t->ncols] = NULL;
    }
    int c = t->ncols++;
    int ok = (cols[c] = strdup(name)) != NULL;
    for (int r = 0; ok && r < t->nrows; r++) ok = (t->cells[r][c] = strdup("-")) != NULL;
    return ok ? 0 : -1;
}

/* The row of ref whose key columns (the first nkey) equal those of row r
 * of k, or -1. */
static int find_row(const hj_table *ref, int nkey, const hj_table *k, int r)
{
    for (int i = 0; i < ref->nrows; i++) {
        int same = 1;
        for (int c = 0; c < nkey && same; c++)
            same = !strcmp(ref->cells[i][c], k->cells[r][hj_table_col(k, ref->cols[c])]);
        if (same) return i;
    }
    return -1;
}

/* The key of row r of t (its first nkey columns) as "a=1,b=2". */
static const char *row_key(const hj_table *t, int nkey, int r, char *buf, size_t size)
{
    buf[0] = '\0';
    for (int c = 0; c < nkey; c++) {
        size_t len = strlen(buf);
        snprintf(buf + len, size - len, "%s%s=%s", c ? "," : "", t->cols[c], t->cells[r][c]);
    }
    return buf;
}

/* Merge the values of one kind, PAPERDIR/reference/<kind>/<table>.tsv, into
 * ref: each of its rows is a row of the definition and holds at least one
 * value; no cell has a value in two files. */
static int merge_values(reference *ref, int nkey, int origin, const char *path, hj_error *err)
{
    hj_table k;
    int rc = hj_table_read(&k, path, err);
    if (rc) return rc;
    char key[1024];
    const char *source = hj_table_meta(&k, "source"), *commit = hj_table_meta(&k, "commit");
    if (!source || !source[0])
        rc = hj_error_set(err, HJ_EFORMAT, "%s: needs '# source:' (where its values come from)", path);
    else if (origin == ORIGIN_REGRESSION && (!commit || !commit[0]))
        rc = hj_error_set(err, HJ_EFORMAT, "%s: regression values need '# commit:' (the run that made them)", path);
    else if (origin != ORIGIN_REGRESSION && commit)
        rc = hj_error_set(err, HJ_EFORMAT, "%s: '# commit:' stamps regression values only", path);
    else if (hj_table_meta(&k, "key") || hj_table_meta(&k, "kind") || hj_table_meta(&k, "origin"))
        rc = hj_error_set(err, HJ_EFORMAT, "%s: '# key:' and '# kind:' belong in %s, and the directory gives the kind "
                                           "of value ('# origin:' is gone)", path, ref->path);
    for (int c = 0; !rc && c < k.ncols; c++) {
        int at = hj_table_col(&ref->t, k.cols[c]);
        if (at < 0)
            rc = hj_error_set(err, HJ_EFORMAT, "%s: column '%s' is neither a key nor a '# kind:' column of %s", path,
                              k.cols[c], ref->path);
        else if (hj_table_col(&k, k.cols[c]) != c)
            rc = hj_error_set(err, HJ_EFORMAT, "%s: column '%s' twice", path, k.cols[c]);
    }
    for (int c = 0; !rc && c < nkey; c++)
        if (hj_table_col(&k, ref->t.cols[c]) < 0)
            rc = hj_error_set(err, HJ_EFORMAT, "%s: key column '%s' missing", path, ref->t.cols[c]);
    for (int r = 0; !rc && r < k.nrows; r++) {
        int row = find_row(&ref->t, nkey, &k, r), nvalues = 0;
        if (row < 0) {
            key[0] = '\0';
            for (int c = 0; c < nkey; c++) {
                size_t len = strlen(key);
                snprintf(key + len, sizeof key - len, "%s%s=%s", c ? "," : "", ref->t.cols[c],
                         k.cells[r][hj_table_col(&k, ref->t.cols[c])]);
            }
            rc = hj_error_set(err, HJ_EFORMAT, "%s: row %d (%s) is not a row of %s", path, r + 1, key, ref->path);
            break;
        }
        for (int c = 0; !rc && c < k.ncols; c++) {
            int at = hj_table_col(&ref->t, k.cols[c]);
            const char *s = k.cells[r][c];
            double v;
            if (at < nkey || !s[0] || !strcmp(s, "-")) continue;
            signed char *o = &ref->origin[(size_t)row * (size_t)ref->t.ncols + (size_t)at];
            if (!strcmp(s, "?") && origin != ORIGIN_PAPER)
                rc = hj_error_set(err, HJ_EFORMAT, "%s: row %d, column %s: '?' (unreadable in the source) is for paper "
                                                   "values only", path, r + 1, k.cols[c]);
            else if (strcmp(s, "?") && parse_cell(s, &v) != 1)
                rc = hj_error_set(err, HJ_EFORMAT, "%s: row %d, column %s: '%s' is not a number", path, r + 1, k.cols[c], s);
            else if (*o >= 0)
                rc = hj_error_set(err, HJ_EFORMAT, "%s: row %d (%s): %s has a value in %s/ already: a cell is defined "
                                                   "once", path, r + 1, row_key(&ref->t, nkey, row, key, sizeof key),
                                  k.cols[c], origin_names[*o]);
            else {
                char *copy = strdup(s);
                if (!copy) { rc = hj_error_set(err, HJ_ENOMEM, "out of memory"); break; }
                free(ref->t.cells[row][at]);
                ref->t.cells[row][at] = copy;
                *o = (signed char)origin;
                nvalues++;
            }
        }
        if (!rc && !nvalues)
            rc = hj_error_set(err, HJ_EFORMAT, "%s: row %d (%s) holds no value: leave it out", path, r + 1,
                              row_key(&ref->t, nkey, row, key, sizeof key));
    }
    if (!rc && origin == ORIGIN_REGRESSION && !(ref->commit = strdup(commit))) rc = hj_error_set(err, HJ_ENOMEM, "out of memory");
    hj_table_free(&k);
    return rc;
}

/* Load PAPERDIR/reference/<table>.tsv, the table's definition ('# key:',
 * '# kind:' and its rows, key columns only), and merge the values of
 * reference/{paper,exact,regression}/<table>.tsv into it. */
static int load_reference_dir(reference *ref, const char *paperdir, const char *table, hj_error *err)
{
    char path[4096], buf[4096], key[1024];
    char *words[MAXCOLS];
    snprintf(ref->path, sizeof ref->path, "%s/reference/%s.tsv", paperdir, table);
    int rc = hj_table_read(&ref->t, ref->path, err);
    if (rc) return rc;
    const char *keymeta = hj_table_meta(&ref->t, "key"), *kindmeta = hj_table_meta(&ref->t, "kind");
    if (!keymeta || !kindmeta || strlen(keymeta) >= sizeof buf || strlen(kindmeta) >= sizeof buf)
        return hj_error_set(err, HJ_EFORMAT, "%s: needs '# key:' and '# kind:' header lines", ref->path);
    if (hj_table_meta(&ref->t, "source") || hj_table_meta(&ref->t, "origin") || hj_table_meta(&ref->t, "commit"))
        return hj_error_set(err, HJ_EFORMAT, "%s: '# source:' and '# commit:' go with the values (paper/, exact/, "
                                             "regression/), and the directory gives the kind of value", ref->path);
    snprintf(buf, sizeof buf, "%s", keymeta);
    int nkey = split_words(buf, words, MAXCOLS);
    if (nkey <= 0 || nkey != ref->t.ncols)
        return hj_error_set(err, HJ_EFORMAT, "%s: its columns are the '# key:' columns, and only they", ref->path);
    for (int c = 0; c < nkey; c++)
        if (strcmp(words[c], ref->t.cols[c]))
            return hj_error_set(err, HJ_EFORMAT, "%s: its columns are the '# key:' columns, and only they", ref->path);
    for (int r = 0; r < ref->t.nrows; r++)
        if (find_row(&ref->t, nkey, &ref->t, r) != r)
            return hj_error_set(err, HJ_EFORMAT, "%s: row %d (%s) twice", ref->path, r + 1,
                                row_key(&ref->t, nkey, r, key, sizeof key));
    snprintf(buf, sizeof buf, "%s", kindmeta);
    int nkind = split_words(buf, words, MAXCOLS);
    if (nkind < 0) return hj_error_set(err, HJ_EFORMAT, "%s: more than %d '# kind:' columns", ref->path, MAXCOLS);
    for (int q = 0; q < nkind; q++) {
        char *eq = strchr(words[q], '=');
        if (!eq || eq == words[q]) return hj_error_set(err, HJ_EFORMAT, "%s: malformed kind '%s'", ref->path, words[q]);
        *eq = '\0';
        if (hj_table_col(&ref->t, words[q]) >= 0)
            return hj_error_set(err, HJ_EFORMAT, "%s: column '%s' twice in '# key:' and '# kind:'", ref->path, words[q]);
        if (add_column(&ref->t, words[q])) return hj_error_set(err, HJ_ENOMEM, "out of memory");
    }
    size_t ncells = (size_t)ref->t.nrows * (size_t)ref->t.ncols;
    ref->origin = malloc(ncells + 1);
    if (!ref->origin) return hj_error_set(err, HJ_ENOMEM, "out of memory");
    memset(ref->origin, -1, ncells + 1);
    char kinds[64] = "";
    int nfiles = 0;
    for (int o = 0; o < NORIGIN; o++) {
        snprintf(path, sizeof path, "%s/reference/%s/%s.tsv", paperdir, origin_names[o], table);
        int p = probe(path, err);
        if (p < 0) return err->code;
        if (p == 0) continue;
        if ((rc = merge_values(ref, nkey, o, path, err))) return rc;
        size_t len = strlen(kinds);
        snprintf(kinds + len, sizeof kinds - len, "%s%s", nfiles++ ? "," : "", origin_names[o]);
    }
    if (nfiles == 0)
        return hj_error_set(err, HJ_EFORMAT, "%s: no values: none of reference/{paper,exact,regression}/%s.tsv exists",
                            ref->path, table);
    snprintf(ref->files, sizeof ref->files, nfiles > 1 ? "%s/reference/{%s}/%s.tsv" : "%s/reference/%s/%s.tsv",
             paperdir, kinds, table);
    /* Every row and every compared column holds a value: a row or column
     * without one would be dead weight in the definition. */
    for (int r = 0; r < ref->t.nrows; r++) {
        int any = 0;
        for (int c = nkey; c < ref->t.ncols && !any; c++) any = ref->origin[(size_t)r * (size_t)ref->t.ncols + (size_t)c] >= 0;
        if (!any)
            return hj_error_set(err, HJ_EFORMAT, "%s: row %d (%s) has no value in paper/, exact/, regression/ or peer/",
                                ref->path, r + 1, row_key(&ref->t, nkey, r, key, sizeof key));
    }
    for (int c = nkey; c < ref->t.ncols; c++) {
        int any = 0;
        for (int r = 0; r < ref->t.nrows && !any; r++) any = ref->origin[(size_t)r * (size_t)ref->t.ncols + (size_t)c] >= 0;
        if (!any)
            return hj_error_set(err, HJ_EFORMAT, "%s: column '%s' has no value in paper/, exact/, regression/ or peer/",
                                ref->path, ref->t.cols[c]);
    }
    return HJ_OK;
}

/* Load PAPERDIR/published/<table>.tsv: its header fields and values in one
 * file, every value transcribed from the paper. */
static int load_published(reference *ref, const char *paperdir, const char *table, hj_error *err)
{
    snprintf(ref->path, sizeof ref->path, "%s/published/%s.tsv", paperdir, table);
    snprintf(ref->files, sizeof ref->files, "%s", ref->path);
    int rc = hj_table_read(&ref->t, ref->path, err);
    if (rc) return rc;
    if (hj_table_meta(&ref->t, "origin") || hj_table_meta(&ref->t, "commit"))
        return hj_error_set(err, HJ_EFORMAT, "%s: published/ holds paper values only; exact and regression values go "
                                             "to reference/ ('# origin:' and '# commit:' are gone)", ref->path);
    size_t ncells = (size_t)ref->t.nrows * (size_t)ref->t.ncols;
    ref->origin = calloc(ncells + 1, 1); /* ORIGIN_PAPER everywhere */
    if (!ref->origin) return hj_error_set(err, HJ_ENOMEM, "out of memory");
    return HJ_OK;
}

/* The reference values of table, by the paper's layout. */
static int load_reference(reference *ref, const char *paperdir, const char *table, hj_error *err)
{
    memset(ref, 0, sizeof *ref);
    int layout = reference_layout(paperdir, err);
    int rc = layout < 0 ? err->code
           : layout ? load_reference_dir(ref, paperdir, table, err) : load_published(ref, paperdir, table, err);
    if (rc) free_reference(ref);
    return rc;
}

static int check_table(const char *name, const char *paperdir, const char *table, const char *resdir, int quick,
                       accepted_list *acc, computed_list *collect, tally *total)
{
    char cpath[4096], opath[4096];
    hj_error err;
    hj_table com;
    reference ref;
    snprintf(cpath, sizeof cpath, "%s/%s/%s.tsv", resdir, name, table);
    snprintf(opath, sizeof opath, "%s/%s/%s.check.tsv", resdir, name, table);
    if (load_reference(&ref, paperdir, table, &err)) {
        fprintf(stderr, "%s: %s\n", prog, err.msg);
        return -1;
    }
    const hj_table *pub = &ref.t;
    const char *path = ref.path;
    const char *keymeta = hj_table_meta(pub, "key"), *kindmeta = hj_table_meta(pub, "kind");
    if (!keymeta || !kindmeta) {
        fprintf(stderr, "%s: %s: needs '# key:' and '# kind:' header lines\n", prog, path);
        free_reference(&ref);
        return -1;
    }
    char keybuf[1024], kindbuf[4096];
    char *keys[MAXCOLS], *kinds[MAXCOLS];
    int nkey = -1, nkind = -1;
    if (strlen(keymeta) < sizeof keybuf && strlen(kindmeta) < sizeof kindbuf) {
        snprintf(keybuf, sizeof keybuf, "%s", keymeta);
        snprintf(kindbuf, sizeof kindbuf, "%s", kindmeta);
        nkey = split_words(keybuf, keys, MAXCOLS), nkind = split_words(kindbuf, kinds, MAXCOLS);
    }
    if (nkey < 0 || nkind < 0) {
        fprintf(stderr, "%s: %s: '# key:' or '# kind:' is longer than %d columns or %zu characters\n", prog, path,
                MAXCOLS, sizeof keybuf);
        free_reference(&ref);
        return -1;
    }
    int have_com = hj_table_read(&com, cpath, &err) == HJ_OK;
    if (!have_com && !quick) fprintf(stderr, "%s: warning: %s\n", prog, err.msg);

    hj_out out;
    char dir[4096];
    snprintf(dir, sizeof dir, "%s/%s", resdir, name);
    if (hj_mkdirs(dir, &err) || hj_out_open(&out, opath, &err)) {
        fprintf(stderr, "%s: %s\n", prog, err.msg);
        free_reference(&ref);
        if (have_com) hj_table_free(&com);
        return -1;
    }
    fprintf(out.fp, "# comparison of %s/%s with %s\n", name, table, ref.files);
    fprintf(out.fp, "table\tkey\tquantity\tkind\tpublished\tcomputed\tdifference\tverdict\taccepted\treason\treference\n");
    tally t = {{0}, 0, 0, 0};
    int bad = 0;
    for (int r = 0; r < pub->nrows && !bad; r++) {
        /* key string and matching computed row */
        char key[1024] = "";
        int crow = -1;
        for (int k = 0; k < nkey; k++) {
            int c = hj_table_col(pub, keys[k]);
            if (c < 0) { fprintf(stderr, "%s: %s: key column '%s' missing\n", prog, path, keys[k]); bad = 1; break; }
            size_t len = strlen(key);
            snprintf(key + len, sizeof key - len, "%s%s=%s", k ? "," : "", keys[k], pub->cells[r][c]);
        }
        if (bad) break;
        if (have_com) {
            for (int cr = 0; cr < com.nrows && crow < 0; cr++) {
                int same = 1;
                for (int k = 0; k < nkey && same; k++) {
                    int pc = hj_table_col(pub, keys[k]), cc = hj_table_col(&com, keys[k]);
                    same = cc >= 0 && !strcmp(pub->cells[r][pc], com.cells[cr][cc]);
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
            int pc = hj_table_col(pub, qname);
            if (kind == HJ_KIND_UNKNOWN || pc < 0) {
                fprintf(stderr, "%s: %s: unknown kind or column in '%s'\n", prog, path, kinds[q]);
                bad = 1;
                break;
            }
            const char *ps = pub->cells[r][pc];
            double pv = NAN, cv = NAN;
            int ambiguous = !strcmp(ps, "?");
            int pok = ambiguous ? 0 : parse_cell(ps, &pv);
            if (pok < 0) { fprintf(stderr, "%s: %s: row %d: '%s' is not a number\n", prog, path, r + 1, ps); bad = 1; break; }
            if (!ambiguous && pok == 0) continue; /* no published cell here */
            int origin = ref.origin[(size_t)r * (size_t)pub->ncols + (size_t)pc];
            if (quick && crow < 0) { t.skipped++; continue; }
            int cc = have_com ? hj_table_col(&com, qname) : -1;
            int cok = (crow >= 0 && cc >= 0) ? parse_cell(com.cells[crow][cc], &cv) : 0;
            int roundoff = 0;
            hj_verdict v;
            if (ambiguous) v = HJ_AMBIGUOUS;
            else if (cok != 1) v = HJ_MISSING;
            else v = hj_compare(kind, pv, cv, &roundoff);
            if (collect && add_computed(collect, key, qname, (int)v)) {
                fprintf(stderr, "%s: out of memory\n", prog);
                bad = 1;
                break;
            }
            accepted_cell *a = find_accepted(acc, table, key, qname);
            if (a) a->used = 1;
            int accepted = a ? a->verdict : HJ_MATCH;
            const char *reason = a ? a->text : roundoff ? "both at round-off level" : "";
            char why[2048] = ""; /* the prefix and the accepted reason whole (reasons run to 900 characters) */
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
                         a ? "; " : "", a ? a->text : "");
                reason = why;
            } else if ((int)v > accepted) {
                t.failed++;
                snprintf(why, sizeof why, "REGRESSION: accepted %s%s%s", hj_verdict_name((hj_verdict)accepted),
                         a ? "; " : "", a ? a->text : "");
                reason = why;
                fprintf(stderr, "%s: %s %s %s %s: %s, computed %s, published %s (accepted: %s)\n", prog, name, table, key,
                        qname, hj_verdict_name(v), cok == 1 ? com.cells[crow][cc] : "none", ps,
                        hj_verdict_name((hj_verdict)accepted));
            } else {
                t.passed++;
                if ((int)v < accepted && kind != HJ_KIND_RATIO) /* ratios vary from run to run */
                    fprintf(stderr, "%s: note: %s %s %s %s is now %s, better than accepted %s: bless it with "
                                    "hjcheck --accept %s\n", prog, name, table, key, qname, hj_verdict_name(v),
                            hj_verdict_name((hj_verdict)accepted), table);
            }
            fprintf(out.fp, "%s\t%s\t%s\t%s\t%s\t", table, key, qname, hj_kind_name(kind), ps);
            if (cok == 1) fprintf(out.fp, "%.6g\t", cv); else fputs("-\t", out.fp);
            if (cok == 1 && !ambiguous) fprintf(out.fp, "%.4g\t", hj_difference(kind, pv, cv)); else fputs("-\t", out.fp);
            fprintf(out.fp, "%s%s\t%s\t%s\t%s%s%s\n", hj_verdict_name(v), roundoff ? " (round-off)" : "",
                    hj_verdict_name((hj_verdict)accepted), reason, origin_names[origin],
                    origin == ORIGIN_REGRESSION ? "@" : "", origin == ORIGIN_REGRESSION ? ref.commit : "");
        }
    }
    free_reference(&ref);
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

/* The accepted list of a paper: accepted-quick.tsv first when quick (its
 * rows take precedence), then accepted.tsv. */
static int load_paper_accepted(const char *paperdir, int quick, reason_list *reasons, accepted_list *acc, hj_error *err)
{
    char path[4096];
    acc->cells = NULL, acc->n = 0;
    snprintf(path, sizeof path, "%s/reasons.tsv", paperdir);
    int rc = load_reasons(path, reasons, err);
    if (!rc && quick) {
        snprintf(path, sizeof path, "%s/accepted-quick.tsv", paperdir);
        rc = load_accepted(path, reasons, acc, err);
    }
    if (!rc) {
        snprintf(path, sizeof path, "%s/accepted.tsv", paperdir);
        rc = load_accepted(path, reasons, acc, err);
    }
    if (rc) free_accepted(acc), free_reasons(reasons);
    return rc;
}

enum { MAXTABLES = 512 };

/* The names (without .tsv) of the tables in dir, sorted; *n of them.  A
 * directory that does not exist holds none when optional. */
static int list_tables(const char *dir, int optional, char **names, int *n, hj_error *err)
{
    *n = 0;
    DIR *d = opendir(dir);
    if (!d) return optional && errno == ENOENT ? HJ_OK : hj_error_set(err, HJ_EIO, "cannot open %s", dir);
    int rc = HJ_OK;
    struct dirent *e;
    while (!rc && (e = readdir(d)) != NULL) {
        size_t len = strlen(e->d_name);
        if (len <= 4 || strcmp(e->d_name + len - 4, ".tsv")) continue;
        if (*n == MAXTABLES) rc = hj_error_set(err, HJ_EFORMAT, "%s holds more than %d tables", dir, MAXTABLES);
        else if (!(names[*n] = strdup(e->d_name))) rc = hj_error_set(err, HJ_ENOMEM, "out of memory");
        else names[(*n)++][len - 4] = '\0';
    }
    closedir(d);
    if (rc) {
        while (*n) free(names[--*n]);
        return rc;
    }
    qsort(names, (size_t)*n, sizeof *names, cmp_str);
    return HJ_OK;
}

/* The tables of a paper, sorted: those of published/, or those defined in
 * reference/, where every file of values must belong to a defined table. */
static int paper_tables(const char *paperdir, char **names, int *n, hj_error *err)
{
    char dir[4096];
    int layout = reference_layout(paperdir, err);
    if (layout < 0) return err->code;
    snprintf(dir, sizeof dir, "%s/%s", paperdir, layout ? "reference" : "published");
    int rc = list_tables(dir, 0, names, n, err);
    for (int o = 0; layout && !rc && o < NORIGIN; o++) {
        char *values[MAXTABLES];
        int nv;
        snprintf(dir, sizeof dir, "%s/reference/%s", paperdir, origin_names[o]);
        rc = list_tables(dir, 1, values, &nv, err);
        for (int i = 0; i < nv; i++) {
            if (!rc && !bsearch(&values[i], names, (size_t)*n, sizeof *names, cmp_str))
                rc = hj_error_set(err, HJ_EFORMAT, "%s/%s.tsv: no table %s/reference/%s.tsv defines its rows and kinds", dir,
                                  values[i], paperdir, values[i]);
            free(values[i]);
        }
    }
    if (rc) while (*n) free(names[--*n]);
    return rc;
}

static int check_paper(const char *name, const char *paperdir, const char *resdir, int quick, tally *total)
{
    hj_error err;
    accepted_list acc;
    reason_list reasons;
    char *names[MAXTABLES];
    int n = 0, rc = 0;
    if (load_paper_accepted(paperdir, quick, &reasons, &acc, &err)) {
        fprintf(stderr, "%s: %s\n", prog, err.msg);
        return -1;
    }
    if (paper_tables(paperdir, names, &n, &err)) {
        fprintf(stderr, "%s: %s\n", prog, err.msg);
        free_accepted(&acc), free_reasons(&reasons);
        return -1;
    }
    for (int i = 0; i < n; i++) {
        if (rc == 0 && check_table(name, paperdir, names[i], resdir, quick, &acc, NULL, total) < 0) rc = -1;
        free(names[i]);
    }
    for (int i = 0; i < acc.n && rc == 0; i++)
        if (!acc.cells[i].used && !quick)
            fprintf(stderr, "%s: note: %s/accepted.tsv names %s %s %s, which no reference table has\n", prog, paperdir,
                    acc.cells[i].table, acc.cells[i].key, acc.cells[i].quantity);
    free_accepted(&acc), free_reasons(&reasons);
    return rc;
}

/* Write an accepted list (rows in order) to path, atomically. */
static int write_accepted(const char *path, const char *name, const accepted_list *acc, int quick, hj_error *err)
{
    hj_out out;
    int rc = hj_out_open(&out, path, err);
    if (rc) return rc;
    fprintf(out.fp, "# Accepted verdicts of %s's cells that are not a match%s; reasons by id in reasons.tsv.\n"
                    "# Written by hjcheck --accept (make accept); make check fails when a cell is worse than its verdict here.\n"
                    "table\tkey\tquantity\tverdict\treason\n",
            name, quick ? ", for the quick run only" : "");
    for (int i = 0; i < acc->n; i++)
        fprintf(out.fp, "%s\t%s\t%s\t%s\t%s\n", acc->cells[i].table, acc->cells[i].key, acc->cells[i].quantity,
                hj_verdict_name((hj_verdict)acc->cells[i].verdict), acc->cells[i].reason);
    return hj_out_commit(&out, err);
}

/* Append "id<TAB>text" to reasons.tsv (created with its header if absent). */
static int add_reason(const char *path, const char *id, const char *text, int exists, hj_error *err)
{
    hj_out out;
    int rc = hj_out_open(&out, path, err);
    if (rc) return rc;
    if (exists) {
        FILE *in = fopen(path, "r");
        if (!in) { hj_out_abort(&out); return hj_error_set(err, HJ_EIO, "%s: %s", path, strerror(errno)); }
        int c;
        while ((c = fgetc(in)) != EOF) fputc(c, out.fp);
        fclose(in);
    } else {
        fprintf(out.fp, "# Reasons for accepted verdicts, each stated once; accepted.tsv names them by id.\nid\ttext\n");
    }
    fprintf(out.fp, "%s\t%s\n", id, text);
    return hj_out_commit(&out, err);
}

/* --accept: compare table, then record its verdicts with reason id. */
static int accept_table(const char *name, const char *paperdir, const char *resdir, int quick, const char *table,
                        const char *id, const char *text)
{
    char apath[4096], rpath[4096];
    hj_error err;
    reason_list reasons;
    accepted_list acc = {NULL, 0};
    snprintf(rpath, sizeof rpath, "%s/reasons.tsv", paperdir);
    snprintf(apath, sizeof apath, "%s/%s", paperdir, quick ? "accepted-quick.tsv" : "accepted.tsv");
    if (strchr(id, '\t') || strchr(id, '\n') || strchr(id, ' ') || (text && (strchr(text, '\t') || strchr(text, '\n')))) {
        fprintf(stderr, "%s: a reason id has no blanks, and neither it nor its text a tab or newline\n", prog);
        return 2;
    }
    if (load_reasons(rpath, &reasons, &err)) { fprintf(stderr, "%s: %s\n", prog, err.msg); return 2; }
    const char *known = reason_text(&reasons, id);
    int rc = 0;
    if (!known && !text) {
        fprintf(stderr, "%s: reason '%s' is not in %s: give its text with --reason-text\n", prog, id, rpath);
        rc = 2;
    } else if (known && text && strcmp(known, text)) {
        fprintf(stderr, "%s: reason '%s' already has another text in %s\n", prog, id, rpath);
        rc = 2;
    } else if (load_accepted(apath, &reasons, &acc, &err)) {
        fprintf(stderr, "%s: %s\n", prog, err.msg);
        rc = 2;
    }
    if (rc) { free_accepted(&acc), free_reasons(&reasons); return rc; }

    /* The comparison itself runs against the lists make check would use. */
    accepted_list gate;
    reason_list gate_reasons;
    computed_list got = {NULL, 0, 0};
    tally t = {{0}, 0, 0, 0};
    if (load_paper_accepted(paperdir, quick, &gate_reasons, &gate, &err)) {
        fprintf(stderr, "%s: %s\n", prog, err.msg);
        rc = 2;
    } else {
        if (check_table(name, paperdir, table, resdir, quick, &gate, &got, &t) < 0) rc = 2;
        free_accepted(&gate), free_reasons(&gate_reasons);
    }
    int added = 0, dropped = 0, kept = 0;
    if (!rc) {
        /* Keep other tables' rows; replace or drop this table's computed cells. */
        accepted_list next = {calloc((size_t)acc.n + (size_t)got.n + 1, sizeof(accepted_cell)), 0};
        if (!next.cells) { fprintf(stderr, "%s: out of memory\n", prog); rc = 2; }
        for (int i = 0; !rc && i < acc.n; i++) {
            accepted_cell *a = &acc.cells[i];
            int covered = 0;
            for (int k = 0; k < got.n && !covered; k++)
                covered = !strcmp(a->table, table) && !strcmp(a->key, got.cells[k].key) &&
                          !strcmp(a->quantity, got.cells[k].quantity);
            if (covered) { dropped++; continue; }
            next.cells[next.n++] = *a;
        }
        /* With --quick, a cell that now matches but that accepted.tsv
         * accepts at a worse verdict is written as a match: the quick
         * check reads accepted.tsv under accepted-quick.tsv, so dropping
         * the row would put the full run's exception back over it. */
        accepted_list full = {NULL, 0};
        reason_list full_reasons = {0};
        if (!rc && quick) {
            char fpath[4096];
            snprintf(fpath, sizeof fpath, "%s/accepted.tsv", paperdir);
            if (load_reasons(rpath, &full_reasons, &err) || load_accepted(fpath, &full_reasons, &full, &err)) {
                fprintf(stderr, "%s: %s\n", prog, err.msg);
                rc = 2;
            }
        }
        for (int k = 0; !rc && k < got.n; k++) {
            const accepted_cell *f = quick ? find_accepted(&full, table, got.cells[k].key, got.cells[k].quantity) : NULL;
            const int over_full = got.cells[k].verdict == HJ_MATCH && f && f->verdict > HJ_MATCH;
            if ((got.cells[k].verdict == HJ_MATCH && !over_full) || got.cells[k].verdict == HJ_AMBIGUOUS) continue;
            /* a cell this list already accepts at the same verdict keeps
             * its own reason: blessing one change does not rewrite why the
             * table's other cells were accepted */
            const accepted_cell *old = find_accepted(&acc, table, got.cells[k].key, got.cells[k].quantity);
            const int keep = old && old->verdict == got.cells[k].verdict;
            accepted_cell *a = &next.cells[next.n++];
            memset(a, 0, sizeof *a);
            a->table = (char *)table, a->key = got.cells[k].key, a->quantity = got.cells[k].quantity;
            a->reason = keep ? old->reason : (char *)id, a->verdict = got.cells[k].verdict;
            if (keep) kept++;
            else added++;
        }
        free_accepted(&full), free_reasons(&full_reasons);
        if (!rc && !known && add_reason(rpath, id, text, reasons.n > 0 || probe(rpath, &err) == 1, &err)) {
            fprintf(stderr, "%s: %s\n", prog, err.msg);
            rc = 2;
        }
        if (!rc && write_accepted(apath, name, &next, quick, &err)) {
            fprintf(stderr, "%s: %s\n", prog, err.msg);
            rc = 2;
        }
        free(next.cells); /* its strings belong to acc, got and the arguments */
    }
    if (!rc)
        printf("%s %s: %d cell%s accepted with reason '%s', %d kept at their verdict and reason (%d earlier row%s of "
               "the table replaced) in %s\n",
               name, table, added, hj_plural(added), id, kept, dropped, hj_plural(dropped), apath);
    free(got.cells);
    free_accepted(&acc), free_reasons(&reasons);
    return rc;
}

static void usage(FILE *f)
{
    fprintf(f, "usage: %s --results DIR [--quick] [--no-fail] NAME=PAPERDIR ...\n"
               "       %s --results DIR [--quick] --accept TABLE --reason ID [--reason-text TEXT] NAME=PAPERDIR\n"
               "       %s --rules   (print the comparison rules as Markdown)\n"
               "Compares reference with computed tables; see the header of common/tools/hjcheck.c.\n",
            prog, prog, prog);
}

/* One message for a usage error, then exit status 2. */
static int bad_usage(const char *fmt, const char *arg)
{
    fprintf(stderr, "%s: ", prog);
    fprintf(stderr, fmt, arg);
    fprintf(stderr, " (see %s --help)\n", prog);
    return 2;
}

int main(int argc, char **argv)
{
    hj_cli_check_stdout("hjcheck");
    const char *resdir = NULL, *accept = NULL, *reason = NULL, *reason_text_arg = NULL;
    int quick = 0, nofail = 0, npapers = 0;
    const char *papers[64];
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--help")) { usage(stdout); return 0; }
        if (!strcmp(a, "--rules")) { hj_compare_rules(stdout); return 0; }
        if (!strcmp(a, "--quick")) quick = 1;
        else if (!strcmp(a, "--no-fail")) nofail = 1;
        else if (!strcmp(a, "--results") || !strcmp(a, "--accept") || !strcmp(a, "--reason") ||
                 !strcmp(a, "--reason-text")) {
            if (i + 1 >= argc || argv[i + 1][0] == '\0') return bad_usage("%s needs a value", a);
            const char *v = argv[++i];
            if (!strcmp(a, "--results")) resdir = v;
            else if (!strcmp(a, "--accept")) accept = v;
            else if (!strcmp(a, "--reason")) reason = v;
            else reason_text_arg = v;
        } else if (a[0] == '-') return bad_usage("unknown option '%s'", a);
        else if (!strchr(a, '=') || strchr(a, '=') == a || strlen(a) >= 1024)
            return bad_usage("expected NAME=PAPERDIR, got '%s'", a);
        else if (npapers == 64) return bad_usage("at most 64 papers, got more at '%s'", a);
        else papers[npapers++] = a;
    }
    if (!resdir) return bad_usage("%s", "--results DIR is required");
    if (npapers == 0) return bad_usage("%s", "name at least one NAME=PAPERDIR");
    if ((reason || reason_text_arg) && !accept) return bad_usage("%s", "--reason goes with --accept");
    if (accept && (!reason || npapers != 1)) return bad_usage("%s", "--accept TABLE needs --reason ID and one NAME=PAPERDIR");
    if (accept) {
        char name[1024];
        snprintf(name, sizeof name, "%s", papers[0]);
        char *eq = strchr(name, '=');
        *eq = '\0';
        return accept_table(name, eq + 1, resdir, quick, accept, reason, reason_text_arg);
    }
    tally total = {{0}, 0, 0, 0};
    int rc = 0;
    for (int i = 0; i < npapers; i++) {
        char name[1024];
        snprintf(name, sizeof name, "%s", papers[i]);
        char *eq = strchr(name, '=');
        *eq = '\0';
        if (check_paper(name, eq + 1, resdir, quick, &total) < 0) rc = 2;
    }
    printf("check: %d passed, %d failed\n", total.passed, total.failed);
    if (rc) return rc;
    return (total.failed && !nofail) ? 1 : 0;
}
