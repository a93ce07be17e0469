/* p3_prog.h -- what the paper-3 programs share: the command line
 * (--help, --quick, --out-dir, --sizes, --max-n, --tables, --extra,
 * --plan, --published), the closed sets of the examples, the output
 * tables (CPU time and peak memory come from hj_sys.h), and the rule
 * that decides which cells of the timing tables run (storage, hjbstep).  p3_args_parse() and p3_die() are for main()
 * only (they print and exit, as hj_cli_fail does); the rest returns codes. */
#ifndef P3_PROG_H
#define P3_PROG_H

#include <math.h>
#include <stdio.h>

#include "hj_band.h"
#include "hj_error.h"
#include "hj_io.h"

#define P3_MAX_SIZES 16

/* The initial set of Table 5's HJB step (hjbstep, bench_ub): the unit
 * ball at the origin of R^3.  The fraction of the cell [blo, bhi] inside
 * it (hj_ub_avg_ball, 4 subdivisions) and whether the cell is wholly
 * inside or outside (hj_ub_ball_uniform); ctx is unused. */
double p3_ball3_avg(const double *blo, const double *bhi, void *ctx);
int p3_ball3_uniform(const double *blo, const double *bhi, void *ctx);

/* The exact sets of the examples are closed: a cell centre on a face is
 * inside.  Their tests allow P3_CLOSED_SLACK dx, so that the round-off of
 * the coordinates (-2 + i dx is ~1e-17 off a face through a centre) does
 * not decide it. */
#define P3_CLOSED_SLACK 1e-9

typedef struct {
    const char *prog;
    const char *out_dir;
    int quick;
    long sizes[P3_MAX_SIZES]; /* --sizes overrides the program's list */
    int nsizes;
    long max_n;               /* --max-n: skip the sizes above it (0: none) */
    long tables[P3_MAX_SIZES]; /* --tables: only these table numbers (none: all) */
    int ntables;
    int extra;                /* --extra: also the cells the paper has no value for, whatever their cost */
    int plan;                 /* --plan: print which cells would run and why, run nothing */
    const char *published;    /* --published: the directory of the paper's tables (published/tableN.tsv) */
    const char *extra_help;   /* set before parsing: the program offers --extra, --plan and --published (NULL: not) */
} p3_args;

/* Whether table number t was asked for (all when --tables is absent). */
int p3_want(const p3_args *a, long t);

/* Parse the common options (hj_cli's option table); usage is printed for
 * --help (then exit 0).  `extra` (may be NULL) is appended to the usage
 * text; --tables takes the numbers first_table..last_table, the tables
 * the program makes. */
void p3_args_parse(p3_args *a, int argc, char **argv, const char *summary, const char *extra, long first_table,
                   long last_table);

/* Print "prog: message" and exit 1 (a run that failed). */
_Noreturn void p3_die(const char *prog, const hj_error *err);

/* Open DIR/NAME for an atomic write (hj_out), creating DIR. */
int p3_open(hj_out *out, const char *dir, const char *name, hj_error *err);

/* Figure data: nf fields on the grid of n nodes per direction in d = 2, 3
 * (field values f[j][l n + i] in the layout of hj_ub_values, node
 * coordinates lo + i dx) as a gnuplot block over the index box
 * [i0[k], i0[k] + m[k]): one line "x y [z] f1 f2 ..." per node, last index
 * fastest, a blank line after each run of it (gnuplot's grid format) and
 * two at the end (the next `index`).  HJ_EIO on a write error. */
int p3_fig_block(FILE *fp, int d, int n, double lo, double dx, const int *i0, const int *m, int nf,
                 const double *const *f, hj_error *err);

/* "%.4g", or "-" for a NaN (no value). */
const char *p3_num(char *buf, double v);

/* ---- which cells of the timing tables run (storage, hjbstep) ----------
 *
 * Every cell the paper has a value for runs, unless its predicted CPU time
 * exceeds the program's budget.  A cell the paper has no value for (its
 * '-' cells, and our own columns) is compared with nothing: it runs only
 * when predicted under P3_EXTRA_BUDGET seconds and when it is not a full
 * store above 1 GB, unless --extra asks for all of them.  The prediction
 * is the time measured at the previous size times the growth between the
 * two sizes before (the ratio of their times, or 2^d with fewer than two,
 * at least 2).  A size after one that did not run (or gave no value) does
 * not run either. */

#define P3_EXTRA_BUDGET 2.0 /* CPU seconds */

/* The paper's values of one table: DIR/<table>.tsv, the file the check
 * reads (hjcheck), whose '# key:' header names the key columns. */
typedef struct {
    hj_table t;
    int nkey;
    int key[4]; /* the key columns' indices */
} p3_pub;

/* Read DIR/NAME.tsv; HJ_EIO / HJ_EFORMAT (no usable '# key:') otherwise. */
int p3_pub_read(p3_pub *p, const char *dir, const char *name, hj_error *err);
void p3_pub_free(p3_pub *p);
/* Whether the paper gives a value for the quantity q (in its column q or
 * q_ratio: seconds, megabytes or their "Order") in the row whose key
 * columns hold the integers key[0 .. nkey-1]. */
int p3_pub_has(const p3_pub *p, const long *key, const char *q);

/* Whether a store of the given kind on n^d nodes is a full one (FS, FLS:
 * 9 bytes a node) above 1 GB. */
int p3_store_big(hj_band_kind kind, int d, long n);

typedef struct {
    double budget; /* CPU seconds a cell with a published value may be predicted to take; INFINITY: any */
    int extra;     /* --extra: every cell as one with a published value */
    double scale;  /* the predicted seconds are scale x the recorded time x the growth */
} p3_rule;

/* One column of a table (one store across the sizes): the times recorded
 * at the sizes before, NaN where the cell did not run or gave no value. */
typedef struct {
    int n;          /* sizes recorded */
    double t1, t2;  /* the last and the one before */
} p3_col;

#define P3_COL_INIT {0, NAN, NAN}

/* Record a cell's time (NaN: not run or no value). */
void p3_col_record(p3_col *c, double t);

typedef enum {
    P3_RUN,
    P3_SKIP_SMALLER, /* a smaller size of the column did not run */
    P3_SKIP_BIG,     /* no published value, and a full store above 1 GB */
    P3_SKIP_COST     /* predicted above the budget */
} p3_decision;

/* Whether the next cell of column c runs: d is the dimension (the growth
 * 2^d), published whether the paper has a value for it, big whether it
 * is a full store above 1 GB.  A column that is never timed (memory)
 * passes an empty one. */
p3_decision p3_rule_decide(const p3_rule *r, const p3_col *c, int d, int published, int big);
/* "run" or "skip: why", as --plan shows it. */
const char *p3_decision_text(char *buf, size_t size, const p3_rule *r, p3_decision dec, int published);
/* Whether a skipped cell is named in the table's closing comment line:
 * no published value, and the first skipped size of its column. */
int p3_rule_listed(p3_decision dec, int published);

/* --plan: which cells of the timing tables would run, without timing
 * anything.  Whether a cell runs may depend on the times measured at the
 * smaller sizes; so the program walks its tables twice, once as if every
 * measured time were 0 s (world 0, the cheapest) and once as if it were
 * P3_PLAN_DEAR s (world 1), noting each decision as text ("run" or
 * "skip: why") under a label.  A cell whose text is the same in both
 * worlds is decided by the rule alone; one whose text differs depends on
 * the measured times ("depends on measured time").  Under the rule of
 * p3_prog.c a cell that runs in world 1 runs whatever the times, and one
 * skipped in world 0 is skipped whatever the times. */
#define P3_PLAN_DEAR 1e30

typedef struct {
    int world; /* 0 or 1: the world being walked */
    int n[2];
    int cap[2];
    char **label[2], **text[2];
} p3_plan;

/* The time a cell "measures" in the current world. */
double p3_plan_time(const p3_plan *p);
/* Note the decision about one cell (or a table's closing comment line)
 * in the current world; HJ_ENOMEM if it cannot be stored. */
int p3_plan_note(p3_plan *p, const char *label, const char *text, hj_error *err);
/* Print "label<TAB>text" for each note of world 0, or "label<TAB>depends
 * on measured time (if cheap: <text 0>; if dear: <text 1>)" where the
 * two worlds differ; HJ_EFORMAT if the worlds did not note the same
 * labels in the same order, HJ_EIO on a write error.  A label holds what
 * does not depend on the world (e.g. whether the paper has a value). */
int p3_plan_print(const p3_plan *p, FILE *fp, hj_error *err);
void p3_plan_free(p3_plan *p);

#endif
