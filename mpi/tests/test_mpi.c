/* test_mpi.c -- hj_mpi on any number of processes (mpirun -np 1..4):
 * every test is collective, and every process runs the same sequence.
 * Only rank 0 reports; the exit status is non-zero on any process's
 * failure. */
#include "hj_test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <mpi.h>

#include "hj_mpi.h"

/* 3-D: extrapolation, Neumann and periodic boundary conditions. */
static void grid3(hj_ls_grid *g)
{
    const hj_ls_bc bc[3] = {{HJ_LS_BC_EXTRAP_AWAY, 0, 0}, {HJ_LS_BC_NEUMANN, 0.5, -0.25}, {HJ_LS_BC_PERIODIC, 0, 0}};
    assert_int_equal(hj_ls_grid_init(g, 3, (const double[]){-1, 0, 0}, (const double[]){1, 2, 3},
                                     (const long[]){5, 12, 12}, bc, NULL), 0);
}

static double field(const double *x, void *ctx)
{
    (void)ctx;
    return sin(3 * x[0] + 1) * cos(2 * x[1]) + 0.3 * sin(2.1 * x[2]) - 0.1;
}

/* Every ghosted node of the block within w layers of the interior after
 * hj_ls_fill_ghosts_width(w) (halo exchange and outer boundary
 * conditions, corners included) equals the undivided grid's node at the
 * same global index, bit for bit, for w = 1, 2, 3; and the halo volume is
 * w times that of one layer. */
static void check_halo(int nsplit, const int *axes)
{
    hj_ls_grid g;
    grid3(&g);
    hj_mpi m;
    hj_error err;
    assert_int_equal(hj_mpi_init(&m, MPI_COMM_WORLD, &g, nsplit, axes, &err), 0);
    const hj_ls_grid *l = &m.local;
    double *a = hj_ls_alloc(&g), *b = hj_ls_alloc(l);
    assert_non_null(a);
    assert_non_null(b);
    hj_ls_fill(&g, a, field, NULL);
    hj_ls_fill_ghosts(&g, a);
    double bytes1 = 0;
    for (int w = 1; w <= HJ_LS_GHOST; w++) {
        hj_ls_fill(l, b, field, NULL); /* ghosts back to zero */
        hj_mpi_stats_reset(&m);
        hj_ls_fill_ghosts_width(l, b, w);
        if (w == 1) bytes1 = m.halo_bytes;
        assert_true(m.halo_bytes == w * bytes1);
        long bad = 0;
        long i[3];
        for (i[2] = -w; i[2] < l->N[2] + w; i[2]++)
            for (i[1] = -w; i[1] < l->N[1] + w; i[1]++)
                for (i[0] = -w; i[0] < l->N[0] + w; i[0]++) {
                    const long gi[3] = {i[0] + l->origin[0], i[1] + l->origin[1], i[2] + l->origin[2]};
                    const double x = b[hj_ls_index(l, i)], y = a[hj_ls_index(&g, gi)];
                    bad += memcmp(&x, &y, sizeof x) != 0;
                }
        MPI_Allreduce(MPI_IN_PLACE, &bad, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
        assert_int_equal(bad, 0);
    }
    hj_ls_free(a), hj_ls_free(b);
    hj_mpi_free(&m);
}

static void halo_default(void **state)
{
    (void)state;
    check_halo(0, NULL);
}

/* The periodic axis alone: blocks wrap around across processes. */
static void halo_periodic(void **state)
{
    (void)state;
    check_halo(1, (const int[]){2});
}

static void halo_neumann(void **state)
{
    (void)state;
    check_halo(1, (const int[]){1});
}

/* A field of wide dynamic range (1e-12 to 1e6): sums in different
 * orders differ in their last bits. */
static double wide(const double *x, void *ctx)
{
    (void)ctx;
    const double f = field(x, NULL);
    return f * pow(10.0, 6 * sin(7 * x[0] + 5 * x[1] + 3 * x[2]) * sin(7 * x[0] + 5 * x[1] + 3 * x[2]) - 6);
}

/* Norms, measures and row sums over processes: bitwise the single-process
 * library's functions on the undivided grid (hj_ls_norms, hj_ls_measure,
 * hj_ls_measure_periodic), for each split; the count of negative nodes
 * exact. */
static void check_sums(int nsplit, const int *axes)
{
    hj_ls_grid g;
    grid3(&g);
    hj_mpi m;
    hj_error err;
    assert_int_equal(hj_mpi_init(&m, MPI_COMM_WORLD, &g, nsplit, axes, &err), 0);
    double *a = hj_ls_alloc(&g), *b = hj_ls_alloc(&m.local), *c = hj_ls_alloc(&g), *d = hj_ls_alloc(&m.local);
    hj_ls_fill(&g, a, wide, NULL);
    hj_ls_fill(&m.local, b, wide, NULL);
    hj_ls_fill(&g, c, field, NULL);
    hj_ls_fill(&m.local, d, field, NULL);
    long neg = 0, i[3];
    double fwd = 0, bwd = 0; /* plain sums of |a| in node order and reversed */
    for (size_t r = 0; r < g.rows; r++) {
        const size_t k = hj_ls_row(&g, r, i), kb = hj_ls_row(&g, g.rows - 1 - r, i);
        for (long j = 0; j < g.N[0]; j++) {
            neg += a[k + (size_t)j] < 0;
            fwd += fabs(a[k + (size_t)j]), bwd += fabs(a[kb + (size_t)(g.N[0] - 1 - j)]);
        }
    }
    assert_true(fwd != bwd); /* the order matters for a plain sum of this field */
    double want[3], got[3];
    hj_ls_norms(&g, a, c, &want[0], &want[1], &want[2]);
    assert_int_equal(hj_mpi_norms(&m, b, d, &got[0], &got[1], &got[2], &err), 0);
    assert_memory_equal(got, want, sizeof want);
    hj_ls_norms(&g, a, NULL, &want[0], &want[1], &want[2]);
    assert_int_equal(hj_mpi_norms(&m, b, NULL, &got[0], &got[1], &got[2], &err), 0);
    assert_memory_equal(got, want, sizeof want);
    assert_int_equal(hj_mpi_count_negative(&m, b), neg);
    /* Measures: without and with the periodic closure along axis 2. */
    assert_int_equal(hj_ls_measure(&g, c, &want[0], NULL), 0);
    assert_int_equal(hj_ls_measure_periodic(&g, c, 2, &want[1], NULL), 0);
    assert_int_equal(hj_mpi_measure(&m, d, -1, &got[0], &err), 0);
    assert_int_equal(hj_mpi_measure(&m, d, 2, &got[1], &err), 0);
    assert_memory_equal(got, want, 2 * sizeof(double));
    assert_true(want[1] > want[0]);
    hj_ls_free(a), hj_ls_free(b), hj_ls_free(c), hj_ls_free(d);
    hj_mpi_free(&m);
}

static void sums_default(void **state)
{
    (void)state;
    check_sums(0, NULL);
}

static void sums_periodic(void **state)
{
    (void)state;
    check_sums(1, (const int[]){2});
}

static void sums_neumann(void **state)
{
    (void)state;
    check_sums(1, (const int[]){1});
}

/* hj_mpi_sum and hj_mpi_rowsum: adversarial terms spread over the
 * processes (1e16 on one, -1e16 on another, subnormals, huge cancelling
 * pairs) give the correctly rounded sum of all terms, on every process. */
static void exact_reduction(void **state)
{
    (void)state;
    hj_ls_grid g;
    grid3(&g);
    hj_mpi m;
    hj_error err;
    assert_int_equal(hj_mpi_init(&m, MPI_COMM_WORLD, &g, 0, NULL, &err), 0);
    enum { K = 7 };
    const double terms[K] = {1e16, 1, -1e16, 0x1p-1074, 1e300, -1e300, 0.1};
    /* Term k goes to process k mod size; every process knows them all. */
    hj_sum s;
    hj_sum_init(&s);
    for (int k = 0; k < K; k++)
        if (k % m.size == m.rank) hj_sum_add(&s, terms[k]);
    double got;
    assert_int_equal(hj_mpi_sum(&m, &s, &got, &err), 0);
    const double want = hj_sum_array(terms, K); /* 1.1 + 2^-1074, rounded: 1.1 */
    assert_memory_equal(&got, &want, sizeof want);
    assert_true(want == 1 + 0.1);
    /* Row sums: part[r] = the global row index times 0.1, so the total is
     * the correctly rounded sum over the global rows. */
    double *part = malloc(sizeof(double) * (m.local.rows + 1)), *all = malloc(sizeof(double) * g.rows);
    long gi[3];
    for (size_t r = 0; r < m.local.rows; r++) {
        hj_ls_row(&m.local, r, gi);
        part[r] = 0.1 * (double)((gi[1] + m.local.origin[1]) + g.N[1] * (gi[2] + m.local.origin[2]));
    }
    for (size_t r = 0; r < g.rows; r++) all[r] = 0.1 * (double)r;
    assert_int_equal(hj_mpi_rowsum(&m, part, &got, &err), 0);
    const double want_rows = hj_sum_array(all, (long)g.rows);
    assert_memory_equal(&got, &want_rows, sizeof got);
    free(part), free(all);
    hj_mpi_free(&m);
}

/* A .raw file written by MPI-IO holds the undivided grid's interior in
 * order after its header; a .vtk file the big-endian doubles. */
static void write_files(void **state)
{
    (void)state;
    hj_ls_grid g;
    grid3(&g);
    hj_mpi m;
    hj_error err;
    assert_int_equal(hj_mpi_init(&m, MPI_COMM_WORLD, &g, 0, NULL, &err), 0);
    double *a = hj_ls_alloc(&g), *b = hj_ls_alloc(&m.local);
    hj_ls_fill(&g, a, field, NULL);
    hj_ls_fill(&m.local, b, field, NULL);
    char path[2][64];
    long pid = 0;
    if (m.rank == 0) pid = (long)getpid();
    MPI_Bcast(&pid, 1, MPI_LONG, 0, MPI_COMM_WORLD);
    snprintf(path[0], sizeof path[0], "test_mpi_%ld.raw", pid);
    snprintf(path[1], sizeof path[1], "test_mpi_%ld.vtk", pid);
    for (int f = 0; f < 2; f++) {
        assert_int_equal(hj_mpi_write(&m, path[f], "phi", b, &err), 0);
        int bad = 0;
        if (m.rank == 0) {
            FILE *fp = fopen(path[f], "rb");
            bad = !fp;
            char line[256];
            const int lines = f ? 10 : 1; /* header lines before the data */
            for (int k = 0; !bad && k < lines; k++) bad |= !fgets(line, sizeof line, fp);
            if (!f) bad |= strcmp(line, "# hj raw float64 little-endian dims 5 12 12\n") != 0;
            long i[3];
            for (size_t r = 0; !bad && r < g.rows; r++) {
                const size_t k = hj_ls_row(&g, r, i);
                for (long j = 0; !bad && j < g.N[0]; j++) {
                    unsigned char c[8];
                    bad |= fread(c, 1, 8, fp) != 8;
                    if (f)
                        for (int q = 0; q < 4; q++) {
                            const unsigned char t = c[q];
                            c[q] = c[7 - q], c[7 - q] = t;
                        }
                    bad |= memcmp(c, &a[k + (size_t)j], 8) != 0;
                }
            }
            if (fp) {
                if (f) bad |= fgetc(fp) != '\n';
                bad |= fgetc(fp) != EOF;
                fclose(fp);
            }
            remove(path[f]);
        }
        MPI_Bcast(&bad, 1, MPI_INT, 0, MPI_COMM_WORLD);
        assert_int_equal(bad, 0);
    }
    hj_ls_free(a), hj_ls_free(b);
    hj_mpi_free(&m);
}

/* Bad decompositions are refused with a message before any exchange. */
static void refused(void **state)
{
    (void)state;
    hj_ls_grid g;
    grid3(&g);
    hj_mpi m;
    hj_error err;
    assert_int_equal(hj_mpi_init(&m, MPI_COMM_WORLD, &g, 1, (const int[]){0}, &err), HJ_EINVAL);
    assert_non_null(strstr(err.msg, "axis 0"));
    assert_int_equal(hj_mpi_init(&m, MPI_COMM_WORLD, &g, 2, (const int[]){1, 1}, &err), HJ_EINVAL);
    assert_int_equal(hj_mpi_init(&m, MPI_COMM_WORLD, &g, 3, (const int[]){1, 2, 0}, &err), HJ_EINVAL);
}

int main(int argc, char **argv)
{
    MPI_Init(&argc, &argv);
    int rank;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank != 0 && !freopen("/dev/null", "w", stdout)) return 1;
    const struct CMUnitTest tests[] = {cmocka_unit_test(halo_default), cmocka_unit_test(halo_periodic),
                                       cmocka_unit_test(halo_neumann), cmocka_unit_test(sums_default),
                                       cmocka_unit_test(sums_periodic), cmocka_unit_test(sums_neumann),
                                       cmocka_unit_test(exact_reduction),
                                       cmocka_unit_test(write_files), cmocka_unit_test(refused)};
    int fails = cmocka_run_group_tests_name("hj_mpi", tests, NULL, NULL);
    MPI_Allreduce(MPI_IN_PLACE, &fails, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
    MPI_Finalize();
    return fails != 0;
}
