/*
# One HJB time step on FLS and on SSD (Table 5)

**Problem.** Section 3.5: the target problem (4) in d = 3 with
f(x, y, z, a) = (a, 1, 1) and N_a = 11 controls a_i = -1 + 2 i / 10, the
unit ball as target, on [-2, 2]^3, CFL = 0.9.

**Method.** The UB-HJB scheme of common/hj_ub.h, on the narrow band kept in the
classical full-matrix narrow band (FLS) and in the sparse semi-dynamic
structure (SSD) behind the same interface.

**Measured.** |D^0| (the nodes of the initial band), the CPU time of one
time step (band extension, scheme for the 11 controls, band reduction;
not the initialisation), averaged over the first `STEPS` steps, its ratio
between successive N (the published "Order") and SSD/FLS.  FLS needs
9 N^3 bytes: at N = 1600 it does not fit in this machine (36.9 GB) and
the store refuses it with "out of memory" (as on the paper's 4 GB laptop
from N = 800 on); the cell is then empty.  Per band node: the SSD step's
CPU time per node of D^0 in nanoseconds (SSD_ns_node; the published one
follows from the paper's seconds and |D^0|, shown beside it) and the bytes
SSD holds per stored node after the steps (SSD_B_node; SSD_MB in all).
peak_MB is the process's peak resident memory so far (it only grows: at
N = 1600 it still shows FLS at N = 800).  An extra column runs the same
step on SSDA (contiguous arrays per line).

**Cost.** The cells the paper has no value for (FLS at N = 800, the SSDA
column) run only when predicted cheap: at most P3_EXTRA_BUDGET CPU
seconds for the steps (the last step time times the growth between the
last two sizes, or 8), and FLS only while its 9 N^3 bytes stay under 1
GB; the others are listed in a comment line at the end of the table.
`--extra` (`make paper3 P3_EXTRA=1`) runs them all; so does `--sizes`.
Every published cell (FLS to N = 400, SSD to N = 1600, as
published/table5.tsv says) runs, whatever its cost.  The rule is
storage's (p3_rule_decide, p3_prog.h); `--plan` prints each cell's
decision without running any.

**Parameters.** N = 50, 100, 200, 400, 800, 1600; `--quick`: 50, 100.

**Output.** table5.tsv.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hj_cli.h"
#include "hj_sys.h"
#include "hj_ub.h"
#include "p3_prog.h"

enum { STEPS = 3, NA = 11 };


static void dyn(double t, const double *x, int a, double *f, void *ctx)
{
    (void)t;
    (void)x;
    (void)ctx;
    f[0] = -1 + 2.0 * a / (NA - 1);
    f[1] = 1;
    f[2] = 1;
}


/* Seconds per step, |D^0|, and the bytes the store holds and its node
 * count after the steps; HJ_ENOMEM when the store does not fit. */
static int run(hj_band_kind kind, int n, double *secs, size_t *d0, double *bytes, double *nodes, hj_error *err)
{
    hj_ub_problem pb = {.d = 3, .n = n, .lo = {-2, -2, -2}, .hi = {2, 2, 2}, .ncontrols = NA, .dyn = dyn, .target = 1,
                     .cfl = 0.9, .boundary = 1, .snap = HJ_UB_SNAP, .avg0 = p3_ball3_avg, .uniform = p3_ball3_uniform,
                     .bbox_lo = {-1, -1, -1}, .bbox_hi = {1, 1, 1}};
    hj_ub_solver sv;
    int rc = hj_ub_init(&sv, &pb, kind, err);
    if (rc) { hj_ub_free(&sv); return rc; }
    *d0 = hj_band_count(sv.s);
    const double t0 = hj_sys_cpu_seconds();
    for (int s = 0; s < STEPS && !rc; s++) rc = hj_ub_step(&sv, 10.0, err);
    *secs = (hj_sys_cpu_seconds() - t0) / STEPS;
    *bytes = (double)hj_band_bytes(sv.s);
    *nodes = (double)hj_band_count(sv.s);
    hj_ub_free(&sv);
    return rc;
}

/* One walk over the sizes: the rows of table5.tsv into out, or with
 * --plan only the decisions into plan. */
static void table5(const p3_args *a, const p3_rule *rule, const p3_pub *pub, hj_out *out, p3_plan *plan)
{
    static const long published[] = {50, 100, 200, 400, 800, 1600};
    static const hj_band_kind kinds[3] = {HJ_BAND_FLS, HJ_BAND_SSD, HJ_BAND_SSDA};
    const long *sizes = a->nsizes ? a->sizes : published;
    const int ns = a->nsizes ? a->nsizes : a->quick ? 2 : 6;
    hj_error err;
    double prev[2] = {NAN, NAN};
    p3_col col[3] = {P3_COL_INIT, P3_COL_INIT, P3_COL_INIT}; /* the step times of each store */
    char skipped[256] = "", buf[96];
    for (int i = 0; i < ns; i++) {
        if (a->max_n && sizes[i] > a->max_n) continue;
        double t[3] = {NAN, NAN, NAN}, bytes[3] = {NAN, NAN, NAN}, nodes[3] = {NAN, NAN, NAN};
        size_t d0 = 0;
        for (int k = 0; k < 3; k++) {
            const char *name = hj_band_kind_name(kinds[k]);
            const int paper = p3_pub_has(pub, &sizes[i], name);
            const p3_decision dec = p3_rule_decide(rule, &col[k], 3, paper, p3_store_big(kinds[k], 3, sizes[i]));
            if (p3_rule_listed(dec, paper)) {
                const size_t len = strlen(skipped);
                snprintf(skipped + len, sizeof skipped - len, "%s%s N>=%ld", len ? ", " : "", name, sizes[i]);
            }
            if (a->plan) {
                char label[96];
                snprintf(label, sizeof label, "table5 N=%ld %s\t%s", sizes[i], name, paper ? "published" : "no published value");
                if (p3_plan_note(plan, label, p3_decision_text(buf, sizeof buf, rule, dec, paper), &err)) p3_die(a->prog, &err);
                p3_col_record(&col[k], dec == P3_RUN ? p3_plan_time(plan) : NAN);
                continue;
            }
            if (dec != P3_RUN) {
                p3_col_record(&col[k], NAN);
                continue;
            }
            hj_progress("table5 N=%ld %s ...\n", sizes[i], name);
            const int rc = run(kinds[k], (int)sizes[i], &t[k], &d0, &bytes[k], &nodes[k], &err);
            if (rc == HJ_ENOMEM) { t[k] = NAN; continue; } /* no value, and no growth to predict from */
            if (rc) { hj_out_abort(out); p3_die(a->prog, &err); }
            p3_col_record(&col[k], t[k]);
        }
        if (a->plan) continue;
        char b[11][32];
        fprintf(out->fp, "%ld\t%zu\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%.0f\n", sizes[i], d0, p3_num(b[0], t[0]),
                p3_num(b[1], t[0] / prev[0]), p3_num(b[2], t[1]), p3_num(b[3], t[1] / prev[1]), p3_num(b[4], t[1] / t[0]),
                p3_num(b[5], t[2]), p3_num(b[6], t[2] / t[0]), p3_num(b[7], 1e9 * t[1] / (double)d0),
                p3_num(b[8], bytes[1] / nodes[1]), p3_num(b[9], bytes[1] / 1e6), hj_sys_peak_rss_mb());
        fflush(out->fp);
        prev[0] = t[0];
        prev[1] = t[1];
    }
    char note[512] = "";
    if (skipped[0])
        snprintf(note, sizeof note, "# not run, no published value and predicted above %g s of CPU or FLS above 1 GB "
                                    "(hjbstep --extra, make paper3 P3_EXTRA=1 runs them): %s", P3_EXTRA_BUDGET, skipped);
    if (a->plan) {
        if (p3_plan_note(plan, "table5 closing comment\t", note[0] ? note : "(none)", &err)) p3_die(a->prog, &err);
    } else if (note[0])
        fprintf(out->fp, "%s\n", note);
}

int main(int argc, char **argv)
{
    p3_args a = {.prog = "hjbstep",
                 .extra_help = "also run the cells without a published value that are predicted above 2 s (FLS at N = 800, "
                               "SSDA from N = 400; minutes)"};
    p3_args_parse(&a, argc, argv, "Table 5: CPU time of one UB-HJB step, FLS against SSD.", NULL, 5, 5);
    /* Published cells run whatever their cost; --sizes runs every cell. */
    const p3_rule rule = {INFINITY, a.extra || a.nsizes, STEPS};
    hj_error err;
    p3_pub pub;
    if (p3_pub_read(&pub, a.published, "table5", &err)) p3_die(a.prog, &err);
    if (a.plan) { /* the two walks of p3_plan (p3_prog.h), then print */
        p3_plan plan = {0};
        for (plan.world = 0; plan.world < 2; plan.world++) table5(&a, &rule, &pub, NULL, &plan);
        if (p3_plan_print(&plan, stdout, &err)) p3_die(a.prog, &err);
        p3_plan_free(&plan);
        p3_pub_free(&pub);
        return 0;
    }
    hj_out out;
    if (p3_open(&out, a.out_dir, "table5.tsv", &err)) p3_die(a.prog, &err);
    fprintf(out.fp, "# table5: CPU seconds of one UB-HJB step (mean of %d), 11 controls, computed by hjbstep%s\n", STEPS,
            a.quick ? " --quick" : "");
    fprintf(out.fp, "N\tD0\tFLS\tFLS_ratio\tSSD\tSSD_ratio\tSSD_over_FLS\tSSDA\tSSDA_over_FLS\tSSD_ns_node\tSSD_B_node\t"
                    "SSD_MB\tpeak_MB\n");
    table5(&a, &rule, &pub, &out, NULL);
    p3_pub_free(&pub);
    if (hj_out_commit(&out, &err)) p3_die(a.prog, &err);
    return 0;
}
