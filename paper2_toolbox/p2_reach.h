/* p2_reach.h -- helpers shared by the demos of sections 2.5 and 2.6 of the
 * toolbox (burgers_lf, nonconvex_lf, air3d, acoustic, air_mode; session
 * h3): the toolbox's accuracy and dissipation names, the measure of
 * {phi < 0} on a grid with a periodic dimension, node counts, and a log of
 * a reachable set's measure and monotonicity at the output times of an
 * integration.  Library code: nothing prints or exits.
 */
#ifndef P2_REACH_H
#define P2_REACH_H

#include <stdio.h>

#include "hj_error.h"
#include "hj_ls_grid.h"

/* The toolbox's accuracy levels: low = first order upwind + RK1, medium =
 * ENO2 + RK2, high = ENO3 + RK3, veryHigh = WENO5 + RK3. */
enum { P2_LOW, P2_MEDIUM, P2_HIGH, P2_VERYHIGH, P2_NACC };
const char *p2_accuracy_name(int acc);
int p2_accuracy_scheme(int acc);
int p2_accuracy_order(int acc);
/* Parse "low", "medium", "high", "veryHigh". */
int p2_parse_accuracy(const char *s, int *acc, hj_error *err);

/* 'global', 'local', 'locallocal' <-> HJ_LS_GLF, HJ_LS_LLF, HJ_LS_LLLF. */
const char *p2_dissipation_name(int diss);
int p2_parse_dissipation(const char *s, int *diss, hj_error *err);

/* Measure of {phi < 0} (hj_ls_measure, second order).  When periodic_dim
 * >= 0, the cells between the last node and the first node's periodic
 * image in that dimension count too (the period is N dx). */
int p2_measure(const hj_ls_grid *g, const double *phi, int periodic_dim, double *m, hj_error *err);

/* Number of interior nodes where b > a (a set that only grows has phi
 * non-increasing in time, so this is 0 from an earlier a to a later b). */
long p2_count_increase(const hj_ls_grid *g, const double *a, const double *b);

/* Number of interior nodes where a and b differ in any bit. */
long p2_count_differ(const hj_ls_grid *g, const double *a, const double *b);

/* Log of a reachable set computation: at the initial time and at every
 * output time of hj_ls_ode, the measure of {phi < 0} and the number of
 * nodes at which phi increased since the previous output.  Pass
 * p2_reach_output as hj_ls_ode's output callback with the log as context;
 * it calls user(k, t, y, user_ctx, err) too when set (to write blocks). */
#define P2_MAXT 64
typedef int (*p2_snapshot_fn)(int k, double t, const double *y, void *ctx, hj_error *err);
typedef struct {
    const hj_ls_grid *g;
    int periodic_dim;
    double *prev;
    int n;
    double t[P2_MAXT], measure[P2_MAXT];
    long increased[P2_MAXT];
    p2_snapshot_fn user;
    void *user_ctx;
} p2_reach_log;
int p2_reach_log_init(p2_reach_log *log, const hj_ls_grid *g, int periodic_dim, double t0, const double *y0,
                      p2_snapshot_fn user, void *user_ctx, hj_error *err);
int p2_reach_output(int k, double t, const double *y, void *ctx, hj_error *err);
void p2_reach_log_free(p2_reach_log *log);

/* Output times t0 + k (tmax - t0) / nint, k = 0..nint (the last exactly
 * tmax), into ts (nint + 1 entries). */
void p2_times(double t0, double tmax, int nint, double *ts);

/* An output callback (hj_ls_output_fn / p2_snapshot_fn) writing one
 * gnuplot index block per output time (hj_ls_write_block, the field named
 * "phi(t=...)") to fp; blocks are separated by two blank lines. */
typedef struct {
    FILE *fp;
    const hj_ls_grid *g;
} p2_blocks;
int p2_write_block(int k, double t, const double *y, void *ctx, hj_error *err);

/* 3-D fields resampled (trilinearly) on an M x M x M lattice spanning the
 * grid's box, for gnuplot's voxel grids (`set vgrid $v size M` with the
 * axis ranges set to the lattice's box, then `vfill ... using
 * 1:2:3:(0):(column)`): one line "x y z f_1 ... f_n" per lattice point.
 * With periodic_dim >= 0 the box extends to the period in that dimension
 * (interpolating between the last node and the first). */
int p2_write_voxels(FILE *fp, const hj_ls_grid *g, int nfields, const double *const *fields, int M, int periodic_dim,
                    hj_error *err);

/* Command-line scanning shared by the demos: classify argv[*i] as --help
 * (*opt = P2_OPT_HELP), --quick (P2_OPT_QUICK) or the option valued[k]
 * taking a value (*opt = k, *value = the next argument, *i advanced).
 * HJ_EINVAL with a message for an unknown option or a missing value. */
enum { P2_OPT_HELP = -2, P2_OPT_QUICK = -3 };
int p2_next_option(int argc, char **argv, int *i, const char *const *valued, int nvalued, int *opt, const char **value,
                   hj_error *err);

/* Peak resident memory of this process in MB (getrusage), or NAN. */
double p2_peak_rss_mb(void);

#endif
