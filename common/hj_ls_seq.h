/* hj_ls_seq.h -- time sequences of the level set kernel: the output times
 * of an integration and the state written at each of them as one gnuplot
 * index block (Mitchell's toolbox, section 2.1: convectionDemo integrates
 * from plot time to plot time, tPlot = tMax / (plotSteps - 1), and draws
 * the zero level set at each; every later example does the same).
 *
 * The blocks are hj_ls_write_block's (hj_ls_io.h), separated by two blank
 * lines (gnuplot's `index` 0, 1, ...).  The writer is also an
 * hj_ls_output_fn (hj_ls_ode.h), so that it sees every output time of an
 * integration; it can flip a flag once a given output time is written
 * (the toolbox's switchValue, with the switch made exactly at an output
 * time so that no Runge-Kutta step mixes the two values) and hand every
 * state to a further callback.  Nothing here prints to stdout or exits.
 */
#ifndef HJ_LS_SEQ_H
#define HJ_LS_SEQ_H

#include <stdio.h>

#include "hj_error.h"
#include "hj_ls_grid.h"
#include "hj_ls_ode.h"
#include "hj_ls_term.h"

#ifdef __cplusplus
extern "C" {
#endif

/* tspan[k] = t0 + (t1 - t0) k / (n - 1), k = 0 .. n - 1, the last exactly
 * t1 (n >= 2). */
void hj_ls_seq_times(double t0, double t1, int n, double *tspan);

#define HJ_LS_SEQ_MAXEXTRA 3

/* The writer, set up by hj_ls_seq_init and then adjusted by the caller.
 *   fp        the stream (NULL: nothing is written; the flag and the hook
 *             still work);
 *   name      the state's column;
 *   digits    > 0: each block starts with "# t = <t>" (t to that many
 *             significant digits); 0: no such line, and the state's
 *             column is named "<name>(t=<t>)" (6 digits);
 *   extra     nextra further fields written beside the state;
 *   flag      when set, *flag = 1 once the block of an output time
 *             t >= t_switch has been written;
 *   hook      when set, called with every state after its block. */
typedef struct {
    FILE *fp;
    const hj_ls_grid *g;
    const char *name;
    int digits;
    int nextra;
    const char *extra_name[HJ_LS_SEQ_MAXEXTRA];
    const double *extra[HJ_LS_SEQ_MAXEXTRA];
    int *flag;
    double t_switch;
    hj_ls_output_fn hook;
    void *hook_ctx;
    long blocks; /* blocks written so far */
} hj_ls_seq;

void hj_ls_seq_init(hj_ls_seq *s, FILE *fp, const hj_ls_grid *g, const char *name, int digits);

/* The block of state y at time t.  HJ_EIO on a write error. */
int hj_ls_seq_write(hj_ls_seq *s, double t, const double *y, hj_error *err);

/* hj_ls_output_fn with ctx = hj_ls_seq: the block, then the flag, then
 * the hook. */
int hj_ls_seq_output(int k, double t, const double *y, void *ctx, hj_error *err);

/* Integrate y over tspan[0 .. n - 1] (hj_ls_ode; opts and stats may be
 * NULL) with s seeing the initial state (k = 0) and every output time. */
int hj_ls_seq_solve(int order, const hj_ls_grid *g, const hj_ls_term *term, const double *tspan, int n, double *y,
                    const hj_ls_ode_opts *opts, hj_ls_seq *s, hj_ls_ode_stats *stats, hj_error *err);

/* The same with the blocks written to the file path (atomically, hj_out:
 * a failed run leaves no file; path NULL: no file, s->fp as set). */
int hj_ls_seq_solve_file(const char *path, int order, const hj_ls_grid *g, const hj_ls_term *term, const double *tspan,
                         int n, double *y, const hj_ls_ode_opts *opts, hj_ls_seq *s, hj_ls_ode_stats *stats,
                         hj_error *err);

#ifdef __cplusplus
}
#endif

#endif
