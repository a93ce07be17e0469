/* p3_prog.h -- what the paper-3 programs share: the command line
 * (--help, --quick, --out-dir, --sizes, --max-n, --tables, --extra), the closed
 * sets of the examples and the output tables (CPU time and peak memory
 * come from hj_sys.h).  p3_args_parse() and p3_die() are for main()
 * only (they print and exit, as hj_cli_fail does); the rest returns codes. */
#ifndef P3_PROG_H
#define P3_PROG_H

#include <stdio.h>

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
    const char *extra_help;   /* set before parsing: the program offers --extra and --plan (NULL: not) */
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
