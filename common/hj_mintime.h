/* hj_mintime.h -- the minimal time function of a target problem, T(x) =
 * the first time at which x belongs to the reachable set, recovered from a
 * run of the UB-HJB scheme (hj_ub.h) on the target problem, equation (4) of
 * Bokanowski, Cristiani & Zidani 2010 (Example 4's target run, Table 11),
 * without a full grid: hj_ub_problem.reached reports each cell when its
 * value first becomes -1 (t = 0 for the cells of the target), and
 * hj_mintime_put streams that record to a file.  hj_mintime_read recovers
 * T on the full grid from the stream.
 *
 * Record: the d cell indices as int32, then T as float64, native byte
 * order, no header.
 *
 * Library code: returns HJ_* codes, never prints.
 */
#ifndef HJ_MINTIME_H
#define HJ_MINTIME_H

#include <stdio.h>

#include "hj_error.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    FILE *fp;   /* the caller's open stream */
    int d;      /* indices per record, 1..8 */
    int failed; /* set when a write failed (the callback cannot return it) */
} hj_mintime_stream;

/* Append the record (idx, t); HJ_EIO (and s->failed set) on a short write. */
int hj_mintime_put(hj_mintime_stream *s, const int *idx, double t);

/* Read the records of path onto the grid {0..n-1}^d: T[lin(idx)] with the
 * last index fastest, +inf for the cells never reached; a cell recorded
 * twice keeps its first time.  HJ_EIO when path cannot be read,
 * HJ_EFORMAT for a truncated record or an index outside the grid. */
int hj_mintime_read(const char *path, int d, int n, double *T, hj_error *err);

#ifdef __cplusplus
}
#endif

#endif
