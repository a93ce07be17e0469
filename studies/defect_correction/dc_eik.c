/* dc_eik.c -- defect correction for the high order Eikonal fast sweeping
 * (an experiment; paper1_fastsweeping/eik/notes/defect-correction.md).
 *
 * Case `linear` of paper1_fastsweeping/eik_convergence.c in 3-D: speed
 * v = 2 + g.x, g = (0.5, -0.3, 0.2), source s = (0.1234, -0.0567, 0.0311)
 * on [-1, 1]^3, (N + 1)^3 nodes, h = 2 / N, closed form
 * T = acosh(1 + |g|^2 |x - s|^2 / (2 v(s) v(x))) / |g|.  The source is
 * treated simply: the closed form is imposed (held) on the nodes with
 * |x - s| <= R (R a fixed physical radius, default 0.2), no factoring.
 *
 * Discretisations, on T itself, as common/hj_eik.c forms them when it
 * does not factor (T0 = 1):
 *   H1(T)_i = sqrt(sum_d ((T_i - min(T_{i-1}, T_{i+1}))_+ / h)^2)
 *     (first order Godunov; a missing neighbour at the boundary does not
 *     count);
 *   Hh(T)_i = sqrt(sum_d (t_d / h)^2), t_d the larger of (h D^- T)_+ and
 *     (-h D^+ T)_+ over the candidate sides (the side of the smaller
 *     neighbour, and any side whose neighbour is earlier than the node),
 *     h D^-/+ the WENO3 (eps 1e-6 M^2) or WENO5 (eps 1e-6 (h / 2)^2 M^2)
 *     one-sided differences, M the first order solution's largest value, the entries past the grid's ends the quadratic
 *     extrapolation of the current in-grid values (hj_eik's
 *     current_ghosts); a stencil that crosses a held node into free
 *     nodes beyond uses WENO3 on its inner five entries (WENO5) or the
 *     first order difference on that axis.
 *
 * Iteration: T^0 is the first order fast sweeping solution (min-update
 * from +inf, 2^3 sweeps per iteration, until no node changes by more
 * than tol max T).  Then
 *     H1(T^{k+1}) = g^k := f + H1(T^k) - Hh(T^k)
 * solved by first order Godunov Gauss-Seidel sweeps (no min: the node
 * takes the root of its local equation) warm-started from T^k: either a
 * fixed number of sweeps (the orientations cycling 0..7 across outer
 * steps) or to convergence (inner change <= itol max T).  g^k < 0 is set
 * to 0 (counted).  Stop when max |T^{k+1} - T^k| <= tol max T.
 *
 * Built by `make` (build/bin/studies/defect_correction/dc_eik; libhj for
 * the comparison), run by hand only, with OMP_NUM_THREADS=1.  (The
 * measurements of the notes used a build with -O2 -march=native.)
 *
 * Usage: dc_eik N order [inner] [R] [tol] [itol]
 *   inner: number of inner sweeps per outer step (8 = one full
 *          iteration), or 0: to convergence.
 *   Prints per outer step the change, its ratio to the last and where it
 *   sits (stderr), and one summary line (stdout).
 * Also: dc_eik hj N order [R] [tol] -- hj_eik_solve at the same tol with
 *   the same held ball as fixed data (no source: full sweeps), then with
 *   the point source (its factoring, the orthant pass), for comparison.
 * Environment (diagnostics): DC_VERBOSE=1 the per-step lines; DC_SAVE=file
 *   writes the result (doubles, x fastest); DC_CHECK=file evaluates
 *   Hh - f on a saved result instead of solving; DC_BFO=1 first order
 *   differences where a stencil reaches the ghosts (changes the scheme at
 *   the boundary); DC_EPS=e sets both WENO eps (1e2: linear weights);
 *   DC_GSCALE=c multiplies the speed's gradient g by c > 0 (c -> 0:
 *   straight rays).
 */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "hj_cli.h"
#include "hj_eik.h"
#include "../eik_study.h"

static const double V0 = EIK_STUDY_V0, S[3] = EIK_STUDY_S;
static double G[3] = EIK_STUDY_G; /* scaled by --gscale */

static long n, N3;
static double h;
static double *f;           /* slowness */
static unsigned char *fix;  /* held nodes */

static double vel(const double *x) { return eik_study_vel(3, V0, G, x); }
static double exact(const double *x) { return hj_eik_linear_time(3, V0, G, S, x); }
static void coords(long id, double *x)
{
    const long i = id % n, j = (id / n) % n, k = id / (n * n);
    x[0] = -1 + i * h, x[1] = -1 + j * h, x[2] = -1 + k * h;
}
static double cpu(void) { return (double)clock() / CLOCKS_PER_SEC; }

/* ---- WENO (as common/hj_eik.c) ---- */
static void weno3(const double *v, double eps, double *hm, double *hp)
{
    const double dc = v[3] - 2 * v[2] + v[1], dm = v[2] - 2 * v[1] + v[0], dp = v[2] - 2 * v[3] + v[4];
    const double den = eps + dc * dc;
    const double rm = (eps + dm * dm) / den, rp = (eps + dp * dp) / den;
    const double wm = 1.0 / (1.0 + 2.0 * rm * rm), wp = 1.0 / (1.0 + 2.0 * rp * rp);
    const double cen = 0.5 * (v[3] - v[1]);
    *hm = (1 - wm) * cen + wm * 0.5 * (3 * v[2] - 4 * v[1] + v[0]);
    *hp = (1 - wp) * cen + wp * 0.5 * (-3 * v[2] + 4 * v[3] - v[4]);
}
static double weno5_one(double d1, double d2, double d3, double d4, double d5, double eps)
{
    const double p1 = d1 / 3 - 7 * d2 / 6 + 11 * d3 / 6;
    const double p2 = -d2 / 6 + 5 * d3 / 6 + d4 / 3;
    const double p3 = d3 / 3 + 5 * d4 / 6 - d5 / 6;
    const double q = d1 - 2 * d2 + d3, b = d1 - 4 * d2 + 3 * d3;
    const double cc = d2 - 2 * d3 + d4, e = d2 - d4;
    const double ff = d3 - 2 * d4 + d5, g = 3 * d3 - 4 * d4 + d5;
    const double s1 = 13.0 / 12 * q * q + 0.25 * b * b;
    const double s2 = 13.0 / 12 * cc * cc + 0.25 * e * e;
    const double s3 = 13.0 / 12 * ff * ff + 0.25 * g * g;
    const double a1 = 0.1 / ((eps + s1) * (eps + s1)), a2 = 0.6 / ((eps + s2) * (eps + s2)),
                 a3 = 0.3 / ((eps + s3) * (eps + s3));
    return (a1 * p1 + a2 * p2 + a3 * p3) / (a1 + a2 + a3);
}
static void weno5(const double *v, double eps, double *hm, double *hp)
{
    const double d0 = v[1] - v[0], d1 = v[2] - v[1], d2 = v[3] - v[2];
    const double d3 = v[4] - v[3], d4 = v[5] - v[4], d5 = v[6] - v[5];
    *hm = weno5_one(d0, d1, d2, d3, d4, eps);
    *hp = weno5_one(d5, d4, d3, d2, d1, eps);
}
static const double ghost_w[4][3] = {{0, 0, 0}, {3, -3, 1}, {6, -8, 3}, {10, -15, 6}};
static void current_ghosts(double *v, int r, long id, long nn)
{
    for (int q = -r; q <= r; q++) {
        const long pos = id + q;
        if (pos > nn - 1) {
            const long g = pos - (nn - 1), b = nn - 1 - id + r;
            v[q + r] = ghost_w[g][0] * v[b] + ghost_w[g][1] * v[b - 1] + ghost_w[g][2] * v[b - 2];
        }
    }
    for (int q = r; q >= -r; q--) {
        const long pos = id + q;
        if (pos < 0) {
            const long g = -pos, b = r - id;
            v[q + r] = ghost_w[g][0] * v[b] + ghost_w[g][1] * v[b + 1] + ghost_w[g][2] * v[b + 2];
        }
    }
}

static int order = 3, bfo = 0;
static double eps3 = 1e-6, eps5;

/* Hh (high order) and H1 (first order) residual operators at node id. */
static void residuals(const double *T, long id, double *Hh, double *H1)
{
    const long st[3] = {1, n, n * n};
    const long ip[3] = {id % n, (id / n) % n, id / (n * n)};
    const int r = order == 5 ? 3 : 2;
    double sh = 0, s1 = 0;
    const double Ti = T[id];
    for (int d = 0; d < 3; d++) {
        const long i = ip[d];
        const double TL = i > 0 ? T[id - st[d]] : INFINITY, TR = i < n - 1 ? T[id + st[d]] : INFINITY;
        const double mn = TL < TR ? TL : TR;
        const double t1 = Ti - mn > 0 ? Ti - mn : 0;
        s1 += t1 * t1;
        double v[7];
        int cut = 0;
        for (int q = -r; q <= r; q++) {
            const long pos = i + q;
            v[q + r] = pos >= 0 && pos < n ? T[id + q * st[d]] : NAN;
        }
        /* crossing held nodes into free ones beyond, within reach q */
        int cutq[4] = {0, 0, 0, 0};
        for (int q = 2; q <= r; q++) {
            const long pp = i + q, pm = i - q;
            cutq[q] = cutq[q - 1];
            if (pp < n && !fix[id + q * st[d]])
                for (int j = 1; j < q; j++)
                    if (fix[id + j * st[d]]) cutq[q] = 1;
            if (pm >= 0 && !fix[id - q * st[d]])
                for (int j = 1; j < q; j++)
                    if (fix[id - j * st[d]]) cutq[q] = 1;
        }
        cut = cutq[r];
        /* as hj_eik: a WENO5 stencil so cut falls back to WENO3 on the
         * inner five entries if they are not cut themselves */
        int rr = r;
        if (cut && r == 3 && !cutq[2]) {
            memmove(v, v + 1, 5 * sizeof v[0]);
            rr = 2, cut = 0;
        }
        /* diagnostic only: first order where the stencil reaches the ghosts */
        if (bfo && (i < rr || i > n - 1 - rr)) cut = 1;
        double hm, hp;
        if (cut) {
            hm = i > 0 ? Ti - TL : NAN;
            hp = i < n - 1 ? TR - Ti : NAN;
        } else {
            if (i < rr || i > n - 1 - rr) current_ghosts(v, rr, i, n);
            if (rr == 3) weno5(v, eps5, &hm, &hp);
            else weno3(v, eps3, &hm, &hp);
        }
        /* candidate sides as hj_eik's local_update: the side of the
         * smaller neighbour, and a side whose neighbour is earlier */
        const int side = TL <= TR ? 0 : 1;
        double t = 0;
        if ((side == 0 || TL < Ti) && i > 0 && hm > t) t = hm;
        if ((side == 1 || TR < Ti) && i < n - 1 && -hp > t) t = -hp;
        sh += t * t;
    }
    *Hh = sqrt(sh) / h;
    *H1 = sqrt(s1) / h;
}

/* First order local solve: smallest t with sum_d (t - a_d)_+^2 = (h g)^2. */
static double local1(const double *T, long id, double g)
{
    const long st[3] = {1, n, n * n};
    const long ip[3] = {id % n, (id / n) % n, id / (n * n)};
    double a[3];
    for (int d = 0; d < 3; d++) {
        const double TL = ip[d] > 0 ? T[id - st[d]] : INFINITY, TR = ip[d] < n - 1 ? T[id + st[d]] : INFINITY;
        a[d] = TL < TR ? TL : TR;
    }
    /* sort */
    for (int i = 1; i < 3; i++)
        for (int j = i; j > 0 && a[j] < a[j - 1]; j--) {
            const double s = a[j]; a[j] = a[j - 1]; a[j - 1] = s;
        }
    if (!(a[0] < INFINITY)) return INFINITY;
    const double hg = h * g;
    double t = a[0] + hg;
    if (t <= a[1]) return t;
    const double disc2 = 2 * hg * hg - (a[0] - a[1]) * (a[0] - a[1]);
    t = 0.5 * (a[0] + a[1] + sqrt(disc2 > 0 ? disc2 : 0));
    if (t <= a[2]) return t;
    const double sm = a[0] + a[1] + a[2], sq = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
    const double disc3 = sm * sm - 3 * (sq - hg * hg);
    return (sm + sqrt(disc3 > 0 ? disc3 : 0)) / 3;
}

/* One sweep of orientation o over the grid; slowness g (per node);
 * minupd: T = min(T, local) (first order start).  Returns the max change. */
static double sweep(double *T, const double *g, int o, int minupd)
{
    double ch = 0;
    const long i0 = o & 1 ? n - 1 : 0, di = o & 1 ? -1 : 1;
    const long j0 = o & 2 ? n - 1 : 0, dj = o & 2 ? -1 : 1;
    const long k0 = o & 4 ? n - 1 : 0, dk = o & 4 ? -1 : 1;
    for (long kk = 0, k = k0; kk < n; kk++, k += dk)
        for (long jj = 0, j = j0; jj < n; jj++, j += dj)
            for (long ii = 0, i = i0; ii < n; ii++, i += di) {
                const long id = i + n * (j + n * k);
                if (fix[id]) continue;
                double t = local1(T, id, g[id]);
                if (minupd && !(t < T[id])) continue;
                if (!(t < INFINITY)) continue;
                const double c = fabs(t - T[id]);
                if (!(c <= ch)) ch = c;
                T[id] = t;
            }
    return ch;
}

static double maxT(const double *T)
{
    double m = 0;
    for (long id = 0; id < N3; id++)
        if (T[id] < INFINITY && T[id] > m) m = T[id];
    return m;
}

static void errors(const double *T, double *l1, double *linf, double *l1a, double *linfa)
{
    double s = 0, m = 0, sa = 0, ma = 0;
    long na = 0;
    for (long id = 0; id < N3; id++) {
        double x[3];
        coords(id, x);
        const double e = fabs(T[id] - exact(x));
        s += e;
        m = e > m ? e : m;
        const double r = sqrt((x[0] - S[0]) * (x[0] - S[0]) + (x[1] - S[1]) * (x[1] - S[1]) +
                              (x[2] - S[2]) * (x[2] - S[2]));
        if (r >= 0.25) sa += e, ma = e > ma ? e : ma, na++;
    }
    *l1 = s / N3, *linf = m, *l1a = sa / na, *linfa = ma;
}

static void setup(long NN, double R)
{
    n = NN + 1;
    N3 = n * n * n;
    h = 2.0 / NN;
    eps5 = 1e-6 * (h / 2) * (h / 2);
    f = malloc(N3 * sizeof *f);
    fix = calloc(N3, 1);
    if (!f || !fix) {
        fprintf(stderr, "dc_eik: out of memory\n");
        exit(1);
    }
    for (long id = 0; id < N3; id++) {
        double x[3];
        coords(id, x);
        f[id] = 1 / vel(x);
        double r2 = 0;
        for (int d = 0; d < 3; d++) r2 += (x[d] - S[d]) * (x[d] - S[d]);
        fix[id] = r2 <= R * R;
    }
}

static int run_hj(long NN, double R, double tol)
{
    const hj_eik_grid gr = {3, {n, n, n}, {-1, -1, -1}, {h, h, h}};
    double *T = malloc(N3 * sizeof *T), *fx = malloc(N3 * sizeof *fx);
    if (!T || !fx) return 1;
    long nfix = 0;
    for (long id = 0; id < N3; id++) {
        double x[3];
        coords(id, x);
        fx[id] = fix[id] ? exact(x) : NAN;
        nfix += fix[id];
    }
    hj_eik_options opt = hj_eik_default_options();
    opt.order = order, opt.tol = tol, opt.max_iter = 100000;
    for (int mode = 0; mode < 2; mode++) {
        hj_eik_stats st;
        hj_error err;
        const hj_eik_source src = {{S[0], S[1], S[2]}, 0};
        const double c0 = cpu();
        const int rc = mode == 0 ? hj_eik_solve(&gr, f, 0, NULL, NULL, 0, fx, &opt, T, &st, &err)
                                 : hj_eik_solve(&gr, f, 0, NULL, &src, 1, NULL, &opt, T, &st, &err);
        const double c1 = cpu();
        double l1, linf, l1a, linfa;
        errors(T, &l1, &linf, &l1a, &linfa);
        printf("hj_eik\t%s\tN=%ld\torder=%d\tR=%g\tnfix=%ld\trc=%d\titer=%ld\tfo_iter=%ld\tsweeps=%ld\t"
               "solves/node=%.1f\tfirst_order=%zu\tL1=%.4e\tLinf=%.4e\tL1away=%.4e\tLinfaway=%.4e\tcpu=%.2f\n",
               mode == 0 ? "fixed-ball" : "point-source", NN, order, R, nfix, rc, st.iterations,
               st.fo_iterations, st.sweeps, (double)st.updates / N3, st.first_order, l1, linf, l1a, linfa, c1 - c0);
        fflush(stdout);
        if (mode == 0 && getenv("DC_SAVE")) {
            FILE *fp = fopen(getenv("DC_SAVE"), "wb");
            if (fp) fwrite(T, sizeof *T, N3, fp), fclose(fp);
        }
    }
    free(T);
    free(fx);
    return 0;
}

/* A whole argument as a number (hj_cli's parsers: the whole string, a
 * finite double); 0 when it is not one. */

int main(int argc, char **argv)
{
    const int hj = argc > 1 && !strcmp(argv[1], "hj");
    const int a0 = hj ? 2 : 1;
    const int amax = hj ? a0 + 4 : a0 + 6; /* the last optional argument's index + 1 */
    if (argc < a0 + 2 || argc > amax) {
        fprintf(stderr, "usage: dc_eik N order [inner] [R] [tol] [itol] | dc_eik hj N order [R] [tol]\n");
        return 2;
    }
    long NN = 0, ord = 0, inner = 8;
    double R = 0.2, tol = 1e-12, itol = 1e-14;
    const int ai = hj ? a0 + 2 : a0 + 3;
    const int ok = eik_study_long(argv[a0], &NN) && eik_study_long(argv[a0 + 1], &ord) &&
                   (hj || argc <= a0 + 2 || eik_study_long(argv[a0 + 2], &inner)) && (argc <= ai || eik_study_double(argv[ai], &R)) &&
                   (argc <= ai + 1 || eik_study_double(argv[ai + 1], &tol)) &&
                   (argc <= ai + 2 || eik_study_double(argv[ai + 2], &itol));
    if (!ok || NN < 4 || NN > 2000 || (ord != 3 && ord != 5) || inner < 0 || inner > 1000000 || !(R > 0) ||
        !(tol > 0) || !(itol >= 0)) {
        fprintf(stderr, "dc_eik: need integers 4 <= N <= 2000, order 3 or 5, 0 <= inner <= 1e6, and numbers R > 0, "
                        "tol > 0, itol >= 0\n");
        return 2;
    }
    order = (int)ord;
    const char *gs = getenv("DC_GSCALE"), *es = getenv("DC_EPS");
    double gscale = 1, epsv = 0;
    if ((gs && (!eik_study_double(gs, &gscale) || !(gscale > 0))) || (es && (!eik_study_double(es, &epsv) || !(epsv > 0)))) {
        fprintf(stderr, "dc_eik: DC_GSCALE and DC_EPS must be numbers > 0\n");
        return 2;
    }
    if (gs) /* diagnostic: the speed's gradient times this (straighter rays) */
        for (int d = 0; d < 3; d++) G[d] *= gscale;
    setup(NN, R);
    long held = 0;
    for (long id = 0; id < N3; id++) held += fix[id];
    if (held == 0 || held == N3) {
        fprintf(stderr, "dc_eik: R = %g holds %s node of the grid (the ball |x - s| <= R must hold some and not all)\n",
                R, held ? "every" : "no");
        return 2;
    }
    bfo = getenv("DC_BFO") != NULL;
    if (es) eps3 = eps5 = epsv; /* diagnostic: 1e2 gives the linear weights */
    if (hj) return run_hj(NN, R, tol);
    if (getenv("DC_CHECK")) { /* residual Hh - f of a saved solution */
        double *U = malloc(N3 * sizeof *U);
        FILE *fp = fopen(getenv("DC_CHECK"), "rb");
        if (!U || !fp || fread(U, sizeof *U, N3, fp) != (size_t)N3) {
            fprintf(stderr, "dc_eik: DC_CHECK: cannot read %ld doubles from %s\n", N3, getenv("DC_CHECK"));
            return 1;
        }
        fclose(fp);
        const double M = maxT(U); /* the eps scale, as in the solve */
        if (!getenv("DC_EPS")) eps3 *= M * M, eps5 *= M * M;
        long cnt = 0;
        for (long id = 0; id < N3; id++) {
            if (fix[id]) continue;
            double Hh, H1;
            residuals(U, id, &Hh, &H1);
            if (fabs(Hh - f[id]) > 1e-9 && cnt++ < 20)
                printf("(%ld,%ld,%ld) res %.3e\n", id % n, (id / n) % n, id / (n * n), Hh - f[id]);
        }
        double mr = 0;
        long at = 0;
        for (long id = 0; id < N3; id++) {
            if (fix[id]) continue;
            double Hh, H1;
            residuals(U, id, &Hh, &H1);
            if (fabs(Hh - f[id]) > mr) mr = fabs(Hh - f[id]), at = id;
        }
        printf("%ld nodes with |Hh - f| > 1e-9; max %.3e at (%ld,%ld,%ld)\n", cnt, mr, at % n, (at / n) % n,
               at / (n * n));
        double mi = 0;
        long atq = 0;
        for (long id = 0; id < N3; id++) {
            const long i = id % n, j = (id / n) % n, k = id / (n * n);
            double x[3];
            coords(id, x);
            const double rr = sqrt((x[0] - S[0]) * (x[0] - S[0]) + (x[1] - S[1]) * (x[1] - S[1]) +
                                   (x[2] - S[2]) * (x[2] - S[2]));
            if (fix[id] || rr < 0.4 || i < 3 || j < 3 || k < 3 || i > n - 4 || j > n - 4 || k > n - 4) continue;
            double Hh, H1;
            residuals(U, id, &Hh, &H1);
            if (fabs(Hh - f[id]) > mi) mi = fabs(Hh - f[id]), atq = id;
        }
        printf("interior, |x - s| >= 0.4: max %.3e at (%ld,%ld,%ld)\n", mi, atq % n, (atq / n) % n, atq / (n * n));
        return 0;
    }

    double *T = malloc(N3 * sizeof *T), *g = malloc(N3 * sizeof *g), *Tk = malloc(N3 * sizeof *Tk);
    if (!T || !g || !Tk) {
        fprintf(stderr, "dc_eik: out of memory\n");
        return 1;
    }
    long nfix = 0;
    for (long id = 0; id < N3; id++) {
        double x[3];
        coords(id, x);
        T[id] = fix[id] ? exact(x) : INFINITY;
        nfix += fix[id];
    }
    const double c0 = cpu();
    /* first order start */
    long sweeps = 0, fo_iter = 0;
    double scale = 1;
    for (;;) {
        double ch = 0;
        for (int o = 0; o < 8; o++) {
            const double c = sweep(T, f, o, 1);
            ch = c > ch ? c : ch;
            sweeps++;
        }
        fo_iter++;
        scale = maxT(T);
        if (ch <= tol * scale || fo_iter > 1000) break;
    }
    double l1, linf, l1a, linfa;
    errors(T, &l1, &linf, &l1a, &linfa);
    fprintf(stderr, "first order: %ld iterations, L1 %.3e Linf %.3e\n", fo_iter, l1, linf);
    /* as hj_eik: the WENO eps scaled by the square of the first order
     * solution's largest value (the unknown's scale) */
    if (!getenv("DC_EPS")) eps3 *= scale * scale, eps5 *= scale * scale;

    long outer = 0, neg = 0, inner_total = 0;
    int o_next = 0, conv = 0;
    double last = 0;
    const double c1 = cpu();
    double resid_cpu = 0;
    while (outer < 2000) {
        const double r0 = cpu();
        double rmax = 0;
        for (long id = 0; id < N3; id++) {
            if (fix[id]) {
                g[id] = 0;
                continue;
            }
            double Hh, H1;
            residuals(T, id, &Hh, &H1);
            const double res = fabs(Hh - f[id]);
            rmax = res > rmax ? res : rmax;
            g[id] = f[id] + H1 - Hh;
            if (g[id] < 0) g[id] = 0, neg++;
        }
        resid_cpu += cpu() - r0;
        memcpy(Tk, T, N3 * sizeof *T);
        long ns = 0;
        if (inner > 0) {
            for (int s = 0; s < inner; s++, ns++) sweep(T, g, (o_next + s) % 8, 0);
            o_next = (o_next + inner) % 8;
        } else {
            for (int it = 0; it < 200; it++) {
                double ch = 0;
                for (int o = 0; o < 8; o++, ns++) {
                    const double c = sweep(T, g, o, 0);
                    ch = c > ch ? c : ch;
                }
                if (ch <= itol * scale) break;
            }
        }
        sweeps += ns;
        inner_total += ns;
        outer++;
        double ch = 0;
        long at = -1;
        for (long id = 0; id < N3; id++) {
            const double c = fabs(T[id] - Tk[id]);
            if (c > ch) ch = c, at = id;
        }
        scale = maxT(T);
        if (getenv("DC_VERBOSE"))
            fprintf(stderr, "outer %3ld: change %.3e ratio %.3f at (%ld,%ld,%ld) residual %.3e inner sweeps %ld\n",
                    outer, ch / scale, last > 0 ? ch / last : 0.0, at % n, (at / n) % n, at / (n * n), rmax, ns);
        last = ch;
        if (ch <= tol * scale) {
            conv = 1;
            break;
        }
    }
    const double c2 = cpu();
    errors(T, &l1, &linf, &l1a, &linfa);
    printf("dc\tN=%ld\torder=%d\tinner=%ld\tR=%g\tnfix=%ld\tconv=%d\tfo_iter=%ld\touter=%ld\tsweeps=%ld\tinner_sweeps=%ld\t"
           "neg_g=%ld\tL1=%.4e\tLinf=%.4e\tL1away=%.4e\tLinfaway=%.4e\tcpu=%.2f\tcpu_fo=%.2f\tcpu_resid=%.2f\n",
           NN, order, inner, R, nfix, conv, fo_iter, outer, sweeps, inner_total, neg, l1, linf, l1a, linfa, c2 - c0,
           c1 - c0, resid_cpu);
    if (getenv("DC_SAVE")) {
        FILE *fp = fopen(getenv("DC_SAVE"), "wb");
        if (fp) fwrite(T, sizeof *T, N3, fp), fclose(fp);
    }
    return conv ? 0 : 3;
}
