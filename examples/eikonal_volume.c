/* # Travel times from two sources through a 3-D volume with a wall
 *
 * **Problem.** |grad T| = f in a 16^3 volume of speeds read from the text
 * file `data/volume.txt` (slices bottom first: speed 1 in the lower layer
 * z <= 7, speed 2 above; f = 1 / speed), in pixel units (node (i, j, k) at
 * (i, j, k)).  A wall fills the plane x = 8 of the lower layer (obstacle
 * nodes: nothing crosses them; fronts pass over it through the upper
 * layer).  Two point sources off the nodes: (3.3, 4.2, 2) starting at
 * t0 = 0 and (12.5, 11.7, 3.1) starting at t0 = 2, one on each side of
 * the wall.
 *
 * **Method.** The general Eikonal solver `hj_eik_solve` (fast sweeping,
 * order 3, factored near the sources, its scale-free stopping rule:
 * defaults from `hj_eik_default_options`), the volume read by `hj_vol_read`
 * (format told by content), the result written as legacy VTK by
 * `hj_vol_write_vtk` (obstacle nodes, +inf in T, written as -1).
 *
 * **Checked number.** Within the lower layer, near a source and on its
 * side of the wall, the first arrival is the straight ray: T = t0 +
 * |x - s| (a head wave through the upper layer comes later below a
 * distance of about 19).  At (5, 6, 2) from the first source T = 2.4759,
 * at (13, 9, 2) from the second T = 4.9582; both must hold to 1e-6
 * (the factored scheme is exact in a uniform medium: measured 6e-12 and
 * 1.5e-7 off).  960 of the 4096 nodes, around the interface z = 7.5 where
 * the speed jumps from node to node, use the first order update (the
 * solver counts them in `stats.first_order`).
 * With an argument, writes T there as VTK for ParaView.
 */
#include <hj/hj.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <stdlib.h>
#define TRY(call) if (call) return fprintf(stderr, "eikonal_volume: %s\n", err.msg), 1

int main(int argc, char **argv)
{
    hj_error err; hj_vol vol; hj_eik_stats st;
    if (argc > 2 || (argc > 1 && argv[1][0] == '-')) { /* --help: the usage, exit 0; a bad command line: 2 */
        const int help = argc == 2 && !strcmp(argv[1], "--help");
        return fputs("usage: eikonal_volume [T.vtk]\n"
                     "Travel times from two sources through a 3-D volume with a wall; checks the straight rays;\n"
                     "T.vtk: the travel times as legacy VTK.\n",
                     help ? stdout : stderr), help ? 0 : 2;
    }
    TRY(hj_vol_read(&vol, "data/volume.txt", 0, 1, &err)); /* 0, 1: the PGM pixel range, unused for text */
    const hj_eik_grid g = {.dim = vol.dim, .n = {vol.n[0], vol.n[1], vol.n[2]}, .x0 = {0, 0, 0}, .dx = {1, 1, 1}};
    const size_t n = (size_t)g.n[0] * (size_t)g.n[1] * (size_t)g.n[2];
    double *f = malloc(n * sizeof *f), *T = malloc(n * sizeof *T);
    unsigned char *wall = calloc(n, 1);
    TRY((!f || !T || !wall) && hj_error_set(&err, HJ_ENOMEM, "out of memory"));
    for (size_t k = 0; k < n; k++) { /* f is read outside obstacles only */
        const long i = (long)(k % (size_t)g.n[0]), z = (long)(k / ((size_t)g.n[0] * (size_t)g.n[1]));
        wall[k] = i == 8 && z <= 7;
        f[k] = vol.v[k] > 0 ? 1 / vol.v[k] : 1;
    }
    const hj_eik_source src[2] = {{.x = {3.3, 4.2, 2}, .t0 = 0}, {.x = {12.5, 11.7, 3.1}, .t0 = 2}};
    const hj_eik_options opt = hj_eik_default_options();
    TRY(hj_eik_solve(&g, f, 0, wall, src, 2, NULL, &opt, T, &st, &err));
    if (argc > 1) TRY(hj_vol_write_vtk(argv[1], g.n, g.x0, g.dx, "eikonal_volume: travel time", "T", T, -1, &err));
    const double T1 = T[5 + 16 * (6 + 16 * 2)], T2 = T[13 + 16 * (9 + 16 * 2)];
    const double e1 = hypot(hypot(5 - 3.3, 6 - 4.2), 0), e2 = 2 + hypot(hypot(13 - 12.5, 9 - 11.7), 2 - 3.1);
    printf("eikonal_volume: %ld iterations, %zu of %zu nodes at first order, %zu unreachable; "
           "T(5, 6, 2) = %.6f (exact %.6f), T(13, 9, 2) = %.6f (exact %.6f)\n",
           st.iterations, st.first_order, n, st.unreachable, T1, e1, T2, e2);
    hj_vol_free(&vol), free(f), free(T), free(wall);
    return fabs(T1 - e1) < 1e-6 && fabs(T2 - e2) < 1e-6 ? 0 : 1;
}
