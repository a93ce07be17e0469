/*
# eikonal: solve your own Eikonal problem from the command line

**Problem.** |grad T| = f on a rectangle (2-D) or a box (3-D), f = 1 /
speed the slowness, T the travel time from the sources: points anywhere
in the domain (`--source`, `--sources FILE`) and/or a polyline with
boundary values (`--polyline FILE`).  Nothing crosses an obstacle: a node
of speed 0 or one marked in `--obstacle MASK`.

**Inputs.** `--speed FILE` reads speeds (f = 1 / value; 0 is an
obstacle), `--slowness FILE` slownesses (every value > 0); or a uniform
`--speed-const` / `--slowness-const` on `--domain` with `--N` intervals
along x.  A map's format is told by its content (common/hj_vol.h): a PGM
image (P2/P5, 8 or 16 bit; pixel v maps to A + (B - A) v / maxval,
`--pgm-range`), a text grid (one row per line, the first line the top
row; slices of a 3-D volume separated by blank lines, bottom slice
first), or with `--raw NX,NY,NZ` a raw little-endian float32/float64
volume (x fastest, bottom row and slice first).  The grid is the map's
nodes: pixel units (one unit per pixel, bottom-left node at the origin)
unless `--domain` gives the box, whose sides need not make dx = dy.

**Method.** The library solver common/hj_eik.h: fast sweeping at order 1,
3 or 5, factored near point sources (full order at the source), stopped
when an iteration changes T by at most `--tol` times max |T| (scale-free:
pixel units or metres alike).  Where the map is rough at the grid scale
(noise at the pixel scale, or a sharp step between regions: a band about
four nodes wide along it) orders 3 and 5 use the first order update at
those nodes; the count is printed on stderr and in the output's header.
Where the fronts of two sources meet T has a kink, and one solve with all
the sources is first order in max norm there; `--separate-sources` solves
each source (and the polyline) alone and takes the minimum, which keeps
the order, at the cost of one solve each (the header's counts are their
sums).

**Output.** 2-D: a TSV grid (x, y, T; a blank line after each row, as
gnuplot's splot wants) or `--format matrix` (one row of T per line,
bottom row first, for `plot ... matrix with image`); T = inf where no
front arrives.  3-D: a legacy VTK file (structured points; -1 where no
front arrives).  Written atomically to `--out`.

Examples (from a fresh clone, see README.md):

    eikonal --speed examples/data/speed.pgm --pgm-range 0,2 --source 10,10 --out time.tsv
    eikonal --speed examples/data/volume.txt --source 2,2,2 --out time.vtk
    eikonal --speed-const 1 --domain 0,40,0,40 --N 40 --obstacle examples/data/wall.txt --source 5,20 --out wall.tsv
*/
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "hj_cli.h"
#include "hj_eik.h"
#include "hj_io.h"
#include "hj_sys.h"
#include "hj_vol.h"

static const char *prog = "eikonal";

/* Exit statuses beyond hj_cli's 1 (failed run) and 2 (bad usage). */
enum { EXIT_NOCONV = 3, EXIT_UNREACHED = 4 };

enum { MAX_SOURCES = 64, MAX_POINTS = 1000000 };

/* n comma-separated finite numbers, whole string. */
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

/* How many comma-separated fields s has. */
static int count_fields(const char *s)
{
    int n = 1;
    for (; *s; s++) n += *s == ',';
    return n;
}

/* A file of points, one per line: lo..hi numbers separated by white space
 * or commas; '#' starts a comment, blank lines are skipped.  *pts (malloc)
 * holds *np rows of hi numbers, the missing trailing ones 0.  Exits with
 * one message on a bad line. */
static double *read_points(const char *path, const char *what, int lo, int hi, long *np)
{
    hj_error err;
    FILE *f = hj_in_open(path, "r", &err);
    if (!f) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    long cap = 64, n = 0, line = 0;
    double *pts = malloc(sizeof *pts * (size_t)(cap * hi));
    char buf[1024], q[64];
    if (!pts) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory");
    while (fgets(buf, sizeof buf, f)) {
        line++;
        size_t len = strlen(buf);
        if (len == sizeof buf - 1 && buf[len - 1] != '\n') {
            fclose(f);
            hj_cli_fail(prog, HJ_EXIT_RUN, "%s:%ld: line longer than %d bytes", path, line, (int)sizeof buf - 2);
        }
        char *hash = strchr(buf, '#');
        if (hash) *hash = '\0';
        double v[4] = {0, 0, 0, 0};
        int k = 0;
        char *p = buf;
        for (;;) {
            while (*p && (isspace((unsigned char)*p) || *p == ',')) p++;
            if (!*p) break;
            char *end;
            errno = 0;
            const double x = strtod(p, &end);
            if (end == p || (*end && !isspace((unsigned char)*end) && *end != ',') || !isfinite(x) || k == hi) {
                char *stop = p;
                while (*stop && !isspace((unsigned char)*stop) && *stop != ',') stop++;
                fclose(f);
                if (k == hi)
                    hj_cli_fail(prog, HJ_EXIT_RUN, "%s:%ld: more than %d numbers in a %s", path, line, hi, what);
                hj_cli_fail(prog, HJ_EXIT_RUN, "%s:%ld: '%s' is not a finite number", path, line,
                            hj_error_quote(p, (size_t)(stop - p), q, sizeof q));
            }
            v[k++] = x;
            p = end;
        }
        if (k == 0) continue;
        if (k < lo) {
            fclose(f);
            hj_cli_fail(prog, HJ_EXIT_RUN, "%s:%ld: a %s needs %d%s numbers, this line has %d", path, line, what, lo,
                        lo < hi ? " or more" : "", k);
        }
        if (n == MAX_POINTS) {
            fclose(f);
            hj_cli_fail(prog, HJ_EXIT_RUN, "%s: more than %d points", path, MAX_POINTS);
        }
        if (n == cap) {
            double *p2 = realloc(pts, sizeof *pts * (size_t)(2 * cap * hi));
            if (!p2) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory");
            pts = p2;
            cap *= 2;
        }
        memcpy(pts + n * hi, v, sizeof *v * (size_t)hi);
        n++;
    }
    const int bad = ferror(f);
    fclose(f);
    if (bad) hj_cli_fail(prog, HJ_EXIT_RUN, "error reading %s", path);
    if (n == 0) hj_cli_fail(prog, HJ_EXIT_RUN, "%s: no %s in the file", path, what);
    *np = n;
    return pts;
}

/* A map is read by its size (raw) or twice (its first bytes tell the
 * format, then its values): a pipe or a device (--speed /dev/stdin, a
 * shell's <(...)) lost the bytes of the first read, and the message then
 * spoke of a malformed file.  A directory is left to the reader, which
 * names it. */
static void need_regular(const char *path)
{
    struct stat sb;
    if (stat(path, &sb) == 0 && !S_ISREG(sb.st_mode) && !S_ISDIR(sb.st_mode))
        hj_cli_fail(prog, HJ_EXIT_RUN,
                    "%s is a pipe or a device, not a regular file: a map is read by its size or twice (its format, then "
                    "its values); write it to a file first",
                    path);
}

/* A map file: raw when dims are given, else told by content. */
static void read_map(hj_vol *v, const char *path, const long *raw, int raw_bytes, const double *pgm)
{
    hj_error err;
    need_regular(path);
    const int rc = raw ? hj_vol_read_raw(v, path, raw, raw_bytes, &err) : hj_vol_read(v, path, pgm[0], pgm[1], &err);
    /* the library names its raw reader; a user of the tool needs the option */
    const char *bin = rc && !raw ? strstr(err.msg, " (binary data:") : NULL;
    if (bin)
        hj_cli_fail(prog, HJ_EXIT_RUN, "%.*s (binary data: a raw volume is read with --raw NX,NY[,NZ])",
                    (int)(bin - err.msg), err.msg);
    if (rc) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
}

/* "(x, y)" or "(x, y, z)" in a static buffer, for a message. */
static const char *point_str(const double *x, int dim)
{
    static char buf[128];
    if (dim == 3) snprintf(buf, sizeof buf, "(%g, %g, %g)", x[0], x[1], x[2]);
    else snprintf(buf, sizeof buf, "(%g, %g)", x[0], x[1]);
    return buf;
}

static void show_progress(long iter, double change, void *ctx)
{
    (void)ctx;
    hj_progress("\reikonal: iteration %ld, max change %.3g of max |T|   ", iter, change);
}

/* Whether coordinate x lies in [lo, hi] up to a rounding of the cell. */
static int inside(double x, double lo, double hi, double h)
{
    return x >= lo - 1e-9 * h && x <= hi + 1e-9 * h;
}

/* The nodes within half a cell of the polyline pts (npts rows of dim + 1
 * numbers: a point and its value g) get, in fixed, g at their nearest
 * point of the line (linear along each segment) plus f times the
 * distance to it: T to first order in the cell's size, exact for a
 * straight line of constant g.  A node near several segments keeps the
 * least.  Returns how many nodes are fixed. */
static long fix_polyline(const hj_eik_grid *g, const double *pts, long npts, const double *f, double f_const,
                         const unsigned char *obst, double *fixed)
{
    const int dim = g->dim, w = dim + 1;
    double hmax = 0;
    for (int d = 0; d < dim; d++) hmax = g->dx[d] > hmax ? g->dx[d] : hmax;
    const double r = 0.5 * hmax;
    long count = 0;
    for (long s = 0; s + 1 < (npts > 1 ? npts : 2); s++) {
        const double *a = pts + s * w, *b = npts > 1 ? pts + (s + 1) * w : a;
        long lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
        double ab[3] = {0, 0, 0}, ab2 = 0;
        for (int d = 0; d < dim; d++) {
            const double m0 = a[d] < b[d] ? a[d] : b[d], m1 = a[d] < b[d] ? b[d] : a[d];
            lo[d] = (long)ceil((m0 - r - g->x0[d]) / g->dx[d]);
            hi[d] = (long)floor((m1 + r - g->x0[d]) / g->dx[d]);
            lo[d] = lo[d] < 0 ? 0 : lo[d];
            hi[d] = hi[d] > g->n[d] - 1 ? g->n[d] - 1 : hi[d];
            ab[d] = b[d] - a[d];
            ab2 += ab[d] * ab[d];
        }
        for (long k = lo[2]; k <= hi[2]; k++)
            for (long j = lo[1]; j <= hi[1]; j++)
                for (long i = lo[0]; i <= hi[0]; i++) {
                    const long id = i + g->n[0] * (j + g->n[1] * k);
                    if (obst && obst[id]) continue;
                    const long ix[3] = {i, j, k};
                    double x[3], t = 0;
                    for (int d = 0; d < dim; d++) {
                        x[d] = g->x0[d] + ix[d] * g->dx[d];
                        t += (x[d] - a[d]) * ab[d];
                    }
                    t = ab2 > 0 ? t / ab2 : 0;
                    t = t < 0 ? 0 : t > 1 ? 1 : t;
                    double dist2 = 0;
                    for (int d = 0; d < dim; d++) {
                        const double e = x[d] - (a[d] + t * ab[d]);
                        dist2 += e * e;
                    }
                    if (dist2 > r * r * (1 + 1e-12)) continue;
                    const double val = a[dim] + t * (b[dim] - a[dim]) + (f ? f[id] : f_const) * sqrt(dist2);
                    if (isnan(fixed[id])) count++;
                    if (isnan(fixed[id]) || val < fixed[id]) fixed[id] = val;
                }
    }
    return count;
}

/* T as text: "x y [z] T" lines with a blank line after each row
 * (gnuplot's grid format), or with matrix one row of T per line, bottom
 * row first; a header of comments first. */
static void write_text(FILE *fp, const hj_eik_grid *g, const double *T, int matrix, const char *title)
{
    /* the coordinates and spacings to T's 12 digits: a reference computed
     * from the file's x and y (10 digits before) differed from the exact
     * one by up to 5e-10 at x = 1.5135135135 */
    fprintf(fp, "# %s\n# grid %ld x %ld x %ld nodes, dx %.12g %.12g %.12g\n", title, g->n[0], g->n[1], g->n[2], g->dx[0],
            g->dx[1], g->dx[2]);
    if (matrix) {
        for (long j = 0; j < g->n[1]; j++)
            for (long i = 0; i < g->n[0]; i++) fprintf(fp, "%.12g%c", T[j * g->n[0] + i], i + 1 < g->n[0] ? '\t' : '\n');
        return;
    }
    fputs(g->dim == 3 ? "# x\ty\tz\tT\n" : "# x\ty\tT\n", fp);
    for (long k = 0; k < g->n[2]; k++)
        for (long j = 0; j < g->n[1]; j++) {
            for (long i = 0; i < g->n[0]; i++) {
                fprintf(fp, "%.12g\t%.12g\t", g->x0[0] + (double)i * g->dx[0], g->x0[1] + (double)j * g->dx[1]);
                if (g->dim == 3) fprintf(fp, "%.12g\t", g->x0[2] + (double)k * g->dx[2]);
                fprintf(fp, "%.12g\n", T[i + g->n[0] * (j + g->n[1] * k)]);
            }
            fputc('\n', fp);
        }
}

/* The node index of x when x is a grid node (to rounding), else -1. */
static long node_at(const hj_eik_grid *g, const double *x)
{
    long id = 0, stride = 1;
    for (int d = 0; d < g->dim; d++) {
        const double u = (x[d] - g->x0[d]) / g->dx[d];
        if (fabs(u - round(u)) > 1e-9 || u < -0.5 || u > (double)g->n[d] - 0.5) return -1;
        id += (long)round(u) * stride;
        stride *= g->n[d];
    }
    return id;
}

int main(int argc, char **argv)
{
    /* The default output; a 3-D result written as VTK by default goes to T.vtk. */
    static const char default_out[] = "T.tsv";
    const char *speed_file = NULL, *slow_file = NULL, *obst_file = NULL, *out_path = default_out, *pgm_s = "0,1";
    const char *dom_s = NULL, *raw_s = NULL, *sources_file = NULL, *poly_file = NULL;
    const char *src_s[MAX_SOURCES];
    double pgm[2] = {0, 1}, dom[6] = {0, 0, 0, 0, 0, 0}, cst = -1, slow_cst = -1;
    int nsrc_s = 0, order_i = 1, format = 0, raw_type = 0;
    long N = -1, max_iter;
    hj_eik_options opt = hj_eik_default_options();
    max_iter = opt.max_iter;
    static const char *const order_w[] = {"1", "3", "5", NULL};
    static const int order_v[] = {1, 3, 5};
    for (int k = 0; k < 3; k++)
        if (order_v[k] == opt.order) order_i = k;
    static const char *const format_w[] = {"auto", "tsv", "matrix", "vtk", NULL};
    static const char *const raw_w[] = {"float32", "float64", NULL};
    hj_error err;
    hj_cli_opt opts[] = {
        {.name = "--speed", .type = HJ_OPT_STRING, .value = &speed_file, .metavar = "FILE",
         .help = "speed map (f = 1 / value; 0 = obstacle): PGM, text grid or volume, or raw with --raw"},
        {.name = "--slowness", .type = HJ_OPT_STRING, .value = &slow_file, .metavar = "FILE",
         .help = "slowness map (f = value, every value > 0), same formats"},
        {.name = "--speed-const", .type = HJ_OPT_DOUBLE, .value = &cst, .min = 1e-300, .max = 1e300, .metavar = "V",
         .help = "uniform speed V > 0 (f = 1 / V) on --domain", .dflt = "none"},
        {.name = "--slowness-const", .type = HJ_OPT_DOUBLE, .value = &slow_cst, .min = 1e-300, .max = 1e300,
         .metavar = "F", .help = "uniform slowness F > 0 on --domain", .dflt = "none"},
        {.name = "--obstacle", .type = HJ_OPT_STRING, .value = &obst_file, .metavar = "FILE",
         .help = "mask, same formats and size as the grid: nonzero nodes are never crossed"},
        {.name = "--pgm-range", .type = HJ_OPT_STRING, .value = &pgm_s, .metavar = "A,B",
         .help = "a PGM pixel v maps to A + (B - A) v / maxval (with --speed, 0 is an obstacle)"},
        {.name = "--raw", .type = HJ_OPT_STRING, .value = &raw_s, .metavar = "NX,NY[,NZ]",
         .help = "the map (and mask) files are raw little-endian volumes of these dimensions, x fastest",
         .dflt = "none: PGM or text, told by content"},
        {.name = "--raw-type", .type = HJ_OPT_CHOICE, .value = &raw_type, .metavar = "T", .choices = raw_w,
         .help = "value type of --raw files"},
        {.name = "--domain", .type = HJ_OPT_STRING, .value = &dom_s, .metavar = "X0,X1,Y0,Y1[,Z0,Z1]",
         .help = "the box; the map's nodes span it (dx and dy may differ)",
         .dflt = "a map: pixel units [0, NX-1] x [0, NY-1] (x [0, NZ-1]); constant: [0, 1]^2"},
        {.name = "--N", .type = HJ_OPT_LONG, .value = &N, .min = 2, .max = 100000, .metavar = "N",
         .help = "constant medium: N intervals along x, the other sides in cells as near to square as fit",
         .dflt = "100"},
        {.name = "--source", .type = HJ_OPT_STRING_LIST, .value = src_s, .metavar = "X,Y[,Z][,T0]",
         .help = "a point source anywhere in the domain, T = T0 there (0 if left out)", .count = &nsrc_s,
         .maxn = MAX_SOURCES},
        {.name = "--sources", .type = HJ_OPT_STRING, .value = &sources_file, .metavar = "FILE",
         .help = "point sources, one per line: x y [z] [t0] ('#' comments)"},
        {.name = "--polyline", .type = HJ_OPT_STRING, .value = &poly_file, .metavar = "FILE",
         .help = "a polyline, one vertex per line: x y [z] T; nodes within half a cell of it are fixed (near several segments: the least time, as with several sources)"},
        {.name = "--order", .type = HJ_OPT_CHOICE, .value = &order_i, .metavar = "P", .choices = order_w,
         .help = "order of the sweeping scheme"},
        {.name = "--tol", .type = HJ_OPT_DOUBLE, .value = &opt.tol, .min = 1e-300, .max = 1, .metavar = "X",
         .help = "stop when an iteration changes T by at most X times max |T| (scale-free)"},
        {.name = "--max-iter", .type = HJ_OPT_LONG, .value = &max_iter, .min = 1, .max = 100000000, .metavar = "N",
         .help = "at most N iterations (convergence tests: 2^dim sweeps each; one orthant pass with one point "
                 "source and no obstacle or fixed nodes; one grid's worth of solves with --causal-sweeps)"},
        {.name = "--separate-sources", .type = HJ_OPT_FLAG, .value = &opt.separate_sources,
         .help = "with two or more sources (a polyline counts as one), solve each alone and take the minimum: "
                 "the scheme's order also where fronts meet, at the cost of one solve per source (--max-iter "
                 "bounds each)"},
        {.name = "--causal-sweeps", .type = HJ_OPT_FLAG, .value = &opt.causal_sweeps,
         .help = "orders 3 and 5 with obstacles, several sources or fixed nodes: each node solved once per "
                 "iteration, in the sweep along its upwind sides: about 0.75-0.9 times the work on walls, mazes "
                 "and two sources, but more on some, in about 3 times the iterations (--max-iter counts them); "
                 "the result within a few times --tol of the default's, except where order 5 demotes rough nodes "
                 "to order 3 (differences up to 1e-3 relative; docs/API.md)"},
        {.name = "--format", .type = HJ_OPT_CHOICE, .value = &format, .metavar = "F", .choices = format_w,
         .help = "output: auto (tsv in 2-D, vtk in 3-D), tsv (x y [z] T), matrix (2-D), vtk"},
        {.name = "--out", .type = HJ_OPT_STRING, .value = &out_path, .metavar = "FILE",
         .help = "output file (default T.tsv, T.vtk for a 3-D result written as VTK; - for stdout, not for vtk)"},
    };
    hj_cli_spec spec = {
        .prog = prog,
        .summary = "Solves |grad T| = f, f = 1 / speed, from point sources and/or a polyline: the travel time, in\n"
                   "2-D or 3-D, around obstacles.  Give one medium (--speed, --slowness, --speed-const or\n"
                   "--slowness-const) and a source (--source, --sources or --polyline); see the top of eikonal.c.",
        .opts = opts,
        .nopts = (int)(sizeof opts / sizeof opts[0]),
        .epilog = "Exit status: 0 converged, every node reached; 1 a failed run (unreadable or malformed file, a\n"
                  "source in an obstacle); 2 bad usage; 3 not converged within --max-iter (the last iterate is\n"
                  "written, with a warning); 4 converged, but some nodes are walled off from every source (written\n"
                  "as inf, -1 in VTK; their count on stderr).  Progress on stderr when it is a terminal.\n"};
    hj_cli_parse_or_exit(&spec, argc, argv);
    int pgm_given = 0, raw_type_given = 0;
    for (int k = 0; k < spec.nopts; k++) {
        if (!strcmp(opts[k].name, "--pgm-range")) pgm_given = opts[k].seen;
        if (!strcmp(opts[k].name, "--raw-type")) raw_type_given = opts[k].seen;
    }
    opt.order = order_v[order_i];
    opt.max_iter = max_iter;

    /* ---- the command line alone, before any file is read ---- */
    if (parse_doubles(pgm_s, pgm, 2) || pgm[0] < 0 || pgm[1] < pgm[0])
        hj_cli_fail(prog, HJ_EXIT_USAGE, "--pgm-range wants A,B with 0 <= A <= B, got '%s'", pgm_s);
    int dom_dim = 0;
    if (dom_s) {
        dom_dim = count_fields(dom_s) == 6 ? 3 : 2;
        if (parse_doubles(dom_s, dom, 2 * dom_dim) || !(dom[1] > dom[0]) || !(dom[3] > dom[2]) ||
            (dom_dim == 3 && !(dom[5] > dom[4])))
            hj_cli_fail(prog, HJ_EXIT_USAGE,
                        "--domain wants X0,X1,Y0,Y1 or X0,X1,Y0,Y1,Z0,Z1 with X0 < X1, Y0 < Y1, Z0 < Z1, got '%s'", dom_s);
    }
    long raw[3] = {0, 0, 1};
    if (raw_s) {
        const int nr = count_fields(raw_s);
        if ((nr != 2 && nr != 3) ||
            hj_parse_long_list(raw_s, "--raw", 2, 100000000, raw, 3, &(int){0}, NULL))
            hj_cli_fail(prog, HJ_EXIT_USAGE, "--raw wants NX,NY or NX,NY,NZ, each from 2 to 100000000, got '%s'", raw_s);
        if (nr == 2) raw[2] = 1;
    }
    const int nmedia = (speed_file != NULL) + (slow_file != NULL) + (cst >= 0) + (slow_cst >= 0);
    if (nmedia == 0)
        hj_cli_fail(prog, HJ_EXIT_USAGE, "give --speed FILE, --slowness FILE, --speed-const V or --slowness-const F (see --help)");
    if (nmedia > 1)
        hj_cli_fail(prog, HJ_EXIT_USAGE, "give only one of --speed, --slowness, --speed-const and --slowness-const");
    const char *map_file = speed_file ? speed_file : slow_file;
    if (map_file && N >= 0)
        hj_cli_fail(prog, HJ_EXIT_USAGE, "--N is for a constant medium; a map's grid is its own nodes (see --domain)");
    if (raw_s && !map_file && !obst_file)
        hj_cli_fail(prog, HJ_EXIT_USAGE, "--raw describes a --speed, --slowness or --obstacle file: none is given");
    /* an option that would be ignored is refused: the user meant something by it */
    if (raw_type_given && !raw_s)
        hj_cli_fail(prog, HJ_EXIT_USAGE, "--raw-type is the value type of --raw files: give --raw NX,NY[,NZ] too");
    if (pgm_given && !map_file)
        hj_cli_fail(prog, HJ_EXIT_USAGE, "--pgm-range maps the pixels of a --speed or --slowness PGM: none is given");
    if (pgm_given && raw_s)
        hj_cli_fail(prog, HJ_EXIT_USAGE, "--pgm-range maps the pixels of a PGM, but --raw reads the map as a raw volume");
    if (nsrc_s == 0 && !sources_file && !poly_file)
        hj_cli_fail(prog, HJ_EXIT_USAGE, "give a source: --source X,Y, --sources FILE or --polyline FILE");
    if (format == 3 && !strcmp(out_path, "-"))
        hj_cli_fail(prog, HJ_EXIT_USAGE, "--format vtk needs --out FILE (not stdout)");
    /* A bad output location fails now, not after the solve. */
    if (strcmp(out_path, "-") && hj_out_check(out_path, &err)) hj_cli_fail(prog, HJ_EXIT_USAGE, "%s", err.msg);

    /* ---- the grid and the medium ---- */
    hj_eik_grid g = {0};
    hj_vol map = {0}, mask = {0};
    const int raw_bytes = raw_type ? 8 : 4;
    if (map_file) {
        if (pgm_given) { /* a text grid's values are taken as they are */
            int is_pgm = 0;
            need_regular(map_file);
            if (hj_vol_is_pgm(map_file, &is_pgm, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
            if (!is_pgm)
                hj_cli_fail(prog, HJ_EXIT_USAGE, "--pgm-range maps the pixels of a PGM, but %s is not one (a text "
                            "grid's values are used as they are)", map_file);
        }
        read_map(&map, map_file, raw_s ? raw : NULL, raw_bytes, pgm);
        if (hj_vol_check_nonzero(&map, map_file, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
        g.dim = map.dim;
        for (int d = 0; d < 3; d++) g.n[d] = map.n[d];
        if (dom_s && dom_dim != g.dim)
            hj_cli_fail(prog, HJ_EXIT_RUN, "%s is %d-D, --domain '%s' %d-D", map_file, g.dim, dom_s, dom_dim);
        for (int d = 0; d < g.dim; d++) {
            g.x0[d] = dom_s ? dom[2 * d] : 0;
            g.dx[d] = dom_s ? (dom[2 * d + 1] - dom[2 * d]) / (double)(g.n[d] - 1) : 1;
        }
    } else {
        g.dim = dom_s ? dom_dim : 2;
        if (!dom_s) dom[1] = dom[3] = 1;
        const long nx = N >= 0 ? N : 100;
        const double h = (dom[1] - dom[0]) / (double)nx;
        for (int d = 0; d < g.dim; d++) {
            const double len = dom[2 * d + 1] - dom[2 * d];
            const double cells = d == 0 ? (double)nx : round(len / h);
            if (cells > 100000)
                hj_cli_fail(prog, HJ_EXIT_USAGE, "the grid would have %.0f cells along %c: at most 100000", cells, "xyz"[d]);
            g.n[d] = (long)(cells < 1 ? 1 : cells) + 1;
            g.x0[d] = dom[2 * d];
            g.dx[d] = len / (double)(g.n[d] - 1);
            /* a cell must be resolvable in the coordinates */
            if (!(g.dx[d] > 1e-100) || g.x0[d] + g.dx[d] == g.x0[d])
                hj_cli_fail(prog, HJ_EXIT_USAGE, "the domain is too small for %ld cells (h = %g): give a larger --domain",
                            g.n[d] - 1, g.dx[d]);
        }
    }
    if (g.dim == 2) g.n[2] = 1, g.x0[2] = 0, g.dx[2] = 1;
    if ((format == 2) && g.dim == 3) hj_cli_fail(prog, HJ_EXIT_USAGE, "--format matrix is for 2-D grids; use vtk or tsv");
    /* the solver's own check numbers dimensions from 0; the tool names the axis */
    for (int d = 0; d < g.dim; d++)
        if (g.n[d] < (opt.order == 1 ? 2 : opt.order))
            hj_cli_fail(prog, HJ_EXIT_RUN, "the grid has %ld nodes along %c; order %d needs at least %d: give --order %d%s",
                        g.n[d], "xyz"[d], opt.order, opt.order, g.n[d] >= 3 ? 3 : 1,
                        map_file ? "" : " or a larger --domain along it");
    const long total = g.n[0] * g.n[1] * g.n[2];
    /* The peak: the solver's work arrays, 56 bytes per node of the grid
     * padded by 3 ghost layers on each side (hj_eik.c: tau, T0, f, owner,
     * label, stamps, flags, the obstacle distance, the high order
     * arrays), T (8 bytes a node), the map (8) and the mask (1), and with
     * --separate-sources the running minimum and its flags (10).  Measured
     * peaks: 60 bytes a node for a constant medium at 2001^2, 72-82 for a
     * PGM map with a mask, 88 at 81^3 with --separate-sources (the old
     * figure, 48, let grids through that needed up to twice that). */
    double padded = 1;
    for (int d = 0; d < g.dim; d++) padded *= (double)(g.n[d] + 6);
    const double per_node = 8 + (map_file ? 8 : 0) + (map_file || obst_file ? 1 : 0) + (opt.separate_sources ? 10 : 0);
    const double have = hj_sys_physical_memory(), need = 56.0 * padded + per_node * (double)total;
    if (have > 0 && need > 0.8 * have)
        hj_cli_fail(prog, HJ_EXIT_RUN, "a grid of %ld nodes needs about %.3g GB, more than this machine has", total, need / 1e9);

    unsigned char *obst = NULL;
    long nobst = 0;
    if (obst_file) {
        read_map(&mask, obst_file, raw_s ? raw : NULL, raw_bytes, (const double[2]){0, 1});
        if (mask.n[0] != g.n[0] || mask.n[1] != g.n[1] || mask.n[2] != g.n[2])
            hj_cli_fail(prog, HJ_EXIT_RUN, "the mask %s is %ld x %ld x %ld, the grid %ld x %ld x %ld", obst_file, mask.n[0],
                        mask.n[1], mask.n[2], g.n[0], g.n[1], g.n[2]);
    }
    double *f = NULL, f_const = cst >= 0 ? 1 / cst : slow_cst;
    if (map_file || obst_file) obst = calloc((size_t)total, 1);
    if (map_file) f = map.v; /* turned into slownesses in place */
    if ((map_file || obst_file) && !obst) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory");
    for (long k = 0; k < total && obst; k++) {
        if (mask.v && mask.v[k] != 0) obst[k] = 1;
        if (f && speed_file) {
            if (f[k] == 0) obst[k] = 1;
            else if (!obst[k] && !isfinite(1 / f[k])) /* a speed so small that 1 / speed overflows */
                hj_cli_fail(prog, HJ_EXIT_RUN, "%s: speed %g at node (%ld, %ld, %ld) is too small (1 / speed overflows)",
                            speed_file, f[k], k % g.n[0], k / g.n[0] % g.n[1], k / (g.n[0] * g.n[1]));
            else f[k] = 1 / f[k];
        } else if (f && f[k] == 0 && !obst[k]) {
            hj_cli_fail(prog, HJ_EXIT_RUN,
                        "%s: slowness 0 at node (%ld, %ld, %ld): every slowness must be > 0 (an obstacle is a speed of "
                        "0 with --speed, or --obstacle)",
                        slow_file, k % g.n[0], k / g.n[0] % g.n[1], k / (g.n[0] * g.n[1]));
        }
        nobst += obst[k];
    }
    hj_vol_free(&mask);
    if (obst && nobst == total) hj_cli_fail(prog, HJ_EXIT_RUN, "every node is an obstacle: nothing can be reached");

    /* ---- sources ---- */
    const int dim = g.dim;
    /* A 3-D grid is written as VTK unless a format is given: a file, never stdout. */
    if (!format && dim == 3 && out_path == default_out) out_path = "T.vtk";
    if (!format && dim == 3 && !strcmp(out_path, "-"))
        hj_cli_fail(prog, HJ_EXIT_USAGE, "a 3-D result is written as VTK, which needs --out FILE (not stdout); or give --format tsv");
    long npts = 0;
    double *pts = NULL; /* rows of 4: x, y, z, t0 */
    if (sources_file) {
        double *p = read_points(sources_file, "source", dim, dim + 1, &npts);
        pts = malloc(sizeof *pts * 4 * (size_t)(npts + nsrc_s));
        if (!pts) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory");
        for (long s = 0; s < npts; s++) {
            double *q = pts + 4 * s;
            q[0] = p[s * (dim + 1)], q[1] = p[s * (dim + 1) + 1];
            q[2] = dim == 3 ? p[s * (dim + 1) + 2] : 0;
            q[3] = p[s * (dim + 1) + dim];
        }
        free(p);
    } else {
        pts = malloc(sizeof *pts * 4 * (size_t)(nsrc_s > 0 ? nsrc_s : 1));
        if (!pts) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory");
    }
    for (int s = 0; s < nsrc_s; s++) {
        double v[4] = {0, 0, 0, 0};
        const int nf = count_fields(src_s[s]);
        if ((nf != dim && nf != dim + 1) || parse_doubles(src_s[s], v, nf))
            hj_cli_fail(prog, HJ_EXIT_USAGE, "--source wants %s (numbers within +-1e300) on this %d-D grid, got '%s'",
                        dim == 2 ? "X,Y or X,Y,T0" : "X,Y,Z or X,Y,Z,T0", dim, src_s[s]);
        double *q = pts + 4 * npts++;
        q[0] = v[0], q[1] = v[1], q[2] = dim == 3 ? v[2] : 0, q[3] = v[dim];
    }
    if (npts > 0x7fffffff) hj_cli_fail(prog, HJ_EXIT_RUN, "too many sources");
    hj_eik_source *src = malloc(sizeof *src * (size_t)(npts > 0 ? npts : 1));
    if (!src) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory");
    const int status_src = sources_file ? HJ_EXIT_RUN : HJ_EXIT_USAGE;
    for (long s = 0; s < npts; s++) {
        const double *q = pts + 4 * s;
        for (int d = 0; d < dim; d++)
            if (!inside(q[d], g.x0[d], g.x0[d] + (double)(g.n[d] - 1) * g.dx[d], g.dx[d]))
                hj_cli_fail(prog, status_src, "source %ld is outside the domain: its %c coordinate is %g, not in [%g, %g]",
                            s + 1, "xyz"[d], q[d], g.x0[d], g.x0[d] + (double)(g.n[d] - 1) * g.dx[d]);
        for (long t = 0; t < s; t++) {
            const double *r = pts + 4 * t;
            int same = 1;
            for (int d = 0; d < dim; d++) same &= fabs(q[d] - r[d]) <= 1e-9 * g.dx[d];
            if (same && q[3] != r[3])
                hj_cli_fail(prog, status_src, "sources %ld and %ld are at the same point with different times %g and %g",
                            t + 1, s + 1, r[3], q[3]);
        }
        if (obst) { /* on an obstacle node (the solver also refuses one nearest to an obstacle) */
            const long id = node_at(&g, q);
            if (id >= 0 && obst[id])
                hj_cli_fail(prog, HJ_EXIT_RUN, "source %ld at %s is inside an obstacle", s + 1, point_str(q, dim));
        }
        src[s] = (hj_eik_source){.x = {q[0], q[1], q[2]}, .t0 = q[3]};
    }
    free(pts);

    double *fixed = NULL;
    if (poly_file) {
        long nv = 0;
        double *p = read_points(poly_file, "polyline vertex", dim + 1, dim + 1, &nv);
        for (long s = 0; s < nv; s++)
            for (int d = 0; d < dim; d++)
                if (!inside(p[s * (dim + 1) + d], g.x0[d], g.x0[d] + (double)(g.n[d] - 1) * g.dx[d], g.dx[d]))
                    hj_cli_fail(prog, HJ_EXIT_RUN, "%s: vertex %ld is outside the domain", poly_file, s + 1);
        /* a segment of length 0 between two times would keep the first
         * (the second depended on the order of the lines): refused, as
         * two point sources at one point with different times are */
        for (long s = 1; s < nv; s++) {
            const double *q = p + s * (dim + 1), *r = q - (dim + 1);
            int same = 1;
            for (int d = 0; d < dim; d++) same &= fabs(q[d] - r[d]) <= 1e-9 * g.dx[d];
            if (same && q[dim] != r[dim])
                hj_cli_fail(prog, HJ_EXIT_RUN, "%s: vertices %ld and %ld are at the same point with different times %g and %g",
                            poly_file, s, s + 1, r[dim], q[dim]);
        }
        fixed = malloc(sizeof *fixed * (size_t)total);
        if (!fixed) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory");
        for (long k = 0; k < total; k++) fixed[k] = NAN;
        const long nfix = fix_polyline(&g, p, nv, f, f_const, obst, fixed);
        free(p);
        if (nfix == 0)
            hj_cli_fail(prog, HJ_EXIT_RUN, "%s: no free node lies within half a cell of the polyline", poly_file);
        /* a point source on a fixed node must agree with it */
        for (long s = 0; s < npts; s++) {
            const long id = node_at(&g, src[s].x);
            if (id >= 0 && !isnan(fixed[id]) && fabs(fixed[id] - src[s].t0) > 1e-9 * (fabs(fixed[id]) + 1))
                hj_cli_fail(prog, HJ_EXIT_RUN,
                            "source %ld sits on a node the polyline fixes at %g, with a different time %g", s + 1,
                            fixed[id], src[s].t0);
        }
    }

    /* ---- solve ---- */
    double *T = malloc(sizeof *T * (size_t)total);
    if (!T) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory for %ld nodes", total);
    opt.progress = show_progress;
    hj_eik_stats st = {0};
    /* a map without a zero (or an empty mask) has no obstacle: no mask
     * array for the solver (it would skip the mask's sight lines anyway) */
    if (obst && nobst == 0) {
        free(obst);
        obst = NULL;
    }
    int rc = hj_eik_solve(&g, f, f_const, obst, src, (int)npts, fixed, &opt, T, &st, &err);
    hj_progress("\n");
    free(obst);
    hj_vol_free(&map);
    if (rc && rc != HJ_ENOCONV) {
        free(T);
        hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    }
    const int converged = rc == HJ_OK;
    hj_error why = err; /* the solver's reason, kept from the output's calls */
    /* T can never fall below the earliest start: below it (or NaN) the
     * iteration has blown up, and such numbers are not written. */
    double t_min = INFINITY;
    for (long s = 0; s < npts; s++) t_min = src[s].t0 < t_min ? src[s].t0 : t_min;
    for (long k = 0; fixed && k < total; k++) t_min = fixed[k] < t_min ? fixed[k] : t_min;
    for (long k = 0; k < total; k++)
        if (isnan(T[k]) || T[k] < t_min - 1e-6 * (fabs(t_min) + 1)) {
            hj_cli_fail(prog, HJ_EXIT_RUN,
                        "the order %d iteration blew up (T = %g at node (%ld, %ld, %ld), below the earliest source "
                        "time %g); nothing is written: try --order %d",
                        opt.order, T[k], k % g.n[0], k / g.n[0] % g.n[1], k / (g.n[0] * g.n[1]), t_min,
                        opt.order > 1 ? opt.order - 2 : 1);
        }
    free(src);
    const int fixed_any = fixed != NULL;
    free(fixed);

    /* ---- output ---- */
    const int fmt = format ? format : dim == 3 ? 3 : 1;
    char title[512], fell[96] = "";
    if (st.first_order > 0)
        snprintf(fell, sizeof fell, ", %zu node%s at first order (map not resolved there)", st.first_order,
                 hj_plural((long)st.first_order));
    /* the solves: one, or with --separate-sources one per source and
     * one for the polyline (the counts below are their sums) */
    const long nsolves = opt.separate_sources ? npts + (fixed_any != 0) : 1;
    char sep[160] = "";
    int at = 0;
    if (nsolves > 1) at = snprintf(sep, sizeof sep, ", %ld separate solves (sums)", nsolves);
    if (st.orthant_stalled > 0) /* arrivals came back toward the source (hj_eik.h) */
        snprintf(sep + at, sizeof sep - (size_t)at, ", full sweeps after iteration %ld (the orthant passes stalled)",
                 st.orthant_stalled);
    snprintf(title, sizeof title,
             "eikonal: T, order %d%s, %ld iteration%s (%ld grid sweep%s)%s%s, change %.3g of max |T|", opt.order, fell,
             st.iterations, hj_plural(st.iterations), st.sweeps, hj_plural(st.sweeps), sep,
             converged ? "" : " (not converged: the last iterate)", st.change);
    if (fmt == 3) {
        if (hj_vol_write_vtk(out_path, g.n, g.x0, g.dx, title, "T", T, -1, &err)) {
            free(T);
            hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
        }
    } else {
        hj_out out = {0};
        FILE *fp = stdout;
        if (strcmp(out_path, "-")) {
            if (hj_out_open(&out, out_path, &err)) { free(T); hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg); }
            fp = out.fp;
        }
        write_text(fp, &g, T, fmt == 2, title);
        if (fp != stdout && hj_out_commit(&out, &err)) { free(T); hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg); }
        if (fp == stdout) hj_cli_flush_stdout(prog);
    }
    free(T);
    /* on a terminal, with the progress: what was written where */
    if (strcmp(out_path, "-")) {
        char dims[96];
        if (dim == 3) snprintf(dims, sizeof dims, "%ld x %ld x %ld", g.n[0], g.n[1], g.n[2]);
        else snprintf(dims, sizeof dims, "%ld x %ld", g.n[0], g.n[1]);
        hj_progress("%s: wrote T on %s nodes (%s) to %s\n", prog, dims, fmt == 3 ? "VTK" : fmt == 2 ? "matrix" : "TSV",
                    out_path);
    }
    /* the loss of order is stated, not an error: the result is still the
     * upwind (first order) solution there */
    if (st.first_order > 0)
        fprintf(stderr, "%s: note: the order %d scheme fell back to the first order update at %zu of %ld nodes "
                        "(%.1f %%), where the map is rough at the grid scale (noise, or along a sharp step) or "
                        "the high order update was not trustworthy; T is first order accurate there\n",
                prog, opt.order, st.first_order, total, 100.0 * (double)st.first_order / (double)total);
    /* the solver's message says why (max_iter used up, tol below the
     * rounding level, the first order start took every iteration, a
     * result that failed its check): the advice differs with the reason */
    if (!converged) {
        /* the solver's message ends by saying the last iterate is kept */
        const char *kept = "; the last iterate is kept";
        const size_t lm = strlen(why.msg), lk = strlen(kept);
        if (lm >= lk && !strcmp(why.msg + lm - lk, kept)) why.msg[lm - lk] = 0;
        fprintf(stderr, "%s: warning: %s (--tol %g, --max-iter %ld); the last iterate is written, exit status %d\n",
                prog, why.msg, opt.tol, opt.max_iter, EXIT_NOCONV);
        return EXIT_NOCONV;
    }
    if (st.unreachable > 0) {
        fprintf(stderr, "%s: %zu of %ld nodes outside the obstacles cannot be reached from any source (walled off); "
                        "they are written as %s, exit status %d\n",
                prog, st.unreachable, total, fmt == 3 ? "-1" : "inf", EXIT_UNREACHED);
        return EXIT_UNREACHED;
    }
    return 0;
}
