/*
# eikonal: solve your own Eikonal problem from the command line

**Problem.** |grad phi| = f(x, y) on a rectangle, with phi given at point
sources: phi is the travel time when f = 1 / speed is the slowness.  The
map comes from a grid file (common/hj_map.h): plain text (one row of
numbers per line, whitespace separated) or a PGM image (P2 or P5; a pixel
value v maps to a + (b - a) v / maxval, see `--pgm-range`).  `--speed FILE`
reads the values as speeds (f = 1 / value, so every value must be
positive), `--slowness FILE` as f itself; `--speed-const V` and
`--slowness-const F` give a uniform medium.  In both formats the first row
is the top of the domain (largest y), as in an image.  Between the map's
nodes f is interpolated bilinearly.

**Method.** The library solver of paper 1 (common/hj_fsm.h): third order
WENO fast sweeping, sources treated by Richardson extrapolation of first
order sweeps in [-2h, 2h]^2 (`--strategy richardson`, the default) or with
the neighbouring nodes frozen at first order (`--strategy first-order`).
The rectangle's boundary is outflow.

**Output.** A TSV grid (x, y, phi) in gnuplot's format (blank line after
each row), to `--out FILE` (written atomically) or stdout with `--out -`.

Example:

    eikonal --speed-const 1 --domain -1,1,-1,1 --N 200 --source 0,0 --out dist.tsv
    eikonal --speed map.pgm --pgm-range 0.5,2 --source 10,20 --out time.tsv
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hj_cli.h"
#include "hj_fsm.h"
#include "hj_io.h"
#include "hj_map.h"
#include "hj_sys.h"

static const char *prog = "eikonal";

static int parse_doubles(const char *s, double *out, int n)
{
    char buf[256];
    if (strlen(s) >= sizeof buf) return -1; /* never cut a list short */
    snprintf(buf, sizeof buf, "%s", s);
    char *p = buf;
    for (int k = 0; k < n; k++) {
        char *comma = strchr(p, ',');
        if ((comma == NULL) != (k == n - 1)) return -1;
        if (comma) *comma = '\0';
        if (hj_parse_double(p, "value", -1e300, 1e300, &out[k], NULL)) return -1;
        p = comma ? comma + 1 : p;
    }
    return 0;
}

/* Exit status of a run that did not converge (its last iterate is written). */
enum { EXIT_NOCONV = 3 };

enum { MAX_SOURCES = 64 };

static void show_progress(int iter, double change, void *ctx)
{
    (void)ctx;
    hj_progress("\reikonal: iteration %d, mean change %.3g   ", iter, change);
}

int main(int argc, char **argv)
{
    const char *speed_file = NULL, *slow_file = NULL, *out_path = "phi.tsv", *pgm_s = "0,1", *dom_s = NULL;
    const char *src_s[MAX_SOURCES];
    double pgm[2] = {0, 1}, dom[4] = {0, 0, 0, 0}, cst = -1, slow_cst = -1;
    int nsrc = 0, strategy = 0;
    long N = -1;
    hj_inflow src[MAX_SOURCES];
    hj_fsm_options opt = hj_fsm_default_options();
    long max_iter = opt.max_iter;
    double delta_rel = 1e-12;
    hj_error err;
    static const char *const strategy_w[] = {"richardson", "first-order", NULL};
    static const hj_bc_strategy strategy_v[] = {HJ_BC_RICHARDSON, HJ_BC_FIRST_ORDER};
    hj_cli_opt opts[] = {
        {.name = "--speed", .type = HJ_OPT_STRING, .value = &speed_file, .metavar = "FILE",
         .help = "speed map (f = 1 / value; every value > 0): plain text grid or PGM (first row = top)"},
        {.name = "--slowness", .type = HJ_OPT_STRING, .value = &slow_file, .metavar = "FILE",
         .help = "slowness map (f = value >= 0), same formats"},
        {.name = "--pgm-range", .type = HJ_OPT_STRING, .value = &pgm_s, .metavar = "A,B",
         .help = "a PGM pixel v maps to the value A + (B - A) v / maxval (a speed image needs A > 0)"},
        {.name = "--speed-const", .type = HJ_OPT_DOUBLE, .value = &cst, .min = 1e-300, .max = 1e300, .metavar = "V",
         .help = "uniform speed V > 0 (f = 1 / V)", .dflt = "none"},
        {.name = "--slowness-const", .type = HJ_OPT_DOUBLE, .value = &slow_cst, .min = 1e-300, .max = 1e300,
         .metavar = "F", .help = "uniform slowness F > 0", .dflt = "none"},
        {.name = "--domain", .type = HJ_OPT_STRING, .value = &dom_s, .metavar = "X0,X1,Y0,Y1", .help = "the rectangle",
         .dflt = "[0, columns-1] x [0, rows-1] of the map, or [0, 1] x [0, 1]"},
        {.name = "--N", .type = HJ_OPT_LONG, .value = &N, .min = 8, .max = 10000, .metavar = "N",
         .help = "intervals in x", .dflt = "the map's columns - 1, or 100"},
        {.name = "--source", .type = HJ_OPT_STRING_LIST, .value = src_s, .metavar = "X,Y[,V]",
         .help = "a point source at a grid node, phi = V there (V = 0 if left out)", .count = &nsrc, .maxn = MAX_SOURCES},
        {.name = "--strategy", .type = HJ_OPT_CHOICE, .value = &strategy, .metavar = "S", .choices = strategy_w,
         .help = "sources: Richardson extrapolation in [-2h, 2h]^2, or neighbours frozen at first order"},
        {.name = "--delta", .type = HJ_OPT_DOUBLE, .value = &delta_rel, .min = 1e-300, .max = 1, .metavar = "X",
         .help = "stop when an iteration's mean |change| < X times the travel-time scale (diagonal times the "
                 "largest slowness)"},
        {.name = "--eps", .type = HJ_OPT_DOUBLE, .value = &opt.eps, .min = 1e-300, .max = 1, .metavar = "X",
         .help = "WENO epsilon"},
        {.name = "--max-iter", .type = HJ_OPT_LONG, .value = &max_iter, .min = 1, .max = 10000000, .metavar = "N",
         .help = "at most N iterations"},
        {.name = "--out", .type = HJ_OPT_STRING, .value = &out_path, .metavar = "FILE",
         .help = "output grid x y phi (- for stdout)"},
    };
    hj_cli_spec spec = {
        .prog = prog,
        .summary = "Solves |grad phi| = f, f = 1 / speed, with phi = V at each --source: the travel time.  Give one\n"
                   "medium (--speed, --slowness, --speed-const or --slowness-const) and at least one --source;\n"
                   "see the top of eikonal.c.",
        .opts = opts,
        .nopts = (int)(sizeof opts / sizeof opts[0]),
        .epilog = "Exit status: 0 converged, 1 a failed run, 2 bad usage, 3 not converged (the last iterate is "
                  "written).\nProgress on stderr when it is a terminal.\n"};
    hj_cli_parse_or_exit(&spec, argc, argv);
    opt.strategy = strategy_v[strategy];
    opt.max_iter = (int)max_iter;
    /* The values with commas, in the order of the checks of the table. */
    if (parse_doubles(pgm_s, pgm, 2) || pgm[0] < 0 || pgm[1] < pgm[0])
        hj_cli_fail(prog, HJ_EXIT_USAGE, "--pgm-range wants A,B with 0 <= A <= B, got '%s'", pgm_s);
    if (dom_s && (parse_doubles(dom_s, dom, 4) || !(dom[1] > dom[0]) || !(dom[3] > dom[2])))
        hj_cli_fail(prog, HJ_EXIT_USAGE, "--domain wants X0,X1,Y0,Y1 with X0 < X1, Y0 < Y1, got '%s'", dom_s);
    const int have_dom = dom_s != NULL;
    for (int k = 0; k < nsrc; k++) {
        double s[3] = {0, 0, 0};
        if (parse_doubles(src_s[k], s, 2) && parse_doubles(src_s[k], s, 3))
            hj_cli_fail(prog, HJ_EXIT_USAGE, "--source wants X,Y or X,Y,VALUE (finite numbers), got '%s'", src_s[k]);
        src[k] = (hj_inflow){.type = HJ_INFLOW_POINT, .x = s[0], .y = s[1], .value = s[2], .richardson = 1};
    }
    const int nmedia = (speed_file != NULL) + (slow_file != NULL) + (cst >= 0) + (slow_cst >= 0);
    if (nmedia == 0)
        hj_cli_fail(prog, HJ_EXIT_USAGE, "give --speed FILE, --slowness FILE, --speed-const V or --slowness-const F (see --help)");
    if (nmedia > 1)
        hj_cli_fail(prog, HJ_EXIT_USAGE, "give only one of --speed, --slowness, --speed-const and --slowness-const");
    if (speed_file && !(pgm[0] > 0) && strstr(speed_file, ".pgm"))
        hj_cli_fail(prog, HJ_EXIT_USAGE, "a speed image needs --pgm-range A,B with A > 0 (the default 0,1 makes pixel 0 a speed of 0)");
    if (nsrc == 0) hj_cli_fail(prog, HJ_EXIT_USAGE, "give at least one --source X,Y");
    /* A bad output location fails now, not after the solve. */
    if (strcmp(out_path, "-") && hj_out_check(out_path, &err)) hj_cli_fail(prog, HJ_EXIT_USAGE, "%s", err.msg);

    hj_map m = {0};
    const char *map_file = speed_file ? speed_file : slow_file;
    if (map_file) {
        if (hj_map_read(&m, map_file, pgm[0], pgm[1], &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
        /* Speeds become slownesses, f = 1 / v. */
        if (speed_file && hj_map_invert(&m, &err)) {
            hj_map_free(&m);
            hj_cli_fail(prog, HJ_EXIT_RUN, "%s: %s (use --slowness for a map of f)", speed_file, err.msg);
        }
        if (!have_dom) {
            dom[0] = 0; dom[1] = m.mx - 1; dom[2] = 0; dom[3] = m.my - 1;
        }
        if (N < 0) N = m.mx - 1;
    } else {
        m.constant = cst >= 0 ? 1 / cst : slow_cst;
        if (!have_dom) { dom[0] = 0; dom[1] = 1; dom[2] = 0; dom[3] = 1; }
        if (N < 0) N = 100;
    }
    m.xmin = dom[0]; m.xmax = dom[1]; m.ymin = dom[2]; m.ymax = dom[3];
    hj_grid2 g;
    g.nx = (int)N;
    g.h = (dom[1] - dom[0]) / N;
    g.x0 = dom[0];
    g.y0 = dom[2];
    /* A cell must be resolvable in the coordinates (and squared in the sweeps). */
    if (!(g.h > 1e-100) || g.x0 + g.h == g.x0 || g.y0 + g.h == g.y0)
        hj_cli_fail(prog, HJ_EXIT_USAGE, "the domain is too small for %ld cells (h = %g): give a larger --domain", N, g.h);
    double ny = (dom[3] - dom[2]) / g.h;
    if (fabs(ny - round(ny)) > 1e-6 * ny || round(ny) < 8)
        hj_cli_fail(prog, HJ_EXIT_USAGE, "the domain height %g is not a whole number (>= 8) of cells of size h = %g", dom[3] - dom[2], g.h);
    g.ny = (int)round(ny);
    if (g.ny > 10000) hj_cli_fail(prog, HJ_EXIT_USAGE, "the grid would have %d rows: at most 10000", g.ny);
    double have = hj_sys_physical_memory();
    if (have > 0 && hj_fsm_memory(&g) > 0.8 * have)
        hj_cli_fail(prog, HJ_EXIT_RUN, "a %dx%d grid needs %.3g GB, more than this machine has", g.nx, g.ny, hj_fsm_memory(&g) / 1e9);
    for (int s = 0; s < nsrc; s++) {
        for (int t = 0; t < s; t++)
            if (fabs(src[t].x - src[s].x) < 1e-9 * g.h && fabs(src[t].y - src[s].y) < 1e-9 * g.h &&
                src[t].value != src[s].value)
                hj_cli_fail(prog, HJ_EXIT_USAGE, "sources %d and %d are at the same node (%g, %g) with different values",
                            t + 1, s + 1, src[s].x, src[s].y);
        double fi = (src[s].x - g.x0) / g.h, fj = (src[s].y - g.y0) / g.h;
        if (fi < 0 || fj < 0 || fi > g.nx || fj > g.ny)
            hj_cli_fail(prog, HJ_EXIT_USAGE, "source (%g, %g) is outside the domain", src[s].x, src[s].y);
        if (fabs(fi - round(fi)) > 1e-9 || fabs(fj - round(fj)) > 1e-9)
            hj_cli_fail(prog, HJ_EXIT_USAGE, "source (%g, %g) is not a grid node; the nearest node is (%.10g, %.10g)", src[s].x,
                        src[s].y, g.x0 + round(fi) * g.h, g.y0 + round(fj) * g.h);
    }
    double *phi = malloc(sizeof(double) * (size_t)(g.nx + 1) * (size_t)(g.ny + 1));
    if (!phi) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory for the %dx%d grid", g.nx, g.ny);
    hj_speed sp = {hj_map_eval, NULL, &m};
    /* The stopping rule in the problem's own scale: an iteration's mean
     * |change| below delta times the largest travel time the domain allows,
     * its diagonal times the largest slowness, whatever the units. */
    double fmax = m.constant;
    for (long k = 0; m.v && k < (long)m.mx * m.my; k++) fmax = m.v[k] > fmax ? m.v[k] : fmax;
    const double scale = hypot(dom[1] - dom[0], dom[3] - dom[2]) * (fmax > 0 ? fmax : 1);
    opt.stop_norm = HJ_STOP_L1_MEAN;
    opt.delta = delta_rel * scale;
    opt.progress = show_progress;
    hj_fsm_stats st;
    int rc = hj_fsm_solve(&g, &sp, src, nsrc, &opt, phi, &st, &err);
    hj_progress("\n");
    const int converged = rc == HJ_OK;
    if (rc && rc != HJ_ENOCONV) { free(phi); hj_map_free(&m); hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg); }
    if (!converged)
        fprintf(stderr, "%s: warning: %s; the last iterate is written, exit status %d\n", prog, err.msg, EXIT_NOCONV);
    hj_out out = {0};
    FILE *fp = stdout;
    if (strcmp(out_path, "-")) {
        if (hj_out_open(&out, out_path, &err)) { free(phi); hj_map_free(&m); hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg); }
        fp = out.fp;
    }
    fprintf(fp, "# eikonal: %dx%d intervals, h = %g, %d WENO iterations%s\n# x\ty\tphi\n", g.nx, g.ny, g.h,
            st.iterations, converged ? "" : " (not converged: the last iterate)");
    for (int j = 0; j <= g.ny; j++) {
        for (int i = 0; i <= g.nx; i++)
            fprintf(fp, "%.10g\t%.10g\t%.12g\n", g.x0 + i * g.h, g.y0 + j * g.h, phi[(long)j * (g.nx + 1) + i]);
        fputc('\n', fp);
    }
    free(phi);
    hj_map_free(&m);
    if (fp != stdout && hj_out_commit(&out, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    if (fp == stdout && fflush(stdout)) hj_cli_fail(prog, HJ_EXIT_RUN, "error writing stdout");
    return converged ? 0 : EXIT_NOCONV;
}
