/*
## ToolboxLS equivalence: our kernel against the toolbox's own final arrays

**What it checks.** Paper 2 publishes no accuracy numbers, so most of its
demos are checked against exact solutions or our own accepted runs.  A
stronger reference is the toolbox itself: `toolboxls/arrays/` holds the
final arrays that ToolboxLS 1.1 produced, run by GNU Octave 7.3 on its own
demos at every accuracy level (provenance, drivers and parameters in
`toolboxls/README.md`).  This program runs the same demo, accuracy and grid
on our kernel and compares node by node:

- air3D (51 x 40 x 50, t = 2.8, 8 chunks), acoustic (201 x 126, t = 4, 8
  chunks, W_p = 1 as the released acoustic.m): termLaxFriedrichs with GLF
  inside termRestrictUpdate;
- burgersLF 1-D N = 80 and 2-D N = 40 (t = 1.5 / pi^2, 10 chunks): GLF;
- convectionDemo 'linear' 2-D 201^2 (one turn, 8 chunks);
- reinitDemo 'star' at every accuracy and 'circle' at medium (100^2
  periodic, t = 1, 10 chunks), with the subcell fix of Russo & Smereka that
  the toolbox applies by default (`subcell_fix = 1`).

Each run uses the toolbox's time-step rule (`HJ_LS_CFL_TOOLBOX`: 1 / sum_d
max_x alpha_d / dx_d) and its chunking (each chunk one integrator call
whose last step is shortened to land on the chunk's end), so that the step
sequences are the same; the run is repeated with our rule (`HJ_LS_CFL_NODE`:
1 / max_x sum_d alpha_d / dx_d, the default of the library) to show how far
the results move with it.

**Measures.** For each array: the largest |ours - toolbox| over all nodes
and over the band |toolbox| < 2 max dx, both divided by the largest
|toolbox| of the array (`rel_max`, `rel_band`), the number of nodes where
the two lie on different sides of zero (`sign_changes`) and our step count
(`steps`, against the toolbox's in the reference table).  The arrays are
written with 11 significant digits (`%.10e`), so a value is known to
within 5e-11 of its magnitude: `rel_max` <= 5e-11 is equality up to the
reference's own rounding, the bound the check uses.

**Parameters.** `--cases` picks the cases (default all); `--quick` runs the
small ones (burgersLF and reinitDemo), which CI checks.
`--toolbox-dir` is where the decompressed arrays are (the Makefile
decompresses the gzipped arrays of `toolboxls/arrays` into the build tree).

**Output.** toolboxls.tsv: case, accuracy, steps, rel_max, rel_band,
band_nodes, sign_changes, and the same with our CFL rule (node_steps,
node_rel_max, node_sign_changes; "-" for convection, which has one rule) and, for WENO5, with our epsilon
(local_eps_rel_max); where `rel_max` exceeds 1e-10, how far our own run
moves when its initial data is raised by one unit in the last place
(ulp_rel_max, ulp_rel_band): the scheme's own sensitivity to round-off.
*/
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hj.h"
#include "p2_acoustic.h"
#include "p2_air3d.h"
#include "p2_cli.h"
#include "p2_convection.h"
#include "p2_oshershu.h"
#include "p2_reinit.h"

static const char *const prog = "toolboxls";

typedef enum { AIR3D, ACOUSTIC, BURGERS1, BURGERS2, CONVECTION, REINIT_STAR, REINIT_CIRCLE, NDEMO } demo;
static const char *const demo_name[NDEMO] = {"air3D", "acoustic", "burgersLF_1D_N80", "burgersLF_2D_N40",
                                             "convectionDemo_linear", "reinitDemo_star", "reinitDemo_circle"};
static const char *const acc_name[4] = {"low", "medium", "high", "veryHigh"};

/* The reference array of one case: "<toolbox-dir>/<file>.txt". */
static void array_file(char *buf, size_t n, const char *dir, demo d, int acc)
{
    if (d == CONVECTION)
        snprintf(buf, n, "%s/convectionDemo_linear_%s_2D_final.txt", dir, acc_name[acc]);
    else
        snprintf(buf, n, "%s/%s_%s_final.txt", dir, demo_name[d], acc_name[acc]);
}

/* Read a toolbox array (header "# N ...", "# min ...", "# dx ...", then one
 * value per line, first index fastest) onto the interior of phi, checking
 * that its grid is g's.  Returns 0 or prints one message and returns -1. */
static int read_array(const char *path, const hj_ls_grid *g, double *phi)
{
    FILE *fp = fopen(path, "r");
    if (!fp) return fprintf(stderr, "%s: %s: %s\n", prog, path, strerror(errno)), -1;
    char line[512];
    long N[HJ_LS_MAXDIM] = {0};
    double mn[HJ_LS_MAXDIM] = {0}, dx[HJ_LS_MAXDIM] = {0};
    int have = 0, lineno = 0;
    long idx[HJ_LS_MAXDIM] = {0};
    size_t count = 0;
    int bad = 0;
    while (fgets(line, sizeof line, fp)) {
        lineno++;
        if (line[0] == '#') {
            double *dst = !strncmp(line, "# min ", 6) ? mn : !strncmp(line, "# dx ", 5) ? dx : NULL;
            if (!strncmp(line, "# N ", 4)) {
                char *s = line + 4;
                for (int d = 0; d < g->dim; d++) N[d] = strtol(s, &s, 10);
                have |= 1;
            } else if (dst) {
                char *s = strchr(line + 2, ' ');
                for (int d = 0; d < g->dim; d++) dst[d] = strtod(s, &s);
                have |= dst == mn ? 2 : 4;
            }
            continue;
        }
        if (have != 7) { bad = 1; fprintf(stderr, "%s: %s:%d: values before the N, min and dx lines\n", prog, path, lineno); break; }
        if (count == 0)
            for (int d = 0; d < g->dim; d++)
                if (N[d] != g->N[d] || fabs(mn[d] - g->min[d]) > 1e-12 * (1 + fabs(mn[d])) ||
                    fabs(dx[d] - g->dx[d]) > 1e-12 * dx[d]) {
                    fprintf(stderr, "%s: %s: grid differs from ours in dimension %d (N %ld/%ld, min %.17g/%.17g, dx %.17g/%.17g)\n",
                            prog, path, d + 1, N[d], g->N[d], mn[d], g->min[d], dx[d], g->dx[d]);
                    bad = 1;
                }
        if (bad) break;
        if (count >= g->nodes) { bad = 1; fprintf(stderr, "%s: %s:%d: more values than nodes\n", prog, path, lineno); break; }
        char *end;
        const double v = strtod(line, &end);
        if (end == line || !isfinite(v)) { bad = 1; fprintf(stderr, "%s: %s:%d: not a number\n", prog, path, lineno); break; }
        phi[hj_ls_index(g, idx)] = v;
        count++;
        for (int d = 0; d < g->dim && ++idx[d] == g->N[d]; d++) idx[d] = 0; /* first index fastest */
    }
    fclose(fp);
    if (!bad && count != g->nodes) {
        fprintf(stderr, "%s: %s: %zu values for %zu nodes\n", prog, path, count, g->nodes);
        bad = 1;
    }
    return bad ? -1 : 0;
}

typedef struct {
    long steps;
    double rel_max, rel_band;
    long band_nodes, sign_changes;
} cmp;

static void compare(const hj_ls_grid *g, const double *ours, const double *tb, cmp *c)
{
    double h = 0, scale = 0, dmax = 0, dband = 0;
    for (int d = 0; d < g->dim; d++) h = g->dx[d] > h ? g->dx[d] : h;
    long idx[HJ_LS_MAXDIM];
    c->band_nodes = c->sign_changes = 0;
    for (size_t r = 0; r < g->rows; r++) {
        const size_t k0 = hj_ls_row(g, r, idx);
        for (long j = 0; j < g->N[0]; j++) {
            const size_t k = k0 + (size_t)j;
            const double e = fabs(ours[k] - tb[k]);
            scale = fabs(tb[k]) > scale ? fabs(tb[k]) : scale;
            dmax = e > dmax ? e : dmax;
            if (fabs(tb[k]) < 2 * h) {
                c->band_nodes++;
                dband = e > dband ? e : dband;
            }
            c->sign_changes += (ours[k] < 0) != (tb[k] < 0);
        }
    }
    c->rel_max = dmax / scale;
    c->rel_band = dband / scale;
}

/* Chunk ends t_k = k tmax / n, k = 0 .. n (the toolbox adds tPlot n times;
 * the two differ in the last bit at most). */
static void chunks(double tmax, int n, double *ts) { hj_ls_seq_times(0, tmax, n + 1, ts); }

/* Raise every interior value by one unit in the last place: a change of
 * the initial data at the size of its rounding. */
static void nudge(const hj_ls_grid *g, double *phi)
{
    long idx[HJ_LS_MAXDIM];
    for (size_t r = 0; r < g->rows; r++) {
        const size_t k = hj_ls_row(g, r, idx);
        for (long j = 0; j < g->N[0]; j++) phi[k + (size_t)j] = nextafter(phi[k + (size_t)j], INFINITY);
    }
}

/* Run demo d at accuracy acc with CFL rule `rule` and WENO5 epsilon `eps`
 * (HJ_LS_WENO_EPS_*) on grid g (set up here), the initial data nudged by
 * one ulp if `perturb` (not offered for burgersLF, whose initial data
 * p2_os_solve sets: HJ_EINVAL); *phi allocated here. */
static int run(demo d, int acc, int rule, int eps, int perturb, hj_ls_grid *g, double **phi, long *steps,
               hj_error *err)
{
    hj_ls_ode_stats st = {0};
    int rc = 0;
    *phi = NULL;
    if (d == AIR3D) {
        p2_air3d_par p;
        p2_air3d_defaults(&p);
        p.cfl_rule = rule;
        p.weno_eps = eps;
        if ((rc = p2_air3d_grid(51, g, err))) return rc;
        if (!(*phi = hj_ls_alloc(g))) return hj_error_set(err, HJ_ENOMEM, "out of memory");
        double ts[9];
        chunks(2.8, 8, ts);
        if (!(rc = p2_air3d_target(g, &p, *phi, err)) && perturb) nudge(g, *phi);
        if (!rc)
            rc = p2_air3d_solve(g, &p, acc, HJ_LS_GLF, ts, 9, *phi, NULL, NULL, &st, err);
    } else if (d == ACOUSTIC) {
        p2_acoustic_par p;
        p2_acoustic_defaults(&p);
        p.Wp = 1.0; /* the released acoustic.m, which the toolbox's run used */
        p.cfl_rule = rule;
        p.weno_eps = eps;
        if ((rc = p2_acoustic_grid(1.0 / 25, g, err))) return rc;
        if (!(*phi = hj_ls_alloc(g))) return hj_error_set(err, HJ_ENOMEM, "out of memory");
        double ts[9];
        chunks(4, 8, ts);
        if (!(rc = p2_acoustic_target(g, *phi, err)) && perturb) nudge(g, *phi);
        if (!rc)
            rc = p2_acoustic_solve(g, &p, acc, HJ_LS_GLF, ts, 9, *phi, NULL, NULL, &st, err);
    } else if (d == BURGERS1 || d == BURGERS2) {
        if (perturb) return hj_error_set(err, HJ_EINVAL, "burgersLF: no perturbed run");
        p2_os_run r = {d == BURGERS1 ? 1 : 2, d == BURGERS1 ? 80 : 40, acc, HJ_LS_GLF, 0, 1.5 / (HJ_PI * HJ_PI), 10};
        rc = p2_os_solve_rule(&p2_os_burgers, &r, rule, eps, g, phi, NULL, NULL, &st, err);
    } else if (d == CONVECTION) {
        const double lo[2] = {-1, -1}, hi[2] = {1, 1};
        const long n[2] = {201, 201};
        const hj_ls_bc bc[2] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
        if ((rc = hj_ls_grid_init(g, 2, lo, hi, n, bc, err))) return rc;
        if (!(*phi = hj_ls_alloc(g))) return hj_error_set(err, HJ_ENOMEM, "out of memory");
        const double center[HJ_LS_MAXDIM] = {-0.4, 0};
        if ((rc = hj_ls_shape_sphere(g, center, 0.35, *phi, err))) return rc;
        if (perturb) nudge(g, *phi);
        p2_flow flow = {1, 0, 2};
        hj_ls_convection term;
        hj_ls_convection_init(&term, g, hj_ls_accuracy_scheme(acc));
        term.velocity_fn = p2_flow_velocity;
        term.ctx = &flow;
        term.weno_eps = eps; /* convection has one CFL rule: rule is not used */
        hj_ls_ode_opts o;
        hj_ls_ode_defaults(&o);
        double ts[9];
        chunks(1, 8, ts);
        rc = hj_ls_ode(hj_ls_accuracy_order(acc), g, &term.base, ts, 9, *phi, &o, NULL, NULL, &st, err);
    } else {
        p2_reinit_case c;
        if ((rc = p2_reinit_setup(&c, d == REINIT_STAR ? P2_STAR : P2_CIRCLE, err))) return rc;
        *g = c.g;
        if (d == REINIT_CIRCLE) {
            /* reinitDemo.m's own circle, not the convectionDemo circle of
             * our reinit demo: radius a quarter of the domain's width,
             * centre (r/2, r/2), exact distance */
            const double r = 0.25 * (g->max[0] - g->min[0]);
            long idx[2];
            for (size_t q = 0; q < g->rows; q++) {
                const size_t k = hj_ls_row(g, q, idx);
                const double y = g->min[1] + (double)idx[1] * g->dx[1] - 0.5 * r;
                for (long j = 0; j < g->N[0]; j++) {
                    const double x = g->min[0] + (double)j * g->dx[0] - 0.5 * r;
                    c.phi0[k + (size_t)j] = sqrt(x * x + y * y) - r;
                }
            }
        }
        if (!(*phi = hj_ls_alloc(g))) rc = hj_error_set(err, HJ_ENOMEM, "out of memory");
        else {
            hj_ls_copy(g, *phi, c.phi0);
            if (perturb) nudge(g, *phi); /* phi_0 in the sign and the fix stays as it was */
            hj_ls_reinit term;
            hj_ls_reinit_init(&term, g, hj_ls_accuracy_scheme(acc), c.phi0);
            term.subcell_fix = 1;
            term.cfl_rule = rule;
            term.weno_eps = eps;
            hj_ls_ode_opts o;
            hj_ls_ode_defaults(&o);
            double ts[11];
            chunks(1, 10, ts);
            rc = hj_ls_ode(hj_ls_accuracy_order(acc), g, &term.base, ts, 11, *phi, &o, NULL, NULL, &st, err);
        }
        p2_reinit_free(&c);
    }
    *steps = st.steps;
    return rc;
}

/* One case, compared with the toolbox's array: as the toolbox (its CFL
 * rule and WENO5 epsilon), with our CFL rule, and (WENO5 only) with our
 * epsilon.  Returns 0 or -1 after one message. */
static int one_case(demo d, int acc, const char *dir, FILE *fp)
{
    char path[4096];
    array_file(path, sizeof path, dir, d, acc);
    cmp c[3];
    /* convection has one CFL rule: no second variant */
    const int has[3] = {1, d != CONVECTION, acc == HJ_LS_ACC_VERYHIGH};
    static const int rules[3] = {HJ_LS_CFL_TOOLBOX, HJ_LS_CFL_NODE, HJ_LS_CFL_TOOLBOX};
    static const int epss[3] = {HJ_LS_WENO_EPS_GRID, HJ_LS_WENO_EPS_GRID, HJ_LS_WENO_EPS_LOCAL};
    static const char *const what[3] = {"as the toolbox", "our CFL rule", "our WENO5 epsilon"};
    hj_ls_grid g0;     /* the run as the toolbox, kept for the sensitivity run */
    double *a = NULL;
    for (int rule = 0; rule < 3; rule++) {
        if (!has[rule]) continue;
        hj_ls_grid g;
        double *phi;
        hj_error err;
        hj_progress("%s %s, %s ...\n", demo_name[d], acc_name[acc], what[rule]);
        if (run(d, acc, rules[rule], epss[rule], 0, &g, &phi, &c[rule].steps, &err)) {
            hj_ls_free(phi), hj_ls_free(a);
            fprintf(stderr, "%s: %s %s: %s\n", prog, demo_name[d], acc_name[acc], err.msg);
            return -1;
        }
        double *tb = hj_ls_alloc(&g);
        int bad = !tb || read_array(path, &g, tb);
        if (!tb) fprintf(stderr, "%s: out of memory\n", prog);
        if (!bad) compare(&g, phi, tb, &c[rule]);
        hj_ls_free(tb);
        if (rule == 0 && !bad) g0 = g, a = phi;
        else hj_ls_free(phi);
        if (bad) {
            hj_ls_free(a);
            return -1;
        }
    }
    char local[32] = "-", node[3][32] = {"-", "-", "-"};
    if (has[2]) snprintf(local, sizeof local, "%.3e", c[2].rel_max);
    if (has[1]) {
        snprintf(node[0], sizeof node[0], "%ld", c[1].steps);
        snprintf(node[1], sizeof node[1], "%.3e", c[1].rel_max);
        snprintf(node[2], sizeof node[2], "%ld", c[1].sign_changes);
    }
    /* Beyond the rounding of the reference: how far does our own result
     * move when the initial data moves by one ulp?  The same size means
     * the scheme amplifies round-off there (operations done in another
     * order than the toolbox's), not a different method. */
    char ulp[2][32] = {"-", "-"};
    if (c[0].rel_max > 1e-10 && d != BURGERS1 && d != BURGERS2) {
        hj_ls_grid g;
        double *b = NULL;
        hj_error err;
        long st;
        hj_progress("%s %s, initial data nudged by one ulp ...\n", demo_name[d], acc_name[acc]);
        if (run(d, acc, rules[0], epss[0], 1, &g, &b, &st, &err)) {
            hj_ls_free(a), hj_ls_free(b);
            fprintf(stderr, "%s: %s %s: %s\n", prog, demo_name[d], acc_name[acc], err.msg);
            return -1;
        }
        cmp u;
        compare(&g0, b, a, &u);
        snprintf(ulp[0], sizeof ulp[0], "%.3e", u.rel_max);
        snprintf(ulp[1], sizeof ulp[1], "%.3e", u.rel_band);
        hj_ls_free(b);
    }
    hj_ls_free(a);
    fprintf(fp, "%s\t%s\t%ld\t%.3e\t%.3e\t%ld\t%ld\t%s\t%s\t%s\t%s\t%s\t%s\n", demo_name[d], acc_name[acc], c[0].steps,
            c[0].rel_max, c[0].rel_band, c[0].band_nodes, c[0].sign_changes, node[0], node[1], node[2], local, ulp[0],
            ulp[1]);
    fflush(fp);
    return 0;
}

int main(int argc, char **argv)
{
    const char *out_dir = ".", *dir = "toolboxls";
    int quick = 0, which[NDEMO], nwhich = 0;
    static const char *const names[] = {"air3D", "acoustic", "burgersLF_1D_N80", "burgersLF_2D_N40",
                                        "convectionDemo_linear", "reinitDemo_star", "reinitDemo_circle", NULL};
    const char *cases = NULL;
    hj_cli_opt opts[] = {
        {.name = "--toolbox-dir", .type = HJ_OPT_STRING, .value = &dir, .metavar = "DIR",
         .help = "the toolbox's decompressed arrays (<case>_<accuracy>_final.txt)"},
        {.name = "--cases", .type = HJ_OPT_STRING, .value = &cases, .metavar = "C,C,...",
         .help = "only these cases (air3D, acoustic, burgersLF_1D_N80, burgersLF_2D_N40, convectionDemo_linear, "
                 "reinitDemo_star, reinitDemo_circle)", .dflt = "all"},
        {.name = "--quick", .type = HJ_OPT_FLAG, .value = &quick, .help = "the small cases only (burgersLF, reinitDemo)"},
        {.name = "--out-dir", .type = HJ_OPT_STRING, .value = &out_dir, .metavar = "DIR",
         .help = "where to write toolboxls.tsv"},
    };
    hj_cli_spec spec = {prog, "Our kernel against ToolboxLS 1.1's own final arrays, node by node.", opts,
                        (int)(sizeof opts / sizeof opts[0]), NULL};
    hj_cli_parse_or_exit(&spec, argc, argv);
    if (cases && quick) hj_cli_fail(prog, HJ_EXIT_USAGE, "--cases and --quick exclude each other");
    if (cases) {
        char buf[256];
        if (strlen(cases) >= sizeof buf) hj_cli_fail(prog, HJ_EXIT_USAGE, "--cases: list too long");
        strcpy(buf, cases);
        for (char *s = strtok(buf, ","); s; s = strtok(NULL, ",")) {
            int k = 0;
            while (names[k] && strcmp(names[k], s)) k++;
            if (!names[k]) hj_cli_fail(prog, HJ_EXIT_USAGE, "--cases: unknown case '%s' (see --help)", s);
            for (int q = 0; q < nwhich; q++)
                if (which[q] == k) hj_cli_fail(prog, HJ_EXIT_USAGE, "--cases: '%s' given twice", s);
            which[nwhich++] = k;
        }
    } else
        for (int k = 0; k < NDEMO; k++)
            if (!quick || k == BURGERS1 || k == BURGERS2 || k == REINIT_STAR || k == REINIT_CIRCLE) which[nwhich++] = k;

    hj_error err;
    hj_out out;
    if (hj_mkdirs(out_dir, &err) || p2_open(&out, out_dir, "toolboxls.tsv", &err))
        hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    hj_out_remove_on_signal();
    fprintf(out.fp, "# toolboxls: our kernel against ToolboxLS 1.1's final arrays; rel_* = max |ours - toolbox| / "
                    "max |toolbox| (all nodes, band |toolbox| < 2 max dx); node_* with our CFL rule%s\n",
            quick ? " --quick" : "");
    fprintf(out.fp, "case\taccuracy\tsteps\trel_max\trel_band\tband_nodes\tsign_changes\tnode_steps\tnode_rel_max\t"
                    "node_sign_changes\tlocal_eps_rel_max\tulp_rel_max\tulp_rel_band\n");
    int bad = 0;
    for (int q = 0; q < nwhich && !bad; q++)
        for (int acc = 0; acc < 4 && !bad; acc++) {
            if (which[q] == REINIT_CIRCLE && acc != HJ_LS_ACC_MEDIUM) continue; /* the toolbox ran medium only */
            bad = one_case((demo)which[q], acc, dir, out.fp);
        }
    if (bad) {
        hj_out_abort(&out);
        return HJ_EXIT_RUN;
    }
    if (hj_out_commit(&out, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    return 0;
}
