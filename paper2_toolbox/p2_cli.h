/* p2_cli.h -- the command lines of the paper 2 demos and the helpers of
 * their main(): the options most of them share (--accuracy, --N,
 * --out-dir, --quick, --help), 0|1 switches, named choices, and ending the
 * program on an error.
 *
 * p2_parse_choice and p2_next_option return hj_error codes and the p2_opt_*
 * functions build option table entries; the others print through
 * hj_cli_fail (or, for --help, the usage) and exit, so they are for main()
 * only.
 */
#ifndef P2_CLI_H
#define P2_CLI_H

#include "hj_cli.h"
#include "hj_error.h"
#include "hj_io.h"
#include "hj_ls_grid.h"

/* *out = index of s in names[0..n-1]; HJ_EINVAL naming `what` and the
 * choices otherwise. */
int p2_parse_choice(const char *s, const char *what, const char *const *names, int n, int *out, hj_error *err);

/* Classify argv[*i] as --help (*opt = P2_OPT_HELP), --quick (P2_OPT_QUICK)
 * or the option valued[k] taking a value (*opt = k, *value = the next
 * argument, *i advanced).  HJ_EINVAL with a message for an unknown option
 * or a missing value. */
enum { P2_OPT_HELP = -2, P2_OPT_QUICK = -3 };
int p2_next_option(int argc, char **argv, int *i, const char *const *valued, int nvalued, int *opt, const char **value,
                   hj_error *err);

/* Entries of the option tables (hj_cli_opt) that the paper 2 programs
 * share: --accuracy (HJ_LS_ACC_*), the Lax-Friedrichs dissipation under
 * the program's own name ("--diss" or "--dissipation"; HJ_LS_GLF ...),
 * --out-dir and --quick (help: what --quick runs).  Each writes to the
 * variable given, which holds the default. */
hj_cli_opt p2_opt_accuracy(int *acc);
hj_cli_opt p2_opt_dissipation(const char *name, int *diss);
hj_cli_opt p2_opt_out_dir(const char **dir);
hj_cli_opt p2_opt_quick(int *quick, const char *help);

/* 1 if any of opts[0 .. n - 1] was given (after hj_cli_parse). */
int p2_seen_any(const hj_cli_opt *opts, int n);

/* The command line of a program whose first nrun options are its run
 * options (any of them given: one run instead of the default set), read
 * against opts[0 .. nopts - 1]: --help prints summary, the options and
 * epilog, and bad usage ends the program with one message.  Then the
 * output directory *out_dir is created.  Returns 1 when a run option was
 * given. */
int p2_parse_runs(const char *prog, const char *summary, const char *epilog, hj_cli_opt *opts, int nopts, int nrun,
                  int argc, char **argv, const char *const *out_dir);

/* One OpenMP thread for the rest of the program: the grids of these
 * programs are too small for a second thread to pay for its
 * synchronisation on a shared machine (the results do not depend on the
 * thread count). */
void p2_one_thread(void);

/* Options of the section 2.3-2.4 demos: --accuracy, --N, --out-dir,
 * --quick, --help. */
typedef struct {
    const char *prog, *usage;
    int acc;        /* HJ_LS_ACC_* */
    long N;         /* nodes per unit dimension of the figure grid */
    const char *out_dir;
    int quick;
} p2_opts;

/* The whole command line of a demo that takes the options above, at most
 * one 0|1 switch (flag, e.g. --reverse-flow; NULL: none; *value is left as
 * it is unless the switch is given) and the demo's own options extra[0 ..
 * nextra - 1] (their `seen` is set), read through hj_cli's option table
 * (usage is the text printed after the options by --help); anything else
 * ends the program.  Then the output directory is created. */
void p2_parse_demo(p2_opts *o, int argc, char **argv, const char *flag, int *value, hj_cli_opt *extra, int nextra);

/* End the program with the error's message when rc != 0. */
void p2_fail_if(const char *prog, int rc, const hj_error *err);

/* Finish a file after the run that wrote it returned rc: commit it, or,
 * when the run failed, remove it and end the program. */
void p2_commit_run(const char *prog, hj_out *out, int rc, const hj_error *err);

/* Commit *out, then open dir/name in it (ends the program on failure). */
void p2_next_file(const char *prog, hj_out *out, const char *dir, const char *name);

/* path = dir/name, then hj_out_open. */
int p2_open(hj_out *out, const char *dir, const char *name, hj_error *err);

/* dir/name holding one block of nfields arrays on g (hj_ls_write_dat). */
int p2_write_dat(const char *dir, const char *name, const hj_ls_grid *g, int nfields, const char *const *names,
                 const double *const *fields, hj_error *err);

#endif
