/* p3_prog.c -- shared command line and output helpers (see p3_prog.h). */
#include "p3_prog.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "hj_cli.h"
#include "hj_ub.h"

void p3_args_parse(p3_args *a, int argc, char **argv, const char *summary, const char *extra, long first_table,
                   long last_table)
{
    a->out_dir = ".";
    a->quick = 0;
    a->nsizes = 0;
    a->max_n = 0;
    a->ntables = 0;
    a->extra = 0;
    a->plan = 0;
    a->published = "paper3_ultrabee/published";
    hj_cli_opt opts[] = {
        {.name = "--quick", .type = HJ_OPT_FLAG, .value = &a->quick, .help = "reduced sizes (CI)"},
        {.name = "--out-dir", .type = HJ_OPT_STRING, .value = &a->out_dir, .metavar = "DIR",
         .help = "where to write the tables"},
        {.name = "--sizes", .type = HJ_OPT_LONG_LIST, .value = a->sizes, .min = 8, .max = 100000, .metavar = "N,N,...",
         .help = "the grid sizes to run instead of the published ones", .count = &a->nsizes, .maxn = P3_MAX_SIZES,
         .dflt = "the published ones"},
        {.name = "--max-n", .type = HJ_OPT_LONG, .value = &a->max_n, .min = 8, .max = 100000, .metavar = "N",
         .help = "skip the sizes above N", .dflt = "none"},
        {.name = "--tables", .type = HJ_OPT_LONG_LIST, .value = a->tables, .min = (double)first_table,
         .max = (double)last_table, .metavar = "T,T,...", .help = "only these tables (numbers)", .count = &a->ntables,
         .maxn = P3_MAX_SIZES, .dflt = "all"},
        {.name = "--extra", .type = HJ_OPT_FLAG, .value = &a->extra, .help = a->extra_help},
        {.name = "--plan", .type = HJ_OPT_FLAG, .value = &a->plan,
         .help = "print for each table and cell whether it would run and why (published value, predicted CPU time, "
                 "store above 1 GB), then exit without running anything"},
        {.name = "--published", .type = HJ_OPT_STRING, .value = &a->published, .metavar = "DIR",
         .help = "the paper's tables (tableN.tsv), which say the cells the paper has a value for"},
    };
    /* --extra, --plan and --published are last */
    const int nopts = (int)(sizeof opts / sizeof opts[0]) - 3 * (a->extra_help == NULL);
    hj_cli_spec spec = {a->prog, summary, opts, nopts, extra};
    hj_cli_parse_or_exit(&spec, argc, argv);
    if (a->quick && a->nsizes) hj_cli_fail(a->prog, HJ_EXIT_USAGE, "give --quick or --sizes, not both");
}

int p3_want(const p3_args *a, long t)
{
    if (a->ntables == 0) return 1;
    for (int i = 0; i < a->ntables; i++)
        if (a->tables[i] == t) return 1;
    return 0;
}

_Noreturn void p3_die(const char *prog, const hj_error *err) { hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err->msg); }

int p3_open(hj_out *out, const char *dir, const char *name, hj_error *err)
{
    int rc = hj_mkdirs(dir, err);
    if (rc) return rc;
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    return hj_out_open(out, path, err);
}

const char *p3_num(char *buf, double v)
{
    if (isnan(v)) strcpy(buf, "-");
    else snprintf(buf, 32, "%.4g", v);
    return buf;
}

int p3_fig_block(FILE *fp, int d, int n, double lo, double dx, const int *i0, const int *m, int nf,
                 const double *const *f, hj_error *err)
{
    int64_t total = 1;
    for (int k = 0; k < d; k++) total *= m[k];
    for (int64_t q = 0; q < total; q++) {
        int idx[4];
        int64_t r = q, lin = 0;
        for (int k = d - 1; k >= 0; k--) { idx[k] = i0[k] + (int)(r % m[k]); r /= m[k]; }
        for (int k = 0; k < d; k++) {
            lin = lin * n + idx[k];
            fprintf(fp, "%s%.6g", k ? " " : "", lo + idx[k] * dx);
        }
        for (int j = 0; j < nf; j++) fprintf(fp, " %.6g", f[j][lin]);
        fputc('\n', fp);
        if ((idx[d - 1] - i0[d - 1]) == m[d - 1] - 1) fputc('\n', fp);
    }
    fputs("\n", fp);
    if (ferror(fp)) return hj_error_set(err, HJ_EIO, "write error (figure data)");
    return HJ_OK;
}

static const double BALL3_CENTRE[3] = {0, 0, 0};

double p3_ball3_avg(const double *blo, const double *bhi, void *ctx)
{
    (void)ctx;
    return hj_ub_avg_ball(3, blo, bhi, BALL3_CENTRE, 1.0, 4);
}

int p3_ball3_uniform(const double *blo, const double *bhi, void *ctx)
{
    (void)ctx;
    return hj_ub_ball_uniform(3, blo, bhi, BALL3_CENTRE, 1.0);
}

double p3_plan_time(const p3_plan *p) { return p->world ? P3_PLAN_DEAR : 0.0; }

int p3_plan_note(p3_plan *p, const char *label, const char *text, hj_error *err)
{
    const int w = p->world;
    if (p->n[w] == p->cap[w]) {
        const int cap = p->cap[w] ? 2 * p->cap[w] : 256;
        char **l = realloc(p->label[w], (size_t)cap * sizeof *l);
        if (l) p->label[w] = l;
        char **t = realloc(p->text[w], (size_t)cap * sizeof *t);
        if (t) p->text[w] = t;
        if (!l || !t) return hj_error_set(err, HJ_ENOMEM, "out of memory (plan)");
        p->cap[w] = cap;
    }
    char *l = strdup(label), *t = strdup(text);
    if (!l || !t) {
        free(l);
        free(t);
        return hj_error_set(err, HJ_ENOMEM, "out of memory (plan)");
    }
    p->label[w][p->n[w]] = l;
    p->text[w][p->n[w]++] = t;
    return HJ_OK;
}

int p3_plan_print(const p3_plan *p, FILE *fp, hj_error *err)
{
    if (p->n[0] != p->n[1]) return hj_error_set(err, HJ_EFORMAT, "plan: the two walks noted %d and %d cells", p->n[0], p->n[1]);
    for (int i = 0; i < p->n[0]; i++) {
        if (strcmp(p->label[0][i], p->label[1][i]))
            return hj_error_set(err, HJ_EFORMAT, "plan: cell %d is %s in one walk, %s in the other", i, p->label[0][i],
                                p->label[1][i]);
        if (!strcmp(p->text[0][i], p->text[1][i])) fprintf(fp, "%s\t%s\n", p->label[0][i], p->text[0][i]);
        else
            fprintf(fp, "%s\tdepends on measured time (if cheap: %s; if dear: %s)\n", p->label[0][i], p->text[0][i],
                    p->text[1][i]);
    }
    if (fflush(fp) || ferror(fp)) return hj_error_set(err, HJ_EIO, "write error (plan)");
    return HJ_OK;
}

void p3_plan_free(p3_plan *p)
{
    for (int w = 0; w < 2; w++) {
        for (int i = 0; i < p->n[w]; i++) {
            free(p->label[w][i]);
            free(p->text[w][i]);
        }
        free(p->label[w]);
        free(p->text[w]);
    }
    memset(p, 0, sizeof *p);
}

int p3_pub_read(p3_pub *p, const char *dir, const char *name, hj_error *err)
{
    memset(p, 0, sizeof *p);
    char path[4096];
    snprintf(path, sizeof path, "%s/%s.tsv", dir, name);
    int rc = hj_table_read(&p->t, path, err);
    if (rc == HJ_EIO && err) { /* the default directory is relative to the repository's root */
        char msg[sizeof err->msg];
        snprintf(msg, sizeof msg, "%s", err->msg);
        return hj_error_set(err, rc, "%s (run from the repository's root or give --published DIR)", msg);
    }
    if (rc) return rc;
    const char *key = hj_table_meta(&p->t, "key");
    char buf[256];
    snprintf(buf, sizeof buf, "%s", key ? key : "");
    for (char *save = NULL, *w = strtok_r(buf, " ", &save); w; w = strtok_r(NULL, " ", &save)) {
        const int c = hj_table_col(&p->t, w);
        if (c < 0 || p->nkey == 4) {
            p3_pub_free(p);
            return hj_error_set(err, HJ_EFORMAT, "%s: key column %s %s", path, w, c < 0 ? "absent" : "beyond 4");
        }
        p->key[p->nkey++] = c;
    }
    if (!p->nkey) {
        p3_pub_free(p);
        return hj_error_set(err, HJ_EFORMAT, "%s: no '# key:' header", path);
    }
    return HJ_OK;
}

void p3_pub_free(p3_pub *p)
{
    hj_table_free(&p->t);
    memset(p, 0, sizeof *p);
}

/* A cell holds a value: not empty and not "-" (hjcheck's "no value"). */
static int has_value(const char *cell) { return cell[0] && strcmp(cell, "-"); }

int p3_pub_has(const p3_pub *p, const long *key, const char *q)
{
    char ratio[64];
    snprintf(ratio, sizeof ratio, "%s_ratio", q);
    const int cq = hj_table_col(&p->t, q), cr = hj_table_col(&p->t, ratio);
    for (int r = 0; r < p->t.nrows; r++) {
        int same = 1;
        for (int k = 0; k < p->nkey && same; k++) {
            char *end;
            const char *cell = p->t.cells[r][p->key[k]];
            same = strtol(cell, &end, 10) == key[k] && end != cell && *end == 0;
        }
        if (same) return (cq >= 0 && has_value(p->t.cells[r][cq])) || (cr >= 0 && has_value(p->t.cells[r][cr]));
    }
    return 0;
}

int p3_store_big(hj_band_kind kind, int d, long n)
{
    double total = 1;
    for (int i = 0; i < d; i++) total *= (double)n;
    return (kind == HJ_BAND_FS || kind == HJ_BAND_FLS) && total * 9.0 > 1e9;
}

void p3_col_record(p3_col *c, double t)
{
    c->t2 = c->t1;
    c->t1 = t;
    c->n++;
}

/* The budget of a cell: an unpublished one gets P3_EXTRA_BUDGET at most. */
static double budget_of(const p3_rule *r, int published)
{
    if (published || r->extra) return r->budget;
    return P3_EXTRA_BUDGET < r->budget ? P3_EXTRA_BUDGET : r->budget;
}

p3_decision p3_rule_decide(const p3_rule *r, const p3_col *c, int d, int published, int big)
{
    if (published || r->extra) {
        if (c->n == 0 || isinf(r->budget)) return P3_RUN;
        if (isnan(c->t1)) return P3_SKIP_SMALLER;
    } else {
        if (c->n > 0 && isnan(c->t1)) return P3_SKIP_SMALLER;
        if (big) return P3_SKIP_BIG;
        if (c->n == 0) return P3_RUN;
    }
    const double growth = c->n >= 2 && c->t2 > 0 ? c->t1 / c->t2 : (double)(1 << d);
    return r->scale * c->t1 * (growth > 2 ? growth : 2) <= budget_of(r, published) ? P3_RUN : P3_SKIP_COST;
}

const char *p3_decision_text(char *buf, size_t size, const p3_rule *r, p3_decision dec, int published)
{
    switch (dec) {
    case P3_RUN: snprintf(buf, size, "run"); break;
    case P3_SKIP_SMALLER: snprintf(buf, size, "skip: a smaller size is not run"); break;
    case P3_SKIP_BIG: snprintf(buf, size, "skip: full store above 1 GB"); break;
    case P3_SKIP_COST: snprintf(buf, size, "skip: predicted above %g s", budget_of(r, published)); break;
    }
    return buf;
}

int p3_rule_listed(p3_decision dec, int published) { return !published && dec != P3_RUN && dec != P3_SKIP_SMALLER; }
