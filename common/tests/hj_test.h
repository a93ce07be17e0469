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

#endif
