/* hj_mpi.c -- see hj_mpi.h. */
#include "hj_mpi.h"

#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* Copy w layers of dimension d starting at ghosted index L (0 = the
 * outermost low ghost) between a and a packed slab: the layers span the
 * full ghosted extent of the other dimensions, in chunks of w stride[d]
 * contiguous doubles, one per index of the dimensions above d. */
static void slab_copy(const hj_ls_grid *g, double *a, int d, long L, long w, double *buf, int pack)
{
    const size_t chunk = (size_t)w * (size_t)g->stride[d];
    const size_t step = (size_t)g->stride[d] * (size_t)g->ext[d];
    const size_t nouter = g->total / step;
    for (size_t o = 0; o < nouter; o++) {
        double *p = a + o * step + (size_t)L * (size_t)g->stride[d];
        if (pack) memcpy(buf + o * chunk, p, chunk * sizeof(double));
        else memcpy(p, buf + o * chunk, chunk * sizeof(double));
    }
}

/* The width layers nearest each shared face of dimension d: as many as
 * the stencil about to run reads (hj_ls_fill_ghosts_width). */
static void halo(const hj_ls_grid *g, double *a, int d, int width, void *ctx)
{
    hj_mpi *m = ctx;
    if (m->p[d] < 2) return; /* undivided: the boundary condition (or periodic wrap) holds */
    const double t0 = MPI_Wtime();
    const long n = g->N[d], G = HJ_LS_GHOST, w = width < 1 ? 1 : width > G ? G : width;
    const size_t len = (size_t)w * g->total / (size_t)g->ext[d];
    double *sbuf = m->buf, *rbuf = m->buf + m->slab_max;
    /* The first w interior layers to the low neighbour; its next-to-face
     * high ghosts are ours. */
    slab_copy(g, a, d, G, w, sbuf, 1);
    MPI_Sendrecv(sbuf, (int)len, MPI_DOUBLE, m->lo[d], 2 * d, rbuf, (int)len, MPI_DOUBLE, m->hi[d], 2 * d, m->comm,
                 MPI_STATUS_IGNORE);
    if (m->hi[d] != MPI_PROC_NULL) slab_copy(g, a, d, G + n, w, rbuf, 0);
    /* The last w interior layers to the high neighbour, into its low
     * ghosts next to the face. */
    slab_copy(g, a, d, G + n - w, w, sbuf, 1);
    MPI_Sendrecv(sbuf, (int)len, MPI_DOUBLE, m->hi[d], 2 * d + 1, rbuf, (int)len, MPI_DOUBLE, m->lo[d], 2 * d + 1,
                 m->comm, MPI_STATUS_IGNORE);
    if (m->lo[d] != MPI_PROC_NULL) slab_copy(g, a, d, G - w, w, rbuf, 0);
    m->halo_bytes += (double)len * sizeof(double) * ((m->lo[d] != MPI_PROC_NULL) + (m->hi[d] != MPI_PROC_NULL));
    m->halo_calls++;
    m->halo_seconds += MPI_Wtime() - t0;
}

static void reduce(double *v, int n, int op, void *ctx)
{
    hj_mpi *m = ctx;
    const double t0 = MPI_Wtime();
    MPI_Allreduce(MPI_IN_PLACE, v, n, MPI_DOUBLE, op == HJ_LS_REDUCE_MIN ? MPI_MIN : MPI_MAX, m->comm);
    m->reduce_calls++;
    m->reduce_seconds += MPI_Wtime() - t0;
}

void hj_mpi_stats_reset(hj_mpi *m)
{
    m->halo_seconds = m->reduce_seconds = m->halo_bytes = 0;
    m->halo_calls = m->reduce_calls = 0;
}

int hj_mpi_init(hj_mpi *m, MPI_Comm comm, const hj_ls_grid *global, int nsplit, const int *axes, hj_error *err)
{
    memset(m, 0, sizeof *m);
    m->comm = MPI_COMM_NULL;
    const int dim = global->dim;
    int size;
    MPI_Comm_size(comm, &size);
    if (nsplit == 0) {
        if (dim < 2 && size > 1) return hj_error_set(err, HJ_EINVAL, "mpi: a 1-D grid cannot be split");
        nsplit = dim >= 3 ? 2 : dim - 1;
        for (int k = 0; k < nsplit; k++) m->axes[k] = dim - 1 - k;
    } else {
        if (nsplit < 0 || nsplit >= dim) return hj_error_set(err, HJ_EINVAL, "mpi: 1..%d axes can be split", dim - 1);
        for (int k = 0; k < nsplit; k++) {
            if (axes[k] < 1 || axes[k] >= dim)
                return hj_error_set(err, HJ_EINVAL, "mpi: split axis %d is not in 1..%d (axis 0 holds the rows)",
                                    axes[k], dim - 1);
            for (int q = 0; q < k; q++)
                if (axes[q] == axes[k]) return hj_error_set(err, HJ_EINVAL, "mpi: split axis %d given twice", axes[k]);
            m->axes[k] = axes[k];
        }
    }
    m->nsplit = nsplit;
    int dims[HJ_LS_MAXDIM], periods[HJ_LS_MAXDIM];
    for (int d = 0; d < dim; d++) dims[d] = 1, periods[d] = global->bc[d].type == HJ_LS_BC_PERIODIC;
    for (int k = 0; k < nsplit; k++) dims[m->axes[k]] = 0;
    if (MPI_Dims_create(size, dim, dims) != MPI_SUCCESS)
        return hj_error_set(err, HJ_EINVAL, "mpi: %d processes do not factor over the split axes", size);
    m->global = *global;
    m->global.dist = NULL;
    hj_ls_grid *l = &m->local;
    *l = m->global;
    for (int d = 0; d < dim; d++) {
        m->p[d] = dims[d];
        const long N = global->N[d], q = N / dims[d];
        /* The smallest block has q nodes; the halo reaches one block. */
        if (q < HJ_LS_GHOST && dims[d] > 1)
            return hj_error_set(err, HJ_EINVAL,
                                "mpi: %d blocks of %ld nodes along axis %d are thinner than the ghost width %d",
                                dims[d], N, d, HJ_LS_GHOST);
    }
    if (MPI_Cart_create(comm, dim, dims, periods, 0, &m->comm) != MPI_SUCCESS)
        return hj_error_set(err, HJ_EINVAL, "mpi: MPI_Cart_create failed");
    MPI_Comm_rank(m->comm, &m->rank);
    m->size = size;
    MPI_Cart_coords(m->comm, m->rank, dim, m->coord);
    /* The block: larger blocks first, then the layout of hj_ls_grid_init
     * for the local node counts (min, max, dx stay the global ones). */
    l->total = 1, l->nodes = 1;
    for (int d = 0; d < dim; d++) {
        MPI_Cart_shift(m->comm, d, 1, &m->lo[d], &m->hi[d]);
        const long N = global->N[d], q = N / dims[d], rem = N % dims[d], c = m->coord[d];
        l->N[d] = q + (c < rem);
        l->origin[d] = c * q + (c < rem ? c : rem);
        l->ext[d] = l->N[d] + 2 * HJ_LS_GHOST;
        l->stride[d] = (ptrdiff_t)l->total;
        l->total *= (size_t)l->ext[d];
        l->nodes *= (size_t)l->N[d];
    }
    l->offset = 0;
    for (int d = 0; d < dim; d++) l->offset += (size_t)HJ_LS_GHOST * (size_t)l->stride[d];
    l->rows = l->nodes / (size_t)l->N[0];
    for (int d = 0; d < dim; d++)
        if (m->p[d] > 1) {
            const size_t len = (size_t)HJ_LS_GHOST * l->total / (size_t)l->ext[d];
            if (len > INT_MAX) return hj_error_set(err, HJ_EINVAL, "mpi: a halo slab exceeds INT_MAX doubles");
            m->slab_max = len > m->slab_max ? len : m->slab_max;
        }
    if (m->slab_max && !(m->buf = malloc(2 * m->slab_max * sizeof(double)))) {
        hj_mpi_free(m);
        return hj_error_set(err, HJ_ENOMEM, "mpi: out of memory for the halo buffers");
    }
    m->dist.halo = halo;
    m->dist.reduce = reduce;
    m->dist.ctx = m;
    l->dist = &m->dist;
    return HJ_OK;
}

void hj_mpi_free(hj_mpi *m)
{
    free(m->buf);
    m->buf = NULL;
    if (m->comm != MPI_COMM_NULL) MPI_Comm_free(&m->comm);
}

int hj_mpi_sum(hj_mpi *m, hj_sum *s, double *sum, hj_error *err)
{
    /* Normalized limbs 0..HJ_SUM_LIMBS-2 are below 2^32: their sum over
     * the processes stays below size 2^32 < 2^63. */
    if (m->size >= (1 << 30)) return hj_error_set(err, HJ_EINVAL, "mpi: %d processes overflow the exact sum", m->size);
    const double t0 = MPI_Wtime();
    hj_sum_normalize(s);
    MPI_Allreduce(MPI_IN_PLACE, s->w, HJ_SUM_WORDS, MPI_INT64_T, MPI_SUM, m->comm);
    s->pending = m->size;
    hj_sum_normalize(s);
    m->reduce_calls++;
    m->reduce_seconds += MPI_Wtime() - t0;
    if (sum) *sum = hj_sum_value(s);
    return HJ_OK;
}

int hj_mpi_rowsum(hj_mpi *m, const double *part, double *sum, hj_error *err)
{
    hj_sum s;
    hj_sum_init(&s);
    for (size_t r = 0; r < m->local.rows; r++) hj_sum_add(&s, part[r]);
    return hj_mpi_sum(m, &s, sum, err);
}

int hj_mpi_norms(hj_mpi *m, const double *a, const double *b, double *max, double *avg, double *rms, hj_error *err)
{
    /* hj_ls_norms' parts on the block, then combined: the maximum by
     * MPI_MAX, the exact sums by hj_mpi_sum; the same final operations. */
    double mx = 0, t1, t2;
    hj_sum s1, s2;
    hj_sum_init(&s1), hj_sum_init(&s2);
    hj_ls_norms_add(&m->local, a, b, &mx, &s1, &s2);
    MPI_Allreduce(MPI_IN_PLACE, &mx, 1, MPI_DOUBLE, MPI_MAX, m->comm);
    int rc = hj_mpi_sum(m, &s1, &t1, err);
    if (!rc) rc = hj_mpi_sum(m, &s2, &t2, err);
    if (rc) return rc;
    if (max) *max = mx;
    if (avg) *avg = t1 / (double)m->global.nodes;
    if (rms) *rms = sqrt(t2 / (double)m->global.nodes);
    return HJ_OK;
}

int hj_mpi_measure(hj_mpi *m, double *phi, int periodic_dim, double *meas, hj_error *err)
{
    const hj_ls_grid *l = &m->local, *g = &m->global;
    /* Checked alike on every process, before the collective ghost fill. */
    if (g->dim < 1 || g->dim > 3) return hj_error_set(err, HJ_EINVAL, "measure: dimension %d (1 to 3 only)", g->dim);
    if (periodic_dim >= g->dim)
        return hj_error_set(err, HJ_EINVAL, "measure: periodic dimension %d of a %d-D grid", periodic_dim, g->dim);
    /* The cells of this block: lowest corner in the block, upper corner a
     * global node (or, along periodic_dim, the first node's image). */
    hj_ls_fill_ghosts(l, phi);
    long ncell[HJ_LS_MAXDIM] = {0};
    for (int d = 0; d < g->dim; d++) {
        const long last = g->N[d] - (d == periodic_dim ? 0 : 1) - l->origin[d];
        ncell[d] = last < l->N[d] ? last : l->N[d];
    }
    hj_sum s;
    hj_sum_init(&s);
    int rc = hj_ls_measure_add(l, phi, ncell, &s, err);
    int fail = rc != HJ_OK;
    MPI_Allreduce(MPI_IN_PLACE, &fail, 1, MPI_INT, MPI_LOR, m->comm);
    if (fail) return rc ? rc : hj_error_set(err, HJ_EINVAL, "measure: failed on another process");
    double total;
    if ((rc = hj_mpi_sum(m, &s, &total, err))) return rc;
    /* The cell of hj_ls_measure_periodic's extended grid along
     * periodic_dim: (min + N dx - min) / N, as hj_ls_grid_init computes it. */
    double cell = 1;
    for (int d = 0; d < g->dim; d++)
        cell *= d == periodic_dim ? (g->min[d] + (double)g->N[d] * g->dx[d] - g->min[d]) / (double)g->N[d] : g->dx[d];
    *meas = total * cell;
    return HJ_OK;
}

long hj_mpi_count_negative(hj_mpi *m, const double *a)
{
    const hj_ls_grid *l = &m->local;
    long long c = 0;
    long i[HJ_LS_MAXDIM];
    for (size_t r = 0; r < l->rows; r++) {
        const size_t k = hj_ls_row(l, r, i);
        for (long j = 0; j < l->N[0]; j++) c += a[k + (size_t)j] < 0;
    }
    MPI_Allreduce(MPI_IN_PLACE, &c, 1, MPI_LONG_LONG, MPI_SUM, m->comm);
    return (long)c;
}

static int ends_with(const char *s, const char *suffix)
{
    const size_t n = strlen(s), k = strlen(suffix);
    return n >= k && strcmp(s + n - k, suffix) == 0;
}

static void swap8(double *v)
{
    unsigned char *c = (unsigned char *)v;
    for (int k = 0; k < 4; k++) {
        const unsigned char t = c[k];
        c[k] = c[7 - k], c[7 - k] = t;
    }
}

int hj_mpi_write(hj_mpi *m, const char *path, const char *name, const double *a, hj_error *err)
{
    const hj_ls_grid *l = &m->local, *g = &m->global;
    const int dim = g->dim, raw = ends_with(path, ".raw");
    if (!raw && dim > 3) return hj_error_set(err, HJ_EINVAL, "mpi: VTK holds up to 3-D fields; write %d-D as .raw", dim);
    if (l->nodes > INT_MAX) return hj_error_set(err, HJ_EINVAL, "mpi: more than INT_MAX nodes in a block");
    char head[1024];
    int len = 0;
    if (raw) {
        len = snprintf(head, sizeof head, "# hj raw float64 little-endian dims");
        for (int d = 0; d < dim; d++) len += snprintf(head + len, sizeof head - (size_t)len, " %ld", g->N[d]);
        len += snprintf(head + len, sizeof head - (size_t)len, "\n");
    } else {
        long n[3] = {1, 1, 1};
        double o[3] = {0, 0, 0}, s[3] = {1, 1, 1};
        for (int d = 0; d < dim; d++) n[d] = g->N[d], o[d] = g->min[d], s[d] = g->dx[d];
        len = snprintf(head, sizeof head,
                       "# vtk DataFile Version 3.0\n%s\nBINARY\nDATASET STRUCTURED_POINTS\nDIMENSIONS %ld %ld %ld\n"
                       "ORIGIN %.17g %.17g %.17g\nSPACING %.17g %.17g %.17g\nPOINT_DATA %zu\n"
                       "SCALARS %s double 1\nLOOKUP_TABLE default\n",
                       name, n[0], n[1], n[2], o[0], o[1], o[2], s[0], s[1], s[2], g->nodes, name);
    }
    if (len <= 0 || (size_t)len >= sizeof head) return hj_error_set(err, HJ_EINVAL, "mpi: file header too long");
    double *buf = malloc(sizeof(double) * (l->nodes ? l->nodes : 1));
    int fail = !buf;
    MPI_Allreduce(MPI_IN_PLACE, &fail, 1, MPI_INT, MPI_LOR, m->comm);
    if (fail) {
        free(buf);
        return hj_error_set(err, HJ_ENOMEM, "mpi: out of memory for the output buffer");
    }
    long i[HJ_LS_MAXDIM];
    for (size_t r = 0; r < l->rows; r++) {
        const size_t k = hj_ls_row(l, r, i);
        for (long j = 0; j < l->N[0]; j++) {
            double v = a[k + (size_t)j];
            if (!raw) swap8(&v); /* legacy VTK binary is big-endian */
            buf[r * (size_t)l->N[0] + (size_t)j] = v;
        }
    }
    /* The block as a subarray of the global array (C order: the last
     * dimension slowest). */
    int gs[HJ_LS_MAXDIM], ls[HJ_LS_MAXDIM], st[HJ_LS_MAXDIM];
    for (int d = 0; d < dim; d++)
        gs[dim - 1 - d] = (int)g->N[d], ls[dim - 1 - d] = (int)l->N[d], st[dim - 1 - d] = (int)l->origin[d];
    MPI_Datatype ft;
    MPI_Type_create_subarray(dim, gs, ls, st, MPI_ORDER_C, MPI_DOUBLE, &ft);
    MPI_Type_commit(&ft);
    long pid = (long)getpid();
    MPI_Bcast(&pid, 1, MPI_LONG, 0, m->comm);
    char tmp[4096];
    snprintf(tmp, sizeof tmp, "%s.tmp.%ld", path, pid);
    MPI_File fh;
    int rc = MPI_File_open(m->comm, tmp, MPI_MODE_CREATE | MPI_MODE_WRONLY, MPI_INFO_NULL, &fh);
    if (rc == MPI_SUCCESS) {
        MPI_File_set_size(fh, 0);
        if (m->rank == 0) rc |= MPI_File_write_at(fh, 0, head, len, MPI_CHAR, MPI_STATUS_IGNORE);
        rc |= MPI_File_set_view(fh, (MPI_Offset)len, MPI_DOUBLE, ft, "native", MPI_INFO_NULL);
        rc |= MPI_File_write_all(fh, buf, (int)l->nodes, MPI_DOUBLE, MPI_STATUS_IGNORE);
        if (!raw) {
            rc |= MPI_File_set_view(fh, 0, MPI_BYTE, MPI_BYTE, "native", MPI_INFO_NULL);
            const MPI_Offset end = (MPI_Offset)len + (MPI_Offset)(g->nodes * sizeof(double));
            if (m->rank == 0) rc |= MPI_File_write_at(fh, end, "\n", 1, MPI_CHAR, MPI_STATUS_IGNORE);
        }
        rc |= MPI_File_close(&fh);
    }
    MPI_Type_free(&ft);
    free(buf);
    MPI_Allreduce(MPI_IN_PLACE, &rc, 1, MPI_INT, MPI_BOR, m->comm);
    if (m->rank == 0) {
        if (rc == MPI_SUCCESS && rename(tmp, path) != 0) rc = 1;
        if (rc != MPI_SUCCESS) remove(tmp);
    }
    MPI_Bcast(&rc, 1, MPI_INT, 0, m->comm);
    if (rc != MPI_SUCCESS) return hj_error_set(err, HJ_EIO, "mpi: cannot write %s", path);
    return HJ_OK;
}
