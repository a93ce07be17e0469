/* p2_motion.c -- see p2_motion.h. */
#include "p2_motion.h"

#include <math.h>
#include <stdio.h>

#include "hj_cli.h"
#include "hj_ls_accuracy.h"
#include "hj_ls_measure.h"
#include "hj_ls_seq.h"

int p2_square_grid(hj_ls_grid *g, long n, hj_error *err)
{
    const hj_ls_bc bc[2] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
    const double lo[2] = {-1, -1}, hi[2] = {1, 1};
    const long N[2] = {n, n};
    return hj_ls_grid_init(g, 2, lo, hi, N, bc, err);
}

double p2_circle_fn(const double *x, void *ctx)
{
    const p2_circle *c = ctx;
    return hypot(x[0] - c->c[0], x[1] - c->c[1]) - c->r;
}

double p2_switch_fn(double t, const double *x, double phi, void *ctx)
{
    (void)t;
    (void)phi;
    const p2_switch *s = ctx;
    const int k = s->after;
    if (s->cos_coef[k] == 0) return s->value[k];
    const double r = hypot(x[0], x[1]);
    const double c = r > 0 ? x[0] / r : 0; /* cos theta; theta = 0 at the origin, as cart2pol */
    return s->value[k] * (1 + s->cos_coef[k] * c);
}

void p2_switch_row(double t, const hj_ls_row_info *row, const double *phi, double *a, void *ctx)
{
    (void)t, (void)phi;
    const p2_switch *s = ctx;
    const int k = s->after;
    const long n = row->n;
    if (s->cos_coef[k] == 0) {
        for (long j = 0; j < n; j++) a[j] = s->value[k];
        return;
    }
    const double y = row->x[1], v = s->value[k], cc = s->cos_coef[k];
    for (long j = 0; j < n; j++) {
        const double x = row->x[0] + (double)j * row->dx0, r = hypot(x, y);
        const double c = r > 0 ? x / r : 0; /* as p2_switch_fn */
        a[j] = v * (1 + cc * c);
    }
}

/* The hook of the sequence: the progress line, then the demo's hook. */
static int progress_hook(int k, double t, const double *y, void *ctx, hj_error *err)
{
    const p2_seq *s = ctx;
    if (s->progress) hj_progress("%s: t = %.4g\n", s->progress, t);
    return s->hook ? s->hook(k, t, y, s->hook_ctx, err) : HJ_OK;
}

int p2_run(int order, const hj_ls_grid *g, const hj_ls_term *term, const double *tspan, int n, double *y,
           p2_seq *seq, double factor_cfl, hj_error *err)
{
    hj_ls_seq s;
    hj_ls_seq_init(&s, seq->fp, seq->grid, seq->name, 6);
    if (seq->sw) s.flag = &seq->sw->after, s.t_switch = seq->sw->t_switch;
    s.hook = progress_hook, s.hook_ctx = seq;
    hj_ls_ode_opts o;
    hj_ls_ode_defaults(&o);
    o.factor_cfl = factor_cfl;
    o.post = seq->post;
    o.post_ctx = seq->post_ctx;
    return hj_ls_seq_solve(order, g, term, tspan, n, y, &o, &s, NULL, err);
}

int p2_area_hook(int k, double t, const double *y, void *ctx, hj_error *err)
{
    (void)t;
    p2_areas *a = ctx;
    return hj_ls_measure(a->grid, y, &a->area[k], err);
}

void p2_check_rows(FILE *fp, const p2_check *c)
{
    for (int n = 0; n < c->ngrids; n++)
        for (int k = 0; k < c->ncase; k++) {
            const double v = c->value[n * c->ncase + k], e = c->exact[k];
            fprintf(fp, "%ld\t%s\t%.6f\t%.6f\t%.3e\n", c->grids[n], c->case_name[k], v, e, fabs(v - e));
        }
}

void p2_cell(FILE *fp, double v)
{
    if (isnan(v)) fputs("\t-", fp);
    else fprintf(fp, "\t%.17g", v);
}

void p2_cells(FILE *fp, const double *v, int n)
{
    for (int k = 0; k < n; k++) p2_cell(fp, v[k]);
    fputc('\n', fp);
}

void p2_check_runs(FILE *fp, const char *accuracy, const p2_check *c)
{
    fprintf(fp, "accuracy\tN\tdx\tcase%s%s\t%s\t%s_exact\terror\terror_dx\n", c->param_name ? "\t" : "",
            c->param_name ? c->param_name : "", c->value_name, c->value_name);
    for (int n = 0; n < c->ngrids; n++)
        for (int k = 0; k < c->ncase; k++) {
            const double v = c->value[n * c->ncase + k], e = c->exact[k], dx = 2.0 / (double)(c->grids[n] - 1);
            fprintf(fp, "%s\t%ld", accuracy, c->grids[n]);
            p2_cell(fp, dx);
            fprintf(fp, "\t%s", c->case_name[k]);
            if (c->param_name) p2_cell(fp, c->param[k]);
            p2_cell(fp, v);
            p2_cell(fp, e);
            p2_cell(fp, fabs(v - e));
            p2_cell(fp, fabs(v - e) / dx);
            fputc('\n', fp);
        }
}

void p2_check_files(const p2_opts *o, const char *tsv, const char *tsv_head, const char *runs, const char *runs_head,
                    const p2_check *c)
{
    hj_error err;
    hj_out out;
    const char *acc = hj_ls_accuracy_name(o->acc);
    p2_fail_if(o->prog, p2_open(&out, o->out_dir, tsv, &err), &err);
    fprintf(out.fp, tsv_head, acc);
    p2_check_rows(out.fp, c);
    p2_next_file(o->prog, &out, o->out_dir, runs);
    fputs(runs_head, out.fp);
    p2_check_runs(out.fp, acc, c);
    p2_fail_if(o->prog, hj_out_commit(&out, &err), &err);
}

void p2_star_figures(const p2_opts *o, const p2_star_figure *f, int only, p2_figure_fn run, void *ctx)
{
    hj_error err;
    hj_ls_grid g;
    p2_fail_if(o->prog, p2_square_grid(&g, o->N, &err), &err);
    double *phi = hj_ls_alloc(&g);
    if (!phi) hj_cli_fail(o->prog, HJ_EXIT_RUN, "out of memory");
    for (int k = 0; k < 2; k++) {
        if (only >= 0 && f->value[k] != only) continue;
        hj_ls_fill(&g, phi, hj_ls_star_fn, (void *)&f->star);
        hj_out out;
        p2_fail_if(o->prog, p2_open(&out, o->out_dir, f->file[k], &err), &err);
        fprintf(out.fp, f->head, hj_ls_accuracy_name(o->acc), f->value[k], o->N);
        p2_commit_run(o->prog, &out, run(&g, f->value[k], phi, out.fp, f->label[k], ctx, &err), &err);
    }
    hj_ls_free(phi);
}

void p2_circle_check(const p2_opts *o, const p2_circle *circ, p2_case_fn run, void *ctx, p2_check *c, const char *tsv,
                     const char *tsv_head, const char *runs, const char *runs_head)
{
    static const long grids[3] = {51, 101, 201};
    double r[3 * 4];
    hj_error err;
    c->grids = grids, c->ngrids = o->quick ? 2 : 3, c->value = r;
    if (c->ncase > 4) hj_cli_fail(o->prog, HJ_EXIT_RUN, "circle check: more than 4 cases");
    for (int n = 0; n < c->ngrids; n++) {
        hj_ls_grid g;
        p2_fail_if(o->prog, p2_square_grid(&g, grids[n], &err), &err);
        double *phi = hj_ls_alloc(&g);
        if (!phi) hj_cli_fail(o->prog, HJ_EXIT_RUN, "out of memory");
        for (int k = 0; k < c->ncase; k++) {
            hj_ls_fill(&g, phi, p2_circle_fn, (void *)circ);
            char label[64];
            snprintf(label, sizeof label, "circle %s, N = %ld", c->case_name[k], grids[n]);
            p2_fail_if(o->prog, run(&g, k, phi, label, ctx, &err), &err);
            p2_fail_if(o->prog, hj_ls_measure_radius(&g, phi, &r[n * c->ncase + k], &err), &err);
        }
        hj_ls_free(phi);
    }
    p2_check_files(o, tsv, tsv_head, runs, runs_head, c);
    c->value = NULL;
}
