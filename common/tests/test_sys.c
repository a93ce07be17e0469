/* Unit tests of hj_sys: the machine and process queries give plausible
 * values, and large blocks are aligned, writable and freed with free(). */
#include "hj_test.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "hj_sys.h"

#ifdef _OPENMP
#include <omp.h>
#endif

static void queries_are_plausible(void **state)
{
    (void)state;
    assert_true(hj_sys_physical_memory() > 1e6);
    const double t0 = hj_sys_cpu_seconds();
    volatile double x = 0;
    for (int i = 0; i < 1000000; i++) x += i;
    assert_true(hj_sys_cpu_seconds() >= t0);
    assert_true(hj_sys_peak_rss_mb() > 0);
}

/* Below 2 MB a plain block; from 2 MB on, aligned to 2 MB.  Every byte
 * is written and read back, and free() takes both. */
static void large_blocks(void **state)
{
    (void)state;
    const size_t sizes[] = {0, 1, 4096, ((size_t)2 << 20) - 1, (size_t)2 << 20, ((size_t)5 << 20) + 3};
    for (size_t k = 0; k < sizeof sizes / sizeof *sizes; k++) {
        unsigned char *p = hj_sys_alloc_large(sizes[k]);
        assert_non_null(p);
        if (sizes[k] >= ((size_t)2 << 20)) assert_int_equal((uintptr_t)p % ((uintptr_t)2 << 20), 0);
        memset(p, 0xa5, sizes[k]);
        for (size_t i = 0; i < sizes[k]; i += 4093) assert_int_equal(p[i], 0xa5);
        free(p);
    }
}

/* hj_sys_team_all: one thread's failure is every thread's answer, so each
 * thread meets the worksharing loop after it or none does. */
static void team_agrees(void **state)
{
    (void)state;
    for (int bad = -1; bad < 2; bad++) { /* the failing thread; -1: none */
        int fail = 0, ran = 0, n_ok = 0, nth = 1;
#ifdef _OPENMP
#pragma omp parallel num_threads(2) reduction(+ : ran, n_ok)
#endif
        {
            int me = 0;
#ifdef _OPENMP
            me = omp_get_thread_num();
#pragma omp single
            nth = omp_get_num_threads();
#endif
            if (hj_sys_team_all(me != bad, &fail)) {
                n_ok++;
#ifdef _OPENMP
#pragma omp for
#endif
                for (int i = 0; i < 100; i++) ran++;
            }
        }
        const int all = bad < 0 || bad >= nth;
        assert_int_equal(n_ok, all ? nth : 0);
        assert_int_equal(ran, all ? 100 : 0);
    }
    int fail = 0;
    assert_int_equal(hj_sys_team_all(1, &fail), 1); /* outside a region */
    assert_int_equal(hj_sys_team_all(0, &fail), 0);
}

HJ_TEST_MAIN("hj_sys", NULL, NULL, cmocka_unit_test(queries_are_plausible), cmocka_unit_test(large_blocks),
             cmocka_unit_test(team_agrees))
