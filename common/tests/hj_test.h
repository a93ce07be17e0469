/* hj_test.h -- shared helpers for the cmocka unit tests.
 * cmocka 1.1.5 compares floats in single precision only; doubles are
 * compared here with an explicit tolerance and a readable failure. */
#ifndef HJ_TEST_H
#define HJ_TEST_H

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <cmocka.h>

/* |a - b| <= abs_tol + rel_tol |b| */
#define assert_close(a, b, abs_tol, rel_tol)                                                              \
    do {                                                                                                  \
        const double hj_a_ = (a), hj_b_ = (b);                                                            \
        if (!(fabs(hj_a_ - hj_b_) <= (abs_tol) + (rel_tol) * fabs(hj_b_)))                                \
            fail_msg("%s = %.17g, expected %s = %.17g (abs tol %g, rel tol %g)", #a, hj_a_, #b, hj_b_,    \
                     (double)(abs_tol), (double)(rel_tol));                                               \
    } while (0)

/* A fresh temporary directory per test group (cmocka group setup and
 * teardown): hj_test_dir() names it. */
#include <stdlib.h>
#include <string.h>
static inline char *hj_test_dir(void)
{
    static char dir[64];
    return dir;
}
static inline int hj_test_mkdir(void **state)
{
    (void)state;
    strcpy(hj_test_dir(), "/tmp/hj_test.XXXXXX");
    return mkdtemp(hj_test_dir()) ? 0 : -1;
}
static inline int hj_test_rmdir(void **state)
{
    (void)state;
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", hj_test_dir());
    return system(cmd) == 0 ? 0 : -1;
}

/* Write len bytes of data to the file name in hj_test_dir(); its path
 * (valid until the next call). */
static inline const char *hj_test_write_file(const char *name, const void *data, size_t len)
{
    static char path[128];
    snprintf(path, sizeof path, "%s/%s", hj_test_dir(), name);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(data, 1, len, f), len);
    fclose(f);
    return path;
}

/* The text msg contains part. */
#define assert_has(msg, part)                                                                                          \
    do {                                                                                                               \
        if (!strstr(msg, part)) fail_msg("'%s' does not contain '%s'", msg, part);                                    \
    } while (0)

/* One OpenMP thread: CI machines are shared, and spinning OpenMP barriers
 * on a busy machine only slow the tests down (thread counts are tested
 * where they matter, e.g. test_ls_ode's threads_bitwise). */
#ifdef _OPENMP
#include <omp.h>
#endif
static inline void hj_test_one_thread(void)
{
#ifdef _OPENMP
    omp_set_num_threads(1);
#endif
}

/* The thread counts a bitwise test compares: 1 and, with OpenMP, 2
 * (hj_test_threads sets one). */
static inline int hj_test_max_threads(void)
{
#ifdef _OPENMP
    return 2;
#else
    return 1;
#endif
}

static inline void hj_test_threads(int th)
{
#ifdef _OPENMP
    omp_set_num_threads(th);
#else
    (void)th;
#endif
}

/* Run a shell command; its stderr (and its stdout too with both set) is
 * captured in text (at most cap - 1 bytes).  Returns the exit status, or -1
 * if it did not exit normally. */
#include <sys/wait.h>
static inline int hj_test_shell(const char *cmd, int both, char *text, size_t cap)
{
    char full[4096], path[128];
    snprintf(path, sizeof path, "%s/captured.txt", hj_test_dir());
    if (both) snprintf(full, sizeof full, "%s > %s 2>&1", cmd, path);
    else snprintf(full, sizeof full, "%s > /dev/null 2> %s", cmd, path);
    int st = system(full);
    FILE *f = fopen(path, "r");
    size_t n = f ? fread(text, 1, cap - 1, f) : 0;
    text[n] = '\0';
    if (f) fclose(f);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* main() of a test program: the cmocka group `name` of the tests given as
 * cmocka_unit_test(fn), ..., with a group setup and teardown (NULL: none). */
#define HJ_TEST_MAIN(name, setup, teardown, ...)                                                          \
    int main(void)                                                                                        \
    {                                                                                                     \
        const struct CMUnitTest tests[] = {__VA_ARGS__};                                                  \
        return cmocka_run_group_tests_name(name, tests, setup, teardown);                                 \
    }

/* The same for the kernel's tests, which run on one OpenMP thread unless
 * they set the count themselves (hj_test_one_thread). */
#define HJ_TEST_MAIN_ONE_THREAD(name, setup, teardown, ...)                                               \
    int main(void)                                                                                        \
    {                                                                                                     \
        hj_test_one_thread();                                                                             \
        const struct CMUnitTest tests[] = {__VA_ARGS__};                                                  \
        return cmocka_run_group_tests_name(name, tests, setup, teardown);                                 \
    }

#endif
