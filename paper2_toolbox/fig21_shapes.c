/*
# Figure 21: shapes and constructive solid geometry in 1, 2 and 3 dimensions

**Problem.** The toolbox's `initialConditionsTest1D/2D/3D` (section 2.7.1):
implicit surface functions (negative inside) of basic shapes combined by
constructive solid geometry (section 3.3), built with `common/hj_ls_shape.h`.

- 1-D on [-1, 1]: an interval (sphere), a half-line (rectangle with an
  unbounded side), the difference of two intervals, a complement; shown as
  function plots (the shape is where the function is negative).
- 2-D on [-1, 1]^2: (a) a square subtracted from a circle (the disc of
  radius 0.6 minus the square [0, 0.8]^2: three quarters of the disc);
  (b) a non-convex polygon, the L made of two rectangles, each the
  intersection of four hyperplanes.
- 3-D on [-1, 1]^3: (c) the union of a sphere (radius 0.5 at (-0.25, 0, 0))
  and a cube (side 0.6 at (0.3, 0, 0)); (d) the octahedron |x|+|y|+|z| <= 0.7,
  the intersection of eight hyperplanes.

**Check.** The measure of each set (the fraction of nodes where the
function is negative, a node on the boundary counting one half, times the
domain's measure) against the exact length, area or volume, on 201, 201^2
and 81^3 nodes: it should agree to about a cell's width times the
boundary's measure (fig21_checks.tsv, presented by notes/fig21_checks.md).

**Output.** fig21.tsv (the measures, held by `make check` against the
exact ones in published/fig21.tsv), fig21_1d.tsv, fig21_2d.tsv (gnuplot grid), fig21_3d.dat
(x y z c d, for gnuplot's voxel isosurfaces) and fig21_3d.vtk (legacy VTK,
both 3-D fields), fig21_checks.tsv; plotted by paper2_toolbox/plot/fig21.gp.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "hj_cli.h"
#include "hj_io.h"
#include "hj_ls_grid.h"
#include "hj_ls_shape.h"
#include "hj_math.h"

static const char *prog = "fig21_shapes";

/* Measure of {phi < 0}: node fraction times the box's measure, a node on
 * the boundary (|phi| < 1e-12, e.g. on a grid line) counting one half. */
static double measure(const hj_ls_grid *g, const double *phi)
{
    long i[HJ_LS_MAXDIM] = {0};
    double inside = 0;
    double box = 1;
    for (int d = 0; d < g->dim; d++) box *= g->max[d] - g->min[d] + g->dx[d]; /* cells around the nodes */
    for (size_t r = 0; r < g->rows; r++) {
        size_t k = hj_ls_row(g, r, i);
        for (long a = 0; a < g->N[0]; a++) {
            const double v = phi[k + (size_t)a];
            inside += v < -1e-12 ? 1.0 : v <= 1e-12 ? 0.5 : 0.0;
        }
    }
    return box * inside / (double)g->nodes;
}

static void die_if(int rc, hj_error *err)
{
    if (rc) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err->msg);
}

/* The intersection of the four half-planes of the box [lo, hi] (2-D). */
static void box_from_hyperplanes(const hj_ls_grid *g, const double *lo, const double *hi, double *out, double *tmp,
                                 hj_error *err)
{
    const double n[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
    const double p[4][2] = {{lo[0], 0}, {hi[0], 0}, {0, lo[1]}, {0, hi[1]}};
    die_if(hj_ls_shape_hyperplane(g, n[0], p[0], out, err), err);
    for (int k = 1; k < 4; k++) {
        die_if(hj_ls_shape_hyperplane(g, n[k], p[k], tmp, err), err);
        hj_ls_shape_intersection(g, out, tmp, out);
    }
}

int main(int argc, char **argv)
{
    const char *out_dir = ".";
    int quick = 0;
    hj_cli_opt opts[] = {
        {.name = "--out-dir", .type = HJ_OPT_STRING, .value = &out_dir, .metavar = "DIR",
         .help = "where the tables, figure data and VTK file go"},
        {.name = "--quick", .type = HJ_OPT_FLAG, .value = &quick, .help = "accepted: the run is small already"},
    };
    hj_cli_spec spec = {prog,
                        "Figure 21 of Mitchell's toolbox: shapes and constructive solid geometry in 1, 2 and 3 "
                        "dimensions.",
                        opts, 2, "See the comment at the top of fig21_shapes.c.\n"};
    hj_cli_parse_or_exit(&spec, argc, argv);
    hj_error err;
    if (hj_mkdirs(out_dir, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    const hj_ls_bc bc[3] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
    const double lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 1};
    char path[4096];
    hj_out out;
    double m[8], exact[8];
    const char *id[8];
    int nm = 0;

    /* 1-D */
    hj_ls_grid g1;
    const long n1 = 201;
    die_if(hj_ls_grid_init(&g1, 1, lo, hi, &n1, bc, &err), &err);
    double *f[4], *tmp = hj_ls_alloc(&g1);
    for (int k = 0; k < 4; k++) f[k] = hj_ls_alloc(&g1);
    if (!tmp || !f[0] || !f[1] || !f[2] || !f[3]) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory");
    const double c0 = 0.1, up = 0.3, minf = -INFINITY, c2 = -0.2;
    die_if(hj_ls_shape_sphere(&g1, &c0, 0.5, f[0], &err), &err);                   /* [-0.4, 0.6] */
    die_if(hj_ls_shape_rectangle_corners(&g1, &minf, &up, f[1], &err), &err);      /* (-inf, 0.3] */
    die_if(hj_ls_shape_sphere(&g1, &c2, 0.2, tmp, &err), &err);                    /* [-0.4, 0] */
    hj_ls_shape_difference(&g1, f[0], tmp, f[2]);                                    /* (0, 0.6] */
    hj_ls_shape_complement(&g1, f[0], f[3]);                                         /* outside */
    const double ex1[4] = {1.0, 1.3, 0.6, 1.0};
    const char *i1[4] = {"interval_1d", "half_line_1d", "difference_1d", "complement_1d"};
    for (int k = 0; k < 4; k++) { m[nm] = measure(&g1, f[k]); exact[nm] = ex1[k]; id[nm++] = i1[k]; }
    snprintf(path, sizeof path, "%s/fig21_1d.tsv", out_dir);
    if (hj_out_open(&out, path, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    fprintf(out.fp, "# x\tinterval\thalf_line\tdifference\tcomplement\n");
    for (long a = 0; a < n1; a++) {
        double x;
        hj_ls_coord(&g1, &a, &x);
        size_t k = hj_ls_index(&g1, &a);
        fprintf(out.fp, "%.5f\t%.6f\t%.6f\t%.6f\t%.6f\n", x, f[0][k], f[1][k], f[2][k], f[3][k]);
    }
    if (hj_out_commit(&out, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    for (int k = 0; k < 4; k++) hj_ls_free(f[k]);
    hj_ls_free(tmp);

    /* 2-D */
    hj_ls_grid g2;
    const long n2[2] = {201, 201};
    die_if(hj_ls_grid_init(&g2, 2, lo, hi, n2, bc, &err), &err);
    double *a2 = hj_ls_alloc(&g2), *b2 = hj_ls_alloc(&g2), *t2 = hj_ls_alloc(&g2), *u2 = hj_ls_alloc(&g2);
    if (!a2 || !b2 || !t2 || !u2) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory");
    const double o2[2] = {0, 0}, sq_lo[2] = {0, 0}, sq_hi[2] = {0.8, 0.8};
    die_if(hj_ls_shape_sphere(&g2, o2, 0.6, a2, &err), &err);
    die_if(hj_ls_shape_rectangle_corners(&g2, sq_lo, sq_hi, t2, &err), &err);
    hj_ls_shape_difference(&g2, a2, t2, a2);
    const double r1lo[2] = {-0.6, -0.6}, r1hi[2] = {0.6, -0.1}, r2lo[2] = {-0.6, -0.6}, r2hi[2] = {-0.1, 0.6};
    box_from_hyperplanes(&g2, r1lo, r1hi, b2, t2, &err);
    box_from_hyperplanes(&g2, r2lo, r2hi, u2, t2, &err);
    hj_ls_shape_union(&g2, b2, u2, b2);
    m[nm] = measure(&g2, a2); exact[nm] = 0.75 * HJ_PI * 0.36; id[nm++] = "disc_minus_square_2d";
    m[nm] = measure(&g2, b2); exact[nm] = 1.2 * 0.5 + 0.5 * 0.7; id[nm++] = "L_polygon_2d";
    snprintf(path, sizeof path, "%s/fig21_2d.tsv", out_dir);
    if (hj_out_open(&out, path, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    fprintf(out.fp, "# x\ty\ta\tb (gnuplot grid format)\n");
    for (long j = 0; j < n2[1]; j++) {
        for (long i = 0; i < n2[0]; i++) {
            long ij[2] = {i, j};
            double x[2];
            hj_ls_coord(&g2, ij, x);
            size_t k = hj_ls_index(&g2, ij);
            fprintf(out.fp, "%.5f\t%.5f\t%.6f\t%.6f\n", x[0], x[1], a2[k], b2[k]);
        }
        fputc('\n', out.fp);
    }
    if (hj_out_commit(&out, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    hj_ls_free(a2); hj_ls_free(b2); hj_ls_free(t2); hj_ls_free(u2);

    /* 3-D */
    hj_ls_grid g3;
    const long n3[3] = {81, 81, 81};
    die_if(hj_ls_grid_init(&g3, 3, lo, hi, n3, bc, &err), &err);
    double *c3 = hj_ls_alloc(&g3), *d3 = hj_ls_alloc(&g3), *t3 = hj_ls_alloc(&g3);
    if (!c3 || !d3 || !t3) hj_cli_fail(prog, HJ_EXIT_RUN, "out of memory");
    const double sc[3] = {-0.25, 0, 0}, cc[3] = {0.3, 0, 0}, cw[3] = {0.6, 0.6, 0.6};
    die_if(hj_ls_shape_sphere(&g3, sc, 0.5, c3, &err), &err);
    die_if(hj_ls_shape_rectangle_center(&g3, cc, cw, t3, &err), &err);
    hj_ls_shape_union(&g3, c3, t3, c3);
    const double a = 0.7;
    for (int s = 0; s < 8; s++) {
        const double n[3] = {s & 1 ? 1 : -1, s & 2 ? 1 : -1, s & 4 ? 1 : -1};
        const double p[3] = {a * n[0] / 3, a * n[1] / 3, a * n[2] / 3}; /* on n . x = a */
        die_if(hj_ls_shape_hyperplane(&g3, n, p, s ? t3 : d3, &err), &err);
        if (s) hj_ls_shape_intersection(&g3, d3, t3, d3);
    }
    m[nm] = measure(&g3, c3); exact[nm] = NAN; id[nm++] = "sphere_union_cube_3d";
    m[nm] = measure(&g3, d3); exact[nm] = 4.0 / 3.0 * a * a * a; id[nm++] = "octahedron_3d";
    snprintf(path, sizeof path, "%s/fig21_3d.dat", out_dir);
    if (hj_out_open(&out, path, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    fprintf(out.fp, "# x y z c d\n");
    hj_out vtk;
    snprintf(path, sizeof path, "%s/fig21_3d.vtk", out_dir);
    if (hj_out_open(&vtk, path, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    fprintf(vtk.fp, "# vtk DataFile Version 3.0\nFigure 21 (c) and (d): implicit surface functions\nASCII\n"
                    "DATASET STRUCTURED_POINTS\nDIMENSIONS %ld %ld %ld\nORIGIN -1 -1 -1\nSPACING %g %g %g\n"
                    "POINT_DATA %zu\n",
            n3[0], n3[1], n3[2], g3.dx[0], g3.dx[1], g3.dx[2], g3.nodes);
    for (int field = 0; field < 2; field++) {
        fprintf(vtk.fp, "SCALARS %s double 1\nLOOKUP_TABLE default\n", field ? "octahedron" : "sphere_union_cube");
        for (long k = 0; k < n3[2]; k++)
            for (long j = 0; j < n3[1]; j++)
                for (long i = 0; i < n3[0]; i++) {
                    long ijk[3] = {i, j, k};
                    size_t q = hj_ls_index(&g3, ijk);
                    fprintf(vtk.fp, "%.6g\n", field ? d3[q] : c3[q]);
                    if (!field) {
                        double x[3];
                        hj_ls_coord(&g3, ijk, x);
                        fprintf(out.fp, "%.4f %.4f %.4f %.6f %.6f\n", x[0], x[1], x[2], c3[q], d3[q]);
                    }
                }
    }
    if (hj_out_commit(&out, &err) || hj_out_commit(&vtk, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    hj_ls_free(c3); hj_ls_free(d3); hj_ls_free(t3);

    /* The measures as a table for make check (reference: the exact measures,
     * paper2_toolbox/published/fig21.tsv). */
    snprintf(path, sizeof path, "%s/fig21.tsv", out_dir);
    if (hj_out_open(&out, path, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    fprintf(out.fp, "# fig21: measure of {phi < 0} by node counting\nset\tmeasure\n");
    for (int k = 0; k < nm; k++) fprintf(out.fp, "%s\t%.6f\n", id[k], m[k]);
    if (hj_out_commit(&out, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);

    /* The measures to full precision against the exact ones ("-" where
     * none is known), for the report's note (notes/fig21_checks.md). */
    snprintf(path, sizeof path, "%s/fig21_checks.tsv", out_dir);
    if (hj_out_open(&out, path, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    fprintf(out.fp, "# fig21: measure of {phi < 0} (node fraction times the box measure) against the exact one\n"
                    "set\tmeasure\texact\trel_diff_percent\n");
    for (int k = 0; k < nm; k++) {
        if (isfinite(exact[k]))
            fprintf(out.fp, "%s\t%.17g\t%.17g\t%.17g\n", id[k], m[k], exact[k], 100 * (m[k] / exact[k] - 1));
        else
            fprintf(out.fp, "%s\t%.17g\t-\t-\n", id[k], m[k]);
    }
    if (hj_out_commit(&out, &err)) hj_cli_fail(prog, HJ_EXIT_RUN, "%s", err.msg);
    return 0;
}
