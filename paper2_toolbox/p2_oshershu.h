/* p2_oshershu.h -- the two general-Hamiltonian examples of Osher & Shu
 * (1991) as the toolbox sets them up (section 2.5: burgersLF, nonconvexLF):
 *     D_t phi + H(grad phi) = 0 on [-d, d)^d, periodic,
 *     phi(x, 0) = -cos(pi / d * sum_i x_i),
 * with H(p) = h(sum_i p_i) for a scalar h: (1 + q)^2 / 2 (Burgers, (15))
 * or -cos(1 + q) (non-convex, (16)).  The solution is a function of
 * s = sum_i x_i / d alone, G(s, t), which solves the 1-D problem
 * G_t + h(G_s) = 0, G(s, 0) = -cos(pi s); it is computed here by
 * characteristics: s = s0 + h'(u0(s0)) t with u0 = pi sin(pi s0), and
 * G = G0(s0) + t (u0 h'(u0) - h(u0)), the minimum over all roots s0 when
 * there are several (convex h: the Hopf-Lax formula).  Roots are bracketed
 * on 400 sub-intervals of the interval of possible feet and refined by
 * bisection to adjacent doubles.
 */
#ifndef P2_OSHERSHU_H
#define P2_OSHERSHU_H

#include <stdio.h>

#include "hj_error.h"
#include "hj_ls_grid.h"
#include "hj_ls_ode.h"

typedef struct {
    const char *name;
    double (*h)(double q);   /* H(p) = h(sum p) */
    double (*dh)(double q);  /* h'(q) */
    double dh_max;           /* bound on |h'| over the solution's range */
    int convex;              /* take the minimum over several characteristics */
} p2_os_problem;

extern const p2_os_problem p2_os_burgers, p2_os_nonconvex;

/* Partial bound for termLaxFriedrichs: the toolbox's (sections 2.5.1-2)
 * or, with tight, the exact max over the box of |h'(sum p)|. */
typedef struct {
    const p2_os_problem *pb;
    int dim;
    int tight;
} p2_os_ctx;

typedef struct {
    int dim;
    long N;        /* nodes per dimension */
    int acc;       /* HJ_LS_ACC_LOW .. HJ_LS_ACC_VERYHIGH */
    int diss;      /* HJ_LS_GLF .. HJ_LS_LLLF */
    int tight;     /* exact partial bound instead of the toolbox's */
    double tmax;
    int nout;      /* output intervals (toolbox: 10) */
} p2_os_run;

/* The toolbox grid: min -d, dx = 2d / N, periodic. */
int p2_os_grid(int dim, long N, hj_ls_grid *g, hj_error *err);

/* Solve; *phi (allocated here, free with hj_ls_free) holds the state at
 * tmax; out (may be NULL) sees the initial state (k = 0) and every output
 * time; stats may be NULL. */
int p2_os_solve(const p2_os_problem *pb, const p2_os_run *r, hj_ls_grid *g, double **phi, hj_ls_output_fn out,
                void *out_ctx, hj_ls_ode_stats *stats, hj_error *err);

/* The same with the CFL rule and WENO5 epsilon of the Lax-Friedrichs term
 * (p2_os_solve: HJ_LS_CFL_NODE, HJ_LS_WENO_EPS_LOCAL; the toolbox's:
 * HJ_LS_CFL_TOOLBOX, HJ_LS_WENO_EPS_GRID). */
int p2_os_solve_rule(const p2_os_problem *pb, const p2_os_run *r, int cfl_rule, int weno_eps, hj_ls_grid *g,
                     double **phi, hj_ls_output_fn out, void *out_ctx, hj_ls_ode_stats *stats, hj_error *err);

/* Exact G(s, t); *nroots (may be NULL) receives the number of feet. */
double p2_os_exact(const p2_os_problem *pb, double s, double t, int *nroots);

/* The exact solution at every node of g (an array on g); returns the
 * largest number of characteristic feet met. */
int p2_os_exact_grid(const p2_os_problem *pb, const hj_ls_grid *g, double t, double *out);

/* Average and maximum of |phi - exact| over the nodes. */
void p2_os_errors(const hj_ls_grid *g, const double *phi, const double *exact, double *l1, double *linf);

/* The same, the time sequence written as gnuplot index blocks to path
 * (atomically; path may be NULL); returns the final state or NULL. */
double *p2_os_solve_to_file(const p2_os_problem *pb, const p2_os_run *r, hj_ls_grid *g, const char *path,
                            hj_error *err);

/* For main(): p2_os_solve_to_file, ending the program with the message
 * (prog: ...) on a failure. */
double *p2_os_solve_or_exit(const char *prog, const p2_os_problem *pb, const p2_os_run *r, hj_ls_grid *g,
                            const char *path);

/* For main(): run r, then append its final state to fp as one gnuplot
 * index block (field "phi") after the comment printed by fmt (the
 * figures' 1-D panels); ends the program on a failure. */
void p2_os_append_block(const char *prog, const p2_os_problem *pb, const p2_os_run *r, FILE *fp, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 5, 6)))
#endif
    ;

/* The command line of burgersLF and nonconvexLF through hj_cli's option
 * table: --accuracy, --diss, --dim (1-3), --N (4-100000), --tmax, and with
 * allow_partial --partial toolbox|tight; --out-dir, --quick, --help.
 * Defaults as the toolbox: low, global, dim 2, N = 80 / 2^(dim - 1),
 * tmax = 1.5/pi^2, toolbox partial.  single is set when any run option
 * (all but --out-dir and --quick) is given.  For main() only: --help
 * prints the table (summary first, epilog last) and ends the program, as
 * does bad usage, with one message; then out_dir is created. */
typedef struct {
    p2_os_run run;
    const char *out_dir;
    int quick, single;
} p2_os_cli;
void p2_os_parse_cli(const char *prog, const char *summary, const char *epilog, int argc, char **argv,
                     int allow_partial, p2_os_cli *c);

#endif
