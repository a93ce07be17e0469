/* p2_cli.c -- see p2_cli.h. */
#include "p2_cli.h"

#include <stdio.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "hj_cli.h"
#include "hj_ls_accuracy.h"
#include "hj_ls_io.h"
#include "hj_ls_term.h"

int p2_parse_choice(const char *s, const char *what, const char *const *names, int n, int *out, hj_error *err)
{
    char list[512] = "";
    for (int k = 0; k < n; k++) {
        if (!strcmp(s, names[k])) {
            *out = k;
            return HJ_OK;
        }
        size_t len = strlen(list);
        snprintf(list + len, sizeof list - len, "%s%s", k ? ", " : "", names[k]);
    }
    return hj_error_set(err, HJ_EINVAL, "unknown %s '%s' (one of: %s)", what, s, list);
}

int p2_next_option(int argc, char **argv, int *i, const char *const *valued, int nvalued, int *opt, const char **value,
                   hj_error *err)
{
    const char *a = argv[*i];
    *value = NULL;
    if (!strcmp(a, "--help")) { *opt = P2_OPT_HELP; return HJ_OK; }
    if (!strcmp(a, "--quick")) { *opt = P2_OPT_QUICK; return HJ_OK; }
    for (int k = 0; k < nvalued; k++)
        if (!strcmp(a, valued[k])) {
            if (*i + 1 >= argc) return hj_error_set(err, HJ_EINVAL, "option %s needs a value (see --help)", a);
            *opt = k;
            *value = argv[++*i];
            return HJ_OK;
        }
    return hj_error_set(err, HJ_EINVAL, "unknown option '%s' (see --help)", a);
}

hj_cli_opt p2_opt_accuracy(int *acc)
{
    static const char *levels[HJ_LS_NACC + 1];
    for (int k = 0; k < HJ_LS_NACC; k++) levels[k] = hj_ls_accuracy_name(k);
    return (hj_cli_opt){.name = "--accuracy", .type = HJ_OPT_CHOICE, .value = acc, .choices = levels, .metavar = "A",
                        .help = "scheme and RK order (section 2.1)"};
}

hj_cli_opt p2_opt_dissipation(const char *name, int *diss)
{
    /* HJ_LS_GLF, HJ_LS_LLF, HJ_LS_LLLF are 0, 1, 2: the index is the value */
    static const char *kinds[4];
    for (int k = 0; k < 3; k++) kinds[k] = hj_ls_dissipation_name(k);
    return (hj_cli_opt){.name = name, .type = HJ_OPT_CHOICE, .value = diss, .choices = kinds, .metavar = "D",
                        .help = "Lax-Friedrichs dissipation (section 2.2.2)"};
}

hj_cli_opt p2_opt_out_dir(const char **dir)
{
    return (hj_cli_opt){.name = "--out-dir", .type = HJ_OPT_STRING, .value = dir, .metavar = "DIR",
                        .help = "where to write the tables and figure data"};
}

hj_cli_opt p2_opt_quick(int *quick, const char *help)
{
    return (hj_cli_opt){.name = "--quick", .type = HJ_OPT_FLAG, .value = quick, .help = help};
}

int p2_seen_any(const hj_cli_opt *opts, int n)
{
    for (int k = 0; k < n; k++)
        if (opts[k].seen) return 1;
    return 0;
}

int p2_parse_runs(const char *prog, const char *summary, const char *epilog, hj_cli_opt *opts, int nopts, int nrun,
                  int argc, char **argv, const char *const *out_dir)
{
    hj_cli_spec spec = {prog, summary, opts, nopts, epilog};
    hj_cli_parse_or_exit(&spec, argc, argv);
    const int single = p2_seen_any(opts, nrun);
    hj_error err;
    p2_fail_if(prog, hj_mkdirs(*out_dir, &err), &err);
    return single;
}

void p2_one_thread(void)
{
#ifdef _OPENMP
    omp_set_num_threads(1);
#endif
}

void p2_parse_demo(p2_opts *o, int argc, char **argv, const char *flag, int *value, hj_cli_opt *extra, int nextra)
{
    static const char *const binary[] = {"0", "1", NULL};
    int choice = 0;
    hj_cli_opt opts[] = {
        p2_opt_accuracy(&o->acc),
        {.name = "--N", .type = HJ_OPT_LONG, .value = &o->N, .min = 11, .max = 801, .metavar = "NODES",
         .help = "nodes of the figure grid", .dflt = o->N ? NULL : "see below"},
        p2_opt_out_dir(&o->out_dir),
        p2_opt_quick(&o->quick, "the reduced runs of CI"),
        {.name = flag, .type = HJ_OPT_CHOICE, .value = &choice, .choices = binary, .metavar = "0|1",
         .help = "run only this case", .dflt = "both cases"},
    };
    enum { NCOMMON = 5, MAXOPTS = 16 };
    hj_cli_opt all[MAXOPTS];
    const int ncommon = flag ? NCOMMON : NCOMMON - 1;
    if (ncommon + nextra > MAXOPTS) hj_cli_fail(o->prog, HJ_EXIT_RUN, "too many options for p2_parse_demo");
    memcpy(all, opts, sizeof opts[0] * (size_t)ncommon);
    if (nextra) memcpy(all + ncommon, extra, sizeof extra[0] * (size_t)nextra);
    p2_parse_runs(o->prog, "A demo of Mitchell's Toolbox of Level Set Methods (2004), section 2.", o->usage, all,
                  ncommon + nextra, 0, argc, argv, &o->out_dir);
    if (flag && all[4].seen) *value = choice;
    for (int k = 0; k < nextra; k++) extra[k].seen = all[ncommon + k].seen;
}

void p2_fail_if(const char *prog, int rc, const hj_error *err)
{
    if (rc) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err->msg);
}

void p2_commit_run(const char *prog, hj_out *out, int rc, const hj_error *err)
{
    if (rc) {
        hj_out_abort(out); /* no half-written figure file is left behind */
        p2_fail_if(prog, 1, err);
    }
    hj_error cerr;
    p2_fail_if(prog, hj_out_commit(out, &cerr), &cerr);
}

void p2_next_file(const char *prog, hj_out *out, const char *dir, const char *name)
{
    hj_error err;
    p2_fail_if(prog, hj_out_commit(out, &err), &err);
    p2_fail_if(prog, p2_open(out, dir, name, &err), &err);
}

/* path = dir/name. */
static int join(char *path, size_t cap, const char *dir, const char *name, hj_error *err)
{
    if ((size_t)snprintf(path, cap, "%s/%s", dir, name) >= cap)
        return hj_error_set(err, HJ_EINVAL, "path too long: %s/%s", dir, name);
    return HJ_OK;
}

int p2_open(hj_out *out, const char *dir, const char *name, hj_error *err)
{
    char path[4096];
    int rc = join(path, sizeof path, dir, name, err);
    return rc ? rc : hj_out_open(out, path, err);
}

int p2_write_dat(const char *dir, const char *name, const hj_ls_grid *g, int nfields, const char *const *names,
                 const double *const *fields, hj_error *err)
{
    char path[4096];
    int rc = join(path, sizeof path, dir, name, err);
    return rc ? rc : hj_ls_write_dat(path, g, nfields, names, fields, err);
}
