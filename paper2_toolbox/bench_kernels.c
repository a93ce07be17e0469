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
  the third step on).  Convection in 2-D adds the steady velocity's cache
  (`velocity_steady`): one row of v_d per dimension, 8 bytes each per
  node-stage.  In 3-D the rotation's callback is called per row and stage
  instead (no bytes: its rows stay in cache): the 101^3 cache (24 MB, with
  v_3's zero rows read for their flow test) streams from memory and cost
  more than the callback, 4-13 % more CPU time at each level of Table 1
  (bench_convection, 1 thread, alternated runs on a shared machine, 28
  November 2026); both give the same bits.
  air3D (`range_free` in `p2_air3d.c`: no pass for the gradient range; the
  restriction clips in the term's pass): the stages as above; order 1 is
  the term's pass (16) and the combination (24).  Checked with
  cachegrind, its last-level cache set to 256 KB (smaller than one array,
  so that every pass streams): 2-D veryHigh, the read and write-allocate
  misses of the convection's functions are 35.4 bytes per node-stage
  (velocity rows 16.0, phi 8.2, the stages' y0 5.5 and dst 5.4), plus the
  write-backs of the in-place last stage it does not count (8/3): 38.1
  against the model's 37.3;
- flops per node-stage: counted, not derived from the scheme's formulas
  (an operation count of the formulas, 544 for air3D veryHigh, missed what
  the compiler keeps and removes: common subexpressions, the smoothness
  sums shared by both sides, the rows' tail lanes).  Counted from the
  executed instructions: a callgrind run with `--dump-instr=yes` of each
  case (`--threads 1 --repeat 1`; convection3d to t = 1/8, 160 steps, as
  the 2-D veryHigh case gave the same count, 194.1 then, at 320 and at 2520
  steps) joined with `objdump -d` of this binary (`scripts/count-flops`,
  whose head shows the commands); every executed add,
  subtract, multiply, divide, max, min and square root counts once per
  lane (4 in a ymm register, 2 in an xmm, 1 scalar), a fused multiply-add
  twice; compares, blends and sign masks not at all; the timed run's
  functions only (not the setup, the triad or the peak loop).  Valgrind
  runs the avx2 clones (it has no AVX-512).  The avx512f clones' loops
  have the same arithmetic instructions per vector, or one fewer or more
  (objdump of both clones' loops: hj_ls_weno5_row_next_eps 54 multiplies,
  32 adds, 16 subtracts, 17 divisions, 4 max in the loop of the first rows,
  57, 30, 23, 2, 4 in the others'; ham_partial_row and
  hj_ls_weno5_transport2_eps identical), so the counts differ mainly in
  the row tails (51 nodes: 52 lanes in ymm, 56 in zmm, up to 8 % more in
  the row loops); conv2_row (convection2d medium) is vectorised
  differently in its avx512f clone, whose count is not checked.  Counted
  (old formula count in brackets): air3D low 66.3 (61), medium 105.2 (97), high 193.7
  (169), veryHigh 351.8 (544: WENO5 rows along x_2 and x_3 211.2, the
  x_1 rows with the gradient mean 104.1, the Lax-Friedrichs finish 18.8,
  H's partials 16.6); convection2d medium 42.2 (25), veryHigh 154.9 (174);
  convection3d veryHigh 161.5 (182; WENO5 137.3, the rows' sums and
  stage 16.1, the rotation's callback 3.0).  WENO5A's blend in Jiang and
  Peng's form (hj_ls_deriv.c, 28 November 2026) took air3D veryHigh from
  421.8 (WENO5 rows 257.8 and 127.4), convection2d veryHigh from 194.1 and
  convection3d from 197.3 (counted with the cached velocity).  Recount
  after a change of the kernel or of its compiler flags;
- the roofline: min(peak flops, bandwidth x flops / byte), with the
  bandwidth of a STREAM triad (a[i] = b[i] + s c[i], 24 bytes per
  element, wall time) over three arrays of the case's grid size
  (`triad_ws_GBs`, 1 and 2 threads: three arrays as large together as
  the case's state, stage arrays and cached velocity rows, so the level
  of the memory hierarchy they live in) and the peak of a register-resident loop of 16
  independent multiply-add chains of 8 doubles (throughput bound: see
  madd), each thread's rate over its own CPU time, summed; both measured
  here with 1 and 2 threads.  Beside it the theoretical peak of one core:
  2 vector multiplies + 2 vector adds per cycle (Zen 5's four FP pipes;
  32 flops per cycle with AVX-512) times the clock, measured by a chain of
  dependent integer adds (the clock in /proc/cpuinfo is a VM's guess).
  The triad over 3 x 32 MB (main memory) is printed in the header line.
  Until 27 November 2026 the roofline took that one for every case: the
  201^2 cases' arrays (343 KB each with the ghost layers) live in the last level cache, whose
  triad runs 4 times as fast here (84-96 against 21.4 GB/s, Zen 4), so
  convection2d medium showed 1.03 of a memory roof it is not under (0.42
  of the cache's); removing its velocity rows' reads (each distinct row
  stored once) left its time as it was (0.342 against 0.343 s).
  The achieved fraction is the case's flop rate over its roofline: with
  the best one-thread run's wall time (`frac_roof_1`, `frac_roof_2`) and
  with its CPU time (`frac_roof_cpu1`, the one to read on a loaded
  machine).

The reference seconds (`ref_s`) are ToolboxLS 1.1 run by GNU Octave 7.3
(tuned malloc) on one core of this machine kind, measured side by side
with this code: air3D low 5.47 s, medium 18.2 s, veryHigh 45.1 s;
convectionDemo 2-D medium 15.9 s, veryHigh 62-105 s (62 used: the least
favourable ratio).  None was measured for air3D high or for 3-D
convection, whose reference is the toolbox document's 2585 s (MATLAB 6.5
on a 2004 Pentium 4: a different machine, shown for scale only).

The machine kind's VMs are not all one core (the header line names the
CPU's vendor, family and model), and the reference seconds were measured
once, on a VM whose core was not recorded, so `ratio` moves with the core
as well as with the code.  The same binary and the same bits (phi_hash),
one thread: on AMD family 26 (Zen 5) air3D veryHigh took 0.865-0.93 s
(48-52x), on family 25 model 17 (Zen 4) 1.33-1.41 s (32-34x), low 0.118
against 0.095 s, convection3d 36.5 s against 24.1 s.  On Zen 4 the
veryHigh case's 428.5 counted flops per node-stage at the measured
multiply-add peak (52.7 GFLOP/s) take 0.906 s, which is the 50x time
(0.902 s): the code there runs at 0.67 of that peak, and only fewer
operations per node would reach 50x on that core.  Jiang and Peng's form
of WENO5A (351.8 flops) took its one-thread CPU time there from 1.328-1.370 s
to 1.246-1.269 s, convection2d veryHigh from 1.512-1.530 to 1.399-1.411 s
(six runs each, alternated, on a shared machine) and convection3d from
33.27-34.18 to 32.15-32.49 s (two runs each).

`phi_hash`: a hash (64-bit FNV-1a) of the bytes of the one-thread run's
final phi at the interior nodes, so that a change meant to keep the bits
can be checked against the same column of the code before it.

Output: `kernels_bench.tsv` and the same table on stdout.  Timings depend
on the machine's load (printed); run with OMP_WAIT_POLICY=passive, which
keeps a loaded machine's runs sane but makes each of the many short
parallel regions of the 201^2 cases pay a thread wake-up: there two
threads were slower than one (medium 0.69x, veryHigh 0.90x, 27 November
2026, idle machine), and 1.38x and 1.64x with libgomp's default policy;
the 3-D case gained 1.95x passive.  `make bench` runs this; the tests
never do.
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

/* The calling thread's CPU seconds: on a shared machine the time it ran,
 * not the time it waited for a core. */
static double thread_cpu(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
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

/* The best of 5 timings of `inner` triads over n elements each. */
static double triad_gbs(double *a, const double *b, const double *c, long n, long inner)
{
    double best = 0;
    for (int rep = 0; rep < 5; rep++) {
        const double t0 = now();
        /* one parallel region: each thread its own static chunk, inner
         * times, without a barrier between the sweeps (a wake-up per
         * sweep would be timed instead of the bandwidth) */
#ifdef _OPENMP
#pragma omp parallel
#endif
        for (long k = 0; k < inner; k++) {
            const double s = 1.0 + 1e-3 * (double)(rep + k);
#ifdef _OPENMP
#pragma omp for schedule(static) nowait
#endif
            for (long i = 0; i < n; i++) a[i] = b[i] + s * c[i];
        }
        const double dt = now() - t0, gbs = 24.0 * (double)n * (double)inner / dt / 1e9;
        best = gbs > best ? gbs : best;
    }
    return best;
}

/* The triad on three arrays of n doubles together as large as the case's
 * working set (the level of the memory hierarchy its state lives in: a
 * 201^2 grid's arrays fit in the last level cache, whose bandwidth is
 * several times the 32 MB triad's), first touched by the threads that use
 * them; NAN without memory. */
static double triad_ws_gbs(size_t n)
{
    double *a = malloc(sizeof(double) * n), *b = malloc(sizeof(double) * n), *c = malloc(sizeof(double) * n);
    double gbs = NAN;
    if (a && b && c) {
        const long nl = (long)n;
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
        for (long i = 0; i < nl; i++) a[i] = 0, b[i] = 1, c[i] = 2;
        gbs = triad_gbs(a, b, c, nl, 1 + 20000000L / nl); /* about 2e7 elements per timing */
    }
    free(a), free(b), free(c);
    return gbs;
}

/* The multiply-add peak: 16 independent chains x = x a + b of 8 doubles
 * each, held in vector registers (GCC's vector types, so that the chains
 * stay in registers instead of an array in memory, whose store-to-load
 * latency bounded the loop), 256 flops per iteration.  A chain's step is a
 * multiply then an add (not contracted to a fused multiply-add under
 * -std=c11, as in the kernel): about 5 cycles of latency, and at 2
 * multiplies + 2 adds per cycle 10 chains keep the pipes busy, so 16 make
 * the loop throughput bound.  The avx2 and default clones split each chain
 * into 2 or 4 registers and spill: on such machines the figure is low. */
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
#include <cpuid.h>
typedef double v8d __attribute__((vector_size(64)));
enum { NCHAIN = 16 };
__attribute__((target_clones("avx512f", "avx2", "default"))) static double madd(long iters)
{
    v8d x[NCHAIN], a, b;
    for (int l = 0; l < 8; l++) {
        a[l] = 0.999999, b[l] = 1e-7;
        for (int k = 0; k < NCHAIN; k++) x[k][l] = 1 + k + 0.125 * l;
    }
    for (long it = 0; it < iters; it++) {
#pragma GCC unroll 16
        for (int k = 0; k < NCHAIN; k++) x[k] = x[k] * a + b;
    }
    double sum = 0;
    for (int k = 0; k < NCHAIN; k++)
        for (int l = 0; l < 8; l++) sum += x[k][l];
    return sum;
}

/* Core cycles per second: a chain of dependent integer adds, one cycle
 * each on any x86-64 core (the empty asm keeps the chain from being folded
 * and the addend from being an immediate, which some cores eliminate). */
static double clock_ghz(void)
{
    double best = 0;
    const long n = 50000000;
    for (int rep = 0; rep < 3; rep++) {
        long x = 0, y = 1;
        __asm__ volatile("" : "+r"(y));
        const double t0 = thread_cpu();
        for (long i = 0; i < n; i++) {
            x += y;
            __asm__ volatile("" : "+r"(x));
            x += y;
            __asm__ volatile("" : "+r"(x));
            x += y;
            __asm__ volatile("" : "+r"(x));
            x += y;
            __asm__ volatile("" : "+r"(x));
        }
        const double dt = thread_cpu() - t0;
        if (x != 4 * n) return NAN;
        best = fmax(best, 4.0 * (double)n / dt / 1e9);
    }
    return best;
}

/* The CPU's vendor, family and model (CPUID leaf 1, extended family
 * added): the machine kind's VMs are not all the same core, and the
 * per-core peak below depends on it. */
static void cpu_id(char vendor[13], unsigned *family, unsigned *model)
{
    unsigned a, b, c, d;
    memset(vendor, 0, 13);
    *family = *model = 0;
    if (!__get_cpuid(0, &a, &b, &c, &d)) return;
    memcpy(vendor, &b, 4), memcpy(vendor + 4, &d, 4), memcpy(vendor + 8, &c, 4);
    if (!__get_cpuid(1, &a, &b, &c, &d)) return;
    const unsigned fam = (a >> 8) & 0xF, ext = (a >> 20) & 0xFF, mod = (a >> 4) & 0xF, emod = (a >> 16) & 0xF;
    *family = fam == 0xF ? fam + ext : fam;
    *model = fam == 0xF || fam == 6 ? (emod << 4) + mod : mod;
}

/* Flops per cycle of one core, multiplies and adds counted apart (the
 * kernel contracts none), at the widest vector its clones use here: AMD
 * Zen 5 (family 26) issues 2 vector multiplies and 2 vector adds per cycle
 * on 512-bit pipes; Zen 2-4 (families 23, 25) the same on 256-bit pipes,
 * so a 512-bit operation takes two slots (16 flops per cycle with AVX-512
 * or AVX2); Intel cores issue 2 multiply-or-add vector operations. */
static double flops_per_cycle(void)
{
    __builtin_cpu_init();
    const double width = __builtin_cpu_supports("avx512f") ? 8 : __builtin_cpu_supports("avx2") ? 4 : 2;
    char vendor[13];
    unsigned family, model;
    cpu_id(vendor, &family, &model);
    if (!strcmp(vendor, "AuthenticAMD")) return family >= 26 ? 4 * width : 4 * fmin(width, 4);
    return 2 * width;
}
#else
enum { NCHAIN = 2 };
static double madd(long iters)
{
    double x[8 * NCHAIN], sum = 0;
    for (int k = 0; k < 8 * NCHAIN; k++) x[k] = 1 + k;
    for (long it = 0; it < iters; it++)
        for (int k = 0; k < 8 * NCHAIN; k++) x[k] = x[k] * 0.999999 + 1e-7;
    for (int k = 0; k < 8 * NCHAIN; k++) sum += x[k];
    return sum;
}
static double clock_ghz(void) { return NAN; }
static double flops_per_cycle(void) { return NAN; }
static void cpu_id(char vendor[13], unsigned *family, unsigned *model)
{
    strcpy(vendor, "unknown");
    *family = *model = 0;
}
#endif

/* The threads' rates summed, each over its own CPU time (wall time on a
 * loaded machine would count the waits for a core). */
static double peak_gflops(void)
{
    double best = 0;
    const long iters = 5000000;
    for (int rep = 0; rep < 3; rep++) {
        double sink = 0, gf = 0;
#ifdef _OPENMP
#pragma omp parallel reduction(+ : sink, gf)
#endif
        {
            const double t0 = thread_cpu();
            sink += madd(iters);
            gf += 16.0 * NCHAIN * (double)iters / (thread_cpu() - t0) / 1e9;
        }
        if (sink != sink) return NAN;
        best = gf > best ? gf : best;
    }
    return best;
}

/* ---- the cases ----------------------------------------------------------- */

/* FNV-1a over the bytes of phi at the interior nodes, row by row. */
static unsigned long long phi_hash(const hj_ls_grid *g, const double *phi)
{
    unsigned long long h = 0xcbf29ce484222325ULL;
    for (size_t r = 0; r < g->rows; r++) {
        long idx[HJ_LS_MAXDIM];
        const unsigned char *b = (const unsigned char *)(phi + hj_ls_row(g, r, idx));
        for (size_t q = 0; q < sizeof(double) * (size_t)g->N[0]; q++) h = (h ^ b[q]) * 0x100000001b3ULL;
    }
    return h;
}

/* Flops per node-stage, counted from the executed arithmetic by
 * scripts/count-flops (the head comment says how); recount after a change
 * of the kernel or of its compiler flags. */
#define FLOPS_AIR3D_LOW 66.3
#define FLOPS_AIR3D_MEDIUM 105.2
#define FLOPS_AIR3D_HIGH 193.7
#define FLOPS_AIR3D_VERYHIGH 351.8
#define FLOPS_CONV2D_MEDIUM 42.2
#define FLOPS_CONV2D_VERYHIGH 154.9
#define FLOPS_CONV3D_VERYHIGH 161.5

enum { AIR3D, CONV2D, CONV3D };
typedef struct {
    int kind, acc;
    double ref_s; /* NAN: none */
    double flops; /* per node-stage, counted (see the head comment) */
} bench_case;
static const bench_case CASES[] = {
    {AIR3D, HJ_LS_ACC_LOW, 5.47, FLOPS_AIR3D_LOW},
    {AIR3D, HJ_LS_ACC_MEDIUM, 18.2, FLOPS_AIR3D_MEDIUM},
    {AIR3D, HJ_LS_ACC_HIGH, NAN, FLOPS_AIR3D_HIGH},
    {AIR3D, HJ_LS_ACC_VERYHIGH, 45.1, FLOPS_AIR3D_VERYHIGH},
    {CONV2D, HJ_LS_ACC_MEDIUM, 15.9, FLOPS_CONV2D_MEDIUM},
    {CONV2D, HJ_LS_ACC_VERYHIGH, 62, FLOPS_CONV2D_VERYHIGH},
    {CONV3D, HJ_LS_ACC_VERYHIGH, 2585, FLOPS_CONV3D_VERYHIGH},
};
enum { NCASE = (int)(sizeof CASES / sizeof CASES[0]) };
static const char *const KIND_NAME[3] = {"air3d", "convection2d", "convection3d"};

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

/* Whether convection keeps the steady velocity's rows (velocity_steady):
 * in 2-D (201^2: 0.65 MB, in cache), not in 3-D (see the comment at the
 * top: reading 24 MB per stage cost more than the rotation's callback). */
static int cache_velocity(const hj_ls_grid *g) { return g->dim == 2; }

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
    term.velocity_steady = cache_velocity(&s->g); /* the rotation does not depend on t */
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
    const double ghz = clock_ghz(), theory = ghz * flops_per_cycle();
    for (int th = 0; th < 2; th++) {
        set_threads(th + 1);
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
        for (long i = 0; i < tn; i++) a[i] = 0, b[i] = 1, cc[i] = 2; /* first touch by the threads that use them */
        bw[th] = triad_gbs(a, b, cc, tn, 1);
        peak[th] = peak_gflops();
    }
    free(a), free(b), free(cc);
    double load[3] = {0, 0, 0};
    getloadavg(load, 3);
    char vendor[13];
    unsigned family, model;
    cpu_id(vendor, &family, &model);
    printf("machine: %s family %u model %u; triad %.1f GB/s (1 thread) %.1f GB/s (2); multiply-add peak %.1f GFLOP/s "
           "(1) %.1f (2), theoretical %.1f per core (%.2f GHz measured x %.0f flops/cycle); load %.2f\n",
           vendor, family, model, bw[0], bw[1], peak[0], peak[1], theory, ghz, flops_per_cycle(), load[0]);

    hj_out o;
    p2_fail_if(PROG, p2_open(&o, dir, "kernels_bench.tsv", &err), &err);
    fprintf(o.fp,
            "# bench_kernels: wall seconds (best of repeat) with 1 and 2 threads; node-stage updates per second; model\n"
            "# bytes and flops per node-stage; roofline = min(peak, bw x flops/byte) with the triad bandwidth and\n"
            "# multiply-add peak measured here (1 thread: %.2f GB/s, %.2f GFLOP/s; 2 threads: %.2f GB/s, %.2f GFLOP/s;\n"
            "# theoretical %.2f GFLOP/s per core: %.3f GHz measured x %.0f flops/cycle); flops_per_ns counted from the\n"
            "# executed vector arithmetic (see bench_kernels.c); CPU %s family %u model %u\n"
            "# frac = achieved flop rate / roofline; ref_s = ToolboxLS under Octave on one core of this machine kind\n"
            "# (convection3d: MATLAB 2004, another machine); ratio = ref_s / s_1thread; cpu_s_1thread = the process's CPU\n"
            "# seconds of the best one-thread run (less moved by the machine's load than wall time); frac_roof_cpu1 = frac\n"
            "# with cpu_s_1thread; the roofline's bandwidth is triad_ws_GBs, a triad over 3 arrays as large together as\n"
            "# the case's working set (1 and 2 threads), the level of the memory hierarchy it lives in; load average %.2f\n"
            "# at start\n"
            "case\tacc\tnodes\tsteps\tstages\ts_1thread\ts_2threads\tspeedup\tmnode_stage_per_s_1\tmnode_stage_per_s_2\t"
            "bytes_per_ns\tflops_per_ns\tfrac_roof_1\tfrac_roof_2\tref_s\tratio_1thread\tbitwise_same\tcpu_s_1thread\t"
            "frac_roof_cpu1\tphi_hash\ttriad_ws_GBs_1\ttriad_ws_GBs_2\n",
            bw[0], peak[0], bw[1], peak[1], theory, ghz, flops_per_cycle(), vendor, family, model, load[0]);
    printf("%-13s %-9s %9s %6s %9s %9s %7s %8s %8s %6s %6s %6s %6s %7s %7s %s\n", "case", "acc", "nodes", "steps",
           "s_1thr", "s_2thr", "speedup", "Mns/s_1", "Mns/s_2", "B/ns", "F/ns", "roof1", "roof2", "ref_s", "ratio",
           "bitwise cpu_1thr roof_cpu1 phi_hash triad_ws1 triad_ws2");
    for (int ci = 0; ci < ncases; ci++) {
        const bench_case *c = &CASES[cases[ci]];
        setup s;
        p2_fail_if(PROG, make_setup(c, &s, &err), &err);
        double secs[2] = {1e300, maxth > 1 ? 1e300 : NAN}, cpu1 = 1e300, bws[2] = {NAN, NAN};
        for (int th = 0; th < maxth; th++) {
            set_threads(th + 1);
            /* the working set: the state, the stage's input and output
             * (3 arrays; air3D's order 1 too), and convection's cached
             * velocity rows (dim arrays, 2-D) */
            const size_t arrays = 3 + (c->kind == AIR3D || !cache_velocity(&s.g) ? 0 : (size_t)s.g.dim);
            bws[th] = triad_ws_gbs(s.g.total * arrays / 3);
        }
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
         * cached velocity rows, 8 B per dimension (2-D) */
        const double fused = (16.0 + 24.0 * (order - 1)) / order;
        const double bytes = c->kind == AIR3D ? (order == 1 ? 16 + 24 : fused)
                                              : fused + (cache_velocity(&s.g) ? 8.0 * dim : 0);
        const double flops = c->flops;
        double rate[2], frac[2], roof[2];
        for (int th = 0; th < 2; th++) {
            rate[th] = ns / secs[th];
            roof[th] = fmin(peak[th] * 1e9, bws[th] * 1e9 * flops / bytes);
            frac[th] = rate[th] * flops / roof[th];
        }
        const double frac_cpu = ns / cpu1 * flops / roof[0];
        const double ratio = c->ref_s / secs[0];
        const char *bits = maxth < 2 ? "-" : same ? "yes" : "NO";
        const unsigned long long hash = phi_hash(&s.g, s.first);
        fprintf(o.fp, "%s\t%s\t%zu\t%ld\t%d\t%.6g\t%.6g\t%.4g\t%.6g\t%.6g\t%.4g\t%.4g\t%.4g\t%.4g\t%g\t%.4g\t%s\t%.6g\t%.4g\t%016llx\t%.4g\t%.4g\n",
                KIND_NAME[c->kind], hj_ls_accuracy_name(c->acc), s.g.nodes, st.steps, order, secs[0], secs[1],
                secs[0] / secs[1], rate[0] / 1e6, rate[1] / 1e6, bytes, flops, frac[0], frac[1], c->ref_s, ratio,
                bits, cpu1, frac_cpu, hash, bws[0], bws[1]);
        printf("%-13s %-9s %9zu %6ld %9.3f %9.3f %7.2f %8.1f %8.1f %6.1f %6.0f %6.3f %6.3f %7.4g %7.3g %s %.3f %.3f %016llx %.1f %.1f\n",
               KIND_NAME[c->kind], hj_ls_accuracy_name(c->acc), s.g.nodes, st.steps, secs[0], secs[1],
               secs[0] / secs[1], rate[0] / 1e6, rate[1] / 1e6, bytes, flops, frac[0], frac[1], c->ref_s, ratio,
               bits, cpu1, frac_cpu, hash, bws[0], bws[1]);
        fflush(stdout);
        hj_ls_free(s.y0), hj_ls_free(s.y), hj_ls_free(s.first);
    }
    p2_fail_if(PROG, hj_out_commit(&o, &err), &err);
    return 0;
}
