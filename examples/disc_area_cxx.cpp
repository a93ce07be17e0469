/* # The library from C++: a disc's area
 *
 * **Problem.** The area of the disc of radius 0.5 about (0.1, -0.2) in
 * [-1, 1]^2, pi / 4, measured from its signed distance function on an
 * N x N grid (--N, default 101).
 *
 * **Method.** The C headers used as they are from C++ (they carry their
 * own extern "C"): the command line by hj_cli (--help included), the
 * signed distance by hj_ls_shape_sphere, the area of {phi < 0} by
 * hj_ls_measure (linear on simplices, second order).
 *
 * **Checked number.** The area, within 2e-3 of pi / 4 for N >= 41.
 */
#include <hj/hj.h>
#include <cmath>
#include <cstdio>

int main(int argc, char **argv)
{
    long n = 101;
    hj_cli_opt opt = {};
    opt.name = "--N", opt.type = HJ_OPT_LONG, opt.value = &n, opt.min = 41, opt.max = 2001;
    opt.metavar = "N", opt.help = "nodes per dimension";
    hj_cli_spec spec = {"disc_area_cxx", "The area of a disc by hj_ls_measure, from C++.", &opt, 1, nullptr};
    hj_cli_parse_or_exit(&spec, argc, argv);

    const double lo[2] = {-1, -1}, hi[2] = {1, 1}, c[2] = {0.1, -0.2}, r = 0.5;
    const long N[2] = {n, n};
    const hj_ls_bc ex = {HJ_LS_BC_EXTRAP_AWAY, 0, 0}, bc[2] = {ex, ex};
    hj_ls_grid g;
    hj_error err;
    double area = 0;
    double *phi = nullptr;
    if (hj_ls_grid_init(&g, 2, lo, hi, N, bc, &err) || !(phi = hj_ls_alloc(&g)) ||
        hj_ls_shape_sphere(&g, c, r, phi, &err) || hj_ls_measure(&g, phi, &area, &err))
        hj_cli_fail("disc_area_cxx", HJ_EXIT_RUN, "%s", phi ? err.msg : "out of memory");
    hj_ls_free(phi);
    const double exact = HJ_PI * r * r;
    std::printf("disc_area_cxx: area %.6f, exact %.6f (N = %ld)\n", area, exact, n);
    return std::fabs(area - exact) < 2e-3 ? 0 : 1;
}
