/* # Ultra-Bee front propagation on the sparse band
 *
 * **Problem.** theta_t + f . grad theta = 0 on [-1, 1]^2 with f = (1, 0.5)
 * and theta_0 = -1 inside the disc of radius 0.3 about (-0.4, -0.2), +1
 * outside: at T = 0.6 the front is the same circle about (0.2, 0.1).
 *
 * **Method.** The UB-HJB scheme of Bokanowski, Cristiani & Zidani (2010):
 * anti-dissipative Ultra-Bee fluxes with dimension splitting, CFL 0.9, on
 * the narrow band of cells next to the front held in the sparse
 * semi-dynamic store (hj_ub.h, hj_band.h).  Only the band is stored: the
 * full grid is never allocated.
 *
 * **Parameters.** 200 cells per direction (dx = 0.01).
 *
 * **Checked number.** The L1 error of the computed set (the area of the
 * cells on the wrong side) against the exact disc: the scheme keeps the
 * front within about a cell, so the error must stay below one cell width
 * times the perimeter, dx 2 pi r (exit status 1 otherwise).
 */
#include <hj/hj.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

typedef struct {
    double c[2], r, v[2], t;
} disc;

static void dyn(double t, const double *x, int a, double *f, void *ctx)
{
    (void)t, (void)x, (void)a;
    const disc *D = ctx;
    f[0] = D->v[0], f[1] = D->v[1];
}
static double avg0(const double *blo, const double *bhi, void *ctx)
{
    const disc *D = ctx;
    return hj_ub_avg_ball(2, blo, bhi, D->c, D->r, 8);
}
static int uniform(const double *blo, const double *bhi, void *ctx)
{
    const disc *D = ctx;
    return hj_ub_ball_uniform(2, blo, bhi, D->c, D->r);
}
/* The exact set at time D->t: the disc carried by the wind. */
static int inside(const double *x, void *ctx)
{
    const disc *D = ctx;
    const double dx = x[0] - D->c[0] - D->v[0] * D->t, dy = x[1] - D->c[1] - D->v[1] * D->t;
    return dx * dx + dy * dy <= D->r * D->r;
}

int main(int argc, char **argv)
{
    if (argc > 1) { /* --help: the usage, exit 0; a bad command line: 2 */
        const int help = argc == 2 && !strcmp(argv[1], "--help");
        return fputs("usage: ultrabee_front\n"
                     "A front carried by the Ultra-Bee scheme on the sparse band; checks the L1 error. No arguments.\n",
                     help ? stdout : stderr), help ? 0 : 2;
    }
    enum { N = 200 };
    disc D = {{-0.4, -0.2}, 0.3, {1.0, 0.5}, 0.6};
    hj_ub_problem pb = {.d = 2, .n = N, .ncontrols = 1, .dyn = dyn, .cfl = 0.9, .boundary = 1, .snap = HJ_UB_SNAP,
                        .avg0 = avg0, .uniform = uniform, .front_sub = 8, .ctx = &D};
    for (int k = 0; k < 2; k++) {
        hj_ub_cell_grid(-1, 1, N, &pb.lo[k], &pb.hi[k]);
        pb.bbox_lo[k] = D.c[k] - D.r, pb.bbox_hi[k] = D.c[k] + D.r;
    }
    hj_ub_solver sv;
    hj_error err;
    double l1, haus;
    if (hj_ub_init(&sv, &pb, HJ_BAND_SSD, &err) || hj_ub_run(&sv, D.t, &err) ||
        hj_ub_errors(&sv, inside, &D, &l1, &haus, &err)) {
        fprintf(stderr, "ultrabee_front: %s\n", err.msg);
        return 1;
    }
    const double bound = sv.dx[0] * 2 * HJ_PI * D.r;
    printf("ultrabee_front: N = %d, %ld steps, largest band %zu of %d cells, L1 error %.3e (bound %.3e), "
           "Hausdorff %.3e\n", N, sv.steps, sv.band_max, N * N, l1, bound, haus);
    hj_ub_free(&sv);
    return l1 < bound ? 0 : 1;
}
