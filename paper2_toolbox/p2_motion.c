/* p2_motion.c -- see p2_motion.h. */
#include "p2_motion.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hj_cli.h"
#include "hj_ls_deriv.h"
#include "hj_ls_io.h"
#include "hj_ls_measure.h"
#include "hj_ls_ode.h"
#include "hj_math.h"

int p2_accuracy(const char *name, int *scheme, int *order)
{
    static const char *names[4] = {"low", "medium", "high", "veryHigh"};
    static const int schemes[4] = {HJ_LS_UPWIND_FIRST, HJ_LS_ENO2, HJ_LS_ENO3A, HJ_LS_WENO5A};
    static const int orders[4] = {1, 2, 3, 3};
    for (int k = 0; k < 4; k++)
        if (!strcmp(name, names[k])) {
            *scheme = schemes[k];
            *order = orders[k];
            return 0;
        }
    return -1;
}

int p2_common_option(p2_opts *o, int argc, char **argv, int *i)
{
    const char *a = argv[*i];
    hj_error err;
    if (!strcmp(a, "--help")) {
        printf("%s", o->usage);
        exit(0);
    }
    if (!strcmp(a, "--quick")) {
        o->quick = 1;
        return 1;
    }
    if (strcmp(a, "--accuracy") && strcmp(a, "--N") && strcmp(a, "--out-dir")) return 0;
    if (*i + 1 >= argc) hj_cli_fail(o->prog, HJ_EXIT_USAGE, "option %s needs a value", a);
    const char *v = argv[++*i];
    if (!strcmp(a, "--out-dir")) {
        o->out_dir = v;
    } else if (!strcmp(a, "--accuracy")) {
        if (p2_accuracy(v, &o->scheme, &o->order))
            hj_cli_fail(o->prog, HJ_EXIT_USAGE, "unknown accuracy '%s' (low, medium, high or veryHigh)", v);
        o->accuracy = v;
    } else if (hj_parse_long(v, "--N", 11, 801, &o->N, &err)) {
        hj_cli_fail(o->prog, HJ_EXIT_USAGE, "%s", err.msg);
    }
    return 1;
}

void p2_fail_if(const char *prog, int rc, const hj_error *err)
{
    if (rc) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err->msg);
}

int p2_binary_option(const char *prog, const char *name, int argc, char **argv, int *i, int *value)
{
    if (strcmp(argv[*i], name)) return 0;
    if (*i + 1 >= argc || (strcmp(argv[*i + 1], "0") && strcmp(argv[*i + 1], "1")))
        hj_cli_fail(prog, HJ_EXIT_USAGE, "%s needs 0 or 1", name);
    *value = argv[++*i][0] - '0';
    return 1;
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

int p2_square_grid(hj_ls_grid *g, long n, hj_error *err)
{
    const hj_ls_bc bc[2] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
    const double lo[2] = {-1, -1}, hi[2] = {1, 1};
    const long N[2] = {n, n};
    return hj_ls_grid_init(g, 2, lo, hi, N, bc, err);
}

double p2_star_fn(const double *x, void *ctx)
{
    const p2_star *s = ctx;
    return hypot(x[0], x[1]) - s->scale * (cos(s->points * atan2(x[1], x[0])) + s->shift);
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

static int seq_write(p2_seq *s, int k, double t, const double *y, hj_error *err)
{
    if (s->fp) {
        if (k > 0) fputs("\n\n", s->fp);
        fprintf(s->fp, "# t = %.6g\n", t);
        const char *names[1] = {s->name};
        const double *fields[1] = {y};
        int rc = hj_ls_write_block(s->fp, s->grid, 1, names, fields, err);
        if (rc) return rc;
    }
    if (s->sw && !s->sw->after && t >= s->sw->t_switch) s->sw->after = 1;
    if (s->progress) hj_progress("%s: t = %.4g\n", s->progress, t);
    return s->hook ? s->hook(k, t, y, s->hook_ctx, err) : HJ_OK;
}

static int seq_out(int k, double t, const double *y, void *ctx, hj_error *err)
{
    return seq_write(ctx, k, t, y, err);
}

int p2_run(int order, const hj_ls_grid *g, const hj_ls_term *term, const double *tspan, int n, double *y,
           p2_seq *seq, double factor_cfl, hj_error *err)
{
    int rc = seq_write(seq, 0, tspan[0], y, err);
    if (rc) return rc;
    hj_ls_ode_opts o;
    hj_ls_ode_defaults(&o);
    o.factor_cfl = factor_cfl;
    o.post = seq->post;
    o.post_ctx = seq->post_ctx;
    return hj_ls_ode(order, g, term, tspan, n, y, &o, seq_out, seq, NULL, err);
}

int p2_radius(const hj_ls_grid *g, const double *phi, double *r, hj_error *err)
{
    double m;
    int rc = hj_ls_measure(g, phi, &m, err);
    if (rc) return rc;
    *r = g->dim == 2 ? sqrt(m / HJ_PI) : cbrt(3 * m / (4 * HJ_PI));
    return HJ_OK;
}

int p2_area_hook(int k, double t, const double *y, void *ctx, hj_error *err)
{
    (void)t;
    p2_areas *a = ctx;
    return hj_ls_measure(a->grid, y, &a->area[k], err);
}

int p2_open(hj_out *out, const char *dir, const char *name, hj_error *err)
{
    char path[4096];
    if ((size_t)snprintf(path, sizeof path, "%s/%s", dir, name) >= sizeof path)
        return hj_error_set(err, HJ_EINVAL, "path too long: %s/%s", dir, name);
    return hj_out_open(out, path, err);
}
