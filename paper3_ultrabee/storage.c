/*
# Storage comparison of section 3.3-3.4 (Tables 1-4)

**Problem.** A fixed front on the grid of n nodes per direction on
[-2, 2]^d (end points included), stored in each structure of section 3:
FS (full), FLS (full + unsorted band list), LS (one sorted list with
compressed keys), CRS (one dynamic list per first index) and SSD (a static
(d-1)-dimensional array of lists along the last index), all behind the
interface of hj_band.h; SSDC is the variant of Remark 3.1 and SSDA the
same line heads with contiguous sorted arrays instead of linked lists.  Fronts
(p3_front.h): Example 1, six nested spheres (radii 0.3 k: the paper does not give them, these reproduce its N_nb
exactly in d = 2 and 3);
Example 2, the cylinder rho <= 0.5, |x_d| <= 1.6 along the last axis
(fitted to the published N_nb in the same way, within 5 %).  The band is F+ u F-, the
nodes with a face neighbour on the other side, stored with values +-1.

**Measured.**
* Tables 1, 2 -- neighbour search: for every band node (every node for
  FS) the values of its 2d face neighbours are looked up in the structure;
  CPU seconds (repeated until 0.05 s and averaged), and the ratios between
  successive n (the published "Order") and SSD/FLS.
* Table 3 -- update (d = 3): insert every face neighbour of F+ that is not
  stored (value ND), then remove every node of F-; only the inserts and
  removes are timed.  Which nodes to insert depends on the band only: it
  is found once per front, not once per structure.
* Table 4 -- memory (d = 3, Example 1): bytes allocated by the structure
  holding the band, in MB (10^6 bytes), and its ratio between successive
  n.  The published "Out of mem." cells came from a 4 GB laptop: the
  full structures at n = 800 are built once under a 4 GB address-space
  limit (setrlimit RLIMIT_AS), where they must fail cleanly with "out of
  memory" (column *_4GB), and, with --extra, once without it.  SSD_B_node: SSD's bytes
  per band node.

Timings are compared only as ratios (the published ones come from a
2 GHz 2008 laptop).  LS and CRS get slow as O(N^d) per sweep in d >= 3: a
size whose predicted time (previous time x ratio of the last two sizes,
or x 2^d) exceeds 100 s (5 s with `--quick`) is not run ('-'), like the published ">1e3" cells.
The 100 s are chosen so that every size with a published time runs: the
largest, LS and CRS of Table 1 at d = 3, n = 400, are predicted at 83 s
and 63 s; the next ones (Table 3's CRS at n = 800; Table 1's LS at n =
800, 660 s) have no published value.  Table 3's CRS at n = 800, once
predicted at 110 s, now runs (predicted 91 s, measured 99 s on 26
November 2026): the faster list walks brought it under the budget.

**Cost.** What is timed is the sweeps and the updates above; everything
else is kept cheap without touching them: the band of a front is found
once per row and every structure of the row is built from it in order
(hj_band_append: O(1) per node, where inserting searched CRS's rows from
their heads, O(row^2) per row); Table 4 takes the bytes of the stores
Table 1 builds for its d = 3 rows and builds only the ones Table 1 skips;
FS and FLS sit on transparent huge pages (hj_sys_alloc_large: filling
14.4 GB 4 KB page by page cost minutes on this virtual machine) and FLS
no longer fills values it never reads.  Two changes reach the timed
code, both the same algorithm with less waste: the list kinds keep keys
and links apart from the values (a walk reads 16 bytes per step instead
of 24; LS and CRS sweeps about 10 % faster), and FS's sweep counts its
indices up instead of dividing them out of the linear index.  Every
structure does the same work per lookup at every size as before, so the
Order columns (ratios between sizes) keep their meaning; SSD_over_FLS
can move by the few per cent SSD's walks gained (26 November 2026).
The cells the paper has no value for (its '-' cells: FS and FLS at
800^3 and 200^4, CRS and FLS in Table 3 at n = 800, LS and CRS where
they exceed the budget; Table 2's FS, LS and CRS columns; our SSDC and
SSDA) are compared with nothing: they run only when predicted under
P3_EXTRA_BUDGET (2 s) and without a full store above 1 GB, and the table's
closing comment line lists the ones left out; --extra (`make paper3
P3_EXTRA=1`) runs them all within the 100 s, as every published cell
runs.  The rule is p3_rule_decide (p3_prog.h), shared with hjbstep; which
cells the paper has a value for is read from published/table1-4.tsv, the
files the check compares against.  `--plan` prints, without timing
anything, each cell's decision and why, or "depends on measured time"
where the prediction decides.  This took Table 1 from 683 to about 450 CPU seconds, Table 2
from 327 to 18, Tables 3-4 from 156 to 44 (26 November 2026).
With `make paper3` the tables run as three processes (Table 1, Table 2,
Tables 3-4; rules.mk); a full store above 1 GB is built only under a lock
on OUT_DIR/.memlock, so that two runs never hold two (FLS at 200^4 is
14.4 GB).

**Parameters.** Published sizes: Table 1 d = 2: 400, 800, 1600; d = 3:
100, 200, 400, 800; d = 4: 25, 50, 100, 200.  Table 2: d = 3 and 4 as in
Table 1.  Table 3: 50 ... 800.  Table 4: 100 ... 800.  `--quick`: the two
smallest sizes of each group.

**Output.** table1.tsv ... table4.tsv (table4.tsv also holds the runs under the
4 GB limit, which notes/table4_limits.md presents); fig05_fronts.dat, the band F+ u F- of
both fronts in d = 2 on the 100^2 grid (x y side), drawn as Figure 5
(fig05.png, plot/fig05.gp), written with Table 1.
*/
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

#include "hj_band.h"
#include "hj_cli.h"
#include "hj_sys.h"
#include "p3_front.h"
#include "p3_prog.h"

/* Which cells run (p3_prog.h): a published one within 100 s predicted (5
 * with --quick, see the header), one the paper has no value for (its '-'
 * cells, and the SSDC and SSDA columns) within P3_EXTRA_BUDGET and not a
 * full store above 1 GB, unless --extra (`make paper3 P3_EXTRA=1`) asks
 * for all of them within the 100 s.  The cells left out are listed in a
 * comment line at the end of each table. */
static p3_rule RULE = {100.0, 0, 1.0};

/* The paper's tables 1-4 (published/tableN.tsv): which cells it has a
 * value for. */
static p3_pub PUB[4];

/* The cells skipped as extra, for the table's closing comment. */
static char SKIPPED[2048];

/* kind at (key = value, N = n) and the larger N after it. */
static void skipped_add(hj_band_kind kind, const char *key, int value, long n)
{
    const size_t len = strlen(SKIPPED);
    if (len + 64 < sizeof SKIPPED)
        snprintf(SKIPPED + len, sizeof SKIPPED - len, "%s%s %s=%d N>=%ld", len ? ", " : "", hj_band_kind_name(kind), key, value, n);
}

/* --plan: the decisions are noted here instead of running the cells. */
static int PLANNING = 0;
static p3_plan PLAN;

static void plan_note(const p3_args *a, const char *label, const char *text)
{
    hj_error err;
    if (p3_plan_note(&PLAN, label, text, &err)) p3_die(a->prog, &err);
}

/* Note the decision about a cell: whether the paper has a value for it,
 * run or skip and why (text: NULL for the rule's own). */
static void plan_cell(const p3_args *a, const char *table, const char *key, int value, long n, hj_band_kind kind, int pub,
                      p3_decision dec, const char *text)
{
    char label[96], buf[96];
    snprintf(label, sizeof label, "%s %s=%d N=%ld %s\t%s", table, key, value, n, hj_band_kind_name(kind),
             pub ? "published" : "no published value");
    plan_note(a, label, text ? text : p3_decision_text(buf, sizeof buf, &RULE, dec, pub));
}

/* Whether a cell of the rule runs; a skipped one is noted for the closing
 * comment as the rule says, every one for --plan. */
static int cell_runs(const p3_args *a, const char *table, const char *key, int value, long n, hj_band_kind kind, int d,
                     const p3_col *c, int pub, int big)
{
    const p3_decision dec = p3_rule_decide(&RULE, c, d, pub, big);
    if (PLANNING) plan_cell(a, table, key, value, n, kind, pub, dec, NULL);
    if (p3_rule_listed(dec, pub)) skipped_add(kind, key, value, n);
    return dec == P3_RUN;
}

static void skipped_write(const p3_args *a, const char *table, FILE *fp)
{
    char line[2560] = "";
    if (SKIPPED[0])
        snprintf(line, sizeof line, "# not run, no published value and predicted above %g s of CPU or a full store above 1 GB "
                                    "(storage --extra, make paper3 P3_EXTRA=1 runs them): %s", P3_EXTRA_BUDGET, SKIPPED);
    if (PLANNING) {
        char label[64];
        snprintf(label, sizeof label, "%s closing comment\t", table);
        plan_note(a, label, line[0] ? line : "(none)");
    } else if (line[0])
        fprintf(fp, "%s\n", line);
    SKIPPED[0] = 0;
}

/* ---- one big full store at a time --------------------------------------- */

/* The tables may run as separate processes side by side (`make paper3`
 * runs Table 1 beside Tables 2-4).  A full store (FS, FLS) above 1 GB is
 * built only while holding a write lock (fcntl, released by the process's
 * end) on OUT_DIR/.memlock: the largest, FLS at 200^4, is 14.4 GB, and two
 * of them do not fit in this machine's 24 GB.  The lock is taken before
 * the build, so a wait never enters a timing. */
static int MEMLOCK_FD = -1;

static void memlock_set(int on)
{
    if (MEMLOCK_FD < 0) return;
    struct flock fl = {.l_type = (short)(on ? F_WRLCK : F_UNLCK), .l_whence = SEEK_SET};
    while (fcntl(MEMLOCK_FD, F_SETLKW, &fl) && errno == EINTR) {}
}

typedef struct {
    hj_band *s;
    hj_error *err;
    int rc;
    size_t nb;
    int64_t *plus; /* F+ nodes (linear), for the update test */
    size_t nplus, capplus;
    int64_t *minus;
    size_t nminus, capminus;
    int n, d;
} build_ctx;

static int64_t lin(int d, int n, const int *idx)
{
    int64_t k = 0;
    for (int i = 0; i < d; i++) k = k * n + idx[i];
    return k;
}

static void unlin(int d, int n, int64_t k, int *idx)
{
    for (int i = d - 1; i >= 0; i--) { idx[i] = (int)(k % n); k /= n; }
}

static int push(int64_t **a, size_t *n, size_t *cap, int64_t v)
{
    if (*n == *cap) {
        size_t c = *cap ? 2 * *cap : 4096;
        int64_t *p = realloc(*a, c * sizeof *p);
        if (!p) return HJ_ENOMEM;
        *a = p;
        *cap = c;
    }
    (*a)[(*n)++] = v;
    return HJ_OK;
}

static int add_node(const int *idx, int side, void *vctx)
{
    build_ctx *c = vctx;
    c->nb++;
    if (c->s && (c->rc = hj_band_append(c->s, idx, side, c->err))) return 1; /* the band comes in order */
    if (c->plus) {
        int64_t k = lin(c->d, c->n, idx);
        if (side > 0 ? push(&c->plus, &c->nplus, &c->capplus, k) : push(&c->minus, &c->nminus, &c->capminus, k)) {
            c->rc = hj_error_set(c->err, HJ_ENOMEM, "out of memory (update lists)");
            return 1;
        }
    }
    return 0;
}

/* The band of the last front asked for, as linear indices times 2 plus 1
 * on F+, in the order p3_front_band gives them (lexicographic): found once
 * and reused by the builds of every structure of a row (at 200^4 finding
 * the band costs about as much as a build). */
static struct {
    int example, d, n;
    int64_t *code;
    size_t len, cap;
} BAND;

static int collect_node(const int *idx, int side, void *vctx)
{
    (void)vctx;
    return push(&BAND.code, &BAND.len, &BAND.cap, 2 * lin(BAND.d, BAND.n, idx) + (side > 0)) ? HJ_ENOMEM : 0;
}

static int band_of(const p3_front *f, hj_error *err)
{
    if (BAND.code && BAND.len && BAND.example == f->example && BAND.d == f->d && BAND.n == f->n) return HJ_OK;
    BAND.example = f->example;
    BAND.d = f->d;
    BAND.n = f->n;
    BAND.len = 0;
    if (p3_front_band(f, collect_node, NULL, err)) { /* only ever out of memory */
        BAND.len = 0;
        return hj_error_set(err, HJ_ENOMEM, "out of memory (band list)");
    }
    return HJ_OK;
}

/* The store of the given kind holding the band of front f. */
static int build(hj_band **s, hj_band_kind kind, const p3_front *f, size_t *nb, hj_error *err)
{
    int rc = band_of(f, err);
    if (rc) return rc;
    rc = hj_band_new(s, kind, f->d, f->n, err);
    if (rc) return rc;
    for (size_t i = 0; i < BAND.len && !rc; i++) {
        int idx[HJ_BAND_DMAX];
        unlin(f->d, f->n, BAND.code[i] >> 1, idx);
        rc = hj_band_append(*s, idx, BAND.code[i] & 1 ? 1 : -1, err); /* the band comes in order */
    }
    *nb = BAND.len;
    if (rc) { hj_band_free(*s); *s = NULL; }
    return rc;
}

/* ---- neighbour search ---------------------------------------------------- */

typedef struct {
    hj_band *s;
    int d, n;
    double sum;
    size_t found;
} search_ctx;

static int search_node(const int *idx, double *v, void *vctx)
{
    search_ctx *c = vctx;
    int j[HJ_BAND_DMAX];
    memcpy(j, idx, sizeof j);
    c->sum += *v;
    for (int k = 0; k < c->d; k++)
        for (int s = -1; s <= 1; s += 2) {
            j[k] = idx[k] + s;
            if (j[k] >= 0 && j[k] < c->n) {
                const double *p = hj_band_find(c->s, j);
                if (p) { c->sum += *p; c->found++; }
            }
            j[k] = idx[k];
        }
    return 0;
}

/* Seconds per search over the band (FS: over the grid). */
static double time_search(hj_band *s, const p3_front *f)
{
    search_ctx c = {s, f->d, f->n, 0, 0};
    int reps = 0;
    const double t0 = hj_sys_cpu_seconds();
    double t;
    do {
        hj_band_foreach(s, search_node, &c);
        reps++;
        t = hj_sys_cpu_seconds() - t0;
    } while (t < 0.05);
    return c.sum == 12345.678 ? 0 : t / reps; /* the sum keeps the loop alive */
}

/* ---- update -------------------------------------------------------------- */

static int cmp64(const void *a, const void *b)
{
    const int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

/* The operations of the update test, which depend on the band only, not on
 * the structure: the face neighbours of F+ that are not stored (sorted,
 * each once) and F- in the order of the band.  Found once per front in an
 * SSDA store (bisection in contiguous lines): a find in the LS list walks
 * from its last position, and the +-e_0 neighbours lie a whole plane of
 * the band away (at N = 800 this untimed search took most of the run
 * when it was done in every structure). */
typedef struct {
    int64_t *ins, *minus;
    size_t nins, nminus;
} update_ops;

static void update_ops_free(update_ops *u)
{
    free(u->ins);
    free(u->minus);
    memset(u, 0, sizeof *u);
}

static int update_lists(const p3_front *f, update_ops *u, hj_error *err)
{
    memset(u, 0, sizeof *u);
    hj_band *s;
    int rc = hj_band_new(&s, HJ_BAND_SSDA, f->d, f->n, err);
    if (rc) return rc;
    build_ctx c = {s, err, 0, 0, NULL, 0, 0, NULL, 0, 0, f->n, f->d};
    c.plus = malloc(sizeof *c.plus);
    c.capplus = 1;
    if (!c.plus) { hj_band_free(s); return hj_error_set(err, HJ_ENOMEM, "out of memory"); }
    p3_front_band(f, add_node, &c, err);
    rc = c.rc;
    size_t capins = 0;
    for (size_t i = 0; i < c.nplus && !rc; i++) {
        int idx[HJ_BAND_DMAX];
        unlin(f->d, f->n, c.plus[i], idx);
        for (int k = 0; k < f->d && !rc; k++)
            for (int sg = -1; sg <= 1 && !rc; sg += 2) {
                idx[k] += sg;
                if (idx[k] >= 0 && idx[k] < f->n && !hj_band_find(s, idx) &&
                    push(&u->ins, &u->nins, &capins, lin(f->d, f->n, idx)))
                    rc = hj_error_set(err, HJ_ENOMEM, "out of memory (update lists)");
                idx[k] -= sg;
            }
    }
    if (!rc) {
        qsort(u->ins, u->nins, sizeof *u->ins, cmp64);
        size_t m = 0;
        for (size_t i = 0; i < u->nins; i++)
            if (m == 0 || u->ins[i] != u->ins[m - 1]) u->ins[m++] = u->ins[i];
        u->nins = m;
    }
    u->minus = c.minus;
    u->nminus = c.nminus;
    free(c.plus);
    hj_band_free(s);
    if (rc) update_ops_free(u);
    return rc;
}

/* Build the band in a store of the given kind, then time the inserts of
 * the unstored neighbours of F+ and the removal of F-. */
static int time_update(hj_band_kind kind, const p3_front *f, const update_ops *u, double *secs, hj_error *err)
{
    hj_band *s;
    size_t nb;
    const int big = p3_store_big(kind, f->d, f->n);
    if (big) memlock_set(1);
    int rc = build(&s, kind, f, &nb, err);
    if (rc) { if (big) memlock_set(0); return rc; }
    const double t0 = hj_sys_cpu_seconds();
    for (size_t i = 0; i < u->nins && !rc; i++) {
        int idx[HJ_BAND_DMAX];
        unlin(f->d, f->n, u->ins[i], idx);
        rc = hj_band_insert(s, idx, 1.0, err);
    }
    for (size_t i = 0; i < u->nminus && !rc; i++) {
        int idx[HJ_BAND_DMAX];
        unlin(f->d, f->n, u->minus[i], idx);
        hj_band_remove(s, idx);
    }
    *secs = hj_sys_cpu_seconds() - t0;
    hj_band_free(s);
    if (big) memlock_set(0);
    return rc;
}

/* ---- tables ----------------------------------------------------------------- */

static const hj_band_kind SEARCH_KINDS[] = {HJ_BAND_FS, HJ_BAND_FLS, HJ_BAND_LS, HJ_BAND_CRS, HJ_BAND_SSD, HJ_BAND_SSDC, HJ_BAND_SSDA};
enum { NSK = 7 };

/* Table 4 measures the stores of Table 1's d = 3 rows (Example 1, n = 100
 * ... 800): the bytes of each store Table 1 builds are kept here (NAN: it
 * did not fit), so that Table 4 builds only the ones Table 1 skipped. */
typedef struct {
    int have;
    double mb;
    size_t nb;
} mem_cell;
static mem_cell MEM_SEEN[NSK][4];

static void search_table(const p3_args *a, const char *table, int example, hj_error *err)
{
    static const long s2[] = {400, 800, 1600}, s3[] = {100, 200, 400, 800}, s4[] = {25, 50, 100, 200};
    hj_out out = {0};
    char name[64];
    snprintf(name, sizeof name, "%s.tsv", table);
    if (!PLANNING) { /* --plan writes no table */
        if (p3_open(&out, a->out_dir, name, err)) p3_die(a->prog, err);
        fprintf(out.fp, "# %s: neighbour search, Example %d, seconds per sweep over the band (FS: over the grid), by storage%s\n", table,
                example, a->quick ? " --quick" : "");
        fprintf(out.fp, "d\tN\tN_nb");
        for (int k = 0; k < NSK; k++) fprintf(out.fp, "\t%s\t%s_ratio", hj_band_kind_name(SEARCH_KINDS[k]), hj_band_kind_name(SEARCH_KINDS[k]));
        fprintf(out.fp, "\tSSD_over_FLS\n");
    }
    for (int d = example == 1 ? 2 : 3; d <= 4; d++) {
        const long *sizes = d == 2 ? s2 : d == 3 ? s3 : s4;
        const int ns = a->quick ? 2 : d == 2 ? 3 : 4;
        double t[NSK][4];
        p3_col col[NSK];
        for (int k = 0; k < NSK; k++) col[k] = (p3_col)P3_COL_INIT;
        for (int i = 0; i < ns; i++) {
            if (a->max_n && sizes[i] > a->max_n) break;
            p3_front f = {example, d, (int)sizes[i], 4.0 / (double)(sizes[i] - 1)};
            size_t nb = 0;
            if (!PLANNING) fprintf(out.fp, "%d\t%ld", d, sizes[i]);
            char line[1024] = "";
            for (int k = 0; k < NSK; k++) {
                t[k][i] = NAN;
                const int big = p3_store_big(SEARCH_KINDS[k], d, f.n);
                const int pub = p3_pub_has(&PUB[example - 1], (const long[]){d, sizes[i]}, hj_band_kind_name(SEARCH_KINDS[k]));
                const int runs = cell_runs(a, table, "d", d, sizes[i], SEARCH_KINDS[k], d, &col[k], pub, big);
                if (runs && PLANNING) {
                    t[k][i] = p3_plan_time(&PLAN);
                    if (example == 1 && d == 3) MEM_SEEN[k][i] = (mem_cell){1, NAN, 0};
                }
                if (!runs || PLANNING) {
                    p3_col_record(&col[k], t[k][i]);
                    continue;
                }
                hj_band *s;
                hj_progress("%s d=%d N=%ld %s ...\n", table, d, sizes[i], hj_band_kind_name(SEARCH_KINDS[k]));
                if (big) memlock_set(1);
                const int rc = build(&s, SEARCH_KINDS[k], &f, &nb, err);
                mem_cell *m = example == 1 && d == 3 ? &MEM_SEEN[k][i] : NULL;
                if (m && (rc == HJ_OK || rc == HJ_ENOMEM)) *m = (mem_cell){1, rc ? NAN : (double)hj_band_bytes(s) / 1e6, nb};
                if (rc == HJ_ENOMEM) { /* beyond this machine: no value */
                    if (big) memlock_set(0);
                    p3_col_record(&col[k], NAN);
                    continue;
                }
                if (rc) p3_die(a->prog, err);
                t[k][i] = time_search(s, &f);
                p3_col_record(&col[k], t[k][i]);
                hj_band_free(s);
                if (big) memlock_set(0);
            }
            if (PLANNING) continue;
            for (int k = 0; k < NSK; k++) {
                char b1[32], b2[32];
                size_t len = strlen(line);
                snprintf(line + len, sizeof line - len, "\t%s\t%s", p3_num(b1, t[k][i]),
                         p3_num(b2, i ? t[k][i] / t[k][i - 1] : NAN));
            }
            char b3[32];
            fprintf(out.fp, "\t%zu%s\t%s\n", nb, line, p3_num(b3, t[4][i] / t[1][i]));
            fflush(out.fp);
        }
    }
    skipped_write(a, table, out.fp);
    if (!PLANNING && hj_out_commit(&out, err)) p3_die(a->prog, err);
}

static const hj_band_kind UPDATE_KINDS[] = {HJ_BAND_FLS, HJ_BAND_LS, HJ_BAND_CRS, HJ_BAND_SSD, HJ_BAND_SSDC, HJ_BAND_SSDA};
enum { NUK = 6 };

static void update_table(const p3_args *a, hj_error *err)
{
    static const long sizes[] = {50, 100, 200, 400, 800};
    hj_out out = {0};
    if (!PLANNING) { /* --plan writes no table */
        if (p3_open(&out, a->out_dir, "table3.tsv", err)) p3_die(a->prog, err);
        fprintf(out.fp, "# table3: update (insert the ND neighbours of F+, remove F-), d = 3, seconds, by storage%s\n",
                a->quick ? " --quick" : "");
        fprintf(out.fp, "ex\tN\tN_nb");
        for (int k = 0; k < NUK; k++) fprintf(out.fp, "\t%s\t%s_ratio", hj_band_kind_name(UPDATE_KINDS[k]), hj_band_kind_name(UPDATE_KINDS[k]));
        fprintf(out.fp, "\tSSD_over_FLS\n");
    }
    for (int ex = 1; ex <= 2; ex++) {
        const int ns = a->quick ? 2 : 5;
        p3_col col[NUK];
        for (int k = 0; k < NUK; k++) col[k] = (p3_col)P3_COL_INIT;
        for (int i = 0; i < ns; i++) {
            if (a->max_n && sizes[i] > a->max_n) break;
            p3_front f = {ex, 3, (int)sizes[i], 4.0 / (double)(sizes[i] - 1)};
            double t[NUK];
            int runs[NUK];
            for (int k = 0; k < NUK; k++) { /* decided first: --plan needs no band */
                const int pub = p3_pub_has(&PUB[2], (const long[]){ex, sizes[i]}, hj_band_kind_name(UPDATE_KINDS[k]));
                runs[k] = cell_runs(a, "table3", "ex", ex, sizes[i], UPDATE_KINDS[k], 3, &col[k], pub,
                                    p3_store_big(UPDATE_KINDS[k], 3, f.n));
                t[k] = runs[k] && PLANNING ? p3_plan_time(&PLAN) : NAN;
                if (!runs[k] || PLANNING) p3_col_record(&col[k], t[k]);
            }
            if (PLANNING) continue;
            build_ctx count = {NULL, err, 0, 0, NULL, 0, 0, NULL, 0, 0, f.n, 3};
            p3_front_band(&f, add_node, &count, err);
            fprintf(out.fp, "%d\t%ld\t%zu", ex, sizes[i], count.nb);
            update_ops u;
            int rc = update_lists(&f, &u, err);
            if (rc) p3_die(a->prog, err);
            for (int k = 0; k < NUK; k++) {
                if (!runs[k]) continue;
                hj_progress("table3 ex=%d N=%ld %s ...\n", ex, sizes[i], hj_band_kind_name(UPDATE_KINDS[k]));
                rc = time_update(UPDATE_KINDS[k], &f, &u, &t[k], err);
                if (rc == HJ_ENOMEM) t[k] = NAN;
                else if (rc) p3_die(a->prog, err);
                p3_col_record(&col[k], t[k]);
            }
            update_ops_free(&u);
            for (int k = 0; k < NUK; k++) {
                char b1[32], b2[32];
                /* col[k].t2: the time at the size before */
                fprintf(out.fp, "\t%s\t%s", p3_num(b1, t[k]), p3_num(b2, i ? t[k] / col[k].t2 : NAN));
            }
            char b3[32];
            fprintf(out.fp, "\t%s\n", p3_num(b3, t[3] / t[0]));
            fflush(out.fp);
        }
    }
    skipped_write(a, "table3", out.fp);
    if (!PLANNING && hj_out_commit(&out, err)) p3_die(a->prog, err);
}

/* Try to build a full store under a 4 GB address-space limit: 4e9 bytes,
 * the unit of the table (MB = 1e6 bytes).  FS at n = 800 needs 4.096e9
 * bytes and fails, as on the paper's 4 GB laptop (whose system took its
 * share too); with 4 GiB = 4.29e9 it would fit. */
static const char *under_4gb(hj_band_kind kind, int n)
{
    struct rlimit old, lim;
    if (getrlimit(RLIMIT_AS, &old)) return "rlimit unavailable";
    lim = old;
    lim.rlim_cur = (rlim_t)4000000000u;
    if (old.rlim_max != RLIM_INFINITY && old.rlim_max < lim.rlim_cur) lim.rlim_cur = old.rlim_max;
    if (setrlimit(RLIMIT_AS, &lim)) return "rlimit unavailable";
    hj_band *s;
    hj_error err;
    const int rc = hj_band_new(&s, kind, 3, n, &err);
    if (!rc) hj_band_free(s);
    setrlimit(RLIMIT_AS, &old);
    return rc == HJ_ENOMEM ? "out_of_memory" : rc ? "error" : "ok";
}

static void memory_table(const p3_args *a, hj_error *err)
{
    static const long sizes[] = {100, 200, 400, 800};
    hj_out out = {0};
    if (!PLANNING) { /* --plan writes no table */
        if (p3_open(&out, a->out_dir, "table4.tsv", err)) p3_die(a->prog, err);
        fprintf(out.fp, "# table4: memory of the band structures, Example 1, d = 3, MB = 1e6 bytes allocated by the structure%s\n",
                a->quick ? " --quick" : "");
        fprintf(out.fp, "d\tN\tN_nb");
        for (int k = 0; k < NSK; k++) fprintf(out.fp, "\t%s\t%s_ratio", hj_band_kind_name(SEARCH_KINDS[k]), hj_band_kind_name(SEARCH_KINDS[k]));
        fprintf(out.fp, "\tSSD_B_node\tFS_4GB\tFLS_4GB\n");
    }
    double mb[NSK][4];
    const int ns = a->quick ? 2 : 4;
    for (int i = 0; i < ns; i++) {
        if (a->max_n && sizes[i] > a->max_n) break;
        p3_front f = {1, 3, (int)sizes[i], 4.0 / (double)(sizes[i] - 1)};
        size_t nb = 0;
        if (!PLANNING) fprintf(out.fp, "3\t%ld", sizes[i]);
        for (int k = 0; k < NSK; k++) {
            hj_band *s;
            mb[k][i] = NAN;
            const int pub = p3_pub_has(&PUB[3], (const long[]){3, sizes[i]}, hj_band_kind_name(SEARCH_KINDS[k]));
            if (MEM_SEEN[k][i].have) {
                if (PLANNING) plan_cell(a, "table4", "d", 3, sizes[i], SEARCH_KINDS[k], pub, P3_RUN, "run: measured by table1");
                mb[k][i] = MEM_SEEN[k][i].mb; nb = MEM_SEEN[k][i].nb; continue;
            }
            /* a store is only built here, not timed: no prediction */
            const p3_col none = P3_COL_INIT;
            const int big = p3_store_big(SEARCH_KINDS[k], 3, f.n);
            if (!cell_runs(a, "table4", "d", 3, sizes[i], SEARCH_KINDS[k], 3, &none, pub, big) || PLANNING) continue;
            hj_progress("table4 N=%ld %s ...\n", sizes[i], hj_band_kind_name(SEARCH_KINDS[k]));
            if (big) memlock_set(1);
            const int rc = build(&s, SEARCH_KINDS[k], &f, &nb, err);
            if (rc == HJ_ENOMEM) { if (big) memlock_set(0); continue; }
            if (rc) p3_die(a->prog, err);
            mb[k][i] = (double)hj_band_bytes(s) / 1e6;
            hj_band_free(s);
            if (big) memlock_set(0);
        }
        if (PLANNING) continue;
        fprintf(out.fp, "\t%zu", nb);
        for (int k = 0; k < NSK; k++) {
            char b1[32], b2[32];
            fprintf(out.fp, "\t%s\t%s", p3_num(b1, mb[k][i]), p3_num(b2, i ? mb[k][i] / mb[k][i - 1] : NAN));
        }
        char bn[32]; /* SSD's bytes per band node (SEARCH_KINDS[4] is SSD) */
        fprintf(out.fp, "\t%s\t%s\t%s\n", p3_num(bn, mb[4][i] * 1e6 / (double)nb), under_4gb(HJ_BAND_FS, f.n),
                under_4gb(HJ_BAND_FLS, f.n));
        fflush(out.fp);
    }
    skipped_write(a, "table4", out.fp);
    if (!PLANNING && hj_out_commit(&out, err)) p3_die(a->prog, err);
}

/* Figure 5: the band F+ u F- of both fronts in d = 2 on the 100^2 grid,
 * "x y side" (side -1 for F-, +1 for F+), index 0 Example 1, index 1
 * Example 2.  Not timed; a few thousand nodes. */
typedef struct {
    FILE *fp;
    double dx;
} fig_ctx;

static int fig_node(const int *idx, int side, void *vctx)
{
    const fig_ctx *c = vctx;
    fprintf(c->fp, "%.6g %.6g %d\n", -2 + idx[0] * c->dx, -2 + idx[1] * c->dx, side);
    return 0;
}

static void fig05(const p3_args *a, hj_error *err)
{
    hj_out out;
    if (p3_open(&out, a->out_dir, "fig05_fronts.dat", err)) p3_die(a->prog, err);
    fprintf(out.fp, "# fig05_fronts.dat: storage, F+ u F- on the 100^2 grid of [-2, 2]^2: x y side; "
                    "index 0 Example 1 (spheres), 1 Example 2 (cylinder)\n");
    for (int ex = 1; ex <= 2; ex++) {
        const p3_front f = {ex, 2, 100, 4.0 / 99};
        fig_ctx c = {out.fp, f.dx};
        if (p3_front_band(&f, fig_node, &c, err)) { hj_out_abort(&out); p3_die(a->prog, err); }
        fputs("\n\n", out.fp);
    }
    if (hj_out_commit(&out, err)) p3_die(a->prog, err);
}

int main(int argc, char **argv)
{
    p3_args a = {.prog = "storage",
                 .extra_help = "also run the cells without a published value that are predicted above 2 s or hold a full "
                               "store above 1 GB (FS and FLS at 800^3 and 200^4; minutes)"};
    p3_args_parse(&a, argc, argv, "Tables 1-4: neighbour search, update and memory of FS, FLS, LS, CRS, SSD.", NULL, 1, 4);
    hj_error err;
    if (a.nsizes) hj_cli_fail(a.prog, HJ_EXIT_USAGE, "--sizes is not supported here (the tables have fixed sizes); use --max-n");
    if (a.quick) RULE.budget = 5.0;
    RULE.extra = a.extra;
    for (int t = 1; t <= 4; t++) {
        char name[16];
        snprintf(name, sizeof name, "table%d", t);
        if (p3_want(&a, t) && p3_pub_read(&PUB[t - 1], a.published, name, &err)) p3_die(a.prog, &err);
    }
    if (a.plan) { /* the two walks of p3_plan, as the tables would run in one process */
        PLANNING = 1;
        for (PLAN.world = 0; PLAN.world < 2; PLAN.world++) {
            memset(MEM_SEEN, 0, sizeof MEM_SEEN);
            if (p3_want(&a, 1)) search_table(&a, "table1", 1, &err);
            if (p3_want(&a, 2)) search_table(&a, "table2", 2, &err);
            if (p3_want(&a, 3)) update_table(&a, &err);
            if (p3_want(&a, 4)) memory_table(&a, &err);
        }
        if (p3_plan_print(&PLAN, stdout, &err)) p3_die(a.prog, &err);
        p3_plan_free(&PLAN);
        for (int t = 0; t < 4; t++) p3_pub_free(&PUB[t]);
        return 0;
    }
    char lock[4096];
    if (snprintf(lock, sizeof lock, "%s/.memlock", a.out_dir) < (int)sizeof lock) {
        if (hj_mkdirs(a.out_dir, &err)) p3_die(a.prog, &err);
        MEMLOCK_FD = open(lock, O_RDWR | O_CREAT, 0644); /* no lock file: run unlocked */
    }
    if (p3_want(&a, 1)) fig05(&a, &err);
    if (p3_want(&a, 1)) search_table(&a, "table1", 1, &err);
    if (p3_want(&a, 2)) search_table(&a, "table2", 2, &err);
    if (p3_want(&a, 3)) update_table(&a, &err);
    if (p3_want(&a, 4)) memory_table(&a, &err);
    free(BAND.code);
    for (int t = 0; t < 4; t++) p3_pub_free(&PUB[t]);
    return 0;
}
