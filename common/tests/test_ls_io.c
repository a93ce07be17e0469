/* Unit tests of common/hj_ls_io's whole-file writers: one block as a
 * file, and 3-D fields resampled on a voxel lattice. */
#include "hj_test.h"

#include <stdlib.h>
#include <string.h>

#include "hj_ls_io.h"

static void dat_file(void **state)
{
    (void)state;
    hj_ls_grid g;
    const double mn = 0, mx = 1;
    const long n = 3;
    const hj_ls_bc bc = {HJ_LS_BC_EXTRAP_AWAY, 0, 0};
    assert_int_equal(hj_ls_grid_init(&g, 1, &mn, &mx, &n, &bc, NULL), HJ_OK);
    double *a = hj_ls_alloc(&g);
    for (long i = 0; i < 3; i++) a[g.offset + (size_t)i] = (double)i;
    char path[256], text[256];
    snprintf(path, sizeof path, "%s/block.dat", hj_test_dir());
    const char *names[1] = {"a"};
    const double *f[1] = {a};
    assert_int_equal(hj_ls_write_dat(path, &g, 1, names, f, NULL), HJ_OK);
    FILE *fp = fopen(path, "r");
    assert_non_null(fp);
    text[fread(text, 1, sizeof text - 1, fp)] = '\0';
    fclose(fp);
    assert_string_equal(text, "# x a\n0 0\n0.5 1\n1 2\n");
    snprintf(path, sizeof path, "%s/no/such/dir/block.dat", hj_test_dir());
    assert_int_equal(hj_ls_write_dat(path, &g, 1, names, f, NULL), HJ_EIO);
    hj_ls_free(a);
    /* each name is one header column: a blank would shift the labels */
    const char *blank[1] = {"my a"};
    hj_error err;
    snprintf(path, sizeof path, "%s/blank.dat", hj_test_dir());
    assert_int_equal(hj_ls_write_dat(path, &g, 1, blank, f, &err), HJ_EINVAL);
    assert_has(err.msg, "one word without blanks");
    /* a 4-D grid's fourth coordinate is labelled x4 */
    hj_ls_grid g4;
    const double mn4[4] = {0, 0, 0, 0}, mx4[4] = {1, 1, 1, 1};
    const long n4[4] = {2, 2, 2, 2};
    const hj_ls_bc bc4[4] = {bc, bc, bc, bc};
    assert_int_equal(hj_ls_grid_init(&g4, 4, mn4, mx4, n4, bc4, NULL), HJ_OK);
    double *a4 = hj_ls_alloc(&g4);
    const double *f4[1] = {a4};
    snprintf(path, sizeof path, "%s/block4.dat", hj_test_dir());
    assert_int_equal(hj_ls_write_dat(path, &g4, 1, names, f4, NULL), HJ_OK);
    fp = fopen(path, "r");
    assert_non_null(fp);
    assert_non_null(fgets(text, sizeof text, fp));
    fclose(fp);
    assert_string_equal(text, "# x y z x4 a\n");
    hj_ls_free(a4);
}

/* A legacy VTK file is line and word oriented: the title is one line and
 * each SCALARS name one word.  A title with a newline or a name with a
 * blank wrote a file that VTK readers reject; those, a NULL name list,
 * field, title or path are refused, and no file is written. */
static void vtk_file(void **state)
{
    (void)state;
    hj_ls_grid g;
    const double mn[2] = {0, 0}, mx[2] = {1, 1};
    const long n[2] = {3, 2};
    const hj_ls_bc bc[2] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}};
    assert_int_equal(hj_ls_grid_init(&g, 2, mn, mx, n, bc, NULL), HJ_OK);
    double *a = hj_ls_alloc(&g);
    assert_non_null(a);
    char path[256], text[512];
    snprintf(path, sizeof path, "%s/f.vtk", hj_test_dir());
    const char *names[1] = {"phi"}, *blank[1] = {"my phi"}, *empty[1] = {""}, *none[1] = {NULL};
    const double *f[1] = {a}, *nof[1] = {NULL};
    hj_error err;
    assert_int_equal(hj_ls_write_vtk(path, &g, "a\nb", 1, names, f, &err), HJ_EINVAL);
    assert_has(err.msg, "title");
    assert_int_equal(hj_ls_write_vtk(path, &g, "t", 1, blank, f, &err), HJ_EINVAL);
    assert_has(err.msg, "my phi");
    assert_int_equal(hj_ls_write_vtk(path, &g, "t", 1, empty, f, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_write_vtk(path, &g, "t", 1, none, f, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_write_vtk(path, &g, "t", 1, NULL, f, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_write_vtk(path, &g, "t", 1, names, nof, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_write_vtk(path, &g, "t", 1, names, NULL, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_write_vtk(path, &g, NULL, 1, names, f, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_write_vtk(NULL, &g, "t", 1, names, f, &err), HJ_EINVAL);
    assert_int_equal(hj_ls_write_dat(NULL, &g, 1, names, f, &err), HJ_EINVAL);
    assert_null(fopen(path, "r"));
    assert_int_equal(hj_ls_write_vtk(path, &g, "t", 1, names, f, &err), HJ_OK);
    FILE *fp = fopen(path, "r");
    assert_non_null(fp);
    text[fread(text, 1, sizeof text - 1, fp)] = '\0';
    fclose(fp);
    assert_string_equal(text, "# vtk DataFile Version 3.0\nt\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 3 2 1\n"
                              "ORIGIN 0 0 0\nSPACING 0.5 1 1\nPOINT_DATA 6\nSCALARS phi double 1\nLOOKUP_TABLE default\n"
                              "0\n0\n0\n0\n0\n0\n");
    /* a NaN or infinite value: "nan" and "inf" in an ASCII legacy file
     * are not numbers to VTK's reader (ParaView stops at them), so the
     * field and node are named and no file is written (before: HJ_OK and
     * a file ParaView could not read) */
    assert_int_equal(remove(path), 0);
    const double bad[3] = {NAN, INFINITY, -INFINITY};
    for (int q = 0; q < 3; q++) {
        a[hj_ls_index(&g, (long[]){1, 1})] = bad[q];
        const char *two[2] = {"phi", "psi"};
        double *zero = hj_ls_alloc(&g);
        const double *f2[2] = {zero, a};
        assert_int_equal(hj_ls_write_vtk(path, &g, "t", 2, two, f2, &err), HJ_ENONFINITE);
        assert_has(err.msg, "field psi");
        assert_has(err.msg, "x = (0.5, 1)");
        assert_null(fopen(path, "r"));
        hj_ls_free(zero);
    }
    hj_ls_free(a);
}

/* A linear field is reproduced exactly by trilinear interpolation; with a
 * periodic dimension the lattice reaches the period and wraps. */
static void voxels(void **state)
{
    (void)state;
    hj_ls_grid g;
    const double mn[3] = {0, 0, 0}, mx[3] = {1, 2, 0.75};
    const long N[3] = {3, 5, 4};
    const hj_ls_bc bc[3] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_PERIODIC, 0, 0}};
    assert_int_equal(hj_ls_grid_init(&g, 3, mn, mx, N, bc, NULL), HJ_OK);
    double *a = hj_ls_alloc(&g);
    for (size_t r = 0; r < g.rows; r++) {
        long i[3] = {0, 0, 0};
        const size_t k = hj_ls_row(&g, r, i);
        for (long j = 0; j < 3; j++) a[k + (size_t)j] = 0.5 * (double)j + 2.0 * (double)i[1] + (i[2] == 0 ? 1 : 0);
    }
    char path[256];
    snprintf(path, sizeof path, "%s/vox.dat", hj_test_dir());
    FILE *fp = fopen(path, "w+");
    const double *f[1] = {a};
    assert_int_equal(hj_ls_write_voxels(fp, &g, 1, f, 5, 2, NULL), HJ_OK);
    rewind(fp);
    char line[256];
    assert_non_null(fgets(line, sizeof line, fp));
    assert_non_null(strstr(line, "[0, 1] x [0, 2] x [0, 1]")); /* z to the period 4 * 0.25 */
    int n = 0;
    double x, y, z, v;
    while (fscanf(fp, "%lg %lg %lg %lg", &x, &y, &z, &v) == 4) {
        const double wrap = z == 0 || z == 1 ? 1 : 0;
        assert_close(v, x + 4 * y + wrap, 1e-6, 1e-6);
        n++;
    }
    assert_int_equal(n, 125);
    fclose(fp);
    hj_error err;
    assert_int_equal(hj_ls_write_voxels(stdout, &g, 1, f, 1, -1, &err), HJ_EINVAL);
    hj_ls_free(a);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(dat_file, hj_test_mkdir, hj_test_rmdir),
        cmocka_unit_test_setup_teardown(voxels, hj_test_mkdir, hj_test_rmdir),
        cmocka_unit_test_setup_teardown(vtk_file, hj_test_mkdir, hj_test_rmdir),
    };
    return cmocka_run_group_tests_name("hj_ls_io", tests, NULL, NULL);
}
