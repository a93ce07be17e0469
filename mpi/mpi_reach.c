/* mpi_reach -- reachability on a block decomposition over MPI (hj_mpi.h):
 * air3D (paper 2's game of two vehicles, p2_air3d set-up) or three
 * decoupled double integrators in 6-D (the set-up of
 * examples/three_double_integrators_6d.c), written as one file by MPI-IO.
 *
 * --serial runs the undivided library (no decomposition, no hook) on one
 * process and writes the same file format: the reference that every
 * process count must reproduce bit for bit.  Rank 0 prints one TSV line
 * (with --header, the column names first): the run's size, steps, time per
 * step, the communication time and volume per step, and the global norms
 * and set size and measure of the result (exact sums: with --serial the
 * single-process library's hj_ls_norms and hj_reach_measure, otherwise
 * hj_mpi_norms and hj_mpi_measure; the same bits on every process count).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mpi.h>

#include "hj_cli.h"
#include "hj_ls_accuracy.h"
#include "hj_ls_seq.h"
#include "hj_mpi.h"
#include "hj_reach.h"
#include "p2_air3d.h"

static const char *const PROG = "mpi_reach";

/* ---- three double integrators (x_k' = v_k, v_k' = u_k, |u_k| <= 1) --- */
static void di_f(double t, const double *x, double *o, void *c)
{
    (void)t, (void)c;
    for (int k = 0; k < 6; k += 2) o[k] = x[k + 1], o[k + 1] = 0;
}
static void di_G(double t, const double *x, double *o, void *c)
{
    (void)t, (void)x, (void)c;
    for (int q = 0; q < 18; q++) o[q] = q == 3 || q == 10 || q == 17;
}
/* The box |x_k|, |v_k| <= 0.5. */
static double di_box(double t, const double *x, void *c)
{
    (void)t, (void)c;
    double m = -INFINITY;
    for (int k = 0; k < 6; k++) m = fmax(m, fabs(x[k]) - 0.5);
    return m;
}

typedef struct {
    int which; /* 0 air3d, 1 di6 */
    long N;
    long nsplit_n; /* di6: nodes on axis 4 (and 5 unless n5) */
    long n5;       /* di6: nodes on axis 5 (0: nsplit_n) */
    double tmax;
    int acc;
    int first;     /* di6: first order in space and time */
    int toolbox;   /* air3d: the toolbox's CFL rule and grid-wide WENO epsilon */
} run_par;

static int grid_of(const run_par *rp, hj_ls_grid *g, hj_error *err)
{
    if (rp->which == 0) return p2_air3d_grid(rp->N, g, err);
    hj_ls_bc bc[6];
    double lo[6], hi[6];
    long n[6];
    for (int d = 0; d < 6; d++)
        bc[d] = (hj_ls_bc){HJ_LS_BC_EXTRAP_AWAY, 0, 0}, lo[d] = -1.5, hi[d] = 1.5, n[d] = d < 4 ? rp->N : d == 5 && rp->n5 ? rp->n5 : rp->nsplit_n;
    return hj_ls_grid_init(g, 6, lo, hi, n, bc, err);
}

/* Solve on g (a block of global, or global itself); phi is written. */
static int solve(const run_par *rp, const hj_ls_grid *global, const hj_ls_grid *g, double *phi, long *steps,
                 hj_error *err)
{
    if (rp->which == 0) {
        p2_air3d_par p;
        p2_air3d_defaults(&p);
        if (rp->toolbox) p.cfl_rule = HJ_LS_CFL_TOOLBOX, p.weno_eps = HJ_LS_WENO_EPS_GRID;
        int rc = p2_air3d_target_block(global, g, &p, phi, err);
        if (rc) return rc;
        const double ts[2] = {0, rp->tmax};
        hj_ls_ode_stats st;
        rc = p2_air3d_solve_block(global, g, &p, rp->acc, HJ_LS_GLF, ts, 2, phi, NULL, NULL, &st, err);
        *steps = st.steps;
        return rc;
    }
    hj_reach_dyn s;
    hj_reach_dyn_init(&s, 6, di_f, NULL);
    hj_reach_dyn_control_box(&s, di_G, 3, (double[]){-1, -1, -1}, (double[]){1, 1, 1});
    hj_reach_problem pb;
    hj_reach_problem_init(&pb, g, &s);
    pb.kind = HJ_REACH_BRS, pb.target.fn = di_box, pb.horizon = rp->tmax;
    if (rp->first) pb.scheme = HJ_LS_UPWIND_FIRST, pb.order = 1;
    hj_reach_stats st;
    int rc = hj_reach_solve(&pb, phi, NULL, &st, err);
    *steps = st.steps;
    return rc;
}

/* A usage error, the same on every process: one message (control bytes
 * escaped by hj_cli_fail) from rank 0, the usage exit status.  The other
 * processes end with status 0: mpirun aborts the job at the first non-zero
 * exit, which could kill rank 0 before its message is out; the job's
 * status is then rank 0's. */
static _Noreturn void usage_fail(int rank, const char *msg)
{
    MPI_Finalize();
    if (rank == 0) hj_cli_fail(PROG, HJ_EXIT_USAGE, "%s", msg);
    exit(0);
}

static _Noreturn void fail(int rank, const hj_error *err)
{
    char msg[sizeof err->msg + 32];
    snprintf(msg, sizeof msg, "rank %d: %s", rank, err->msg);
    for (char *p = msg; *p; p++)
        if ((unsigned char)*p < 0x20 || *p == 0x7f) *p = '?'; /* one line */
    fprintf(stderr, "%s: %s\n", PROG, msg);
    MPI_Abort(MPI_COMM_WORLD, HJ_EXIT_RUN);
    exit(HJ_EXIT_RUN);
}

int main(int argc, char **argv)
{
    MPI_Init(&argc, &argv);
    int wrank, wsize;
    MPI_Comm_rank(MPI_COMM_WORLD, &wrank);
    MPI_Comm_size(MPI_COMM_WORLD, &wsize);
    static const char *const cases[] = {"air3d", "di6", NULL};
    static const char *const accs[] = {"low", "medium", "high", "veryHigh", NULL};
    run_par rp = {0, 0, 0, 0, 0, 1, 0, 0};
    int serial = 0, header = 0, nsplit = 0;
    long split[HJ_LS_MAXDIM];
    const char *out = NULL;
    hj_cli_opt opts[] = {
        {.name = "--case", .type = HJ_OPT_CHOICE, .value = &rp.which, .choices = cases,
         .help = "air3d (3-D, paper 2) or di6 (three double integrators, 6-D)"},
        {.name = "--N", .type = HJ_OPT_LONG, .value = &rp.N, .min = 0, .max = 100000, .metavar = "N",
         .help = "air3d: NX (default 26); di6: nodes on axes 0-3 (default 7)", .dflt = "per case"},
        {.name = "--Nsplit", .type = HJ_OPT_LONG, .value = &rp.nsplit_n, .min = 0, .max = 100000, .metavar = "N",
         .help = "di6: nodes on axes 4 and 5", .dflt = "9"},
        {.name = "--N5", .type = HJ_OPT_LONG, .value = &rp.n5, .min = 0, .max = 100000, .metavar = "N",
         .help = "di6: nodes on axis 5 (weak scaling: grows with the processes)", .dflt = "--Nsplit"},
        {.name = "--first-order", .type = HJ_OPT_FLAG, .value = &rp.first,
         .help = "di6: first order upwind differences and forward Euler (default ENO2, RK2)"},
        {.name = "--toolbox-rules", .type = HJ_OPT_FLAG, .value = &rp.toolbox,
         .help = "air3d: the toolbox's CFL rule (per-dimension maxima) and grid-wide WENO5 epsilon"},
        {.name = "--tmax", .type = HJ_OPT_DOUBLE, .value = &rp.tmax, .min = 0, .max = 1000, .metavar = "T",
         .help = "horizon (default: air3d 2.8, di6 0.5)", .dflt = "per case"},
        {.name = "--accuracy", .type = HJ_OPT_CHOICE, .value = &rp.acc, .choices = accs,
         .help = "air3d: the toolbox's accuracy (di6: ENO2, RK2)"},
        {.name = "--split", .type = HJ_OPT_LONG_LIST, .value = split, .min = 1, .max = HJ_LS_MAXDIM - 1,
         .metavar = "A,B", .count = &nsplit, .maxn = HJ_LS_MAXDIM,
         .help = "axes to split (default: the two outermost)", .dflt = "outermost two"},
        {.name = "--serial", .type = HJ_OPT_FLAG, .value = &serial,
         .help = "the undivided library on one process (the reference)"},
        {.name = "--out", .type = HJ_OPT_STRING, .value = &out, .metavar = "FILE",
         .help = "the final value: .vtk (up to 3-D) or .raw (any dimension)"},
        {.name = "--header", .type = HJ_OPT_FLAG, .value = &header, .help = "print the TSV column names first"},
    };
    hj_cli_spec spec = {PROG, "reachability over MPI, bitwise equal to the single-process library", opts,
                        (int)(sizeof opts / sizeof opts[0]), NULL};
    int help = 0;
    hj_error err;
    if (hj_cli_parse(&spec, argc, argv, &help, &err)) usage_fail(wrank, err.msg);
    if (help) {
        if (wrank == 0) {
            if (help == HJ_CLI_LIST) hj_cli_list(&spec, stdout);
            else hj_cli_help(&spec, stdout);
        }
        MPI_Finalize();
        return 0;
    }
    if (rp.N == 0) rp.N = rp.which == 0 ? 26 : 7;
    if (rp.nsplit_n == 0) rp.nsplit_n = 9;
    if (rp.tmax == 0) rp.tmax = rp.which == 0 ? 2.8 : 0.5;
    const char *bad = NULL;
    if (serial && wsize != 1) bad = "--serial runs on one process";
    else if (rp.which == 0 && rp.N < 8) bad = "air3d needs --N >= 8";
    else if (rp.which == 1 && (rp.N < 2 || rp.nsplit_n < 2 || rp.n5 == 1)) bad = "di6 needs at least 2 nodes per axis";
    else if (out && !(strlen(out) > 4 && (!strcmp(out + strlen(out) - 4, ".vtk") || !strcmp(out + strlen(out) - 4, ".raw"))))
        bad = "--out must end in .vtk or .raw";
    if (bad) usage_fail(wrank, bad);
    int axes[HJ_LS_MAXDIM];
    for (int k = 0; k < nsplit; k++) axes[k] = (int)split[k];

    hj_ls_grid global;
    if (grid_of(&rp, &global, &err)) fail(wrank, &err);
    hj_mpi m;
    /* A refused decomposition is refused on every process alike: one
     * message, the usage exit status. */
    if (hj_mpi_init(&m, MPI_COMM_WORLD, &global, nsplit, axes, &err)) usage_fail(wrank, err.msg);
    /* --serial: the undivided grid without hooks (its layout is the local
     * grid's on one process, so the writer takes the array as it is). */
    const hj_ls_grid *g = serial ? &m.global : &m.local;
    double *phi = hj_ls_alloc(g);
    if (!phi) {
        hj_error_set(&err, HJ_ENOMEM, "out of memory");
        fail(wrank, &err);
    }
    hj_progress("%s: %s on %d process(es) ...\n", PROG, cases[rp.which], m.size);
    long steps = 0;
    MPI_Barrier(m.comm);
    hj_mpi_stats_reset(&m);
    const double t0 = MPI_Wtime();
    if (solve(&rp, &m.global, g, phi, &steps, &err)) fail(m.rank, &err);
    const double secs = MPI_Wtime() - t0;
    /* Per-process communication, averaged; the slowest process's wall. */
    double v[4] = {m.halo_seconds + m.reduce_seconds, m.halo_bytes, secs, m.halo_seconds};
    double wall = secs;
    MPI_Allreduce(MPI_IN_PLACE, v, 4, MPI_DOUBLE, MPI_SUM, m.comm);
    MPI_Allreduce(MPI_IN_PLACE, &wall, 1, MPI_DOUBLE, MPI_MAX, m.comm);
    /* Norms and measure: the single-process library's functions in
     * --serial, their MPI counterparts otherwise (exact sums: the same
     * bits).  The measure of a 6-D set is not computed. */
    int pdim = -1;
    for (int d = 0; d < global.dim; d++)
        if (global.bc[d].type == HJ_LS_BC_PERIODIC) pdim = d;
    double mx, avg, rms, meas = NAN;
    if (serial) {
        hj_ls_norms(g, phi, NULL, &mx, &avg, &rms);
        if (global.dim <= 3 && hj_reach_measure(g, phi, &meas, &err)) fail(m.rank, &err);
    } else {
        if (hj_mpi_norms(&m, phi, NULL, &mx, &avg, &rms, &err)) fail(m.rank, &err);
        if (global.dim <= 3 && hj_mpi_measure(&m, phi, pdim, &meas, &err)) fail(m.rank, &err);
    }
    const long neg = hj_mpi_count_negative(&m, phi);
    if (out && hj_mpi_write(&m, out, "phi", phi, &err)) fail(m.rank, &err);
    if (m.rank == 0) {
        if (header)
            printf("case\tranks\tsplit\tnodes\tsteps\tseconds\tstep_ms\tcomm_frac\thalo_frac\thalo_bytes_per_rank_step\t"
                   "max\tavg\trms\tnegative\tmeasure\n");
        char sp[64] = "none";
        if (!serial && m.size > 1) {
            int len = 0;
            for (int d = 0; d < global.dim; d++)
                if (m.p[d] > 1) len += snprintf(sp + len, sizeof sp - (size_t)len, "%s%d:%d", len ? "," : "", d, m.p[d]);
        }
        printf("%s\t%d\t%s\t%zu\t%ld\t%.3f\t%.3f\t%.3f\t%.3f\t%.0f\t%.17g\t%.17g\t%.17g\t%ld\t%.17g\n", cases[rp.which], m.size,
               serial ? "serial" : sp, global.nodes, steps, wall, 1e3 * wall / (double)(steps ? steps : 1),
               v[0] / v[2], v[3] / v[2], v[1] / m.size / (double)(steps ? steps : 1), mx, avg, rms, neg, meas);
    }
    hj_ls_free(phi);
    hj_mpi_free(&m);
    MPI_Finalize();
    return 0;
}
