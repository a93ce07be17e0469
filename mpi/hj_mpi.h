/* hj_mpi.h -- the level set kernel on a block decomposition over MPI.
 *
 * A global grid (hj_ls_grid) is cut into blocks along the axes the user
 * chooses by an MPI Cartesian topology (MPI_Cart_create).  Each process
 * holds one block as a grid of its own (the local grid: the global min,
 * max and dx, its own N, origin = global index of its first node) and runs
 * the unchanged kernel (terms, integrators, hj_reach) on it.  The local
 * grid's hooks (hj_ls_dist, hj_ls_grid.h) make the kernel distributed:
 *   - ghost fill: after the boundary conditions of dimension d, the
 *     layers of each face shared with a neighbour that the stencil about
 *     to run reads (hj_ls_fill_ghosts_width: 1 for first order and
 *     centred terms, 2 for ENO2 and WENO3, 3 = HJ_LS_GHOST for ENO3, WENO5
 *     and a plain hj_ls_fill_ghosts) are exchanged (one MPI_Sendrecv per
 *     direction), over the full ghosted extent of the other dimensions, so
 *     corners match the undivided grid; periodic dimensions wrap across
 *     processes; halo_bytes counts what was sent;
 *   - maxima and minima (the CFL bound, Lax-Friedrichs ranges, WENO
 *     epsilons, blow-up and convergence tests) by MPI_Allreduce, exact in
 *     any order.
 * Every node of the result is then bitwise the one of the single-process
 * library, for any number of processes and any split.
 *
 * Sums (norms, set measures) are exact (hj_sum.h): each process adds its
 * nodes into a fixed-point accumulator, the accumulators are added as
 * integers (MPI_Allreduce of int64 limbs) and the exact total is rounded
 * once.  So norms and measures are bitwise those of the single-process
 * library functions (hj_ls_norms, hj_ls_measure_periodic), which sum the
 * same way, on any number of processes; the cost is one reduction of
 * HJ_SUM_WORDS (70) integers, whatever the grid size.
 *
 * Dimension 0 (contiguous, the kernel's rows) is never split.  Every
 * split axis needs at least HJ_LS_GHOST nodes per block.  Errors are
 * returned (hj_error.h); an error inside the kernel on one process leaves
 * the others waiting in a collective, so a program ends the run with
 * MPI_Abort on any error.
 */
#ifndef HJ_MPI_H
#define HJ_MPI_H

#include <mpi.h>

#include "hj_error.h"
#include "hj_ls_grid.h"
#include "hj_ls_measure.h"
#include "hj_sum.h"

typedef struct {
    MPI_Comm comm;                 /* the Cartesian communicator */
    int rank, size;
    int nsplit, axes[HJ_LS_MAXDIM]; /* the split axes */
    int p[HJ_LS_MAXDIM];           /* processes along each dimension */
    int coord[HJ_LS_MAXDIM];       /* this block's position */
    int lo[HJ_LS_MAXDIM], hi[HJ_LS_MAXDIM]; /* neighbour ranks (MPI_PROC_NULL at an outer face) */
    hj_ls_grid global, local;
    hj_ls_dist dist;
    double *buf;                   /* halo pack buffers (4 slabs) */
    size_t slab_max;
    /* Communication statistics since init (or hj_mpi_stats_reset). */
    double halo_seconds, reduce_seconds;
    double halo_bytes;             /* bytes sent by this process */
    long halo_calls, reduce_calls;
} hj_mpi;

/* Decompose global over the processes of comm along the nsplit axes
 * (each in 1..dim-1, distinct; nsplit = 0 takes the default: the two
 * outermost axes for dim >= 3, the outermost for dim 2).  Block sizes
 * differ by at most one node, the larger blocks first.  m->local is the
 * grid to run the kernel on; m must not move while it is used.  HJ_EINVAL
 * for a bad axis, a 1-D grid with more than one process, or a block
 * thinner than HJ_LS_GHOST; HJ_ENOMEM. */
int hj_mpi_init(hj_mpi *m, MPI_Comm comm, const hj_ls_grid *global, int nsplit, const int *axes, hj_error *err);
void hj_mpi_free(hj_mpi *m);
void hj_mpi_stats_reset(hj_mpi *m);

/* The exact global sum of the accumulators s of all processes: on
 * return s holds it (normalized) on every process and *sum (if not NULL)
 * its correctly rounded value.  Collective.  Exact for fewer than 2^30
 * processes (HJ_EINVAL beyond). */
int hj_mpi_sum(hj_mpi *m, hj_sum *s, double *sum, hj_error *err);

/* The global sum of local per-row values part[0..local.rows-1], exact and
 * correctly rounded (hj_mpi_sum): the same bits on every process count
 * and every split. */
int hj_mpi_rowsum(hj_mpi *m, const double *part, double *sum, hj_error *err);

/* Maximum, average and root mean square of |a - b| (b may be NULL) over
 * the global grid: the maximum by MPI_MAX, the sums exact (hj_ls_norms_add
 * on the block, hj_mpi_sum): bitwise hj_ls_norms of the undivided grid. */
int hj_mpi_norms(hj_mpi *m, const double *a, const double *b, double *max, double *avg, double *rms, hj_error *err);

/* The measure of {phi < 0} (hj_ls_measure.h) of a grid of dimension 1..3,
 * a full period along periodic_dim (< 0: none): bitwise
 * hj_ls_measure_periodic of the undivided grid (so hj_reach_measure).
 * Refills the ghosts of phi (collective: the cells on a block's upper face
 * read the neighbour's nodes).  HJ_EINVAL for a dimension above 3. */
int hj_mpi_measure(hj_mpi *m, double *phi, int periodic_dim, double *meas, hj_error *err);

/* The global number of nodes with a < 0 (an exact integer sum; the set's
 * measure is this count times the cell volume). */
long hj_mpi_count_negative(hj_mpi *m, const double *a);

/* Write the field a (on m->local) to path as one file by MPI-IO, written
 * under a temporary name and renamed by rank 0 when complete:
 *   dim <= 3: legacy VTK, BINARY STRUCTURED_POINTS (big-endian doubles,
 *             ParaView and VisIt read it), one SCALARS field named name;
 *   any dim:  ".raw" if path ends so: a one-line text header
 *             "# hj raw float64 little-endian dims N0 N1 ...\n", then the
 *             global interior nodes, dimension 0 fastest.
 * Collective.  HJ_EIO on an MPI-IO failure. */
int hj_mpi_write(hj_mpi *m, const char *path, const char *name, const double *a, hj_error *err);

#endif
