/*
# Benchmark of the Ultra-Bee step against the machine's memory bandwidth

**Problem.** Table 5's step (hjbstep.c): d = 3, f = (a, 1, 1) with 11
controls a_i = -1 + 2 i / 10, the unit ball as target on [-2, 2]^3,
CFL 0.9, the target problem (4).

**Measured.** For the dense step (common/hj_ub_dense.h, the full N^3
grid, the dynamics given a row at a time, the CFL rate computed once
since f does not depend on t) with 1 and 2 OpenMP threads,
and for the band step on SSD (common/hj_ub.h, sequential): wall seconds
per step (best of 3), node updates per second (one node and one
control, its d sweeps; the band step counts the nodes of D^{n+1/2}), the
model's bytes and floating point operations per node update, and the
achieved fraction of the bandwidth of a triad a = b + s c measured here
with the same thread count.  Bytes per node update of the dense step:
the last three directions run plane by plane without a grid between
them, the controls in groups of G (as many as fit the workspace's cache
budget: 3 at 200^3, all 11 at 100^3), and each group's pass reads V^n
and the running minimum over the controls and writes the minimum (24 B
per node), the other controls of the group finding them in cache: 24
ceil(11 / G) / 11 B per node update.  Flops of the dense step: per node
and sweep mu = c f (1), the flux (4, one division) and the update (3),
and the minimum over controls (1); compares and selects, about 25 per
node and sweep, are not counted, and they, not the bandwidth, bound the
kernel (the fraction stays well below 1).  The band step's arithmetic
(hj_ub.c) has 10 flops per sweep (two divisions); its bytes are those its
arrays hold per node (snapshot values, mu, f, links) read once per sweep,
a lower bound.  Timings move with the machine's load: compare ratios from
one run.  The check: the dense step gives the same bits with 1 and 2
threads (else the program fails).

**Parameters.** `--sizes N`: the dense grid (default 200; 100 with
`--quick`); the band runs Table 5 at N = 200 (100).

**Output.** bench_ub.tsv, and the same lines on stdout.
*/
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "hj_cli.h"
#include "hj_sys.h"
#include "hj_ub.h"
#include "hj_ub_dense.h"
#include "p3_prog.h"

enum { NA = 11 };

static double now(void)
{
#ifdef _OPENMP
    return omp_get_wtime();
#else
    return hj_sys_cpu_seconds();
#endif
}

static void set_threads(int th)
{
#ifdef _OPENMP
    omp_set_num_threads(th);
#else
    (void)th;
#endif
}

static void dyn(double t, const double *x, int a, double *f, void *ctx)
{
    (void)t;
    (void)x;
    (void)ctx;
    f[0] = -1 + 2.0 * a / (NA - 1);
    f[1] = 1;
    f[2] = 1;
}

/* The batched dynamics, built for AVX-512 and AVX2 besides the baseline
 * (gcc picks one at run time), as a user's vectorised callback would be. */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__SANITIZE_ADDRESS__)
__attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
#endif
static void dyn_row(double t, const double *x, const double *xl, long len, int a, double *f, void *ctx)
{
    (void)t;
    (void)x;
    (void)xl;
    (void)ctx;
    const double fa = -1 + 2.0 * a / (NA - 1);
    for (long j = 0; j < len; j++) {
        f[j] = fa;
        f[len + j] = 1;
        f[2 * len + j] = 1;
    }
}


static hj_ub_problem problem(int n)
{
    return (hj_ub_problem){.d = 3, .n = n, .lo = {-2, -2, -2}, .hi = {2, 2, 2}, .ncontrols = NA, .dyn = dyn,
                           .target = 1, .cfl = 0.9, .boundary = 1, .snap = HJ_UB_SNAP, .avg0 = p3_ball3_avg,
                           .uniform = p3_ball3_uniform, .bbox_lo = {-1, -1, -1}, .bbox_hi = {1, 1, 1}};
}

/* Triad bandwidth in bytes per second (24 B per element; best of 5). */
static double triad(size_t m)
{
    double *a = malloc(m * sizeof *a), *b = malloc(m * sizeof *b), *c = malloc(m * sizeof *c), best = 0;
    if (!a || !b || !c) { free(a); free(b); free(c); return 0; }
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < m; i++) { a[i] = 0; b[i] = 1; c[i] = 2; }
    for (int r = 0; r < 5; r++) {
        const double t0 = now();
#pragma omp parallel for schedule(static)
        for (size_t i = 0; i < m; i++) a[i] = b[i] + 0.5 * c[i];
        const double s = now() - t0, bw = 24.0 * (double)m / s;
        best = bw > best ? bw : best;
    }
    volatile double sink = a[m / 2];
    (void)sink;
    free(a); free(b); free(c);
    return best;
}

/* Best wall and CPU seconds of one dense step (its time step included),
 * from the ball's averages (7b); the values after the steps in v (n^3);
 * the controls per pass in *group. */
static int dense(int n, int steps, double *v, double *secs, double *cpu, int *group, hj_error *err)
{
    hj_ub_problem pb = problem(n);
    hj_ub_dense ws;
    int rc = hj_ub_dense_init(&ws, &pb, dyn_row, err);
    if (rc) return rc;
    ws.autonomous = 1; /* f does not depend on t: the CFL rate once */
    *group = ws.group;
    for (size_t l = 0; l < ws.total; l++) {
        const int idx[3] = {(int)(l / ((size_t)n * n)), (int)(l / n % n), (int)(l % n)};
        double blo[3], bhi[3];
        for (int k = 0; k < 3; k++) {
            blo[k] = pb.lo[k] + (idx[k] - 0.5) * ws.dx[k];
            bhi[k] = blo[k] + ws.dx[k];
        }
        v[l] = p3_ball3_avg(blo, bhi, NULL);
    }
    double t = 0;
    *secs = *cpu = 1e300;
    for (int s = 0; s < steps && !rc; s++) {
        const double t0 = now(), c0 = hj_sys_cpu_seconds(), dt = hj_ub_dense_dt(&ws, t, 10.0);
        rc = hj_ub_dense_step(&ws, v, t, dt, err);
        const double e = now() - t0, c = hj_sys_cpu_seconds() - c0;
        *secs = e < *secs ? e : *secs;
        *cpu = c < *cpu ? c : *cpu;
        t += dt;
    }
    hj_ub_dense_free(&ws);
    return rc;
}

/* Best seconds of one band step on SSD and the mean |D^{n+1/2}|. */
static int band(int n, int steps, double *secs, double *nodes, size_t *bytes, hj_error *err)
{
    hj_ub_problem pb = problem(n);
    hj_ub_solver sv;
    int rc = hj_ub_init(&sv, &pb, HJ_BAND_SSD, err);
    *secs = 1e300;
    for (int s = 0; s < steps && !rc; s++) {
        const double t0 = hj_sys_cpu_seconds();
        rc = hj_ub_step(&sv, 10.0, err);
        const double e = hj_sys_cpu_seconds() - t0;
        *secs = e < *secs ? e : *secs;
    }
    *nodes = sv.steps ? sv.band_sum / (double)sv.steps : 0;
    *bytes = hj_band_bytes(sv.s);
    hj_ub_free(&sv);
    return rc;
}

int main(int argc, char **argv)
{
    p3_args a = {.prog = "bench_ub"};
    p3_args_parse(&a, argc, argv, "Benchmark: the dense and the band UB-HJB step against a measured triad bandwidth.",
                  NULL, 5, 5);
    const int n = a.nsizes ? (int)a.sizes[0] : a.quick ? 100 : 200, nb = a.quick ? 100 : 200, steps = 3;
    hj_error err;
    hj_out out;
    if (p3_open(&out, a.out_dir, "bench_ub.tsv", &err)) p3_die(a.prog, &err);
    char line[4][512];
    int nl = 0;
    const char *head = "kernel\tN\tthreads\twall_s_step\tcpu_s_step\tMupd_per_s\tMupd_per_cpu_s\tB_per_upd\tflop_per_upd\ttriad_GB_s\tbw_fraction\n";
    /* dense: per pass of a group of controls, V^n (read) and the min over
     * the controls (read + write); the rest works on planes in cache */
    const double dense_flops = 8.0 * 3 + 1;
    const size_t total = (size_t)n * (size_t)n * (size_t)n;
    double *v[2] = {malloc(total * sizeof(double)), malloc(total * sizeof(double))};
    if (!v[0] || !v[1]) {
        hj_error_set(&err, HJ_ENOMEM, "out of memory: two %d^3 grids", n);
        hj_out_abort(&out);
        p3_die(a.prog, &err);
    }
    for (int th = 1; th <= 2; th++) {
        set_threads(th);
        double secs = 0, cpu = 0;
        int group = 1;
        hj_progress("bench_ub: dense N=%d, %d thread(s) ...\n", n, th);
        if (dense(n, steps, v[th - 1], &secs, &cpu, &group, &err)) { hj_out_abort(&out); p3_die(a.prog, &err); }
        const double dense_bytes = 24.0 * ((NA + group - 1) / group) / NA;
        const double upd = (double)n * n * n * NA / secs, bw = triad((size_t)1 << 24);
        snprintf(line[nl++], sizeof line[0], "UB dense\t%d\t%d\t%.4g\t%.4g\t%.4g\t%.4g\t%.3g\t%.0f\t%.4g\t%.3f\n", n, th,
                 secs, cpu, upd / 1e6, (double)n * n * n * NA / cpu / 1e6, dense_bytes, dense_flops, bw / 1e9, upd * dense_bytes / bw);
    }
    /* the check: the same bits for 1 and 2 threads */
    const int same = !memcmp(v[0], v[1], total * sizeof(double));
    free(v[0]);
    free(v[1]);
    if (!same) {
        hj_error_set(&err, HJ_EINVAL, "dense step: 1 and 2 threads give different values");
        hj_out_abort(&out);
        p3_die(a.prog, &err);
    }
    set_threads(1);
    {
        double secs = 0, nodes = 0;
        size_t bytes;
        hj_progress("bench_ub: band SSD N=%d ...\n", nb);
        if (band(nb, steps, &secs, &nodes, &bytes, &err)) { hj_out_abort(&out); p3_die(a.prog, &err); }
        /* per node and sweep: w, wn, mu, v0 (32 B) and two links (8 B);
         * f and mu written once per control (48 B / 3 sweeps) */
        const double upd = nodes * NA / secs, bb = 3 * (32.0 + 8.0) + 48.0, bw = triad((size_t)1 << 24);
        snprintf(line[nl++], sizeof line[0], "UB band SSD\t%d\t1\t%.4g\t%.4g\t%.4g\t%.4g\t%.0f\t%.0f\t%.4g\t%.4f\n", nb, secs, secs,
                 upd / 1e6, upd / 1e6, bb, 10.0 * 3 + 1, bw / 1e9, upd * bb / bw);
        (void)bytes;
    }
    fputs(head, stdout);
    fprintf(out.fp, "# bench_ub: Table 5's step (11 controls), wall seconds (dense) / CPU seconds (band), best of %d\n",
            steps);
    fprintf(out.fp, "# dense step after %d steps: the same bits with 1 and 2 threads\n", steps);
    fputs(head, out.fp);
    for (int i = 0; i < nl; i++) {
        fputs(line[i], stdout);
        fputs(line[i], out.fp);
    }
    if (hj_out_commit(&out, &err)) p3_die(a.prog, &err);
    return 0;
}
