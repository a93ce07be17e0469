/*
# Benchmark: the level set kernel against the machine's roofline

The demos of the toolbox timed on the toolbox's own grids, each with 1 and 2
OpenMP threads (wall clock, the best of `--repeat` runs), and set against
what the hardware could do:

| case | grid | run |
|---|---|---|
| air3D low, medium, high, veryHigh | 51 x 40 x 50 | t = 2.8, global Lax-Friedrichs (`p2_air3d.c`) |
| convection2d medium, veryHigh | 201^2 on [-1, 1]^2 | convectionDemo('linear'), t = 1 |
| convection3d veryHigh | 101^3 on [-1, 1]^3 | the same in 3-D (Table 1) |

Per case: seconds with 1 and 2 threads and their ratio, node-stage updates
per second (steps x RK stages x nodes / seconds), whether the 1- and
2-thread states agree bit for bit, the CPU seconds of the best one-thread
run (`cpu_s_1thread`: on a loaded machine wall time counts the waits for
a core, CPU time much less, so before/after ratios are taken from it;
`--threads 1` runs the one-thread figures only), and a roofline line:

- bytes per node-stage: the compulsory traffic of the passes over the grid
  (a model, not a counter: this machine exposes no hardware counters),
  counted from the arrays of grid size each pass reads and writes once
  (the rows of differences, the ring along dimension 1 and the row of G
  live in a per-thread workspace of a few rows, in cache).  Every RK stage
  is one pass of the term that reads its input and the state it combines
  with and writes the stage (`hj_ls_term_stage`): the first stage, whose
  two are the same array, 16 bytes, the others 24 (the first stage is
  fused too once the bound repeats, as the steady velocity's does: from
  the third step on).  Convection adds the steady velocity's cache
  (`velocity_steady`): one row of v_d per dimension, 8 bytes each per
  node-stage (in 3-D the row of v_3, zero, is read for its flow test).
  air3D (`range_free` in `p2_air3d.c`: no pass for the gradient range; the
  restriction clips in the term's pass): the stages as above; order 1 is
  the term's pass (16) and the combination (24).  Checked with
  cachegrind, its last-level cache set to 256 KB (smaller than one array,
  so that every pass streams): 2-D veryHigh, the read and write-allocate
  misses of the convection's functions are 35.4 bytes per node-stage
  (velocity rows 16.0, phi 8.2, the stages' y0 5.5 and dst 5.4), plus the
  write-backs of the in-place last stage it does not count (8/3): 38.1
  against the model's 37.3;
- flops per node-stage: an operation count of the scheme (per dimension,
  both one-sided derivatives of upwind first order 4, ENO2 16, ENO3 40,
  WENO5 165; convection computes only the upwind side, half of these, plus
  2 for the velocity product and its sum into G, and in 3-D 4 more for the
  CFL sum and maximum, which the 2-D rows take from the steady velocity's
  cache; Lax-Friedrichs 8 per dimension for the gradient, dissipation and
  CFL sums plus 20 for air3D's H and partials; 5 for the RK combination),
  again a model;
- the roofline: min(peak flops, bandwidth x flops / byte), with the
  bandwidth of a STREAM triad (a[i] = b[i] + s c[i], 3 x 32 MB, 24 bytes
  per element) and the peak of a register-resident multiply-add loop,
  both measured here with 1 and 2 threads; the achieved fraction is the
  case's flop rate over its roofline.

The reference seconds (`ref_s`) are ToolboxLS 1.1 run by GNU Octave 7.3
(tuned malloc) on one core of this machine kind, measured side by side
with this code: air3D low 5.47 s, medium 18.2 s, veryHigh 45.1 s;
convectionDemo 2-D medium 15.9 s, veryHigh 62-105 s (62 used: the least
favourable ratio).  None was measured for air3D high or for 3-D
convection, whose reference is the toolbox document's 2585 s (MATLAB 6.5
on a 2004 Pentium 4: a different machine, shown for scale only).

Output: `kernels_bench.tsv` and the same table on stdout.  Timings depend
on the machine's load (printed); run with OMP_WAIT_POLICY=passive.  `make
bench` runs this; the tests never do.
*/
#define _DEFAULT_SOURCE /* getloadavg */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "hj_cli.h"
#include "hj_io.h"
#include "hj_ls_accuracy.h"
#include "hj_ls_ode.h"
#include "hj_ls_shape.h"
#include "hj_ls_term.h"
#include "p2_air3d.h"
#include "p2_cli.h"
#include "p2_convection.h"

static const char *const PROG = "bench_kernels";

static double now(void)
{
#ifdef _OPENMP
    return omp_get_wtime();
#else
    return (double)clock() / CLOCKS_PER_SEC;
#endif
}

static void set_threads(int n)
{
#ifdef _OPENMP
    omp_set_num_threads(n);
#else
    (void)n;
#endif
}

/* ---- the machine: triad bandwidth and multiply-add peak ---------------- */

static double triad_gbs(double *a, const double *b, const double *c, long n)
{
    double best = 0;
    for (int rep = 0; rep < 5; rep++) {
        const double t0 = now(), s = 1.0 + 1e-3 * rep;
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
        for (long i = 0; i < n; i++) a[i] = b[i] + s * c[i];
        const double dt = now() - t0, gbs = 24.0 * (double)n / dt / 1e9;
        best = gbs > best ? gbs : best;
    }
    return best;
}

/* 64 independent chains x = x a + b in registers (enough vectors to hide
 * the latency of the multiply and the add): 2 flops per element and
 * iteration, vectorised as the kernel's clones are. */
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
__attribute__((target_clones("avx512f", "avx2", "default")))
#endif
static void madd(double *x, long iters)
{
    for (long it = 0; it < iters; it++)
        for (int k = 0; k < 64; k++) x[k] = x[k] * 0.999999 + 1e-7;
}

static double peak_gflops(void)
{
    double best = 0;
    const long iters = 5000000;
    for (int rep = 0; rep < 3; rep++) {
        double sink = 0;
        const double t0 = now();
#ifdef _OPENMP
#pragma omp parallel reduction(+ : sink)
#endif
        {
            double x[64];
            for (int k = 0; k < 64; k++) x[k] = 1 + k;
            madd(x, iters);
            for (int k = 0; k < 64; k++) sink += x[k];
        }
        const double dt = now() - t0;
        int nth = 1;
#ifdef _OPENMP
        nth = omp_get_max_threads();
#endif
        if (sink != sink) return NAN;
        const double gf = 128.0 * (double)iters * nth / dt / 1e9;
        best = gf > best ? gf : best;
    }
    return best;
}

/* ---- the cases ----------------------------------------------------------- */

enum { AIR3D, CONV2D, CONV3D };
typedef struct {
    int kind, acc;
    double ref_s; /* NAN: none */
} bench_case;
static const bench_case CASES[] = {
    {AIR3D, HJ_LS_ACC_LOW, 5.47},     {AIR3D, HJ_LS_ACC_MEDIUM, 18.2}, {AIR3D, HJ_LS_ACC_HIGH, NAN},
    {AIR3D, HJ_LS_ACC_VERYHIGH, 45.1}, {CONV2D, HJ_LS_ACC_MEDIUM, 15.9}, {CONV2D, HJ_LS_ACC_VERYHIGH, 62},
    {CONV3D, HJ_LS_ACC_VERYHIGH, 2585},
};
enum { NCASE = (int)(sizeof CASES / sizeof CASES[0]) };
static const char *const KIND_NAME[3] = {"air3d", "convection2d", "convection3d"};

/* Model flops of both one-sided derivatives along one dimension. */
static double deriv_flops(int acc)
{
    static const double f[4] = {4, 16, 40, 165};
    return f[acc];
}

typedef struct {
    hj_ls_grid g;
    double *y0, *y, *first;
} setup;

static int make_setup(const bench_case *c, setup *s, hj_error *err)
{
    int rc;
    if (c->kind == AIR3D) rc = p2_air3d_grid(51, &s->g, err);
    else {
        const int dim = c->kind == CONV2D ? 2 : 3;
        const long n = dim == 2 ? 201 : 101;
        double lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 1};
        long N[3] = {n, n, n};
        hj_ls_bc bc[3];
        for (int d = 0; d < 3; d++) bc[d] = (hj_ls_bc){HJ_LS_BC_EXTRAP_AWAY, 0, 0};
        rc = hj_ls_grid_init(&s->g, dim, lo, hi, N, bc, err);
    }
    if (rc) return rc;
    s->y0 = hj_ls_alloc(&s->g), s->y = hj_ls_alloc(&s->g), s->first = hj_ls_alloc(&s->g);
    if (!s->y0 || !s->y || !s->first) return hj_error_set(err, HJ_ENOMEM, "out of memory");
    if (c->kind == AIR3D) {
        p2_air3d_par par;
        p2_air3d_defaults(&par);
        return p2_air3d_target(&s->g, &par, s->y0, err);
    }
    const double center[3] = {-0.4, 0, 0};
    return hj_ls_shape_sphere(&s->g, center, 0.35, s->y0, err);
}

static int run_case(const bench_case *c, setup *s, hj_ls_ode_stats *st, hj_error *err)
{
    memcpy(s->y, s->y0, sizeof(double) * s->g.total);
    if (c->kind == AIR3D) {
        p2_air3d_par par;
        p2_air3d_defaults(&par);
        const double ts[2] = {0, 2.8};
        return p2_air3d_solve(&s->g, &par, c->acc, HJ_LS_GLF, ts, 2, s->y, NULL, NULL, st, err);
    }
    p2_flow flow = {1, 0, s->g.dim};
    hj_ls_convection term;
    hj_ls_convection_init(&term, &s->g, hj_ls_accuracy_scheme(c->acc));
    term.velocity_fn = p2_flow_velocity;
    term.ctx = &flow;
    term.velocity_steady = 1; /* the rotation does not depend on t */
    hj_ls_ode_opts opts;
    hj_ls_ode_defaults(&opts);
    opts.max_step = 1.0 / (P2_NT - 1);
    const int rc = p2_solve(NULL, c->acc, &s->g, &term.base, 1, s->y, &opts, NULL, st, err);
    hj_ls_convection_free(&term);
    return rc;
}

int main(int argc, char **argv)
{
    const char *dir = NULL;
    long repeat = 3, cases[NCASE], quick = 0, maxth = 2;
    int ncases = 0;
    hj_error err;
    hj_cli_opt opts[] = {
        {.name = "--repeat", .type = HJ_OPT_LONG, .value = &repeat, .min = 1, .max = 100, .metavar = "K",
         .help = "runs of each configuration but the 3-D one (the fastest is kept)"},
        {.name = "--cases", .type = HJ_OPT_LONG_LIST, .value = cases, .min = 0, .max = NCASE - 1, .count = &ncases,
         .maxn = NCASE, .metavar = "LIST",
         .help = "cases to run: 0-3 air3d low..veryHigh, 4-5 convection2d medium, veryHigh, 6 convection3d "
                 "veryHigh (default all)"},
        {.name = "--out-dir", .type = HJ_OPT_STRING, .value = &dir, .metavar = "DIR",
         .help = "where the benchmark's table goes (required)"},
        {.name = "--quick", .type = HJ_OPT_FLAG, .value = &quick, .help = "one run each, the 3-D case left out"},
        {.name = "--threads", .type = HJ_OPT_LONG, .value = &maxth, .min = 1, .max = 2, .metavar = "K",
         .help = "run the cases with 1 .. K threads (default 2; 1: one-thread figures only, no bitwise test)"},
    };
    hj_cli_spec spec = {PROG, "Benchmark: the level set kernel's demos against the machine's roofline, 1 and 2 threads.",
                        opts, (int)(sizeof opts / sizeof opts[0]), "See the comment at the top of bench_kernels.c.\n"};
    hj_cli_parse_or_exit(&spec, argc, argv);
    if (!dir) hj_cli_fail(PROG, HJ_EXIT_USAGE, "--out-dir is required (see --help)");
    if (hj_mkdirs(dir, &err)) hj_cli_fail(PROG, HJ_EXIT_RUN, "%s", err.msg);
    if (!ncases) {
        ncases = quick ? NCASE - 1 : NCASE;
        for (int i = 0; i < ncases; i++) cases[i] = i;
    }
    if (quick) repeat = 1;

    /* the machine */
    const long tn = 4L << 20;
    double *a = malloc(sizeof(double) * (size_t)tn), *b = malloc(sizeof(double) * (size_t)tn),
           *cc = malloc(sizeof(double) * (size_t)tn);
    if (!a || !b || !cc) hj_cli_fail(PROG, HJ_EXIT_RUN, "out of memory");
    double bw[2], peak[2];
    for (int th = 0; th < 2; th++) {
        set_threads(th + 1);
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
        for (long i = 0; i < tn; i++) a[i] = 0, b[i] = 1, cc[i] = 2; /* first touch by the threads that use them */
        bw[th] = triad_gbs(a, b, cc, tn);
        peak[th] = peak_gflops();
    }
    free(a), free(b), free(cc);
    double load[3] = {0, 0, 0};
    getloadavg(load, 3);
    printf("machine: triad %.1f GB/s (1 thread) %.1f GB/s (2); multiply-add peak %.1f GFLOP/s (1) %.1f (2); "
           "load %.2f\n", bw[0], bw[1], peak[0], peak[1], load[0]);

    hj_out o;
    p2_fail_if(PROG, p2_open(&o, dir, "kernels_bench.tsv", &err), &err);
    fprintf(o.fp,
            "# bench_kernels: wall seconds (best of repeat) with 1 and 2 threads; node-stage updates per second; model\n"
            "# bytes and flops per node-stage; roofline = min(peak, bw x flops/byte) with the triad bandwidth and\n"
            "# multiply-add peak measured here (1 thread: %.2f GB/s, %.2f GFLOP/s; 2 threads: %.2f GB/s, %.2f GFLOP/s);\n"
            "# frac = achieved flop rate / roofline; ref_s = ToolboxLS under Octave on one core of this machine kind\n"
            "# (convection3d: MATLAB 2004, another machine); ratio = ref_s / s_1thread; cpu_s_1thread = the process's CPU\n"
            "# seconds of the best one-thread run (less moved by the machine's load than wall time); load average %.2f at start\n"
            "case\tacc\tnodes\tsteps\tstages\ts_1thread\ts_2threads\tspeedup\tmnode_stage_per_s_1\tmnode_stage_per_s_2\t"
            "bytes_per_ns\tflops_per_ns\tfrac_roof_1\tfrac_roof_2\tref_s\tratio_1thread\tbitwise_same\tcpu_s_1thread\n",
            bw[0], peak[0], bw[1], peak[1], load[0]);
    printf("%-13s %-9s %9s %6s %9s %9s %7s %8s %8s %6s %6s %6s %6s %7s %7s %s\n", "case", "acc", "nodes", "steps",
           "s_1thr", "s_2thr", "speedup", "Mns/s_1", "Mns/s_2", "B/ns", "F/ns", "roof1", "roof2", "ref_s", "ratio",
           "bitwise cpu_1thr");
    for (int ci = 0; ci < ncases; ci++) {
        const bench_case *c = &CASES[cases[ci]];
        setup s;
        p2_fail_if(PROG, make_setup(c, &s, &err), &err);
        double secs[2] = {1e300, maxth > 1 ? 1e300 : NAN}, cpu1 = 1e300;
        hj_ls_ode_stats st = {0};
        int same = 1;
        const long reps = c->kind == CONV3D ? 1 : repeat;
        for (int th = 0; th < maxth; th++) {
            set_threads(th + 1);
            for (long r = 0; r < reps; r++) {
                hj_progress("\r%s %s, %d thread(s), run %ld of %ld   ", KIND_NAME[c->kind], hj_ls_accuracy_name(c->acc),
                            th + 1, r + 1, reps);
                const double t0 = now();
                const clock_t c0 = clock();
                p2_fail_if(PROG, run_case(c, &s, &st, &err), &err);
                const double dt = now() - t0, cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
                secs[th] = dt < secs[th] ? dt : secs[th];
                if (th == 0) cpu1 = cpu < cpu1 ? cpu : cpu1; /* one thread: the process's CPU time, less moved by load */
            }
            if (th == 0) memcpy(s.first, s.y, sizeof(double) * s.g.total);
            else same = !memcmp(s.first, s.y, sizeof(double) * s.g.total);
        }
        hj_progress("\r%60s\r", "");
        const int order = hj_ls_accuracy_order(c->acc), dim = s.g.dim;
        const double stages = (double)st.steps * order, ns = stages * (double)s.g.nodes;
        /* bytes: fused stages (16 B the first, 24 B later; air3D's order 1
         * unfused: the term's pass and the combination), and convection's
         * cached velocity rows, 8 B per dimension */
        const double fused = (16.0 + 24.0 * (order - 1)) / order;
        const double bytes = c->kind == AIR3D ? (order == 1 ? 16 + 24 : fused) : fused + 8.0 * dim;
        /* flops: the rotation moves no node along x_3 in 3-D: two dimensions
         * carry flow; the 2-D rows take the CFL bound from the cache */
        const double flops = c->kind == AIR3D ? dim * (deriv_flops(c->acc) + 8) + 20 + 5
                                              : 2 * (deriv_flops(c->acc) / 2 + (dim == 2 ? 2 : 6)) + 5;
        double rate[2], frac[2];
        for (int th = 0; th < 2; th++) {
            rate[th] = ns / secs[th];
            const double roof = fmin(peak[th] * 1e9, bw[th] * 1e9 * flops / bytes);
            frac[th] = rate[th] * flops / roof;
        }
        const double ratio = c->ref_s / secs[0];
        const char *bits = maxth < 2 ? "-" : same ? "yes" : "NO";
        fprintf(o.fp, "%s\t%s\t%zu\t%ld\t%d\t%.6g\t%.6g\t%.4g\t%.6g\t%.6g\t%.4g\t%.4g\t%.4g\t%.4g\t%g\t%.4g\t%s\t%.6g\n",
                KIND_NAME[c->kind], hj_ls_accuracy_name(c->acc), s.g.nodes, st.steps, order, secs[0], secs[1],
                secs[0] / secs[1], rate[0] / 1e6, rate[1] / 1e6, bytes, flops, frac[0], frac[1], c->ref_s, ratio,
                bits, cpu1);
        printf("%-13s %-9s %9zu %6ld %9.3f %9.3f %7.2f %8.1f %8.1f %6.1f %6.0f %6.3f %6.3f %7.4g %7.3g %s %.3f\n",
               KIND_NAME[c->kind], hj_ls_accuracy_name(c->acc), s.g.nodes, st.steps, secs[0], secs[1],
               secs[0] / secs[1], rate[0] / 1e6, rate[1] / 1e6, bytes, flops, frac[0], frac[1], c->ref_s, ratio,
               bits, cpu1);
        fflush(stdout);
        hj_ls_free(s.y0), hj_ls_free(s.y), hj_ls_free(s.first);
    }
    p2_fail_if(PROG, hj_out_commit(&o, &err), &err);
    return 0;
}
