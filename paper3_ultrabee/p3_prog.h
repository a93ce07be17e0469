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
    const char *extra_help;   /* set before parsing: the program offers --extra (NULL: not) */
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

#endif
