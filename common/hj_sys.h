/* hj_sys.h -- what the system says about this process and machine.
 *
 * Small queries that numerics may call (a memory check before a large
 * allocation) as well as programs (CPU time and peak memory in their
 * tables).  None of them prints or fails: an unknown value is 0 or NaN as
 * stated per function.
 */
#ifndef HJ_SYS_H
#define HJ_SYS_H

#include <stddef.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* Physical memory of the machine in bytes (0 if unknown). */
double hj_sys_physical_memory(void);

/* CPU time of this process (all its threads) in seconds. */
double hj_sys_cpu_seconds(void);

/* Peak resident memory of this process in MB (getrusage), NaN if unknown. */
double hj_sys_peak_rss_mb(void);

/* A block of `bytes` for a large array that will be touched throughout,
 * freed with free(); NULL if out of memory.  Blocks of 2 MB and more are
 * aligned to 2 MB and marked for transparent huge pages where the system
 * offers them (Linux madvise): one page fault per 2 MB instead of per
 * 4 KB, which on virtual machines is most of the cost of filling
 * gigabytes. */
void *hj_sys_alloc_large(size_t bytes);

/* The number of threads a parallel region would get here
 * (omp_get_max_threads; 1 without OpenMP).  Inline so that it is compiled
 * with the caller's OpenMP flag. */
static inline int hj_sys_max_threads(void)
{
#ifdef _OPENMP
    return omp_get_max_threads();
#else
    return 1;
#endif
}

/* Inside an OpenMP parallel region, before a worksharing loop that every
 * thread of the team must meet or none may (OpenMP's rule): returns 1 on
 * every thread if ok is nonzero on every thread, else 0 on every thread,
 * so that a thread whose workspace allocation failed does not skip the
 * loop alone.  fail: an int shared by the team, 0 before the region; one
 * call per region.  A barrier; outside a region (or without OpenMP)
 * simply ok != 0.  Inline so that it is compiled with the caller's
 * OpenMP flag. */
static inline int hj_sys_team_all(int ok, int *fail)
{
    if (!ok) {
#ifdef _OPENMP
#pragma omp atomic write
#endif
        *fail = 1;
    }
#ifdef _OPENMP
#pragma omp barrier
#endif
    int f;
#ifdef _OPENMP
#pragma omp atomic read
#endif
    f = *fail;
    return !f;
}

#ifdef __cplusplus
}
#endif

#endif
