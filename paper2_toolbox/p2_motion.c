/* p2_motion.c -- see p2_motion.h. */
#include "p2_motion.h"

#include <math.h>
#include <stdio.h>

#include "hj_cli.h"
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

int p2_circle_radii(const long *grids, int ngrids, const p2_circle *circ, int ncase, const char *const *case_name,
                    p2_case_fn run, void *ctx, double *r, hj_error *err)
{
    int rc = HJ_OK;
    for (int n = 0; n < ngrids && !rc; n++) {
        hj_ls_grid g;
        if ((rc = p2_square_grid(&g, grids[n], err))) break;
        double *phi = hj_ls_alloc(&g);
        if (!phi) return hj_error_set(err, HJ_ENOMEM, "out of memory");
        for (int c = 0; c < ncase && !rc; c++) {
            hj_ls_fill(&g, phi, p2_circle_fn, (void *)circ);
            char label[64];
            snprintf(label, sizeof label, "circle %s, N = %ld", case_name[c], grids[n]);
            rc = run(&g, c, phi, label, ctx, err);
            if (!rc) rc = hj_ls_measure_radius(&g, phi, &r[n * ncase + c], err);
        }
        hj_ls_free(phi);
    }
    return rc;
}

void p2_check_rows(FILE *fp, const long *grids, int ngrids, int ncase, const char *const *case_name,
                   const double *value, const double *exact)
{
    for (int n = 0; n < ngrids; n++)
        for (int c = 0; c < ncase; c++) {
            const double v = value[n * ncase + c];
            fprintf(fp, "%ld\t%s\t%.6f\t%.6f\t%.3e\n", grids[n], case_name[c], v, exact[c], fabs(v - exact[c]));
        }
}

void p2_check_notes(FILE *fp, const long *grids, int ngrids, int ncase, const char *const *case_label,
                    const double *value, const double *exact)
{
    for (int n = 0; n < ngrids; n++)
        for (int c = 0; c < ncase; c++) {
            const double v = value[n * ncase + c];
            fprintf(fp, "| %ld | %s | %.5f | %.2f | %.2e | %.3f |\n", grids[n], case_label[c], v, exact[c],
                    fabs(v - exact[c]), fabs(v - exact[c]) * (grids[n] - 1) / 2.0);
        }
}
