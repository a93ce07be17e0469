/* p2_reinit.c -- see p2_reinit.h. */
#include "p2_reinit.h"

#include <stdlib.h>
#include <string.h>

#include "hj_cli.h"
#include "hj_ls_accuracy.h"
#include "hj_ls_front.h"
#include "hj_ls_helper.h"
#include "hj_ls_measure.h"
#include "hj_math.h"
#include "p2_cli.h"

const char *const p2_shape_name[P2_NSHAPE] = {"circle", "star"};

enum { NCOARSE = P2_CURVE_SAMPLES / P2_CURVE_STRIDE };

int p2_reinit_setup(p2_reinit_case *c, int shape, hj_error *err)
{
    memset(c, 0, sizeof *c);
    c->shape = shape;
    c->star = (hj_ls_star){0.25, 2.0, 7};
    c->center[0] = -0.4, c->center[1] = 0, c->radius = 0.35;
    const double dx = 0.02, lo[2] = {-1, -1}, hi[2] = {1 - dx, 1 - dx};
    const long n[2] = {100, 100};
    const hj_ls_bc bc[2] = {{HJ_LS_BC_PERIODIC, 0, 0}, {HJ_LS_BC_PERIODIC, 0, 0}};
    int rc = hj_ls_grid_init(&c->g, 2, lo, hi, n, bc, err);
    if (rc) return rc;
    c->phi0 = hj_ls_alloc(&c->g), c->dist = hj_ls_alloc(&c->g), c->work = hj_ls_alloc(&c->g);
    if (!c->phi0 || !c->dist || !c->work) {
        p2_reinit_free(c);
        return hj_error_set(err, HJ_ENOMEM, "reinit case: out of memory");
    }
    if (shape == P2_STAR) {
        rc = hj_ls_shape_star(&c->g, &c->star, c->phi0, err);
        c->exact_area = hj_ls_star_area(&c->star);
    } else {
        rc = hj_ls_shape_sphere(&c->g, c->center, c->radius, c->phi0, err);
        c->exact_area = HJ_PI * c->radius * c->radius;
    }
    if (!rc)
        rc = hj_ls_shape_curve(shape == P2_STAR ? &c->star : NULL, c->center, c->radius, P2_CURVE_SAMPLES, &c->curve,
                               err);
    if (!rc) rc = hj_ls_unsigned_distance(&c->g, c->curve, P2_CURVE_SAMPLES, c->dist, err);
    if (!rc && !(c->coarse = malloc(sizeof(double) * 2 * NCOARSE)))
        rc = hj_error_set(err, HJ_ENOMEM, "reinit case: out of memory");
    if (rc) {
        p2_reinit_free(c);
        return rc;
    }
    for (long k = 0; k < NCOARSE; k++)
        c->coarse[2 * k] = c->curve[2 * k * P2_CURVE_STRIDE],
                      c->coarse[2 * k + 1] = c->curve[2 * k * P2_CURVE_STRIDE + 1];
    long idx[2];
    for (size_t r = 0; r < c->g.rows; r++) {
        const size_t k = hj_ls_row(&c->g, r, idx);
        for (long j = 0; j < c->g.N[0]; j++)
            if (c->phi0[k + (size_t)j] < 0) c->dist[k + (size_t)j] = -c->dist[k + (size_t)j];
    }
    return HJ_OK;
}

void p2_reinit_free(p2_reinit_case *c)
{
    hj_ls_free(c->phi0), hj_ls_free(c->dist), hj_ls_free(c->work);
    free(c->curve), free(c->coarse);
    c->phi0 = c->dist = c->work = c->curve = c->coarse = NULL;
}

int p2_reinit_measure(const p2_reinit_case *c, double *phi, p2_reinit_meas *m, hj_error *err)
{
    const double band = 5 * c->g.dx[0];
    int rc = hj_ls_front_grad_deviation(&c->g, phi, c->dist, band, c->work, &m->grad_mean, &m->grad_max, err);
    if (rc) return rc;
    double mean;
    hj_ls_front_error(&c->g, phi, c->dist, band, &m->sd_err, &mean);
    double *pts;
    long np;
    if ((rc = hj_ls_front_crossings(&c->g, phi, &pts, &np, err))) return rc;
    hj_ls_front_distance(pts, np, c->coarse, NCOARSE, &m->shift_max, &m->shift_mean);
    free(pts);
    return hj_ls_measure(&c->g, phi, &m->area, err);
}

void p2_reinit_header(FILE *fp)
{
    fprintf(fp, "shape\tacc\tgrad_before\tgrad_after\tgrad_max_after\tsd_err_before\tsd_err_after\tshift_floor\t"
                "shift_max\tshift_mean\tarea_before\tarea_after\texact_area\tsteps\n");
}

void p2_reinit_row(FILE *fp, const p2_reinit_case *c, int acc, const p2_reinit_meas *b, const p2_reinit_meas *a,
                   long steps)
{
    fprintf(fp, "%s\t%s\t%.4e\t%.4e\t%.4e\t%.4e\t%.4e\t%.4e\t%.4e\t%.4e\t%.6g\t%.6g\t%.6g\t%ld\n",
            p2_shape_name[c->shape], hj_ls_accuracy_name(acc), b->grad_mean, a->grad_mean, a->grad_max, b->sd_err,
            a->sd_err, b->shift_max, a->shift_max, a->shift_mean, b->area, a->area, c->exact_area, steps);
}

void p2_reinit_run_header(FILE *fp)
{
    fprintf(fp, "shape\taccuracy\tgrad_before\tgrad_after\tgrad_max_after\tsd_err_before\tsd_err_after\t"
                "shift_max_before\tshift_mean_before\tshift_max_after\tshift_mean_after\tarea_before\tarea_after\t"
                "exact_area\tarea_change_percent\tsteps");
}

void p2_reinit_run_row(FILE *fp, const p2_reinit_case *c, int acc, const p2_reinit_meas *b, const p2_reinit_meas *a,
                       long steps)
{
    const double v[13] = {b->grad_mean, a->grad_mean, a->grad_max, b->sd_err, a->sd_err, b->shift_max, b->shift_mean,
                          a->shift_max, a->shift_mean, b->area, a->area, c->exact_area, 100 * (a->area / b->area - 1)};
    fprintf(fp, "%s\t%s", p2_shape_name[c->shape], hj_ls_accuracy_name(acc));
    for (int k = 0; k < 13; k++) fprintf(fp, "\t%.17g", v[k]);
    fprintf(fp, "\t%ld", steps);
}

void p2_reinit_begin(const char *prog, const char *summary, const char *epilog, int argc, char **argv,
                     const char *base, const char *comment, p2_reinit_opts *o, hj_out *tab)
{
    static const char *levels[HJ_LS_NACC + 1], *shapes[P2_NSHAPE + 1];
    for (int k = 0; k < HJ_LS_NACC; k++) levels[k] = hj_ls_accuracy_name(k);
    for (int k = 0; k < P2_NSHAPE; k++) shapes[k] = p2_shape_name[k];
    *o = (p2_reinit_opts){P2_STAR, HJ_LS_ACC_LOW, 0, 0, "."};
    hj_cli_opt opts[] = {
        {.name = "--shape", .type = HJ_OPT_CHOICE, .value = &o->shape, .choices = shapes, .metavar = "S",
         .help = "the shape of one run (the toolbox's initialType)"},
        {.name = "--accuracy", .type = HJ_OPT_CHOICE, .value = &o->acc, .choices = levels, .metavar = "A",
         .help = "the accuracy of one run (section 2.1)"},
        {.name = "--quick", .type = HJ_OPT_FLAG, .value = &o->quick,
         .help = "accepted: the default set is already quick"},
        {.name = "--out-dir", .type = HJ_OPT_STRING, .value = &o->dir, .metavar = "DIR", .help = "output directory"},
    };
    o->single =
        p2_parse_runs(prog, summary, epilog, opts, (int)(sizeof opts / sizeof opts[0]), 2, argc, argv, &o->dir);
    hj_error err;
    char name[256];
    snprintf(name, sizeof name, "%s%s.tsv", base, o->single ? "_run" : "");
    p2_fail_if(prog, p2_open(tab, o->dir, name, &err), &err);
    fputs(comment, tab->fp);
    p2_reinit_header(tab->fp);
}

void p2_reinit_begin_runs(const char *prog, const p2_reinit_opts *o, const char *base, const char *comment,
                          const char *extra, hj_out *runs)
{
    char name[256];
    snprintf(name, sizeof name, "%s_runs.tsv", base);
    hj_error err;
    p2_fail_if(prog, p2_open(runs, o->dir, name, &err), &err);
    fputs(comment, runs->fp);
    p2_reinit_run_header(runs->fp);
    fprintf(runs->fp, "%s\n", extra);
}

void p2_reinit_end(const char *prog, const p2_reinit_opts *o, hj_out *tab, hj_out *runs)
{
    hj_error err;
    p2_fail_if(prog, hj_out_commit(tab, &err), &err);
    if (!o->single) p2_fail_if(prog, hj_out_commit(runs, &err), &err);
}
