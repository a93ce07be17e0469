/* hj_reach_fused.c -- the fused path of hj_reach_solve.
 *
 * Any upwind scheme with TVD Runge-Kutta of order 1..3, the exact
 * control-affine Hamiltonian and its Lax-Friedrichs bounds.  Per block of
 * consecutive rows of dimension 0 (within one plane of dimensions 0 and
 * 1) one pass computes the 2 dim one-sided derivatives, f and G (H) at
 * the nodes, the Hamiltonian, the dissipation and the time derivative;
 * streaming passes combine the Runge-Kutta stages, the last one together
 * with the target, the obstacle, the convergence measure and the
 * time-to-reach (hj_reach.h).  The state is interior-sized (no ghost
 * layers): a value beyond a face of the grid is the one the kernel's
 * ghost node would hold (hj_ls_grid.h), made per block: by index for a
 * periodic dimension, from the boundary value and its inward neighbour
 * otherwise.  A stencil along one dimension reaches only the ghosts of
 * that dimension's faces, never corner ones, so these are all it reads.
 *
 * The arithmetic per node is that of the general path (hj_ls_upwind_row,
 * hj_ls_lax_friedrichs, hj_ls_ode's combine, hj_reach's post step), in the
 * same order, so both give the same bits: the partial bounds of a
 * control-affine system do not depend on the gradient, so the three
 * Lax-Friedrichs dissipations coincide.  Matrices declared constant
 * (G_const, H_const) are evaluated once and their zero entries skipped: a
 * product with an exact zero adds +-0, which changes no sum of finite
 * terms except, at most, the sign of an exact zero.
 */
#include "hj_reach.h"
#include "hj_sys.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#define MATMAX (HJ_LS_MAXDIM * HJ_REACH_MAXIN)

/* AVX-512 and AVX2 clones of the row pipeline where the CPU has them
 * (-std=c11 contracts no multiply-add: the bits are the SSE2 code's), and
 * vector reductions without -ffast-math ("omp simd": the lane order is
 * fixed at compile time, and max and & are exact in any order). */
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__SANITIZE_ADDRESS__) && !defined(__clang__)
#define CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define CLONES
#endif
#ifdef _OPENMP
#define SIMD_REDUCE(...) _Pragma(STR(omp simd reduction(__VA_ARGS__)))
#define SIMD_REDUCE2(a, b) _Pragma(STR(omp simd reduction(a) reduction(b)))
#else
#define SIMD_REDUCE(...)
#define SIMD_REDUCE2(a, b)
#endif
#define STR(x) #x

/* One player's input set as the node loop uses it. */
typedef struct {
    int n;      /* inputs, 0: no player */
    int box;    /* 1 box, 0 ball */
    double sg;  /* -1 minimising, +1 maximising */
    double c[HJ_REACH_MAXIN], w[HJ_REACH_MAXIN], r;
    hj_reach_vec_fn fn; /* the matrix, when not constant */
    int cnst;
    double M[MATMAX]; /* the constant matrix */
    /* constant: q_j = sum over the nonzero M_ij (i increasing) of M_ij p_i */
    int nq[HJ_REACH_MAXIN], qi[HJ_REACH_MAXIN][HJ_LS_MAXDIM];
    double qm[HJ_REACH_MAXIN][HJ_LS_MAXDIM];
    /* constant: the nonzero products M_dj c_j added to f_d (j increasing) */
    int nf[HJ_LS_MAXDIM];
    double fc[HJ_LS_MAXDIM][HJ_REACH_MAXIN];
} player;

typedef struct {
    int nx;
    hj_reach_vec_fn f;
    hj_reach_row_fn f_row;
    void *ctx;
    player in[2];
    int b_const;              /* every matrix constant: b below is final */
    double b[HJ_LS_MAXDIM];   /* the input part of alpha_d */
} fused_dyn;

/* b[d] += the bound of player P's inputs on |dx_d/dt| (hj_reach.c's order). */
static void add_bounds(const player *P, int nx, const double *M, double *b)
{
    for (int d = 0; d < nx; d++) {
        double n2 = 0;
        for (int j = 0; j < P->n; j++) {
            const double m = M[d * P->n + j];
            if (P->box) b[d] += fabs(m) * P->w[j];
            else n2 += m * m;
        }
        if (!P->box) b[d] += P->r * sqrt(n2);
    }
}

static void fused_dyn_init(fused_dyn *F, const hj_reach_dyn *s, double t0)
{
    memset(F, 0, sizeof *F);
    F->nx = s->nx, F->f = s->f, F->f_row = s->f_row, F->ctx = s->ctx;
    const hj_reach_input *in[2] = {&s->u, &s->d};
    const hj_reach_vec_fn mf[2] = {s->G, s->H};
    const int cn[2] = {s->G_const, s->H_const};
    F->b_const = 1;
    for (int k = 0; k < 2; k++) {
        player *P = &F->in[k];
        P->n = in[k]->n;
        if (P->n == 0) continue;
        P->box = in[k]->shape == HJ_REACH_BOX;
        P->sg = in[k]->mode == HJ_REACH_MIN ? -1.0 : 1.0;
        for (int j = 0; j < P->n; j++) {
            if (P->box) {
                P->c[j] = 0.5 * (in[k]->lo[j] + in[k]->hi[j]);
                P->w[j] = 0.5 * (in[k]->hi[j] - in[k]->lo[j]);
            } else
                P->c[j] = in[k]->c[j], P->w[j] = 0;
        }
        P->r = in[k]->r;
        P->fn = mf[k];
        P->cnst = cn[k] != 0;
        F->b_const &= P->cnst;
        if (!P->cnst) continue;
        double x[HJ_LS_MAXDIM] = {0};
        mf[k](t0, x, P->M, s->ctx);
        for (int j = 0; j < P->n; j++)
            for (int i = 0; i < s->nx; i++) {
                const double m = P->M[i * P->n + j];
                if (m != 0) P->qi[j][P->nq[j]] = i, P->qm[j][P->nq[j]++] = m;
            }
        for (int d = 0; d < s->nx; d++)
            for (int j = 0; j < P->n; j++) {
                const double pc = P->M[d * P->n + j] * P->c[j];
                if (pc != 0) P->fc[d][P->nf[d]++] = pc;
            }
    }
    if (F->b_const)
        for (int k = 0; k < 2; k++)
            if (F->in[k].n) add_bounds(&F->in[k], s->nx, F->in[k].M, F->b);
}

/* Player P's part of -H and of the bounds at one node, for a matrix
 * that is not constant (hj_reach.c's node_ham_partials): h, fx and b
 * updated. */
static void node_player(const player *P, int nx, double t, const double *x, const double *p, double *h, double *fx,
                        double *b, void *ctx)
{
    double M[MATMAX], q[HJ_REACH_MAXIN];
    const int n = P->n;
    P->fn(t, x, M, ctx);
    for (int j = 0; j < n; j++) q[j] = 0;
    for (int i = 0; i < nx; i++)
        for (int j = 0; j < n; j++) q[j] += M[i * n + j] * p[i];
    double val = 0;
    if (P->box)
        for (int j = 0; j < n; j++) {
            const double aq = fabs(q[j]);
            val += q[j] * P->c[j] + P->sg * aq * P->w[j];
        }
    else {
        double n2 = 0;
        for (int j = 0; j < n; j++) val += q[j] * P->c[j], n2 += q[j] * q[j];
        val += P->sg * P->r * sqrt(n2);
    }
    *h += val;
    for (int d = 0; d < nx; d++)
        for (int j = 0; j < n; j++) fx[d] += M[d * n + j] * P->c[j];
    add_bounds(P, nx, M, b);
}

/* The ghost node at distance 1 beyond the face: hj_ls_grid.c's fill_line
 * for k = 1, from the boundary value v and its inward neighbour w (the
 * opposite boundary value for a periodic dimension). */
static inline double ghost(const hj_ls_bc *bc, int hi, double v, double w, double dx)
{
    switch (bc->type) {
    case HJ_LS_BC_PERIODIC: return w;
    case HJ_LS_BC_DIRICHLET: return hi ? bc->hi : bc->lo;
    case HJ_LS_BC_NEUMANN: return v + (double)1 * dx * (hi ? bc->hi : bc->lo);
    default: {
        const double dir = bc->type == HJ_LS_BC_EXTRAP_AWAY ? 1.0 : -1.0;
        const double sv = v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0);
        return v + (double)1 * dir * sv * fabs(v - w);
    }
    }
}

/* The ghost node at distance k = 1..HJ_LS_GHOST beyond a face that is not
 * periodic (fill_line for any k): v the boundary value, w its inward
 * neighbour. */
static inline double ghost_k(const hj_ls_bc *bc, int hi, long k, double v, double w, double dx)
{
    switch (bc->type) {
    case HJ_LS_BC_DIRICHLET: return hi ? bc->hi : bc->lo;
    case HJ_LS_BC_NEUMANN: return v + (double)k * dx * (hi ? bc->hi : bc->lo);
    default: {
        const double dir = bc->type == HJ_LS_BC_EXTRAP_AWAY ? 1.0 : -1.0;
        const double sv = v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0);
        return v + (double)k * dir * sv * fabs(v - w);
    }
    }
}

/* The grid index a periodic ghost at index i (< 0 or >= N) copies. */
static inline long wrap(long i, long N)
{
    if (i < 0) {
        const long k = -i;
        return (N - k % N) % N;
    }
    return (i - N) % N;
}

typedef struct {
    const hj_reach_problem *pb;
    const fused_dyn *F;
    const hj_ls_grid *g;
    size_t cs[HJ_LS_MAXDIM]; /* strides of the interior-only layout */
    double T;
    long rows_per_block;     /* consecutive rows of a plane (dimensions 0, 1) */
    long blocks_per_plane;
    size_t blocks;
    long block_nodes;        /* the most nodes of a block */
} fused;

/* Blocks: runs of consecutive rows of one plane of dimensions 0 and 1, so
 * that the vector loops run over about BLOCK_NODES nodes even where rows
 * are short (6-D grids), while a block's buffers stay in cache. */
#define BLOCK_NODES 512

static void blocks_init(fused *fs)
{
    const hj_ls_grid *g = fs->g;
    const long n0 = g->N[0], n1 = g->dim > 1 ? g->N[1] : 1;
    long rpb = BLOCK_NODES / n0;
    rpb = rpb < 1 ? 1 : rpb > n1 ? n1 : rpb;
    fs->rows_per_block = rpb;
    fs->blocks_per_plane = (n1 + rpb - 1) / rpb;
    fs->blocks = g->rows / (size_t)n1 * (size_t)fs->blocks_per_plane;
    fs->block_nodes = rpb * n0;
}

/* Block b: its first row and number of rows. */
static void block_rows(const fused *fs, size_t b, size_t *r0, long *nrows)
{
    const long n1 = fs->g->dim > 1 ? fs->g->N[1] : 1;
    const size_t plane = b / (size_t)fs->blocks_per_plane;
    const long first = (long)(b % (size_t)fs->blocks_per_plane) * fs->rows_per_block;
    *r0 = plane * (size_t)n1 + (size_t)first;
    *nrows = n1 - first < fs->rows_per_block ? n1 - first : fs->rows_per_block;
}

/* Buffers of one thread for a block of up to nb nodes. */
typedef struct {
    double *gl, *gh;   /* nb: ghost values of a face */
    double *L, *R, *P; /* dim nb each: one-sided differences, their mean */
    double *FX, *B;    /* dim nb: f + G c_u + H c_d, the input bounds */
    double *Q;         /* HJ_REACH_MAXIN nb: G^T p (or H^T p) */
    double *h, *val, *n2, *DS, *S;
    double *frow;      /* dim N[0]: f_row's output for one row */
    double *pad;       /* N[0] + 6: a row with its ghosts (higher orders) */
    double *G;         /* 7 nb: the stencil's rows gathered (higher orders) */
    double *uw;        /* HJ_LS_ROW_WORK nb: hj_ls_upwind_row's workspace */
} block_bufs;

static size_t block_work(const hj_ls_grid *g, long nb)
{
    return (size_t)(7 * g->dim + HJ_REACH_MAXIN + 7 + 7 + HJ_LS_ROW_WORK) * (size_t)nb +
           (size_t)(g->dim + 1) * (size_t)g->N[0] + 6;
}

static void block_bufs_init(block_bufs *w, double *ws, const hj_ls_grid *g, long nb)
{
    const size_t n = (size_t)nb, dn = (size_t)g->dim * n;
    w->gl = ws, w->gh = ws + n;
    w->L = w->gh + n, w->R = w->L + dn, w->P = w->R + dn, w->FX = w->P + dn, w->B = w->FX + dn;
    w->Q = w->B + dn;
    w->h = w->Q + HJ_REACH_MAXIN * n, w->val = w->h + n, w->n2 = w->val + n, w->DS = w->n2 + n, w->S = w->DS + n;
    w->frow = w->S + n;
    w->pad = w->frow + (size_t)g->dim * (size_t)g->N[0];
    w->G = w->pad + (size_t)g->N[0] + 6;
    w->uw = w->G + 7 * n;
}

/* Coordinates of the first node of row r0 + q (q < rows of its block). */
static void row_x(const hj_ls_grid *g, const long *idx0, long q, double *x)
{
    long idx[HJ_LS_MAXDIM];
    memcpy(idx, idx0, sizeof(long) * (size_t)g->dim);
    if (g->dim > 1) idx[1] += q;
    hj_ls_coord(g, idx, x);
}

/* -H and alpha_d over a block of nrows rows from the row of index idx0,
 * in vector loops over the block (the per-node sums in node_player's
 * order): h = H at each node (the sign flipped by the caller), FX and B
 * as alpha_d = |FX| + B needs them. */
CLONES
static void block_ham(const fused_dyn *F, double t, const hj_ls_grid *g, const long *idx0, long nrows, block_bufs *w,
                      int *b_rows)
{
    const int nx = F->nx;
    const long n0 = g->N[0], n = n0 * nrows;
    const double dx0 = g->dx[0];
    double *h = w->h;
    for (long j = 0; j < n; j++) h[j] = 0;
    if (F->f) {
        for (long q = 0; q < nrows; q++) {
            double x[HJ_LS_MAXDIM], rx[HJ_LS_MAXDIM], fx[HJ_LS_MAXDIM];
            row_x(g, idx0, q, rx);
            const size_t o = (size_t)q * (size_t)n0;
            if (F->f_row) {
                F->f_row(t, rx, dx0, n0, w->frow, F->ctx);
                for (int i = 0; i < nx; i++)
                    memcpy(w->FX + (size_t)i * (size_t)n + o, w->frow + (size_t)i * (size_t)n0,
                           sizeof(double) * (size_t)n0);
            } else {
                memcpy(x, rx, sizeof(double) * (size_t)nx);
                for (long j = 0; j < n0; j++) {
                    x[0] = rx[0] + (double)j * dx0;
                    F->f(t, x, fx, F->ctx);
                    for (int i = 0; i < nx; i++) w->FX[(size_t)i * (size_t)n + o + (size_t)j] = fx[i];
                }
            }
        }
        for (int i = 0; i < nx; i++) {
            const double *p = w->P + (size_t)i * (size_t)n, *fi = w->FX + (size_t)i * (size_t)n;
            for (long j = 0; j < n; j++) h[j] += p[j] * fi[j];
        }
    } else
        for (size_t k = 0; k < (size_t)nx * (size_t)n; k++) w->FX[k] = 0;
    *b_rows = !F->b_const;
    if (*b_rows)
        for (size_t k = 0; k < (size_t)nx * (size_t)n; k++) w->B[k] = 0;
    for (int k = 0; k < 2; k++) {
        const player *P = &F->in[k];
        if (P->n == 0) continue;
        if (!P->cnst) {
            /* node by node through the matrix callback */
            for (long q = 0; q < nrows; q++) {
                double x[HJ_LS_MAXDIM], rx[HJ_LS_MAXDIM], p[HJ_LS_MAXDIM], fx[HJ_LS_MAXDIM], b[HJ_LS_MAXDIM];
                row_x(g, idx0, q, rx);
                memcpy(x, rx, sizeof(double) * (size_t)nx);
                for (long j = 0; j < n0; j++) {
                    x[0] = rx[0] + (double)j * dx0;
                    const size_t node = (size_t)q * (size_t)n0 + (size_t)j;
                    for (int i = 0; i < nx; i++) {
                        const size_t o = (size_t)i * (size_t)n + node;
                        p[i] = w->P[o], fx[i] = w->FX[o], b[i] = w->B[o];
                    }
                    node_player(P, nx, t, x, p, &h[node], fx, b, F->ctx);
                    for (int i = 0; i < nx; i++) {
                        const size_t o = (size_t)i * (size_t)n + node;
                        w->FX[o] = fx[i], w->B[o] = b[i];
                    }
                }
            }
            continue;
        }
        /* constant matrix: q_jj = sum of its nonzero M_i,jj p_i */
        for (int jj = 0; jj < P->n; jj++) {
            double *q = w->Q + (size_t)jj * (size_t)n;
            for (long j = 0; j < n; j++) q[j] = 0;
            for (int e = 0; e < P->nq[jj]; e++) {
                const double m = P->qm[jj][e], *p = w->P + (size_t)P->qi[jj][e] * (size_t)n;
                for (long j = 0; j < n; j++) q[j] += m * p[j];
            }
        }
        double *val = w->val, *n2 = w->n2;
        for (long j = 0; j < n; j++) val[j] = 0, n2[j] = 0;
        for (int jj = 0; jj < P->n; jj++) {
            const double *q = w->Q + (size_t)jj * (size_t)n, c = P->c[jj], sw = P->sg, wj = P->w[jj];
            if (P->box)
                for (long j = 0; j < n; j++) {
                    const double aq = fabs(q[j]);
                    val[j] += q[j] * c + sw * aq * wj;
                }
            else
                for (long j = 0; j < n; j++) val[j] += q[j] * c, n2[j] += q[j] * q[j];
        }
        if (!P->box) {
            const double sr = P->sg * P->r;
            for (long j = 0; j < n; j++) val[j] += sr * sqrt(n2[j]);
        }
        for (long j = 0; j < n; j++) h[j] += val[j];
        for (int d = 0; d < nx; d++) {
            double *fd = w->FX + (size_t)d * (size_t)n;
            for (int e = 0; e < P->nf[d]; e++) {
                const double pc = P->fc[d][e];
                for (long j = 0; j < n; j++) fd[j] += pc;
            }
        }
        if (*b_rows) /* the bounds of a constant matrix, added per node */
            for (int d = 0; d < nx; d++) {
                double *B = w->B + (size_t)d * (size_t)n, nn = 0;
                for (int jj = 0; jj < P->n; jj++) {
                    const double m = P->M[d * P->n + jj];
                    if (P->box) {
                        const double a = fabs(m) * P->w[jj];
                        for (long j = 0; j < n; j++) B[j] += a;
                    } else
                        nn += m * m;
                }
                if (!P->box) {
                    const double a = P->r * sqrt(nn);
                    for (long j = 0; j < n; j++) B[j] += a;
                }
            }
    }
}

/* First order: the one-sided differences L, R and their mean P of a
 * block of nrows rows from index idx, row its first node: neighbours at
 * +-1 and +-stride, the face ghosts made per row. */
CLONES
static void block_derivs_first(const fused *fs, const double *row, const long *idx, long nrows, block_bufs *w)
{
    const hj_ls_grid *g = fs->g;
    const int dim = g->dim;
    const long n0 = g->N[0], n = n0 * nrows;
    /* dimension 0: neighbours at +-1, the ghosts at the ends of each row */
    {
        const double inv0 = 1.0 / g->dx[0];
        const int per = g->bc[0].type == HJ_LS_BC_PERIODIC;
        double *L = w->L, *R = w->R, *P = w->P;
        for (long j = 1; j < n; j++) L[j] = (row[j] - row[j - 1]) * inv0;
        for (long j = 0; j < n - 1; j++) R[j] = (row[j + 1] - row[j]) * inv0;
        for (long q = 0; q < nrows; q++) {
            const double *a = row + q * n0;
            const double gl = ghost(&g->bc[0], 0, a[0], per ? a[n0 - 1] : a[1], g->dx[0]);
            const double gh = ghost(&g->bc[0], 1, a[n0 - 1], per ? a[0] : a[n0 - 2], g->dx[0]);
            L[q * n0] = (a[0] - gl) * inv0;
            R[q * n0 + n0 - 1] = (gh - a[n0 - 1]) * inv0;
        }
        for (long j = 0; j < n; j++) P[j] = 0.5 * (L[j] + R[j]);
    }
    /* other dimensions: neighbours at +-stride, ghost rows at the faces
     * (dimension 1: its first and last rows, in the block or not) */
    for (int d = 1; d < dim; d++) {
        const size_t s = fs->cs[d];
        const int per = g->bc[d].type == HJ_LS_BC_PERIODIC;
        const double invd = 1.0 / g->dx[d];
        double *L = w->L + (size_t)d * (size_t)n, *R = w->R + (size_t)d * (size_t)n, *P = w->P + (size_t)d * (size_t)n;
        /* the nodes [lo_from, n) have a lower neighbour on the grid,
         * [0, hi_to) an upper one; the others are on a face */
        long lo_from = 0, hi_to = n, lo_face = 0, hi_face = 0;
        if (d == 1) {
            if (idx[1] == 0) lo_from = n0, lo_face = n0;
            if (idx[1] + nrows == g->N[1]) hi_to = n - n0, hi_face = n0;
        } else {
            if (idx[d] == 0) lo_from = n, lo_face = n;
            if (idx[d] == g->N[d] - 1) hi_to = 0, hi_face = n;
        }
        for (long j = lo_from; j < n; j++) L[j] = (row[j] - row[(ptrdiff_t)j - (ptrdiff_t)s]) * invd;
        for (long j = 0; j < hi_to; j++) R[j] = (row[j + (long)s] - row[j]) * invd;
        const size_t span = s * (size_t)(g->N[d] - 1);
        if (lo_face) { /* nodes [0, lo_face) on the lower face */
            double *q = w->gl;
            if (per)
                for (long j = 0; j < lo_face; j++) q[j] = row[(size_t)j + span];
            else
                for (long j = 0; j < lo_face; j++) q[j] = ghost(&g->bc[d], 0, row[j], row[(size_t)j + s], g->dx[d]);
            for (long j = 0; j < lo_face; j++) L[j] = (row[j] - q[j]) * invd;
        }
        if (hi_face) { /* nodes [n - hi_face, n) on the upper face */
            double *q = w->gh;
            const double *a = row + (n - hi_face);
            if (per)
                for (long j = 0; j < hi_face; j++) q[j] = a[(ptrdiff_t)j - (ptrdiff_t)span];
            else
                for (long j = 0; j < hi_face; j++) q[j] = ghost(&g->bc[d], 1, a[j], a[(ptrdiff_t)j - (ptrdiff_t)s], g->dx[d]);
            for (long j = 0; j < hi_face; j++) R[n - hi_face + j] = (q[j] - a[j]) * invd;
        }
        for (long j = 0; j < n; j++) P[j] = 0.5 * (L[j] + R[j]);
    }
}

/* Higher order schemes (hj_ls_upwind_row_eps, the local WENO epsilon of
 * the general path): the one-sided derivatives L, R and their mean P of a
 * block of nrows rows from index idx, y the state, row its first node.
 * Along dimension 0 each row is padded with its 3 ghosts on each side;
 * along d >= 1 the 7 rows (blocks) of the stencil are read in place with
 * stride cs[d] where they are all on the grid, else gathered with ghost
 * rows made from the boundary conditions (a face's ghosts only: the
 * stencil along d reads no corner ghost). */
CLONES
static void block_derivs_high(const fused *fs, const double *row, const long *idx, long nrows, block_bufs *w)
{
    const hj_ls_grid *g = fs->g;
    const int scheme = fs->pb->scheme;
    const long n0 = g->N[0], n = n0 * nrows;
    {
        const hj_ls_bc *bc = &g->bc[0];
        const int per = bc->type == HJ_LS_BC_PERIODIC;
        double *pad = w->pad;
        for (long q = 0; q < nrows; q++) {
            const double *a = row + q * n0;
            memcpy(pad + 3, a, sizeof(double) * (size_t)n0);
            for (long k = 1; k <= HJ_LS_GHOST; k++) {
                pad[3 - k] = per ? a[wrap(-k, n0)] : ghost_k(bc, 0, k, a[0], a[1], g->dx[0]);
                pad[2 + n0 + k] = per ? a[wrap(n0 - 1 + k, n0)] : ghost_k(bc, 1, k, a[n0 - 1], a[n0 - 2], g->dx[0]);
            }
            hj_ls_upwind_row_eps(scheme, pad + 3, 1, n0, g->dx[0], -1, w->L + q * n0, w->R + q * n0, w->uw);
        }
    }
    for (int d = 1; d < g->dim; d++) {
        const hj_ls_bc *bc = &g->bc[d];
        const int per = bc->type == HJ_LS_BC_PERIODIC;
        const long N = g->N[d];
        /* the stencil's extent along d: the rows of a block along dimension
         * 1 span nrows indices; along d >= 2 the block is one index */
        const long span = d == 1 ? nrows : 1, first = idx[d] - HJ_LS_GHOST, lastx = idx[d] + span - 1 + HJ_LS_GHOST;
        double *L = w->L + (size_t)d * (size_t)n, *R = w->R + (size_t)d * (size_t)n;
        if (first >= 0 && lastx < N) {
            hj_ls_upwind_row_eps(scheme, row, (ptrdiff_t)fs->cs[d], n, g->dx[d], -1, L, R, w->uw);
            continue;
        }
        /* gather: slot o = 0..6 holds the nodes at offset o - 3 along d
         * of every node of the block; the unit of an offset along d is
         * one row (n0 nodes) for d = 1, the whole block for d >= 2 */
        const size_t s = fs->cs[d];
        const long unit = d == 1 ? n0 : n; /* nodes sharing one index along d */
        /* (the node at index i along d of this part's position is at
         * row + (i - idx[d]) s: for d = 1 the part's own offset is that of
         * its index) */
        for (int o = 0; o < 7; o++) {
            double *dst = w->G + (size_t)o * (size_t)n;
            for (long part = 0; part < n / unit; part++) {
                const long i = idx[d] + part + (o - 3); /* index along d of this part */
                double *to = dst + part * unit;
                if (i >= 0 && i < N) {
                    memcpy(to, row + (ptrdiff_t)(i - idx[d]) * (ptrdiff_t)s, sizeof(double) * (size_t)unit);
                    continue;
                }
                if (per) {
                    memcpy(to, row + (ptrdiff_t)(wrap(i, N) - idx[d]) * (ptrdiff_t)s, sizeof(double) * (size_t)unit);
                    continue;
                }
                /* ghost at distance k from the face: from the boundary
                 * row b and its inward neighbour */
                const int hiface = i >= N;
                const long k = hiface ? i - (N - 1) : -i, bi = hiface ? N - 1 : 0, wi = hiface ? N - 2 : 1;
                const double *bv = row + (ptrdiff_t)(bi - idx[d]) * (ptrdiff_t)s;
                const double *wv = row + (ptrdiff_t)(wi - idx[d]) * (ptrdiff_t)s;
                for (long j = 0; j < unit; j++) to[j] = ghost_k(bc, hiface, k, bv[j], wv[j], g->dx[d]);
            }
        }
        hj_ls_upwind_row_eps(scheme, w->G + 3 * (size_t)n, (ptrdiff_t)n, n, g->dx[d], -1, L, R, w->uw);
    }
    for (int d = 0; d < g->dim; d++) {
        const double *L = w->L + (size_t)d * (size_t)n, *R = w->R + (size_t)d * (size_t)n;
        double *P = w->P + (size_t)d * (size_t)n;
        for (long j = 0; j < n; j++) P[j] = 0.5 * (L[j] + R[j]);
    }
}

/* One block of ydot = -(H(x, (p+ + p-)/2) - sum_d alpha_d (p+_d - p-_d)/2)
 * into out (the block's nodes of next); *inv = max over the block of
 * sum_d alpha_d / dx_d; the first node (row r, node j) with a non-finite
 * H or alpha in *bad_r, *bad_j (*bad_j = -1: none). */
CLONES
static void block_ydot(const fused *fs, double tau, const double *y, size_t blk, double *out, block_bufs *w,
                       double *inv, size_t *bad_r, long *bad_j)
{
    const hj_ls_grid *g = fs->g;
    const int dim = g->dim;
    const long n0 = g->N[0];
    size_t r0;
    long nrows, idx[HJ_LS_MAXDIM];
    block_rows(fs, blk, &r0, &nrows);
    hj_ls_row(g, r0, idx);
    const long n = n0 * nrows;
    const double *row = y + r0 * (size_t)n0; /* the block's first node */
    if (fs->pb->scheme != HJ_LS_UPWIND_FIRST) block_derivs_high(fs, row, idx, nrows, w);
    else
        block_derivs_first(fs, row, idx, nrows, w);
    int b_rows;
    block_ham(fs->F, fs->T - tau, g, idx, nrows, w, &b_rows);
    /* dissipation, CFL sum, finiteness, the time derivative */
    double *DS = w->DS, *S = w->S, *h = w->h;
    int fin_any = 1;
    for (long j = 0; j < n; j++) DS[j] = 0, S[j] = 0;
    for (int d = 0; d < dim; d++) {
        const size_t o = (size_t)d * (size_t)n;
        const double *FX = w->FX + o, *L = w->L + o, *R = w->R + o, dx = g->dx[d];
        const double bc = fs->F->b[d], *B = w->B + o;
        SIMD_REDUCE(& : fin_any)
        for (long j = 0; j < n; j++) {
            const double alpha = fabs(FX[j]) + (b_rows ? B[j] : bc);
            const double a = fabs(alpha);
            fin_any &= alpha - alpha == 0;
            DS[j] += a * 0.5 * (R[j] - L[j]);
            S[j] += a / dx;
        }
    }
    double m = 0;
    SIMD_REDUCE2(& : fin_any, max : m)
    for (long j = 0; j < n; j++) {
        const double H = -h[j];
        fin_any &= H - H == 0;
        out[j] = -(H - DS[j]);
        m = S[j] > m ? S[j] : m;
    }
    long b = -1;
    if (!fin_any) /* the first bad node, as the general path names it */
        for (long j = 0; j < n && b < 0; j++) {
            int ok = h[j] - h[j] == 0;
            for (int d = 0; d < dim; d++) {
                const size_t q = (size_t)d * (size_t)n + (size_t)j;
                const double alpha = fabs(w->FX[q]) + (b_rows ? w->B[q] : fs->F->b[d]);
                ok &= alpha - alpha == 0;
            }
            if (!ok) b = j;
        }
    *inv = m;
    *bad_r = b < 0 ? 0 : r0 + (size_t)(b / n0);
    *bad_j = b < 0 ? -1 : b % n0;
}


/* The offset of interior row r's first node in the caller's arrays. */
static size_t user_row(const hj_ls_grid *g, int compact, size_t r)
{
    long idx[HJ_LS_MAXDIM];
    return compact ? r * (size_t)g->N[0] : hj_ls_row(g, r, idx);
}

/* The error for a NaN target value, naming the first such node in the
 * order of the rows (the parallel pass only knows that there is one). */
static int target_nan_error(const hj_reach_problem *pb, int compact, double T, hj_error *err)
{
    const hj_ls_grid *g = pb->grid;
    for (size_t r = 0; r < g->rows; r++) {
        long i[HJ_LS_MAXDIM];
        double x[HJ_LS_MAXDIM];
        hj_ls_row(g, r, i);
        hj_ls_coord(g, i, x);
        const size_t ku = user_row(g, compact, r);
        for (long j = 0; j < g->N[0]; j++) {
            x[0] = g->min[0] + (double)j * g->dx[0];
            if (!isnan(hj_reach_set_at(&pb->target, T, x, ku + (size_t)j))) continue;
            char at[256];
            hj_ls_format_node(g, r, j, at, sizeof at);
            return hj_error_set(err, HJ_ENONFINITE, "reach: the target is NaN at x = (%s)", at);
        }
    }
    return hj_error_set(err, HJ_ENONFINITE, "reach: the target is NaN at a node");
}

int hj_reach_fused_applies(const hj_reach_problem *pb)
{
    return !pb->general && !pb->per_node && hj_ls_scheme_name(pb->scheme) && pb->order >= 1 && pb->order <= 3 &&
           pb->discount == 0 && pb->grid && !pb->grid->dist;
}

size_t hj_reach_fused_bytes(const hj_reach_problem *pb, int threads)
{
    fused fs;
    fs.g = pb->grid;
    blocks_init(&fs);
    const size_t narrays = (pb->compact ? 1 : 2) + (pb->order > 1);
    return sizeof(double) * (narrays * fs.g->nodes + (size_t)threads * block_work(fs.g, fs.block_nodes));
}

static double wall(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The error of the first row (in row order) with a non-finite H or alpha. */
static int report_bad(const hj_ls_grid *g, size_t r, long j, double tau, hj_error *err)
{
    char pos[256];
    hj_ls_format_node(g, r, j, pos, sizeof pos);
    return hj_error_set(err, HJ_ENONFINITE,
                        "Hamiltonian or partial callback returned a non-finite value at x = (%s), tau = %g", pos, tau);
}

/* ydot of the state y into out over every block, in parallel; *m = the
 * largest sum_d alpha_d / dx_d.  Errors as the general path's term. */
static int eval_pass(const fused *fs, double tau, const double *y, double *out, size_t wsz, double *m_out,
                     hj_error *err)
{
    const hj_ls_grid *g = fs->g;
    const long n = g->N[0];
    double m = 0;
    int nomem = 0, ws_fail = 0;
    size_t bad_r = (size_t)-1;
    long bad_j = -1;
#ifdef _OPENMP
#pragma omp parallel reduction(max : m) reduction(| : nomem)
#endif
    {
        double *ws = malloc(sizeof(double) * wsz);
        block_bufs w;
        if (!hj_sys_team_all(ws != NULL, &ws_fail)) nomem = 1;
        else {
            block_bufs_init(&w, ws, g, fs->block_nodes);
            int nan_seen = 0;
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 4)
#endif
            for (size_t b = 0; b < fs->blocks; b++) {
                double inv;
                size_t br, r0;
                long bj, nr;
                block_rows(fs, b, &r0, &nr);
                block_ydot(fs, tau, y, b, out + r0 * (size_t)n, &w, &inv, &br, &bj);
                if (bj >= 0) {
#ifdef _OPENMP
#pragma omp critical(hj_reach_fused_bad)
#endif
                    if (br < bad_r) bad_r = br, bad_j = bj;
                }
                if (inv != inv) nan_seen = 1;
                else m = inv > m ? inv : m;
            }
            if (nan_seen) m = NAN;
        }
        free(ws);
    }
    if (nomem) return hj_error_set(err, HJ_ENOMEM, "reach: out of memory for the row workspace");
    if (bad_r != (size_t)-1) return report_bad(g, bad_r, bad_j, tau, err);
    if (m != m || m == INFINITY)
        return hj_error_set(err, HJ_ENONFINITE, "Hamiltonian or partial callback: non-finite CFL bound at tau = %g",
                            tau);
    *m_out = m;
    return HJ_OK;
}

/* dst = a y + b (u + dt f) (hj_ls_ode's combine); dst may alias y or u. */
static void combine_pass(const hj_ls_grid *g, double *dst, double a, const double *y, double b, const double *u,
                         double dt, const double *f)
{
    const long n = g->N[0];
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 32)
#endif
    for (size_t r = 0; r < g->rows; r++) {
        const size_t k = r * (size_t)n;
        for (long q = 0; q < n; q++) dst[k + q] = a * y[k + q] + b * (u[k + q] + dt * f[k + q]);
    }
}

int hj_reach_solve_fused(const hj_reach_problem *pb, double *phi, double *ttr, hj_reach_stats *stats, hj_error *err)
{
    int rc = hj_reach_problem_check(pb, err);
    if (rc) return rc;
    if (!phi) return hj_error_set(err, HJ_EINVAL, "reach: NULL value array");
    if (!hj_reach_fused_applies(pb))
        return hj_error_set(err, HJ_EINVAL,
                            "reach: the fused path needs an upwind scheme, RK order 1..3, no discount, general and "
                            "per_node 0 and an undivided grid");
    const double start = wall();
    const hj_ls_grid *g = pb->grid;
    const int compact = pb->compact != 0, tube = pb->kind == HJ_REACH_BRT, obst = hj_reach_set_given(&pb->obstacle);
    const double T = isinf(pb->horizon) ? 0 : pb->horizon;
    const long n = g->N[0];
    fused_dyn F;
    fused_dyn_init(&F, pb->dyn, T);
    fused fs = {pb, &F, g, {1}, T, 0, 0, 0, 0};
    for (int d = 1; d < g->dim; d++) fs.cs[d] = fs.cs[d - 1] * (size_t)g->N[d - 1];
    blocks_init(&fs);
    /* the state y (the caller's phi when compact), the time derivative f,
     * a Runge-Kutta stage u */
    const size_t narrays = (compact ? 1 : 2) + (pb->order > 1);
    /* Its own arrays and the caller's against the machine's memory, before
     * any allocation (hj_reach_check_memory). */
    if ((rc = hj_reach_check_memory(pb, ttr != NULL, err))) return rc;
    double *own = malloc(sizeof(double) * g->nodes * narrays);
    if (!own)
        return hj_error_set(err, HJ_ENOMEM, "reach: out of memory for %zu node%s", g->nodes, hj_plural((long)g->nodes));
    double *y = compact ? phi : own + g->nodes * (narrays - 1), *f = own, *u = pb->order > 1 ? own + g->nodes : NULL;
    long steps = 0;
    double tau = 0, change = INFINITY;
    int converged = 0, stopped = 0;
    /* tau = 0: max(target(T), -obstacle(T)), node by node in parallel. */
    int nan_target = 0;
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 16) reduction(| : nan_target)
#endif
    for (size_t r = 0; r < g->rows; r++) {
        long i[HJ_LS_MAXDIM];
        double x[HJ_LS_MAXDIM];
        hj_ls_row(g, r, i);
        hj_ls_coord(g, i, x);
        const size_t ku = user_row(g, compact, r), kc = r * (size_t)n;
        for (long j = 0; j < n; j++) {
            const size_t k = ku + (size_t)j;
            x[0] = g->min[0] + (double)j * g->dx[0];
            double v = hj_reach_set_at(&pb->target, T, x, k);
            nan_target |= isnan(v);
            if (ttr) ttr[k] = v <= 0 ? 0 : INFINITY;
            if (obst) {
                const double o = -hj_reach_set_at(&pb->obstacle, T, x, k);
                v = o > v ? o : v;
            }
            y[kc + (size_t)j] = v;
        }
    }
    if (nan_target) rc = target_nan_error(pb, compact, T, err);
    const double tk = isinf(pb->horizon) ? DBL_MAX / 4 : T;
    const double small = hj_ls_ode_span_small(0, tk);
    const size_t wsz = block_work(g, fs.block_nodes);
    const int set_fn = (tube && pb->target.fn) || (obst && pb->obstacle.fn);
    const double steps_start = wall();
    while (rc == HJ_OK && tk - tau > small) {
        /* hj_ls_ode's TVD Runge-Kutta step; the first evaluation sets dt */
        double m;
        if ((rc = eval_pass(&fs, tau, y, f, wsz, &m, err))) break;
        /* m = 0: no node moves (every alpha_d is 0, so is H); see below */
        if (!(m >= 0)) {
            rc = hj_error_set(err, HJ_ENONFINITE, "non-finite CFL bound at tau = %g", tau);
            break;
        }
        double dt = m > 0 ? pb->factor_cfl * (1 / m) : DBL_MAX;
        dt = dt < DBL_MAX ? dt : DBL_MAX;
        if (!isinf(pb->horizon) && (rc = hj_reach_check_steps_left(tk, tau, dt, pb->conv_tol, err))) break;
        int last = 0;
        if (dt >= tk - tau) dt = tk - tau, last = 1;
        /* a step that leaves tau as it is never ends the run (hj_ls_ode's
         * check): an infinite horizon, which the check above skips, or a
         * finite one whose steps shrink far below the ulp of tau */
        if (!last && tau + dt == tau) {
            rc = hj_error_set(err, HJ_EINVAL, "reach: the step %g (from the CFL bound) does not advance tau = %g", dt,
                              tau);
            break;
        }
        if (!(m > 0)) {
            /* No motion (an infinite bound): one step to the horizon, as
             * hj_ls_ode takes it, if nothing moves at its end either; f is
             * zero, and stays zero when the end's evaluation goes into it. */
            if ((rc = eval_pass(&fs, tau + dt, y, f, wsz, &m, err))) break;
            if (m > 0) {
                rc = hj_error_set(err, HJ_EINVAL,
                                  "reach: no motion at tau = %g (infinite CFL bound) but motion at tau = %g, the end "
                                  "of the step to the horizon",
                                  tau, tau + dt);
                break;
            }
        }
        const double tau_new = last ? tk : tau + dt, t = T - tau_new, dtp = tau_new - tau;
        /* the last combination a y + b (u + dt f), fused with the post step */
        double a = 0, b = 1;
        const double *uu = y;
        if (pb->order > 1) {
            combine_pass(g, u, 0, y, 1, y, dt, f);
            if ((rc = eval_pass(&fs, tau + dt, u, f, wsz, &m, err))) break;
            a = 0.5, b = 0.5, uu = u;
            if (pb->order == 3) {
                combine_pass(g, u, 0.75, y, 0.25, u, dt, f);
                if ((rc = eval_pass(&fs, tau + 0.5 * dt, u, f, wsz, &m, err))) break;
                a = 1.0 / 3, b = 2.0 / 3;
            }
        }
        /* Euler step or last stage, target and obstacle, change,
         * time-to-reach: y in place */
        double ch = 0;
        int bad_state = 0, bad_set = 0;
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 16) reduction(max : ch) reduction(| : bad_state, bad_set)
#endif
        for (size_t r = 0; r < g->rows; r++) {
            long i[HJ_LS_MAXDIM];
            double x[HJ_LS_MAXDIM];
            if (set_fn) { /* coordinates only for set functions */
                hj_ls_row(g, r, i);
                hj_ls_coord(g, i, x);
            }
            const size_t kc = r * (size_t)n, ku = compact ? kc : user_row(g, 0, r);
            double *yo = y + kc, rch = 0;
            const double *fr = f + kc, *ur = uu + kc;
            int rb = 0, rs = 0;
            for (long j = 0; j < n; j++) {
                const double old = yo[j];
                double v = a * old + b * (ur[j] + dt * fr[j]);
                rb |= !(v - v == 0);
                if (tube || obst) {
                    const size_t k = ku + (size_t)j;
                    x[0] = g->min[0] + (double)j * g->dx[0];
                    v = hj_reach_set_constrain(&pb->target, &pb->obstacle, tube, obst, t, x, k, v, &rs);
                }
                yo[j] = v;
                const double dv = fabs(v - old);
                rch = dv > rch ? dv : rch;
                if (ttr) {
                    const size_t k = ku + (size_t)j;
                    if (old > 0 && v <= 0 && isinf(ttr[k])) ttr[k] = tau + dtp * old / (old - v);
                }
            }
            ch = rch > ch ? rch : ch;
            bad_state |= rb;
            bad_set |= rs;
        }
        steps++;
        if (bad_state) {
            rc = hj_error_set(err, HJ_ENONFINITE, "blow-up: NaN or Inf in the state at tau = %.17g after step %ld",
                              tau_new, steps);
            break;
        }
        if (bad_set) {
            rc = hj_error_set(err, HJ_ENONFINITE, "a target or obstacle function returned NaN at t = %g", t);
            break;
        }
        if (isinf(pb->horizon) && last && ch == 0) {
            /* Nothing moves under an infinite horizon (only such a step
             * reaches tk): the value is the limit from the step's start,
             * which tau stays at. */
            change = 0;
            converged = 1;
        } else {
            tau = tau_new;
            change = ch / dtp;
            converged = pb->conv_tol > 0 && change <= pb->conv_tol;
        }
        if ((rc = hj_reach_progress_call(pb, pb->horizon, tau, steps, last || converged, err))) {
            stopped = 1;
            break;
        }
        if (converged) break;
    }
    const double step_seconds = wall() - steps_start;
    /* the value into the caller's array (that of stats.tau when the
     * progress callback stopped the run) */
    if (rc == HJ_OK || stopped) {
        if (!compact) {
            for (size_t r = 0; r < g->rows; r++)
                memcpy(phi + user_row(g, 0, r), y + r * (size_t)n, sizeof(double) * (size_t)n);
            hj_ls_fill_ghosts(g, phi);
        }
    }
    free(own);
    if (stats) {
        stats->steps = steps;
        stats->tau = tau;
        stats->converged = converged;
        stats->seconds = wall() - start;
        stats->step_seconds = step_seconds;
        stats->bytes = hj_reach_fused_bytes(pb, hj_sys_max_threads());
    }
    return rc;
}
