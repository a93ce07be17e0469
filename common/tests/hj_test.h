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

#endif
