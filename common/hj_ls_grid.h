/* hj_ls_grid.h -- Cartesian grids of any dimension and arrays with ghost
 * layers for the level set kernel (Mitchell's toolbox, sections 3.1-3.2).
 *
 * A grid is a fixed rectangular mesh in dim = 1..HJ_LS_MAXDIM dimensions
 * with N[d] nodes from min[d] to max[d] (dx[d] = (max - min) / (N - 1))
 * and one boundary condition per dimension.  Node coordinates are computed
 * on the fly (hj_ls_coord); there are no dim x N^d coordinate arrays.
 *
 * Every array on the grid carries HJ_LS_GHOST ghost nodes on both sides of
 * every dimension, allocated once with the array (hj_ls_alloc), unlike the
 * toolbox, which reallocates them on every call (its section 3.2 names this
 * as a future improvement).  Dimension 0 is contiguous; the node with
 * interior index (i_0, ..., i_{dim-1}), 0 <= i_d < N[d], sits at
 *     offset + sum_d i_d stride[d],
 * and ghost nodes have i_d in [-HJ_LS_GHOST, 0) or [N[d], N[d] + HJ_LS_GHOST).
 *
 * Boundary conditions (toolbox addGhost*):
 *   PERIODIC      ghost i = node i mod N (the period is N dx, so max is the
 *                 last node before the period repeats, as in the toolbox);
 *   DIRICHLET     ghosts below take lo, ghosts above take hi;
 *   NEUMANN       linear, with outward normal derivative lo (below) and hi
 *                 (above): ghost at distance k dx = boundary value + k dx s;
 *   EXTRAP_AWAY   linear from the two outermost nodes with slope magnitude
 *                 |phi_b - phi_{b-1}| directed away from zero:
 *                 ghost k = phi_b + k sign(phi_b) |phi_b - phi_{b-1}|;
 *   EXTRAP_TOWARD the same toward zero (sign flipped).
 * Ghosts are filled dimension by dimension, along d over the full (ghosted)
 * extent of the dimensions below d, so corner ghosts are defined too (the
 * ghosts of the dimensions above d are filled later, from their interior).
 */
#ifndef HJ_LS_GRID_H
#define HJ_LS_GRID_H

#include <stddef.h>

#include "hj_error.h"
#include "hj_sum.h"

#ifdef __cplusplus
extern "C" {
#endif

#define HJ_LS_MAXDIM 8
/* Ghost width: the widest stencil of the kernel (ENO3, WENO5) reaches 3. */
#define HJ_LS_GHOST 3

enum { HJ_LS_BC_PERIODIC, HJ_LS_BC_DIRICHLET, HJ_LS_BC_NEUMANN, HJ_LS_BC_EXTRAP_AWAY, HJ_LS_BC_EXTRAP_TOWARD };

typedef struct {
    int type;      /* HJ_LS_BC_* */
    double lo, hi; /* Dirichlet values or Neumann outward derivatives */
} hj_ls_bc;

struct hj_ls_dist;

typedef struct {
    int dim;
    long N[HJ_LS_MAXDIM];
    double min[HJ_LS_MAXDIM], max[HJ_LS_MAXDIM], dx[HJ_LS_MAXDIM];
    hj_ls_bc bc[HJ_LS_MAXDIM];
    long ext[HJ_LS_MAXDIM];        /* N + 2 HJ_LS_GHOST */
    ptrdiff_t stride[HJ_LS_MAXDIM]; /* stride[0] = 1 */
    size_t total;                  /* doubles per array, ghosts included */
    size_t nodes;                  /* interior nodes, prod N */
    size_t offset;                 /* index of interior node (0, ..., 0) */
    size_t rows;                   /* interior rows along dimension 0 */
    /* A block of a grid distributed over processes (hj_mpi.h): origin[d]
     * is the global index of local node 0 (coordinates min + (i + origin)
     * dx keep the global grid's bits), dist fills the ghosts of faces
     * shared with a neighbouring block and makes per-block maxima and
     * minima global.  Single process: origin 0, dist NULL (grid init). */
    long origin[HJ_LS_MAXDIM];
    const struct hj_ls_dist *dist;
} hj_ls_grid;

/* The hooks of a distributed grid.  halo(g, a, d, width, ctx) overwrites
 * the width (1..HJ_LS_GHOST) ghost layers of dimension d nearest each face
 * shared with a neighbour; it is called by hj_ls_fill_ghosts_width after
 * the boundary conditions of dimension d are applied, dimension by
 * dimension, so corner ghosts are those of the undivided grid.  Layers
 * beyond width keep the boundary condition's values there: only a stencil
 * at most width wide may read them.  reduce(v, n, op, ctx) replaces v[0..n-1] by the
 * maximum (HJ_LS_REDUCE_MAX) or minimum over all blocks: exact in any
 * order, so the CFL bound, Lax-Friedrichs ranges and blow-up and
 * convergence tests keep the bits of the undivided grid. */
enum { HJ_LS_REDUCE_MAX, HJ_LS_REDUCE_MIN };
typedef struct hj_ls_dist {
    void (*halo)(const hj_ls_grid *g, double *a, int d, int width, void *ctx);
    void (*reduce)(double *v, int n, int op, void *ctx);
    void *ctx;
} hj_ls_dist;

/* v[0..n-1] combined over the blocks of a distributed grid (no-op on an
 * undivided grid). */
void hj_ls_grid_reduce(const hj_ls_grid *g, double *v, int n, int op);

/* Grid with N[d] >= 2 nodes from min[d] to max[d] > min[d].  Fails with
 * HJ_EINVAL for a bad dimension, bound or boundary condition (or a NULL
 * argument, here and in the constructors below), and with HJ_ENOMEM when
 * one array would not fit in memory ("grid too large"). */
int hj_ls_grid_init(hj_ls_grid *g, int dim, const double *min, const double *max, const long *N, const hj_ls_bc *bc,
                    hj_error *err);

/* The same where the periodic dimensions are given by their period: for
 * bc[d] PERIODIC, max[d] = min[d] + period is the first node's periodic
 * image, excluded (N[d] nodes per period, dx = period / N[d], the last node
 * at max[d] - dx); other dimensions as in hj_ls_grid_init.  A periodic
 * angle is then [0, 2 pi) with no node duplicated. */
int hj_ls_grid_init_period(hj_ls_grid *g, int dim, const double *min, const double *max, const long *N,
                           const hj_ls_bc *bc, hj_error *err);

/* The period N[d] dx[d] of a periodic dimension d, 0 for another. */
double hj_ls_grid_period(const hj_ls_grid *g, int d);

/* The layout of hj_ls_grid_init (sizes, strides, offsets, all size_t)
 * without the check against the machine's memory: the index arithmetic of
 * grids too large to allocate can be computed and checked. */
int hj_ls_grid_layout(hj_ls_grid *g, int dim, const double *min, const double *max, const long *N, const hj_ls_bc *bc,
                      hj_error *err);

/* The same with a spacing instead of a node count: N = round((max - min) /
 * dx) + 1 and max is moved to min + (N - 1) dx (the toolbox's processGrid). */
int hj_ls_grid_init_dx(hj_ls_grid *g, int dim, const double *min, const double *max, const double *dx,
                       const hj_ls_bc *bc, hj_error *err);

/* A zeroed array on g (ghosts included), or NULL (out of memory, or g
 * NULL).  Free with hj_ls_free. */
double *hj_ls_alloc(const hj_ls_grid *g);
void hj_ls_free(double *a);

/* Index of the interior node i[0..dim-1] (entries may be ghost indices). */
size_t hj_ls_index(const hj_ls_grid *g, const long *i);

/* Coordinates x[0..dim-1] of node i (ghost indices give ghost coordinates). */
void hj_ls_coord(const hj_ls_grid *g, const long *i, double *x);

/* The coordinates of node j of interior row r as text, "x0, x1, ..." (%g
 * each), in buf[0..n-1], for error messages that say where. */
void hj_ls_format_node(const hj_ls_grid *g, size_t r, long j, char *buf, size_t n);

/* Index of the first node of interior row r (0 <= r < g->rows), a line of
 * N[0] nodes along dimension 0; i[1..dim-1] receives its node index
 * (i[0] = 0).  Rows are numbered with dimension 1 fastest. */
size_t hj_ls_row(const hj_ls_grid *g, size_t r, long *i);

/* Fill the ghost layer of a according to the grid's boundary conditions. */
void hj_ls_fill_ghosts(const hj_ls_grid *g, double *a);

/* The same for a stencil that reads width (1..HJ_LS_GHOST) ghost layers:
 * on a distributed grid only those are exchanged with the neighbours (the
 * boundary conditions fill all layers, as hj_ls_fill_ghosts).  A width
 * outside 1..HJ_LS_GHOST is taken as the nearest of them. */
void hj_ls_fill_ghosts_width(const hj_ls_grid *g, double *a, int width);

/* The face ghosts that a stencil along one axis reads, in two parts, for a
 * row pass that fills them inside its own parallel region (one region and
 * one barrier per pass instead of a region per dimension):
 * hj_ls_fill_ghost_faces fills the ghosts of dimensions 1..dim-1 at the
 * interior indices of every other dimension (an orphaned OpenMP loop: it
 * shares the lines among the calling team, or runs them all outside a
 * parallel region, and ends in a barrier); hj_ls_fill_row_ghosts fills
 * the dimension-0 ghosts of the row whose first interior node is k.  Each
 * fills the width (1..HJ_LS_GHOST) layers nearest the faces, those a
 * stencil that wide reads.  Together they give the values
 * hj_ls_fill_ghosts gives there (the same bits); edge and corner ghosts,
 * and the layers beyond width, are left alone.  Each reads interior nodes
 * only.  Not for a distributed grid (no halo exchange).  A width outside
 * 1..HJ_LS_GHOST is taken as the nearest of them, as by
 * hj_ls_fill_ghosts_width (the arrays have HJ_LS_GHOST layers). */
void hj_ls_fill_ghost_faces(const hj_ls_grid *g, double *a, int width);
void hj_ls_fill_row_ghosts(const hj_ls_grid *g, double *a, size_t k, int width);

/* a(x) = f(x, ctx) at every interior node.  Rows are filled in parallel
 * with OpenMP, so f must be thread-safe (as every callback of the kernel);
 * each node is written once, so the result does not depend on the number
 * of threads. */
typedef double (*hj_ls_field_fn)(const double *x, void *ctx);
void hj_ls_fill(const hj_ls_grid *g, double *a, hj_ls_field_fn f, void *ctx);

/* Arrays without ghost layers (a ToolboxLS or numpy array, a file's
 * values): g->nodes doubles, dimension 0 fastest, node (i_0, ..., i_{dim-1})
 * at i_0 + N_0 (i_1 + N_1 (i_2 + ...)).  Such an array is not an array on
 * the grid (the kernel's functions would read it with the ghosted strides,
 * out of its bounds): hj_ls_unpack copies one into the interior of an
 * array from hj_ls_alloc (ghosts left as they are; the terms fill them),
 * hj_ls_pack copies an array's interior out into one. */
void hj_ls_pack(const hj_ls_grid *g, double *packed, const double *a);
void hj_ls_unpack(const hj_ls_grid *g, double *a, const double *packed);

/* Copy the interior nodes of src to dst. */
void hj_ls_copy(const hj_ls_grid *g, double *dst, const double *src);

/* Maximum, average and root mean square of |a - b| over interior nodes
 * (b may be NULL for |a|).  The sums are exact (hj_sum) and rounded once:
 * the result does not depend on the number of threads, nor, over MPI
 * (hj_mpi_norms), on the number of processes. */
void hj_ls_norms(const hj_ls_grid *g, const double *a, const double *b, double *max, double *avg, double *rms);

/* The parts of hj_ls_norms: *max = max(*max, max |a - b|), and |a - b|
 * and |a - b|^2 added exactly to s1 and s2 (either may be NULL), over the
 * interior nodes of g (of a block: the caller combines the blocks). */
void hj_ls_norms_add(const hj_ls_grid *g, const double *a, const double *b, double *max, hj_sum *s1, hj_sum *s2);

/* Number of interior nodes where b > a (a set that only grows, as under
 * the toolbox's termRestrictUpdate, section 2.6, has phi non-increasing
 * in time: 0 from an earlier a to a later b). */
long hj_ls_count_increase(const hj_ls_grid *g, const double *a, const double *b);

/* Number of interior nodes where a and b differ in any bit. */
long hj_ls_count_differ(const hj_ls_grid *g, const double *a, const double *b);

#ifdef __cplusplus
}
#endif

#endif
