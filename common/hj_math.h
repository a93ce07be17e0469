/* hj_math.h -- constants shared by the library and its programs. */
#ifndef HJ_MATH_H
#define HJ_MATH_H

#ifdef __cplusplus
extern "C" {
#endif

/* pi to the precision of a double (M_PI is not part of C11). */
#define HJ_PI 3.14159265358979323846

#ifdef __cplusplus
}
#endif

#endif
